#!/usr/bin/env python3
"""Wall time and peak memory of building a crate that derives one long mechanism.

Generates a throwaway crate depending on this repository's `precess` (or `--repo`'s) that
holds the spatial chain of `scripts/expansion_time.py`: n thin rods (mass 0.5, length 0.3)
hanging along −z, each on a revolute about x (odd links) or y (even links), literal
constants, optionally with `taylor = K`. The crate has its own workspace, so it builds in
cargo's default profiles: `dev` (opt-level 0, full debug info) and `release`, as a user's
crate would. Each build runs under `/usr/bin/time -v`; the peak memory is the largest
resident set of any process of the build (rustc compiling the chain).

Dependencies (precess, the proc macro, nalgebra, …) are built once per profile first and
not counted, so a figure is the derive's expansion plus compiling what it emits. Every
figure depends on the machine and its load: the load average is printed beside it.

    python3 scripts/build_cost.py --n 25 50 100 --profile dev
    python3 scripts/build_cost.py --n 10 --taylor 20 --profile release
    python3 scripts/build_cost.py --n 50 --repo /path/to/an/older/checkout --timeout 1200
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from expansion_time import spatial_chain  # noqa: E402

REPO = Path(__file__).resolve().parent.parent


def source(n: int, taylor: int | None) -> str:
    body = spatial_chain(n, derive=True)
    if taylor is not None:
        body = body.replace(
            "#[mechanism(gravity = 9.81)]", f"#[mechanism(gravity = 9.81, taylor = {taylor})]"
        )
    return f"#![allow(dead_code)]\nuse precess::prelude::*;\n\n{body}\n"


def build(crate: Path, env, profile: str, timeout: float):
    """(seconds, peak MiB, ok, tail of stderr) of one `cargo build`."""
    cmd = ["/usr/bin/time", "-v", "cargo", "build", "--quiet"]
    if profile == "release":
        cmd.append("--release")
    start = time.perf_counter()
    try:
        result = subprocess.run(
            cmd, cwd=crate, env=env, capture_output=True, text=True, timeout=timeout
        )
    except subprocess.TimeoutExpired:
        return time.perf_counter() - start, float("nan"), False, f"timed out after {timeout} s"
    elapsed = time.perf_counter() - start
    peak = re.search(r"Maximum resident set size \(kbytes\): (\d+)", result.stderr)
    mib = int(peak.group(1)) / 1024 if peak else float("nan")
    ok = result.returncode == 0 and "Command exited with non-zero status" not in result.stderr
    return elapsed, mib, ok, result.stderr[-2000:]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, nargs="+", default=[25, 50, 100])
    parser.add_argument("--taylor", type=int, default=None, help="add `taylor = K`")
    parser.add_argument("--profile", choices=["dev", "release"], default="dev")
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds per build")
    parser.add_argument("--repo", type=Path, default=REPO, help="the precess checkout to use")
    parser.add_argument("--dir", type=Path, default=None, help="where to put the crate")
    args = parser.parse_args()

    work = args.dir or Path(tempfile.mkdtemp(prefix="precess-build-cost-"))
    crate = work / "chain"
    (crate / "src").mkdir(parents=True, exist_ok=True)
    (crate / "Cargo.toml").write_text(
        "[package]\nname = \"chain\"\nversion = \"0.0.0\"\nedition = \"2024\"\n"
        "publish = false\n\n[dependencies]\n"
        f"precess = {{ path = \"{args.repo.resolve()}\" }}\n\n[workspace]\n"
    )
    lib = crate / "src" / "lib.rs"
    env = dict(os.environ, CARGO_TARGET_DIR=str(work / "target"))
    # Dependencies once, outside every figure: the struct alone.
    lib.write_text("pub struct Chain;\n")
    secs, _, ok, err = build(crate, env, args.profile, args.timeout)
    if not ok:
        sys.stderr.write(err)
        raise SystemExit("building the dependencies failed")

    taylor = f", taylor = {args.taylor}" if args.taylor is not None else ""
    print(f"precess at {args.repo.resolve()}, profile {args.profile}{taylor}")
    print(f"dependencies built in {secs:.0f} s (not counted)")
    print(" n   build (s)  peak (MiB)  result   load before/after")
    for n in args.n:
        lib.write_text(source(n, args.taylor))
        before = os.getloadavg()[0]
        secs, mib, ok, err = build(crate, env, args.profile, args.timeout)
        after = os.getloadavg()[0]
        status = "ok" if ok else "FAILED"
        print(f"{n:3} {secs:10.1f} {mib:11.0f}  {status:7}  {before:.1f}/{after:.1f}", flush=True)
        if not ok:
            sys.stderr.write(err + "\n")


if __name__ == "__main__":
    main()
