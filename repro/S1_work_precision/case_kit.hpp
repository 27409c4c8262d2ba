// S1 work precision: the parts every scene's cases are built from (the dt
// ladder, the option names, the conservation monitor and the observers
// made of it). Used by cases.cpp (the paper's scenes) and cases_ours.cpp
// (our scenes).
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/S1_work_precision/work_precision.hpp"

namespace s1::kit {

inline constexpr double kG = 9.81;
inline constexpr double kPi = 3.14159265358979323846;

// paper_dt * 2^k for k = k_lo .. k_hi (ascending).
std::vector<double> pow2_dts(double paper_dt, int k_lo, int k_hi);

// "paper segmentation" / "exact integration", with ", H unified" /
// ", H inscribed radius" when show_h.
std::string option_name(dda::Integration rule, dda::HRule h, bool show_h);

// A case of scene `sc` (its dt is the paper's) swept over paper dt * 2^k,
// k = k_lo .. k_hi, with trajectory samples every `sample_every` s.
Case make_case(const std::string& scene, const std::string& option, const dda::Scene& sc, int k_lo, int k_hi,
               double sample_every);
// One trajectory measure over the whole run ("trajectory").
void whole_run_trajectory(Case& c);

// Energy and momentum monitors shared by several scenes.
// Energy is checked separately out of contact and in contact: the contact
// force acts on the strain DOFs through one point (T(pg)^T f, Eqs. 22-23),
// which is not the gradient of the contact energy for them, so in contact
// the energy balance of deformable blocks is off by a model error that dt
// does not reduce; after separation it closes again.
struct Conservation {
  double e0 = 0.0, e_mech = 0.0, de = 0.0, de_contact = 0.0;
  dda::Vec2 p0{};
  double dp = 0.0;
  void begin(const dda::Simulation& sim);
  void step(const dda::Simulation& sim);
  double energy_error() const { return de / e_mech; }  // out of contact
  double energy_error_contact() const { return de_contact / e_mech; }
  double momentum_error() const { return dp / dda::length(p0); }
};

// An observer keeping a Conservation monitor over the run; `end` turns it
// and the end state into the case's errors.
using ConservationEnd = std::function<std::vector<double>(const Conservation&, const dda::Simulation&)>;
Observer conservation_observer(ConservationEnd end);
// The energy out of contact alone.
Observer energy_observer();
// The energy budget (Budget) alone.
Observer budget_observer();

// A rigid 1 m square (2000 kg/m^3) moving at `velocity` and spinning at
// `spin`, no gravity, dt 1e-4 s over 1.024 s.
dda::Scene spinning_square(const std::string& name, dda::RotationUpdate update, dda::Vec2 velocity, double spin);
// The largest distance of block 0's vertices from `spec`'s vertices turned
// by `angle` and moved by `shift`.
double vertex_error(const dda::Simulation& sim, const dda::BlockSpec& spec, dda::Vec2 shift, double angle);

}  // namespace s1::kit

namespace s1 {
// Our scenes (cases_ours.cpp; free_rotation_cases is in work_precision.hpp).
std::vector<Case> resting_cases();
std::vector<Case> damping_cases();
}  // namespace s1
