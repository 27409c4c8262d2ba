// Internal: the per-edge clipping step and the "nothing to clean" test shared
// by clip_ring / clean_ring (polygon.cpp) and the intersection polygon's
// clipper (overlap.cpp), inline so that the hot clipper runs them without a
// call. Not part of the public API.
#pragma once
#include "dda/polygon.hpp"
#include "lanes.hpp"

namespace dda::detail {

// What edge p = in[i] -> q = in[k] of a ring contributes when the ring is
// cut by a line (clip_ring's rule; dp, dq the snapped signed distances of p
// and q): p when dp <= 0, then the crossing when the signs differ strictly
// (a NaN dp keeps nothing; a NaN at either end crosses nothing). Labels
// (kLabels): the kept p starts the edge along the line when p is on it and
// q outside, else p's own edge; the crossing into the outside starts the
// edge along the line, the crossing back inside continues edge p -> q.
// Appends at out (and out_label), advancing them. kGuard: stop appending
// at out_cap, kMaxVertices points past the ring's start (unneeded when
// 2 n <= kMaxVertices, since an edge appends at most two points).
template <bool kLabels, bool kGuard>
inline void clip_edge(const Vec2* in, const int* in_label, int i, int k, double dp, double dq, int line_label,
                      Vec2*& out, int*& out_label, const Vec2* out_cap) {
  if (kGuard && out >= out_cap) return;
  // Three cases by p's side, the commonest first: strictly inside,
  // strictly outside, on the line (a NaN dp is none of them).
  if (dp < 0.0) {
    if (kLabels) *out_label++ = in_label[i];
    *out++ = in[i];
    if (dq > 0.0 && (!kGuard || out < out_cap)) {
      if (kLabels) *out_label++ = line_label;
      *out++ = lerp(in[i], in[k], dp / (dp - dq));
    }
  } else if (dp > 0.0) {
    if (dq < 0.0) {
      if (kLabels) *out_label++ = in_label[i];
      *out++ = lerp(in[i], in[k], dp / (dp - dq));
    }
  } else if (dp == 0.0) {
    if (kLabels) *out_label++ = dq > 0.0 ? line_label : in_label[i];
    *out++ = in[i];
  }
}

// clip_ring on in[0..n) (n >= 1) with distances dist[0..n): the edges in
// order, the closing edge n-1 -> 0 peeled off so that the loop needs no
// wrap-around index. Returns the count written. kN: n when known at compile
// time (0: read it), the edges then unrolled.
template <bool kLabels, bool kGuard, int kN = 0>
inline int clip_ring_n(const Vec2* in, const double* dist, int n_in, Vec2* out, const int* in_label, int line_label,
                       int* out_label) {
  const int n = kN ? kN : n_in;
  Vec2* o = out;
  int* ol = out_label;
  const Vec2* const cap = out + kMaxVertices;
  double dp = dist[0];
  if constexpr (kN != 0) {
#pragma GCC unroll 16
    for (int i = 0; i + 1 < kN; ++i) {
      const double dq = dist[i + 1];
      clip_edge<kLabels, kGuard>(in, in_label, i, i + 1, dp, dq, line_label, o, ol, cap);
      dp = dq;
    }
  } else {
    for (int i = 0; i + 1 < n; ++i) {
      const double dq = dist[i + 1];
      clip_edge<kLabels, kGuard>(in, in_label, i, i + 1, dp, dq, line_label, o, ol, cap);
      dp = dq;
    }
  }
  clip_edge<kLabels, kGuard>(in, in_label, n - 1, 0, dp, dist[0], line_label, o, ol, cap);
  return static_cast<int>(o - out);
}

// clean_ring's test for vertex b between a and c, with tol2 = tol * tol:
// b repeats a (closer than tol), or lies within tol of the chord a-c
// (|ac x ab| / |ac| <= tol, squared; a chord within tol of zero counts).
inline bool removable_vertex(Vec2 a, Vec2 b, Vec2 c, double tol2) {
  const Vec2 ac = c - a;
  const double lac2 = length_squared(ac);
  const bool repeated = length_squared(a - b) <= tol2;
  const double h = cross(ac, b - a);
  const bool straight = lac2 > tol2 ? h * h <= tol2 * lac2 : true;
  return repeated || straight;
}

// removable_vertex for two vertices at once, lane l testing b between a
// and c; returns the mask of the removable lanes. The same products and
// comparisons per lane (|b - a|^2 for |a - b|^2: the negation is exact and
// the squares drop the sign); a chord within tol of zero counts as
// straight, a NaN chord too, as there. The comparisons are combined as
// masks (lane_or, lane_not_greater), and a caller or-s the masks of
// several pairs before one lane_bits.
inline LaneMask removable_mask(Lanes ax, Lanes ay, Lanes bx, Lanes by, Lanes cx, Lanes cy, Lanes tol2) {
  const Lanes acx = cx - ax, acy = cy - ay, abx = bx - ax, aby = by - ay;
  const Lanes lac2 = acx * acx + acy * acy;
  const Lanes h = acx * aby - acy * abx;  // cross(ac, ab)
  const LaneMask repeated = abx * abx + aby * aby <= tol2;
  // straight: lac2 > tol2 ? h * h <= tol2 * lac2 : true.
  const LaneMask straight = lane_or(h * h <= tol2 * lac2, lane_not_greater(lac2, tol2));
  return lane_or(repeated, straight);
}

// True when clean_ring would remove some vertex of v[0..n) (n >= 3): its
// first sweep tests every vertex of the unchanged ring, so a ring with no
// removable vertex comes back as it is. Two vertices at a time (pair k:
// vertices 2k and 2k + 1), an odd count's last vertex alone by
// removable_vertex (the same products and comparisons). kN: n when known
// at compile time (0: read it).
template <int kN>
inline bool ring_needs_clean(const Vec2* v, int n_in, double tol2) {
  const int n = kN ? kN : n_in;
  const Lanes t2 = {tol2, tol2};
  if constexpr (kN == 3) {
    // A triangle: with its edges e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2,
    // vertex 0 has ab = e2, ac = v1 - v2 = -e1 exactly (rounding is
    // symmetric), vertex 1 ab = e0, ac = -e2, vertex 2 ab = e1, ac = -e0:
    // each |e|^2 once serves as some vertex's |ab|^2 and another's |ac|^2,
    // and cross(ac, ab) = -cross(e_ac, e_ab) has the same square. A
    // repeated vertex (|ab|^2 <= tol2) has a chord of the same length
    // within tol (|ac|^2 > tol2 false), so the chords alone tell those.
    // Lanes: edges (e0, e1), e2 alone; crosses (e0 x e1, e1 x e2) for
    // vertices 2 and 0 against |e0|^2 and |e1|^2, e2 x e0 for vertex 1.
    const Lanes x0 = {v[0].x, v[1].x}, y0 = {v[0].y, v[1].y}, x1 = {v[1].x, v[2].x}, y1 = {v[1].y, v[2].y};
    const Lanes ex = x1 - x0, ey = y1 - y0;  // (e0, e1)
    const Vec2 e2 = v[0] - v[2];
    const Lanes fx = {ex[1], e2.x}, fy = {ey[1], e2.y};  // (e1, e2)
    const Lanes len2 = ex * ex + ey * ey;
    const Lanes h = ex * fy - ey * fx;
    const double len2_2 = e2.x * e2.x + e2.y * e2.y;
    const double h1 = e2.x * ey[0] - e2.y * ex[0];
    const unsigned lanes_removable = lane_bits(lane_or(h * h <= t2 * len2, lane_not_greater(len2, t2)));
    return lanes_removable != 0 || !(len2_2 > tol2) || h1 * h1 <= tol2 * len2_2;
  }
  if constexpr (kN == 4) {
    // A quadrilateral: the chords of vertices 2 and 3 (1 -> 3, 2 -> 0) are
    // those of vertices 0 and 1 (3 -> 1, 0 -> 2) reversed, and c - a =
    // -(a - c) exactly (rounding is symmetric), so |ac|^2 is the same and
    // cross(ac, ab) only changes sign: the same squares, one chord per lane
    // pair for both pairs of vertices.
    const Lanes ax = {v[3].x, v[0].x}, ay = {v[3].y, v[0].y};  // vertices 3, 0: a of pair 0, c of pair 1
    const Lanes bx = {v[0].x, v[1].x}, by = {v[0].y, v[1].y};  // b of pair 0
    const Lanes cx = {v[1].x, v[2].x}, cy = {v[1].y, v[2].y};  // vertices 1, 2: c of pair 0, a of pair 1
    const Lanes dx = {v[2].x, v[3].x}, dy = {v[2].y, v[3].y};  // b of pair 1
    const Lanes acx = cx - ax, acy = cy - ay;
    const Lanes lac2 = acx * acx + acy * acy;
    const Lanes tl = t2 * lac2;
    const Lanes abx0 = bx - ax, aby0 = by - ay, abx1 = dx - cx, aby1 = dy - cy;
    const Lanes h0 = acx * aby0 - acy * abx0, h1 = acx * aby1 - acy * abx1;  // h1: cross(ca, cd) negated
    const LaneMask repeated = lane_or(abx0 * abx0 + aby0 * aby0 <= t2, abx1 * abx1 + aby1 * aby1 <= t2);
    const LaneMask straight = lane_or(lane_or(h0 * h0 <= tl, h1 * h1 <= tl), lane_not_greater(lac2, t2));
    return lane_bits(lane_or(repeated, straight)) != 0;
  }
  LaneMask removable = {0, 0};
  for (int k = 0; k < n / 2; ++k) {
    const int i0 = 2 * k, i1 = 2 * k + 1;
    const Vec2 a0 = v[i0 == 0 ? n - 1 : i0 - 1], a1 = v[i0];
    const Vec2 b0 = v[i0], b1 = v[i1];
    const Vec2 c0 = v[i1], c1 = v[i1 + 1 == n ? 0 : i1 + 1];
    removable = lane_or(removable, removable_mask(Lanes{a0.x, a1.x}, Lanes{a0.y, a1.y}, Lanes{b0.x, b1.x},
                                                  Lanes{b0.y, b1.y}, Lanes{c0.x, c1.x}, Lanes{c0.y, c1.y}, t2));
  }
  if (n % 2 != 0 && removable_vertex(v[n - 2], v[n - 1], v[0], tol2)) return true;
  return lane_bits(removable) != 0;
}

}  // namespace dda::detail
