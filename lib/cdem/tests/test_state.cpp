// The model's state in parts (dda/cdem/model_state.hpp) is plain values: a
// copy of a model taken in the middle of a collision, with a clone tied and
// a sub-model (or a patch) live, runs on bit for bit as the original, and
// the parts hold what the read-out reports. What a checkpoint relies on.
#include <catch2/catch.hpp>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

// The prisms of Paper B Sect. 6: the touch at 1/3 s, the clone separates at
// about 0.3405 s; 0.3345 s lies between.
constexpr double kMidCollision = 0.3345;
constexpr double kEnd = 0.5;

}  // namespace

TEST_CASE("a copy of the model mid-collision runs on bit for bit", "[cdem][state]") {
  for (SubdivisionMode mode : {SubdivisionMode::kSubModel, SubdivisionMode::kInPlace}) {
    const bool sub = mode == SubdivisionMode::kSubModel;
    INFO((sub ? "sub-model" : "in-place"));
    CdemOptions o;
    o.subdivision_mode = mode;
    Model a(two_prisms(2, o));
    a.advance_to(kMidCollision);
    REQUIRE_FALSE(a.clones().empty());
    if (sub)
      REQUIRE(a.live_submodels() == 1);
    else
      REQUIRE(a.active_elements(true) > 0);
    Model b = a;
    a.advance_to(kEnd);
    b.advance_to(kEnd);
    REQUIRE(a.node_count() == b.node_count());
    REQUIRE(a.step_count() == b.step_count());
    int differ = 0;
    for (int i = 0; i < a.node_count(); ++i)
      if (!(a.node_position(i) == b.node_position(i)) || !(a.node_velocity(i) == b.node_velocity(i))) ++differ;
    CHECK(differ == 0);
    const CdemEnergyAccount ea = a.energy_account(), eb = b.energy_account();
    CHECK(ea.kinetic == eb.kinetic);
    CHECK(ea.strain == eb.strain);
    CHECK(ea.other == eb.other);
    CHECK(a.separations().size() == b.separations().size());
  }
}

TEST_CASE("the state's parts hold what the read-out reports", "[cdem][state]") {
  Model m(two_prisms(2));
  m.advance_to(kMidCollision);
  const ModelState& s = m.state();
  CHECK(s.time == m.time());
  CHECK(s.steps == m.step_count());
  CHECK(s.nodes.size() == static_cast<std::size_t>(m.node_count()));
  CHECK(s.clones.size() == m.clones().size());
  CHECK(s.submodels.live.size() == static_cast<std::size_t>(m.live_submodels()));
  CHECK(s.log.touches.size() == m.touches().size());
  Vec2 p{};
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.nodes.kind[i] == NodeKind::kCoarse || s.nodes.kind[i] == NodeKind::kFine) p += s.nodes.m[i] * s.nodes.v[i];
  CHECK(p == m.momentum());
  // the scratch of one step is empty between steps
  CHECK(s.submodels.requests.empty());
  CHECK(s.submodels.request_touch.empty());
}
