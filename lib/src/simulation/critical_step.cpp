// Bounds on the critical time step of velocity Verlet, 2 / omega_max: before
// any contact (predict_critical_step) and for the current contacts
// (critical_time_step); see simulation.hpp.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "simulation/internal.hpp"

namespace dda {

double Engine::block_strain_omega2(int i) const {
  // Generalised eigenproblem K x = w^2 M x on (r, ex, ey, gxy); K has the
  // elastic block S D on the strains and nothing on the rotation.
  if (!strains_) return 0.0;
  const Mat6 m = mass_matrix(moments_[i], density_[i]);
  Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
  k.bottomRightCorner<3, 3>() = moments_[i].area * elastic(i);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> es(k, m.bottomRightCorner<4, 4>(), Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

namespace {

// Point compliance of a block: the largest displacement per unit force of a
// point of the block loaded there, max over p of lambda_max(T(p) M^-1 T(p)^T)
// (Eqs. 1-3, 5a). It is a convex function of p, so the maximum is at a
// vertex. Without strains M acts on (u, v, r) only. A contact of stiffness k
// anywhere on the block adds at most k times this to omega^2.
double point_compliance(PolygonView poly, const AreaMoments& m, double density, bool strains) {
  const Mat6 mm = mass_matrix(m, density);
  Mat6 inv = Mat6::Zero();
  if (strains) {
    inv = mm.ldlt().solve(Mat6::Identity());
  } else {
    inv(0, 0) = 1.0 / mm(0, 0);
    inv(1, 1) = 1.0 / mm(1, 1);
    inv(2, 2) = 1.0 / mm(2, 2);
  }
  double c = 0.0;
  for (int v = 0; v < poly.count; ++v) {
    const double xt = poly.v[v].x - m.centroid.x, yt = poly.v[v].y - m.centroid.y;
    Eigen::Matrix<double, 2, 6> t;
    t << 1.0, 0.0, -yt, xt, 0.0, 0.5 * yt, 0.0, 1.0, xt, 0.0, yt, 0.5 * xt;
    const Eigen::Matrix2d a = t * inv * t.transpose();
    const double mean = 0.5 * (a(0, 0) + a(1, 1)), half = 0.5 * (a(0, 0) - a(1, 1));
    c = std::max(c, mean + std::sqrt(half * half + a(0, 1) * a(0, 1)));
  }
  return c;
}

}  // namespace

void Engine::predict_critical_step() {
  // Before any contact: each block pressed along its longest edge L by a
  // block with the smallest H of the assembly, k = kn L (1/H_i + 1/H_min)
  // (+ kt with friction), at the block's most compliant point: omega^2 <=
  // k c_i, twice that if the partner may be a free block as compliant as
  // this one (more than one free block), plus the block's own strain modes
  // (stiffnesses add: omega^2 of a sum <= the sum of the omega^2).
  double w2 = 0.0, h_min = DBL_MAX;
  int free_blocks = 0;
  min_inscribed_radius_ = DBL_MAX;
  for (int i = 0; i < block_count(); ++i) {
    radius_[i] = inscribed_circle(polygon_view(i)).radius;
    min_inscribed_radius_ = std::min(min_inscribed_radius_, radius_[i]);
    h_min = std::min(h_min, h_[i]);
    if (!fixed_[i]) ++free_blocks;
  }
  const double partner = free_blocks > 1 ? 2.0 : 1.0;
  const double kt = friction_ ? scene_.contact.kt : 0.0;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const double k = scene_.contact.kn * max_edge_length(polygon_view(i)) * (1.0 / h_[i] + 1.0 / h_min) + kt;
    const double c = point_compliance(polygon_view(i), moments_[i], density_[i], strains_);
    w2 = std::max(w2, partner * k * c + block_strain_omega2(i));
  }
  dt_crit_prior_ = w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
}

double Engine::critical_time_step() const {
  // Each current contact is a spring k = kn L (1/H_cp + 1/H_tp) (+ kt with
  // friction), L its length, between the two blocks. Block Gershgorin bound
  // on the largest eigenvalue of M^-1 K: omega^2 <= max over blocks i of
  // strain_i + sum over i's contacts of k (c_i + sqrt(c_i c_j)), c the point
  // compliance (0 for a fixed block).
  const std::size_t n = static_cast<std::size_t>(block_count());
  std::vector<double> comp(n, -1.0), row(n, 0.0);
  auto compliance = [&](int b) {
    if (fixed_[b]) return 0.0;
    if (comp[b] < 0.0) comp[b] = point_compliance(polygon_view(b), moments_[b], density_[b], strains_);
    return comp[b];
  };
  const double kt = friction_ ? scene_.contact.kt : 0.0;
  each_contact([&](std::size_t p, const ContactSlot& c) {
    const int cp = near_pairs_[p].i, tp = near_pairs_[p].j;
    const double k = scene_.contact.kn * c.result.ip_length * (1.0 / h_[cp] + 1.0 / h_[tp]) + kt;
    const double ca = compliance(cp), cb = compliance(tp), cross = std::sqrt(ca * cb);
    row[cp] += k * (ca + cross);
    row[tp] += k * (cb + cross);
  });
  double w2 = 0.0;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const double wi = row[i] + block_strain_omega2(i);
    if (!std::isfinite(wi)) return std::numeric_limits<double>::quiet_NaN();
    w2 = std::max(w2, wi);
  }
  return w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
}

}  // namespace dda
