// The messages compiled by lcm-gen at build time encode and decode losslessly.
#include <gtest/gtest.h>

#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"

namespace {

TEST(LcmTypes, BallStateRoundTripsBitForBit) {
  billiard::ball_state_t in{};
  in.utime = 1'700'000'000'123'456;
  in.ball_id = 7;
  in.position[0] = 1.25;
  in.position[1] = -0.5;
  in.velocity[1] = 1.0 / 3.0;
  in.spin[2] = -150.0;
  for (int i = 0; i < 49; ++i) in.covariance[i] = 1e-6 * i;

  std::vector<uint8_t> buffer(in.getEncodedSize());
  ASSERT_EQ(in.encode(buffer.data(), 0, static_cast<int>(buffer.size())),
            static_cast<int>(buffer.size()));
  billiard::ball_state_t out{};
  ASSERT_EQ(out.decode(buffer.data(), 0, static_cast<int>(buffer.size())),
            static_cast<int>(buffer.size()));
  EXPECT_EQ(out.utime, in.utime);
  EXPECT_EQ(out.ball_id, in.ball_id);
  EXPECT_EQ(out.position[0], in.position[0]);
  EXPECT_EQ(out.velocity[1], in.velocity[1]);
  EXPECT_EQ(out.spin[2], in.spin[2]);
  EXPECT_EQ(out.covariance[48], in.covariance[48]);
}

TEST(LcmTypes, TruncatedBufferIsRejected) {
  billiard::ball_state_t in{};
  std::vector<uint8_t> buffer(in.getEncodedSize());
  in.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
  billiard::ball_state_t out{};
  EXPECT_LT(out.decode(buffer.data(), 0, static_cast<int>(buffer.size()) - 1), 0);
}

}  // namespace
