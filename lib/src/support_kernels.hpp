// Internal: the per-block facts of a polygon that the overlap test reads
// (overlap.cpp) and that a simulation's geometry update finds with the
// normals at hand (polygon.cpp). Not part of the public API.
#pragma once
#include <cstdint>

#include "dda/overlap.hpp"
#include "lanes.hpp"

namespace dda::detail {

// Cosine of the turn between consecutive edge normals below which a contact
// corner gets a bevel (dimensionless): dot(n_prev, n) < -cos(30 deg), a turn
// of more than 150 degrees, i.e. an interior angle theta below 30 degrees.
// Unbevelled corners (theta >= 30 deg) keep every IP vertex within
// tol / sin(15 deg) = 3.9 tol of the contact (see clip_target). Why not
// 60 or 90 degrees (bound 2 or 1.4 tol): joint-set blocks have many corners
// of 30..60 degrees; bevelling them was 2e6 extra cuts per 3000 steps of the
// Sect. 6.1 collapse (+11 % run time, measured) against 8e3 below 30 deg.
constexpr double kBevelCos = -0.86602540378443865;

// Eq. 9's support offsets of an edge pair, lane by lane: dot(n, v) of each
// edge's normal (nx, ny) and start vertex (vx, vy). The one formula for the
// overlap test's own lanes, support_lines() and the block geometry update,
// so that lines kept by a caller are the test's bits.
[[gnu::always_inline]] inline Lanes support_offsets(Lanes nx, Lanes ny, Lanes vx, Lanes vy) {
  return nx * vx + ny * vy;
}

// A support-line pair as SupportLines keeps it (plain arrays) from lanes,
// and back.
[[gnu::always_inline]] inline void store_support_pair(SupportLines::Pair& g, Lanes nx, Lanes ny, Lanes off) {
  __builtin_memcpy(g.nx, &nx, sizeof(Lanes));
  __builtin_memcpy(g.ny, &ny, sizeof(Lanes));
  __builtin_memcpy(g.off, &off, sizeof(Lanes));
}
[[gnu::always_inline]] inline Lanes load_lanes(const double* a) {
  Lanes l;
  __builtin_memcpy(&l, a, sizeof(Lanes));
  return l;
}

// sharp_corners_n from the support lines' normals, pair k (edges 2k and
// 2k + 1) giving corners 2k and 2k + 1: lane by lane the dot products of
// edges (2k - 1, 2k) and (2k, 2k + 1), the same operations in the same
// order (an odd count's last pair repeats its edge: its lane 1 is masked
// off as there).
template <int kN>
inline std::uint32_t sharp_corners_lines(const SupportLines::Pair* lines, int count) {
  const int n = kN ? kN : count, pairs = (n + 1) / 2;
  const Lanes bevel{kBevelCos, kBevelCos};
  Lanes px = load_lanes(lines[pairs - 1].nx), py = load_lanes(lines[pairs - 1].ny);  // the pair before pair 0
  std::uint32_t sharp = 0;
  for (int k = 0; k < pairs; ++k) {
    const Lanes qx = load_lanes(lines[k].nx), qy = load_lanes(lines[k].ny);
    const Lanes dots = upper_lower(px, qx) * qx + upper_lower(py, qy) * qy;
    sharp |= lane_bits(dots < bevel) << (2 * k);
    px = qx;
    py = qy;
  }
  return n & 1 ? sharp & ((std::uint32_t{1} << n) - 1u) : sharp;
}

}  // namespace dda::detail
