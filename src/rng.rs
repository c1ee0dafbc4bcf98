//! Deterministic random numbers for Monte Carlo parts of the renderer (anti-aliasing jitter, glossy
//! sampling, photon emission).
//!
//! The generator is PCG32 (`rand_pcg::Pcg32`, whose output is documented and value-stable across
//! versions and platforms). Every pixel gets its own stream, seeded from (seed, x, y): the picture is
//! therefore the same byte for byte whatever the number of threads or the order in which rows are
//! rendered. Never seed from the clock or the thread.

use rand_core::RngCore;
use rand_pcg::Pcg32;

/// A small deterministic random generator.
#[derive(Clone, Debug)]
pub struct Rng(Pcg32);

/// SplitMix64's finaliser: spreads the bits of a key so that neighbouring pixels get unrelated seeds.
pub fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

impl Rng {
    /// A generator for one stream identified by `keys` (for example seed, x, y, pass).
    pub fn for_keys(keys: &[u64]) -> Rng {
        let h = keys.iter().fold(0x243f_6a88_85a3_08d3_u64, |h, &k| mix64(h ^ k));
        Rng(Pcg32::new(h, mix64(h) | 1))
    }
    /// The generator of pixel (x, y) for a render with the given seed.
    pub fn for_pixel(seed: u64, x: u32, y: u32) -> Rng {
        Rng::for_keys(&[seed, x as u64, y as u64])
    }
    pub fn next_u32(&mut self) -> u32 {
        self.0.next_u32()
    }
    /// A uniform float in [0, 1): the top 24 bits of the next output, so every value is exact.
    pub fn next_f32(&mut self) -> f32 {
        (self.0.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }
    /// A uniform integer in [0, n) (n > 0), without modulo bias (Lemire's method).
    pub fn below(&mut self, n: u32) -> u32 {
        let mut m = self.0.next_u32() as u64 * n as u64;
        if (m as u32) < n {
            let t = n.wrapping_neg() % n;
            while (m as u32) < t {
                m = self.0.next_u32() as u64 * n as u64;
            }
        }
        (m >> 32) as u32
    }
}
