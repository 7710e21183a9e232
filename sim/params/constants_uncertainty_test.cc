// The table's constants drawn within their uncertainty: the strict reading of "uncertainty", the
// draws' spread against the sds they were given, the truncation at the physical range, and the
// pool set's shipped uncertainty.
#include "sim/params/constants_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "sim/params/parameter_sets.h"

namespace billiard::params {
namespace {

// The pool set as JSON with `uncertainty` (a JSON object's text) in place of its own.
std::string PoolWithUncertainty(const std::string& uncertainty) {
  physics::ModelParameters p = LoadParameters("pool");
  p.uncertainty = {};
  std::string json = ParametersJson(p);
  json.insert(json.rfind('}'), ", \"uncertainty\": " + uncertainty);
  return json;
}

// What ParseParameters says of `uncertainty`, or "" when it accepts it.
std::string Refusal(const std::string& uncertainty) {
  try {
    ParseParameters(PoolWithUncertainty(uncertainty), "t.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ConstantsUncertainty, IsReadStrictlyNamingTheKey) {
  EXPECT_EQ(Refusal(R"({"contact.mu": 0.01, "source": "a guess"})"), "");
  EXPECT_NE(Refusal(R"({"contact.muu": 0.01})").find("unknown key uncertainty.contact.muu"),
            std::string::npos);
  // The geometry and the robot's limits are not drawn.
  EXPECT_NE(Refusal(R"({"table.length": 0.01})").find("uncertainty.table.length"), std::string::npos);
  EXPECT_NE(Refusal(R"({"cue.max_speed": 0.1})").find("uncertainty.cue.max_speed"), std::string::npos);
  EXPECT_NE(Refusal(R"({"collision.cushion_restitution": -0.1})")
                .find("uncertainty.collision.cushion_restitution must be a standard deviation"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"contact.mu": "big"})").find("uncertainty.contact.mu"), std::string::npos);
  EXPECT_NE(Refusal("3").find("\"uncertainty\" must be an object"), std::string::npos);
}

TEST(ConstantsUncertainty, IsWrittenAsItIsRead) {
  const physics::ModelParameters pool = LoadParameters("pool");
  ASSERT_FALSE(pool.uncertainty.sd.empty());
  const physics::ModelParameters back = ParseParameters(ParametersJson(pool), "x");
  EXPECT_EQ(back.uncertainty.source, pool.uncertainty.source);
  EXPECT_EQ(back.uncertainty.sd, pool.uncertainty.sd);
}

// The pool set's sds are a quarter of the published ranges its source names.
TEST(ConstantsUncertainty, PoolSetCarriesAQuarterOfThePublishedRanges) {
  const physics::ModelParameters pool = LoadParameters("pool");
  auto sd = [&](const std::string& key) {
    for (const auto& [k, v] : pool.uncertainty.sd) {
      if (k == key) return v;
    }
    return -1.0;
  };
  constexpr double kRounding = 1e-12;  // the file's decimals
  EXPECT_NEAR(sd("collision.cushion_restitution"), (0.98 - 0.85) / 4, kRounding);  // Mathavan, pooltool
  EXPECT_NEAR(sd("collision.cushion_friction"), (0.2 - 0.14) / 4, kRounding);
  EXPECT_NEAR(sd("collision.ball_restitution"), (0.98 - 0.92) / 4, kRounding);
  EXPECT_NEAR(sd("contact.mu"), (0.4 - 0.15) / 4, kRounding);
  // mu_r = a d / (5 r): the range of mu_r, 0.005-0.015, in d.
  const double d_per_mu_r = 5 * pool.ball.radius / pool.contact.patch_radius;
  EXPECT_NEAR(sd("contact.d"), d_per_mu_r * (0.015 - 0.005) / 4, kRounding);
  EXPECT_NE(pool.uncertainty.source.find("Mathavan"), std::string::npos);
}

TEST(ConstantsUncertainty, ASetWithoutUncertaintyIsDrawnAsItIs) {
  const physics::ModelParameters paper = LoadParameters("paper");
  ASSERT_TRUE(paper.uncertainty.sd.empty());
  int calls = 0;
  const physics::ModelParameters drawn = SampledConstants(paper, [&] { return ++calls, 1.0; });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(ParameterHash(drawn), ParameterHash(paper));
}

// Far from the range's ends the draws are the normal distribution the sds give: mean and sd
// within four standard errors, and the constants not named untouched.
TEST(ConstantsUncertainty, DrawsSpreadAsTheirSds) {
  physics::ModelParameters p = LoadParameters("pool");
  p.uncertainty.sd = {{"collision.cushion_friction", 0.015}, {"contact.mu", 0.02}};
  std::mt19937_64 engine(7);
  std::normal_distribution<double> normal;
  constexpr int kDraws = 4000;
  double sum = 0, sum2 = 0, mu_sum = 0;
  for (int i = 0; i < kDraws; ++i) {
    const physics::ModelParameters s = SampledConstants(p, [&] { return normal(engine); });
    sum += s.collision.cushion_friction;
    sum2 += s.collision.cushion_friction * s.collision.cushion_friction;
    mu_sum += s.contact.mu;
    EXPECT_EQ(s.collision.cushion_restitution, p.collision.cushion_restitution);
    EXPECT_EQ(s.contact.d, p.contact.d);
  }
  const double mean = sum / kDraws;
  const double sd = std::sqrt(sum2 / kDraws - mean * mean);
  EXPECT_NEAR(mean, p.collision.cushion_friction, 4 * 0.015 / std::sqrt(kDraws));
  EXPECT_NEAR(sd, 0.015, 4 * 0.015 / std::sqrt(2.0 * kDraws));
  EXPECT_NEAR(mu_sum / kDraws, p.contact.mu, 4 * 0.02 / std::sqrt(kDraws));
}

// Near the range's end the normal is truncated: a restitution one sd below 1 never exceeds 1,
// and its draws are the normal's below 1 (mean value - sd phi(1) / Phi(1) = value - 0.2876 sd).
TEST(ConstantsUncertainty, DrawsStayInThePhysicalRange) {
  physics::ModelParameters p = LoadParameters("pool");
  p.collision.cushion_restitution = 0.95;
  p.uncertainty.sd = {{"collision.cushion_restitution", 0.05}};
  std::mt19937_64 engine(11);
  std::normal_distribution<double> normal;
  constexpr int kDraws = 4000;
  double sum = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double e = SampledConstants(p, [&] { return normal(engine); }).collision.cushion_restitution;
    ASSERT_LE(e, 1.0);
    sum += e;
  }
  const double phi1 = std::exp(-0.5) / std::sqrt(2 * M_PI);
  const double truncated_mean = 0.95 - 0.05 * phi1 / (0.5 * std::erfc(-1 / std::sqrt(2.0)));
  EXPECT_NEAR(sum / kDraws, truncated_mean, 4 * 0.05 / std::sqrt(kDraws));
}

TEST(ConstantsUncertainty, TheSameNumbersDrawTheSameTable) {
  const physics::ModelParameters pool = LoadParameters("pool");
  std::mt19937_64 a(3), b(3);
  std::normal_distribution<double> na, nb;
  const auto x = SampledConstants(pool, [&] { return na(a); });
  const auto y = SampledConstants(pool, [&] { return nb(b); });
  EXPECT_EQ(ParameterHash(x), ParameterHash(y));
  EXPECT_NE(ParameterHash(x), ParameterHash(pool));
}

}  // namespace
}  // namespace billiard::params
