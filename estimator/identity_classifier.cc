#include "estimator/identity_classifier.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "estimator/ball_features.h"

namespace billiard::estimator {

namespace internal {
// The shipped model's text (generated from estimator/models/identity.yml).
const std::string& BuiltinIdentityModelText();
}  // namespace internal

namespace {

// Votes added to every class before the shares are taken: a class no tree voted for costs about
// ln(trees / kVotePrior + classes), not infinity.
constexpr double kVotePrior = 0.5;

constexpr BallSet kSets[] = {BallSet::kPool, BallSet::kSnooker, BallSet::kCarom,
                             BallSet::kBlackball};

cv::Mat Row(const std::vector<float>& features) {
  if (static_cast<int>(features.size()) != kBallFeatureCount) {
    throw std::invalid_argument("identity classifier: a descriptor of " +
                                std::to_string(features.size()) + " values, not " +
                                std::to_string(kBallFeatureCount));
  }
  return cv::Mat(1, kBallFeatureCount, CV_32F, const_cast<float*>(features.data())).clone();
}

cv::Ptr<cv::ml::RTrees> TrainForest(const cv::Mat& samples, const cv::Mat& labels,
                                    const ForestOptions& options) {
  cv::Ptr<cv::ml::RTrees> forest = cv::ml::RTrees::create();
  forest->setMaxDepth(options.max_depth);
  forest->setMinSampleCount(options.min_samples);
  forest->setCalculateVarImportance(false);
  forest->setActiveVarCount(0);  // sqrt of the descriptor's length, Breiman's choice
  forest->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER, options.trees, 0));
  cv::RNG& rng = cv::theRNG();
  const cv::RNG before = rng;
  rng = cv::RNG(options.seed);
  forest->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, labels));
  rng = before;
  return forest;
}

}  // namespace

IdentityClassifier IdentityClassifier::Train(const std::vector<IdentitySample>& samples,
                                             const ForestOptions& options) {
  IdentityClassifier classifier;
  for (const BallSet set : kSets) {
    cv::Mat rows, labels;
    for (const IdentitySample& s : samples) {
      if (s.set != set) continue;
      if (CountIn(set, s.ball_class) == 0) {
        throw std::invalid_argument("identity classifier: a " + BallClassName(s.ball_class) +
                                    " is no ball of " + BallSetName(set));
      }
      rows.push_back(Row(s.features));
      labels.push_back(static_cast<int>(s.ball_class));
    }
    if (!rows.empty()) classifier.forests_[set] = TrainForest(rows, labels, options);
  }
  return classifier;
}

IdentityClassifier IdentityClassifier::FromText(const std::string& text) {
  IdentityClassifier classifier;
  try {
    cv::FileStorage file(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    for (const BallSet set : kSets) {
      const cv::FileNode node = file[BallSetName(set)];
      if (node.empty()) continue;
      cv::Ptr<cv::ml::RTrees> forest = cv::ml::RTrees::create();
      forest->read(node);
      if (!forest->isTrained()) {
        throw std::invalid_argument("its " + BallSetName(set) + " forest does not read");
      }
      classifier.forests_[set] = forest;
    }
  } catch (const cv::Exception& e) {
    throw std::invalid_argument("not an identity model: " + e.msg);
  }
  if (classifier.forests_.empty()) {
    throw std::invalid_argument("not an identity model: no set's forest in it");
  }
  return classifier;
}

IdentityClassifier IdentityClassifier::Load(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::invalid_argument("cannot read '" + path + "'");
  std::ostringstream text;
  text << file.rdbuf();
  try {
    return FromText(text.str());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("'" + path + "': " + e.what());
  }
}

std::string IdentityClassifier::ToText() const {
  cv::FileStorage file(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  for (const auto& [set, forest] : forests_) {
    file << BallSetName(set) << "{";
    forest->write(file);
    file << "}";
  }
  return file.releaseAndGetString();
}

void IdentityClassifier::Save(const std::string& path) const {
  std::ofstream file(path, std::ios::binary);
  file << ToText();
  if (!file.flush()) throw std::invalid_argument("cannot write '" + path + "'");
}

std::vector<double> IdentityClassifier::ClassCosts(const std::vector<float>& features,
                                                   BallSet set) const {
  const auto forest = forests_.find(set);
  if (forest == forests_.end()) {
    throw std::invalid_argument("identity classifier: no forest for " + BallSetName(set));
  }
  cv::Mat votes;
  forest->second->getVotes(Row(features), votes, 0);
  const std::vector<BallClass> classes = ClassesIn(set);
  std::vector<double> count(classes.size(), 0.0);
  double total = 0;
  for (int j = 0; j < votes.cols; ++j) {
    const auto label = static_cast<BallClass>(votes.at<int>(0, j));
    const auto at = std::find(classes.begin(), classes.end(), label);
    if (at != classes.end()) count[at - classes.begin()] = votes.at<int>(1, j);
    total += votes.at<int>(1, j);
  }
  const double all = total + kVotePrior * classes.size();
  std::vector<double> costs;
  for (const double c : count) costs.push_back(-std::log((c + kVotePrior) / all));
  return costs;
}

BallClass IdentityClassifier::Classify(const std::vector<float>& features, BallSet set) const {
  const std::vector<double> costs = ClassCosts(features, set);
  return ClassesIn(set)[std::min_element(costs.begin(), costs.end()) - costs.begin()];
}

std::shared_ptr<const IdentityClassifier> BuiltinIdentityClassifier() {
  static const std::shared_ptr<const IdentityClassifier> classifier =
      std::make_shared<const IdentityClassifier>(
          IdentityClassifier::FromText(internal::BuiltinIdentityModelText()));
  return classifier;
}

}  // namespace billiard::estimator
