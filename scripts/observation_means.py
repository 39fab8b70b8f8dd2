#!/usr/bin/env python3
"""Donor means of the inclination angles of data/observations/fischer2015.csv, for a fit of a typical cell.

Each row of the original file is one donor's angle at one (shear rate, viscosity); the donors differ by 1-3 deg,
far above the 0.2 deg reading error, so the spread between donors is the uncertainty that matters. This script
averages the donors at each condition and gives the mean's standard error, sd/sqrt(n) (sample sd over the n
donors), floored at the reading error 0.2 deg; conditions with fewer than MIN_DONORS donors are dropped (no
spread to estimate). Only the inclination_angle rows are used. The output keeps the original's comment lines
and says how it was made, so the derived file is never edited by hand:

    python3 scripts/observation_means.py data/observations/fischer2015.csv data/observations/fischer2015_means.csv
"""
import csv
import io
import math
import os
import sys
import tempfile

MIN_DONORS = 3
READING_ERROR_DEG = 0.2


def means(text):
    comments, body = [], []
    for line in text.splitlines():
        (comments if line.startswith("#") else body).append(line)
    rows = list(csv.DictReader(io.StringIO("\n".join(body))))
    groups = {}
    for r in rows:
        if r["observable"] != "inclination_angle":
            continue
        if r["unit"] != "deg":
            raise SystemExit(f"unexpected unit {r['unit']!r} on an inclination_angle row (expected deg)")
        key = (float(r["viscosity[mPa s]"]), float(r["shear_rate[1/s]"]))
        groups.setdefault(key, []).append(float(r["value"]))
    out = []
    for (eta, rate), v in sorted(groups.items()):
        n = len(v)
        if n < MIN_DONORS:
            continue
        m = sum(v) / n
        sd = math.sqrt(sum((x - m) ** 2 for x in v) / (n - 1))
        se = max(sd / math.sqrt(n), READING_ERROR_DEG)
        out.append((rate, eta, m, se, n, sd))
    return comments, out


def render(source, comments, out):
    lines = [f"# DERIVED from {source} by scripts/observation_means.py (do not edit by hand: rerun the script)."]
    lines.append(f"# One row per (shear rate, viscosity) with >= {MIN_DONORS} donors: value = mean over donors of the")
    lines.append(f"# inclination angle; uncertainty = max(sd/sqrt(n), {READING_ERROR_DEG} deg reading error), sd the sample SD")
    lines.append("# over the n donors (the donor spread; the mean's standard error). Tank-treading frequency rows not used.")
    lines.append("# The original file's comments follow.")
    lines += comments
    lines.append("observable,shear_rate[1/s],viscosity[mPa s],value,uncertainty,unit,regime,note")
    for rate, eta, m, se, n, sd in out:
        lines.append(f"inclination_angle,{rate:.5g},{eta:.4g},{m:.4f},{se:.4f},deg,tank-treading,"
                     f"mean of {n} donors; donor sd {sd:.3f} deg")
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    src, dst = argv[1], argv[2]
    with open(src, encoding="utf-8") as f:
        comments, out = means(f.read())
    text = render(os.path.basename(src), comments, out)
    d = os.path.dirname(os.path.abspath(dst))
    fd, tmp = tempfile.mkstemp(dir=d, prefix=".means.")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, dst)  # atomic: a reader never sees half a file
    print(f"{dst}: {len(out)} rows")


if __name__ == "__main__":
    main(sys.argv)
