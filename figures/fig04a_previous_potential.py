"""Paper A Fig. 4a (beside 4b): 'previous' sub-polygon potential, RECONSTRUCTED, vs the shortest-exit one.

usage: fig04a_previous_potential.py DATA_DIR OUT_PNG   (DATA_DIR from the previous_potential driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
notes, g = read_csv(os.path.join(sys.argv[1], "fig04a_grid.csv"))
_, o = read_csv(os.path.join(sys.argv[1], "outline.csv"))
_, sp = read_csv(os.path.join(sys.argv[1], "subpolygons.csv"))
xs, ys = np.unique(g["x"]), np.unique(g["y"])
nx, ny = xs.size, ys.size
if nx * ny != g["x"].size:
    raise SystemExit("fig04a_grid.csv is not a full grid")
X, Y = g["x"].reshape(ny, nx), g["y"].reshape(ny, nx)
inside = g["inside"].reshape(ny, nx) > 0.5
defined = g["defined"].reshape(ny, nx) > 0.5
top = float(g["phi_current"].max())
levels = np.linspace(0.0, top, 21)
fig, axes = plt.subplots(1, 2, figsize=(13, 7.2), layout="constrained")
px, py = np.append(o["x"], o["x"][0]), np.append(o["y"], o["y"][0])
for ax, key, mask, title in (
        (axes[0], "phi_previous", ~defined, "(a) previous sub-polygon definition (RECONSTRUCTED):\n"
                                            "hatched = inside the polygon but in no sub-polygon"),
        (axes[1], "phi_current", ~inside, "(b) shortest-exit definition (Eq. 12), as Fig. 4b")):
    field = np.ma.masked_where(mask, g[key].reshape(ny, nx))
    cf = ax.contourf(X, Y, field, levels=levels, cmap="viridis")
    if key == "phi_previous":
        hole = np.ma.masked_where(~(inside & ~defined), np.ones_like(X))
        ax.contourf(X, Y, hole, levels=[0.5, 1.5], colors="none", hatches=["///"])
        for k in np.unique(sp["subpolygon"]):
            m = sp["subpolygon"] == k
            ax.plot(np.append(sp["x"][m], sp["x"][m][0]), np.append(sp["y"][m], sp["y"][m][0]), "w-", lw=0.5)
    ax.plot(px, py, "k-", lw=1.2, label="polygon outline (reconstructed)")
    for i in range(o["x"].size):
        if o["edge_length"][i] < 0.1:
            j = (i + 1) % o["x"].size
            ax.plot([o["x"][i], o["x"][j]], [o["y"][i], o["y"][j]], "r-", lw=3)
    ax.plot([], [], "r-", lw=3, label="edges shorter than 0.1 m (0.03 and 0.05 m)")
    if key == "phi_previous":
        ax.plot([], [], "-", color="0.75", lw=0.8, label="sub-polygon boundaries (white)")
        ax.add_patch(plt.Rectangle((0, 0), 0, 0, fc="none", ec="k", hatch="///",
                                   label="inside, in no sub-polygon: no potential"))
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.1), ncol=2, frameon=False)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
cb = fig.colorbar(cf, ax=axes, shrink=0.8)
cb.set_label(r"potential $\varphi$ (Pa), kn = 1 Pa, H = 1 m")
undef = 100.0 * (1.0 - defined.sum() / inside.sum())
fig.suptitle("Paper A Fig. 4: potential of a polygon with small edges, previous definition (a) against the shortest "
             "exit (b)\n(geometry and the previous sub-polygons reconstructed, figure lost; kn = 1 Pa, H = 1 m as in "
             "Sect. 3.2.2)\nours: %.0f %% of the polygon has no potential under (a); paper: 'a large inner part without "
             "a valid potential definition'" % undef, fontsize=10)
save_atomic(fig, sys.argv[2])
