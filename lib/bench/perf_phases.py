#!/usr/bin/python3
"""Where the time of a run goes, by phase of the explicit DDA step.

Reads `perf report --no-children --sort symbol --stdio` (self time per
function, from `perf record -e cpu-clock`) on standard input or from a file,
and sums the functions into the step's phases (lib/src/simulation/step.cpp
lists them in order). Functions the compiler inlined count for their caller:
the pair loop's own line holds the bookkeeping it inlines. Used by
`make profile` (profile first, write down where the time goes per
phase before and after a change).

Usage: perf report ... | perf_phases.py [--title TEXT]
"""
import re
import sys

# (phase, regular expression on the symbol), first match wins: the order
# matters where one name contains another.
PHASES = [
    ("pair: potential normal force and pg (Paper A Eqs. 11-20)",
     r"contact_force_n|one_side_edge|EdgeLines|normal_contact_force|potential_integral|bound_to_ip|inside_ip|"
     r"area_centroid|add_envelope_breaks|bisectors"),
    ("pair: overlap test + intersection polygon (Sect. 3.1)",
     r"clip_target|OverlapAndClip|cut_ring|clip_ring|overlap_and_intersection|separating_axes|emit_ring|"
     r"clean_result|overlap_state|intersection_polygon"),
    ("pair: friction (Eqs. 24-26)", r"pair_friction"),
    ("pair: loop, bookkeeping, guard measures", r"Simulation::pair_forces|extent_along|min_width|approach_energy"),
    ("blocks: move, geometry, body force (Eqs. 7-8, 4)",
     r"displace_vertices|move_blocks|update_block_geometry|green_moments|green_centroid|edge_normals|"
     r"update_polygon_geometry|body_force"),
    ("blocks: gather + kick (Eqs. 22-23, 28-29, 6-7)",
     r"gather_contact_forces|kick_block|gather_and_kick|force_acceleration"),
    ("guards and energy checks", r"guard|block_energy|contact_energy|energy"),
    ("broad phase", r"near_pairs|pair_before|introsort|insertion_sort|sweep|rebuild"),
    # perf shows libgomp's spin-wait (a worker idle between run_steps calls,
    # while the driver writes its output) as bare addresses.
    ("threads: team barrier, OpenMP idle wait, scheduler, kernel",
     r"team_barrier|sched|yield|omp|syscall|finish_task|^0x"),
    # The step loop itself, with whatever phase the compiler inlined into it.
    ("step loop (run_steps, with the phases inlined into it)", r"run_steps"),
]

LINE = re.compile(r"^\s*([0-9.]+)%\s+\[(.)\]\s+(.*?)\s*(?:-\s+-\s*)?$")


def main():
    args = sys.argv[1:]
    title = ""
    if len(args) >= 2 and args[0] == "--title":
        title = args[1]
        args = args[2:]
    text = open(args[0]).read() if args else sys.stdin.read()
    totals = {name: 0.0 for name, _ in PHASES}
    other = []
    seen = 0
    for line in text.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        seen += 1
        pct, space, sym = float(m.group(1)), m.group(2), m.group(3)
        if space == "k":
            sym = "syscall " + sym  # kernel time: the thread phase
        for name, rx in PHASES:
            if re.search(rx, sym):
                totals[name] += pct
                break
        else:
            other.append((pct, sym))
    if not seen:
        sys.exit("perf_phases.py: no 'perf report --stdio' lines on the input")
    if title:
        print(title)
    for name, _ in PHASES:
        # No sample at all: the phase's functions were inlined into a caller
        # (with link-time optimisation, e.g. friction into the pair loop).
        note = "  (inlined: counted in its caller)" if totals[name] == 0.0 else ""
        print(f"  {totals[name]:5.1f} %  {name}{note}")
    print(f"  {sum(p for p, _ in other):5.1f} %  other, largest: " +
          ", ".join(f"{s[:40]} {p:.2f} %" for p, s in sorted(other, reverse=True)[:3]))


if __name__ == "__main__":
    main()
