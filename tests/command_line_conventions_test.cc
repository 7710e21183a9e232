// docs/exit-codes.md as a user meets them: every script, node binary and billiard
// subcommand answers --help (exit 0, the usage on stdout) and a bad command line (exit 2, one
// line on stderr) alike, and refusals, internal failures and signals exit as the table says.
// The scripts run with fakes of the tools their real work starts (cmake, apt-get, ...) first on
// the PATH: that a fake ran is how a test sees work that --help or a usage error must not do.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.h"

namespace {

namespace fs = std::filesystem;
using billiard::testing::RunCommandApart;
using billiard::testing::SeparateOutput;

// What a usage error or a failure prints on stderr: its reason, in exactly one line.
bool OneLine(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n') == 1 && text.back() == '\n';
}

struct Script {
  std::string path;  // in the source tree
  std::vector<std::string> options;
};

const std::vector<Script> kScripts = {
    {"launch_scripts/setup.sh", {}},
    {"launch_scripts/build.sh", {"--target"}},
    {"launch_scripts/test.sh", {"--no-build"}},
    {"launch_scripts/run_loop.sh",
     {"--game", "--racks", "--shot-limit", "--shots", "--seed", "--noise", "--params", "--log", "--log-frames",
      "--lockstep", "--realtime", "--json", "--no-build", "--camera", "--camera-model"}},
    {"launch_scripts/replay.sh", {"--params", "--camera", "--json"}},
    {"launch_scripts/fault_drill.sh", {"--shots", "--no-build"}},
    {"launch_scripts/two_hosts.sh", {"--shots", "--seed", "--dask", "--no-build"}},
    {"launch_scripts/reliability_report.sh", {"--fuzz-seconds", "--shots", "--no-build"}},
    {"launch_scripts/spy.sh", {"--lcm-url", "--build-dir", "--check"}},
    {"fuzz/run_fuzzers.sh",
     {"--minutes", "--seconds", "--json", "--seed", "--corpus", "--artifacts", "--bin-dir"}},
};

// What the scripts' real work would run first: installing, building, testing, entering a network
// namespace, recording, a JVM; and a fuzz target, in a folder of its own for --bin-dir. Each fake
// only writes its name into the fakes' log.
const std::vector<std::string> kFakedTools = {"apt-get", "sudo",    "dpkg-query", "cmake",
                                              "ctest",   "unshare", "lcm-logger", "java"};

class Scripts : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fakes_ = ::testing::TempDir() + "/command_line_conventions_fakes";
    fs::remove_all(fakes_);
    fs::create_directories(FuzzTargets());
    for (const std::string& tool : kFakedTools) Fake(fakes_ + "/" + tool);
    Fake(FuzzTargets() + "/fuzz_fake");
  }

  static void Fake(const std::string& path) {
    std::ofstream(path) << "#!/bin/sh\necho \"$0 $*\" >>" << Log() << "\n";
    fs::permissions(path, fs::perms::owner_all);
  }

  static std::string FuzzTargets() { return fakes_ + "/fuzz_targets"; }

  void SetUp() override { fs::remove(Log()); }

  static std::string Log() { return fakes_ + "/ran.log"; }

  // The tools that ran since SetUp, one line each ("" when none).
  static std::string WorkDone() {
    std::ifstream in(Log());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  static SeparateOutput Run(const Script& script, const std::string& args) {
    return RunCommandApart("PATH=" + fakes_ + ":$PATH bash " + SOURCE_DIR + "/" + script.path +
                           " " + args + " </dev/null");
  }

  // Exit 2, nothing on stdout, exactly one line on stderr, no work done.
  static void ExpectUsageError(const Script& script, const std::string& args) {
    const SeparateOutput r = Run(script, args);
    const std::string what = script.path + " " + args;
    EXPECT_EQ(r.status, 2) << what << ": " << r.err;
    EXPECT_EQ(r.out, "") << what;
    EXPECT_TRUE(OneLine(r.err)) << what << ": " << r.err;
    EXPECT_EQ(WorkDone(), "") << what;
  }

  static std::string fakes_;
};

std::string Scripts::fakes_;

TEST_F(Scripts, HelpPrintsTheUsageWithEveryOptionAndDoesNoWork) {
  for (const Script& script : kScripts) {
    for (const std::string help : {"--help", "-h"}) {
      const SeparateOutput r = Run(script, help);
      EXPECT_EQ(r.status, 0) << script.path << " " << help << ": " << r.err;
      EXPECT_EQ(r.err, "") << script.path << " " << help;
      EXPECT_NE(r.out.find("usage: "), std::string::npos) << script.path << ": " << r.out;
      for (const std::string& option : script.options) {
        EXPECT_NE(r.out.find(option), std::string::npos) << script.path << ": " << option;
      }
      EXPECT_NE(r.out.find("--help"), std::string::npos) << script.path << ": " << r.out;
      EXPECT_EQ(WorkDone(), "") << script.path << " " << help;
      fs::remove(Log());
    }
  }
}

TEST_F(Scripts, AnUnknownOptionIsAUsageError) {
  for (const Script& script : kScripts) {
    ExpectUsageError(script, "--no-such-option");
    fs::remove(Log());
  }
}

TEST_F(Scripts, MissingOrBadValuesAndStrayArgumentsAreUsageErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"launch_scripts/setup.sh", "extra"},
      {"launch_scripts/build.sh", "extra"},
      {"launch_scripts/build.sh", "--target"},
      {"launch_scripts/run_loop.sh", "--params"},
      {"launch_scripts/test.sh", "extra"},
      {"launch_scripts/run_loop.sh", "--shots"},
      {"launch_scripts/run_loop.sh", "--shots abc"},
      {"launch_scripts/run_loop.sh", "--shots 0"},
      {"launch_scripts/run_loop.sh", "--seed -1"},
      {"launch_scripts/run_loop.sh", "--noise maybe"},
      {"launch_scripts/run_loop.sh", "--game chess"},
      {"launch_scripts/run_loop.sh", "--racks 0"},
      {"launch_scripts/run_loop.sh", "--game drill --shots 3"},
      {"launch_scripts/run_loop.sh", "extra"},
      {"launch_scripts/run_loop.sh", "--camera"},
      {"launch_scripts/run_loop.sh", "--camera /no/such.avi"},
      {"launch_scripts/run_loop.sh", "--camera 97"},
      {"launch_scripts/run_loop.sh", "--camera /tmp --shots 3"},
      {"launch_scripts/run_loop.sh", "--camera /tmp --camera-model /no/such.json"},
      {"launch_scripts/run_loop.sh", "--camera-model /tmp/camera.json"},
      {"launch_scripts/replay.sh", ""},
      {"launch_scripts/fault_drill.sh", "--shots"},
      {"launch_scripts/two_hosts.sh", "--shots 0"},
      {"launch_scripts/two_hosts.sh", "--dask 0"},
      {"launch_scripts/fault_drill.sh", "--shots abc"},
      {"launch_scripts/reliability_report.sh", "--fuzz-seconds"},
      {"launch_scripts/reliability_report.sh", "--fuzz-seconds abc"},
      {"launch_scripts/reliability_report.sh", "--shots 0"},
      {"launch_scripts/spy.sh", "--lcm-url"},
      {"launch_scripts/spy.sh", "extra"},
      {"fuzz/run_fuzzers.sh", "--bin-dir " + FuzzTargets() + " --minutes"},
      {"fuzz/run_fuzzers.sh", "--bin-dir " + FuzzTargets() + " --seconds abc"},
      {"fuzz/run_fuzzers.sh", "--bin-dir " + FuzzTargets() + " --seed x"},
  };
  for (const auto& [path, args] : cases) {
    ExpectUsageError({path, {}}, args);
    fs::remove(Log());
  }
}

// A port on 127.0.0.1 that this test listens on, the kernel's choice (free until now), while
// it lives.
class ListeningPort {
 public:
  ListeningPort() : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof(address);
    const bool listening =
        fd_ >= 0 && bind(fd_, reinterpret_cast<sockaddr*>(&address), size) == 0 &&
        listen(fd_, 1) == 0 && getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size) == 0;
    EXPECT_TRUE(listening);
    port_ = std::to_string(ntohs(address.sin_port));
  }
  ~ListeningPort() { close(fd_); }
  const std::string& port() const { return port_; }

 private:
  int fd_;
  std::string port_;
};

// run_loop.sh --view on a port in use on this host: said before anything is built or started.
TEST_F(Scripts, ALiveViewOnAPortInUseIsAUsageError) {
  const ListeningPort taken;
  ExpectUsageError({"launch_scripts/run_loop.sh", {}}, "--view-port " + taken.port());
}

SeparateOutput RunBinary(const std::string& command) {
  return RunCommandApart(command + " </dev/null");
}

void ExpectStatus(const std::string& command, int status) {
  const SeparateOutput r = RunBinary(command);
  EXPECT_EQ(r.status, status) << command << ": " << r.err;
}

void ExpectOneLine(const std::string& command, int status) {
  const SeparateOutput r = RunBinary(command);
  EXPECT_EQ(r.status, status) << command << ": " << r.err;
  EXPECT_TRUE(OneLine(r.err)) << command << ": " << r.err;
}

const std::string kBilliard = BILLIARD_BIN;
const std::string kPlannerNode = PLANNER_NODE_BIN;
const std::string kEstimatorNode = ESTIMATOR_NODE_BIN;
const std::string kViewerNode = VIEWER_NODE_BIN;
const std::string kTableSimNode = TABLE_SIM_NODE_BIN;
const std::string kCameraNode = CAMERA_NODE_BIN;
// A source camera_node finds (a directory, of no images: the node stays up, reporting it).
const std::string kCameraSource = " --images " + ::testing::TempDir();

// The subcommands `billiard --help` lists, so that a new one is held to the convention too.
std::vector<std::string> BilliardSubcommands() {
  std::istringstream help(RunBinary(kBilliard + " --help").out);
  std::vector<std::string> names;
  bool listed = false;
  for (std::string line; std::getline(help, line);) {
    if (line == "Subcommands:") {
      listed = true;
    } else if (listed && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return names;
}

TEST(Binaries, HelpExitsZeroAndAnUnknownOptionTwo) {
  std::vector<std::string> commands = {kBilliard,    kPlannerNode, kEstimatorNode,
                                       kTableSimNode, kViewerNode,  kCameraNode};
  const std::vector<std::string> subcommands = BilliardSubcommands();
  EXPECT_GE(subcommands.size(), 13u);
  for (const std::string& sub : subcommands) commands.push_back(kBilliard + " " + sub);
  for (const std::string& command : commands) {
    const SeparateOutput help = RunBinary(command + " --help");
    EXPECT_EQ(help.status, 0) << command << ": " << help.err;
    EXPECT_NE(help.out.find("--help"), std::string::npos) << command << ": " << help.out;
    ExpectOneLine(command + " --no-such-option", 2);
  }
}

// --version, like --help, exits 0 and does no work: the name and the project's one version.
TEST(Binaries, VersionPrintsTheNameAndTheProjectVersion) {
  for (const std::string& command :
       {kBilliard, kPlannerNode, kEstimatorNode, kTableSimNode, kCameraNode, kViewerNode}) {
    const SeparateOutput r = RunBinary(command + " --version");
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_EQ(r.out, fs::path(command).filename().string() + " " + PROJECT_VERSION + "\n");
  }
}

// A port another program listens on: an output that cannot be made, said in one line before
// LCM is opened (exit 2), as for a file that cannot be written.
TEST(Binaries, AViewerOnAPortInUseIsOneLineAndExitsTwo) {
  const ListeningPort taken;
  const SeparateOutput r = RunBinary(kViewerNode + " --port " + taken.port());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(OneLine(r.err)) << r.err;
  EXPECT_NE(r.err.find("127.0.0.1:" + taken.port()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("in use"), std::string::npos) << r.err;
}

TEST(Binaries, RefusalsExitThree) {
  ExpectOneLine(kBilliard + " plan --from 0.5,0.5 --to 5,0.5 --json", 3);
  // A frame without the four corner markers: the calibration's answer is no, as for a misfit.
  const std::string blank = ::testing::TempDir() + "/blank_frame.pgm";
  std::ofstream(blank) << "P5 64 48 255\n" << std::string(64 * 48, '\x80');
  const std::string camera = ::testing::TempDir() + "/blank_camera.json";
  fs::remove(camera);  // an earlier run's, in the shared temporary directory
  ExpectOneLine(kBilliard + " calibrate " + blank + " --out " + camera, 3);
  EXPECT_FALSE(fs::exists(camera));
}

TEST(Binaries, UsageErrorsExitTwo) {
  const std::string unwritable = "/dev/null/out";  // not a directory, even for root
  for (const std::string& args : std::vector<std::string>{
           "plan --from nan,0 --to 1,1", "calibrate /no/such.png --out /tmp/x.json",
           "detect /no/such.png", "node-status /no/such.lcm", "replay /no/such.lcm",
           "simulate --state 0,0,0,1,0,0,0 --t-end 1 --trajectory " + unwritable + ".csv",
           "bench-planner --requests 1 --out " + unwritable,
           "bench-estimator --scenes 1 --balls 1 --struck 1 --out " + unwritable,
           "bench --quick --shots 0 --out " + unwritable, "burst --requests 0",
           "burst --timeout 0", "plan --from 0.5,0.5 --to 1,0.5 --final-speed -0.3",
           "rack nine-ball --seed -1"}) {
    ExpectOneLine(kBilliard + " " + args, 2);
  }
  ExpectOneLine(kPlannerNode + " --params /no/such.json", 2);
  ExpectOneLine(kEstimatorNode + " --camera /no/such.json", 2);
  ExpectOneLine(kTableSimNode + " --shots 0", 2);
  ExpectOneLine(kViewerNode + " --port 0", 2);
  ExpectOneLine(kCameraNode + " --video /no/such.avi", 2);
  ExpectOneLine(kCameraNode + kCameraSource + " --video /no/such.avi", 2);
}

// A mistyped subcommand is named, with the nearest one when it is a few letters away (not a
// guess at an unrelated word), exit 2; no subcommand at all is said so.
TEST(Binaries, AnUnknownSubcommandIsNamedWithTheNearest) {
  const SeparateOutput near = RunBinary(kBilliard + " simulat --json");
  EXPECT_EQ(near.status, 2);
  EXPECT_EQ(near.err,
            "billiard: unknown subcommand 'simulat'; did you mean 'simulate'? (see --help)\n");
  EXPECT_TRUE(near.out.empty());
  EXPECT_NE(RunBinary(kBilliard + " choose_shot").err.find("did you mean 'choose-shot'?"),
            std::string::npos);
  const SeparateOutput far = RunBinary(kBilliard + " xyz");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err, "billiard: unknown subcommand 'xyz' (see --help)\n");
  ExpectOneLine(kBilliard, 2);
}

TEST(Binaries, InternalFailuresExitOne) {
  // LCM that cannot be opened (LCM itself says so in a line of its own first).
  for (const std::string& command : std::vector<std::string>{kPlannerNode, kEstimatorNode,
                                                             kTableSimNode, kViewerNode,
                                                             kCameraNode + kCameraSource,
                                                             kBilliard + " burst"}) {
    ExpectStatus(command + " --lcm-url nosuch://", 1);
  }
  // Nodes that do not answer in time: there are none on a private in-memory LCM.
  ExpectOneLine(kTableSimNode + " --lcm-url memq:// --reply-timeout 0.3", 1);
  ExpectOneLine(kBilliard + " burst --lcm-url memq:// --timeout 0.3", 1);
}

// `command` started, sent `signal` two seconds later, and its exit status. Two seconds: a node
// links OpenCV's video backends and LCM, and on a machine running two tests at once its start
// alone has taken more than half a second, before any handler could be installed.
int StatusAfterSignal(const std::string& command, const std::string& signal) {
  // A background job of a non-interactive shell ignores SIGINT unless it installs a handler,
  // which is what this is to see.
  return RunBinary(command + " & pid=$!; sleep 2; kill -" + signal + " $pid; wait $pid").status;
}

TEST(Binaries, SignalsStopNodesWithZeroAndCommandsWith130) {
  // A signal is how a node is stopped normally: not a failure.
  EXPECT_EQ(StatusAfterSignal(kPlannerNode + " --lcm-url memq://", "TERM"), 0);
  EXPECT_EQ(StatusAfterSignal(kEstimatorNode + " --lcm-url memq://", "INT"), 0);
  EXPECT_EQ(StatusAfterSignal(kViewerNode + " --lcm-url memq:// --port 8797", "TERM"), 0);
  EXPECT_EQ(StatusAfterSignal(kCameraNode + kCameraSource + " --lcm-url memq://", "TERM"), 0);
  // A session or a command that a signal cuts short did not finish.
  EXPECT_EQ(StatusAfterSignal(kTableSimNode + " --lcm-url memq:// --reply-timeout 30", "TERM"),
            130);
  EXPECT_EQ(StatusAfterSignal(kBilliard + " burst --lcm-url memq://", "TERM"), 130);
  EXPECT_EQ(StatusAfterSignal(kBilliard + " burst --lcm-url memq://", "INT"), 130);
}

}  // namespace
