#include "sim/shot_fit/fit_constants.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/params/parameter_sets.h"

namespace billiard::shot_fit {
namespace {

constexpr Constant kAll[] = {Constant::kMu,      Constant::kRolling,         Constant::kSpin,
                             Constant::kCushion, Constant::kCushionFriction, Constant::kBallBall};

std::string RefusalOf(const std::string& list) {
  try {
    ParseConstants(list);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Constants, ParseReadsTheNamesInOrderAndRefusesUnknownOrRepeatedOnes) {
  for (Constant c : kAll) EXPECT_EQ(ParseConstants(ConstantName(c)), std::vector<Constant>{c});
  EXPECT_EQ(ParseConstants("ball_ball,,mu"),
            (std::vector<Constant>{Constant::kBallBall, Constant::kMu}));
  EXPECT_TRUE(ParseConstants("").empty());
  EXPECT_NE(RefusalOf("mu,friction").find("unknown constant \"friction\""), std::string::npos);
  EXPECT_NE(RefusalOf("mu,spin,mu").find("constant \"mu\" named twice"), std::string::npos);
}

// Each constant set reads back as set, and leaves the others as they were.
TEST(Constants, AConstantSetReadsBackAndLeavesTheOthers) {
  const physics::ModelParameters p = params::LoadParameters("carom");
  for (Constant c : kAll) {
    SCOPED_TRACE(ConstantName(c));
    const double value = 0.9 * ConstantValue(p, c);
    const physics::ModelParameters q = WithConstants(p, {c}, {value});
    EXPECT_NEAR(ConstantValue(q, c), value, 1e-15);
    for (Constant other : kAll) {
      if (other != c) {
        EXPECT_NEAR(ConstantValue(q, other), ConstantValue(p, other), 1e-15);
      }
    }
  }
}

// mu_r = a d / (5 r): the rolling resistance moves d and keeps the patch radius a; a new patch
// radius keeps mu_r, d following; where d would pass 1, d = 1 and a = 5 r mu_r.
TEST(Constants, TheRollingResistanceAndThePatchRadiusShareD) {
  const physics::ModelParameters p = params::LoadParameters("carom");
  const double r = p.ball.radius, a = p.contact.patch_radius;
  const physics::ModelParameters rolling = WithConstants(p, {Constant::kRolling}, {0.004});
  EXPECT_EQ(rolling.contact.patch_radius, a);
  EXPECT_NEAR(rolling.contact.d, 5.0 * r * 0.004 / a, 1e-15);

  const physics::ModelParameters spin = WithConstants(p, {Constant::kSpin}, {2.0 * a});
  EXPECT_EQ(spin.contact.patch_radius, 2.0 * a);
  EXPECT_NEAR(spin.RollingResistance(), p.RollingResistance(), 1e-15);

  const double large = 2.0 * a / (5.0 * r);  // d = 2 with the patch kept
  const physics::ModelParameters capped = WithConstants(p, {Constant::kRolling}, {large});
  EXPECT_EQ(capped.contact.d, 1.0);
  EXPECT_NEAR(capped.contact.patch_radius, 5.0 * r * large, 1e-15);
  EXPECT_NEAR(capped.RollingResistance(), large, 1e-15);
}

TEST(Constants, WithConstantsNeedsOneValuePerConstant) {
  EXPECT_THROW(WithConstants(params::LoadParameters("carom"), {Constant::kMu}, {}),
               std::invalid_argument);
}

// The ranges the fits search hold every shipped table: a fit is never kept from the truth of a
// real cloth, cushion or ball by its range.
TEST(Constants, EveryShippedSetLiesInsideTheRanges) {
  for (const std::string& name : params::BuiltinParameterSetNames()) {
    const physics::ModelParameters p = params::LoadParameters(name);
    for (Constant c : kAll) {
      SCOPED_TRACE(name + " " + ConstantName(c));
      const Range range = ConstantRange(c);
      EXPECT_LT(range.lo, range.hi);
      EXPECT_GE(ConstantValue(p, c), range.lo);
      EXPECT_LE(ConstantValue(p, c), range.hi);
    }
  }
}

}  // namespace
}  // namespace billiard::shot_fit
