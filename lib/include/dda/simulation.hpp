// Explicit DDA time stepping (Paper A Sect. 2.3, Eqs. 6-8) with the
// potential-based contact of Sect. 3. The library does no I/O: callers read
// state through the accessors and write it where they like.
#pragma once
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/block.hpp"
#include "dda/potential.hpp"
#include "dda/scene.hpp"

namespace dda {

namespace detail {
class Engine;  // lib/src/simulation/internal.hpp
}
class ByteWriter;  // dda/state_bytes.hpp
class ByteReader;

// A scene that cannot be simulated; what() names the field and the reason,
// e.g. "blocks[2].vertices[1]: clockwise vertex order".
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Why a run stopped: the guard that fired (guards.cpp,
// penetration_guard.cpp; the CDEM model's checks, lib/cdem), so that
// callers classify a stop by its cause, not by its message text.
enum class StopReason : std::uint8_t {
  kOther,           // none of the below (an internal bookkeeping error; CDEM: a touch repeated without end)
  kNonFinite,       // a block's (CDEM: a node's or sub-node's) velocity or position is not finite
  kAreaCollapsed,   // a block's area is no longer positive (CDEM: an element or sub-element inverted)
  kStepMotion,      // a vertex moved more than guards.max_step_motion in one step
  kEnergyGrowth,    // the total energy grew by more than guards.max_energy_growth
  kEnergyBudget,    // the energy budget is off by more than guards.max_balance_error
  kPenetration,     // a pair is deeper than guards.max_penetration (CDEM: a node deeper than d_tol)
  kApproachEnergy,  // a first contact brings more energy than the pair can store
};

// A run that went wrong (non-finite state, a collapsed block); what() says
// the step, the time, the block and what was exceeded; reason the guard.
// The same facts as fields, for callers that act on them (the Python
// module's exception): set by Simulation's guards, left at "not known"
// (-1, NaN) where a thrower does not know them.
struct SimulationError : std::runtime_error {
  explicit SimulationError(const std::string& what, StopReason why = StopReason::kOther)
      : std::runtime_error(what), reason(why) {}
  StopReason reason;
  std::int64_t step = -1;   // the step that failed (its count after the step)
  double time = NAN;        // its time, s
  int block = -1;           // the block named (-1: none)
  int pair_a = -1, pair_b = -1;  // the pair named, pair_a < pair_b (-1: none)
};

// Throws SceneError for the first problem found in the scene.
void check_scene(const Scene& scene);

// The energy of the state and its budget, J/m: initial = total() +
// dissipated, up to the time integration's error: O(dt^2) for rigid blocks
// in translation without friction (test_energy.cpp); a spinning block adds
// an O(dt) drift (the linearised rotation of Eq. 1 grows it a little each
// step), deformable blocks a small floor.
struct Energy {
  double kinetic = 0.0;
  double gravity = 0.0;  // -sum m g.x_c, relative to the origin
  double strain = 0.0;
  double contact = 0.0;  // penalty energy stored in overlaps
  // Elastic energy of the friction springs of the pairs in contact:
  // 1/2 kt |d_tan|^2 of each sticking pair (and of a pair sliding under the
  // return mapping, its d_tan returned onto the limit); none in a pair
  // sliding under the paper's rule, which keeps no shear (energy.cpp).
  double friction_spring = 0.0;
  // Work taken out of the blocks since t = 0 (or since the end of a settle,
  // Scene::damping.settle_time) that no spring holds: friction sliding,
  // shear dropped by a restart or a separation, and the work of Eq. 5c's
  // damping forces when Scene::damping is on.
  double dissipated = 0.0;
  double initial = 0.0;  // total() at t = 0
  double total() const { return kinetic + gravity + strain + contact + friction_spring; }
  double balance_error() const { return total() + dissipated - initial; }
};

// A contact as seen in the last force evaluation.
struct ContactInfo {
  int cp = -1, tp = -1;  // block indices: contact and target polygon
  Vec2 normal_force{};   // on CP, N
  Vec2 tangential_force{};
  Vec2 point{};          // loading point pg
  double couple = 0.0;   // pure moment on CP besides the forces at pg (pg kept in the IP), N m/m
  double ip_area = 0.0;
  double ip_length = 0.0;  // half the IP perimeter: the contact length, m
  bool sliding = false;
};

class Simulation {
 public:
  explicit Simulation(const Scene& scene);
  // Not copyable: a copy would need a geometry pool of its own with each
  // block's contact side bound to it. A move hands the state over (a
  // moved-from simulation may only be assigned to or destroyed). Out of
  // line: the state is complete only there.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  ~Simulation();

  // One explicit step (velocity Verlet, Eqs. 7-8). Throws SimulationError.
  void step();
  // `count` steps. With threads() > 1 one OpenMP team serves all of them
  // (no thread wake-up per step): prefer it to a loop over step() when
  // nothing is read between the steps.
  void advance(std::int64_t count);
  // Steps until time() >= t (within half a step), as one advance().
  void advance_to(double t);

  double time() const;
  std::int64_t step_count() const;
  double dt() const;
  // Threads (OpenMP builds; 1 otherwise) for the per-block phases and the
  // contact loop. Results are bit-identical for any count: each block and
  // each pair is computed by one thread, and the pair forces are summed in a
  // fixed order. Every step ends in barriers: on cores shared with other
  // work a descheduled thread stalls the team, so use 1 thread there.
  void set_threads(int n);
  int threads() const;
  // The scene's settings as given (materials, boundaries, contact, guards,
  // dt, duration, ...). Its block list is empty: the simulation keeps each
  // block's polygon and state in its own arrays, not the BlockSpecs (see
  // polygon(), mass(), fixed(), material()).
  const Scene& scene() const;

  int block_count() const;
  // Blocks made from boundary segments come after the scene's blocks.
  int scene_block_count() const;
  // Block i's polygon as a value (a copy of its pooled vertices and normals).
  Polygon polygon(int i) const { return copy_polygon(polygon_view(i)); }
  // Block i's polygon in the pool, without a copy: valid until the
  // simulation is destroyed (the pool is sized once, at construction).
  PolygonView polygon_view(int i) const;
  // Bytes of block geometry (the pool and its offsets) per block.
  std::size_t geometry_bytes_per_block() const;
  Vec2 centroid(int i) const;
  double area(int i) const;
  double mass(int i) const;
  bool fixed(int i) const;
  // Block i's index into scene().materials (-1 for a boundary polygon).
  int material(int i) const;
  // Velocity DOFs at the current time (synchronised, not half-step).
  const Vec6& velocity(int i) const;
  // Total displacement DOFs accumulated since t = 0 (translation and
  // rotation are meaningful; strains are the accumulated small strains).
  const Vec6& displacement(int i) const;
  const Vec3& stress(int i) const;
  // The H used for block i's potential.
  double potential_length(int i) const;

  // Critical step of velocity Verlet, 2 / omega_max, from an upper bound on
  // the stiffest mode: each contact is a spring k = kn L (1/H_cp + 1/H_tp)
  // (+ kt with friction), L its length, acting at the most compliant point
  // of each block (point compliance c = max over the vertices of
  // lambda_max(T M^-1 T^T)); block Gershgorin over the contacts,
  // omega^2 <= max_i [strain_i + sum_c k (c_i + sqrt(c_i c_j))], plus the
  // block's own strain modes (generalised eigenvalues of S D against M).
  // Never above the linearised system's 2 / omega_max (checked against it by
  // repro/S2_stability_maps). predicted_critical_step assumes every block
  // pressed along its longest edge by a block with the smallest H of the
  // assembly, free (factor 2) when there is more than one free block: an
  // a-priori bound usable before any contact exists.
  double critical_time_step() const;
  double predicted_critical_step() const;
  // 2 / omega of block i's stiffest own strain mode (infinite without strains).
  double strain_critical_step(int i) const;

  Vec2 momentum() const;
  Energy energy() const;  // recomputes contact energy: call at output time
  // The contacts of the last force evaluation in pair order ((cp, tp)
  // increasing), built at each call from the pairs' state (the simulation
  // keeps no copy): call it once per output, and contact_count() to know
  // only whether or how many pairs touch.
  std::vector<ContactInfo> contacts() const;
  std::size_t contact_count() const;  // contacts().size(), without building them
  // Broad-phase candidate pairs of the last force evaluation (boxes
  // overlapping, touching or not): with contact_count() the per-pair cost
  // of a step can be measured.
  std::size_t candidate_count() const;
  // Bytes of solver state per broad-phase near pair in this scene (its
  // pair, load and two block-list entries; plus its friction work only when
  // the scene has friction), for the benchmarks. A touching pair holds a
  // contact slot besides (its result, and its friction history when the
  // scene has friction).
  std::size_t bytes_per_near_pair() const;
  // Broad-phase near pairs now (candidates and the pairs within the skin):
  // each holds bytes_per_near_pair() of solver state.
  std::size_t near_pair_count() const;
  // Times the sweep broad phase rebuilt its pair list (BroadPhase::kSweep).
  std::int64_t broad_phase_rebuilds() const;
  // Where each thread's wall time went in the steps run since the last
  // reset_phase_times (or construction), for the benchmarks: per phase of
  // the step, the time working and the time waiting at the barrier that
  // closes it (zero alone). Phases: moving the blocks; the broad phase's
  // rebuilds (and BroadPhase::kNone's test); the pair loop; gathering and
  // kicking; the guards' reports and energy checks (when one is due: one
  // thread checks, the others wait) with the share balancing. Element t:
  // thread t of the last team size.
  enum PhaseIndex { kPhaseMove, kPhaseBroad, kPhasePairs, kPhaseKick, kPhaseGuards, kPhaseCount };
  struct alignas(64) PhaseTimes {  // a cache line each: the threads write their own
    double work[kPhaseCount] = {};
    double wait[kPhaseCount] = {};
  };
  const std::vector<PhaseTimes>& phase_times() const;
  void reset_phase_times();

  // The full state a step reads (simulation/state.cpp): the blocks, the
  // near-pair lists with each pair's contact and friction history, the
  // broad phase's grown boxes and order, the guards' and the energy
  // budget's accumulators, the clock. restore_state reads what save_state
  // wrote into a simulation built from the same scene: the run then goes on
  // with the same bits as the one saved (any thread count). Throws
  // StateError (the stream is truncated, inconsistent or of another scene).
  void save_state(ByteWriter& out) const;
  void restore_state(ByteReader& in);

 private:
  // The state and the step's phases (lib/src/simulation/internal.hpp:
  // users need not see them); each public call above is forwarded to it.
  std::unique_ptr<detail::Engine> engine_;
};

}  // namespace dda
