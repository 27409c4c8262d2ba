"""Shared reading and drawing of block snapshots (Paper A Sect. 6, Figs. 20 and 22).

The drivers write, per run directory:
  frames.csv      time,block,vertex,x,y     polygons of every block (boundary polygons after the scene's blocks)
  blocks.csv      time,block,cx,cy,vx,vy,speed,dx,dy,rotation   per scene block at the same times
  boundaries.csv  ax,ay,bx,by,depth         fixed segments, solid on the right of a -> b
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402,F401
from matplotlib.collections import PolyCollection  # noqa: E402


class Frames:
    """Block polygons and per-block state at the written times."""

    def __init__(self, run_dir):
        _, f = read_csv(os.path.join(run_dir, "frames.csv"))
        _, b = read_csv(os.path.join(run_dir, "blocks.csv"))
        self.n_blocks = int(b["block"].max()) + 1  # scene blocks (boundary polygons are not in blocks.csv)
        self.times = np.unique(b["time"])
        self._f, self._b = f, b
        # Index the frames by time once (rows are grouped by time, then block, then vertex).
        self._frame_rows = {}
        t = f["time"]
        starts = np.flatnonzero(np.r_[True, t[1:] != t[:-1]])
        ends = np.r_[starts[1:], t.size]
        for s, e in zip(starts, ends):
            self._frame_rows[float(t[s])] = (s, e)
        tb = b["time"]
        starts = np.flatnonzero(np.r_[True, tb[1:] != tb[:-1]])
        ends = np.r_[starts[1:], tb.size]
        self._block_rows = {float(tb[s]): (s, e) for s, e in zip(starts, ends)}

    def nearest(self, t):
        return float(self.times[np.argmin(np.abs(self.times - t))])

    def polygons(self, t):
        """List of (N_i x 2) arrays for the scene blocks at time t (the nearest written)."""
        s, e = self._frame_rows[self.nearest(t)]
        blk = self._f["block"][s:e].astype(int)
        xy = np.column_stack([self._f["x"][s:e], self._f["y"][s:e]])
        cut = np.flatnonzero(np.r_[True, blk[1:] != blk[:-1]])
        parts = np.split(xy, cut[1:])
        ids = blk[cut]
        return [p for p, i in zip(parts, ids) if i < self.n_blocks]

    def state(self, t, column):
        s, e = self._block_rows[self.nearest(t)]
        return self._b[column][s:e]


def read_boundaries(path):
    _, b = read_csv(path)
    return [(b["ax"][i], b["ay"][i], b["bx"][i], b["by"][i], b["depth"][i]) for i in range(b["ax"].size)]


def draw_boundaries(ax, segments, shade=1.0):
    """Draws each fixed segment and a hatched strip on its solid side."""
    for ax_, ay_, bx_, by_, depth in segments:
        a, b = np.array([ax_, ay_]), np.array([bx_, by_])
        d = b - a
        right = np.array([d[1], -d[0]]) / np.hypot(*d)
        strip = np.array([a, b, b + shade * right, a + shade * right])
        ax.add_patch(plt.Polygon(strip, closed=True, facecolor="0.85", edgecolor="none", hatch="///", zorder=0))
        ax.plot([a[0], b[0]], [a[1], b[1]], color="0.2", lw=1.2, zorder=1)


def draw_blocks(ax, polys, values, norm, cmap="viridis", lw=0.3):
    pc = PolyCollection(polys, array=values, cmap=cmap, norm=norm, edgecolors="k", linewidths=lw, zorder=2)
    ax.add_collection(pc)
    return pc
