#include "estimator/identity_fit.h"

#include <algorithm>
#include <map>
#include <utility>

namespace billiard::estimator {

namespace {

bool IsCue(const KnownBall& b) { return b.ball_class == BallClass::kCue; }

bool IsBlack(const KnownBall& b) {
  return b.ball_class == BallClass::kBlack ||
         (b.set == BallSet::kPool && b.ball_class == PoolBall(8));
}

int PoolNumber(const KnownBall& b) {
  const int number = static_cast<int>(b.ball_class);
  return b.set == BallSet::kPool && number >= 1 && number <= 15 ? number : 0;
}

bool IsStripe(const KnownBall& b) { return b.group == PoolGroup::kStripe || PoolNumber(b) > 8; }

bool IsSolid(const KnownBall& b) {
  return b.group == PoolGroup::kSolid || (PoolNumber(b) >= 1 && PoolNumber(b) <= 7);
}

// A ball of a coloured class: known, neither the cue ball nor a black ball.
bool IsColoured(const KnownBall& b) {
  const bool known = b.ball_class != BallClass::kUnknown || b.group != PoolGroup::kNone;
  return known && !IsCue(b) && !IsBlack(b);
}

template <typename Pick, typename Share>
std::vector<double> SharesOf(const std::vector<KnownBall>& balls, Pick pick, Share share) {
  std::vector<double> shares;
  for (const KnownBall& b : balls) {
    if (b.look.seen && pick(b)) shares.push_back(share(b.look));
  }
  return shares;
}

// Sets `*threshold` to the split of `above` and `below` when each has kMinBallsPerSide shares;
// whether it did.
bool FitThreshold(const std::vector<double>& above, const std::vector<double>& below,
                  double* threshold) {
  if (above.size() < static_cast<std::size_t>(kMinBallsPerSide) ||
      below.size() < static_cast<std::size_t>(kMinBallsPerSide)) {
    return false;
  }
  *threshold = *SplitShares(above, below);
  return true;
}

void FitThresholds(const std::vector<KnownBall>& balls, IdentityFit* fit) {
  IdentityParameters& p = fit->parameters;
  const auto white = [](const BallLook& l) { return l.white; };
  const auto colour = [](const BallLook& l) { return l.colour; };
  const auto black = [](const BallLook& l) { return l.black; };
  const auto plain = [](const BallLook& l) { return l.plain; };
  const auto not_cue_nor_stripe = [](const KnownBall& b) {
    return (IsColoured(b) || IsBlack(b)) && !IsStripe(b);
  };
  fit->cue_white = FitThreshold(SharesOf(balls, IsCue, white),
                                SharesOf(balls, not_cue_nor_stripe, white), &p.cue_white);
  fit->cue_colour = FitThreshold(SharesOf(balls, IsColoured, colour),
                                 SharesOf(balls, IsCue, colour), &p.cue_colour);
  fit->black_share = FitThreshold(SharesOf(balls, IsBlack, black),
                                  SharesOf(balls, IsColoured, black), &p.black_share);
  fit->stripe_plain = FitThreshold(SharesOf(balls, IsStripe, plain),
                                   SharesOf(balls, IsSolid, plain), &p.stripe_plain);
}

// The per-channel median of colours, of which there is at least one.
cv::Vec3f MedianOf(std::vector<cv::Vec3f> colours) {
  cv::Vec3f median;
  std::vector<float> channel(colours.size());
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < colours.size(); ++i) channel[i] = colours[i][c];
    std::nth_element(channel.begin(), channel.begin() + channel.size() / 2, channel.end());
    median[c] = channel[channel.size() / 2];
  }
  return median;
}

// The colours of the classes the balls show, one per source (its balls' median), under the
// fitted thresholds; the prior's for the other classes.
void FitColours(const std::vector<KnownBall>& balls, const IdentityParameters& prior,
                IdentityFit* fit) {
  using Key = std::pair<BallSet, BallClass>;  // a colour table and a class in it
  std::map<Key, std::map<int, std::vector<cv::Vec3f>>> seen;  // by source
  for (const KnownBall& b : balls) {
    if (!b.look.seen || !IsColoured(b) || b.ball_class == BallClass::kUnknown) continue;
    const std::optional<cv::Vec3f> colour = JudgedColour(b.look, fit->parameters);
    if (!colour) continue;
    seen[{ColourTableOf(b.set), ColourClassOf(b.ball_class, b.set)}][b.source].push_back(*colour);
  }
  std::vector<ColourPrototype> colours;
  std::map<Key, bool> kept;
  for (const ColourPrototype& c : prior.colours) {
    if (seen.count({c.table, c.ball_class})) continue;
    colours.push_back(c);
    kept[{c.table, c.ball_class}] = true;
  }
  for (const auto& [key, by_source] : seen) {
    for (const auto& [source, of_source] : by_source) {
      colours.push_back({key.first, key.second, MedianOf(of_source)});
    }
  }
  fit->parameters.colours = std::move(colours);
  fit->classes_fitted = static_cast<int>(seen.size());
  fit->classes_kept = static_cast<int>(kept.size());
}

}  // namespace

std::optional<double> SplitShares(const std::vector<double>& above,
                                  const std::vector<double>& below) {
  if (above.empty() || below.empty()) return std::nullopt;
  std::vector<double> values = above;
  values.insert(values.end(), below.begin(), below.end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (values.size() == 1) return values.front();
  const auto wrong = [&](double t) {
    return std::count_if(above.begin(), above.end(), [t](double v) { return v < t; }) +
           std::count_if(below.begin(), below.end(), [t](double v) { return v >= t; });
  };
  double best = 0, best_gap = -1;
  auto fewest = above.size() + below.size() + 1;
  for (std::size_t i = 0; i + 1 < values.size(); ++i) {
    const double t = 0.5 * (values[i] + values[i + 1]), gap = values[i + 1] - values[i];
    const auto n = static_cast<std::size_t>(wrong(t));
    if (n < fewest || (n == fewest && gap > best_gap)) {
      best = t;
      best_gap = gap;
      fewest = n;
    }
  }
  return best;
}

IdentityFit FitIdentity(const std::vector<KnownBall>& balls, const IdentityParameters& prior) {
  IdentityFit fit;
  fit.parameters = prior;
  FitThresholds(balls, &fit);
  FitColours(balls, prior, &fit);
  return fit;
}

}  // namespace billiard::estimator
