#!/usr/bin/env python3
"""Peers of the work-precision report on the same problems with the same references.

Runs SciPy's solve_ivp (DOP853, RK45), heyoka (Taylor) and MuJoCo (RK4, implicitfast) where
installed, and writes docs/perf/peers.csv (problem, peer, method, setting, error,
median_time_s, evaluations), which `cargo run --release --example work_precision` reads and
plots. The references and parameters come from docs/perf/references.csv, which the report
writes (run it once first): the exact torque-free motion, B5's 30-digit value, and the
heavy top's elliptic cos θ(T).

Times are medians of 5 runs after one warm-up and include Python call overhead (for SciPy
and MuJoCo, one Python call per right-hand side or per step); heyoka's exclude its JIT
compilation. Absent packages are skipped and named on stderr.

MuJoCo can express the tops (a ball joint at the pivot, the centre of mass offset) but not
(a): I = (3, 5, 9) breaks the triangle inequality I1 + I2 >= I3 that MuJoCo demands of a
body's inertia, and B5 is not the Euler equation of any body (it needs I3 = 0).

Usage: python3 scripts/peers.py   (from the repository's root)
"""

import csv
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
REFS = ROOT / "docs" / "perf" / "references.csv"
OUT = ROOT / "docs" / "perf" / "peers.csv"
REPEATS = 5


def load_refs():
    refs = {}
    with open(REFS) as f:
        for row in csv.DictReader(f):
            refs.setdefault(row["problem"], {})[row["key"]] = float(row["value"])
    return refs


def median_time(fn):
    fn()
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


# --- right-hand sides -------------------------------------------------------------------


def free_body(i):
    i1, i2, i3 = i

    def f(_t, m):
        w = (m[0] / i1, m[1] / i2, m[2] / i3)
        return [m[1] * w[2] - m[2] * w[1], m[2] * w[0] - m[0] * w[2], m[0] * w[1] - m[1] * w[0]]

    return f


def b5(_t, y):
    return [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]]


def top_rhs(p):
    """The top in Eulerian form: q (w, x, y, z) body to space, body ω; inertia about the
    pivot diag(I1, I1, I3); torque c × (Rᵀ(−M g ẑ)) with c = (0, 0, l)."""
    i1, i3, w = p["I1"], p["I3"], p["mass"] * p["g"]
    lev = p["lever"]

    def f(_t, y):
        qw, qx, qy, qz, o1, o2, o3 = y
        # Rᵀ ẑ: the third row of R.
        d = (2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy))
        down = (-w * d[0], -w * d[1], -w * d[2])
        g = (-lev * down[1], lev * down[0], 0.0)
        l1, l2, l3 = i1 * o1, i1 * o2, i3 * o3
        do1 = (l2 * o3 - l3 * o2 + g[0]) / i1
        do2 = (l3 * o1 - l1 * o3 + g[1]) / i1
        do3 = (l1 * o2 - l2 * o1 + g[2]) / i3
        dq = (
            0.5 * (-qx * o1 - qy * o2 - qz * o3),
            0.5 * (qw * o1 + qy * o3 - qz * o2),
            0.5 * (qw * o2 + qz * o1 - qx * o3),
            0.5 * (qw * o3 + qx * o2 - qy * o1),
        )
        return [*dq, do1, do2, do3]

    return f


def top_y0(p):
    h = 0.5 * p["theta0"]
    return [math.cos(h), math.sin(h), 0.0, 0.0, 0.0, 0.0, p["omega3"]]


def cos_theta(y):
    n = y[0] ** 2 + y[1] ** 2 + y[2] ** 2 + y[3] ** 2
    return 1 - 2 * (y[1] ** 2 + y[2] ** 2) / n


def problems(refs):
    """(key, f, y0, T, error(y_end))."""
    s, b, out = refs["separatrix"], refs["b5"], []
    sep_ref = np.array([s["ref_1"], s["ref_2"], s["ref_3"]])
    out.append((
        "separatrix",
        free_body((s["I1"], s["I2"], s["I3"])),
        [s["m0_1"], s["m0_2"], s["m0_3"]],
        s["T"],
        lambda y: float(np.max(np.abs(np.asarray(y[:3]) - sep_ref))),
    ))
    b5_ref = np.array([b["ref_1"], b["ref_2"], b["ref_3"]])
    out.append((
        "b5",
        b5,
        [b["y0_1"], b["y0_2"], b["y0_3"]],
        b["T"],
        lambda y: float(np.max(np.abs(np.asarray(y[:3]) - b5_ref))),
    ))
    for key in ("heavy_top", "fast_top"):
        p = refs[key]
        out.append((key, top_rhs(p), top_y0(p), p["T"],
                    lambda y, u=p["ref_cos_theta"]: abs(cos_theta(y) - u)))
    return out


# --- peers ------------------------------------------------------------------------------


def run_scipy(refs, rows):
    from scipy.integrate import solve_ivp

    for key, f, y0, t_end, err in problems(refs):
        for method, tols in (("DOP853", (1e-6, 1e-8, 1e-10, 1e-12)), ("RK45", (1e-6, 1e-8, 1e-10))):
            for tol in tols:
                def go():
                    return solve_ivp(f, (0.0, t_end), y0, method=method, rtol=tol, atol=tol)
                sol = go()
                rows.append((key, "scipy", method, f"tol {tol:.0e}", err(sol.y[:, -1]),
                             median_time(go), sol.nfev))


def run_heyoka(refs, rows):
    import heyoka as hy

    s, b = refs["separatrix"], refs["b5"]
    x, y, z = hy.make_vars("x", "y", "z")
    i1, i2, i3 = s["I1"], s["I2"], s["I3"]
    sep = [(x, y * z / i3 - z * y / i2), (y, z * x / i1 - x * z / i3), (z, x * y / i2 - y * x / i1)]
    b5s = [(x, y * z), (y, -x * z), (z, -0.51 * x * y)]
    systems = [("separatrix", sep, [s["m0_1"], s["m0_2"], s["m0_3"]], s["T"]),
               ("b5", b5s, [b["y0_1"], b["y0_2"], b["y0_3"]], b["T"])]
    qw, qx, qy, qz, o1, o2, o3 = hy.make_vars("qw", "qx", "qy", "qz", "o1", "o2", "o3")
    for key in ("heavy_top", "fast_top"):
        p = refs[key]
        j1, j3, w, lev = p["I1"], p["I3"], p["mass"] * p["g"], p["lever"]
        d0, d1 = 2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx)
        g0, g1 = lev * w * d1, -lev * w * d0
        sys_top = [
            (qw, 0.5 * (-qx * o1 - qy * o2 - qz * o3)),
            (qx, 0.5 * (qw * o1 + qy * o3 - qz * o2)),
            (qy, 0.5 * (qw * o2 + qz * o1 - qx * o3)),
            (qz, 0.5 * (qw * o3 + qx * o2 - qy * o1)),
            (o1, ((j1 - j3) * o2 * o3 + g0) / j1),
            (o2, ((j3 - j1) * o3 * o1 + g1) / j1),
            (o3, 0.0 * o3),
        ]
        systems.append((key, sys_top, top_y0(p), p["T"]))
    errs = {k: e for k, _, _, _, e in problems(refs)}
    for key, sys_, y0, t_end in systems:
        for tol in (1e-6, 1e-9, 1e-12, 1e-15):
            ta = hy.taylor_adaptive(sys_, y0, tol=tol)

            def go(ta=ta, y0=y0, t_end=t_end):
                ta.time = 0.0
                ta.state[:] = y0
                return ta.propagate_until(t_end)

            res = go()
            steps = res[3] if len(res) > 3 else ""
            rows.append((key, "heyoka", "Taylor", f"tol {tol:.0e}", errs[key](ta.state),
                         median_time(go), f"{steps} steps"))


def run_mujoco(refs, rows):
    import mujoco

    for key in ("heavy_top", "fast_top"):
        p = refs[key]
        m, lev = p["mass"], p["lever"]
        ic = p["I1"] - m * lev * lev
        xml = f"""
<mujoco>
  <option gravity="0 0 -{p['g']}" timestep="0.001" integrator="RK4"/>
  <worldbody>
    <body name="top">
      <joint type="ball" damping="0" armature="0"/>
      <inertial pos="0 0 {lev!r}" mass="{m!r}" diaginertia="{ic!r} {ic!r} {p['I3']!r}"/>
    </body>
  </worldbody>
</mujoco>"""
        model = mujoco.MjModel.from_xml_string(xml)
        data = mujoco.MjData(model)
        q0 = top_y0(p)[:4]
        for integ, name in ((mujoco.mjtIntegrator.mjINT_RK4, "RK4"),
                            (mujoco.mjtIntegrator.mjINT_IMPLICITFAST, "implicitfast")):
            per = (100, 300, 1000) if name == "RK4" else (1000, 10000)
            for k in per:
                n = int(round(p["T"] / (p["period"] / k)))
                model.opt.integrator = integ
                model.opt.timestep = p["T"] / n

                def go(n=n):
                    mujoco.mj_resetData(model, data)
                    data.qpos[:] = q0
                    data.qvel[:] = [0.0, 0.0, p["omega3"]]
                    for _ in range(n):
                        mujoco.mj_step(model, data)
                    return data.qpos.copy()

                q = go()
                rows.append((key, "mujoco", name, f"h {model.opt.timestep:.3g}",
                             abs(cos_theta(q) - p["ref_cos_theta"]), median_time(go),
                             f"{n} steps"))


def main():
    if not REFS.exists():
        sys.exit(f"{REFS} missing: run `cargo run --release --example work_precision` first")
    refs = load_refs()
    rows = []
    for name, fn in (("scipy", run_scipy), ("heyoka", run_heyoka), ("mujoco", run_mujoco)):
        try:
            fn(refs, rows)
            print(f"{name}: done", file=sys.stderr)
        except ImportError as e:
            print(f"{name}: absent ({e})", file=sys.stderr)
    with open(OUT, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["problem", "peer", "method", "setting", "error", "median_time_s", "evaluations"])
        for r in rows:
            w.writerow([r[0], r[1], r[2], r[3], f"{r[4]:.3e}", f"{r[5]:.4e}", r[6]])
    print(f"wrote {OUT} ({len(rows)} rows)", file=sys.stderr)


if __name__ == "__main__":
    main()
