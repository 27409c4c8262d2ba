#!/usr/bin/python3
"""Reads the ParaView series back with VTK's own reader and checks it against the CSV files.

Paper A (`dda run` on lib/io/tests/data/vtk_stack.json, blocks falling and sliding onto a floor):
  * blocks.pvd / contacts.pvd list one frame per snapshot time, with the times of snapshots.csv;
  * each blocks_*.vtu: as many polygons and points as snapshots.csv at that time, the same
    coordinates (exactly: both are shortest round-trip text), the cell data equal to blocks.csv
    (velocity, spin, rotation, stress, centroid) and to run.json (fixed, boundary polygons);
  * each contacts_*.vtu: as many points as the `contacts` column of timeseries.csv at that time,
    the forces on the contact polygon pushing it away from the target, penetration =
    overlap_area / contact_length;
  * --vtk-every N: frames every N steps and at the last, at the times of timeseries.csv.
figures/plot_run.py draws the Paper A run into a PNG.
Paper B (io_vtk_cdem_series on the two-prisms scene): elements_*.vtu and clones_*.vtu hold the
triangles, stresses, clone points and forces that the model reported (elements.csv, clones.csv),
the triangles share their nodes, and the clone's force splits into a normal and a shear part.

Usage: vtk_readback.py DDA_CLI SCENE CDEM_SERIES_EXE TMP_DIR
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    return rows


def read_pvd(path):
    root = ET.parse(path).getroot()
    sets = root.find("Collection").findall("DataSet")
    return [(float(d.get("timestep")), os.path.join(os.path.dirname(path), d.get("file"))) for d in sets]


def read_vtu(path):
    """The grid VTK's XML reader makes of `path`; fails on any reader error or warning."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    messages = []

    def on_event(obj, event):
        messages.append(event)

    reader.AddObserver("ErrorEvent", on_event)
    reader.AddObserver("WarningEvent", on_event)
    reader.Update()
    check(not messages, f"{path}: VTK reader reported {messages}")
    grid = reader.GetOutput()
    check(grid is not None, f"{path}: no output")
    return grid


def array(data, name, path):
    a = data.GetArray(name)
    if a is None:
        raise SystemExit(f"{path}: no array '{name}'")
    return vtk_to_numpy(a)


def cells(grid):
    """[(type, [point ids])] of every cell."""
    out = []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        ids = cell.GetPointIds()
        out.append((grid.GetCellType(c), [ids.GetId(k) for k in range(ids.GetNumberOfIds())]))
    return out


def run(cmd):
    print("$", " ".join(cmd))
    p = subprocess.run(cmd, capture_output=True, text=True)
    print(p.stdout + p.stderr, end="")
    if p.returncode != 0:
        raise SystemExit(f"exit {p.returncode}: {' '.join(cmd)}")


def check_paper_a(dda, scene, out):
    shutil.rmtree(out, ignore_errors=True)
    run([dda, "run", scene, "--out", out, "--quiet"])
    with open(os.path.join(out, "run.json")) as f:
        info = json.load(f)
    kinds = [b["kind"] for b in info["blocks"]]
    fixed = [1 if b["fixed"] or b["kind"] == "boundary" else 0 for b in info["blocks"]]
    n_scene = kinds.count("block")

    snaps = defaultdict(list)  # time -> rows
    for r in read_csv(os.path.join(out, "snapshots.csv")):
        snaps[float(r["time"])].append(r)
    table = defaultdict(dict)  # time -> block -> row
    for r in read_csv(os.path.join(out, "blocks.csv")):
        table[float(r["time"])][int(r["block"])] = r
    series = {float(r["time"]): r for r in read_csv(os.path.join(out, "timeseries.csv"))}

    blocks = read_pvd(os.path.join(out, "vtk", "blocks.pvd"))
    contacts = read_pvd(os.path.join(out, "vtk", "contacts.pvd"))
    check([t for t, _ in blocks] == sorted(snaps), f"blocks.pvd times {[t for t, _ in blocks]} != snapshot times {sorted(snaps)}")
    check([t for t, _ in contacts] == [t for t, _ in blocks], "contacts.pvd and blocks.pvd times differ")
    check(info["vtk_frames"] == len(blocks), f"run.json vtk_frames {info['vtk_frames']} != {len(blocks)}")
    total_contacts = 0
    for (t, bpath), (_, cpath) in zip(blocks, contacts):
        g = read_vtu(bpath)
        check(vtk_to_numpy(g.GetFieldData().GetArray("TimeValue"))[0] == t, f"{bpath}: TimeValue != {t}")
        rows = snaps[t]
        n_poly = len({int(r["block"]) for r in rows})
        check(g.GetNumberOfCells() == n_poly, f"{bpath}: {g.GetNumberOfCells()} cells, snapshots.csv has {n_poly} polygons")
        check(g.GetNumberOfPoints() == len(rows), f"{bpath}: {g.GetNumberOfPoints()} points, snapshots.csv {len(rows)} vertices")
        pts = vtk_to_numpy(g.GetPoints().GetData())
        cs = cells(g)
        # vertices of polygon b in snapshots.csv order
        for b in range(n_poly):
            verts = [(float(r["x"]), float(r["y"])) for r in rows if int(r["block"]) == b]
            typ, ids = cs[b]
            check(typ == (vtk.VTK_TRIANGLE if len(verts) == 3 else vtk.VTK_POLYGON), f"{bpath}: cell {b} type {typ}")
            got = [(pts[i][0], pts[i][1]) for i in ids]
            check(got == verts, f"{bpath}: cell {b} vertices {got} != snapshots.csv {verts}")
            check(all(pts[i][2] == 0.0 for i in ids), f"{bpath}: cell {b} has z != 0")
        cd = g.GetCellData()
        block = array(cd, "block", bpath)
        check(list(block) == list(range(n_poly)), f"{bpath}: block ids {list(block)}")
        check(list(array(cd, "fixed", bpath)) == fixed, f"{bpath}: fixed != run.json")
        check(list(array(cd, "boundary", bpath)) == [1 if k == "boundary" else 0 for k in kinds], f"{bpath}: boundary flags")
        velocity, spin = array(cd, "velocity", bpath), array(cd, "spin", bpath)
        rotation, stress, centroid = array(cd, "rotation", bpath), array(cd, "stress", bpath), array(cd, "centroid", bpath)
        check(cd.GetArray("stress").GetComponentName(2) == "sxy", f"{bpath}: stress component names")
        speed = array(cd, "speed", bpath)
        rows_t = table[t]
        check(len(rows_t) == n_scene, f"blocks.csv has {len(rows_t)} rows at t = {t}, expected {n_scene}")
        for b in range(n_scene):
            r = rows_t[b]
            want = {
                "vx": velocity[b][0], "vy": velocity[b][1], "spin": spin[b], "rot": rotation[b],
                "sxx": stress[b][0], "syy": stress[b][1], "sxy": stress[b][2], "x": centroid[b][0], "y": centroid[b][1],
            }
            for col, v in want.items():
                check(float(r[col]) == v, f"{bpath}: block {b} {col} = {v}, blocks.csv {r[col]}")
            check(math.isclose(speed[b], math.hypot(velocity[b][0], velocity[b][1]), rel_tol=1e-15, abs_tol=1e-300),
                  f"{bpath}: block {b} speed")
            check(velocity[b][2] == 0.0, f"{bpath}: block {b} velocity z")
        # contacts
        c = read_vtu(cpath)
        n_contacts = int(series[t]["contacts"])
        total_contacts += n_contacts
        check(c.GetNumberOfPoints() == n_contacts,
              f"{cpath}: {c.GetNumberOfPoints()} contact points, timeseries.csv says {n_contacts} at t = {t}")
        check(c.GetNumberOfCells() == n_contacts, f"{cpath}: {c.GetNumberOfCells()} cells")
        check(all(typ == vtk.VTK_VERTEX and len(ids) == 1 for typ, ids in cells(c)), f"{cpath}: not vertex cells")
        if n_contacts == 0:
            continue
        pd = c.GetPointData()
        cp, tp = array(pd, "block", cpath), array(pd, "target", cpath)
        fn, ft = array(pd, "normal_force", cpath), array(pd, "shear_force", cpath)
        pen, area, length = array(pd, "penetration", cpath), array(pd, "overlap_area", cpath), array(pd, "contact_length", cpath)
        cpts = vtk_to_numpy(c.GetPoints().GetData())
        for k in range(n_contacts):
            a, b = int(cp[k]), int(tp[k])
            check(0 <= a < n_poly and 0 <= b < n_poly and a != b, f"{cpath}: contact {k} blocks {a}, {b}")
            check(math.isclose(pen[k], area[k] / length[k], rel_tol=1e-15), f"{cpath}: contact {k} penetration != area / length")
            check(pen[k] >= 0 and area[k] >= 0 and length[k] > 0, f"{cpath}: contact {k} negative size")
            # The normal force on CP pushes it away from TP: from TP's centroid toward CP's
            # (centroids of the vertices in snapshots.csv).
            ca = np.mean([(float(r["x"]), float(r["y"])) for r in rows if int(r["block"]) == a], axis=0)
            cb = np.mean([(float(r["x"]), float(r["y"])) for r in rows if int(r["block"]) == b], axis=0)
            check(np.dot(fn[k][:2], ca - cb) > 0, f"{cpath}: contact {k} normal force {fn[k]} pulls block {a} toward {b}")
            check(np.dot(fn[k][:2], ft[k][:2]) <= 1e-9 * np.linalg.norm(fn[k]) * np.linalg.norm(ft[k]) + 1e-300,
                  f"{cpath}: contact {k} shear force not perpendicular to the normal force")
            # The loading point lies in both polygons' bounding boxes (grown by the penetration).
            for blk in (a, b):
                xy = np.array([(float(r["x"]), float(r["y"])) for r in rows if int(r["block"]) == blk])
                lo, hi = xy.min(axis=0) - pen[k] - 1e-12, xy.max(axis=0) + pen[k] + 1e-12
                check(np.all(cpts[k][:2] >= lo) and np.all(cpts[k][:2] <= hi),
                      f"{cpath}: contact {k} point {cpts[k]} outside block {blk}'s box")
    check(total_contacts > 0, "the test scene has no contact at any snapshot time (a test that cannot fail)")
    print(f"Paper A: {len(blocks)} frames, {n_scene} blocks + {len(kinds) - n_scene} boundary polygons, "
          f"{total_contacts} contact points checked")

    # --vtk-every: frames at steps 0, N, 2N, ... and the last step.
    every = 700
    out2 = out + "_every"
    shutil.rmtree(out2, ignore_errors=True)
    run([dda, "run", scene, "--out", out2, "--quiet", "--vtk-every", str(every)])
    frames = read_pvd(os.path.join(out2, "vtk", "blocks.pvd"))
    rows = read_csv(os.path.join(out2, "timeseries.csv"))
    last = int(rows[-1]["step"])
    want_steps = sorted(set(list(range(0, last + 1, every)) + [last]))
    by_step = {int(r["step"]): float(r["time"]) for r in rows}
    want_times = [by_step[s] for s in want_steps]
    check([t for t, _ in frames] == want_times, f"--vtk-every {every}: frame times {[t for t, _ in frames]} != {want_times}")
    for t, path in frames:
        check(read_vtu(path).GetNumberOfCells() == len(kinds), f"{path}: cell count")
    print(f"--vtk-every {every}: {len(frames)} frames at steps {want_steps}")


def check_paper_b(exe, out):
    shutil.rmtree(out, ignore_errors=True)
    run([exe, out])
    tris = defaultdict(list)
    for r in read_csv(os.path.join(out, "elements.csv")):
        tris[int(r["frame"])].append(r)
    clones = defaultdict(list)
    with open(os.path.join(out, "clones.csv"), newline="") as f:
        for r in csv.DictReader(f):
            clones[int(r["frame"])].append(r)
    elements = read_pvd(os.path.join(out, "vtk", "elements.pvd"))
    contacts = read_pvd(os.path.join(out, "vtk", "clones.pvd"))
    check(len(elements) == len(tris) == len(contacts), f"{len(elements)} element frames, {len(tris)} in elements.csv")
    frames_with_clones = frames_with_sub = 0
    for k, ((t, epath), (tc, cpath)) in enumerate(zip(elements, contacts)):
        g = read_vtu(epath)
        rows = tris[k]
        check(float(rows[0]["time"]) == t == tc, f"{epath}: time {t} != elements.csv {rows[0]['time']}")
        check(g.GetNumberOfCells() == len(rows), f"{epath}: {g.GetNumberOfCells()} triangles, elements.csv {len(rows)}")
        pts = vtk_to_numpy(g.GetPoints().GetData())
        cs = cells(g)
        stress = array(g.GetCellData(), "stress", epath)
        blk = array(g.GetCellData(), "block", epath)
        for c, r in enumerate(rows):
            typ, ids = cs[c]
            check(typ == vtk.VTK_TRIANGLE, f"{epath}: cell {c} type {typ}")
            got = [(pts[i][0], pts[i][1]) for i in ids]
            want = [(float(r[f"x{q}"]), float(r[f"y{q}"])) for q in range(3)]
            check(got == want, f"{epath}: triangle {c} {got} != {want}")
            check([stress[c][0], stress[c][1], stress[c][2]] == [float(r["sxx"]), float(r["syy"]), float(r["sxy"])],
                  f"{epath}: triangle {c} stress")
            check(blk[c] == int(r["block"]), f"{epath}: triangle {c} block")
        check(g.GetNumberOfPoints() < 3 * g.GetNumberOfCells(), f"{epath}: triangles share no node")
        node = array(g.GetPointData(), "node", epath)
        kind = array(g.GetPointData(), "kind", epath)
        ids = node[node >= 0]
        check(len(set(ids.tolist())) == len(ids), f"{epath}: a model node written twice")
        check(np.all((kind == 3) == (node < 0)), f"{epath}: sub-nodes are the points without a node id")
        frames_with_sub += int(np.any(kind == 3))
        c = read_vtu(cpath)
        want = clones[k]
        check(c.GetNumberOfPoints() == len(want), f"{cpath}: {c.GetNumberOfPoints()} clone points, clones.csv {len(want)}")
        if want:
            frames_with_clones += 1
            pd = c.GetPointData()
            cpts = vtk_to_numpy(c.GetPoints().GetData())
            force, fn, ft = array(pd, "force", cpath), array(pd, "normal_force", cpath), array(pd, "shear_force", cpath)
            nodes = array(pd, "node", cpath)
            for q, r in enumerate(want):
                check((cpts[q][0], cpts[q][1]) == (float(r["x"]), float(r["y"])), f"{cpath}: clone {q} point")
                check(int(nodes[q]) == int(r["node"]), f"{cpath}: clone {q} node")
                check((force[q][0], force[q][1]) == (float(r["fx"]), float(r["fy"])), f"{cpath}: clone {q} force")
                n = np.array([float(r["nx"]), float(r["ny"])])
                scale = np.linalg.norm(force[q]) + 1e-300
                check(np.allclose(fn[q][:2] + ft[q][:2], force[q][:2], rtol=0, atol=1e-12 * scale), f"{cpath}: clone {q} split")
                check(abs(np.dot(ft[q][:2], n)) <= 1e-12 * scale, f"{cpath}: clone {q} shear along the normal")
    check(frames_with_clones > 0, "no frame with a clone node (a test that cannot fail)")
    check(frames_with_sub > 0, "no frame with a live sub-model")
    print(f"Paper B: {len(elements)} frames, {frames_with_clones} with clone nodes, {frames_with_sub} with a sub-model")


def check_plot(run_dir):
    """figures/plot_run.py draws the run into a PNG; a time without a snapshot is named on stderr."""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "figures", "plot_run.py")
    png = os.path.join(run_dir, "plot.png")
    if os.path.exists(png):
        os.remove(png)
    p = subprocess.run([sys.executable, script, run_dir, "--times", "0", "0.1", "0.3", "--out", png],
                       capture_output=True, text=True)
    print(p.stdout + p.stderr, end="")
    check(p.returncode == 0, f"plot_run.py exit {p.returncode}")
    check("no snapshot at t = 0.3 s; drawing the nearest, t = 0.35 s" in p.stderr, "plot_run.py: nearest-time note")
    with open(png, "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{png}: not a PNG")
    check(not os.path.exists(png + ".tmp"), f"{png}.tmp left behind")


def main():
    if len(sys.argv) != 5:
        raise SystemExit(__doc__)
    dda, scene, exe, tmp = sys.argv[1:]
    os.makedirs(tmp, exist_ok=True)
    print("VTK", vtk.vtkVersion.GetVTKVersion())
    check_paper_a(dda, scene, os.path.join(tmp, "paper_a"))
    check_plot(os.path.join(tmp, "paper_a"))
    check_paper_b(exe, os.path.join(tmp, "paper_b"))
    if failures:
        print(f"{len(failures)} checks failed")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
