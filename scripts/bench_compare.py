#!/usr/bin/env python3
"""Compare two Google Benchmark JSON files (baseline, current) and report changes by ratio.

    scripts/bench_compare.py benchmarks/baseline/simulate_bench.json current.json [--noise 0.10] [--fail]

For every benchmark present in both: the ratio current/baseline of cpu_time, a verdict
(faster / slower / same within the noise band), and any change in the work counters
(rhs_evals, jac_evals, steps: deterministic, so any change is reported) and in the error
counters (err_*: reported when they grow by more than 10x). Exits 0 unless --fail is given and
a regression (time beyond the band, or more work) was found. Timing is never a CI gate.
"""
import argparse
import json
import math
import sys

WORK = ("rhs_evals", "jac_evals", "steps")


def load(path):
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        out[b["name"]] = b
    return data.get("context", {}), out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("baseline")
    ap.add_argument("current")
    ap.add_argument("--noise", type=float, default=0.10, help="relative band treated as noise (default 0.10)")
    ap.add_argument("--fail", action="store_true", help="exit 1 when a regression is found")
    a = ap.parse_args()
    if not (0 <= a.noise < 10):
        sys.exit("bench_compare: --noise = %g is out of range: must be in [0, 10)" % a.noise)
    ctx_b, base = load(a.baseline)
    ctx_c, cur = load(a.current)
    print(f"baseline: {ctx_b.get('date', '?')} on {ctx_b.get('host_name', '?')}, "
          f"current: {ctx_c.get('date', '?')} on {ctx_c.get('host_name', '?')}; noise band ±{a.noise:.0%}")
    regressions = 0
    width = max([len(n) for n in cur] + [9])
    print(f"{'benchmark':<{width}}  {'base ms':>10} {'now ms':>10} {'ratio':>7}  verdict / counter changes")
    for name in sorted(set(base) & set(cur)):
        b, c = base[name], cur[name]
        tb, tc = b["cpu_time"], c["cpu_time"]
        ratio = tc / tb if tb > 0 else math.inf
        if ratio > 1 + a.noise:
            verdict = "SLOWER"
            regressions += 1
        elif ratio < 1 / (1 + a.noise):
            verdict = "faster"
        else:
            verdict = "same"
        notes = []
        for k in WORK:
            if k in b and k in c and b[k] != c[k]:
                notes.append(f"{k} {b[k]:.0f}->{c[k]:.0f}")
                if c[k] > b[k]:
                    regressions += 1
        for k in sorted(b):
            if k.startswith("err_") and k in c and c[k] > 10 * max(b[k], 1e-300):
                notes.append(f"{k} {b[k]:.2e}->{c[k]:.2e}")
        unit = 1e-6 if b.get("time_unit") == "ns" else (1e-3 if b.get("time_unit") == "us" else 1.0)
        if b.get("time_unit") == "s":
            unit = 1e3
        print(f"{name:<{width}}  {tb * unit:>10.3f} {tc * unit:>10.3f} {ratio:>7.3f}  {verdict} {'; '.join(notes)}")
    for name in sorted(set(base) - set(cur)):
        print(f"{name:<{width}}  only in the baseline")
    for name in sorted(set(cur) - set(base)):
        print(f"{name:<{width}}  new (no baseline)")
    print(f"{regressions} regression(s)")
    return 1 if (a.fail and regressions) else 0


if __name__ == "__main__":
    sys.exit(main())
