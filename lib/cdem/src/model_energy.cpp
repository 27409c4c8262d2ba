// Read-out of the model's state: energy (kinetic, strain, gravity),
// momentum, block averages, clones and snapshots.
#include "dda/cdem/model.hpp"

#include <algorithm>
#include <limits>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

double Model::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) e += 0.5 * m_[i] * length_squared(v_[i]);
  return e;
}

CdemEnergy Model::energy() const {
  CdemEnergy en;
  en.kinetic = kinetic_energy();
  en.contact = penalty_energy();
  for (const std::vector<int>* list : {&coarse_elems_, &fine_elems_})
    for (int ei : *list) {
      if (in_submodel(ei)) continue;  // counted in its sub-model
      const Elem& e = elem(ei);
      en.strain += cst_strain_energy({x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]}, e.stress, c_[blocks_[e.block].material]);
    }
  if (!subs_.empty()) en.strain += submodel_strain();
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) en.gravity -= m_[i] * dot(scene_.gravity, x_[i]);
  return en;
}

Vec2 Model::momentum() const {
  Vec2 p{};
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) p += m_[i] * v_[i];
  return p;
}

double Model::block_mass(int b) const {
  double m = 0.0;
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) m += m_[i];
  return m;
}

Vec2 Model::block_momentum(int b) const {
  Vec2 p{};
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) p += m_[i] * v_[i];
  return p;
}

Vec2 Model::block_velocity(int b) const { return block_momentum(b) / block_mass(b); }

Vec2 Model::block_mean_position(int b) const {
  Vec2 p{};
  double m = 0.0;
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) {
      p += m_[i] * x_[i];
      m += m_[i];
    }
  return p / m;
}

Vec2 Model::block_displacement(int b) const { return block_mean_position(b) - blocks_[b].initial_mean; }

double Model::block_max_velocity_x(int b) const {
  double v = -std::numeric_limits<double>::infinity();
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) v = std::max(v, v_[i].x);
  return v;
}

double Model::block_min_velocity_x(int b) const {
  double v = std::numeric_limits<double>::infinity();
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) v = std::min(v, v_[i].x);
  return v;
}

std::vector<Vec2> Model::block_outline(int b) const {
  std::vector<Vec2> o;
  for (int i : blocks_[b].outline) o.push_back(x_[i]);
  return o;
}

std::vector<CloneView> Model::clones() const {
  std::vector<CloneView> out;
  for (const Clone& c : clones_) {
    CloneView v;
    v.main_node = c.main;
    v.target = c.t;
    v.weight = c.w;
    v.point = x_[c.main];
    v.force = c.lambda;
    v.normal = clone_normal(c);
    v.fine = c.fine;
    out.push_back(v);
  }
  return out;
}

int Model::active_elements(bool fine) const {
  return static_cast<int>(fine ? fine_elems_.size() : coarse_elems_.size());
}

Snapshot Model::snapshot() const {
  Snapshot s;
  s.time = time_;
  for (std::size_t ei = 0; ei < elems_.size(); ++ei) {
    const Elem& e = elems_[ei];
    if (!e.active) continue;
    if (in_submodel(static_cast<int>(ei))) continue;  // drawn as its sub-model
    Snapshot::Tri t;
    t.x = {x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
    t.velocity = (v_[e.n[0]] + v_[e.n[1]] + v_[e.n[2]]) / 3.0;
    t.block = e.block;
    t.fine = e.level > 0;
    t.node = e.n;
    t.v = {v_[e.n[0]], v_[e.n[1]], v_[e.n[2]]};
    t.stress = e.stress;
    s.tris.push_back(t);
  }
  for (const SubModel& sm : subs_)
    for (const SubElem& se : sm.elems) {
      Snapshot::Tri t;
      t.x = {sm.x[se.n[0]], sm.x[se.n[1]], sm.x[se.n[2]]};
      t.velocity = (sm.v[se.n[0]] + sm.v[se.n[1]] + sm.v[se.n[2]]) / 3.0;
      t.block = elem(se.parent).block;
      t.fine = true;
      t.v = {sm.v[se.n[0]], sm.v[se.n[1]], sm.v[se.n[2]]};
      t.stress = se.stress;
      s.tris.push_back(t);
    }
  for (const Clone& c : clones_) s.clone_points.push_back(x_[c.main]);
  return s;
}

CdemEnergyAccount Model::energy_account() const {
  CdemEnergyAccount a;
  const CdemEnergy e = energy();
  a.time = time_;
  a.initial = initial_energy_;
  a.kinetic = e.kinetic;
  a.strain = e.strain;
  a.gravity = e.gravity;
  a.touch_loss = impact_loss_;
  a.touch_loss_eq5 = touch_loss_eq5_;
  a.touch_loss_eq5_group = touch_loss_eq5_group_;
  a.refine_loss = refine_loss_;
  a.deletion_loss = deletion_loss_;
  a.submodel_kinetic = submodel_kinetic();
  a.other = a.initial - e.total() - a.touch_loss - a.refine_loss - a.deletion_loss;
  return a;
}

}  // namespace dda::cdem
