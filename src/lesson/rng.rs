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

/// One 64-bit word for a list of keys (for example seed, x, y, pass): lists that differ anywhere give
/// unrelated words.
pub fn key_of(keys: &[u64]) -> u64 {
    keys.iter().fold(0x243f_6a88_85a3_08d3_u64, |h, &k| mix64(h ^ k))
}

impl Rng {
    /// A generator for one stream identified by `keys` (for example seed, x, y, pass).
    pub fn for_keys(keys: &[u64]) -> Rng {
        Rng::for_key(key_of(keys))
    }
    /// The generator of the stream whose keys make the word `key` ([`key_of`]): [`Rng::for_keys`] when the
    /// word is needed for something else too (a pixel's sample-set key), so that it is found once.
    pub fn for_key(key: u64) -> Rng {
        Rng(Pcg32::new(key, mix64(key) | 1))
    }
    /// The generator of pixel (x, y) for a render with the given seed.
    pub fn for_pixel(seed: u64, x: u32, y: u32) -> Rng {
        Rng::for_keys(&[seed, x as u64, y as u64])
    }
    /// The next 32 random bits of the PCG32 stream.
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

/// A random permutation of 0..n that needs no table: `shuffled_index(i, n, key)` is where index `i` goes,
/// and the indices 0..n go to 0..n in an order chosen by `key`, each exactly once. The N-rooks rows of a
/// pixel's samples and spectral sampling's bands use it, so that their memory does not grow with the
/// sample count and every pixel's order depends on its own key alone.
///
/// How: every step of `scramble` (an XOR, a multiplication by an odd number, an XOR with the word shifted
/// right) is a one-to-one map of the k-bit words, k the bits of n - 1, so their composition is a
/// permutation of 0..2^k; applying it again while the result is n or more ("cycle walking") stays on the
/// cycle of `i` and ends inside 0..n, a permutation of 0..n. Since 2^k < 2n, a step is repeated less than
/// twice on average.
pub fn shuffled_index(i: u32, n: u32, key: u32) -> u32 {
    debug_assert!(i < n, "index {i} outside 0..{n}");
    let mask = u32::MAX >> (n.max(2) - 1).leading_zeros();
    let scramble = |mut x: u32| {
        x ^= key;
        x = x.wrapping_mul(0x9e37_79b1) & mask;
        x ^= x >> 7;
        x = (x ^ key.rotate_left(13)).wrapping_mul(0x85eb_ca6b) & mask;
        x ^= x >> 11;
        x = x.wrapping_mul(0xc2b2_ae35) & mask;
        x ^ (x >> 5)
    };
    let mut x = scramble(i);
    while x >= n {
        x = scramble(x);
    }
    x
}

/// A salt for the pixels' sample-set keys, so that they are unrelated to the seeds of the pixels' streams.
const SAMPLE_SET_KEY: u64 = 0x5345_5453_414d_504c;

/// The `PixelSample::pixel_key` of the pixel (or wavelength pass of a pixel) whose random stream is keyed
/// by `stream_keys` (see [`Rng::for_keys`]). The adaptive anti-aliasing pass asks for it again to give a
/// refined pixel's extra samples the same set.
pub fn pixel_key(stream_keys: &[u64]) -> u64 {
    pixel_key_of(key_of(stream_keys))
}

/// [`pixel_key`] from the stream's key word ([`key_of`] of its keys), found once for both.
pub(crate) fn pixel_key_of(stream_key: u64) -> u64 {
    mix64(stream_key ^ SAMPLE_SET_KEY)
}
