#include "tools/billiard/train_identity_command.h"

#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bench/identity_training.h"
#include "estimator/ball_class.h"
#include "estimator/identity_classifier.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The check's frames: another seed's (kCheckSeedOffset past the training's), a quarter as many.
constexpr std::uint64_t kCheckSeedOffset = 1000;
constexpr int kCheckShare = 4;

struct TrainIdentityArgs {
  std::string out;
  std::uint64_t seed = 1;
  int frames = bench::IdentityTrainingOptions().frames_per_set;
  int trees = estimator::ForestOptions().trees;
  bool json = false;
};

// Per set, how many of the samples the classifier names right, and of how many.
std::map<estimator::BallSet, std::pair<int, int>> NamedRight(
    const estimator::IdentityClassifier& classifier,
    const std::vector<estimator::IdentitySample>& samples) {
  std::map<estimator::BallSet, std::pair<int, int>> right;
  for (const estimator::IdentitySample& s : samples) {
    right[s.set].first += classifier.Classify(s.features, s.set) == s.ball_class;
    ++right[s.set].second;
  }
  return right;
}

void RunTrainIdentity(const TrainIdentityArgs& args) {
  if (args.frames < 1) throw UsageError("--frames: must be at least 1");
  if (args.trees < 1) throw UsageError("--trees: must be at least 1");
  // Said before the minutes of rendering, not after them.
  if (!std::ofstream(args.out, std::ios::app)) {
    throw UsageError("--out: cannot write '" + args.out + "'");
  }
  bench::IdentityTrainingOptions training;
  training.frames_per_set = args.frames;
  training.seed = args.seed;
  const auto samples = bench::RenderedIdentitySamples(training);
  estimator::ForestOptions forest;
  forest.trees = args.trees;
  const auto classifier = estimator::IdentityClassifier::Train(samples, forest);
  try {
    classifier.Save(args.out);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--out: ") + e.what());
  }
  bench::IdentityTrainingOptions check = training;
  check.seed = args.seed + kCheckSeedOffset;
  check.frames_per_set = std::max(1, args.frames / kCheckShare);
  nlohmann::json report{{"out", args.out}, {"seed", args.seed}, {"samples", samples.size()},
                        {"check_seed", check.seed}};
  for (const auto& [set, right] : NamedRight(classifier, bench::RenderedIdentitySamples(check))) {
    report["check"][estimator::BallSetName(set)] = {
        {"right", right.first}, {"balls", right.second},
        {"share", static_cast<double>(right.first) / right.second}};
  }
  if (args.json) {
    std::cout << report.dump() << std::endl;
  } else {
    std::cerr << "fitted on " << samples.size() << " rendered balls (seed " << args.seed
              << "), written to " << args.out << "; named right on seed " << check.seed << ":";
    for (const auto& [set, r] : report["check"].items()) {
      std::cerr << " " << set << " " << r["right"] << "/" << r["balls"];
    }
    std::cerr << "\n";
  }
}

}  // namespace

void AddTrainIdentityCommand(CLI::App& app) {
  auto args = std::make_shared<TrainIdentityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "train-identity", "Fit the ball identity classifier on rendered balls (never real frames)");
  cmd->add_option("--out", args->out, "The model file to write (OpenCV YAML)")->required();
  cmd->add_option("--seed", args->seed, "Seed of the rendered frames")->capture_default_str();
  cmd->add_option("--frames", args->frames,
                  "Rendered pool frames (the other sets in proportion to their classes)")
      ->capture_default_str();
  cmd->add_option("--trees", args->trees, "Trees per set's forest")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunTrainIdentity(*args); });
}

}  // namespace billiard::cli
