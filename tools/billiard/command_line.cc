#include "tools/billiard/command_line.h"

#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace billiard::cli {

std::vector<double> ParseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what) {
  std::vector<double> numbers;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string field = text.substr(start, end - start);
    char* stop = nullptr;
    errno = 0;
    const double value = std::strtod(field.c_str(), &stop);
    if (field.empty() || stop != field.c_str() + field.size() || errno == ERANGE) {
      throw UsageError(what + ": '" + field + "' is not a number");
    }
    RequireFinite(value, what);
    numbers.push_back(value);
    start = end + 1;
  }
  if (numbers.size() != count) {
    throw UsageError(what + ": expected " + std::to_string(count) +
                     " comma-separated numbers, got " + std::to_string(numbers.size()));
  }
  return numbers;
}

namespace {

// The edit distance between a and b, row by row of the Wagner-Fischer table.
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substituted = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({substituted, row[j] + 1, row[j - 1] + 1});
    }
  }
  return row[b.size()];
}

}  // namespace

std::string NearestName(const std::string& word, const std::vector<std::string>& names,
                        std::size_t max_edits) {
  std::string nearest;
  std::size_t best = max_edits + 1;
  for (const std::string& name : names) {
    const std::size_t d = EditDistance(word, name);
    if (d < best) {
      nearest = name;
      best = d;
    }
  }
  return nearest;
}

void RequireFinite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw UsageError(what + ": numbers must be finite (no NaN or inf)");
}

std::string Fixed(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  if (rounded == 0.0) return "0";
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << rounded;
  return out.str();
}

namespace {

constexpr double kMmPerM = 1000.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;

// "3.0 mm right", "" for the centre: one offset of the tip as the player sees it.
std::string TipOffset(double metres, const char* positive, const char* negative) {
  const std::string mm = Fixed(std::abs(metres) * kMmPerM, 1);
  if (mm == "0") return "";
  return mm + " mm " + (metres > 0.0 ? positive : negative);
}

}  // namespace

std::string StrokeInWords(const physics::CueStroke& stroke) {
  const std::string side = TipOffset(stroke.tip_side, "right", "left");
  const std::string height = TipOffset(stroke.tip_height, "above", "below");
  std::string tip = "tip at centre";
  if (!side.empty() && !height.empty()) {
    tip = "tip " + side + " and " + height + " centre";
  } else if (!side.empty()) {
    tip = "tip " + side + " of centre";
  } else if (!height.empty()) {
    tip = "tip " + height + " centre";
  }
  // The heading in (-180, 180], as a protractor laid along the long axis reads it.
  const double heading = std::remainder(stroke.heading, 2.0 * kPi) * kDegPerRad;
  return "speed " + Fixed(stroke.speed, 3) + " m/s, heading " + Fixed(heading, 2) + " deg, " +
         tip + ", elevation " + Fixed(stroke.elevation * kDegPerRad, 1) + " deg";
}

cue::Robot LoadRobotOption(const std::string& name_or_path) {
  try {
    return params::LoadRobot(name_or_path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--robot: ") + e.what());
  }
}

std::optional<cue::Robot> LoadRobotOrNone(const std::string& name_or_path) {
  if (name_or_path == "none") return std::nullopt;
  return LoadRobotOption(name_or_path);
}

void DescribeParameters(const physics::ModelParameters& p, nlohmann::json* j) {
  (*j)["params"] = p.name;
  if (!p.file.empty()) (*j)["params_file"] = p.file;
}

void RequireWritableDirectory(const std::string& dir, const std::string& option) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) {
    throw UsageError(option + ": cannot make the directory '" + dir + "': " + error.message());
  }
  if (access(dir.c_str(), W_OK | X_OK) != 0) {
    throw UsageError(option + ": cannot write in '" + dir + "': " + std::strerror(errno));
  }
}

physics::ModelParameters LoadParametersOption(const std::string& name_or_path) {
  try {
    return params::LoadParameters(name_or_path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--params: ") + e.what());
  }
}

double TrajectorySamples(double t_end, double dt) { return std::ceil(t_end / dt - 1e-9) + 1.0; }

void RequireTrajectoryWithinLimit(double t_end, double dt, int balls) {
  const double samples = TrajectorySamples(t_end, dt);
  if (samples * balls <= kMaxTrajectoryRows) return;
  std::ostringstream reason;
  reason.precision(15);
  reason << "--sample-dt " << dt << " to t = " << t_end << " s asks for " << samples << " samples";
  if (balls > 1) reason << " of " << balls << " balls";
  reason << ", more than the " << kMaxTrajectoryRows << " rows"
         << " a trajectory file may hold (raise --sample-dt)";
  throw UsageError(reason.str());
}

void WriteTrajectoryCsv(const std::string& path, double t_end, double dt, int balls,
                        const std::function<physics::BallState(double t, int k)>& state,
                        const std::function<int(int k)>& id) {
  RequireTrajectoryWithinLimit(t_end, dt, balls);
  std::ofstream out(path);
  if (!out) throw UsageError("cannot write trajectory file '" + path + "'");
  out.precision(17);
  out << (id ? "t,id," : "t,") << "X,Y,vx,vy,wx,wy,wz\n";
  const long samples = static_cast<long>(TrajectorySamples(t_end, dt));
  for (long i = 0; i < samples; ++i) {
    const double t = std::min(i * dt, t_end);
    for (int k = 0; k < balls; ++k) {
      const physics::BallState s = state(t, k);
      out << t;
      if (id) out << ',' << id(k);
      for (int c = 0; c < 7; ++c) out << ',' << s[c];
      out << '\n';
    }
  }
  if (!out) throw std::runtime_error("writing trajectory file '" + path + "' failed");
}

}  // namespace billiard::cli
