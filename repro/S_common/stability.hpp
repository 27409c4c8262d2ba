// Shared by the drivers S1 (work precision), S2 (stability maps) and S3
// (extreme cases): wall-clock medians, the observed order of convergence,
// sampled trajectories, a run's stability class, and an independent check of
// the solver's critical time step (the stiffest mode of the linearised
// system, from central differences of the library's own contact force).
#pragma once
#include <algorithm>
#include <chrono>
#include <ctime>
#include <string>
#include <vector>

#include "dda/simulation.hpp"

namespace repro::stab {

// Medians over `repeats` calls of f: wall time (std::chrono::steady_clock)
// and the calling thread's CPU time (CLOCK_THREAD_CPUTIME_ID), s. On a
// loaded machine the wall time includes waiting for a core; the CPU time
// does not (nor the work of other threads running other cases).
struct Timing {
  double wall = 0.0;
  double cpu = 0.0;
  int repeats = 0;
};
double median(std::vector<double> v);
// The calling thread's CPU time, s.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
template <class F>
Timing median_time(int repeats, F&& f) {
  std::vector<double> wall, cpu;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds();
    f();
    cpu.push_back(thread_cpu_seconds() - c0);
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return {median(wall), median(cpu), static_cast<int>(wall.size())};
}

// Observed order p of err ~ C dt^p: the least-squares slope of log(err) on
// log(dt) over the `points` smallest dt whose error lies above `floor` (the
// round-off level of the measure). Entries with err < 0 (failed runs) are
// skipped. p is NaN and `note` says why when fewer than 2 points qualify.
// A plateau (the fitted errors change by less than a factor 1.5 over a dt
// range of 4 or more) is a model error that dt does not reduce: note
// "plateau", no order.
struct Order {
  double p = 0.0;
  int used = 0;
  double dt_lo = 0.0, dt_hi = 0.0;  // range of the fit
  std::string note;                 // "" or "round-off" / "plateau" / "too few points"
  bool valid() const { return note.empty(); }
};
Order observed_order(const std::vector<double>& dt, const std::vector<double>& err, double floor, int points = 4);

// Vertex coordinates of the free scene blocks, concatenated: one sample of
// a trajectory. Compared sample by sample against a reference run.
std::vector<double> vertex_state(const dda::Simulation& sim);
// max_k |a_k - b_k| (same length required), m.
double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b);

// The stiffest mode of the linearised system at sim's current state:
// K = -dF/dd by central differences of the contact forces (the library's
// normal_contact_force, the same integration rule and H as sim; friction in
// its stick state adds kt along the contact tangent) plus the strain
// stiffness area*D, M the DDA mass matrices (Eq. 5a); omega_max^2 is the
// largest eigenvalue of K x = omega^2 M x over the free DOFs (6 per block,
// 3 without strains). dt_crit = 2 / omega_max is velocity Verlet's limit.
// Independent of Simulation::critical_time_step(), which it checks.
struct Linearized {
  double omega_max = 0.0;
  double dt_crit = 0.0;  // s; +inf when nothing is stiff
  int dofs = 0;
  int contacts = 0;
};
Linearized linearized_critical_step(const dda::Simulation& sim);

// What can go wrong in a run, worst last.
enum class RunClass { kStable, kEnergyGrowth, kFlipThrough, kBlowUp };
const char* class_name(RunClass c);  // "stable", "energy growth > 1%", ...

// Deep penetration of one pair: the intersection polygon contains the
// centroid of either block. Beyond that the shortest-exit potential of that
// block is smallest toward its far side for part of the overlap, and its
// contribution to the force pushes the blocks further into each other.
bool deep_penetration(const dda::Polygon& a, const dda::Polygon& b);

}  // namespace repro::stab
