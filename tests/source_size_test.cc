// A file holds one job and a function reads as named steps: no source file over 500 lines and no
// function body over 80, read off the source tree. A function over today that waits for its split
// is listed below with the job it holds too many of; a listed one that has come under its limit
// fails too, so that the list shrinks and never hides a new one.
//
// Functions are read the way the tree writes them (Google style, as Drake and Ceres): a
// definition starts at column 0 with its name and an opening parenthesis, its body opens at the
// first line ending in '{' and closes at the next line that is '}' alone. Members defined inside
// a class body are indented and not read: they are the short ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr int kMaxFileLines = 500;
constexpr int kMaxFunctionLines = 80;

// The module folders whose production code is read (tests and test fixtures are not: a test
// file holds one module's tests).
constexpr const char* kTopFolders[] = {"sim", "planner", "estimator", "lcmtypes", "plot",
                                       "tools", "bench", "fuzz"};

// Functions over the limit today, by "file:name".
const std::map<std::string, std::string>& LongFunctions() {
  static const std::map<std::string, std::string> functions = {
      {"tools/billiard/simulate_command.cc:Run", "one ball, a scene and their outputs"},
      {"tools/billiard/burst_command.cc:Run", "the burst, its answers and the summary"},
      {"tools/billiard/replay_command.cc:Run", "the log read, replayed and compared"},
      {"plot/table_picture.cc:DrawTable", "the table, the paths, the events and the labels"},
      {"plot/chart.cc:DrawChart", "the axes, the lines and the labels"},
      {"sim/table/table_simulation_held.cc:TableSimulation::ResolveHeld", "the held set's solve and its release"},
      {"sim/table/table_simulation.cc:TableSimulation::Apply", "every kind of event"},
      {"sim/table/held_contacts.cc:SolveHeldContacts", "the contact graph, the solve and the check"},
      {"sim/table/table_geometry.cc:BuildTable", "the cushions, the jaws and the pockets"},
      {"sim/render/table_renderer.cc:TableRenderer::TableRenderer", "the cloth, the rails and the pockets drawn once"},
      {"sim/render/table_renderer.cc:TableRenderer::Render", "the balls, their blur and the noise"},
      {"sim/render/table_renderer.cc:TableRenderer::RenderRegion", "the shading of one region"},
      {"bench/game_benchmark.cc:WriteGameReport", "every table of the report"},
  };
  return functions;
}

bool IsProductionSource(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::string generic = path.generic_string();
  const std::string ext = path.extension().string();
  if (ext != ".h" && ext != ".cc") return false;
  return name.find("_test.cc") == std::string::npos && generic.find("/testing/") == std::string::npos;
}

struct Source {
  std::string path;  // from the repository root
  std::vector<std::string> lines;
};

std::vector<Source> ProductionSources() {
  const fs::path root = PROJECT_SOURCE_DIR;
  std::vector<Source> sources;
  for (const char* top : kTopFolders) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file() || !IsProductionSource(entry.path())) continue;
      Source source{fs::relative(entry.path(), root).generic_string(), {}};
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);) source.lines.push_back(line);
      sources.push_back(std::move(source));
    }
  }
  return sources;
}

struct Function {
  std::string name;  // as written before its '(': "Run", "TableSimulation::Apply"
  int first_line;    // 1-based, the line of its name
  int body_lines;    // from the line that opens the body to the '}' that closes it
};

// A definition's first line: at column 0, a return type or none (a constructor), a name and '(',
// not a declaration of a scope.
const std::regex& DefinitionStart() {
  static const std::regex start(
      R"(^(?!namespace|class|struct|enum|union|using|typedef|template|extern|static_assert|return)(?:[A-Za-z_][^;{}(]*?[\s*&>])?([A-Za-z_~][A-Za-z_0-9:~]*)\()");
  return start;
}

std::vector<Function> FunctionsOf(const Source& source) {
  std::vector<Function> functions;
  const std::vector<std::string>& lines = source.lines;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!std::regex_search(lines[i], m, DefinitionStart())) continue;
    std::size_t open = i;
    while (open < lines.size() && !lines[open].empty() && lines[open].back() != '{' &&
           lines[open].back() != ';') {
      ++open;
    }
    if (open == lines.size() || lines[open].empty() || lines[open].back() != '{') continue;
    std::size_t close = open;
    while (close < lines.size() && lines[close] != "}") ++close;
    if (close == lines.size()) continue;
    functions.push_back({m[1], static_cast<int>(i) + 1, static_cast<int>(close - open) + 1});
    i = close;
  }
  return functions;
}

TEST(SourceSize, TheFunctionReaderFindsDefinitionsAndSkipsDeclarations) {
  Source source{"x.cc",
                {"int Declared(int a);", "namespace {", "int Short(int a,", "          int b) {",
                 "  return a + b;", "}", "}  // namespace", "Foo::Foo(int a)", "    : a_(a) {",
                 "  if (a) {", "  }", "}", "class Bar {", " public:", "  void Inline() {}", "};"}};
  const std::vector<Function> functions = FunctionsOf(source);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].name, "Short");
  EXPECT_EQ(functions[0].body_lines, 3);
  EXPECT_EQ(functions[1].name, "Foo::Foo");
  EXPECT_EQ(functions[1].body_lines, 4);
}

TEST(SourceSize, NoFileOverItsLimit) {
  const std::vector<Source> sources = ProductionSources();
  ASSERT_GT(sources.size(), 200u) << "the tree was not read";
  for (const Source& s : sources) {
    EXPECT_LE(static_cast<int>(s.lines.size()), kMaxFileLines)
        << s.path << ": a file holds one job; split it";
  }
}

TEST(SourceSize, NoFunctionOverItsLimitButThoseWaitingForTheirSplit) {
  std::map<std::string, int> long_functions;
  for (const Source& s : ProductionSources()) {
    for (const Function& f : FunctionsOf(s)) {
      if (f.body_lines <= kMaxFunctionLines) continue;
      const std::string key = s.path + ":" + f.name;
      long_functions[key] = f.body_lines;
      EXPECT_TRUE(LongFunctions().count(key))
          << s.path << ":" << f.first_line << " " << f.name << " is " << f.body_lines
          << " lines (at most " << kMaxFunctionLines << "): let it read as named steps";
    }
  }
  for (const auto& [key, why] : LongFunctions()) {
    EXPECT_TRUE(long_functions.count(key))
        << key << " is listed as too long (" << why << ") but is not: take it off the list";
  }
}

}  // namespace
