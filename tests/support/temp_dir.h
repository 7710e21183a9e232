// A directory of a test's own (its logs, its copies), removed with it.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <string>

namespace billiard::testing {

class TempDir {
 public:
  TempDir() {
    char name[] = "/tmp/billiard_test_XXXXXX";
    path_ = mkdtemp(name) ? name : "";
  }
  ~TempDir() {
    if (!path_.empty()) std::filesystem::remove_all(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string operator/(const std::string& file) const { return path_ + "/" + file; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace billiard::testing
