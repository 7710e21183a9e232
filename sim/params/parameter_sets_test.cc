// Parameter sets as data: the built-in sets, files, and the rejection of bad values.
#include "sim/params/parameter_sets.h"

#include <gtest/gtest.h>

#include <array>
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

// ParametersJson writes what ParseParameters reads back to the same numbers, bit for bit, with a
// "fit" report that the physics does not read.
TEST(Parameters, WriteWhatTheyReadWithAFitReport) {
  for (const std::string& name : BuiltinParameterSetNames()) {
    const physics::ModelParameters p = LoadParameters(name);
    const physics::ModelParameters back =
        ParseParameters(ParametersJson(p, R"({"how": "by hand"})"), "x");
    EXPECT_EQ(ParameterHash(back), ParameterHash(p)) << name;
    EXPECT_EQ(back.name, p.name);
    EXPECT_EQ(back.source, p.source);
  }
  EXPECT_THROW(ParseParameters(R"({"fit": 3})", "x"), std::invalid_argument);
}

// The carom set identified from tracked shots (docs/identification.md) is the carom set with its
// cloth, cushion and ball constants changed, and nothing else.
TEST(Parameters, TheFittedCaromSetChangesOnlyItsFittedConstants) {
  const physics::ModelParameters carom = LoadParameters("carom");
  physics::ModelParameters fitted = LoadParameters("carom-fitted");
  EXPECT_EQ(fitted.name, "carom-fitted");
  EXPECT_NE(fitted.source.find("tailuge/billiards"), std::string::npos);
  EXPECT_NE(ParameterHash(fitted), ParameterHash(carom));
  fitted.contact.mu = carom.contact.mu;
  fitted.contact.d = carom.contact.d;
  fitted.contact.patch_radius = carom.contact.patch_radius;
  fitted.collision.cushion_restitution = carom.collision.cushion_restitution;
  fitted.collision.cushion_friction = carom.collision.cushion_friction;
  fitted.collision.ball_restitution = carom.collision.ball_restitution;
  EXPECT_EQ(ParameterHash(fitted), ParameterHash(carom));
}

TEST(Parameters, LoadsAFile) {
  const std::string path = ::testing::TempDir() + "/custom_params.json";
  std::ofstream(path) << R"({"name":"mine","ball":{"radius":0.03,"mass":0.2,"gravity":9.8},
    "contact":{"patch_radius":0.002,"mu":0.15,"d":0.5,"eps_t":0.01,"eps_r":0.02,
               "b_t":0.7,"m_t":2,"b_m":0.5,"m_m":2},
    "cue":{"mass":0.5,"tip_restitution":0.8,"max_tip_offset":0.5,"max_speed":5,
           "end_mass":0.01},
    "collision":{"ball_restitution":0.95,"ball_friction_a":0.01,"ball_friction_b":0.108,
                 "ball_friction_c":1.088,"cushion_restitution":0.9,"cushion_friction":0.2},
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
    "cue":{"mass":0.5,"tip_restitution":E,"max_tip_offset":0.5,"max_speed":5,
           "end_mass":0.01},
    "collision":{"ball_restitution":0.95,"ball_friction_a":0.01,"ball_friction_b":0.108,
                 "ball_friction_c":1.088,"cushion_restitution":0.9,"cushion_friction":0.2},
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

// A valid set as JSON, with `extra` spliced into its contact section.
std::string SetWithContact(const std::string& extra) {
  return R"({"name":"mine","ball":{"radius":0.03,"mass":0.2,"gravity":9.8},
    "contact":{"patch_radius":0.002,"mu":0.15,"d":0.5,"eps_t":0.01,"eps_r":0.02,
               "b_t":0.7,"m_t":2,"b_m":0.5,"m_m":2)" +
         extra + R"(},
    "cue":{"mass":0.5,"tip_restitution":0.8,"max_tip_offset":0.5,"max_speed":5,
           "end_mass":0.01},
    "collision":{"ball_restitution":0.95,"ball_friction_a":0.01,"ball_friction_b":0.108,
                 "ball_friction_c":1.088,"cushion_restitution":0.9,"cushion_friction":0.2},
    "table":{"length":2.84,"width":1.42}})";
}

// The reason ParseParameters gives for `json`, "" if it takes it.
std::string Refusal(const std::string& json) {
  try {
    ParseParameters(json, "t.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, RefusesAnUnknownKeyNamingIt) {
  EXPECT_EQ(Refusal(SetWithContact("")), "");
  const std::string misspelt = Refusal(SetWithContact(R"(,"muu":0.3)"));
  EXPECT_NE(misspelt.find("t.json"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("contact.muu"), std::string::npos) << misspelt;
  std::string top = SetWithContact("");
  top.insert(1, R"("colour":"green",)");
  EXPECT_NE(Refusal(top).find("colour"), std::string::npos) << Refusal(top);
}

TEST(Parameters, RefusesAWrongTypeNamingTheKeyAndTheType) {
  std::string text = SetWithContact("");
  text.replace(text.find(R"("mu":0.15)"), 9, R"("mu":"0.2")");
  const std::string why = Refusal(text);
  EXPECT_NE(why.find("contact.mu"), std::string::npos) << why;
  EXPECT_NE(why.find("string"), std::string::npos) << why;
  EXPECT_EQ(why.find("missing"), std::string::npos) << why;
  std::string name = SetWithContact("");
  name.replace(name.find(R"("mine")"), 6, "7");
  EXPECT_NE(Refusal(name).find("name"), std::string::npos) << Refusal(name);
}

TEST(Parameters, ASetReadFromAFileNamesTheFile) {
  const std::string path = ::testing::TempDir() + "/named_params.json";
  std::ofstream(path) << SetWithContact("");
  const physics::ModelParameters p = LoadParameters(path);
  EXPECT_EQ(p.file, path);
  EXPECT_EQ(ParameterSetLabel(p), "mine (" + path + ")");
  EXPECT_EQ(LoadParameters("pool").file, "");
  EXPECT_EQ(ParameterSetLabel(LoadParameters("pool")), "pool");
  std::remove(path.c_str());
}

TEST(Parameters, TheHashIsTheSameForTheSameNumbersWhateverTheName) {
  const physics::ModelParameters pool = LoadParameters("pool");
  physics::ModelParameters renamed = pool;
  renamed.name = "my pool";
  renamed.file = "/somewhere/pool.json";
  EXPECT_EQ(ParameterHash(renamed), ParameterHash(pool));
  EXPECT_EQ(ParameterHash(pool).size(), 16u);
  EXPECT_NE(ParameterHash(LoadParameters("paper")), ParameterHash(pool));
  for (std::size_t i = 0; i < physics::kParameterCount; ++i) {
    // Any one number moved by one part in 1e15 is other physics.
    physics::ModelParameters moved = pool;
    physics::CollisionParameters& k = moved.collision;
    const std::array<double*, physics::kParameterCount> fields = {
        &moved.ball.radius,        &moved.ball.mass,
        &moved.ball.gravity,       &moved.contact.patch_radius,
        &moved.contact.mu,         &moved.contact.d,
        &moved.contact.eps_t,      &moved.contact.eps_r,
        &moved.contact.b_t,        &moved.contact.m_t,
        &moved.contact.b_m,        &moved.contact.m_m,
        &moved.cue.mass,           &moved.cue.tip_restitution,
        &moved.cue.max_tip_offset, &moved.cue.max_speed,
        &moved.cue.end_mass,       &k.ball_restitution,
        &k.ball_friction_a,        &k.ball_friction_b,
        &k.ball_friction_c,        &k.cushion_restitution,
        &k.cushion_friction,       &moved.table.length,
        &moved.table.width};
    ASSERT_NE(fields[i], nullptr) << "number " << i << " is not in the list above";
    *fields[i] *= 1.0 + 1e-15;
    EXPECT_NE(ParameterHash(moved), ParameterHash(pool)) << "number " << i;
  }
}

}  // namespace
}  // namespace billiard::params
