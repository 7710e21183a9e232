// --model auto against the measured table: properties any sane table must give.
#include "sim/model_choice/model_choice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/physics/testing/test_support.h"

namespace billiard::model_choice {
namespace {

const double kAccuracies[] = {1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0};

TEST(ModelChoice, ClassifiesScenes) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  const auto figures = physics::testing::PaperFigureStates();
  EXPECT_EQ(SceneKindOf(figures[0], p), "rolling");
  EXPECT_EQ(SceneKindOf(figures[1], p), "sliding");
  EXPECT_EQ(SceneKindOf(figures[3], p), "side-spin");
}

TEST(ModelChoice, SideSpinNeverGetsTheClosedForm) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  for (double accuracy : kAccuracies) {
    EXPECT_NE(ChooseModel(physics::testing::PaperFigureStates()[4], p, accuracy).options.model,
              physics::Model::kClosedForm)
        << accuracy;
  }
}

TEST(ModelChoice, LooseAccuracyWithoutSideSpinDoesNotPayForTheFiveDofModel) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  EXPECT_EQ(ChooseModel(physics::testing::PaperFigureStates()[0], p, 1e-3).options.model,
            physics::Model::kClosedForm);
  EXPECT_EQ(ChooseModel(physics::testing::PaperFigureStates()[1], p, 10.0).options.model,
            physics::Model::kClosedForm);
}

TEST(ModelChoice, ChoiceMeetsTheAccuracyAndTighterNeverCostsLess) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  for (const physics::BallState& s : physics::testing::PaperFigureStates()) {
    double previous_us = INFINITY;
    for (double accuracy : kAccuracies) {
      const ModelChoice c = ChooseModel(s, p, accuracy);
      if (c.accuracy_met) {
        EXPECT_LE(c.expected_error_m, accuracy);
      }
      EXPECT_LE(c.expected_us, previous_us * (1 + 1e-12)) << accuracy;
      previous_us = c.expected_us;
    }
  }
}

TEST(ModelChoice, ImpossibleAccuracyFallsBackToTheMostAccurateAndSaysSo) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  const ModelChoice c = ChooseModel(physics::testing::PaperFigureStates()[3], p, 1e-15);
  EXPECT_FALSE(c.accuracy_met);
  EXPECT_EQ(c.options.model, physics::Model::kIntegral);
}

TEST(ModelChoice, RejectsNonsenseAccuracy) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    EXPECT_THROW(ChooseModel(physics::testing::PaperFigureStates()[0], p, bad),
                 std::invalid_argument);
  }
}

}  // namespace
}  // namespace billiard::model_choice
