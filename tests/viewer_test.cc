// build/bin/viewer_node in a real browser: a one-shot loop runs in a private network namespace
// with the viewer following it, headless Chromium loads the page, and the balls the page drew
// (its own record, <pre id="drawn">) sit where the table simulator's summary says the ball
// rests, in the page's documented frame (tools/viewer_node/viewer_node.h). Hostile requests get
// an error status and nothing else. The screenshot is the README's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tests/support/run_command.h"

namespace {

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Viewer, ChromiumDrawsTheBallWhereTheTruthSays) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "no chromium";
  if (std::system("unshare -n true 2>/dev/null") != 0) GTEST_SKIP() << "no network namespace";
  const std::string dir = ::testing::TempDir() + "/viewer_test";
  const std::string bin = BIN_DIR;
  std::ofstream(dir + ".sh") << R"(set -e
ip link set lo up multicast on; ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
out=$1 bin=$2 browser="chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=2000"
mkdir -p "$out"
"$bin/viewer_node" --port 8799 2>/dev/null & v=$!
"$bin/estimator_node" 2>/dev/null & e=$!
"$bin/planner_node" >/dev/null 2>&1 & p=$!
trap 'kill $v $e $p 2>/dev/null; wait' EXIT
sleep 0.5
"$bin/table_sim_node" --shots 1 --seed 2 >"$out/summary.json" 2>/dev/null
sleep 0.3
$browser --dump-dom http://127.0.0.1:8799/ >"$out/dom.html" 2>/dev/null
$browser --hide-scrollbars --window-size=1120,720 --screenshot="$out/viewer.png" \
  http://127.0.0.1:8799/ >/dev/null 2>&1
exec 3<>/dev/tcp/127.0.0.1/8799; printf 'GARBAGE\r\n\r\n' >&3; head -c 200 <&3 >"$out/garbage.txt"
exec 3>&-
curl -s -o /dev/null -w "%{http_code}" "http://127.0.0.1:8799/../../etc/passwd" >"$out/traversal.txt"
curl -s -o /dev/null -w "%{http_code}" -X POST -d x http://127.0.0.1:8799/ >"$out/post.txt"
)";
  const auto r = billiard::testing::RunCommand("unshare -n bash " + dir + ".sh " + dir + " " + bin);
  ASSERT_EQ(r.status, 0) << r.out;

  const nlohmann::json summary = nlohmann::json::parse(Slurp(dir + "/summary.json"));
  const double x = summary["shots"][0]["final"][0], y = summary["shots"][0]["final"][1];
  std::smatch m;
  const std::string dom = Slurp(dir + "/dom.html");
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("<pre id=\"drawn\">([^<]*)</pre>"))) << dom;
  const nlohmann::json drawn = nlohmann::json::parse(m[1].str());
  // 400 px a metre, a 40 px rail, y up, on the 1.27 m wide pool table.
  const double u = 40 + 400 * x, v = 40 + 400 * (1.27 - y);
  // The last truth is the last frame's, the ball a few hundredths of a millimetre from where it
  // comes to rest after it: 0.05 px is 0.12 mm.
  ASSERT_EQ(drawn["truth"].size(), 1u) << drawn;
  EXPECT_NEAR(drawn["truth"][0]["u"].get<double>(), u, 0.05);
  EXPECT_NEAR(drawn["truth"][0]["v"].get<double>(), v, 0.05);
  // The estimate within 2 px (5 mm) of the truth: the estimator's error is about 1 mm.
  ASSERT_EQ(drawn["estimate"].size(), 1u) << drawn;
  EXPECT_NEAR(drawn["estimate"][0]["u"].get<double>(), u, 2.0);
  EXPECT_NEAR(drawn["estimate"][0]["v"].get<double>(), v, 2.0);
  EXPECT_GT(Slurp(dir + "/viewer.png").size(), 1000u);

  const std::string garbage = Slurp(dir + "/garbage.txt");
  EXPECT_EQ(garbage.rfind("HTTP/1.1 400", 0), 0u) << garbage;
  EXPECT_EQ(Slurp(dir + "/traversal.txt"), "404");
  EXPECT_EQ(Slurp(dir + "/post.txt"), "405");
}

}  // namespace
