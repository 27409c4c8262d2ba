// Unit tests of Paper B Sect. 5 as written (SubdivisionMode::kSubModel):
// the sub-model of the colliding elements, driven by the coarse nodes
// (steps 1-5, Eq. 12), on the two prisms of Sect. 6.
#include <catch2/catch.hpp>
#include <cmath>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

CdemOptions submodel_options(int min_k = 2, int max_k = 6) {
  CdemOptions o;
  o.subdivision = true;
  o.subdivision_mode = SubdivisionMode::kSubModel;
  o.min_subdivision = min_k;
  o.max_subdivision = max_k;
  return o;
}

CdemOptions coarse_options() {
  CdemOptions o;
  o.subdivision = false;
  return o;
}

// The prisms run to 0.5 s (separation at about 0.34 s).
constexpr double kEnd = 0.5;

// j's block velocity after separation: the no-subdivision run and the
// sub-model with k = 1 agree to this relative difference (the k = 1
// sub-element is its parent, integrated with n substeps of the same linear
// motion: the incremental stress differs by the geometric terms of the
// substeps, and the force sums' order differs).
constexpr double kK1Agreement = 1e-6;

}  // namespace

TEST_CASE("sub-model: the prisms run to separation, the sub-model lives from touch to separation",
          "[cdem][submodel]") {
  Model m(two_prisms(2, submodel_options()));
  bool seen_live = false;
  double first_live = -1.0;
  while (m.time() < kEnd - 1e-12) {
    m.step();
    if (m.live_submodels() > 0 && !seen_live) {
      seen_live = true;
      first_live = m.time();
    }
  }
  REQUIRE_FALSE(m.touches().empty());
  REQUIRE_FALSE(m.separations().empty());
  REQUIRE(seen_live);
  REQUIRE_FALSE(m.submodels().empty());
  const TouchRecord& t = m.touches().front();
  const SubModelRecord& r = m.submodels().front();
  CHECK(r.created == Approx(t.step_end).margin(1e-12));  // built at the end of the touch's step
  CHECK(first_live == Approx(t.step_end).margin(1e-12));
  CHECK(r.deleted >= m.separations().front().time);     // deleted once the clone separated
  CHECK(r.deleted <= m.separations().back().time + m.dt() + 1e-12);
  CHECK(m.live_submodels() == 0);
  CHECK(r.k >= 2);
  CHECK(r.elements >= 2);  // at least one element on each block
  CHECK(t.subdivision == r.k);
  CHECK(r.free_nodes > 0);
  CHECK(r.substeps_taken > 0);
  // the coarse contact: the clone's masses are the coarse lumped masses
  const Model coarse(two_prisms(2, coarse_options()));
  CHECK(t.mass_main == coarse.node_mass(t.main_node));
  // the exchange of velocities (Paper B Sect. 6): j takes most of i's speed
  CHECK(m.block_velocity(1).x > 2.0);
  CHECK(m.block_velocity(1).x < 3.0 + 1e-9);
}

TEST_CASE("sub-model: the touch time is the coarse touch time (contact at coarse nodes)", "[cdem][submodel]") {
  Model a(two_prisms(2, submodel_options())), b(two_prisms(2, coarse_options()));
  a.advance_to(0.34);
  b.advance_to(0.34);
  REQUIRE_FALSE(a.touches().empty());
  REQUIRE_FALSE(b.touches().empty());
  CHECK(a.touches().front().time == b.touches().front().time);
  CHECK(a.touches().front().main_node == b.touches().front().main_node);
  CHECK(a.touches().front().energy_loss_eq5 == b.touches().front().energy_loss_eq5);
}

TEST_CASE("sub-model: n follows the sub-elements' critical step", "[cdem][submodel]") {
  for (int k : {2, 4, 6}) {
    CdemOptions o = submodel_options(k, k);
    Model m(two_prisms(2, o));
    m.advance_to(0.34);
    REQUIRE_FALSE(m.submodels().empty());
    const SubModelRecord& r = m.submodels().front();
    INFO("k " << k << " n " << r.substeps << " sub-critical " << r.sub_critical_dt << " dt " << m.dt());
    CHECK(r.k == k);
    // dt / n <= safety * dt_sub, and n - 1 would not do
    CHECK(m.dt() / r.substeps <= o.substep_safety * r.sub_critical_dt * (1.0 + 1e-12));
    if (r.substeps > 1) CHECK(m.dt() / (r.substeps - 1) > o.substep_safety * r.sub_critical_dt);
    // the sub-elements are k times smaller: their critical step about 1/k of the coarse element bound
    CHECK(r.sub_critical_dt < m.element_critical_dt());
    CHECK(r.sub_critical_dt == Approx(m.element_critical_dt() / k).epsilon(0.5));
  }
}

TEST_CASE("sub-model with k = 1 reproduces the coarse elements (the limit of one sub-element)", "[cdem][submodel]") {
  Model a(two_prisms(2, submodel_options(1, 1))), b(two_prisms(2, coarse_options()));
  a.advance_to(kEnd);
  b.advance_to(kEnd);
  REQUIRE_FALSE(a.submodels().empty());
  CHECK(a.submodels().front().k == 1);
  CHECK(a.submodels().front().free_nodes == 0);  // every sub-node is an initial node
  const double va = a.block_velocity(1).x, vb = b.block_velocity(1).x;
  INFO("j: sub-model k 1 " << va << " coarse " << vb);
  CHECK(std::abs(va - vb) <= kK1Agreement * std::abs(vb));
  CHECK(a.separations().front().time == Approx(b.separations().front().time).margin(a.dt()));
}

TEST_CASE("negative control: the k = 1 agreement fails for a real sub-model (k = 4)", "[cdem][submodel][control]") {
  Model a(two_prisms(2, submodel_options(4, 4))), b(two_prisms(2, coarse_options()));
  a.advance_to(kEnd);
  b.advance_to(kEnd);
  const double va = a.block_velocity(1).x, vb = b.block_velocity(1).x;
  INFO("j: sub-model k 4 " << va << " coarse " << vb);
  CHECK_FALSE(std::abs(va - vb) <= kK1Agreement * std::abs(vb));
}

TEST_CASE("sub-model: energy account and momentum, measured", "[cdem][submodel]") {
  Model m(two_prisms(2, submodel_options()));
  const Vec2 p0 = m.momentum();
  const double e0 = m.energy_account().initial;
  double worst_other = 0.0, max_total = 0.0, max_drift = 0.0;
  while (m.time() < kEnd - 1e-12) {
    m.step();
    const CdemEnergyAccount a = m.energy_account();
    worst_other = std::max(worst_other, std::abs(a.other) / e0);
    max_total = std::max(max_total, (a.kinetic + a.strain + a.gravity) / e0);
    max_drift = std::max(max_drift, dda::length(m.momentum() - p0) / dda::length(p0));
    REQUIRE(std::isfinite(a.other));
  }
  const CdemEnergyAccount a = m.energy_account();
  const SubModelRecord& r = m.submodels().front();
  INFO("worst |other|/E0 " << worst_other << " max E/E0 " << max_total << " momentum drift " << max_drift
                           << " final drift " << dda::length(m.momentum() - p0) / dda::length(p0) << " touch "
                           << a.touch_loss / e0 << " deletion " << a.deletion_loss / e0 << " dropped KE "
                           << r.kinetic_dropped / e0);
  // the energy never grows above its start
  CHECK(max_total <= 1.0 + 1e-9);
  CHECK(std::isfinite(max_drift));
  WARN("sub-model prisms: worst |other|/E0 " << worst_other << ", max |p - p0|/|p0| " << max_drift
                                             << ", kinetic dropped at deletion / E0 " << r.kinetic_dropped / e0);
}

TEST_CASE("sub-model: contact_point_mass is an in-place option", "[cdem][submodel]") {
  CdemOptions o = submodel_options();
  o.contact_point_mass = 1.0;
  CHECK_THROWS_AS(Model(two_prisms(2, o)), dda::SceneError);
}

TEST_CASE("a run whose elements turn inside out stops, naming the element, the step and why", "[cdem][submodel]") {
  // The prisms at 3000 m/s (the paper's i moves at 3 m/s; the material's
  // wave speed is about 700 m/s): an impact no mesh survives. Every mode
  // stops with the element that inverted, kAreaCollapsed, never a normal
  // end. The sub-model's own check fires inside its substeps; the in-place
  // and the coarse runs fire in the coarse element force.
  struct Case {
    const char* name;
    bool subdivision;
    SubdivisionMode mode;
    const char* names;  // what the message must name
  };
  for (const Case& c : {Case{"sub-model", true, SubdivisionMode::kSubModel, "sub-element"},
                        Case{"in place", true, SubdivisionMode::kInPlace, "element of block"},
                        Case{"no subdivision", false, SubdivisionMode::kSubModel, "element of block"}}) {
    INFO(c.name);
    CdemOptions o = c.subdivision ? submodel_options() : coarse_options();
    o.subdivision_mode = c.mode;
    CdemScene s = two_prisms(2, o);
    s.blocks[0].velocity = {3000.0, 0.0};
    Model m(s);
    bool stopped = false;
    try {
      while (m.time() < kEnd - 1e-12) m.step();
    } catch (const ContactError&) {
      FAIL("a ContactError, not the element check");
    } catch (const dda::SimulationError& e) {
      stopped = true;
      CHECK(e.reason == dda::StopReason::kAreaCollapsed);
      CHECK_THAT(std::string(e.what()),
                 Catch::Contains(c.names) && Catch::Contains("inverted") && Catch::Contains(" s (step "));
      if (c.mode == SubdivisionMode::kSubModel && c.subdivision)
        CHECK_THAT(std::string(e.what()), Catch::Contains("of the sub-model of element"));
    }
    CHECK(stopped);
  }
  // Control: at 300 m/s the same scene runs to its end in every mode.
  for (bool sub : {true, false}) {
    CdemScene s = two_prisms(2, sub ? submodel_options() : coarse_options());
    s.blocks[0].velocity = {300.0, 0.0};
    Model m(s);
    CHECK_NOTHROW(m.advance_to(kEnd));
  }
}
