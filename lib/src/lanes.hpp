// Internal: two doubles handled as one value, for the per-vertex kernels
// (polygon.cpp, block.cpp), the separating-axis test (overlap.cpp) and the
// normal-force kernel (contact.cpp). Not part of the public API.
#pragma once
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>

#include "dda/vec2.hpp"

namespace dda::detail {

// The GCC/Clang vector extension, one SSE2 register on x86-64 (baseline, no
// -march), NEON or scalar code elsewhere. Lane-wise +, - and * round exactly
// as the scalar operations (no FMA contraction: ISO -std=c++17 keeps
// -ffp-contract=off).
using Lanes = double __attribute__((vector_size(16)));
using LaneMask = long long __attribute__((vector_size(16)));

// std::min(lo, t) and std::max(hi, t) lane by lane, operands in that order
// (a NaN t leaves lo, hi as they are). SSE2's minpd / maxpd are exactly
// these selections (named, since GCC turns the plain form against a
// constant into a four-instruction blend); elsewhere the plain form.
inline Lanes lane_min(Lanes lo, Lanes t) {
#if defined(__SSE2__)
  return _mm_min_pd(t, lo);
#else
  return t < lo ? t : lo;
#endif
}
inline Lanes lane_max(Lanes hi, Lanes t) {
#if defined(__SSE2__)
  return _mm_max_pd(t, hi);
#else
  return hi < t ? t : hi;
#endif
}

// std::sqrt lane by lane (both correctly rounded).
inline Lanes lane_sqrt(Lanes a) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(a);
#else
  return Lanes{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
}

// std::sqrt of one double (both correctly rounded), without the call
// std::sqrt keeps for a negative argument (errno): SSE2's sqrtsd.
inline double root(double a) {
#if defined(__SSE2__)
  const __m128d v = _mm_set_sd(a);
  return _mm_cvtsd_f64(_mm_sqrt_sd(v, v));
#else
  return std::sqrt(a);
#endif
}

// a where m is set, +0 elsewhere.
inline Lanes lane_where(LaneMask m, Lanes a) { return (Lanes)(m & (LaneMask)a); }

// Bit l set when lane l of a comparison result is true.
inline unsigned lane_bits(LaneMask m) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd((__m128d)m));
#else
  return static_cast<unsigned>((m[0] & 1) | (m[1] & 2));
#endif
}

// Comparison masks combined as masks, for one lane_bits of several tests:
// lane_or(a, b) has the bits of a | b; lane_not_greater(a, b) is !(a > b)
// lane by lane (true for a NaN lane). SSE2's orpd and cmpngtpd by name, as
// GCC widens the plain or-ed or negated mask lane by lane.
inline LaneMask lane_or(LaneMask a, LaneMask b) {
#if defined(__SSE2__)
  return (LaneMask)_mm_or_pd((__m128d)a, (__m128d)b);
#else
  return a | b;
#endif
}
inline LaneMask lane_not_greater(Lanes a, Lanes b) {
#if defined(__SSE2__)
  return (LaneMask)_mm_cmpngt_pd(a, b);
#else
  return ~(a > b);
#endif
}

// A point as lanes (x, y) and back.
inline Lanes lanes(Vec2 p) { return Lanes{p.x, p.y}; }
inline Vec2 vec2(Lanes l) { return {l[0], l[1]}; }
// (l[1], l[0]).
inline Lanes swapped(Lanes l) { return Lanes{l[1], l[0]}; }
// (a[1], b[0]): the element before each of b's when a holds the pair
// before b (two at a time around a polygon: its lines, its normals).
inline Lanes upper_lower(Lanes a, Lanes b) {
#if defined(__SSE2__)
  return _mm_shuffle_pd(a, b, 1);
#else
  return Lanes{a[1], b[0]};
#endif
}
// The low lanes (a[0], b[0]) and the high lanes (a[1], b[1]) of two values:
// the x and the y components of two points.
inline Lanes low_lanes(Lanes a, Lanes b) { return Lanes{a[0], b[0]}; }
inline Lanes high_lanes(Lanes a, Lanes b) { return Lanes{a[1], b[1]}; }

}  // namespace dda::detail
