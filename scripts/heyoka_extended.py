"""heyoka on the torque-free bodies of `benches/taylor.rs` (I = (3, 5, 7) and (3, 5, 9),
m0 = (0, 2, 0.01), T = 200) in its three accuracy modes, for comparison with the rows
"Taylor ext" (the extended mode: low orders in double-double) of that bench:

- plain double precision,
- `high_accuracy=True` (compensated summation of the Taylor polynomial),
- the whole integrator in 80-bit long double (`fp_type=numpy.longdouble`).

    pip install heyoka
    python3 scripts/heyoka_extended.py

Each time is the median (and minimum) over 21 batches of one `propagate_until` from the
initial state, Python call overhead included (about 1 µs). The references are the exact
m(200) of precess's `FreeBodyExact`, as printed by `cargo bench -p precess-benches --bench taylor`.
"""

import heyoka as hy
import numpy as np

# The timing and the references are heyoka_bench.py's (this script's directory is on the
# import path when it is run as `python3 scripts/heyoka_extended.py`).
from heyoka_bench import FREE_M200, median_us

M0 = [0.0, 2.0, 0.01]


def integrator(inertia, tol, mode):
    m1, m2, m3 = hy.make_vars("m1", "m2", "m3")
    ld = mode == "longdouble"
    f = np.longdouble if ld else float
    i1, i2, i3 = map(f, inertia)
    one = f(1)
    a = [one / i3 - one / i2, one / i1 - one / i3, one / i2 - one / i1]
    extra = {"fp_type": np.longdouble} if ld else {}
    return hy.taylor_adaptive(
        [(m1, a[0] * m2 * m3), (m2, a[1] * m3 * m1), (m3, a[2] * m1 * m2)],
        np.array(M0, dtype=np.longdouble) if ld else M0,
        tol=f(tol),
        high_accuracy=(mode == "high_accuracy"),
        **extra,
    )


def main():
    print(f"heyoka {hy.__version__}")
    print(f"{'problem':<8} {'mode':<14} {'tol':>6} {'error':>9} {'order':>5} {'median µs':>10} {'min µs':>8}")
    for inertia, name in [((3.0, 5.0, 7.0), "Free357"), ((3.0, 5.0, 9.0), "Free359")]:
        for mode in ["plain", "high_accuracy", "longdouble"]:
            for tol in [1e-15, 1e-16, 1e-18]:
                if mode != "longdouble" and tol < 1e-16:
                    continue  # below double precision: the order grows, the error does not fall
                ta = integrator(inertia, tol, mode)
                f = np.longdouble if mode == "longdouble" else float

                def call():
                    ta.time = f(0)
                    ta.state[:] = M0
                    ta.propagate_until(f(200))

                call()
                err = max(abs(float(x) - y) for x, y in zip(ta.state, FREE_M200[inertia]))
                med, low = median_us(call)
                print(f"{name:<8} {mode:<14} {tol:>6.0e} {err:>9.2e} {ta.order:>5} {med:>10.1f} {low:>8.1f}")


if __name__ == "__main__":
    main()
