// Internal: the engine behind Simulation -- its state and the phases of
// its step, the private structures of its pair lists and thread team, the
// OpenMP helpers and the tuning constants of the team's shares. Not part of
// the public API (the public header only names the engine). One file per
// step of the algorithm (run_steps in step.cpp is the table of contents):
//   simulation.cpp      Simulation's public calls, forwarded to the engine
//   setup.cpp           scene checks, blocks, H (Eq. 12), broad-phase skin
//   step.cpp            run_steps(): the step as a table of contents
//   integration.cpp     velocity Verlet (Eqs. 6-8): move, body forces, gather, kick
//   damping.cpp         Eq. 5c damping and the settling start
//   broad_phase.cpp     the near-pair list (sort and sweep with a skin)
//   contact_forces.cpp  the pair loop: overlap, IP, normal force (Eqs. 10-20)
//   friction.hpp        Coulomb friction with history (Eqs. 24-26)
//   guards.cpp          the per-block and energy guards, the stop message
//   penetration_guard.cpp  the penetration guard (depth, approach energy)
//   energy.cpp          energy and momentum
//   critical_step.cpp   the critical time step bounds
//   team.cpp            the thread team's barrier and shares
//   state.cpp           saving and restoring the state (checkpoints)
#pragma once
#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

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

namespace detail {

class TeamBarrier;  // team_barrier.hpp

// The state of a Simulation and the phases of its step, each a member
// function with the engine as its `this` (the hot loops read the state
// directly); Simulation owns one and forwards each public call to it once
// (run_steps once per advance). Not copyable: each block's contact side
// points into the engine's own geometry pool and bisector lists.
class Engine {
 public:
  using PhaseIndex = Simulation::PhaseIndex;
  using PhaseTimes = Simulation::PhaseTimes;

  explicit Engine(const Scene& scene);
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  // The step (step.cpp: run_steps is the table of contents) and its phases,
  // one file each under lib/src/simulation/.
  void run_steps(std::int64_t count);
  void advance_to(double t);

  // What Simulation's public calls of the same names return.
  int block_count() const { return geometry_offset_.empty() ? 0 : static_cast<int>(geometry_offset_.size()) - 1; }
  PolygonView polygon_view(int i) const {
    const int o = geometry_offset_[static_cast<std::size_t>(i)];
    const int c = geometry_offset_[static_cast<std::size_t>(i) + 1] - o;
    return {c, geometry_.data() + 2 * o, geometry_.data() + 2 * o + c};
  }
  std::size_t geometry_bytes_per_block() const;
  double critical_time_step() const;
  double block_strain_omega2(int i) const;
  Vec2 momentum() const;
  Energy energy() const;
  std::vector<ContactInfo> contacts() const;
  // The touching pairs: each holds a slot (the slots not in use are free).
  std::size_t contact_count() const { return contact_slots_.size() - free_slots_.size(); }
  std::size_t bytes_per_near_pair() const;
  void save_state(ByteWriter& out) const;
  void restore_state(ByteReader& in);

 private:
  friend class dda::Simulation;  // its accessors read the state below

  struct PairHistory;   // a pair's friction history
  struct PairResult;    // a touching pair's contact of the last force evaluation
  struct alignas(64) ContactSlot;  // a touching pair's result and friction history
  struct BornContact;   // a pair that began to touch in the pair loop, until merge_contacts
  struct alignas(64) ThreadContacts;  // a thread's pairs that began or stopped touching
  struct NearPair;      // a broad-phase pair
  struct PairLoad;      // what a block's force sum reads of a touching pair
  struct ThreadFlags;   // a thread's guard flags and measured speeds
  struct BlockShare;    // a thread's blocks in a per-block phase
  struct BlockSide;     // what a pair's contact reads of a block

  void compute_forces();
  void count_candidates();
  // Touching pair k's contact (NearPair::active, after merge_contacts): its
  // blocks (NearPair), load point and couple (PairLoad), forces, IP
  // measures and sliding flag (its contact slot).
  ContactInfo contact_info(std::size_t k) const;
  // each(k, slot) for every touching pair k, in near-pair order (the order
  // of every sum over contacts).
  template <class Each>
  void each_contact(Each each) const;
  // setup.cpp
  void bind_sides();
  void build_blocks(const std::vector<BlockSpec>& blocks);
  void choose_potential_length();
  void choose_broad_phase_skin();
  // integration.cpp: per block, half kick, drift, geometry, body force; gather, kick
  void move_blocks();
  void update_geometry();
  void update_block_geometry(int i);
  void update_block_geometry(int i, PolygonSpan poly);  // poly: polygon_span(i)
  void block_facts(int i);
  Vec6 body_force(int i) const;
  void gather_and_kick();
  // The arrays gather_contact_forces reads, taken once per block loop: the
  // kicks' stores could alias the vectors' members, which would be reloaded
  // per block.
  struct GatherArrays {
    const int* offset;
    const int* pairs;
    const unsigned char* active;
    const NearPair* near;
    const PairLoad* loads;
  };
  GatherArrays gather_arrays();
  Vec6 gather_contact_forces(int i);
  Vec6 gather_contact_forces(int i, const GatherArrays& a);
  void kick_block(int i, const Vec6& force);
  void kick();
  // Eq. 5c damping (Scene::damping): the kick with C = a M + b K, switching
  // it on or off (a^n recomputed), and the constructor's settling run.
  Vec6 force_acceleration(int i, const Vec6& f) const;
  void damped_kick_block(int i, const Vec6& force);
  void start_damping(bool on);
  void settle();
  void start_energy_guard();
  void check_stiffness_damping() const;
  void prefetch_block(int i) const;
  void prefetch_gather(int i) const;
  template <class Prefetch, class Each>
  double over_block_share(const ThreadFlags& mine, Prefetch prefetch, Each each);
  // broad_phase.cpp: the near-pair list, rebuilt when a block left its skin
  void update_near_pairs();
  void rebuild_near_pairs();
  void set_pair_radii();
  bool near_pairs_unchanged() const;  // BroadPhase::kNone: would a rebuild list the same pairs?
  // contact_forces.cpp: per near pair, overlap, IP, contact force
  void pair_forces(bool with_energy);
  PairResult* pair_force(long k, bool was_active, const Polygon& ip, const IpEdge* source, double tol, bool& pair_fault,
                         ThreadContacts& mine);
  void merge_contacts();  // serial: the slots of the pairs that began or stopped touching
  // friction.hpp (inlined into the pair loop)
  void pair_friction(int cp, int tp, PairResult& r, PairHistory& hist, double& friction_work, bool was_active,
                     Vec2 last_point, Vec2 last_ft, const NormalForce& nf);
  double friction_tan(int a, int b) const;
  // guards.cpp, penetration_guard.cpp
  enum class GuardFault { kNone, kNonFinite, kAreaCollapsed, kStepMotion };
  GuardFault guard_fault(int i) const;
  double reach_radius(int i) const;
  bool guards_stop(std::int64_t done, bool energy_due, std::exception_ptr& error);
  void check_state(bool energy_due);
  bool pair_guard_fault(int cp, int tp, const PairResult& r) const;
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
  // team.cpp
  void start_team();
  void team_barrier(PhaseIndex phase);
  BlockShare block_share() const;
  void split_evenly(int team);
  void balance_block_split();
  void balance_pair_split();

  // Block i's mutable polygon in the pool (it moves every step).
  PolygonSpan polygon_span(int i) {
    const int o = geometry_offset_[static_cast<std::size_t>(i)];
    const int c = geometry_offset_[static_cast<std::size_t>(i) + 1] - o;
    return {c, geometry_.data() + 2 * o, geometry_.data() + 2 * o + c};
  }

  // The scene's settings; its blocks are not kept (build_blocks made the
  // arrays below from them), only their names when the scene names a
  // block (block_label; else empty).
  Scene scene_;
  std::vector<std::string> block_names_;
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
  // (The force F^{n+1} of Eq. 6 is no array: each block's is summed and
  // used in its own iteration of gather_and_kick, 48 bytes a block fewer.)
  std::vector<Vec6> vel_, acc_, step_disp_, disp_;
  std::vector<Vec2> start_centroid_;  // centroid at the start of the step (friction history)
  std::vector<double> step_motion2_;  // largest vertex motion of the step, squared, m^2 (guard)
  std::vector<Vec3> stress_;

  // Per-block constants and bookkeeping.
  std::vector<double> density_, mass_, h_;  // density follows area: mass_ is conserved
  // The elastic matrix D of each material (Eq. 4), and a zero one last for
  // the boundary polygons; block i's is elastic(i). One per material, not
  // per block: 72 bytes a block fewer at 10^6 blocks.
  std::vector<Mat3> elastic_table_;
  std::vector<int> elastic_index_;  // per block: its row of elastic_table_
  const Mat3& elastic(int i) const { return elastic_table_[static_cast<std::size_t>(elastic_index_[static_cast<std::size_t>(i)])]; }
  std::vector<char> fixed_;
  std::vector<int> group_;
  std::vector<double> friction_tan_table_;
  int group_count_ = 1;

  // Guards.
  double min_inscribed_radius_ = 0.0;
  std::vector<double> radius_;  // inscribed radii at t = 0
  // Block i's reach (reach_radius(i), the step-motion guard's radius) is
  // the smallest radius_ of it and its candidates, found from the pairs'
  // candidate flags when asked for. near_radius_: per block, the smallest
  // radius_ of it and all its near pairs (set_pair_radii), a lower bound of
  // its reach whatever the candidates: the guard asks for the reach only
  // when the motion exceeds the bound's limit.
  std::vector<double> near_radius_;
  double dt_crit_prior_ = 0.0;
  double energy0_ = 0.0, energy_scale_ = 0.0;
  double dropped_friction_work_ = 0.0;  // friction work of the pairs that left the near list, J/m

  // Contacts. The broad phase's near pairs (i < j, sorted) each own a
  // load (pair_loads_) and, with friction, their friction work, as long as
  // the pair stays near. Only a touching pair (a few in ten of the near
  // ones) owns a contact slot (contact_slots_): its result and friction
  // history, kept in place from step to step while it
  // touches. A pair that begins to touch writes its contact to its thread's
  // ThreadContacts; merge_contacts (serial, after the pair loop) gives it a
  // slot and frees the slots of the pairs that stopped touching. A slot's
  // place never enters a result: each pair's contact is its own, and every
  // sum over contacts runs in near-pair order (each_contact). Each field of
  // a contact is kept once: contacts() builds the public ContactInfo of
  // each touching pair from its pair, load and slot when it is called.
  // near_pair_offset_ and block_pairs_ list each block's near pairs (their
  // indices) in increasing order (CSR), so that each block sums its contact
  // forces in that fixed order; the pair names the other block.
  std::vector<NearPair> near_pairs_;
  std::vector<PairLoad> pair_loads_;
  std::vector<double> pair_friction_work_;   // per near pair, J/m; empty without friction
  std::vector<ContactSlot> contact_slots_;  // per slot (NearPair::slot)
  std::vector<int> free_slots_;
  std::vector<ThreadContacts> thread_contacts_;  // per thread of the team
  std::vector<int> near_pair_offset_;
  std::vector<int> block_pairs_;
  std::vector<double> pair_radius_;  // per near pair, the smaller radius_ of its blocks (reach_radius)
  // Per near pair, NearPair::active once more, a byte each: what the
  // per-block sum reads of every near pair, without its 16-byte record.
  // Written with the flag (the pair loop; set_pair_radii after a rebuild
  // or restore).
  std::vector<unsigned char> pair_active_;
  std::size_t candidate_count_ = 0;

  // The thread team (team.cpp).
  int threads_ = 1;
  std::vector<ThreadFlags> flags_;
  // The team's barrier during run_steps (null outside it).
  TeamBarrier* barrier_ = nullptr;
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
  // geometry: sides_[i].side.bisectors, count sides_[i].side.bisector_count.
  // Without a small edge they are the vertex rays, which depend on the
  // vertex count only: the side points into the shared detail::vertex_rays
  // table. A block with a small edge (a virtual node) gets a list of its
  // own, room for 2 rays per vertex, the first time it has one, kept in
  // own_bisectors_[i] (empty for every other block: 8 bytes a block, where
  // a list per block cost 32 bytes a vertex).
  std::vector<std::unique_ptr<Bisector[]>> own_bisectors_;
  std::vector<BlockSide> sides_;
  // The overlap test's facts of each block's polygon, rebuilt with the
  // geometry (block_facts): sharp_corners() (the clipper's bevels when the
  // block is the contact) and support_lines() (Eq. 9's edge lines), pooled
  // by vertex count: block i's support_line_pairs(count) pairs begin at
  // support_[i], in support_store_ (none for a block of more than
  // kMaxBlockVertices vertices: the test builds its lines). A pointer per
  // block rather than an offset: the pair loop reads it with one load.
  std::vector<std::uint32_t> sharp_corners_;
  std::vector<SupportLines::Pair> support_store_;
  std::vector<SupportLines::Pair*> support_;
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

}  // namespace detail

using detail::Engine;

// Per-pair history for friction (Sect. 3.2.5-3.2.6); left fresh without
// friction. What the friction also reads of the last force evaluation, pg
// and the tangential force on CP (the friction work's trapezoid), is the
// pair's load point (PairLoad::point) and its result's tangential force,
// written by the same evaluation; `sliding` is also the contact's
// ContactInfo::sliding.
struct Engine::PairHistory {
  Vec2 d{};               // accumulated relative displacement of CP w.r.t. TP
  Vec2 slide_dir{};       // sliding direction s of the last sliding step
  bool sliding = false;
  double friction_tan = 0.0;  // friction_tan of its blocks, kept from its first contact (no table look-up per step)
};

// One touching pair's contact, computed independently of all others
// (whether it is a candidate and in contact: its PairLoad). The rest of
// its ContactInfo is kept once, elsewhere (contact_info): the blocks in its
// NearPair, the load point and couple in its PairLoad, `sliding` in its
// friction history.
struct Engine::PairResult {
  Vec2 normal_force{};      // on CP, N/m
  Vec2 tangential_force{};  // on CP (friction), N/m
  double ip_area = 0.0;     // m^2
  double ip_length = 0.0;   // half the IP perimeter, m
  double energy = 0.0;      // penalty energy, J/m (set on steps with an energy check)
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

// A touching pair's contact slot: its result and its friction history
// (left fresh without friction), 80 + 48 = 128 B, two cache lines of its
// own (128 B). Slots are handed out from a free list, so neighbouring slots
// mostly belong to pairs of different threads of a team: with slots
// sharing a line, every contact's write would take the line from the other
// core (measured on the 6.1 collapse: the 2-thread pair loop's work 1.75x
// the 1-thread one with shared lines, 1.05-1.25x without). One aligned
// slot, not an aligned result and an aligned history: 64 B a touching
// pair fewer.
struct alignas(64) Engine::ContactSlot {
  PairResult result;
  PairHistory history;
};

// A near pair of the broad phase (i < j), and what the pair loop found of
// it at this step (read by the per-block sum with the pair's blocks, in the
// same 16 bytes).
struct Engine::NearPair {
  int i = -1, j = -1;
  int slot = -1;              // its contact slot while it touches (active), else -1
  std::int16_t witness = -1;  // separating axis the overlap test found last (-1: none yet)
  bool candidate = false;     // the two boxes overlap at this step
  bool active = false;        // in contact: its load and PairResult are this step's
};

// A pair that began to touch at this step, kept by its thread until
// merge_contacts gives it a slot.
struct Engine::BornContact {
  long pair = -1;
  PairResult result;
  PairHistory history;
};

// What a thread's share of the pair loop changed in the contact slots,
// on its own cache lines: the pairs that began to touch and those (with a
// slot) that stopped.
struct alignas(64) Engine::ThreadContacts {
  std::vector<BornContact> born;
  std::vector<long> ended;
};

// What the per-block sum reads of each touching near pair (NearPair::
// active), compact (its contact slot spans two cache lines): written by the
// pair loop, read per block; also the touching pair's ContactInfo::point
// and couple. 40 bytes: the pair's flags are in its NearPair.
struct Engine::PairLoad {
  Vec2 force{};         // normal + tangential force on the pair's first block, N/m
  Vec2 point{};         // loading point pg
  double couple = 0.0;  // pure moment on the first block besides force at point (NormalForce::couple), N m/m
};

// One flag block per thread, each on its own cache line: set in a
// worksharing loop, read by every thread after the loop's barrier.
struct alignas(64) Engine::ThreadFlags {
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
struct Engine::BlockShare {
  bool team = false;
  int begin = 0, end = 0, prefetch_end = 0;
};

// What a pair's contact reads of each block, in one cache line: its
// potential side (polygon, kn/H, small edge, its bisectors and their
// count) and its round-off tolerance.
struct alignas(64) Engine::BlockSide {
  PotentialSide side;
  double tol = 0.0;  // geometric_tolerance of the block's box, m
};

namespace detail {

// The vertex rays of a polygon of n = 3 .. kMaxVertices vertices, what
// bisectors() gives without a small edge: ray k between edges k - 1 and k
// (mod n) from vertex k, d0 = 0. Polygon n's begin at n (n - 1) / 2.
constexpr int kVertexRayEntries = kMaxVertices * (kMaxVertices + 1) / 2;
constexpr std::array<Bisector, kVertexRayEntries> make_vertex_rays() {
  std::array<Bisector, kVertexRayEntries> rays{};
  for (int n = 3; n <= kMaxVertices; ++n)
    for (int k = 0; k < n; ++k) {
      Bisector& b = rays[static_cast<std::size_t>(n * (n - 1) / 2 + k)];
      b.line_a = k == 0 ? n - 1 : k - 1;
      b.line_b = k;
      b.d0 = 0.0;
    }
  return rays;
}
inline constexpr std::array<Bisector, kVertexRayEntries> kVertexRays = make_vertex_rays();
inline const Bisector* vertex_rays(int n) { return kVertexRays.data() + n * (n - 1) / 2; }

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
#if defined(DDA_HAVE_OPENMP)
inline int thread_index() { return omp_get_thread_num(); }
inline int team_size() { return omp_get_num_threads(); }
#else
inline int thread_index() { return 0; }
inline int team_size() { return 1; }
#endif

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
inline bool Engine::pair_guard_fault(int cp, int tp, const PairResult& r) const {
  const StabilityGuards& g = scene_.guards;
  if (r.depth > r.depth_bound && g.max_penetration > 0.0) return true;
  return r.approach_energy > 0.0 && r.approach_energy > g.max_approach_energy * pair_energy_bound(cp, tp);
}

inline ContactInfo Engine::contact_info(std::size_t k) const {
  const NearPair& p = near_pairs_[k];
  const PairLoad& l = pair_loads_[k];
  const ContactSlot& s = contact_slots_[static_cast<std::size_t>(p.slot)];
  ContactInfo c;
  c.cp = p.i;
  c.tp = p.j;
  c.normal_force = s.result.normal_force;
  c.tangential_force = s.result.tangential_force;
  c.point = l.point;
  c.couple = l.couple;
  c.ip_area = s.result.ip_area;
  c.ip_length = s.result.ip_length;
  c.sliding = s.history.sliding;
  return c;
}

template <class Each>
void Engine::each_contact(Each each) const {
  for (std::size_t k = 0; k < near_pairs_.size(); ++k)
    if (near_pairs_[k].active) each(k, contact_slots_[static_cast<std::size_t>(near_pairs_[k].slot)]);
}

}  // namespace dda
