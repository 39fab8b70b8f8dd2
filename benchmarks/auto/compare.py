#!/usr/bin/env python3
"""Orbit continuation cost per point: rbcstab against AUTO-07p on the same branch (docs/benchmarks.md).

The branch: Fig. 2's in-plane reduced scene (lambda = 5, Delta0 = 0.01, B = 2, C = 0.04, beta = pi/2), the
swinging orbits from Delta = 0.05 to 0.5. AUTO-07p runs benchmarks/auto/rbc.f90 (the same equations, made
autonomous with AUTO's forcing oscillator; analytic Jacobian, Floquet multipliers at every point, one thread)
at several NTST (NCOL = 4); rbcstab runs continuation_bench's BM_InPlaneOrbitBranchNoEvent (the same work per
point: Newton, tangent, multipliers) and BM_InPlaneOrbitBranchDelta (plus the swinging/tumbling event) at N
shooting segments. Accuracy: the periodicity defect of each tool's orbit at Delta = 0.5, integrated over one
period at rtol 1e-13 (an attracting orbit's state is off by about defect / (1 - |multiplier|)).

Usage: PYTHONPATH=build/release/python python3 benchmarks/auto/compare.py --bench build/release/bench/continuation_bench
AUTO-07p is found through $AUTO_DIR (a built source tree: lib/*.o); without it the script says so and exits 0.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
DELTA_START, DELTA_END = 0.05, 0.5


def scene():
    import rbcstab
    return rbcstab.Scene(lambda_=5, Delta=DELTA_START, Delta0=0.01, B=2, C=0.04, beta=math.pi / 2, delta=0, L=2,
                         model='reduced')


def forcing_constants():
    """kappa z0(0) (real, imaginary), 1/Lambda and kappa w0 at Delta = 0.05, read from rbcstab.rhs and checked."""
    import rbcstab
    s = scene()
    f = lambda t, y: np.asarray(rbcstab.rhs(s, 'reduced', t, np.asarray(y, float)))
    e1, e3 = [1.0, 0, 0], [0, 0, 1.0]
    kzr, kzi = f(0, e3)[0], -f(math.pi / 2, e3)[0]
    invL, kw = kzi - f(0, e3)[1], f(0, e1)[2]
    c = (kzr, kzi, invL, kw)
    rng = np.random.default_rng(1)
    for _ in range(5):  # the closed form below must be rbcstab's right-hand side
        y = rng.normal(size=3)
        t = rng.uniform(0, 2 * math.pi)
        assert np.max(np.abs(rhs(t, y, DELTA_START, c) - f(t, y))) < 1e-13
    return c


def rhs(t, y, Delta, c):
    kzr, kzi, invL, kw = c
    s = math.sqrt(DELTA_START / Delta)
    F = s * np.array([kzr * math.cos(t) - kzi * math.sin(t), kzr * math.sin(t) + kzi * math.cos(t) - invL, kw])
    mu = -(y @ F) / (y @ y)
    return mu * y + np.array([-y[1], y[0], 0.0]) + F


def defect(u0, t0, Delta, c):
    r = solve_ivp(lambda t, y: rhs(t, y, Delta, c), (t0, t0 + 2 * math.pi), u0, rtol=1e-13, atol=1e-14,
                  method='DOP853')
    return float(np.max(np.abs(r.y[:, -1] - u0)))


def start_data(c, path):
    y = solve_ivp(lambda t, y: rhs(t, y, DELTA_START, c), (0, 300 * 2 * math.pi), [1.0, 0, 0], rtol=1e-12,
                  atol=1e-13, method='DOP853').y[:, -1]
    ts = np.linspace(0, 2 * math.pi, 401)
    r = solve_ivp(lambda t, y: rhs(t, y, DELTA_START, c), (0, 2 * math.pi), y, rtol=1e-12, atol=1e-13,
                  method='DOP853', t_eval=ts)
    with open(path, 'w') as o:
        for i, t in enumerate(ts):
            o.write(' '.join('%.17e' % v for v in [t / (2 * math.pi), *r.y[:, i], math.sin(t), math.cos(t)]) + '\n')


def auto_constants(c, ntst):
    kzr, kzi, invL, kw = c
    return f"""e = 'rbc'
dat = 'rbc'
NDIM=   5, IPS =   2, IRS =   0, ILP =   1
ICP =  [1, 11]
NTST= {ntst}, NCOL=   4, IAD =   3, ISP =   2, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  500, NPR=  1000, MXBF=   0, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 1
EPSL= 1e-10, EPSU = 1e-10, EPSS =1e-8
DS  =  0.01, DSMIN= 1e-5, DSMAX=   0.5, IADS=   1
NPAR = 11, THL =  {{11: 0.0}}, THU =  {{}}
PAR = {{1: {DELTA_START}, 2: {kzr!r}, 3: {kzi!r}, 4: {invL!r}, 5: {kw!r}, 11: {2 * math.pi!r}}}
UZSTOP = {{1: {DELTA_END}}}
"""


def read_fort8(path):
    """AUTO's solution file: per label a header (12 integers), then t, U(1..NDIM) rows, then the parameters."""
    lines = open(path).read().split('\n')
    sols, i = [], 0
    while i < len(lines):
        h = lines[i].split()
        if len(h) < 12:
            i += 1
            continue
        lab, ntpl, nar, nrowpr, npar = int(h[3]), int(h[6]), int(h[7]), int(h[8]), int(h[11])
        vals = np.array(' '.join(lines[i + 1:i + 1 + nrowpr]).split(), float)
        sols.append((lab, vals[:ntpl * nar].reshape(ntpl, nar), vals[-npar:]))
        i += 1 + nrowpr
    return sols


def run_auto(auto_dir, c, ntsts, repeats):
    work = tempfile.mkdtemp(prefix='rbcstab_auto_')
    shutil.copy(os.path.join(HERE, 'rbc.f90'), work)
    objs = sorted(os.path.join(auto_dir, 'lib', f) for f in os.listdir(os.path.join(auto_dir, 'lib'))
                  if f.endswith('.o'))
    subprocess.run(['gfortran', '-O', '-fopenmp', 'rbc.f90', *objs, '-o', 'rbc.exe'], cwd=work, check=True)
    start_data(c, os.path.join(work, 'rbc.dat'))
    env = dict(os.environ, OMP_NUM_THREADS='1')
    rows = []
    for ntst in ntsts:
        with open(os.path.join(work, 'fort.2'), 'w') as f:
            f.write(auto_constants(c, ntst))
        before = os.times()
        for _ in range(repeats):
            subprocess.run(['./rbc.exe'], cwd=work, env=env, check=True, stdout=subprocess.DEVNULL)
        after = os.times()
        cpu = (after.children_user - before.children_user + after.children_system - before.children_system) / repeats
        # fort.7: one row per point, the branch number first (negative: stable), 0 on the header rows
        points = sum(1 for line in open(os.path.join(work, 'fort.7'))
                     if len(line.split()) > 5 and line.split()[0] in ('1', '-1'))
        lab, data, par = read_fort8(os.path.join(work, 'fort.8'))[-1]
        err = defect(data[0, 1:4], math.atan2(data[0, 4], data[0, 5]), par[0], c)
        rows.append(('AUTO-07p', f'NTST = {ntst}, NCOL = 4', points, cpu, err))
    shutil.rmtree(work)
    return rows


def run_ours(bench, c, configs):
    import rbcstab
    out = subprocess.run([bench, '--benchmark_filter=InPlaneOrbitBranch(NoEvent|Delta)/', '--benchmark_format=json',
                          '--benchmark_min_time=1'], check=True, capture_output=True, text=True).stdout
    cpu = {b['name']: (b['cpu_time'] / 1e3, b['points']) for b in json.loads(out)['benchmarks']}  # ms -> s
    rows = []
    for n, e in configs:
        rtol = 10.0 ** -e
        run = rbcstab.continuation(scene(), kind='orbit', parameter='Delta', min=DELTA_START, max=DELTA_END,
                                   direction='forward', segments=n, orbit_rtol=rtol, orbit_atol=rtol / 10)
        with tempfile.TemporaryDirectory() as d:
            run.save(os.path.join(d, 'b.json'))
            last = json.load(open(os.path.join(d, 'b.json')))['branch'][-1]
        err = defect(np.array(last['x'][:3]), 0.0, last['Delta'], c)
        names = [(f'NoEvent/{n}/{e}', 'same work as AUTO')]
        if e == 12:  # the event benchmark runs at the default rtol
            names.append((f'Delta/{n}', '+ swinging/tumbling event'))
        for name, what in names:
            t, points = cpu[f'BM_InPlaneOrbitBranch{name}']
            rows.append(('rbcstab', f'N = {n} segments, rtol 1e-{e} ({what})', int(points), t, err))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--bench', default='build/release/bench/continuation_bench')
    ap.add_argument('--auto-dir', default=os.environ.get('AUTO_DIR', ''))
    ap.add_argument('--repeats', type=int, default=10)
    a = ap.parse_args()
    if not a.auto_dir or not os.path.isdir(os.path.join(a.auto_dir, 'lib')):
        print('AUTO-07p not found (set AUTO_DIR to a built AUTO-07p tree): skipping the comparison')
        return 0
    if not shutil.which('gfortran'):
        print('gfortran not found: skipping the comparison')
        return 0
    c = forcing_constants()
    rows = run_auto(a.auto_dir, c, [4, 8, 16, 20, 40, 80], a.repeats) + run_ours(a.bench, c, [(4, 12), (8, 12), (16, 12), (4, 10), (4, 8)])
    print('| tool | mesh | points | CPU per branch | CPU per point | defect at Delta = 0.5 |')
    print('| --- | --- | --- | --- | --- | --- |')
    for tool, mesh, points, cpu, err in rows:
        print(f'| {tool} | {mesh} | {points} | {cpu * 1e3:.1f} ms | {cpu / points * 1e3:.2f} ms | {err:.1e} |')
    return 0


if __name__ == '__main__':
    sys.exit(main())
