// Saving and restoring the CDEM model's full state (checkpoints of dda run,
// pickling in the Python module): every field of ModelState
// (dda/cdem/model_state.hpp), doubles by their bits, in the order the
// header lists them, with the dda/state_bytes.hpp encoding. Nothing is
// left out, not even the fields that are empty or rewritten before they
// are read (the scratch of one step): the stream holds the state as it is,
// so that a restored model is the saved one. The hash-map parts (the edge
// map, the touches per node of the current step) are written in the order
// of their keys, so that one state always gives the same bytes.
//
// ModelSetup is not saved: the restoring model is built from the same scene
// and derives it again. The stream's opening record checks that it is that
// scene's: the block and material counts, dt, the number of coarse
// elements, and a hash (64-bit FNV-1a) of everything that shapes a step:
// the scene's materials, blocks (outline, divisions or own mesh, initial
// velocity, fixed flag, material), gravity, dt and options, and the set-up
// derived from them (elastic and compliance matrices, wave speeds, critical
// steps, the penalty's kn). The scene's name and duration are not in it: a
// restored model may be run on past the duration it was saved with.
//
// A restore reads the whole stream into a new state and checks every index
// against the sizes it read (node, element, lattice, edge, block, material,
// sub-model and record ids; enum values; per-node arrays of one length)
// before it replaces the model's state: a stream that is truncated,
// inconsistent or of another scene throws StateError and leaves the model
// as it was.
//
// The encoding of each part is state_records.hpp / .cpp's; this file holds
// the stream's opening record, its order of the parts and the checks.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/mesh.hpp"
#include "dda/state_bytes.hpp"
#include "model_ops.hpp"
#include "state_records.hpp"

namespace dda::cdem {

using namespace state_io;

namespace {

// The stream's layout; a change of what is saved changes it.
constexpr std::uint32_t kStateLayout = 1;

// --- the opening record ----------------------------------------------------

// 64-bit FNV-1a of a byte string.
std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

// Everything of the set-up that shapes a step, as bytes (the header above).
std::uint64_t setup_hash(const ModelSetup& su) {
  ByteWriter w;
  const CdemScene& sc = su.scene;
  w.u64(sc.materials.size());
  for (const Material& m : sc.materials) {
    put_all(w, m.density, m.young, m.poisson);
  }
  w.u64(sc.blocks.size());
  for (const CdemBlock& b : sc.blocks) {
    put_all(w, b.outline, b.divisions, b.mesh.nodes, b.mesh.triangles, b.velocity, b.fixed, b.material);
  }
  put_all(w, sc.gravity, sc.dt);
  const CdemOptions& o = su.opt;
  put_enum(w, o.contact);
  put_enum(w, o.touch_impact);
  put_all(w, o.penalty_kn, o.tolerance, o.strength.tensile, o.strength.cohesion, o.strength.friction_deg,
          o.subdivision);
  put_enum(w, o.subdivision_mode);
  put_enum(w, o.submodel_transfer);
  put_all(w, o.min_subdivision, o.max_subdivision, o.substep_safety, o.mass_damping, o.check_stability,
          o.capture_touch_snapshots);
  put_enum(w, o.patch_deletion);
  put_all(w, o.contact_point_mass, su.dt, su.d, su.c, su.wave_speed, su.critical_dt, su.element_critical_dt,
          su.contact_critical_dt, su.penalty_kn, su.penalty_max_depth);
  return fnv1a(w.bytes());
}

int coarse_element_count(const MeshState& mesh) {
  return static_cast<int>(std::count_if(mesh.elems.begin(), mesh.elems.end(), [](const Element& e) { return e.level == 0; }));
}

// --- the checks of a state read back --------------------------------------

// Index checks: each id must lie in [lo, n) of the list it indexes.
struct Ids {
  ByteReader& r;
  void in(int id, std::size_t n, const char* what, int lo = 0) const {
    if (id < lo || (id >= 0 && static_cast<std::size_t>(id) >= n))
      r.fail(std::string(what) + " " + std::to_string(id) + " is out of range (" + std::to_string(n) + ")");
  }
  template <class C>
  void all(const C& ids, std::size_t n, const char* what, int lo = 0) const {
    for (int id : ids) in(id, n, what, lo);
  }
  void size(std::size_t got, std::size_t want, const char* what) const {
    if (got != want)
      r.fail(std::string(what) + " has " + std::to_string(got) + " entries, expected " + std::to_string(want));
  }
};

void check(ByteReader& r, const ModelSetup& su, const ModelState& st) {
  const Ids ids{r};
  const NodeState& nd = st.nodes;
  const std::size_t n = nd.x.size();
  for (const auto* v : {&nd.v, &nd.xs, &nd.f, &nd.iface, &nd.iface0, &nd.iimp, &nd.scratch})
    ids.size(v->size(), n, "a per-node list of vectors");
  for (const auto* v : {&nd.m, &nd.inv_m, &nd.hang_w, &nd.released_at}) ids.size(v->size(), n, "a per-node list of numbers");
  for (const auto* v : {&nd.block, &nd.hang_a, &nd.hang_b, &nd.clone_count}) ids.size(v->size(), n, "a per-node list of ids");
  ids.size(nd.kind.size(), n, "the node kinds");
  const std::size_t nb = st.blocks.size(), ne = st.mesh.elems.size(), nl = st.mesh.lattices.size();
  ids.all(nd.block, nb, "a node's block");
  ids.all(nd.hang_a, n, "a hanging node's tie", -1);
  ids.all(nd.hang_b, n, "a hanging node's tie", -1);
  for (const BlockState& b : st.blocks) {
    ids.all(b.nodes, n, "a block's node");
    ids.all(b.outline, n, "a block's outline node");
    ids.in(b.material, su.d.size(), "a block's material");
  }
  const MeshState& mesh = st.mesh;
  for (const Element& e : mesh.elems) {
    ids.all(e.n, n, "an element's corner");
    ids.in(e.block, nb, "an element's block");
    ids.in(e.parent, ne, "an element's parent", -1);
    ids.in(e.lattice, nl, "an element's lattice", -1);
    if (e.level != 0 && e.level != 1) r.fail("an element's level " + std::to_string(e.level) + " is neither 0 nor 1");
  }
  for (const Lattice& l : mesh.lattices) {
    if (l.k < 1) ids.r.fail("a lattice's k " + std::to_string(l.k) + " is below 1");
    ids.size(l.nodes.size(), static_cast<std::size_t>(lattice_count(l.k)), "a lattice's node list");
    ids.in(l.elem, ne, "a lattice's element");
    ids.all(l.nodes, n, "a lattice's node");
    ids.all(l.children, ne, "a lattice's element");
  }
  for (const auto& kv : mesh.edges) {
    const MeshEdge& e = kv.second;
    ids.in(e.lo, n, "an edge's node");
    ids.in(e.hi, n, "an edge's node");
    ids.all(e.elems, ne, "an edge's element", -1);
    ids.all(e.nodes, n, "an edge's node");
  }
  for (const auto* list : {&mesh.coarse_bedges, &mesh.bedges})
    for (const BoundaryEdge& e : *list) {
      ids.in(e.a, n, "a boundary edge's node");
      ids.in(e.b, n, "a boundary edge's node");
      ids.in(e.block, nb, "a boundary edge's block");
    }
  ids.size(mesh.coarse_bedge_elem.size(), mesh.coarse_bedges.size(), "the coarse boundary's elements");
  ids.all(mesh.coarse_bedge_elem, ne, "a coarse boundary edge's element");
  ids.size(mesh.block_bedges.size(), nb, "the blocks' boundary edge lists");
  for (const std::vector<int>& b : mesh.block_bedges) ids.all(b, mesh.bedges.size(), "a block's boundary edge");
  ids.all(mesh.bnodes, n, "a boundary node");
  for (const auto* list : {&mesh.coarse_elems, &mesh.fine_elems, &mesh.coarse_eval, &mesh.patch_eval})
    ids.all(*list, ne, "an element list's element");
  for (const auto* list : {&mesh.coarse_dofs, &mesh.fine_dofs, &mesh.hanging}) ids.all(*list, n, "a node list's node");
  for (const Clone& c : st.clones) {
    ids.in(c.main, n, "a clone's main node");
    ids.all(c.t, n, "a clone's tied node", -1);
    ids.in(c.ea, n, "a clone's edge node", -1);
    ids.in(c.eb, n, "a clone's edge node", -1);
  }
  for (const auto& kv : st.step_touch_count) ids.in(kv.first, n, "a touched node");
  const SubModels& subs = st.submodels;
  for (const SubModel& s : subs.live) {
    const std::size_t ns = s.x.size(), nc = s.coarse.size();
    ids.in(s.record, subs.records.size(), "a sub-model's record");
    ids.all(s.parents, ne, "a sub-model's parent");
    for (const auto* v : {&s.v, &s.f, &s.bc}) ids.size(v->size(), ns, "a sub-model's per-node list");
    for (const auto* v : {&s.m, &s.inv_m, &s.drive_w}) ids.size(v->size(), ns, "a sub-model's per-node list");
    ids.size(s.block.size(), ns, "a sub-model's node blocks");
    ids.size(s.drive.size(), ns, "a sub-model's drives");
    ids.size(s.prescribed.size(), ns, "a sub-model's prescribed flags");
    ids.size(s.home.size(), ns, "a sub-model's homes");
    ids.size(s.home_ab.size(), ns, "a sub-model's home coordinates");
    ids.size(s.home_c.size(), ns, "a sub-model's home corners");
    ids.all(s.block, nb, "a sub-node's block");
    for (const auto& d : s.drive) ids.all(d, nc, "a sub-node's drive", -1);
    ids.all(s.home, ne, "a sub-node's home element", -1);
    for (const auto& c : s.home_c) ids.all(c, nc, "a sub-node's home corner");
    for (const SubElement& e : s.elems) {
      ids.all(e.n, ns, "a sub-element's corner");
      ids.in(e.parent, ne, "a sub-element's parent");
    }
    ids.all(s.coarse, n, "a sub-model's coarse node");
    ids.size(s.coarse_x0.size(), nc, "a sub-model's coarse positions");
    ids.size(s.coarse_force.size(), nc, "a sub-model's coarse forces");
  }
  for (const SubModelRequest& q : subs.requests) {
    ids.in(q.main_node, n, "a sub-model request's node");
    ids.in(q.ea, n, "a sub-model request's edge node", -1);
    ids.in(q.eb, n, "a sub-model request's edge node", -1);
  }
  ids.size(subs.request_touch.size(), subs.requests.size(), "the sub-model requests' touches");
  ids.all(subs.request_touch, st.log.touches.size(), "a sub-model request's touch");
  if (!subs.elem_owner.empty()) ids.size(subs.elem_owner.size(), ne, "the element owners");
  ids.all(subs.elem_owner, subs.live.size(), "an element's sub-model", -1);
  for (const PenaltyContact& p : st.penalty_contacts) {
    ids.in(p.node, n, "a penalty spring's node");
    ids.in(p.a, n, "a penalty spring's edge node");
    ids.in(p.b, n, "a penalty spring's edge node");
  }
}

}  // namespace

void write_state(ByteWriter& w, const ModelSetup& su, const ModelState& st) {
  // The opening record: what the restoring model checks it matches.
  w.u32(kStateLayout);
  w.u64(setup_hash(su));
  w.u64(su.scene.blocks.size());
  w.u64(su.scene.materials.size());
  w.i32(coarse_element_count(st.mesh));
  w.f64(su.dt);

  // The clock.
  put_all(w, st.time, st.step_t0, st.steps);
  // The nodes, the blocks.
  const NodeState& nd = st.nodes;
  for (const auto* v : {&nd.x, &nd.v, &nd.xs, &nd.f, &nd.iface, &nd.iface0, &nd.iimp}) put(w, *v);
  put_all(w, nd.m, nd.inv_m, nd.block);
  w.u64(nd.kind.size());
  for (NodeKind k : nd.kind) put_enum(w, k);
  put_all(w, nd.hang_a, nd.hang_b, nd.hang_w, nd.clone_count, nd.released_at, nd.scratch, st.blocks);
  // The mesh: elements, lattices, the edge map by key, the coarse boundary,
  // then the derived lists.
  const MeshState& mesh = st.mesh;
  put_all(w, mesh.elems, mesh.lattices);
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.edges.size());
  for (const auto& kv : mesh.edges) keys.push_back(kv.first);
  std::sort(keys.begin(), keys.end());
  w.u64(keys.size());
  for (std::uint64_t key : keys) {
    w.u64(key);
    put(w, mesh.edges.at(key));
  }
  put_all(w, mesh.coarse_bedges, mesh.coarse_bedge_elem, mesh.bedges, mesh.block_bedges, mesh.bnodes);
  for (const auto* v : {&mesh.coarse_elems, &mesh.fine_elems, &mesh.coarse_eval, &mesh.patch_eval, &mesh.coarse_dofs,
                        &mesh.fine_dofs, &mesh.hanging})
    put(w, *v);
  // Clones, the touches per node of the current step (by node).
  put(w, st.clones);
  std::vector<std::pair<int, int>> touched(st.step_touch_count.begin(), st.step_touch_count.end());
  std::sort(touched.begin(), touched.end());
  w.u64(touched.size());
  for (const auto& [node, count] : touched) {
    w.i32(node);
    w.i32(count);
  }
  // The in-place patches, the sub-models.
  put_all(w, st.patches.k, st.patches.substeps, st.patches.substeps_taken);
  const SubModels& subs = st.submodels;
  put_all(w, subs.live, subs.records, subs.requests, subs.request_touch, subs.elem_owner, subs.substeps_taken);
  // The penalty springs, the energy ledger, the contact log.
  put(w, st.penalty_contacts);
  const EnergyLedger& e = st.energy;
  for (double x : {e.initial, e.impact_loss, e.remap_change, e.refine_loss, e.deletion_loss, e.touch_loss_eq5,
                   e.touch_loss_eq5_group})
    put(w, x);
  put_all(w, st.log.touches, st.log.separations, st.log.slips);
}

ModelState read_state(ByteReader& r, const ModelSetup& su) {
  const std::uint32_t layout = r.u32();
  if (layout != kStateLayout)
    r.fail("cdem state layout " + std::to_string(layout) + ", this build reads layout " + std::to_string(kStateLayout));
  const std::uint64_t hash = r.u64(), blocks = r.u64(), materials = r.u64();
  const int coarse = r.i32();
  const double dt = r.f64();
  if (blocks != su.scene.blocks.size() || materials != su.scene.materials.size())
    r.fail("a state of another scene: " + std::to_string(blocks) + " blocks of " + std::to_string(materials) +
           " materials, this scene has " + std::to_string(su.scene.blocks.size()) + " of " +
           std::to_string(su.scene.materials.size()));
  if (!(dt == su.dt))
    r.fail("a state of another scene: its dt differs from this scene's");
  if (hash != setup_hash(su))
    r.fail("a state of another scene: its blocks, meshes, materials, gravity or cdem options differ from this scene's");

  ModelState st;
  get_all(r, st.time, st.step_t0, st.steps);
  NodeState& nd = st.nodes;
  for (auto* v : {&nd.x, &nd.v, &nd.xs, &nd.f, &nd.iface, &nd.iface0, &nd.iimp}) get(r, *v);
  get_all(r, nd.m, nd.inv_m, nd.block);
  nd.kind.resize(r.count(1));
  for (NodeKind& k : nd.kind) k = get_enum<NodeKind>(r, static_cast<std::uint8_t>(NodeKind::kDead), "a node kind");
  get_all(r, nd.hang_a, nd.hang_b, nd.hang_w, nd.clone_count, nd.released_at, nd.scratch, st.blocks);
  MeshState& mesh = st.mesh;
  get_all(r, mesh.elems, mesh.lattices);
  // The edges and the touch counts in increasing key order (one state, one stream).
  const std::size_t edges = r.count(8);
  std::uint64_t last_key = 0;
  for (std::size_t k = 0; k < edges; ++k) {
    const std::uint64_t key = r.u64();
    if (k > 0 && !(key > last_key)) r.fail("the edges are not in increasing key order");
    last_key = key;
    MeshEdge& e = mesh.edges[key];
    get(r, e);
    if (e.lo < 0 || e.hi < 0 || !(e.lo < e.hi) || edge_key(e.lo, e.hi) != key) r.fail("an edge's nodes do not match its key");
  }
  get_all(r, mesh.coarse_bedges, mesh.coarse_bedge_elem, mesh.bedges, mesh.block_bedges, mesh.bnodes);
  for (auto* v : {&mesh.coarse_elems, &mesh.fine_elems, &mesh.coarse_eval, &mesh.patch_eval, &mesh.coarse_dofs,
                  &mesh.fine_dofs, &mesh.hanging})
    get(r, *v);
  get(r, st.clones);
  const std::size_t touched = r.count(8);
  int last_node = 0;
  for (std::size_t k = 0; k < touched; ++k) {
    const int node = r.i32();
    if (k > 0 && !(node > last_node)) r.fail("the touch counts are not in increasing node order");
    last_node = node;
    st.step_touch_count.emplace(node, r.i32());
  }
  get_all(r, st.patches.k, st.patches.substeps, st.patches.substeps_taken);
  SubModels& subs = st.submodels;
  get_all(r, subs.live, subs.records, subs.requests, subs.request_touch, subs.elem_owner, subs.substeps_taken,
          st.penalty_contacts);
  EnergyLedger& e = st.energy;
  for (double* x : {&e.initial, &e.impact_loss, &e.remap_change, &e.refine_loss, &e.deletion_loss, &e.touch_loss_eq5,
                    &e.touch_loss_eq5_group})
    get(r, *x);
  get_all(r, st.log.touches, st.log.separations, st.log.slips);

  if (st.blocks.size() != su.scene.blocks.size()) r.fail("the state's blocks do not match the scene's");
  if (coarse_element_count(mesh) != coarse)
    r.fail("the state holds " + std::to_string(coarse_element_count(mesh)) + " coarse elements, its opening record " +
           std::to_string(coarse));
  check(r, su, st);
  return st;
}

void Model::save_state(ByteWriter& w) const { write_state(w, setup_, state_); }

void Model::restore_state(ByteReader& r) {
  // Read and checked whole before the model's state is replaced.
  ModelState st = read_state(r, setup_);
  const int coarse = coarse_element_count(state_.mesh);
  if (coarse_element_count(st.mesh) != coarse)
    r.fail("a state of another scene: " + std::to_string(coarse_element_count(st.mesh)) + " coarse elements, this scene has " +
           std::to_string(coarse));
  state_ = std::move(st);
}

}  // namespace dda::cdem
