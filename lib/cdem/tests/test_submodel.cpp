// Unit tests of Paper B Sect. 5 (SubdivisionMode::kSubModel): the
// sub-model of the colliding elements, driven by the coarse nodes (steps
// 1-5, Eq. 12), on the two prisms of Sect. 6; step (5) in both readings
// (CdemOptions::submodel_transfer).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

CdemOptions submodel_options(int min_k = 2, int max_k = 6,
                             SubModelTransfer transfer = SubModelTransfer::kWholeElement) {
  CdemOptions o;
  o.submodel_transfer = transfer;
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

// Round-off bounds of the conservation checks, in units in the last place
// (ulp) of the conserved total, per coarse step: each step adds forces that
// sum to zero in exact arithmetic (element forces, clone ties) times dt to
// the nodal velocities, so a conserved total drifts by the rounding of
// those sums, a small multiple of its ulp per step (measured on the prisms:
// 0.07 ulp per step for the momentum, 0.15 for the energy before the touch).
constexpr double kMomentumUlpsPerStep = 4.0;
constexpr double kEnergyUlpsPerStep = 4.0;
double ulp(double x) { return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x); }

// The largest momentum drift |p - p0| and mechanical energy (kinetic +
// strain + gravity) of a run to kEnd, N s/m and J/m.
struct Conservation {
  double p0 = 0.0, e0 = 0.0;
  double worst_momentum = 0.0, max_energy = 0.0;
  std::int64_t steps = 0;
  int free_sub_nodes = 0;  // in the first sub-model
  double momentum_tolerance() const { return kMomentumUlpsPerStep * static_cast<double>(steps) * ulp(p0); }
  double energy_tolerance() const { return kEnergyUlpsPerStep * static_cast<double>(steps) * ulp(e0); }
};
Conservation run_conservation(const CdemScene& scene) {
  Model m(scene);
  Conservation c;
  const Vec2 p0 = m.momentum();
  c.p0 = dda::length(p0);
  c.e0 = m.energy_account().initial;
  while (m.time() < kEnd - 1e-12) {
    m.step();
    const CdemEnergyAccount a = m.energy_account();
    c.worst_momentum = std::max(c.worst_momentum, dda::length(m.momentum() - p0));
    c.max_energy = std::max(c.max_energy, a.kinetic + a.strain + a.gravity);
  }
  c.steps = m.step_count();
  if (!m.submodels().empty()) c.free_sub_nodes = m.submodels().front().free_nodes;
  return c;
}

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

TEST_CASE("sub-model: momentum is conserved to round-off through the collision (the whole-element transfer)",
          "[cdem][submodel]") {
  const Conservation c = run_conservation(two_prisms(2, submodel_options()));
  INFO("max |p - p0| " << c.worst_momentum << " N s/m (" << c.worst_momentum / c.p0 << " of p0), tolerance "
                       << c.momentum_tolerance() << " N s/m over " << c.steps << " steps");
  REQUIRE(c.free_sub_nodes > 0);  // a real sub-model lived (k = 6)
  CHECK(c.worst_momentum <= c.momentum_tolerance());
}

TEST_CASE("negative control: the literal transfer (prescribed sub-nodes only) loses momentum", "[cdem][submodel][control]") {
  const Conservation c =
      run_conservation(two_prisms(2, submodel_options(2, 6, SubModelTransfer::kPrescribedNodes)));
  INFO("max |p - p0| " << c.worst_momentum << " N s/m (" << c.worst_momentum / c.p0 << " of p0), tolerance "
                       << c.momentum_tolerance() << " N s/m");
  REQUIRE(c.free_sub_nodes > 0);
  CHECK_FALSE(c.worst_momentum <= c.momentum_tolerance());
  CHECK(c.worst_momentum > 0.1 * c.p0);  // the free sub-nodes' inertia: a third of the momentum
}

TEST_CASE("sub-model: the mechanical energy never grows above its start", "[cdem][submodel]") {
  // Eq. 4 and the deletion remove energy; central differences below the
  // critical step add none. On the paper's mesh and on one twice as fine
  // (dt with h), where the sub-model lives longer against more coarse nodes.
  for (int divisions : {2, 4}) {
    CdemScene s = two_prisms(divisions, submodel_options());
    s.dt *= 2.0 / divisions;
    const Conservation c = run_conservation(s);
    INFO(divisions << " divisions: max E / E0 - 1 = " << c.max_energy / c.e0 - 1.0 << ", tolerance "
                   << c.energy_tolerance() / c.e0 << "; max |p - p0| / p0 " << c.worst_momentum / c.p0);
    REQUIRE(c.free_sub_nodes > 0);
    CHECK(c.max_energy <= c.e0 + c.energy_tolerance());
    CHECK(c.worst_momentum <= c.momentum_tolerance());
  }
}

TEST_CASE("negative control: the energy check fails on the literal transfer of a finer mesh", "[cdem][submodel][control]") {
  // The literal reading's returned inertia does work the coarse model does
  // not hold: on 8 divisions (dt with h) the energy rises above E0.
  CdemScene s = two_prisms(8, submodel_options(2, 6, SubModelTransfer::kPrescribedNodes));
  s.dt *= 2.0 / 8.0;
  const Conservation c = run_conservation(s);
  INFO("max E / E0 - 1 = " << c.max_energy / c.e0 - 1.0);
  CHECK_FALSE(c.max_energy <= c.e0 + c.energy_tolerance());
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
