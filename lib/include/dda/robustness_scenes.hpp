// The robustness scenes of Paper A Sect. 5 as Scene values, shared by the
// Sect. 5 repro drivers and the fast tests, plus the measures they report
// (overlap thickness, vertex depth, symmetry errors, energy error). A block's
// own stability limit is dda::Simulation::strain_critical_step.
// Parameters from SPEC.md section 7 (Table 5). Figs. 13, 15 and 17 (the
// geometry) are lost: every scene here is a RECONSTRUCTION from the prose,
// and each function says what was chosen.
//
// Friction: Table 5 lists kt = 1e7 N/m but no friction angle. Every scene
// below runs frictionless (kt = 0, which is what a friction angle of 0 means:
// the Coulomb limit fn tan(0) = 0), so that the total energy is conserved and
// is itself a check. Callers may set scene.contact.kt / friction_deg (kt > 0
// with friction_deg = 0 is frictionless too: the solver then never applies a
// tangential force).
//
// Small edges: every scene uses the library default
// ContactParams::small_edge_rays = kVirtualAndVertex (the paper's printed
// rule); repro/5_5_segmentation compares SPEC.md's replacing reading.
#pragma once
#include <array>

#include "dda/scene.hpp"
#include "dda/simulation.hpp"

namespace dda::paper {

// Sect. 5.1 (geometry RECONSTRUCTED, Fig. 13 lost): block A, a 1 m square
// (block 1), falls from rest with its base 0.5 m above the top of a fixed
// 4 m wide block B (block 0) of height `b_height` (paper: 0.1 m case 1,
// 1 m case 2), centred on the same vertical axis x = 0; gravity 9.81; 2.0 s (three impacts).
// rho 2000, E 1 GPa, nu 0.25, kn 50 MPa, dt 1e-4. h_rule: kMinMaxEdge is the
// paper's unified H (here (4 + min(b_height, 1)) / 2 m), kInscribedRadius the
// 'previous' per-polygon H (0.5 m for A, b_height / 2 for B).
struct BouncingBlock {
  Scene scene;
  int fixed = 0;    // block B
  int falling = 1;  // block A
  double b_height = 0.0;
  double drop = 0.5;  // initial gap between A's base and B's top, m
};
BouncingBlock bouncing_block(double b_height, HRule h_rule, double duration = 2.0);

// Sect. 5.2 (geometry RECONSTRUCTED, Fig. 15 lost): two identical isosceles
// triangles with apex angle `angle_deg` (paper 5 deg), 1 m from the apex to
// the base; block 1 is the point image of block 0 through the collision
// centre c = (0, 0) (rotation by 180 deg), block 0 moves up at 1 m/s and
// block 1 down at 1 m/s; no gravity. rho 2000, E 1 GPa, nu 0.25, kn 50 MPa,
// dt 2e-5, 0.2 s. By symmetry block 1 = 2 c - block 0 at all times.
// Layout kLongSidesFacing (the main reconstruction): axes horizontal, block
//   0's apex pointing right at x = +0.25, block 1's pointing left at
//   x = -0.25, so the two long sides that face each other overlap over 0.5 m
//   and each apex (the small angle) lies inside that overlap: both small
//   angles become corners of the intersection polygon. The facing sides are
//   parallel (point images), inclined by half the apex angle, 0.01 m apart.
// Layout kApexToApex (a variant): axes vertical, apex to apex on x = 0,
//   0.01 m apart, each tilted by 0.2 * angle_deg about its apex.
enum class TriangleLayout { kLongSidesFacing, kApexToApex };
struct SmallAngleTriangles {
  Scene scene;
  Vec2 centre{};              // collision centre
  std::array<int, 2> apex{};  // vertex index of the small angle in blocks 0 and 1
  double angle_deg = 0.0;
  TriangleLayout layout = TriangleLayout::kLongSidesFacing;
};
SmallAngleTriangles small_angle_triangles(double angle_deg = 5.0, double duration = 0.2,
                                          TriangleLayout layout = TriangleLayout::kLongSidesFacing);

// Sect. 5.3 (geometry RECONSTRUCTED, Fig. 17 lost): a fixed lower block
// (block 0), a hexagon 1 m wide and 1 m high whose roof rises from
// (+-0.5, 0.7) to a top edge of length `small_edge` (paper 0.01 m) centred
// on x = 0 at y = 1; an upper block (block 1), a 0.5 m square turned 45 deg,
// its lowest vertex (index 0) 0.01 m above the lower block. Case kOnSmallEdge
// (Fig. 17a): the vertex is above the small edge's midpoint (x = 0; the
// scene is mirror symmetric about x = 0). Case kOnNeighbourEdge (Fig. 17b):
// above the right roof edge, 0.02 m to the right of the small edge's end.
// The upper block starts at 1 m/s downward under gravity 9.81. rho 2000,
// E 1 GPa, nu 0.25, kn 50 MPa, dt 1e-4, 0.2 s.
enum class SmallEdgeCase { kOnSmallEdge, kOnNeighbourEdge };
struct SmallEdgeImpact {
  Scene scene;
  int lower = 0, upper = 1;
  int contact_vertex = 0;  // vertex of the upper block that hits
  double small_edge = 0.0;
  Vec2 hit_point{};        // where that vertex would first touch the lower block
  bool mirror_symmetric = false;  // about x = 0
};
SmallEdgeImpact small_edge_impact(SmallEdgeCase which, double small_edge = 0.01, double duration = 0.2);

// ---- measures ----------------------------------------------------------------

// Overlap thickness: the diameter of the largest circle inscribed in the
// intersection polygon of a and b, i.e. 2 max over the overlap of
// min(d_exit_a, d_exit_b) (the measure Scene::initial_overlap uses). 0 when
// the interiors do not overlap.
double overlap_thickness(const Polygon& a, const Polygon& b);

// Deepest vertex penetration: the largest exit distance of a vertex of one
// polygon inside the other (both ways). 0 when no vertex is inside.
double vertex_depth(const Polygon& a, const Polygon& b);

// Deviation from point symmetry through `centre` of blocks a and b built as
// point images vertex by vertex (b[k] = 2 centre - a[k], as in
// small_angle_triangles): max over k of |a[k] + b[k] - 2 centre|, m. It
// covers translation, rotation and strain at once.
double point_symmetry_error(const Polygon& a, const Polygon& b, Vec2 centre);

// Deviation of one block from mirror symmetry about the line x = x0, for a
// block that starts symmetric about it: max(|x_c - x0|, |r| R), with r the
// accumulated rotation and R the largest centroid-vertex distance, m.
double mirror_symmetry_error(const Simulation& sim, int block, double x0);

// What every Sect. 5 run reports, sampled after each step by RunMonitor.
struct RunStats {
  double energy_error = 0.0;   // max |E - E0| / E_mech, E_mech the largest kinetic + strain + contact energy seen
  double energy_growth = 0.0;  // max (E - E0) / E_mech (> 0: energy created)
  double peak_thickness = 0.0; // max overlap_thickness of the watched pair, m
  double peak_vertex_depth = 0.0;  // max vertex_depth of the watched pair, m
  double first_contact = -1.0, last_contact = -1.0;  // s; -1 if never
  long contact_steps = 0;
  long samples = 0;
};

class RunMonitor {
 public:
  // Watches the pair (a, b) of `sim`; records the state at construction.
  RunMonitor(const Simulation& sim, int a, int b);
  void sample();  // call after every step
  const RunStats& stats() const { return stats_; }

 private:
  const Simulation* sim_;
  int a_, b_;
  double e0_ = 0.0, e_mech_ = 0.0, max_dev_ = 0.0, max_growth_ = 0.0;
  RunStats stats_;
};

}  // namespace dda::paper
