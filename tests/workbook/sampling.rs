//! The points of the unit disc for glossy reflections (src/lesson/sampling.rs): the stratified and joint sets
//! are (0, m, 2)-nets where the module says they are, each pixel has its own, and every set lies in the disc.

use lecture6::lesson::rng::{Rng, key_of};
use lecture6::lesson::sampling::{DiscSampler, DiscSamples, concentric_disc};
use lecture6::lesson::scene::PixelSample;

/// Whether the 2^m points (32-bit fractions) are a (0, m, 2)-net: every elementary box of area 2^-m
/// (2^a columns by 2^(m-a) rows) holds exactly one point.
fn is_net(points: &[(u32, u32)], m: u32) -> bool {
    points.len() == 1 << m
        && (0..=m).all(|a| {
            let mut seen = vec![false; points.len()];
            points.iter().all(|&(u, v)| {
                let (x, y) = (u as u64 >> (32 - a), v as u64 >> (32 - (m - a)));
                !std::mem::replace(&mut seen[((x << (m - a)) | y) as usize], true)
            })
        })
}

/// The points of camera sample `index` of a pixel of `count` samples with key `pixel_key`, `n` of them,
/// in the unit square.
fn block(index: u32, count: u32, pixel_key: u64, n: u32) -> Vec<(u32, u32)> {
    let sample = PixelSample { index, count, pixel_key };
    let set = DiscSamples::for_pixel_sample(DiscSampler::Joint, &sample, n, &mut Rng::for_keys(&[0]));
    (0..n).map(|i| set.unit_square_point(i)).collect()
}

/// The first 2^m points of the sequence are a (0, m, 2)-net, whatever its random shift.
#[test]
fn power_of_two_prefixes_are_nets() {
    for m in 0..=8u32 {
        for seed in [0, 1, 2] {
            let set = DiscSamples::new(DiscSampler::Stratified, &mut Rng::for_keys(&[seed]));
            let points: Vec<_> = (0..1 << m).map(|i| set.unit_square_point(i)).collect();
            assert!(is_net(&points, m), "m = {m}, seed {seed}");
        }
    }
    // The check can fail: a set with two points in one box is not a net.
    assert!(!is_net(&[(0, 0), (1, 1)], 1));
}

/// A pixel of S camera samples with N joint points each (S and N powers of two): every camera sample's
/// block is a net of N points and the pixel's S N points are a net too.
#[test]
fn a_pixels_joint_points_are_one_net_and_each_block_is_a_net() {
    for pixel_key in [1, 0xdead_beef_u64, u64::MAX] {
        for (s_bits, n_bits) in [(0, 2), (2, 0), (2, 2), (4, 2), (4, 3), (6, 4)] {
            let (count, n) = (1 << s_bits, 1 << n_bits);
            let mut pixel = Vec::new();
            for index in 0..count {
                let points = block(index, count, pixel_key, n);
                assert!(is_net(&points, n_bits), "{count} x {n}: sample {index}'s block is not a net");
                pixel.extend(points);
            }
            assert!(is_net(&pixel, s_bits + n_bits), "{count} x {n}: the pixel's points are not a net");
        }
    }
}

/// Counts that are not powers of two (5 under adaptive anti-aliasing, 3 glossy samples): the pixel's
/// points are still the first S N points of its sequence, each once.
#[test]
fn other_counts_share_out_the_first_points_of_the_sequence() {
    for (count, n) in [(5, 4), (3, 3), (9, 2)] {
        let mut pixel: Vec<_> = (0..count).flat_map(|index| block(index, count, 42, n)).collect();
        // The one sample of a pixel of one sample takes the start of the pixel's sequence.
        let mut prefix = block(0, 1, 42, count * n);
        pixel.sort_unstable();
        prefix.sort_unstable();
        assert_eq!(pixel, prefix, "{count} x {n}");
    }
}

/// Neighbouring pixels have unrelated sets (their keys differ), and the block a camera sample gets
/// depends on the pixel: sample 0 does not always take the first points of its pixel's sequence.
#[test]
fn each_pixel_has_its_own_points_and_its_own_block_order() {
    let keys: Vec<u64> = (0..64).map(|x| key_of(&[1, x, 0])).collect();
    for pair in keys.windows(2) {
        assert_ne!(block(0, 16, pair[0], 4), block(0, 16, pair[1], 4), "neighbours share their points");
    }
    let first_blocks: std::collections::HashSet<u32> = keys
        .iter()
        .map(|&key| {
            // Which block of 4 of the pixel's sequence sample 0 takes.
            let sequence = block(0, 1, key, 64);
            (0..16).find(|&b| sequence[4 * b as usize..4 * b as usize + 4] == block(0, 16, key, 4)[..]).unwrap()
        })
        .collect();
    assert!(first_blocks.len() > 8, "sample 0 takes blocks {first_blocks:?} only");
}

/// What sharing gains: a pixel of 16 camera samples with 4 points each estimates the mean of a smooth
/// function over the disc with much less error from one joint set than from a set per camera sample
/// (and both beat independent points).
#[test]
fn one_set_for_the_pixel_estimates_better_than_a_set_per_camera_sample() {
    let f = |(x, y): (f32, f32)| (3.0 * x + 1.0).sin() * (2.0 * y).cos() + x * y + x;
    let exact = {
        let set = DiscSamples::new(DiscSampler::Stratified, &mut Rng::for_keys(&[0]));
        (0..1 << 20).map(|i| f64::from(f(set.point(i, &mut Rng::for_keys(&[0]))))).sum::<f64>() / (1 << 20) as f64
    };
    let mean_squared_error = |sampler| {
        let pixels = 512;
        let mut rng = Rng::for_keys(&[11]);
        let sum: f64 = (0..pixels)
            .map(|pixel| {
                let (count, n) = (16, 4);
                let mut estimate = 0.0;
                for index in 0..count {
                    let sample = PixelSample { index, count, pixel_key: key_of(&[pixel]) };
                    let set = DiscSamples::for_pixel_sample(sampler, &sample, n, &mut rng);
                    estimate += (0..n).map(|i| f64::from(f(set.point(i, &mut rng)))).sum::<f64>();
                }
                (estimate / (count * n) as f64 - exact).powi(2)
            })
            .sum();
        sum / pixels as f64
    };
    let [random, stratified, joint] =
        [DiscSampler::Random, DiscSampler::Stratified, DiscSampler::Joint].map(mean_squared_error);
    assert!(stratified < random / 2.0, "stratified {stratified:e}, random {random:e}");
    assert!(joint < stratified / 4.0, "joint {joint:e}, stratified {stratified:e}");
}

/// The other samplers ignore the pixel: for them a pixel sample's set is an ordinary new set.
#[test]
fn the_per_shading_point_samplers_ignore_the_pixel() {
    let sample = PixelSample { index: 3, count: 16, pixel_key: 9 };
    for sampler in [DiscSampler::Random, DiscSampler::Stratified] {
        let (mut a, mut b) = (Rng::for_keys(&[5]), Rng::for_keys(&[5]));
        let (p, q) = (DiscSamples::for_pixel_sample(sampler, &sample, 4, &mut a), DiscSamples::new(sampler, &mut b));
        for i in 0..4 {
            assert_eq!(p.point(i, &mut a), q.point(i, &mut b), "{sampler:?}");
        }
    }
}

#[test]
fn points_lie_in_the_disc() {
    let mut rng = Rng::for_keys(&[7]);
    for sampler in [DiscSampler::Random, DiscSampler::Stratified, DiscSampler::Joint] {
        let set = DiscSamples::new(sampler, &mut rng);
        for i in 0..1000 {
            let (x, y) = set.point(i, &mut rng);
            assert!(x * x + y * y <= 1.0 + 2.0 * f32::EPSILON, "{sampler:?} point {i}: ({x}, {y})");
        }
    }
}

#[test]
fn the_concentric_mapping_keeps_areas() {
    // Each quadrant of the square's centre-symmetric rings maps to a ring of the same area fraction: a
    // point at square radius r lands at disc radius r.
    for (u, v, r) in [(0.75, 0.5, 0.5), (0.5, 1.0, 1.0), (0.0, 0.25, 1.0), (0.625, 0.625, 0.25)] {
        let (x, y) = concentric_disc(u, v);
        assert!(((x * x + y * y).sqrt() - r).abs() <= 4.0 * f32::EPSILON, "({u}, {v}) -> ({x}, {y})");
    }
}
