#include "sim/batch/simulate_batch.h"

namespace billiard::batch {

std::vector<JobResult<physics::SimulationResult>> SimulateBatch(
    const physics::ModelParameters& params, const std::vector<BatchShot>& shots,
    const physics::SimulationOptions& options, ThreadPool& pool, const Progress& progress) {
  return pool.Map(
      shots.size(),
      [&](std::size_t i) {
        return physics::Simulate(params, shots[i].initial, shots[i].t_end, options);
      },
      progress);
}

std::vector<JobResult<physics::SimulationResult>> SimulateBatch(
    const physics::ModelParameters& params, const std::vector<BatchShot>& shots,
    const physics::SimulationOptions& options, int threads) {
  ThreadPool pool(threads);
  return SimulateBatch(params, shots, options, pool);
}

}  // namespace billiard::batch
