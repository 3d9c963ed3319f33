//! Sharding: the sleeping-top sweep of `examples/sleeping_sweep.rs` run whole and as shards
//! through the library, its shards' CSV files concatenated (in any order) and read back,
//! gives the same rows and the same threshold to the bit — and that threshold agrees with
//! ω3² = 4 M g l I1 / I3².

#[path = "../../examples/common/shards.rs"]
mod shards;
#[path = "../../examples/common/sweep.rs"]
mod sweep;

use precess::ensemble::Ensemble;
use precess::prelude::*;
use precess::top::HeavyTopTheory;

use shards::{parse_shard, shard};
use sweep::{Row, Sweep, read_csv, threshold_from_falls, threshold_from_growth, write_csv};

/// A short sweep: 24 spins from 3 to 4.5 rad/s (threshold 4), runs of at most 60 s, so the
/// spins up to about 3.95 fall.
const SMALL: Sweep = Sweep {
    lo: 3.0,
    hi: 4.5,
    runs: 24,
    t_end: 60.0,
};

fn rows_of(runs: std::ops::Range<usize>) -> Vec<Row> {
    let results = Ensemble::new(runs).run(|i| SMALL.run(i));
    assert_eq!(results.failures(), 0, "{:?}", results.errors().next());
    results.outputs().map(|(_, r)| *r).collect()
}

/// Bit patterns of a row, so that 0.1 + 0.2 ≠ 0.3 shows and NaN would equal NaN.
fn bits(r: &Row) -> (usize, u64, u64, Option<u64>) {
    (
        r.index,
        r.omega3.to_bits(),
        r.largest_tilt.to_bits(),
        r.growth_rate.map(f64::to_bits),
    )
}

#[test]
fn three_shards_merged_from_csv_give_the_whole_sweeps_bits() {
    let whole = rows_of(0..SMALL.runs);
    // Shards written in reverse order: the merge sorts by the global index.
    let csv: String = (0..3)
        .rev()
        .map(|k| write_csv(&rows_of(shard(k, 3, SMALL.runs))))
        .collect();
    let merged = read_csv(&csv).unwrap();
    assert_eq!(merged.len(), SMALL.runs);
    assert_eq!(
        merged.iter().map(bits).collect::<Vec<_>>(),
        whole.iter().map(bits).collect::<Vec<_>>()
    );
    let fit = threshold_from_growth(&whole).unwrap();
    assert_eq!(
        threshold_from_growth(&merged).unwrap().to_bits(),
        fit.to_bits()
    );
    assert_eq!(
        threshold_from_falls(&merged).map(f64::to_bits),
        threshold_from_falls(&whole).map(f64::to_bits)
    );

    // Independent of the code: the closed-form threshold √(4 M g l I1) / I3 = 4, which the
    // fit of σ² on ω3² over the 15 spins that fell finds to 2.6e-6 relative.
    let theory = HeavyTopTheory::from_principal(sweep::SweepTop.principal().moments, 1.0).unwrap();
    assert_eq!(theory.sleeping_threshold(), 4.0);
    assert!((fit - 4.0).abs() / 4.0 < 1e-5, "fitted threshold {fit}");
    // Some spins fell, some slept: the sweep brackets the threshold.
    let fell = whole.iter().filter(|r| r.growth_rate.is_some()).count();
    assert!(
        fell > 2 && fell < SMALL.runs,
        "{fell} of {} fell",
        SMALL.runs
    );
}

#[test]
fn shards_partition_the_runs_in_order() {
    for total in [0, 1, 2, 7, 24, 1000] {
        for n in 1..=9 {
            let ranges: Vec<_> = (0..n).map(|k| shard(k, n, total)).collect();
            // Consecutive, covering 0..total, sizes differing by at most one.
            assert_eq!(ranges[0].start, 0);
            assert_eq!(ranges[n - 1].end, total);
            for w in ranges.windows(2) {
                assert_eq!(w[0].end, w[1].start, "total {total}, n {n}");
            }
            let sizes: Vec<usize> = ranges.iter().map(|r| r.len()).collect();
            let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
            assert!(hi - lo <= 1, "total {total}, n {n}: {sizes:?}");
        }
        // Out of range asks for nothing.
        assert!(shard(3, 3, total).is_empty());
        assert!(shard(0, 0, total).is_empty());
    }
}

#[test]
fn a_merge_refuses_a_duplicated_run_and_a_malformed_line() {
    let row = Row {
        index: 5,
        omega3: 3.5,
        largest_tilt: 0.01,
        growth_rate: None,
    };
    let one = write_csv(&[row]);
    let twice = format!("{one}{one}");
    assert!(read_csv(&twice).unwrap_err().to_string().contains("run 5"));
    assert!(read_csv("index,omega3,largest_tilt,growth_rate\n1,2,x,\n").is_err());
    assert!(read_csv("1,2,3\n").is_err());
    // A shard of no runs writes only its header, which merges to nothing.
    assert!(read_csv(&write_csv(&[])).unwrap().is_empty());
}

#[test]
fn a_shard_argument_is_k_of_n_with_k_below_n() {
    assert_eq!(parse_shard("0/3"), Ok((0, 3)));
    assert_eq!(parse_shard("2/3"), Ok((2, 3)));
    for bad in ["3/3", "1", "a/3", "1/b", "-1/3", "1/0"] {
        let err = parse_shard(bad).expect_err(bad);
        assert!(err.contains(bad), "{err}");
    }
}
