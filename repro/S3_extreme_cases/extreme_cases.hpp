// S3 extreme cases (extreme_cases.cpp says what they are and expect): the
// cases (cases.cpp), one run (run.cpp) and the row criteria (criteria.cpp),
// declared here so that the negative controls
// (controls.cpp beside it) apply the same criteria to deliberately
// wrong configurations.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"

namespace s3 {
using dda::Vec2;
using repro::format_short;
using repro::stab::RunClass;

inline std::string num(double x) { return repro::format_full(x); }

// One impact of two blocks, A (block 0) moving into B at rest along x.
struct Extreme {
  std::string name, parameter;
  dda::Scene scene;
  double duration = 1.0;
  double va_expected = 0.0, vb_expected = 0.0;  // x-velocities after the impact (rigid 1D elastic)
  double v0 = 1.0;
};

// Mass ratios, impact speeds, a size ratio, slivers, a deep penetration.
std::vector<Extreme> cases();


struct Outcome {
  RunClass cls = RunClass::kStable;
  double dt = 0.0, ratio0 = 0.0, ratio_max = 0.0;
  double momentum_error = 0.0, energy_error = 0.0;
  double va = 0.0, vb = 0.0, velocity_error = 0.0;
  double overlap = 0.0;  // deepest overlap thickness / smaller inscribed diameter
  double t_deep = -1.0, t_wrong = -1.0, t_swap = -1.0, t_soft = -1.0;
  bool penetration_stop = false;  // the penetration guard stopped the run
  std::string message;
  const char* class_name() const { return penetration_stop ? "penetration guard stop" : repro::stab::class_name(cls); }
};

// Runs e at dt = dt_fraction x the predicted critical step (0: the scene's
// dt), watching momentum, energy, overlap, softening, wrong-way forces and
// crossing; a guard stop ends it with its message.
Outcome run(const Extreme& e, double dt_fraction);

// The row criterion: a clean run (stable, velocities within 5 % of the
// rigid answer) at a dt below dt_crit, a guard stop naming dt/dt_crit above
// it; the deep cases (the contact cannot stop the blocks: their approach
// energy exceeds what the pair can store) must be stopped by the
// penetration guard before the blocks cross. A run in which the centroids
// swapped (the blocks passed through each other) never passes. Returns the
// verdict and the criterion in words.
std::pair<bool, std::string> row_verdict(const Extreme& e, const Outcome& o);
inline const char* const kRowControl =
    "repro_controls: S3 rows: FAIL with the penetration guard off and with the wrong expected velocities";

// ---- the guard row: a too-large dt is stopped with a full message ----------

// Two squares at 1 m/s, 1 mm apart, kn 1e10 Pa, dt = dt_fraction x the
// predicted critical step (the row: 3), the energy checked every step so
// that the stop comes during the impact.
dda::Scene guard_scene(double dt_fraction);

// The row's criterion: the solver stopped the run with a message naming the
// step, the time, the block, the pair, dt/dt_crit and what was exceeded (a
// guard limit, or a non-finite or collapsed state), and at least one row
// was written before the stop.
bool guard_stop_complete(const std::string& message, long rows_kept);
inline constexpr const char* kControlGuardStop = "S3 guard stop: FAIL below the critical step and on a bare message";

// A guarded run's series: `sim` stepped to `duration`, after every step one
// row (time, x_A, x_B, vx_A, vx_B, total_energy) written to `path`. A guard
// stop (dda::SimulationError) ends the run; the rows written so far are
// committed either way, all finite (the table refuses NaN and the guard
// stops before a non-finite state is reported).
struct Series {
  std::string message;  // the guard's stop message; empty: the run finished
  std::size_t rows = 0;
};
Series guarded_series(dda::Simulation& sim, double duration, const std::string& path, const std::string& comment);

}  // namespace s3
