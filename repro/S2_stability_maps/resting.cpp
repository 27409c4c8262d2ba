// S2, part 1: resting contacts and the empirical stability limit (resting.hpp).
#include "repro/S2_stability_maps/resting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "repro/S2_stability_maps/maps.hpp"
#include "repro/common/common.hpp"

namespace s2 {

using dda::Vec2;
using repro::format_short;

double old_prior(const dda::Simulation& sim) {
  double w2 = 0.0;
  for (int i = 0; i < sim.block_count(); ++i) {
    if (sim.fixed(i)) continue;
    const dda::Polygon& p = sim.polygon(i);
    const dda::AreaMoments m = dda::area_moments(p);
    const double rho = sim.mass(i) / m.area;
    const double k = sim.scene().contact.kn * dda::max_edge_length(p) * 2.0 / sim.potential_length(i);
    double r2 = 0.0;
    for (int v = 0; v < p.count; ++v) r2 = std::max(r2, dda::length_squared(p.vertex(v) - m.centroid));
    double ws = 0.0;
    if (sim.scene().strains) {
      const double d = sim.strain_critical_step(i);
      ws = 4.0 / (d * d);
    }
    w2 = std::max({w2, k / sim.mass(i) + k * r2 / (rho * (m.sxx + m.syy)), ws});
  }
  return w2 > 0.0 ? 2.0 / std::sqrt(w2) : std::numeric_limits<double>::infinity();
}

namespace {

// Static penetration of a flat contact of length L carrying weight w:
// kn [L d (1/H_a + 1/H_b) - d^2 / H_a] = w (see S1's resting block).
double static_pen(double kn, double w, double len, double h_a, double h_b) {
  const double s = 1.0 / h_a + 1.0 / h_b;
  return 0.5 * h_a * (len * s - std::sqrt(len * len * s * s - 4.0 * w / (kn * h_a)));
}

constexpr double kSeedVelocity = 1e-9;  // m/s, lateral: seeds the sliding mode
constexpr double kSeedSpin = 1e-9;      // rad/s: seeds the rocking mode

}  // namespace

// A 1 m square A (two_high: on a free 2 m x 1 m block on) a fixed 4 m x 0.1 m
// block, each at its static penetration. H: unified (min-max edge) or
// inscribed radius.
RestCase resting(double kn, bool inscribed, bool strains, bool two_high) {
  RestCase rc;
  dda::Scene& s = rc.scene;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = kn;
  s.contact.h_rule = inscribed ? dda::HRule::kInscribedRadius : dda::HRule::kMinMaxEdge;
  s.gravity = {0.0, -kG};
  s.strains = strains;
  s.guards.energy_check_every = 0;
  const double hu = 0.5 * (4.0 + 0.1);  // unified: (largest + smallest edge) / 2
  const double w1 = 2000.0 * kG;        // weight of the 1 m square per unit thickness
  dda::BlockSpec base;
  base.vertices = rect(-2.0, -0.1, 4.0, 0.1);
  base.fixed = true;
  s.blocks = {base};
  if (!two_high) {
    const double d = static_pen(kn, w1, 1.0, inscribed ? 0.5 : hu, inscribed ? 0.05 : hu);
    dda::BlockSpec a;
    a.vertices = rect(-0.5, -d, 1.0, 1.0);
    s.blocks.push_back(a);
    s.initial_overlap = 2.0 * d * (1.0 + 1e-9);
  } else {
    const double d1 = static_pen(kn, 3.0 * w1, 2.0, inscribed ? 0.5 : hu, inscribed ? 0.05 : hu);
    const double d2 = static_pen(kn, w1, 1.0, inscribed ? 0.5 : hu, inscribed ? 0.5 : hu);
    dda::BlockSpec l, u;
    l.vertices = rect(-1.0, -d1, 2.0, 1.0);
    u.vertices = rect(-0.5, 1.0 - d1 - d2, 1.0, 1.0);
    s.blocks.push_back(l);
    s.blocks.push_back(u);
    s.initial_overlap = 2.0 * std::max(d1, d2) * (1.0 + 1e-9);
  }
  // Every mode seeded on purpose: the symmetric rest state leaves the
  // rocking and sliding modes at exactly zero when the contact force is
  // computed without round-off asymmetry (exact normals), and an unstable
  // mode that is never excited never shows. A nudge this small cannot make
  // a stable run grow tenfold; an unstable mode (amplified ~2x per step just
  // above 2/omega) blows up from it within the run.
  for (dda::BlockSpec& b : s.blocks)
    if (!b.fixed) {
      b.velocity = {kSeedVelocity, 0.0};
      b.spin = kSeedSpin;
    }
  rc.name = std::string(two_high ? "1 m square on a free 2 m block on a fixed block" : "1 m square on a fixed block") +
            ", " + (strains ? "deformable" : "rigid") + ", " + (inscribed ? "H inscribed radius" : "H unified") +
            ", kn " + format_short(kn) + " Pa";
  return rc;
}

// Whether the resting contact is unstable at dt. Two signs: the energy
// grows tenfold (or a guard stops the run), or a contact of the rest state
// opens. A stable run stays within the seed's ~1e-9 m of rest, far inside
// the static penetration (>= 1e-6 m here), so no contact can open. Above
// the limit on stiff contacts the unstable mode lifts the block off within
// the first tenth of the run and then stays bounded (it saturates: the
// contact is open half the time), which the energy ratio alone misses.
bool unstable(dda::Scene s, double dt, int steps) {
  s.dt = dt;
  try {
    dda::Simulation sim(s);
    double early = 0.0, late = 0.0;
    std::size_t resting_contacts = 0;
    for (int k = 0; k < steps; ++k) {
      sim.step();
      if (k == 0) resting_contacts = sim.contact_count();
      if (sim.contact_count() < resting_contacts) return true;  // the rest state is lost: a contact opened
      if (k % 50 != 0) continue;
      const dda::Energy e = sim.energy();
      const double m = e.kinetic + e.strain + e.contact;
      if (k < steps / 10) early = std::max(early, m);
      if (k >= steps - steps / 10) late = std::max(late, m);
    }
    return late > 10.0 * early;
  } catch (const dda::SimulationError&) {
    return true;
  }
}

double empirical_limit(const dda::Scene& s, double guess) {
  double lo = 0.3 * guess, hi = 3.0 * guess;
  for (int it = 0; it < kBisections; ++it) {
    const double mid = std::sqrt(lo * hi);
    (unstable(s, mid, kBisectionSteps) ? hi : lo) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace s2
