// Paper B Sect. 4.1: the clone (unified) node formed at a touch, the
// perfectly inelastic impact that sets its velocity (Eq. 4, energy loss
// Eq. 5), and the clone's geometry (normal, tributary length A_c).
#include "model_ops.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

// A node cannot start a new touch while it is a clone's main node or is tied
// node-to-node; a node tied as an end of a touched edge (weight < 1) can, so
// that a corner of a face in contact still finds the other block.
bool touch_blocked(const std::vector<Clone>& clones, int node) {
  for (const Clone& c : clones)
    if (c.main == node || (c.t[0] == node && c.t[1] < 0)) return true;
  return false;
}

// Nodes tied with `node` by some clone (a touch between them is that clone).
std::vector<int> tied_partners(const std::vector<Clone>& clones, int node) {
  std::vector<int> out;
  for (const Clone& c : clones) {
    const bool has = c.main == node || c.t[0] == node || c.t[1] == node;
    if (!has) continue;
    for (int a : {c.main, c.t[0], c.t[1]})
      if (a >= 0 && a != node) out.push_back(a);
  }
  return out;
}

std::vector<int> clone_component(const std::vector<Clone>& clones, int ci) {
  std::vector<int> comp{ci};
  std::vector<char> in(clones.size(), 0);
  in[static_cast<std::size_t>(ci)] = 1;
  auto nodes_of = [&](const Clone& c) {
    std::vector<int> n{c.main};
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0 && c.w[q] != 0.0) n.push_back(c.t[q]);
    return n;
  };
  for (std::size_t head = 0; head < comp.size(); ++head) {
    const std::vector<int> a = nodes_of(clones[static_cast<std::size_t>(comp[head])]);
    for (std::size_t j = 0; j < clones.size(); ++j) {
      if (in[j] || clones[j].fine != clones[static_cast<std::size_t>(ci)].fine) continue;
      const std::vector<int> b = nodes_of(clones[j]);
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
double group_eq5(const std::vector<Clone>& clones, const NodeState& nd, const MeshState& mesh, const std::vector<int>& comp) {
  constexpr double kRankTolerance = 1e-12;  // relative; W's entries are sums of 1/m, round-off ~1e-16
  std::vector<Vec2> dirs;                   // one row per tie direction
  std::vector<int> row_clone;
  for (std::size_t k = 0; k < comp.size(); ++k) {
    const Clone& cl = clones[static_cast<std::size_t>(comp[k])];
    if (cl.sliding && k > 0) {
      dirs.push_back(clone_normal(cl, mesh, nd.x));
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
    const auto ti = terms(clones[static_cast<std::size_t>(row_clone[i])]);
    for (const auto& [node, c] : ti) r(i) += c * dot(dirs[i], nd.v[node]);
    for (int j = 0; j < n; ++j) {
      const auto tj = terms(clones[static_cast<std::size_t>(row_clone[j])]);
      for (const auto& [a, ca] : ti)
        for (const auto& [b, cb] : tj)
          if (a == b) w(i, j) += ca * cb * nd.inv_m[a] * dot(dirs[i], dirs[j]);
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
double project_component(std::vector<Clone>& clones, NodeState& nd, const MeshState& mesh, const CdemOptions& opt, int ci,
                         TouchRecord* rec) {
  const std::vector<int> comp = clone_component(clones, ci);
  std::vector<int> nodes;
  for (int c : comp) {
    const Clone& cl = clones[static_cast<std::size_t>(c)];
    nodes.push_back(cl.main);
    for (int q = 0; q < 2; ++q)
      if (cl.t[q] >= 0 && cl.w[q] != 0.0) nodes.push_back(cl.t[q]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto ke = [&] {
    double e = 0.0, vmax = 0.0;
    for (int n : nodes) {
      e += 0.5 * nd.m[n] * length_squared(nd.v[n]);
      vmax = std::max(vmax, length(nd.v[n]));
    }
    return std::make_pair(e, vmax);
  };
  if (rec) rec->energy_loss_eq5_group = group_eq5(clones, nd, mesh, comp);
  const bool coulomb = rec && opt.touch_impact == TouchImpact::kCoulomb;
  constexpr double kPi = 3.14159265358979323846;
  const double tan_phi = std::tan(opt.strength.friction_deg * kPi / 180.0);
  double jn_new = 0.0, jt_new = 0.0;  // the new clone's accumulated impulse (normal, tangential)
  bool capped = false;
  const auto [before, vscale] = ke();
  for (int it = 0; it < 500; ++it) {
    double worst = 0.0;
    for (int c : comp) {
      const Clone& cl = clones[static_cast<std::size_t>(c)];
      Vec2 r = nd.v[cl.main];
      double w = nd.inv_m[cl.main];
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) {
          r -= cl.w[q] * nd.v[cl.t[q]];
          w += cl.w[q] * cl.w[q] * nd.inv_m[cl.t[q]];
        }
      if (!(w > 0.0)) continue;
      if (cl.sliding) {  // only the normal velocity is tied (Eq. 10)
        const Vec2 n = clone_normal(cl, mesh, nd.x);
        r = dot(r, n) * n;
      }
      Vec2 j = -(1.0 / w) * r;
      if (c == ci && rec) {
        const Vec2 n = clone_normal(cl, mesh, nd.x), u = perp_left(n);
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
      nd.v[cl.main] += nd.inv_m[cl.main] * j;
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) nd.v[cl.t[q]] -= (cl.w[q] * nd.inv_m[cl.t[q]]) * j;
    }
    if (worst <= 1e-14 * (vscale + 1e-300)) break;
  }
  if (rec) {
    rec->impulse_normal = jn_new;
    rec->impulse_tangential = jt_new;
    rec->coulomb_capped = capped;
    if (capped) clones[static_cast<std::size_t>(ci)].sliding = true;
  }
  return before - ke().first;
}

// A touch of `touch.node` at time t within the interval [t0, t1]: the
// sub-model's request (kSubModel) or the refinement (kInPlace), the clone
// and its Eq. 4 projection, the record. False when the node cannot touch
// (tied already, a dead or hanging node).
bool process_touch(const ModelSetup& su, ModelState& st, const Touch& touch, bool fine_level, double t, double t0,
                   double t1) {
  NodeState& nd = st.nodes;
  const int m = touch.node;
  if (touch_blocked(st.clones, m) || nd.kind[m] == NodeKind::kDead || nd.kind[m] == NodeKind::kHanging) return false;
  {
    const std::vector<int> partners = tied_partners(st.clones, m);
    auto tied = [&](int a) { return std::find(partners.begin(), partners.end(), a) != partners.end(); };
    if ((touch.xi <= kNodeTieXi && tied(touch.ea)) || (touch.xi >= 1.0 - kNodeTieXi && tied(touch.eb))) return false;
  }
  int ea = touch.ea, eb = touch.eb;
  const int bm = nd.block[m], bt = nd.block[ea];
  // A node that touches again and again within one coarse step chatters
  // (each touch separates at once): the contact is not resolved.
  constexpr int kMaxTouchesPerStep = 1000;
  if (++st.step_touch_count[m] > kMaxTouchesPerStep) {
    const Vec2 e = nd.x[eb] - nd.x[ea];
    const double depth = std::max(0.0, -cross(nd.x[m] - nd.x[ea], e) / length(e));
    std::ostringstream s;
    s << "cdem: node " << m << " of block " << bm << " touched block " << bt << " " << kMaxTouchesPerStep
      << " times within step " << st.steps + 1 << " (t = " << t << " s, depth " << depth
      << " m): each clone separates at once and the contact is not resolved; try a smaller dt";
    throw ContactError(s.str(), m, bm, bt, st.steps + 1, t, depth, StopReason::kOther);
  }
  double xi = touch.xi;
  {
    const Vec2 e = nd.x[eb] - nd.x[ea];
    xi = std::clamp(dot(nd.x[m] - nd.x[ea], e) / length_squared(e), 0.0, 1.0);
  }
  const Vec2 point = lerp(nd.x[ea], nd.x[eb], xi);
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

  if (submodel_mode(su.opt))
    request_submodel(st.submodels, static_cast<int>(st.log.touches.size()), m, point, ea, eb, rec.dt2);  // Sect. 5 step 1
  else if (su.opt.subdivision)
    refine_contact_zone(su, st, m, point, ea, eb, xi, rec);

  Clone c;
  c.main = m;
  c.ea = ea;
  c.eb = eb;
  const double len = distance(nd.x[ea], nd.x[eb]);
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
  c.area = tributary_length(st.mesh, nd.x, m);
  c.fine = nd.kind[m] == NodeKind::kFine;
  for (int q = 0; q < 2; ++q) {
    const int a = c.t[q];
    if (a < 0 || st.blocks[nd.block[a]].fixed) continue;
    if ((nd.kind[a] == NodeKind::kFine) != c.fine)
      throw SimulationError("cdem: clone nodes on two integration levels (internal error)");
  }
  rec.mass_main = nd.m[m];
  double inv_t = 0.0;
  Vec2 vt{};
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) {
      inv_t += c.w[q] * c.w[q] * nd.inv_m[c.t[q]];
      vt += c.w[q] * nd.v[c.t[q]];
    }
  rec.mass_target = inv_t > 0.0 ? 1.0 / inv_t : 0.0;
  rec.v_main = nd.v[m];
  rec.v_target = vt;
  const double inv_sum = nd.inv_m[m] + inv_t;
  rec.energy_loss_eq5 = inv_sum > 0.0 ? 0.5 / inv_sum * length_squared(nd.v[m] - vt) : 0.0;
  st.clones.push_back(c);
  nd.clone_count[m] += 1;
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) nd.clone_count[c.t[q]] += 1;
  rec.energy_loss = project_component(st.clones, nd, st.mesh, su.opt, static_cast<int>(st.clones.size()) - 1, &rec);
  rec.v_clone = nd.v[m];
  st.energy.impact_loss += rec.energy_loss;
  st.energy.touch_loss_eq5 += rec.energy_loss_eq5;
  st.energy.touch_loss_eq5_group += rec.energy_loss_eq5_group;
  if (su.opt.capture_touch_snapshots) {
    rec.snapshot.push_back(snapshot_of(st));
    rec.snapshot.back().time = t;
  }
  st.log.touches.push_back(std::move(rec));
  return true;
}

Vec2 vertex_normal(const MeshState& mesh, const std::vector<Vec2>& x, int node) {
  Vec2 n{};
  for (const BoundaryEdge& e : mesh.bedges)
    if (e.a == node || e.b == node) n += normalized(perp_right(x[e.b] - x[e.a]));
  return normalized(n);
}

// Normal of a clone, pointing from the target into the main block: the
// touched edge's outward normal; for two merged nodes the difference of
// their vertex normals, so that it does not depend on which of the two was
// found as the main node (an apex on a flat face gets the face normal).
Vec2 clone_normal(const Clone& c, const MeshState& mesh, const std::vector<Vec2>& x) {
  if (c.t[1] < 0) {
    const Vec2 n = normalized(vertex_normal(mesh, x, c.t[0]) - vertex_normal(mesh, x, c.main));
    if (n != Vec2{}) return n;
  }
  return normalized(perp_right(x[c.eb] - x[c.ea]));
}

double tributary_length(const MeshState& mesh, const std::vector<Vec2>& x, int node) {
  double l = 0.0;
  for (const BoundaryEdge& e : mesh.bedges)
    if (e.a == node || e.b == node) l += 0.5 * distance(x[e.a], x[e.b]);
  return l;
}

}  // namespace dda::cdem
