// Read-out of the model's state: energy (kinetic, strain, gravity),
// momentum, block averages, clones and snapshots.
#include "dda/cdem/model.hpp"

#include <algorithm>
#include <limits>

#include "geometry.hpp"
#include "model_ops.hpp"

namespace dda::cdem {

using namespace detail;

double kinetic_energy(const NodeState& nd) {
  double e = 0.0;
  for (std::size_t i = 0; i < nd.x.size(); ++i)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) e += 0.5 * nd.m[i] * length_squared(nd.v[i]);
  return e;
}

CdemEnergy energy_of(const ModelSetup& su, const ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  CdemEnergy en;
  en.kinetic = kinetic_energy(nd);
  en.contact = penalty_energy(su, st.penalty_contacts);
  for (const std::vector<int>* list : {&mesh.coarse_elems, &mesh.fine_elems})
    for (int ei : *list) {
      if (in_submodel(st.submodels, ei)) continue;  // counted in its sub-model
      const Element& e = mesh.elem(ei);
      en.strain += cst_strain_energy({nd.x[e.n[0]], nd.x[e.n[1]], nd.x[e.n[2]]}, e.stress, su.c[st.blocks[e.block].material]);
    }
  if (!st.submodels.live.empty()) en.strain += submodel_strain(su, st);
  for (std::size_t i = 0; i < nd.x.size(); ++i)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) en.gravity -= nd.m[i] * dot(su.scene.gravity, nd.x[i]);
  return en;
}

Vec2 Model::momentum() const {
  const NodeState& nd = state_.nodes;
  Vec2 p{};
  for (std::size_t i = 0; i < nd.x.size(); ++i)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) p += nd.m[i] * nd.v[i];
  return p;
}

double Model::block_mass(int b) const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  double m = 0.0;
  for (int i : st.blocks[b].nodes)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) m += nd.m[i];
  return m;
}

Vec2 Model::block_momentum(int b) const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  Vec2 p{};
  for (int i : st.blocks[b].nodes)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) p += nd.m[i] * nd.v[i];
  return p;
}

Vec2 Model::block_velocity(int b) const { return block_momentum(b) / block_mass(b); }

Vec2 block_mean_position(const ModelState& st, int b) {
  const NodeState& nd = st.nodes;
  Vec2 p{};
  double m = 0.0;
  for (int i : st.blocks[b].nodes)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) {
      p += nd.m[i] * nd.x[i];
      m += nd.m[i];
    }
  return p / m;
}

Vec2 Model::block_mean_position(int b) const { return cdem::block_mean_position(state_, b); }

Vec2 Model::block_displacement(int b) const { return block_mean_position(b) - state_.blocks[b].initial_mean; }

double Model::block_max_velocity_x(int b) const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  double v = -std::numeric_limits<double>::infinity();
  for (int i : st.blocks[b].nodes)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) v = std::max(v, nd.v[i].x);
  return v;
}

double Model::block_min_velocity_x(int b) const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  double v = std::numeric_limits<double>::infinity();
  for (int i : st.blocks[b].nodes)
    if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) v = std::min(v, nd.v[i].x);
  return v;
}

std::vector<Vec2> Model::block_outline(int b) const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  std::vector<Vec2> o;
  for (int i : st.blocks[b].outline) o.push_back(nd.x[i]);
  return o;
}

std::vector<CloneView> Model::clones() const {
  const NodeState& nd = state_.nodes;
  const ModelState& st = state_;
  std::vector<CloneView> out;
  for (const Clone& c : st.clones) {
    CloneView v;
    v.main_node = c.main;
    v.target = c.t;
    v.weight = c.w;
    v.point = nd.x[c.main];
    v.force = c.lambda;
    v.normal = clone_normal(c, st.mesh, nd.x);
    v.fine = c.fine;
    out.push_back(v);
  }
  return out;
}

int Model::active_elements(bool fine) const {
  const MeshState& mesh = state_.mesh;
  return static_cast<int>(fine ? mesh.fine_elems.size() : mesh.coarse_elems.size());
}

Snapshot snapshot_of(const ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  Snapshot s;
  s.time = st.time;
  for (std::size_t ei = 0; ei < mesh.elems.size(); ++ei) {
    const Element& e = mesh.elems[ei];
    if (!e.active) continue;
    if (in_submodel(st.submodels, static_cast<int>(ei))) continue;  // drawn as its sub-model
    Snapshot::Tri t;
    t.x = {nd.x[e.n[0]], nd.x[e.n[1]], nd.x[e.n[2]]};
    t.velocity = (nd.v[e.n[0]] + nd.v[e.n[1]] + nd.v[e.n[2]]) / 3.0;
    t.block = e.block;
    t.fine = e.level > 0;
    t.node = e.n;
    t.v = {nd.v[e.n[0]], nd.v[e.n[1]], nd.v[e.n[2]]};
    t.stress = e.stress;
    s.tris.push_back(t);
  }
  for (const SubModel& sm : st.submodels.live)
    for (const SubElement& se : sm.elems) {
      Snapshot::Tri t;
      t.x = {sm.x[se.n[0]], sm.x[se.n[1]], sm.x[se.n[2]]};
      t.velocity = (sm.v[se.n[0]] + sm.v[se.n[1]] + sm.v[se.n[2]]) / 3.0;
      t.block = mesh.elem(se.parent).block;
      t.fine = true;
      t.v = {sm.v[se.n[0]], sm.v[se.n[1]], sm.v[se.n[2]]};
      t.stress = se.stress;
      s.tris.push_back(t);
    }
  for (const Clone& c : st.clones) s.clone_points.push_back(nd.x[c.main]);
  return s;
}

Snapshot Model::snapshot() const { return snapshot_of(state_); }

CdemEnergy Model::energy() const { return energy_of(setup_, state_); }

CdemEnergyAccount Model::energy_account() const {
  const ModelState& st = state_;
  CdemEnergyAccount a;
  const CdemEnergy e = energy();
  a.time = st.time;
  a.initial = st.energy.initial;
  a.kinetic = e.kinetic;
  a.strain = e.strain;
  a.gravity = e.gravity;
  a.touch_loss = st.energy.impact_loss;
  a.touch_loss_eq5 = st.energy.touch_loss_eq5;
  a.touch_loss_eq5_group = st.energy.touch_loss_eq5_group;
  a.refine_loss = st.energy.refine_loss;
  a.deletion_loss = st.energy.deletion_loss;
  a.submodel_kinetic = submodel_kinetic(st);
  a.other = a.initial - e.total() - a.touch_loss - a.refine_loss - a.deletion_loss;
  return a;
}

}  // namespace dda::cdem
