// Two elastic bars head on against 1D wave theory (bar_waves.cpp says what
// it reproduces): the scene, one run per model, the measured quantities and
// the criteria of the rows, here so that the negative controls
// (controls.cpp beside this file) apply the same criteria to
// deliberately wrong configurations.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/cdem/mesh.hpp"
#include "dda/cdem/model.hpp"
#include "dda/scene.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"

namespace bars {
using repro::format_short;

// ---- the scene ---------------------------------------------------------------
// Two equal bars on the x-axis: bar 0 (the striker) at `speed` along +x, bar
// 1 at rest, `gap` apart. Material: Paper A Sect. 4.1's (rho 2000 kg/m3,
// E 1 GPa) with nu = 0 (see bar_waves.cpp: plane stress with nu = 0 makes
// a uniaxial stress state exact, so 1D bar theory holds with
// c = sqrt(E / rho) and no lateral (Poisson) dispersion).
struct Setup {
  double length = 1.0;  // m, L of each bar
  double width = 0.2;   // m, W: L / W = 5, a slender bar for 1D theory
  // m: wider than the contact tolerance d_tol = 5e-3 m, so that the touch is
  // found on the collision path, not already inside the tolerance at t = 0
  double gap = 0.01;
  double speed = 1.0;  // m/s, striker; strain v / (2 c) = 7e-4: small
  dda::Material material{2000.0, 1e9, 0.0};
  // Mass density of bar 1 relative to bar 0 (1: equal bars; the negative
  // controls change it).
  double target_density_factor = 1.0;

  double wave_speed() const { return std::sqrt(material.young / material.density); }  // m/s
  double contact_time() const { return 2.0 * length / wave_speed(); }                 // s, 2 L / c
  double contact_stress() const { return 0.5 * material.density * wave_speed() * speed; }  // Pa, rho c v / 2
  double touch_time() const { return gap / speed; }                                    // s
};

// Rectangle outline CCW from (x0, y0).
std::vector<dda::Vec2> rect(double x0, double y0, double w, double h);

// The CDEM scene: each bar a structured ny-by-(ny L / W) mesh (square cells
// of side h = W / ny, each two CST elements), the touching faces carrying
// nodes at the same heights; dt as given; tension separation at any tension
// (sigma_t = 0, Paper B's default here); no friction needed (a head-on impact
// has no shear at the faces; phi kept at the library default).
dda::cdem::CdemScene cdem_scene(const Setup& s, int ny, double dt, bool subdivision);

// Paper A's DDA scene: the same bars as 6-DOF blocks with the potential
// contact, kn as given (Paper A Sect. 4.1's ratio kn = E / 100 by default).
dda::Scene dda_scene(const Setup& s, double dt, double kn);

// ---- one run -------------------------------------------------------------------
struct Trace {  // contact stress history: the mean contact force over each step / W
  std::vector<double> t, stress;
};

struct Run {
  std::string model;    // "B" (clone + subdivision), "B0" (clone, no subdivision), "A" (DDA penalty)
  std::string series;   // "mesh" (ny refined, dt with h), "dt" (dt refined on one mesh), "kn" (A's penalty)
  std::string stopped;  // empty: completed; else the error that stopped the run (no result values)
  int ny = 0;           // CDEM elements across the width (0 for A)
  double h = 0.0;       // CDEM cell size W / ny, m (0 for A)
  double dt = 0.0, kn = 0.0, wall = 0.0, critical_dt = 0.0;
  long steps = 0;
  double t_touch = -1.0, t_end = -1.0;  // first touch, final separation, s
  double duration = 0.0;                // t_end - t_touch, s
  double mean_stress = 0.0;             // impulse on bar 1 / (duration W), Pa
  double plateau_stress = 0.0;          // mean contact stress over the middle half of 2 L / c after the touch, Pa
  double v0 = 0.0, v1 = 0.0;            // block-average x-velocities at the end, m/s
  double energy_end = 0.0;              // E_end / E0 - 1
  double energy_growth = 0.0;           // max over the run (also a stopped one) of (E - E0) / E0
  double momentum_err = 0.0;            // max |p - p0| / p0
  int touches = 0, separations = 0;
  // errors against 1D theory
  double duration_err = 0.0;  // (duration - 2 L / c) / (2 L / c)
  double stress_err = 0.0;    // (mean_stress - rho c v / 2) / (rho c v / 2)
  double plateau_err = 0.0;   // (plateau_stress - rho c v / 2) / (rho c v / 2)
  double exchange_err = 0.0;  // max(|v0|, |v1 - v|) / v
  bool ok() const { return stopped.empty(); }
};

void set_errors(Run& r, const Setup& s);

// Accumulates the plateau: the contact stress of the steps within
// [t_touch + T/4, t_touch + 3T/4], T = 2 L / c, weighted by their overlap.
struct Plateau {
  double sum = 0.0, time = 0.0;
  void add(double t0, double t1, double stress, double t_touch, double T) {
    const double lo = std::max(t0, t_touch + 0.25 * T), hi = std::min(t1, t_touch + 0.75 * T);
    if (hi > lo) {
      sum += stress * (hi - lo);
      time += hi - lo;
    }
  }
  double mean() const { return time > 0.0 ? sum / time : 0.0; }
};

double seconds_since(std::chrono::steady_clock::time_point a);

// c dt / h of the CDEM runs unless dt is given: below the checkerboard CST
// mesh's critical value (about 0.77 here: critical step 5.4e-5 s at h = 0.05 m).
inline constexpr double kCourant = 0.3;
// How long a run goes on: until the contact ended half of 2 L / c ago; a run
// that does not touch or separate within kMaxContacts 2 L / c of the touch
// time stops (CDEM 4: it should end at 1; A 200: kn = E / 100 lasts 6).
inline constexpr double kCdemMaxContacts = 4.0, kDdaMaxContacts = 200.0;

// The CDEM bars on an ny mesh at dt (dt <= 0: kCourant h / c). A run that
// leaves the model's domain (dda::SimulationError: an inverted element, a
// non-finite state, an unresolved contact) or does not separate is returned
// with `stopped` set and no result values (energy_growth up to the stop).
Run run_cdem(const Setup& s, int ny, double dt, bool subdivision, Trace* trace = nullptr,
             bool check_stability = true);

// Paper A's DDA bars at dt with penalty kn, until the contact (the step ends
// with an overlap) ended half of 2 L / c ago; stopped as run_cdem.
Run run_dda(const Setup& s, double dt, double kn, Trace* trace = nullptr);

// Least-squares slope of log|err| against log h over the runs given (the
// observed order p of err ~ h^p); 0 if fewer than two runs or a zero error.
double observed_order(const std::vector<Run>& runs, double Run::*err);

// ---- criteria of the rows ----------------------------------------------------
// Tolerances of the CDEM rows on the finest mesh of the default sequence
// (ny = 16, h = W / 16 = 12.5 mm). The CST mesh is dispersive: the wave
// front spreads over a width growing as (h^2 L)^(1/3), so the errors fall
// slowly (asymptotically as h^(2/3); observed order 0.7 to 1.0 over ny 4,
// 8, 16; measured on B0 with the capped sliding friction: duration +4.7,
// +2.1, +1.1 % at ny 4, 8, 16; mean stress -6.5, -3.3, -1.9 %; exchange 2.1,
// 1.3, 0.8 %). The duration and stress bounds lie between B0's errors at
// ny = 16 and at ny = 8, so that they tell the finest mesh from the coarser
// ones; the exchange bound is 2.5 times the error at ny = 16.
inline constexpr double kDurationTol = 0.02;  // |T - 2 L / c| / (2 L / c)
inline constexpr double kStressTol = 0.03;    // |impulse / (T W) - rho c v / 2| / (rho c v / 2)
inline constexpr double kPlateauTol = 0.02;   // plateau within 2 %: measured within 0.6 % on every B0 mesh
inline constexpr double kExchangeTol = 0.02;  // max(|v0|, |v1 - v|) / v
// Energy "never grows": every step's E - E0 below round-off of E0 (the
// clone's inelastic projection only removes energy; explicit integration
// alone keeps it within O(dt^2) of the post-impact value).
inline constexpr double kEnergyGrowthTol = 1e-9;

bool duration_ok(const Run& r, const Setup& s);
bool stress_ok(const Run& r, const Setup& s);
bool plateau_ok(const Run& r, const Setup& s);
bool exchange_ok(const Run& r, const Setup& s);
// Every run (a stopped one up to its stop) keeps E <= E0 (1 + tol).
bool energy_never_grows(const std::vector<Run>& runs);

// The negative controls in controls.cpp beside this file: their exact
// test-case names (a row names one with repro::control_test).
inline const char* const kTestDuration = "B-8 contact duration: FAIL with bars half as long";
inline const char* const kTestStress = "B-8 mean contact stress: FAIL with bars four times as stiff";
inline const char* const kTestPlateau = "B-8 contact stress plateau: FAIL with bars four times as stiff";
inline const char* const kTestExchange = "B-8 velocity exchange: FAIL with the target bar twice as dense";
inline const char* const kTestEnergy = "B-8 energy never grows: FAIL with dt above the critical step";

// ---- the study (study.cpp, rows.cpp) ------------------------------------------
inline constexpr int kMeshNy[] = {1, 2, 4, 8, 16};  // elements across the width: h = 200 ... 12.5 mm
inline constexpr int kDtSweepNy = 4;                // the mesh of the dt series
inline constexpr double kDtSweepCourant[] = {0.15, 0.075};  // c dt / h below the mesh series' 0.3
inline constexpr double kDdaDt[] = {1e-4, 5e-5, 2.5e-5, 1.25e-5};  // s: Paper A Sect. 4.1's 1e-4 s, halved
inline constexpr double kKnFactors[] = {0.01, 0.1, 1.0, 10.0};     // kn / E; 0.01: Paper A Sect. 4.1's ratio

// Every run of the study and the traces of one run per model ("B", "B0":
// the finest completed mesh; "A": kn = E/100 at kDdaDt[2]; "A kn=E").
struct Study {
  std::vector<Run> runs;
  std::map<std::string, Trace> traces;
};
// The mesh series of B0 and B up to max_ny (dt = kCourant h / c), their dt
// series on kDtSweepNy, and A's dt and kn series; note(run) after each run.
Study run_study(const Setup& s, int max_ny, const std::function<void(const Run&)>& note);

// The claim rows of the study's runs; run_note appended to the rows' claims.
std::vector<repro::Claim> rows(const std::vector<Run>& runs, const Setup& s, const std::string& run_note);
// A fraction as a percentage with 3 digits, "1.23 %".
std::string pct(double x);

}  // namespace bars
