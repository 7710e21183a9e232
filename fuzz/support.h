// What every fuzz target shares: the properties a decoded message must have, and the seed corpus.
//
// A property that fails aborts with a one-line description on stderr, so that libFuzzer keeps the
// input as a crash artifact: every finding is a broken promise of message_checks.h or
// image_codec.h, not a mere refusal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lcmtypes/message_checks.h"

namespace billiard::fuzz {

using Bytes = std::vector<std::uint8_t>;

// The target's seed corpus: valid payloads of its type. Each target defines it; running a target
// with -write_seeds=DIR writes them into DIR (one file each) and exits, so the corpus is made
// from the current message types rather than kept as binary files.
std::vector<Bytes> Seeds();

[[noreturn]] void Fail(const std::string& what);

// The decoders' contract for a refusal's reason: one line, for a node's log.
void RequireOneLine(const std::string& reason, const char* who);

template <class Message>
Bytes Encode(const Message& m) {
  Bytes bytes(static_cast<std::size_t>(m.getEncodedSize()));
  const int n = m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  if (n != static_cast<int>(bytes.size())) {
    Fail("encode wrote " + std::to_string(n) + " of the " + std::to_string(bytes.size()) +
         " bytes getEncodedSize announced");
  }
  return bytes;
}

// Decodes `data` through message_checks into `out` and asserts what any answer must satisfy:
// one-line reasons, and that a payload Decode accepts (whether Check accepts its meaning or not)
// is exactly what the decoded message encodes to, so that a node which forwards, logs or replays
// it sends what it received. Returns whether Decode accepted it.
template <class Message>
bool DecodeAndCheck(const std::uint8_t* data, std::size_t size, Message& out) {
  const std::string why = messages::Decode(data, size, out);
  RequireOneLine(why, "Decode");
  if (!why.empty()) return false;
  if (Encode(out) != Bytes(data, data + size)) {
    Fail("an accepted payload of " + std::to_string(size) + " bytes re-encodes differently");
  }
  RequireOneLine(messages::Check(out), "Check");
  return true;
}

}  // namespace billiard::fuzz
