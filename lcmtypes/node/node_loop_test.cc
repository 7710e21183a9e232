// What a node says about its UDP receive buffer: nothing when a burst fits, else what to run.
#include "lcmtypes/node/node_loop.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace billiard::nodes {
namespace {

constexpr long kStockDefault = 212992, kStockMax = 212992;  // a stock Linux kernel's
constexpr char kProjectUrl[] = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304";

TEST(ReceiveBufferAdvice, SaysWhatToRunWhenTheKernelGrantsLessThanAsked) {
  const std::string advice = ReceiveBufferAdvice(kProjectUrl, kStockDefault, kStockMax);
  EXPECT_NE(advice.find("212992 (net.core.rmem_max)"), std::string::npos) << advice;
  EXPECT_NE(advice.find("sysctl -w net.core.rmem_max=4194304"), std::string::npos) << advice;
  EXPECT_EQ(ReceiveBufferAdvice(kProjectUrl, kStockDefault, 4194304), "");
}

TEST(ReceiveBufferAdvice, SaysToAskForABufferWhenTheUrlAsksForNone) {
  const std::string advice =
      ReceiveBufferAdvice("udpm://239.255.76.67:7667?ttl=0", kStockDefault, 1 << 30);
  EXPECT_NE(advice.find("recv_buf_size=4194304"), std::string::npos) << advice;
  // Options in another order, and another provider, which has no socket buffer.
  EXPECT_EQ(ReceiveBufferAdvice("udpm://239.255.76.67:7667?recv_buf_size=4194304&ttl=1",
                                kStockDefault, 1 << 30),
            "");
  EXPECT_EQ(ReceiveBufferAdvice("memq://", kStockDefault, kStockMax), "");
}

TEST(ReceiveBufferAdvice, WithoutAUrlJudgesLcmDefaultUrlOrLcmsOwn) {
  ASSERT_EQ(setenv("LCM_DEFAULT_URL", kProjectUrl, 1), 0);
  EXPECT_NE(ReceiveBufferAdvice("", kStockDefault, kStockMax).find(kProjectUrl), std::string::npos);
  EXPECT_EQ(ReceiveBufferAdvice("", kStockDefault, 4194304), "");
  ASSERT_EQ(unsetenv("LCM_DEFAULT_URL"), 0);
  EXPECT_NE(ReceiveBufferAdvice("", kStockDefault, 4194304).find(kLcmDefaultUrl),
            std::string::npos);
}

}  // namespace
}  // namespace billiard::nodes
