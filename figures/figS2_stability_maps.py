"""Stability maps (S2): run class over (kn, dt) with the dt_crit lines.

usage: figS2_stability_maps.py DATA_DIR OUT_PNG
  DATA_DIR from the stability_maps driver: map_<name>.csv and
  boundary_<name>.csv for two_squares, bouncing_unified, bouncing_inscribed,
  and dt_crit_check.csv.

Left three panels: one per map, a marker per run (stable, energy growth
> 1 %, flip-through, blow-up), the solver's predicted dt_crit with the
region below it shaded (where the map's rows expect every run to be
stable), the simpler per-block estimate 2 kn L_max / H, the linearised
2/omega_max at the peak contact force (independent check), and the paper's
own (kn, dt) of the scene (Tables 4-5). Right panel: the dt_crit check on
resting contacts, each estimate divided by the linearised limit (<= 1 safe).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from paper_common import BAND_STYLE  # noqa: E402
from potential_common import finite as f, plt, read_rows, save_atomic  # noqa: E402

# Per map: title and the paper's own kn and dt for that scene (Paper A Tables 4 and 5).
MAPS = [("two_squares", "4.1 two squares, 1 m/s, unified H", (paper.A_41_KN, paper.A_41_DT, "Table 4")),
        ("bouncing_unified", "5.1 bouncing block case 1, unified H", (paper.A_5_KN, paper.A_51_DT, "Table 5")),
        ("bouncing_inscribed", "5.1 bouncing block case 1, inscribed-radius H",
         (paper.A_5_KN, paper.A_51_DT, "Table 5"))]
CLASSES = [("stable", "o", "tab:green", 18), ("energy growth > 1%", "^", "tab:orange", 26),
           ("flip-through", "D", "tab:purple", 24), ("blow-up", "x", "tab:red", 30)]


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    data, out_png = argv[1], argv[2]
    fig, grid = plt.subplots(2, 2, figsize=(15, 11.5))
    axes = list(grid.flat)
    for ax, (name, title, (kn_paper, dt_paper, table)) in zip(axes, MAPS):
        runs = read_rows(os.path.join(data, f"map_{name}.csv"))
        bnd = read_rows(os.path.join(data, f"boundary_{name}.csv"))
        kn_b = [f(b["kn"]) for b in bnd]
        dts = [f(r["dt"]) for r in runs]
        ax.fill_between(kn_b, min(dts) / 2.0, [f(b["predicted"]) for b in bnd], **BAND_STYLE,
                        label="dt <= predicted dt_crit: expected stable")
        for cls, marker, color, size in CLASSES:
            pts = [(f(r["kn"]), f(r["dt"])) for r in runs if r["class"] == cls]
            if pts:
                ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker=marker, c=color, s=size,
                           label=f"{cls} ({len(pts)})", zorder=3)
        kn = [f(b["kn"]) for b in bnd]
        ax.plot(kn, [f(b["predicted"]) for b in bnd], "k-", lw=2, label="predicted dt_crit (solver)", zorder=4)
        ax.plot(kn, [f(b["linearized_at_peak"]) for b in bnd], "b--", lw=1.3,
                label="linearised 2/omega at peak force", zorder=4)
        ax.plot(kn, [f(b["old_estimate"]) for b in bnd], ":", color="0.45", lw=1.5,
                label="per-block estimate 2 kn L_max / H", zorder=4)
        ax.plot([kn_paper], [dt_paper], "*", color="k", ms=16, mfc="gold", zorder=6,
                label=f"paper's kn {kn_paper / 1e6:g} MPa, dt {dt_paper:g} s ({table})")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(min(dts) / 2.0, max(dts) * 2.0)
        ax.set_xlabel("normal penalty kn (Pa)")
        ax.set_ylabel("time step dt (s)")
        ax.set_title("ours: " + title, fontsize=10)
        ax.grid(alpha=0.3, which="major")
        ax.legend(fontsize=7, loc="lower left", framealpha=0.9)
    ax = axes[3]
    check = read_rows(os.path.join(data, "dt_crit_check.csv"))
    y = list(range(len(check)))
    ax.axvspan(0.3, 1.0, **BAND_STYLE, label="<= 1: at or below the linearised limit (safe)")
    for key, marker, color, label in [("empirical_over_linearized", "o", "tab:green", "empirical (bisection)"),
                                      ("current_over_linearized", "s", "k", "solver: critical step in contact"),
                                      ("predicted_over_linearized", "^", "tab:blue", "solver: predicted"),
                                      ("old_over_linearized", "x", "tab:red", "per-block estimate 2 kn L_max / H")]:
        ax.scatter([f(r[key]) for r in check], y, marker=marker, c=color, label=label, zorder=3,
                   facecolors="none" if marker in "s^" else None)
    ax.axvline(1.0, color="0.3", lw=1)
    ax.set_yticks(y)
    ax.set_yticklabels([r["case"].replace("1 m square on a ", "").replace(" Pa", "") for r in check], fontsize=6)
    ax.invert_yaxis()
    ax.set_xlabel("dt_crit estimate / linearised 2/omega_max of the resting contact (dimensionless)")
    ax.set_title("ours: dt_crit check on resting contacts; > 1 is unsafe", fontsize=10)
    ax.grid(alpha=0.3, axis="x")
    ax.set_xlim(0.4, 1.25)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.4, 1.0))
    fig.suptitle("Beyond the papers: stability maps of Paper A's contact over kn and dt, collision window only "
                 "(2 ms + 4 contact half-periods, <= 0.4 s, >= 10 steps)\ndeformable blocks, rho 2000 kg/m3, E 1 GPa, "
                 "frictionless; 5.1 geometry reconstructed; star: the paper's own kn and dt", fontsize=11)
    fig.tight_layout()
    save_atomic(fig, out_png)


if __name__ == "__main__":
    main(sys.argv)
