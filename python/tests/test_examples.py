"""The Monte Carlo example runs (a few short realisations) and reports what its table holds."""
import csv
import re
import subprocess
import sys

import numpy as np


def test_monte_carlo_slope(examples_dir, tmp_path):
    out = tmp_path / "mc"
    r = subprocess.run([sys.executable, str(examples_dir / "monte_carlo_slope.py"), "--n", "8", "--duration", "1.0",
                        "--threshold", "0.3", "--workers", "2", "--out", str(out)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    print(r.stdout)
    rows = list(csv.DictReader(open(out / "realisations.csv")))
    assert [int(row["realisation"]) for row in rows] == list(range(8))
    assert (out / "runout.png").stat().st_size > 10000
    ok = [row for row in rows if not row["error"]]
    k = sum(float(row["runout"]) > 0.3 for row in ok)
    m = re.search(r"P\(runout > 0.3 m\) = (\d+)/(\d+) = ([\d.]+), 95 % Wilson interval \[([\d.]+), ([\d.]+)\]",
                  r.stdout)
    assert m, r.stdout
    assert (int(m.group(1)), int(m.group(2))) == (k, len(ok))
    lo, p, hi = float(m.group(4)), float(m.group(3)), float(m.group(5))
    assert lo <= p <= hi and 0 <= lo and hi <= 1
    # The drawn dips and spacings are in the rows, and differ between realisations.
    dips = np.array([float(row["dip_deg"]) for row in rows])
    assert len(set(dips)) == 8 and 10 < dips.mean() < 60
