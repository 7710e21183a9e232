// Parameter sets as data: the built-in sets, files, and the rejection of bad values.
#include "sim/params/parameter_sets.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace billiard::params {
namespace {

TEST(Parameters, PaperSetHoldsTheValuesOfFiguresSixToTen) {
  const physics::ModelParameters p = LoadParameters("paper");
  EXPECT_EQ(p.contact.patch_radius, 0.003);
  EXPECT_EQ(p.contact.mu, 0.2);
  EXPECT_EQ(p.contact.d, 1.0);
  EXPECT_EQ(p.contact.eps_t, 0.01);
  EXPECT_EQ(p.contact.eps_r, 0.01);
  EXPECT_EQ(p.ball.gravity, 9.81);
  EXPECT_EQ(p.ball.radius, 0.02);
  EXPECT_EQ(p.contact.b_t, 0.68102);
  EXPECT_EQ(p.contact.b_m, 0.480909);
  EXPECT_EQ(p.contact.m_t, 2.0);
  EXPECT_EQ(p.contact.m_m, 2.0);
}

TEST(Parameters, PoolSetIsARegulationBallWithTypicalClothValues) {
  const physics::ModelParameters p = LoadParameters("pool");
  EXPECT_EQ(p.ball.radius, 0.028575);
  EXPECT_EQ(p.ball.mass, 0.17);
  EXPECT_NEAR(p.RollingResistance(), 0.01, 1e-12);
  EXPECT_FALSE(p.source.empty());
}

TEST(Parameters, BuiltinNamesAreListed) {
  const auto names = BuiltinParameterSetNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "paper"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "pool"), names.end());
}

TEST(Parameters, LoadsAFile) {
  const std::string path = ::testing::TempDir() + "/custom_params.json";
  std::ofstream(path) << R"({"name":"mine","ball":{"radius":0.03,"mass":0.2,"gravity":9.8},
    "contact":{"patch_radius":0.002,"mu":0.15,"d":0.5,"eps_t":0.01,"eps_r":0.02,
               "b_t":0.7,"m_t":2,"b_m":0.5,"m_m":2},
    "cue":{"mass":0.5,"tip_restitution":0.8,"max_tip_offset":0.5,"max_speed":5},
    "table":{"length":2.84,"width":1.42}})";
  const physics::ModelParameters p = LoadParameters(path);
  EXPECT_EQ(p.name, "mine");
  EXPECT_EQ(p.contact.eps_r, 0.02);
  EXPECT_EQ(p.cue.tip_restitution, 0.8);
  EXPECT_EQ(p.table.length, 2.84);
  std::remove(path.c_str());
}

TEST(Parameters, RejectsUnknownNamesBadJsonMissingFieldsAndBadValues) {
  EXPECT_THROW(LoadParameters("no-such-set"), std::invalid_argument);
  EXPECT_THROW(ParseParameters("{", "t"), std::invalid_argument);
  EXPECT_THROW(ParseParameters(R"({"ball":{}})", "t"), std::invalid_argument);
  const std::string good = R"({"ball":{"radius":0.03,"mass":0.2,"gravity":9.8},
    "contact":{"patch_radius":0.002,"mu":0.15,"d":D,"eps_t":0.01,"eps_r":0.02,
               "b_t":0.7,"m_t":2,"b_m":0.5,"m_m":2},
    "cue":{"mass":0.5,"tip_restitution":E,"max_tip_offset":0.5,"max_speed":5},
    "table":{"length":2.84,"width":1.42}})";
  const auto with = [&](const std::string& d, const std::string& e) {
    std::string s = good;
    s.replace(s.find("D"), 1, d);
    s.replace(s.find("E"), 1, e);
    return s;
  };
  const auto with_d = [&](const std::string& d) { return with(d, "0.8"); };
  EXPECT_NO_THROW(ParseParameters(with_d("0.5"), "t"));
  EXPECT_THROW(ParseParameters(with_d("1.5"), "t"), std::invalid_argument);
  EXPECT_THROW(ParseParameters(with_d("\"x\""), "t"), std::invalid_argument);
  EXPECT_THROW(ParseParameters(with("0.5", "1.2"), "t"), std::invalid_argument);
  EXPECT_THROW(ParseParameters(good.substr(0, good.find(",\n    \"cue\"")) + "}", "t"),
               std::invalid_argument);
}

}  // namespace
}  // namespace billiard::params
