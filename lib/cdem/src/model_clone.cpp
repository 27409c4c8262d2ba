// Paper B Sect. 4.1: the clone (unified) node formed at a touch, the
// perfectly inelastic impact that sets its velocity (Eq. 4, energy loss
// Eq. 5), and the clone's geometry (normal, tributary length A_c).
#include "dda/cdem/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

bool Model::in_clone(int node) const { return clone_count_[node] > 0; }

// A node cannot start a new touch while it is a clone's main node or is tied
// node-to-node; a node tied as an end of a touched edge (weight < 1) can, so
// that a corner of a face in contact still finds the other block.
bool Model::touch_blocked(int node) const {
  for (const Clone& c : clones_)
    if (c.main == node || (c.t[0] == node && c.t[1] < 0)) return true;
  return false;
}

// Nodes tied with `node` by some clone (a touch between them is that clone).
std::vector<int> Model::tied_partners(int node) const {
  std::vector<int> out;
  for (const Clone& c : clones_) {
    const bool has = c.main == node || c.t[0] == node || c.t[1] == node;
    if (!has) continue;
    for (int a : {c.main, c.t[0], c.t[1]})
      if (a >= 0 && a != node) out.push_back(a);
  }
  return out;
}

std::vector<int> Model::clone_component(int ci) const {
  std::vector<int> comp{ci};
  std::vector<char> in(clones_.size(), 0);
  in[static_cast<std::size_t>(ci)] = 1;
  auto nodes_of = [&](const Clone& c) {
    std::vector<int> n{c.main};
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0 && c.w[q] != 0.0) n.push_back(c.t[q]);
    return n;
  };
  for (std::size_t head = 0; head < comp.size(); ++head) {
    const std::vector<int> a = nodes_of(clones_[static_cast<std::size_t>(comp[head])]);
    for (std::size_t j = 0; j < clones_.size(); ++j) {
      if (in[j] || clones_[j].fine != clones_[static_cast<std::size_t>(ci)].fine) continue;
      const std::vector<int> b = nodes_of(clones_[j]);
      bool share = false;
      for (int x : a)
        for (int y : b) share = share || x == y;
      if (share) {
        in[j] = 1;
        comp.push_back(static_cast<int>(j));
      }
    }
  }
  return comp;
}

// Eq. 5 for a clone group (the clones projected together at a touch, see
// project_component). The group's perfectly inelastic projection is Eq. 4
// for several ties at once: it conserves momentum (equal and opposite
// impulses along the ties) and leaves every tie's relative velocity zero,
// the tie of a sliding clone its normal part only (Eq. 10). Its loss, from
// the group's masses and velocities, is
//   dE = 1/2 r^T W^+ r,  r = C v (the ties' relative velocities),
//   W = C M^-1 C^T (the ties' inverse effective masses),
// the least-squares form of the same projection; for one clone W is the
// scalar 1/m_m + sum w_q^2 / m_tq and dE is Eq. 5 (1/2 m_m m_t / (m_m +
// m_t) |v_m - v_t|^2). It bounds the loss of any impulses along these ties
// (the projection is the least kinetic energy they reach), so it also bounds
// a Coulomb touch (TouchImpact::kCoulomb). comp[0] (the new clone) counts
// with both rows, as in Eq. 4. W^+ by eigen-decomposition: eigenvalues
// below kRankTolerance of the largest are dropped (ties that repeat others,
// e.g. two corners each tied to the other's face).
double Model::group_eq5(const std::vector<int>& comp) const {
  constexpr double kRankTolerance = 1e-12;  // relative; W's entries are sums of 1/m, round-off ~1e-16
  std::vector<Vec2> dirs;                   // one row per tie direction
  std::vector<int> row_clone;
  for (std::size_t k = 0; k < comp.size(); ++k) {
    const Clone& cl = clones_[static_cast<std::size_t>(comp[k])];
    if (cl.sliding && k > 0) {
      dirs.push_back(clone_normal(cl));
      row_clone.push_back(comp[k]);
    } else {
      dirs.push_back({1.0, 0.0});
      row_clone.push_back(comp[k]);
      dirs.push_back({0.0, 1.0});
      row_clone.push_back(comp[k]);
    }
  }
  const int n = static_cast<int>(dirs.size());
  // the tie's nodes and coefficients: main +1, targets -w_q
  auto terms = [&](const Clone& cl) {
    std::vector<std::pair<int, double>> t{{cl.main, 1.0}};
    for (int q = 0; q < 2; ++q)
      if (cl.t[q] >= 0 && cl.w[q] != 0.0) t.push_back({cl.t[q], -cl.w[q]});
    return t;
  };
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    const auto ti = terms(clones_[static_cast<std::size_t>(row_clone[i])]);
    for (const auto& [node, c] : ti) r(i) += c * dot(dirs[i], v_[node]);
    for (int j = 0; j < n; ++j) {
      const auto tj = terms(clones_[static_cast<std::size_t>(row_clone[j])]);
      for (const auto& [a, ca] : ti)
        for (const auto& [b, cb] : tj)
          if (a == b) w(i, j) += ca * cb * inv_m_[a] * dot(dirs[i], dirs[j]);
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(w);
  const double top = eig.eigenvalues().cwiseAbs().maxCoeff();
  if (!(top > 0.0)) return 0.0;
  const Eigen::VectorXd q = eig.eigenvectors().transpose() * r;
  double e = 0.0;
  for (int i = 0; i < n; ++i)
    if (eig.eigenvalues()(i) > kRankTolerance * top) e += q(i) * q(i) / eig.eigenvalues()(i);
  return 0.5 * e;
}

// Perfectly inelastic impact (Eq. 4): the velocities of the clone's nodes
// are projected onto the tie (main = sum w_q target_q) with the impulse
// that conserves momentum; coupled clones (sharing nodes) are projected
// together by Gauss-Seidel (the group's Eq. 4, its loss the group's Eq. 5,
// group_eq5). Returns the kinetic energy lost. With `rec` (a touch: clone
// ci is new) the new clone's impulse is recorded, and with
// TouchImpact::kCoulomb (beyond the paper) the new clone's tangential
// impulse is capped at tan(phi) times its normal impulse (a projected
// Gauss-Seidel step: each update minimises the kinetic energy over the
// clone's impulse within the cap, so the loss stays below the group's
// Eq. 5); capped, the clone starts sliding (Eq. 10).
double Model::project_component(int ci, TouchRecord* rec) {
  const std::vector<int> comp = clone_component(ci);
  std::vector<int> nodes;
  for (int c : comp) {
    const Clone& cl = clones_[static_cast<std::size_t>(c)];
    nodes.push_back(cl.main);
    for (int q = 0; q < 2; ++q)
      if (cl.t[q] >= 0 && cl.w[q] != 0.0) nodes.push_back(cl.t[q]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto ke = [&] {
    double e = 0.0, vmax = 0.0;
    for (int n : nodes) {
      e += 0.5 * m_[n] * length_squared(v_[n]);
      vmax = std::max(vmax, length(v_[n]));
    }
    return std::make_pair(e, vmax);
  };
  if (rec) rec->energy_loss_eq5_group = group_eq5(comp);
  const bool coulomb = rec && opt_.touch_impact == TouchImpact::kCoulomb;
  constexpr double kPi = 3.14159265358979323846;
  const double tan_phi = std::tan(opt_.strength.friction_deg * kPi / 180.0);
  double jn_new = 0.0, jt_new = 0.0;  // the new clone's accumulated impulse (normal, tangential)
  bool capped = false;
  const auto [before, vscale] = ke();
  for (int it = 0; it < 500; ++it) {
    double worst = 0.0;
    for (int c : comp) {
      const Clone& cl = clones_[static_cast<std::size_t>(c)];
      Vec2 r = v_[cl.main];
      double w = inv_m_[cl.main];
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) {
          r -= cl.w[q] * v_[cl.t[q]];
          w += cl.w[q] * cl.w[q] * inv_m_[cl.t[q]];
        }
      if (!(w > 0.0)) continue;
      if (cl.sliding) {  // only the normal velocity is tied (Eq. 10)
        const Vec2 n = clone_normal(cl);
        r = dot(r, n) * n;
      }
      Vec2 j = -(1.0 / w) * r;
      if (c == ci && rec) {
        const Vec2 n = clone_normal(cl), u = perp_left(n);
        const double jn = jn_new + dot(j, n), jt_want = jt_new + dot(j, u);
        double jt = jt_want;
        if (coulomb) {
          const double lim = tan_phi * std::max(jn, 0.0);
          jt = std::clamp(jt_want, -lim, lim);
          capped = jt != jt_want;
        }
        j = (jn - jn_new) * n + (jt - jt_new) * u;
        jn_new = jn;
        jt_new = jt;
      }
      worst = std::max(worst, w * length(j));
      v_[cl.main] += inv_m_[cl.main] * j;
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) v_[cl.t[q]] -= (cl.w[q] * inv_m_[cl.t[q]]) * j;
    }
    if (worst <= 1e-14 * (vscale + 1e-300)) break;
  }
  if (rec) {
    rec->impulse_normal = jn_new;
    rec->impulse_tangential = jt_new;
    rec->coulomb_capped = capped;
    if (capped) clones_[static_cast<std::size_t>(ci)].sliding = true;
  }
  return before - ke().first;
}

bool Model::process_touch(const Touch& touch, bool fine_level, double t, double t0, double t1) {
  const int m = touch.node;
  if (touch_blocked(m) || kind_[m] == NodeKind::kDead || kind_[m] == NodeKind::kHanging) return false;
  {
    const std::vector<int> partners = tied_partners(m);
    auto tied = [&](int a) { return std::find(partners.begin(), partners.end(), a) != partners.end(); };
    if ((touch.xi <= kNodeTieXi && tied(touch.ea)) || (touch.xi >= 1.0 - kNodeTieXi && tied(touch.eb))) return false;
  }
  int ea = touch.ea, eb = touch.eb;
  const int bm = node_block_[m], bt = node_block_[ea];
  // A node that touches again and again within one coarse step chatters
  // (each touch separates at once): the contact is not resolved.
  constexpr int kMaxTouchesPerStep = 1000;
  if (++step_touch_count_[m] > kMaxTouchesPerStep) {
    const Vec2 e = x_[eb] - x_[ea];
    const double depth = std::max(0.0, -cross(x_[m] - x_[ea], e) / length(e));
    std::ostringstream s;
    s << "cdem: node " << m << " of block " << bm << " touched block " << bt << " " << kMaxTouchesPerStep
      << " times within step " << steps_ + 1 << " (t = " << t << " s, depth " << depth
      << " m): each clone separates at once and the contact is not resolved; try a smaller dt";
    throw ContactError(s.str(), m, bm, bt, steps_ + 1, t, depth, StopReason::kOther);
  }
  double xi = touch.xi;
  {
    const Vec2 e = x_[eb] - x_[ea];
    xi = std::clamp(dot(x_[m] - x_[ea], e) / length_squared(e), 0.0, 1.0);
  }
  const Vec2 point = lerp(x_[ea], x_[eb], xi);
  TouchRecord rec;
  rec.time = t;
  rec.step_start = t0;
  rec.step_end = t1;
  rec.dt1 = t - t0;
  rec.dt2 = t1 - t;
  rec.fine = fine_level;
  rec.main_node = m;
  rec.main_block = bm;
  rec.target_block = bt;
  rec.point = point;

  if (submodel_mode())
    request_submodel(m, point, ea, eb, rec);  // Sect. 5 step 1, built at the step end
  else if (opt_.subdivision)
    refine_contact_zone(m, point, ea, eb, xi, rec);

  Clone c;
  c.main = m;
  c.ea = ea;
  c.eb = eb;
  const double len = distance(x_[ea], x_[eb]);
  if (xi * len <= kNodeTieXi * len) {
    c.t = {ea, -1};
    c.w = {1.0, 0.0};
  } else if ((1.0 - xi) * len <= kNodeTieXi * len) {
    c.t = {eb, -1};
    c.w = {1.0, 0.0};
  } else {
    c.t = {ea, eb};
    c.w = {1.0 - xi, xi};
  }
  rec.node_to_node = c.t[1] < 0;
  c.area = tributary_length(m);
  c.fine = kind_[m] == NodeKind::kFine;
  for (int q = 0; q < 2; ++q) {
    const int a = c.t[q];
    if (a < 0 || blocks_[node_block_[a]].fixed) continue;
    if ((kind_[a] == NodeKind::kFine) != c.fine)
      throw SimulationError("cdem: clone nodes on two integration levels (internal error)");
  }
  rec.mass_main = m_[m];
  double inv_t = 0.0;
  Vec2 vt{};
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) {
      inv_t += c.w[q] * c.w[q] * inv_m_[c.t[q]];
      vt += c.w[q] * v_[c.t[q]];
    }
  rec.mass_target = inv_t > 0.0 ? 1.0 / inv_t : 0.0;
  rec.v_main = v_[m];
  rec.v_target = vt;
  const double inv_sum = inv_m_[m] + inv_t;
  rec.energy_loss_eq5 = inv_sum > 0.0 ? 0.5 / inv_sum * length_squared(v_[m] - vt) : 0.0;
  clones_.push_back(c);
  clone_count_[m] += 1;
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) clone_count_[c.t[q]] += 1;
  rec.energy_loss = project_component(static_cast<int>(clones_.size()) - 1, &rec);
  rec.v_clone = v_[m];
  impact_loss_ += rec.energy_loss;
  touch_loss_eq5_ += rec.energy_loss_eq5;
  touch_loss_eq5_group_ += rec.energy_loss_eq5_group;
  if (opt_.capture_touch_snapshots) {
    rec.snapshot.push_back(snapshot());
    rec.snapshot.back().time = t;
  }
  touches_.push_back(std::move(rec));
  return true;
}

Vec2 Model::vertex_normal(int node) const {
  Vec2 n{};
  for (const BEdge& e : bedges_)
    if (e.a == node || e.b == node) n += normalized(perp_right(x_[e.b] - x_[e.a]));
  return normalized(n);
}

// Normal of a clone, pointing from the target into the main block: the
// touched edge's outward normal; for two merged nodes the difference of
// their vertex normals, so that it does not depend on which of the two was
// found as the main node (an apex on a flat face gets the face normal).
Vec2 Model::clone_normal(const Clone& c) const {
  if (c.t[1] < 0) {
    const Vec2 n = normalized(vertex_normal(c.t[0]) - vertex_normal(c.main));
    if (n != Vec2{}) return n;
  }
  return normalized(perp_right(x_[c.eb] - x_[c.ea]));
}

double Model::tributary_length(int node) const {
  double l = 0.0;
  for (const BEdge& e : bedges_)
    if (e.a == node || e.b == node) l += 0.5 * distance(x_[e.a], x_[e.b]);
  return l;
}

}  // namespace dda::cdem
