#include "dda/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <exception>
#include <sstream>

#if defined(DDA_HAVE_OPENMP)
#include <omp.h>
#endif

#include "block_lanes.hpp"
#include "team_barrier.hpp"

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

namespace {

constexpr double kPi = 3.14159265358979323846;

// Broad-phase skin as a fraction of the mean inscribed radius of the free
// blocks (dimensionless); see Simulation::choose_broad_phase_skin.
constexpr double kBroadPhaseSkin = 0.25;

// Relative cost of a near pair in the pair loop by what it turned out to
// be (dimensionless; instructions measured on the 6.1 collapse: ~2,500 for
// a touching pair, ~120 for a separate candidate, ~20 for a pair whose
// boxes do not overlap). Only the shares' balance depends on them.
constexpr long kWorkTouching = 125;
constexpr long kWorkCandidate = 6;
constexpr long kWorkOther = 1;

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

double seconds_since(PhaseClock::time_point t0) {
  return std::chrono::duration<double>(PhaseClock::now() - t0).count();
}

// x smoothed towards the latest measurement (the first one taken as is).
double smoothed(double x, double latest) { return x > 0.0 ? x + kSpeedSmoothing * (latest - x) : latest; }

// The lines a pair's contact or a block's move reads of a polygon: its
// first vertices and normals (a block has 3-5 of each). kWrite: the caller
// is about to write them.
template <int kWrite>
void prefetch_polygon(const Polygon& p) {
  const char* v = reinterpret_cast<const char*>(p.v.data());
  const char* n = reinterpret_cast<const char*>(p.n.data());
  __builtin_prefetch(v, kWrite);
  __builtin_prefetch(v + 64, kWrite);
  __builtin_prefetch(n, kWrite);
  __builtin_prefetch(n + 64, kWrite);
}

std::string field(const char* name, std::size_t i) {
  std::ostringstream s;
  s << name << '[' << i << ']';
  return s.str();
}

[[noreturn]] void fail(const std::string& where, const std::string& why) { throw SceneError(where + ": " + why); }

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

// The virtual polygon behind a boundary segment: a rectangle on the
// segment's right side (the solid side).
std::vector<Vec2> segment_polygon(const BoundarySegment& s) {
  const Vec2 ab = s.b - s.a;
  const double depth = s.depth > 0.0 ? s.depth : length(ab);
  const Vec2 out = normalized(perp_right(ab)) * depth;
  return {s.a + out, s.b + out, s.b, s.a};
}

std::vector<int> sweep_pairs_order(const std::vector<Aabb>& boxes) {
  std::vector<int> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].lo.x < boxes[b].lo.x; });
  return order;
}

}  // namespace

void check_scene(const Scene& scene) {
  if (!positive_finite(scene.dt)) fail("dt", "must be a positive finite time step");
  if (!(std::isfinite(scene.dt_fraction) && scene.dt_fraction >= 0.0)) fail("dt_fraction", "must be >= 0");
  if (!(std::isfinite(scene.guards.max_step_motion) && scene.guards.max_step_motion > 0.0))
    fail("guards.max_step_motion", "must be positive");
  if (!(std::isfinite(scene.guards.max_energy_growth) && scene.guards.max_energy_growth > 0.0))
    fail("guards.max_energy_growth", "must be positive");
  if (scene.guards.energy_check_every < 0) fail("guards.energy_check_every", "must be >= 0");
  if (!(std::isfinite(scene.initial_overlap) && scene.initial_overlap >= 0.0))
    fail("initial_overlap", "must be finite and >= 0");
  if (!(std::isfinite(scene.duration) && scene.duration >= 0.0)) fail("duration", "must be finite and >= 0");
  if (!is_finite(scene.gravity)) fail("gravity", "must be finite");
  if (scene.materials.empty()) fail("materials", "at least one material is needed");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::string f = field("materials", i);
    if (!positive_finite(m.density)) fail(f + ".density", "must be positive");
    if (!positive_finite(m.young)) fail(f + ".young", "must be positive");
    if (!(std::isfinite(m.poisson) && m.poisson > -1.0 && m.poisson < 0.5))
      fail(f + ".poisson", "must lie in (-1, 0.5)");
  }
  const ContactParams& c = scene.contact;
  if (!positive_finite(c.kn)) fail("contact.kn", "must be positive");
  if (!(std::isfinite(c.kt) && c.kt >= 0.0)) fail("contact.kt", "must be >= 0 (0 switches friction off)");
  auto check_angle = [](double deg, const std::string& where) {
    if (!(std::isfinite(deg) && deg >= 0.0 && deg < 90.0)) fail(where, "friction angle must lie in [0, 90) degrees");
  };
  check_angle(c.friction_deg, "contact.friction_deg");
  for (std::size_t i = 0; i < c.friction_rules.size(); ++i) {
    check_angle(c.friction_rules[i].friction_deg, field("contact.friction_rules", i) + ".friction_deg");
    if (c.friction_rules[i].group_a < 0 || c.friction_rules[i].group_b < 0)
      fail(field("contact.friction_rules", i), "groups must be >= 0");
  }
  if (c.h_rule == HRule::kGiven && !positive_finite(c.h)) fail("contact.h", "must be positive when H is given");
  if (!(std::isfinite(c.small_edge_fraction) && c.small_edge_fraction >= 0.0))
    fail("contact.small_edge_fraction", "must be >= 0");

  std::vector<Polygon> polys(scene.blocks.size());
  for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
    const BlockSpec& b = scene.blocks[i];
    const std::string f = field("blocks", i);
    const PolygonCheck pc = validate_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
    if (!pc.ok()) {
      if (pc.vertex >= 0) fail(f + field(".vertices", static_cast<std::size_t>(pc.vertex)), describe(pc.fault));
      fail(f + ".vertices", describe(pc.fault));
    }
    if (b.material < 0 || static_cast<std::size_t>(b.material) >= scene.materials.size())
      fail(f + ".material", "no such material");
    if (b.group < 0) fail(f + ".group", "must be >= 0");
    if (!is_finite(b.velocity) || !std::isfinite(b.spin)) fail(f + ".velocity", "must be finite");
    polys[i] = make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
  }
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundarySegment& s = scene.boundaries[i];
    if (!is_finite(s.a) || !is_finite(s.b) || !(length(s.b - s.a) > 0.0))
      fail(field("boundaries", i), "segment end points must be finite and distinct");
    if (!(std::isfinite(s.depth) && s.depth >= 0.0)) fail(field("boundaries", i) + ".depth", "must be >= 0");
  }
  // Blocks overlapping at t = 0, each other or a boundary's virtual polygon
  // (sort and sweep on x).
  std::vector<char> fixed(polys.size());
  for (std::size_t i = 0; i < scene.blocks.size(); ++i) fixed[i] = scene.blocks[i].fixed ? 1 : 0;
  for (const BoundarySegment& b : scene.boundaries) {
    const std::vector<Vec2> pts = segment_polygon(b);
    polys.push_back(make_polygon(pts.data(), static_cast<int>(pts.size())));
    fixed.push_back(1);
  }
  auto name = [&](int i) {
    const std::size_t nb = scene.blocks.size();
    return static_cast<std::size_t>(i) < nb ? field("blocks", static_cast<std::size_t>(i))
                                             : field("boundaries", static_cast<std::size_t>(i) - nb);
  };
  std::vector<Aabb> boxes(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) boxes[i] = bounds(polys[i]);
  const std::vector<int> order = sweep_pairs_order(boxes);
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size() && boxes[order[b]].lo.x <= boxes[order[a]].hi.x; ++b) {
      const int i = std::min(order[a], order[b]), j = std::max(order[a], order[b]);
      if (fixed[i] && fixed[j]) continue;
      if (!aabb_overlap(boxes[i], boxes[j])) continue;
      if (overlap_state(polys[i], polys[j]) == OverlapState::kOverlapping) {
        const Polygon ip = intersection_polygon(polys[i], polys[j]);
        const double thickness = ip.count >= 3 ? 2.0 * inscribed_circle(ip).radius : 0.0;
        if (thickness < scene.initial_overlap) continue;
        std::ostringstream s;
        s << "overlaps " << name(j) << " at t = 0 (overlap " << thickness << " m thick";
        if (scene.initial_overlap > 0.0) s << ", more than initial_overlap = " << scene.initial_overlap << " m";
        s << ")";
        fail(name(i), s.str());
      }
    }
}

Simulation::Simulation(const Scene& scene) : scene_(scene) {
  check_scene(scene_);
  dt_ = scene_.dt;
  strains_ = scene_.strains;
  friction_ = scene_.contact.friction();
  build_blocks();
  choose_potential_length();
  update_geometry();
  predict_critical_step();
  choose_broad_phase_skin();
  if (scene_.dt_fraction > 0.0) dt_ = scene_.dt_fraction * dt_crit_prior_;
  compute_forces();
  kick();  // the first half kick uses a^0; v^0 is restored below
  for (std::size_t i = 0; i < vel_.size(); ++i) vel_[i] -= 0.5 * dt_ * acc_[i];
  const Energy e = energy();
  energy0_ = e.total();
  energy_scale_ = e.kinetic + e.strain + e.contact;
}

void Simulation::build_blocks() {
  const std::size_t n = scene_.blocks.size() + scene_.boundaries.size();
  scene_blocks_ = static_cast<int>(scene_.blocks.size());
  poly_.resize(n);
  moments_.resize(n);
  vel_.assign(n, Vec6::Zero());
  acc_.assign(n, Vec6::Zero());
  force_.assign(n, Vec6::Zero());
  step_disp_.assign(n, Vec6::Zero());
  step_motion2_.assign(n, 0.0);
  start_centroid_.assign(n, Vec2{});
  disp_.assign(n, Vec6::Zero());
  stress_.assign(n, Vec3::Zero());
  density_.assign(n, 0.0);
  mass_.assign(n, 0.0);
  radius_.assign(n, 0.0);
  reach_radius_.assign(n, 0.0);
  h_.assign(n, 0.0);
  kn_over_h_.assign(n, 0.0);
  elastic_.assign(n, Mat3::Zero());
  fixed_.assign(n, 1);
  group_.assign(n, 0);
  for (std::size_t i = 0; i < scene_.blocks.size(); ++i) {
    const BlockSpec& b = scene_.blocks[i];
    const Material& m = scene_.materials[static_cast<std::size_t>(b.material)];
    poly_[i] = make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
    density_[i] = m.density;
    elastic_[i] = elastic_matrix(m.young, m.poisson);
    fixed_[i] = b.fixed ? 1 : 0;
    group_[i] = b.group;
    if (!b.fixed) {
      vel_[i][0] = b.velocity.x;
      vel_[i][1] = b.velocity.y;
      vel_[i][2] = b.spin;
    }
  }
  for (std::size_t k = 0; k < scene_.boundaries.size(); ++k) {
    const std::size_t i = scene_.blocks.size() + k;
    const std::vector<Vec2> pts = segment_polygon(scene_.boundaries[k]);
    poly_[i] = make_polygon(pts.data(), static_cast<int>(pts.size()));
    density_[i] = scene_.materials[0].density;
    group_[i] = scene_.boundaries[k].group;
  }
  // Friction angle table by group pair.
  group_count_ = 1;
  for (int g : group_) group_count_ = std::max(group_count_, g + 1);
  for (const FrictionRule& r : scene_.contact.friction_rules)
    group_count_ = std::max({group_count_, r.group_a + 1, r.group_b + 1});
  friction_tan_table_.assign(static_cast<std::size_t>(group_count_ * group_count_),
                             std::tan(scene_.contact.friction_deg * kPi / 180.0));
  for (const FrictionRule& r : scene_.contact.friction_rules) {
    const double t = std::tan(r.friction_deg * kPi / 180.0);
    friction_tan_table_[static_cast<std::size_t>(r.group_a * group_count_ + r.group_b)] = t;
    friction_tan_table_[static_cast<std::size_t>(r.group_b * group_count_ + r.group_a)] = t;
  }
  boxes_.resize(n);
  // Room for 2 rays per vertex (a vertex ray and at most one virtual node per edge).
  bisector_offset_.assign(n, 0);
  sides_.assign(n, BlockSide{});
  int total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bisector_offset_[i] = total;
    total += 2 * poly_[i].count;
  }
  bisector_store_.resize(static_cast<std::size_t>(total));
  for (std::size_t i = 0; i < n; ++i) {
    sides_[i].side.poly = &poly_[i];
    sides_[i].side.small_edge_rays = scene_.contact.small_edge_rays;
    sides_[i].side.bisectors = bisector_store_.data() + bisector_offset_[i];
  }
}

void Simulation::choose_broad_phase_skin() {
  // The skin trades list length against rebuild frequency: a quarter of the
  // mean inscribed radius of the free blocks lets a block move that far (or
  // deform or turn as much) before the list is rebuilt -- tens of steps at
  // the fastest motion the step guards allow -- while adding only pairs
  // whose gap is below half a typical block radius.
  double sum = 0.0;
  int free_blocks = 0;
  for (int i = 0; i < scene_blocks_; ++i)
    if (!fixed_[i]) {
      sum += radius_[i];
      ++free_blocks;
    }
  skin_ = free_blocks > 0 ? kBroadPhaseSkin * sum / free_blocks : 0.0;
}

double Simulation::friction_tan(int a, int b) const {
  return friction_tan_table_[static_cast<std::size_t>(group_[a] * group_count_ + group_[b])];
}

void Simulation::choose_potential_length() {
  // H of Eq. 12 from the scene's blocks (boundary polygons have an arbitrary
  // depth and are left out of the edge statistics).
  const ContactParams& c = scene_.contact;
  double lmin = DBL_MAX, lmax = 0.0, lsum = 0.0;
  int edges = 0;
  for (int i = 0; i < scene_blocks_; ++i)
    for (int e = 0; e < poly_[i].count; ++e) {
      const double l = length(poly_[i].edge(e));
      lmin = std::min(lmin, l);
      lmax = std::max(lmax, l);
      lsum += l;
      ++edges;
    }
  double h = 1.0;
  switch (c.h_rule) {
    case HRule::kMinMaxEdge: h = 0.5 * (lmin + lmax); break;
    case HRule::kMeanEdge: h = edges > 0 ? lsum / edges : 1.0; break;
    case HRule::kGiven: h = c.h; break;
    case HRule::kInscribedRadius: break;
  }
  for (int i = 0; i < block_count(); ++i) {
    h_[i] = c.h_rule == HRule::kInscribedRadius ? inscribed_circle(poly_[i]).radius : h;
    kn_over_h_[i] = c.kn / h_[i];
    sides_[i].side.kn_over_h = kn_over_h_[i];
    sides_[i].side.small_edge = c.small_edge_fraction * h_[i];
  }
}

void Simulation::step() { run_steps(1); }

void Simulation::advance_to(double t) {
  std::int64_t count = 0;
  while (static_cast<double>(steps_ + count) * dt_ + 0.5 * dt_ < t) ++count;
  run_steps(count);
}

namespace {

// This thread's index in the team (0 outside a parallel region), and the
// team's size (1 outside).
int thread_index() {
#if defined(DDA_HAVE_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}

int team_size() {
#if defined(DDA_HAVE_OPENMP)
  return omp_get_num_threads();
#else
  return 1;
#endif
}

// The near-pair order: by first block, then second.
template <class P>
bool pair_before(const P& x, const P& y) {
  return x.i < y.i || (x.i == y.i && x.j < y.j);
}

bool inside(const Aabb& b, const Aabb& grown) {
  return !(b.lo.x < grown.lo.x || b.lo.y < grown.lo.y || b.hi.x > grown.hi.x || b.hi.y > grown.hi.y);
}

}  // namespace

void Simulation::run_steps(std::int64_t count) {
  // One parallel region for all `count` steps; every thread runs the loop
  // and the phases share out their loops (per block, per near pair). Each
  // block's and each pair's result is computed by one thread from the same
  // inputs, and each block sums its pair forces in pair order: the same
  // bits for any thread count. Three barriers per step (after the moves,
  // the pair forces and the kicks: the team barrier), more (OpenMP's, at
  // the end of an `omp single`) only when the broad phase rebuilds or a
  // guard is due. A guard's SimulationError cannot leave a parallel
  // region: it is caught where it is thrown, every thread stops after that
  // step, and it is rethrown here.
  if (count <= 0) return;
  flags_.assign(static_cast<std::size_t>(threads_), ThreadFlags{});
  const std::int64_t first = steps_;
  const int every = scene_.guards.energy_check_every;
  std::exception_ptr error;
  detail::TeamBarrier barrier;
  barrier_ = &barrier;
  DDA_OMP(omp parallel num_threads(threads_) if (threads_ > 1))
  {
    DDA_OMP(omp single)
    {
      split_evenly(team_size());
      barrier.reset(team_size());
    }  // implicit barrier: every thread sees the reset
    for (std::int64_t k = 0; k < count; ++k) {
      const std::int64_t done = first + k + 1;
      const bool energy_due = every > 0 && done % every == 0;
      move_blocks();                // v^{n+1/2} = v^n + h/2 a^n; move by h v^{n+1/2}; geometry; body forces
      update_near_pairs();          // only when a block left its grown box
      pair_forces(energy_due);      // friction history, overlap, pair forces at t^{n+1} (and energies when due)
      gather_and_kick();            // contact forces summed in pair order; a^{n+1}; v^{n+1}; per-block guards
      if (thread_index() == 0) balance_pair_split();  // read by the next pair loop, after two barriers
      // The flags were set before the kick loop's barrier: every thread
      // takes the same branch.
      bool failed = false;
      for (const ThreadFlags& f : flags_) failed = failed || f.guard_failed;
      if (failed || energy_due) {
        DDA_OMP(omp single)
        {
          steps_ = done;
          time_ = static_cast<double>(steps_) * dt_;
          try {
            collect_contacts();
            check_state(energy_due);  // stops at the failed block; the energy check when due
          } catch (...) {
            error = std::current_exception();
          }
        }  // implicit barrier: every thread sees `error` before reading it
        if (error) break;
      }
    }
  }
  barrier_ = nullptr;
  if (error) std::rethrow_exception(error);
  steps_ = first + count;
  time_ = static_cast<double>(steps_) * dt_;
  collect_contacts();
}


void Simulation::team_barrier() {
  // Every thread of a team waits here for the others (a no-op alone).
  if (team_size() > 1) barrier_->wait();
}

void Simulation::move_blocks() {
  // One pass per block: the half kick and drift of Eq. 8, the moved
  // block's geometry, its body forces, and whether its box left its grown
  // box (the broad phase's list then needs a rebuild).
  const bool sweep = scene_.broad_phase == BroadPhase::kSweep;
  bool left_skin = false;
  const BlockShare share = block_share();
  const PhaseClock::time_point t0 = share.team ? PhaseClock::now() : PhaseClock::time_point{};
  for (int i = share.begin; i < share.end; ++i) {
    if (i < share.prefetch_end) prefetch_block(i + kPrefetchBlocks);
    if (fixed_[i]) continue;
    vel_[i] += 0.5 * dt_ * acc_[i];
    const Vec6 dd = dt_ * vel_[i];  // Eq. 8
    step_disp_[i] = dd;
    disp_[i] += dd;
    const Vec2 c = moments_[i].centroid;
    start_centroid_[i] = c;
    step_motion2_[i] = displace_vertices(poly_[i], c, dd);  // the largest vertex motion, squared (guard)
    if (strains_) stress_[i] += elastic_[i] * dd.tail<3>();
    update_block_geometry(i);
    body_force(i);
    if (sweep && !inside(boxes_[i], skin_boxes_[i])) left_skin = true;
  }
  ThreadFlags& mine = flags_[static_cast<std::size_t>(thread_index())];
  mine.left_skin = left_skin;
  if (share.team && share.end > share.begin)
    mine.move_seconds_per_block = seconds_since(t0) / (share.end - share.begin);
  team_barrier();
}

Simulation::BlockShare Simulation::block_share() const {
  // This thread's contiguous share of the blocks (all of them outside a
  // team); which thread moves or kicks a block changes only the time.
  const int team = team_size(), t = thread_index();
  BlockShare s;
  if (team < 2) {
    s.end = block_count();
    return s;
  }
  s.team = true;
  s.begin = block_split_[static_cast<std::size_t>(t)];
  s.end = block_split_[static_cast<std::size_t>(t) + 1];
  s.prefetch_end = s.end - kPrefetchBlocks;
  return s;
}

void Simulation::prefetch_block(int i) const {
  // What moving block i reads and writes, for writing where it is written
  // (the other core may hold a copy from the pair loop).
  prefetch_polygon<1>(poly_[i]);
  __builtin_prefetch(&vel_[i], 1);
  __builtin_prefetch(&acc_[i]);
  __builtin_prefetch(&moments_[i], 1);
  __builtin_prefetch(&sides_[i], 1);
  __builtin_prefetch(&boxes_[i], 1);
  __builtin_prefetch(&disp_[i], 1);
  __builtin_prefetch(&step_disp_[i], 1);
}

void Simulation::prefetch_gather(int i) const {
  // Block i's pair loads (the other core wrote those of its pairs) and the
  // force and velocity its kick writes.
  for (int q = near_pair_offset_[i], end = near_pair_offset_[i + 1]; q < end; ++q)
    __builtin_prefetch(&pair_loads_[block_pairs_[q].pair]);
  __builtin_prefetch(&vel_[i], 1);
  __builtin_prefetch(&force_[i], 1);
}

void Simulation::update_near_pairs() {
  // Every thread reads every flag after move_blocks' barrier: the same
  // verdict in all of them. Without the sweep the list is rebuilt every step.
  bool rebuild = scene_.broad_phase == BroadPhase::kNone;
  for (const ThreadFlags& f : flags_) rebuild = rebuild || f.left_skin;
  if (!rebuild) return;
  DDA_OMP(omp single)
  {
    // The shares keep their proportions of the new list.
    const long before = static_cast<long>(near_pairs_.size());
    rebuild_near_pairs();
    const long after = static_cast<long>(near_pairs_.size());
    if (before > 0 && pair_split_.size() == static_cast<std::size_t>(team_size()) + 1) {
      for (long& b : pair_split_) b = b * after / before;
      pair_split_.back() = after;
    } else {
      split_evenly(team_size());
    }
  }
}

void Simulation::update_geometry() {
  for (int i = 0; i < block_count(); ++i) update_block_geometry(i);
}

void Simulation::update_block_geometry(int i) {
  const PolygonGeometry g = update_polygon_geometry(poly_[i]);
  moments_[i] = g.moments;
  boxes_[i] = g.box;
  sides_[i].tol = geometric_tolerance(g.box);
  if (scene_.contact.integration == Integration::kPaperBisector) {
    // Without a small edge the bisectors are the vertex rays, the same list
    // from step to step: rebuilt only when a small edge comes or goes. The
    // stored list is the vertex rays exactly when it has one ray per vertex
    // (a virtual node adds a ray, or replaces two by one), 0 before the first.
    const double small = scene_.contact.small_edge_fraction * h_[i];
    const bool plain = !(g.min_edge2 < small * small);  // bisectors()' small-edge test on every edge
    PotentialSide& side = sides_[i].side;
    if (!(plain && side.bisector_count == poly_[i].count))
      side.bisector_count =
          bisectors(poly_[i], small, scene_.contact.small_edge_rays, bisector_store_.data() + bisector_offset_[i]);
  }
  // Mass is conserved (set once, at t = 0): the density follows the strained area.
  if (mass_[i] == 0.0) mass_[i] = density_[i] * moments_[i].area;
  density_[i] = mass_[i] / moments_[i].area;
}

void Simulation::rebuild_near_pairs() {
  // The pairs that may touch before the next rebuild, sorted by (i, j).
  // Sweep: sort and sweep along x on the boxes grown by the skin; the order
  // of the last rebuild is nearly sorted, so insertion sort is linear in
  // practice. Every pair whose current boxes overlap is in the list as
  // long as both boxes stay inside their grown boxes, so skipping the
  // others gives exactly the pairs a full sweep would give, in the same
  // order. Without the sweep (rebuilt every step): every pair with a free
  // block whose boxes overlap now, by testing all pairs.
  const int n = block_count();
  std::vector<NearPair> pairs;
  if (scene_.broad_phase == BroadPhase::kNone) {
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (!(fixed_[i] && fixed_[j]) && aabb_overlap(boxes_[i], boxes_[j])) pairs.push_back({i, j, -1});
  } else {
    ++broad_phase_rebuilds_;
    skin_boxes_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      skin_boxes_[i] = boxes_[i];
      if (fixed_[i]) continue;  // a fixed box never moves: no skin needed
      skin_boxes_[i].lo -= Vec2{skin_, skin_};
      skin_boxes_[i].hi += Vec2{skin_, skin_};
    }
    if (order_.size() != static_cast<std::size_t>(n)) {
      order_.resize(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) order_[i] = i;
    }
    const std::vector<Aabb>& g = skin_boxes_;
    for (std::size_t a = 1; a < order_.size(); ++a) {
      const int key = order_[a];
      std::size_t b = a;
      while (b > 0 && g[order_[b - 1]].lo.x > g[key].lo.x) {
        order_[b] = order_[b - 1];
        --b;
      }
      order_[b] = key;
    }
    for (std::size_t a = 0; a < order_.size(); ++a) {
      const int i = order_[a];
      for (std::size_t b = a + 1; b < order_.size(); ++b) {
        const int j = order_[b];
        if (g[j].lo.x > g[i].hi.x) break;
        if (fixed_[i] && fixed_[j]) continue;
        if (g[j].lo.y > g[i].hi.y || g[i].lo.y > g[j].hi.y) continue;
        pairs.push_back({std::min(i, j), std::max(i, j), -1});
      }
    }
    std::sort(pairs.begin(), pairs.end(), pair_before<NearPair>);
  }
  // A pair on both lists keeps its slot's state (witness, contact, history):
  // one merge pass over the two sorted lists. A pair in contact now is on
  // both (its boxes overlap, so its grown boxes do).
  std::vector<PairResult> results(pairs.size());
  std::vector<PairLoad> loads(pairs.size());
  std::size_t h = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    while (h < near_pairs_.size() && pair_before(near_pairs_[h], pairs[k])) ++h;
    if (h < near_pairs_.size() && !pair_before(pairs[k], near_pairs_[h])) {
      pairs[k].witness = near_pairs_[h].witness;
      results[k] = pair_results_[h];
      loads[k] = pair_loads_[h];
    }
  }
  near_pairs_.swap(pairs);
  pair_results_.swap(results);
  pair_loads_.swap(loads);
  // Each block's pairs in increasing order (CSR).
  near_pair_offset_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const NearPair& p : near_pairs_) {
    ++near_pair_offset_[static_cast<std::size_t>(p.i) + 1];
    ++near_pair_offset_[static_cast<std::size_t>(p.j) + 1];
  }
  for (int i = 0; i < n; ++i) near_pair_offset_[i + 1] += near_pair_offset_[i];
  block_pairs_.resize(static_cast<std::size_t>(near_pair_offset_[n]));
  std::vector<int> fill(near_pair_offset_.begin(), near_pair_offset_.end() - 1);
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
    const int i = near_pairs_[k].i, j = near_pairs_[k].j;
    block_pairs_[static_cast<std::size_t>(fill[i]++)] = {static_cast<int>(k), j, true};
    block_pairs_[static_cast<std::size_t>(fill[j]++)] = {static_cast<int>(k), i, false};
  }
}

void Simulation::compute_forces() {
  // Serial: the forces at the current state (the constructor's a^0).
  for (int i = 0; i < block_count(); ++i) body_force(i);
  rebuild_near_pairs();
  pair_forces(false);
  for (int i = 0; i < block_count(); ++i) gather_contact_forces(i);
  collect_contacts();
}

void Simulation::body_force(int i) {
  // Gravity (int T^T rho g dS = rho S g on the translation DOFs) and the
  // step's initial stress on the strain DOFs (K d of Eq. 4 carried as
  // accumulated stress because d is reset every step).
  force_[i].setZero();
  if (fixed_[i]) return;
  const double m = density_[i] * moments_[i].area;
  force_[i][0] = m * scene_.gravity.x;
  force_[i][1] = m * scene_.gravity.y;
  if (strains_) force_[i].tail<3>() = -moments_[i].area * stress_[i];
}

void Simulation::pair_forces(bool with_energy) {
  // Pair forces, independent of each other. Each thread takes its
  // contiguous share of the list (pair_split_; all of it outside a
  // parallel region), not a dynamic schedule: its shared chunk counter
  // costs a cross-core round trip per chunk, which on a virtual machine
  // with slow core-to-core latency cost more than the uneven pair costs it
  // evens out (measured: 2 threads 0.9x of 1 thread with dynamic chunks of
  // 16). A pair whose boxes do not overlap is no candidate; a pair that
  // did not touch at the last step starts its friction history afresh
  // (pair_force). with_energy: each contact also stores its penalty energy
  // (for the energy guard, summed in pair order as energy() sums it).
  const int team = team_size(), t = thread_index();
  const long n = static_cast<long>(near_pairs_.size());
  const long begin = team > 1 ? pair_split_[static_cast<std::size_t>(t)] : 0;
  const long end = team > 1 ? pair_split_[static_cast<std::size_t>(t) + 1] : n;
  // The loop's arrays in locals: its stores could alias the vectors' members.
  NearPair* const near = near_pairs_.data();
  PairLoad* const loads = pair_loads_.data();
  const Aabb* const boxes = boxes_.data();
  const Polygon* const poly = poly_.data();
  const BlockSide* const sides = sides_.data();
  // The intersection polygon and its edges' sources, rewritten by every
  // overlap test.
  Polygon ip;
  std::array<IpEdge, kMaxVertices> source;
  long work = 0;
  const PhaseClock::time_point t0 = team > 1 ? PhaseClock::now() : PhaseClock::time_point{};
  if (team > 1 && t == 0) balance_block_split();
  const long prefetch_end = team > 1 ? end - kPrefetchPairs : begin;
  for (long k = begin; k < end; ++k) {
    if (k < prefetch_end) {
      // The second block of a pair ahead (the first is mostly this pair's).
      const int j = near[k + kPrefetchPairs].j;
      prefetch_polygon<0>(poly[j]);
      __builtin_prefetch(&boxes[j]);
      __builtin_prefetch(&sides[j]);
    }
    NearPair& p = near[k];
    PairLoad& load = loads[k];
    const bool was_active = load.active;
    load.active = false;
    load.candidate = aabb_overlap(boxes[p.i], boxes[p.j]);
    if (!load.candidate) {
      work += kWorkOther;
      continue;
    }
    // Sect. 3.1.2 (overlap) and 3.1.3 (intersection polygon by cutting).
    const double tol = std::max(sides[p.i].tol, sides[p.j].tol);
    if (overlap_and_intersection(poly[p.i], poly[p.j], tol, ip, source.data(), &p.witness) !=
            OverlapState::kOverlapping ||
        ip.count < 3 || !pair_force(k, was_active, ip, source.data(), tol)) {
      work += kWorkCandidate;
      continue;
    }
    work += kWorkTouching;
    // The penalty energy of the contact, as energy() computes it (the same
    // IP: the lines left out of the cut leave it unchanged).
    if (with_energy) {
      pair_results_[static_cast<std::size_t>(k)].energy = contact_energy(sides[p.i].side, sides[p.j].side, ip, tol);
    }
  }
  if (team > 1) {
    // The share's cost for the next split: its estimated work at this
    // core's measured speed.
    ThreadFlags& mine = flags_[static_cast<std::size_t>(t)];
    if (work > 0) mine.seconds_per_work = smoothed(mine.seconds_per_work, seconds_since(t0) / static_cast<double>(work));
    mine.pair_work = static_cast<double>(work) * (mine.seconds_per_work > 0.0 ? mine.seconds_per_work : 1.0);
  }
  team_barrier();
}

void Simulation::split_evenly(int team) {
  // Equal numbers of pairs and of blocks per thread (a start, before any
  // work or core speed is known).
  const long n = static_cast<long>(near_pairs_.size());
  pair_split_.resize(static_cast<std::size_t>(team) + 1);
  for (int t = 0; t <= team; ++t) pair_split_[static_cast<std::size_t>(t)] = n * t / team;
  block_split_.resize(static_cast<std::size_t>(team) + 1);
  for (int t = 0; t <= team; ++t) block_split_[static_cast<std::size_t>(t)] = block_count() * t / team;
  split_scratch_.resize(pair_split_.size());
  work_scratch_.resize(pair_split_.size());
}

void Simulation::balance_block_split() {
  // Shares of the blocks in proportion to each core's measured speed
  // (blocks per second in the per-block phases), so that the phases end
  // together. Kept as they are until every core has a measurement.
  const int team = static_cast<int>(block_split_.size()) - 1;
  double speed_sum = 0.0;
  for (int t = 0; t < team; ++t) {
    const double c = flags_[static_cast<std::size_t>(t)].seconds_per_block;
    if (!(c > 0.0)) return;
    speed_sum += 1.0 / c;
  }
  double before = 0.0;
  for (int t = 1; t < team; ++t) {
    before += 1.0 / flags_[static_cast<std::size_t>(t) - 1].seconds_per_block;
    const int b = static_cast<int>(std::llround(block_count() * before / speed_sum));
    block_split_[static_cast<std::size_t>(t)] = std::clamp(b, block_split_[static_cast<std::size_t>(t) - 1], block_count());
  }
}

void Simulation::balance_pair_split() {
  // The cost of each share in the last pair loop (its estimated work at
  // its core's measured speed, pair_work), taken as spread evenly over the
  // share's pairs; the new boundaries cut that cost into equal parts (by
  // linear interpolation inside the shares). Pairs change slowly from step
  // to step, so this follows the pile as it moves. Results do not depend
  // on the split: only the time.
  const int team = static_cast<int>(pair_split_.size()) - 1;
  if (team < 2) return;
  std::vector<double>& cum = work_scratch_;
  cum[0] = 0.0;
  for (int t = 0; t < team; ++t)
    cum[static_cast<std::size_t>(t) + 1] = cum[static_cast<std::size_t>(t)] + flags_[static_cast<std::size_t>(t)].pair_work;
  const double total = cum[static_cast<std::size_t>(team)];
  if (!(total > 0.0)) return;
  std::vector<long>& old = split_scratch_;
  old = pair_split_;
  int u = 0;
  for (int t = 1; t < team; ++t) {
    const double target = total * t / team;
    while (u < team - 1 && cum[static_cast<std::size_t>(u) + 1] <= target) ++u;
    const double w = cum[static_cast<std::size_t>(u) + 1] - cum[static_cast<std::size_t>(u)];
    const double frac = w > 0.0 ? (target - cum[static_cast<std::size_t>(u)]) / w : 0.0;
    const long lo = old[static_cast<std::size_t>(u)], hi = old[static_cast<std::size_t>(u) + 1];
    const long b = lo + static_cast<long>(std::llround(frac * static_cast<double>(hi - lo)));
    pair_split_[static_cast<std::size_t>(t)] = std::max(b, pair_split_[static_cast<std::size_t>(t) - 1]);
  }
}

void Simulation::gather_contact_forces(int i) {
  // Block i's contact forces, Eqs. 22-23 and 28-29 through T(pg)^T, added
  // in increasing pair order (the same bits for any thread count); and the
  // smallest inscribed radius within its reach (itself and its candidates)
  // for the step-motion guard. The sum is kept in lanes (point_load_lanes)
  // and the arrays in locals: the force's stores could alias them.
  const BlockPair* pairs = block_pairs_.data();
  const PairLoad* loads = pair_loads_.data();
  const double* radius = radius_.data();
  double reach = radius[i];
  const detail::Lanes c = detail::lanes(moments_[i].centroid);
  const bool free_block = !fixed_[i];
  Vec6& force = force_[i];
  detail::Lanes6 sum{{force[0], force[1]}, {force[2], force[3]}, {force[4], force[5]}};
  for (int q = near_pair_offset_[i], end = near_pair_offset_[i + 1]; q < end; ++q) {
    const BlockPair& bp = pairs[q];
    const PairLoad& load = loads[bp.pair];
    if (!load.candidate) continue;
    reach = std::min(reach, radius[bp.other]);
    if (!load.active || !free_block) continue;
    const detail::Lanes6 g = detail::point_load_lanes(c, load.point, load.force);
    if (bp.first) {
      sum.g01 += g.g01;
      sum.g23 += g.g23;
      sum.g45 += g.g45;
    } else {
      sum.g01 -= g.g01;
      sum.g23 -= g.g23;
      sum.g45 -= g.g45;
    }
  }
  force << sum.g01[0], sum.g01[1], sum.g23[0], sum.g23[1], sum.g45[0], sum.g45[1];
  reach_radius_[i] = reach;
}

void Simulation::collect_contacts() {
  // The active pairs in pair order, for the accessors and the guards.
  contact_info_.clear();
  candidate_count_ = 0;
  for (std::size_t k = 0; k < pair_loads_.size(); ++k) {
    candidate_count_ += pair_loads_[k].candidate ? 1 : 0;
    if (pair_loads_[k].active) contact_info_.push_back(pair_results_[k].info);
  }
}

void Simulation::gather_and_kick() {
  // Per block: its contact forces, a^{n+1}, the second half kick, and the
  // per-block guards (flagged here, reported by check_state).
  bool failed = false;
  const BlockShare share = block_share();
  const PhaseClock::time_point t0 = share.team ? PhaseClock::now() : PhaseClock::time_point{};
  for (int i = share.begin; i < share.end; ++i) {
    if (i < share.prefetch_end) prefetch_gather(i + kPrefetchBlocks);
    gather_contact_forces(i);
    if (fixed_[i]) continue;
    kick_block(i);
    if (guard_fault(i) != GuardFault::kNone) failed = true;
  }
  ThreadFlags& mine = flags_[static_cast<std::size_t>(thread_index())];
  mine.guard_failed = failed;
  if (share.team && share.end > share.begin)
    mine.seconds_per_block =
        smoothed(mine.seconds_per_block, mine.move_seconds_per_block + seconds_since(t0) / (share.end - share.begin));
  team_barrier();
}

void Simulation::kick_block(int i) {
  const AreaMoments& m = moments_[i];
  const double mass = density_[i] * m.area;
  acc_[i][0] = force_[i][0] / mass;
  acc_[i][1] = force_[i][1] / mass;
  if (strains_) {
    // Rotation and strains couple through the 4x4 lower block of M (Eq. 5a).
    acc_[i].tail<4>() = rotation_strain_acceleration(m, density_[i], force_[i].tail<4>());
  } else {
    acc_[i][2] = force_[i][2] / (density_[i] * (m.sxx + m.syy));
  }
  vel_[i] += 0.5 * dt_ * acc_[i];
}

void Simulation::kick() {
  for (int i = 0; i < block_count(); ++i)
    if (!fixed_[i]) kick_block(i);
}

// Inlined into the pair loop (its only caller): a call frame of its own
// costs about as much as the bookkeeping it does.
[[gnu::always_inline]] inline bool Simulation::pair_force(long k, bool was_active, const Polygon& ip,
                                                          const IpEdge* source, double tol) {
  const int cp = near_pairs_[static_cast<std::size_t>(k)].i, tp = near_pairs_[static_cast<std::size_t>(k)].j;
  const ContactParams& c = scene_.contact;
  const NormalForce nf =
      normal_contact_force(sides_[cp].side, sides_[tp].side, ip, c.integration, tol, source);  // Eqs. 11-20
  if (!nf.valid) return false;
  PairResult& r = pair_results_[static_cast<std::size_t>(k)];
  ContactInfo& info = r.info;
  info.cp = cp;
  info.tp = tp;
  info.normal_force = nf.force;
  info.tangential_force = Vec2{};
  info.point = nf.point;
  info.ip_area = nf.ip_area;
  info.ip_length = 0.5 * nf.ip_perimeter;
  info.sliding = false;
  if (friction_) {
    // Coulomb friction with stick/slide history, Eqs. 24-26. A pair that
    // was not in contact at the last step starts afresh.
    PairHistory& hist = r.history;
    if (was_active) {
      // Sect. 3.2.6: Delta d = Delta u_g(CP) - Delta u_g(TP) at the last pg;
      // a sticking pair accumulates it, a sliding pair restarts from it
      // (kPaper) or, with the return mapping, accumulates it onto the shear
      // it was returned to (below). The centroids are those of the step's
      // start configuration.
      using detail::Lanes;
      const Lanes pg = detail::lanes(hist.point);
      const auto du = [&](int b) {
        return fixed_[b] ? Lanes{0.0, 0.0}
                         : detail::point_displacement_lanes(detail::lanes(start_centroid_[b]), pg, step_disp_[b]);
      };
      const Lanes dd = du(cp) - du(tp);
      const bool restart = c.friction_update == FrictionUpdate::kPaper;
      hist.d = detail::vec2(hist.sliding && restart ? dd : detail::lanes(hist.d) + dd);
    } else {
      hist = PairHistory{};
    }
    const double fn = length(nf.force);
    const Vec2 ng = nf.force / fn;
    const Vec2 dtan = hist.d - dot(hist.d, ng) * ng;
    const double lt = length(dtan);
    const Vec2 s = lt > 0.0 ? dtan / lt : Vec2{};
    const double limit = fn * friction_tan(cp, tp);
    Vec2 ft{};
    if (c.friction_update == FrictionUpdate::kReturnMapping) {
      // Elastic-plastic Coulomb (not the paper's Eq. 26, see FrictionUpdate):
      // Eq. 25 from either state; sliding returns d_tan onto the limit,
      // d_tan = -f_t / kt, so the spring keeps the shear it carries.
      if (c.kt * lt < limit) {
        ft = -c.kt * dtan;
        hist.sliding = false;
      } else {
        ft = -limit * s;
        hist.sliding = true;
        hist.d += (limit / c.kt) * s - dtan;
      }
    } else if (!hist.sliding) {
      if (c.kt * lt < limit) {
        ft = -c.kt * dtan;
      } else {
        ft = -limit * s;
        hist.sliding = true;
      }
    } else if (limit <= 0.0 || dot(hist.slide_dir, dtan) > 0.0) {
      // Eq. 26 keeps sliding while f_t(n-1) . d_tan < 0. With f_t(n-1) =
      // -limit s(n-1) that is s(n-1) . d_tan > 0, the form used here: it
      // stays defined when the limit is zero (phi = 0), where the literal
      // test would stick every other step: a zero limit keeps sliding with
      // zero force (it has no sliding direction yet when it started at rest).
      ft = -limit * s;
    } else {
      ft = -c.kt * dtan;
      hist.sliding = false;
    }
    if (hist.sliding && lt > 0.0) hist.slide_dir = s;
    hist.point = nf.point;
    info.tangential_force = ft;
    info.sliding = hist.sliding;
  }
  PairLoad& load = pair_loads_[static_cast<std::size_t>(k)];
  load.active = true;
  load.force = info.normal_force + info.tangential_force;
  load.point = info.point;
  return true;
}

[[noreturn]] void Simulation::stop(int block, const std::string& what) const {
  std::ostringstream s;
  s << "step " << steps_ << " (t = " << time_ << " s): block " << block;
  // The pair through which the block takes its largest contact force.
  double fmax = 0.0;
  int other = -1;
  for (const ContactInfo& c : contact_info_)
    if ((c.cp == block || c.tp == block) && length(c.normal_force) > fmax) {
      fmax = length(c.normal_force);
      other = c.cp == block ? c.tp : c.cp;
    }
  if (other >= 0) s << ", pair (" << std::min(block, other) << ", " << std::max(block, other) << ")";
  s << ": " << what << "; dt/dt_crit = ";
  const double now = critical_time_step();
  if (std::isfinite(now) && now < DBL_MAX) s << dt_ / now << " now, ";
  else s << "undefined now (state not finite), ";
  s << dt_ / dt_crit_prior_ << " predicted at start";
  throw SimulationError(s.str());
}

Simulation::GuardFault Simulation::guard_fault(int i) const {
  // Block i (free) after its kick: a non-finite state, a collapsed area, or
  // a vertex that moved more in this step than max_step_motion of the
  // thinnest block within its reach (itself and its candidates: a block in
  // free flight is not stopped because a thin plate exists somewhere else).
  const bool finite = vel_[i].allFinite() && std::isfinite(moments_[i].centroid.x) &&
                      std::isfinite(moments_[i].centroid.y) && std::isfinite(moments_[i].area);
  if (!finite) return GuardFault::kNonFinite;
  if (!(moments_[i].area > 0.0)) return GuardFault::kAreaCollapsed;
  const double motion_limit = scene_.guards.max_step_motion * reach_radius_[i];
  if (step_motion2_[i] > motion_limit * motion_limit) return GuardFault::kStepMotion;
  return GuardFault::kNone;
}

void Simulation::check_state(bool energy_due) {
  // The first block that fails a per-block guard, with the reason.
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const GuardFault fault = guard_fault(i);
    if (fault == GuardFault::kNone) continue;
    std::ostringstream s;  // built only for the message
    switch (fault) {
      case GuardFault::kNone: continue;
      case GuardFault::kNonFinite: stop(i, "non-finite velocity or position");
      case GuardFault::kAreaCollapsed: s << "area collapsed to " << moments_[i].area << " m^2"; break;
      case GuardFault::kStepMotion:
        // Largest vertex motion of this step, |T(p) dd| at the vertices
        // (squared, recorded by move_blocks as it moved them).
        s << "a vertex moved " << std::sqrt(step_motion2_[i]) << " m in one step, more than "
          << scene_.guards.max_step_motion << " of the smallest inscribed radius within reach (" << reach_radius_[i]
          << " m)";
        break;
    }
    stop(i, s.str());
  }
  if (energy_due) {
    // energy() with this step's stored contact energies, in pair order.
    Energy e = block_energy();
    for (std::size_t k = 0; k < pair_loads_.size(); ++k)
      if (pair_loads_[k].active) e.contact += pair_results_[k].energy;
    energy_scale_ = std::max(energy_scale_, e.kinetic + e.strain + e.contact);
    const double growth = (e.total() - energy0_) / std::max(energy_scale_, DBL_MIN);
    if (growth > scene_.guards.max_energy_growth) {
      int worst = 0;
      double kmax = -1.0;
      for (int i = 0; i < block_count(); ++i) {
        if (fixed_[i]) continue;
        const double k = vel_[i].head<2>().squaredNorm() * mass_[i];
        if (k > kmax) {
          kmax = k;
          worst = i;
        }
      }
      std::ostringstream s;
      s << "total energy grew by " << growth << " of the largest mechanical energy (" << energy_scale_
        << " J), more than " << scene_.guards.max_energy_growth;
      stop(worst, s.str());
    }
  }
}

double Simulation::block_strain_omega2(int i) const {
  // Generalised eigenproblem K x = w^2 M x on (r, ex, ey, gxy); K has the
  // elastic block S D on the strains and nothing on the rotation.
  if (!strains_) return 0.0;
  const Mat6 m = mass_matrix(moments_[i], density_[i]);
  Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
  k.bottomRightCorner<3, 3>() = moments_[i].area * elastic_[i];
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> es(k, m.bottomRightCorner<4, 4>(), Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

namespace {

// Point compliance of a block: the largest displacement per unit force of a
// point of the block loaded there, max over p of lambda_max(T(p) M^-1 T(p)^T)
// (Eqs. 1-3, 5a). It is a convex function of p, so the maximum is at a
// vertex. Without strains M acts on (u, v, r) only. A contact of stiffness k
// anywhere on the block adds at most k times this to omega^2.
double point_compliance(const Polygon& poly, const AreaMoments& m, double density, bool strains) {
  const Mat6 mm = mass_matrix(m, density);
  Mat6 inv = Mat6::Zero();
  if (strains) {
    inv = mm.ldlt().solve(Mat6::Identity());
  } else {
    inv(0, 0) = 1.0 / mm(0, 0);
    inv(1, 1) = 1.0 / mm(1, 1);
    inv(2, 2) = 1.0 / mm(2, 2);
  }
  double c = 0.0;
  for (int v = 0; v < poly.count; ++v) {
    const double xt = poly.v[v].x - m.centroid.x, yt = poly.v[v].y - m.centroid.y;
    Eigen::Matrix<double, 2, 6> t;
    t << 1.0, 0.0, -yt, xt, 0.0, 0.5 * yt, 0.0, 1.0, xt, 0.0, yt, 0.5 * xt;
    const Eigen::Matrix2d a = t * inv * t.transpose();
    const double mean = 0.5 * (a(0, 0) + a(1, 1)), half = 0.5 * (a(0, 0) - a(1, 1));
    c = std::max(c, mean + std::sqrt(half * half + a(0, 1) * a(0, 1)));
  }
  return c;
}

}  // namespace

void Simulation::predict_critical_step() {
  // Before any contact: each block pressed along its longest edge L by a
  // block with the smallest H of the assembly, k = kn L (1/H_i + 1/H_min)
  // (+ kt with friction), at the block's most compliant point: omega^2 <=
  // k c_i, twice that if the partner may be a free block as compliant as
  // this one (more than one free block), plus the block's own strain modes
  // (stiffnesses add: omega^2 of a sum <= the sum of the omega^2).
  double w2 = 0.0, h_min = DBL_MAX;
  int free_blocks = 0;
  min_inscribed_radius_ = DBL_MAX;
  for (int i = 0; i < block_count(); ++i) {
    radius_[i] = inscribed_circle(poly_[i]).radius;
    min_inscribed_radius_ = std::min(min_inscribed_radius_, radius_[i]);
    h_min = std::min(h_min, h_[i]);
    if (!fixed_[i]) ++free_blocks;
  }
  const double partner = free_blocks > 1 ? 2.0 : 1.0;
  const double kt = friction_ ? scene_.contact.kt : 0.0;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const double k = scene_.contact.kn * max_edge_length(poly_[i]) * (1.0 / h_[i] + 1.0 / h_min) + kt;
    const double c = point_compliance(poly_[i], moments_[i], density_[i], strains_);
    w2 = std::max(w2, partner * k * c + block_strain_omega2(i));
  }
  dt_crit_prior_ = w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
}

double Simulation::critical_time_step() const {
  // Each current contact is a spring k = kn L (1/H_cp + 1/H_tp) (+ kt with
  // friction), L its length, between the two blocks. Block Gershgorin bound
  // on the largest eigenvalue of M^-1 K: omega^2 <= max over blocks i of
  // strain_i + sum over i's contacts of k (c_i + sqrt(c_i c_j)), c the point
  // compliance (0 for a fixed block).
  std::vector<double> comp(poly_.size(), -1.0), row(poly_.size(), 0.0);
  auto compliance = [&](int b) {
    if (fixed_[b]) return 0.0;
    if (comp[b] < 0.0) comp[b] = point_compliance(poly_[b], moments_[b], density_[b], strains_);
    return comp[b];
  };
  const double kt = friction_ ? scene_.contact.kt : 0.0;
  for (const ContactInfo& c : contact_info_) {
    const double k = scene_.contact.kn * c.ip_length * (1.0 / h_[c.cp] + 1.0 / h_[c.tp]) + kt;
    const double ca = compliance(c.cp), cb = compliance(c.tp), cross = std::sqrt(ca * cb);
    row[c.cp] += k * (ca + cross);
    row[c.tp] += k * (cb + cross);
  }
  double w2 = 0.0;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const double wi = row[i] + block_strain_omega2(i);
    if (!std::isfinite(wi)) return std::numeric_limits<double>::quiet_NaN();
    w2 = std::max(w2, wi);
  }
  return w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
}

Vec2 Simulation::momentum() const {
  Vec2 p{};
  for (int i = 0; i < block_count(); ++i)
    if (!fixed_[i]) p += mass(i) * Vec2{vel_[i][0], vel_[i][1]};
  return p;
}

Energy Simulation::energy() const {
  Energy e = block_energy();
  for (const ContactInfo& ci : contact_info_) {
    const Polygon& a = poly_[ci.cp];
    const Polygon& b = poly_[ci.tp];
    const double tol = pair_tolerance(a, b);
    const Polygon ip = intersection_polygon(a, b, tol);
    e.contact += contact_energy(sides_[ci.cp].side, sides_[ci.tp].side, ip, tol);
  }
  return e;
}

Energy Simulation::block_energy() const {
  // Kinetic, gravity and strain energy of the free blocks (no contacts).
  Energy e;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const Mat6 m = mass_matrix(moments_[i], density_[i]);
    e.kinetic += 0.5 * vel_[i].dot(m * vel_[i]);
    e.gravity -= mass(i) * dot(scene_.gravity, moments_[i].centroid);
    if (strains_) e.strain += 0.5 * moments_[i].area * stress_[i].dot(elastic_[i].ldlt().solve(stress_[i]));
  }
  return e;
}

}  // namespace dda
