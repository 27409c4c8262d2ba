// Baseline, NOT Paper B's method: the conventional node-to-edge penalty
// contact on the same CST blocks (CdemOptions::contact =
// ContactMode::kNodeToEdgePenalty), the contact Paper B argues against
// (Paper B Sect. 1: contact springs whose stiffness is "difficult to
// identify", penetration, a step limited by the spring).
//
// Source: the standard node-to-segment penalty method of explicit FE/DEM
// codes (e.g. Hallquist, Goudreau & Benson 1985, "Sliding interfaces with
// contact-impact in large-scale Lagrangian computations", CMAME 51; Wriggers,
// "Computational Contact Mechanics", 2006, Sect. 8.3 on explicit steps):
//  * detection: at each force evaluation (the step end), a boundary node of
//    one block lying inside another block's boundary loop (crossing number)
//    penetrates that block's nearest boundary edge a -> b (CCW, outward unit
//    normal n = perp_right(b - a) / |b - a|) by the depth
//      g = -n . (p - a) > 0,   foot xi = (p - a) . (b - a) / |b - a|^2;
//  * force: the potential W = kn g^2 / 2 per node-edge pair gives
//      f_node = kn g n,  f_a = -(1 - xi) kn g n,  f_b = -xi kn g n
//    (dg/da = (1 - xi) n, dg/db = xi n exactly for the distance to the
//    line), equal and opposite (momentum exact to round-off) and collinear
//    through the node and its foot (angular momentum exact as well);
//    frictionless, undamped: conservative while a node keeps its edge;
//  * time integration: the model's explicit central-difference step (Eq. 1,
//    kick-drift-kick), no time-of-impact split, no clone node, no
//    subdivision: the contact starts at the first step end with a node
//    behind an edge (late by up to one step);
//  * kn, Pa (N/m per unit thickness per m of penetration): CdemOptions::
//    penalty_kn, or E / 100 of the stiffest block material (Paper A Sect.
//    4.1's ratio, so that the baseline uses the kn of Paper A's scenes);
//  * stability: omega_max^2 of M^-1 (K + K_c) <= omega_mesh^2 + lambda_max
//    of M^-1/2 K_c M^-1/2 (lambda_max of a sum <= the sum), K_c = sum over
//    the springs of kn w w^T, w = (n, -(1-xi) n, -xi n) on (node, a, b).
//    Gershgorin on the springs' part: a row sums kn |w_i| sum_j |w_j| /
//    sqrt(m_i m_j) <= 2 kn max(1/m) per spring at the node, and a boundary
//    node carries at most three springs when two blocks touch with meshes
//    no finer than each other's (its own, and one on each of its two
//    boundary edges), so the predicted critical step is
//      dt_c = 2 / sqrt(omega_mesh^2 + 6 kn max_boundary(1/m))
//    (one spring per node, 2 kn max(1/m), is not enough: face-to-face
//    contact of the B-7 squares at kn 100 E is unstable at 0.8 x that
//    step; a node touching three blocks, or an edge pressed by several
//    nodes of a finer mesh, carries more springs than assumed here);
//  * domain: a node deeper than half the smallest element length scale
//    (h_e = sqrt(2 A_e), as in the subdivision) stops the run with a
//    ContactError: the penalty is far too soft for the impact (or dt too
//    large) and the node would pass through the edge; so does a node whose
//    drift within one step went that deep into another block and out again
//    (a fast block through a thin one, never inside at a step end).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "model_ops.hpp"
#include "dda/polygon.hpp"
#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

namespace {
// Ratio kn / E of the default penalty: Paper A Sect. 4.1 (kn 10 MPa for E 1 GPa).
constexpr double kDefaultKnPerYoung = 1.0 / 100.0;
// Fraction of the smallest element length scale a node may penetrate before
// the run stops: beyond half an element the nearest edge is no longer the
// one crossed and the spring pushes the node on through the block.
constexpr double kMaxDepthPerElement = 0.5;
}  // namespace

// The penalty constants of the set-up: kn, the depth limit, the critical
// step with the springs (SceneError when dt exceeds it).
void setup_penalty(ModelSetup& su, const ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  su.contact_critical_dt = su.critical_dt;
  if (su.opt.contact == ContactMode::kTwoScale) return;
  if (su.opt.contact != ContactMode::kNodeToEdgePenalty) throw SceneError("options.contact: unknown contact mode");
  if (su.opt.subdivision)
    throw SceneError(
        "options.subdivision: the node-to-edge penalty contact has no local subdivision; set subdivision = false");
  if (!(std::isfinite(su.opt.penalty_kn) && su.opt.penalty_kn >= 0.0))
    throw SceneError("options.penalty_kn: must be >= 0 (Pa; 0 = E / 100)");
  double young = 0.0;
  for (const BlockState& b : st.blocks) young = std::max(young, su.scene.materials[static_cast<std::size_t>(b.material)].young);
  su.penalty_kn = su.opt.penalty_kn > 0.0 ? su.opt.penalty_kn : kDefaultKnPerYoung * young;
  double h_min = std::numeric_limits<double>::infinity();
  for (int e : mesh.coarse_elems) {
    const Element& el = mesh.elem(e);
    h_min = std::min(h_min, std::sqrt(2.0 * cst({nd.x[el.n[0]], nd.x[el.n[1]], nd.x[el.n[2]]}).area));
  }
  su.penalty_max_depth = kMaxDepthPerElement * h_min;
  double max_inv_m = 0.0;
  for (int n : mesh.bnodes) max_inv_m = std::max(max_inv_m, nd.inv_m[n]);
  const double omega_mesh = std::isfinite(su.critical_dt) ? 2.0 / su.critical_dt : 0.0;
  constexpr double kSpringsPerNode = 3.0;  // its own and one on each adjacent boundary edge (above)
  const double omega2 = omega_mesh * omega_mesh + kSpringsPerNode * 2.0 * su.penalty_kn * max_inv_m;
  su.contact_critical_dt = omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
  if (su.opt.check_stability && su.dt > su.contact_critical_dt) {
    std::ostringstream s;
    s << "dt: time step " << su.dt << " s exceeds the critical step " << su.contact_critical_dt
      << " s of the mesh with the node-to-edge penalty springs (kn " << su.penalty_kn << " Pa; mesh alone "
      << su.critical_dt << " s): use a smaller dt or a smaller kn";
    throw SceneError(s.str());
  }
}

namespace {
// The depth limit applied along the drift, not only at its end: a node that
// enters another block and leaves it within one step is never found inside
// at a step end (a fast block through a thin one). The distance of a node
// to a block's boundary changes by at most the node's drift plus the
// block's largest node drift D (edges interpolate their nodes), so a
// passage entered and left within the step reaches at most D: only nodes
// with D > penalty_max_depth are searched (check_no_passage, along the
// linear drift x1 - dt v -> x1 with the half-kicked v).
void check_no_passages(const ModelSetup& su, const ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::vector<double> block_drift(st.blocks.size(), 0.0);
  double most = 0.0;
  for (int n : mesh.bnodes) {
    double& d = block_drift[static_cast<std::size_t>(nd.block[n])];
    d = std::max(d, su.dt * length(nd.v[n]));
    most = std::max(most, d);
  }
  if (!(2.0 * most > su.penalty_max_depth)) return;  // no pair can pass
  std::vector<Vec2> p0;
  for (int n : mesh.bnodes) {
    const int bn = nd.block[n];
    const double dn = su.dt * length(nd.v[n]);
    for (std::size_t ob = 0; ob < st.blocks.size(); ++ob) {
      if (static_cast<int>(ob) == bn || (st.blocks[bn].fixed && st.blocks[ob].fixed)) continue;
      if (!(dn + block_drift[ob] > su.penalty_max_depth)) continue;
      if (p0.empty()) {
        p0 = nd.x;
        for (int m : mesh.coarse_dofs) p0[m] = nd.x[m] - su.dt * nd.v[m];
      }
      check_no_passage(st, n, static_cast<int>(ob), p0, nd.x, st.time, st.time + su.dt, su.penalty_max_depth,
                       "half the smallest element");
    }
  }
}
}  // namespace

// One explicit central-difference step (Eq. 1) with the penalty springs as
// external forces: half-kick, drift, forces at t1 (elements, gravity,
// damping, add_penalty_forces via compute_coarse_forces), half-kick.
void penalty_step(const ModelSetup& su, ModelState& st) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  st.step_t0 = st.time;
  kick_coarse_first_half(nd, mesh, su.dt);
  for (int n : mesh.coarse_dofs) nd.x[n] += su.dt * nd.v[n];
  check_no_passages(su, st);
  st.time += su.dt;
  forces_and_second_half_kick(su, st);
  ++st.steps;
  check_state(st);
}

void add_penalty_forces(const ModelSetup& su, ModelState& st) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  st.penalty_contacts.clear();
  std::vector<Aabb> box(st.blocks.size());
  for (int n : mesh.bnodes) {
    Aabb& b = box[static_cast<std::size_t>(nd.block[n])];
    b.lo = {std::min(b.lo.x, nd.x[n].x), std::min(b.lo.y, nd.x[n].y)};
    b.hi = {std::max(b.hi.x, nd.x[n].x), std::max(b.hi.y, nd.x[n].y)};
  }
  for (int n : mesh.bnodes) {
    const int bn = nd.block[n];
    const Vec2 p = nd.x[n];
    for (std::size_t ob = 0; ob < st.blocks.size(); ++ob) {
      if (static_cast<int>(ob) == bn || (st.blocks[bn].fixed && st.blocks[ob].fixed)) continue;
      const Aabb& o = box[ob];
      if (p.x < o.lo.x || p.x > o.hi.x || p.y < o.lo.y || p.y > o.hi.y) continue;
      // inside the boundary loop (crossing number) and the nearest edge
      bool inside = false;
      double best = std::numeric_limits<double>::infinity();
      const BoundaryEdge* near = nullptr;
      for (int ei : mesh.block_bedges[ob]) {
        const BoundaryEdge& e = mesh.bedges[static_cast<std::size_t>(ei)];
        const Vec2 a = nd.x[e.a], c = nd.x[e.b];
        if ((a.y > p.y) != (c.y > p.y) && p.x < a.x + (p.y - a.y) / (c.y - a.y) * (c.x - a.x)) inside = !inside;
        const double d = point_segment_distance(p, a, c);
        if (d < best) {
          best = d;
          near = &e;
        }
      }
      if (!inside || near == nullptr) continue;
      const Vec2 a = nd.x[near->a], edge = nd.x[near->b] - a;
      const double len = length(edge);
      const Vec2 normal = perp_right(edge) / len;
      const double depth = -dot(normal, p - a);
      if (!(depth > 0.0)) continue;
      if (depth > su.penalty_max_depth) {
        std::ostringstream s;
        s << "cdem: node-to-edge penalty: node " << n << " of block " << bn << " is " << depth << " m inside block "
          << ob << " at t = " << st.time << " s (step " << st.steps << "), deeper than half the smallest element ("
          << su.penalty_max_depth << " m): kn = " << su.penalty_kn
          << " Pa is far too small for this impact (or dt too large); the node would pass through the edge";
        throw ContactError(s.str(), n, bn, static_cast<int>(ob), st.steps, st.time, depth);
      }
      const double xi = std::clamp(dot(p - a, edge) / (len * len), 0.0, 1.0);
      const Vec2 f = (su.penalty_kn * depth) * normal;
      if (nd.inv_m[n] > 0.0) nd.f[n] += f;
      if (nd.inv_m[near->a] > 0.0) nd.f[near->a] -= (1.0 - xi) * f;
      if (nd.inv_m[near->b] > 0.0) nd.f[near->b] -= xi * f;
      st.penalty_contacts.push_back({n, near->a, near->b, xi, depth, normal});
    }
  }
}

double penalty_energy(const ModelSetup& su, const std::vector<PenaltyContact>& contacts) {
  double w = 0.0;
  for (const PenaltyContact& c : contacts) w += 0.5 * su.penalty_kn * c.depth * c.depth;
  return w;
}

}  // namespace dda::cdem
