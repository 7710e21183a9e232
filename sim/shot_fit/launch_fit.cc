#include "sim/shot_fit/launch_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/physics/closed_form.h"
#include "sim/physics/golden_section.h"

namespace billiard::shot_fit {

namespace {

// The strike time and the slide's end are found to this [s]: far below a frame, far above
// rounding.
constexpr double kTimeTolerance = 1e-6;
// A sample this many position_sd from the rest position shows the ball moving.
constexpr double kMovedInSd = 3.0;
// Samples are used until this fraction of the commanded stroke's stop time.
constexpr double kBeforeRest = 0.8;
// A sample is used only where the commanded stroke's path, this much faster, is clear up to its
// time: a ball that met a cushion between two frames may be back inside at the second, and the
// robot's stroke may be a few per cent faster than the command.
constexpr double kFasterThanCommanded = 1.15;
// The slide of the stroke played ends within this factor of the commanded one's (a millimetre
// of tip height moves it by a tenth), and is seen to end with this many frames after it.
constexpr double kSlideEndSpread = 1.25, kFramesPastTheSlide = 3.0;
// The launch is seen where the slide spans this many frames: with one, its acceleration rests on
// one sample and the launch's covariance is singular to rounding (a slow follow's slide).
constexpr double kFramesInTheSlide = 2.0;
// The rolling line is taken from the fit again at most this many times, until it turns by less
// than kSettledLine [rad] (a micrometre over a metre).
constexpr int kMaxRefits = 20;
constexpr double kSettledLine = 1e-6;
// The commanded path is checked for clearance at this spacing [s]: a ball at 8 m/s moves 8 mm.
constexpr double kPathStep = 1e-3;

// What the commanded stroke predicts of the motion after the strike: the slide's duration and
// acceleration, the rolling deceleration and direction, the stop time.
struct Predicted {
  double slide_time = 0.0;
  Eigen::Vector2d slide_acceleration = Eigen::Vector2d::Zero();
  double rolling_deceleration = 0.0;
  Eigen::Vector2d rolling_direction = Eigen::Vector2d::Zero();
  double stop_time = 0.0;
  // The latest time the commanded path is clear of other balls and the cushions [s].
  double clear_until = 0.0;
};

bool Clear(const Eigen::Vector2d& at, const std::vector<Eigen::Vector2d>& others,
           const physics::ModelParameters& p, double clearance) {
  const double r = p.ball.radius, edge = r + clearance;
  if (at.x() < edge || at.y() < edge || at.x() > p.table.length - edge ||
      at.y() > p.table.width - edge) {
    return false;
  }
  return std::all_of(others.begin(), others.end(), [&](const Eigen::Vector2d& o) {
    return (at - o).norm() >= 2.0 * r + clearance;
  });
}

Predicted Predict(const physics::CueStroke& commanded, const Eigen::Vector2d& start,
                  const std::vector<Eigen::Vector2d>& others, const physics::ModelParameters& p,
                  const LaunchFitOptions& o) {
  const physics::ClosedFormParameters closed = physics::ClosedFormParameters::From(p);
  const physics::BallState launch = physics::StrikeBall(commanded, start, p);
  const physics::ClosedFormTrajectory path(closed, launch);
  Predicted out;
  out.slide_time = path.slide_end_time();
  const Eigen::Vector2d v1 = path.slide_end_state().segment<2>(physics::kVx);
  if (out.slide_time > 0.0) {
    out.slide_acceleration = (v1 - launch.segment<2>(physics::kVx)) / out.slide_time;
  }
  if (v1.norm() > 0.0) out.rolling_direction = v1.normalized();
  out.rolling_deceleration = 5.0 / 7.0 * closed.mu_roll * closed.gravity;
  out.stop_time = path.stop_time();
  while (out.clear_until < out.stop_time &&
         Clear(path.At(out.clear_until + kPathStep).segment<2>(physics::kX), others, p,
               o.clearance)) {
    out.clear_until += kPathStep;
  }
  return out;
}

// The samples a launch is fitted to, on the shot's clock: those at rest before the strike, then
// the moving ones; and the bracket of the strike.
struct Stretch {
  std::vector<double> t;
  std::vector<Eigen::Vector2d> position;
  int moving = 0;
  double strike_lo = 0.0, strike_hi = 0.0;
};

// `s` without the frames near the slide's end, unless enough follow it to see where it ends: the
// robot's error moves the end by a tenth or so, and a model that puts it in the wrong frame
// bends the launch. A slide shorter than a frame is kept whole (the rolling frames are the data).
Stretch WithinOneMotion(Stretch s, double slide_time) {
  if (s.moving == 0) return s;
  const double frame = (s.t.back() - s.strike_lo) / static_cast<double>(s.moving);
  const double last = s.t.back() - s.strike_lo;
  if (slide_time < frame || last > kSlideEndSpread * slide_time + kFramesPastTheSlide * frame) {
    return s;
  }
  while (s.moving > 0 && s.t.back() - s.strike_lo > slide_time / kSlideEndSpread) {
    s.t.pop_back();
    s.position.pop_back();
    --s.moving;
  }
  return s;
}

std::vector<Eigen::Vector2d> OtherBalls(const TrackedShot& shot) {
  std::vector<Eigen::Vector2d> others;
  for (std::size_t i = 0; i < shot.balls.size(); ++i) {
    if (i != shot.cue && !shot.balls[i].position.empty()) others.push_back(shot.balls[i].position[0]);
  }
  return others;
}

Stretch MovingSamples(const TrackedShot& shot, const Predicted& predicted,
                      const physics::ModelParameters& p, const LaunchFitOptions& o) {
  const TrackedBall& ball = shot.balls[shot.cue];
  const std::vector<Eigen::Vector2d> others = OtherBalls(shot);
  Stretch s;
  std::size_t first = 1;
  while (first < ball.t.size() &&
         (ball.position[first] - ball.position[0]).norm() < kMovedInSd * o.position_sd) {
    ++first;
  }
  if (first >= ball.t.size()) return s;
  s.t.assign(ball.t.begin(), ball.t.begin() + static_cast<std::ptrdiff_t>(first));
  s.position.assign(ball.position.begin(), ball.position.begin() + static_cast<std::ptrdiff_t>(first));
  s.strike_lo = ball.t[first - 1];
  s.strike_hi = ball.t[first];
  for (std::size_t k = first; k < ball.t.size(); ++k) {
    const double longest = ball.t[k] - s.strike_lo;  // since the earliest the strike can be
    if (longest > kBeforeRest * predicted.stop_time ||
        kFasterThanCommanded * longest > predicted.clear_until ||
        !Clear(ball.position[k], others, p, o.clearance)) {
      break;
    }
    s.t.push_back(ball.t[k]);
    s.position.push_back(ball.position[k]);
    ++s.moving;
  }
  return WithinOneMotion(s, predicted.slide_time);
}

// The launch's least squares for one strike time: per coordinate, p - known(tau) =
// p0 + v tau + a c(tau), with tau = max(0, t - t_s) (the samples at rest see p0 alone) and
// c(tau) = tau^2 / 2 while sliding, T (tau - T / 2) after. The rest position p0 is fitted too:
// one sample of it carries the tracking's error, which turns the launch's line about it.
class LaunchModel {
 public:
  LaunchModel(const Stretch& s, const Predicted& predicted, bool free_slide)
      : s_(s), pr_(predicted), free_slide_(free_slide) {}

  double SlideTerm(double tau) const {
    const double T = pr_.slide_time;
    return tau <= T ? 0.5 * tau * tau : T * (tau - 0.5 * T);
  }
  Eigen::Vector2d Known(double tau) const {
    const double rolled = std::max(0.0, tau - pr_.slide_time);
    Eigen::Vector2d k = -0.5 * pr_.rolling_deceleration * rolled * rolled * pr_.rolling_direction;
    if (!free_slide_) k += pr_.slide_acceleration * SlideTerm(tau);
    return k;
  }
  static double Tau(double t, double strike) { return std::max(0.0, t - strike); }
  // The design [1, tau, c(tau)] (or [1, tau] with the slide held) and its solution per
  // coordinate.
  Eigen::MatrixXd Design(double strike) const {
    Eigen::MatrixXd x(s_.t.size(), free_slide_ ? 3 : 2);
    for (std::size_t k = 0; k < s_.t.size(); ++k) {
      const double tau = Tau(s_.t[k], strike);
      x(k, 0) = 1.0;
      x(k, 1) = tau;
      if (free_slide_) x(k, 2) = SlideTerm(tau);
    }
    return x;
  }
  Eigen::MatrixXd Targets(double strike) const {
    Eigen::MatrixXd y(s_.t.size(), 2);
    for (std::size_t k = 0; k < s_.t.size(); ++k) {
      y.row(k) = (s_.position[k] - Known(Tau(s_.t[k], strike))).transpose();
    }
    return y;
  }
  // Rows: p0, v, then a when free; columns: x, y.
  Eigen::MatrixXd Solve(double strike) const {
    return Design(strike).colPivHouseholderQr().solve(Targets(strike));
  }
  double SumOfSquares(double strike) const {
    return (Design(strike) * Solve(strike) - Targets(strike)).squaredNorm();
  }
  // The motion's rate dp/dtau at tau for the solution `c`.
  Eigen::Vector2d Rate(double tau, const Eigen::MatrixXd& c) const {
    const Eigen::Vector2d v = c.row(1).transpose();
    const Eigen::Vector2d a = free_slide_ ? Eigen::Vector2d(c.row(2).transpose())
                                          : pr_.slide_acceleration;
    const double T = pr_.slide_time;
    if (tau <= T) return v + a * tau;
    return v + a * T - pr_.rolling_deceleration * (tau - T) * pr_.rolling_direction;
  }
  // Gauss-Newton's J over (t_s, p0, v, a) at the solution.
  Eigen::MatrixXd Jacobian(double strike, const Eigen::MatrixXd& c) const {
    const int n = static_cast<int>(s_.t.size()), m = free_slide_ ? 7 : 5;
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(2 * n, m);
    for (int k = 0; k < n; ++k) {
      const double tau = Tau(s_.t[k], strike);
      if (s_.t[k] > strike) j.block<2, 1>(2 * k, 0) = -Rate(tau, c);
      j.block<2, 2>(2 * k, 1) = Eigen::Matrix2d::Identity();
      j.block<2, 2>(2 * k, 3) = tau * Eigen::Matrix2d::Identity();
      if (free_slide_) j.block<2, 2>(2 * k, 5) = SlideTerm(tau) * Eigen::Matrix2d::Identity();
    }
    return j;
  }

 private:
  const Stretch& s_;
  const Predicted& pr_;
  bool free_slide_;
};

// One pass of the fit with the slide's duration `predicted.slide_time`: the strike time, the
// launch and the rolling velocity, their covariance.
void FitPass(const Stretch& s, const Predicted& predicted, bool free_slide,
             const LaunchFitOptions& options, MeasuredLaunch& out) {
  const LaunchModel model(s, predicted, free_slide);
  out.strike_time = physics::GoldenSectionMinimum(
      [&](double strike) { return model.SumOfSquares(strike); }, s.strike_lo, s.strike_hi,
      [](double lo, double hi) { return hi - lo < kTimeTolerance; });
  const Eigen::MatrixXd c = model.Solve(out.strike_time);
  out.velocity = c.row(1).transpose();
  const double slide = predicted.slide_time;
  out.rolling = out.velocity + slide * (free_slide ? Eigen::Vector2d(c.row(2).transpose())
                                                   : predicted.slide_acceleration);
  const Eigen::MatrixXd j = model.Jacobian(out.strike_time, c);
  const double squares = model.SumOfSquares(out.strike_time);
  out.rms = std::sqrt(squares / static_cast<double>(j.rows()));
  const double dof = static_cast<double>(j.rows() - j.cols());
  const double sd2 = std::max(options.position_sd * options.position_sd,
                              dof > 0.0 ? squares / dof : 0.0);
  out.squares = squares;
  out.dof = dof;
  out.variance = sd2;
  const Eigen::MatrixXd covariance = sd2 * (j.transpose() * j).inverse();
  // (v, v + T a) from (v, a).
  Eigen::MatrixXd to_rolling = Eigen::MatrixXd::Zero(4, covariance.cols() - 3);
  to_rolling.topLeftCorner(2, 2).setIdentity();
  to_rolling.bottomLeftCorner(2, 2).setIdentity();
  if (free_slide) to_rolling.bottomRightCorner(2, 2) = slide * Eigen::Matrix2d::Identity();
  const Eigen::MatrixXd va =
      covariance.bottomRightCorner(covariance.rows() - 3, covariance.cols() - 3);
  out.joint_covariance = to_rolling * va * to_rolling.transpose();
  out.covariance = covariance.block<2, 2>(3, 3);
  out.ok = out.joint_covariance.allFinite();
  if (!out.ok) out.reason = "the launch's samples do not determine it";
}

// The slide's duration for which the fit's slide decelerates at `slide_deceleration` (mu_s g),
// within kSlideEndSpread of the commanded one's: a slide's frames alone place its end only
// roughly, and the rolling frames after it, extrapolated to an end placed wrong, would bend
// the launch (a long roll's weight against a draw's few sliding frames).
double PlayedSlideTime(const Stretch& s, Predicted predicted, const LaunchFitOptions& options,
                       double slide_deceleration) {
  const double commanded = predicted.slide_time;
  const auto mismatch = [&](double slide_time) {
    predicted.slide_time = slide_time;
    MeasuredLaunch fit;
    FitPass(s, predicted, true, options, fit);
    const double deceleration = (fit.rolling - fit.velocity).norm() / slide_time;
    return std::pow(deceleration - slide_deceleration, 2);
  };
  return physics::GoldenSectionMinimum(
      mismatch, commanded / kSlideEndSpread, commanded * kSlideEndSpread,
      [](double lo, double hi) { return hi - lo < kTimeTolerance; });
}

}  // namespace

MeasuredLaunch FitLaunch(const TrackedShot& shot, const physics::CueStroke& commanded,
                         const physics::ModelParameters& p, const LaunchFitOptions& options) {
  MeasuredLaunch out;
  if (shot.cue >= shot.balls.size() || shot.balls[shot.cue].t.empty()) {
    out.reason = "the shot has no samples of its struck ball";
    return out;
  }
  const Eigen::Vector2d rest = shot.balls[shot.cue].position[0];
  Predicted predicted = Predict(commanded, rest, OtherBalls(shot), p, options);
  const Stretch s = MovingSamples(shot, predicted, p, options);
  out.samples = s.moving;
  if (out.samples < options.min_samples) {
    out.reason = "only " + std::to_string(out.samples) +
                 " samples of the struck ball before it met a ball, a cushion or rest";
    return out;
  }
  // A slide shorter than two frames leaves at most one frame inside it to tell a from v: the
  // launch is then not seen, the velocity it rolls on is. A slide that outlasts the frames
  // leaves the rolling velocity unseen: the slide's acceleration is mu_s g whatever the spin,
  // which only sets how long it lasts.
  const double frame = (s.t.back() - s.strike_lo) / static_cast<double>(s.moving);
  out.launch_seen = predicted.slide_time > kFramesInTheSlide * frame;
  FitPass(s, predicted, out.launch_seen, options, out);
  out.rolling_seen = s.t.back() - out.strike_time > predicted.slide_time + frame;
  if (!out.rolling_seen) return out;
  // The stroke played, not the commanded one, sets where its slide ends and the line it rolls
  // along (launch_fit.h): both taken from the fit until the line settles.
  const double slide_deceleration = p.contact.mu * p.ball.gravity;
  for (int pass = 0; pass < kMaxRefits; ++pass) {
    const Eigen::Vector2d line = out.rolling.normalized();
    const Eigen::Vector2d& was = predicted.rolling_direction;
    const double turned = std::abs(was.x() * line.y() - was.y() * line.x());
    predicted.rolling_direction = line;
    if (out.launch_seen) {
      predicted.slide_time = PlayedSlideTime(s, predicted, options, slide_deceleration);
    }
    FitPass(s, predicted, out.launch_seen, options, out);
    if (turned < kSettledLine) break;
  }
  return out;
}

}  // namespace billiard::shot_fit
