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
  // Largest growth of the total energy above its initial value, relative to
  // the largest mechanical (kinetic + strain + contact) energy seen so far.
  // Without damping an explicit run conserves energy to O(dt^2); friction
  // only removes it. Checked every `energy_check_every` steps; 0 disables.
  double max_energy_growth = 0.5;
  int energy_check_every = 100;
};

struct Scene {
  std::string name;
  std::vector<Material> materials{Material{}};
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
};

}  // namespace dda
