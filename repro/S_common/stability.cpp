#include "repro/S_common/stability.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dda/block.hpp"
#include "dda/contact.hpp"
#include "dda/overlap.hpp"

namespace repro::stab {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Order observed_order(const std::vector<double>& dt, const std::vector<double>& err, double floor, int points) {
  if (dt.size() != err.size()) throw std::invalid_argument("observed_order: dt and err differ in length");
  std::vector<std::size_t> idx(dt.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return dt[a] < dt[b]; });
  std::vector<double> x, y;
  bool below_floor = false;
  for (std::size_t i : idx) {
    if (!(err[i] >= 0.0) || !std::isfinite(err[i])) continue;  // failed run
    if (err[i] <= floor) {
      below_floor = true;
      continue;
    }
    x.push_back(std::log(dt[i]));
    y.push_back(std::log(err[i]));
    if (static_cast<int>(x.size()) == points) break;
  }
  Order o;
  o.used = static_cast<int>(x.size());
  if (o.used < 2) {
    o.p = std::numeric_limits<double>::quiet_NaN();
    o.note = below_floor ? "round-off" : "too few points";
    return o;
  }
  double mx = 0.0, my = 0.0;
  for (int i = 0; i < o.used; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= o.used;
  my /= o.used;
  double sxy = 0.0, sxx = 0.0;
  for (int i = 0; i < o.used; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  o.p = sxy / sxx;
  o.dt_lo = std::exp(x.front());
  o.dt_hi = std::exp(x.back());
  const auto [ylo, yhi] = std::minmax_element(y.begin(), y.end());
  if (o.dt_hi >= 4.0 * o.dt_lo && *yhi - *ylo < std::log(1.5)) o.note = "plateau";
  return o;
}

std::vector<double> vertex_state(const dda::Simulation& sim) {
  std::vector<double> s;
  for (int i = 0; i < sim.scene_block_count(); ++i) {
    if (sim.fixed(i)) continue;
    const dda::Polygon& p = sim.polygon(i);
    for (int k = 0; k < p.count; ++k) {
      s.push_back(p.vertex(k).x);
      s.push_back(p.vertex(k).y);
    }
  }
  return s;
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("max_abs_difference: sizes differ");
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

namespace {

struct Dofs {
  std::vector<int> base;  // first DOF of block i, -1 if fixed
  int per_block = 6;
  int total = 0;
};

// Generalized contact forces of every pair at the configuration `poly`
// (the solver's moved polygons), in the solver's pair order (cp < tp).
Eigen::VectorXd contact_forces(const dda::Simulation& sim, const std::vector<dda::Polygon>& poly, const Dofs& dofs,
                               int* contacts) {
  const dda::ContactParams& c = sim.scene().contact;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.total);
  const int n = sim.block_count();
  int count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (dofs.base[i] < 0 && dofs.base[j] < 0) continue;
      const dda::Polygon& a = poly[i];
      const dda::Polygon& b = poly[j];
      if (!dda::aabb_overlap(dda::bounds(a), dda::bounds(b))) continue;
      const double tol = dda::pair_tolerance(a, b);
      if (dda::overlap_state(a, b, tol) != dda::OverlapState::kOverlapping) continue;
      const dda::Polygon ip = dda::intersection_polygon(a, b, tol);
      if (ip.count < 3) continue;
      const double ha = sim.potential_length(i), hb = sim.potential_length(j);
      const dda::PotentialSide sa{a, c.kn / ha, c.small_edge_fraction * ha};
      const dda::PotentialSide sb{b, c.kn / hb, c.small_edge_fraction * hb};
      const dda::NormalForce nf = dda::normal_contact_force(sa, sb, ip, c.integration, tol);
      if (!nf.valid) continue;
      ++count;
      auto load = [&](int blk, double sign) {
        if (dofs.base[blk] < 0) return;
        const dda::Vec6 g = dda::point_load(dda::area_moments(poly[blk]).centroid, nf.point, sign * nf.force);
        for (int k = 0; k < dofs.per_block; ++k) f[dofs.base[blk] + k] += g[k];
      };
      load(i, 1.0);
      load(j, -1.0);
    }
  if (contacts) *contacts = count;
  return f;
}

}  // namespace

Linearized linearized_critical_step(const dda::Simulation& sim) {
  const int n = sim.block_count();
  const bool strains = sim.scene().strains;
  Dofs dofs;
  dofs.per_block = strains ? 6 : 3;
  dofs.base.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i)
    if (!sim.fixed(i)) {
      dofs.base[i] = dofs.total;
      dofs.total += dofs.per_block;
    }
  Linearized out;
  out.dofs = dofs.total;
  if (dofs.total == 0) {
    out.dt_crit = std::numeric_limits<double>::infinity();
    return out;
  }
  std::vector<dda::Polygon> poly0(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) poly0[i] = sim.polygon(i);

  // Mass matrix and strain stiffness, block diagonal.
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(dofs.total, dofs.total);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(dofs.total, dofs.total);
  for (int i = 0; i < n; ++i) {
    const int b = dofs.base[i];
    if (b < 0) continue;
    const dda::AreaMoments am = dda::area_moments(poly0[i]);
    const double density = sim.mass(i) / am.area;
    const dda::Mat6 mm = dda::mass_matrix(am, density);
    if (strains) {
      m.block(b, b, 6, 6) = mm;
      const dda::Material& mat = sim.scene().materials[static_cast<std::size_t>(sim.material(i))];
      k.block(b + 3, b + 3, 3, 3) = am.area * dda::elastic_matrix(mat.young, mat.poisson);
    } else {
      m(b, b) = m(b + 1, b + 1) = mm(0, 0);
      m(b + 2, b + 2) = mm(2, 2);
    }
  }

  // Contact stiffness by central differences of the generalized forces.
  auto perturbed = [&](int dof, double h) {
    std::vector<dda::Polygon> p = poly0;
    for (int i = 0; i < n; ++i) {
      const int b = dofs.base[i];
      if (b < 0 || dof < b || dof >= b + dofs.per_block) continue;
      dda::Vec6 d = dda::Vec6::Zero();
      d[dof - b] = h;
      const dda::Vec2 c = dda::area_moments(poly0[i]).centroid;
      for (int v = 0; v < p[i].count; ++v) p[i].v[v] = poly0[i].v[v] + dda::point_displacement(c, poly0[i].v[v], d);
      dda::update_normals(p[i]);
    }
    return p;
  };
  int contacts = 0;
  contact_forces(sim, poly0, dofs, &contacts);
  out.contacts = contacts;
  if (contacts > 0) {
    for (int dof = 0; dof < dofs.total; ++dof) {
      int blk = 0;
      while (dofs.base[blk] < 0 || dof >= dofs.base[blk] + dofs.per_block) ++blk;
      const int local = dof - dofs.base[blk];
      // Step: 1e-8 of the block's size for translations and rotation (as a
      // displacement), 1e-8 for strains.
      const double size = dda::diameter(poly0[blk]);
      const double h = local < 2 ? 1e-8 * size : (local == 2 ? 1e-8 : 1e-8);
      const Eigen::VectorXd fp = contact_forces(sim, perturbed(dof, h), dofs, nullptr);
      const Eigen::VectorXd fm = contact_forces(sim, perturbed(dof, -h), dofs, nullptr);
      k.col(dof) -= (fp - fm) / (2.0 * h);
    }
    // Friction in its stick state: a spring kt on the relative tangential
    // displacement of the loading point.
    const dda::ContactParams& c = sim.scene().contact;
    if (c.kt > 0.0) {
      for (const dda::ContactInfo& ci : sim.contacts()) {
        const double fn = dda::length(ci.normal_force);
        if (!(fn > 0.0)) continue;
        const dda::Vec2 nrm = ci.normal_force / fn;
        const dda::Vec2 t = dda::perp_left(nrm);
        Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs.total);
        auto add = [&](int blk, double sign) {
          if (dofs.base[blk] < 0) return;
          const dda::Vec6 gl = dda::point_load(sim.centroid(blk), ci.point, sign * t);
          for (int q = 0; q < dofs.per_block; ++q) g[dofs.base[blk] + q] += gl[q];
        };
        add(ci.cp, 1.0);
        add(ci.tp, -1.0);
        k += c.kt * g * g.transpose();
      }
    }
  }
  const Eigen::MatrixXd ks = 0.5 * (k + k.transpose());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(ks, m, Eigen::EigenvaluesOnly);
  const double w2 = es.eigenvalues().maxCoeff();
  out.omega_max = w2 > 0.0 ? std::sqrt(w2) : 0.0;
  out.dt_crit = w2 > 0.0 ? 2.0 / out.omega_max : std::numeric_limits<double>::infinity();
  return out;
}

const char* class_name(RunClass c) {
  // In RunClass's order.
  static const char* const kNames[] = {"stable", "energy growth > 1%", "flip-through", "blow-up"};
  const auto i = static_cast<std::size_t>(c);
  return i < sizeof(kNames) / sizeof(kNames[0]) ? kNames[i] : "?";
}

bool deep_penetration(const dda::Polygon& a, const dda::Polygon& b) {
  const double tol = dda::pair_tolerance(a, b);
  if (dda::overlap_state(a, b, tol) != dda::OverlapState::kOverlapping) return false;
  const dda::Polygon ip = dda::intersection_polygon(a, b, tol);
  if (ip.count < 3) return false;
  return dda::locate_point(ip, dda::centroid(a)) != dda::PointLocation::kOutside ||
         dda::locate_point(ip, dda::centroid(b)) != dda::PointLocation::kOutside;
}

}  // namespace repro::stab
