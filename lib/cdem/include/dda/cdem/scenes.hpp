// Scenes for the CDEM two-scale contact model (Paper B) and for comparing it
// with Paper A's penalty contact on the same collisions.
#pragma once
#include "dda/cdem/model.hpp"
#include "dda/scene.hpp"

namespace dda::cdem {

// Paper B Sect. 6, two triangular prisms. Fig. 12 is lost and the text gives
// no dimensions: RECONSTRUCTED as two identical isosceles triangles with
// their axis on y = 0, each `length` m long in x with a vertical base of
// `height` m; block i (block 0) has its apex A at (0, 0) pointing +x, block
// j (block 1) has its base at x = gap, so A meets the middle of j's base
// after gap / speed = 1/3 s. Equal masses make the ideal (rigid, elastic)
// outcome an exchange of velocities, which is what Paper B reports ("the
// velocity of block j after collision is approximately equal to the initial
// velocity of block i"). Size: 7 m x 7 m meshed with 2 divisions (4 CST
// elements per block, apex and base midpoint are nodes), so that the coarse
// elements satisfy c dt < h at dt = 5e-4 s (c dt = 1.9 m, Sect. 5; critical
// step 7.4e-4 s) and the clone node separates at about the time of Paper B
// Fig. 15a (0.3405 s); 6 m separates at 0.3389 s, 8 m at 0.3409 s.
struct PrismGeometry {
  double length = 7.0;  // m, along x
  double height = 7.0;  // m, base (vertical)
  double gap = 1.0;     // m, apex of i to base of j (Paper B: "1 m in the x-direction")
  double speed = 3.0;   // m/s, block i along +x
};

// As a dda::Scene (shared by both models): E 40 GPa, nu 0.25, rho 2700,
// dt 5e-4 s, duration 0.5 s, no gravity. For Paper A's penalty contact,
// which Paper B does not use, kn = E / 100 (the ratio of Paper A Sect. 4.1:
// 10 MPa for 1 GPa) = 0.4 GPa.
dda::Scene two_prisms_scene(const PrismGeometry& g = {});

// The CDEM scene of Paper B Sect. 6: the prisms meshed with `divisions`
// (apex and base midpoint are nodes for even divisions); tolerance 5e-3 m.
CdemScene two_prisms(int divisions = 2, const CdemOptions& options = {}, const PrismGeometry& g = {});

// Paper A Sect. 4.1 (dda::paper::two_squares(): 1 m squares, 0.5 m gap,
// A at 1 m/s) meshed for the CDEM model: fan from the centroid, each fan
// triangle split `divisions` times, so both faces carry nodes at the same
// heights. dt 1e-4 s as in Paper A.
CdemScene two_squares(int divisions = 4, const CdemOptions& options = {});

}  // namespace dda::cdem
