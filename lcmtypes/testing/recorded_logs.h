// Recorded LCM logs for the loop's tests: what a log holds, and copies of a log with a message
// changed or lost (as a logger that missed it wrote it), through LCM's log file API.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>
#include <vector>

#include "lcmtypes/billiard/image_t.hpp"

namespace billiard::messages::testing {

// How many messages of each channel a log holds.
inline std::map<std::string, int> ChannelCounts(const std::string& path) {
  std::map<std::string, int> counts;
  lcm::LogFile log(path, "r");
  while (const lcm::LogEvent* e = log.good() ? log.readNextEvent() : nullptr) ++counts[e->channel];
  return counts;
}

// Copies the log `from` to `to`, each event as `copy` gives it back: unchanged, changed, or
// nothing (false: the event is left out).
inline void CopyLog(const std::string& from, const std::string& to,
                    const std::function<bool(lcm::LogEvent&, std::vector<std::uint8_t>&)>& copy) {
  lcm::LogFile in(from, "r"), out(to, "w");
  ASSERT_TRUE(in.good() && out.good());
  while (const lcm::LogEvent* e = in.readNextEvent()) {
    lcm::LogEvent event = *e;
    std::vector<std::uint8_t> bytes;  // the event's data when `copy` changes it
    if (copy(event, bytes)) {
      ASSERT_EQ(out.writeEvent(&event), 0);
    }
  }
}

// Copies the log `from` to `to` with the index-th message on `channel` decoded as a Message,
// changed by `alter` and encoded again.
template <class Message>
void CopyWithOneMessageAltered(const std::string& from, const std::string& to,
                               const std::string& channel, int index,
                               const std::function<void(Message&)>& alter) {
  int seen = 0;
  CopyLog(from, to, [&](lcm::LogEvent& e, std::vector<std::uint8_t>& bytes) {
    if (e.channel != channel || seen++ != index) return true;
    Message m;
    EXPECT_EQ(m.decode(e.data, 0, e.datalen), e.datalen);
    alter(m);
    bytes.resize(m.getEncodedSize());
    m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    e.data = bytes.data();
    e.datalen = static_cast<std::int32_t>(bytes.size());
    return true;
  });
  ASSERT_GT(seen, index) << "the log has " << seen << " messages on " << channel;
}

// The utime of the index-th message on `channel` of a log, decoded as a Message; -1 when it has
// fewer.
template <class Message>
std::int64_t UtimeOf(const std::string& path, const std::string& channel, int index) {
  lcm::LogFile log(path, "r");
  int seen = 0;
  while (const lcm::LogEvent* e = log.good() ? log.readNextEvent() : nullptr) {
    if (e->channel != channel || seen++ != index) continue;
    Message m{};
    return m.decode(e->data, 0, e->datalen) == e->datalen ? m.utime : -1;
  }
  return -1;
}

// Copies the log `from` to `to` without the index-th message on `channel`, as a logger that lost
// it wrote it.
inline void CopyWithOneMessageLost(const std::string& from, const std::string& to,
                                   const std::string& channel, int index) {
  int seen = 0;
  CopyLog(from, to, [&](lcm::LogEvent& e, std::vector<std::uint8_t>&) {
    return e.channel != channel || seen++ != index;
  });
}

// Copies the log `from` to `to` without the frames at `utime` (a frame sent again unanswered
// has several), as a logger that lost that frame wrote it.
inline void CopyWithAFrameLost(const std::string& from, const std::string& to, std::int64_t utime) {
  CopyLog(from, to, [utime](lcm::LogEvent& e, std::vector<std::uint8_t>&) {
    image_t frame{};
    return e.channel != "CAMERA_IMAGE" || frame.decode(e.data, 0, e.datalen) != e.datalen ||
           frame.utime != utime;
  });
}

}  // namespace billiard::messages::testing
