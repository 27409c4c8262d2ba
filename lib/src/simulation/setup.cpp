// Setting up a simulation: the scene checks, the blocks (polygons, masses,
// elastic matrices, friction table), H of Eq. 12, the broad phase's skin;
// the constructor computes the forces at t = 0 and the first half kick (or,
// with Eq. 5c damping, settles: damping.cpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "simulation/internal.hpp"

namespace dda {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Broad-phase skin as a fraction of the mean inscribed radius of the free
// blocks (dimensionless); see Engine::choose_broad_phase_skin.
constexpr double kBroadPhaseSkin = 0.25;

std::string field(const char* name, std::size_t i) {
  std::ostringstream s;
  s << name << '[' << i << ']';
  return s.str();
}

[[noreturn]] void fail(const std::string& where, const std::string& why) { throw SceneError(where + ": " + why); }

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

// Friction groups index a group_count x group_count table of friction
// tangents (build_blocks): 1024 groups make it 8 MiB. A bigger group number
// would make it huge, and beyond 46,340 overflow group_count^2 (an int);
// found by the scene-file fuzzer (a group of 1e6 filled gigabytes).
constexpr int kMaxFrictionGroups = 1024;
bool valid_group(int g) { return g >= 0 && g < kMaxFrictionGroups; }
const std::string kGroupRange = "must lie in [0, " + std::to_string(kMaxFrictionGroups) + ")";

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
  if (!(std::isfinite(scene.guards.max_penetration) && scene.guards.max_penetration >= 0.0))
    fail("guards.max_penetration", "must be >= 0 (0 switches the penetration check off)");
  if (!(std::isfinite(scene.guards.max_approach_energy) && scene.guards.max_approach_energy >= 0.0))
    fail("guards.max_approach_energy", "must be >= 0 (0 switches the approach-energy check off)");
  if (!(std::isfinite(scene.guards.max_balance_error) && scene.guards.max_balance_error >= 0.0))
    fail("guards.max_balance_error", "must be >= 0 (0 switches the energy budget check off)");
  if (!(std::isfinite(scene.initial_overlap) && scene.initial_overlap >= 0.0))
    fail("initial_overlap", "must be finite and >= 0");
  if (!(std::isfinite(scene.duration) && scene.duration >= 0.0)) fail("duration", "must be finite and >= 0");
  if (!is_finite(scene.gravity)) fail("gravity", "must be finite");
  const Damping& dmp = scene.damping;
  if (!(std::isfinite(dmp.mass) && dmp.mass >= 0.0)) fail("damping.mass", "must be finite and >= 0 (a of Eq. 5c, 1/s)");
  if (!(std::isfinite(dmp.stiffness) && dmp.stiffness >= 0.0))
    fail("damping.stiffness", "must be finite and >= 0 (b of Eq. 5c, s)");
  if (!(std::isfinite(dmp.settle_time) && dmp.settle_time >= 0.0))
    fail("damping.settle_time", "must be finite and >= 0");
  if (dmp.settle_time > 0.0 && !dmp.on())
    fail("damping.settle_time", "settling needs damping: set damping.mass or damping.stiffness > 0");
  if (dmp.settle_sticking && !(dmp.settle_time > 0.0 && scene.contact.friction()))
    fail("damping.settle_sticking", "needs damping.settle_time > 0 and friction (contact.kt > 0)");
  if (!(std::isfinite(dmp.settle_slip_time) && dmp.settle_slip_time >= 0.0))
    fail("damping.settle_slip_time", "must be finite and >= 0");
  if (dmp.settle_slip_time > 0.0 && !(dmp.settle_sticking && dmp.settle_slip_time < dmp.settle_time))
    fail("damping.settle_slip_time", "needs damping.settle_sticking and a value below damping.settle_time");
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
    if (!valid_group(c.friction_rules[i].group_a) || !valid_group(c.friction_rules[i].group_b))
      fail(field("contact.friction_rules", i), "groups " + kGroupRange);
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
    if (!valid_group(b.group)) fail(f + ".group", kGroupRange);
    if (!is_finite(b.velocity) || !std::isfinite(b.spin)) fail(f + ".velocity", "must be finite");
    polys[i] = make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
  }
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundarySegment& s = scene.boundaries[i];
    if (!is_finite(s.a) || !is_finite(s.b) || !(length(s.b - s.a) > 0.0))
      fail(field("boundaries", i), "segment end points must be finite and distinct");
    if (!(std::isfinite(s.depth) && s.depth >= 0.0)) fail(field("boundaries", i) + ".depth", "must be >= 0");
    if (!valid_group(s.group)) fail(field("boundaries", i) + ".group", kGroupRange);
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

namespace {

// The scene's settings: every field but the blocks (the engine keeps their
// polygons and state in its own arrays, 176 bytes a block fewer than a
// copy of their specs and vertex lists). Copied whole, then the block list
// dropped, so that every other field, one added later too, is kept.
Scene scene_settings(const Scene& s) {
  Scene out = s;
  std::vector<BlockSpec>().swap(out.blocks);
  return out;
}

}  // namespace

Engine::Engine(const Scene& scene) : scene_(scene_settings(scene)) {
  check_scene(scene);
  dt_ = scene_.dt;
  strains_ = scene_.strains;
  friction_ = scene_.contact.friction();
  exact_rotation_ = scene_.rotation_update == RotationUpdate::kExact;
  build_blocks(scene.blocks);
  choose_potential_length();
  update_geometry();
  predict_critical_step();
  choose_broad_phase_skin();
  if (scene_.dt_fraction > 0.0) dt_ = scene_.dt_fraction * dt_crit_prior_;
  check_stiffness_damping();
  compute_forces();
  if (scene_.damping.on()) {
    settle();  // Eq. 5c damping from the start (damping.cpp)
    return;
  }
  kick();  // the first half kick uses a^0; v^0 is restored below
  for (std::size_t i = 0; i < vel_.size(); ++i) vel_[i] -= 0.5 * dt_ * acc_[i];
  start_energy_guard();
}

void Engine::start_energy_guard() {
  // What is held plus what was dissipated so far (after a settle the
  // budget restarts from the settled state).
  const Energy e = energy();
  energy0_ = e.total() + e.dissipated;
  energy_scale_ = e.kinetic + e.strain + e.contact;
}

std::size_t Engine::geometry_bytes_per_block() const {
  const int n = block_count();
  if (n == 0) return 0;
  return (geometry_.size() * sizeof(Vec2) + geometry_offset_.size() * sizeof(int)) / static_cast<std::size_t>(n);
}

void Engine::build_blocks(const std::vector<BlockSpec>& blocks) {
  static_assert(sizeof(BlockSide) == 64, "a block's side and tolerance in one cache line");
  const std::size_t n = blocks.size() + scene_.boundaries.size();
  scene_blocks_ = static_cast<int>(blocks.size());
  // The blocks' polygons as values first, then pooled by vertex count.
  std::vector<Polygon> poly(n);
  moments_.resize(n);
  vel_.assign(n, Vec6::Zero());
  acc_.assign(n, Vec6::Zero());
  step_disp_.assign(n, Vec6::Zero());
  step_motion2_.assign(n, 0.0);
  start_centroid_.assign(n, Vec2{});
  disp_.assign(n, Vec6::Zero());
  stress_.assign(n, Vec3::Zero());
  density_.assign(n, 0.0);
  mass_.assign(n, 0.0);
  radius_.assign(n, 0.0);
  h_.assign(n, 0.0);
  const int boundary_elastic = static_cast<int>(scene_.materials.size());
  elastic_table_.assign(scene_.materials.size() + 1, Mat3::Zero());
  for (std::size_t k = 0; k < scene_.materials.size(); ++k)
    elastic_table_[k] = elastic_matrix(scene_.materials[k].young, scene_.materials[k].poisson);
  elastic_index_.assign(n, boundary_elastic);
  fixed_.assign(n, 1);
  group_.assign(n, 0);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockSpec& b = blocks[i];
    const Material& m = scene_.materials[static_cast<std::size_t>(b.material)];
    poly[i] = make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
    density_[i] = m.density;
    elastic_index_[i] = b.material;
    fixed_[i] = b.fixed ? 1 : 0;
    group_[i] = b.group;
    if (!b.fixed) {
      vel_[i][0] = b.velocity.x;
      vel_[i][1] = b.velocity.y;
      vel_[i][2] = b.spin;
    }
  }
  for (std::size_t k = 0; k < scene_.boundaries.size(); ++k) {
    const std::size_t i = blocks.size() + k;
    const std::vector<Vec2> pts = segment_polygon(scene_.boundaries[k]);
    poly[i] = make_polygon(pts.data(), static_cast<int>(pts.size()));
    density_[i] = scene_.materials[0].density;
    group_[i] = scene_.boundaries[k].group;
  }
  // The blocks' names (guard messages), only when the scene names a block.
  block_names_.clear();
  for (const BlockSpec& b : blocks)
    if (!b.name.empty()) {
      block_names_.reserve(blocks.size());
      for (const BlockSpec& named : blocks) block_names_.push_back(named.name);
      break;
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
  geometry_offset_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) geometry_offset_[i + 1] = geometry_offset_[i] + poly[i].count;
  geometry_.assign(2 * static_cast<std::size_t>(geometry_offset_[n]), Vec2{});
  for (std::size_t i = 0; i < n; ++i) {
    const PolygonSpan g = polygon_span(static_cast<int>(i));
    for (int k = 0; k < g.count; ++k) {
      g.v[k] = poly[i].vertex(k);
      g.n[k] = poly[i].normal(k);
    }
  }
  boxes_.resize(n);
  own_bisectors_.resize(n);  // a block's own bisector list only once it has a small edge
  sides_.assign(n, BlockSide{});
  sharp_corners_.assign(n, 0u);
  support_.assign(n, nullptr);
  int pairs = 0;
  for (std::size_t i = 0; i < n; ++i) pairs += support_line_pairs(poly[i].count);
  support_store_.assign(static_cast<std::size_t>(pairs), SupportLines::Pair{});
  for (std::size_t i = 0; i < n; ++i) sides_[i].side.small_edge_rays = scene_.contact.small_edge_rays;
  bind_sides();
}

void Engine::bind_sides() {
  // Each block's contact side reads its polygon from the geometry pool
  // (its bisectors: update_block_geometry); its support lines are in the
  // support store, support_line_pairs(count) per block in block order.
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < sides_.size(); ++i) {
    sides_[i].side.poly = polygon_view(static_cast<int>(i));
    support_[i] = support_store_.data() + pairs;
    pairs += static_cast<std::size_t>(support_line_pairs(sides_[i].side.poly.count));
  }
}

void Engine::choose_broad_phase_skin() {
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

void Engine::choose_potential_length() {
  // H of Eq. 12 from the scene's blocks (boundary polygons have an arbitrary
  // depth and are left out of the edge statistics).
  const ContactParams& c = scene_.contact;
  double lmin = DBL_MAX, lmax = 0.0, lsum = 0.0;
  int edges = 0;
  for (int i = 0; i < scene_blocks_; ++i)
    for (int e = 0; e < polygon_view(i).count; ++e) {
      const double l = length(polygon_view(i).edge(e));
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
    h_[i] = c.h_rule == HRule::kInscribedRadius ? inscribed_circle(polygon_view(i)).radius : h;
    sides_[i].side.kn_over_h = c.kn / h_[i];
    sides_[i].side.small_edge = c.small_edge_fraction * h_[i];
  }
}

}  // namespace dda
