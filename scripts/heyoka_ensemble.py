"""heyoka's ensembles on the problems of `benches/ensemble.rs`, at the same tolerances, against
the same references: runs per second of

  (a) the heavy top of examples/heavy_top.rs (Euler–Poisson form) released 20° from the
      vertical at 150 rad/s, to 10¼ nutation periods, run i turned by ψ0 = 2π i / N about its
      figure axis (a symmetry: every run has the same exact cos θ(t), but its own arithmetic);
  (b) the torque-free body I = (3, 5, 9) from m0 = (0, 2, 0.01 (1 + i / N)) to T = 200;

each by `ensemble_propagate_until` (one scalar integrator per run, copied from a template)
and `ensemble_propagate_until_batch` (runs in SIMD lanes, `recommended_simd_size()` of them),
on one worker and on all cores (Python threads; heyoka releases the GIL while it integrates),
and by plain loops that reuse one integrator (scalar, or batch on one thread per core). The
bench's "top (EP)" and "free (eq)" rows integrate these same equations in precess.

    pip install heyoka
    python3 scripts/heyoka_ensemble.py [N]

The error of (a) is the largest over the runs of |cos θ(T) − cos θ_exact(T)|, the exact value
from `HeavyTopMotion::cos_theta_at` (printed by `cargo bench -p precess-benches --bench ensemble`, copied here);
the error of (b) is run 0's max-norm error against the exact m(200) of `FreeBodyExact` (its
other runs start elsewhere). Times are the best of 3 whole ensembles (on a shared machine the
minimum is the closer to the unloaded time), set-up (building and JIT-compiling the
integrator) outside the timing.
"""

import copy
import math
import os
import sys
import time

import heyoka as hy
import numpy as np
from concurrent.futures import ThreadPoolExecutor

TOP_I1 = 0.0006013558333333334
TOP_I3 = 0.000160045
TOP_MGL = 0.10202399999999999
TOP_PERIOD = 0.20103746949366902
# cos θ at 10¼ nutation periods, the elliptic closed form (benches/ensemble.rs prints it).
TOP_COS_END = 9.19302867564536275e-1
FREE_I = (3.0, 5.0, 9.0)
FREE_M200 = [0.5586653843883227, -1.794361298823517, 0.6842956360891311]
TOLS = [1e-10, 1e-12, 1e-14]
THETA0 = math.radians(20.0)


def heavy_top_sys():
    w1, w2, w3, g1, g2, g3 = hy.make_vars("w1", "w2", "w3", "g1", "g2", "g3")
    r, s = (TOP_I1 - TOP_I3) / TOP_I1, TOP_MGL / TOP_I1
    return [
        (w1, r * w2 * w3 + s * g2),
        (w2, -r * w3 * w1 - s * g1),
        (w3, 0.0 * w3),
        (g1, g2 * w3 - g3 * w2),
        (g2, g3 * w1 - g1 * w3),
        (g3, g1 * w2 - g2 * w1),
    ]


def heavy_top_y0(i, n):
    psi = 2.0 * math.pi * i / n
    st = math.sin(THETA0)
    return [0.0, 0.0, 150.0, st * math.sin(psi), st * math.cos(psi), math.cos(THETA0)]


def free_sys():
    m1, m2, m3 = hy.make_vars("m1", "m2", "m3")
    i1, i2, i3 = FREE_I
    a = [1 / i3 - 1 / i2, 1 / i1 - 1 / i3, 1 / i2 - 1 / i1]
    return [(m1, a[0] * m2 * m3), (m2, a[1] * m3 * m1), (m3, a[2] * m1 * m2)]


def free_y0(i, n):
    return [0.0, 2.0, 0.01 * (1.0 + i / n)]


def best_of(call, repeats=3):
    best = math.inf
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = call()
        best = min(best, time.perf_counter() - t0)
    return best, out


def scalar_ensemble(sys_, y0, t_end, n, tol, workers):
    ta = hy.taylor_adaptive(sys_, y0(0, n), tol=tol)

    def gen(ta_i, i):
        ta_i.time = 0.0
        ta_i.state[:] = y0(i, n)
        return ta_i

    def call():
        res = hy.ensemble_propagate_until(ta, t_end, n, gen, max_workers=workers)
        return np.array([r[0].state for r in res])

    return best_of(call)


def scalar_loop(sys_, y0, t_end, n, tol):
    """Not an ensemble: one integrator reset and reused by a plain loop on one core, no copy
    per run (the cheapest way to run many on one core from Python)."""
    ta = hy.taylor_adaptive(sys_, y0(0, n), tol=tol)

    def call():
        out = []
        for i in range(n):
            ta.time = 0.0
            ta.state[:] = y0(i, n)
            ta.propagate_until(t_end)
            out.append(ta.state.copy())
        return out

    return best_of(call)


def batch_loop(sys_, y0, t_end, n, tol):
    """As `scalar_loop`, a batch integrator over the runs `lanes` at a time."""
    lanes = hy.recommended_simd_size()
    init = np.array([y0(i, n) for i in range(lanes)]).T.copy()
    ta = hy.taylor_adaptive_batch(sys_, init, tol=tol)
    batches = n // lanes

    def call():
        out = []
        for b in range(batches):
            ta.set_time(0.0)
            ta.state[:] = np.array([y0(b * lanes + k, n) for k in range(lanes)]).T
            ta.propagate_until(t_end)
            out.append(ta.state.T.copy())
        return np.concatenate(out)

    return best_of(call), batches * lanes


def batch_threads(sys_, y0, t_end, n, tol, workers):
    """heyoka's fastest way we found: `workers` threads, each with its own batch integrator
    (copied once, not per run) reused over its share of the batches. heyoka releases the GIL
    while it integrates."""
    lanes = hy.recommended_simd_size()
    init = np.array([y0(i, n) for i in range(lanes)]).T.copy()
    template = hy.taylor_adaptive_batch(sys_, init, tol=tol)
    copies = [copy.deepcopy(template) for _ in range(workers)]
    batches = n // lanes

    def work(w):
        ta = copies[w]
        out = []
        for b in range(w, batches, workers):
            ta.set_time(0.0)
            ta.state[:] = np.array([y0(b * lanes + k, n) for k in range(lanes)]).T
            ta.propagate_until(t_end)
            out.append(ta.state.T.copy())
        return out

    def call():
        with ThreadPoolExecutor(max_workers=workers) as ex:
            parts = list(ex.map(work, range(workers)))
        return np.concatenate([s for part in parts for s in part])

    return best_of(call), batches * lanes


def batch_ensemble(sys_, y0, t_end, n, tol, workers):
    lanes = hy.recommended_simd_size()
    init = np.array([y0(i, n) for i in range(lanes)]).T.copy()
    ta = hy.taylor_adaptive_batch(sys_, init, tol=tol)
    batches = n // lanes

    def gen(ta_b, b):
        ta_b.set_time(0.0)
        ta_b.state[:] = np.array([y0(b * lanes + k, n) for k in range(lanes)]).T
        return ta_b

    def call():
        res = hy.ensemble_propagate_until_batch(ta, t_end, batches, gen, max_workers=workers)
        return np.concatenate([r[0].state.T for r in res])

    return best_of(call), batches * lanes


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    cores = os.cpu_count() or 1
    print(f"heyoka {hy.__version__}, {cores} cores, {hy.recommended_simd_size()} SIMD lanes, "
          f"{n} runs per ensemble, load {os.getloadavg()[0]:.2f}")
    print(f"{'problem':<9} {'tol':>7} {'mode':<22} {'error':>9} {'runs/s':>10}")
    problems = [
        ("heavy top", heavy_top_sys(), heavy_top_y0, 10.25 * TOP_PERIOD,
         lambda states: max(abs(s[5] - TOP_COS_END) for s in states)),
        ("free body", free_sys(), free_y0, 200.0,
         lambda states: max(abs(a - b) for a, b in zip(states[0], FREE_M200))),
    ]
    for name, sys_, y0, t_end, error in problems:
        for tol in TOLS:
            for workers in [1, cores]:
                secs, states = scalar_ensemble(sys_, y0, t_end, n, tol, workers)
                mode = f"scalar, {workers} worker{'s' if workers > 1 else ''}"
                print(f"{name:<9} {tol:>7.0e} {mode:<22} {error(states):>9.2e} {n / secs:>10.0f}")
            secs, states = scalar_loop(sys_, y0, t_end, n, tol)
            print(f"{name:<9} {tol:>7.0e} {'scalar loop, 1 core':<22} {error(states):>9.2e} {n / secs:>10.0f}")
            (secs, states), runs = batch_loop(sys_, y0, t_end, n, tol)
            print(f"{name:<9} {tol:>7.0e} {'batch loop, 1 core':<22} {error(states):>9.2e} {runs / secs:>10.0f}")
            (secs, states), runs = batch_threads(sys_, y0, t_end, n, tol, cores)
            mode = f"batch loop, {cores} threads"
            print(f"{name:<9} {tol:>7.0e} {mode:<22} {error(states):>9.2e} {runs / secs:>10.0f}")
            for workers in [1, cores]:
                (secs, states), runs = batch_ensemble(sys_, y0, t_end, n, tol, workers)
                mode = f"batch, {workers} worker{'s' if workers > 1 else ''}"
                print(f"{name:<9} {tol:>7.0e} {mode:<22} {error(states):>9.2e} {runs / secs:>10.0f}")


if __name__ == "__main__":
    main()
