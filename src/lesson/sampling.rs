//! Points in the unit disc for glossy reflections (slide "Симулиране на грапави отражения", step 2:
//! "generate a random 2D vector in the unit disc").
//!
//! Three samplers:
//! - [`DiscSampler::Random`] is the slide's: each point independent and uniform, drawn by rejection from the
//!   square [-1, 1]^2 (the course's `randomUnitDiscPoint`). Its error falls as 1 / sqrt(N).
//! - [`DiscSampler::Stratified`] spreads the N points of one shading point evenly over the disc: the first N
//!   points of the 2D Sobol (0, 2)-sequence (the van der Corput sequence in base 2 and its Sobol partner),
//!   randomised by a random digital shift (an XOR of each coordinate with a random 32-bit word drawn from the
//!   pixel's generator, which keeps every power-of-two prefix a (0, m, 2)-net and decorrelates neighbouring
//!   pixels and samples), then carried to the disc by Shirley and Chiu's concentric mapping, which keeps
//!   the strata compact. The error of a glossy reflection falls markedly faster than with the slide's
//!   sampler; the study (`benches/error_vs_time.rs`) measures by how much.
//! - [`DiscSampler::Joint`], the default, spreads the points of a whole pixel: with S camera samples of N
//!   points each, the pixel has one digitally shifted (0, 2)-sequence (the shift drawn once per pixel, from
//!   the pixel's key [`PixelSample::pixel_key`]) and each camera sample takes a block of N consecutive points
//!   of it, camera sample s the block number `shuffled_index(s, S, key)` (a keyed random order, so that which
//!   block a sample gets does not depend on where in the pixel it lies), i.e. points b N .. b N + N - 1. When
//!   N is a power of two each block starts at a multiple of N and is itself a (0, m, 2)-net, so every camera
//!   ray still has N well-spread points; when S is one too, the blocks together are a (0, m, 2)-net of S N
//!   points. Stratified sets are one per camera ray, so the pixel's S N points are S unrelated nets: two
//!   camera samples may put points side by side and leave holes. With other counts the pixel's points are
//!   still the first S N points of the sequence, well spread though not a net. The joint set belongs to the
//!   first glossy bounce of each camera ray ([`DiscSamples::for_pixel_sample`]); deeper glossy bounces and
//!   shading points outside a pixel ([`crate::lesson::scene::TraceContext::pixel_sample`] `None`) draw a set of their
//!   own, as the stratified sampler does. Every point of a randomly shifted sequence is uniform over the
//!   square, so each rule is unbiased whatever the counts; the counts only decide how well the points spread
//!   (camera samples whose first glossy surfaces take different counts, or two glossy layers of one `Layered`
//!   shader, which get the same block, still average to the right picture).
//!
//! Deviation from the slide: the slide draws from the C library's global `rand()`; here every point comes
//! from the pixel's own deterministic stream (`ctx.rng`) or its key, so pictures do not depend on the thread
//! count (ledger: `pixel-streams`).

use crate::lesson::rng::{Rng, mix64, shuffled_index};
use std::f32::consts::FRAC_PI_4;

/// Which of its pixel's camera samples is being traced: sample `index` of the `count` the pixel gets. A
/// shader that takes many samples of its own (a glossy mirror's disc points) can spread them over the whole
/// pixel with it, one well-distributed set for all the pixel's camera samples instead of one per camera ray
/// (see [`crate::lesson::sampling::DiscSampler::Joint`]). Shaders that do not need it ignore it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelSample {
    /// This camera sample's index, `0..count`.
    pub index: u32,
    /// How many camera samples the pixel gets in all: the `spp`, or, under the course's adaptive
    /// anti-aliasing, the most a pixel may get ([`crate::lesson::adaptive_aa::SAMPLES_PER_REFINED_PIXEL`]): a pixel
    /// that is never refined uses only sample 0 of them.
    pub count: u32,
    /// A random word of the pixel (and of the wavelength pass), the same for all its camera samples and
    /// unrelated to its neighbours': what a sampler randomises its pixel-wide set with.
    pub pixel_key: u64,
}

/// How the points in the unit disc are chosen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DiscSampler {
    /// Independent uniform points (the slide's sampler).
    Random,
    /// A randomly shifted (0, 2)-sequence mapped concentrically to the disc, one per shading point.
    Stratified,
    /// One randomly shifted (0, 2)-sequence per pixel, shared out between its camera samples.
    #[default]
    Joint,
}

/// A salt for the word that orders a pixel's blocks, so that it is unrelated to the pixel's shift.
const BLOCK_ORDER_KEY: u64 = 0x424c_4f43_4b53_4f52;

/// The points of one shading point: create it with [`DiscSamples::new`] or
/// [`DiscSamples::for_pixel_sample`], then ask for points 0, 1, 2, ...
#[derive(Clone, Copy, Debug)]
pub struct DiscSamples {
    sampler: DiscSampler,
    /// The random digital shift of the sequence (one word per coordinate).
    shift: [u32; 2],
    /// The index in the sequence of point 0 of the set: the start of the camera sample's block.
    first: u32,
}

impl DiscSamples {
    /// Starts a new set of points for one shading point, drawing whatever randomisation the sampler needs
    /// from `rng`; the joint sampler, given no pixel, draws a set of its own as the stratified one does.
    pub fn new(sampler: DiscSampler, rng: &mut Rng) -> DiscSamples {
        let shift = match sampler {
            DiscSampler::Random => [0, 0],
            DiscSampler::Stratified | DiscSampler::Joint => {
                beyond!(DiscSamples);
                [rng.next_u32(), rng.next_u32()]
            }
        };
        DiscSamples { sampler, shift, first: 0 }
    }

    /// The `count` points of a shading point that camera sample `sample` reaches first: with the joint
    /// sampler, the sample's block of its pixel's set (see the module documentation); with the others, a
    /// new set as [`DiscSamples::new`] makes.
    pub fn for_pixel_sample(sampler: DiscSampler, sample: &PixelSample, count: u32, rng: &mut Rng) -> DiscSamples {
        if sampler != DiscSampler::Joint {
            return DiscSamples::new(sampler, rng);
        }
        beyond!(DiscSamples);
        let shift = mix64(sample.pixel_key);
        let block = shuffled_index(sample.index, sample.count, mix64(sample.pixel_key ^ BLOCK_ORDER_KEY) as u32);
        DiscSamples { sampler, shift: [shift as u32, (shift >> 32) as u32], first: block * count }
    }

    /// Point `i` of the set, inside the unit disc.
    pub fn point(&self, i: u32, rng: &mut Rng) -> (f32, f32) {
        match self.sampler {
            DiscSampler::Random => random_unit_disc_point(rng),
            DiscSampler::Stratified | DiscSampler::Joint => {
                let (u, v) = self.unit_square_point(i);
                concentric_disc(to_unit(u), to_unit(v))
            }
        }
    }

    /// Point `i` of a stratified or joint set in the unit square, before the mapping to the disc, as 32-bit
    /// fractions (what the tests check the nets on).
    pub fn unit_square_point(&self, i: u32) -> (u32, u32) {
        let k = self.first + i;
        (van_der_corput(k) ^ self.shift[0], sobol2(k) ^ self.shift[1])
    }
}

/// A uniform random point of the unit disc, by rejection from the square [-1, 1]^2 as in the course's code.
pub fn random_unit_disc_point(rng: &mut Rng) -> (f32, f32) {
    exercise!(random_unit_disc_point(rng));
    loop {
        let x = 2.0 * rng.next_f32() - 1.0;
        let y = 2.0 * rng.next_f32() - 1.0;
        if x * x + y * y <= 1.0 {
            return (x, y);
        }
    }
}

/// Shirley and Chiu's concentric mapping of the unit square onto the unit disc: concentric squares go to
/// concentric circles, so points that are evenly spread in the square stay evenly spread in the disc, and
/// equal areas map to equal areas.
pub fn concentric_disc(u: f32, v: f32) -> (f32, f32) {
    exercise!(concentric_disc(u, v));
    let (a, b) = (2.0 * u - 1.0, 2.0 * v - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) =
        if a.abs() > b.abs() { (a, FRAC_PI_4 * (b / a)) } else { (b, 2.0 * FRAC_PI_4 - FRAC_PI_4 * (a / b)) };
    (r * phi.cos(), r * phi.sin())
}

/// A 32-bit fixed-point fraction as a float in [0, 1): the top 24 bits, so the value is exact and below 1.
fn to_unit(bits: u32) -> f32 {
    (bits >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
}

/// The van der Corput radical inverse in base 2 (the first Sobol dimension), as a 32-bit fraction.
fn van_der_corput(i: u32) -> u32 {
    i.reverse_bits()
}

/// The second dimension of the Sobol sequence, as a 32-bit fraction: the XOR of the direction numbers of the
/// set bits of `i`. Its direction numbers are those of the primitive polynomial x + 1: v_1 = 1/2 and
/// v_k = v_{k-1} XOR v_{k-1} / 2, i.e. the rows of Pascal's triangle mod 2 read as binary fractions.
fn sobol2(mut i: u32) -> u32 {
    let mut v = 1u32 << 31;
    let mut x = 0;
    while i != 0 {
        if i & 1 != 0 {
            x ^= v;
        }
        i >>= 1;
        v ^= v >> 1;
    }
    x
}
