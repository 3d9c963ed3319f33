#!/usr/bin/env python3
"""The cost of `#[derive(Mechanism)]` to a user's build, for n-link chains.

Generates a throwaway crate that depends on this repository's `precess` and holds one
mechanism, and times `cargo build` (debug, the everyday build) of it with the derive and of
the same crate without it (the struct alone). The difference is the macro's expansion plus
compiling the code it emits. `cargo check` is timed the same way: its difference is the
expansion plus type checking, without code generation.

Two chains, n = 2, 5, 10, 25 by default:
- spatial: n thin rods (mass 0.5, length 0.3) hanging along −z, each on a revolute about x
  (odd links) or y (even links) at the end of the last, literal constants (the chain of
  `benches/mechanism_scale.rs`);
- planar: PyDy's n-link pendulum on a cart: a cart of mass m0 on a prismatic joint along x
  pushed by a force F, n point masses m_i at distance l_{i-1} along links turning about z,
  every constant a field of the struct, gravity along −y.

Each timing is the median of `--repeat` builds after touching the source; dependencies are
built once first (not counted). Every figure depends on the machine and its load: state
the load beside it.

    python3 scripts/expansion_time.py            # n = 2, 5, 10, 25
    python3 scripts/expansion_time.py --n 2 5 --repeat 3
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def spatial_chain(n: int, derive: bool) -> str:
    lines = []
    if derive:
        lines += ["#[derive(Mechanism)]", "#[mechanism(gravity = 9.81)]"]
        for i in range(1, n + 1):
            axis = "x" if i % 2 == 1 else "y"
            parent = "ground" if i == 1 else f"rod{i - 1}"
            at = "" if i == 1 else ", at = [0.0, 0.0, -0.3]"
            lines.append(
                f"#[body(rod{i}, parent = {parent}, joint = revolute(axis = {axis}{at}), "
                f"q = q{i}, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]"
            )
    lines.append("pub struct Chain;")
    return "\n".join(lines)


def planar_chain(n: int, derive: bool) -> str:
    lines = []
    fields = ["pub m0: f64", "pub F: f64"]
    fields += [f"pub m{i}: f64" for i in range(1, n + 1)]
    fields += [f"pub l{i}: f64" for i in range(n)]
    if derive:
        lines += ["#[derive(Mechanism)]", "#[mechanism(gravity = [0.0, -9.81, 0.0])]"]
        lines.append(
            "#[body(cart, parent = ground, joint = prismatic(axis = x), q = q0, "
            "effort = F, parts(particle(mass = m0, at = [0.0, 0.0, 0.0])))]"
        )
        for i in range(1, n + 1):
            parent = "cart" if i == 1 else f"link{i - 1}"
            at = "" if i == 1 else f", at = [0.0, l{i - 2}, 0.0]"
            lines.append(
                f"#[body(link{i}, parent = {parent}, joint = revolute(axis = z{at}), "
                f"q = q{i}, parts(particle(mass = m{i}, at = [0.0, l{i - 1}, 0.0])))]"
            )
    lines.append("#[allow(non_snake_case)]")
    lines.append("pub struct Chain { " + ", ".join(fields) + " }")
    return "\n".join(lines)


def source(kind: str, n: int, derive: bool) -> str:
    body = spatial_chain(n, derive) if kind == "spatial" else planar_chain(n, derive)
    header = "#![allow(dead_code)]\nuse precess::prelude::*;\n" if derive else ""
    return f"{header}\n{body}\n"


def run(cmd, cwd, env):
    result = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stderr[-4000:])
        raise SystemExit(f"{' '.join(cmd)} failed in {cwd}")


def timed(cmd, crate: Path, lib: Path, text: str, env, repeat: int) -> float:
    lib.write_text(text)
    run(cmd, crate, env)  # first build of this source, not counted
    samples = []
    for _ in range(repeat):
        lib.write_text(text)  # a new mtime: cargo rebuilds the crate, not its dependencies
        os.utime(lib, None)
        start = time.perf_counter()
        run(cmd, crate, env)
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, nargs="+", default=[2, 5, 10, 25])
    parser.add_argument("--kinds", nargs="+", default=["spatial", "planar"])
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument(
        "--dir",
        type=Path,
        default=None,
        help="where to put the throwaway crate (default: a temporary directory)",
    )
    args = parser.parse_args()

    work = args.dir or Path(tempfile.mkdtemp(prefix="precess-expansion-"))
    crate = work / "chain"
    (crate / "src").mkdir(parents=True, exist_ok=True)
    (crate / "Cargo.toml").write_text(
        "[package]\nname = \"chain\"\nversion = \"0.0.0\"\nedition = \"2024\"\n"
        "publish = false\n\n[dependencies]\n"
        f"precess = {{ path = \"{REPO}\" }}\n\n[workspace]\n"
    )
    lib = crate / "src" / "lib.rs"
    env = dict(os.environ, CARGO_TARGET_DIR=str(work / "target"))
    # Dependencies (precess, the proc macro, nalgebra, …) once, outside every timing.
    lib.write_text(source("spatial", 2, derive=False))
    run(["cargo", "build", "--quiet"], crate, env)

    print(f"load average before: {os.getloadavg()[0]:.1f} ({os.cpu_count()} cores)")
    print("kind     n   build: with  without  derive | check: with  without  derive   (s)")
    for kind in args.kinds:
        for n in args.n:
            row = []
            for cmd in (["cargo", "build", "--quiet"], ["cargo", "check", "--quiet"]):
                with_derive = timed(cmd, crate, lib, source(kind, n, True), env, args.repeat)
                without = timed(cmd, crate, lib, source(kind, n, False), env, args.repeat)
                row += [with_derive, without, with_derive - without]
            print(
                f"{kind:8} {n:2}  {row[0]:11.2f} {row[1]:8.2f} {row[2]:7.2f} |"
                f" {row[3]:11.2f} {row[4]:8.2f} {row[5]:7.2f}",
                flush=True,
            )
    print(f"load average after: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
