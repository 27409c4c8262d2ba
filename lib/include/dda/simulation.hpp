// Explicit DDA time stepping (Paper A Sect. 2.3, Eqs. 6-8) with the
// potential-based contact of Sect. 3. The library does no I/O: callers read
// state through the accessors and write it where they like.
#pragma once
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/block.hpp"
#include "dda/potential.hpp"
#include "dda/scene.hpp"

namespace dda {

namespace detail {
class TeamBarrier;
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
  // Not copyable: each block's contact side points into this simulation's
  // geometry pool and bisector store, which a member-wise copy would share
  // with the original (a copy would read the original's blocks). A move
  // keeps the buffers. Out of line: the private pair and team structures
  // are complete only there.
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
  void advance(std::int64_t count) { run_steps(count); }
  // Steps until time() >= t (within half a step), as one advance().
  void advance_to(double t);

  double time() const { return time_; }
  std::int64_t step_count() const { return steps_; }
  double dt() const { return dt_; }
  // Threads (OpenMP builds; 1 otherwise) for the per-block phases and the
  // contact loop. Results are bit-identical for any count: each block and
  // each pair is computed by one thread, and the pair forces are summed in a
  // fixed order. Every step ends in barriers: on cores shared with other
  // work a descheduled thread stalls the team, so use 1 thread there.
  void set_threads(int n) { threads_ = n < 1 ? 1 : n; }
  int threads() const { return threads_; }
  const Scene& scene() const { return scene_; }

  int block_count() const { return geometry_offset_.empty() ? 0 : static_cast<int>(geometry_offset_.size()) - 1; }
  // Blocks made from boundary segments come after the scene's blocks.
  int scene_block_count() const { return scene_blocks_; }
  // Block i's polygon as a value (a copy of its pooled vertices and normals).
  Polygon polygon(int i) const { return copy_polygon(polygon_view(i)); }
  // Block i's polygon in the pool, without a copy: valid until the
  // simulation is destroyed (the pool is sized once, at construction).
  PolygonView polygon_view(int i) const {
    const int o = geometry_offset_[static_cast<std::size_t>(i)];
    const int c = geometry_offset_[static_cast<std::size_t>(i) + 1] - o;
    return {c, geometry_.data() + 2 * o, geometry_.data() + 2 * o + c};
  }
  // Bytes of block geometry (the pool and its offsets) per block.
  std::size_t geometry_bytes_per_block() const;
  Vec2 centroid(int i) const { return moments_[i].centroid; }
  double area(int i) const { return moments_[i].area; }
  double mass(int i) const { return mass_[i]; }
  bool fixed(int i) const { return fixed_[i]; }
  // Velocity DOFs at the current time (synchronised, not half-step).
  const Vec6& velocity(int i) const { return vel_[i]; }
  // Total displacement DOFs accumulated since t = 0 (translation and
  // rotation are meaningful; strains are the accumulated small strains).
  const Vec6& displacement(int i) const { return disp_[i]; }
  const Vec3& stress(int i) const { return stress_[i]; }
  // The H used for block i's potential.
  double potential_length(int i) const { return h_[i]; }

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
  double predicted_critical_step() const { return dt_crit_prior_; }
  // 2 / omega of block i's stiffest own strain mode (infinite without strains).
  double strain_critical_step(int i) const {
    const double w2 = block_strain_omega2(i);
    return w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
  }

  Vec2 momentum() const;
  Energy energy() const;  // recomputes contact energy: call at output time
  const std::vector<ContactInfo>& contacts() const { return contact_info_; }
  // Broad-phase candidate pairs of the last force evaluation (boxes
  // overlapping, touching or not): with contacts().size() the per-pair cost
  // of a step can be measured.
  std::size_t candidate_count() const { return candidate_count_; }
  // Bytes of solver state per broad-phase near pair in this scene (its
  // pair, result, load and two block-list entries; plus the friction
  // history only when the scene has friction), for the benchmarks.
  std::size_t bytes_per_near_pair() const;
  // Times the sweep broad phase rebuilt its pair list (BroadPhase::kSweep).
  std::int64_t broad_phase_rebuilds() const { return broad_phase_rebuilds_; }
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
  const std::vector<PhaseTimes>& phase_times() const { return phase_times_; }
  void reset_phase_times() { phase_times_.clear(); }

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
  // Defined in lib/src/simulation/internal.hpp (users need not see them).
  struct PairHistory;   // a pair's friction history
  struct PairFriction;  // its history and friction work (scenes with friction only)
  struct PairResult;   // a near pair's contact of the last force evaluation
  struct NearPair;     // a broad-phase pair
  struct PairLoad;     // what a block's force sum reads of a pair
  struct BlockPair;    // an entry of a block's near-pair list
  struct ThreadFlags;  // a thread's guard flags and measured speeds
  struct BlockShare;   // a thread's blocks in a per-block phase
  struct BlockSide;    // what a pair's contact reads of a block

  // The step (step.cpp: run_steps is the table of contents) and its phases,
  // one file each under lib/src/simulation/.
  void run_steps(std::int64_t count);
  void compute_forces();
  void collect_contacts();
  // setup.cpp
  void bind_sides();
  void build_blocks();
  void choose_potential_length();
  void choose_broad_phase_skin();
  // integration.cpp: per block, half kick, drift, geometry, body force; gather, kick
  void move_blocks();
  void update_geometry();
  void update_block_geometry(int i);
  void body_force(int i);
  void gather_and_kick();
  void gather_contact_forces(int i);
  void kick_block(int i);
  void kick();
  // Eq. 5c damping (Scene::damping): the kick with C = a M + b K, switching
  // it on or off (a^n recomputed), and the constructor's settling run.
  Vec6 force_acceleration(int i, const Vec6& f) const;
  void damped_kick_block(int i);
  void start_damping(bool on);
  void settle();
  void start_energy_guard();
  void check_stiffness_damping() const;
  void prefetch_block(int i) const;
  void prefetch_gather(int i) const;
  // broad_phase.cpp: the near-pair list, rebuilt when a block left its skin
  void update_near_pairs();
  void rebuild_near_pairs();
  bool near_pairs_unchanged() const;  // BroadPhase::kNone: would a rebuild list the same pairs?
  // contact_forces.cpp: per near pair, overlap, IP, contact force
  void pair_forces(bool with_energy);
  bool pair_force(long k, bool was_active, const Polygon& ip, const IpEdge* source, double tol, bool& pair_fault);
  // friction.cpp
  void pair_friction(PairResult& r, PairFriction& fr, bool was_active, const NormalForce& nf);
  double friction_tan(int a, int b) const;
  // guards.cpp, penetration_guard.cpp
  enum class GuardFault { kNone, kNonFinite, kAreaCollapsed, kStepMotion };
  GuardFault guard_fault(int i) const;
  bool guards_stop(std::int64_t done, bool energy_due, std::exception_ptr& error);
  void check_state(bool energy_due);
  bool pair_guard_fault(const PairResult& r) const;
  double pair_energy_bound(int a, int b) const;
  double approach_energy(int a, int b, Vec2 point, Vec2 normal, double* speed = nullptr, double* mass = nullptr) const;
  void check_pairs() const;
  std::string block_label(int i) const;
  [[noreturn]] void stop(int block, StopReason why, const std::string& what) const;
  [[noreturn]] void stop_pair(int a, int b, StopReason why, const std::string& what) const;
  // energy.cpp
  Energy block_energy() const;
  void add_friction_energy(Energy& e) const;
  void bank_friction_work(const std::vector<NearPair>& kept);
  void add_budget_terms(Energy& e) const;  // friction (add_friction_energy) and damping work
  // critical_step.cpp
  void predict_critical_step();
  double block_strain_omega2(int i) const;
  // team.cpp
  void start_team();
  void team_barrier(PhaseIndex phase);
  BlockShare block_share() const;
  void split_evenly(int team);
  void balance_block_split();
  void balance_pair_split();

  Scene scene_;
  double dt_ = 0.0;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  int scene_blocks_ = 0;
  bool strains_ = true;
  bool friction_ = false;
  bool exact_rotation_ = false;  // RotationUpdate::kExact
  bool damped_ = false;          // Eq. 5c damping acts now (off after a settle)
  double damp_a_ = 0.0, damp_b_ = 0.0;  // a (1/s) and b (s) of Eq. 5c while damped_
  std::vector<Vec6> force_prev_;        // F^n of the last kick, for b K d' (only with b > 0)
  std::vector<Vec6> damp_force_;        // the damping force -a M v - b K v of the last kick (only damped)
  std::vector<double> damping_work_;    // per block: work of the damping forces so far, J/m (<= 0)

  // Block i's mutable polygon in the pool (it moves every step).
  PolygonSpan polygon_span(int i) {
    const int o = geometry_offset_[static_cast<std::size_t>(i)];
    const int c = geometry_offset_[static_cast<std::size_t>(i) + 1] - o;
    return {c, geometry_.data() + 2 * o, geometry_.data() + 2 * o + c};
  }

  // Hot state, one entry per block.
  // Block geometry pooled by vertex count (a Polygon value
  // has room for kMaxVertices = 32, a block mostly has 3-8): block i's
  // count vertices then its count normals, adjacent for the cache, from
  // geometry_[2 * geometry_offset_[i]]; count = geometry_offset_[i + 1] -
  // geometry_offset_[i] (offsets count vertices, each with its normal).
  // Sized once (build_blocks): views of it stay valid.
  std::vector<Vec2> geometry_;
  std::vector<int> geometry_offset_;  // block_count() + 1 entries
  std::vector<AreaMoments> moments_;
  std::vector<Vec6> vel_, acc_, force_, step_disp_, disp_;
  std::vector<Vec2> start_centroid_;  // centroid at the start of the step (friction history)
  std::vector<double> step_motion2_;  // largest vertex motion of the step, squared, m^2 (guard)
  std::vector<Vec3> stress_;

  // Per-block constants and bookkeeping.
  std::vector<double> density_, mass_, h_;  // density follows area: mass_ is conserved
  std::vector<double> kn_over_h_;  // kn / H of each block (H is fixed at construction), Pa/m
  std::vector<Mat3> elastic_;
  std::vector<char> fixed_;
  std::vector<int> group_;
  std::vector<double> friction_tan_table_;
  int group_count_ = 1;

  // Guards.
  double min_inscribed_radius_ = 0.0;
  std::vector<double> radius_, reach_radius_;  // inscribed radii at t = 0; per-step reach
  double dt_crit_prior_ = 0.0;
  double energy0_ = 0.0, energy_scale_ = 0.0;
  double dropped_friction_work_ = 0.0;  // friction work of the pairs that left the near list, J/m

  // Contacts. The broad phase's near pairs (i < j, sorted) each own a
  // result slot (pair_results_, pair_loads_) that lives as long as the pair
  // stays near: its friction history stays in place from step to step.
  // near_pair_offset_ and block_pairs_ list each block's near pairs in
  // increasing order (CSR), so that each block sums its contact forces in
  // that fixed order.
  std::vector<NearPair> near_pairs_;
  std::vector<PairResult> pair_results_;
  std::vector<PairFriction> pair_friction_;  // same slots; empty without friction
  std::vector<PairLoad> pair_loads_;
  std::vector<int> near_pair_offset_;
  std::vector<BlockPair> block_pairs_;
  std::vector<ContactInfo> contact_info_;  // active pairs in near-pair order, after each advance
  std::size_t candidate_count_ = 0;

  // The thread team (team.cpp).
  int threads_ = 1;
  std::vector<ThreadFlags> flags_;
  // The team's barrier during run_steps (null outside it).
  detail::TeamBarrier* barrier_ = nullptr;
  std::vector<PhaseTimes> phase_times_;  // per thread, see phase_times()
  // The pair loop's shares: thread t takes near pairs [pair_split_[t],
  // pair_split_[t + 1]), contiguous (a thread's pairs mostly involve the
  // blocks it moves: fewer polygons travel between cores) and moved every
  // step so that the shares' cost (estimated work at each core's measured
  // speed) is even (balance_pair_split).
  std::vector<long> pair_split_, split_scratch_;
  std::vector<double> work_scratch_;
  // The per-block phases' shares: thread t moves and kicks blocks
  // [block_split_[t], block_split_[t + 1]), sized by each core's measured
  // time per block (balance_block_split, in the pair phase, when no thread
  // reads them).
  std::vector<int> block_split_;

  std::vector<Aabb> boxes_;
  // Bisectors of each block (paper integration rule), rebuilt with the
  // geometry: block i's are bisector_store_[bisector_offset_[i] ...], count sides_[i].side.bisector_count.
  std::vector<Bisector> bisector_store_;
  std::vector<int> bisector_offset_;
  std::vector<BlockSide> sides_;
  std::vector<std::uint32_t> sharp_corners_;  // sharp_corners() of each block's polygon, rebuilt with the geometry
  std::vector<int> order_;
  // Sweep broad phase with a skin (a Verlet list): near_pairs_ holds the
  // pairs whose boxes, grown by skin_ on every side, overlapped at the last
  // rebuild; it stays valid while every block's box stays inside its grown
  // box (skin_boxes_), and each step's pair loop skips the pairs whose
  // current boxes do not overlap. Without the sweep (BroadPhase::kNone)
  // near_pairs_ is rebuilt every step from all pairs: the pairs with a free
  // block whose boxes overlap.
  std::vector<Aabb> skin_boxes_;
  double skin_ = 0.0;  // m
  std::int64_t broad_phase_rebuilds_ = 0;
};

}  // namespace dda
