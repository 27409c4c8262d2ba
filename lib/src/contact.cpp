#include "dda/contact.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "area_kernels.hpp"
#include "lanes.hpp"

namespace dda {

namespace {

constexpr double kSixth = 1.0 / 6.0;  // a multiplication instead of a division per segment

// Insertion sort of t[0..count) > 0 after a sentinel t[-1] <= 0 (a
// handful of points): each shift is stopped by the sentinel rather than
// by an index test.
inline void sort_after_sentinel(double* t, int count) {
  for (int i = 1; i < count; ++i) {
    const double x = t[i];
    double* p = t + i;
    for (; p[-1] > x; --p) p[0] = p[-1];
    p[0] = x;
  }
}

// Crossings of one IP edge with rays or envelope kinks: parameters strictly
// inside (0, 1) (the end points are demarcation points anyway; so is 1/2,
// which integrate_edge skips as a repeated point), after the sort's
// sentinel 0.
struct Crossings {
  static constexpr int kCapacity = 4 * kMaxVertices;
  std::array<double, kCapacity + 1> slots;  // [0]: the sentinel; then count crossings, the rest unset
  int count = 0;
  Crossings() { slots[0] = 0.0; }
  const double* t() const { return slots.data() + 1; }
  void add(double x) {
    if (x > 0.0 && x < 1.0 && count < kCapacity) slots[static_cast<std::size_t>(++count)] = x;
  }
  void sort() { sort_after_sentinel(slots.data() + 1, count); }
};

using detail::LaneMask;
using detail::Lanes;
using detail::lane_bits;
using detail::lane_min;
using detail::upper_lower;

// d[1] < d[0] ? d[1] : d[0]: SSE2's minsd on the swapped pair (the plain
// form costs GCC a register copy more); elsewhere the plain form.
inline double across_min(Lanes d) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(_mm_unpackhi_pd(d, d), d));
#else
  return d[1] < d[0] ? d[1] : d[0];
#endif
}
// {across_min(a), across_min(b)}: the two folds finished by one minpd on
// their high and low lanes (the same selection lane by lane).
inline Lanes across_min2(Lanes a, Lanes b) {
#if defined(__SSE2__)
  return _mm_min_pd(_mm_unpackhi_pd(a, b), _mm_unpacklo_pd(a, b));
#else
  return Lanes{across_min(a), across_min(b)};
#endif
}

// lane_bits(m0) | lane_bits(m1) << 2 for two comparison results: SSE2
// packs their four lanes' 32-bit halves into one register (each lane's
// sign in the high half of a 32-bit slot) for one movmskps.
inline unsigned pair_bits(LaneMask m0, LaneMask m1) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(_mm_packs_epi32((__m128i)m0, (__m128i)m1))));
#else
  return lane_bits(m0) | lane_bits(m1) << 2;
#endif
}

// lane_bits(a) & lane_bits(b), the masks' and taken in their register
// (SSE2; GCC's generic form of it re-derives each lane).
inline unsigned lane_bits_and(LaneMask a, LaneMask b) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd(_mm_and_pd((__m128d)a, (__m128d)b)));
#else
  return lane_bits(a) & lane_bits(b);
#endif
}

// Line i of lines kept two at a time (pair i / 2, lane i % 2): the i-th
// double of the pairs' storage, read as such (GCC does not fold the pair
// and lane indices back into i).
inline double line_at(const Lanes* pairs, int i) {
  double x;
  std::memcpy(&x, reinterpret_cast<const char*>(pairs) + sizeof(double) * static_cast<std::size_t>(i), sizeof x);
  return x;
}

// The lane constants of paper_side_edge, {x, x} each. GCC builds such a
// constant from its scalar (movsd + unpcklpd: two instructions, again each
// time register pressure evicts it); read through a pointer it cannot see
// through, each is one memory operand. The same values: the same bits.
struct alignas(16) LaneConstants {
  double half[2];  // {1/2, 1/2}: the midpoint's t
  double max[2];   // {DBL_MAX, DBL_MAX}: a fold's start
  double sign[2];  // {-0.0, -0.0}: -x is x with the sign bit flipped
};
constexpr LaneConstants kLaneConstants = {{0.5, 0.5}, {DBL_MAX, DBL_MAX}, {-0.0, -0.0}};
inline const LaneConstants* lane_constants() {
  const LaneConstants* k = &kLaneConstants;
#if defined(__GNUC__)
  asm("" : "+r"(k));  // opaque: not folded back into a built constant
#endif
  return k;
}
// -v lane by lane (v with kc->sign's bit flipped), the sign read as
// xorpd's memory operand (GCC would keep the constant in a register for
// the whole edge, which the rest of the edge's work then lacks).
inline Lanes negated(const LaneConstants* kc, Lanes v) {
#if defined(__SSE2__) && defined(__GNUC__)
  asm("xorpd %1, %0" : "+x"(v) : "m"(*reinterpret_cast<const Lanes*>(kc->sign)));
  return v;
#else
  return -v;
#endif
}
inline Lanes load(const double* pair) {
#if defined(__SSE2__)
  return _mm_load_pd(pair);
#else
  return Lanes{pair[0], pair[1]};
#endif
}

// The crossings of an IP edge with a polygon's vertex rays (Sect. 3.2.3):
// ray i between lines i - 1 and i (line n - 1 for i = 0), d0 = 0, on the
// edge's lines d_i(t) = c_i + s_i t kept two at a time (pair p: lines 2p
// and 2p + 1, an odd count's last line repeated, which meets itself: num =
// 0, never a hit). Two rays at a time, each by EdgeLines::crossing's test
// (num and den negated together when den < 0; a hit needs 0 < num < den
// and d_a(t) >= 0 at t = num / den); add(t) for each hit in ray order.
template <class Add>
[[gnu::always_inline]] inline void vertex_ray_crossings(const Lanes* c, const Lanes* s, int pairs, Add&& add) {
  const Lanes zero = {0.0, 0.0};
  const LaneMask sign = (LaneMask)Lanes{-0.0, -0.0};
  for (int p = 0; p < pairs; ++p) {
    const int q = p == 0 ? pairs - 1 : p - 1;
    const Lanes ca = upper_lower(c[q], c[p]), sa = upper_lower(s[q], s[p]);  // lines 2p - 1, 2p
    const LaneMask flip = (sa - s[p] < zero) & sign;                         // den < 0: negate both
    const Lanes num = (Lanes)((LaneMask)(c[p] - ca) ^ flip), den = (Lanes)((LaneMask)(sa - s[p]) ^ flip);
    unsigned hits = lane_bits_and(num > zero, num < den);
    if (!hits) continue;
    const Lanes t = num / den;
    hits &= lane_bits(ca + sa * t >= zero);
    if (hits & 1u) add(t[0]);
    if (hits & 2u) add(t[1]);
  }
}

// The signed distances inside one polygon's edge lines along one IP edge
// a + t (b - a), t in [0, 1]: d_i(t) = c_i + s_i t (Eq. 13), so that
// d_exit(t) = min_i d_i(t) (Eq. 14). Built once per edge and side; every
// demarcation point of the edge, and every ray test, reuses them. The lines
// are kept two at a time: pair p holds lines 2p and 2p + 1 in its lanes, an
// odd count's last line repeated to fill the last pair (a repeated line
// changes no minimum). kN: the polygon's vertex count when known at compile
// time (0: read it), so that the loops over a quadrilateral's lines are
// unrolled.
template <int kN>
struct EdgeLines {
  static constexpr int kCapacity = kN ? (kN + 1) / 2 : kMaxVertices / 2;
  Lanes c[kCapacity], s[kCapacity];  // left uninitialised: the first pairs() are set
  int count = kN;
  int size() const { return kN ? kN : count; }
  int pairs() const { return kN ? kCapacity : (count + 1) / 2; }
  double c_at(int i) const { return line_at(c, i); }
  double s_at(int i) const { return line_at(s, i); }
  void build(const PolygonView& poly, Vec2 a, Vec2 ab) {
    if (!kN) count = poly.count;
    const Lanes ax = {a.x, a.x}, ay = {a.y, a.y}, abx = {ab.x, ab.x}, aby = {ab.y, ab.y};
    for (int p = 0; p < pairs(); ++p) {
      const int i = 2 * p, j = std::min(i + 1, size() - 1);
      const Vec2 ni = poly.normal(i), nj = poly.normal(j), vi = poly.vertex(i), vj = poly.vertex(j);
      const Lanes nx = {ni.x, nj.x}, ny = {ni.y, nj.y};
      c[p] = nx * (Lanes{vi.x, vj.x} - ax) + ny * (Lanes{vi.y, vj.y} - ay);  // dot(n, v - a)
      s[p] = -(nx * abx + ny * aby);                                         // -dot(n, ab)
    }
  }
  // min_i d_i, folded from DBL_MAX as d_i < d ? d_i : d in each lane over
  // its own lines, then across the two lanes: the minimum of the scalar fold
  // in line order (a NaN d_i skipped alike). Only on a tie of +0 and -0 may
  // the sign of the zero differ, which no caller reads (d > 0, d <= tol).
  template <class Distance>
  double fold_min(Distance&& d_pair) const {
    Lanes d = {DBL_MAX, DBL_MAX};
    for (int p = 0; p < pairs(); ++p) d = lane_min(d, d_pair(p));
    return across_min(d);
  }
  double at(double t) const {
    const Lanes tt = {t, t};
    return fold_min([&](int p) { return c[p] + s[p] * tt; });
  }
  double at_start() const {
    return fold_min([&](int p) { return c[p]; });
  }
  // at(1.0) without the multiplications (s_i * 1.0 is s_i exactly).
  double at_end() const {
    return fold_min([&](int p) { return c[p] + s[p]; });
  }
  // Where the edge crosses bisector `ray` (Sect. 3.2.3): d_a(t) = d_b(t) >=
  // d0 for its two lines, or -1 for a miss. The range test is done on the
  // numerator against the denominator, so a miss costs no division.
  double crossing(const Bisector& ray) const {
    const int la = ray.line_a, lb = ray.line_b;
    double num = c_at(lb) - c_at(la), den = s_at(la) - s_at(lb);
    if (den < 0.0) {
      num = -num;
      den = -den;
    }
    if (!(num > 0.0 && num < den)) return -1.0;
    const double t = num / den;
    return c_at(la) + s_at(la) * t >= ray.d0 ? t : -1.0;
  }
  // crossing() for the polygon's vertex rays, ray i between lines i - 1 and
  // i (line n - 1 for i = 0) with d0 = 0, two rays at a time; cr.add(t) for
  // each hit in ray order. An odd count's repeated line meets itself
  // (num = 0): never a hit.
  void vertex_crossings(Crossings& cr) const {
    vertex_ray_crossings(c, s, pairs(), [&cr](double t) { cr.add(t); });
  }
};

// Kinks of the lower envelope of d_i(t) = c_i + s_i t on (0, 1). Walks the
// envelope from t = 0: at each step the next kink is the earliest crossing
// with a line that falls faster than the current one.
template <class Lines, class Add>
void add_envelope_breaks(const Lines& lines, Add&& add) {
  auto c = [&lines](int i) { return lines.c_at(i); };
  auto s = [&lines](int i) { return lines.s_at(i); };
  int cur = 0;
  for (int i = 1; i < lines.size(); ++i)
    if (c(i) < c(cur) || (c(i) == c(cur) && s(i) < s(cur))) cur = i;
  double t = 0.0;
  for (int guard = 0; guard < lines.size(); ++guard) {
    int next = -1;
    double tn = 1.0;
    for (int j = 0; j < lines.size(); ++j) {
      if (s(j) >= s(cur)) continue;
      const double tj = (c(j) - c(cur)) / (s(cur) - s(j));
      if (tj > t && tj < tn) {
        tn = tj;
        next = j;
      }
    }
    if (next < 0) break;
    add(tn);
    t = tn;
    cur = next;
  }
}

struct BisectorSpan {
  const Bisector* b = nullptr;
  int count = 0;
};

// Eqs. 16-17 on each segment [t0, t1] of one IP edge with end tractions fa,
// fb. Along one edge all segments share the normal n, so only two sums are
// kept:
//   S0 = sum (t1 - t0) (fa + fb)                      -> force  L S0 / 2,
//   S1 = sum (t1 - t0) [fa (2 t0 + t1) + fb (t0 + 2 t1)] -> int f t dl = L S1 / 6.
// The edge's force L S0 / 2 n acts at a + (S1 / 3 S0) (b - a) (Eq. 17);
// its moment about c is taken as L [S0 / 2 a + S1 / 6 (b - a)] x n,
// which stays finite when S0 = 0.
// No member initialisers: EdgeSums{} is zero, a plain declaration is left
// for its producer to fill.
struct EdgeSums {
  double s0, s1;
  int segments;
};

// The sums over the demarcation points of one edge: t = 0, the sorted
// crossings t[0..count) (all inside (0, 1)) below 1/2, 1/2, those above, 1,
// each point once (a crossing equal to the one before, or to 1/2, adds no
// segment); traction_at(t) gives the traction at a crossing (f_start, f_mid,
// f_end at the fixed points).
template <class TractionAt>
[[gnu::always_inline]] inline EdgeSums integrate_sorted(const double* t_sorted, int count, double f_start, double f_mid,
                                                        double f_end, TractionAt&& traction_at) {
  EdgeSums sums{};
  double t0 = 0.0, fa = f_start;
  auto segment_to = [&](double t1, double fb) {
    const double dt = t1 - t0;
    sums.s0 += dt * (fa + fb);
    sums.s1 += dt * (fa * (2.0 * t0 + t1) + fb * (t0 + 2.0 * t1));
    ++sums.segments;
    t0 = t1;
    fa = fb;
  };
  int i = 0;
  for (; i < count && t_sorted[i] < 0.5; ++i) {
    const double t = t_sorted[i];
    if (t != t0) segment_to(t, traction_at(t));  // two rays, one point: once
  }
  segment_to(0.5, f_mid);
  for (; i < count; ++i) {  // all the rest are below 1
    const double t = t_sorted[i];
    if (t != t0) segment_to(t, traction_at(t));
  }
  segment_to(1.0, f_end);
  return sums;
}
template <class TractionAt>
[[gnu::always_inline]] inline EdgeSums integrate_edge(const Crossings& cr, double f_start, double f_mid, double f_end,
                                                      TractionAt&& traction_at) {
  return integrate_sorted(cr.t(), cr.count, f_start, f_mid, f_end, traction_at);
}

// Demarcation points of one side on an edge (Sect. 3.2.3 steps 1-4): the
// crossings with its bisectors, or its envelope's kinks.
template <int kN>
[[gnu::always_inline]] inline void add_side_crossings(const EdgeLines<kN>& lines, BisectorSpan rays, Integration rule, Crossings& cr) {
  if (rule == Integration::kPaperBisector) {
    // bisectors() gives exactly n rays when no small edge has a virtual node
    // (which adds one ray, or replaces two by one): the vertex rays in order.
    if (rays.count == lines.size())
      lines.vertex_crossings(cr);
    else
      for (int r = 0; r < rays.count; ++r) cr.add(lines.crossing(rays.b[r]));
  } else {
    add_envelope_breaks(lines, [&cr](double t) { cr.add(t); });
  }
}

// The exact envelope (Integration::kExactEnvelope) on an edge of known
// source, as paper_side_edge: split at the envelope's kinks. Out of line:
// the simulation's default is the paper's rule.
template <bool kMinus>
[[gnu::noinline]] bool envelope_side_edge(const PolygonView& poly, double k, Vec2 a, Vec2 ab, double tol,
                                          bool zero_start, bool zero_end, EdgeSums& sums) {
  EdgeLines<0> lines;
  lines.build(poly, a, ab);
  const double mid = lines.at(0.5);
  if (mid <= tol) return false;
  Crossings cr;
  add_envelope_breaks(lines, [&cr](double t) { cr.add(t); });
  cr.sort();
  auto traction = [k](double d) {
    if (!(d > 0.0)) return 0.0;
    return kMinus ? 0.0 - k * d : k * d;
  };
  const double f_start = zero_start ? 0.0 : traction(lines.at_start());
  const double f_end = zero_end ? 0.0 : traction(lines.at_end());
  sums = integrate_edge(cr, f_start, traction(mid), f_end, [&](double t) { return traction(lines.at(t)); });
  return true;
}

// Eqs. 16-17 on an edge split only at its start, midpoint and end (no
// crossing strictly inside): integrate_edge's two segments with their
// parameters written out (0 -> 1/2: dt = 1/2, 2 t0 + t1 = 1/2, t0 + 2 t1 = 1;
// 1/2 -> 1: dt = 1/2, 2 t0 + t1 = 2, t0 + 2 t1 = 5/2), the same operations
// in the same order: the same bits.
[[gnu::always_inline]] inline EdgeSums integrate_halves(double fa, double fm, double fb) {
  EdgeSums sums;
  sums.s0 = 0.0 + 0.5 * (fa + fm);
  sums.s1 = 0.0 + 0.5 * (fa * 0.5 + fm * 1.0);
  sums.s0 += 0.5 * (fm + fb);
  sums.s1 += 0.5 * (fm * 2.0 + fb * 2.5);
  sums.segments = 2;
  return sums;
}

// paper_side_edge's general case, an edge that takes neither shortcut:
// the crossings with the rays, sorted, and the paper's segments between
// them (integrate_halves when there are none). c, s: the edge's lines as
// paper_side_edge builds them; mid, f_start, f_end: its d_exit at t = 1/2
// and end tractions. Hexagons to octagons: first the envelope walk from
// line walk_i to line walk_j (when >= 0; see paper_side_edge), and the
// midpoint's distance taken here (mid is not read).
template <int kN, bool kMinus>
[[gnu::always_inline]] inline void paper_side_crossings(const Lanes* c, const Lanes* s, int n, double k,
                                                        BisectorSpan rays, double mid, double f_start, double f_end,
                                                        EdgeSums& sums, int walk_i = -1, int walk_j = -1) {
  if constexpr (kN >= 6) n = kN;  // the count known at compile time (loops unrolled, indices folded)
  const int pairs = (n + 1) / 2;
  const LaneConstants* const kc = lane_constants();
  const auto at = [&](double t) {
    const Lanes tt = {t, t};
    // With the count known, folded from pair 0 as paper_side_edge's
    // fold_pairs (the same bits for finite distances).
    Lanes d;
    if constexpr (kN >= 3) {
      d = lane_min(c[0] + s[0] * tt, c[1] + s[1] * tt);
      for (int p = 2; p < pairs; ++p) d = lane_min(d, c[p] + s[p] * tt);
    } else {
      d = load(kc->max);
      for (int p = 0; p < pairs; ++p) d = lane_min(d, c[p] + s[p] * tt);
    }
    return across_min(d);
  };
  const auto traction = [k](double d) {
    if (!(d > 0.0)) return 0.0;
    return kMinus ? 0.0 - k * d : k * d;
  };
  if constexpr (kN >= 6) {
    // The envelope walk (see paper_side_edge): from line walk_i at t = 0,
    // at each step the earlier crossing t_b > t_a of the current line with
    // one of its two adjacent lines (the one that falls below it: den > 0),
    // accepted when no line lies below both there and d(t_b) > 0; the
    // trapezoid t_a -> t_b, then on from that line, until walk_j's last
    // trapezoid to t = 1. Any other step falls through to the paper's
    // crossings below.
    if (walk_i >= 0) {
      int cur = walk_i;
      double t0 = 0.0, fa = f_start;
      EdgeSums w{};
      for (int step = 0; step < n; ++step) {
        if (cur == walk_j) {
          const double dt = 1.0 - t0;
          w.s0 += dt * (fa + f_end);
          w.s1 += dt * (fa * (2.0 * t0 + 1.0) + f_end * (t0 + 2.0));
          ++w.segments;
          sums = w;
          return;
        }
        const double cc = line_at(c, cur), sc = line_at(s, cur);
        int best = -1;
        double tb = 1.0;
        const auto neighbour = [&](int nb) {
          const double num = line_at(c, nb) - cc, den = sc - line_at(s, nb);
          if (!(den > 0.0)) return;
          const double t = num / den;
          if (t > t0 && t < tb) {
            tb = t;
            best = nb;
          }
        };
        neighbour(cur == 0 ? n - 1 : cur - 1);
        neighbour(cur == n - 1 ? 0 : cur + 1);
        if (best < 0) break;
        const double dt = at(tb), vi = cc + sc * tb, vj = line_at(c, best) + line_at(s, best) * tb;
        if (!(dt > 0.0 && dt == (vj < vi ? vj : vi))) break;
        const double fb = traction(dt), dtt = tb - t0;
        w.s0 += dtt * (fa + fb);
        w.s1 += dtt * (fa * (2.0 * t0 + tb) + fb * (t0 + 2.0 * tb));
        ++w.segments;
        t0 = tb;
        fa = fb;
        cur = best;
      }
    }
    mid = at(0.5);  // the midpoint's distance, taken here (paper_side_edge's fold_at)
  }
  const double f_mid = traction(mid);
  // The crossings strictly inside (0, 1), in ray order (Crossings::add's
  // test), at most 2 kN (a virtual node adds a ray), after a sentinel 0
  // (below every crossing: the sort's shifts stop there without an index test).
  double slots[2 * (kN ? kN : kMaxVertices) + 1];
  slots[0] = 0.0;
  double* const cross = slots + 1;
  int count = 0;
  const auto add = [&](double x) {
    if (x > 0.0 && x < 1.0) cross[count++] = x;
  };
  if (rays.count == n) {
    vertex_ray_crossings(c, s, pairs, add);
  } else {
    for (int r = 0; r < rays.count && r < 2 * n; ++r) {
      const Bisector& ray = rays.b[r];
      const int la = ray.line_a, lb = ray.line_b;
      const double ca = line_at(c, la), cb = line_at(c, lb), sa = line_at(s, la), sb = line_at(s, lb);
      double num = cb - ca, den = sa - sb;
      if (den < 0.0) {
        num = -num;
        den = -den;
      }
      if (!(num > 0.0 && num < den)) continue;
      const double t = num / den;
      if (ca + sa * t >= ray.d0) add(t);
    }
  }
  if (count == 0) {
    sums = integrate_halves(f_start, f_mid, f_end);
    return;
  }
  sort_after_sentinel(cross, count);
  sums = integrate_sorted(cross, count, f_start, f_mid, f_end, [&](double t) { return traction(at(t)); });
}

// paper_side_crossings out of line, for the counts known at compile time:
// the shallow contacts of a jointed rock mass (triangles to pentagons) take
// a shortcut on most edges, and the general case inline costs every edge;
// for hexagons to octagons (deep overlaps of round particles, a quarter of
// the edges in the general case) it costs the other edges' registers
// (measured).
template <int kN, bool kMinus>
[[gnu::noinline]] void paper_side_crossings_call(const Lanes* c, const Lanes* s, int n, double k, BisectorSpan rays,
                                                 double mid, double f_start, double f_end, EdgeSums& sums,
                                                 int walk_i = -1, int walk_j = -1) {
  paper_side_crossings<kN, kMinus>(c, s, n, k, rays, mid, f_start, f_end, sums, walk_i, walk_j);
}

// The pairs (first, last) of line masks of a kN-gon (kN = 3 to 8) in
// which each mask is one line and the two lines are adjacent (i - j = +-1
// or +-(kN - 1)): bit first | last << kN of a table built at compile time
// (2^(2 kN) bits: 8 KB for octagons), so that paper_side_edge's two-line
// test is one lookup instead of two single-bit tests and an index
// difference (the same predicate).
template <int kN>
struct AdjacentLines {
  static constexpr int kKeys = 1 << (2 * kN);
  std::uint64_t bits[(kKeys + 63) / 64] = {};
  constexpr AdjacentLines() {
    for (int i = 0; i < kN; ++i)
      for (int j : {i + 1 < kN ? i + 1 : 0, i > 0 ? i - 1 : kN - 1}) {
        const unsigned key = 1u << i | (1u << j) << kN;
        bits[key / 64] |= std::uint64_t{1} << (key % 64);
      }
  }
  // first, last: masks of kN bits.
  constexpr bool test(unsigned first, unsigned last) const {
    const unsigned key = first | last << kN;
    return (bits[key / 64] >> (key % 64)) & 1u;
  }
};
template <int kN>
constexpr AdjacentLines<kN> kAdjacentLines{};

// A polygon's lines two at a time as paper_side_edge pairs them (pair p:
// lines 2p and 2p + 1, an odd count's last line repeated): the normals' and
// vertices' components {n_i.x, n_j.x}, {n_i.y, n_j.y}, {v_i.x, v_j.x},
// {v_i.y, v_j.y}. Hexagons to octagons: gathered once per contact, so that
// each IP edge reads its lines' components as whole pairs (each pair is
// otherwise assembled again on every edge from the polygon's points). The
// same values: the same bits.
template <int kN>
struct PairedLines {
  static constexpr int kCapacity = (kN + 1) / 2;
  Lanes nx[kCapacity], ny[kCapacity], vx[kCapacity], vy[kCapacity];  // set by gather
  void gather(const PolygonView& poly) {
    for (int p = 0; p < kCapacity; ++p) {
      const int i = 2 * p, j = i + 1 < kN ? i + 1 : kN - 1;
      const Vec2 ni = poly.normal(i), nj = poly.normal(j), vi = poly.vertex(i), vj = poly.vertex(j);
      nx[p] = Lanes{ni.x, nj.x};
      ny[p] = Lanes{ni.y, nj.y};
      vx[p] = Lanes{vi.x, vj.x};
      vy[p] = Lanes{vi.y, vj.y};
    }
  }
};
// The paired lines a paper_side_edge<kN> reads: hexagons to octagons only
// (an empty type for the other counts, which build theirs per edge).
template <int kN>
using PairedFor = std::conditional_t<(kN >= 6 && kN <= 8), PairedLines<kN>, std::nullptr_t>;

// An IP edge of known source lies on one polygon's boundary, where that
// polygon's potential is zero: only the other side's phi enters Eq. 11,
// phi_CP with a plus sign (kMinus false), phi_TP with a minus. The same
// operations as the two-sided form with the zero side's distance left out
// (0 + k d for CP, 0 - k d for TP). zero_start / zero_end: the edge's end
// is on this side's boundary too (an adjacent IP edge lies on it), d = 0.
// Returns false when the edge is on this side's boundary as well (mid-point
// distance within tol): zero traction, no sums.
// paper_side_edge: the paper's rule (Sect. 3.2.3) on such an edge, with P's
// kN lines (0: poly.count) in locals, so that they stay in registers:
// EdgeLines' lines, distances and crossings and integrate_edge's sums,
// computed by the same operations in the same order (the same bits).
// The lines two at a time as in EdgeLines (pair p: lines 2p, 2p + 1, an odd
// count's last line repeated). Vertex rays (rays.count == kN) are tested
// two at a time as in EdgeLines::vertex_crossings; an edge that crosses none
// is integrated over its two halves with no list of crossings.
//
// One line, or two adjacent lines, nearest all along. On the edge
// d_exit(t) = min_i l_i(t), l_i(t) = c_i + s_i t, is concave and piecewise
// linear, and the paper's trapezoids (Eqs. 16-17) are exact on every piece
// whose ends are demarcation points. Two cases need no ray test, no sort
// and no distance at the midpoint or the crossings:
//   - one line i attains the minimum at both ends (c_i = min_j c_j and
//     c_i + s_i = min_j (c_j + s_j)): then d_exit = l_i on all of [0, 1]
//     (d_exit <= l_i everywhere, and d_exit, concave, is >= its chord,
//     which is l_i). Every demarcation point lies on one linear piece, so
//     the paper's segments sum (in exact arithmetic) to the one trapezoid
//     t0 = 0, t1 = 1:  S0 = fa + fb,  S1 = fa + 2 fb;
//   - line i alone attains it at t = 0, line j alone at t = 1, i and j
//     adjacent (the vertex ray between them is a demarcation point: the n
//     vertex rays, rays.count == n), and at their crossing
//       t* = (c_j - c_i) / (s_i - s_j),  0 < t* < 1
//     (the ray test's num / den, the same value whichever line is the ray's
//     first) no line lies below both: min_k l_k(t*) = min(l_i, l_j)(t*) =
//     d* > 0. Then d_exit = l_i on [0, t*] and l_j on [t*, 1]: every line
//     l_k is >= l_i at 0 and at t*, so on [0, t*] (linear), where l_i <=
//     l_j; likewise >= l_j on [t*, 1]. t* passes the ray test (d* >= 0),
//     the paper's other points split these two pieces only, and its sum is
//     the two trapezoids 0 -> t* -> 1 with f* = k d*, the traction the
//     paper's rule takes at that crossing (the same bits).
// Hexagons to octagons, where an edge's envelope has more pieces, walk it
// (in paper_side_crossings, before the paper's general case): line i alone
// at t = 0, line j alone at t = 1 (vertex rays, rays.count == n). From the
// current line a at t_a (the minimum there: d_exit(t_a) = l_a(t_a)), the
// earlier crossing t_b in (t_a, 1) of l_a with one of its two adjacent
// lines b that falls below it (s_a > s_b), accepted when no line lies
// below both there, min_k l_k(t_b) = min(l_a, l_b)(t_b) = d_b > 0; then on
// from b at t_b, until the current line is j, whose piece runs to t = 1.
// Each piece [t_a, t_b] is one line: every l_k is >= l_a at t_a and at t_b
// (in exact arithmetic l_a(t_b) = l_b(t_b) = d_b), so on all of it
// (linear), and d_exit = l_a there; the last piece likewise, j attaining
// the minimum at its start and at t = 1. Every kink is the crossing of two
// adjacent lines, on the vertex ray between them, with d_b > 0: a point
// the ray test passes (Sect. 3.2.3), where the paper takes f_b = k d_b
// (the same bits). The paper's other points split these pieces only, so
// its segments (Eqs. 13-17) sum in exact arithmetic to the walk's
// trapezoids t_a -> t_b. A step with no adjacent crossing before t = 1
// (the next kink between lines that are not adjacent, on no vertex ray),
// with a line below both, or with d_b <= 0 leaves the walk for the
// paper's general case. The walk's sums differ from the paper's by
// round-off only (adding its trapezoids in place of the paper's segments).
// All of these need the traction linear on each piece: the end distances > 0 (the
// clamp d > 0 ? k d : 0 would bend it), or the end known on this side's
// boundary (zero_start / zero_end: d = 0 there, f = 0). The midpoint's
// tol test comes first, as on every edge (for hexagons to octagons, after
// the ends, which may settle it). The sums differ from the paper's
// segment by segment only by round-off; segments counts the trapezoids
// integrated (1 or 2 here, up to n in the walk).
template <int kN, bool kMinus>
[[gnu::always_inline]] inline bool paper_side_edge(const PolygonView& poly, double k, BisectorSpan rays, Vec2 a, Vec2 ab,
                                                   double tol, bool zero_start, bool zero_end, EdgeSums& sums,
                                                   const PairedFor<kN>* paired = nullptr) {
  // paired: null where the caller gathered none (paper_side_edge_any).
  const int n = kN ? kN : poly.count;
  const int pairs = (n + 1) / 2;
  constexpr int kCapacity = kN ? (kN + 1) / 2 : kMaxVertices / 2;
  const LaneConstants* const kc = lane_constants();
  Lanes c[kCapacity], s[kCapacity];  // left uninitialised: the first `pairs` are set
  if constexpr (kN >= 3 && kN <= 5) {
    // Each line's products in the lanes of its point, {n.x (v.x - a.x),
    // n.y (v.y - a.y)} and {n.x ab.x, n.y ab.y}, then the two lines' sums
    // across: the same operations as the scalar dot products, with no
    // broadcast of a and ab (measured: fewer instructions for triangles to
    // pentagons, more for hexagons and octagons, where the broadcasts below
    // are shared by more lines).
    using detail::lanes;
    const Lanes al = lanes(a), abl = lanes(ab);
    for (int p = 0; p < pairs; ++p) {
      const int i = 2 * p, j = i + 1 < n ? i + 1 : n - 1;
      const Lanes ni = lanes(poly.normal(i)), nj = lanes(poly.normal(j));
      const Lanes pi = ni * (lanes(poly.vertex(i)) - al), pj = nj * (lanes(poly.vertex(j)) - al);
      const Lanes qi = ni * abl, qj = nj * abl;
      c[p] = detail::low_lanes(pi, pj) + detail::high_lanes(pi, pj);                        // dot(n, v - a)
      s[p] = negated(kc, detail::low_lanes(qi, qj) + detail::high_lanes(qi, qj));  // -dot(n, ab)
    }
  } else if (kN >= 6 && kN <= 8 && paired) {
    // The contact's paired lines (PairedLines, hexagons to octagons), the
    // same operations as below.
    const Lanes ax = {a.x, a.x}, ay = {a.y, a.y}, abx = {ab.x, ab.x}, aby = {ab.y, ab.y};
    if constexpr (kN >= 6 && kN <= 8)
      for (int p = 0; p < pairs; ++p) {
        const Lanes nx = paired->nx[p], ny = paired->ny[p];
        c[p] = nx * (paired->vx[p] - ax) + ny * (paired->vy[p] - ay);  // dot(n, v - a)
        s[p] = negated(kc, nx * abx + ny * aby);                        // -dot(n, ab)
      }
  } else {
    // The lines' components two at a time, {n_i.x, n_j.x} and so on.
    const Lanes ax = {a.x, a.x}, ay = {a.y, a.y}, abx = {ab.x, ab.x}, aby = {ab.y, ab.y};
    for (int p = 0; p < pairs; ++p) {
      const int i = 2 * p, j = i + 1 < n ? i + 1 : n - 1;
      const Vec2 ni = poly.normal(i), nj = poly.normal(j), vi = poly.vertex(i), vj = poly.vertex(j);
      const Lanes nx = {ni.x, nj.x}, ny = {ni.y, nj.y};
      c[p] = nx * (Lanes{vi.x, vj.x} - ax) + ny * (Lanes{vi.y, vj.y} - ay);  // dot(n, v - a)
      s[p] = negated(kc, nx * abx + ny * aby);                                // -dot(n, ab)
    }
  }
  // The lane by lane minimum of value(p) over the pairs p, folded as
  // EdgeLines does (d_i < d ? d_i : d from DBL_MAX). With the count known
  // (two pairs or more), the fold starts from pair 0 itself: the first
  // step from DBL_MAX returns a finite d_0 unchanged, so for finite
  // distances the same values in the same order give the same bits (an
  // infinite or NaN d_0 would be kept where DBL_MAX's step replaces it).
  const auto fold_pairs = [&](auto&& value) {
    if constexpr (kN > 0) {
      Lanes d = lane_min(value(0), value(1));
      for (int p = 2; p < pairs; ++p) d = lane_min(d, value(p));
      return d;
    } else {
      Lanes d = load(kc->max);
      for (int p = 0; p < pairs; ++p) d = lane_min(d, value(p));
      return d;
    }
  };
  // d_exit at the midpoint: EdgeLines::at's fold (at_start: t = 0 without
  // the products, at_end: t = 1 without them).
  const auto fold_at = [&](Lanes tt) { return across_min(fold_pairs([&](int p) { return c[p] + s[p] * tt; })); };
  double mid = 0.0;  // d_exit(1/2), when taken
  if constexpr (kN < 6) {
    mid = fold_at(load(kc->half));
    if (mid <= tol) return false;
  }
  // +k d or -k d for d > 0 (k = kn / H >= +0): k d is then never -0, so
  // 0.0 + k d would be k d itself; 0.0 - k d is +0 where -(k d) is -0.
  const auto traction = [k](double d) {
    if (!(d > 0.0)) return 0.0;
    return kMinus ? 0.0 - k * d : k * d;
  };
  // d_exit at the ends (at_start's and at_end's folds) and the lines that
  // attain it there.
  Lanes e[kCapacity];  // c_i + s_i: d_i(1)
  for (int p = 0; p < pairs; ++p) e[p] = c[p] + s[p];
  const Lanes m0 = fold_pairs([&](int p) { return c[p]; }), m1 = fold_pairs([&](int p) { return e[p]; });
  const Lanes d01 = across_min2(m0, m1);  // {d_exit(0), d_exit(1)}
  const double d0 = d01[0], d1 = d01[1];
  if constexpr (kN >= 6) {
    // Hexagons to octagons: the midpoint's tol test after the ends. Each
    // line's d_i(1/2) = c_i + (s_i / 2), the sum of c_i and a term between
    // 0 and s_i, lies between c_i and c_i + s_i, and so does its rounded
    // value (rounding is monotone): as computed, d_i(1/2) >= min(d_i(0),
    // d_i(1)), and the midpoint's fold >= min(d0, d1). An edge whose ends
    // are both beyond tol passes the test without the fold (the general
    // case takes it for its traction at t = 1/2).
    if (!((d1 < d0 ? d1 : d0) > tol)) {
      mid = fold_at(load(kc->half));
      if (mid <= tol) return false;
    }
  }
  const double f_start = zero_start ? 0.0 : traction(d0);
  const double f_end = zero_end ? 0.0 : traction(d1);
  int walk_i = -1, walk_j = -1;  // the envelope walk's end lines (hexagons to octagons)
  if ((zero_start || d0 > 0.0) && (zero_end || d1 > 0.0)) {
    // Bit i: line i attains d_exit at t = 0 (first) / t = 1 (last); an odd
    // count's repeated line masked off.
    const Lanes l0 = {d0, d0}, l1 = {d1, d1};
    // Two pairs at a time (pair_bits), an odd number's last alone.
    unsigned first = 0, last = 0;
    int q = 0;
    for (; q + 1 < pairs; q += 2) {
      first |= pair_bits(c[q] == l0, c[q + 1] == l0) << (2 * q);
      last |= pair_bits(e[q] == l1, e[q + 1] == l1) << (2 * q);
    }
    if (q < pairs) {
      first |= lane_bits(c[q] == l0) << (2 * q);
      last |= lane_bits(e[q] == l1) << (2 * q);
    }
    if (n % 2) {
      first &= ~(1u << n);
      last &= ~(1u << n);
    }
    if (first & last) {
      // One line nearest all along: the trapezoid t0 = 0, t1 = 1.
      sums.s0 = f_start + f_end;
      sums.s1 = f_start + 2.0 * f_end;
      sums.segments = 1;
      return true;
    }
    // i, j: the lines nearest at the start and at the end when adjacent.
    int i = 0, j = 0;
    bool adjacent;
    if constexpr (kN >= 3 && kN <= 8) {
      adjacent = rays.count == n && kAdjacentLines<kN>.test(first, last);
      if (adjacent) {
        i = __builtin_ctz(first);  // one bit each
        j = __builtin_ctz(last);
      }
    } else {
      i = __builtin_ctz(first | 1u << 31);
      j = __builtin_ctz(last | 1u << 31);
      const int ij = i - j;
      adjacent = rays.count == n && first == 1u << i && last == 1u << j && (ij == 1 || ij == -1 || ij == n - 1 || ij == 1 - n);
    }
    if (adjacent) {
      // Two adjacent lines, i nearest at the start, j at the end: their
      // crossing t* = num / den inside (0, 1), then d* and the two
      // trapezoids 0 -> t* (2 t0 + t1 = t*, t0 + 2 t1 = 2 t*) and t* -> 1
      // (2 t* + 1, t* + 2).
      // Triangles to pentagons: the lines read by index from a copy, so
      // that c and s themselves are read by constant indices only (kept in
      // registers, not stored for every edge; the general case is out of
      // line for them). Larger counts keep theirs in memory anyway.
      Lanes cl[kN >= 3 && kN <= 5 ? kCapacity : 1], sl[kN >= 3 && kN <= 5 ? kCapacity : 1];
      const Lanes *cx = c, *sx = s;
      if constexpr (kN >= 3 && kN <= 5) {
        for (int p = 0; p < pairs; ++p) {
          cl[p] = c[p];
          sl[p] = s[p];
        }
        cx = cl;
        sx = sl;
      }
      const double ci = line_at(cx, i), cj = line_at(cx, j);
      const double num = cj - ci, den = line_at(sx, i) - line_at(sx, j);
      if (num > 0.0 && num < den) {
        const double t = num / den;
        const Lanes tt = {t, t};
        Lanes v[kCapacity];
        for (int p = 0; p < pairs; ++p) v[p] = c[p] + s[p] * tt;
        const Lanes d = fold_pairs([&](int p) { return v[p]; });
        const double dt = across_min(d), vi = line_at(v, i), vj = line_at(v, j);
        // No other line below the two at t*, and d* > 0 (t* inside P, the
        // ray test's d >= 0, the traction unclamped).
        if (dt > 0.0 && dt == (vj < vi ? vj : vi)) {
          const double ft = traction(dt), u = 1.0 - t;
          sums.s0 = t * (f_start + ft) + u * (ft + f_end);
          sums.s1 = t * (f_start * t + ft * (2.0 * t)) + u * (ft * (2.0 * t + 1.0) + f_end * (t + 2.0));
          sums.segments = 2;
          return true;
        }
      }
    }
    // The walk for lines i and j that are not adjacent. Adjacent ones
    // failed the two-line test above, and the walk cannot join them the
    // other way round: the slopes s_k = -n_k . ab of the envelope's lines
    // fall from piece to piece (d_exit is concave), and -cos falls over at
    // most half a turn of the normals, while that way spans more (in exact
    // arithmetic). Such an edge takes the paper's general case directly.
    if constexpr (kN >= 6 && kN <= 8)
      if (!adjacent && rays.count == n && first != 0 && last != 0 && (first & (first - 1)) == 0 &&
          (last & (last - 1)) == 0) {
        walk_i = __builtin_ctz(first);  // one bit each
        walk_j = __builtin_ctz(last);
      }
  }
  if constexpr (kN >= 3 && kN <= 5) {
    Lanes cl[kCapacity], sl[kCapacity];  // a copy, as in the two-line shortcut
    for (int p = 0; p < pairs; ++p) {
      cl[p] = c[p];
      sl[p] = s[p];
    }
    paper_side_crossings_call<kN, kMinus>(cl, sl, n, k, rays, mid, f_start, f_end, sums);
  }
  else if constexpr (kN >= 6)  // the midpoint's distance taken there, after the walk
    paper_side_crossings_call<kN, kMinus>(c, s, n, k, rays, 0.0, f_start, f_end, sums, walk_i, walk_j);
  else
    paper_side_crossings<kN, kMinus>(c, s, n, k, rays, mid, f_start, f_end, sums);
  return true;
}

// The edge of known source under `rule`, with the vertex count a compile-time
// constant where it is a common one (unrolled loops over the edge lines:
// triangles, quadrilaterals and pentagons are most blocks of a jointed rock
// mass; hexagons to octagons, Box2D's limit, are the other common small
// blocks), else read at run time. The same operations in the same order
// either way: the same bits.
template <bool kMinus>
[[gnu::noinline]] bool paper_side_edge_any(const PolygonView& poly, double k, BisectorSpan rays, Vec2 a, Vec2 ab,
                                           double tol, bool zero_start, bool zero_end, EdgeSums& sums) {
  switch (poly.count) {
    case 3: return paper_side_edge<3, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    case 4: return paper_side_edge<4, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    case 5: return paper_side_edge<5, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    case 6: return paper_side_edge<6, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    case 7: return paper_side_edge<7, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    case 8: return paper_side_edge<8, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
    default: return paper_side_edge<0, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
  }
}

// kPaper: the rule is Integration::kPaperBisector (known for the whole
// contact, so that no edge tests it).
template <int kN, bool kMinus, bool kPaper>
[[gnu::always_inline]] inline bool one_side_edge(const PolygonView& poly, double k, BisectorSpan rays, Vec2 a, Vec2 ab,
                                                 double tol, bool zero_start, bool zero_end, EdgeSums& sums,
                                                 const PairedFor<kN>* paired) {
  if constexpr (!kPaper)
    return envelope_side_edge<kMinus>(poly, k, a, ab, tol, zero_start, zero_end, sums);
  else if constexpr (kN > 0)
    return paper_side_edge<kN, kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums, paired);
  else
    return paper_side_edge_any<kMinus>(poly, k, rays, a, ab, tol, zero_start, zero_end, sums);
}

// The loading point kept within the intersection polygon (Eq. 20,
// LoadingPoint::kWithinIp). Eq. 20 puts pg where the acting line of the
// net force f = sum f_k (Eq. 18) crosses the auxiliary line through the IP
// centroid c: pg = c + lambda t, t = perp_left(f) / |f|, lambda = -M / |f|
// with M = sum (p_k - c) x f_k. When the segment forces nearly cancel
// (|f| << sum |f_k|, e.g. a bar inside a block whose two halves are pushed
// to opposite sides) lambda grows without bound, and with it everything
// the point stands for besides the moment about c: the strain load
// T(pg)^T f, the friction history's relative displacement at pg, and the
// tangential force's lever arm. Where pg lies inside the IP the paper's
// point is kept unchanged (the same bits). Outside, pg goes to where the
// auxiliary line leaves the IP on the side of the crossing (lambda clamped
// to [lambda_lo, lambda_hi], continuous in lambda), and the moment that f
// no longer carries there is kept as a pure couple
//   couple = M - (pg - c) x f
// on CP's rotation DOF, and -couple on TP's (what F += T^T f cannot carry
// with a point inside the IP). The pair's total force is unchanged (f on
// CP, -f on TP) and so is its total moment about any point (f and -f act at
// the same pg, the couples cancel): linear and angular momentum are
// conserved, and each block's moment about c is M as before.
//
// inside_ip: pg on the inner side of (or on) every IP edge. The quick test
// of every contact; an edge no longer than tol (no reliable direction) may
// call a point outside by round-off: bound_to_ip, which bounds by the
// longer edges only, then finds it inside after all and keeps it.
// cross(b - a, p - a) = (b - a).x (p - a).y - (b - a).y (p - a).x is
// taken as the two lanes' products of b - a and the swapped p - a; the
// cross product is negative exactly when the first product is below the
// second (x - y < 0 iff x < y, infinities and NaN alike), which is tested
// without the difference. The edges from the closing one (count - 1 -> 0)
// on, so that no index wraps. kN: the IP's vertex count when known at
// compile time (0: read it), so that a triangle's or quadrilateral's edges
// run unrolled; the same tests in the same order either way.
template <int kN = 0>
bool inside_ip(const Polygon& ip, Vec2 p) {
  const int n = kN ? kN : ip.count;
  const Lanes pl = detail::lanes(p);
  Lanes a = detail::lanes(ip.vertex(n - 1));
#pragma GCC unroll 4
  for (int e = 0; e < n; ++e) {
    const Lanes b = detail::lanes(ip.vertex(e));
    const Lanes t = (b - a) * detail::swapped(pl - a);
    if (t[0] < t[1]) return false;  // cross < 0 (CCW: the inside is on the left)
    a = b;
  }
  return true;
}
// inside_ip with the count known for the common IPs, triangles to
// pentagons.
inline bool inside_ip_any(const Polygon& ip, Vec2 p) {
  return ip.count == 4   ? inside_ip<4>(ip, p)
         : ip.count == 3 ? inside_ip<3>(ip, p)
         : ip.count == 5 ? inside_ip<5>(ip, p)
                         : inside_ip<0>(ip, p);
}

void bound_to_ip(const Polygon& ip, double tol, NormalForce& out) {
  // Along c + lambda t, edge e (from a along ab) keeps the inside where
  // g + lambda k >= 0 with g = ab x (c - a) >= 0 and k = ab x t.
  const Vec2 c = out.ip_centroid;
  const double fl = length(out.force);
  const Vec2 t = perp_left(out.force) / fl;
  const double lambda = -out.moment / fl;
  const double tol2 = tol * tol;
  double lo = -DBL_MAX, hi = DBL_MAX;
  for (int e = 0; e < ip.count; ++e) {
    const Vec2 a = ip.vertex(e), ab = ip.vertex(ip.next(e)) - a;
    if (length_squared(ab) <= tol2) continue;
    const double g = cross(ab, c - a), k = cross(ab, t);
    if (k < 0.0) hi = std::min(hi, g / -k);
    else if (k > 0.0) lo = std::max(lo, -g / k);
  }
  // A degenerate IP (c not inside within round-off): the centroid itself.
  // Within [lo, hi] after all (a crossing on an edge, within round-off):
  // the paper's point stays, with no couple.
  const double clamped = lo <= hi ? std::clamp(lambda, lo, hi) : 0.0;
  if (clamped == lambda) return;
  out.point = c + clamped * t;
  out.couple = out.moment - cross(out.point - c, out.force);
}

// Where an IP edge lies as far as its source tells: on CP's boundary, on
// TP's, or neither (unknown source).
enum class On { kNeither = 0, kCp = 1, kTp = 2 };

// The sums of an edge of unknown source (both potentials; in a simulation, a
// bevel's edge). Out of line: the common edges lie on one polygon's
// boundary. Returns false when the edge carries zero traction (on the
// boundary of each side it would use).
[[gnu::noinline]] bool two_sided_edge(const PotentialSide& cp, const PotentialSide& tp, BisectorSpan rays_cp,
                                      BisectorSpan rays_tp, Integration rule, Vec2 a, Vec2 ab, double tol, On on_prev,
                                      On on_next, EdgeSums& sums) {
  // Unknown source: each potential is zero on the edge if its midpoint's
  // distance is within tol.
  EdgeLines<0> lines_cp, lines_tp;
  lines_cp.build(cp.poly, a, ab);
  lines_tp.build(tp.poly, a, ab);
  const double mid_cp = lines_cp.at(0.5), mid_tp = lines_tp.at(0.5);
  const bool use_cp = !(mid_cp <= tol);
  const bool use_tp = !(mid_tp <= tol);
  if (!use_cp && !use_tp) return false;  // on both boundaries: zero traction on its two halves
  // Demarcation points: the end points, the midpoint, and the crossings
  // strictly inside the edge (a crossing at 0, 1/2 or 1 adds nothing).
  Crossings cr;
  if (use_cp) add_side_crossings(lines_cp, rays_cp, rule, cr);
  if (use_tp) add_side_crossings(lines_tp, rays_tp, rule, cr);
  cr.sort();
  // Net normal traction phi_CP - phi_TP (Eq. 11) at t, each side only
  // where its potential is not zero on the edge; d_*: exit distances, or
  // negative for "not evaluated".
  auto traction = [&](double d_cp, double d_tp) {
    double f = 0.0;
    if (d_cp > 0.0) f += cp.kn_over_h * d_cp;
    if (d_tp > 0.0) f -= tp.kn_over_h * d_tp;
    return f;
  };
  auto traction_at = [&](double t) {
    return traction(use_cp ? lines_cp.at(t) : 0.0, use_tp ? lines_tp.at(t) : 0.0);
  };
  const double f_start = traction(use_cp && on_prev != On::kCp ? lines_cp.at_start() : 0.0,
                                  use_tp && on_prev != On::kTp ? lines_tp.at_start() : 0.0);
  const double f_mid = traction(use_cp ? mid_cp : 0.0, use_tp ? mid_tp : 0.0);
  const double f_end = traction(use_cp && on_next != On::kCp ? lines_cp.at_end() : 0.0,
                                use_tp && on_next != On::kTp ? lines_tp.at_end() : 0.0);
  sums = integrate_edge(cr, f_start, f_mid, f_end, traction_at);
  return true;
}

// area_centroid of an IP of 5 or more vertices: unrolled for 5 to 7.
[[gnu::noinline]] AreaMoments ip_centroid_5_up(const Vec2* v, int count) {
  return count == 5   ? detail::green_centroid<5>(v, 5)
         : count == 6 ? detail::green_centroid<6>(v, 6)
         : count == 7 ? detail::green_centroid<7>(v, 7)
                      : detail::green_centroid(v, count);
}

// normal_contact_force for CP and TP with kNc and kNt vertices (0: any),
// ip.count >= 3, and kPaper: rule is Integration::kPaperBisector. One named
// result, returned on every path, so that it is built in the caller's slot
// (no copy of it at the end).
template <int kNc, int kNt, bool kPaper>
[[gnu::always_inline]] inline NormalForce contact_force_ip(const PotentialSide& cp, const PotentialSide& tp,
                                                           const Polygon& ip, Integration rule, double tol,
                                                           const IpEdge* source, LoadingPoint where) {
  // area_centroid(ip): inline and unrolled for the common triangles and
  // quadrilaterals, and for pentagons where both blocks have 3 to 5
  // vertices (a quarter of two quadrilaterals' IPs), a call for the rest
  // (unrolled there for 5 to 7 vertices); the same operations in the same
  // order: the same bits.
  constexpr bool kSmall = kNc >= 3 && kNc <= 5 && kNt >= 3 && kNt <= 5;
  const AreaMoments am = ip.count == 4             ? detail::green_centroid<4>(ip.v.data(), 4)
                         : ip.count == 3           ? detail::green_centroid<3>(ip.v.data(), 3)
                         : kSmall && ip.count == 5 ? detail::green_centroid<5>(ip.v.data(), 5)
                                                   : ip_centroid_5_up(ip.v.data(), ip.count);
  const Vec2 c = am.centroid;
  const Lanes c_lanes = detail::lanes(c);
  // The sums in locals, the result built once at the end: a NormalForce
  // made first would be zeroed (a string store) and its counters summed
  // through memory in the edge loop.
  // The force's two components in lanes: one product and one sum for both
  // (the same operations as Vec2's, lane by lane).
  Lanes force_lanes = {0.0, 0.0};
  double moment = 0.0;     // about the IP centroid
  double perimeter = 0.0;  // NormalForce::ip_perimeter
  int segments = 0;        // NormalForce::segments
  // Bisectors (paper rule only): the caller's, or built here into
  // thread-local scratch (a BisectorSet is 1 KB that would otherwise be
  // zeroed on every call).
  static thread_local BisectorSet own_cp, own_tp;
  BisectorSpan rays_cp{cp.bisectors, cp.bisector_count}, rays_tp{tp.bisectors, tp.bisector_count};
  if (kPaper) {
    if (!rays_cp.b) {
      own_cp.count = bisectors(cp.poly, cp.small_edge, cp.small_edge_rays, own_cp.b.data());
      rays_cp = {own_cp.b.data(), own_cp.count};
    }
    if (!rays_tp.b) {
      own_tp.count = bisectors(tp.poly, tp.small_edge, tp.small_edge_rays, own_tp.b.data());
      rays_tp = {own_tp.b.data(), own_tp.count};
    }
  }
  // Where each IP edge lies (On), found by arithmetic, not by branches on
  // the source (which of an IP's edges lies on which polygon changes from
  // pair to pair).
  // Without sources every edge is unknown: a table of unknown edges, so
  // that no edge tests for it.
  static const IpEdge kUnknown[kMaxVertices]{};
  const IpEdge* const sources = source ? source : kUnknown;
  auto on = [sources](int k) {
    const IpEdge s = sources[k];
    return static_cast<On>((2 - static_cast<int>(s.on_contact)) & -static_cast<int>(s.known()));
  };
  // Hexagons to octagons: each side's lines paired once for all its edges.
  PairedFor<kNc> paired_cp;  // left uninitialised: gathered when used
  PairedFor<kNt> paired_tp;
  if constexpr (kPaper && kNc >= 6 && kNc <= 8) paired_cp.gather(cp.poly);
  if constexpr (kPaper && kNt >= 6 && kNt <= 8) paired_tp.gather(tp.poly);
  // Eqs. 16-18 over the IP's edges, kCount of them (0: ip.count): where
  // both blocks have 3 to 5 vertices (kSmall), a triangle's or
  // quadrilateral's IP runs unrolled, its edges' indices constants. The
  // same operations in the same order for any count: the same bits. Both
  // lambdas always inline (measured: without it, hexagons and octagons
  // take more instructions than a plain loop).
  const auto integrate_edges = [&](auto count) __attribute__((always_inline)) {
    constexpr int kCount = decltype(count)::value;
    // The previous, this and the next edge's, carried along the loop.
    On on_prev = On::kNeither, on_this = on((kCount ? kCount : ip.count) - 1), on_next = on(0);
    const auto edge = [&](int e) __attribute__((always_inline)) {
      const int e1 = kCount ? (e + 1 == kCount ? 0 : e + 1) : ip.next(e);
      on_prev = on_this;
      on_this = on_next;
      on_next = on(e1);
      const Vec2 a = ip.vertex(e), ab = ip.vertex(e1) - a;
      const Lanes ab2 = detail::lanes(ab) * detail::lanes(ab);
      const double len = detail::root(ab2[0] + ab2[1]);  // length(ab): x x + y y, lane by lane
      if (len <= tol) return;
      perimeter += len;
      // A vertex where an edge on CP's boundary starts or ends is on that
      // boundary: d_exit = 0 there (likewise for TP). For the potential of a
      // side that is used on edge e (so e is not on that side's boundary),
      // its start a is on it when the previous IP edge is, its end when the
      // next one is.
      EdgeSums sums;  // set when used
      bool used = false;
      if (on_this == On::kCp)
        used = one_side_edge<kNt, true, kPaper>(tp.poly, tp.kn_over_h, rays_tp, a, ab, tol, on_prev == On::kTp,
                                                on_next == On::kTp, sums, &paired_tp);
      else if (on_this == On::kTp)
        used = one_side_edge<kNc, false, kPaper>(cp.poly, cp.kn_over_h, rays_cp, a, ab, tol, on_prev == On::kCp,
                                                 on_next == On::kCp, sums, &paired_cp);
      else
        used = two_sided_edge(cp, tp, rays_cp, rays_tp, rule, a, ab, tol, on_prev, on_next, sums);
      if (!used) {
        // On the boundary of each side it would use: zero traction on its two halves.
        segments += 2;
        return;
      }
      segments += sums.segments;
      const Vec2 n = ip.normal(e);
      const double w = 0.5 * len * sums.s0;
      force_lanes += Lanes{w, w} * detail::lanes(n);
      // cross(w (a - c) + w1 ab, n) lane by lane: u = {u.x, u.y}, u * {n.y, n.x},
      // then the difference of the lanes (the same operations).
      const double w1 = len * sums.s1 * kSixth;
      const Lanes u = Lanes{w, w} * (detail::lanes(a) - c_lanes) + Lanes{w1, w1} * detail::lanes(ab);
      const Lanes un = u * detail::swapped(detail::lanes(n));
      moment += un[0] - un[1];
    };
    if constexpr (kCount != 0) {
#pragma GCC unroll 4
      for (int e = 0; e < kCount; ++e) edge(e);
    } else {
      for (int e = 0; e < ip.count; ++e) edge(e);
    }
  };
  if constexpr (kSmall) {
    if (ip.count == 4) integrate_edges(std::integral_constant<int, 4>{});
    else if (ip.count == 3) integrate_edges(std::integral_constant<int, 3>{});
    else integrate_edges(std::integral_constant<int, 0>{});
  } else {
    integrate_edges(std::integral_constant<int, 0>{});
  }
  const Vec2 force = detail::vec2(force_lanes);
  // Every member written (in declaration order: force, point, moment,
  // couple, ip_centroid, ip_area, ip_perimeter, segments, valid), so that
  // nothing is zeroed first; a vanishing net force leaves force, point and
  // moment zero (valid false).
  const double f2 = length_squared(force);
  const bool valid = f2 > 0.0;
  // Acting line: points p with (p - c) x f = moment. pg = c + lambda t with
  // t = perp_left(f) / |f|, so lambda (t x f) = moment, t x f = -|f|.
  Vec2 point{};
  if (valid) {
    const double fl = detail::root(f2);
    const double lambda = -moment / fl;
    point = c + lambda * (perp_left(force) / fl);
  }
  NormalForce out{valid ? force : Vec2{}, point, valid ? moment : 0.0, 0.0, c, am.area, perimeter, segments, valid};
  if (valid && where == LoadingPoint::kWithinIp && !inside_ip_any(ip, out.point)) bound_to_ip(ip, tol, out);
  return out;
}

// Another rule than the paper's (the exact envelope): out of line, with the
// vertex counts read at run time.
[[gnu::noinline]] NormalForce contact_force_other_rule(const PotentialSide& cp, const PotentialSide& tp,
                                                       const Polygon& ip, Integration rule, double tol,
                                                       const IpEdge* source, LoadingPoint where) {
  if (ip.count < 3) return NormalForce{};
  return contact_force_ip<0, 0, false>(cp, tp, ip, rule, tol, source, where);
}

// The paper's rule (Integration::kPaperBisector) from here on: the rule is
// no argument of the dispatch below, so that all of its arguments travel in
// registers (none on the stack) and no contact tests it again; the loading
// point's rule takes the rule's place, so that the other arguments stay in
// the registers normal_contact_force receives them in.
template <int kNc, int kNt>
NormalForce contact_force_n(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, LoadingPoint where,
                            double tol, const IpEdge* source) {
  if (ip.count < 3) return NormalForce{};
  return contact_force_ip<kNc, kNt, true>(cp, tp, ip, Integration::kPaperBisector, tol, source, where);
}

// contact_force_n with the vertex counts of CP and TP as compile-time
// constants when both are 3 to 5 (blocks cut by joint sets are mostly
// quadrilaterals, then pentagons and triangles), else read at run time.
template <int kNc>
NormalForce by_tp_count(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, LoadingPoint where,
                        double tol, const IpEdge* source) {
  switch (tp.poly.count) {
    case 3: return contact_force_n<kNc, 3>(cp, tp, ip, where, tol, source);
    case 4: return contact_force_n<kNc, 4>(cp, tp, ip, where, tol, source);
    case 5: return contact_force_n<kNc, 5>(cp, tp, ip, where, tol, source);
    default: return contact_force_n<0, 0>(cp, tp, ip, where, tol, source);
  }
}

// Two hexagons, heptagons or octagons (Box2D's limit; round particles made
// of polygons): the counts as constants too, so that no IP edge pays
// paper_side_edge_any's call and switch. Out of line: the common blocks
// are triangles to pentagons.
[[gnu::noinline]] NormalForce by_equal_count(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip,
                                             LoadingPoint where, double tol, const IpEdge* source) {
  if (cp.poly.count == tp.poly.count) switch (cp.poly.count) {
      case 6: return contact_force_n<6, 6>(cp, tp, ip, where, tol, source);
      case 7: return contact_force_n<7, 7>(cp, tp, ip, where, tol, source);
      case 8: return contact_force_n<8, 8>(cp, tp, ip, where, tol, source);
      default: break;
    }
  return contact_force_n<0, 0>(cp, tp, ip, where, tol, source);
}

NormalForce by_counts(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, LoadingPoint where,
                      double tol, const IpEdge* source) {
  switch (cp.poly.count) {
    case 3: return by_tp_count<3>(cp, tp, ip, where, tol, source);
    case 4: return by_tp_count<4>(cp, tp, ip, where, tol, source);
    case 5: return by_tp_count<5>(cp, tp, ip, where, tol, source);
    default: return by_equal_count(cp, tp, ip, where, tol, source);
  }
}

}  // namespace

NormalForce normal_contact_force(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip,
                                 Integration rule, double tol, const IpEdge* source, LoadingPoint where) {
  if (rule != Integration::kPaperBisector) return contact_force_other_rule(cp, tp, ip, rule, tol, source, where);
  return by_counts(cp, tp, ip, where, tol, source);
}


double potential_integral(const PotentialSide& side, const Polygon& region, double tol) {
  // Cell of edge i: where d_i <= d_j for all j, i.e. (n_j - n_i).x <=
  // n_j.v_j - n_i.v_i. On it phi = kn/H d_i is linear, so its integral is
  // area * phi(cell centroid). Each cell is cut from the region in two
  // small ping-pong rings (not Polygon copies: no normals are needed).
  const PolygonView& p = side.poly;
  const double snap = tol * 1e-3;  // a vertex this close to a cell line is on it
  double total = 0.0;
  // Scratch, not zeroed per call (Vec2's members are initialised): counts
  // say how many are set.
  static thread_local std::array<Vec2, kMaxVertices> ring[2];
  std::array<double, kMaxVertices> d;
  // The edges' offsets n_j . v_j, once per call (every cell reads them).
  std::array<double, kMaxVertices> support;
  for (int j = 0; j < p.count; ++j) support[static_cast<std::size_t>(j)] = dot(p.normal(j), p.vertex(j));
  for (int i = 0; i < p.count; ++i) {
    const Vec2 ni = p.normal(i);
    const double ci = support[static_cast<std::size_t>(i)];
    const Vec2* cell = region.v.data();
    int count = region.count, next = 0;
    for (int j = 0; j < p.count && count >= 3; ++j) {
      if (j == i) continue;
      const Vec2 nj = p.normal(j);
      // Keep normal.x <= offset; a vertex within snap of the line is on it.
      const Vec2 normal = nj - ni;
      const double offset = support[static_cast<std::size_t>(j)] - ci;
      // A region wholly on the kept side (every d <= 0) is what clip_ring
      // would copy, one wholly beyond (every d > 0) what it would empty:
      // neither is cut (mostly the case, an IP being small beside its block).
      // Two vertices at a time in lanes (the same operations, lane by lane),
      // an odd count's last alone.
      using detail::Lanes;
      using detail::LaneMask;
      const Lanes nl = detail::lanes(normal), off = {offset, offset}, snap_lanes = {snap, snap}, zero = {0.0, 0.0};
      const LaneMask magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
      LaneMask on_kept = ~LaneMask{}, beyond = ~LaneMask{};
      int k = 0;
      for (; k + 1 < count; k += 2) {
        const Lanes p0 = nl * detail::lanes(cell[k]), p1 = nl * detail::lanes(cell[k + 1]);
        Lanes dk = (detail::low_lanes(p0, p1) + detail::high_lanes(p0, p1)) - off;
        dk = (Lanes)(~((Lanes)((LaneMask)dk & magnitude) <= snap_lanes) & (LaneMask)dk);
        std::memcpy(d.data() + k, &dk, sizeof dk);
        on_kept &= dk <= zero;
        beyond &= dk > zero;
      }
      bool inside = detail::lane_bits(on_kept) == 3u, outside = detail::lane_bits(beyond) == 3u;
      if (k < count) {
        double dk = dot(normal, cell[k]) - offset;
        if (std::fabs(dk) <= snap) dk = 0.0;
        d[static_cast<std::size_t>(k)] = dk;
        inside = inside && dk <= 0.0;
        outside = outside && dk > 0.0;
      }
      if (inside) continue;
      if (outside) {
        count = 0;
        continue;
      }
      count = clip_ring(cell, d.data(), count, ring[next].data());
      if (count < 3) count = 0;
      cell = ring[next].data();
      next = 1 - next;
    }
    if (count < 3) continue;
    // area_centroid, inline for the common triangles and quadrilaterals
    // (the same template: the same bits).
    const AreaMoments m = count == 3   ? detail::green_centroid<3>(cell, 3)
                          : count == 4 ? detail::green_centroid<4>(cell, 4)
                                       : area_centroid(cell, count);
    const double dc = dot(ni, p.vertex(i) - m.centroid);
    total += m.area * side.kn_over_h * std::max(dc, 0.0);
  }
  return total;
}

double contact_energy(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, double tol) {
  if (ip.count < 3) return 0.0;
  return potential_integral(cp, ip, tol) + potential_integral(tp, ip, tol);
}

}  // namespace dda
