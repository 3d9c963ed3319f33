#!/usr/bin/env python3
"""SymPy's own Whipple-bicycle derivation, timed, for docs/performance.md.

SymPy ships the benchmark bicycle of Meijaard et al. (2007) as the slow test
`sympy.physics.mechanics.tests.test_kane3.test_bicycle` (ported from Autolev: KanesMethod with
yaw, roll, pitch and steer, six speeds, three of them dependent through the two rolling
wheels, then `KanesMethod.linearize` and the eigenvalues at 5 m/s against the paper). This
script runs that test function as SymPy ships it and times its two phases, by wrapping
`KanesMethod.kanes_equations` to note when it returns:

  derivation   from the start of the test to Kane's equations (fr + fr* formed)
  rest         the linearisation, the substitution of the paper's values and the eigenvalues

precess's counterpart is `MechanismScene::derive_rolling` on the same bicycle (M, f, the five
rolling rows and Ȧq̇, exactly), timed by the bicycle's bench or test.

Usage: python3 scripts/sympy_bicycle.py   (needs sympy; takes minutes)
       python3 scripts/sympy_bicycle.py --derivation-only [runs]
           stops at Kane's equations and repeats that in `runs` fresh processes (default 5),
           printing each time and the median: the figure compared with the derivation bench
           (`cargo bench -p precess-benches --bench bicycle_derivation`)
"""

import statistics
import subprocess
import sys
import time

import sympy
import sympy.physics.mechanics as me
from sympy.physics.mechanics.tests import test_kane3

marks = {}
original = me.KanesMethod.kanes_equations


class Derived(Exception):
    """Raised after Kane's equations when only the derivation is timed."""


def timed_kanes_equations(self, *args, **kwargs):
    out = original(self, *args, **kwargs)
    marks["kane"] = time.perf_counter()
    if marks.get("stop"):
        raise Derived
    return out


def derivation_only():
    """One derivation in this process (SymPy's caches start empty), in seconds."""
    marks["stop"] = True
    start = time.perf_counter()
    try:
        test_kane3.test_bicycle()
    except Derived:
        pass
    return marks["kane"] - start


me.KanesMethod.kanes_equations = timed_kanes_equations
if len(sys.argv) > 1 and sys.argv[1] == "--child":
    print(derivation_only())
elif len(sys.argv) > 1 and sys.argv[1] == "--derivation-only":
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    times = []
    for _ in range(runs):
        child = subprocess.run(
            [sys.executable, __file__, "--child"], capture_output=True, text=True, check=True
        )
        times.append(float(child.stdout.split()[-1]))
        print(f"derivation (to Kane's equations): {times[-1]:.3f} s")
    print(f"sympy {sympy.__version__}, median of {runs}: {statistics.median(times):.3f} s")
else:
    start = time.perf_counter()
    test_kane3.test_bicycle()
    end = time.perf_counter()
    derivation = marks["kane"] - start
    print(f"sympy {sympy.__version__}")
    print(f"derivation (to Kane's equations): {derivation:.2f} s")
    print(f"linearisation and eigenvalues:    {end - marks['kane']:.2f} s")
    print(f"whole test:                        {end - start:.2f} s")
