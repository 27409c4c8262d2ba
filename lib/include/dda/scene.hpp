// One scene description shared by drivers, tests, benchmarks and the scene
// file reader: blocks, materials, contact parameters, boundaries, features.
#pragma once
#include <string>
#include <vector>

#include "dda/contact.hpp"
#include "dda/vec2.hpp"

namespace dda {

struct Material {
  double density = 2000.0;  // kg/m^3
  double young = 1e9;       // Pa
  double poisson = 0.25;    // dimensionless, in (-1, 0.5)
};

struct BlockSpec {
  std::vector<Vec2> vertices;  // CCW, convex
  Vec2 velocity{};             // initial centroid velocity, m/s
  double spin = 0.0;           // initial angular velocity, rad/s
  bool fixed = false;          // takes part in contact, never moves
  int material = 0;            // index into Scene::materials
  int group = 0;               // friction group (see FrictionRule)
  std::string name;            // optional label for outputs
};

// A boundary segment from a to b; the solid lies on its right (the domain on
// its left, the side its left normal points to). Treated as the edge of a
// fixed 'virtual' polygon (Paper A Sect. 3.3).
struct BoundarySegment {
  Vec2 a{}, b{};
  double depth = 0.0;  // thickness of the virtual polygon; 0: the segment length
  int group = 0;
};

// How H of Eq. 12 is chosen.
enum class HRule {
  kMinMaxEdge,       // Paper A Sect. 5.1: mean of the largest and smallest edge of the assembly
  kMeanEdge,         // mean edge length of the assembly (Sect. 3.2.2)
  kGiven,            // ContactParams::h
  kInscribedRadius,  // 'previous' approach: each polygon's inscribed-circle radius
};

// Friction angle between two groups (both orders).
struct FrictionRule {
  int group_a = 0, group_b = 0;
  double friction_deg = 0.0;
};

// What a contact pair's accumulated relative displacement d keeps after a
// sliding step (Paper A Sect. 3.2.5-3.2.6, Eqs. 24-26).
enum class FrictionUpdate {
  // Paper A as written (the default): a sliding pair restarts d from the
  // step's increment (Sect. 3.2.6: d^{n+1} = Delta d^n; Sect. 3.2.5: "if
  // the contact status ... is sliding, d will also be set to zero"), stays
  // sliding while f_t(n-1) . d_tan < 0 and sticks again (Eq. 26, second
  // line) with f_t = -kt d_tan: a spring holding one step's Delta d, so the
  // shear the contact carried at the friction limit is dropped. Under a
  // sustained load (a block on a slope with phi > theta) each re-stick
  // restarts the undamped stick phase from zero shear; it overshoots the
  // limit again and the block ratchets down the slope without end (1 m
  // square, 6.2 penalties, H = 1 m, 30 deg slope, phi = 32 deg: 1.28 m in
  // 3.5 s, 19.6 m in 10 s; see the 6.2 driver).
  kPaper,
  // Elastic-plastic Coulomb update (return mapping), NOT the paper's rule: d
  // accumulates Delta d in both states, Eq. 25 decides stick or slide from
  // either state, and a sliding step returns d_tan onto the friction limit,
  // d_tan = -f_t / kt. A pair that sticks again after sliding keeps the
  // shear it carried (the spring starts at the limit, not from zero), and
  // it never sticks while the trial force is beyond the limit. Same square
  // as above: 1.5 mm, at rest. Not the default: the paper's text is
  // explicit, and the paper's Sect. 6.2 result does not need it (the
  // reconstructed left slope "slumps" only through the kPaper ratchet).
  kReturnMapping,
};

struct ContactParams {
  double kn = 1e7;             // normal penalty, Pa
  double kt = 0.0;             // tangential penalty, N/m; 0 switches friction off
  double friction_deg = 0.0;   // default friction angle, degrees in [0, 90)
  std::vector<FrictionRule> friction_rules;
  HRule h_rule = HRule::kMinMaxEdge;
  double h = 0.0;              // m, used by HRule::kGiven
  Integration integration = Integration::kPaperBisector;
  // Edges shorter than this fraction of H get a virtual node (Sect. 3.2.3).
  double small_edge_fraction = 0.05;
  // Whether a virtual node adds to or replaces its edge's vertex rays.
  SmallEdgeRays small_edge_rays = SmallEdgeRays::kVirtualAndVertex;
  // Stick/slide history update (Sect. 3.2.5-3.2.6).
  FrictionUpdate friction_update = FrictionUpdate::kPaper;
  bool friction() const { return kt > 0.0; }
};

enum class BroadPhase { kNone, kSweep };

// What the solver watches every step; a violation stops the run with a
// SimulationError naming the step, time, block, pair and dt/dt_crit.
struct StabilityGuards {
  // Largest vertex displacement in one step, as a fraction of the smallest
  // inscribed radius within the block's reach (itself and its broad-phase
  // candidates): beyond it a vertex can pass through a thin block between
  // two contact checks (flip-through).
  double max_step_motion = 0.25;
  // Largest error of the energy budget (Energy::balance_error: kinetic +
  // gravity + strain + contact + friction springs + dissipated work against
  // the initial energy), relative to the largest mechanical energy seen so
  // far; checked with the energy growth below. 0 switches it off. Measured
  // on the paper's scenes at their dt (4.1-4.3, 5.1-5.3; 6.1 and 6.2 over
  // their first 0.5 s): at most 5e-3 (4.2, dt = 1e-3 s), mostly 1e-5 to 4e-4.
  double max_balance_error = 0.1;
  // Largest growth of the total energy above its initial value, relative to
  // the largest mechanical (kinetic + strain + contact) energy seen so far.
  // Without damping an explicit run conserves energy to O(dt^2); friction
  // only removes it. Checked every `energy_check_every` steps; 0 disables.
  double max_energy_growth = 0.5;
  int energy_check_every = 100;
  // Penetration guard (derived in lib/src/simulation/penetration_guard.cpp
  // from Eqs. 10-14). A block's potential is largest, kn r / H, at its
  // inscribed-circle centre (r its inscribed radius): material pressed past
  // a block's middle is pushed on, through it, not back, and a pair stores
  // at most a finite energy. The run stops before two blocks cross when
  //  - a pair's penetration depth (the intersection polygon's width, its
  //    smallest extent over all directions) exceeds max_penetration times
  //    the smaller half-thickness of the two blocks across the contact
  //    (half their extent along the contact normal, at least r), or
  //  - at a pair's first contact, the relative approach energy (1/2 m_eff
  //    v_n^2, v_n the normal closing speed at the loading point, m_eff the
  //    pair's effective mass there) exceeds max_approach_energy times the
  //    largest contact energy the pair can store.
  // 0 switches a check off (for studies of what happens without it).
  double max_penetration = 0.5;
  double max_approach_energy = 1.0;
};

// How a step's displacement increment Delta d (Eq. 8) moves a block's
// vertices. Eqs. 1 and 3 are linear in the rotation r0 = omega h: a vertex
// moves by (-yt, xt) r0, perpendicular to its radius, so a freely spinning
// block grows by sqrt(1 + r0^2) per step (area and moment of inertia by
// 1 + r0^2), and its kinetic energy and angular momentum drift at first
// order in h.
enum class RotationUpdate {
  // Paper A as written (the default): p' = p + T(p) Delta d (Eqs. 1, 3).
  kPaperLinear,
  // NOT the paper's rule: the rigid part turned exactly, the strain part a
  // separate small increment before it, p' = c + u0 + R(r0) (I + E) (p - c)
  // with E = [[ex, gxy/2], [gxy/2, ey]]: a rigid rotation stays rigid to
  // round-off, and the stress turns with the material (sigma' = R sigma R^T).
  // Chosen over a second-order correction of the displacement function
  // (cos r0 ~ 1 - r0^2/2, sin r0 ~ r0: the block still grows, by
  // 1 + O(r0^4) a step) because it is exact at one sine per block and step
  // and changes only the drift's geometry: M, the kick and the centroid
  // motion u0 stay the paper's. With it, rigid blocks (strains = false)
  // conserve angular momentum to round-off and energy to O(h^2). What it
  // leaves: the friction history's Delta d at pg is still T(pg) Delta d
  // (Sect. 3.2.6; O(r0^2) off a rigid motion), and with strain DOFs the
  // equation of motion (Eq. 4, M taken constant over the step) leaves out
  // the rate of M, so a spinning block that vibrates changes its energy and
  // angular momentum by ~1e-5 relative, independently of h.
  kExact,
};

// Eq. 5c damping, C = a M + b K, in the kicks of velocity Verlet (see
// Simulation::kick_block). Off by default (a = b = 0: the paper's Eq. 6
// leaves C d' out). K is the block's elastic stiffness (Eq. 5b) together
// with its contact springs (the stiffness matrix of the global equation).
struct Damping {
  double mass = 0.0;       // a, 1/s: the decay rate of every mode grows by a/2
  double stiffness = 0.0;  // b, s: the decay rate of a mode of frequency omega grows by b omega^2 / 2
  // Settle-then-load (dynamic relaxation): if > 0 the constructor first
  // runs this long (s) from rest with the damping above (the blocks'
  // initial velocities held back), then switches the damping off and
  // starts the clock at t = 0 from the settled configuration at rest (the
  // velocity the settling left is dropped; stresses and contact springs
  // stay pre-loaded) with the blocks' initial velocities. 0: the damping
  // acts during the whole run.
  double settle_time = 0.0;
  // Friction start-up (with settle_time > 0 and friction): while settling
  // every contact sticks (no friction limit), so its tangential spring
  // loads to the static shear it carries; at t = 0 the friction angles
  // apply, and a contact whose shear exceeds its limit starts sliding at
  // the limit (Eq. 25) instead of from an unloaded spring that lets the
  // block gain a head start while it loads (Sect. 4.3: 7 % on Eq. 30 at
  // kt = 1e7 N/m). false: the friction angles apply while settling too.
  bool settle_sticking = false;
  // With settle_sticking: the last this many seconds of the settle (s, <
  // settle_time) run with the friction angles, still damped, so a contact
  // that took more shear while sticking than its limit allows (a corner
  // touching with almost no normal force) sheds it before t = 0 instead of
  // shedding it undamped at the release (Sect. 6.2's toe corners). 0: every
  // contact sticks until t = 0.
  double settle_slip_time = 0.0;
  bool on() const { return mass > 0.0 || stiffness > 0.0; }
};

struct Scene {
  std::string name;
  std::vector<Material> materials = std::vector<Material>(1);  // one default material
  std::vector<BlockSpec> blocks;
  std::vector<BoundarySegment> boundaries;
  ContactParams contact;
  Vec2 gravity{};               // m/s^2; zero switches gravity off
  bool strains = true;          // deformable blocks (constant-strain DOFs)
  BroadPhase broad_phase = BroadPhase::kNone;
  // Blocks may overlap at t = 0 only by less than this thickness (m,
  // measured as the diameter of the overlap's inscribed circle): a preloaded
  // contact placed at its static penetration. 0 rejects every overlap.
  double initial_overlap = 0.0;
  double dt = 1e-4;             // s
  // If > 0, dt is replaced by this fraction of the predicted critical step
  // (Simulation::predicted_critical_step) when the simulation is built.
  double dt_fraction = 0.0;
  double duration = 1.0;        // s
  StabilityGuards guards;
  RotationUpdate rotation_update = RotationUpdate::kPaperLinear;
  Damping damping;
};

}  // namespace dda
