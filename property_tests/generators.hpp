// rapidcheck generators of convex CCW polygons (3..8 vertices), polygon pairs,
// cutting lines, sample points and rigid motions, with the degenerate
// families a geometry kernel gets wrong, not only random blobs:
//
//  single polygons (base_shape):
//    hull        convex hull of 3..8 random points
//    regular     regular n-gon, possibly perturbed in angle and radius
//    sliver      triangle with a smallest angle of 0.5 .. 30 degrees
//    thin        rectangle / parallelogram of aspect ratio 1 .. 1e6 (edges down to 1e-6 of the size)
//    cornercut   a polygon with one or two corners cut by an edge of 1e-6 .. 1e-2 of its size
//    grid        convex hull of points of a coarse dyadic grid (exact collinearities between polygons)
//    needle      a triangle or kite with a sharp corner of 1e-6 .. 0.3 rad
//  then a similarity: scale 1, 0.1 .. 10, tiny (1e-6 .. 1e-4) or huge (1e4 ..
//  1e6) (or 2^-4 .. 2^4), rotation 0, down to 1e-12 rad, or any, and a
//  translation of 0, of the size, up to 1e6, or far: 1e6 .. 1e9 times the size.
//
//  pairs (polygon_pair): independent placement; identical; a copy rotated by
//  1e-12 .. 0.1 rad (about its centroid, a shared vertex or any point); a
//  copy shifted by 1e-16 .. 1 of its size; vertex on vertex; vertex on edge;
//  edge on edge (the same two vertices, or a partial collinear edge); one
//  polygon scaled inside the other (about an interior point or a shared
//  vertex, factor 1e-3 .. 1 +- 1e-15); two grid hulls; crossing:
//  an edge of B along an edge of A turned by +-1e-6 .. 2e-2 rad about a point
//  of it, at gap 0 or +-1e-16 .. 1e-3 (near-parallel edges that cross or just
//  miss); shared-vertex: B's edge starting at A's vertex bit for bit, along
//  A's edge (collinear) in either sense. Touching families get a gap of 0
//  (exact contact), +-1e-16 .. 1e-2 of the size, or a deep penetration of
//  1e-2 .. 0.5 of the size (a needle's tip deep in the other block). Pairs are built
//  in a local frame and then moved by one common similarity, so a vertex
//  shared in the local frame stays shared bit for bit.
//
// Every generated polygon still has to pass validate_polygon: the properties
// discard the rare case that does not (RC_PRE), e.g. a 1e-6 edge at an offset
// of 1e6 that rounding made collinear.
#pragma once
#include <rapidcheck.h>

#include "support.hpp"

namespace prop::gen {

rc::Gen<double> uniform(double lo, double hi);      // [lo, hi)
rc::Gen<double> log_uniform(double lo, double hi);  // log-uniform in [lo, hi)
rc::Gen<int> index(int lo, int hi);                 // [lo, hi), independent of rapidcheck's size

rc::Gen<PolygonCase> polygon();
rc::Gen<PairCase> polygon_pair();
// A line through, along, tangent to or near the polygon p.
rc::Gen<LineCase> cutting_line(const Points& p);
// `count` points, each inside, near the boundary, at a vertex, near `centre`,
// at `centre`, or outside.
rc::Gen<Samples> sample_points(const Points& p, Vec2 centre, int count);
// A rigid motion sized for polygons around p: rotation 0, tiny (1e-12 ..
// 1e-3 rad) or any; translation 0, of the polygon's size, or up to 1e6.
rc::Gen<Motion> rigid_motion(const Points& p);

}  // namespace prop::gen
