//! A small multiplicative hasher for the interning maps.
//!
//! The keys are short arrays of `u32` ids built by the engine itself, never by an adversary,
//! so SipHash's flooding resistance buys nothing and costs a third of the derivation time.

use std::hash::{BuildHasherDefault, Hasher};

/// Fx-style hasher (rotate, xor, multiply), as used inside rustc.
#[derive(Default, Clone, Copy)]
pub struct IdHasher(u64);

const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl Hasher for IdHasher {
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut buf = [0u8; 8];
            buf[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(buf));
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(SEED);
    }

    fn write_u32(&mut self, n: u32) {
        self.write_u64(n as u64);
    }

    fn write_usize(&mut self, n: usize) {
        self.write_u64(n as u64);
    }

    fn finish(&self) -> u64 {
        // The multiply leaves its entropy in the high bits, while hashbrown picks the bucket
        // from the low ones: rotated down, as rustc-hash does.
        self.0.rotate_left(26)
    }
}

/// `HashMap` with [`IdHasher`].
pub type IdMap<K, V> = std::collections::HashMap<K, V, BuildHasherDefault<IdHasher>>;
