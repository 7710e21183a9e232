#include "planner/choice/screening.h"

#include <algorithm>

namespace billiard::choice {

Tally TallyOf(const std::vector<Execution>& executions, std::size_t k, int samples) {
  int successes = 0;
  double value_sum = 0.0;
  for (int s = 0; s < samples; ++s) {
    const Execution& e = executions[k * samples + s];
    successes += e.potted;
    value_sum += e.next_value;
  }
  return {Binomial(successes, samples), successes > 0 ? value_sum / successes : 0.0};
}

double Score(const Tally& tally, bool lookahead) {
  return lookahead ? tally.pots.probability * (1 + tally.next_shot_value) : tally.pots.probability;
}

int Screen(const table::TableGeometry& table, const physics::ModelParameters& params,
           const std::vector<table::SceneBall>& balls, const std::vector<std::size_t>& which,
           const ChoiceOptions& options, batch::ThreadPool& pool, std::vector<Candidate>* candidates) {
  const std::vector<Execution> screened =
      ExecuteAll(table, params, balls, PlansOf(*candidates, which), options.screen_samples,
                 options, {}, options.lookahead, pool);
  for (std::size_t k = 0; k < which.size(); ++k) {
    Candidate& c = (*candidates)[which[k]];
    const Tally tally = TallyOf(screened, k, options.screen_samples);
    c.screen_probability = tally.pots.probability;
    c.score = Score(tally, options.lookahead);
  }
  return static_cast<int>(screened.size());
}

bool ScreenedBetter(const Candidate& a, const Candidate& b) {
  if (a.score != b.score) return a.score > b.score;
  return std::min(a.plan.margin_left_deg, a.plan.margin_right_deg) >
         std::min(b.plan.margin_left_deg, b.plan.margin_right_deg);
}

}  // namespace billiard::choice
