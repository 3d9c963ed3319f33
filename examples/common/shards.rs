//! Shards of an ensemble's index range, shared by the examples that take `--shard k/n`
//! (`sleeping_sweep`, `chaos_map`) and by the shard test (`tests/it/ensemble_shards.rs`).

use std::ops::Range;

/// Shard `k` of `n` of the runs `0..total`: consecutive runs, the first `total % n` shards
/// one run longer; empty when `n` is 0 or `k ≥ n`.
pub fn shard(k: usize, n: usize, total: usize) -> Range<usize> {
    if n == 0 || k >= n {
        return total..total;
    }
    let (base, extra) = (total / n, total % n);
    let start = k * base + k.min(extra);
    start..start + base + usize::from(k < extra)
}

/// `k/n` from the command line, with 0 ≤ k < n.
///
/// # Errors
/// A message naming the argument when it is not two counts with k < n.
pub fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("--shard {s}: expected k/n with 0 ≤ k < n");
    let (k, n) = s.split_once('/').ok_or_else(bad)?;
    let (k, n): (usize, usize) = (k.parse().map_err(|_| bad())?, n.parse().map_err(|_| bad())?);
    if k >= n {
        return Err(bad());
    }
    Ok((k, n))
}
