#include "dda/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lanes.hpp"
#include "ring_kernels.hpp"
#include "support_kernels.hpp"

namespace dda {

namespace {

// Index of the lowest vertex (smallest y, then smallest x): the edge walk
// starts there so that edge normals sweep angles in increasing order from -pi/2.
int lowest_vertex(const PolygonView& p, double sign) {
  int best = 0;
  for (int i = 1; i < p.count; ++i) {
    const Vec2 q = sign * p.vertex(i), r = sign * p.vertex(best);
    if (q.y < r.y || (q.y == r.y && q.x < r.x)) best = i;
  }
  return best;
}

// Monotone stand-in for atan2 in [0, 4): the "diamond angle" of direction d.
// Exact for comparisons of exactly parallel directions, and cheap.
double pseudo_angle(Vec2 d) {
  if (d.y >= 0.0) return d.x >= 0.0 ? d.y / (d.x + d.y) : 1.0 - d.x / (-d.x + d.y);
  return d.x < 0.0 ? 2.0 - d.y / (-d.x - d.y) : 3.0 + d.x / (d.x - d.y);
}

}  // namespace

double pair_tolerance(const PolygonView& a, const PolygonView& b) {
  return std::max(geometric_tolerance(a), geometric_tolerance(b));
}

EntranceBlock entrance_block(const PolygonView& a, const PolygonView& b, Vec2 a0) {
  // -A has vertices -a_i in the same (CCW) order; its edge i is -(edge i of A).
  EntranceBlock e;
  const int n = a.count, m = b.count;
  const int ia0 = lowest_vertex(a, -1.0);  // lowest vertex of -A
  const int jb0 = lowest_vertex(b, 1.0);
  int i = 0, j = 0, k = 0;
  while ((i < n || j < m) && k < kMaxVertices) {
    const int ia = (ia0 + i) % n, jb = (jb0 + j) % m;
    e.poly.v[k] = b.vertex(jb) - a.vertex(ia) + a0;
    const Vec2 ea = -a.edge(ia);  // edge of -A leaving vertex -a_ia
    const Vec2 eb = b.edge(jb);
    // Merge by edge direction: from the lowest vertex each polygon's edge
    // directions increase monotonically through [0, 2 pi), so the edge with
    // the smaller angle comes first. With one polygon exhausted the other
    // finishes. c > 0: take the edge of -A; c < 0: of B; c == 0: both.
    double c = 0.0;
    if (i == n) c = -1.0;
    else if (j == m) c = 1.0;
    else c = pseudo_angle(eb) - pseudo_angle(ea);
    // The edge normal comes from its source edge, not from the vertex
    // difference, so a near-zero edge of E (nearly parallel edges of A and B)
    // still has an exact outward normal and the inside test stays robust.
    if (c > 0.0) {
      e.source[k] = {false, ia, jb};
      e.poly.n[k] = -a.normal(ia);
      ++i;
    } else {
      e.source[k] = {true, jb, ia};
      e.poly.n[k] = b.normal(jb);
      ++j;
      if (c == 0.0) ++i;  // exactly parallel: one merged edge
    }
    ++k;
  }
  e.poly.count = k;
  return e;
}

namespace {

using detail::LaneMask;
using detail::Lanes;
using detail::lane_bits;
using detail::lane_max;
using detail::lane_min;

// A polygon's edge lines two at a time: pair k holds edges 2k and 2k + 1 in
// its two lanes, an odd count's last edge repeated to fill the last pair (a
// repeated axis changes no maximum; its cut bit, >= count, is masked off).
// kN: the polygon's vertex count when known at compile time (0: up to
// kMaxVertices, the count read at run time).
template <int kN>
struct EdgeLanes {
  static constexpr int kCapacity = kN ? (kN + 1) / 2 : kMaxVertices / 2;
  Lanes nx[kCapacity], ny[kCapacity];  // components of the edge normals
  Lanes off[kCapacity];                // support offsets n . v of the edges' start vertices
};

// Pair k of p's support lines (edges 2k and 2k + 1, an odd count's last
// edge repeated): the normals' components and dot(n, v) per lane. One
// computation for the test's own lanes and for support_lines(), so that a
// caller's kept lines are the test's bits.
[[gnu::always_inline]] inline void support_pair(const PolygonView& p, int n, int k, Lanes& nx, Lanes& ny, Lanes& off) {
  const int j0 = 2 * k, j1 = std::min(2 * k + 1, n - 1);
  const Vec2 n0 = p.normal(j0), n1 = p.normal(j1), v0 = p.vertex(j0), v1 = p.vertex(j1);
  nx = Lanes{n0.x, n1.x};
  ny = Lanes{n0.y, n1.y};
  off = detail::support_offsets(nx, ny, Lanes{v0.x, v1.x}, Lanes{v0.y, v1.y});
}

// Fills the first `pairs` = (count + 1) / 2 pairs of e from polygon p, or
// (given) from its support_lines(), which holds the same values.
template <int kN>
[[gnu::always_inline]] inline void edge_lanes(const PolygonView& p, int pairs, const SupportLines::Pair* given,
                                              EdgeLanes<kN>& e) {
  const int n = kN ? kN : p.count;
  if (given) {
    for (int k = 0; k < (kN ? (kN + 1) / 2 : pairs); ++k) {
      const SupportLines::Pair& g = given[k];
      e.nx[k] = detail::load_lanes(g.nx);
      e.ny[k] = detail::load_lanes(g.ny);
      e.off[k] = detail::load_lanes(g.off);
    }
    return;
  }
  for (int k = 0; k < (kN ? (kN + 1) / 2 : pairs); ++k) support_pair(p, n, k, e.nx[k], e.ny[k], e.off[k]);
}

// lo[k] = min over q's vertices of n . q for both edges of pair k, and (kHi)
// hi[k] the max, as std::min / std::max fold them (same operand order, so a
// NaN product is skipped as there). The vertex loop is outermost: each
// vertex is broadcast once and serves every pair. kN, kM: e's and q's
// vertex counts when known at compile time (0: read them).
template <bool kHi, int kN, int kM>
[[gnu::always_inline]] inline void extremes(const EdgeLanes<kN>& e, int pairs, const PolygonView& q, Lanes* lo,
                                            Lanes* hi) {
  const int np = kN ? (kN + 1) / 2 : pairs, m = kM ? kM : q.count;
  for (int k = 0; k < np; ++k) {
    lo[k] = Lanes{DBL_MAX, DBL_MAX};
    if (kHi) hi[k] = Lanes{-DBL_MAX, -DBL_MAX};
  }
  for (int i = 0; i < m; ++i) {
    const Vec2 v = q.vertex(i);
    const Lanes x = {v.x, v.x}, y = {v.y, v.y};
    for (int k = 0; k < np; ++k) {
      const Lanes t = e.nx[k] * x + e.ny[k] * y;  // dot(n, v) per lane
      lo[k] = lane_min(lo[k], t);
      if (kHi) hi[k] = lane_max(hi[k], t);
    }
  }
}

// One separating axis alone (numbered as in separating_axes_n): for axis
// j < nb the distance of edge line j of B to A, min_i n_j . a_i - n_j . b_j
// (> 0: A lies outside it), else of edge line i = j - nb of A to B. The same
// dot products, folded in the same order, as the lanes of separating_axes_n.
// kA, kB: the vertex counts when known at compile time (0: read them).
template <int kA, int kB>
double axis_distance(const PolygonView& a, const PolygonView& b, int axis) {
  const int na = kA ? kA : a.count, nb = kB ? kB : b.count;
  const bool on_b = axis < nb;
  const PolygonView& p = on_b ? b : a;  // the axis' polygon
  const PolygonView& q = on_b ? a : b;  // the other one
  const int e = on_b ? axis : axis - nb, m = on_b ? na : nb;
  const Vec2 n = p.normal(e);
  double lo = DBL_MAX;
  for (int i = 0; i < m; ++i) lo = std::min(lo, dot(n, q.vertex(i)));
  return lo - dot(n, p.vertex(e));
}

// The first axis, in the order B's edges then A's, that separates by more
// than tol (the caller found one; the last axis if none). Out of line: only
// a pair that separates past its witness axis comes here, and keeping these
// scalar loops apart keeps their loads out of the lanes' registers.
[[gnu::noinline, gnu::cold]] int first_separating_axis(const PolygonView& a, const PolygonView& b, double tol) {
  const int last = a.count + b.count - 1;
  int axis = 0;
  while (axis < last && !(axis_distance<0, 0>(a, b, axis) > tol)) ++axis;
  return axis;
}

// Fraction of tol (dimensionless) by which a vertex of B must lie outside
// an edge line of A for that line to count as cutting (see below): half of
// the clipper's snapping tol, far above the few eps |x| by which the two
// roundings of n . b - n . a differ, so a skipped line never cuts.
constexpr double kCutMargin = 0.5;

// The overlap test on E(A, B)'s edge lines (Table 2), shared by
// overlap_state and overlap_and_intersection. a0 in E(A, B), evaluated on
// E's edge lines without building E: every edge of E has the outward normal
// N of an edge of B or of -A and passes through its support point, so the
// signed distance of a0 to it is
//   edge j of B  (N = n_j):  min_i n_j . a_i - n_j . b_j
//   edge i of -A (N = -n_i): min_j n_i . b_j - n_i . a_i
// (a0 cancels: the verdict does not depend on the reference point). a0 is
// inside E iff all are negative: the same half-planes entrance_block()
// builds, in O(n m) with no construction; d = their maximum.
// kCuts: also sets bit i of *cuts when the line of A's edge i may cut B,
// i.e. some vertex of B lies more than tol / 2 outside it (max_j n_i . b_j -
// n_i . a_i > tol / 2). A line with no such vertex leaves B, and any part of
// B, unchanged in intersection_polygon: there every distance is within tol
// (the two ways of rounding differ by a few eps |x|, far below tol / 2)
// and snapped to 0, so the line does not cut.
// witness: see overlap_and_intersection. Axis j < b.count is edge j of B,
// b.count + i is edge i of A. The witness axis is tried alone first (a
// pair that stays apart ends there); otherwise every axis is evaluated, two
// at a time (EdgeLanes), and only a separated verdict (rare past the
// witness) looks for the first separating axis, in the order B's edges then
// A's, to store. Any other verdict clears the witness: a pair in contact
// stays so for many steps, and its stale axis would be tried in vain before
// every full test. A NaN distance is skipped, witness or not.
// kA, kB: the vertex counts when known at compile time (0: read them), so
// that the common pairs of triangles to pentagons run unrolled; every
// distance is the same dot product, rounded the same way, either way.
// kWitness: false when the caller has tried the witness axis already.
template <bool kCuts, int kA = 0, int kB = 0, bool kWitness = true>
OverlapState separating_axes_n(const PolygonView& a, const PolygonView& b, double tol, std::uint32_t* cuts,
                               int* witness, const SupportLines::Pair* support_a,
                               const SupportLines::Pair* support_b) {
  const int na = kA ? kA : a.count, nb = kB ? kB : b.count;
  const int pa = (na + 1) / 2, pb = (nb + 1) / 2;
  if (kWitness && witness && static_cast<unsigned>(*witness) < static_cast<unsigned>(nb + na))
    if (axis_distance<kA, kB>(a, b, *witness) > tol) return OverlapState::kSeparate;
  // Every axis, two per lane pair; dmax: the lane-wise maximum distance.
  EdgeLanes<kB> eb;
  EdgeLanes<kA> ea;
  Lanes lo_b[EdgeLanes<kB>::kCapacity];
  Lanes lo_a[EdgeLanes<kA>::kCapacity], hi_a[EdgeLanes<kA>::kCapacity];
  // B's axes first, folded into dmax before A's are evaluated (the same
  // order of the fold), so that B's lanes are dead during A's.
  edge_lanes(b, pb, support_b, eb);
  extremes<false, kB, kA>(eb, pb, a, lo_b, nullptr);
  Lanes dmax = {-DBL_MAX, -DBL_MAX};
  for (int k = 0; k < pb; ++k) dmax = lane_max(dmax, lo_b[k] - eb.off[k]);
  edge_lanes(a, pa, support_a, ea);
  extremes<kCuts, kA, kB>(ea, pa, b, lo_a, hi_a);
  for (int k = 0; k < pa; ++k) dmax = lane_max(dmax, lo_a[k] - ea.off[k]);
  const double d = std::max(dmax[0], dmax[1]);
  if (d > tol) {
    if (witness) *witness = first_separating_axis(a, b, tol);
    return OverlapState::kSeparate;
  }
  if (witness) *witness = -1;
  if (kCuts) {
    const Lanes half_tol = {kCutMargin * tol, kCutMargin * tol};
    std::uint64_t mask = 0;
    for (int k = 0; k < pa; ++k) mask |= std::uint64_t{lane_bits(hi_a[k] - ea.off[k] > half_tol)} << (2 * k);
    // An odd count's last pair repeats its last edge in lane 1: that bit
    // (na) off. An even count's lanes are its edges (no bit past na - 1).
    if (kA == 0 || kA % 2 == 1) mask &= (std::uint64_t{1} << na) - 1u;
    *cuts = static_cast<std::uint32_t>(mask);
  }
  return d < -tol ? OverlapState::kOverlapping : OverlapState::kTouching;
}

// Dispatch on the vertex counts: blocks cut by joint sets are mostly
// quadrilaterals, the rest mostly pentagons and triangles (of the overlap
// tests in the Sect. 6.1 collapse about 79 % are 4-4 pairs, 17 % 4-5 or
// 5-4, 3 % other pairs of triangles to pentagons), so every pair of counts
// 3 to 8 runs unrolled (the generic loops take two to three times as many
// instructions). by_counts calls Op::run<kA, kB>(a, b, args) with kA, kB
// the counts of a and b when both are 3 to 8, else Op::run<0, 0>;
// by_counts_b: on B's count, A's known to be kA (3 to 5). The pairs of
// triangles to pentagons are told apart inline; the rest (a count of 6 or
// more) go through by_counts_wide, out of line, so that the common
// dispatch stays a short chain of compares with no call frame.
template <class Op, int kA, class... Args>
OverlapState by_counts_wide_b(const PolygonView& a, const PolygonView& b, Args&&... args) {
  switch (b.count) {
    case 3: return Op::template run<kA, 3>(a, b, args...);
    case 4: return Op::template run<kA, 4>(a, b, args...);
    case 5: return Op::template run<kA, 5>(a, b, args...);
    case 6: return Op::template run<kA, 6>(a, b, args...);
    case 7: return Op::template run<kA, 7>(a, b, args...);
    case 8: return Op::template run<kA, 8>(a, b, args...);
    default: return Op::template run<0, 0>(a, b, args...);
  }
}

// Its arguments by value (those of OverlapAndClip::run): a reference to
// the caller's tol would make the caller keep tol in memory.
template <class Op>
[[gnu::noinline]] OverlapState by_counts_wide(const PolygonView& a, const PolygonView& b, double tol, Polygon& ip,
                                              IpEdge* source, int* witness, const OverlapFacts& facts) {
  switch (a.count) {
    case 3: return by_counts_wide_b<Op, 3>(a, b, tol, ip, source, witness, facts);
    case 4: return by_counts_wide_b<Op, 4>(a, b, tol, ip, source, witness, facts);
    case 5: return by_counts_wide_b<Op, 5>(a, b, tol, ip, source, witness, facts);
    case 6: return by_counts_wide_b<Op, 6>(a, b, tol, ip, source, witness, facts);
    case 7: return by_counts_wide_b<Op, 7>(a, b, tol, ip, source, witness, facts);
    case 8: return by_counts_wide_b<Op, 8>(a, b, tol, ip, source, witness, facts);
    default: return Op::template run<0, 0>(a, b, tol, ip, source, witness, facts);
  }
}

template <class Op, int kA, class... Args>
OverlapState by_counts_b(const PolygonView& a, const PolygonView& b, Args&&... args) {
  switch (b.count) {
    case 3: return Op::template run<kA, 3>(a, b, args...);
    case 4: return Op::template run<kA, 4>(a, b, args...);
    case 5: return Op::template run<kA, 5>(a, b, args...);
    default: return by_counts_wide<Op>(a, b, args...);
  }
}

template <class Op, class... Args>
OverlapState by_counts(const PolygonView& a, const PolygonView& b, Args&&... args) {
  switch (a.count) {
    case 3: return by_counts_b<Op, 3>(a, b, args...);
    case 4: return by_counts_b<Op, 4>(a, b, args...);
    case 5: return by_counts_b<Op, 5>(a, b, args...);
    default: return by_counts_wide<Op>(a, b, args...);
  }
}

// Ring edge labels while clipping: target edge j is j, contact edge c is -1 - c.
constexpr int contact_label(int c) { return -1 - c; }

// Edge i of an intersection polygon from its clipping label l (a target
// edge j >= 0 or a contact edge -1 - c): its normal is the source edge's,
// and its source that edge.
inline void set_labelled_edge(int i, int l, const PolygonView& contact, const PolygonView& target, Polygon& result,
                              IpEdge* source) {
  const bool on_contact = l < 0;
  const int e = on_contact ? contact_label(l) : l;  // contact_label is its own inverse
  result.n[static_cast<std::size_t>(i)] = on_contact ? contact.normal(e) : target.normal(e);
  if (source) source[i] = {on_contact, e};
}


// clip_ring_n for a ring of kN points none of which is on the line (each
// distance < 0 or > 0), the points outside the bits of kOut: the same
// points and labels as clip_edge's first two cases, with the sides known
// at compile time (no comparisons).
template <int kN, unsigned kOut>
[[gnu::always_inline]] inline int cut_sided(const Vec2* in, const int* in_label, const double* dist, int line_label,
                                            Vec2* out, int* out_label) {
  int o = 0;
#pragma GCC unroll 8
  for (int i = 0; i < kN; ++i) {
    const int k = i + 1 == kN ? 0 : i + 1;
    const bool p_out = (kOut >> i) & 1u, q_out = (kOut >> k) & 1u;
    if (!p_out) {
      out_label[o] = in_label[i];
      out[o++] = in[i];
      if (q_out) {
        out_label[o] = line_label;
        out[o++] = lerp(in[i], in[k], dist[i] / (dist[i] - dist[k]));
      }
    } else if (!q_out) {
      out_label[o] = in_label[i];
      out[o++] = lerp(in[i], in[k], dist[i] / (dist[i] - dist[k]));
    }
  }
  return o;
}

// cut_sided for a quadrilateral, the mask `outside` of its points outside
// (not 0) known at run time.
[[gnu::always_inline]] inline int cut_sided_4(unsigned outside, const Vec2* in, const int* in_label,
                                              const double* dist, int line_label, Vec2* out, int* out_label) {
#define DDA_CUT_SIDED(m) \
  case m: return cut_sided<4, m>(in, in_label, dist, line_label, out, out_label);
  switch (outside) {
    DDA_CUT_SIDED(1) DDA_CUT_SIDED(2) DDA_CUT_SIDED(3) DDA_CUT_SIDED(4) DDA_CUT_SIDED(5) DDA_CUT_SIDED(6)
    DDA_CUT_SIDED(7) DDA_CUT_SIDED(8) DDA_CUT_SIDED(9) DDA_CUT_SIDED(10) DDA_CUT_SIDED(11) DDA_CUT_SIDED(12)
    DDA_CUT_SIDED(13) DDA_CUT_SIDED(14)
    default: return 0;  // every point outside
  }
#undef DDA_CUT_SIDED
}

// One cut of clip_target: the ring in[0..n) with its labels cut by the line
// through pc with unit normal nc, keeping the inner side. Signed distances
// within tol of the line are snapped to 0 (no duplicate vertex, no sliver
// edge). Returns -1, and writes nothing, when no vertex lies outside (the
// ring stays as it is); else the new count. The distances two points at a
// time (pair k: points 2k and 2k + 1 in its lanes, an odd count's last
// point repeated), each nc . (p - pc) rounded as the scalar dot product and
// snapped by the same test (fabs(NaN) <= tol is false: a NaN stays). kN: n
// when known at compile time (0: read it), so that the common small rings
// run unrolled; the same operations in the same order either way. A ring
// of 4 points none of which is on the line (the usual cut) goes through
// cut_sided, one straight sequence per mask of the points outside.
template <int kN>
int cut_ring(const Vec2* in, const int* in_label, int n_in, Vec2 nc, Vec2 pc, double tol, int line_label, Vec2* out,
             int* out_label) {
  const int n = kN ? kN : n_in;
  constexpr int kPairs = kN ? (kN + 1) / 2 : kMaxVertices / 2;
  alignas(16) double dist[2 * kPairs];  // left uninitialised: the first n are set
  const Lanes nxy = {nc.x, nc.y}, pxy = {pc.x, pc.y};
  const Lanes tol_l = {tol, tol};
  const LaneMask sign = {INT64_MIN, INT64_MIN};
  LaneMask outside = {0, 0};  // lanes of the points outside, or-ed over the pairs
  constexpr bool kSided = kN == 4;         // measured: fewer instructions than for 3 to 5 points
  unsigned out_bits = 0, sided_bits = 0;  // kSided: the points outside, and those off the line
  for (int k = 0; k < (kN ? kPairs : (n + 1) / 2); ++k) {
    const Vec2 p = in[2 * k], q = in[std::min(2 * k + 1, n - 1)];
    const Lanes tp = nxy * (Lanes{p.x, p.y} - pxy), tq = nxy * (Lanes{q.x, q.y} - pxy);  // the terms of dot(nc, p - pc)
    Lanes d = Lanes{tp[0], tq[0]} + Lanes{tp[1], tq[1]};
    d = (Lanes)((LaneMask)d & ~((Lanes)((LaneMask)d & ~sign) <= tol_l));  // |d| <= tol: +0
    const LaneMask out_k = d > Lanes{0.0, 0.0};
    outside = detail::lane_or(outside, out_k);
    if constexpr (kSided) {
      out_bits |= lane_bits(out_k) << (2 * k);
      sided_bits |= lane_bits(detail::lane_or(out_k, d < Lanes{0.0, 0.0})) << (2 * k);
    }
    __builtin_memcpy(&dist[2 * k], &d, sizeof d);
  }
  if constexpr (kSided) {
    if (out_bits == 0) return -1;
    // No point on the line (nor NaN): the cut by the mask of the points outside.
    if (sided_bits == 15u) return cut_sided_4(out_bits, in, in_label, dist, line_label, out, out_label);
  } else if (!lane_bits(outside)) {
    return -1;
  }
  return 2 * n > kMaxVertices
             ? detail::clip_ring_n<true, true, kN>(in, dist, n, out, in_label, line_label, out_label)
             : detail::clip_ring_n<true, false, kN>(in, dist, n, out, in_label, line_label, out_label);
}

// The last ring of clip_target into `result`: its vertices, the source
// edges' normals and the sources (clipping labels are a target edge j >= 0
// or a contact edge -1 - c, never kMixedEdgeLabel), and clean_ring's test of
// each vertex between its two neighbours, two vertices at a time (pair k:
// vertices 2k and 2k + 1, an odd count's last vertex paired with vertex 0,
// tested twice). Returns false when some vertex is removable (then `result`
// is to be cleaned). kN as cut_ring's.
template <int kN>
[[gnu::always_inline]] inline bool emit_ring(const Vec2* in, const int* in_label, int n_in, const PolygonView& contact,
                                             const PolygonView& target, double tol, Polygon& result, IpEdge* source) {
  const int n = kN ? kN : n_in;
  const bool removable = detail::ring_needs_clean<kN>(in, n, tol * tol);
  for (int i = 0; i < n; ++i) {
    result.v[static_cast<std::size_t>(i)] = in[i];
    set_labelled_edge(i, in_label[i], contact, target, result, source);
  }
  result.count = n;
  return !removable;
}

// clip_target's rare end: result (its ring and count set, labels in_label)
// has a vertex to remove. clean_ring on the ring and its labels, then the
// normals and sources again. Out of line: it keeps its registers out of
// the clipping loop's.
[[gnu::noinline, gnu::cold]] void clean_result(const int* in_label, const PolygonView& contact,
                                               const PolygonView& target, double tol, Polygon& result,
                                               IpEdge* source) {
  std::array<int, kMaxVertices> label;
  for (int i = 0; i < result.count; ++i) label[static_cast<std::size_t>(i)] = in_label[i];
  result.count = clean_ring(result.v.data(), result.count, tol, label.data());
  for (int i = 0; i < result.count; ++i) {
    const int l = label[static_cast<std::size_t>(i)];
    if (l == kMixedEdgeLabel) {
      result.n[static_cast<std::size_t>(i)] = normalized(perp_right(result.edge(i)));
      if (source) source[i] = IpEdge{};
      continue;
    }
    set_labelled_edge(i, l, contact, target, result, source);
  }
}

// clip_target's scratch: a ring of vertices and their edge labels.
struct ClipRing {
  std::array<Vec2, kMaxVertices> v;
  std::array<int, kMaxVertices> label;
};

// clip_target's two rings on its stack, left uninitialised (a ClipRing
// would zero its Vec2s on every call): every element is written before it
// is read.
union ClipRings {
  ClipRings() {}
  ClipRing ring[2];
};

// finish_ring's end for a ring of more than four vertices, apart (as
// cut_ring_any): rings of 5 to 8 vertices unrolled, the rest emit_ring<0>.
[[gnu::noinline]] void finish_ring_wide(const Vec2* in, const int* in_label, int n, const PolygonView& contact,
                                        const PolygonView& target, double tol, Polygon& result, IpEdge* source) {
  bool clean = false;
  switch (n) {
    case 5: clean = emit_ring<5>(in, in_label, 5, contact, target, tol, result, source); break;
    case 6: clean = emit_ring<6>(in, in_label, 6, contact, target, tol, result, source); break;
    case 7: clean = emit_ring<7>(in, in_label, 7, contact, target, tol, result, source); break;
    case 8: clean = emit_ring<8>(in, in_label, 8, contact, target, tol, result, source); break;
    default: clean = emit_ring<0>(in, in_label, n, contact, target, tol, result, source); break;
  }
  if (!clean) clean_result(in_label, contact, target, tol, result, source);
}

// clip_target's end on its last ring in[0..n) (labels in_label, no
// kMixedEdgeLabel): emit_ring, then cleaning only if a vertex is
// removable; no IP when fewer than 3 vertices are left. kPentagons:
// pentagons inline too (measured: fewer instructions for the pairs of
// equal counts, more for those of a quadrilateral and a pentagon).
// kTarget: the target's count when known at compile time (0: not known);
// for a target of 6 to 8 vertices, rings of its count, then one fewer or
// more, two fewer or more, three more (the last rings by their frequency),
// inline with the count known too.
template <bool kPentagons, int kTarget = 0>
[[gnu::always_inline]] inline void finish_ring(const Vec2* in, const int* in_label, int n, const PolygonView& contact,
                                               const PolygonView& target, double tol, Polygon& result,
                                               IpEdge* source) {
  if (n < 3) {
    result.count = 0;
    return;
  }
  // The counts by their frequency: a 6-8 target's own and those near it
  // (kTarget), then triangles, quadrilaterals, pentagons.
  bool clean = false;
  if (kTarget > 5 && n == kTarget)
    clean = emit_ring<kTarget>(in, in_label, kTarget, contact, target, tol, result, source);
  else if (kTarget > 5 && n == kTarget - 1)
    clean = emit_ring<kTarget - 1>(in, in_label, kTarget - 1, contact, target, tol, result, source);
  else if (kTarget > 5 && n == kTarget + 1)
    clean = emit_ring<kTarget + 1>(in, in_label, kTarget + 1, contact, target, tol, result, source);
  else if (kTarget > 5 && n == kTarget - 2)
    clean = emit_ring<kTarget - 2>(in, in_label, kTarget - 2, contact, target, tol, result, source);
  else if (kTarget > 5 && n == kTarget + 2)
    clean = emit_ring<kTarget + 2>(in, in_label, kTarget + 2, contact, target, tol, result, source);
  else if (kTarget > 5 && n == kTarget + 3)
    clean = emit_ring<kTarget + 3>(in, in_label, kTarget + 3, contact, target, tol, result, source);
  else if (n == 3) clean = emit_ring<3>(in, in_label, 3, contact, target, tol, result, source);
  else if (n == 4) clean = emit_ring<4>(in, in_label, 4, contact, target, tol, result, source);
  else if (kPentagons && n == 5) clean = emit_ring<5>(in, in_label, 5, contact, target, tol, result, source);
  else return finish_ring_wide(in, in_label, n, contact, target, tol, result, source);
  if (!clean) clean_result(in_label, contact, target, tol, result, source);
}

// One cut of a ring of more than five vertices, apart: such rings are rare
// in the simulations, and one out-of-line call keeps the clipping loop's
// registers (not cold: the pair benchmarks of hexagons and octagons use it
// for most cuts). Rings of 6 to 10 vertices (the cuts of two hexagons or
// octagons) with their count known at compile time, the rest cut_ring<0>.
[[gnu::noinline]] int cut_ring_any(const Vec2* in, const int* in_label, int n, Lanes nc_l, Lanes pc_l, double tol,
                                   int line_label, Vec2* out, int* out_label) {
  const Vec2 nc = detail::vec2(nc_l), pc = detail::vec2(pc_l);  // one register each across the call
  switch (n) {
    case 6: return cut_ring<6>(in, in_label, 6, nc, pc, tol, line_label, out, out_label);
    case 7: return cut_ring<7>(in, in_label, 7, nc, pc, tol, line_label, out, out_label);
    case 8: return cut_ring<8>(in, in_label, 8, nc, pc, tol, line_label, out, out_label);
    case 9: return cut_ring<9>(in, in_label, 9, nc, pc, tol, line_label, out, out_label);
    case 10: return cut_ring<10>(in, in_label, 10, nc, pc, tol, line_label, out, out_label);
    default: return cut_ring<0>(in, in_label, n, nc, pc, tol, line_label, out, out_label);
  }
}

// clip_target's end when the contact has sharp corners (or they are not
// given, kSharpCornersUnknown: found here): the cuts by the bevels, then
// finish_ring, or, when a bevel cut, the general (cleaning) end, as the
// labels may hold kMixedEdgeLabel. Out of line: most contacts have no sharp
// corner.
//
// Bevels at the contact's sharp corners. Every vertex left is within tol of
// every edge line of the contact (a vertex within tol of a line is kept
// where it is, and crossing points are convex combinations of such
// vertices), but near a corner of interior angle theta the points within tol
// of both lines reach tol / sin(theta / 2) from the corner: 1e6 tol at theta
// = 1e-6 rad (vertices far outside the contact at sharp wedges and
// crossings). A bevel is the line through the corner whose normal bisects
// the corner's outward normals: it supports the contact (any normal inside
// the corner's normal cone does, so the rounding of n0 + n1 at a needle's
// tip cannot tilt it out), and the corners it makes with the two edge lines
// have interior angles (pi + theta) / 2 >= pi / 2. Cutting by it
// (tol-snapped like every cut) bounds every vertex within sqrt(2) tol of the
// contact near a bevelled corner and within tol / sin(15 deg) = 3.9 tol near
// the others, plus round-off: hence kIpVertexReach. The target needs none:
// every vertex lies on the target's ring (its vertices or convex
// combinations of them). A bevel removes only what lies more than tol beyond
// the corner, so on ordinary contacts it is one distance per vertex and
// changes nothing; its edge has no source edge (kMixedEdgeLabel: normal from
// its end points). The sharp corners are a fact of the contact alone
// (sharp_corners), given by a caller that keeps it per polygon, else found
// here.
[[gnu::noinline, gnu::cold]] void bevel_and_finish(const PolygonView& contact, const PolygonView& target, double tol,
                                                   std::uint32_t sharp, const Vec2* in, const int* in_label,
                                                   int in_count, ClipRing* out_ring, ClipRing* spare_ring,
                                                   Polygon& result, IpEdge* source) {
  bool bevelled = false;
  if (sharp == kSharpCornersUnknown) sharp = sharp_corners(contact);
  for (; sharp != 0 && in_count >= 3; sharp &= sharp - 1u) {
    const int c = __builtin_ctz(sharp);
    const Vec2 n0 = contact.normal(contact.prev(c)), n1 = contact.normal(c);
    Vec2* out = out_ring->v.data();
    int* out_label = out_ring->label.data();
    const int count = cut_ring<0>(in, in_label, in_count, normalized(n0 + n1), contact.vertex(c), tol, kMixedEdgeLabel,
                                  out, out_label);
    if (count < 0) continue;
    bevelled = true;
    in_count = count;
    in = out;
    in_label = out_label;
    std::swap(out_ring, spare_ring);
  }
  if (in_count < 3 || !bevelled) {
    finish_ring<false>(in, in_label, in_count, contact, target, tol, result, source);
    return;
  }
  for (int i = 0; i < in_count; ++i) result.v[static_cast<std::size_t>(i)] = in[i];
  result.count = in_count;
  clean_result(in_label, contact, target, tol, result, source);
}

// The target cut by the lines of the contact's edges whose bit is set in
// `lines` (Table 3; bits at or above contact.count must be clear), with
// edge labels; normals taken from the labelled source edges. Two rings
// (vertices and labels), ping-ponged by swapping their pointers: each cut
// of a convex polygon by a half-plane adds at most one vertex, so n + m
// fits in kMaxVertices. The rings are uninitialised stack scratch
// (ClipRings); one pointer per ring, rather than a buffer index, keeps the
// loop's addresses in registers. The first input is the target itself,
// and a line that leaves every vertex inside (the usual case: a shallow
// contact is cut by one or two of the contact polygon's edge lines) costs
// one distance per vertex and no copy. Then the bevels at the contact's sharp corners
// (bevel_and_finish), if any. The last ring goes to `result` in one pass
// with its normals and sources, which also runs clean_ring's test; only a
// ring that has a vertex to remove (rare) is then cleaned (clean_result).
// Inline in OverlapAndClip::run for the pairs of counts known at compile
// time (3 to 8: no call frame, no arguments spilled across a call); the
// rest share one out-of-line copy, clip_target. kPentagons as finish_ring's;
// kTarget: target.count when known at compile time (0: read it).
template <bool kPentagons = false, int kTarget = 0>
[[gnu::always_inline]] inline void clip_target_inline(const PolygonView& contact, const PolygonView& target,
                                                       double tol, std::uint32_t lines, std::uint32_t sharp,
                                                       Polygon& result, IpEdge* source) {
  ClipRings rings;
  // The target's own edges label themselves: label j for edge j.
  static constexpr std::array<int, kMaxVertices> target_label = [] {
    std::array<int, kMaxVertices> l{};
    for (int j = 0; j < kMaxVertices; ++j) l[static_cast<std::size_t>(j)] = j;
    return l;
  }();
  const Vec2* in = target.v;
  const int* in_label = target_label.data();
  int in_count = kTarget ? kTarget : target.count;
  ClipRing* out_ring = &rings.ring[0];
  ClipRing* spare_ring = &rings.ring[1];
  // Only the lines whose bit is set, in increasing order, while 3 vertices
  // are left.
  if (kTarget == 0 && in_count < 3) lines = 0;
  if (kTarget > 5 && lines != 0) {
    // The first cut of a target of 6 to 8 vertices, inline with its count
    // known (the loop would cut it out of line, cut_ring_any).
    const int c = __builtin_ctz(lines);
    Vec2* out = out_ring->v.data();
    int* out_label = out_ring->label.data();
    const int count = cut_ring<kTarget>(in, in_label, kTarget, contact.normal(c), contact.vertex(c), tol,
                                        contact_label(c), out, out_label);
    lines &= lines - 1u;
    if (count >= 0) {
      in_count = count;
      in = out;
      in_label = out_label;
      std::swap(out_ring, spare_ring);
      if (count < 3) lines = 0;
    }
  }
  for (; lines != 0; lines &= lines - 1u) {
    const int c = __builtin_ctz(lines);
    const Vec2 nc = contact.normal(c), pc = contact.vertex(c);
    Vec2* out = out_ring->v.data();
    int* out_label = out_ring->label.data();
    const int line = contact_label(c);
    // The counts by their frequency: for a target of 6 to 8 vertices its
    // count plus one and its count (a cut removing one or two vertices),
    // inline with the count known; then quadrilaterals, triangles (a corner
    // cut off), pentagons, the rest.
    int count = 0;
    if (kTarget > 5 && in_count == kTarget + 1)
      count = cut_ring<kTarget + 1>(in, in_label, kTarget + 1, nc, pc, tol, line, out, out_label);
    else if (kTarget > 5 && in_count == kTarget)
      count = cut_ring<kTarget>(in, in_label, kTarget, nc, pc, tol, line, out, out_label);
    else if (in_count == 4) count = cut_ring<4>(in, in_label, 4, nc, pc, tol, line, out, out_label);
    else if (in_count == 3) count = cut_ring<3>(in, in_label, 3, nc, pc, tol, line, out, out_label);
    else if (in_count == 5) count = cut_ring<5>(in, in_label, 5, nc, pc, tol, line, out, out_label);
    else count = cut_ring_any(in, in_label, in_count, detail::lanes(nc), detail::lanes(pc), tol, line, out, out_label);
    if (count < 0) continue;  // no vertex outside: the ring stays
    in_count = count;
    in = out;
    in_label = out_label;
    std::swap(out_ring, spare_ring);
    if (count < 3) break;
  }
  if (sharp != 0) {
    bevel_and_finish(contact, target, tol, sharp, in, in_label, in_count, out_ring, spare_ring, result, source);
    return;
  }
  finish_ring<kPentagons, kTarget>(in, in_label, in_count, contact, target, tol, result, source);
}

// clip_target_inline out of line: pairs with a count above 8, and
// intersection_polygon.
[[gnu::noinline]] void clip_target(const PolygonView& contact, const PolygonView& target, double tol,
                                   std::uint32_t lines, std::uint32_t sharp, Polygon& result, IpEdge* source) {
  clip_target_inline(contact, target, tol, lines, sharp, result, source);
}

// overlap_and_intersection for the vertex counts kA, kB (0: read them):
// the overlap test and, when the polygons overlap, the cut by the lines it
// found cutting. Flattened, so that the test runs in this call frame with
// its pointer arguments known: a pair that does not overlap (most
// candidates) costs the dispatch, this frame and the test, no more.
// kWitness: false when the caller has tried the witness axis already.
struct OverlapAndClip {
  template <int kA, int kB, bool kWitness = true>
  [[gnu::noinline, gnu::flatten]] static OverlapState run(const PolygonView& contact, const PolygonView& target,
                                                          double tol, Polygon& ip, IpEdge* source, int* witness,
                                                          const OverlapFacts& facts) {
    if (kA == 0 && (contact.count < 3 || target.count < 3)) return OverlapState::kSeparate;
    if (kA == 0 && (facts.contact_support || facts.target_support) &&
        (contact.count > kMaxBlockVertices || target.count > kMaxBlockVertices)) {
      // Support lines are kept for block polygons only: built here.
      const OverlapFacts own = {facts.contact_sharp, nullptr, nullptr};
      return run<0, 0>(contact, target, tol, ip, source, witness, own);
    }
    std::uint32_t lines = 0;
    const OverlapState state = separating_axes_n<true, kA, kB, kWitness>(contact, target, tol, &lines, witness,
                                                                         facts.contact_support, facts.target_support);
    if (state != OverlapState::kOverlapping) return state;
    // One verdict from one computation: the separating-axis test
    // says the interiors overlap by more than tol along every axis, yet the
    // clipper may leave fewer than 3 vertices (a sliver thinner than tol,
    // e.g. a needle's tip deep in a block far from the origin, whose
    // vertices clean_ring merges): then the pair is touching, with no
    // intersection polygon and no contact force.
    // The clipper inline for the counts known at compile time.
    if (kA != 0)
      clip_target_inline<kA == kB, kB>(contact, target, tol, lines, facts.contact_sharp, ip, source);
    else
      clip_target(contact, target, tol, lines, facts.contact_sharp, ip, source);
    if (ip.count >= 3) return OverlapState::kOverlapping;
    ip.count = 0;
    return OverlapState::kTouching;
  }
};

// overlap_and_intersection with the pair's own tolerance, apart: the
// dispatch with a given tolerance (the hot path) then needs no call frame.
[[gnu::noinline, gnu::cold]] OverlapState overlap_and_intersection_own_tol(const PolygonView& contact,
                                                                          const PolygonView& target, Polygon& ip,
                                                                          IpEdge* source, int* witness,
                                                                          const OverlapFacts& facts) {
  return overlap_and_intersection(contact, target, pair_tolerance(contact, target), ip, source, witness, facts);
}

constexpr std::uint32_t kAllLines = ~std::uint32_t{0};

}  // namespace

OverlapState overlap_state(const PolygonView& a, const PolygonView& b, double tol) {
  if (a.count < 3 || b.count < 3) return OverlapState::kSeparate;
  if (tol < 0.0) tol = pair_tolerance(a, b);
  // overlap_and_intersection's verdict (kOverlapping only with an IP): one
  // separating-axis test, and the clip only for a pair it finds overlapping.
  Polygon ip;
  return overlap_and_intersection(a, b, tol, ip, nullptr);
}

OverlapState overlap_and_intersection(const PolygonView& contact, const PolygonView& target, double tol, Polygon& ip,
                                      IpEdge* source, int* witness, const OverlapFacts& facts) {
  ip.count = 0;
  if (tol < 0.0) return overlap_and_intersection_own_tol(contact, target, ip, source, witness, facts);
  if (contact.count == 4 && target.count == 4) {
    // The common pair, two quadrilaterals, tries its witness axis here
    // (separating_axes_n's first step): a pair that stays apart, most of
    // them, ends with no call frame.
    if (witness && static_cast<unsigned>(*witness) < 8u && axis_distance<4, 4>(contact, target, *witness) > tol)
      return OverlapState::kSeparate;
    return OverlapAndClip::run<4, 4, false>(contact, target, tol, ip, source, witness, facts);
  }
  return by_counts<OverlapAndClip>(contact, target, tol, ip, source, witness, facts);
}

OverlapState overlap_and_intersection(const PolygonView& contact, const PolygonView& target, double tol, Polygon& ip,
                                      IpEdge* source, int* witness, std::uint32_t contact_sharp) {
  const OverlapFacts facts = {contact_sharp, nullptr, nullptr};
  return overlap_and_intersection(contact, target, tol, ip, source, witness, facts);
}

namespace {

// support_lines for a count kN known at compile time (0: read it).
template <int kN>
void support_lines_n(const PolygonView& p, SupportLines::Pair* out) {
  const int n = kN ? kN : p.count;
  for (int k = 0; k < (n + 1) / 2; ++k) {
    Lanes nx, ny, off;
    support_pair(p, n, k, nx, ny, off);
    detail::store_support_pair(out[k], nx, ny, off);
  }
}

}  // namespace

void support_lines(const PolygonView& poly, SupportLines::Pair* out) {
  if (poly.count == 4) return support_lines_n<4>(poly, out);
  if (poly.count < 3 || poly.count > kMaxBlockVertices) return;
  support_lines_n<0>(poly, out);
}

void intersection_polygon(const PolygonView& contact, const PolygonView& target, double tol, Polygon& result) {
  if (tol < 0.0) tol = pair_tolerance(contact, target);
  const std::uint32_t lines = contact.count < 32 ? (std::uint32_t{1} << contact.count) - 1u : kAllLines;
  clip_target(contact, target, tol, lines, kSharpCornersUnknown, result, nullptr);
}

namespace {

// sharp_corners for kN vertices (0: poly.count, at most 32), two corners at
// a time: lane 0 corner c, lane 1 corner c + 1 (an odd count's last corner
// in both), each dot product lane by lane the scalar dot's operations.
template <int kN>
std::uint32_t sharp_corners_n(const PolygonView& poly) {
  using detail::high_lanes;
  using detail::lanes;
  using detail::low_lanes;
  const int n = kN ? kN : std::min(poly.count, 32);
  const Lanes bevel{detail::kBevelCos, detail::kBevelCos};
  std::uint32_t sharp = 0;
  for (int c = 0; c < n; c += 2) {
    const int d = c + 1 < n ? c + 1 : c;
    const Lanes pc = lanes(poly.n[c == 0 ? n - 1 : c - 1]), pd = lanes(poly.n[d - 1]);
    const Lanes qc = lanes(poly.n[c]), qd = lanes(poly.n[d]);
    const Lanes dots = low_lanes(pc, pd) * low_lanes(qc, qd) + high_lanes(pc, pd) * high_lanes(qc, qd);
    sharp |= detail::lane_bits(dots < bevel) << c;
  }
  return n & 1 ? sharp & ((std::uint32_t{1} << n) - 1u) : sharp;  // an odd n: its repeated lane's bit n off
}

}  // namespace

std::uint32_t sharp_corners(const PolygonView& poly) {
  // Corner c lies between edges c - 1 and c.
  if (poly.count == 4) return sharp_corners_n<4>(poly);
  if (poly.count < 3) return 0;
  return sharp_corners_n<0>(poly);
}

Polygon intersection_polygon(const PolygonView& contact, const PolygonView& target, double tol) {
  Polygon ip;
  intersection_polygon(contact, target, tol, ip);
  return ip;
}

}  // namespace dda
