// The model's state in parts (dda/cdem/model_state.hpp) is plain values: a
// copy of a model taken in the middle of a collision, with a clone tied and
// a sub-model (or a patch) live, runs on bit for bit as the original, and
// the parts hold what the read-out reports. Saved by its bits
// (Model::save_state) and restored into a model built from the same scene,
// it runs on to the same bits too; a stream that is truncated, inconsistent
// or of another scene is refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "dda/state_bytes.hpp"

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

// --- saving and restoring the state by its bits (state.cpp) ----------------

namespace {

std::string saved(const Model& m) {
  dda::ByteWriter w;
  m.save_state(w);
  return w.take();
}

void restore(Model& m, const std::string& bytes) {
  dda::ByteReader r(bytes.data(), bytes.size(), "test state");
  m.restore_state(r);
  r.expect_end();
}

std::string written(const ModelSetup& su, const ModelState& st) {
  dda::ByteWriter w;
  write_state(w, su, st);
  return w.take();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Vec2 a, Vec2 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

// Nodes whose position or velocity differ in any bit between the two models
// (every node when their node counts differ).
int differing_nodes(const Model& a, const Model& b) {
  if (a.node_count() != b.node_count()) return std::max(a.node_count(), b.node_count());
  int differ = 0;
  for (int i = 0; i < a.node_count(); ++i)
    if (!same_bits(a.node_position(i), b.node_position(i)) || !same_bits(a.node_velocity(i), b.node_velocity(i))) ++differ;
  return differ;
}

CdemOptions options_of(SubdivisionMode mode) {
  CdemOptions o;
  o.subdivision_mode = mode;
  o.capture_touch_snapshots = true;  // the touch records' snapshots are in the state too
  return o;
}

}  // namespace

TEST_CASE("a state saved mid-collision and restored into a new model runs on to the same bits", "[cdem][state]") {
  for (SubdivisionMode mode : {SubdivisionMode::kSubModel, SubdivisionMode::kInPlace}) {
    const bool sub = mode == SubdivisionMode::kSubModel;
    INFO((sub ? "sub-model" : "in-place"));
    const CdemScene scene = two_prisms(2, options_of(mode));
    Model a(scene);
    a.advance_to(kMidCollision);
    REQUIRE_FALSE(a.clones().empty());
    REQUIRE(a.touches().size() >= 1);
    REQUIRE(a.touches()[0].snapshot.size() == 1);
    if (sub)
      REQUIRE(a.live_submodels() == 1);
    else
      REQUIRE(a.active_elements(true) > 0);
    const std::string bytes = saved(a);
    // A model built from the scene, at t = 0, takes the state whole.
    Model b(scene);
    REQUIRE(b.node_count() <= a.node_count());
    restore(b, bytes);
    CHECK(saved(b) == bytes);
    CHECK(b.time() == a.time());
    CHECK(b.step_count() == a.step_count());
    CHECK(b.node_count() == a.node_count());
    CHECK(b.clones().size() == a.clones().size());
    CHECK(b.live_submodels() == a.live_submodels());
    // Run on past the separation, the sub-model's (or patch's) deletion.
    a.advance_to(kEnd);
    b.advance_to(kEnd);
    REQUIRE(a.step_count() == b.step_count());
    CHECK(a.node_count() == b.node_count());
    CHECK(differing_nodes(a, b) == 0);
    CHECK(a.separations().size() >= 1);
    CHECK(a.separations().size() == b.separations().size());
    const CdemEnergyAccount ea = a.energy_account(), eb = b.energy_account();
    CHECK(same_bits(ea.kinetic, eb.kinetic));
    CHECK(same_bits(ea.strain, eb.strain));
    CHECK(same_bits(ea.other, eb.other));
    CHECK(saved(a) == saved(b));
  }
}

TEST_CASE("the comparison of a restored run sees a state that lost a part or was nudged", "[cdem][state]") {
  // Negative controls of the test above: the same comparison, after a
  // restore of the mid-collision state with its clones dropped, or with the
  // clone's main node's velocity changed by 1e-9 of itself, finds the runs
  // apart.
  for (SubdivisionMode mode : {SubdivisionMode::kSubModel, SubdivisionMode::kInPlace}) {
    INFO((mode == SubdivisionMode::kSubModel ? "sub-model" : "in-place"));
    const CdemScene scene = two_prisms(2, options_of(mode));
    Model a(scene);
    a.advance_to(kMidCollision);
    REQUIRE_FALSE(a.clones().empty());
    Model reference = a;
    reference.advance_to(kEnd);

    ModelState no_clones = a.state();
    no_clones.clones.clear();
    Model b(scene);
    restore(b, written(a.setup(), no_clones));
    CHECK(b.clones().empty());
    b.advance_to(kEnd);
    CHECK(differing_nodes(reference, b) > 0);

    // (One ulp of a velocity can be absorbed by the rounding of the next
    // position update; 1e-9 of itself cannot.)
    ModelState nudged = a.state();
    double& vx = nudged.nodes.v[static_cast<std::size_t>(nudged.clones.front().main)].x;
    REQUIRE(vx != 0.0);
    vx *= 1.0 + 1e-9;
    Model c(scene);
    restore(c, written(a.setup(), nudged));
    c.advance_to(kEnd);
    CHECK(differing_nodes(reference, c) > 0);
  }
}

TEST_CASE("a truncated, inconsistent or other scene's state is refused, the model unchanged", "[cdem][state]") {
  const CdemScene scene = two_prisms(2, options_of(SubdivisionMode::kSubModel));
  Model a(scene);
  a.advance_to(kMidCollision);
  const std::string bytes = saved(a);
  Model b(scene);
  const std::string before = saved(b);
  auto refused = [&](Model& m, const std::string& s, const std::string& reason) {
    const std::string was = saved(m);
    dda::ByteReader r(s.data(), s.size(), "test state");
    CHECK_THROWS_WITH(m.restore_state(r), Catch::Contains(reason));
    CHECK(saved(m) == was);
  };
  // Every cut of the stream at 1 of 97 places, and its first bytes.
  for (std::size_t cut : {std::size_t{0}, std::size_t{3}, std::size_t{4}, std::size_t{11}, bytes.size() - 1})
    refused(b, bytes.substr(0, cut), "truncated");
  for (std::size_t k = 1; k < 97; ++k) {
    dda::ByteReader r(bytes.data(), bytes.size() * k / 97, "test state");
    CHECK_THROWS_AS(b.restore_state(r), dda::StateError);
  }
  CHECK(saved(b) == before);
  // Another layout.
  std::string layout = bytes;
  layout[0] = 9;
  refused(b, layout, "cdem state layout 9, this build reads layout 1");
  // Another scene: finer meshes, another subdivision mode, another dt.
  Model finer(two_prisms(3, options_of(SubdivisionMode::kSubModel)));
  refused(finer, bytes, "a state of another scene");
  Model in_place(two_prisms(2, options_of(SubdivisionMode::kInPlace)));
  refused(in_place, bytes, "cdem options differ");
  CdemScene slower = scene;
  slower.dt *= 0.5;
  Model other_dt(slower);
  refused(other_dt, bytes, "its dt differs");
  // The name and the duration are not the state's: accepted.
  CdemScene longer = scene;
  longer.duration *= 2.0;
  longer.name = "renamed";
  Model c(longer);
  restore(c, bytes);
  CHECK(saved(c) == bytes);
  // An id out of range, and per-node lists of different lengths.
  ModelState bad = a.state();
  bad.clones.front().main = a.node_count() + 5;
  refused(b, written(a.setup(), bad), "a clone's main node");
  bad = a.state();
  bad.nodes.v.pop_back();
  refused(b, written(a.setup(), bad), "a per-node list of vectors has");
  bad = a.state();
  bad.submodels.live.front().elems.front().n[1] = -1;
  refused(b, written(a.setup(), bad), "a sub-element's corner -1 is out of range");
}

TEST_CASE("a state with random bytes changed is refused, or restored as those bytes", "[cdem][state]") {
  // Past the opening record (a change there is another scene), each of 400
  // streams has 1 to 4 random bytes changed. A restore either throws
  // StateError, the model unchanged, or takes the stream whole: saving the
  // restored model gives the changed stream back (the format has one
  // stream per state). Nothing is read out of range (run it under
  // valgrind to see).
  const CdemScene scene = two_prisms(2, options_of(SubdivisionMode::kSubModel));
  Model a(scene);
  a.advance_to(kMidCollision);
  const std::string bytes = saved(a);
  constexpr std::size_t kOpening = 4 + 8 + 8 + 8 + 4 + 8;
  std::mt19937 rng(20261128);
  std::uniform_int_distribution<std::size_t> where(kOpening, bytes.size() - 1);
  std::uniform_int_distribution<int> value(0, 255), changes(1, 4);
  int refused = 0, taken = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string s = bytes;
    for (int k = changes(rng); k > 0; --k) s[where(rng)] = static_cast<char>(value(rng));
    Model b(scene);
    const std::string before = saved(b);
    dda::ByteReader r(s.data(), s.size(), "test state");
    try {
      b.restore_state(r);
    } catch (const dda::StateError&) {
      CHECK(saved(b) == before);
      ++refused;
      continue;
    }
    // Taken: the bytes it read are the state's stream (a changed length
    // may leave bytes over, which the caller refuses with expect_end).
    CHECK(saved(b) == s.substr(0, s.size() - r.remaining()));
    ++taken;
  }
  // Most changes land in doubles, which any bits are; some in lengths and ids.
  CHECK(taken > 0);
  CHECK(refused > 0);
}

namespace {

// Steps `scene` until `ready` holds (within its duration), saves, restores
// into a model built from the scene, runs both `more` steps and compares
// every node's bits.
template <class Ready>
void check_round_trip(const CdemScene& scene, Ready ready, int more) {
  Model a(scene);
  while (!ready(a) && a.time() < scene.duration) a.step();
  REQUIRE(ready(a));
  Model b(scene);
  restore(b, saved(a));
  for (int k = 0; k < more; ++k) {
    a.step();
    b.step();
  }
  CHECK(differing_nodes(a, b) == 0);
  CHECK(saved(a) == saved(b));
}

}  // namespace

TEST_CASE("the penalty baseline's springs and a sliding clone are restored too", "[cdem][state]") {
  SECTION("node-to-edge penalty contact, springs active") {
    CdemOptions o;
    o.contact = ContactMode::kNodeToEdgePenalty;
    o.subdivision = false;
    CdemScene s = two_squares(4, o);
    s.duration = 0.6;
    check_round_trip(s, [](const Model& m) { return m.penalty_contacts().size() >= 2; }, 400);
  }
  SECTION("Coulomb touch impact on an oblique face: the clone slides") {
    for (SubdivisionMode mode : {SubdivisionMode::kSubModel, SubdivisionMode::kInPlace}) {
      INFO((mode == SubdivisionMode::kSubModel ? "sub-model" : "in-place"));
      CdemOptions o = options_of(mode);
      o.touch_impact = TouchImpact::kCoulomb;
      o.strength.friction_deg = 10.0;
      CdemScene s = two_squares(2, o);
      // A strikes B at 60 degrees from the face normal.
      for (CdemBlock& b : s.blocks)
        if (b.velocity.x != 0.0) b.velocity = {b.velocity.x, 1.7 * b.velocity.x};
      s.duration = 1.0;
      check_round_trip(
          s,
          [](const Model& m) {
            for (const Clone& c : m.state().clones)
              if (c.sliding) return true;
            return false;
          },
          2000);
    }
  }
}
