#!/usr/bin/env python3
"""SymPy's KanesMethod (and PyDy's generated code) on the tops on a table, for
docs/performance.md: the time to derive each scene's equations, the operation count of what
it derives, and the time of one right-hand side in PyDy's fastest back end.

Scenes, each rolling without slip on the plane z = 0 with gravity along -z, the same as
precess's examples:
  rolling_disk   thin uniform disk (m = 1, r = 0.1), SymPy's own rolling-disk example
  rattleback     Kane & Levinson's ellipsoid (a, b, c) = (0.2, 0.03, 0.02), CoM 0.01 above
                 the centre, A, B, C, D = 2e-4, 1.6e-3, 1.7e-3, -2e-5
  tippe_top      a sphere of radius 0.02 with the CoM 0.003 below its centre (rolling)
  chaplygin_ball a ball of radius 0.1, CoM at the centre, moments (1, 2, 3)e-3

The rolling constraint is written as SymPy's rolling-disk example does: the material contact
point has zero velocity, the centre of mass is reached from it through the body, so the three
body rates are the only generalised speeds (Kane's method with the dependent speeds
eliminated by construction). The contact point's body coordinates are the surface's support
map evaluated at the downward normal, exactly as precess's derivation does.

Times are medians of 3 runs; derivation includes forming the mass matrix and forcing of
Kane's equations; "solve" adds the symbolic solve M^-1 f that precess also performs, and
"cse" the common-subexpression pass that turns the equations into straight-line code (PyDy
runs it before writing code; precess's lowering does the same job).

Usage: python3 scripts/sympy_contact.py [--no-pydy]   (needs sympy; pydy and cython optional)
"""

import statistics
import sys
import time

import sympy as sm
import sympy.physics.mechanics as me

REPEATS = 3
# Gravity is a symbol so PyDy's generated function takes it as its constants array.
GRAVITY = sm.Symbol("g")


def median_time(fn):
    times, out = [], None
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def rolling_body(name, support, mass, inertia, center):
    """Kane's equations of a body rolling on z = 0.

    support(n): the support point (body coordinates) for the outward unit normal n (a tuple of
    three sympy expressions); inertia: 3x3 tuple about the CoM in body axes; center: the CoM.
    """
    q1, q2, q3 = me.dynamicsymbols(f"{name}_q1:4")
    u1, u2, u3 = me.dynamicsymbols(f"{name}_u1:4")
    g = GRAVITY
    n_frame = me.ReferenceFrame("N")
    # Yaw, pitch, roll: the body frame B.
    b_frame = n_frame.orientnew("B", "Body", (q1, q2, q3), "ZXY")
    b_frame.set_ang_vel(n_frame, u1 * b_frame.x + u2 * b_frame.y + u3 * b_frame.z)
    b_angles = n_frame.orientnew("BA", "Body", (q1, q2, q3), "ZXY")
    w_q = b_angles.ang_vel_in(n_frame).to_matrix(b_angles)
    kd = [w_q[i] - u for i, u in enumerate((u1, u2, u3))]
    down = [-(n_frame.z.dot(e)) for e in (b_frame.x, b_frame.y, b_frame.z)]
    s = support(down)
    r = [s[i] - center[i] for i in range(3)]  # CoM -> contact, body axes
    contact = me.Point("C")
    contact.set_vel(n_frame, 0)
    cm = contact.locatenew("G", -(r[0] * b_frame.x + r[1] * b_frame.y + r[2] * b_frame.z))
    cm.v2pt_theory(contact, n_frame, b_frame)
    ixx, iyy, izz, ixy, iyz, izx = (
        inertia[0][0],
        inertia[1][1],
        inertia[2][2],
        inertia[0][1],
        inertia[1][2],
        inertia[2][0],
    )
    body = me.RigidBody(
        "body",
        cm,
        b_frame,
        mass,
        (me.inertia(b_frame, ixx, iyy, izz, ixy, iyz, izx), cm),
    )
    loads = [(cm, -mass * g * n_frame.z)]
    kane = me.KanesMethod(
        n_frame, q_ind=[q1, q2, q3], u_ind=[u1, u2, u3], kd_eqs=kd
    )
    fr, frstar = kane.kanes_equations([body], loads)
    return kane, fr, frstar


def sphere(center, radius):
    return lambda n: [center[i] + radius * n[i] for i in range(3)]


def ellipsoid(center, axes):
    def support(n):
        d2n = [axes[i] ** 2 * n[i] for i in range(3)]
        norm = sm.sqrt(sum(d2n[i] * n[i] for i in range(3)))
        return [center[i] + d2n[i] / norm for i in range(3)]

    return support


def disk_rim(center, radius):
    def support(n):
        norm = sm.sqrt(n[0] ** 2 + n[1] ** 2)
        return [center[0] + radius * n[0] / norm, center[1] + radius * n[1] / norm, center[2]]

    return support


def scenes():
    z = sm.Integer(0)
    m, r = sm.Integer(1), sm.Rational(1, 10)
    disk_i = m * r**2 / 4
    yield "rolling_disk", lambda: rolling_body(
        "disk",
        disk_rim((z, z, z), r),
        m,
        ((disk_i, 0, 0), (0, disk_i, 0), (0, 0, 2 * disk_i)),
        (z, z, z),
    )
    a, b, c, h = (sm.Rational(2, 10), sm.Rational(3, 100), sm.Rational(2, 100), sm.Rational(1, 100))
    aa, bb, cc, dd = (sm.Rational(2, 10**4), sm.Rational(16, 10**4), sm.Rational(17, 10**4), sm.Rational(-2, 10**5))
    yield "rattleback", lambda: rolling_body(
        "rattle",
        ellipsoid((z, z, -h), (a, b, c)),
        sm.Integer(1),
        ((aa, dd, 0), (dd, bb, 0), (0, 0, cc)),
        (z, z, z),
    )
    rho, off = sm.Rational(2, 100), sm.Rational(3, 1000)
    i1, i3 = sm.Rational(9, 10**6), sm.Rational(1, 10**5)
    yield "tippe_top", lambda: rolling_body(
        "tippe",
        sphere((z, z, off), rho),
        sm.Rational(15, 1000),
        ((i1, 0, 0), (0, i1, 0), (0, 0, i3)),
        (z, z, z),
    )
    yield "chaplygin_ball", lambda: rolling_body(
        "ball",
        sphere((z, z, z), sm.Rational(1, 10)),
        sm.Integer(1),
        ((sm.Rational(1, 1000), 0, 0), (0, sm.Rational(2, 1000), 0), (0, 0, sm.Rational(3, 1000))),
        (z, z, z),
    )


def main():
    use_pydy = "--no-pydy" not in sys.argv
    print("scene,derive_s,ops_mass_forcing,solve_s,ops_solved,cse_s,ops_after_cse,pydy_backend,pydy_rhs_us")
    for name, build in scenes():
        t_derive, (kane, _fr, _frstar) = median_time(build)
        mass = kane.mass_matrix_full
        forcing = kane.forcing_full
        ops = sm.count_ops(mass) + sm.count_ops(forcing)
        t_solve, solved = median_time(lambda: kane.mass_matrix.LUsolve(kane.forcing))
        ops_solved = sm.count_ops(solved)
        # Straight-line code from the equations: SymPy's common-subexpression pass over the
        # mass matrix and forcing, as PyDy's generators run it before writing code.
        exprs = list(mass) + list(forcing)
        t_cse, (subs, reduced) = median_time(lambda: sm.cse(exprs))
        ops_cse = sum(sm.count_ops(e) for _, e in subs) + sum(sm.count_ops(e) for e in reduced)
        backend, rhs_us = "-", float("nan")
        if use_pydy:
            try:
                rhs_us, backend = pydy_rhs_time(kane)
            except Exception as e:  # the peer is optional: say why it was skipped
                print(f"{name}: pydy skipped: {e}", file=sys.stderr)
        print(f"{name},{t_derive:.3f},{ops},{t_solve:.3f},{ops_solved},{t_cse:.3f},{ops_cse},{backend},{rhs_us:.2f}")
        sys.stdout.flush()


def pydy_rhs_time(kane):
    import numpy as np
    from pydy.codegen.ode_function_generators import generate_ode_function

    q = list(kane.q)
    u = list(kane.u)
    for backend in ("cython", "lambdify"):
        try:
            rhs = generate_ode_function(
                kane.forcing_full,
                q,
                u,
                [GRAVITY],
                mass_matrix=kane.mass_matrix_full,
                generator=backend,
            )
            break
        except Exception as e:
            print(f"pydy {backend} failed: {e}", file=sys.stderr)
    else:
        raise RuntimeError("no pydy backend")
    x = np.array([0.1, 0.2, 0.3, 1.0, -2.0, 3.0])
    p = np.array([9.81])
    rhs(x, 0.0, p)
    n = 2000
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        for _ in range(n):
            rhs(x, 0.0, p)
        times.append((time.perf_counter() - t0) / n * 1e6)
    return statistics.median(times), backend


if __name__ == "__main__":
    main()
