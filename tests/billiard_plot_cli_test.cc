// `billiard plot` as a user runs it: the PNG and the SVG of a scene put each ball where the
// scene (and `billiard simulate --scene`, for a ball that moves) puts it, in the picture's
// documented frame (plot/table_picture.h: 400 px a metre, a 60 px rail, y up); a plan's
// ball ends on its target; bad input exits 2.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

constexpr double kScale = 400.0, kRail = 60.0;  // the frame the header documents
constexpr double kLength = 2.54, kWidth = 1.27;  // pool-9ft's playing surface

cv::Point2d Pixel(double x, double y) {
  return {kRail + kScale * x, kRail + kScale * (kWidth - y)};
}

struct Ball {
  int id;
  double x, y;
  cv::Vec3b bgr;         // its colour in the PNG
  std::string svg_fill;  // and in the SVG
};

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// Three still balls and the cue ball rolling up the table, clear of them.
std::string Scene() {
  nlohmann::json scene = {{"table", "pool-9ft"}, {"params", "pool"}};
  scene["balls"] = {{{"id", 0}, {"state", {0.3, 0.9, 1.0, 0, 0, 0, 0}}},
                    {{"id", 1}, {"state", {0.5, 0.4, 0, 0, 0, 0, 0}}},
                    {{"id", 2}, {"state", {2.0, 0.3, 0, 0, 0, 0, 0}}},
                    {{"id", 8}, {"state", {1.27, 0.635, 0, 0, 0, 0, 0}}}};
  return Write("plot_scene.json", scene.dump());
}

std::vector<Ball> Expected(const std::string& scene) {
  const std::string args = "simulate --scene " + scene + " --json";
  const nlohmann::json run = OneObject(Billiard(args), args);
  double x0 = 0, y0 = 0;
  for (const auto& b : run["balls"]) {
    if (b["id"] == 0) x0 = b["state"][0], y0 = b["state"][1];
  }
  EXPECT_GT(x0, 0.8);  // it moved
  return {{0, x0, y0, {255, 255, 255}, "100%,100%,100%"},
          {1, 0.5, 0.4, {0, 204, 255}, "100%,80%,0%"},
          {2, 2.0, 0.3, {191, 64, 0}, "0%,25%,75%"},
          {8, 1.27, 0.635, {13, 13, 13}, "5%,5%,5%"}};
}

bool Near(const cv::Vec3b& a, const cv::Vec3b& b) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(a[k] - b[k]) > 12) return false;
  }
  return true;
}

TEST(BilliardPlot, APngPutsEveryBallWhereTheSceneDoes) {
  const std::string scene = Scene();
  const std::string png = ::testing::TempDir() + "/plot_scene.png";
  const CommandResult r = Billiard("plot --scene " + scene + " --out " + png, true);
  ASSERT_EQ(r.status, 0) << r.out;
  const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, static_cast<int>(std::ceil(2 * kRail + kScale * kLength)));
  EXPECT_EQ(image.rows, static_cast<int>(std::ceil(2 * kRail + kScale * kWidth)));
  const double r_px = kScale * 0.028575;
  for (const Ball& b : Expected(scene)) {
    const cv::Point2d c = Pixel(b.x, b.y);
    // Its colour at its centre and a little inside its edge, not a diameter away.
    for (const cv::Point2d d : {cv::Point2d(0, 0), cv::Point2d(0.6 * r_px, 0),
                                cv::Point2d(0, -0.6 * r_px)}) {
      const cv::Point p(std::lround(c.x + d.x), std::lround(c.y + d.y));
      EXPECT_TRUE(Near(image.at<cv::Vec3b>(p), b.bgr))
          << "ball " << b.id << " at " << p << ": " << image.at<cv::Vec3b>(p);
    }
    const cv::Point away(std::lround(c.x), std::lround(c.y + 2.5 * r_px));
    EXPECT_FALSE(Near(image.at<cv::Vec3b>(away), b.bgr)) << "ball " << b.id;
  }
}

// Pool's set as a player knows it: the 9 a white ball with the 1's yellow as a band round its
// middle, the 1 yellow all over; and the key of the paths down the right rail, the cue ball (the
// one that moved) drawn there.
TEST(BilliardPlot, AStripeIsAWhiteBallWithItsSolidsBand) {
  nlohmann::json scene = {{"table", "pool-9ft"}, {"params", "pool"}};
  scene["balls"] = {{{"id", 0}, {"state", {0.3, 0.9, 1.0, 0, 0, 0, 0}}},
                    {{"id", 1}, {"state", {0.5, 0.4, 0, 0, 0, 0, 0}}},
                    {{"id", 9}, {"state", {1.0, 0.4, 0, 0, 0, 0, 0}}}};
  const std::string png = ::testing::TempDir() + "/plot_stripe.png";
  const CommandResult r = Billiard("plot --scene " + Write("plot_stripe.json", scene.dump()) + " --out " + png, true);
  ASSERT_EQ(r.status, 0) << r.out;
  const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const double r_px = kScale * 0.028575;
  const cv::Vec3b yellow{0, 204, 255}, white{255, 255, 255};
  const auto at = [&](double x, double y, double dy) {
    const cv::Point2d c = Pixel(x, y);
    return image.at<cv::Vec3b>(cv::Point(std::lround(c.x), std::lround(c.y + dy * r_px)));
  };
  EXPECT_TRUE(Near(at(1.0, 0.4, 0.0), yellow)) << at(1.0, 0.4, 0.0);
  EXPECT_TRUE(Near(at(1.0, 0.4, 0.75), white)) << at(1.0, 0.4, 0.75);
  EXPECT_TRUE(Near(at(1.0, 0.4, -0.75), white)) << at(1.0, 0.4, -0.75);
  EXPECT_TRUE(Near(at(0.5, 0.4, -0.75), yellow)) << at(0.5, 0.4, -0.75);
  // The key's first row: a ball of 6 px at 8 + 16 + 6 px into the right rail, 50 px below it.
  const cv::Point key(std::lround(image.cols - kRail + 30), std::lround(kRail + 50));
  EXPECT_TRUE(Near(image.at<cv::Vec3b>(key), white)) << image.at<cv::Vec3b>(key);
}

TEST(BilliardPlot, AnSvgPutsEveryBallWhereTheSceneDoes) {
  const std::string scene = Scene();
  const std::string svg = ::testing::TempDir() + "/plot_scene.svg";
  const CommandResult r = Billiard("plot --scene " + scene + " --out " + svg, true);
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(svg);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("<svg"), std::string::npos);
  for (const Ball& b : Expected(scene)) {
    // The filled ball: a path of its fill outlined in black; its centre the middle of the
    // path's bounding box.
    const std::regex path("<path style=\"[^\"]*fill:rgb\\(" +
                          std::regex_replace(b.svg_fill, std::regex("%"), "%") +
                          "\\)[^\"]*stroke:rgb\\(0%,0%,0%\\)[^\"]*\" d=\"([^\"]*)\"");
    bool found = false;
    for (std::sregex_iterator it(text.begin(), text.end(), path), end; it != end; ++it) {
      std::istringstream d(std::regex_replace((*it)[1].str(), std::regex("[A-Za-z]"), " "));
      double u, v, u_min = 1e9, u_max = -1e9, v_min = 1e9, v_max = -1e9;
      while (d >> u >> v) {
        u_min = std::min(u_min, u), u_max = std::max(u_max, u);
        v_min = std::min(v_min, v), v_max = std::max(v_max, v);
      }
      const cv::Point2d c = Pixel(b.x, b.y);
      found = found || (std::abs(0.5 * (u_min + u_max) - c.x) < 0.5 &&
                        std::abs(0.5 * (v_min + v_max) - c.y) < 0.5);
    }
    EXPECT_TRUE(found) << "ball " << b.id << " not drawn at " << Pixel(b.x, b.y);
  }
}

TEST(BilliardPlot, APlansBallEndsOnItsTarget) {
  const std::string args = "plan --from 0.5,0.5 --to 1.5,0.8 --spin draw --side-spin 10 --json";
  const CommandResult planned = Billiard(args);
  ASSERT_EQ(planned.status, 0);
  const std::string plan = Write("plot_plan.json", planned.out);
  const std::string png = ::testing::TempDir() + "/plot_plan.png";
  const CommandResult r = Billiard("plot --plan " + plan + " --out " + png, true);
  ASSERT_EQ(r.status, 0) << r.out;
  const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const cv::Point2d t = Pixel(1.5, 0.8);
  EXPECT_TRUE(Near(image.at<cv::Vec3b>(cv::Point(std::lround(t.x + 3), std::lround(t.y + 3))),
                   {255, 255, 255}));
}

// The cue ball in the open with a stroke on it, and ball 1 `behind` metres behind it on the cue's
// line (heading 200 degrees: the cue lies up and to the right of the ball).
constexpr double kCueX = 1.0, kCueY = 0.5, kHeadingDeg = 200.0;
constexpr double kGantryCue = 0.5;  // sim/params/robots/gantry.json's cue length [m]
std::string CueScene(const std::string& name, double elevation_deg, double behind) {
  const double h = kHeadingDeg * M_PI / 180.0;
  nlohmann::json scene = {{"table", "pool-9ft"}, {"params", "pool"}};
  scene["balls"] = {{{"id", 0},
                     {"state", {kCueX, kCueY, 0, 0, 0, 0, 0}},
                     {"cue", {{"speed", 1.0}, {"heading", h}, {"elevation", elevation_deg * M_PI / 180.0}}}},
                    {{"id", 1},
                     {"state", {kCueX - behind * std::cos(h), kCueY - behind * std::sin(h), 0, 0, 0, 0, 0}}}};
  return Write(name, scene.dump());
}

// The point of the cue's axis `d` metres back from its tip as seen from above: the tip R cos(e)
// behind the ball's centre (a centre stroke), the axis foreshortened to L cos(e).
cv::Point BehindTip(double d, double elevation_deg) {
  constexpr double kR = 0.028575;
  const double h = kHeadingDeg * M_PI / 180.0;
  const double back = kR * std::cos(elevation_deg * M_PI / 180.0) + d;
  const cv::Point2d p = Pixel(kCueX - back * std::cos(h), kCueY - back * std::sin(h));
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}

// The gantry's cue is drawn from the cue ball back along the heading for its length seen from
// above, L cos(e), in its maple colour, and no farther; the label names the elevation and what it
// clears.
TEST(BilliardPlot, TheRobotsCueLiesAlongTheHeadingBackFromTheCueBall) {
  const cv::Vec3b maple(140, 204, 237);  // plot::kCueRgb, as BGR
  for (const double elevation : {0.0, 25.0}) {
    SCOPED_TRACE(elevation);
    const std::string png = ::testing::TempDir() + "/plot_cue.png";
    const CommandResult r =
        Billiard("plot --scene " + CueScene("plot_cue.json", elevation, 0.9) + " --out " + png, true);
    ASSERT_EQ(r.status, 0) << r.out;
    const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
    ASSERT_FALSE(image.empty());
    const double drawn = kGantryCue * std::cos(elevation * M_PI / 180.0);  // 0.453 m at 25 deg
    int on_cue = 0, samples = 0;
    for (double d = 0.02; d < drawn - 0.02; d += 0.01, ++samples) {
      on_cue += Near(image.at<cv::Vec3b>(BehindTip(d, elevation)), maple);
    }
    EXPECT_GE(on_cue, samples - 2) << "the outline runs from the tip back " << drawn << " m";
    for (const double past : {0.02, 0.04}) {
      EXPECT_FALSE(Near(image.at<cv::Vec3b>(BehindTip(drawn + past, elevation)), maple)) << "past the butt";
    }
    EXPECT_FALSE(Near(image.at<cv::Vec3b>(BehindTip(-0.1, elevation)), maple)) << "in front of the ball";
    const std::string label = elevation == 0.0 ? "cue level, clears " : "cue at 25.00 deg, clears ";
    EXPECT_NE(r.out.find(label), std::string::npos) << r.out;
  }
}

// Ball 1 on the cue's line 20 cm behind the cue ball: a level cue meets it; raised 15 degrees
// (above the 10.1 its tapered side needs, sim/cue/clearance_test.cc's tangent), it clears
// it; the label says which.
TEST(BilliardPlot, TheLabelSaysWhetherTheCueClearsABallBehind) {
  const std::string png = ::testing::TempDir() + "/plot_cue_ball.png";
  const CommandResult level = Billiard("plot --scene " + CueScene("plot_cue_level.json", 0.0, 0.2) + " --out " + png, true);
  EXPECT_NE(level.out.find("cue level, meets ball 1"), std::string::npos) << level.out;
  const CommandResult raised = Billiard("plot --scene " + CueScene("plot_cue_up.json", 15.0, 0.2) + " --out " + png, true);
  EXPECT_NE(raised.out.find("cue at 15.00 deg, clears ball 1 by"), std::string::npos) << raised.out;
  const CommandResult plain =
      Billiard("plot --scene " + CueScene("plot_cue_up.json", 15.0, 0.2) + " --robot none --out " + png, true);
  EXPECT_EQ(plain.out.find("cue at"), std::string::npos) << plain.out;
}

TEST(BilliardPlot, BadInputExitsTwoWithOneLine) {
  const std::string scene = Scene();
  const CommandResult jpg = Billiard("plot --scene " + scene + " --out x.jpg", true);
  const CommandResult none = Billiard("plot --out x.png", true);
  const CommandResult dir = Billiard("plot --scene " + scene + " --out /no/dir/x.png", true);
  const std::string refused =
      Write("plot_refused.json", Billiard("plan --from 0.5,0.5 --to 5,0.5 --json").out);
  const CommandResult plan = Billiard("plot --plan " + refused + " --out x.png", true);
  for (const CommandResult& r : {jpg, none, dir, plan}) {
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
  EXPECT_NE(plan.out.find("refused"), std::string::npos) << plan.out;
  // A refusal leaves no picture behind, not even an empty file.
  const std::string none_made = ::testing::TempDir() + "/plot_not_made.png";
  EXPECT_EQ(Billiard("plot --plan " + refused + " --out " + none_made).status, 2);
  EXPECT_FALSE(std::ifstream(none_made).good());
}

}  // namespace
}  // namespace billiard::testing
