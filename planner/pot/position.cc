#include "planner/pot/position.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "planner/pot/cue_elevation.h"
#include "planner/pot/pace.h"

namespace billiard::pot {

namespace {

// Position play: the grid of cue speeds (times the slowest that pots) and tip heights (times the
// largest offset) the Newton iteration starts from the best of.
constexpr double kGridSpeeds[] = {1.15, 1.5, 2.0, 2.8, 4.0};
constexpr double kGridTips[] = {-0.8, -0.4, 0.0, 0.4, 0.8};
constexpr int kMaxPositionIterations = 10;
// The Levenberg-Marquardt damping of position play's steps, relative to the normal matrix's trace.
constexpr double kPositionDamping = 1e-6;
// Position play's side spins, as fractions of the largest tip offset: none first.
constexpr double kPositionSides[] = {0.0, 0.5, -0.5};
// Newton's method starts from this many of the grid's nearest rest points, in turn.
constexpr std::size_t kPositionStarts = 3;
constexpr int kMaxTruthCorrections = 4;

// Where the truth or the search leaves the cue ball for a stroke: the pot aimed at the window's
// middle.
struct Landing {
  Eigen::Vector2d rest = Eigen::Vector2d::Zero();
  Aimed aimed;
};

// The hop of a stroke does not depend on its heading (the strike turns with it, and the bed is
// level): any heading tells the fastest stroke whose hop the table's motion covers.
constexpr double kAnyHeading = 0.0;

// A stroke of the search, x = (cue speed, tip height), and where it leaves the cue ball.
using Stroke = std::pair<Eigen::Vector2d, Landing>;

// Position play at one side spin: the cue speed and tip height, bounded by the cue's limits
// (the tip within the offset the side leaves), each stroke aimed at the window's middle.
class SideSearch {
 public:
  SideSearch(SearchContext& search, const CueTarget& target, const StrokeShape& shape, const Drop& drop)
      : search_(search), target_(target), shape_(shape), middle_(drop.Middle()) {
    const double max_tip = search.params().cue.max_tip_offset * search.radius();
    const double side = shape.tip_side;
    tip_room_ = std::sqrt(std::max(0.0, max_tip * max_tip - side * side)) * 0.999;
    top_ = TopCueSpeed(search, shape, kAnyHeading);
    base_ = shape.speed;
    tolerance_ = std::max(target.radius, search.options().position_tolerance);
    span_ = Eigen::Vector2d(base_, tip_room_ > 0.0 ? tip_room_ : 1.0);
  }

  // The shape and aims that meet the target, as Position() says.
  std::optional<Refusal> Solve(const Aimed& aimed, StrokeShape* shape, Aimed* search_aim,
                               std::optional<Aimed>* truth_aim) {
    std::vector<Stroke> grid = Grid(aimed);
    if (grid.empty()) return Refusal{PotStatus::kTargetUnreachable, "no stroke of the grid pots and leaves the cue ball on the table"};
    std::sort(grid.begin(), grid.end(), [&](const auto& a, const auto& b) { return Miss(a.second) < Miss(b.second); });
    const auto [x_search, here] = Descend(grid);
    Eigen::Vector2d x = x_search;
    const std::optional<Landing> truth = OnTheTruth(here, &x);
    if (!truth || (truth->rest - target_.point).norm() > tolerance_) return Unreachable(truth ? truth->rest : here.rest);
    *shape = Shaped(x);
    std::optional<Aimed> again = AimAt(search_, *shape, here.aimed.heading, middle_, false, here.aimed.slope);
    if (!again) return Refusal{PotStatus::kTargetUnreachable, "the stroke for the target loses ball " + std::to_string(search_.object_id())};
    *search_aim = *again;
    *truth_aim = truth->aimed;
    return std::nullopt;
  }

 private:
  Eigen::Vector2d Bounded(Eigen::Vector2d x) const {
    x.y() = std::clamp(x.y(), -tip_room_, tip_room_);
    // An elevated cue's fastest stroke within the hop covered moves with the tip height.
    x.x() = std::max(kSlowestCue, std::min({x.x(), top_, TopCueSpeed(search_, Shaped(x), kAnyHeading)}));
    return x;
  }

  StrokeShape Shaped(const Eigen::Vector2d& x) const {
    StrokeShape s = shape_;
    s.speed = x.x();
    s.tip_height = x.y();
    return s;
  }

  // Where stroke x, aimed from `from`, leaves the cue ball, if it pots legally.
  std::optional<Landing> Land(const Eigen::Vector2d& x, const Aimed& from, bool truth) {
    const StrokeShape shape = Shaped(x);
    std::optional<Aimed> aimed = AimAt(search_, shape, from.heading, middle_, truth, from.slope);
    if (!aimed) return std::nullopt;
    const PotOutcome o = search_.Play(shape.At(aimed->heading), truth).outcome;
    if (!o.legal) return std::nullopt;
    return Landing{o.cue_rest, *aimed};
  }

  double Miss(const Landing& l) const { return (l.rest - target_.point).norm(); }

  // The grid of strokes about the pace's speed that pot legally, from the pace's aim.
  std::vector<Stroke> Grid(const Aimed& aimed) {
    std::vector<Stroke> grid;
    for (double speed : kGridSpeeds) {
      for (double tip : kGridTips) {
        const Eigen::Vector2d xi = Bounded({base_ * speed / kGridSpeeds[1], tip * tip_room_});
        std::optional<Landing> l = Land(xi, aimed, false);
        if (l) grid.emplace_back(xi, *l);
      }
    }
    return grid;
  }

  // d rest / d (speed, tip height) by forward differences on the search.
  bool Jacobian(const Eigen::Vector2d& at, const Landing& l, Eigen::Matrix2d* j) {
    const Eigen::Vector2d steps(0.02 * at.x(), 0.05 * tip_room_);
    for (int c = 0; c < 2; ++c) {
      Eigen::Vector2d probe = at;
      probe[c] += (at[c] + steps[c] > (c == 0 ? top_ : tip_room_)) ? -steps[c] : steps[c];
      std::optional<Landing> p = Land(probe, l.aimed, false);
      if (!p) return false;
      j->col(c) = (p->rest - l.rest) / (probe[c] - at[c]);
    }
    return j->allFinite();
  }

  // A Levenberg-Marquardt step in units of the grid's spans: where speed and tip move the rest
  // point along one line (a cue ball already rolling at contact, whatever the tip), the step to
  // the nearest point of that line.
  Eigen::Vector2d StepTo(const Eigen::Matrix2d& jacobian, const Eigen::Vector2d& miss) const {
    const Eigen::Matrix2d js = jacobian * span_.asDiagonal();
    const Eigen::Matrix2d normal = js.transpose() * js;
    const Eigen::Matrix2d damped = normal + kPositionDamping * normal.trace() * Eigen::Matrix2d::Identity();
    return Eigen::Vector2d(span_.asDiagonal() * (damped.inverse() * (js.transpose() * miss)));
  }

  // Gauss-Newton (a step that does not come closer is halved) from the nearest grid points in
  // turn: the rest point jumps where the cue ball's path meets a cushion or a ball.
  Stroke Descend(const std::vector<Stroke>& grid) {
    Stroke best = grid.front();
    for (std::size_t start = 0; start < grid.size() && start < kPositionStarts; ++start) {
      const Stroke reached = DescendFrom(grid[start]);
      if (Miss(reached.second) < Miss(best.second)) best = reached;
      if (Miss(best.second) < 0.25 * tolerance_) break;
    }
    return best;
  }

  Stroke DescendFrom(Stroke from) {
    auto& [xs, at] = from;
    Eigen::Matrix2d j;
    for (int i = 0; i < kMaxPositionIterations; ++i) {
      const Eigen::Vector2d miss = target_.point - at.rest;
      if (miss.norm() < 0.25 * tolerance_ || !Jacobian(xs, at, &j)) break;
      Eigen::Vector2d step = StepTo(j, miss);
      bool better = false;
      for (int halving = 0; halving < 5 && !better; ++halving, step *= 0.5) {
        const Eigen::Vector2d xn = Bounded(xs + step);
        std::optional<Landing> l = Land(xn, at.aimed, false);
        if (l && Miss(*l) < miss.norm()) {
          xs = xn;
          at = *l;
          better = true;
        }
      }
      if (!better) break;
    }
    return from;
  }

  // The truth's rest point for the search's best stroke *x, corrected with the search's Jacobian
  // there (*x moved with it).
  std::optional<Landing> OnTheTruth(const Landing& here, Eigen::Vector2d* x) {
    std::optional<Landing> truth = Land(*x, here.aimed, true);
    Eigen::Matrix2d j;
    const bool have_jacobian = Jacobian(*x, here, &j);
    for (int i = 0; truth && have_jacobian && i < kMaxTruthCorrections; ++i) {
      const Eigen::Vector2d miss = target_.point - truth->rest;
      if (miss.norm() < 0.5 * tolerance_) break;
      const Eigen::Vector2d xn = Bounded(*x + StepTo(j, miss));
      std::optional<Landing> l = Land(xn, truth->aimed, true);
      if (!l || (l->rest - target_.point).norm() >= miss.norm()) break;
      *x = xn;
      truth = l;
    }
    return truth;
  }

  Refusal Unreachable(const Eigen::Vector2d& nearest) const {
    std::ostringstream reason;
    reason.precision(3);
    reason << "the cue ball stops at best " << (nearest - target_.point).norm()
           << " m from the target, at (" << nearest.x() << ", " << nearest.y() << ")";
    return Refusal{PotStatus::kTargetUnreachable, reason.str()};
  }

  SearchContext& search_;
  const CueTarget& target_;
  const StrokeShape shape_;
  const double middle_;
  double tip_room_, top_, base_, tolerance_;
  Eigen::Vector2d span_;
};

}  // namespace

std::optional<Refusal> Position(SearchContext& search, const CueTarget& target, StrokeShape* shape, Aimed* aimed,
                                const Drop& drop, std::optional<Aimed>* truth_aim) {
  // Without side spin first; then with it either way (it turns the cue ball off the rails and
  // throws K, so it reaches rest points that speed and follow or draw alone do not).
  std::optional<Refusal> first;
  for (double side : kPositionSides) {
    StrokeShape s = *shape;
    s.tip_side = side * search.params().cue.max_tip_offset * search.radius();
    Aimed a = *aimed;
    if (side != 0.0) {
      std::optional<Aimed> again = AimAt(search, s, aimed->heading - physics::SquirtAngle(s.tip_side, search.params()),
                                         drop.Middle(), false, aimed->slope);
      if (!again) continue;
      a = *again;
    }
    std::optional<Refusal> refused = SideSearch(search, target, s, drop).Solve(a, &s, &a, truth_aim);
    if (!refused) {
      *shape = s;
      *aimed = a;
      return std::nullopt;
    }
    if (!first) first = refused;
  }
  first->reason += " (with side spin too)";
  return first;
}

}  // namespace billiard::pot
