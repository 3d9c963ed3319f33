#!/usr/bin/env python3
"""Pinocchio's articulated-body algorithm on the chains of benches/mechanism_scale.rs.

- planar: PyDy's n_link_pendulum_on_cart(n): a cart (prismatic along x, mass m0, force F)
  carrying n point masses m_i at l_{i-1} along their links' y axes, every link turning about
  z, gravity -9.81 y; m_i = 1 + i/10, l_i = 1/2 + i/20, F = 0.7 (the benchmark's values).
- spatial: n uniform rods (1/2 kg, 0.3 m, radius 0.02 m) hanging along -z on revolutes about
  x (odd links) and y (even links), gravity -9.81 z.

Each q̈ = aba(q, q̇, τ) is timed from Python with timeit, so the figure includes the Python
call overhead (Pinocchio has no pure C++ timing loop in its Python API); the script also
times pin.aba on a one-joint model, the floor that overhead sets. The state is the
benchmark's: q_i = 0.3 + i/7, q̇_i = 0.5 - i/11. The first q̈ entries are printed so they can be
compared with the generated code's.

    pip install pin
    python3 scripts/pinocchio_chain.py
"""

import timeit

import numpy as np
import pinocchio as pin


def planar(n):
    model = pin.Model()
    model.gravity.linear = np.array([0.0, -9.81, 0.0])
    cart = model.addJoint(0, pin.JointModelPX(), pin.SE3.Identity(), "cart")
    model.appendBodyToJoint(cart, pin.Inertia(1.0, np.zeros(3), np.zeros((3, 3))), pin.SE3.Identity())
    parent, offset = cart, np.zeros(3)
    for i in range(1, n + 1):
        placement = pin.SE3(np.eye(3), offset)
        joint = model.addJoint(parent, pin.JointModelRZ(), placement, f"link{i}")
        length = 0.5 + (i - 1) / 20.0
        mass = 1.0 + i / 10.0
        inertia = pin.Inertia(mass, np.array([0.0, length, 0.0]), np.zeros((3, 3)))
        model.appendBodyToJoint(joint, inertia, pin.SE3.Identity())
        parent, offset = joint, np.array([0.0, length, 0.0])
    tau = np.zeros(model.nv)
    tau[0] = 0.7
    return model, tau


def spatial(n):
    model = pin.Model()
    model.gravity.linear = np.array([0.0, 0.0, -9.81])
    parent = 0
    rod = pin.Inertia(0.5, np.array([0.0, 0.0, -0.15]), np.diag([3.0 / 800, 3.0 / 800, 1e-4]))
    for i in range(n):
        offset = np.zeros(3) if i == 0 else np.array([0.0, 0.0, -0.3])
        kind = pin.JointModelRX() if i % 2 == 0 else pin.JointModelRY()
        joint = model.addJoint(parent, kind, pin.SE3(np.eye(3), offset), f"rod{i + 1}")
        model.appendBodyToJoint(joint, rod, pin.SE3.Identity())
        parent = joint
    return model, np.zeros(model.nv)


def time_aba(model, tau):
    data = model.createData()
    q = np.array([0.3 + i / 7.0 for i in range(model.nq)])
    v = np.array([0.5 - i / 11.0 for i in range(model.nv)])
    qdd = pin.aba(model, data, q, v, tau).copy()
    timer = timeit.Timer(lambda: pin.aba(model, data, q, v, tau))
    loops, _ = timer.autorange()
    best = min(timer.repeat(repeat=7, number=loops)) / loops
    return best, qdd


def main():
    print(f"pinocchio {pin.__version__}")
    floor, _ = time_aba(*spatial(1))
    print(f"one joint (call-overhead floor): {floor * 1e6:.2f} µs")
    for name, build in (("planar", planar), ("spatial", spatial)):
        for n in (2, 5, 10, 25):
            model, tau = build(n)
            t, qdd = time_aba(model, tau)
            head = ", ".join(f"{x:.12g}" for x in qdd[:3])
            print(f"{name:8s} n = {n:2d} ({model.nv:2d} dof): {t * 1e6:6.2f} µs   q̈[:3] = [{head}]")


if __name__ == "__main__":
    main()
