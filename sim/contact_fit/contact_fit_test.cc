// The least-squares fit of eq. 17 to the integral model reproduces the paper's table
// (Kudra et al. 2016, section 2.3; shared/docs/physics-notes.md).
#include "sim/contact_fit/contact_fit.h"

#include <gtest/gtest.h>

namespace billiard::contact_fit {
namespace {

double RelativeError(double value, double published) {
  return std::abs(value - published) / published;
}

TEST(ContactFit, WithExponentsFixedAtTwoMatchesThePaperWithinTwoPercent) {
  ContactFitOptions options;
  options.fixed_m = 2.0;
  const ContactFit fit = FitContactApproximation(options);
  EXPECT_EQ(fit.m_t, 2.0);
  EXPECT_EQ(fit.m_m, 2.0);
  EXPECT_LT(RelativeError(fit.b_t, 0.68102), 0.02) << fit.b_t;
  EXPECT_LT(RelativeError(fit.b_m, 0.480909), 0.02) << fit.b_m;
}

TEST(ContactFit, AllFreeMatchesThePaperWithinFivePercent) {
  const ContactFit fit = FitContactApproximation(ContactFitOptions{});
  EXPECT_LT(RelativeError(fit.b_t, 0.771), 0.05) << fit.b_t;
  EXPECT_LT(RelativeError(fit.m_t, 2.655), 0.05) << fit.m_t;
  EXPECT_LT(RelativeError(fit.b_m, 0.419), 0.05) << fit.b_m;
  EXPECT_LT(RelativeError(fit.m_m, 3.073), 0.05) << fit.m_m;
}

TEST(ContactFit, FreeExponentsFitBetterThanFixedOnes) {
  ContactFitOptions fixed;
  fixed.fixed_m = 2.0;
  EXPECT_LT(FitContactApproximation(ContactFitOptions{}).cost(),
            FitContactApproximation(fixed).cost());
}

TEST(ContactFit, ResultDoesNotDependOnTheGridOverD) {
  ContactFitOptions coarse, fine;
  fine.nodes_d = 10;
  fine.nodes_gamma = 20;
  fine.nodes_theta = 48;
  const ContactFit a = FitContactApproximation(coarse), b = FitContactApproximation(fine);
  EXPECT_NEAR(a.b_t, b.b_t, 2e-3);
  EXPECT_NEAR(a.m_t, b.m_t, 2e-2);
  EXPECT_NEAR(a.b_m, b.b_m, 2e-3);
  EXPECT_NEAR(a.m_m, b.m_m, 2e-2);
}

}  // namespace
}  // namespace billiard::contact_fit
