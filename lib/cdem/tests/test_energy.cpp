// The energy account of the CDEM model (Model::energy_account): kinetic +
// strain + gravity + the touches' loss (Eq. 5) + the loss of refining and of
// deleting patches (Sect. 5) + the rest closes on the initial energy; the
// rest (time integration, clone drift) stays within a stated tolerance.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

// Closure tolerances, as fractions of the initial energy, from the measured
// worst |other| / E0 over the run (prisms with subdivision 3.5e-3, the (5, 2)
// square impact 4.0e-3; without subdivision 1.2e-2 and 3.5e-3): the
// remainder is the explicit integration's energy error during contact.
constexpr double kClosureSubdivision = 5e-3;
constexpr double kClosureCoarse = 2e-2;

struct Worst {
  double other = 0.0;               // max |other| / E0 over the rows
  double without_deletion = 0.0;    // the same with the deletion loss left out (negative control)
  CdemEnergyAccount last;
};

Worst run_account(const CdemScene& s, double t_end) {
  Model m(s);
  Worst w;
  while (m.time() < t_end - 1e-12) {
    m.step();
    const CdemEnergyAccount a = m.energy_account();
    const double sum = a.kinetic + a.strain + a.gravity + a.touch_loss + a.refine_loss + a.deletion_loss + a.other;
    REQUIRE(sum == Approx(a.initial).epsilon(1e-12));  // the row closes by definition of `other`
    w.other = std::max(w.other, std::fabs(a.other) / a.initial);
    w.without_deletion = std::max(w.without_deletion, std::fabs(a.other + a.deletion_loss) / a.initial);
    w.last = a;
  }
  return w;
}

std::vector<Vec2> square(double x0, double y0) { return {{x0, y0}, {x0 + 1.0, y0}, {x0 + 1.0, y0 + 1.0}, {x0, y0 + 1.0}}; }

// The (5, 2) m/s square impact of test_oblique.cpp, frictionless.
CdemScene oblique_squares(bool subdivision = true) {
  CdemScene s;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.dt = 1e-4;
  CdemBlock a, b;
  a.outline = square(-1.05, -0.5);
  a.divisions = 2;
  a.velocity = {5.0, 2.0};
  b.outline = square(0.0, -0.5);
  b.divisions = 2;
  s.blocks = {a, b};
  s.options.subdivision = subdivision;
  s.options.strength.friction_deg = 0.0;
  return s;
}

}  // namespace

TEST_CASE("energy account of the prisms (Paper B Sect. 6) closes", "[cdem][energy]") {
  for (bool sub : {true, false}) {
    CdemOptions o;
    o.subdivision = sub;
    const Worst w = run_account(two_prisms(2, o), 0.5);
    INFO("subdivision " << sub << " worst |other|/E0 " << w.other << " touch " << w.last.touch_loss << " deletion "
                        << w.last.deletion_loss);
    CHECK(w.other <= (sub ? kClosureSubdivision : kClosureCoarse));
    CHECK(w.last.touch_loss == Approx(w.last.touch_loss_eq5).epsilon(1e-6));  // one touch: measured = Eq. 5
    if (sub) {
      // the patch deletion's loss, reported as measured (2.64 kJ/m, about
      // five times the touch's): leaving it out breaks the closure
      CHECK(w.last.deletion_loss > 4.0 * w.last.touch_loss);
      CHECK(w.without_deletion > kClosureSubdivision);
    } else {
      CHECK(w.last.deletion_loss == 0.0);
    }
  }
}

TEST_CASE("energy account of an oblique square impact closes", "[cdem][energy]") {
  for (bool sub : {true, false}) {
    const CdemScene s = oblique_squares(sub);
    const Worst w = run_account(s, 0.03);
    INFO("subdivision " << sub << " worst |other|/E0 " << w.other);
    CHECK(w.other <= (sub ? kClosureSubdivision : kClosureCoarse));
    if (sub) CHECK(w.without_deletion > kClosureSubdivision);
  }
}

// PatchDeletion::kEnergyMatched (beyond Paper B Sect. 5): the energy the
// restriction drops is handed to the coarse velocity deviations and stresses.
// Measured: prisms 2636.5 -> 47.6 J/m, the (5, 2) m/s square impact 1091.9 ->
// 4.7 J/m; what is left is where a scaling factor reached its cap.
constexpr double kMatchedDeletionFraction = 0.05;  // option's loss / default loss: 'reduced' means 20 x smaller

TEST_CASE("energy-matched patch deletion keeps the energy the restriction drops", "[cdem][energy]") {
  for (int scene = 0; scene < 2; ++scene) {
    double loss[2] = {0.0, 0.0};
    for (PatchDeletion d : {PatchDeletion::kAtSeparation, PatchDeletion::kEnergyMatched}) {
      CdemScene s = scene == 0 ? two_prisms(2) : oblique_squares();
      s.options.patch_deletion = d;
      const double t_end = scene == 0 ? 0.5 : 0.03;
      const Worst w = run_account(s, t_end);
      Model m(s);
      const dda::Vec2 p0 = m.momentum();
      m.advance_to(t_end);
      INFO("scene " << scene << " mode " << static_cast<int>(d) << " deletion loss " << w.last.deletion_loss
                    << " worst |other|/E0 " << w.other);
      CHECK(w.other <= kClosureSubdivision);
      CHECK(dda::length(m.momentum() - p0) <= 1e-12 * dda::length(p0));  // momentum: round-off
      loss[d == PatchDeletion::kEnergyMatched] = w.last.deletion_loss;
    }
    INFO("scene " << scene << " deletion loss default " << loss[0] << ", energy-matched " << loss[1]);
    CHECK(loss[0] > 100.0);  // J/m: the default restriction loses a measurable amount
    CHECK(loss[1] >= 0.0);
    CHECK(loss[1] < kMatchedDeletionFraction * loss[0]);
  }
}

// CdemOptions::contact_point_mass (Paper B Sect. 4.1): the touch's measured
// loss is Eq. 5 with the clone's masses, and falls with them (measured: the
// prisms' touch loses 4651, 1163, 291 J/m at k = 2, 4, 8, i.e. M / k^2).
constexpr double kEq5Relative = 1e-9;  // one touch: the projection is Eq. 5 up to round-off (measured 2e-16)

TEST_CASE("contact-point mass sets the touch's loss (Eq. 5)", "[cdem][energy]") {
  Model paper(two_prisms(2));
  paper.advance_to(0.34);
  const double m_node = Model(two_prisms(2)).node_mass(paper.touches().front().main_node);  // coarse lumped mass
  double previous = 0.0;
  for (int k : {8, 4, 2}) {  // rising mass
    CdemOptions o;
    o.contact_point_mass = m_node / (k * k);
    o.max_subdivision = 8;
    Model m(two_prisms(2, o));
    m.advance_to(0.34);
    REQUIRE_FALSE(m.touches().empty());
    const TouchRecord& t = m.touches().front();
    INFO("k " << k << " masses " << t.mass_main << " / " << t.mass_target << " loss " << t.energy_loss);
    CHECK(t.subdivision == k);
    CHECK(t.mass_main == Approx(m_node / (k * k)).epsilon(1e-12));
    CHECK(std::fabs(t.energy_loss - t.energy_loss_eq5) <= kEq5Relative * t.energy_loss_eq5);
    CHECK(t.energy_loss > previous);
    previous = t.energy_loss;
  }
  CdemOptions too_light;
  too_light.contact_point_mass = m_node / 1000.0;  // needs k = 32 > max_subdivision 6
  Model m(two_prisms(2, too_light));
  CHECK_THROWS_AS(m.advance_to(0.34), dda::SceneError);
  CdemOptions coarse;
  coarse.subdivision = false;
  coarse.contact_point_mass = 100.0;
  CHECK_THROWS_AS(Model(two_prisms(2, coarse)), dda::SceneError);
}
