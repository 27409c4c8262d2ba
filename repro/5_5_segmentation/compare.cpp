// The 5.5 driver's comparison of one configuration (the paper's segmentation
// under both small-edge readings against the exact integration), the error
// statistics and the rectangle case (segmentation.hpp).
#include <algorithm>
#include <cmath>

#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/common.hpp"

namespace segmentation {

using dda::Integration;
using dda::NormalForce;
using dda::Polygon;
using dda::PotentialSide;
using dda::Vec2;
using repro::format_short;

Errors compare(const Polygon& a, double kn_h_a, double small_a, const Polygon& b, double kn_h_b, double small_b) {
  Errors e;
  const double tol = dda::pair_tolerance(a, b);
  const Polygon ip = dda::intersection_polygon(a, b, tol);
  if (ip.count < 3) return e;
  PotentialSide sa{a, kn_h_a, small_a}, sb{b, kn_h_b, small_b};
  const NormalForce fe = dda::normal_contact_force(sa, sb, ip, Integration::kExactEnvelope, tol);
  const double fe_len = dda::length(fe.force), dia = dda::diameter(ip);
  if (!fe.valid || !(fe_len > 0.0)) return e;
  for (std::size_t m = 0; m < kModes.size(); ++m) {
    sa.small_edge_rays = sb.small_edge_rays = kModes[m];
    const NormalForce fp = dda::normal_contact_force(sa, sb, ip, Integration::kPaperBisector, tol);
    if (!fp.valid) return e;
    e.mode[m].force = dda::length(fp.force - fe.force) / fe_len;
    e.mode[m].point = dda::distance(fp.point, fe.point) / dia;
  }
  e.valid = true;
  const double r = std::min(dda::inscribed_circle(a).radius, dda::inscribed_circle(b).radius);
  e.depth_ratio = 2.0 * dda::inscribed_circle(ip).radius / (2.0 * r);
  return e;
}

// ---- ModeStats ---------------------------------------------------------------------

void ModeStats::add(const ModeError& m) {
  ++n;
  nonzero += m.force > kExactTolerance ? 1 : 0;
  max_force = std::max(max_force, m.force);
  max_point = std::max(max_point, m.point);
  force_errors.push_back(m.force);
}

double ModeStats::nonzero_percent() const {
  return n ? 100.0 * static_cast<double>(nonzero) / static_cast<double>(n) : 0.0;
}

double ModeStats::percentile(double q) const {
  if (force_errors.empty()) return 0.0;
  std::vector<double> v = force_errors;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

bool ModeStats::same_as(const ModeStats& o) const { return force_errors == o.force_errors && max_point == o.max_point; }

std::string ModeStats::describe() const {
  return format_short(nonzero_percent(), 3) + " % with a force error > 1e-8 (above round-off); relative force error max " +
         format_short(max_force, 3) + ", median " + format_short(percentile(0.5), 3) + ", 99th percentile " +
         format_short(percentile(0.99), 3) + "; loading point error max " + format_short(max_point, 3) +
         " of the IP diameter";
}

std::string ModeStats::brief() const {
  return format_short(nonzero_percent(), 3) + " % with a force error > 1e-8, median " + format_short(percentile(0.5), 3) +
         ", max " + format_short(max_force, 3) + ", loading point error max " + format_short(max_point, 3) +
         " of the IP diameter";
}

// ---- 4. the rectangle's middle segment ------------------------------------------

Errors rectangle_case(double depth) {
  const Vec2 r[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const Polygon tp = dda::make_polygon(r, 4);
  const double s = 0.5 * std::sqrt(2.0);
  const Vec2 q[4] = {{1.0, 1.0 - depth}, {1.0 + s, 1.0 - depth + s}, {1.0, 1.0 - depth + 2 * s}, {1.0 - s, 1.0 - depth + s}};
  const Polygon cp = dda::make_polygon(q, 4);
  return compare(cp, 1.0, 0.0, tp, 1.0, 0.0);  // no small edges: both readings are the same rays
}

}  // namespace segmentation
