"""The thrown T-handle of benches/free.rs (group free_flight) integrated by SciPy's DOP853,
for the figures quoted in docs/free-bodies.md. Not run in CI:

    python3 benches/scipy_flight.py

The body: principal moments about the centre of mass summed from its two cylinders (as the
derive does), mass 0.5 kg, gravity 9.81 m/s² along -z, no other force. State as precess's:
[x, v, q (w, x, y, z), omega (principal)].
"""

import time

import numpy as np
from scipy.integrate import solve_ivp

I = np.array([
    0.2 * (3e-4 + 0.04) / 12 + 0.2 * 0.0036 + 0.5 * 0.3 * 1e-4 + 0.3 * 0.0016,
    0.2 * (3e-4 + 0.04) / 12 + 0.2 * 0.0036 + 0.3 * (3e-4 + 0.04) / 12 + 0.3 * 0.0016,
    0.5 * 0.2 * 1e-4 + 0.3 * (3e-4 + 0.04) / 12,
])
G = np.array([0.0, 0.0, -9.81])


def rhs(_t, y):
    v, q, w = y[3:6], y[6:10], y[10:13]
    qw, qx, qy, qz = q
    p, r, s = w
    qd = 0.5 * np.array([
        -qx * p - qy * r - qz * s,
        qw * p + qy * s - qz * r,
        qw * r + qz * p - qx * s,
        qw * s + qx * r - qy * p,
    ])
    wd = np.array([
        (I[1] - I[2]) * r * s / I[0],
        (I[2] - I[0]) * s * p / I[1],
        (I[0] - I[1]) * p * r / I[2],
    ])
    return np.concatenate([v, G, qd, wd])


y0 = np.array([0, 0, 1.5, 0.8, 0, 10.0, 1, 0, 0, 0, 50.0, 2.0, 3.0])
t_end = 2 * 10.0 / 9.81
best = float("inf")
for _ in range(5):
    start = time.perf_counter()
    sol = solve_ivp(rhs, (0, t_end), y0, method="DOP853", rtol=1e-10, atol=1e-10)
    best = min(best, time.perf_counter() - start)
print(f"scipy DOP853 rtol=atol=1e-10: {best * 1e3:.1f} ms (best of 5), nfev {sol.nfev}, "
      f"steps {sol.t.size - 1}, |q| - 1 at the end {np.linalg.norm(sol.y[6:10, -1]) - 1:.1e}")
start = time.perf_counter()
n = 100_000
for _ in range(n):
    rhs(0.0, y0)
print(f"scipy rhs in Python/NumPy: {(time.perf_counter() - start) / n * 1e9:.0f} ns per call")
