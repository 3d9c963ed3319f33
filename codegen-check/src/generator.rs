//! A deterministic generator of random expressions, shared by the build script (which emits
//! them as Rust) and the tests (which rebuild and interpret them).

use precess_core::sym::{Arena, ExprId};

/// Number of generated programs.
pub const PROGRAMS: usize = 300;
/// Symbols available to the expressions; `env[i]` holds the value of `VARS[i]`.
pub const VARS: [&str; 4] = ["a", "b", "q", "w"];

/// SplitMix64: tiny, seedable, good enough to pick tree shapes.
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n`.
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The arena holding every program's outputs, symbols created in `VARS` order.
pub fn arena_with_vars() -> Arena {
    let mut a = Arena::new();
    for v in VARS {
        a.parameter(v);
    }
    a
}

/// Program `k`: one to three related outputs (sharing subexpressions, as derivations do).
pub fn program(a: &mut Arena, k: usize) -> Vec<ExprId> {
    let mut rng = Rng::new(0x5EED_0000 + k as u64);
    let n_out = 1 + rng.below(3) as usize;
    let shared = expr(a, &mut rng, 3);
    (0..n_out)
        .map(|_| {
            let e = expr(a, &mut rng, 3);
            match rng.below(3) {
                0 => a.mul(e, shared),
                1 => a.add(e, shared),
                _ => e,
            }
        })
        .collect()
}

fn expr(a: &mut Arena, rng: &mut Rng, depth: u32) -> ExprId {
    if depth == 0 || rng.below(4) == 0 {
        return match rng.below(5) {
            0 => {
                let n = rng.below(9) as i64 - 4;
                let d = 1 + rng.below(5) as i64;
                let num = a.integer(n);
                let den = a.integer(d);
                a.div(num, den).unwrap_or(num)
            }
            _ => {
                let i = rng.below(VARS.len() as u64) as usize;
                a.parameter(VARS[i])
            }
        };
    }
    let x = expr(a, rng, depth - 1);
    match rng.below(9) {
        0 | 1 => {
            let y = expr(a, rng, depth - 1);
            a.add(x, y)
        }
        2 => {
            let y = expr(a, rng, depth - 1);
            a.sub(x, y)
        }
        3 | 4 => {
            let y = expr(a, rng, depth - 1);
            a.mul(x, y)
        }
        5 => {
            // Divide by something bounded away from zero: 2 + cos(y).
            let y = expr(a, rng, depth - 1);
            let c = a.cos(y);
            let two = a.integer(2);
            let d = a.add(two, c);
            a.div(x, d).unwrap_or(x)
        }
        6 => {
            let n = rng.below(6) as i64 + 2;
            a.powi(x, n).unwrap_or(x)
        }
        7 => {
            if rng.below(2) == 0 {
                a.sin(x)
            } else {
                a.cos(x)
            }
        }
        _ => {
            let x2 = a.mul(x, x);
            let one = a.one();
            let u = a.add(x2, one);
            a.sqrt(u).unwrap_or(x)
        }
    }
}
