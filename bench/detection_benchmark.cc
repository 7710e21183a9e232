#include "bench/detection_benchmark.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <tuple>

#include "bench/format.h"
#include "bench/one_thread.h"
#include "estimator/detection_overlay.h"

namespace billiard::bench {

namespace {

// A detection matches within max(kMinMatchPx, kMatchRadii R) of its label.
constexpr double kMinMatchPx = 8.0, kMatchRadii = 0.6;
// A next frame's time is the median of this many.
constexpr int kNextFrameRepeats = 3;
// ExplainMisses' neighbourhoods, in ball radii.
constexpr double kCushionRadii = 1.5, kClusterRadii = 2.5, kDuplicateRadii = 2.0;

template <class Run>
double MillisecondsOf(const Run& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

std::vector<Eigen::Vector2d> Points(const nlohmann::json& entry, const char* key,
                                    const std::string& where) {
  std::vector<Eigen::Vector2d> points;
  if (!entry.contains(key)) return points;
  const auto& list = entry.at(key);
  if (!list.is_array()) throw std::invalid_argument(where + ": '" + key + "' is not a list");
  for (const auto& p : list) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      throw std::invalid_argument(where + ": '" + key + "' holds an entry that is not [u, v]");
    }
    points.emplace_back(p[0].get<double>(), p[1].get<double>());
  }
  return points;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

std::string Stem(const std::string& file) { return std::filesystem::path(file).stem().string(); }

// The JSON object in a file; throws std::invalid_argument naming the file when it is not one.
nlohmann::json ReadJsonObject(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read '" + path + "'");
  nlohmann::json object;
  try {
    in >> object;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("'" + path + "' is not JSON: " + e.what());
  }
  if (!object.is_object()) throw std::invalid_argument("'" + path + "' is not a JSON object");
  return object;
}

}  // namespace

std::vector<LabelledFrame> LoadLabelledSet(const std::string& directory) {
  const std::string path = directory + "/labels.json";
  const nlohmann::json labels = ReadJsonObject(path);
  std::vector<LabelledFrame> frames;
  for (const auto& [file, entry] : labels.items()) {
    if (!file.empty() && file[0] == '_') continue;  // notes
    const std::string where = path + ": '" + file + "'";
    if (!entry.is_object()) throw std::invalid_argument(where + " is not an object");
    LabelledFrame frame;
    frame.file = file;
    frame.balls = Points(entry, "balls", where);
    for (const char* key : {"in_pocket", "ignore"}) {
      const auto more = Points(entry, key, where);
      frame.ignored.insert(frame.ignored.end(), more.begin(), more.end());
    }
    if (!entry.contains("ball_radius_px") || !entry.at("ball_radius_px").is_number() ||
        !(entry.at("ball_radius_px").get<double>() > 0)) {
      throw std::invalid_argument(where + ": 'ball_radius_px' is not a positive number");
    }
    frame.radius_px = entry.at("ball_radius_px").get<double>();
    if (entry.contains("view")) {
      frame.view = entry.at("view").is_string() ? entry.at("view").get<std::string>() : "";
      if (frame.view != "overhead" && frame.view != "oblique") {
        throw std::invalid_argument(where + ": 'view' is neither \"overhead\" nor \"oblique\"");
      }
    }
    if (entry.contains("source") && entry.at("source").is_string()) {
      frame.source = entry.at("source").get<std::string>();
    }
    if (entry.contains("kind")) {
      frame.kind = entry.at("kind").is_string() ? entry.at("kind").get<std::string>() : "";
      if (frame.kind != "pool" && frame.kind != "snooker" && frame.kind != "carom") {
        throw std::invalid_argument(where + ": 'kind' is none of \"pool\", \"snooker\", \"carom\"");
      }
    }
    if (entry.contains("classes")) {
      const auto& classes = entry.at("classes");
      if (!classes.is_array() || classes.size() != frame.balls.size()) {
        throw std::invalid_argument(where + ": 'classes' is not a list as long as 'balls'");
      }
      for (const auto& c : classes) {
        if (!c.is_null() && !c.is_string()) {
          throw std::invalid_argument(where + ": 'classes' holds an entry that is not a name");
        }
        frame.classes.push_back(c.is_string() ? c.get<std::string>() : "");
      }
    }
    frames.push_back(frame);
  }
  if (frames.empty()) throw std::invalid_argument("'" + path + "' labels no frame");
  return frames;
}

void LoadTableCorners(const std::string& path, std::vector<LabelledFrame>* frames) {
  const nlohmann::json labels = ReadJsonObject(path);
  for (LabelledFrame& frame : *frames) {
    if (!labels.contains(frame.file)) continue;
    const std::string where = path + ": '" + frame.file + "'";
    const auto& entry = labels.at(frame.file);
    if (!entry.is_object()) throw std::invalid_argument(where + " is not an object");
    const std::vector<Eigen::Vector2d> corners = Points(entry, "corners", where);
    if (corners.size() != 4) throw std::invalid_argument(where + ": 'corners' is not 4 [u, v]");
    frame.corners = {corners[0], corners[1], corners[2], corners[3]};
    frame.unseen_side = -1;
    if (entry.contains("unseen_side")) {
      const auto& side = entry.at("unseen_side");
      if (!side.is_number_integer() || side.get<int>() < 0 || side.get<int>() > 3) {
        throw std::invalid_argument(where + ": 'unseen_side' is not a side (0..3)");
      }
      frame.unseen_side = side.get<int>();
    }
  }
}

estimator::BallSet BallSetFor(const LabelledFrame& frame) {
  if (frame.kind == "snooker") return estimator::BallSet::kSnooker;
  if (frame.kind == "carom") return estimator::BallSet::kCarom;
  const bool by_colour = std::any_of(frame.classes.begin(), frame.classes.end(), [](const auto& c) {
    return c == "red" || c == "yellow";
  });
  return by_colour ? estimator::BallSet::kBlackball : estimator::BallSet::kPool;
}

bool ClassMatches(const std::string& label, estimator::BallClass detected) {
  const std::string name = estimator::BallClassName(detected);
  if (label == name) return true;
  if (label == "white") return detected == estimator::BallClass::kCue;
  const int number = static_cast<int>(detected);
  if (label == "solid") return number >= 1 && number <= 7;
  if (label == "stripe") return number >= 9 && number <= 15;
  if (label == "eight") return number == 8 || detected == estimator::BallClass::kBlack;
  if (label == "black") return number == 8;
  return false;
}

namespace {

// The segment from `a` to `b` within the frame `size` (Liang and Barsky 1984); false when none
// of it is.
bool ClipToFrame(const cv::Size& size, Eigen::Vector2d* a, Eigen::Vector2d* b) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = *b - *a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a->x(), size.width - 1 - a->x(), a->y(), size.height - 1 - a->y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Eigen::Vector2d start = *a;
  *a = start + t0 * d;
  *b = start + t1 * d;
  return true;
}

double DistanceToLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = (b - a).normalized();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x()));
}

// The largest distance of a found side from its labelled one at the labelled side's ends in the
// frame, the found corners matched to the labelled ones by the turn and direction around the
// table that puts them nearest.
double TableSideError(const LabelledFrame& frame, const estimator::TableRegion& table,
                      const cv::Size& size) {
  const auto& label = *frame.corners;
  std::array<Eigen::Vector2d, 4> found{};
  double best = HUGE_VAL;
  for (int turn = 0; turn < 4; ++turn) {
    for (const int direction : {1, -1}) {
      std::array<Eigen::Vector2d, 4> candidate;
      double sum = 0;
      for (int i = 0; i < 4; ++i) {
        candidate[i] = table.corners[((turn + direction * i) % 4 + 4) % 4];
        sum += (candidate[i] - label[i]).norm();
      }
      if (sum < best) {
        best = sum;
        found = candidate;
      }
    }
  }
  double error = 0;
  for (int side = 0; side < 4; ++side) {
    if (side == frame.unseen_side) continue;
    Eigen::Vector2d a = label[side], b = label[(side + 1) % 4];
    if (!ClipToFrame(size, &a, &b)) continue;
    for (const Eigen::Vector2d& end : {a, b}) {
      error = std::max(error, DistanceToLine(end, found[side], found[(side + 1) % 4]));
    }
  }
  return error;
}

bool InsideLabelledTable(const std::array<Eigen::Vector2d, 4>& corners, const Eigen::Vector2d& p) {
  std::vector<cv::Point2f> polygon;
  for (const auto& c : corners) {
    polygon.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
  }
  return cv::pointPolygonTest(polygon, cv::Point2f(static_cast<float>(p.x()),
                                                   static_cast<float>(p.y())),
                              false) >= 0;
}

}  // namespace

void ExplainMisses(const LabelledFrame& frame, FrameScore* score) {
  const double r = frame.radius_px;
  score->missed_causes.clear();
  for (const Eigen::Vector2d& p : score->missed) {
    std::string cause = "on open cloth";
    bool by_cushion = false;
    if (frame.corners) {
      for (int side = 0; side < 4; ++side) {
        by_cushion = by_cushion || DistanceToLine(p, (*frame.corners)[side],
                                                  (*frame.corners)[(side + 1) % 4]) <
                                       kCushionRadii * r;
      }
    }
    const bool clustered = std::any_of(frame.balls.begin(), frame.balls.end(), [&](const auto& q) {
      return q != p && (q - p).norm() < kClusterRadii * r;
    });
    if (!score->table) {
      cause = "no table";
    } else if (!score->table->Contains(p)) {
      cause = "outside the table found";
    } else if (by_cushion) {
      cause = "by the cushion";
    } else if (clustered) {
      cause = "in a cluster";
    }
    score->missed_causes.push_back(cause);
  }
  score->false_causes.clear();
  for (std::size_t i = 0; i < score->detections.size(); ++i) {
    if (score->detection_matched[i]) continue;
    const Eigen::Vector2d& p = score->detections[i].pixel;
    bool duplicate = false;
    for (std::size_t j = 0; j < score->detections.size(); ++j) {
      duplicate = duplicate || (score->detection_label[j] >= 0 &&
                                (frame.balls[score->detection_label[j]] - p).norm() <
                                    kDuplicateRadii * r);
    }
    if (duplicate) {
      score->false_causes.push_back("duplicate");
    } else if (frame.corners && !InsideLabelledTable(*frame.corners, p)) {
      score->false_causes.push_back("off the table");
    } else {
      score->false_causes.push_back("on the table");
    }
  }
}

double MatchDistancePx(double radius_px) { return std::max(kMinMatchPx, kMatchRadii * radius_px); }

FrameScore ScoreFrame(const LabelledFrame& frame,
                      const std::vector<estimator::BallDetection>& detections) {
  FrameScore score;
  score.file = frame.file;
  score.source = frame.source;
  score.labels = static_cast<int>(frame.balls.size());
  score.detections = detections;
  score.detection_matched.assign(detections.size(), false);
  score.detection_label.assign(detections.size(), -1);
  const double gate = MatchDistancePx(frame.radius_px);
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < detections.size(); ++i) {
    for (std::size_t j = 0; j < frame.balls.size(); ++j) {
      const double d = (detections[i].pixel - frame.balls[j]).norm();
      if (d < gate) pairs.emplace_back(d, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> label_matched(frame.balls.size(), false);
  for (const auto& [d, i, j] : pairs) {
    if (score.detection_matched[i] || label_matched[j]) continue;
    score.detection_matched[i] = label_matched[j] = true;
    score.detection_label[i] = static_cast<int>(j);
    score.centre_errors.push_back(d);
    if (j < frame.classes.size() && !frame.classes[j].empty()) {
      ++score.classed;
      score.classed_right += ClassMatches(frame.classes[j], detections[i].ball_class);
    }
  }
  score.found = static_cast<int>(score.centre_errors.size());
  for (std::size_t j = 0; j < frame.balls.size(); ++j) {
    if (!label_matched[j]) score.missed.push_back(frame.balls[j]);
  }
  for (std::size_t i = 0; i < detections.size(); ++i) {
    if (score.detection_matched[i]) continue;
    const bool ignored =
        std::any_of(frame.ignored.begin(), frame.ignored.end(),
                    [&](const auto& p) { return (detections[i].pixel - p).norm() < gate; });
    if (ignored) {
      score.detection_matched[i] = true;
    } else {
      ++score.false_detections;
    }
  }
  return score;
}

DetectionBenchmarkResult RunDetectionBenchmark(const std::string& set,
                                               const std::vector<LabelledFrame>& frames,
                                               const DetectionBenchmarkOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const OneThread one_thread;
  DetectionBenchmarkResult result;
  result.set = set;
  if (!options.overlay_dir.empty()) std::filesystem::create_directories(options.overlay_dir);
  for (const LabelledFrame& frame : frames) {
    const cv::Mat image =
        frame.image.empty() ? options.read_image(set + "/" + frame.file) : frame.image;
    estimator::DetectorOptions detector_options;
    detector_options.ball_set = BallSetFor(frame);
    detector_options.identity.classifier = options.classifier;
    estimator::BallDetector detector(detector_options);
    std::vector<estimator::BallDetection> balls;
    const double first_ms = MillisecondsOf([&] { balls = detector.Detect(image); });
    std::vector<double> next_ms;
    for (int i = 0; i < kNextFrameRepeats; ++i) {
      next_ms.push_back(MillisecondsOf([&] { detector.Detect(image); }));
    }
    FrameScore score = ScoreFrame(frame, balls);
    score.size = image.size();
    score.first_frame_ms = first_ms;
    score.next_frame_ms = Median(next_ms);
    score.failure = detector.failure();
    if (detector.knows_table()) score.table = detector.table();
    score.table_view = score.table ? estimator::TableViewName(score.table->view) : "";
    score.view = !frame.view.empty() ? frame.view : score.table_view;
    score.table_labelled = frame.corners.has_value();
    if (frame.corners && score.table) {
      score.table_side_error_px = TableSideError(frame, *score.table, image.size());
    }
    ExplainMisses(frame, &score);
    if (!options.overlay_dir.empty()) {
      const std::string path = options.overlay_dir + "/" + Stem(frame.file) + ".jpg";
      if (!cv::imwrite(path, ScoreOverlay(image, frame, score))) {
        throw std::runtime_error("cannot write '" + path + "'");
      }
    }
    options.progress(frame.file + ": " + std::to_string(score.found) + " of " +
                     std::to_string(score.labels) + " found, " +
                     std::to_string(score.false_detections) + " false" +
                     (score.table_side_error_px >= 0
                          ? ", table " + Fixed(score.table_side_error_px, 1) + " px"
                          : std::string()) +
                     ", " + Fixed(first_ms, 1) +
                     " ms" + (score.failure.empty() ? "" : " (" + score.failure + ")"));
    result.frames.push_back(std::move(score));
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

cv::Mat ScoreOverlay(const cv::Mat& image, const LabelledFrame& frame, const FrameScore& score) {
  cv::Mat out = image.clone();
  if (score.table) estimator::DrawTable(*score.table, &out);
  const double gate = MatchDistancePx(frame.radius_px);
  const auto point = [](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
  };
  const int thickness = std::max(1, static_cast<int>(frame.radius_px / 8));
  for (const auto& p : frame.ignored) {
    cv::circle(out, point(p), static_cast<int>(gate), {160, 160, 160}, thickness);
  }
  for (const auto& p : score.missed) {
    cv::circle(out, point(p), static_cast<int>(frame.radius_px + 3), {0, 255, 255}, 2 * thickness);
  }
  for (std::size_t i = 0; i < score.detections.size(); ++i) {
    const auto& d = score.detections[i];
    const cv::Scalar colour =
        score.detection_matched[i] ? cv::Scalar(0, 255, 0) : cv::Scalar(0, 0, 255);
    cv::circle(out, point(d.pixel), static_cast<int>(std::lround(d.radius_px)), colour, thickness);
    cv::drawMarker(out, point(d.pixel), colour, cv::MARKER_CROSS, 5, 1);
  }
  for (const auto& p : frame.balls)
    cv::drawMarker(out, point(p), {255, 0, 255}, cv::MARKER_TILTED_CROSS, 5, 1);
  return out;
}

Totals Total(const std::vector<const FrameScore*>& frames) {
  Totals t;
  std::vector<double> errors, first_ms, next_ms;
  for (const FrameScore* f : frames) {
    ++t.frames;
    t.labels += f->labels;
    t.found += f->found;
    t.false_detections += f->false_detections;
    errors.insert(errors.end(), f->centre_errors.begin(), f->centre_errors.end());
    first_ms.push_back(f->first_frame_ms);
    next_ms.push_back(f->next_frame_ms);
    t.tables_labelled += f->table_labelled;
    t.tables_found += f->table_side_error_px >= 0 && f->table_side_error_px <= kTableSideTolerancePx;
    t.classed += f->classed;
    t.classed_right += f->classed_right;
    for (const auto& c : f->missed_causes) ++t.missed_by_cause[c];
    for (const auto& c : f->false_causes) ++t.false_by_cause[c];
  }
  t.recall = t.labels ? static_cast<double>(t.found) / t.labels : 0;
  t.precision = t.found + t.false_detections
                    ? static_cast<double>(t.found) / (t.found + t.false_detections)
                    : 0;
  t.median_error_px = Median(errors);
  t.median_first_frame_ms = Median(first_ms);
  t.median_next_frame_ms = Median(next_ms);
  return t;
}

std::map<std::string, std::vector<const FrameScore*>> ByView(
    const std::vector<FrameScore>& frames) {
  std::map<std::string, std::vector<const FrameScore*>> groups;
  for (const FrameScore& f : frames) {
    groups[f.view.empty() ? "no table" : f.view].push_back(&f);
    groups["all"].push_back(&f);
  }
  return groups;
}

nlohmann::json FiguresJson(const Totals& t) {
  return {{"frames", t.frames},
          {"labels", t.labels},
          {"found", t.found},
          {"false", t.false_detections},
          {"recall", t.recall},
          {"precision", t.precision},
          {"classed", t.classed},
          {"classed_right", t.classed_right},
          {"identity", t.classed ? static_cast<double>(t.classed_right) / t.classed : 0.0}};
}

namespace {

nlohmann::json TotalsJson(const Totals& t) {
  nlohmann::json j = FiguresJson(t);
  j.update({{"median_centre_error_px", t.median_error_px},
            {"median_first_frame_ms", t.median_first_frame_ms},
            {"median_next_frame_ms", t.median_next_frame_ms},
            {"tables_labelled", t.tables_labelled},
            {"tables_within_2px", t.tables_found},
            {"missed_by_cause", t.missed_by_cause},
            {"false_by_cause", t.false_by_cause}});
  return j;
}

}  // namespace

nlohmann::json DetectionSummaryJson(const DetectionBenchmarkResult& result) {
  nlohmann::json views = nlohmann::json::object();
  for (const auto& [view, frames] : ByView(result.frames)) views[view] = TotalsJson(Total(frames));
  return {{"set", result.set}, {"views", views}, {"wall_s", result.wall_s}};
}

void WriteDetectionReport(const DetectionBenchmarkResult& result, const std::string& dir) {
  std::filesystem::create_directories(dir);
  nlohmann::json frames = nlohmann::json::array();
  for (const FrameScore& f : result.frames) {
    nlohmann::json missed = nlohmann::json::array();
    for (const auto& p : f.missed) missed.push_back({p.x(), p.y()});
    frames.push_back({{"file", f.file},
                      {"view", f.view},
                      {"table_view", f.table_view},
                      {"labels", f.labels},
                      {"found", f.found},
                      {"false", f.false_detections},
                      {"median_centre_error_px", Median(f.centre_errors)},
                      {"width", f.size.width},
                      {"height", f.size.height},
                      {"first_frame_ms", f.first_frame_ms},
                      {"next_frame_ms", f.next_frame_ms},
                      {"missed", missed},
                      {"missed_causes", f.missed_causes},
                      {"false_causes", f.false_causes},
                      {"table_side_error_px", f.table_side_error_px},
                      {"table_within_2px", f.table_side_error_px >= 0 &&
                                               f.table_side_error_px <= kTableSideTolerancePx},
                      {"classed", f.classed},
                      {"classed_right", f.classed_right},
                      {"failure", f.failure}});
  }
  nlohmann::json all = DetectionSummaryJson(result);
  all["frames"] = frames;
  OpenForWriting(dir + "/detection_results.json") << all.dump(1) << "\n";

  std::ofstream md = OpenForWriting(dir + "/detection_report.md");
  md << "# Ball detection on a labelled set\n\n"
     << "`billiard bench-detect --set " << result.set << "`: every frame through the detector "
     << "from scratch (table, cloth, scale, balls), no radius given. A detection matches a label "
     << "within max(8 px, 0.6 R); balls labelled in a pocket or ignored count neither way. "
     << "Overlays: matched detections green, false ones red, missed labels yellow. Times are "
     << "wall time on one core: a camera's first frame (the table, the cloth and the scale "
     << "learnt, then the balls) and its next frames (the balls only, median of "
     << kNextFrameRepeats << ").\n\n"
     << "The table is found when every labelled side of the playing surface found is within "
     << Fixed(kTableSideTolerancePx, 0) << " px of the labelled side at both of its ends (corner "
     << "labels from `--corners`). Identity: the matched balls whose class is labelled, named "
     << "right (the ball set from the frame's `kind`).\n\n"
     << "| view | frames | labels | found | false | recall | precision | median centre error "
        "[px] | median time, first / next frame [ms] | tables within 2 px | identity |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [view, group] : ByView(result.frames)) {
    const Totals t = Total(group);
    md << "| " << view << " | " << t.frames << " | " << t.labels << " | " << t.found << " | "
       << t.false_detections << " | " << Fixed(100 * t.recall, 1) << " % | "
       << Fixed(100 * t.precision, 1) << " % | " << Fixed(t.median_error_px, 2) << " | "
       << Fixed(t.median_first_frame_ms, 1) << " / " << Fixed(t.median_next_frame_ms, 1) << " | "
       << t.tables_found << " / " << t.tables_labelled << " | " << t.classed_right << " / "
       << t.classed << " |\n";
  }
  const Totals overall = Total(ByView(result.frames)["all"]);
  md << "\nMisses by cause:";
  for (const auto& [cause, n] : overall.missed_by_cause) md << " " << cause << " " << n << ";";
  md << "\nFalse detections by cause:";
  for (const auto& [cause, n] : overall.false_by_cause) md << " " << cause << " " << n << ";";
  md << "\n";
  md << "\n| frame | size | view (found) | labels | found | false | median error [px] | time, "
        "first / next frame [ms] | table side error [px] | identity | note |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FrameScore& f : result.frames) {
    md << "| " << f.file << " | " << f.size.width << "x" << f.size.height << " | " << f.view
       << (f.table_view.empty() || f.table_view == f.view ? "" : " (" + f.table_view + ")") << " | "
       << f.labels << " | " << f.found << " | " << f.false_detections << " | "
       << Fixed(Median(f.centre_errors), 2) << " | " << Fixed(f.first_frame_ms, 1) << " / "
       << Fixed(f.next_frame_ms, 1) << " | "
       << (f.table_side_error_px >= 0 ? Fixed(f.table_side_error_px, 1) : std::string("-"))
       << " | " << (f.classed ? std::to_string(f.classed_right) + " / " + std::to_string(f.classed)
                              : std::string("-"))
       << " | " << f.failure << " |\n";
  }
  if (!md) throw std::runtime_error("writing the detection report failed");
}

}  // namespace billiard::bench
