#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

#include "dda/block.hpp"
#include "dda/joint_sets.hpp"
#include "dda/paper_scenes.hpp"
#include "dda/potential.hpp"
#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "state_hash.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

TEST_CASE("a free-falling block follows g t^2 / 2 exactly (Verlet is exact for constant force)", "[simulation]") {
  Scene s;
  s.gravity = {0.0, -9.81};
  s.dt = 1e-3;
  BlockSpec b;
  b.vertices = rect_vertices(0, 0, 1, 2);
  b.velocity = {0.5, 0.0};
  s.blocks = {b};
  Simulation sim(s);
  const Vec2 c0 = sim.centroid(0);
  sim.advance_to(0.5);
  const double t = sim.time();
  CHECK(t == Approx(0.5));
  CHECK(sim.centroid(0).y - c0.y == Approx(-0.5 * 9.81 * t * t).epsilon(1e-12));
  CHECK(sim.centroid(0).x - c0.x == Approx(0.5 * t).epsilon(1e-12));
  CHECK(sim.velocity(0)[1] == Approx(-9.81 * t).epsilon(1e-12));
}

TEST_CASE("contact forces are equal and opposite: momentum is conserved to round-off", "[simulation]") {
  Scene s = paper::two_squares();
  s.blocks[1].vertices = {{0, -0.3}, {1, -0.5}, {1.2, 0.4}, {0.3, 0.6}};  // oblique impact
  Simulation sim(s);
  const Vec2 p0 = sim.momentum();
  double worst = 0.0;
  int contact_steps = 0;
  while (sim.time() < 1.0) {
    sim.step();
    contact_steps += sim.contacts().empty() ? 0 : 1;
    worst = std::max(worst, length(sim.momentum() - p0));
  }
  CHECK(contact_steps > 10);
  // Tolerance: a few ulps of the momentum per contact step (~500 steps).
  CHECK(worst < 1e-9 * length(p0));
}

TEST_CASE("two squares exchange velocities (Sect. 4.1)", "[simulation]") {
  Simulation sim(paper::two_squares());
  bool touched = false;
  while (sim.time() < 1.0) {
    sim.step();
    touched = touched || !sim.contacts().empty();
  }
  CHECK(touched);
  CHECK(std::fabs(sim.velocity(0)[0]) < 1e-3);
  CHECK(sim.velocity(1)[0] == Approx(1.0).epsilon(1e-3));
  // Energy: a slow penalty collision of elastic blocks is nearly elastic.
  const Energy e = sim.energy();
  CHECK(e.total() == Approx(0.5 * 2000.0).epsilon(1e-3));
}

TEST_CASE("a frictionless block slides down the incline as Eq. 30 says", "[simulation]") {
  paper::Incline in = paper::incline(0.0, 30.0, 0.1);
  Simulation sim(in.scene);
  const Vec2 c0 = sim.centroid(1);
  sim.advance_to(0.1);
  const double l = dot(sim.centroid(1) - c0, in.downhill);
  CHECK(l == Approx(paper::incline_distance(9.81, in.theta_rad, 0.0, sim.time())).epsilon(1e-6));
}

TEST_CASE("the symmetric stack stays symmetric (Sect. 4.2, short run)", "[simulation]") {
  paper::SymmetricStack st = paper::symmetric_stack();
  st.scene.duration = 0.4;
  Simulation sim(st.scene);
  double asym = 0.0;
  while (sim.time() < st.scene.duration) {
    sim.step();
    for (int i = 0; i < sim.block_count(); ++i) {
      const int j = st.mirror[static_cast<std::size_t>(i)];
      asym = std::max({asym, std::fabs(sim.centroid(i).x + sim.centroid(j).x),
                       std::fabs(sim.centroid(i).y - sim.centroid(j).y)});
    }
  }
  CHECK(asym < 1e-9);
}

TEST_CASE("broad phase on or off gives the same run", "[simulation]") {
  paper::SymmetricStack st = paper::symmetric_stack();
  Scene a = st.scene, b = st.scene;
  a.duration = b.duration = 0.3;
  b.broad_phase = BroadPhase::kSweep;
  Simulation sa(a), sb(b);
  sa.advance_to(0.3);
  sb.advance_to(0.3);
  CHECK(state_hash(sa) == state_hash(sb));
}

TEST_CASE("a run is deterministic: the same scene gives the same bits", "[simulation]") {
  // The hash of the final state is printed so that builds can be compared;
  // within one build two runs must agree bit for bit.
  paper::Incline in = paper::incline(20.0, 30.0, 0.05);
  Simulation s1(in.scene), s2(in.scene);
  s1.advance_to(0.05);
  s2.advance_to(0.05);
  const std::uint64_t h1 = state_hash(s1), h2 = state_hash(s2);
  INFO("determinism hash " << h1);
  CHECK(h1 == h2);
}

TEST_CASE("scene checks name the field and the reason", "[simulation]") {
  auto message = [](const Scene& s) {
    try {
      check_scene(s);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  Scene s = paper::two_squares();
  Scene bad = s;
  bad.dt = 0.0;
  CHECK(message(bad).find("dt") == 0);
  bad = s;
  bad.materials[0].poisson = 0.5;
  CHECK(message(bad).find("materials[0].poisson") == 0);
  bad = s;
  bad.contact.friction_deg = 90.0;
  CHECK(message(bad).find("contact.friction_deg") == 0);
  bad = s;
  std::swap(bad.blocks[1].vertices[1], bad.blocks[1].vertices[3]);
  CHECK(message(bad).find("blocks[1].vertices") == 0);
  CHECK(message(bad).find("clockwise") != std::string::npos);
  bad = s;
  bad.blocks[1].vertices = rect_vertices(-0.6, -0.5, 1.0, 1.0);
  CHECK(message(bad).find("overlaps blocks[1]") != std::string::npos);
  bad = s;
  bad.boundaries.push_back({{-2.0, 0.0}, {2.0, 0.0}});  // solid below y = 0 cuts both squares
  CHECK(message(bad).find("overlaps boundaries[0]") != std::string::npos);
  CHECK(message(s) == "accepted");
}

TEST_CASE("a blow-up stops with a message naming step and block", "[simulation]") {
  Scene s = paper::two_squares();
  s.contact.kn = 1e13;  // far above what dt = 1e-4 can integrate
  s.blocks[0].velocity = {100.0, 0.0};
  Simulation sim(s);
  std::string what;
  StopReason reason = StopReason::kOther;
  try {
    sim.advance_to(1.0);
  } catch (const SimulationError& e) {
    what = e.what();
    reason = e.reason;
  }
  INFO(what);
  CHECK(reason != StopReason::kOther);  // one of the guards stopped it, and says which
  CHECK(what.find("step") != std::string::npos);
  CHECK(what.find("block") != std::string::npos);
  CHECK(what.find("dt/dt_crit") != std::string::npos);
}

TEST_CASE("a time step above the predicted critical step is caught, one below runs clean", "[simulation]") {
  // dt_crit = 2 / omega_max of velocity Verlet; the strain modes of a 1 m
  // block with E = 1 GPa, rho = 2000 limit it to ~1e-3 s.
  Scene s = paper::two_squares();
  Simulation probe(s);
  const double dt_crit = probe.predicted_critical_step();
  CHECK(dt_crit > 5e-4);
  CHECK(dt_crit < 2e-3);
  s.dt_fraction = 0.5;
  Simulation ok(s);
  CHECK(ok.dt() == Approx(0.5 * dt_crit));
  CHECK_NOTHROW(ok.advance_to(1.0));
  s.dt_fraction = 1.5;
  Simulation bad(s);
  // On one thread and from inside a 2-thread team (the guard's error must
  // leave the parallel region and stop every thread after that step).
  bad.set_threads(GENERATE(1, 2));
  std::string what;
  try {
    bad.advance_to(1.0);
  } catch (const SimulationError& e) {
    what = e.what();
  }
  INFO(what);
  CHECK(what.find("dt/dt_crit") != std::string::npos);
  CHECK(bad.time() < 1.0);
}

namespace {
// A jointed column on a floor against a wall: ~80 blocks, several hundred
// candidate pairs, friction rules.
Scene jointed_column() {
  Scene s = jointed_rock({{0, 0}, {10, 0}, {10, 20}, {0, 20}}, {{80.0, 1.5, {0, 0}}, {40.0, 2.5, {0, 0}}}, 0.5, 15.0);
  s.boundaries.push_back({{-5, 0}, {40, 0}, 0.0, 1});  // floor, solid below
  s.boundaries.push_back({{0, 20}, {0, -1}, 0.0, 1});  // wall, solid on the left
  return s;
}
}  // namespace

TEST_CASE("the same bits on 1 and 2 threads, step by step or in one thread team", "[simulation]") {
  const Scene s = jointed_column();
  Simulation one(s), two(s), team(s);
  two.set_threads(2);
  team.set_threads(2);
  for (int k = 0; k < 300; ++k) {
    one.step();
    two.step();
  }
  team.advance(300);  // one parallel region for all 300 steps
  CHECK(one.contacts().size() > 80);
  CHECK(team.step_count() == 300);
  CHECK(state_hash(one) == state_hash(two));
  CHECK(state_hash(one) == state_hash(team));
}

TEST_CASE("phase times account for each thread's time in the steps run since their reset", "[simulation]") {
  // Simulation::phase_times (for the benchmarks): per thread and phase, the
  // time working and waiting at the phase's closing barrier. Each thread's
  // sum lies within the wall time of the advance() that ran the steps;
  // alone, the phases cover most of it (the contact list after the last step
  // is outside every phase) and the thread never waits. (A team's second
  // thread may start late on a loaded machine: its wake-up is outside too.)
  const Scene s = jointed_column();
  for (const int threads : {1, 2}) {
    Simulation sim(s);
    sim.set_threads(threads);
    sim.advance(20);
    CHECK(!sim.phase_times().empty());
    sim.reset_phase_times();
    CHECK(sim.phase_times().empty());  // the control: the warm-up's times are gone
    const auto start = std::chrono::steady_clock::now();
    sim.advance(200);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto& times = sim.phase_times();
    REQUIRE(!times.empty());
    REQUIRE(times.size() <= static_cast<std::size_t>(threads));
    for (const Simulation::PhaseTimes& t : times) {
      double total = 0.0;
      for (int p = 0; p < Simulation::kPhaseCount; ++p) {
        // Every step moves, loops over its pairs and kicks; the broad phase
        // rebuilds and the energy checks come now and then.
        const bool every_step = p == Simulation::kPhaseMove || p == Simulation::kPhasePairs || p == Simulation::kPhaseKick;
        CHECK(t.work[p] >= 0.0);
        if (every_step) CHECK(t.work[p] > 0.0);
        CHECK(t.wait[p] >= 0.0);
        if (times.size() == 1) CHECK(t.wait[p] == 0.0);
        total += t.work[p] + t.wait[p];
      }
      CHECK(total <= wall);
      if (times.size() == 1) CHECK(total >= 0.5 * wall);
    }
  }
}

TEST_CASE("the sweep broad phase with its skin finds exactly the all-pairs candidates", "[simulation]") {
  // The skin list must contain every pair whose boxes overlap now: the run
  // with the sweep is bit-identical to the run testing all pairs, and the
  // list is rebuilt only now and then.
  Scene s = jointed_column();
  Simulation sweep(s);
  s.broad_phase = BroadPhase::kNone;
  Simulation all(s);
  for (int k = 0; k < 20; ++k) {
    sweep.advance(25);
    all.advance(25);
    REQUIRE(sweep.candidate_count() == all.candidate_count());
  }
  CHECK(state_hash(sweep) == state_hash(all));
  CHECK(sweep.broad_phase_rebuilds() >= 1);
  CHECK(sweep.broad_phase_rebuilds() < 500);
}

TEST_CASE("a zero friction angle never produces a tangential force, whatever kt", "[simulation]") {
  // A square lands obliquely on a fixed slab with phi = 0 and kt > 0. A pair
  // that starts sliding with no sliding direction must not fall back to a
  // stick spring on the next step.
  Scene s;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = 1e7;
  s.contact.kt = 1e7;
  s.contact.friction_deg = 0.0;
  // Under the paper's update and the elastic-plastic one alike.
  s.contact.friction_update = GENERATE(FrictionUpdate::kPaper, FrictionUpdate::kReturnMapping);
  s.gravity = {0.0, -9.81};
  s.dt = 1e-4;
  BlockSpec slab, box;
  slab.vertices = rect_vertices(-5, -1, 10, 1);
  slab.fixed = true;
  box.vertices = rect_vertices(0, 0.01, 1, 1);
  box.velocity = {2.0, -1.0};
  s.blocks = {slab, box};
  Simulation sim(s);
  double worst = 0.0;
  int contact_steps = 0;
  while (sim.time() < 0.3) {
    sim.step();
    for (const ContactInfo& c : sim.contacts()) {
      worst = std::max(worst, length(c.tangential_force));
      ++contact_steps;
    }
  }
  CHECK(contact_steps > 100);
  CHECK(worst == 0.0);
  CHECK(sim.velocity(1)[0] == Approx(2.0).epsilon(1e-9));  // no friction: x-velocity kept
}

namespace {
// A 1 m square at rest on a fixed slab inclined at 30 deg, friction 32 deg
// (stable in limit equilibrium: tan 32 > tan 30), with the Sect. 6.2
// penalties (kn 0.5 GPa, kt 1e8 N/m, rho 2700, E 2 GPa), H = 1 m, dt 1e-4 s,
// started at its static penetration (normal force at its equilibrium).
struct SlopeBlock {
  Scene scene;
  Vec2 downhill{};
};
SlopeBlock stable_slope_block(FrictionUpdate update) {
  constexpr double kTheta = 30.0 * 3.14159265358979323846 / 180.0;
  constexpr double kH = 1.0;        // m
  constexpr double kSide = 1.0;     // m
  constexpr double kSlab = 12.0;    // m
  SlopeBlock b;
  Scene& s = b.scene;
  s.materials = {{2700.0, 2e9, 0.3}};
  s.contact.kn = 0.5e9;
  s.contact.kt = 1e8;
  s.contact.friction_deg = 32.0;
  s.contact.h_rule = HRule::kGiven;
  s.contact.h = kH;
  s.contact.friction_update = update;
  s.gravity = {0.0, -9.81};
  s.dt = 1e-4;
  const Vec2 along{std::cos(kTheta), std::sin(kTheta)};
  const Vec2 up = perp_left(along);
  b.downhill = -along;
  // Static penetration of a flat contact: W cos(theta) = 2 kn delta L / H.
  const double weight = 2700.0 * kSide * kSide * 9.81;
  const double delta = weight * std::cos(kTheta) * kH / (2.0 * s.contact.kn * kSide);
  BlockSpec slab, box;
  slab.vertices = {-1.0 * up, kSlab * along - 1.0 * up, kSlab * along, {0.0, 0.0}};
  slab.fixed = true;
  const Vec2 o = 6.0 * along - delta * up;
  box.vertices = {o, o + kSide * along, o + kSide * along + kSide * up, o + kSide * up};
  s.blocks = {slab, box};
  s.initial_overlap = 2.0 * delta;
  return b;
}
}  // namespace

TEST_CASE("friction update: the paper's Eq. 26 is the default", "[simulation]") {
  CHECK(ContactParams{}.friction_update == FrictionUpdate::kPaper);
}

TEST_CASE("friction update: on a slope with phi > theta the paper's rule ratchets the block down, "
          "the return mapping holds it", "[simulation]") {
  // The stick phase overshoots the limit (undamped, gravity applied at
  // t = 0); with the paper's rule every re-stick restarts the tangential
  // spring from zero shear and the block creeps on (full driver numbers:
  // 1.28 m in 3.5 s); the return mapping keeps the shear and the block
  // stops after ~1.5 mm.
  const double t_end = 0.5;  // s
  double slip[2] = {0.0, 0.0}, speed[2] = {0.0, 0.0};
  const FrictionUpdate updates[2] = {FrictionUpdate::kPaper, FrictionUpdate::kReturnMapping};
  for (int k = 0; k < 2; ++k) {
    const SlopeBlock b = stable_slope_block(updates[k]);
    Simulation sim(b.scene);
    const Vec2 c0 = sim.centroid(1);
    sim.advance_to(t_end);
    slip[k] = dot(sim.centroid(1) - c0, b.downhill);
    speed[k] = std::hypot(sim.velocity(1)[0], sim.velocity(1)[1]);
  }
  INFO("slip: paper " << slip[0] << " m, return mapping " << slip[1] << " m; speed " << speed[0] << ", "
                      << speed[1] << " m/s");
  CHECK(slip[0] > 0.02);   // paper's rule: creeping (0.067 m at 0.5 s)
  CHECK(slip[1] < 0.005);  // return mapping: settled (1.5 mm)
  CHECK(speed[1] < 1e-3);
}

TEST_CASE("friction update: continuous sliding is the same with either rule (Sect. 4.3, phi = 10 deg)",
          "[simulation]") {
  // While a pair keeps sliding both rules apply -|fn| tan(phi) s; they differ
  // only in what a re-stick starts from.
  double l[2] = {0.0, 0.0};
  const FrictionUpdate updates[2] = {FrictionUpdate::kPaper, FrictionUpdate::kReturnMapping};
  for (int k = 0; k < 2; ++k) {
    paper::Incline in = paper::incline(10.0, 30.0, 0.2);
    in.scene.contact.friction_update = updates[k];
    Simulation sim(in.scene);
    const Vec2 c0 = sim.centroid(1);
    sim.advance_to(0.2);
    l[k] = dot(sim.centroid(1) - c0, in.downhill);
  }
  CHECK(l[1] == Approx(l[0]).epsilon(1e-9));
  CHECK(l[0] == Approx(paper::incline_distance(9.81, 30.0 * 3.14159265358979323846 / 180.0,
                                               10.0 * 3.14159265358979323846 / 180.0, 0.2))
                    .epsilon(0.05));  // sliding (it leads Eq. 30 by the stick phase, 3 % at 0.2 s)
}


// The simulation pools its blocks' geometry by vertex
// count and its kernels read it through PolygonView. The pool's view and a
// view of a Polygon value with the same vertices and normals give the same
// bits, and polygon(i) hands back the scene's block after 0 steps.
TEST_CASE("pooled block polygons round-trip and read as Polygon values do", "[simulation]") {
  const Scene scene = paper::collapse(15.0).scene;
  Simulation sim(scene);
  REQUIRE(sim.scene_block_count() == static_cast<int>(scene.blocks.size()));
  for (int i = 0; i < sim.scene_block_count(); ++i) {
    const BlockSpec& b = scene.blocks[static_cast<std::size_t>(i)];
    const Polygon expect = make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
    const Polygon got = sim.polygon(i);
    REQUIRE(got.count == expect.count);
    CHECK(std::memcmp(got.v.data(), expect.v.data(), sizeof got.v) == 0);  // the rest zero, as make_polygon leaves it
    CHECK(std::memcmp(got.n.data(), expect.n.data(), sizeof got.n) == 0);
    const PolygonView view = sim.polygon_view(i);
    REQUIRE(view.count == expect.count);
    CHECK(view.v != got.v.data());  // the pool's storage, not a copy
  }
  // A few kernels on the pool's views against the same on Polygon values,
  // once the blocks have settled onto each other (pairs that overlap, with
  // intersection polygons).
  sim.advance(300);
  int overlapping = 0;
  for (int i = 0; i < sim.block_count(); ++i) {
    const PolygonView va = sim.polygon_view(i);
    const Polygon pa = sim.polygon(i);
    const AreaMoments m1 = area_moments(va), m2 = area_moments(pa);
    CHECK(std::memcmp(&m1, &m2, sizeof m1) == 0);
    const Aabb b1 = bounds(va), b2 = bounds(pa);
    CHECK(std::memcmp(&b1, &b2, sizeof b1) == 0);
    CHECK(geometric_tolerance(va) == geometric_tolerance(pa));
    std::array<Bisector, 2 * kMaxVertices> r1{}, r2{};
    const int n1 = bisectors(va, 0.1, SmallEdgeRays::kVirtualAndVertex, r1.data());
    const int n2 = bisectors(pa, 0.1, SmallEdgeRays::kVirtualAndVertex, r2.data());
    REQUIRE(n1 == n2);
    CHECK(std::memcmp(r1.data(), r2.data(), sizeof(Bisector) * static_cast<std::size_t>(n1)) == 0);
    for (int j = 0; j < sim.block_count(); ++j) {
      if (j == i || !aabb_overlap(b1, bounds(sim.polygon_view(j)))) continue;
      const PolygonView vb = sim.polygon_view(j);
      const Polygon pb = sim.polygon(j);
      const double tol = pair_tolerance(va, vb);
      CHECK(tol == pair_tolerance(pa, pb));
      Polygon ip1, ip2;
      const OverlapState s1 = overlap_and_intersection(va, vb, tol, ip1, nullptr);
      const OverlapState s2 = overlap_and_intersection(pa, pb, tol, ip2, nullptr);
      REQUIRE(s1 == s2);
      REQUIRE(ip1.count == ip2.count);
      CHECK(std::memcmp(ip1.v.data(), ip2.v.data(), sizeof(Vec2) * static_cast<std::size_t>(ip1.count)) == 0);
      CHECK(std::memcmp(ip1.n.data(), ip2.n.data(), sizeof(Vec2) * static_cast<std::size_t>(ip1.count)) == 0);
      if (s1 == OverlapState::kOverlapping) ++overlapping;
    }
  }
  CHECK(overlapping > 0);
  // A move through a span over pool-like storage (count vertices, then
  // count normals) and through a Polygon value: the same vertices.
  Polygon moved = sim.polygon(0);
  std::vector<Vec2> store(static_cast<std::size_t>(2 * moved.count));
  for (int k = 0; k < moved.count; ++k) {
    store[static_cast<std::size_t>(k)] = moved.vertex(k);
    store[static_cast<std::size_t>(moved.count + k)] = moved.normal(k);
  }
  const PolygonSpan span(moved.count, store.data(), store.data() + moved.count);
  Vec6 d;
  d << 1e-3, -2e-3, 1e-4, 1e-5, -1e-5, 2e-5;
  const Vec2 c = area_moments(moved).centroid;
  CHECK(rotate_and_displace_vertices(moved, c, d) == rotate_and_displace_vertices(span, c, d));
  CHECK(displace_vertices(moved, c, d) == displace_vertices(span, c, d));
  const PolygonGeometry g1 = update_polygon_geometry(moved), g2 = update_polygon_geometry(span);
  CHECK(std::memcmp(&g1, &g2, sizeof g1) == 0);
  CHECK(std::memcmp(moved.v.data(), store.data(), sizeof(Vec2) * static_cast<std::size_t>(moved.count)) == 0);
  CHECK(std::memcmp(moved.n.data(), store.data() + moved.count, sizeof(Vec2) * static_cast<std::size_t>(moved.count)) ==
        0);
}

TEST_CASE("a moved simulation runs on: the same bits as one never moved", "[simulation]") {
  // The contact sides point into the geometry pool and the bisector store;
  // a move keeps those buffers (a copy, which would share them, is
  // deleted). Negative control of the comparison: a shorter run differs.
  static_assert(!std::is_copy_constructible<Simulation>::value, "a copy would read the original's geometry");
  static_assert(!std::is_copy_assignable<Simulation>::value, "a copy would read the original's geometry");
  const Scene scene = paper::collapse(15.0).scene;
  Simulation reference(scene);
  reference.advance(200);
  auto original = std::make_unique<Simulation>(scene);
  original->advance(100);
  Simulation moved(std::move(*original));
  original.reset();
  moved.advance(50);
  Simulation assigned(scene);
  assigned = std::move(moved);
  assigned.advance(50);
  CHECK(state_hash(assigned) == state_hash(reference));
  Simulation shorter(scene);
  shorter.advance(150);
  CHECK(state_hash(shorter) != state_hash(reference));
}

TEST_CASE("a simulation keeps the scene's settings, not its blocks", "[simulation]") {
  Scene s = paper::symmetric_stack().scene;
  s.materials.push_back({2500.0, 2e9, 0.2});
  s.blocks[1].material = 1;
  Simulation sim(s);
  CHECK(sim.scene().blocks.empty());
  CHECK(sim.scene().materials.size() == 2);
  CHECK(sim.scene().boundaries.size() == s.boundaries.size());
  CHECK(sim.scene().contact.kn == s.contact.kn);
  CHECK(sim.scene().duration == s.duration);
  CHECK(sim.scene().guards.max_step_motion == s.guards.max_step_motion);
  CHECK(sim.scene_block_count() == static_cast<int>(s.blocks.size()));
  for (int i = 0; i < sim.scene_block_count(); ++i) CHECK(sim.material(i) == s.blocks[static_cast<std::size_t>(i)].material);
  for (int i = sim.scene_block_count(); i < sim.block_count(); ++i) CHECK(sim.material(i) == -1);
}
