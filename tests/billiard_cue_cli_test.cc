// `billiard simulate --cue` as a user runs it: a stroke instead of a launch, for one ball and for
// a scene's balls. The launches are held to Alciatore's closed forms (TP A.30 for a vertical
// offset, TP A.31's squirt for a side one) worked here from the parameter set's masses, and a
// stroke `billiard plan` prints is played back to its target.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "sim/params/parameter_sets.h"
#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

// The state right after the stroke (--t-end 0).
std::vector<double> Launch(const std::string& cue, const std::string& extra = "") {
  const std::string args = "simulate --cue " + cue + " --t-end 0 --json " + extra;
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args;
  return OneObject(r, args)["launch"].get<std::vector<double>>();
}

std::string Number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

TEST(BilliardSimulateCue, FollowAndDrawAreTheTipAboveAndBelowCentreAlongTheHeading) {
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius, m = p.ball.mass, M = p.cue.mass, e = p.cue.tip_restitution;
  const double V = 2.0, q = 0.5;
  // TP A.30: v = (1 + e) V / (1 + m / M + 5/2 q^2), and the spin of the same impulse about the
  // centre, w = 5/2 v q / r, about the axis across the travel.
  const double v = (1 + e) * V / (1 + m / M + 2.5 * q * q);
  const double w = 2.5 * v * q / r;
  const auto follow = Launch(Number(V) + ",0,0," + Number(q * r) + ",0");
  EXPECT_NEAR(follow[2], v, 1e-12);
  EXPECT_NEAR(follow[3], 0.0, 1e-12);
  // Along +x, rolling forward is wy = vx / r > 0: follow spins faster than that, draw backwards.
  EXPECT_NEAR(follow[5], w, 1e-9);
  EXPECT_GT(follow[5] * r, follow[2]);
  const auto draw = Launch(Number(V) + ",0,0," + Number(-q * r) + ",0");
  EXPECT_NEAR(draw[5], -w, 1e-9);
  // Heading +y (pi/2): the same follow is about -x (wx = -vy / r when rolling).
  const auto up = Launch(Number(V) + "," + Number(M_PI / 2) + ",0," + Number(q * r) + ",0");
  EXPECT_NEAR(up[3], v, 1e-12);
  EXPECT_NEAR(up[2], 0.0, 1e-12);
  EXPECT_NEAR(up[4], -w, 1e-9);
  // Struck where --at says.
  const auto at = Launch(Number(V) + ",0,0,0,0", "--at 1.5,0.25");
  EXPECT_EQ(at[0], 1.5);
  EXPECT_EQ(at[1], 0.25);
}

TEST(BilliardSimulateCue, RightEnglishSpinsCounterclockwiseAndSquirtsTheBallLeft) {
  const physics::ModelParameters& p = Pool();
  const double q = 0.4;
  const auto right = Launch("2,0," + Number(q * p.ball.radius) + ",0,0");
  EXPECT_GT(right[6], 0.0);  // wz > 0: counterclockwise seen from above
  EXPECT_GT(right[3], 0.0);  // the launch turned left of the heading (+y)
  // TP A.31: tan(alpha) = 5/2 q sqrt(1 - q^2) / (1 + m / m_e + 5/2 (1 - q^2)).
  const double squirt = std::atan(2.5 * q * std::sqrt(1 - q * q) /
                                  (1 + p.ball.mass / p.cue.end_mass + 2.5 * (1 - q * q)));
  EXPECT_NEAR(std::atan2(right[3], right[2]), squirt, 1e-12);
  const auto left = Launch("2,0," + Number(-q * p.ball.radius) + ",0,0");
  EXPECT_LT(left[6], 0.0);
  EXPECT_NEAR(std::atan2(left[3], left[2]), -squirt, 1e-12);
}

TEST(BilliardSimulateCue, ThePlannersStrokePlayedBackArrivesAtItsTarget) {
  const std::string plan_args = "plan --from 0.5,0.5 --to 1.5,0.8 --spin draw --json";
  const CommandResult planned = Billiard(plan_args);
  ASSERT_EQ(planned.status, 0) << planned.out;
  const nlohmann::json c = OneObject(planned, plan_args)["cue"];
  const std::string args = "simulate --cue " + Number(c["speed"]) + "," + Number(c["heading"]) +
                           "," + Number(c["tip_side"]) + "," + Number(c["tip_height"]) + "," +
                           Number(c["elevation"]) + " --at 0.5,0.5 --until-speed 0 --t-end 20 " +
                           "--json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto state = OneObject(r, args)["state"].get<std::vector<double>>();
  EXPECT_NEAR(state[0], 1.5, 1e-4);
  EXPECT_NEAR(state[1], 0.8, 1e-4);
}

std::string WriteScene(const std::string& name, const nlohmann::json& scene) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << scene.dump();
  return path;
}

TEST(BilliardSimulateCue, StrikesAScenesBallFromTheFileOrTheCommandLine) {
  nlohmann::json scene = {{"table", "pool-9ft"}, {"params", "pool"}};
  scene["balls"] = {{{"id", 0}, {"state", {0.6, 0.6, 0, 0, 0, 0, 0}}},
                    {{"id", 1}, {"state", {1.6, 0.6, 0, 0, 0, 0, 0}}}};
  const std::string plain = WriteScene("cue_plain.json", scene);
  scene["balls"][0]["cue"] = {{"speed", 3.0}, {"heading", 0.0}, {"tip_height", -0.01}};
  const std::string struck = WriteScene("cue_struck.json", scene);
  const auto run = [](const std::string& args) {
    const CommandResult r = Billiard(args);
    EXPECT_EQ(r.status, 0) << args << ": " << r.out;
    return OneObject(r, args);
  };
  const nlohmann::json from_file = run("simulate --scene " + struck + " --json");
  const nlohmann::json from_option =
      run("simulate --scene " + plain + " --cue 3,0,0,-0.01,0 --json");
  EXPECT_EQ(from_file["balls"], from_option["balls"]);
  // The cue ball, drawn, hits ball 1 full and comes back: it ends left of where it started.
  EXPECT_EQ(from_file["events"][0]["type"], "ball_ball");
  EXPECT_LT(from_file["balls"][0]["state"][0].get<double>(), 0.6);
  // A struck ball must be at rest; a stroke no cue gives is refused; one line each, exit 2.
  scene["balls"][0]["state"][2] = 1.0;
  const CommandResult moving =
      Billiard("simulate --scene " + WriteScene("cue_moving.json", scene) + " --json", true);
  EXPECT_EQ(moving.status, 2);
  EXPECT_NE(moving.out.find("ball 0: a struck ball starts at rest"), std::string::npos)
      << moving.out;
  const CommandResult miscue = Billiard("simulate --cue 2,0,0.03,0,0 --t-end 1", true);
  EXPECT_EQ(miscue.status, 2);
  EXPECT_NE(miscue.out.find("--cue: tip offset"), std::string::npos) << miscue.out;
  const CommandResult both = Billiard("simulate --cue 2,0,0,0,0 --state 0,0,1,0,0,0,0 --t-end 1");
  EXPECT_EQ(both.status, 2);
  for (const auto& r : {moving, miscue}) {
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
}

// Without --json a scene prints a table of its balls on stderr: where each ended, which dropped
// where, and the models it ran with.
TEST(BilliardSimulateScene, PrintsAReadableTableOfTheBallsAndTheModels) {
  nlohmann::json scene = {{"table", "pool-9ft"}, {"params", "pool"}};
  // Ball 5 sent straight into the lower-left corner pocket; ball 7 left alone.
  scene["balls"] = {{{"id", 5}, {"state", {0.4, 0.4, -1.5, -1.5, 0, 0, 0}}},
                    {{"id", 7}, {"state", {1.2, 0.7, 0, 0, 0, 0, 0}}}};
  // Nothing on stdout without --json: what is read is stderr.
  const CommandResult r = Billiard("simulate --scene " + WriteScene("table.json", scene), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("models: motion auto"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cushion mathavan-2010"), std::string::npos) << r.out;
  std::istringstream lines(r.out);
  std::string line;
  bool saw5 = false, saw7 = false;
  while (std::getline(lines, line)) {
    std::istringstream row(line);
    int id;
    double x0, y0, x1, y1;
    char comma;
    if (!(row >> id >> x0 >> comma >> y0 >> x1 >> comma >> y1)) continue;
    if (id == 5) {
      saw5 = true;
      EXPECT_NE(line.find("lower_left at"), std::string::npos) << line;
    } else if (id == 7) {
      saw7 = true;
      EXPECT_DOUBLE_EQ(x1, 1.2);
      EXPECT_DOUBLE_EQ(y1, 0.7);
      EXPECT_EQ(line.substr(line.size() - 1), "-") << line;
    }
  }
  EXPECT_TRUE(saw5 && saw7) << r.out;
}

}  // namespace
}  // namespace billiard::testing
