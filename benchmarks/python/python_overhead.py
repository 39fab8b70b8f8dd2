"""What the Python layer costs: rbcstab.simulate on a scene against the same C++ work (truncation, run, JSON),
timed in one process, interleaved so that machine load affects both alike. A benchmark, not a test:

    PYTHONPATH=build/release/python /usr/bin/python3 benchmarks/python/python_overhead.py [--repeats N]

Prints the median seconds of each and their ratio (docs/benchmarks.md records it)."""
import argparse
import statistics
import time

import rbcstab
from rbcstab import _rbcstab


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=200)
    args = ap.parse_args()
    scene = rbcstab.Scene()
    rbcstab.simulate(scene)  # warm up (page faults, first allocations)
    py_times, cpp_times = [], []
    for _ in range(args.repeats):
        start = time.perf_counter()
        rbcstab.simulate(scene)
        py_times.append(time.perf_counter() - start)
        cpp_times.append(_rbcstab._time_simulate_cpp(scene, 1)[0])
    py, cpp = statistics.median(py_times), statistics.median(cpp_times)
    print(f"default scene, {args.repeats} interleaved repeats: Python rbcstab.simulate {py * 1e3:.3f} ms, "
          f"C++ (truncation + simulate + JSON) {cpp * 1e3:.3f} ms, ratio {py / cpp:.3f} "
          f"(Python overhead {100 * (py / cpp - 1):.1f} %)")


if __name__ == "__main__":
    main()
