// Paper A against Paper B on the same collisions (contact_comparison.cpp
// says what it compares): the scenes, one run per model and dt, and the
// criteria of the rows, here so that the negative controls
// (controls.cpp beside this file) apply the same
// criteria to deliberately wrong configurations.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"

namespace compare {
using repro::format_short;

struct Result {
  std::string scene, model;
  double dt = 0.0, wall = 0.0;
  double t_touch = -1.0, touch_err = 0.0, mom_err = 0.0, energy_err_end = 0.0, energy_err_max = 0.0;
  double v_i = 0.0, v_j = 0.0, vj_err_exchange = 0.0, vj_err_self = 0.0;
  double contact_start = -1.0, contact_end = -1.0;
  long steps = 0;
};

struct History {
  std::vector<double> t, vi, vj;
  std::vector<dda::cdem::CdemEnergyAccount> accounts;  // CDEM runs (B, B0) only, one per row
};

// The largest |initial - (kinetic + strain + gravity + touch + refine +
// deletion losses)| / initial over an energy-account series (the remainder:
// time integration, clone drift), as B-6's closure criterion computes it.
double worst_energy_remainder(const std::vector<dda::cdem::CdemEnergyAccount>& rows);

struct SceneDef {
  std::string name;
  double t_touch_exact, v0, duration;
  std::function<dda::Scene()> dda_scene;
  std::function<dda::cdem::CdemScene(bool)> cdem_scene;
  std::vector<double> dts;
};


// One run of Paper A's DDA ("A") or Paper B's CDEM ("B" with the in-place
// subdivision, "B0" without) on the scene at dt, timed (the mean of repeats
// of a short run); hist: its history (may be null).
Result run_dda(const SceneDef& def, double dt, History* hist);
Result run_cdem(const SceneDef& def, bool subdivision, double dt, History* hist);

// The meshes and base time steps of the two collisions (defaults: Paper B's
// 2-division prisms at its 5e-4 s, Paper A Sect. 4.1's squares at 1e-4 s
// with 4 x 4 fan triangles); each dt sweep halves from the base dt.
struct Settings {
  int prism_divisions = 2, square_divisions = 4;
  double prisms_dt = 5e-4, squares_dt = 1e-4;  // s
  bool is_default() const {
    const Settings d;
    return prism_divisions == d.prism_divisions && square_divisions == d.square_divisions &&
           prisms_dt == d.prisms_dt && squares_dt == d.squares_dt;
  }
};
std::vector<double> halving(double base, int count);

// The two collisions: the Paper B prisms (reconstructed) and the Paper A
// Sect. 4.1 squares, each with its dt sweep.
std::vector<SceneDef> scene_defs(const Settings& set = {});

// One model ("A", "B" or "B0") over the scene's dt sweep (or its first dt
// only if base_only), with the errors against the scene's reference;
// hist: the base dt's history (may be null).
std::vector<Result> run_sweep(const SceneDef& def, const std::string& model, History* hist,
                              bool base_only = false);

double worst_of(const std::vector<Result>& v, double Result::*f);

// ---- criteria of the rows ----------------------------------------------------
// Touch time: B and B0 exact to round-off, A late by at most one step.
bool touch_ok(const std::vector<Result>& a, const std::vector<Result>& b, const std::vector<Result>& b0);
// Momentum conserved to round-off by every run.
bool momentum_ok(const std::vector<Result>& a, const std::vector<Result>& b, const std::vector<Result>& b0);
// Post-impact velocities at the base dt: A exchanges to 1e-3, B to 10 %.
bool exchange_ok(const Result& a0, const Result& b0);
// Energy at the base dt: A's elastic penalty keeps it to 1e-3, better than B.
bool energy_ok(const Result& a0, const Result& b0);
// Contact duration of the prisms at the base dt: B within 2 ms of Paper B's
// 7.2 ms (0.3333 to 0.3405 s; the rebuilt size was fitted to it), A's
// penalty contact more than 3 times as long.
bool prisms_duration_ok(const Result& a0, const Result& b0);
// The contact time of two elastic bars of length L = 1 m of the squares'
// material: 2 L / c, c = sqrt(E / rho), s.
double squares_wave_time();
// Contact duration of the squares at the base dt: B's within 25 % of 2 L / c,
// A's farther from it than B's.
bool squares_duration_ok(const Result& a0, const Result& b0, double t_ref);
// A on a scene with its penalty kn scaled by each factor, at the base dt.
struct KnRun {
  double factor = 1.0;
  Result result;
};
std::vector<KnRun> kn_sweep(const SceneDef& def, const std::vector<double>& factors);
// A's collision depends on kn: its contact duration falls strictly as kn
// grows (factors in increasing order), while every run exchanges the
// velocities within 1 % of v0 and conserves momentum to round-off.
bool kn_dependence_ok(const std::vector<KnRun>& runs, double v0);
// The negative controls (controls.cpp) named by the rows.
inline const char* const kControlTouch = "repro_controls: B-7 touch: FAIL against a wrong time of impact";
inline const char* const kControlMomentum = "repro_controls: B-7 momentum: FAIL with block j fixed";
inline const char* const kControlExchange = "repro_controls: B-7 exchange: FAIL with block j twice as dense";
// The negative controls in controls.cpp beside this file: their exact
// test-case names (a row names one with repro::control_test).
inline const char* const kTestEnergy = "B-7 energy: FAIL with mass damping in A";
inline const char* const kTestPrismsDuration =
    "B-7 prisms contact duration: FAIL with B a quarter as stiff and with A's kn 10^4 times stiffer";
inline const char* const kTestSquaresDuration = "B-7 squares contact duration: FAIL with B a quarter as stiff";
inline const char* const kTestKn = "B-7 kn dependence: FAIL with block j twice as dense";

// ---- the rows (rows.cpp) -------------------------------------------------------
// The runs of `model` on `scene` among the results, in sweep order.
std::vector<Result> pick(const std::vector<Result>& results, const std::string& scene, const std::string& model);
// The rows of A, B and B0 on one scene (histories by "scene/model").
std::vector<repro::Claim> scene_rows(const SceneDef& def, const std::vector<Result>& results,
                                     const std::map<std::string, History>& histories);
// A's kn dependence on the scene (the kn sweep `runs`) beside B's base run `b`.
repro::Claim kn_row(const SceneDef& def, const std::vector<KnRun>& runs, const Result& b);

}  // namespace compare
