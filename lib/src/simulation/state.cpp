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
#include <cstdint>
#include <cstring>

#include "dda/state_bytes.hpp"
#include "simulation/friction.hpp"  // friction_tan
#include "simulation/internal.hpp"

namespace dda {

namespace {

// The stream's layout; a change of what is saved changes it.
constexpr std::uint32_t kStateLayout = 2;

// One field of a record, written (Put) or read into the record (Get).
struct Put {
  ByteWriter& w;
  void operator()(double x) { w.f64(x); }
  void operator()(int x) { w.i32(x); }
  void operator()(bool x) { w.boolean(x); }
  void operator()(Vec2 v) { w.vec2(v); }
  void operator()(const Vec3& v) {
    for (int k = 0; k < 3; ++k) w.f64(v[k]);
  }
  void operator()(const Vec6& v) {
    for (int k = 0; k < 6; ++k) w.f64(v[k]);
  }
};
struct Get {
  ByteReader& r;
  void operator()(double& x) { x = r.f64(); }
  void operator()(int& x) { x = r.i32(); }
  void operator()(bool& x) { x = r.boolean(); }
  void operator()(Vec2& v) { v = r.vec2(); }
  void operator()(Vec3& v) {
    for (int k = 0; k < 3; ++k) v[k] = r.f64();
  }
  void operator()(Vec6& v) {
    for (int k = 0; k < 6; ++k) v[k] = r.f64();
  }
};

// Each record's fields in stream order, once for both directions: `io` is
// a Put (the record const) or a Get.
constexpr auto value = [](auto& io, auto& x) { io(x); };
constexpr auto moments = [](auto& io, auto& m) {
  io(m.area);
  io(m.centroid);
  io(m.sxx);
  io(m.syy);
  io(m.sxy);
};
constexpr auto box = [](auto& io, auto& b) {
  io(b.lo);
  io(b.hi);
};
constexpr auto bisector = [](auto& io, auto& b) {
  io(b.line_a);
  io(b.line_b);
  io(b.d0);
};
constexpr auto block_side = [](auto& io, auto& s) {
  io(s.tol);
  io(s.side.bisector_count);
};
constexpr auto contact = [](auto& io, auto& c) {
  io(c.cp);
  io(c.tp);
  io(c.normal_force);
  io(c.tangential_force);
  io(c.point);
  io(c.couple);
  io(c.ip_area);
  io(c.ip_length);
  io(c.sliding);
};
// A near pair as the stream stores it: its blocks and witness (an int).
struct NearPairRecord {
  int i = -1, j = -1, witness = -1;
};
constexpr auto near_pair = [](auto& io, auto& p) {
  io(p.i);
  io(p.j);
  io(p.witness);
};
// A near pair's contact as the stream stores it: its ContactInfo (the
// engine keeps its fields in the pair, its load and its contact slot) and
// the guards' measures; a pair not touching stores a fresh one.
struct PairResultRecord {
  ContactInfo info;
  double energy = 0.0, depth = 0.0, depth_bound = 0.0, approach_energy = 0.0;
};
constexpr auto pair_result = [](auto& io, auto& x) {
  contact(io, x.info);
  io(x.energy);
  io(x.depth);
  io(x.depth_bound);
  io(x.approach_energy);
};
// A near pair's friction state as the stream stores it: the history with
// the last evaluation's pg and tangential force (the engine reads them from
// the pair's load and result), and the work friction took out of the two
// blocks while the pair was near (J/m). A pair not touching stores a fresh
// history.
struct FrictionRecord {
  Vec2 d{}, slide_dir{}, point{}, ft{};
  bool sliding = false;
  double friction_work = 0.0;
};
constexpr auto friction_history = [](auto& io, auto& f) {
  io(f.d);
  io(f.slide_dir);
  io(f.point);
  io(f.ft);
  io(f.sliding);
  io(f.friction_work);
};
// A near pair's load as the stream stores it: with the pair's flags (the
// engine keeps them in its NearPair).
struct PairLoadRecord {
  Vec2 force{}, point{};
  double couple = 0.0;
  bool candidate = false, active = false;
};
constexpr auto pair_load = [](auto& io, auto& l) {
  io(l.force);
  io(l.point);
  io(l.couple);
  io(l.candidate);
  io(l.active);
};
// A block's near-pair entry as the stream stores it: with the other block
// and whether the block is the pair's first (the engine keeps the pair's
// index and derives them from the pair).
struct BlockPairRecord {
  int pair = -1, other = -1;
  bool first = false;
};
constexpr auto block_pair = [](auto& io, auto& b) {
  io(b.pair);
  io(b.other);
  io(b.first);
};

template <class T, class Fields>
void put_list(ByteWriter& w, const std::vector<T>& v, Fields fields) {
  w.list(v, [&](ByteWriter& out, const T& x) {
    Put io{out};
    fields(io, x);
  });
}

// One element of a list, read by `fields`.
template <class T, class Fields>
auto element(Fields fields) {
  return [fields](ByteReader& in) {
    T x;
    Get io{in};
    fields(io, x);
    return x;
  };
}

// Reads a list that must have `expected` elements (the same scene's).
template <class T, class Fields>
void get_list(ByteReader& r, std::vector<T>& v, std::size_t expected, const char* name, Fields fields) {
  r.list(v, 1, element<T>(fields));
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
  put_list(w, force_prev_, value);
  put_list(w, damp_force_, value);
  put_list(w, damping_work_, value);

  // The blocks: geometry pool (vertices and normals), moments, boxes, the
  // contact sides' tolerance and bisectors, DOFs, stresses, densities.
  put_list(w, geometry_, value);
  put_list(w, moments_, moments);
  put_list(w, boxes_, box);
  {
    // Each block's bisectors in block order, as many as its side counts.
    std::vector<Bisector> listed;
    for (const BlockSide& b : sides_) listed.insert(listed.end(), b.side.bisectors, b.side.bisectors + b.side.bisector_count);
    put_list(w, listed, bisector);
  }
  put_list(w, sides_, block_side);
  for (const std::vector<Vec6>* v : {&vel_, &acc_, &step_disp_, &disp_}) put_list(w, *v, value);
  put_list(w, start_centroid_, value);
  put_list(w, step_motion2_, value);
  put_list(w, stress_, value);
  put_list(w, density_, value);
  put_list(w, mass_, value);

  // The guards' and the energy budget's accumulators.
  {
    std::vector<double> reach(static_cast<std::size_t>(block_count()));
    for (int i = 0; i < block_count(); ++i) reach[static_cast<std::size_t>(i)] = reach_radius(i);
    put_list(w, reach, value);
  }
  w.f64(energy0_);
  w.f64(energy_scale_);
  w.f64(dropped_friction_work_);

  // The broad phase and the near pairs with their history: per near pair,
  // its contact (from its slot, its load and the pair; a pair not touching
  // has none, and stores a fresh one, which no step reads) and its friction
  // state. The slots themselves are not saved: where a contact sits never
  // enters a result.
  {
    std::vector<NearPairRecord> records(near_pairs_.size());
    for (std::size_t k = 0; k < near_pairs_.size(); ++k)
      records[k] = {near_pairs_[k].i, near_pairs_[k].j, near_pairs_[k].witness};
    put_list(w, records, near_pair);
  }
  {
    std::vector<PairResultRecord> results(near_pairs_.size());
    std::vector<FrictionRecord> friction(friction_ ? near_pairs_.size() : 0);
    for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
      const int slot = near_pairs_[k].slot;
      if (slot >= 0) {
        const PairResult& c = contact_slots_[static_cast<std::size_t>(slot)].result;
        results[k] = {contact_info(k), c.energy, c.depth, c.depth_bound, c.approach_energy};
      }
      if (!friction_) continue;
      if (slot >= 0) {
        const PairHistory& h = contact_slots_[static_cast<std::size_t>(slot)].history;
        const PairResultRecord& c = results[k];
        friction[k] = {h.d, h.slide_dir, c.info.point, c.info.tangential_force, h.sliding, 0.0};
      }
      friction[k].friction_work = pair_friction_work_[k];
    }
    put_list(w, results, pair_result);
    put_list(w, friction, friction_history);
  }
  {
    std::vector<PairLoadRecord> records(near_pairs_.size());
    for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
      const PairLoad& l = pair_loads_[k];
      records[k] = {l.force, l.point, l.couple, near_pairs_[k].candidate, near_pairs_[k].active};
    }
    put_list(w, records, pair_load);
  }
  put_list(w, near_pair_offset_, value);
  {
    std::vector<BlockPairRecord> records(block_pairs_.size());
    for (int i = 0; i < block_count(); ++i)
      for (int q = near_pair_offset_[static_cast<std::size_t>(i)]; q < near_pair_offset_[static_cast<std::size_t>(i) + 1]; ++q) {
        const int k = block_pairs_[static_cast<std::size_t>(q)];
        const NearPair& p = near_pairs_[static_cast<std::size_t>(k)];
        records[static_cast<std::size_t>(q)] = {k, p.i == i ? p.j : p.i, p.i == i};
      }
    put_list(w, records, block_pair);
  }
  put_list(w, contacts(), contact);
  w.u64(candidate_count_);
  put_list(w, skin_boxes_, box);
  put_list(w, order_, value);
  w.i64(broad_phase_rebuilds_);
}

void Engine::restore_state(ByteReader& r) {
  const std::uint32_t layout = r.u32();
  if (layout != kStateLayout)
    r.fail("state layout " + std::to_string(layout) + ", this build reads layout " + std::to_string(kStateLayout));
  const int blocks = r.i32(), scene_blocks = r.i32();
  const std::uint64_t pool = r.u64();
  const double dt = r.f64();
  const bool strains = r.boolean(), friction = r.boolean(), exact = r.boolean();
  if (blocks != block_count() || scene_blocks != scene_blocks_ || pool != geometry_.size())
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
  r.list(force_prev_, 48, element<Vec6>(value));
  r.list(damp_force_, 48, element<Vec6>(value));
  r.list(damping_work_, 8, element<double>(value));

  get_list(r, geometry_, geometry_.size(), "the geometry pool", value);
  get_list(r, moments_, n, "the area moments", moments);
  get_list(r, boxes_, n, "the boxes", box);
  std::vector<Bisector> rays_listed;
  r.list(rays_listed, 16, element<Bisector>(bisector));
  if (r.count(1) != n) r.fail("the contact sides do not match the blocks");
  std::size_t at = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Get io{r};
    block_side(io, sides_[i]);
    PotentialSide& side = sides_[i].side;
    const int count = side.bisector_count, vertices = polygon_view(static_cast<int>(i)).count;
    if (count < 0 || count > 2 * vertices || at + static_cast<std::size_t>(count) > rays_listed.size())
      r.fail("a block's bisector count is out of range");
    // The vertex rays (bit for bit) point to the shared list, others to the block's own.
    const Bisector* const from = rays_listed.data() + at;
    const Bisector* const rays = detail::vertex_rays(vertices);
    bool plain = count == vertices;
    for (int k = 0; plain && k < count; ++k)
      plain = from[k].line_a == rays[k].line_a && from[k].line_b == rays[k].line_b &&
                    std::memcmp(&from[k].d0, &rays[k].d0, sizeof(double)) == 0;
    if (count == 0) {
      side.bisectors = nullptr;
    } else if (plain) {
      side.bisectors = rays;
    } else {
      std::unique_ptr<Bisector[]>& own = own_bisectors_[i];
      if (!own) own.reset(new Bisector[static_cast<std::size_t>(2 * vertices)]);
      std::copy(from, from + count, own.get());
      side.bisectors = own.get();
    }
    at += static_cast<std::size_t>(count);
  }
  if (at != rays_listed.size()) r.fail("the bisector list does not match the blocks' counts");
  for (std::vector<Vec6>* v : {&vel_, &acc_, &step_disp_, &disp_}) get_list(r, *v, n, "the block DOFs", value);
  get_list(r, start_centroid_, n, "the step-start centroids", value);
  get_list(r, step_motion2_, n, "the step motions", value);
  get_list(r, stress_, n, "the stresses", value);
  get_list(r, density_, n, "the densities", value);
  get_list(r, mass_, n, "the masses", value);
  {
    // What reach_radius finds from the candidate flags restored below.
    std::vector<double> reach;
    get_list(r, reach, n, "the reach radii", value);
  }
  energy0_ = r.f64();
  energy_scale_ = r.f64();
  dropped_friction_work_ = r.f64();

  const int nb = block_count();
  const auto read_pair = element<NearPairRecord>(near_pair);
  r.list(near_pairs_, 12, [&](ByteReader& in) {
    const NearPairRecord p = read_pair(in);
    if (p.i < 0 || p.i >= p.j || p.j >= nb) in.fail("a near pair's blocks are out of range");
    if (p.witness < -1 || p.witness > INT16_MAX) in.fail("a near pair's witness axis is out of range");
    NearPair q;
    q.i = p.i;
    q.j = p.j;
    q.witness = static_cast<std::int16_t>(p.witness);
    return q;
  });
  const std::size_t pairs = near_pairs_.size();
  std::vector<PairResultRecord> results;
  std::vector<FrictionRecord> frictions;
  get_list(r, results, pairs, "the pair results", pair_result);
  get_list(r, frictions, friction_ ? pairs : 0, "the friction histories", friction_history);
  {
    std::vector<PairLoadRecord> records;
    get_list(r, records, pairs, "the pair loads", pair_load);
    pair_loads_.resize(pairs);
    for (std::size_t k = 0; k < pairs; ++k) {
      pair_loads_[k] = {records[k].force, records[k].point, records[k].couple};
      near_pairs_[k].candidate = records[k].candidate;
      near_pairs_[k].active = records[k].active;
    }
  }
  // The touching pairs' contacts into slots (in pair order); what the
  // others stored is never read (a pair that begins to touch starts afresh).
  // Of a contact's blocks, load point and couple, and of its history's pg
  // and tangential force, the engine keeps one copy (the pair's, its
  // load's and its result's): a stream saved by save_state holds the same
  // values in each.
  std::size_t touching = 0;
  for (const NearPair& p : near_pairs_) touching += p.active ? 1 : 0;
  contact_slots_.clear();
  contact_slots_.reserve(touching);
  free_slots_.clear();
  pair_friction_work_.assign(friction_ ? pairs : 0, 0.0);
  for (std::size_t k = 0; k < pairs; ++k) {
    if (friction_) pair_friction_work_[k] = frictions[k].friction_work;
    near_pairs_[k].slot = -1;
    if (!near_pairs_[k].active) continue;
    near_pairs_[k].slot = static_cast<int>(contact_slots_.size());
    const PairResultRecord& c = results[k];
    ContactSlot s;
    s.result = {c.info.normal_force, c.info.tangential_force, c.info.ip_area, c.info.ip_length,
                c.energy,           c.depth,                  c.depth_bound,  c.approach_energy};
    if (friction_)
      s.history = {frictions[k].d, frictions[k].slide_dir, frictions[k].sliding,
                   friction_tan(near_pairs_[k].i, near_pairs_[k].j)};
    contact_slots_.push_back(s);
  }
  get_list(r, near_pair_offset_, n + 1, "the block pair offsets", value);
  const auto read_block_pair = element<BlockPairRecord>(block_pair);
  std::vector<BlockPairRecord> records;
  r.list(records, 9, [&](ByteReader& in) {
    const BlockPairRecord b = read_block_pair(in);
    if (b.pair < 0 || static_cast<std::size_t>(b.pair) >= pairs || b.other < 0 || b.other >= nb)
      in.fail("a block's pair entry is out of range");
    return b;
  });
  if (near_pair_offset_.front() != 0 || near_pair_offset_.back() != static_cast<int>(records.size()) ||
      !std::is_sorted(near_pair_offset_.begin(), near_pair_offset_.end()))
    r.fail("the block pair offsets do not index the block pair list");
  block_pairs_.resize(records.size());
  for (int i = 0; i < nb; ++i)
    for (int q = near_pair_offset_[static_cast<std::size_t>(i)]; q < near_pair_offset_[static_cast<std::size_t>(i) + 1]; ++q) {
      const BlockPairRecord& b = records[static_cast<std::size_t>(q)];
      const NearPair& p = near_pairs_[static_cast<std::size_t>(b.pair)];
      if ((p.i != i && p.j != i) || b.other != (p.i == i ? p.j : p.i) || b.first != (p.i == i))
        r.fail("a block's pair entry names the wrong blocks");
      block_pairs_[static_cast<std::size_t>(q)] = b.pair;
    }
  set_pair_radii();
  // The touching pairs' contacts once more (what contacts() returned when
  // the stream was saved): checked, not kept (contacts() builds them from
  // the pairs).
  const auto read_contact = element<ContactInfo>(contact);
  std::vector<ContactInfo> listed;
  r.list(listed, 1, [&](ByteReader& in) {
    const ContactInfo c = read_contact(in);
    if (c.cp < 0 || c.cp >= nb || c.tp < 0 || c.tp >= nb) in.fail("a contact's blocks are out of range");
    return c;
  });
  candidate_count_ = static_cast<std::size_t>(r.u64());
  r.list(skin_boxes_, 32, element<Aabb>(box));
  if (!skin_boxes_.empty() && skin_boxes_.size() != n) r.fail("the grown boxes do not match the blocks");
  r.list(order_, 4, [&](ByteReader& in) {
    const int i = in.i32();
    if (i < 0 || i >= nb) in.fail("the broad phase's order is out of range");
    return i;
  });
  if (!order_.empty() && order_.size() != n) r.fail("the broad phase's order does not match the blocks");
  broad_phase_rebuilds_ = r.i64();
  // The contact sides read the pools through pointers: bind them again;
  // the overlap test's facts of each polygon are found again, not stored.
  bind_sides();
  for (int i = 0; i < nb; ++i) block_facts(i);
}

}  // namespace dda
