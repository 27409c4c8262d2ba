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

// The signed distances inside one polygon's edge lines along one IP edge
// a + t (b - a), t in [0, 1]: d_i(t) = c_i + s_i t (Eq. 13), so that
// d_exit(t) = min_i d_i(t) (Eq. 14). Built once per edge and side; every
// demarcation point of the edge, and every ray test, reuses them.
// kN: the polygon's vertex count when known at compile time (0: read it),
// so that the loops over a quadrilateral's lines are unrolled.
template <int kN>
struct EdgeLines {
  std::array<double, kMaxVertices> c, s;  // left uninitialised: the first `count` are set
  int count = kN;
  void build(const Polygon& poly, Vec2 a, Vec2 ab) {
    if (!kN) count = poly.count;
    for (int i = 0; i < size(); ++i) {
      const Vec2 n = poly.normal(i);
      c[static_cast<std::size_t>(i)] = dot(n, poly.vertex(i) - a);
      s[static_cast<std::size_t>(i)] = -dot(n, ab);
    }
  }
  int size() const { return kN ? kN : count; }
  double at(double t) const {
    double d = DBL_MAX;
    for (int i = 0; i < size(); ++i) {
      const double di = c[static_cast<std::size_t>(i)] + s[static_cast<std::size_t>(i)] * t;
      d = di < d ? di : d;
    }
    return d;
  }
  double at_start() const {
    double d = DBL_MAX;
    for (int i = 0; i < size(); ++i) d = c[static_cast<std::size_t>(i)] < d ? c[static_cast<std::size_t>(i)] : d;
    return d;
  }
  // Where the edge crosses bisector `ray` (Sect. 3.2.3): d_a(t) = d_b(t) >=
  // d0 for its two lines, or -1 for a miss. The range test is done on the
  // numerator against the denominator, so a miss costs no division.
  double crossing(const Bisector& ray) const {
    const std::size_t la = static_cast<std::size_t>(ray.line_a), lb = static_cast<std::size_t>(ray.line_b);
    double num = c[lb] - c[la], den = s[la] - s[lb];
    if (den < 0.0) {
      num = -num;
      den = -den;
    }
    if (!(num > 0.0 && num < den)) return -1.0;
    const double t = num / den;
    return c[la] + s[la] * t >= ray.d0 ? t : -1.0;
  }
};

// Kinks of the lower envelope of d_i(t) = c_i + s_i t on (0, 1). Walks the
// envelope from t = 0: at each step the next kink is the earliest crossing
// with a line that falls faster than the current one.
template <class Lines, class Add>
void add_envelope_breaks(const Lines& lines, Add&& add) {
  const auto& c = lines.c;
  const auto& s = lines.s;
  int cur = 0;
  for (int i = 1; i < lines.size(); ++i)
    if (c[i] < c[cur] || (c[i] == c[cur] && s[i] < s[cur])) cur = i;
  double t = 0.0;
  for (int guard = 0; guard < lines.size(); ++guard) {
    int next = -1;
    double tn = 1.0;
    for (int j = 0; j < lines.size(); ++j) {
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

struct BisectorSpan {
  const Bisector* b = nullptr;
  int count = 0;
};

// normal_contact_force for CP and TP with kNc and kNt vertices (0: any).
template <int kNc, int kNt>
NormalForce contact_force_n(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, Integration rule,
                            double tol, const IpEdge* source) {
  NormalForce out;
  if (ip.count < 3) return out;
  const AreaMoments am = area_centroid(ip);
  out.ip_area = am.area;
  out.ip_centroid = am.centroid;
  const Vec2 c = am.centroid;
  Vec2 force{};
  double moment = 0.0;  // about the IP centroid
  // Bisectors (paper rule only): the caller's, or built here into
  // thread-local scratch (a BisectorSet is 1 KB that would otherwise be
  // zeroed on every call).
  static thread_local BisectorSet own_cp, own_tp;
  BisectorSpan rays_cp{cp.bisectors, cp.bisector_count}, rays_tp{tp.bisectors, tp.bisector_count};
  if (rule == Integration::kPaperBisector) {
    if (!rays_cp.b) {
      own_cp.count = bisectors(*cp.poly, cp.small_edge, cp.small_edge_rays, own_cp.b.data());
      rays_cp = {own_cp.b.data(), own_cp.count};
    }
    if (!rays_tp.b) {
      own_tp.count = bisectors(*tp.poly, tp.small_edge, tp.small_edge_rays, own_tp.b.data());
      rays_tp = {own_tp.b.data(), own_tp.count};
    }
  }
  // A vertex where an edge on CP's boundary starts or ends is on that
  // boundary: d_exit = 0 there (likewise for TP); bit k of zero_* says so
  // for IP vertex k. Edges of unknown source say nothing about their end points.
  std::uint32_t zero_cp = 0, zero_tp = 0;
  if (source) {
    for (int k = 0; k < ip.count; ++k) {
      const IpEdge in = source[ip.prev(k)], out_edge = source[k];
      const std::uint32_t bit = std::uint32_t{1} << k;
      if ((in.known() && in.on_contact) || (out_edge.known() && out_edge.on_contact)) zero_cp |= bit;
      if ((in.known() && !in.on_contact) || (out_edge.known() && !out_edge.on_contact)) zero_tp |= bit;
    }
  }
  EdgeLines<kNc> lines_cp;
  EdgeLines<kNt> lines_tp;
  Crossings cr;
  for (int e = 0; e < ip.count; ++e) {
    const int e1 = ip.next(e);
    const Vec2 a = ip.vertex(e), ab = ip.vertex(e1) - a;
    const double len = length(ab);
    if (len <= tol) continue;
    out.ip_perimeter += len;
    // An IP edge on the boundary of a polygon carries zero potential of it:
    // known from its source, else found from the midpoint's distance.
    const bool known = source && source[e].known();
    const bool src_cp = known && source[e].on_contact, src_tp = known && !source[e].on_contact;
    double mid_cp = 0.0, mid_tp = 0.0;
    if (!src_cp) {
      lines_cp.build(*cp.poly, a, ab);
      mid_cp = lines_cp.at(0.5);
    }
    if (!src_tp) {
      lines_tp.build(*tp.poly, a, ab);
      mid_tp = lines_tp.at(0.5);
    }
    const bool use_cp = !(src_cp || mid_cp <= tol);
    const bool use_tp = !(src_tp || mid_tp <= tol);
    if (!use_cp && !use_tp) {  // on both boundaries: zero traction on its two halves
      out.segments += 2;
      continue;
    }
    // Demarcation points (Sect. 3.2.3 steps 1-4): the end points, the
    // midpoint, and the crossings strictly inside the edge (a crossing at
    // 0, 1/2 or 1 adds nothing), sorted.
    cr.count = 0;
    if (rule == Integration::kPaperBisector) {
      if (use_cp)
        for (int r = 0; r < rays_cp.count; ++r) cr.add(lines_cp.crossing(rays_cp.b[r]));
      if (use_tp)
        for (int r = 0; r < rays_tp.count; ++r) cr.add(lines_tp.crossing(rays_tp.b[r]));
    } else {
      auto add = [&cr](double t) { cr.add(t); };
      if (use_cp) add_envelope_breaks(lines_cp, add);
      if (use_tp) add_envelope_breaks(lines_tp, add);
    }
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
    const std::uint32_t bit_a = std::uint32_t{1} << e, bit_b = std::uint32_t{1} << e1;
    const double f_start = traction(use_cp && !(zero_cp & bit_a) ? lines_cp.at_start() : 0.0,
                                    use_tp && !(zero_tp & bit_a) ? lines_tp.at_start() : 0.0);
    const double f_mid = traction(use_cp ? mid_cp : 0.0, use_tp ? mid_tp : 0.0);
    const double f_end = traction(use_cp && !(zero_cp & bit_b) ? lines_cp.at(1.0) : 0.0,
                                  use_tp && !(zero_tp & bit_b) ? lines_tp.at(1.0) : 0.0);
    // Eqs. 16-17 on each segment [t0, t1] with end tractions fa, fb. Along
    // one edge all segments share the normal n, so only two sums are kept:
    //   S0 = sum (t1 - t0) (fa + fb)                      -> force  L S0 / 2,
    //   S1 = sum (t1 - t0) [fa (2 t0 + t1) + fb (t0 + 2 t1)] -> int f t dl = L S1 / 6.
    // The edge's force L S0 / 2 n acts at a + (S1 / 3 S0) (b - a) (Eq. 17);
    // its moment about c is taken as L [S0 / 2 a + S1 / 6 (b - a)] x n,
    // which stays finite when S0 = 0.
    double s0 = 0.0, s1 = 0.0, t0 = 0.0, fa = f_start;
    auto segment_to = [&](double t1, double fb) {
      const double dt = t1 - t0;
      s0 += dt * (fa + fb);
      s1 += dt * (fa * (2.0 * t0 + t1) + fb * (t0 + 2.0 * t1));
      ++out.segments;
      t0 = t1;
      fa = fb;
    };
    auto crossings_below = [&](int& i, double below) {
      for (; i < cr.count && cr.t[static_cast<std::size_t>(i)] < below; ++i) {
        const double t = cr.t[static_cast<std::size_t>(i)];
        if (t != t0) segment_to(t, traction_at(t));  // two rays, one point: once
      }
    };
    int next = 0;
    crossings_below(next, 0.5);
    segment_to(0.5, f_mid);
    crossings_below(next, 1.0);
    segment_to(1.0, f_end);
    const Vec2 n = ip.normal(e);
    force += (0.5 * len * s0) * n;
    moment += cross((0.5 * len * s0) * (a - c) + (len * s1 * kSixth) * ab, n);
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

}  // namespace

NormalForce normal_contact_force(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip,
                                 Integration rule, double tol, const IpEdge* source) {
  if (cp.poly->count == 4 && tp.poly->count == 4) return contact_force_n<4, 4>(cp, tp, ip, rule, tol, source);
  return contact_force_n<0, 0>(cp, tp, ip, rule, tol, source);
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
  // area * phi(cell centroid). Each cell is cut from the region in two
  // small ping-pong rings (not Polygon copies: no normals are needed).
  const Polygon& p = *side.poly;
  const double snap = tol * 1e-3;  // a vertex this close to a cell line is on it
  double total = 0.0;
  std::array<Vec2, kMaxVertices> ring[2];  // left uninitialised: counts say how many are set
  std::array<double, kMaxVertices> d;
  for (int i = 0; i < p.count; ++i) {
    const Vec2 ni = p.normal(i);
    const double ci = dot(ni, p.vertex(i));
    const Vec2* cell = region.v.data();
    int count = region.count, next = 0;
    for (int j = 0; j < p.count && count >= 3; ++j) {
      if (j == i) continue;
      const Vec2 nj = p.normal(j);
      const Vec2 normal = nj - ni;
      const double offset = dot(nj, p.vertex(j)) - ci;
      for (int k = 0; k < count; ++k) {
        double dk = dot(normal, cell[k]) - offset;
        if (std::fabs(dk) <= snap) dk = 0.0;
        d[static_cast<std::size_t>(k)] = dk;
      }
      count = clip_ring(cell, d.data(), count, ring[next].data());
      if (count < 3) count = 0;
      cell = ring[next].data();
      next = 1 - next;
    }
    if (count < 3) continue;
    const AreaMoments m = area_centroid(cell, count);
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
