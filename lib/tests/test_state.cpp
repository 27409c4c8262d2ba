// Simulation::save_state / restore_state: a simulation restored from the
// saved state of another runs on with the same bits as the one saved
// (checkpoints of dda run), whatever it does (friction history, sweep broad
// phase, damping, exact rotation, rigid blocks), and a stream that is not
// such a state is refused.
#include <catch2/catch.hpp>

#include <array>
#include <string>

#include "dda/joint_sets.hpp"
#include "dda/potential.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "dda/state_bytes.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {

// A column of jointed rock on a floor, collapsing under gravity: many pairs
// coming and going, sliding and sticking; the variants switch the
// features whose state a step carries.
struct Variant {
  FrictionUpdate friction = FrictionUpdate::kPaper;
  BroadPhase broad_phase = BroadPhase::kSweep;
  RotationUpdate rotation = RotationUpdate::kPaperLinear;
  double mass_damping = 0.0;        // a of Eq. 5c, 1/s
  double stiffness_damping = 0.0;   // b, s
  bool strains = true;
};

Scene collapsing_column(const Variant& v) {
  Scene s = jointed_rock({{0, 0}, {4, 0}, {4, 8}, {0, 8}}, {{70.0, 1.0, {0, 0}}, {30.0, 1.6, {0, 0}}}, 0.2, 20.0);
  s.contact.friction_update = v.friction;
  s.dt_fraction = 0.5;  // of the predicted critical step
  s.broad_phase = v.broad_phase;
  s.rotation_update = v.rotation;
  s.strains = v.strains;
  s.damping.mass = v.mass_damping;
  s.damping.stiffness = v.stiffness_damping;
  s.guards.energy_check_every = 25;
  s.blocks[0].velocity = {0.5, 0.2};  // one block thrown against the others
  s.boundaries.push_back({{-5, 0}, {20, 0}, 0.0, 1});  // floor, solid below
  return s;
}

std::string state_of(const Simulation& sim) {
  ByteWriter w;
  sim.save_state(w);
  return w.take();
}

// `before` steps, saved, restored into a new simulation of the scene; the
// original runs `after` steps one at a time, the restored one in one team of
// `threads`: the same state (every byte of save_state), energy and contacts.
void check_round_trip(const Scene& s, int before, int after, int threads) {
  Simulation original(s);
  original.advance(before);
  const std::string saved = state_of(original);
  Simulation restored(s);
  restored.set_threads(threads);
  ByteReader r(saved.data(), saved.size(), "state");
  restored.restore_state(r);
  r.expect_end();
  CHECK(state_of(restored) == saved);
  for (int k = 0; k < after; ++k) original.step();
  restored.advance(after);
  CHECK(restored.step_count() == before + after);
  CHECK(restored.time() == original.time());
  CHECK(state_of(restored) == state_of(original));
  const Energy a = original.energy(), b = restored.energy();
  CHECK(a.total() == b.total());
  CHECK(a.dissipated == b.dissipated);
  CHECK(a.friction_spring == b.friction_spring);
  CHECK(original.contacts().size() == restored.contacts().size());
  CHECK(restored.contact_count() == restored.contacts().size());
  CHECK(original.contact_count() == original.contacts().size());
  CHECK(original.broad_phase_rebuilds() == restored.broad_phase_rebuilds());
}

}  // namespace

TEST_CASE("a restored simulation runs on with the same bits as the one saved", "[simulation][state]") {
  SECTION("friction as the paper writes it, sweep broad phase") {
    const Scene s = collapsing_column({});
    Simulation probe(s);
    probe.advance(400);
    // What the state must carry is there: pairs in contact, some sliding.
    REQUIRE(probe.contacts().size() > 10);
    REQUIRE(probe.energy().dissipated > 0.0);
    check_round_trip(s, 400, 300, 2);
  }
  SECTION("return mapping, exact rotation, all-pairs broad phase, Eq. 5c damping") {
    Variant v;
    v.friction = FrictionUpdate::kReturnMapping;
    v.broad_phase = BroadPhase::kNone;
    v.rotation = RotationUpdate::kExact;
    v.mass_damping = 2.0;
    v.stiffness_damping = 1e-6;
    check_round_trip(collapsing_column(v), 350, 250, 2);
  }
  SECTION("rigid blocks, saved at t = 0") {
    Variant v;
    v.strains = false;
    check_round_trip(collapsing_column(v), 0, 200, 1);
  }
  SECTION("a block with a small edge: bisectors of its own (a virtual node), the others the shared vertex rays") {
    for (SmallEdgeRays rays : {SmallEdgeRays::kVirtualAndVertex, SmallEdgeRays::kVirtualReplacesVertex}) {
      paper::SmallEdgeImpact si = paper::small_edge_impact(paper::SmallEdgeCase::kOnSmallEdge);
      si.scene.contact.small_edge_rays = rays;
      Simulation probe(si.scene);
      probe.advance(300);
      REQUIRE(probe.contact_count() > 0);
      // Some block's bisectors are not its vertex rays, some block's are.
      int own = 0, shared = 0;
      for (int i = 0; i < probe.block_count(); ++i) {
        const PolygonView p = probe.polygon_view(i);
        std::array<Bisector, 2 * kMaxVertices> b{};
        const double small = si.scene.contact.small_edge_fraction * probe.potential_length(i);
        (bisectors(p, small, rays, b.data()) != p.count ? own : shared) += 1;
      }
      REQUIRE(own > 0);
      REQUIRE(shared > 0);
      check_round_trip(si.scene, 300, 200, 1);
    }
  }
}

TEST_CASE("restoring a state refuses another scene and a truncated stream", "[simulation][state]") {
  const Scene s = collapsing_column({});
  Simulation sim(s);
  sim.advance(20);
  const std::string saved = state_of(sim);

  Scene other = s;
  other.blocks.pop_back();
  Simulation wrong(other);
  ByteReader r(saved.data(), saved.size(), "state");
  CHECK_THROWS_WITH(wrong.restore_state(r), Catch::Contains("a state of another scene"));

  Scene finer = s;
  finer.dt_fraction = 0.25;
  Simulation other_dt(finer);
  ByteReader r2(saved.data(), saved.size(), "state");
  CHECK_THROWS_WITH(other_dt.restore_state(r2), Catch::Contains("another scene"));

  Simulation fresh(s);
  ByteReader cut(saved.data(), saved.size() / 2, "state");
  CHECK_THROWS_WITH(fresh.restore_state(cut), Catch::Contains("truncated"));
}
