#include "tools/billiard/noise_option.h"

#include <stdexcept>

#include "tools/billiard/command_line.h"

namespace billiard::cli {

params::ExecutionNoise LoadNoiseOption(const std::string& name_or_path, const std::string& flag) {
  try {
    return params::LoadNoise(name_or_path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(flag + ": " + e.what());
  }
}

}  // namespace billiard::cli
