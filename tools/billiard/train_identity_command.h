#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard train-identity --out MODEL.yml [--seed N] [--frames N] [--trees N] [--json]`: the
// identity classifier (estimator/identity_classifier.h) fitted on rendered balls only
// (bench/identity_training.h), deterministic for a seed, written as OpenCV YAML; then named on
// frames rendered from another seed (other cameras, lights and balls), its share right per set
// reported (JSON on stdout with --json, else on stderr). The shipped model is
// `billiard train-identity --out estimator/models/identity.yml` with the defaults. Bad numbers
// are usage errors (2); an --out that cannot be written too.
void AddTrainIdentityCommand(CLI::App& app);

}  // namespace billiard::cli
