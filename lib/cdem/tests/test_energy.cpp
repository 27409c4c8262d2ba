// The energy account of the CDEM model (Model::energy_account): kinetic +
// strain + gravity + the touches' loss (Eq. 5) + the loss of refining and of
// deleting patches (Sect. 5) + the rest closes on the initial energy; the
// rest (time integration, clone drift) stays within a stated tolerance.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dda/cdem/mesh.hpp"
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
  s.options.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
  s.options.strength.friction_deg = 0.0;
  return s;
}

}  // namespace

TEST_CASE("energy account of the prisms (Paper B Sect. 6) closes", "[cdem][energy]") {
  for (bool sub : {true, false}) {
    CdemOptions o;
    o.subdivision = sub;
    o.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
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
      s.options.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement's patch deletion
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
  CdemOptions inplace;
  inplace.subdivision_mode = SubdivisionMode::kInPlace;
  Model paper(two_prisms(2, inplace));
  paper.advance_to(0.34);
  const double m_node = Model(two_prisms(2)).node_mass(paper.touches().front().main_node);  // coarse lumped mass
  double previous = 0.0;
  for (int k : {8, 4, 2}) {  // rising mass
    CdemOptions o;
    o.contact_point_mass = m_node / (k * k);
    o.subdivision_mode = SubdivisionMode::kInPlace;  // contact_point_mass is an in-place option
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
  too_light.subdivision_mode = SubdivisionMode::kInPlace;
  Model m(two_prisms(2, too_light));
  CHECK_THROWS_AS(m.advance_to(0.34), dda::SceneError);
  CdemOptions coarse;
  coarse.subdivision = false;
  coarse.contact_point_mass = 100.0;
  CHECK_THROWS_AS(Model(two_prisms(2, coarse)), dda::SceneError);
}

namespace {

// B-8's bars (repro/B_8_bar_waves): two elastic bars 1 m x 0.2 m (nu = 0),
// one at 1 m/s onto the other at rest, 10 mm apart; each an ny x 5 ny mesh
// of square cells, dt = 0.3 h / c (c dt / h = 0.3) unless given.
CdemScene bars(int ny, bool subdivision, double dt = 0.0) {
  const dda::Material mat{2000.0, 1e9, 0.0};
  const double length = 1.0, width = 0.2, gap = 0.01;
  auto rect = [](double x0, double y0, double w, double h) {
    return std::vector<Vec2>{{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
  };
  CdemScene s;
  s.materials = {mat};
  const double h = width / ny;
  s.dt = dt > 0.0 ? dt : 0.3 * h / std::sqrt(mat.young / mat.density);
  CdemBlock a, b;
  a.outline = rect(-gap - length, -0.5 * width, length, width);
  a.mesh = mesh_rectangle(a.outline.front(), length, width, 5 * ny, ny);
  a.velocity = {1.0, 0.0};
  b.outline = rect(0.0, -0.5 * width, length, width);
  b.mesh = mesh_rectangle(b.outline.front(), length, width, 5 * ny, ny);
  s.blocks = {a, b};
  s.options.subdivision = subdivision;
  s.options.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
  return s;
}

struct BarRun {
  double growth = 0.0;  // max over the steps of (KE + strain - E0) / E0
  bool clones_left = true;
  std::size_t touches = 0;
};

// Until t_end (contact from 0.01 s for 2 L / c = 2.83 ms).
BarRun run_bars(const CdemScene& s, double t_end) {
  Model m(s);
  const double e0 = m.energy().kinetic + m.energy().strain;
  BarRun r;
  while (m.time() < t_end) {
    m.step();
    const CdemEnergy e = m.energy();
    r.growth = std::max(r.growth, (e.kinetic + e.strain - e0) / e0);
  }
  r.clones_left = !m.clones().empty();
  r.touches = m.touches().size();
  return r;
}

// "Never grows": above round-off of E0 (the clone projections only remove
// energy; explicit integration of the bars keeps it to round-off before the
// touch and below the post-impact value after); B-8's criterion.
constexpr double kGrowthTol = 1e-9;
constexpr double kBarsEnd = 0.0135;  // s: the contact ends at about 0.0128 s

}  // namespace

// Regression (B-8): with subdivision the patch steps were cut at every touch
// (irregular leapfrog steps) and a sliding clone's friction could reverse the
// sliding at every kick; the subdivided contact face chattered and gained
// energy: ny 8 rose to 2.39 E0 (3374 touches), with the cut steps alone fixed
// still +1.5e-3; ny 1 (friction alone) +1.1e-3. Measured after both fixes:
// below 1e-14, and the bars separate.
TEST_CASE("bars head on with subdivision: the energy never grows", "[cdem][energy][subdivision]") {
  for (int ny : {1, 8}) {
    const BarRun r = run_bars(bars(ny, true), kBarsEnd);
    INFO("ny " << ny << ": growth " << r.growth << ", touches " << r.touches);
    CHECK(r.growth < kGrowthTol);
    CHECK_FALSE(r.clones_left);
  }
  // Negative control: the same measure sees the growth of a run that is
  // unstable on purpose (dt 1.2 x the mesh's critical step, no subdivision).
  CdemScene bad = bars(1, false);
  bad.dt = 1.2 * Model(bad).critical_dt();
  bad.options.check_stability = false;
  BarRun r;
  try {
    r = run_bars(bad, 0.005);
  } catch (const dda::SimulationError&) {
    r.growth = std::numeric_limits<double>::infinity();  // grew until it broke
  }
  INFO("unstable dt: growth " << r.growth);
  CHECK(r.growth > kGrowthTol);
}
