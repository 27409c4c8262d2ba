// The rock-mechanics applications of Paper A Sect. 6 as Scene values, shared
// by the repro drivers (repro/6_1_collapse, repro/6_2_toppling_slumping) and
// the tests. Parameters from SPEC.md section 7 (rows 6.1, 6.2). Figs. 19 and
// 21 (the models) are lost: both geometries are RECONSTRUCTIONS from the
// prose, and each function says what was chosen and why.
//
// Blocks come from dda::generate_blocks (persistent joint sets cutting a
// region); pieces below `min_area` are dropped (slivers whose strain and
// contact modes would be far stiffer than the rest and set the stable time
// step) and counted in `dropped` / `dropped_area`.
#pragma once
#include <vector>

#include "dda/joint_sets.hpp"
#include "dda/scene.hpp"

namespace dda::paper {

// Friction groups of the Sect. 6 scenes.
inline constexpr int kRockGroup = 0;      // generated rock blocks
inline constexpr int kBoundaryGroup = 1;  // fixed walls, floors, sliding bases

// Sect. 6.1 "Frictional collapse of a rock mass system" (Figs. 19-20).
//
// GEOMETRY RECONSTRUCTED (Fig. 19 lost). The paper gives a 20 m x 50 m
// region cut by two persistent joint sets (dip 80 and 40 deg, spacing 1.5
// and 2.5 m) and a block-to-boundary friction, nothing about the boundary.
// Our model: a column 20 m wide and 50 m tall, x in [0, 20], y in [0, 50],
// standing on a long fixed floor (y = 0, x from -5 to `floor_length`) against
// a fixed vertical wall on its left (x = 0, up to 60 m); its right side is
// free. Both joint sets dip toward the free side (+x) and pass through the
// origin: the 40 deg set daylights on the free face and is steeper than both
// joint friction angles (15 and 30 deg), so the column can collapse by
// sliding on it and run out along the floor -- the behaviour the paper
// describes ("a faster collapsing process and a larger runout mass ... with
// lower friction angle"). A column (not a 50 m wide, 20 m high slab) because
// only a column collapses under gravity with both friction angles.
// rho 2700, E 2 GPa, nu 0.3, kn 2 GPa, kt 1e9 N/m, joint friction
// `joint_friction_deg` (case 1: 15, case 2: 30), rock-boundary friction 35
// deg, gravity 9.81, dt 1e-4 s, 7.5 s, sweep broad phase, H by the paper's
// min-max edge rule.
struct Collapse {
  Scene scene;
  std::vector<Vec2> region;  // the column outline (CCW)
  std::vector<JointSet> joint_sets;
  double min_area = 0.0;      // m^2, slivers below it dropped
  int dropped = 0;            // pieces dropped
  double dropped_area = 0.0;  // m^2
  double width = 20.0, height = 50.0;  // m
  double floor_length = 0.0;           // m, floor from x = -5 to here
};
Collapse collapse(double joint_friction_deg, double min_area = 0.5, double duration = 7.5,
                  double floor_length = 200.0);

// Sect. 6.2 "Rock toppling and rock slumping" (Figs. 21-22).
//
// GEOMETRY RECONSTRUCTED (Fig. 21 lost). The paper: "rock slopes in a valley
// region cut by a joint set with dip angle of 75 deg and spacing of 3 m",
// "a sliding base with an inclined angle of 30 deg", base friction 32 deg
// ("both the left slope and right slope will keep stable as one unique
// block"), joint friction 22 deg; "the left part will fail in slumping
// pattern, while the right part will fail with toppling pattern".
// Our model: a valley with a flat floor y = 0 for |x| < `valley_half_width`
// and two fixed sliding bases dipping 30 deg toward the valley axis. On each
// base sits a rock wedge of height `height` with a horizontal top: its base
// is the 30 deg sliding base, its face rises from the toe (x = -/+ a, y = 0)
// to the top. ONE joint set, dip 75 deg toward +x, spacing 3 m, cuts both
// wedges (origin at each toe), so that
//  - on the LEFT slope (valley to its right) the joints dip toward the valley,
//    with the slope: the slabs lean back into the hill and can only move by
//    sliding down the base with shear on the joints (slumping); the left face
//    is itself a joint plane;
//  - on the RIGHT slope (valley to its left) the joints dip into the slope:
//    the columns lean 15 deg out over the valley on a base dipping 30 deg
//    toward it, and the tall ones (their centroid outside their base) topple.
// The right face rises at `right_face_deg` (60 deg) from its toe.
// rho 2700, E 2 GPa, nu 0.3, kn 0.5 GPa, kt 1e8 N/m, base (rock-boundary)
// friction 32 deg, joint friction 22 deg, gravity 9.81, dt 1e-4 s, 3.5 s.
struct TopplingSlumping {
  Scene scene;
  std::vector<Vec2> left_region, right_region;  // wedge outlines (CCW)
  JointSet joints;                              // dip and spacing (origin per wedge: its toe)
  double min_area = 0.0;
  int dropped = 0;
  double dropped_area = 0.0;
  std::vector<int> side;  // per scene block: -1 left wedge, +1 right wedge
  // Unit vectors along each sliding base, pointing down-dip (toward the valley).
  Vec2 left_downdip{}, right_downdip{};
  double base_dip_deg = 30.0;
  double valley_half_width = 0.0, height = 0.0;
};
TopplingSlumping toppling_slumping(double min_area = 0.5, double duration = 3.5, double height = 24.0,
                                   double valley_half_width = 8.0, double right_face_deg = 60.0);

// The same scene with each slope as ONE block (its wedge outline): the
// premise of Sect. 6.2, "both slopes keep stable as one unique block".
Scene one_block_per_slope(const TopplingSlumping& ts);

}  // namespace dda::paper
