// Internal: the area and centroid of a ring by Green's theorem, inline so
// that the normal-force kernel (contact.cpp) takes its intersection
// polygon's without a call; polygon.cpp's area_centroid is the same
// template. Not part of the public API.
#pragma once
#include "dda/polygon.hpp"

namespace dda::detail {

// Green's theorem on edges, in coordinates relative to v[0] so that large
// offsets do not cancel catastrophically. For edge (a, b), c = a x b:
//   S += c / 2,  Sx += c (ax + bx) / 6,  Sy += c (ay + by) / 6.
// green_centroid: area and centroid only, one edge at a time. kN: the
// vertex count when known at compile time (0: `n`), so that a
// quadrilateral's loop is unrolled. The two edges at v[0] are left out:
// one end is the origin, so c = a x b is a zero, and a zero added to the
// sums (+0 at the start, never -0 after: x + (-x) rounds to +0) leaves
// their bits as they are; every other vertex is an end of edges 1 to
// count - 2, so a non-finite vertex still makes the sums non-finite.
template <int kN = 0>
[[gnu::always_inline]] inline AreaMoments green_centroid(const Vec2* v, int n) {
  const int count = kN ? kN : n;
  AreaMoments m;
  if (count < 3) return m;
  const Vec2 o = v[0];
  double s = 0, sx = 0, sy = 0;
  for (int i = 1; i + 1 < count; ++i) {
    const Vec2 a = v[i] - o;
    const Vec2 b = v[i + 1] - o;
    const double c = cross(a, b);
    s += c;
    sx += c * (a.x + b.x);
    sy += c * (a.y + b.y);
  }
  s *= 0.5;
  sx /= 6.0;
  sy /= 6.0;
  m.area = s;
  if (s == 0.0) return m;
  m.centroid = o + Vec2{sx / s, sy / s};
  return m;
}

}  // namespace dda::detail
