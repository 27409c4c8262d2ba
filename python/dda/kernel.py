"""The contact kernel of Paper A on numpy polygons, to probe the method.

Polygons are (n, 2) arrays of the counter-clockwise vertices of a convex
block (3 to MAX_BLOCK_VERTICES vertices), checked as the library checks a
block (ValueError naming the vertex and the reason). tol < 0 (the default)
means the pair's geometric tolerance (pair_tolerance).

  overlap_state(a, b)               'separate' | 'touching' | 'overlapping' (Sect. 3.1.2)
  intersection_polygon(cp, tp)      (m, 2) the intersection polygon by cutting (Sect. 3.1.3)
  entrance_block(a, b)              (m, 2) E(A, B) = B - A + a0 (Eq. 9)
  exit_distance(poly, points)       d_exit (Eqs. 13-14)
  potential(poly, points, kn, h)    phi (Eq. 12), Pa
  potential_gradient(poly, points, kn, h)
  inscribed_circle(poly)            (centre, radius)
  normal_contact_force(cp, tp, kn, h_cp, h_tp, integration='paper_bisector' | 'exact_envelope')
                                    the normal force and its loading point (Eqs. 10-20), dict
  check_polygon, geometric_tolerance, pair_tolerance
  IP_VERTEX_REACH, IP_AREA_BOUND    what intersection_polygon promises, in units of the pair
                                    tolerance (see lib/include/dda/overlap.hpp)
"""
from ._core import kernel as _kernel

check_polygon = _kernel.check_polygon
geometric_tolerance = _kernel.geometric_tolerance
pair_tolerance = _kernel.pair_tolerance
overlap_state = _kernel.overlap_state
intersection_polygon = _kernel.intersection_polygon
entrance_block = _kernel.entrance_block
exit_distance = _kernel.exit_distance
potential = _kernel.potential
potential_gradient = _kernel.potential_gradient
inscribed_circle = _kernel.inscribed_circle
normal_contact_force = _kernel.normal_contact_force
MAX_BLOCK_VERTICES = _kernel.MAX_BLOCK_VERTICES
IP_VERTEX_REACH = _kernel.IP_VERTEX_REACH
IP_AREA_BOUND = _kernel.IP_AREA_BOUND

__all__ = ["check_polygon", "geometric_tolerance", "pair_tolerance", "overlap_state", "intersection_polygon",
           "entrance_block", "exit_distance", "potential", "potential_gradient", "inscribed_circle",
           "normal_contact_force", "MAX_BLOCK_VERTICES", "IP_VERTEX_REACH", "IP_AREA_BOUND"]
