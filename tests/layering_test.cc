// The architecture as the tree shows it: every module includes only the modules below it, the
// physics depends on Eigen alone, and the README's layout table names every module folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Each module and the modules its production code may include (besides itself). Listed from
// the bottom up; a folder's files belong to the longest module folder that holds them.
const std::map<std::string, std::set<std::string>>& Layers() {
  static const std::map<std::string, std::set<std::string>> layers = {
      {"tests/support", {}},
      {"lcmtypes", {}},
      {"lcmtypes/node", {"lcmtypes"}},
      {"lcmtypes/testing", {"lcmtypes"}},
      {"sim/physics", {}},
      {"sim/batch", {"sim/physics"}},
      {"sim/table", {"sim/physics"}},
      {"sim/table/testing", {"sim/table", "sim/physics", "sim/params"}},
      {"sim/cue", {"sim/physics", "sim/table"}},
      {"sim/params", {"sim/physics", "sim/table", "sim/cue"}},
      {"sim/rules", {"sim/table", "sim/physics", "sim/batch"}},
      {"sim/physics/testing", {"sim/physics", "sim/params"}},
      {"sim/model_choice", {"sim/physics", "sim/table"}},
      {"sim/contact_fit", {"sim/physics"}},
      {"sim/shot_fit", {"sim/physics", "sim/table", "sim/batch"}},
      {"sim/camera", {"sim/physics"}},
      {"sim/render", {"sim/camera", "sim/physics"}},
      {"sim/table_sim_node",
       {"sim/render", "sim/camera", "sim/physics", "sim/table", "sim/cue", "sim/model_choice",
        "sim/params", "sim/rules", "sim/batch", "lcmtypes", "lcmtypes/node"}},
      {"planner", {"sim/physics", "sim/params", "sim/cue", "sim/table"}},
      {"planner/testing", {"planner", "sim/physics"}},
      {"planner/pot", {"sim/physics", "sim/table", "sim/cue", "sim/model_choice"}},
      {"planner/pot/testing", {"planner/pot", "sim/table", "sim/physics"}},
      {"planner/choice",
       {"planner/pot", "sim/cue", "sim/physics", "sim/table", "sim/params", "sim/model_choice", "sim/batch",
        "sim/rules"}},
      {"planner/players",
       {"planner/choice", "sim/rules", "sim/physics", "sim/table", "sim/params", "sim/batch"}},
      {"planner/game",
       {"planner/players", "planner/choice", "planner/pot", "sim/rules", "sim/physics", "sim/table",
        "sim/params", "sim/model_choice", "sim/batch", "sim/cue"}},
      {"planner/node",
       {"planner", "planner/pot", "planner/choice", "planner/players", "planner/game", "sim/physics",
        "sim/table",
        "sim/params", "sim/shot_fit", "sim/rules", "sim/batch", "lcmtypes", "lcmtypes/node"}},
      {"estimator", {"sim/physics", "sim/camera"}},
      {"estimator/testing", {"estimator", "sim/physics", "sim/params", "tests/support"}},
      {"estimator/node",
       {"estimator", "sim/camera", "sim/physics", "sim/params", "lcmtypes", "lcmtypes/node"}},
      {"fuzz",
       {"lcmtypes", "lcmtypes/testing", "sim/table", "sim/table/testing", "sim/params",
        "sim/physics"}},
      {"plot", {"sim/table", "sim/physics"}},
      {"bench",
       {"plot", "sim/physics", "sim/batch", "sim/table", "sim/table/testing", "sim/params",
        "sim/model_choice", "sim/camera", "sim/render", "planner", "planner/testing", "planner/pot",
        "planner/pot/testing", "planner/choice", "planner/players", "planner/game", "sim/rules",
        "estimator", "estimator/testing", "sim/shot_fit", "tests/support"}},
      {"tools/billiard",
       {"sim/physics", "sim/batch", "sim/table", "sim/cue", "sim/params", "sim/model_choice",
        "sim/contact_fit", "sim/shot_fit", "sim/camera", "sim/render", "sim/table_sim_node",
        "lcmtypes", "lcmtypes/node", "planner", "planner/pot", "planner/choice", "planner/players",
        "planner/game", "sim/rules", "planner/node", "estimator",
        "estimator/node", "bench", "planner/pot/testing", "plot", "tools/camera_node"}},
      {"tools/viewer_node",
       {"lcmtypes", "lcmtypes/node", "sim/params", "sim/physics", "sim/table", "plot"}},
      {"tools/camera_node", {"lcmtypes", "lcmtypes/node"}},
      {"tools/python",
       {"sim/physics", "sim/table", "sim/cue", "sim/params", "sim/batch", "sim/rules", "planner",
        "planner/pot", "planner/choice", "planner/players", "planner/game", "estimator"}},
      {"tests", {}},  // the cross-module tests may include anything
  };
  return layers;
}

// The module a repository path belongs to, "" if none.
std::string ModuleOf(const std::string& path) {
  std::string best;
  for (const auto& [module, allowed] : Layers()) {
    if (path.rfind(module + "/", 0) == 0 && module.size() > best.size()) best = module;
  }
  return best;
}

bool IsTestCode(const std::string& path) {
  return path.find("_test.cc") != std::string::npos || path.find("/testing/") != std::string::npos;
}

struct Include {
  std::string file;  // repository path of the file that includes
  int line;
  std::string target;
  bool quoted;  // "..." (the repository's) rather than <...>
};

std::vector<Include> IncludesOfTheTree() {
  const fs::path root = PROJECT_SOURCE_DIR;
  const std::regex directive(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::vector<Include> found;
  for (const char* top :
       {"sim", "planner", "estimator", "lcmtypes", "plot", "tools", "bench", "fuzz", "tests"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cc" && ext != ".in")) continue;
      const std::string file = fs::relative(entry.path(), root).generic_string();
      std::ifstream in(entry.path());
      std::string text;
      int line = 0;
      while (std::getline(in, text)) {
        ++line;
        std::smatch m;
        if (std::regex_search(text, m, directive))
          found.push_back({file, line, m[2], m[1] == "\""});
      }
    }
  }
  return found;
}

// The module of a "module/..." include: generated messages belong to lcmtypes.
std::string ModuleOfInclude(const std::string& target) { return ModuleOf(target); }

TEST(Layering, NoModuleIncludesOneAboveIt) {
  const std::vector<Include> includes = IncludesOfTheTree();
  ASSERT_GT(includes.size(), 500u) << "the tree was not read";
  for (const Include& i : includes) {
    if (!i.quoted) continue;
    const std::string from = ModuleOf(i.file);
    ASSERT_FALSE(from.empty()) << i.file << " belongs to no module of the layering";
    const std::string to = ModuleOfInclude(i.target);
    EXPECT_FALSE(to.empty()) << i.file << ":" << i.line << " includes \"" << i.target
                             << "\", which does not name its module from the repository root";
    if (to.empty() || to == from || from == "tests") continue;
    const std::set<std::string>& allowed = Layers().at(from);
    if (allowed.count(to)) continue;
    // Tests and fixtures may also use the fixtures and the modules that make test scenes, but
    // never the benchmarks or the tool above them.
    if (IsTestCode(i.file) && to != "tools/billiard" && (to != "bench" || from == "bench")) {
      continue;
    }
    ADD_FAILURE() << i.file << ":" << i.line << " (" << from << ") includes \"" << i.target
                  << "\" (" << to << "), which is not below it";
  }
}

TEST(Layering, ThePhysicsDependsOnEigenAlone) {
  // The standard library, Eigen, and Ceres' header-only Jet for automatic differentiation.
  const std::regex allowed(R"(^(Eigen/\w+|ceres/jet\.h|[a-z_]+)$)");
  for (const Include& i : IncludesOfTheTree()) {
    if (ModuleOf(i.file) != "sim/physics" || IsTestCode(i.file) || i.quoted) continue;
    EXPECT_TRUE(std::regex_match(i.target, allowed))
        << i.file << ":" << i.line << " includes <" << i.target << ">";
  }
  std::ifstream cmake(std::string(PROJECT_SOURCE_DIR) + "/sim/physics/CMakeLists.txt");
  std::stringstream text;
  text << cmake.rdbuf();
  const std::regex link(R"(target_link_libraries\(physics ([^)]*)\))");
  std::smatch m;
  const std::string s = text.str();
  ASSERT_TRUE(std::regex_search(s, m, link)) << "no target_link_libraries(physics ...)";
  EXPECT_EQ(m[1].str(), "PUBLIC Eigen3::Eigen");
}

TEST(Layering, TheReadmesLayoutTableNamesEveryModule) {
  std::ifstream readme(std::string(PROJECT_SOURCE_DIR) + "/README.md");
  std::stringstream text;
  text << readme.rdbuf();
  const std::string s = text.str();
  const std::size_t table = s.find("## Layout");
  ASSERT_NE(table, std::string::npos) << "README.md has no Layout section";
  const std::string layout = s.substr(table, s.find("\n## ", table + 1) - table);
  for (const auto& [module, allowed] : Layers()) {
    EXPECT_NE(layout.find("`" + module + "/`"), std::string::npos)
        << "README.md's layout table does not name `" << module << "/`";
    EXPECT_TRUE(fs::is_directory(fs::path(PROJECT_SOURCE_DIR) / module)) << module;
  }
}

}  // namespace
