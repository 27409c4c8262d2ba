#!/usr/bin/python3
"""Instruction counts of the solver's hot paths, against the same counts taken
on commit 48051c9, so that a reader sees before and after in one table.

Instructions, not seconds: a shared virtual machine's speed varies by 2x
from one minute to the next, its instruction count for a deterministic run
does not. Counted with valgrind's callgrind (Debian package valgrind):

  the collapse window   BIN/collapse --out TMP --case 1 --threads 1 --duration 0.2
                        (Paper A Sect. 6.1, case 1: the first 0.2 s, 2000 steps,
                        the driver with its output)
  the guards' share     BIN/bench_collapse --window 0.2 with and without
                        --no-guards: the same trajectory (the fingerprints must
                        agree), the difference is what the switchable guards cost
  per overlapping pair  BIN/bench_pair_instructions N MODE PASSES, N = 4, 6, 8:
                        (I(3 passes) - I(1 pass)) / (2 * 1024 pairs), our full
                        normal contact (MODE 0) against Box2D 2.4's
                        b2CollidePolygons (MODE 2) on the same pairs

The 48051c9 numbers were counted by this script's method on a Release build
with link-time optimisation (the default), built from that commit, on
2026-11-28. Beside each count the script prints its target: the collapse
window at most 1.9e9 instructions (0.7 of 48051c9), the switchable guards
under 3 % of the window, the full normal contact at most 2.0 times Box2D's
manifold per pair.

usage: instructions.py BIN_DIR [--skip-collapse]
"""
import os
import re
import subprocess
import sys
import tempfile

# Counted on 48051c9 (Release, LTO), by the commands above.
BASE_COMMIT = "48051c9"
BASE_COLLAPSE = 2_718_508_198
BASE_PAIR = {4: (3617, 1285), 6: (6734, 1927), 8: (9399, 2760)}  # n: (ours, Box2D) per pair
TARGET_COLLAPSE = 1.9e9  # instructions of the collapse window
TARGET_GUARDS = 3.0      # % of the window
TARGET_RATIO = 2.0       # ours / Box2D per overlapping pair
PAIRS = 1024  # bench_pair_instructions' pairs per pass (pair_sides.hpp, kPairs)


def callgrind(cmd):
    """Instructions executed by cmd under callgrind, and its standard output."""
    run = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("instructions.py: %s failed:\n%s" % (" ".join(cmd), run.stderr[-2000:]))
    m = re.search(r"refs:\s+([\d,]+)", run.stderr)
    if not m:
        sys.exit("instructions.py: no instruction count from callgrind for %s" % " ".join(cmd))
    return int(m.group(1).replace(",", "")), run.stdout


def per_pair(bin_dir, n, mode):
    exe = os.path.join(bin_dir, "bench_pair_instructions")
    one, out1 = callgrind([exe, str(n), str(mode), "1"])
    three, _ = callgrind([exe, str(n), str(mode), "3"])
    return (three - one) / (2 * PAIRS), out1.strip()


def build_setting(bin_dir, name):
    """A cache entry of the CMake build tree that holds bin_dir ("?" if not found)."""
    cache = os.path.join(os.path.dirname(os.path.abspath(bin_dir)), "CMakeCache.txt")
    try:
        with open(cache) as f:
            for line in f:
                if line.startswith(name + ":"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return "?"


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    bin_dir = sys.argv[1]
    skip_collapse = "--skip-collapse" in sys.argv[2:]
    lto = build_setting(bin_dir, "DDA_LTO")
    print("== instructions (callgrind), against %s (Release, DDA_LTO=ON); this build: %s, DDA_LTO=%s" %
          (BASE_COMMIT, build_setting(bin_dir, "CMAKE_BUILD_TYPE"), lto))
    if lto != "ON":
        print("   (not like with like: without link-time optimisation the collapse window counts ~2.5 % more; "
              "make bench LTO=ON, or a build tree configured with -DDDA_LTO=ON)")
    if not skip_collapse:
        with tempfile.TemporaryDirectory() as tmp:
            ir, _ = callgrind([os.path.join(bin_dir, "collapse"), "--out", tmp, "--case", "1", "--threads", "1",
                               "--duration", "0.2"])
        print("   collapse window (case 1, 0.2 s, 1 thread): %.4e, %s: %.4e (%+.1f %%); target <= %.2g: %s" %
              (ir, BASE_COMMIT, BASE_COLLAPSE, 100.0 * (ir / BASE_COLLAPSE - 1.0), TARGET_COLLAPSE,
               "met" if ir <= TARGET_COLLAPSE else "not met"))
        bench = os.path.join(bin_dir, "bench_collapse")
        on, out_on = callgrind([bench, "--window", "0.2"])
        off, out_off = callgrind([bench, "--window", "0.2", "--no-guards"])
        same = out_on.split("fingerprint")[-1] == out_off.split("fingerprint")[-1]
        share = 100.0 * (on - off) / on
        print("   the switchable guards (bench_collapse --window 0.2, on - off): %.4e of %.4e = %.2f %% "
              "(same trajectory: %s); target < %.0f %%: %s" %
              (on - off, on, share, "yes" if same else "NO", TARGET_GUARDS,
               "met" if share < TARGET_GUARDS else "not met"))
    print("   per overlapping pair (bench_pair_instructions): ours / Box2D 2.4 b2CollidePolygons")
    print("   %3s %10s %10s %8s   %s %10s %8s   (target ratio <= %.1f)" %
          ("n", "ours", "Box2D", "ratio", BASE_COMMIT, "ours", "ratio", TARGET_RATIO))
    for n in (4, 6, 8):
        ours, checksum = per_pair(bin_dir, n, 0)
        box2d, _ = per_pair(bin_dir, n, 2)
        b_ours, b_box = BASE_PAIR[n]
        print("   %3d %10.0f %10.0f %8.2f   %7s %10d %8.2f   %s (checksum %s)" %
              (n, ours, box2d, ours / box2d, "", b_ours, b_ours / b_box,
               "met" if ours / box2d <= TARGET_RATIO else "not met", checksum))


if __name__ == "__main__":
    main()
