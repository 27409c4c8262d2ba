// Unit tests of the CDEM two-scale contact model (Paper B): time of impact,
// clone-node momentum and energy (Eqs. 4-5), separation criteria (Eqs. 6-10),
// local subdivision bookkeeping, stability check.
#include <catch2/catch.hpp>
#include <cmath>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

std::vector<Vec2> square(double x0, double y0, double s) {
  return {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
}

// Two 1 m squares, A moving with `velocity` toward B at rest, `gap` apart in x.
CdemScene squares(double gap, Vec2 velocity, bool subdivision, double dt = 1e-4, int divisions = 2) {
  CdemScene s;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.dt = dt;
  CdemBlock a, b;
  a.outline = square(-1.0 - gap, -0.5, 1.0);
  a.divisions = divisions;
  a.velocity = velocity;
  b.outline = square(0.0, -0.5, 1.0);
  b.divisions = divisions;
  s.blocks = {a, b};
  s.options.subdivision = subdivision;
  s.options.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
  return s;
}

void run_until(Model& m, double t) {
  while (m.time() < t - 1e-12) m.step();
}

}  // namespace

TEST_CASE("straight approach: the touch time is distance / speed, inside its step", "[cdem][touch]") {
  for (bool sub : {false, true}) {
    const double gap = 0.123456, speed = 1.7;
    Model m(squares(gap, {speed, 0.0}, sub));
    run_until(m, 0.1);
    REQUIRE_FALSE(m.touches().empty());
    const TouchRecord& t = m.touches().front();
    const double expected = gap / speed;
    CHECK(t.time == Approx(expected).margin(1e-12));
    CHECK(t.step_start <= t.time);
    CHECK(t.time <= t.step_end);
    CHECK(t.dt1 + t.dt2 == Approx(m.dt()).margin(1e-15));
    CHECK(t.dt1 == Approx(expected - t.step_start).margin(1e-12));
    CHECK(t.node_to_node);  // aligned face nodes
    CHECK(t.subdivision == (sub ? t.subdivision : 0));
    if (sub) CHECK(t.subdivision >= 2);
  }
}

TEST_CASE("node to an edge interior: touch time and the tie weights", "[cdem][touch]") {
  CdemScene s;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.dt = 1e-4;
  CdemBlock tri, sq;
  tri.outline = {{-1.0, -0.4}, {-0.3, 0.1}, {-1.0, 0.6}};  // apex at (-0.3, 0.1)
  tri.divisions = 2;
  tri.velocity = {2.0, 0.0};
  sq.outline = square(0.0, -0.5, 1.0);
  sq.divisions = 2;  // face nodes at y = -0.5, 0, 0.5: y = 0.1 is inside an edge
  s.blocks = {tri, sq};
  s.options.subdivision = false;
  Model m(s);
  run_until(m, 0.16);
  REQUIRE_FALSE(m.touches().empty());
  const TouchRecord& t = m.touches().front();
  CHECK(t.time == Approx(0.3 / 2.0).margin(1e-12));
  CHECK_FALSE(t.node_to_node);
  CHECK(t.point.y == Approx(0.1).margin(1e-9));
  // Eq. 4 with the edge point's effective mass: the clone takes the
  // momentum-weighted velocity; Eq. 5 gives the loss.
  const double mu = 1.0 / (1.0 / t.mass_main + 1.0 / t.mass_target);
  CHECK(t.energy_loss_eq5 == Approx(0.5 * mu * std::pow(t.v_main.x - t.v_target.x, 2)).epsilon(1e-12));
  CHECK(t.energy_loss == Approx(t.energy_loss_eq5).epsilon(1e-9));
}

TEST_CASE("clone node: Eq. 4 velocity, Eq. 5 loss, momentum conserved through impact and separation", "[cdem][clone]") {
  for (bool sub : {false, true}) {
    CdemOptions o;
    o.subdivision = sub;
    o.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
    Model m(two_prisms(2, o));
    const Vec2 p0 = m.momentum();
    const double e0 = m.energy().total();
    double worst = 0.0;
    while (m.time() < 0.36) {
      m.step();
      worst = std::max(worst, length(m.momentum() - p0) / length(p0));
    }
    INFO("subdivision " << sub);
    CHECK(worst < 1e-12);
    REQUIRE_FALSE(m.touches().empty());
    const TouchRecord& t = m.touches().front();
    CHECK(t.time == Approx(1.0 / 3.0).margin(1e-12));
    REQUIRE(t.node_to_node);
    const Vec2 vc = (t.mass_main * t.v_main + t.mass_target * t.v_target) / (t.mass_main + t.mass_target);
    CHECK(t.v_clone.x == Approx(vc.x).margin(1e-12));
    CHECK(t.v_clone.y == Approx(vc.y).margin(1e-12));
    const double de =
        0.5 * t.mass_main * t.mass_target / (t.mass_main + t.mass_target) * dda::length_squared(t.v_main - t.v_target);
    CHECK(t.energy_loss_eq5 == Approx(de).epsilon(1e-12));
    CHECK(t.energy_loss == Approx(de).epsilon(1e-9));
    // the clone separated (tension, sigma_t = 0) and block j leaves near i's initial speed
    REQUIRE_FALSE(m.separations().empty());
    CHECK(m.separations().front().criterion == SeparationCriterion::kTension);
    CHECK(m.clones().empty());
    CHECK(m.block_velocity(1).x > 2.7);
    CHECK(m.block_velocity(0).x < 0.3);
    // energy accounted: impact loss + patch remaps + O(dt^2) integration error
    const double e1 = m.energy().total();
    CHECK(e1 < e0);
    CHECK(std::fabs(e0 - e1 - m.impact_energy_loss() - (-m.remap_energy_change())) < 0.01 * e0);
    // subdivision: the patch is deleted after separation, masses restored
    CHECK(m.active_elements(true) == 0);
    CHECK(m.block_mass(0) == Approx(2700.0 * 24.5).epsilon(1e-12));
    CHECK(m.block_mass(1) == Approx(2700.0 * 24.5).epsilon(1e-12));
  }
}

TEST_CASE("subdivision shrinks the clone masses and the Eq. 5 loss", "[cdem][subdivision]") {
  CdemOptions coarse, fine;
  coarse.subdivision = false;
  fine.subdivision = true;
  fine.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
  Model a(two_prisms(2, coarse)), b(two_prisms(2, fine));
  run_until(a, 0.334);
  run_until(b, 0.334);
  REQUIRE(a.touches().size() == 1);
  REQUIRE(b.touches().size() == 1);
  const TouchRecord& ta = a.touches().front();
  const TouchRecord& tb = b.touches().front();
  CHECK(tb.subdivision >= 2);
  CHECK(tb.radius == Approx(std::sqrt(40e9 / 2700.0) * tb.dt2).epsilon(1e-12));
  CHECK(tb.mass_main < ta.mass_main / 10.0);
  CHECK(tb.energy_loss < ta.energy_loss / 10.0);
  CHECK(b.active_elements(true) > 0);
}

TEST_CASE("separation in tension follows Eq. 6", "[cdem][separation]") {
  // sigma_t = 0: the clone separates as soon as the interaction force pulls;
  // a huge sigma_t keeps the blocks tied (plastic impact, common velocity).
  for (double sigma_t : {0.0, 1e15}) {
    CdemOptions o;
    o.subdivision = false;
    o.strength.tensile = sigma_t;
    Model m(two_prisms(2, o));
    run_until(m, 0.40);
    INFO("sigma_t " << sigma_t);
    for (const SeparationRecord& r : m.separations()) {
      if (r.criterion != SeparationCriterion::kTension) continue;
      CHECK(r.normal_force < 0.0);
      CHECK(-r.normal_force > r.limit);
      CHECK(r.limit == Approx(sigma_t * r.contact_area));
    }
    if (sigma_t == 0.0) {
      CHECK(m.clones().empty());
      CHECK(m.separations().size() >= 1);
    } else {
      CHECK(m.separations().empty());
      REQUIRE(m.clones().size() == 1);
      // still tied: the apex and the touched node move as one node, and the
      // blocks oscillate about their common velocity instead of parting
      const CloneView c = m.clones().front();
      CHECK(dda::distance(m.node_position(c.main_node), m.node_position(c.target[0])) < 1e-9);
      CHECK(dda::length(m.node_velocity(c.main_node) - m.node_velocity(c.target[0])) < 1e-9);
      CHECK(0.5 * (m.block_velocity(0).x + m.block_velocity(1).x) == Approx(1.5).epsilon(1e-12));
    }
  }
}

TEST_CASE("slip in shear follows Eqs. 7-10", "[cdem][separation]") {
  // An oblique impact: A slides along B's face while it hits it. With no
  // friction and no cohesion any shear makes the clone slide (Eq. 10); with
  // a huge cohesion no clone slides.
  for (double cohesion : {0.0, 1e15}) {
    for (bool sub : {false, true}) {
      CdemScene s = squares(0.01, {1.0, 0.8}, sub);
      s.options.strength.friction_deg = 0.0;
      s.options.strength.cohesion = cohesion;
      Model m(s);
      run_until(m, 0.02);
      INFO("cohesion " << cohesion << " subdivision " << sub);
      REQUIRE_FALSE(m.touches().empty());
      int shear = 0;
      for (const SeparationRecord& r : m.slips()) {
        REQUIRE(r.criterion == SeparationCriterion::kShear);
        ++shear;
        CHECK(std::fabs(r.shear_force) > r.limit);
        CHECK(r.limit == Approx(std::max(r.normal_force, 0.0) * 0.0 + cohesion * r.contact_area));
      }
      if (cohesion == 0.0)
        CHECK(shear > 0);
      else
        CHECK(shear == 0);
    }
  }
}

TEST_CASE("a time step above the mesh's critical step is refused", "[cdem][stability]") {
  CdemScene s = two_prisms(2);
  const double crit = Model(s).critical_dt();
  CHECK(crit > s.dt);
  CHECK(crit < 1.2 * 7.0 / std::sqrt(40e9 / 2700.0));
  s.dt = 1.5 * crit;
  CHECK_THROWS_AS(Model(s), dda::SceneError);
  s.options.check_stability = false;
  CHECK_NOTHROW(Model(s));
}

TEST_CASE("scene errors name the field", "[cdem][scene]") {
  CdemScene s = two_prisms(2);
  s.blocks[1].outline = {{0, 0}, {0, 1}, {1, 0}};  // clockwise
  CHECK_THROWS_WITH(Model(s), Catch::Contains("blocks[1].outline"));
  s = two_prisms(2);
  s.options.tolerance = 0.0;
  CHECK_THROWS_WITH(Model(s), Catch::Contains("tolerance"));
}

TEST_CASE("a block's own mesh: used as given, checked against its outline", "[cdem][scene]") {
  CdemScene s = squares(0.5, {1.0, 0.0}, true);
  for (CdemBlock& b : s.blocks) b.mesh = mesh_rectangle(b.outline.front(), 1.0, 1.0, 3, 3);
  const Model m(s);
  CHECK(m.node_count() == 2 * 16);
  CHECK(m.block_mass(0) == Approx(2000.0).epsilon(1e-12));
  s.blocks[1].mesh.nodes[0].x += 0.1;  // not the outline's first vertex
  CHECK_THROWS_WITH(Model(s), Catch::Contains("blocks[1].mesh.nodes[0]"));
  s.blocks[1].mesh = mesh_rectangle(s.blocks[1].outline.front(), 1.0, 1.0, 3, 3);
  s.blocks[1].mesh.triangles.push_back(s.blocks[1].mesh.triangles.front());  // an edge in three triangles
  CHECK_THROWS_WITH(Model(s), Catch::Contains("blocks[1].mesh"));
}
