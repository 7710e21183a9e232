// What a valid message is: every node decodes what it receives through these functions, so that
// a payload from a buggy, foreign or hostile sender is refused with a one-line reason instead of
// crashing or misleading the node.
//
// Decoding trusts nothing. lcm-gen's decoders size a vector or a string from a count in the
// payload before they check that the payload holds it, so a corrupt count allocates gigabytes,
// throws, or (a string length of 0) reads before the buffer. Decode walks the wire layout first
// (every count against the bytes that remain, every string terminated and without a NUL
// inside), then decodes, and refuses trailing bytes: they mean the sender's type is not ours.
//
// Check is about meaning: finite numbers, known enum values, ids and counts in range, times that
// are not negative. Where physical ranges are tested they are generous (a robot's table, not a
// pool table), because the nodes test the real limits themselves with better reasons (the
// planner's table bounds, the estimator's camera size).
#pragma once

#include <cstddef>
#include <string>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"

namespace billiard::messages {

// Limits of a sane message.
inline constexpr int kMaxBalls = 64;             // balls in one table_state_t
inline constexpr int kMaxPathPoints = 100000;    // points of a cue_command_t's path, and of
                                                 // each of its ball paths
inline constexpr int kMaxBallPaths = kMaxBalls;  // ball paths of a cue_command_t (one a ball)
inline constexpr int kMaxReasonLength = 4096;    // bytes of a string field
inline constexpr double kMaxPosition = 100.0;    // |X|, |Y| [m]
inline constexpr double kMaxSpeed = 100.0;       // |v| [m/s]
inline constexpr double kMaxSpin = 1.0e4;        // |w| [rad/s]
inline constexpr int kMaxImageBytes = 64 << 20;  // image_t data
inline constexpr int kMaxImageSide = 16384;      // image_t width, height [px]

// Decodes the `size` bytes at `data` (a whole LCM payload, hash included) into `out`: the empty
// string, or why the payload is not a message of that type. `out` is unspecified after a refusal.
std::string Decode(const void* data, std::size_t size, table_state_t& out);
std::string Decode(const void* data, std::size_t size, shot_request_t& out);
std::string Decode(const void* data, std::size_t size, cue_command_t& out);
std::string Decode(const void* data, std::size_t size, image_t& out);
std::string Decode(const void* data, std::size_t size, node_status_t& out);

// The empty string, or why a decoded message must not be acted on.
std::string Check(const table_state_t& m);
std::string Check(const shot_request_t& m);
std::string Check(const cue_command_t& m);
std::string Check(const image_t& m);  // the header; the pixels are image_codec.h's business
std::string Check(const node_status_t& m);

// Decode, then Check.
template <class Message>
std::string DecodeChecked(const void* data, std::size_t size, Message& out) {
  std::string why = Decode(data, size, out);
  return why.empty() ? Check(out) : why;
}

}  // namespace billiard::messages
