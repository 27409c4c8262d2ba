// Paper B Sects. 2-3: contact detection (boundary nodes against boundary
// edges of other blocks) and the time of impact on the collision path, which
// splits a step into its two time stages dt1 and dt2.
#include "model_ops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

namespace {

// A node moving p0 -> p1 against the edge a0 -> a1, b0 -> b1 over one
// interval (all motions linear in s in [0, 1]): w = p - a and e = b - a at
// s = 0 and their changes over the interval, and the coefficients of
// G(s) = cross(w, e) = c0 + c1 s + c2 s^2, the signed gap times the edge
// length (positive on the outer side of a CCW boundary edge).
struct SweptGap {
  Vec2 w0, dw, e0, de;
  double c0, c1, c2;
};

SweptGap swept_gap(Vec2 p0, Vec2 p1, Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1) {
  SweptGap g;
  g.w0 = p0 - a0;
  g.dw = (p1 - a1) - g.w0;
  g.e0 = b0 - a0;
  g.de = (b1 - a1) - g.e0;
  g.c0 = cross(g.w0, g.e0);
  g.c1 = cross(g.w0, g.de) + cross(g.dw, g.e0);
  g.c2 = cross(g.dw, g.de);
  return g;
}

// G taken as linear: |c2| below 1e-12 of the coefficients' magnitude.
bool gap_is_linear(const SweptGap& g) {
  return std::fabs(g.c2) <= 1e-12 * (std::fabs(g.c0) + std::fabs(g.c1) + std::fabs(g.c2));
}

// The real roots of G(s) = c0 + c1 s + c2 s^2 in increasing order, into r;
// returns their count (0 to 2). Linear (gap_is_linear): a root only if
// c1 != 0; the quadratic's roots by the cancellation-free form
// q = -(c1 + sign(c1) sqrt(disc)) / 2, r = q / c2 and c0 / q.
int gap_roots(const SweptGap& g, double r[2]) {
  const double c0 = g.c0, c1 = g.c1, c2 = g.c2;
  if (gap_is_linear(g)) {
    if (c1 == 0.0) return 0;
    r[0] = -c0 / c1;
    return 1;
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc < 0.0) return 0;
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  r[0] = q / c2;
  if (q == 0.0) return 1;
  r[1] = c0 / q;
  if (r[0] > r[1]) std::swap(r[0], r[1]);
  return 2;
}

// Touch of a node moving p0 -> p1 with the edge a0 -> a1, b0 -> b1 over one
// interval (all motions linear in s in [0, 1]): the collision path of
// Paper B Sect. 3. G(s) = cross(p - a, b - a) is the signed gap times the
// edge length (positive on the outer side of a CCW boundary edge) and is
// quadratic in s. A candidate ends the interval closer than tol; the touch
// is the first s where G = 0 with the foot of the node inside the edge.
// A node that starts on or up to tol behind the edge and approaches touches
// at s = 0.
bool swept_touch(Vec2 p0, Vec2 p1, Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1, double tol, double& s_out, double& xi_out) {
  const SweptGap g = swept_gap(p0, p1, a0, a1, b0, b1);
  const Vec2 w0 = g.w0, dw = g.dw, e0 = g.e0, de = g.de;
  const double c0 = g.c0, c1 = g.c1, c2 = g.c2;
  const double l0 = length(e0), l1 = length(e0 + de);
  if (!(l0 > 0.0) || !(l1 > 0.0)) return false;
  const double gap0 = c0 / l0;
  const double gap1 = (c0 + c1 + c2) / l1;
  if (gap1 >= tol) return false;  // not within the contact tolerance at the end
  auto foot = [&](double s) {
    const Vec2 w = w0 + s * dw, e = e0 + s * de;
    return dot(w, e) / length_squared(e);
  };
  constexpr double kFootSlack = 1e-9;
  auto on_edge = [&](double xi) { return xi >= -kFootSlack && xi <= 1.0 + kFootSlack; };
  double s = -1.0;
  if (gap0 <= 0.0) {
    if (gap0 < -tol) return false;                 // behind the edge: not this edge's node
    if (!(c1 < 0.0 || gap1 < gap0)) return false;  // not approaching
    s = 0.0;
  } else {
    // the smallest root of G in (0, 1] (a linear G's up to 1 + 1e-12, then
    // taken as 1)
    double r[2];
    const int roots = gap_roots(g, r);
    const double last = gap_is_linear(g) ? 1.0 + 1e-12 : 1.0;
    for (int k = roots - 1; k >= 0; --k)
      if (r[k] > 0.0 && r[k] <= last) s = r[k];
    if (!(s > 0.0 && s <= 1.0 + 1e-12)) return false;
    s = std::min(s, 1.0);
  }
  const double xi = foot(s);
  if (!on_edge(xi)) return false;
  s_out = s;
  xi_out = std::clamp(xi, 0.0, 1.0);
  return true;
}

}  // namespace

// The touches over one interval (coarse step or patch step) of every
// boundary node moving p0 -> p1 (at the times t_p0 -> t_p1) against the
// boundary edges of the other blocks, earliest first; at most one (the
// earliest) per node. t_start: the start of the coarse or patch step.
std::vector<Touch> find_touches(const ModelSetup& su, const ModelState& st, bool coarse_level, double t_start,
                                double t_p0, double t_p1, const std::vector<Vec2>& p0, const std::vector<Vec2>& p1) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  const double tol = su.opt.tolerance;
  std::vector<Aabb> box(st.blocks.size());
  auto grow = [](Aabb& b, Vec2 p) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
  };
  for (int n : mesh.bnodes) {
    grow(box[nd.block[n]], p0[n]);
    grow(box[nd.block[n]], p1[n]);
  }
  for (Aabb& b : box) {
    b.lo = b.lo - Vec2{tol, tol};
    b.hi = b.hi + Vec2{tol, tol};
  }
  std::vector<Touch> out;
  for (int n : mesh.bnodes) {
    const NodeKind kn = nd.kind[n];
    if (kn == NodeKind::kDead || kn == NodeKind::kHanging || touch_blocked(st.clones, n)) continue;
    // A node whose clone was removed may touch again within the same coarse
    // or patch step (a sliding clone keeps a pressed node tied, so a release
    // is a separation or a slide past the target's corner).
    if (coarse_level && kn != NodeKind::kCoarse) continue;
    const bool node_fine = kn == NodeKind::kFine;
    const std::vector<int> partners = in_clone(nd, n) ? tied_partners(st.clones, n) : std::vector<int>{};
    auto tied = [&](int a) { return std::find(partners.begin(), partners.end(), a) != partners.end(); };
    const int bn = nd.block[n];
    Aabb nb;
    grow(nb, p0[n]);
    grow(nb, p1[n]);
    Touch best;
    best.s = 2.0;
    for (std::size_t ob = 0; ob < st.blocks.size(); ++ob) {
      if (static_cast<int>(ob) == bn || (st.blocks[bn].fixed && st.blocks[ob].fixed) || !aabb_overlap(nb, box[ob]))
        continue;
      bool found = false;
      for (int ei : mesh.block_bedges[ob]) {
        const BoundaryEdge& e = mesh.bedges[static_cast<std::size_t>(ei)];
        const bool any_fine = node_fine || nd.kind[e.a] == NodeKind::kFine || nd.kind[e.b] == NodeKind::kFine;
        if (coarse_level == any_fine) continue;  // coarse step: all-coarse pairs; patch steps: the rest
        double s = 0.0, xi = 0.0;
        if (swept_touch(p0[n], p1[n], p0[e.a], p1[e.a], p0[e.b], p1[e.b], tol, s, xi)) {
          found = true;
          // at a node it is already tied with: that clone itself
          if ((xi <= kNodeTieXi && tied(e.a)) || (xi >= 1.0 - kNodeTieXi && tied(e.b))) continue;
          // A touch is a node moving into the block: near a corner a node
          // may cross one edge's line (or approach it from behind) while it
          // stays outside the other edge, and a clone formed there separates
          // at once and re-forms, without end.
          // A node that crossed the edge and left the block again within
          // the interval deeper than d_tol passed through it: out of the
          // domain, as a node found inside at the interval start.
          if (s < 1.0 && !(depth_inside(mesh, static_cast<int>(ob), p1[n], p1) > 0.0)) {
            check_no_passage(st, n, static_cast<int>(ob), p0, p1, t_p0, t_p1,
                             tol, "the contact tolerance d_tol");
            continue;
          }
          // A node released at the start of this interval touches again in
          // the next patch step (a coarse step: later in this one): touching
          // at once, its clone re-forms and separates again and again within
          // ever shorter steps (seen after tension releases next to sliding
          // clones). Its motion meanwhile, |v| dt/n, is found at s = 0 next.
          constexpr double kStartFraction = 1e-9;  // of the interval: the patch loop's grouping of simultaneous touches
          if (nd.released_at[n] >= t_start && (!coarse_level || s <= kStartFraction)) continue;
          if (s < best.s) {
            best.s = s;
            best.node = n;
            best.ea = e.a;
            best.eb = e.b;
            best.xi = xi;
          }
        }
      }
      // A node that starts the interval inside the other block at any depth
      // is never skipped: within d_tol of its boundary and approaching it
      // touches at s = 0 (above); deeper, its time of impact lies in an
      // earlier step, and the run stops.
      if (!found) check_not_inside(su, st, n, static_cast<int>(ob), p0, t_start);
    }
    if (best.node >= 0) out.push_back(best);
  }
  std::sort(out.begin(), out.end(), [](const Touch& a, const Touch& b) { return a.s < b.s; });
  return out;
}

namespace {
// Depth of p inside block b, its boundary nodes at pos(node): the distance
// to the block's boundary if p lies inside its boundary loop (crossing
// number), else 0.
template <class Pos>
double depth_inside_of(const MeshState& mesh, int b, Vec2 p, const Pos& pos) {
  bool inside = false;
  double depth = std::numeric_limits<double>::infinity();
  for (int ei : mesh.block_bedges[static_cast<std::size_t>(b)]) {
    const BoundaryEdge& e = mesh.bedges[static_cast<std::size_t>(ei)];
    const Vec2 a = pos(e.a), c = pos(e.b);
    if ((a.y > p.y) != (c.y > p.y) && p.x < a.x + (p.y - a.y) / (c.y - a.y) * (c.x - a.x)) inside = !inside;
    depth = std::min(depth, point_segment_distance(p, a, c));
  }
  return inside ? depth : 0.0;
}
}  // namespace

double depth_inside(const MeshState& mesh, int b, Vec2 p, const std::vector<Vec2>& pos) {
  return depth_inside_of(mesh, b, p, [&](int i) { return pos[i]; });
}

// The deepest point of a passage of node `node` through block b over one
// interval (every node moving linearly p0 -> p1 in s in [0, 1]): a stretch
// of s where the node lies inside b and that ends before s = 1 (the node
// entered, or started inside, and left again within the interval, unseen
// by a check at the interval's end). The stretches are bounded by the roots
// of G(s) = cross(p - a, b - a) of b's boundary edges (quadratic in s, as in
// swept_touch); on each piece between roots the depth is found by a golden-
// section search (the distance to the boundary is concave along a straight
// path through a convex polygon, and nearly so for a block deforming within
// one step). Returns the greatest depth (0: no passage) and its s.
double deepest_passage(const MeshState& mesh, int b, int node, const std::vector<Vec2>& p0,
                       const std::vector<Vec2>& p1, double& s_deep) {
  auto at = [&](int i, double s) { return p0[i] + s * (p1[i] - p0[i]); };
  auto depth = [&](double s) {
    return depth_inside_of(mesh, b, at(node, s), [&](int i) { return at(i, s); });
  };
  std::vector<double> cuts{0.0, 1.0};
  for (int ei : mesh.block_bedges[static_cast<std::size_t>(b)]) {
    const BoundaryEdge& e = mesh.bedges[static_cast<std::size_t>(ei)];
    double r[2];
    const int roots = gap_roots(swept_gap(p0[node], p1[node], p0[e.a], p1[e.a], p0[e.b], p1[e.b]), r);
    for (int k = 0; k < roots; ++k)
      if (r[k] > 0.0 && r[k] < 1.0) cuts.push_back(r[k]);
  }
  std::sort(cuts.begin(), cuts.end());
  // the pieces inside, and whether the run of inside pieces reaches s = 1
  const std::size_t pieces = cuts.size() - 1;
  std::vector<char> inside(pieces, 0);
  for (std::size_t i = 0; i < pieces; ++i)
    inside[i] = cuts[i + 1] > cuts[i] && depth(0.5 * (cuts[i] + cuts[i + 1])) > 0.0;
  double best = 0.0;
  s_deep = 0.0;
  bool to_end = true;  // the current run of inside pieces, scanned from s = 1 back, reaches s = 1
  for (std::size_t k = pieces; k-- > 0;) {
    if (!inside[k]) {
      to_end = false;
      continue;
    }
    if (to_end) continue;  // inside at the end: the end-of-interval checks see it
    constexpr int kGoldenIterations = 40;  // the piece shrunk by 0.618^40 ~ 4e-9
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = cuts[k], hi = cuts[k + 1];
    for (int it = 0; it < kGoldenIterations; ++it) {
      const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
      if (depth(m1) < depth(m2))
        lo = m1;
      else
        hi = m2;
    }
    const double s = 0.5 * (lo + hi), d = depth(s);
    if (d > best) {
      best = d;
      s_deep = s;
    }
  }
  return best;
}

void check_no_passage(const ModelState& st, int node, int other, const std::vector<Vec2>& p0,
                      const std::vector<Vec2>& p1, double t0, double t1, double limit, const char* limit_name) {
  double s = 0.0;
  const double depth = deepest_passage(st.mesh, other, node, p0, p1, s);
  if (!(depth > limit)) return;
  const NodeState& nd = st.nodes;
  const double t = t0 + s * (t1 - t0);
  std::ostringstream msg;
  msg << "cdem: node " << node << " of block " << nd.block[node] << " passed through block " << other
      << " between t = " << t0 << " and " << t1 << " s (step " << st.steps + 1 << "): its path reached "
      << depth << " m inside at t = " << t << " s, deeper than " << limit_name << " = " << limit
      << " m, and left it again before " << t1 << " s, never found inside: the blocks closed further in one step "
      << "than the block is thick; use a smaller dt (below the thickness over the closing speed)";
  throw ContactError(msg.str(), node, nd.block[node], other, st.steps + 1, t, depth);
}

void check_not_inside(const ModelSetup& su, const ModelState& st, int node, int other, const std::vector<Vec2>& pos,
                      double t) {
  const NodeState& nd = st.nodes;
  const double depth = depth_inside(st.mesh, other, pos[node], pos);
  if (!(depth > su.opt.tolerance)) return;
  std::ostringstream s;
  s << "cdem: node " << node << " of block " << nd.block[node] << " is " << depth << " m inside block " << other
    << " at t = " << t << " s (step " << st.steps + 1 << "), deeper than the contact tolerance d_tol = "
    << su.opt.tolerance << " m: its time of impact lies in an earlier step and the contact cannot be resolved; "
    << "use a smaller dt or check that the blocks do not overlap at the start";
  throw ContactError(s.str(), node, nd.block[node], other, st.steps + 1, t, depth);
}

bool locate_edge(const MeshState& mesh, const std::vector<Vec2>& x, int block, Vec2 p, int& a, int& b, double& xi) {
  double best = std::numeric_limits<double>::infinity();
  for (const BoundaryEdge& e : mesh.bedges) {
    if (e.block != block) continue;
    const double d = point_segment_distance(p, x[e.a], x[e.b]);
    if (d < best) {
      best = d;
      a = e.a;
      b = e.b;
    }
  }
  if (!std::isfinite(best)) return false;
  const Vec2 e = x[b] - x[a];
  xi = std::clamp(dot(p - x[a], e) / length_squared(e), 0.0, 1.0);
  return true;
}

// The coarse step's candidates: every coarse node moving linearly with its
// half-kicked velocity over [t0, t0 + dt].
std::vector<Touch> coarse_touches(const ModelSetup& su, const ModelState& st, double t0) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::vector<Vec2> p0 = nd.x, p1 = nd.x;
  for (int n : mesh.coarse_dofs) p1[n] = nd.x[n] + su.dt * nd.v[n];
  return find_touches(su, st, true, t0, t0, t0 + su.dt, p0, p1);
}

// Sect. 3's two time stages over a coarse step (without subdivision, and
// with the sub-model, whose contact stays at the coarse nodes): the
// touching nodes move dt1 with their free velocity, take the inelastic
// impact, and move dt2 as a clone; every other node moves the full dt.
void two_stage_step(const ModelSetup& su, ModelState& st, const std::vector<Touch>& touches, double t0) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::vector<double> tau(nd.x.size(), 0.0);
  std::vector<char> changed(nd.x.size(), 0);
  for (const Touch& T : touches) {
    if (touch_blocked(st.clones, T.node)) continue;
    std::vector<int> set{T.node, T.ea, T.eb};
    for (std::size_t head = 0; head < set.size(); ++head)
      for (const Clone& c : st.clones) {
        std::vector<int> cn{c.main};
        for (int a : c.t)
          if (a >= 0) cn.push_back(a);
        if (std::find(cn.begin(), cn.end(), set[head]) == cn.end()) continue;
        for (int a : cn)
          if (std::find(set.begin(), set.end(), a) == set.end()) set.push_back(a);
      }
    bool stale = false;
    for (int a : set) stale = stale || changed[a];
    if (stale) continue;  // found again next step from the updated motion
    for (int a : set)
      if (nd.kind[a] == NodeKind::kCoarse && !st.blocks[nd.block[a]].fixed) {
        nd.x[a] += ((T.s - tau[a]) * su.dt) * nd.v[a];
        tau[a] = T.s;
      }
    if (process_touch(su, st, T, false, t0 + T.s * su.dt, t0, t0 + su.dt))
      for (int a : set) changed[a] = 1;
  }
  for (int n : mesh.coarse_dofs) nd.x[n] += ((1.0 - tau[n]) * su.dt) * nd.v[n];
}

}  // namespace dda::cdem
