// The table simulation on scenes at its degenerate edges (sim/table/testing/degenerate_scenes.h):
// balls frozen to the cushions and to each other, a cue ball along a cushion it touches, into a
// chain, grazing a ball, with every spin, drawn from the fuzzer's bytes. Every such scene is
// valid, so every run must end without an exception and keep the invariants: no overlap beyond
// the contact tolerance (the 5-DOF model's, for `auto`: what its pushes allow), no ball off the
// surface unpocketed, the energy never rising.
#include <algorithm>
#include <cstring>
#include <random>

#include "fuzz/support.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/contact_search.h"
#include "sim/table/table_simulation.h"
#include "sim/table/testing/degenerate_scenes.h"

namespace billiard::fuzz {
namespace {

// A run under the sanitizers is some 20 times slower than in the build: the 5-DOF model is run
// for this long of a scene, the closed form to rest.
constexpr double kFiveDofSeconds = 1.0;
// The closed form takes at most a few hundred events for a break.
constexpr std::int64_t kEventBudget = 200000;
constexpr double kSampleStep = 1e-2;  // [s]
constexpr double kFiveDofOverlap = 1e-5;  // [m], as sim/table/degenerate_scenes_test.cc holds

// Draws from the input's bytes, two at a time, then from a generator seeded by its length.
class ByteDraws {
 public:
  ByteDraws(const std::uint8_t* data, std::size_t size) : data_(data), size_(size), rng_(size) {}
  double operator()() {
    if (at_ + 2 <= size_) {
      const unsigned v = data_[at_] | (static_cast<unsigned>(data_[at_ + 1]) << 8);
      at_ += 2;
      return v / 65536.0;
    }
    return static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 1;  // byte 0 chooses the motion
  std::mt19937_64 rng_;
};

}  // namespace

std::vector<Bytes> Seeds() {
  std::vector<Bytes> seeds;
  for (std::uint8_t mode : {0, 3}) {
    for (int k = 0; k < 4; ++k) {
      Bytes b(64);
      b[0] = mode;
      std::mt19937 rng(k);
      for (std::size_t i = 1; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(rng());
      seeds.push_back(b);
    }
  }
  return seeds;
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace billiard;
  if (size < 1) return 0;
  static const physics::ModelParameters p = params::LoadParameters("pool");
  static const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  fuzz::ByteDraws draws(data, size);
  const table::testing::Uniform uniform = [&draws] { return draws(); };
  const std::vector<table::SceneBall> balls =
      table::testing::DegenerateScene(geometry, p.ball.radius, uniform);
  const bool five_dof = data[0] % 4 == 3;
  table::TableSimulationOptions options =
      table::testing::MotionOptions(five_dof ? "auto" : "closed-form", p);
  options.max_events = fuzz::kEventBudget;
  try {
    table::TableSimulation sim(geometry, p, balls, options);
    sim.Run(five_dof ? fuzz::kFiveDofSeconds : INFINITY);
    const table::testing::SceneInvariants kept =
        table::testing::MeasureInvariants(sim, geometry, p, fuzz::kSampleStep);
    const double bound = five_dof ? fuzz::kFiveDofOverlap : 2.0 * table::kContactTolerance;
    if (kept.overlap > bound) fuzz::Fail("balls overlap by " + std::to_string(kept.overlap) + " m");
    if (kept.off_surface > bound) {
      fuzz::Fail("a ball is " + std::to_string(kept.off_surface) + " m off the surface");
    }
    if (kept.energy_rise > 1e-9) {
      fuzz::Fail("the energy rose by " + std::to_string(kept.energy_rise) + " of itself");
    }
  } catch (const std::exception& e) {
    fuzz::Fail(std::string("a valid scene failed: ") + e.what());
  }
  return 0;
}
