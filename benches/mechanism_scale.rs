//! Mechanisms at scale: the n-link planar chain (PyDy's `n_link_pendulum_on_cart`) and a 3D
//! chain, n = 2, 5, 10, 25, in one criterion run:
//! - `derive`: scene → q̈ by the recursive route → lowered program → Rust tokens, which is the
//!   work the derive macro does at expansion;
//! - `generated`: q̈ of the generated code (`benches/generated/`, kept current by
//!   `tests/mechanism_recursive.rs`);
//! - `aba`: the generic numeric articulated-body algorithm ([`MechanismAba`]) on the same
//!   chain with the same parameters.
//!
//! The operation count of each lowered program is printed first. With `PRECESS_FASTEST=1` the
//! benchmark also prints, for `generated` and `aba`, the fastest of many short batches of
//! calls: a figure a loaded machine inflates far less than criterion's medians (a batch that
//! ran without being preempted), for comparing the two in one run.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use precess_core::mechanism::MechanismAba;
use precess_core::mechanism::recursive::chains::{ChainKind, generated_source, lowered_chain};
use precess_core::sym::Arena;
use std::hint::black_box;
use std::time::Instant;

#[allow(clippy::all, clippy::pedantic, unused_parens)]
mod generated {
    macro_rules! chains {
        ($($name:ident => $file:literal),* $(,)?) => {
            $(pub mod $name {
                include!($file);
            })*
        };
    }
    chains! {
        planar_2 => "generated/planar_2.rs",
        planar_5 => "generated/planar_5.rs",
        planar_10 => "generated/planar_10.rs",
        planar_25 => "generated/planar_25.rs",
        spatial_2 => "generated/spatial_2.rs",
        spatial_5 => "generated/spatial_5.rs",
        spatial_10 => "generated/spatial_10.rs",
        spatial_25 => "generated/spatial_25.rs",
    }
}

const SIZES: [usize; 4] = [2, 5, 10, 25];

/// Masses 1 + i/10, lengths 1/2 + i/20, g = 9.81, F = 0.7 (the planar chain's parameters).
fn planar_value(name: &str) -> f64 {
    let index = |s: &str| s.parse::<f64>().unwrap_or(0.0);
    match name {
        "g" => 9.81,
        "F" => 0.7,
        _ if name.starts_with('m') => 1.0 + index(&name[1..]) / 10.0,
        _ if name.starts_with('l') => 0.5 + index(&name[1..]) / 20.0,
        _ => 0.0,
    }
}

/// A state away from rest: qᵢ = 0.3 + i/7, q̇ᵢ = 0.5 − i/11.
fn state<const D: usize>() -> ([f64; D], [f64; D]) {
    (
        std::array::from_fn(|i| 0.3 + i as f64 / 7.0),
        std::array::from_fn(|i| 0.5 - i as f64 / 11.0),
    )
}

fn print_op_counts() {
    for kind in [ChainKind::Planar, ChainKind::Spatial] {
        for n in SIZES {
            if let Ok((_, program, coords, _)) = lowered_chain(kind, n) {
                eprintln!(
                    "{} chain, n = {n} ({} coordinates): {}",
                    kind.name(),
                    coords.q.len(),
                    program.op_count()
                );
            }
        }
    }
}

fn bench_derive(c: &mut Criterion) {
    print_op_counts();
    let mut group = c.benchmark_group("mechanism_scale/derive");
    group.sample_size(10);
    for kind in [ChainKind::Planar, ChainKind::Spatial] {
        for n in SIZES {
            group.bench_with_input(BenchmarkId::new(kind.name(), n), &n, |b, &n| {
                b.iter(|| generated_source(kind, black_box(n)).map(|s| s.len()))
            });
        }
    }
    group.finish();
}

/// The fastest of `batches` batches of `calls` calls of `f`, in ns per call.
fn fastest_ns(mut f: impl FnMut(), batches: usize, calls: usize) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..batches {
        let start = Instant::now();
        for _ in 0..calls {
            f();
        }
        best = best.min(start.elapsed().as_nanos() as f64 / calls as f64);
    }
    best
}

/// The fastest-batch figure of the generated q̈ and of the numeric ABA on each chain.
fn print_fastest() {
    if std::env::var_os("PRECESS_FASTEST").is_none() {
        return;
    }
    let mut generated_ns = Vec::new();
    macro_rules! time {
        ($kind:literal, $n:literal, $module:ident) => {{
            let p = generated::$module::PARAMETERS.map(planar_value);
            let (q, qd) = state();
            let ns = fastest_ns(
                || {
                    black_box(generated::$module::accelerations(
                        black_box(&q),
                        black_box(&qd),
                        black_box(&p),
                    ));
                },
                2000,
                50,
            );
            generated_ns.push(($kind, $n, ns));
        }};
    }
    time!("planar", 2, planar_2);
    time!("planar", 5, planar_5);
    time!("planar", 10, planar_10);
    time!("planar", 25, planar_25);
    time!("spatial", 2, spatial_2);
    time!("spatial", 5, spatial_5);
    time!("spatial", 10, spatial_10);
    time!("spatial", 25, spatial_25);
    eprintln!("fastest batch (ns per q̈): chain, n, generated, numeric ABA, ratio");
    for (kind, n, generated_ns) in generated_ns {
        let chain = if kind == "planar" {
            ChainKind::Planar
        } else {
            ChainKind::Spatial
        };
        let Some(mut aba) = numeric_aba(chain, n) else {
            continue;
        };
        let aba_ns = fastest_ns(
            || {
                black_box(aba.run());
            },
            2000,
            50,
        );
        eprintln!(
            "  {kind:8} {n:2}  {generated_ns:8.1}  {aba_ns:8.1}  {:5.1}",
            aba_ns / generated_ns
        );
    }
}

/// The numeric ABA of a chain at the benchmark state, ready to run.
struct NumericChain {
    aba: MechanismAba,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
}

impl NumericChain {
    fn run(&mut self) -> f64 {
        self.aba
            .accelerations(black_box(&self.q), black_box(&self.qd), &mut self.qdd)
            .map_or(f64::NAN, |_| self.qdd[0])
    }
}

fn numeric_aba(kind: ChainKind, n: usize) -> Option<NumericChain> {
    let mut arena = Arena::new();
    let scene = kind.scene(&mut arena, n);
    let mut env = vec![0.0; arena.symbol_count()];
    for (s, symbol) in arena.symbols() {
        env[s.index()] = planar_value(&symbol.name);
    }
    let aba = MechanismAba::new(&mut arena, &scene, &env).ok()?;
    let dof = aba.dof();
    Some(NumericChain {
        aba,
        q: (0..dof).map(|i| 0.3 + i as f64 / 7.0).collect(),
        qd: (0..dof).map(|i| 0.5 - i as f64 / 11.0).collect(),
        qdd: vec![0.0; dof],
    })
}

fn bench_generated(c: &mut Criterion) {
    print_fastest();
    let mut group = c.benchmark_group("mechanism_scale/generated");
    macro_rules! run {
        ($kind:literal, $n:literal, $module:ident) => {{
            let p = generated::$module::PARAMETERS.map(planar_value);
            let (q, qd) = state();
            let qdd = generated::$module::accelerations(&q, &qd, &p);
            eprintln!(
                "{} n = {}: q̈[..3] = {:?}",
                $kind,
                $n,
                &qdd[..qdd.len().min(3)]
            );
            group.bench_function(BenchmarkId::new($kind, $n), |b| {
                b.iter(|| {
                    generated::$module::accelerations(black_box(&q), black_box(&qd), black_box(&p))
                })
            });
        }};
    }
    run!("planar", 2, planar_2);
    run!("planar", 5, planar_5);
    run!("planar", 10, planar_10);
    run!("planar", 25, planar_25);
    run!("spatial", 2, spatial_2);
    run!("spatial", 5, spatial_5);
    run!("spatial", 10, spatial_10);
    run!("spatial", 25, spatial_25);
    group.finish();
}

fn bench_aba(c: &mut Criterion) {
    let mut group = c.benchmark_group("mechanism_scale/aba");
    for kind in [ChainKind::Planar, ChainKind::Spatial] {
        for n in SIZES {
            let Some(mut chain) = numeric_aba(kind, n) else {
                continue;
            };
            group.bench_function(BenchmarkId::new(kind.name(), n), |b| b.iter(|| chain.run()));
        }
    }
    group.finish();
}

criterion_group!(benches, bench_derive, bench_generated, bench_aba);
criterion_main!(benches);
