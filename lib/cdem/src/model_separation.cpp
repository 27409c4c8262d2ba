// Paper B Sect. 4.2: the interaction force of each clone node (Eq. 11) and
// the separation criteria, tension (Eq. 6) and Mohr-Coulomb shear
// (Eqs. 7-10).
#include "dda/cdem/model.hpp"

#include <cmath>

namespace dda::cdem {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

// Interaction forces of the clone nodes (Eq. 11) at the current forces f_:
// the force on each main node that gives it the acceleration of the point
// it is tied to, solved by Gauss-Seidel over coupled clones. Then the
// separation criteria: tension beyond sigma_t A_c (Eq. 6) removes the clone
// and its forces; shear beyond F_n tan(phi) + c A_c (Eqs. 7-9) limits the
// shear force to that value (Eq. 10) for this evaluation and removes the
// clone after it. The resulting forces are added to f_.
void Model::solve_clones(bool fine, double t) {
  std::vector<int> ids;
  for (int i = 0; i < static_cast<int>(clones_.size()); ++i)
    if (clones_[static_cast<std::size_t>(i)].fine == fine) ids.push_back(i);
  if (ids.empty()) return;
  std::vector<char> removed(clones_.size(), 0), limited(clones_.size(), 0);
  const double tan_phi = std::tan(opt_.strength.friction_deg * kPi / 180.0);
  for (std::size_t pass = 0; pass <= ids.size(); ++pass) {
    for (int i : ids) {
      const Clone& c = clones_[static_cast<std::size_t>(i)];
      scratch_[c.main] = inv_m_[c.main] * f_[c.main];
      for (int q = 0; q < 2; ++q)
        if (c.t[q] >= 0) scratch_[c.t[q]] = inv_m_[c.t[q]] * f_[c.t[q]];
    }
    for (int i : ids) {
      Clone& c = clones_[static_cast<std::size_t>(i)];
      if (removed[i]) continue;
      if (limited[i]) {
        scratch_[c.main] += inv_m_[c.main] * c.lambda;
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) scratch_[c.t[q]] -= (c.w[q] * inv_m_[c.t[q]]) * c.lambda;
      } else {
        c.lambda = Vec2{};
      }
    }
    for (int it = 0; it < 500; ++it) {
      double worst = 0.0, scale = 0.0;
      for (int i : ids) {
        if (removed[i] || limited[i]) continue;
        Clone& c = clones_[static_cast<std::size_t>(i)];
        Vec2 r = scratch_[c.main];
        double w = inv_m_[c.main];
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) {
            r -= c.w[q] * scratch_[c.t[q]];
            w += c.w[q] * c.w[q] * inv_m_[c.t[q]];
          }
        if (!(w > 0.0)) continue;
        const Vec2 dl = -(1.0 / w) * r;
        c.lambda += dl;
        scratch_[c.main] += inv_m_[c.main] * dl;
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) scratch_[c.t[q]] -= (c.w[q] * inv_m_[c.t[q]]) * dl;
        worst = std::max(worst, length(dl));
        scale = std::max(scale, length(c.lambda));
      }
      if (worst <= 1e-13 * scale || worst == 0.0) break;
    }
    bool changed = false;
    for (int i : ids) {
      if (removed[i] || limited[i]) continue;
      Clone& c = clones_[static_cast<std::size_t>(i)];
      const Vec2 n = clone_normal(c);
      const Vec2 u = perp_left(n);
      const double fn = dot(c.lambda, n), fs = dot(c.lambda, u);
      // Round-off guard: forces below 1e-12 E A_c are zero (a fresh clone
      // carries only round-off).
      const double noise =
          1e-12 * scene_.materials[static_cast<std::size_t>(blocks_[node_block_[c.main]].material)].young * c.area;
      SeparationRecord rec;
      rec.time = t;
      rec.main_node = c.main;
      rec.main_block = node_block_[c.main];
      rec.target_block = node_block_[c.ea];
      rec.normal_force = fn;
      rec.shear_force = fs;
      rec.contact_area = c.area;
      rec.fine = c.fine;
      if (fn < 0.0 && -fn > opt_.strength.tensile * c.area + noise) {
        rec.criterion = SeparationCriterion::kTension;
        rec.limit = opt_.strength.tensile * c.area;
        removed[i] = 1;
        c.lambda = Vec2{};
        separations_.push_back(rec);
        changed = true;
        continue;
      }
      const double fs_max = std::max(fn, 0.0) * tan_phi + opt_.strength.cohesion * c.area;
      if (std::fabs(fs) > fs_max + noise) {
        rec.criterion = SeparationCriterion::kShear;
        rec.limit = fs_max;
        limited[i] = 1;
        c.lambda = fn * n + std::copysign(fs_max, fs) * u;
        separations_.push_back(rec);
        changed = true;
      }
    }
    if (!changed) break;
  }
  for (int i : ids) {
    if (removed[i]) continue;
    const Clone& c = clones_[static_cast<std::size_t>(i)];
    f_[c.main] += c.lambda;
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0) f_[c.t[q]] -= c.w[q] * c.lambda;
  }
  std::vector<Clone> keep;
  for (std::size_t i = 0; i < clones_.size(); ++i) {
    if (removed[i] || limited[i]) {
      const Clone& c = clones_[i];
      clone_count_[c.main] -= 1;
      released_at_[c.main] = t;
      for (int q = 0; q < 2; ++q)
        if (c.t[q] >= 0) {
          clone_count_[c.t[q]] -= 1;
          released_at_[c.t[q]] = t;
        }
      continue;
    }
    keep.push_back(clones_[i]);
  }
  clones_.swap(keep);
}

}  // namespace dda::cdem
