// B-7's fourth model "P": the conventional node-to-edge penalty contact on
// the same CST blocks as B and B0 (dda::cdem ContactMode::kNodeToEdgePenalty,
// lib/cdem/src/model_penalty.cpp), the method Paper B argues against, as a
// baseline. Same scenes, meshes and dt sweeps as B0; kn =
// E / 100 of the scene's material (0.4 GPa on the prisms, 10 MPa on the
// squares: the kn of A), frictionless, undamped.
// The runs and the criteria of P's rows are here (header-only, like
// contact_comparison.hpp) so that the negative controls
// (repro/common/controls_node_to_edge.cpp) apply the same criteria; the rows
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
inline dda::cdem::CdemScene penalty_scene(const SceneDef& def, double kn_factor = 1.0) {
  dda::cdem::CdemScene s = def.cdem_scene(false);
  s.options.contact = dda::cdem::ContactMode::kNodeToEdgePenalty;
  s.options.subdivision = false;
  double young = 0.0;
  for (const dda::Material& m : s.materials) young = std::max(young, m.young);
  s.options.penalty_kn = kn_factor * young / 100.0;
  return s;
}

// One P run: as run_cdem, the touch time being the first step end with a
// penalty spring (a node behind an edge), the contact lasting to the last
// one; the energy includes the springs' kn g^2 / 2.
inline Result run_penalty(const SceneDef& def, double dt, History* hist) {
  Result r;
  r.scene = def.name;
  r.model = "P";
  r.dt = dt;
  r.wall = timed([&](bool first) {
    dda::cdem::CdemScene s = penalty_scene(def);
    s.dt = dt;
    s.duration = def.duration;
    dda::cdem::Model m(s);
    const double p0 = m.momentum().x, e0 = m.energy().total();
    Result q = r;
    long k = 0;
    const long every = std::max(1L, std::lround(2e-4 / dt));
    while (m.time() < def.duration - 0.5 * dt) {
      m.step();
      ++k;
      q.mom_err = std::max(q.mom_err, std::fabs(m.momentum().x - p0) / std::fabs(p0));
      if (!m.penalty_contacts().empty()) {
        if (q.contact_start < 0.0) q.contact_start = m.time();
        q.contact_end = m.time();
      }
      if (first) {
        q.energy_err_max = std::max(q.energy_err_max, std::fabs(m.energy().total() - e0) / e0);
        if (hist && k % every == 0) {
          hist->t.push_back(m.time());
          hist->vi.push_back(m.block_velocity(0).x);
          hist->vj.push_back(m.block_velocity(1).x);
        }
      }
    }
    if (first) {
      if (q.contact_start < 0.0) throw std::runtime_error("B-7: penalty run without a contact");
      q.t_touch = q.contact_start;
      q.energy_err_end = (m.energy().total() - e0) / e0;
      q.v_i = m.block_velocity(0).x;
      q.v_j = m.block_velocity(1).x;
      q.steps = k;
      r = q;
    }
  });
  return r;
}

// P over the scene's dt sweep (or its base dt only), errors as run_sweep's.
inline std::vector<Result> penalty_sweep(const SceneDef& def, History* hist, bool base_only = false) {
  std::vector<Result> sweep;
  const std::size_t n = base_only ? 1 : def.dts.size();
  for (std::size_t i = 0; i < n; ++i) {
    Result r = run_penalty(def, def.dts[i], i == 0 ? hist : nullptr);
    r.touch_err = std::fabs(r.t_touch - def.t_touch_exact);
    r.vj_err_exchange = std::fabs(r.v_j - def.v0) / def.v0;
    sweep.push_back(r);
  }
  for (Result& r : sweep) r.vj_err_self = std::fabs(r.v_j - sweep.back().v_j) / def.v0;
  return sweep;
}

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
inline StabilityProbe probe_stability(const SceneDef& def, double kn_factor, double after) {
  StabilityProbe p;
  p.kn_factor = kn_factor;
  const auto a = std::chrono::steady_clock::now();
  {
    dda::cdem::CdemScene s = penalty_scene(def, kn_factor);
    s.options.check_stability = false;  // the prediction only
    const dda::cdem::Model m(s);
    p.kn = m.penalty_kn();
    p.dt_mesh = m.critical_dt();
    p.dt_pred = m.contact_critical_dt();
  }
  const double t_end = def.t_touch_exact + after;
  for (double f : kStabilityLadder) {
    dda::cdem::CdemScene s = penalty_scene(def, kn_factor);
    s.options.check_stability = false;
    s.dt = f * p.dt_pred;
    s.duration = t_end;
    std::string why;
    try {
      dda::cdem::Model m(s);
      const double e0 = m.energy().total();
      while (why.empty() && m.time() < t_end - 0.5 * s.dt) {
        m.step();
        const double e = m.energy().total();
        if (!(std::fabs(e - e0) <= kBlowUpEnergy * e0))
          why = "energy " + format_short(e / e0, 3) + " x E0 at t = " + format_short(m.time(), 5) + " s";
      }
    } catch (const dda::SimulationError& e) {
      why = e.what();
    }
    if (!why.empty()) {
      p.dt_unstable = s.dt;
      p.failure = why;
      break;
    }
    p.dt_stable = s.dt;
  }
  p.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
  return p;
}

// ---- criteria of P's rows ----------------------------------------------------
// Touch time: the penalty contact starts at the first step end with a node
// behind an edge, so never before the exact time and at most one step late.
inline bool penalty_touch_ok(const std::vector<Result>& p, double t_exact) {
  bool ok = !p.empty();
  for (const Result& r : p) ok = ok && r.t_touch >= t_exact && r.t_touch - t_exact <= r.dt * (1.0 + 1e-6);
  return ok;
}
// Momentum: equal and opposite node-edge forces, conserved to round-off by
// every run of the sweep (relative to p0; the same 1e-12 as A, B, B0).
inline bool penalty_momentum_ok(const std::vector<Result>& p) {
  return !p.empty() && worst_of(p, &Result::mom_err) < 1e-12;
}
// The predicted critical step (mesh + three penalty springs per node,
// Model::contact_critical_dt) is a usable stability limit: the runs at the prediction or below it were
// stable (dt_stable >= dt_pred), and the first unstable ladder dt is within
// kStabilityMargin of it (the one-spring estimate is not off by more).
// x dt_pred: the prediction adds three springs' 6 kn max(1/m) to omega^2,
// at most 3 times what one spring (a node pressing one edge) adds, so the
// measured limit may exceed it by sqrt(3) = 1.73, plus one ladder step.
inline constexpr double kStabilityMargin = 2.0;
inline bool stability_prediction_ok(const StabilityProbe& p, double dt_predicted) {
  return p.dt_stable >= dt_predicted * (1.0 - 1e-12) && p.dt_unstable > 0.0 &&
         p.dt_unstable <= kStabilityMargin * dt_predicted;
}

// Names of the negative controls in repro/common/controls_node_to_edge.cpp.
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
