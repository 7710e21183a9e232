#include "fuzz/support.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace billiard::fuzz {

void Fail(const std::string& what) {
  std::fprintf(stderr, "fuzz property failed: %s\n", what.c_str());
  std::abort();
}

void RequireOneLine(const std::string& reason, const char* who) {
  if (reason.find('\n') != std::string::npos) {
    Fail(std::string(who) + " gave a reason of more than one line: " + reason);
  }
}

}  // namespace billiard::fuzz

// libFuzzer calls this before it parses its own flags, so -write_seeds never reaches it.
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  constexpr std::string_view kFlag = "-write_seeds=";
  for (int i = 1; i < *argc; ++i) {
    const std::string_view arg = (*argv)[i];
    if (arg.substr(0, kFlag.size()) != kFlag) continue;
    const std::string dir(arg.substr(kFlag.size()));
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    const std::vector<billiard::fuzz::Bytes> seeds = billiard::fuzz::Seeds();
    for (std::size_t k = 0; k < seeds.size(); ++k) {
      const std::string path = dir + "/seed-" + std::to_string(k);
      std::ofstream out(path, std::ios::binary);
      out.write(reinterpret_cast<const char*>(seeds[k].data()),
                static_cast<std::streamsize>(seeds[k].size()));
      if (!out) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        std::exit(2);
      }
    }
    std::exit(0);
  }
  return 0;
}
