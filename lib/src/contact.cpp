#include "dda/contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dda {

namespace {

constexpr double kSixth = 1.0 / 6.0;  // a multiplication instead of a division per segment

// Crossings of one IP edge with rays or envelope kinks: parameters strictly
// inside (0, 1) other than 1/2 (those points are demarcation points anyway).
struct Crossings {
  std::array<double, 4 * kMaxVertices> t;  // left uninitialised: count says how many are set
  int count = 0;
  void add(double x) {
    if (count < static_cast<int>(t.size()) && x > 0.0 && x < 1.0 && x != 0.5) t[static_cast<std::size_t>(count++)] = x;
  }
  // Insertion sort: a handful of points.
  void sort() {
    for (int i = 1; i < count; ++i) {
      const double x = t[static_cast<std::size_t>(i)];
      int j = i;
      for (; j > 0 && t[static_cast<std::size_t>(j - 1)] > x; --j) t[static_cast<std::size_t>(j)] = t[static_cast<std::size_t>(j - 1)];
      t[static_cast<std::size_t>(j)] = x;
    }
  }
};

// Demarcation points of one IP edge in order, each with the net traction there.
struct Breaks {
  struct Break {
    double t, f;
  };
  std::array<Break, 4 * kMaxVertices + 3> b;  // left uninitialised: count says how many are set
  int count = 0;
  void push(double t, double f) { b[static_cast<std::size_t>(count++)] = {t, f}; }
};

// Kinks of the lower envelope of d_i(t) = c_i + s_i t on (0, 1), where
// d_i is the distance of a + t (b - a) inside edge line i of `poly`. Walks
// the envelope from t = 0: at each step the next kink is the earliest
// crossing with a line that falls faster than the current one.
template <class Add>
void add_envelope_breaks(const Polygon& poly, Vec2 a, Vec2 b, Add&& add) {
  const Vec2 ab = b - a;
  std::array<double, kMaxVertices> c{}, s{};
  for (int i = 0; i < poly.count; ++i) {
    c[i] = dot(poly.normal(i), poly.vertex(i) - a);
    s[i] = -dot(poly.normal(i), ab);
  }
  int cur = 0;
  for (int i = 1; i < poly.count; ++i)
    if (c[i] < c[cur] || (c[i] == c[cur] && s[i] < s[cur])) cur = i;
  double t = 0.0;
  for (int guard = 0; guard < poly.count; ++guard) {
    int next = -1;
    double tn = 1.0;
    for (int j = 0; j < poly.count; ++j) {
      if (s[j] >= s[cur]) continue;
      const double tj = (c[j] - c[cur]) / (s[cur] - s[j]);
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

struct RaySpan {
  const Ray* ray = nullptr;
  int count = 0;
};

}  // namespace

NormalForce normal_contact_force(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip,
                                 Integration rule, double tol, const IpEdge* source) {
  NormalForce out;
  if (ip.count < 3) return out;
  const AreaMoments am = area_centroid(ip);
  out.ip_area = am.area;
  out.ip_centroid = am.centroid;
  const Vec2 c = am.centroid;
  Vec2 force{};
  double moment = 0.0;  // about the IP centroid
  // Bisector rays (paper rule only): the caller's, or built here into
  // thread-local scratch (a RaySet is 2 KB that would otherwise be zeroed
  // on every call).
  static thread_local RaySet own_cp, own_tp;
  RaySpan rays_cp{cp.rays, cp.ray_count}, rays_tp{tp.rays, tp.ray_count};
  if (rule == Integration::kPaperBisector) {
    if (!rays_cp.ray) {
      own_cp.count = bisector_rays(*cp.poly, cp.small_edge, cp.small_edge_rays, own_cp.ray.data());
      rays_cp = {own_cp.ray.data(), own_cp.count};
    }
    if (!rays_tp.ray) {
      own_tp.count = bisector_rays(*tp.poly, tp.small_edge, tp.small_edge_rays, own_tp.ray.data());
      rays_tp = {own_tp.ray.data(), own_tp.count};
    }
  }
  // Exit distances at the IP vertices, each computed on first use (a vertex
  // ends one edge and starts the next): bit k of known_* says dv_*[k] is set.
  std::array<double, kMaxVertices> dv_cp, dv_tp;  // left uninitialised: guarded by the masks
  std::uint32_t known_cp = 0, known_tp = 0;
  if (source) {
    // A vertex where an edge on CP's boundary starts or ends is on that
    // boundary: d_exit = 0 there (likewise for TP).
    // Edges of unknown source say nothing about their end points.
    for (int k = 0; k < ip.count; ++k) {
      const IpEdge in = source[ip.prev(k)], out_edge = source[k];
      const std::uint32_t bit = std::uint32_t{1} << k;
      if ((in.known() && in.on_contact) || (out_edge.known() && out_edge.on_contact)) {
        dv_cp[static_cast<std::size_t>(k)] = 0.0;
        known_cp |= bit;
      }
      if ((in.known() && !in.on_contact) || (out_edge.known() && !out_edge.on_contact)) {
        dv_tp[static_cast<std::size_t>(k)] = 0.0;
        known_tp |= bit;
      }
    }
  }
  auto vertex_d = [&ip](const PotentialSide& side, std::array<double, kMaxVertices>& dv, std::uint32_t& known, int k) {
    const std::uint32_t bit = std::uint32_t{1} << k;
    if (!(known & bit)) {
      dv[static_cast<std::size_t>(k)] = exit_distance(*side.poly, ip.vertex(k));
      known |= bit;
    }
    return dv[static_cast<std::size_t>(k)];
  };
  // Net normal traction phi_CP - phi_TP (Eq. 11) from the two exit
  // distances, each side only where its potential is not zero on the edge.
  auto traction = [&](bool use_cp, double d_cp, bool use_tp, double d_tp) {
    double f = 0.0;
    if (use_cp) f += d_cp > 0.0 ? cp.kn_over_h * d_cp : 0.0;
    if (use_tp) f -= d_tp > 0.0 ? tp.kn_over_h * d_tp : 0.0;
    return f;
  };
  for (int e = 0; e < ip.count; ++e) {
    const int e1 = ip.next(e);
    const Vec2 a = ip.vertex(e), b = ip.vertex(e1);
    const Vec2 n = ip.normal(e);
    const double len = length(b - a);
    if (len <= tol) continue;
    out.ip_perimeter += len;
    const Vec2 mid = lerp(a, b, 0.5);
    // An IP edge on the boundary of a polygon carries zero potential of it:
    // known from its source, else found from the midpoint's distance.
    const bool known = source && source[e].known();
    const bool src_cp = known && source[e].on_contact, src_tp = known && !source[e].on_contact;
    const double mid_cp = src_cp ? 0.0 : exit_distance(*cp.poly, mid);
    const double mid_tp = src_tp ? 0.0 : exit_distance(*tp.poly, mid);
    const bool use_cp = !(src_cp || mid_cp <= tol);
    const bool use_tp = !(src_tp || mid_tp <= tol);
    if (!use_cp && !use_tp) {  // on both boundaries: zero traction on its two halves
      out.segments += 2;
      continue;
    }
    // Demarcation points (Sect. 3.2.3 steps 1-4): the end points, the
    // midpoint, and the crossings strictly inside the edge (a crossing at
    // 0, 1/2 or 1 adds nothing), sorted, then merged with the three.
    Crossings cr;
    if (rule == Integration::kPaperBisector) {
      // Where edge a-b crosses each ray (segment_ray_crossing: -1 for a miss).
      auto add_crossings = [&](RaySpan rays) {
        for (int r = 0; r < rays.count; ++r) cr.add(segment_ray_crossing(a, b, rays.ray[r]));
      };
      if (use_cp) add_crossings(rays_cp);
      if (use_tp) add_crossings(rays_tp);
    } else {
      auto add = [&cr](double t) { cr.add(t); };
      if (use_cp) add_envelope_breaks(*cp.poly, a, b, add);
      if (use_tp) add_envelope_breaks(*tp.poly, a, b, add);
    }
    cr.sort();
    // Tractions: the end points and the midpoint reuse the distances found above.
    Breaks br;
    auto push_crossings = [&](int& i, double below) {
      for (; i < cr.count && cr.t[static_cast<std::size_t>(i)] < below; ++i) {
        const double t = cr.t[static_cast<std::size_t>(i)];
        if (t == br.b[static_cast<std::size_t>(br.count - 1)].t) continue;  // two rays, one point
        const Vec2 p = lerp(a, b, t);
        br.push(t, traction(use_cp, use_cp ? exit_distance(*cp.poly, p) : 0.0, use_tp,
                            use_tp ? exit_distance(*tp.poly, p) : 0.0));
      }
    };
    int next = 0;
    br.push(0.0, traction(use_cp, use_cp ? vertex_d(cp, dv_cp, known_cp, e) : 0.0, use_tp,
                          use_tp ? vertex_d(tp, dv_tp, known_tp, e) : 0.0));
    push_crossings(next, 0.5);
    br.push(0.5, traction(use_cp, mid_cp, use_tp, mid_tp));
    push_crossings(next, 1.0);
    br.push(1.0, traction(use_cp, use_cp ? vertex_d(cp, dv_cp, known_cp, e1) : 0.0, use_tp,
                          use_tp ? vertex_d(tp, dv_tp, known_tp, e1) : 0.0));
    // Eqs. 16-17 on each segment. The segment force L (fa + fb) / 2 acts at
    // pk of Eq. 17; its moment about c is taken in the equivalent form
    // L [(fa + fb) / 2 (pa - c) + (fa + 2 fb) / 6 (pb - pa)] x n, which is
    // Eq. 17 times the force but stays finite when fa + fb = 0.
    double t0 = br.b[0].t;
    Vec2 pa = lerp(a, b, t0);
    double fa = br.b[0].f;
    for (int k = 1; k < br.count; ++k) {
      const double t1 = br.b[k].t;
      const Vec2 pb = lerp(a, b, t1);
      const double fb = br.b[k].f;
      const double l = len * (t1 - t0);
      const double fs = 0.5 * l * (fa + fb);
      force += fs * n;
      const Vec2 arm = 0.5 * l * (fa + fb) * (pa - c) + (l * (fa + 2.0 * fb) * kSixth) * (pb - pa);
      moment += cross(arm, n);
      ++out.segments;
      t0 = t1;
      pa = pb;
      fa = fb;
    }
  }
  const double f2 = length_squared(force);
  if (!(f2 > 0.0)) return out;
  // Acting line: points p with (p - c) x f = moment. pg = c + lambda t with
  // t = perp_left(f) / |f|, so lambda (t x f) = moment, t x f = -|f|.
  const double fl = std::sqrt(f2);
  const double lambda = -moment / fl;
  out.force = force;
  out.point = c + lambda * (perp_left(force) / fl);
  out.valid = true;
  return out;
}

void clip_half_plane(Polygon& poly, Vec2 normal, double offset, double tol) {
  std::array<double, kMaxVertices> d;  // left uninitialised: the first poly.count are set
  for (int i = 0; i < poly.count; ++i) {
    double di = dot(normal, poly.vertex(i)) - offset;
    if (std::fabs(di) <= tol) di = 0.0;
    d[static_cast<std::size_t>(i)] = di;
  }
  std::array<Vec2, kMaxVertices> out;
  const int n = clip_ring(poly.v.data(), d.data(), poly.count, out.data());
  poly.count = n < 3 ? 0 : n;
  for (int i = 0; i < poly.count; ++i) poly.v[static_cast<std::size_t>(i)] = out[static_cast<std::size_t>(i)];
}

double potential_integral(const PotentialSide& side, const Polygon& region, double tol) {
  // Cell of edge i: where d_i <= d_j for all j, i.e. (n_j - n_i).x <=
  // n_j.v_j - n_i.v_i. On it phi = kn/H d_i is linear, so its integral is
  // area * phi(cell centroid).
  const Polygon& p = *side.poly;
  double total = 0.0;
  for (int i = 0; i < p.count; ++i) {
    Polygon cell = region;
    const Vec2 ni = p.normal(i);
    const double ci = dot(ni, p.vertex(i));
    for (int j = 0; j < p.count && cell.count >= 3; ++j) {
      if (j == i) continue;
      const Vec2 nj = p.normal(j);
      clip_half_plane(cell, nj - ni, dot(nj, p.vertex(j)) - ci, tol * 1e-3);
    }
    if (cell.count < 3) continue;
    const AreaMoments m = area_moments(cell);
    const double d = dot(ni, p.vertex(i) - m.centroid);
    total += m.area * side.kn_over_h * std::max(d, 0.0);
  }
  return total;
}

double contact_energy(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, double tol) {
  if (ip.count < 3) return 0.0;
  return potential_integral(cp, ip, tol) + potential_integral(tp, ip, tol);
}

}  // namespace dda
