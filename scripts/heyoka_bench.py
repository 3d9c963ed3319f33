"""heyoka on the problems of `benches/taylor.rs`, at the same tolerances, against the same
references: DETEST B5 to t = 20, the torque-free bodies I = (3, 5, 7) and (3, 5, 9) from
m0 = (0, 2, 0.01) to T = 200, and the heavy top of examples/heavy_top.rs (Euler–Poisson form)
over 10 nutation periods with its nutation maxima as events.

    pip install heyoka
    python3 scripts/heyoka_bench.py
    # at matched error against precess's table, run just before in the same sitting:
    cargo bench -p precess-benches --bench taylor -- nothing > precess_taylor.txt
    python3 scripts/heyoka_bench.py --precess precess_taylor.txt

With `--precess FILE` (the table `benches/taylor.rs` prints), each heyoka rung is set beside
the fastest precess Taylor rung of the same problem whose error is no larger (any of the
table's Taylor methods: the default order of least work checked, unchecked or at the max-norm
scale, Jorba and Zou's order, heyoka's whole rule), and the ratio heyoka time / precess time
is printed, from the minima of both (on a loaded machine the minimum is the closer to the
unloaded time). The heavy top is matched five times: against precess's run of the same
Euler–Poisson equations, hand-written, with the event scanned on the dense output
("HeavyTop") and expanded in the jet as heyoka's is, interpreted ("HeavyTopExpanded"); through
`taylor_system!` with the event scanned ("HeavyTopGen") and compiled with the system
("HeavyTopGenCompiled"); and against its generated Euler-angle form ("TopAngles").

Each figure is the median over many repeats of one `propagate_until` from the initial state
(the integrator is built, and its code compiled by LLVM, once per problem and tolerance,
outside the timing). The times include the Python call overhead, about 1 µs per call (it is
printed below, measured on an empty propagation), and for the heavy top one Python callback
per event. heyoka takes one tolerance; precess's runs use rtol = atol = tol.

The references are copied here, not read from disk: B5's published 30-digit y(20); the exact
torque-free states from precess's `FreeBodyExact` (printed by `cargo bench -p precess-benches --bench taylor`);
the heavy top's moments, M g l and exact nutation period from its body description and
`HeavyTopTheory` (printed by the same bench).
"""

import math
import re
import statistics
import sys
import time

import heyoka as hy

B5_Y20 = [-0.93965707987292039619, -0.34211777540007490653, 0.74141265961999530078]
FREE_M200 = {
    (3.0, 5.0, 7.0): [-0.20025294777805186, -1.966298347069268, 0.30605484348211964],
    (3.0, 5.0, 9.0): [0.5586653843883227, -1.794361298823517, 0.6842956360891311],
}
TOP_I1 = 0.0006013558333333334
TOP_I3 = 0.000160045
TOP_MGL = 0.10202399999999999
TOP_PERIOD = 0.20103746949366902
TOLS = [1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 1e-15, 1e-16]


def median_us(call, min_batch_s=2e-3, batches=21):
    """Median and minimum over `batches` batches of the time of one call, in µs (on a loaded
    machine the minimum is the closer to the unloaded time)."""
    t0 = time.perf_counter()
    call()
    once = max(time.perf_counter() - t0, 1e-7)
    reps = max(1, int(min_batch_s / once))
    times = []
    for _ in range(batches):
        t0 = time.perf_counter()
        for _ in range(reps):
            call()
        times.append((time.perf_counter() - t0) / reps)
    return statistics.median(times) * 1e6, min(times) * 1e6


def fmt(times):
    return f"{times[0]:>10.2f} {times[1]:>8.2f}"


def max_err(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def b5(tol):
    x, y, z = hy.make_vars("x", "y", "z")
    return hy.taylor_adaptive(
        [(x, y * z), (y, -x * z), (z, -0.51 * x * y)], [0.0, 1.0, 1.0], tol=tol
    )


def free(inertia, tol):
    m1, m2, m3 = hy.make_vars("m1", "m2", "m3")
    i1, i2, i3 = inertia
    a = [1 / i3 - 1 / i2, 1 / i1 - 1 / i3, 1 / i2 - 1 / i1]
    return hy.taylor_adaptive(
        [(m1, a[0] * m2 * m3), (m2, a[1] * m3 * m1), (m3, a[2] * m1 * m2)],
        [0.0, 2.0, 0.01],
        tol=tol,
    )


def heavy_top(tol, maxima):
    w1, w2, w3, g1, g2, g3 = hy.make_vars("w1", "w2", "w3", "g1", "g2", "g3")
    r, s = (TOP_I1 - TOP_I3) / TOP_I1, TOP_MGL / TOP_I1

    def cb(ta, t, d_sgn):
        maxima.append(t)

    # θ̇ has the sign of γ2 ω1 − γ1 ω2: its falling zeros are the maxima of θ.
    ev = hy.nt_event(g2 * w1 - g1 * w2, callback=cb, direction=hy.event_direction.negative)
    th0 = math.radians(20.0)
    return hy.taylor_adaptive(
        [
            (w1, r * w2 * w3 + s * g2),
            (w2, -r * w3 * w1 - s * g1),
            (w3, 0.0 * w3),
            (g1, g2 * w3 - g3 * w2),
            (g2, g3 * w1 - g1 * w3),
            (g3, g1 * w2 - g2 * w1),
        ],
        [0.0, 0.0, 150.0, 0.0, math.sin(th0), math.cos(th0)],
        tol=tol,
        nt_events=[ev],
    )


def timed_run(ta, y0, t_end, before=None):
    """One propagation from (0, y0) to t_end, resetting the integrator first."""

    def call():
        ta.time = 0.0
        ta.state[:] = y0
        if before is not None:
            before()
        ta.propagate_until(t_end)

    return call


ROW = re.compile(
    r"^(\S+)\s+(Taylor(?: \S+)? (?:tol )?\S+)\s+(\S+)\s+(\d+)\s+(\d+)\s+([0-9.]+)\s+([0-9.]+)$"
)


def precess_rows(path):
    """The Taylor rows of precess's table: {problem: [(method, error, steps, min µs)]}."""
    rows = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = ROW.match(line.strip())
            if not m or "ext" in m.group(2):
                continue
            err = float(m.group(3))
            if math.isnan(err):
                continue
            rows.setdefault(m.group(1), []).append(
                (m.group(2), err, int(m.group(4)), float(m.group(7)))
            )
    return rows


def matched(precess, problem, hy_err, hy_min):
    """The fastest precess rung of `problem` whose error is no larger than heyoka's."""
    fits = [r for r in precess.get(problem, []) if r[1] <= hy_err]
    if not fits:
        return "no precess rung that accurate"
    best = min(fits, key=lambda r: r[3])
    return f"{best[0]} {best[1]:.2e} {best[2]} steps {best[3]:.2f} µs: ratio {hy_min / best[3]:.2f}"


def main():
    precess = {}
    if "--precess" in sys.argv:
        precess = precess_rows(sys.argv[sys.argv.index("--precess") + 1])
    print(f"heyoka {hy.__version__}")
    x = hy.make_vars("x")
    empty = hy.taylor_adaptive([(x, 0.0 * x)], [0.0], tol=1e-10)
    empty_call = timed_run(empty, [0.0], 0.0)
    med, low = median_us(empty_call)
    print(f"python call overhead (propagate_until to the current time): median {med:.2f} µs, min {low:.2f} µs")
    print(
        f"{'problem':<10} {'tol':>7} {'error':>10} {'order':>6} {'steps':>6} {'median µs':>10} {'min µs':>8}"
        + ("   precess at matched error" if precess else "")
    )

    def line(name, tol, err, ta, steps, times, extra="", against=()):
        out = f"{name:<10} {tol:>7.0e} {err:>10.2e} {ta.order:>6} {steps:>6} {fmt(times)}{extra}"
        for problem in against if precess else ():
            out += f"\n{'':<10} {'':>7} precess {problem}: {matched(precess, problem, err, times[1])}"
        print(out)

    for tol in TOLS:
        ta = b5(tol)
        call = timed_run(ta, [0.0, 1.0, 1.0], 20.0)
        ta.time = 0.0
        ta.state[:] = [0.0, 1.0, 1.0]
        steps = ta.propagate_until(20.0)[3]
        err = max_err(ta.state, B5_Y20)
        line("B5", tol, err, ta, steps, median_us(call), against=("B5",))
    for inertia, name in [((3.0, 5.0, 7.0), "Free357"), ((3.0, 5.0, 9.0), "Free359")]:
        for tol in TOLS:
            ta = free(inertia, tol)
            call = timed_run(ta, [0.0, 2.0, 0.01], 200.0)
            ta.time = 0.0
            ta.state[:] = [0.0, 2.0, 0.01]
            steps = ta.propagate_until(200.0)[3]
            err = max_err(ta.state, FREE_M200[inertia])
            line(name, tol, err, ta, steps, median_us(call), against=(name,))
    y0 = [0.0, 0.0, 150.0, 0.0, math.sin(math.radians(20.0)), math.cos(math.radians(20.0))]
    for tol in TOLS:
        maxima = []
        ta = heavy_top(tol, maxima)
        call = timed_run(ta, y0, 10.0 * TOP_PERIOD, before=maxima.clear)
        ta.time = 0.0
        ta.state[:] = y0
        maxima.clear()
        steps = ta.propagate_until(10.0 * TOP_PERIOD)[3]
        period = (maxima[-1] - maxima[0]) / (len(maxima) - 1)
        err = abs(period - TOP_PERIOD) / TOP_PERIOD
        count = len(maxima)
        line(
            "HeavyTop", tol, err, ta, steps, median_us(call), f"   ({count} maxima)",
            against=(
                "HeavyTop",
                "HeavyTopExpanded",
                "HeavyTopGen",
                "HeavyTopGenCompiled",
                "TopAngles",
            ),
        )


if __name__ == "__main__":
    main()
