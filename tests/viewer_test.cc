// build/bin/viewer_node in a real browser: the break and one chosen shot of a nine-ball rack run
// in a private network namespace with the viewer following them, and headless Chromium, with no
// time given to the page's script beyond its load, saves the page (--dump-dom) and a screenshot.
// What the page drew (its own record, <script id="drawn">) is checked against independent truth:
// the balls left are the rack's ten less those the session's summary says dropped, each drawn by
// its number where the table simulator's truth puts that ball; the six pockets where the WPA
// table's geometry has them, in the page's documented frame (tools/viewer_node/viewer_node.h);
// the chosen stroke's pot chance on the status line. The screenshot's pixels: the cloth, and the
// 9 a stripe (yellow band, white cap) beside a solid. Hostile requests get an error status and
// nothing else. The screenshot is the README's (docs/pictures/viewer.png). A snooker table's
// balls, in their colours, in a page the viewer serves.
#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/names.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "tests/support/run_command.h"
#include "tools/viewer_node/viewer_node.h"

namespace {

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The page's frame: 400 px a metre, a 40 px rail, y up; the canvas 8 px into the page.
constexpr double kScale = 400, kMargin = 40, kPageMargin = 8;

constexpr char kScript[] = R"(set -e
ip link set lo up multicast on; ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
out=$1 bin=$2 browser="chromium --headless --no-sandbox --disable-gpu --force-device-scale-factor=1"
mkdir -p "$out"
"$bin/viewer_node" --port 8799 2>/dev/null & v=$!
"$bin/estimator_node" 2>/dev/null & e=$!
"$bin/planner_node" >/dev/null 2>&1 & p=$!
trap 'kill $v $e $p 2>/dev/null; wait' EXIT
sleep 0.5
"$bin/table_sim_node" --game nine-ball --shot-limit 2 --seed 3 >"$out/summary.json" 2>/dev/null
sleep 0.3
$browser --dump-dom http://127.0.0.1:8799/ >"$out/dom.html" 2>/dev/null & d=$!
$browser --hide-scrollbars --window-size=1112,632 --screenshot="$out/viewer.png" \
  http://127.0.0.1:8799/ >/dev/null 2>&1
wait $d
exec 3<>/dev/tcp/127.0.0.1/8799; printf 'GARBAGE\r\n\r\n' >&3; head -c 200 <&3 >"$out/garbage.txt"
exec 3>&-
curl -s -o /dev/null -w "%{http_code}" "http://127.0.0.1:8799/../../etc/passwd" >"$out/traversal.txt"
curl -s -o /dev/null -w "%{http_code}" -X POST -d x http://127.0.0.1:8799/ >"$out/post.txt"
)";

// The screenshot's pixels (Cairo reads the PNG).
class Screenshot {
 public:
  explicit Screenshot(const std::string& path)
      : surface_(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Screenshot() { cairo_surface_destroy(surface_); }
  bool Ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  int Width() const { return cairo_image_surface_get_width(surface_); }
  int Height() const { return cairo_image_surface_get_height(surface_); }
  // The pixel at canvas pixel (u, v), 0xRRGGBB.
  unsigned At(double u, double v) const {
    const int x = static_cast<int>(u + kPageMargin), y = static_cast<int>(v + kPageMargin);
    if (x < 0 || y < 0 || x >= Width() || y >= Height()) return 0xffffffffu;
    const unsigned char* row =
        cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
    return reinterpret_cast<const uint32_t*>(row)[x] & 0xffffffu;
  }

 private:
  cairo_surface_t* surface_;
};

bool Near(unsigned rgb, unsigned want, int tolerance) {
  for (int shift : {0, 8, 16}) {
    if (std::abs(static_cast<int>((rgb >> shift) & 0xff) - static_cast<int>((want >> shift) & 0xff)) >
        tolerance) {
      return false;
    }
  }
  return true;
}

// What the page says it drew (<script id="drawn">), null when the page has no record.
nlohmann::json Drawn(const std::string& dom) {
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("<script type=\"application/json\" id=\"drawn\">([^<]*)</script>"))) {
    return nullptr;
  }
  return nlohmann::json::parse(m[1].str());
}

nlohmann::json DrawnBall(const nlohmann::json& balls, int number) {
  for (const auto& b : balls) if (b["number"] == number) return b;
  return nullptr;
}

// The rack's balls 0-9 less those the summary says dropped, by number, where the truth has them.
void ExpectTheBallsLeft(const nlohmann::json& drawn, const nlohmann::json& summary) {
  std::set<int> left = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (const auto& shot : summary["game"]["racks"][0]["shots"]) {
    for (int potted : shot["potted"]) left.erase(potted);
  }
  std::set<int> truth, estimate;
  for (const auto& b : drawn["truth"]) truth.insert(b["number"].get<int>());
  for (const auto& b : drawn["estimate"]) {
    estimate.insert(b["number"].get<int>());
    const nlohmann::json t = DrawnBall(drawn["truth"], b["number"]);
    ASSERT_FALSE(t.is_null()) << b;
    // Within 2 px (5 mm) of its truth: the estimator's error is about 1 mm.
    EXPECT_NEAR(b["u"].get<double>(), t["u"].get<double>(), 2.0) << b;
    EXPECT_NEAR(b["v"].get<double>(), t["v"].get<double>(), 2.0) << b;
  }
  EXPECT_EQ(truth, left);
  EXPECT_EQ(estimate, left);
}

void ExpectPocketsStrokeAndPaths(const nlohmann::json& drawn, const std::string& dom,
                                 const nlohmann::json& summary) {
  const auto pool =
      billiard::table::BuildTable(billiard::params::LoadTableSpec(billiard::params::kDefaultTable));
  ASSERT_EQ(drawn["pockets"].size(), pool.pockets.size());
  ASSERT_EQ(pool.pockets.size(), 6u);
  for (std::size_t k = 0; k < pool.pockets.size(); ++k) {
    const Eigen::Vector2d c = 0.5 * (pool.pockets[k].capture_a + pool.pockets[k].capture_b);
    EXPECT_NEAR(drawn["pockets"][k]["u"].get<double>(), kMargin + kScale * c.x(), 1e-6);
    EXPECT_NEAR(drawn["pockets"][k]["v"].get<double>(), kMargin + kScale * (pool.width - c.y()),
                1e-6);
  }
  // The chosen shot moved the cue ball: its path of this shot is drawn.
  const nlohmann::json cue_path = DrawnBall(drawn["paths"], 0);
  ASSERT_FALSE(cue_path.is_null()) << drawn["paths"];
  EXPECT_GT(cue_path["points"].get<int>(), 10);
  // One status line with the called pot's chance, and no JSON on the page.
  std::smatch status;
  ASSERT_TRUE(std::regex_search(dom, status, std::regex("<div id=\"status\">(.*?)</div>")));
  const auto& called = summary["game"]["racks"][0]["shots"][1]["called"];
  EXPECT_NE(status[1].str().find(called["ball"].dump() + " in "), std::string::npos) << status[1];
  EXPECT_NE(status[1].str().find("pot chance"), std::string::npos) << status[1];
  EXPECT_EQ(status[1].str().find('{'), std::string::npos) << status[1];
}

void ExpectClothAndStripes(const nlohmann::json& drawn, const std::string& png) {
  const Screenshot shot(png);
  ASSERT_TRUE(shot.Ok());
  constexpr unsigned kCloth = 0x0b7340, kYellow = 0xffcc00, kWhite = 0xffffff;
  int cloth = 0;
  for (int y = 0; y < shot.Height(); ++y) {
    for (int x = 0; x < shot.Width(); ++x) cloth += shot.At(x - kPageMargin, y - kPageMargin) == kCloth;
  }
  EXPECT_GT(cloth, shot.Width() * shot.Height() / 3);
  // The 9: a yellow band across its middle, white above it; a pool ball's radius is 11.4 px.
  const nlohmann::json nine = DrawnBall(drawn["estimate"], 9);
  ASSERT_FALSE(nine.is_null()) << drawn;
  const double u = nine["u"], v = nine["v"];
  EXPECT_TRUE(Near(shot.At(u + 8, v), kYellow, 24)) << std::hex << shot.At(u + 8, v);
  EXPECT_TRUE(Near(shot.At(u, v - 8), kWhite, 24)) << std::hex << shot.At(u, v - 8);
  // The 2: blue right across.
  const nlohmann::json two = DrawnBall(drawn["estimate"], 2);
  ASSERT_FALSE(two.is_null()) << drawn;
  EXPECT_TRUE(Near(shot.At(two["u"].get<double>(), two["v"].get<double>() - 8), 0x0040bf, 24));
}

void ExpectErrorsForHostileRequests(const std::string& dir) {
  const std::string garbage = Slurp(dir + "/garbage.txt");
  EXPECT_EQ(garbage.rfind("HTTP/1.1 400", 0), 0u) << garbage;
  EXPECT_EQ(Slurp(dir + "/traversal.txt"), "404");
  EXPECT_EQ(Slurp(dir + "/post.txt"), "405");
}

TEST(Viewer, ChromiumDrawsTheNumberedBallsPocketsStrokeAndPaths) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "no chromium";
  if (std::system("unshare -n true 2>/dev/null") != 0) GTEST_SKIP() << "no network namespace";
  const std::string dir = ::testing::TempDir() + "/viewer_test";
  std::ofstream(dir + ".sh") << kScript;
  const auto r = billiard::testing::RunCommand("unshare -n bash " + dir + ".sh " + dir + " " +
                                               std::string(BIN_DIR));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string dom = Slurp(dir + "/dom.html");
  const nlohmann::json drawn = Drawn(dom);
  ASSERT_FALSE(drawn.is_null()) << dom;
  const nlohmann::json summary = nlohmann::json::parse(Slurp(dir + "/summary.json"));
  ExpectTheBallsLeft(drawn, summary);
  ExpectPocketsStrokeAndPaths(drawn, dom, summary);
  ExpectClothAndStripes(drawn, dir + "/viewer.png");
  ExpectErrorsForHostileRequests(dir);
}

// Snooker in its colours: a table state of snooker's classes (the estimator's) drawn by the page
// PageHtml serves, in headless Chromium. Each ball's pixel, beside its middle and at it, is
// nearest to its colour's CSS named colour of the eight a snooker set has (the truth: the names
// the World Snooker rules give the balls), so the colours are told apart, none is the grey of a
// ball not told, and no number is drawn on them.
const char* NearestNamedColour(unsigned rgb) {
  static const std::pair<const char*, unsigned> kNamed[] = {
      {"white", 0xffffff}, {"red", 0xff0000},  {"yellow", 0xffff00}, {"green", 0x008000},
      {"brown", 0xa52a2a}, {"blue", 0x0000ff}, {"pink", 0xffc0cb},   {"black", 0x000000},
      {"grey", 0x9a9a9a}};
  const auto distance = [rgb](unsigned c) {
    double sum = 0;
    for (int shift : {0, 8, 16}) sum += std::pow(double((rgb >> shift) & 0xff) - double((c >> shift) & 0xff), 2);
    return sum;
  };
  const auto* best = std::min_element(std::begin(kNamed), std::end(kNamed), [&](const auto& a, const auto& b) {
    return distance(a.second) < distance(b.second);
  });
  return best->first;
}

TEST(Viewer, ChromiumDrawsSnookerInItsColours) {
  using billiard::ball_state_t;
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "no chromium";
  lcm::LCM lcm("memq://");
  const auto table = billiard::table::BuildTable(billiard::params::LoadTableSpec("snooker-12ft"));
  billiard::viewer::ViewState view(lcm, billiard::params::LoadParameters("snooker"), table);
  // The cue ball, two reds and the six colours, in a row across the table.
  const std::vector<std::pair<int, std::string>> balls = {
      {ball_state_t::CLASS_CUE, "white"},   {ball_state_t::CLASS_RED, "red"},
      {ball_state_t::CLASS_RED, "red"},     {ball_state_t::CLASS_YELLOW, "yellow"},
      {ball_state_t::CLASS_GREEN, "green"}, {ball_state_t::CLASS_BROWN, "brown"},
      {ball_state_t::CLASS_BLUE, "blue"},   {ball_state_t::CLASS_PINK, "pink"},
      {ball_state_t::CLASS_BLACK, "black"}};
  billiard::table_state_t state{};
  state.utime = 1'000'000;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    ball_state_t b{};
    b.utime = state.utime;
    b.ball_id = static_cast<int>(i);
    b.ball_class = static_cast<int8_t>(balls[i].first);
    b.class_confidence = 1.0f;
    b.position[0] = 0.4 + 0.35 * static_cast<double>(i);
    b.position[1] = 0.9;
    state.balls.push_back(b);
  }
  state.num_balls = static_cast<int>(state.balls.size());
  lcm.publish(billiard::messages::kTableStateChannel, &state);
  while (lcm.handleTimeout(0) > 0) {
  }
  const std::string dir = ::testing::TempDir() + "/viewer_snooker";
  ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
  std::ofstream(dir + "/page.html") << billiard::viewer::PageHtml(view.Json());
  const std::string browser = "chromium --headless --no-sandbox --disable-gpu --force-device-scale-factor=1 ";
  const auto r = billiard::testing::RunCommand(
      browser + "--dump-dom file://" + dir + "/page.html > " + dir + "/dom.html 2>/dev/null && " +
      browser + "--hide-scrollbars --window-size=1600,900 --screenshot=" + dir + "/snooker.png file://" +
      dir + "/page.html >/dev/null 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string dom = Slurp(dir + "/dom.html");
  const nlohmann::json drawn = Drawn(dom);
  ASSERT_FALSE(drawn.is_null()) << dom;
  ASSERT_EQ(drawn["estimate"].size(), balls.size()) << drawn;
  const Screenshot shot(dir + "/snooker.png");
  ASSERT_TRUE(shot.Ok());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const nlohmann::json& b = drawn["estimate"][i];
    EXPECT_EQ(b["id"], static_cast<int>(i));
    const double u = b["u"], v = b["v"];  // a snooker ball's radius is 10.5 px
    EXPECT_STREQ(NearestNamedColour(shot.At(u + 6, v)), balls[i].second.c_str()) << i;
    EXPECT_STREQ(NearestNamedColour(shot.At(u, v)), balls[i].second.c_str()) << i << ": a label";
  }
}

}  // namespace
