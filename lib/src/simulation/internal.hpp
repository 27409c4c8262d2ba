// Internal: what the files of Simulation share and users need not see --
// the private structures of its pair lists and thread team, the OpenMP
// helpers and the tuning constants of the team's shares. Not part of the
// public API. One file per step of the algorithm (run_steps in step.cpp is
// the table of contents):
//   setup.cpp           scene checks, blocks, H (Eq. 12), broad-phase skin
//   step.cpp            step(), run_steps(): the step as a table of contents
//   integration.cpp     velocity Verlet (Eqs. 6-8): move, body forces, gather, kick
//   broad_phase.cpp     the near-pair list (sort and sweep with a skin)
//   contact_forces.cpp  the pair loop: overlap, IP, normal force (Eqs. 10-20)
//   friction.cpp        Coulomb friction with history (Eqs. 24-26)
//   guards.cpp          the per-block and energy guards, the stop message
//   penetration_guard.cpp  the penetration guard (depth, approach energy)
//   energy.cpp          energy and momentum
//   critical_step.cpp   the critical time step bounds
//   team.cpp            the thread team's barrier and shares
#pragma once
#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>

#if defined(DDA_HAVE_OPENMP)
#include <omp.h>
#endif

#include "dda/simulation.hpp"

// OpenMP worksharing inside the phase functions. They are "orphaned"
// directives: called from run_steps' parallel region they split the work of
// one team that lives for the whole call (no thread start-up per step);
// called from anywhere else (the constructor) they run serially.
#if defined(DDA_HAVE_OPENMP)
#define DDA_OMP(directive) _Pragma(#directive)
#else
#define DDA_OMP(directive)
#endif

namespace dda {

// Per-pair history for friction (Sect. 3.2.5-3.2.6); only with friction.
struct Simulation::PairHistory {
  Vec2 d{};               // accumulated relative displacement of CP w.r.t. TP
  Vec2 slide_dir{};       // sliding direction s of the last sliding step
  Vec2 point{};           // pg of the last force evaluation
  Vec2 ft{};              // tangential force on CP of the last evaluation (the friction work's trapezoid)
  bool sliding = false;
};

// A near pair's friction state, in its own array (pair_friction_, beside
// pair_results_) that a frictionless scene never allocates.
struct Simulation::PairFriction {
  PairHistory history;
  // Work friction took out of the two blocks while this pair was near
  // (outlives the history's restarts), J/m.
  double friction_work = 0.0;
};

// One near pair's contact, computed independently of all others (whether
// it is a candidate and in contact: its PairLoad).
struct Simulation::PairResult {
  ContactInfo info;
  double energy = 0.0;  // penalty energy, J/m (set on steps with an energy check)
  // The penetration guard's measures (set while a check is on): the depth
  // and its bound, m (where the depth may exceed the bound: the
  // intersection polygon's width and max_penetration times the smaller
  // half-thickness of the blocks along the normal; elsewhere upper and lower
  // bounds of them), and the relative approach energy, J/m, at the pair's
  // first contact (0 after it).
  double depth = 0.0;
  double depth_bound = 0.0;
  double approach_energy = 0.0;
};

// A near pair of the broad phase (i < j).
struct Simulation::NearPair {
  int i = -1, j = -1;
  int witness = -1;  // separating axis the overlap test found last (-1: none yet)
};

// What the per-block sum reads of each near pair, compact (a PairResult
// spans several cache lines): written by the pair loop, read per block.
struct Simulation::PairLoad {
  Vec2 force{};            // normal + tangential force on the pair's first block, N/m
  Vec2 point{};            // loading point pg
  double couple = 0.0;     // pure moment on the first block besides force at point (NormalForce::couple), N m/m
  bool candidate = false;  // the two boxes overlap at this step
  bool active = false;     // in contact: force, point and the PairResult are this step's
};

// One entry of a block's near-pair list: the pair, the other block, and
// whether this block is the pair's first (the force acts on it with +).
struct Simulation::BlockPair {
  int pair = -1, other = -1;
  bool first = false;
};

// One flag block per thread, each on its own cache line: set in a
// worksharing loop, read by every thread after the loop's barrier.
struct alignas(64) Simulation::ThreadFlags {
  bool left_skin = false;     // a block of this thread's share left its grown box
  bool guard_failed = false;  // a block of this thread's share failed a per-block guard
  bool pair_failed = false;   // a pair of this thread's share failed the penetration guard
  double pair_work = 0.0;     // its share of the last pair loop: estimated work x seconds_per_work
  // Measured on this thread's core (team runs; only the shares, never the
  // results, depend on them): seconds per unit of estimated pair work and
  // per block (move and kick), smoothed over steps; this step's move
  // seconds per block of its share (the kick's share may differ: the
  // split moves in between, in the pair phase).
  double seconds_per_work = 0.0;
  double seconds_per_block = 0.0;
  double move_seconds_per_block = 0.0;
  // When its current phase began (the last team_barrier's exit): phase_times
  // and the speeds above time the phase from it.
  std::chrono::steady_clock::time_point phase_start{};
};

// This thread's blocks [begin, end) in a per-block phase; with a team
// (only then: prefetching and timing) prefetching stops kPrefetchBlocks
// before the end of the share.
struct Simulation::BlockShare {
  bool team = false;
  int begin = 0, end = 0, prefetch_end = 0;
};

// What a pair's contact reads of each block, in one cache line: its
// potential side (polygon, kn/H, small edge, its bisectors and their
// count) and its round-off tolerance.
struct alignas(64) Simulation::BlockSide {
  PotentialSide side;
  double tol = 0.0;  // geometric_tolerance of the block's box, m
};

namespace detail {

// With a team, the per-block and per-pair loops prefetch the data of the
// block (pair) this many ahead: a line last written or read by the other
// core takes ~100-600 ns to arrive on a virtual machine (measured core-to-
// core round trip, varying with the host's placement of the vCPUs), longer
// than the work of one block (~60 ns) or pair (~130 ns). One core alone
// needs no hint (the data stays in its own cache).
constexpr int kPrefetchBlocks = 2;
constexpr long kPrefetchPairs = 4;

// Weight of the latest step in the smoothed per-core speeds that size the
// team's shares (dimensionless; ~20 steps of memory): slow enough that one
// step hit by an interrupt does not move the split, fast enough to follow
// the pile and the host.
constexpr double kSpeedSmoothing = 0.05;

using PhaseClock = std::chrono::steady_clock;

inline double seconds_since(PhaseClock::time_point t0) {
  return std::chrono::duration<double>(PhaseClock::now() - t0).count();
}

// x smoothed towards the latest measurement (the first one taken as is).
inline double smoothed(double x, double latest) { return x > 0.0 ? x + kSpeedSmoothing * (latest - x) : latest; }

// The lines a pair's contact or a block's move reads of a polygon: its
// first vertices and normals (a block has 3-5 of each). kWrite: the caller
// is about to write them.
template <int kWrite>
void prefetch_polygon(PolygonView p) {
  const char* v = reinterpret_cast<const char*>(p.v);
  const char* n = reinterpret_cast<const char*>(p.n);
  __builtin_prefetch(v, kWrite);
  __builtin_prefetch(v + 64, kWrite);
  __builtin_prefetch(n, kWrite);
  __builtin_prefetch(n + 64, kWrite);
}

// This thread's index in the team (0 outside a parallel region), and the
// team's size (1 outside).
inline int thread_index() {
#if defined(DDA_HAVE_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}

inline int team_size() {
#if defined(DDA_HAVE_OPENMP)
  return omp_get_num_threads();
#else
  return 1;
#endif
}

// The extent of `ip` along direction `dir` (any length), times |dir|:
// max - min of v . dir over its vertices. Along the pair's normal force
// (divided by its length): an upper bound of min_width(ip), a few dot
// products.
inline double extent_along(PolygonView ip, Vec2 dir) {
  double lo = DBL_MAX, hi = -DBL_MAX;
  for (int q = 0; q < ip.count; ++q) {
    const double x = dot(ip.v[q], dir);
    lo = x < lo ? x : lo;
    hi = x > hi ? x : hi;
  }
  return hi - lo;
}

// The width of convex polygon `ip`: its smallest extent over all
// directions, which is attained across one of its edges (rotating
// calipers): min over edges of the farthest vertex behind the edge's line.
// A zero-length edge (no normal) is skipped. The penetration guard's depth:
// a thin sliver along a joint has width ~0 whatever its length, where the
// extent along its (then ill-defined) normal force can be long.
inline double min_width(const Polygon& ip) {
  double width = DBL_MAX;
  for (int e = 0; e < ip.count; ++e) {
    const Vec2 n = ip.n[e];
    if (!(dot(n, n) > 0.5)) continue;
    const double line = dot(n, ip.v[e]);
    double deepest = 0.0;
    for (int q = 0; q < ip.count; ++q) deepest = std::max(deepest, line - dot(n, ip.v[q]));
    width = std::min(width, deepest);
  }
  return width == DBL_MAX ? 0.0 : width;
}

}  // namespace detail

// Whether pair result r fails the penetration guard (guards.cpp): inlined
// into the pair loop; the energy bound is computed only at a first contact
// that approaches.
inline bool Simulation::pair_guard_fault(const PairResult& r) const {
  const StabilityGuards& g = scene_.guards;
  if (r.depth > r.depth_bound && g.max_penetration > 0.0) return true;
  return r.approach_energy > 0.0 && r.approach_energy > g.max_approach_energy * pair_energy_bound(r.info.cp, r.info.tp);
}

}  // namespace dda
