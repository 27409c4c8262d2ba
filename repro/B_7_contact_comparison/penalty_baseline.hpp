// B-7's fourth model "P": the conventional node-to-edge penalty contact on
// the same CST blocks as B and B0 (dda::cdem ContactMode::kNodeToEdgePenalty,
// lib/cdem/src/model_penalty.cpp), the method Paper B argues against, as a
// baseline. Same scenes, meshes and dt sweeps as B0; kn =
// E / 100 of the scene's material (0.4 GPa on the prisms, 10 MPa on the
// squares: the kn of A), frictionless, undamped.
// The runs (run.cpp) and the criteria of P's rows (criteria.cpp) are
// declared here so that the negative controls
// (controls.cpp beside this file) apply the same criteria; the rows
// are written by penalty_baseline.cpp.
#pragma once
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "repro/B_7_contact_comparison/contact_comparison.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/cli.hpp"

namespace compare {

// The scene's CDEM blocks (B0's mesh) with the node-to-edge penalty contact;
// kn = kn_factor x E / 100.
dda::cdem::CdemScene penalty_scene(const SceneDef& def, double kn_factor = 1.0);

// One P run: as run_cdem, the touch time being the first step end with a
// penalty spring (a node behind an edge), the contact lasting to the last
// one; the energy includes the springs' kn g^2 / 2.
Result run_penalty(const SceneDef& def, double dt, History* hist);

// P over the scene's dt sweep (or its base dt only), errors as run_sweep's.
std::vector<Result> penalty_sweep(const SceneDef& def, History* hist, bool base_only = false);

// ---- stability: the largest stable dt, measured ------------------------------
// A run is unstable when the model stops it (dda::SimulationError: a
// non-finite state, an inverted element, a node deeper than half an element)
// or its total energy leaves E0 by more than this fraction (a mildly
// unstable step grows the energy before anything breaks): an elastic
// collision keeps E, and the stable runs keep it to < 1e-3.
inline constexpr double kBlowUpEnergy = 0.5;  // of E0
// The dt ladder, as multiples of the predicted critical step.
inline const std::vector<double> kStabilityLadder = {0.9, 1.0, 1.05, 1.1, 1.2, 1.35, 1.5, 1.7, 2.0, 2.5, 3.0, 4.0};
struct StabilityProbe {
  double kn_factor = 1.0, kn = 0.0;  // x E/100; Pa
  double dt_mesh = 0.0;              // the mesh's critical step (no springs), s
  double dt_pred = 0.0;              // with the penalty springs (Model::contact_critical_dt), s
  double dt_stable = 0.0;            // the largest ladder dt that ran stably, s (0: none)
  double dt_unstable = 0.0;          // the first ladder dt that did not, s (0: none up to the ladder's top)
  std::string failure;               // how that run ended
  double wall = 0.0;                 // s, the whole probe
};
// Runs the scene (P, kn x kn_factor) from its start to the touch + `after`
// seconds at dt = f x dt_pred for f along the ladder, with the model's dt
// check off, until a run is unstable.
StabilityProbe probe_stability(const SceneDef& def, double kn_factor, double after);

// ---- criteria of P's rows ----------------------------------------------------
// Touch time: the penalty contact starts at the first step end with a node
// behind an edge, so never before the exact time and at most one step late.
bool penalty_touch_ok(const std::vector<Result>& p, double t_exact);
// Momentum: equal and opposite node-edge forces, conserved to round-off by
// every run of the sweep (relative to p0; the same 1e-12 as A, B, B0).
bool penalty_momentum_ok(const std::vector<Result>& p);
// The predicted critical step (mesh + three penalty springs per node,
// Model::contact_critical_dt) is a usable stability limit: the runs at the prediction or below it were
// stable (dt_stable >= dt_pred), and the first unstable ladder dt is within
// kStabilityMargin of it (the one-spring estimate is not off by more).
// x dt_pred: the prediction adds three springs' 6 kn max(1/m) to omega^2,
// at most 3 times what one spring (a node pressing one edge) adds, so the
// measured limit may exceed it by sqrt(3) = 1.73, plus one ladder step.
inline constexpr double kStabilityMargin = 2.0;
bool stability_prediction_ok(const StabilityProbe& p, double dt_predicted);

// Names of the negative controls in controls.cpp beside this file.
inline const char* const kTestPenaltyTouch = "B-7 P touch: FAIL against a wrong time of impact";
inline const char* const kTestPenaltyMomentum = "B-7 P momentum: FAIL with block j fixed";
inline const char* const kTestPenaltyStability =
    "B-7 P stable dt: FAIL for the mesh's critical step without the penalty spring";

// B-7's P on every scene (penalty_baseline.cpp): the dt sweep (results
// and the base dt's history appended, model "P"), and the stability probes
// (kn x 1 and x kStiffKnFactor).
inline constexpr double kStiffKnFactor = 1e4;  // x E/100 = 100 E: a spring stiff enough to set the step
struct PenaltyRuns {
  std::map<std::string, std::vector<StabilityProbe>> probes;  // by scene
};
PenaltyRuns run_penalty_baseline(const std::vector<SceneDef>& scenes, std::vector<Result>& results,
                          std::map<std::string, History>& histories, const repro::Progress& progress);
// Appends P's rows of every scene (penalty_rows) to claims.
void add_penalty_rows(const std::vector<SceneDef>& scenes, const std::vector<Result>& results, const PenaltyRuns& runs,
               std::vector<repro::Claim>& claims);

// The rows of P (penalty_baseline.cpp): touch, momentum, energy, stable dt,
// cost, beside A, B, B0 of the same scene. probes: the stability probes of
// the scene (kn x 1 and a stiff kn).
std::vector<repro::Claim> penalty_rows(const SceneDef& def, const std::vector<Result>& p,
                                const std::vector<Result>& a, const std::vector<Result>& b,
                                const std::vector<Result>& b0, const std::vector<StabilityProbe>& probes);

}  // namespace compare
