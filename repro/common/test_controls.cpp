// Negative controls of the claim rows: every check that
// names a control here ("repro_controls: <test name>") is run with the
// driver's own criterion on a deliberately wrong configuration that the claim
// depends on, and must come out FAIL. A criterion that passes anyway checks
// nothing, and this test fails.
#include <catch2/catch.hpp>  // main(): Catch2::Catch2WithMain (CMakeLists.txt)

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/3_1_contact_statements/contact_statements.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/5_4_extreme_geometry/extreme_geometry.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/B_7_contact_comparison/contact_comparison.hpp"
#include "repro/6_2_toppling_slumping/toppling_slumping.hpp"
#include "repro/S1_work_precision/work_precision.hpp"
#include "repro/S2_stability_maps/maps.hpp"
#include "repro/S2_stability_maps/resting.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/S3_extreme_cases/penetration_cells.hpp"
#include "repro/4_1_two_squares/two_squares.hpp"
#include "repro/4_2_symmetric_stack/symmetric_stack.hpp"
#include "repro/4_3_incline/incline.hpp"
#include "repro/5_1_bouncing_block/bouncing_block.hpp"
#include "repro/5_2_small_angles/small_angles.hpp"
#include "repro/5_3_small_edges/small_edges.hpp"
#include "repro/common/claims.hpp"

namespace {

// The row with key `key`; fails the test if there is none or it is not a check.
const repro::Claim& row(const std::vector<repro::Claim>& rows, const std::string& key) {
  for (const repro::Claim& c : rows)
    if (c.key == key) {
      REQUIRE(c.kind == repro::Kind::kCheck);
      return c;
    }
  FAIL("no row with key " << key);
  return rows.front();
}

// The control named in the row must be this test case (so that the report's
// count of controlled checks names real tests).
void names_control(const repro::Claim& c, const std::string& test) {
  CHECK(c.control == "repro_controls: " + test);
}

}  // namespace

// --- Sects. 3.1.2 and 3.2.1, contact statements ---------------------------------
TEST_CASE("3.1.2 entrance block: FAIL when A is not reflected", "[controls][3.1]") {
  // E built as B + A + a0: a0 inside it says nothing about the overlap.
  namespace cs = contact_statements;
  const std::vector<cs::Pair> pairs = cs::random_pairs(1500, 1);
  CHECK(cs::entrance_row(pairs).pass);
  const repro::Claim c = cs::entrance_row(pairs, cs::Variant::kEntranceWithoutReflection);
  CHECK_FALSE(c.pass);
  CHECK(c.key == cs::kKeyEntrance);
}

TEST_CASE("3.2.1 energy gradient: FAIL when the force leaves out TP's potential", "[controls][3.2]") {
  // The force integrates phi_CP alone (TP's kn / H = 0 in the force, not in
  // the energy): no longer the gradient of the energy.
  namespace cs = contact_statements;
  const std::vector<cs::Pair> pairs = cs::random_pairs(1000, 2);
  CHECK(cs::gradient_row(pairs, dda::Integration::kExactEnvelope).pass);
  const repro::Claim c =
      cs::gradient_row(pairs, dda::Integration::kExactEnvelope, cs::Variant::kForceWithoutTargetPotential);
  CHECK_FALSE(c.pass);
  CHECK(c.key == cs::kKeyGradientExact);
}

TEST_CASE("3.2.4 moment about pg: FAIL about the IP centroid", "[controls][3.2]") {
  // The same energy derivative taken about the IP centroid: the force's
  // line misses it, so the moment there is not zero.
  namespace cs = contact_statements;
  const std::vector<cs::Pair> pairs = cs::random_pairs(1000, 3);
  CHECK(cs::moment_row(pairs, dda::Integration::kExactEnvelope).pass);
  const repro::Claim c = cs::moment_row(pairs, dda::Integration::kExactEnvelope, cs::Variant::kMomentAboutCentroid);
  CHECK_FALSE(c.pass);
  CHECK(c.key == cs::kKeyMomentExact);
}

// --- Sect. 3.2.2, potential fields: the checks shared by Figs. 4b and 5 ---------
TEST_CASE("3.2.2 potential field: FAIL on an offset, a shifted and a doubled field", "[controls][3.2.2]") {
  // The Fig. 4b polygon's grid filled with Eq. 12's field and with three
  // wrong ones; add_common_claims gives rows [0] zero on the boundary and
  // positive inside, [1] defined everywhere inside, [2] slope <= kn/H.
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> pts = pf::small_edge_polygon();
  const dda::Polygon poly = dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
  auto rows = [&](auto phi) {
    pf::Grid g = pf::make_grid(pts);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t k = g.idx(i, j);
        g.inside[k] = dda::locate_point(poly, g.at(i, j)) == dda::PointLocation::kInside;
        g.phi[k] = phi(g.at(i, j));
      }
    std::vector<repro::Claim> c;
    pf::add_common_claims(c, "control", g, pf::boundary_max_abs(pts, phi));
    REQUIRE(c.size() == 3);
    return c;
  };
  const double k = pf::kKn / pf::kH;
  auto eq12 = [&](dda::Vec2 p) { return dda::potential(poly, p, pf::kKn, pf::kH); };
  const auto good = rows(eq12);
  for (const repro::Claim& c : good) CHECK(c.pass);
  // Offset by 1 cm: not zero on the boundary.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return eq12(p) + 0.01 * k; })[0].pass);
  // Shifted 5 cm inward: phi <= 0 in a band inside the boundary.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return k * (dda::exit_distance(poly, p) - 0.05); })[1].pass);
  // Doubled (H / 2 in the field only): slope 2 kn/H.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return 2.0 * eq12(p); })[2].pass);
}

// --- S1 work precision: the order, round-off and plateau criteria -------------
namespace {
// The errors of measure `m` of case `c` at four dts halving from `dt_hi`,
// and their observed order (as the S1 sweep fits it).
struct Curve {
  std::vector<double> dts, errors;
  repro::stab::Order order;
};
Curve s1_curve(const s1::Case& c, std::size_t m, double dt_hi) {
  Curve k;
  for (int i = 3; i >= 0; --i) k.dts.push_back(std::ldexp(dt_hi, -i));
  for (double dt : k.dts) {
    const s1::RunOut r = s1::monitored_run(c, dt);
    REQUIRE(r.ok);
    k.errors.push_back(r.errors[m]);
  }
  k.order = repro::stab::observed_order(k.dts, k.errors, c.measures[m].floor);
  return k;
}
s1::Case s1_case(const std::string& scene) {
  for (const s1::Case& c : s1::all_cases())
    if (c.scene == scene) return c;
  FAIL("no S1 case " << scene);
  return {};
}
constexpr std::size_t kVertexPosition = 1;  // free rotation: area, vertex position
constexpr std::size_t kArea = 0;
constexpr std::size_t kDampedPosition = 0;  // damped flight: vertex position, kinetic energy, budget
}  // namespace

TEST_CASE("S1 order 2: FAIL on a first-order configuration", "[controls][S1]") {
  // The spinning block with the paper's linearised rotation: first order.
  const Curve k = s1_curve(s1::free_rotation_cases()[0], kVertexPosition, 2e-4);
  CHECK(s1::order_met(k.order, 1.0, 0.3));
  CHECK_FALSE(s1::order_met(k.order, 2.0, 0.3));
}

TEST_CASE("S1 order 1: FAIL on a second-order configuration", "[controls][S1]") {
  // The damped flight (exact rotation, semi-implicit mass damping): second order.
  const Curve k = s1_curve(s1_case("damped flight"), kDampedPosition, 2e-4);
  CHECK(s1::order_met(k.order, 2.0, 0.3));
  CHECK_FALSE(s1::order_met(k.order, 1.0, 0.3));
}

TEST_CASE("S1 round-off: FAIL on a first-order configuration", "[controls][S1]") {
  // The paper's rotation grows a spinning block: its area is off by far more
  // than round-off; the exact rotation keeps it (the criterion passes).
  const Curve paper = s1_curve(s1::free_rotation_cases()[0], kArea, 2e-4);
  const Curve exact = s1_curve(s1::free_rotation_cases()[1], kArea, 2e-4);
  auto largest = [](const Curve& k) { return *std::max_element(k.errors.begin(), k.errors.end()); };
  constexpr double kLevel = 1e-10;  // the largest level of the S1 round-off rows
  CHECK(s1::roundoff_met(largest(exact), kLevel));
  CHECK_FALSE(s1::roundoff_met(largest(paper), kLevel));
}

TEST_CASE("S1 plateau: FAIL on a converging curve", "[controls][S1]") {
  const Curve k = s1_curve(s1_case("damped flight"), kDampedPosition, 2e-4);
  CHECK_FALSE(s1::plateau_met(k.order));
}

namespace {
// The S1 case of `scene` whose option contains `option`.
s1::Case s1_case(const std::string& scene, const std::string& option) {
  for (const s1::Case& c : s1::all_cases())
    if (c.scene == scene && c.option.find(option) != std::string::npos) return c;
  FAIL("no S1 case " << scene << " / " << option);
  return {};
}
std::size_t measure_index(const s1::Case& c, const std::string& name) {
  for (std::size_t m = 0; m < c.measures.size(); ++m)
    if (c.measures[m].name == name) return m;
  FAIL("no measure " << name << " in " << c.scene);
  return 0;
}
}  // namespace

TEST_CASE("S1 model error: FAIL with the friction start-up option", "[controls][S1]") {
  // With the start-up option B follows Eq. 30 (error ~1e-4): the gap to
  // Eq. 30 is no longer a model error far above the dt error. The dt error
  // here: the trajectory at the paper's dt against a run at dt / 16.
  const s1::Case c = s1_case("4.3 incline", "friction start-up");
  const s1::RunOut run = s1::monitored_run(c, c.paper_dt), ref = s1::monitored_run(c, c.paper_dt / 16.0, false);
  REQUIRE(run.ok);
  REQUIRE(ref.ok);
  REQUIRE(run.samples.size() == ref.samples.size());
  double traj = 0.0;
  for (std::size_t k = 0; k < run.samples.size(); ++k)
    traj = std::max(traj, repro::stab::max_abs_difference(run.samples[k], ref.samples[k]));
  const double eq30 = run.errors[measure_index(c, "Eq. 30")];
  INFO("Eq. 30 rel. error " << eq30 << ", trajectory error " << traj << " m");
  CHECK_FALSE(s1::model_error_dominates(eq30, traj));
}

TEST_CASE("S1 Eq. 30 at every dt: FAIL with the paper's start", "[controls][S1]") {
  // The row's criterion on the paper's start from rest (no settling): the
  // stick-phase lead puts B 7 % beyond Eq. 30 at the paper's dt.
  const s1::Case c = s1_case("4.3 incline", "phi = 20 deg, paper");
  const s1::RunOut run = s1::monitored_run(c, c.paper_dt);
  REQUIRE(run.ok);
  const double eq30 = run.errors[measure_index(c, "Eq. 30")];
  INFO("Eq. 30 rel. error " << eq30);
  CHECK_FALSE(s1::within_eq30(eq30));
}

TEST_CASE("S1 static penetration: FAIL at the other H rule's penetration", "[controls][S1]") {
  // Released at the static penetration of the other H rule, A is not at
  // rest: it moves towards its own, far more than 1e-6 of it.
  const double unified = s1::resting_block(dda::HRule::kMinMaxEdge, 0.0).static_pen();
  const double inscribed = s1::resting_block(dda::HRule::kInscribedRadius, 0.0).static_pen();
  CHECK_FALSE(s1::stays_at(s1::resting_deviation(dda::HRule::kMinMaxEdge, inscribed), unified));
  CHECK_FALSE(s1::stays_at(s1::resting_deviation(dda::HRule::kInscribedRadius, unified), inscribed));
  CHECK(s1::stays_at(s1::resting_deviation(dda::HRule::kMinMaxEdge, unified), unified));
}

TEST_CASE("S1 energy budget: FAIL without the dissipated sliding work", "[controls][S1]") {
  // The budget rows' criterion on the sliding block with friction, at the
  // paper's dt: with the sliding work in the budget it closes; without it,
  // the energy friction took is missing and the row must FAIL.
  for (const char* phi : {"phi = 10 deg", "phi = 20 deg, paper"}) {
    const s1::Case c = s1_case("4.3 incline", phi);
    dda::Scene sc = c.sc;
    sc.dt = c.paper_dt;
    dda::Simulation sim(sc);
    s1::Budget with, without;
    without.count_dissipated = false;
    with.step(sim);
    without.step(sim);
    while (sim.time() < sc.duration - 0.5 * sim.dt()) {
      sim.step();
      with.step(sim);
      without.step(sim);
    }
    INFO(phi << ": budget error " << with.error() << " with, " << without.error() << " without the sliding work");
    CHECK(s1::budget_closes(with.error()));
    CHECK_FALSE(s1::budget_closes(without.error()));
  }
}

// --- 5.4 extreme geometry: the "clean" criterion -----------------------------------
namespace {
extreme::Case extreme_case(const std::string& label) {
  for (const extreme::Case& c : extreme::make_cases())
    if (c.label == label) return c;
  FAIL("no 5.4 case " << label);
  return {};
}
}  // namespace

TEST_CASE("5.4 clean: FAIL on a damped, an asymmetric and a pierced run", "[controls][5.4]") {
  // Each run below differs from a clean paper-size case in one thing the
  // criterion must see.
  const extreme::Case bounce = extreme_case("bouncing block, B height 0.1 m, unified H");
  const extreme::Outcome ok = extreme::attempt(bounce, bounce.scene.dt, true);
  CHECK(ok.clean);
  // Energy: mass damping (1 1/s) takes energy out; the run is otherwise clean.
  extreme::Case damped = bounce;
  damped.scene.damping.mass = 1.0;
  const extreme::Outcome d = extreme::attempt(damped, damped.scene.dt, true);
  INFO(d.verdict);
  CHECK_FALSE(d.clean);
  CHECK(d.energy_bad);
  // Symmetry: the upper 5 deg triangle drifts sideways at 1 cm/s.
  extreme::Case tri = extreme_case("triangles, apex angle 5 deg");
  CHECK(extreme::attempt(tri, tri.scene.dt, true).clean);
  tri.scene.blocks[static_cast<std::size_t>(tri.pushed)].velocity.x += 0.01;
  const extreme::Outcome a = extreme::attempt(tri, tri.scene.dt, true);
  INFO(a.verdict);
  CHECK_FALSE(a.clean);
  CHECK(a.asymmetric);
  // Flip-through: the 1 mm thin B with every guard off: A goes through.
  extreme::Case thin = extreme_case("bouncing block, B height 0.001 m, unified H");
  thin.scene.guards.max_penetration = 0.0;
  thin.scene.guards.max_approach_energy = 0.0;
  const extreme::Outcome f = extreme::attempt(thin, thin.scene.dt, false);
  INFO(f.verdict);
  CHECK_FALSE(f.clean);
  CHECK((f.flip || f.pierced));
}

// --- Sect. 6.2, toppling and slumping: the mechanism criteria ------------------
TEST_CASE("6.2 toppling, slumping, premise: FAIL with locked joints, a rough base and a gentle friction",
          "[controls][6.2]") {
  // Each criterion of the 6.2 rows on a configuration that removes what it
  // looks for (3.5 s, the paper's duration; about 5 s of runs).
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  // Joints locked (80 deg): nothing topples, and the joints carry no slip
  // beyond what the same locked model does.
  dda::Scene locked = ts.scene;
  locked.contact.friction_deg = 80.0;
  const topple::Control l = topple::run_control(ts, locked, ts.side, 1, "control: joints locked");
  CHECK_FALSE(topple::topples(l.right, l.right));
  CHECK_FALSE(topple::joints_carry_slip(l.left, l.left));
  // A rough base (80 deg on the sliding base): the left slope cannot slide
  // down it, so it does not slump.
  dda::Scene rough = ts.scene;
  rough.contact.friction_rules = {{dda::paper::kRockGroup, dda::paper::kBoundaryGroup, 80.0}};
  const topple::Control r = topple::run_control(ts, rough, ts.side, 1, "control: rough base");
  INFO("left base slip on a rough base " << r.left.base_slip << " m");
  CHECK_FALSE(topple::slumps(r.left, r.right));
  // Each slope as one block on a base with 20 deg friction (< the 30 deg
  // slope): it slides, and the premise row must see it.
  dda::Scene gentle = topple::one_block_per_slope(ts);
  gentle.contact.friction_rules = {{dda::paper::kRockGroup, dda::paper::kBoundaryGroup, 20.0}};
  const topple::Control g = topple::run_control(ts, gentle, {-1, +1}, 1, "control: base friction 20 deg");
  INFO("one block per slope, base friction 20 deg: left slip " << g.left.base_slip << " m");
  CHECK_FALSE(topple::stays(g));
}

TEST_CASE("6.2 stable run: FAIL at twice the critical step", "[controls][6.2]") {
  // The valley model at dt = 2 x the predicted critical step for 200 steps
  // (or until a guard stops it): the stability row must see it.
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  dda::Scene over = ts.scene;
  over.dt_fraction = 2.0;
  topple::Health h;
  try {
    dda::Simulation sim(over);
    h.sample(sim);
    for (int k = 0; k < 200; ++k) {
      sim.step();
      h.sample(sim);
    }
  } catch (const dda::SimulationError& e) {
    INFO("stopped: " << e.what());
  }
  INFO("dt/dt_crit at most " << h.ratio_max << ", energy rise " << h.rise << " J/m of " << h.e0);
  CHECK_FALSE(topple::runs_stably(h));
}

TEST_CASE("6.2 ratchet diagnosis: FAIL when both runs use the paper's update", "[controls][6.2]") {
  // The diagnosis compares the late slip of the elastic-plastic update with
  // the paper's rule; with the paper's rule on both sides (each slope as one
  // block, 3.5 s) the two are the same and the row must FAIL.
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  const topple::Control c = topple::run_control(ts, topple::one_block_per_slope(ts), {-1, +1}, 1, "control: ratchet");
  const double late = c.left.base_slip - c.left_half.base_slip;
  INFO("late slip, paper rule " << late << " m");
  CHECK_FALSE(topple::ratchet_explains(late, late));
}

// --- S3 extreme cases: the row criterion ------------------------------------------
TEST_CASE("S3 rows: FAIL with the penetration guard off and with the wrong expected velocities", "[controls][S3]") {
  auto find = [](const std::string& name, const std::string& parameter) {
    for (const s3::Extreme& e : s3::cases())
      if (e.name == name && e.parameter == parameter) return e;
    FAIL("no S3 case " << name << " / " << parameter);
    return s3::Extreme{};
  };
  // 100 m/s: with the guards the run stops before the blocks cross (PASS);
  // without the penetration and approach-energy checks they pass through.
  s3::Extreme fast = find("impact speed", "100 m/s");
  CHECK(s3::row_verdict(fast, s3::run(fast, 0.0)).first);
  fast.scene.guards.max_penetration = 0.0;
  fast.scene.guards.max_approach_energy = 0.0;
  const s3::Outcome through = s3::run(fast, 0.0);
  INFO("guard off: " << through.class_name() << ", centroids swapped at " << through.t_swap << " s");
  CHECK_FALSE(s3::row_verdict(fast, through).first);
  // 1 m/s: the velocities are exchanged (PASS); against the answer of a
  // perfectly inelastic collision (both at v / 2) the same run must FAIL.
  s3::Extreme slow = find("impact speed", "1 m/s");
  CHECK(s3::row_verdict(slow, s3::run(slow, 0.0)).first);
  slow.va_expected = slow.vb_expected = 0.5 * slow.v0;
  CHECK_FALSE(s3::row_verdict(slow, s3::run(slow, 0.0)).first);
}

// --- Paper B Sect. 6, two prisms ---------------------------------------------------
namespace {
// Block j (index 1) of a DDA or CDEM scene made `factor` times as dense,
// through a material of its own.
template <class SceneT>
void make_j_denser(SceneT& s, double factor) {
  s.materials.push_back(s.materials[static_cast<std::size_t>(s.blocks[1].material)]);
  s.materials.back().density *= factor;
  s.blocks[1].material = static_cast<int>(s.materials.size()) - 1;
}
// The rows of a run of the prisms scene with geometry g, block j
// j_density_factor times as dense and fixed if asked; the coarse run beside
// it is the paper's scene without subdivision.
// mode: the subdivision (the default: Sect. 5 as written, the sub-model; the
// rows beside its failing ones use the in-place option).
std::vector<repro::Claim> prism_rows(const dda::cdem::PrismGeometry& g, double j_density_factor, bool j_fixed,
                                     dda::cdem::SubdivisionMode mode = dda::cdem::SubdivisionMode::kSubModel) {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = mode;
  dda::cdem::CdemScene s = dda::cdem::two_prisms(2, o, g);
  if (j_density_factor != 1.0) make_j_denser(s, j_density_factor);
  s.blocks[1].fixed = j_fixed;
  dda::cdem::CdemOptions coarse;
  coarse.subdivision = false;
  return prisms::rows(prisms::simulate(s), prisms::simulate(dda::cdem::two_prisms(2, coarse)));
}
// The rows that name `control`, with their verdicts.
std::vector<bool> verdicts_of(const std::vector<repro::Claim>& rows, const char* control) {
  std::vector<bool> v;
  for (const repro::Claim& c : rows)
    if (c.control == control) v.push_back(c.pass);
  return v;
}
}  // namespace

// Each in both modes: the sub-model (the paper's rows) and the in-place
// option (the rows beside the sub-model's failing ones).
TEST_CASE("B-6 touch: FAIL with the gap 0.1 m wider", "[controls][B-6]") {
  for (auto mode : {dda::cdem::SubdivisionMode::kSubModel, dda::cdem::SubdivisionMode::kInPlace}) {
    const std::vector<bool> paper = verdicts_of(prism_rows({}, 1.0, false, mode), prisms::kControlTouch);
    REQUIRE(paper.size() == 2);
    for (bool v : paper) CHECK(v);
    dda::cdem::PrismGeometry g;
    g.gap += 0.1;  // touch at 1.1 / 3 s
    for (bool v : verdicts_of(prism_rows(g, 1.0, false, mode), prisms::kControlTouch)) CHECK_FALSE(v);
  }
}

TEST_CASE("B-6 exchange: FAIL with block j twice as dense", "[controls][B-6]") {
  // Unequal masses: j leaves at 2 m / (m + M) v = 2 m/s, not i's 3 m/s.
  for (auto mode : {dda::cdem::SubdivisionMode::kSubModel, dda::cdem::SubdivisionMode::kInPlace}) {
    const std::vector<bool> wrong = verdicts_of(prism_rows({}, 2.0, false, mode), prisms::kControlExchange);
    REQUIRE(wrong.size() == 2);
    for (bool v : wrong) CHECK_FALSE(v);
  }
  // The real run: the in-place option passes both (the sub-model's FAILs are
  // its rows' paper_method verdicts).
  for (bool v : verdicts_of(prism_rows({}, 1.0, false, dda::cdem::SubdivisionMode::kInPlace), prisms::kControlExchange))
    CHECK(v);
}

TEST_CASE("B-6 momentum: FAIL with block j fixed", "[controls][B-6]") {
  // A fixed j is a wall: i bounces back and the momentum is not conserved.
  for (auto mode : {dda::cdem::SubdivisionMode::kSubModel, dda::cdem::SubdivisionMode::kInPlace}) {
    const std::vector<bool> wrong = verdicts_of(prism_rows({}, 1.0, true, mode), prisms::kControlMomentum);
    REQUIRE(wrong.size() == 1);
    CHECK_FALSE(wrong[0]);
  }
  const std::vector<bool> inplace =
      verdicts_of(prism_rows({}, 1.0, false, dda::cdem::SubdivisionMode::kInPlace), prisms::kControlMomentum);
  REQUIRE(inplace.size() == 1);
  CHECK(inplace[0]);
}

// --- A against B on the same collisions (B-7): the squares at the base dt ---------
namespace {
compare::SceneDef squares() {
  for (const compare::SceneDef& d : compare::scene_defs())
    if (d.name == "squares") return d;
  FAIL("no B-7 squares scene");
  return {};
}
struct Runs {
  std::vector<compare::Result> a, b, b0;
};
Runs base_runs(const compare::SceneDef& d) {
  return {compare::run_sweep(d, "A", nullptr, true), compare::run_sweep(d, "B", nullptr, true),
          compare::run_sweep(d, "B0", nullptr, true)};
}
}  // namespace

TEST_CASE("B-7 touch: FAIL against a wrong time of impact", "[controls][B-7]") {
  compare::SceneDef d = squares();
  const Runs ok = base_runs(d);
  CHECK(compare::touch_ok(ok.a, ok.b, ok.b0));
  d.t_touch_exact = 0.45;  // s: the reference of a 0.45 m gap; the scene's is 0.5 m
  const Runs wrong = base_runs(d);
  CHECK_FALSE(compare::touch_ok(wrong.a, wrong.b, wrong.b0));
}

TEST_CASE("B-7 momentum: FAIL with block j fixed", "[controls][B-7]") {
  compare::SceneDef d = squares();
  const auto dda_scene = d.dda_scene;
  const auto cdem_scene = d.cdem_scene;
  d.dda_scene = [dda_scene] {
    dda::Scene s = dda_scene();
    s.blocks[1].fixed = true;
    return s;
  };
  d.cdem_scene = [cdem_scene](bool sub) {
    dda::cdem::CdemScene s = cdem_scene(sub);
    s.blocks[1].fixed = true;
    return s;
  };
  const Runs wrong = base_runs(d);
  CHECK_FALSE(compare::momentum_ok(wrong.a, wrong.b, wrong.b0));
}

TEST_CASE("B-7 exchange: FAIL with block j twice as dense", "[controls][B-7]") {
  compare::SceneDef d = squares();
  const Runs ok = base_runs(d);
  CHECK(compare::exchange_ok(ok.a.front(), ok.b.front()));
  const auto dda_scene = d.dda_scene;
  const auto cdem_scene = d.cdem_scene;
  d.dda_scene = [dda_scene] {
    dda::Scene s = dda_scene();
    make_j_denser(s, 2.0);
    return s;
  };
  d.cdem_scene = [cdem_scene](bool sub) {
    dda::cdem::CdemScene s = cdem_scene(sub);
    make_j_denser(s, 2.0);
    return s;
  };
  const Runs wrong = base_runs(d);
  CHECK_FALSE(compare::exchange_ok(wrong.a.front(), wrong.b.front()));
}

// --- Sect. 4.1, two squares --------------------------------------------------
TEST_CASE("4.1 velocity exchange: FAIL when B is twice as heavy", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.materials.push_back(s.materials[0]);
  s.materials[1].density *= 2.0;  // unequal masses: velocities are not exchanged
  s.blocks[1].material = 1;
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyAStops).pass);
  names_control(row(rows, two_squares::kKeyAStops), "4.1 velocity exchange: FAIL when B is twice as heavy");
  CHECK_FALSE(row(rows, two_squares::kKeyBLeaves).pass);
  names_control(row(rows, two_squares::kKeyBLeaves), "4.1 velocity exchange: FAIL when B is twice as heavy");
}

TEST_CASE("4.1 momentum: FAIL when B is fixed", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.blocks[1].fixed = true;  // a wall: A bounces back, momentum is not conserved
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyMomentum).pass);
  names_control(row(rows, two_squares::kKeyMomentum), "4.1 momentum: FAIL when B is fixed");
}

TEST_CASE("4.1 energy: FAIL with mass damping", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.damping.mass = 1.0;  // 1/s: A loses most of its kinetic energy within the 1 s run
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyEnergy).pass);
  names_control(row(rows, two_squares::kKeyEnergy), "4.1 energy: FAIL with mass damping");
}

// --- Sect. 4.2, symmetric stack --------------------------------------------------
TEST_CASE("4.2 symmetry: FAIL when the impactor drifts sideways", "[controls][4.2]") {
  dda::paper::SymmetricStack st = dda::paper::symmetric_stack();
  // Symmetric at t = 0, but the impactor drifts sideways at 2.5 % of its
  // 2 m/s fall: the asymmetry must come from the motion, not the start.
  constexpr double kSideSpeed = 0.05;  // m/s
  st.scene.blocks.back().velocity.x = kSideSpeed;
  const repro::Claim c = symmetric_stack::row(symmetric_stack::run(st, nullptr, nullptr));
  CHECK_FALSE(c.pass);
  CHECK(c.control == "repro_controls: 4.2 symmetry: FAIL when the impactor drifts sideways");
}

// --- Sect. 4.3, incline ----------------------------------------------------------
TEST_CASE("4.3 Eq. 30 with friction: FAIL with friction off", "[controls][4.3]") {
  for (double phi : {10.0, 20.0}) {
    dda::paper::Incline in = dda::paper::incline(phi);
    in.scene.contact.kt = 0.0;  // friction off: B slides as on a frictionless plane
    const repro::Claim c = incline::eq30_row(phi, incline::run(in, nullptr, phi, dda::FrictionUpdate::kPaper));
    CHECK_FALSE(c.pass);
    CHECK(c.control == incline::kControlEq30Friction);
  }
  // The other configurations whose rows name this control, each judged
  // against Eq. 30 at phi = 20 deg without friction: H = 1 m, B starting
  // just touching, and the start-up option (which needs kt > 0 to settle:
  // there the friction angle is 0 instead).
  const auto paper = dda::FrictionUpdate::kPaper;
  dda::paper::Incline h1 = dda::paper::incline(20.0, 30.0, 1.0, true, 1.0);
  h1.scene.contact.kt = 0.0;
  CHECK_FALSE(incline::eq30_met(incline::run(h1, nullptr, 20.0, paper)));
  dda::paper::Incline touching = dda::paper::incline(20.0, 30.0, 1.0, false);
  touching.scene.contact.kt = 0.0;
  CHECK_FALSE(incline::eq30_met(incline::run(touching, nullptr, 20.0, paper)));
  CHECK_FALSE(incline::eq30_met(incline::run(incline::with_start_up(dda::paper::incline(0.0)), nullptr, 20.0, paper)));
  CHECK_FALSE(incline::eq30_met(
      incline::run(incline::with_start_up(dda::paper::incline(0.0, 30.0, 1.0, true, 1.0)), nullptr, 20.0, paper)));
}

TEST_CASE("4.3 Eq. 30 without friction: FAIL with friction on", "[controls][4.3]") {
  // The phi = 0 row judged on a run with the 10 deg friction of the next case.
  const repro::Claim c =
      incline::eq30_row(0.0, incline::run(dda::paper::incline(10.0), nullptr, 0.0, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(c.pass);
  CHECK(c.control == repro::control_test(incline::kControlEq30Frictionless));
  // The phi = 0 start-up option's row, on the option's run with 10 deg friction.
  CHECK_FALSE(incline::eq30_met(incline::run(incline::with_start_up(dda::paper::incline(10.0)), nullptr, 0.0,
                                             dda::FrictionUpdate::kPaper)));
}

TEST_CASE("4.3 creep: FAIL on a slope steeper than the friction angle", "[controls][4.3]") {
  // With a friction angle of 15 deg on the 20 deg slope B never stops: it
  // accelerates downhill at g (sin 20 - cos 20 tan 15) = 0.88 m/s^2, so the
  // "creep" after the would-be stop is a slide, with either update.
  for (dda::FrictionUpdate u : {dda::FrictionUpdate::kPaper, dda::FrictionUpdate::kReturnMapping}) {
    const incline::Creep c = incline::creep(u, 15.0);
    INFO("rate " << c.rate << " m/s");
    CHECK_FALSE(incline::creep_stopped(c));
  }
  CHECK(incline::creep_stopped(incline::creep(dda::FrictionUpdate::kReturnMapping)));
}

TEST_CASE("4.3 rest: FAIL with friction off", "[controls][4.3]") {
  dda::paper::Incline in = dda::paper::incline(incline::kRestPhi);
  in.scene.contact.kt = 0.0;  // friction off: the block slides down the 30 deg slope
  const repro::Claim c =
      incline::rest_row(incline::run(in, nullptr, incline::kRestPhi, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(c.pass);
  CHECK(c.control == std::string("repro_controls: ") + incline::kControlRest);
  // The start-up option's row (settling needs kt > 0: friction angle 0 instead).
  const repro::Claim s = incline::rest_row(incline::run(incline::with_start_up(dda::paper::incline(0.0)), nullptr,
                                                        incline::kRestPhi, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(s.pass);
}

// --- Sect. 5.1, bouncing block ----------------------------------------------------
TEST_CASE("5.1 H comparison: FAIL with the H rules swapped", "[controls][5.1]") {
  // The wrong H rule: the runs judged as 'unified H' use the inscribed radius
  // and the other way round.
  using dda::HRule;
  const double diff_inscribed = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kInscribedRadius, "c1"),
                                                               bouncing_block::run(1.0, HRule::kInscribedRadius, "c2"));
  const double diff_unified = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kMinMaxEdge, "c1"),
                                                             bouncing_block::run(1.0, HRule::kMinMaxEdge, "c2"));
  const repro::Claim swapped = bouncing_block::comparison_row(diff_inscribed, diff_unified);
  CHECK_FALSE(swapped.pass);
  CHECK(swapped.control == "repro_controls: 5.1 H comparison: FAIL with the H rules swapped");
}

TEST_CASE("5.1 sane run: FAIL with mass damping", "[controls][5.1]") {
  // 1/s: A loses energy in its fall and bounce, so the undamped run's energy
  // criterion must fail (the criterion also checks flip-through and symmetry).
  const bouncing_block::Run r = bouncing_block::run(0.1, dda::HRule::kMinMaxEdge, "damped",
                                                    [](dda::Scene& s) { s.damping.mass = 1.0; });
  const repro::Claim c = bouncing_block::sane_row(r);
  CHECK_FALSE(c.pass);
  CHECK(c.control == std::string("repro_controls: ") + bouncing_block::kControlSane);
}

// --- Sect. 5.2, small angles ------------------------------------------------------
namespace {
// The 5.2 rows for a modified scene (the run stands in for the apex-to-apex variant too).
std::vector<repro::Claim> small_angle_rows(const dda::paper::SmallAngleTriangles& st) {
  const small_angles::Result r = small_angles::run(st, nullptr, nullptr);
  return small_angles::claims(r, r, "");
}
std::string control(const char* name) { return std::string("repro_controls: ") + name; }
}  // namespace

TEST_CASE("5.2 point symmetry: FAIL when one triangle is 1 % faster", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  st.scene.blocks[0].velocity = st.scene.blocks[0].velocity * 1.01;  // no longer point images in velocity
  const repro::Claim c = row(small_angle_rows(st), "symmetry");
  CHECK_FALSE(c.pass);
  CHECK(c.control == control(small_angles::kControlFaster));
}

TEST_CASE("5.2 contact: FAIL when the triangles move apart", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  for (dda::BlockSpec& b : st.scene.blocks) b.velocity = -1.0 * b.velocity;  // no collision at all
  const repro::Claim c = row(small_angle_rows(st), "separate");
  CHECK_FALSE(c.pass);
  CHECK(c.control == control(small_angles::kControlApart));
}

TEST_CASE("5.2 energy: FAIL with mass damping", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  st.scene.damping.mass = 1.0;  // 1/s: about a fifth of the energy lost over the 0.2 s run
  const auto rows = small_angle_rows(st);
  for (const char* key : {"energy", "apex-to-apex"}) {
    CHECK_FALSE(row(rows, key).pass);
    CHECK(row(rows, key).control == control(small_angles::kControlDamped));
  }
}

// --- Sect. 5.3, small edges -------------------------------------------------------
namespace {
// The rows of case 1 (on the small edge) for a modified scene.
std::vector<repro::Claim> small_edge_rows(const dda::paper::SmallEdgeImpact& si) {
  std::vector<repro::Claim> rows;
  small_edges::add_claims(rows, "5.3", "control", small_edges::run(si, 1, nullptr, nullptr), true);
  REQUIRE(rows.size() == 3);  // sane, energy, penetration
  return rows;
}
}  // namespace

TEST_CASE("5.3 sane: FAIL when kn is 1000 times too soft and the guards are off", "[controls][5.3]") {
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  si.scene.contact.kn *= 1e-3;              // too soft to stop the square: it passes into the hexagon
  si.scene.guards.max_penetration = 0.0;    // the solver's guards would stop such a run first
  si.scene.guards.max_approach_energy = 0.0;
  const auto rows = small_edge_rows(si);
  CHECK_FALSE(rows[0].pass);
  CHECK(rows[0].control == std::string("repro_controls: ") + small_edges::kControlFlip);
}

TEST_CASE("5.3 penetration: FAIL when kn is 100 times too soft", "[controls][5.3]") {
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  si.scene.contact.kn *= 1e-2;  // the depth grows as 1/sqrt(kn): about 10 times the paper's
  const auto rows = small_edge_rows(si);
  CHECK_FALSE(rows[2].pass);
  CHECK(rows[2].control == std::string("repro_controls: ") + small_edges::kControlSoft);
}

TEST_CASE("5.3 energy: FAIL with mass damping", "[controls][5.3]") {
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  si.scene.damping.mass = 1.0;  // 1/s: about a fifth of the energy lost over the 0.2 s run
  const auto rows = small_edge_rows(si);
  CHECK_FALSE(rows[1].pass);
  CHECK(rows[1].control == std::string("repro_controls: ") + small_edges::kControlDamped);
}

// --- S2, stability maps ----------------------------------------------------------

TEST_CASE("S2 no blow-up: FAIL against a bound 4 times too large", "[controls][S2]") {
  // A dt above the true limit counts against a bound that claims it is safe:
  // the run must be a blow-up (not hidden as an energy-budget stop), so the
  // row comes out FAIL. Below the true limit the same cell is no blow-up.
  const s2::MapScene m = s2::two_squares_map();
  const double kn = 1e8;
  dda::Scene s = m.scene;
  s.contact.kn = kn;
  const double predicted = dda::Simulation(s).predicted_critical_step();
  const double wrong_bound = 4.0 * predicted;
  const s2::MapRun over = s2::map_run(m, kn, 3.0 * predicted);
  INFO(over.message);
  CHECK(s2::blowup_at_or_below(over, 3.0 * predicted, wrong_bound));
  CHECK_FALSE(s2::blowup_at_or_below(over, 3.0 * predicted, predicted));
  const s2::MapRun under = s2::map_run(m, kn, 0.5 * predicted);
  CHECK_FALSE(s2::blowup_at_or_below(under, 0.5 * predicted, wrong_bound));
}

TEST_CASE("S2 no blow-up or pass-through: FAIL against a bound 4 times too large and at a kn that passes through",
          "[controls][S2]") {
  // The row's criterion counts blow-ups and pass-throughs at dt <= bound.
  // (1) A blow-up above the true limit counts against a bound that claims it
  // is safe; (2) on the bouncing block (B 0.1 m), a kn 50 times below the
  // paper's passes through at half the predicted step and counts, while the
  // paper's kn at the same fraction of its predicted step does not.
  {
    const s2::MapScene m = s2::two_squares_map();
    const double kn = 1e8;
    dda::Scene s = m.scene;
    s.contact.kn = kn;
    const double predicted = dda::Simulation(s).predicted_critical_step();
    const s2::MapRun over = s2::map_run(m, kn, 3.0 * predicted);
    INFO(over.message);
    CHECK(s2::fails_at_or_below(over, 3.0 * predicted, 4.0 * predicted));
    CHECK_FALSE(s2::fails_at_or_below(over, 3.0 * predicted, predicted));
  }
  const s2::MapScene m = s2::bouncing_map(dda::HRule::kMinMaxEdge);
  for (const double factor : {1.0 / 50.0, 1.0}) {
    const double kn = factor * m.scene.contact.kn;
    dda::Scene s = m.scene;
    s.contact.kn = kn;
    const double predicted = dda::Simulation(s).predicted_critical_step();
    const s2::MapRun r = s2::map_run(m, kn, 0.5 * predicted);
    INFO("kn " << kn << ": " << r.message);
    CHECK(s2::fails_at_or_below(r, 0.5 * predicted, predicted) == (factor < 1.0));
  }
}

TEST_CASE("S2 classification: an energy-budget stop that stays bounded is not a blow-up", "[controls][S2]") {
  // The cell that was called a blow-up at 0.78 x predicted: 5.1 case 1 with
  // the inscribed-radius H at kn = 10^11.5 Pa, dt = 1e-5 s. The energy-budget
  // guard stops it; with the guard off the contact lasts a few steps and A
  // leaves with about a fifth more energy, then flies on: energy growth.
  const s2::MapScene m = s2::bouncing_map(dda::HRule::kInscribedRadius);
  const s2::MapRun r = s2::map_run(m, std::pow(10.0, 11.5), 1e-5);
  INFO(r.message);
  CHECK(r.cls == repro::stab::RunClass::kEnergyGrowth);
  CHECK(r.message.find("energy-budget guard stopped it") != std::string::npos);
  CHECK(r.energy_change > 0.1);
  CHECK(r.energy_change < 0.5);
}

TEST_CASE("S2 dt_crit: FAIL when the linearised limit is taken at 4 times the contact's kn", "[controls][S2]") {
  // The independent linearised limit of the wrong system (kn four times the
  // resting contact's: omega doubles, the limit halves) must not match the
  // empirical limit of the real one.
  const s2::RestCase rc = s2::resting(1e8, false, false, false);
  dda::Scene stiffer = rc.scene;
  stiffer.contact.kn *= 4.0;
  const double wrong_lin = repro::stab::linearized_critical_step(dda::Simulation(stiffer)).dt_crit;
  const double emp = s2::empirical_limit(rc.scene, wrong_lin);
  INFO("empirical " << emp << " s, linearised at 4 kn " << wrong_lin << " s");
  CHECK_FALSE(s2::linearised_is_empirical(std::fabs(emp / wrong_lin - 1.0)));
  // The right one passes (the row's configuration).
  const double lin = repro::stab::linearized_critical_step(dda::Simulation(rc.scene)).dt_crit;
  CHECK(s2::linearised_is_empirical(std::fabs(s2::empirical_limit(rc.scene, lin) / lin - 1.0)));
}

TEST_CASE("S2 dt_crit: FAIL for critical steps taken at a sixteenth of the contact's kn", "[controls][S2]") {
  // The solver's current and predicted steps of a softer contact (kn / 16:
  // steps four times as long; a quarter would not do, the solver's steps
  // keep a factor-2 margin below this rigid case's limit) are not safe for
  // the real one.
  const s2::RestCase rc = s2::resting(1e8, false, false, false);
  dda::Scene softer = rc.scene;
  softer.contact.kn /= 16.0;
  const dda::Simulation real(rc.scene), soft(softer);
  const double lin = repro::stab::linearized_critical_step(real).dt_crit;
  const double cur = soft.critical_time_step() / lin, pred = soft.predicted_critical_step() / lin;
  INFO("current / linearised " << cur << ", predicted / linearised " << pred);
  CHECK_FALSE(s2::solver_steps_are_safe(cur, pred));
  CHECK(s2::solver_steps_are_safe(real.critical_time_step() / lin, real.predicted_critical_step() / lin));
}

TEST_CASE("S3 guard stop: FAIL below the critical step and on a bare message", "[controls][S3]") {
  // The row's run at 3 x dt_crit passes; at half the critical step nothing
  // stops the run (no message), and a message without the step, block and
  // pair (a bare exception text) does not name what a user needs.
  auto run = [](double fraction) {
    dda::Simulation sim(s3::guard_scene(fraction));
    long rows = 0;
    try {
      while (sim.time() < sim.scene().duration) {
        sim.step();
        ++rows;
      }
    } catch (const dda::SimulationError& e) {
      return std::make_pair(std::string(e.what()), rows);
    }
    return std::make_pair(std::string(), rows);
  };
  const auto over = run(3.0);
  INFO(over.first);
  CHECK(s3::guard_stop_complete(over.first, over.second));
  const auto under = run(0.5);
  CHECK(under.first.empty());
  CHECK_FALSE(s3::guard_stop_complete(under.first, under.second));
  CHECK_FALSE(s3::guard_stop_complete("energy budget off by 0.5, more than guards.max_balance_error", over.second));
}

TEST_CASE("S3 map bounces: FAIL against a run with kn changed by 1e-9", "[controls][S3]") {
  // A guard that touched the trajectory at all, here as a contact stiffness
  // off by one part in 1e9, must show in the bit-for-bit comparison: the
  // bounce counts as changed and the row FAILs. The guard itself passes.
  const s3map::Setup c{"head on, v-kn", false, 1.0, 1e7, s3map::kPaperDt};
  const s3map::Result on = s3map::run(s3map::scene(c, true)), off = s3map::run(s3map::scene(c, false));
  REQUIRE(on.cls == s3map::Cell::kBounced);
  REQUIRE(off.cls == s3map::Cell::kBounced);
  CHECK(s3map::bounces_untouched(1, on.final_state == off.final_state ? 1 : 0));
  dda::Scene touched = s3map::scene(c, true);
  touched.contact.kn *= 1.0 + 1e-9;
  const s3map::Result changed = s3map::run(touched);
  REQUIRE(changed.cls == s3map::Cell::kBounced);
  CHECK_FALSE(s3map::bounces_untouched(1, changed.final_state == off.final_state ? 1 : 0));
}

TEST_CASE("S3 map messages: FAIL on a map without stops and on another guard's message", "[controls][S3]") {
  // A map where the guard never stops a run shows nothing; the message of a
  // different guard (the energy budget of the S3 guard row's run at 3 x
  // dt_crit) does not give the penetration bound and what to change.
  const s3map::Setup fast{"head on, v-dt", false, 64.0, s3map::kSoftKn, s3map::kPaperDt};
  const s3map::Result stop = s3map::run(s3map::scene(fast, true));
  REQUIRE(stop.cls == s3map::Cell::kGuardStop);
  INFO(stop.message);
  CHECK(s3map::stops_actionable(1, s3map::actionable(stop.message) ? 1 : 0));
  CHECK_FALSE(s3map::stops_actionable(0, 0));
  std::string other;
  try {
    dda::Simulation sim(s3::guard_scene(3.0));
    while (sim.time() < sim.scene().duration) sim.step();
  } catch (const dda::SimulationError& e) {
    other = e.what();
  }
  INFO(other);
  REQUIRE_FALSE(other.empty());
  CHECK_FALSE(s3map::stops_actionable(1, s3map::actionable(other) ? 1 : 0));
}
