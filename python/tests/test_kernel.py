"""The contact kernel from Python, and intersection_polygon against Shapely's
(GEOS) intersection on random convex pairs: a second oracle beside CGAL's
exact kernel (property_tests/)."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import Point, Polygon as ShapelyPolygon

from dda import kernel

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


def shoelace(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_kernel_on_two_squares():
    b = SQUARE + [0.5, 0.25]
    assert kernel.overlap_state(SQUARE, b) == "overlapping"
    assert kernel.overlap_state(SQUARE, SQUARE + [1.0, 0.0]) == "touching"
    assert kernel.overlap_state(SQUARE, SQUARE + [1.5, 0.0]) == "separate"
    ip = kernel.intersection_polygon(SQUARE, b)
    assert shoelace(ip) == pytest.approx(0.5 * 0.75)
    assert kernel.intersection_polygon(SQUARE, SQUARE + [2.0, 0.0]).shape == (0, 2)
    # d_exit: 0.25 at (0.25, 0.5), negative outside; phi = kn d / H inside, 0 outside.
    assert kernel.exit_distance(SQUARE, [0.25, 0.5]) == pytest.approx(0.25)
    d = kernel.exit_distance(SQUARE, np.array([[0.5, 0.5], [2.0, 0.5]]))
    assert d[0] == pytest.approx(0.5) and d[1] == pytest.approx(-1.0)
    phi = kernel.potential(SQUARE, np.array([[0.5, 0.5], [2.0, 0.5]]), kn=1e7, h=0.5)
    assert phi[0] == pytest.approx(1e7) and phi[1] == 0.0
    c, r = kernel.inscribed_circle(SQUARE)
    assert np.allclose(c, [0.5, 0.5]) and r == pytest.approx(0.5)
    e = kernel.entrance_block(SQUARE, b)
    assert shoelace(e) == pytest.approx(4.0)  # B - A of two unit squares: a 2 x 2 square


def test_normal_force_of_a_flat_overlap_both_integrations():
    # Two unit squares overlapping by a strip of depth delta: by symmetry of
    # the two potentials (same H), the force is normal to the strip, on CP
    # pointing away from TP, and both integrations agree (the exit distance
    # is linear along each IP edge but for its kinks at the bisectors).
    delta, kn, h = 0.01, 1e7, 1.0
    cp, tp = SQUARE, SQUARE + [0.0, 1.0 - delta]
    f = {rule: kernel.normal_contact_force(cp, tp, kn=kn, h_cp=h, h_tp=h, integration=rule)
         for rule in ("paper_bisector", "exact_envelope")}
    for r in f.values():
        assert r["valid"] and r["force"][1] < 0 and abs(r["force"][0]) < 1e-9 * abs(r["force"][1])
        assert r["ip_area"] == pytest.approx(delta)
        assert r["energy"] > 0
    assert f["paper_bisector"]["force"] == pytest.approx(f["exact_envelope"]["force"], rel=1e-9)
    with pytest.raises(ValueError, match="integration"):
        kernel.normal_contact_force(cp, tp, kn=kn, h_cp=h, h_tp=h, integration="simpson")


def test_bad_polygons_are_refused_naming_the_vertex():
    with pytest.raises(ValueError, match=r"contact: vertex \d: clockwise"):
        kernel.intersection_polygon(SQUARE[::-1], SQUARE)
    with pytest.raises(ValueError, match=r"target: vertex 2: polygon is not convex"):
        kernel.intersection_polygon(SQUARE, [[0, 0], [1, 0], [0.9, 0.1], [1, 1], [0, 1]])
    with pytest.raises(ValueError, match="expected an \\(n, 2\\) array"):
        kernel.overlap_state([1, 2, 3], SQUARE)
    n = kernel.MAX_BLOCK_VERTICES + 1
    circle = np.c_[np.cos(np.linspace(0, 2 * np.pi, n, endpoint=False)), np.sin(np.linspace(0, 2 * np.pi, n,
                                                                                               endpoint=False))]
    with pytest.raises(ValueError, match="at most 16"):
        kernel.check_polygon(circle)


# --- property: intersection_polygon against Shapely ---------------------------
@st.composite
def convex_polygon(draw):
    """A convex polygon of 3 to 16 vertices on an ellipse, turned and moved:
    angular gaps drawn as weights (none below 1/20 of the largest, none
    of half a turn or more), sizes 1e-2 to 1e2 m, offsets up to 1e3 sizes."""
    n = draw(st.integers(3, kernel.MAX_BLOCK_VERTICES))
    # The gaps from a seed (drawing n floats one by one costs hypothesis ~10 ms an example).
    weights = np.random.default_rng(draw(st.integers(0, 2**32 - 1))).uniform(0.05, 1.0, n)
    k = int(np.argmax(weights))  # no gap of half a turn or more: the largest below the others' sum
    weights[k] = min(weights[k], 0.95 * (weights.sum() - weights[k]))
    gaps = 2 * math.pi * weights / weights.sum()
    angles = draw(st.floats(0, 2 * math.pi)) + np.cumsum(gaps)
    size = 10.0 ** draw(st.floats(-2, 2))
    aspect = draw(st.floats(0.2, 1.0))
    turn = draw(st.floats(0, 2 * math.pi))
    centre = np.array([draw(st.floats(-1e3, 1e3)), draw(st.floats(-1e3, 1e3))]) * size
    p = np.c_[np.cos(angles), aspect * np.sin(angles)] * size
    c, s = math.cos(turn), math.sin(turn)
    return p @ np.array([[c, s], [-s, c]]) + centre


@st.composite
def convex_pair(draw):
    """Two convex polygons placed to overlap, touch or miss: the second's
    centre put near the first's at a random fraction of their sizes."""
    a, b = draw(convex_polygon()), draw(convex_polygon())
    ra = np.ptp(a, axis=0).max()
    rb = np.ptp(b, axis=0).max()
    direction = draw(st.floats(0, 2 * math.pi))
    distance = draw(st.floats(0, 0.7)) * (ra + rb)
    b = b - b.mean(axis=0) + a.mean(axis=0) + distance * np.array([math.cos(direction), math.sin(direction)])
    return a, b


def accepted(p):
    try:
        kernel.check_polygon(p)
        return True
    except ValueError:
        return False


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(convex_pair())
def test_intersection_polygon_against_shapely(pair):
    a, b = pair
    assume(accepted(a) and accepted(b))
    tol = kernel.pair_tolerance(a, b)
    ip = kernel.intersection_polygon(a, b)
    # Areas about a local origin: the shoelace sum at offsets of 1e3 sizes
    # loses far more than the bound to round-off (eps |x| |y| per term).
    c = a.mean(axis=0)
    sa, sb = ShapelyPolygon(a - c), ShapelyPolygon(b - c)
    exact = sa.intersection(sb)
    exact_area = exact.area if not exact.is_empty else 0.0
    ip = ip - c
    d = min(np.ptp(a, axis=0).max(), np.ptp(b, axis=0).max()) * math.sqrt(2)  # >= the smaller diameter
    n = len(a) + len(b)
    # The area of the IP within kIpAreaBound (n + m) tol D of the exact one
    # (lib/include/dda/overlap.hpp); Shapely's own round-off is far below it.
    ip_area = shoelace(ip) if len(ip) else 0.0
    bound = kernel.IP_AREA_BOUND * n * tol * d
    assert abs(ip_area - exact_area) <= bound, (ip_area, exact_area, bound)
    # The overlap verdict: overlapping comes with an IP; separate with no
    # intersection beyond the bound.
    state = kernel.overlap_state(a, b)
    if state == "overlapping":
        assert len(ip) >= 3
    if state == "separate":
        assert exact_area <= bound
    if len(ip) == 0:
        return
    # Counter-clockwise and convex (every turn to the left).
    assert ip_area > 0
    e = np.roll(ip, -1, axis=0) - ip
    turns = e[:, 0] * np.roll(e, -1, axis=0)[:, 1] - e[:, 1] * np.roll(e, -1, axis=0)[:, 0]
    assert (turns > 0).all()
    # Every vertex within kIpVertexReach tol (Euclidean) of both inputs.
    reach = kernel.IP_VERTEX_REACH * tol
    for v in ip:
        pt = Point(v)
        assert sa.distance(pt) <= reach and sb.distance(pt) <= reach, (sa.distance(pt), sb.distance(pt), tol)


def test_the_normal_force_is_minus_the_gradient_of_the_contact_energy():
    # Eq. 10: f = -dE/dx for the contact polygon moved by x. A triangle's
    # corner pressed into a square near its corner (both of the square's
    # edges there shape the potential: the force has both components);
    # central differences of the exact contact energy against the force.
    tri = np.array([[0.9, 0.85], [1.7, 1.3], [1.1, 1.7]])
    sq = SQUARE * 1.2
    kn, h = 1e7, 0.8

    def energy(shift):
        return kernel.normal_contact_force(tri + shift, sq, kn=kn, h_cp=h, h_tp=h,
                                           integration="exact_envelope")["energy"]

    f = kernel.normal_contact_force(tri, sq, kn=kn, h_cp=h, h_tp=h, integration="exact_envelope")
    assert f["valid"] and f["energy"] > 0 and (np.abs(f["force"]) > 0.5 * np.abs(f["force"]).max()).all()
    step = 1e-6
    grad = np.array([(energy([step, 0]) - energy([-step, 0])) / (2 * step),
                     (energy([0, step]) - energy([0, -step])) / (2 * step)])
    assert np.allclose(f["force"], -grad, rtol=1e-5, atol=1e-6 * np.abs(f["force"]).max())
