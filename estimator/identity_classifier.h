// A learnt classifier of balls: which class of its set a ball is, from its descriptor
// (ball_features.h), as a cost per class that ball_identity.h's assignment takes in place of the
// hand-set rules' (the rack's count of each class still respected).
//
// One random forest per ball set (Breiman 2001, "Random forests", Machine Learning 45; OpenCV's
// cv::ml::RTrees, its random draws seeded, so that the same samples give the same forest). It is fitted on rendered balls only (`billiard train-identity`,
// bench/identity_training.h: every ball of every set turned every way, under lights, white
// balances, camera hue responses, blur, noise and JPEG drawn at random), never on real frames,
// which stay test data. A class's cost is -ln of its share of the trees' votes (smoothed by
// kVotePrior votes per class), so that a ball the forest is unsure of is as cheap to leave
// unnamed (ball_identity.cc's kUnknownCost, a share of about 2 %) as to name.
//
// The model's file is OpenCV's FileStorage YAML: a node per set ("pool", "snooker", "carom",
// "blackball") holding its forest. The one fitted with the default options is shipped as
// estimator/models/identity.yml and built into the library (BuiltinIdentityClassifier).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/ml.hpp>
#include <string>
#include <vector>

#include "estimator/ball_class.h"

namespace billiard::estimator {

// A labelled descriptor: a ball of `set` known to be `ball_class`.
struct IdentitySample {
  BallSet set = BallSet::kPool;
  BallClass ball_class = BallClass::kUnknown;
  std::vector<float> features;  // kBallFeatureCount
};

struct ForestOptions {
  int trees = 40;
  int max_depth = 10;
  int min_samples = 5;  // a node with fewer is not split
  // OpenCV's forests draw their bootstrap samples and split variables from the calling thread's
  // cv::theRNG(): seeded with this for each forest (and put back after), so that the same
  // samples give the same forest.
  std::uint64_t seed = 1;
};

class IdentityClassifier {
 public:
  // A forest per set that `samples` hold balls of. Throws std::invalid_argument when a sample's
  // descriptor is not kBallFeatureCount long or its class is not of its set.
  static IdentityClassifier Train(const std::vector<IdentitySample>& samples,
                                  const ForestOptions& options = {});

  // The classifier in FileStorage YAML `text`. Throws std::invalid_argument with the reason when
  // it is not one (no set's forest, or a forest that does not read).
  static IdentityClassifier FromText(const std::string& text);
  static IdentityClassifier Load(const std::string& path);
  std::string ToText() const;
  // Throws std::invalid_argument when `path` cannot be written.
  void Save(const std::string& path) const;

  // Whether there is a forest for `set`.
  bool Knows(BallSet set) const { return forests_.count(set) > 0; }
  // The cost of each class of ClassesIn(set), in its order: -ln of its smoothed vote share.
  // Throws std::invalid_argument for a set it does not know.
  std::vector<double> ClassCosts(const std::vector<float>& features, BallSet set) const;
  // The class of the lowest cost.
  BallClass Classify(const std::vector<float>& features, BallSet set) const;

 private:
  std::map<BallSet, cv::Ptr<cv::ml::RTrees>> forests_;
};

// The classifier shipped (estimator/models/identity.yml, built in), read once.
std::shared_ptr<const IdentityClassifier> BuiltinIdentityClassifier();

}  // namespace billiard::estimator
