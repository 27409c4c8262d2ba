#include "dda/joint_sets.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dda {

namespace {

constexpr double kPi = 3.14159265358979323846;

double signed_area(const std::vector<Vec2>& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) s += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * s;
}

bool is_convex_ccw(const std::vector<Vec2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    if (cross(p[(i + 1) % n] - p[i], p[(i + 2) % n] - p[(i + 1) % n]) < 0.0) return false;
  return true;
}

bool point_in_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

// Removes vertices on a straight run (turn within kCollinearSin).
std::vector<Vec2> drop_straight(std::vector<Vec2> p) {
  bool changed = true;
  while (changed && p.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 a = p[(i + p.size() - 1) % p.size()], b = p[i], c = p[(i + 1) % p.size()];
      const double s = cross(b - a, c - b) / (length(b - a) * length(c - b));
      if (std::fabs(s) <= kCollinearSin && dot(b - a, c - b) > 0.0) {
        p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  return p;
}

}  // namespace

std::vector<std::vector<Vec2>> convex_parts(const std::vector<Vec2>& poly) {
  if (is_convex_ccw(poly)) return {poly};
  // Ear clipping: O(n^3) worst case, fine for region outlines.
  std::vector<int> idx(poly.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  std::vector<std::vector<Vec2>> tris;
  while (idx.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      const Vec2 a = poly[idx[(k + idx.size() - 1) % idx.size()]], b = poly[idx[k]], c = poly[idx[(k + 1) % idx.size()]];
      if (cross(b - a, c - b) <= 0.0) continue;  // reflex or straight: not an ear
      bool empty = true;
      for (int j : idx) {
        const Vec2 q = poly[j];
        if (q == a || q == b || q == c) continue;
        if (point_in_triangle(q, a, b, c)) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      tris.push_back({a, b, c});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
      break;
    }
    if (!clipped) throw std::invalid_argument("region: not a simple counter-clockwise polygon (no ear found)");
  }
  tris.push_back({poly[idx[0]], poly[idx[1]], poly[idx[2]]});
  // Merge neighbours across a shared diagonal while the union stays convex
  // (Hertel-Mehlhorn: at most 4x the optimal number of parts).
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t i = 0; i < tris.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < tris.size() && !merged; ++j) {
        const auto& p = tris[i];
        const auto& q = tris[j];
        for (std::size_t a = 0; a < p.size() && !merged; ++a)
          for (std::size_t b = 0; b < q.size() && !merged; ++b) {
            // Shared edge p[a]->p[a+1] == q[b+1]->q[b].
            if (!(p[a] == q[(b + 1) % q.size()] && p[(a + 1) % p.size()] == q[b])) continue;
            std::vector<Vec2> u;
            for (std::size_t k = 0; k < p.size(); ++k) u.push_back(p[(a + 1 + k) % p.size()]);
            u.pop_back();  // p[a] comes again from q
            for (std::size_t k = 0; k < q.size(); ++k) u.push_back(q[(b + 1 + k) % q.size()]);
            u.pop_back();
            u = drop_straight(u);
            if (is_convex_ccw(u)) {
              tris[i] = u;
              tris.erase(tris.begin() + static_cast<std::ptrdiff_t>(j));
              merged = true;
            }
          }
      }
  }
  return tris;
}

// Largest joint line number |offset / spacing| counted exactly with k += 1
// in a double (2^52: every integer up to 2^53 is representable).
constexpr double kMaxLineNumber = 4503599627370496.0;

GeneratedBlocks generate_blocks(const std::vector<Vec2>& region, const std::vector<JointSet>& sets, double min_area) {
  if (region.size() < 3) throw std::invalid_argument("region: fewer than 3 vertices");
  for (const Vec2& p : region)
    if (!is_finite(p)) throw std::invalid_argument("region: non-finite coordinate");
  if (!(signed_area(region) > 0.0)) throw std::invalid_argument("region: vertices must be counter-clockwise");
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const std::string f = "joint_sets[" + std::to_string(k) + "]";
    if (!(sets[k].spacing > 0.0) || !std::isfinite(sets[k].spacing)) throw std::invalid_argument(f + ".spacing: must be positive");
    if (!(sets[k].dip_deg > 0.0 && sets[k].dip_deg < 180.0)) throw std::invalid_argument(f + ".dip: must lie in (0, 180) degrees");
  }
  std::vector<Polygon> pieces;
  for (const auto& part : convex_parts(region)) {
    if (part.size() > static_cast<std::size_t>(kMaxVertices)) throw std::invalid_argument("region: convex part with too many vertices");
    pieces.push_back(make_polygon(part.data(), static_cast<int>(part.size())));
  }
  for (const JointSet& js : sets) {
    // Line direction (cos dip, -sin dip): descending toward +x for dip < 90.
    const double a = js.dip_deg * kPi / 180.0;
    const Vec2 dir{std::cos(a), -std::sin(a)};
    const Vec2 nrm = perp_left(dir);
    std::vector<Polygon> next;
    for (const Polygon& piece : pieces) {
      // Lines through this piece: offsets k * spacing from the origin.
      double lo = DBL_MAX, hi = -DBL_MAX;
      for (int i = 0; i < piece.count; ++i) {
        const double s = dot(nrm, piece.vertex(i) - js.origin);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      Polygon rest = piece;
      // Line numbers are counted in a double: beyond 2^53 k += 1 no longer
      // advances (an origin absurdly far from the region) and the loop
      // would never end, so such a set is refused.
      if (!(std::fabs(lo / js.spacing) < kMaxLineNumber) || !(std::fabs(hi / js.spacing) < kMaxLineNumber))
        throw std::invalid_argument("joint set origin more than 2^52 spacings from the region: line numbers lose "
                                    "their integer precision");
      for (double k = std::ceil(lo / js.spacing); k * js.spacing < hi; k += 1.0) {
        Polygon below, above;
        split_polygon(rest, js.origin + (k * js.spacing) * nrm, nrm, below, above);
        if (below.count >= 3) next.push_back(below);
        rest = above;
        if (rest.count < 3) break;
      }
      if (rest.count >= 3) next.push_back(rest);
    }
    pieces.swap(next);
  }
  GeneratedBlocks out;
  for (const Polygon& p : pieces) {
    const double a = area(p);
    if (a < min_area) {
      ++out.dropped;
      out.dropped_area += a;
      continue;
    }
    if (p.count > kMaxBlockVertices) throw std::invalid_argument("a generated block has more than 16 vertices");
    out.blocks.push_back(p);
  }
  return out;
}

}  // namespace dda
