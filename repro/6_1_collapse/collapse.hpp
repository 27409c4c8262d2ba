// Paper A Sect. 6.1 (collapse.cpp says what it reproduces): the measures of
// a run, one case's run (with or without its output files), the renumbered
// reruns and the criteria of the claim rows, here so that the negative
// controls (controls.cpp beside it) apply the same criteria to
// deliberately wrong configurations.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "dda/joint_sets.hpp"
#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"

namespace collapse61 {

inline constexpr double kSeriesEvery = 0.05;  // s
inline constexpr double kFrameEvery = 0.1;    // s
inline constexpr double kPaperTimes[] = {2.5, 5.0, 7.5};  // s, Fig. 20's snapshots
inline constexpr double kFrictions[2] = {15.0, 30.0};     // deg, joint friction of cases 1 and 2
// The block numberings of the round-off check: as generated, then by
// increasing centroid x and y.
inline constexpr const char* kNumberings[] = {"generator", "x", "y"};

struct Sample {
  double t = 0.0;
  double front_x = 0.0;      // largest vertex x of a rock block, m
  double front_cx = 0.0;     // largest centroid x, m
  double mean_drop = 0.0;    // mass-weighted mean centroid drop, m
  double max_travel = 0.0;   // largest centroid travel, m
  double runout_mass = 0.0;  // share of the rock mass with centroid x > column width
  double kinetic = 0.0, total = 0.0, gravity = 0.0;  // J per m
  double dt_ratio = 0.0;     // dt / current critical step
};

struct CaseResult {
  int index = 0;
  double friction = 0.0;
  int blocks = 0, dropped = 0;
  double dropped_area = 0.0, region_area = 0.0, h = 0.0, dt = 0.0, dt_ratio0 = 0.0, dt_ratio_max = 0.0;
  double duration = 0.0, wall = 0.0;
  long long steps = 0;
  std::string stopped;  // the solver's message if a stability guard stopped the run; empty: ran to the end
  std::vector<Sample> series;
  // The sample nearest to time t (the series is every 0.05 s).
  const Sample& at(double t) const;
};

// "%.1f" of a time (file names and row texts).
std::string time_tag(double t);

// The scene of case k's friction, run to `duration`, with the rotation update.
dda::paper::Collapse scene(double friction, double duration, dda::RotationUpdate rotation);

// Runs case k of `col` (its joint friction and duration are the scene's):
// the series every kSeriesEvery; with a non-empty `dir` also the output files
// (dir/case<k>/{series,frames,blocks}.csv, dir/vtk/). A stability guard's stop
// (dda::SimulationError) ends the run and is kept in `stopped`.
CaseResult run_case(int k, const dda::paper::Collapse& col, int threads, const std::string& dir);

// Case k of `col` rerun with the rock blocks numbered by increasing centroid
// coordinate `axis` (0: x, 1: y; stable, so ties keep the generator's order):
// the same blocks, joints and boundaries. Returns the end state's measures.
Sample rerun_renumbered(int k, dda::paper::Collapse col, int threads, int axis);

// The column recut by other joint sets, slivers below min_area dropped (for
// the controls of the generator row).
dda::paper::Collapse recut(dda::paper::Collapse col, const std::vector<dda::JointSet>& sets, double min_area);

// Output files: summary.csv, boundaries.csv and renumbered.csv under dir.
using Ends = std::array<std::array<Sample, 2>, 3>;  // [numbering][case - 1] (kNumberings)
void write_summary(const std::string& dir, const std::vector<CaseResult>& runs);
void write_boundaries(const std::string& dir);
void write_renumbered(const std::string& dir, const Ends& ends);

// ---- criteria of the claim rows ---------------------------------------------
// Generator: dt/dt_crit < kStartRatio at start (against the a-priori bound
// predicted_critical_step) and < 1 throughout (live contacts); the dropped
// slivers < kDroppedShare of the region.
inline constexpr double kStartRatio = 0.6;
inline constexpr double kDroppedShare = 0.01;
bool generator_ok(const CaseResult& r);

// Energy: friction only removes it. The largest rise of the total above the
// start is compared with the potential energy released by the end; a run a
// guard stopped fails.
inline constexpr double kEnergyRise = 0.01;  // of the released potential energy
struct EnergyBudget {
  double rise = 0.0, released = 0.0, change = 0.0;  // J/m
  bool pass = false;
};
EnergyBudget energy_budget(const CaseResult& r);

// The lower-friction case (a) must lead the other (b) by more than one joint
// spacing (kLead of front, and kDropFactor of the mean drop) at
// faster_time(duration): a smaller gap could be one block bouncing ahead,
// not a faster collapse of the mass.
inline constexpr double kLead = 2.5;         // m: the 40 deg set's spacing
inline constexpr double kDropFactor = 1.1;
inline constexpr double kFasterAt = 2.5;     // s: Fig. 20 a/b
inline double faster_time(double duration) { return duration < kFasterAt ? duration : kFasterAt; }
bool collapses_faster(const Sample& a, const Sample& b);
// How many samples after kStanding (both columns still standing before: the
// fronts equal) have a's front ahead or level.
inline constexpr double kStanding = 0.5;  // s
struct FrontLead {
  int ahead = 0, compared = 0;
};
FrontLead front_lead(const CaseResult& a, const CaseResult& b);

// Runout: a's front > b's + kLead and a's runout mass > b's.
bool runs_out_further(const Sample& a, const Sample& b);
// Round-off: runs_out_further(case 1, case 2) in every numbering.
bool ordering_survives(const Ends& ends);

// ---- the negative controls (controls.cpp beside it) named by the rows
inline constexpr const char* kControlGenerator =
    "6.1 generator: FAIL without the sliver filter and with the joint spacings a third";
inline constexpr const char* kControlStable = "6.1 stable run: FAIL with dt twice the critical step";
inline constexpr const char* kControlFaster = "6.1 faster collapse: FAIL with the friction swapped between the cases";
inline constexpr const char* kControlRunout = "6.1 runout: FAIL with the friction swapped between the cases";
inline constexpr const char* kControlRenumbered =
    "6.1 renumbering: FAIL when the cases' order flips in one numbering";
inline std::string control(const char* name) { return repro::control_test(name); }

}  // namespace collapse61
