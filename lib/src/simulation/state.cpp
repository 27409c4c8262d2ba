// Saving and restoring the full state of a simulation (checkpoints): every
// member a step reads and writes, by its bits. What the constructor derives
// from the scene alone and never changes afterwards (materials' elastic
// matrices, H and kn/H, the inscribed radii at t = 0, the friction table,
// the skin, the predicted critical step, the pools' offsets) is not saved:
// the restoring simulation is built from the same scene and has them
// already; the stream's opening record checks that it is that scene's
// (block count, pool sizes, dt, flags). What only sets the thread team's
// shares (measured core speeds, the split of blocks and pairs) is not saved
// either: it changes the time a step takes, never its bits.
#include <algorithm>

#include "dda/state_bytes.hpp"
#include "simulation/internal.hpp"

namespace dda {

namespace {

// The stream's layout; a change of what is saved changes it.
constexpr std::uint32_t kStateLayout = 1;

void put(ByteWriter& w, const Vec6& v) {
  for (int k = 0; k < 6; ++k) w.f64(v[k]);
}
void put(ByteWriter& w, const Vec3& v) {
  for (int k = 0; k < 3; ++k) w.f64(v[k]);
}
void put(ByteWriter& w, const AreaMoments& m) {
  w.f64(m.area);
  w.vec2(m.centroid);
  w.f64(m.sxx);
  w.f64(m.syy);
  w.f64(m.sxy);
}
void put(ByteWriter& w, const Aabb& b) {
  w.vec2(b.lo);
  w.vec2(b.hi);
}
void put(ByteWriter& w, const ContactInfo& c) {
  w.i32(c.cp);
  w.i32(c.tp);
  w.vec2(c.normal_force);
  w.vec2(c.tangential_force);
  w.vec2(c.point);
  w.f64(c.couple);
  w.f64(c.ip_area);
  w.f64(c.ip_length);
  w.boolean(c.sliding);
}

Vec6 get_vec6(ByteReader& r) {
  Vec6 v;
  for (int k = 0; k < 6; ++k) v[k] = r.f64();
  return v;
}
Vec3 get_vec3(ByteReader& r) {
  Vec3 v;
  for (int k = 0; k < 3; ++k) v[k] = r.f64();
  return v;
}
AreaMoments get_moments(ByteReader& r) {
  AreaMoments m;
  m.area = r.f64();
  m.centroid = r.vec2();
  m.sxx = r.f64();
  m.syy = r.f64();
  m.sxy = r.f64();
  return m;
}
Aabb get_aabb(ByteReader& r) {
  Aabb b;
  b.lo = r.vec2();
  b.hi = r.vec2();
  return b;
}
ContactInfo get_contact(ByteReader& r) {
  ContactInfo c;
  c.cp = r.i32();
  c.tp = r.i32();
  c.normal_force = r.vec2();
  c.tangential_force = r.vec2();
  c.point = r.vec2();
  c.couple = r.f64();
  c.ip_area = r.f64();
  c.ip_length = r.f64();
  c.sliding = r.boolean();
  return c;
}

template <class T, class Put>
void put_list(ByteWriter& w, const std::vector<T>& v, Put each) {
  w.list(v, [&](ByteWriter& out, const T& x) { each(out, x); });
}

// Reads a list that must have `expected` elements (the same scene's).
template <class T, class Get>
void get_list(ByteReader& r, std::vector<T>& v, std::size_t expected, const char* name, Get each) {
  r.list(v, 1, each);
  if (v.size() != expected)
    r.fail(std::string(name) + " has " + std::to_string(v.size()) + " entries, this scene needs " +
           std::to_string(expected));
}

}  // namespace

void Engine::save_state(ByteWriter& w) const {
  // The opening record: what the restoring simulation checks it matches.
  w.u32(kStateLayout);
  w.i32(block_count());
  w.i32(scene_blocks_);
  w.u64(geometry_.size());
  w.u64(bisector_store_.size());
  w.f64(dt_);
  w.boolean(strains_);
  w.boolean(friction_);
  w.boolean(exact_rotation_);

  // The clock and the damping's state (Eq. 5c; off after a settle).
  w.f64(time_);
  w.i64(steps_);
  w.boolean(damped_);
  w.f64(damp_a_);
  w.f64(damp_b_);
  put_list(w, force_prev_, [](ByteWriter& o, const Vec6& v) { put(o, v); });
  put_list(w, damp_force_, [](ByteWriter& o, const Vec6& v) { put(o, v); });
  put_list(w, damping_work_, [](ByteWriter& o, double x) { o.f64(x); });

  // The blocks: geometry pool (vertices and normals), moments, boxes, the
  // contact sides' tolerance and bisectors, DOFs, stresses, densities.
  put_list(w, geometry_, [](ByteWriter& o, Vec2 v) { o.vec2(v); });
  put_list(w, moments_, [](ByteWriter& o, const AreaMoments& m) { put(o, m); });
  put_list(w, boxes_, [](ByteWriter& o, const Aabb& b) { put(o, b); });
  put_list(w, bisector_store_, [](ByteWriter& o, const Bisector& b) {
    o.i32(b.line_a);
    o.i32(b.line_b);
    o.f64(b.d0);
  });
  put_list(w, sides_, [](ByteWriter& o, const BlockSide& s) {
    o.f64(s.tol);
    o.i32(s.side.bisector_count);
  });
  for (const std::vector<Vec6>* v : {&vel_, &acc_, &force_, &step_disp_, &disp_})
    put_list(w, *v, [](ByteWriter& o, const Vec6& x) { put(o, x); });
  put_list(w, start_centroid_, [](ByteWriter& o, Vec2 v) { o.vec2(v); });
  put_list(w, step_motion2_, [](ByteWriter& o, double x) { o.f64(x); });
  put_list(w, stress_, [](ByteWriter& o, const Vec3& v) { put(o, v); });
  put_list(w, density_, [](ByteWriter& o, double x) { o.f64(x); });
  put_list(w, mass_, [](ByteWriter& o, double x) { o.f64(x); });

  // The guards' and the energy budget's accumulators.
  put_list(w, reach_radius_, [](ByteWriter& o, double x) { o.f64(x); });
  w.f64(energy0_);
  w.f64(energy_scale_);
  w.f64(dropped_friction_work_);

  // The broad phase and the near pairs with their history.
  put_list(w, near_pairs_, [](ByteWriter& o, const NearPair& p) {
    o.i32(p.i);
    o.i32(p.j);
    o.i32(p.witness);
  });
  put_list(w, pair_results_, [](ByteWriter& o, const PairResult& r) {
    put(o, r.info);
    o.f64(r.energy);
    o.f64(r.depth);
    o.f64(r.depth_bound);
    o.f64(r.approach_energy);
  });
  put_list(w, pair_friction_, [](ByteWriter& o, const PairFriction& f) {
    o.vec2(f.history.d);
    o.vec2(f.history.slide_dir);
    o.vec2(f.history.point);
    o.vec2(f.history.ft);
    o.boolean(f.history.sliding);
    o.f64(f.friction_work);
  });
  put_list(w, pair_loads_, [](ByteWriter& o, const PairLoad& l) {
    o.vec2(l.force);
    o.vec2(l.point);
    o.f64(l.couple);
    o.boolean(l.candidate);
    o.boolean(l.active);
  });
  put_list(w, near_pair_offset_, [](ByteWriter& o, int x) { o.i32(x); });
  put_list(w, block_pairs_, [](ByteWriter& o, const BlockPair& b) {
    o.i32(b.pair);
    o.i32(b.other);
    o.boolean(b.first);
  });
  put_list(w, contact_info_, [](ByteWriter& o, const ContactInfo& c) { put(o, c); });
  w.u64(candidate_count_);
  put_list(w, skin_boxes_, [](ByteWriter& o, const Aabb& b) { put(o, b); });
  put_list(w, order_, [](ByteWriter& o, int x) { o.i32(x); });
  w.i64(broad_phase_rebuilds_);
}

void Engine::restore_state(ByteReader& r) {
  const std::uint32_t layout = r.u32();
  if (layout != kStateLayout)
    r.fail("state layout " + std::to_string(layout) + ", this build reads layout " + std::to_string(kStateLayout));
  const int blocks = r.i32(), scene_blocks = r.i32();
  const std::uint64_t pool = r.u64(), bisectors = r.u64();
  const double dt = r.f64();
  const bool strains = r.boolean(), friction = r.boolean(), exact = r.boolean();
  if (blocks != block_count() || scene_blocks != scene_blocks_ || pool != geometry_.size() ||
      bisectors != bisector_store_.size())
    r.fail("a state of another scene: " + std::to_string(scene_blocks) + " blocks and " +
           std::to_string(blocks - scene_blocks) + " boundary polygons with " + std::to_string(pool / 2) +
           " vertices, this scene has " + std::to_string(scene_blocks_) + " and " +
           std::to_string(block_count() - scene_blocks_) + " with " + std::to_string(geometry_.size() / 2));
  if (!(dt == dt_) || strains != strains_ || friction != friction_ || exact != exact_rotation_)
    r.fail("a state of another scene: its dt, strains, friction or rotation update differ from this scene's");
  const std::size_t n = static_cast<std::size_t>(block_count());

  time_ = r.f64();
  steps_ = r.i64();
  damped_ = r.boolean();
  damp_a_ = r.f64();
  damp_b_ = r.f64();
  r.list(force_prev_, 48, get_vec6);
  r.list(damp_force_, 48, get_vec6);
  r.list(damping_work_, 8, [](ByteReader& in) { return in.f64(); });

  get_list(r, geometry_, geometry_.size(), "the geometry pool", [](ByteReader& in) { return in.vec2(); });
  get_list(r, moments_, n, "the area moments", get_moments);
  get_list(r, boxes_, n, "the boxes", get_aabb);
  get_list(r, bisector_store_, bisector_store_.size(), "the bisector store", [](ByteReader& in) {
    Bisector b;
    b.line_a = in.i32();
    b.line_b = in.i32();
    b.d0 = in.f64();
    return b;
  });
  if (r.count(1) != n) r.fail("the contact sides do not match the blocks");
  for (std::size_t i = 0; i < n; ++i) {
    sides_[i].tol = r.f64();
    const int count = r.i32();
    if (count < 0 || count > 2 * polygon_view(static_cast<int>(i)).count) r.fail("a block's bisector count is out of range");
    sides_[i].side.bisector_count = count;
  }
  for (std::vector<Vec6>* v : {&vel_, &acc_, &force_, &step_disp_, &disp_}) get_list(r, *v, n, "the block DOFs", get_vec6);
  get_list(r, start_centroid_, n, "the step-start centroids", [](ByteReader& in) { return in.vec2(); });
  get_list(r, step_motion2_, n, "the step motions", [](ByteReader& in) { return in.f64(); });
  get_list(r, stress_, n, "the stresses", get_vec3);
  get_list(r, density_, n, "the densities", [](ByteReader& in) { return in.f64(); });
  get_list(r, mass_, n, "the masses", [](ByteReader& in) { return in.f64(); });
  get_list(r, reach_radius_, n, "the reach radii", [](ByteReader& in) { return in.f64(); });
  energy0_ = r.f64();
  energy_scale_ = r.f64();
  dropped_friction_work_ = r.f64();

  const int nb = block_count();
  r.list(near_pairs_, 12, [&](ByteReader& in) {
    NearPair p;
    p.i = in.i32();
    p.j = in.i32();
    p.witness = in.i32();
    if (p.i < 0 || p.i >= p.j || p.j >= nb) in.fail("a near pair's blocks are out of range");
    return p;
  });
  const std::size_t pairs = near_pairs_.size();
  get_list(r, pair_results_, pairs, "the pair results", [](ByteReader& in) {
    PairResult x;
    x.info = get_contact(in);
    x.energy = in.f64();
    x.depth = in.f64();
    x.depth_bound = in.f64();
    x.approach_energy = in.f64();
    return x;
  });
  get_list(r, pair_friction_, friction_ ? pairs : 0, "the friction histories", [](ByteReader& in) {
    PairFriction f;
    f.history.d = in.vec2();
    f.history.slide_dir = in.vec2();
    f.history.point = in.vec2();
    f.history.ft = in.vec2();
    f.history.sliding = in.boolean();
    f.friction_work = in.f64();
    return f;
  });
  get_list(r, pair_loads_, pairs, "the pair loads", [](ByteReader& in) {
    PairLoad l;
    l.force = in.vec2();
    l.point = in.vec2();
    l.couple = in.f64();
    l.candidate = in.boolean();
    l.active = in.boolean();
    return l;
  });
  get_list(r, near_pair_offset_, n + 1, "the block pair offsets", [](ByteReader& in) { return in.i32(); });
  r.list(block_pairs_, 9, [&](ByteReader& in) {
    BlockPair b;
    b.pair = in.i32();
    b.other = in.i32();
    b.first = in.boolean();
    if (b.pair < 0 || static_cast<std::size_t>(b.pair) >= pairs || b.other < 0 || b.other >= nb)
      in.fail("a block's pair entry is out of range");
    return b;
  });
  if (near_pair_offset_.front() != 0 || near_pair_offset_.back() != static_cast<int>(block_pairs_.size()) ||
      !std::is_sorted(near_pair_offset_.begin(), near_pair_offset_.end()))
    r.fail("the block pair offsets do not index the block pair list");
  r.list(contact_info_, 1, [&](ByteReader& in) {
    const ContactInfo c = get_contact(in);
    if (c.cp < 0 || c.cp >= nb || c.tp < 0 || c.tp >= nb) in.fail("a contact's blocks are out of range");
    return c;
  });
  candidate_count_ = static_cast<std::size_t>(r.u64());
  r.list(skin_boxes_, 32, get_aabb);
  if (!skin_boxes_.empty() && skin_boxes_.size() != n) r.fail("the grown boxes do not match the blocks");
  r.list(order_, 4, [&](ByteReader& in) {
    const int i = in.i32();
    if (i < 0 || i >= nb) in.fail("the broad phase's order is out of range");
    return i;
  });
  if (!order_.empty() && order_.size() != n) r.fail("the broad phase's order does not match the blocks");
  broad_phase_rebuilds_ = r.i64();
  // The contact sides read the pools through pointers: bind them again.
  bind_sides();
}

}  // namespace dda
