// `billiard detect` and `billiard calibrate` as a user runs them on the real photograph: one JSON
// object on stdout, every ball once; a missing, unreadable or damaged image is a usage error
// (exit 2, one line); a calibration that does not fit is refused (exit 3), and one that does not
// agree with the frame is said so on stderr.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "estimator/testing/real_table_photo.h"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/testing/damaged_jpeg.h"
#include "tests/support/billiard_command.h"
#include "tests/support/test_data.h"

namespace {

using billiard::estimator::testing::HandBall;
using billiard::estimator::testing::kRealTablePhoto;
using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::OneObject;

// A temporary directory, removed with what it holds.
class ScratchDir {
 public:
  ScratchDir() {
    char name[] = "/tmp/billiard_detect_XXXXXX";
    if (mkdtemp(name) != nullptr) path_ = name;
    EXPECT_FALSE(path_.empty()) << "mkdtemp failed";
  }
  ~ScratchDir() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// The lines of a command's output (stdout with stderr merged): the JSON objects, and the others
// (the tool's notes and errors, on stderr).
struct OutputLines {
  std::vector<std::string> json, notes;
};

OutputLines SplitLines(const std::string& out) {
  OutputLines lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    (line.rfind('{', 0) == 0 ? lines.json : lines.notes).push_back(line);
  }
  return lines;
}

// The figures in pixels a line names ("... 10.0 px ..." gives 10).
std::vector<double> PixelFigures(const std::string& line) {
  static const std::regex kFigure("([0-9]+(\\.[0-9]+)?) px");
  std::vector<double> figures;
  for (auto m = std::sregex_iterator(line.begin(), line.end(), kFigure);
       m != std::sregex_iterator(); ++m) {
    figures.push_back(std::stod((*m)[1]));
  }
  return figures;
}

// `bytes` written to the file `path`; returns the path.
std::string WriteFile(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  return path;
}

// The notes that contain `word`.
std::vector<std::string> NotesWith(const OutputLines& lines, const std::string& word) {
  std::vector<std::string> found;
  for (const std::string& note : lines.notes) {
    if (note.find(word) != std::string::npos) found.push_back(note);
  }
  return found;
}

// The photo's geometry read off by hand: a pool ball (radius 28.575 mm) is 15 px in radius, so
// 1.905 mm per pixel; the cloth's bottom-left corner is at pixel (80, 665).
constexpr double kMetresPerPixel = 0.028575 / 15.0;

// The markers' centres in the photo [px], read off by hand, in image order (top-left, top-right,
// bottom-right, bottom-left).
constexpr std::array<std::array<double, 2>, 4> kMarkerPixels = {
    {{144, 37}, {1177, 34}, {1172, 683}, {149, 681}}};

// The markers' table coordinates (--markers) as that geometry puts them, times `scale`, listed in
// `order`. At scale 1 in image order they fit the photo and its ball size; at another scale they
// fit as well (from a camera further away or closer), but the balls the calibration expects are
// `scale` times too small.
std::string HandReadMarkers(double scale = 1.0, std::array<int, 4> order = {0, 1, 2, 3}) {
  std::string list;
  for (const int i : order) {
    const auto [u, v] = kMarkerPixels[i];
    list += (list.empty() ? "" : ",") + std::to_string(scale * (u - 80) * kMetresPerPixel) + "," +
            std::to_string(scale * (665 - v) * kMetresPerPixel);
  }
  return list;
}

// Each hand-listed ball exactly once within 4 px, and nothing else.
void ExpectEveryBallOnce(const nlohmann::json& balls) {
  ASSERT_EQ(balls.size(), 21u) << balls;
  std::vector<int> used(balls.size(), 0);
  for (const HandBall& hand : billiard::estimator::testing::RealTablePhotoBalls()) {
    int times = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const double du = balls[i]["u"].get<double>() - hand.pixel.x();
      const double dv = balls[i]["v"].get<double>() - hand.pixel.y();
      if (std::hypot(du, dv) < 4.0) {
        ++times;
        ++used[i];
      }
    }
    EXPECT_EQ(times, 1) << hand.name << " at " << hand.pixel.transpose();
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), 21);
}

// The commands on the real photograph, skipped with the reason where the test data is absent.
class BilliardDetect : public ::testing::Test {
 protected:
  void SetUp() override {
    photo_ = billiard::testing::TestDataPath(kRealTablePhoto);
    if (photo_.empty()) GTEST_SKIP() << billiard::testing::MissingTestData(kRealTablePhoto);
  }
  const std::string& photo() const { return photo_; }

 private:
  std::string photo_;
};

TEST_F(BilliardDetect, FindsTheTwentyOneBallsOfTheRealPhotograph) {
  for (const std::string options : {"", " --ball-radius-px 15"}) {
    const std::string args = "detect " + photo() + options + " --json";
    const CommandResult r = Billiard(args);
    ASSERT_EQ(r.status, 0) << args;
    const auto j = OneObject(r, args);
    ExpectEveryBallOnce(j["balls"]);
    for (const auto& ball : j["balls"]) {
      for (const char* key : {"u", "v", "radius_px", "score"})
        EXPECT_TRUE(ball.contains(key)) << ball;
      EXPECT_FALSE(ball.contains("x")) << "table coordinates need --calib";
      EXPECT_GE(ball["score"].get<double>(), 0.5);
      EXPECT_LE(ball["score"].get<double>(), 1.0);
      EXPECT_NEAR(ball["radius_px"].get<double>(), 15.0, 2.5);
    }
  }
}

// Which ball each is: the photograph's hand-read colours (snooker), and its table.
TEST_F(BilliardDetect, SaysWhichBallEachIsAndWhereTheTableIs) {
  const std::string args = "detect " + photo() + " --ball-set snooker --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args;
  const auto j = OneObject(r, args);
  std::map<std::string, int> classes;
  for (const auto& ball : j["balls"]) {
    ASSERT_TRUE(ball.contains("class")) << ball;
    const double confidence = ball["class_confidence"].get<double>();
    EXPECT_GE(confidence, 0.0);
    EXPECT_LE(confidence, 1.0);
    // Each hand-read ball's name is its class.
    for (const HandBall& hand : billiard::estimator::testing::RealTablePhotoBalls()) {
      if (std::hypot(ball["u"].get<double>() - hand.pixel.x(),
                     ball["v"].get<double>() - hand.pixel.y()) > 4.0) {
        continue;
      }
      EXPECT_EQ(ball["class"], hand.name) << ball;
    }
    ++classes[ball["class"]];
  }
  EXPECT_EQ(classes["red"], 15);
  EXPECT_EQ(classes["cue"], 1);
  // The table: an overhead view, the playing surface inside the cloth's outline.
  const auto& table = j["table"];
  EXPECT_EQ(table["view"], "overhead");
  ASSERT_EQ(table["corners"].size(), 4u);
  ASSERT_EQ(table["cloth_corners"].size(), 4u);
  EXPECT_LT(table["side_fit_rms_px"].get<double>(), 2.0);
  EXPECT_LT(table["depth_ratio"].get<double>(), 1.2);
  // A frame without a table is refused, with the reason, in one line.
  cv::Mat noise(300, 400, CV_8UC3);
  cv::RNG(3).fill(noise, cv::RNG::UNIFORM, 0, 256);
  const std::string path = ::testing::TempDir() + "/no_table.png";
  ASSERT_TRUE(cv::imwrite(path, noise));
  const CommandResult none = Billiard("detect " + path + " --json", true);
  EXPECT_EQ(none.status, 3) << none.out;
  EXPECT_EQ(std::count(none.out.begin(), none.out.end(), '\n'), 1) << none.out;
  EXPECT_NE(none.out.find("no table"), std::string::npos) << none.out;
  EXPECT_EQ(none.out.find('{'), std::string::npos) << none.out;
}

// The real frames of the test data's dev set through `billiard bench-detect`: the report and
// the results, and bounds on them. The detector was developed on the first 15 frames (98 %
// recall and 97 % precision overhead, 90 % and 95 % oblique); the 11 frames added for issue 27
// (clutter, arms, projected lines) brought precision to 91 % overhead and 94.8 % oblique, and
// identity (on the frames with classes) to 63 %. Issue 27's first steps (balls on sleeves and
// hands dropped, identity given all at once with the rack's count of each class) raised them to
// 95.0 % overhead precision and 82 % identity, and the near cushion's nose found from its faint
// line brought the tables found within 2 px per side of the corner labels
// (estimator/testing/real_table_corners.json) from 15 to 18 of 26. A side's outline taken as its
// straight stretches found dap_snooker2's ball beyond its left side, and an unsure outline in a
// pocket's mouth dropped brought precision to 96.1 % overhead and 97.7 % oblique. Identity at
// 91.5 % (86 of 94): a stripe by its plain share (its white at any shade), the rack's numbers to
// the sure balls first, a TV set's pink 4 and a brown 7, the white balance off clipped pixels.
// Unsure outlines on what reaches over a rail (an arm and its dark glove, not_cloth.h) dropped
// brought overhead precision to 98.9 %, and a sure one surrounded by it (a logo on grr_03's cap)
// to 99.4 %; identity fell to 90.4 % (85 of 94) with it: the logo had taken the 10, which went to
// grr_03's blue solid instead of its blue stripe, whose caps its disc does not show as plain.
// Trying scales 10 and 20 % larger than the measured one (ball_detector.cc) found ph_taiwan's
// far cue ball and put mech_webcam0's outlines on its balls: oblique precision 99.2 %, identity
// 92.6 % (87 of 94).
TEST(BilliardBenchDetect, TheDevSetOfRealFramesWithinTheBounds) {
  BILLIARD_TEST_DATA_OR_SKIP(labels, "real-tables/dev/labels.json");
  const std::string set = labels.substr(0, labels.rfind('/'));
  const ScratchDir out;
  const std::string args = "bench-detect --set " + set + " --corners " + TABLE_CORNERS_JSON +
                           " --out " + (out / "report");
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args;
  const auto j = OneObject(r, args);
  const auto& views = j["views"];
  EXPECT_GE(views["overhead"]["recall"].get<double>(), 0.98) << views;
  EXPECT_GE(views["overhead"]["precision"].get<double>(), 0.99) << views;
  EXPECT_GE(views["oblique"]["recall"].get<double>(), 0.945) << views;
  EXPECT_GE(views["oblique"]["precision"].get<double>(), 0.99) << views;
  EXPECT_LT(views["all"]["median_centre_error_px"].get<double>(), 1.5) << views;
  EXPECT_EQ(views["all"]["frames"], 26);
  EXPECT_EQ(views["all"]["tables_labelled"], 26);
  EXPECT_GE(views["all"]["tables_within_2px"].get<int>(), 18) << views;
  EXPECT_GE(views["all"]["classed"].get<int>(), 90) << views;
  EXPECT_GE(views["all"]["identity"].get<double>(), 0.92) << views;
  // Every miss and every false detection has its cause.
  nlohmann::json results;
  std::ifstream(out / "report/detection_results.json") >> results;
  for (const auto& frame : results["frames"]) {
    EXPECT_EQ(frame["missed_causes"].size(), frame["missed"].size()) << frame["file"];
    EXPECT_EQ(frame["false_causes"].size(), frame["false"].get<std::size_t>()) << frame["file"];
    EXPECT_GE(frame["table_side_error_px"].get<double>(), 0.0) << frame["file"];
  }
  for (const char* file : {"detection_report.md", "detection_results.json",
                           "overlays/lk_halo_01.jpg"}) {
    EXPECT_TRUE(std::filesystem::exists(out / ("report/" + std::string(file)))) << file;
  }
  // Neither a set nor the synthetic suite, or both: a usage error.
  EXPECT_EQ(Billiard("bench-detect --out " + (out / "x"), true).status, 2);
  EXPECT_EQ(Billiard("bench-detect --set /nonexistent --out " + (out / "x"), true).status, 2);
  // The hard suite renders its own frames: with a set, a usage error.
  EXPECT_EQ(Billiard("bench-detect --hard-suite --set " + set + " --out " + (out / "x"), true).status,
            2);
  // --case picks cases of the hard suite, by the start of their names: one no case has, or without
  // the hard suite, a usage error.
  EXPECT_EQ(Billiard("bench-detect --hard-suite --case nothing --out " + (out / "x"), true).status,
            2);
  EXPECT_EQ(Billiard("bench-detect --set " + set + " --case lens --out " + (out / "x"), true).status,
            2);
  EXPECT_EQ(Billiard("bench-detect --set " + set + " --corners /nonexistent --out " + (out / "x"),
                     true)
                .status,
            2);
}

// A drawn carom table (a green cloth twice as long as wide in a wooden rail, three balls) as a
// labelled set's frame `name` from repository `source`: its entry of labels.json.
nlohmann::json DrawnCaromFrame(const std::string& dir, const std::string& name,
                               const std::string& source, int shift) {
  cv::Mat frame(400, 640, CV_8UC3, cv::Scalar(60, 60, 60));
  cv::rectangle(frame, {50, 50}, {590, 350}, cv::Scalar(30, 60, 95), cv::FILLED);
  cv::rectangle(frame, {80, 80}, {560, 320}, cv::Scalar(40, 130, 30), cv::FILLED);
  const std::vector<std::pair<cv::Point, cv::Scalar>> balls = {
      {{200 + shift, 150}, {235, 240, 240}},
      {{320, 220 + shift}, {30, 30, 200}},
      {{450 - shift, 180}, {20, 200, 240}}};
  nlohmann::json centres = nlohmann::json::array();
  for (const auto& [centre, colour] : balls) {
    cv::circle(frame, centre, 8, colour, cv::FILLED, cv::LINE_AA);
    centres.push_back({centre.x, centre.y});
  }
  EXPECT_TRUE(cv::imwrite(dir + "/" + name, frame));
  return {{"balls", centres}, {"ball_radius_px", 8}, {"source", source + " " + name + "@1"},
          {"kind", "carom"},  {"view", "overhead"},  {"classes", {"white", "red", "yellow"}}};
}

// `billiard bench-detect --cross-validate` on two sets of drawn frames from two repositories: a
// fold per repository, the report written, one JSON object on stdout. Its usage errors are one
// line each, exit 2: no set, the synthetic suite or corners asked for too, several sets without
// it, a single source (nothing to fit on when it is left out).
TEST(BilliardBenchDetect, CrossValidatesOneRepositoryAtATime) {
  const ScratchDir dir;
  for (const char* set : {"first", "second"}) {
    std::filesystem::create_directories(dir / set);
  }
  const nlohmann::json first = {{"a.png", DrawnCaromFrame(dir / "first", "a.png", "one/repo", 0)},
                                {"b.png", DrawnCaromFrame(dir / "first", "b.png", "two/repo", 9)}};
  const nlohmann::json second = {
      {"c.png", DrawnCaromFrame(dir / "second", "c.png", "two/repo", 20)}};
  std::ofstream(dir / "first/labels.json") << first.dump();
  std::ofstream(dir / "second/labels.json") << second.dump();
  const std::string sets = " --set " + (dir / "first") + " --set " + (dir / "second");
  const std::string args = "bench-detect --cross-validate" + sets + " --out " + (dir / "out");
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args;
  const auto j = OneObject(r, args);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["sources"], 2);
  EXPECT_EQ(j["folds"][0]["held_out"], "one/repo");
  EXPECT_EQ(j["folds"][1]["frames"], 2);
  EXPECT_EQ(j["pooled"]["set_by_hand"]["all"]["labels"], 9);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/cross_validation_report.md"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/cross_validation_results.json"));
  const std::string out = " --out " + (dir / "x");
  for (const std::string& wrong :
       {"bench-detect --cross-validate" + out,
        "bench-detect --cross-validate --synthetic" + sets + out,
        "bench-detect --cross-validate --corners c.json" + sets + out, "bench-detect" + sets + out,
        "bench-detect --cross-validate --set " + (dir / "second") + out}) {
    const CommandResult usage = Billiard(wrong, true);
    EXPECT_EQ(usage.status, 2) << wrong << ": " << usage.out;
    EXPECT_EQ(std::count(usage.out.begin(), usage.out.end(), '\n'), 1)
        << wrong << ": " << usage.out;
  }
  EXPECT_NE(Billiard("bench-detect --cross-validate --set " + (dir / "second") + out, true)
                .out.find("1 source"),
            std::string::npos);
}

TEST_F(BilliardDetect, DrawsTheDetectionsOnAnOverlay) {
  const std::string overlay = ::testing::TempDir() + "/detect_overlay.png";
  std::remove(overlay.c_str());
  const std::string args = "detect " + photo() + " --overlay " + overlay + " --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args;
  const auto j = OneObject(r, args);
  const cv::Mat frame = cv::imread(photo()), drawn = cv::imread(overlay);
  ASSERT_FALSE(drawn.empty()) << "no overlay written";
  ASSERT_EQ(drawn.size(), frame.size());
  // Each ball's outline is drawn: the frame differs on the circle of every detection.
  for (const auto& ball : j["balls"]) {
    const int u =
        static_cast<int>(std::lround(ball["u"].get<double>() - ball["radius_px"].get<double>()));
    const int v = static_cast<int>(std::lround(ball["v"].get<double>()));
    EXPECT_NE(drawn.at<cv::Vec3b>(v, u), frame.at<cv::Vec3b>(v, u)) << ball;
  }
  const CommandResult bad = Billiard("detect " + photo() + " --overlay /nonexistent/o.png", true);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--overlay"), std::string::npos) << bad.out;
}

TEST_F(BilliardDetect, TableCoordinatesFromACalibration) {
  const ScratchDir dir;
  const std::string camera = dir / "camera.json";
  const std::string& photo = this->photo();
  const std::string calibrate = "calibrate " + photo +
                                " --params pool --markers=" + HandReadMarkers() + " --out " +
                                camera + " --json";
  const CommandResult c = Billiard(calibrate);
  ASSERT_EQ(c.status, 0) << calibrate;
  EXPECT_LT(OneObject(c, calibrate)["rms_reprojection_px"].get<double>(), 3.0);

  const std::string detect = "detect " + photo + " --calib " + camera + " --params pool --json";
  const CommandResult r = Billiard(detect, true);
  ASSERT_EQ(r.status, 0) << detect;
  // The calibration agrees with the frame: nothing to say on stderr.
  const auto j = OneObject(r, detect);
  ExpectEveryBallOnce(j["balls"]);
  for (const auto& ball : j["balls"]) {
    ASSERT_TRUE(ball.contains("x") && ball.contains("y")) << ball;
    // Where the hand-read scale puts it, within a centimetre (the markers' pose is only as good
    // as that scale and the guessed focal length).
    const double x = (ball["u"].get<double>() - 80) * kMetresPerPixel;
    const double y = (665 - ball["v"].get<double>()) * kMetresPerPixel;
    EXPECT_NEAR(ball["x"].get<double>(), x, 0.01) << ball;
    EXPECT_NEAR(ball["y"].get<double>(), y, 0.01) << ball;
  }
}

TEST_F(BilliardDetect, ACalibrationThatDoesNotFitIsRefused) {
  const ScratchDir dir;
  const std::string camera = dir / "camera.json";
  // The default layout (markers 0.1 m outside the corners of the paper's table) is not this
  // snooker table's, and the hand-read one with its top markers swapped is a mirror image no
  // camera sees.
  const std::string swapped = HandReadMarkers(1.0, {1, 0, 2, 3});
  for (const std::string& layout : {std::string(), " --markers=" + swapped}) {
    const std::string args = "calibrate " + photo() + layout + " --out " + camera + " --json";
    const CommandResult r = Billiard(args, true);
    EXPECT_EQ(r.status, 3) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
    EXPECT_EQ(r.out.find('{'), std::string::npos) << args << ": " << r.out;
    EXPECT_NE(r.out.find("reprojection"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" px"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(camera)) << args;
  }
  // The refusal says where the markers were found, and where they lie on the table the frame
  // shows: a layout that fits.
  const std::string snooker = "calibrate " + photo() + " --params snooker --out " + camera;
  const CommandResult refused = Billiard(snooker, true);
  ASSERT_EQ(refused.status, 3) << refused.out;
  EXPECT_NE(refused.out.find("47.1 px"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("markers found at"), std::string::npos) << refused.out;
  for (const auto& [u, v] : kMarkerPixels) {
    // Each marker's centre, to the pixel, as the hand read it within 2 px.
    bool named = false;
    for (int du = -2; du <= 2; ++du) {
      for (int dv = -2; dv <= 2; ++dv) {
        named = named || refused.out.find("(" + std::to_string(static_cast<int>(u) + du) + ", " +
                                          std::to_string(static_cast<int>(v) + dv) + ")") !=
                             std::string::npos;
      }
    }
    EXPECT_TRUE(named) << u << ", " << v << ": " << refused.out;
  }
  const std::size_t at = refused.out.find("--markers=");
  ASSERT_NE(at, std::string::npos) << refused.out;
  const std::string suggested = refused.out.substr(at, refused.out.find(';', at) - at);
  const CommandResult fits = Billiard(snooker + " " + suggested + " --json");
  ASSERT_EQ(fits.status, 0) << suggested;
  EXPECT_LT(OneObject(fits, suggested)["rms_reprojection_px"].get<double>(), 3.0);
  std::filesystem::remove(camera);
  // The default layout misses the photo's markers by 41.5 px (RMS), which the threshold names.
  const std::string args = "calibrate " + photo() + " --out " + camera;
  EXPECT_NE(Billiard(args, true).out.find("41.5 px"), std::string::npos);
  const CommandResult r = Billiard(args + " --max-reprojection-px 50 --json");
  EXPECT_EQ(r.status, 0);
  EXPECT_NEAR(OneObject(r, args)["rms_reprojection_px"].get<double>(), 41.5, 0.1);
  EXPECT_TRUE(std::filesystem::exists(camera));
}

TEST_F(BilliardDetect, DetectSaysWhenTheCalibrationDisagreesWithTheFrame) {
  const ScratchDir dir;
  // Markers 1.5 times too far apart fit as well, from a camera 1.5 times as high: the balls it
  // expects are 10 px in radius, the photo's 15-16 px.
  const std::string far = dir / "far.json";
  const std::string calibrate = "calibrate " + photo() +
                                " --params pool --markers=" + HandReadMarkers(1.5) + " --out " +
                                far + " --json";
  const CommandResult c = Billiard(calibrate);
  ASSERT_EQ(c.status, 0) << calibrate;
  EXPECT_LT(OneObject(c, calibrate)["rms_reprojection_px"].get<double>(), 3.0);

  const std::string detect = "detect " + photo() + " --calib " + far + " --params pool --json";
  const CommandResult r = Billiard(detect, true);
  EXPECT_EQ(r.status, 0) << r.out;
  const OutputLines lines = SplitLines(r.out);
  ASSERT_EQ(lines.json.size(), 1u) << r.out;
  const std::vector<std::string> radius = NotesWith(lines, "ball radius");
  ASSERT_EQ(radius.size(), 1u) << r.out;
  const std::vector<double> figures = PixelFigures(radius[0]);
  ASSERT_EQ(figures.size(), 2u) << radius[0];
  EXPECT_NEAR(figures[0], 10.0, 0.5) << "expected: " << radius[0];
  EXPECT_NEAR(figures[1], 15.9, 0.5) << "measured: " << radius[0];
  const auto balls = nlohmann::json::parse(lines.json[0])["balls"];
  EXPECT_EQ(NotesWith(lines, "no balls").size(), balls.empty() ? 1u : 0u) << r.out;

  // A calibration of another camera: its image size is not the frame's.
  nlohmann::json other;
  std::ifstream(far) >> other;
  other["width"] = 1920;
  other["height"] = 1080;
  const std::string wide = dir / "wide.json";
  std::ofstream(wide) << other.dump();
  const std::string args = "detect " + photo() + " --calib " + wide + " --json";
  const CommandResult w = Billiard(args, true);
  EXPECT_EQ(w.status, 2) << w.out;
  EXPECT_EQ(std::count(w.out.begin(), w.out.end(), '\n'), 1) << w.out;
  EXPECT_EQ(w.out.find('{'), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("1920x1080"), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("1280x720"), std::string::npos) << w.out;
}

TEST_F(BilliardDetect, BadInputExitsTwoWithAOneLineReason) {
  const ScratchDir dir;
  const std::string empty = dir / "empty.png", text = dir / "text.png";
  std::ofstream(empty).close();
  std::ofstream(text) << "not an image\n";
  const std::string& photo = this->photo();
  const std::string bad[] = {
      "detect /no/such/image.png --json",
      "detect " + empty + " --json",
      "detect " + text + " --json",
      "detect --json",
      "detect " + photo + " --ball-radius-px nan --json",
      "detect " + photo + " --ball-radius-px=-3 --json",
      "detect " + photo + " --calib /no/such/camera.json --json",
      "detect " + photo + " --calib " + text + " --json",
      "calibrate " + empty + " --out " + (dir / "camera.json") + " --json",
      "calibrate " + photo + " --out " + (dir / "camera.json") + " --max-reprojection-px nan",
      "calibrate " + photo + " --out " + (dir / "camera.json") + " --max-reprojection-px=-1",
  };
  for (const std::string& args : bad) {
    const CommandResult r = Billiard(args, true);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(r.out.find('{'), std::string::npos) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
}

TEST_F(BilliardDetect, HumanSummaryGoesToStderr) {
  const CommandResult r = Billiard("detect " + photo());
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// Damaged JPEG files, made here (no test data needed): each refused in one line, where libjpeg
// alone would hand back a damaged image for the detector to find phantom balls in.
TEST(BilliardDetectJpeg, ACorruptOrTruncatedJpegIsRefused) {
  namespace damage = billiard::messages::testing;
  // Cloth with three balls on it.
  cv::Mat frame(360, 640, CV_8UC3, cv::Scalar(40, 140, 30));
  for (const auto& [x, y] : {std::pair{150, 100}, {320, 200}, {500, 260}}) {
    cv::circle(frame, {x, y}, 12, cv::Scalar(230, 230, 230), cv::FILLED, cv::LINE_AA);
  }
  const damage::JpegBytes jpeg =
      billiard::messages::EncodeImage(frame, 0, billiard::messages::ImageEncoding::kMjpeg).data;
  const ScratchDir dir;
  const std::string good = "detect " + WriteFile(dir / "good.jpg", jpeg) + " --json";
  const CommandResult r = Billiard(good);
  EXPECT_EQ(r.status, 0) << good;
  EXPECT_EQ(OneObject(r, good)["balls"].size(), 3u);

  const std::pair<std::string, damage::JpegBytes> damaged[] = {
      {"corrupt.jpg", damage::WithStrayMarker(jpeg, 0.5)},
      {"closed.jpg", damage::CutAndClosed(jpeg, 0.5)},
      {"junk.jpg", damage::WithJunkBeforeTheEnd(jpeg)},
      {"truncated.jpg", damage::Truncated(jpeg, jpeg.size() / 2)},
      {"cut_in_header.jpg", damage::Truncated(jpeg, 100)},
  };
  for (const auto& [name, bytes] : damaged) {
    const std::string args = "detect " + WriteFile(dir / name, bytes) + " --json";
    const CommandResult d = Billiard(args, true);
    EXPECT_EQ(d.status, 2) << args << ": " << d.out;
    EXPECT_EQ(d.out.find('{'), std::string::npos) << args << ": " << d.out;
    EXPECT_EQ(std::count(d.out.begin(), d.out.end(), '\n'), 1) << args << ": " << d.out;
    EXPECT_NE(d.out.find(name), std::string::npos) << d.out;
  }
}

// An empty table is an answer, but not a silent one.
TEST(BilliardDetectJpeg, NoBallsFoundIsSaid) {
  const cv::Mat cloth(360, 640, CV_8UC3, cv::Scalar(40, 140, 30));
  const auto jpeg =
      billiard::messages::EncodeImage(cloth, 0, billiard::messages::ImageEncoding::kMjpeg).data;
  const ScratchDir dir;
  const CommandResult r =
      Billiard("detect " + WriteFile(dir / "cloth.jpg", jpeg) + " --json", true);
  EXPECT_EQ(r.status, 0) << r.out;
  const OutputLines lines = SplitLines(r.out);
  ASSERT_EQ(lines.json.size(), 1u) << r.out;
  EXPECT_TRUE(nlohmann::json::parse(lines.json[0])["balls"].empty());
  EXPECT_EQ(NotesWith(lines, "no balls").size(), 1u) << r.out;
}

}  // namespace
