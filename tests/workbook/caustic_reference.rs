//! The photon_map example's caustic against its independent reference (`benches/caustic_reference.rs`, a
//! light tracer sharing none of the renderer's code; its rings in `benches/results/caustic_reference.tsv`):
//! the reference is the example's scene and is as precise as it says, and the photon map's estimate at the
//! example's settings, averaged over 16 maps of their own seeds, lies within 1% of it in every ring from
//! 0.02 out to where the caustic's light falls to a hundredth of its centre's (a radius of 8). One map is
//! not held to it: near the centre its error is that map's own, several per cent, and only maps of other
//! seeds average it out. Nor is the central ring, where the estimate's disc is wider than the ring, nor the
//! faint rings beyond (out to the shadow's edge, 14.24), where the estimate's disc reaches its maximum radius
//! and blurs the reference's sharp steps (at 9.84 and 13.33) by more than 1% (+1.54% at 13.42 even with
//! 1.6 M photons per map). docs/beyond-the-slides.md, "The caustic against an independent light tracer".

use crate::common;

use common::caustic::{REFERENCE, Reference, estimated_rings, progressive_rings, read_reference, relative_errors};
use common::examples::photon_map::{GLASS_CENTER, LIGHT, Options};
use lecture6::lesson::photon_map::PhotonMap;

/// The maps averaged, each with its own seed.
const SEEDS: u64 = 16;
/// The rings held to 1%: those whose light is at least this fraction of the central ring's.
const BRIGHT: f64 = 0.01;
/// Estimates along each ring's circles are this far apart (the estimate's disc is about as wide near the
/// centre, and wider farther out).
const SPACING: f64 = 0.2;

#[test]
fn the_reference_is_the_examples_caustic_within_its_stated_error() {
    let reference = read_reference(&common::root().join(REFERENCE));
    // Centred where the line from the example's lamp through its glass ball's centre meets the floor.
    let (light, ball) = (LIGHT.as_dvec3(), GLASS_CENTER.as_dvec3());
    let centre = light + (ball - light) * (light.y / (light.y - ball.y));
    let off_centre = (reference.centre.0 - centre.x).hypot(reference.centre.1 - centre.z);
    assert!(off_centre <= 1e-6 * centre.length(), "centre {:?} instead of {centre}", reference.centre);
    // Rings 0.02 wide from the centre, each with at most 0.3% standard error.
    assert!(reference.rings.len() >= 100, "{} rings", reference.rings.len());
    for (i, ring) in reference.rings.iter().enumerate() {
        let inner = 0.02 * i as f64;
        assert!((ring.inner - inner).abs() < 1e-9 && (ring.outer - inner - 0.02).abs() < 1e-9, "ring {i}: {ring:?}");
        assert!(ring.irradiance > 0.0 && ring.standard_error <= 0.003 * ring.irradiance, "ring {i}: {ring:?}");
    }
}

#[test]
fn the_photon_maps_caustic_averaged_over_seeds_is_within_one_percent_of_the_reference_in_its_bright_rings() {
    let reference = read_reference(&common::root().join(REFERENCE));
    let (scene, _) = common::parse::<Options>(&[]).prepare().expect("the example's scene");
    let mut sum = vec![0.0; reference.rings.len()];
    for seed in 1..=SEEDS {
        let map = PhotonMap::build(&scene, seed).expect("valid settings").expect("the glass casts a caustic");
        let values = estimated_rings(&map, &scene, &reference, SPACING);
        sum.iter_mut().zip(values).for_each(|(s, v)| *s += v / SEEDS as f64);
    }
    let errors = relative_errors(&sum, &reference);
    let bright = reference.rings.iter().take_while(|r| r.irradiance >= BRIGHT * reference.rings[0].irradiance).count();
    assert!(bright > 300, "{bright} rings: the caustic is shorter than the reference says");
    assert_rings_off_centre_within_one_percent(&errors[..bright], &reference);
}

/// Every ring but the central one within 1% of the reference; the failure names the worst and lists all.
fn assert_rings_off_centre_within_one_percent(errors: &[f64], reference: &Reference) {
    let (worst, error) =
        errors.iter().enumerate().skip(1).max_by(|a, b| a.1.abs().total_cmp(&b.1.abs())).expect("rings");
    let ring = reference.rings[worst];
    assert!(
        error.abs() <= 0.01,
        "ring {:.2}-{:.2}: {:+.2}% against the reference (every ring's: {:?})",
        ring.inner,
        ring.outer,
        100.0 * error,
        errors.iter().map(|e| format!("{:+.2}%", 100.0 * e)).collect::<Vec<_>>()
    );
}

/// The progressive caustic's budget in the test below: passes of the example's 400,000 photons.
const PASSES: u32 = 32;

/// The progressive caustic (`--photon-passes`, `src/lesson/photon_map/progressive.rs`) of ONE render, seed 1:
/// 32 passes of the example's 400,000 photons, each with a map of its own, the later ones gathering within
/// their shrinking radius, are within 2% of the reference in the central ring (0-0.02, -1.38%; the first
/// map alone is 8.4% off there) and within 1% in every other ring out to a hundredth of the centre's light
/// (7.92; the worst -0.74%, at 0.26-0.28). 16 passes are not enough: +1.16% at 0.06-0.08. It takes 46 s of
/// CPU time in the release profile (66 s wall on 2 cores busy with other work): 32 photon maps, each
/// estimated on the rings.
#[test]
fn the_progressive_caustic_of_one_render_is_within_two_percent_at_its_centre_and_one_percent_elsewhere() {
    let mut reference = read_reference(&common::root().join(REFERENCE));
    let bright = reference.rings.iter().take_while(|r| r.irradiance >= BRIGHT * reference.rings[0].irradiance).count();
    reference.rings.truncate(bright);
    let (scene, settings) =
        common::parse::<Options>(&["--photon-passes", &PASSES.to_string()]).prepare().expect("the example's scene");
    assert_eq!(settings.photon_passes, PASSES);
    let values = progressive_rings(&scene, &reference, settings.photon_passes, settings.seed, SPACING);
    let errors = relative_errors(&values, &reference);
    let all = || errors.iter().map(|e| format!("{:+.2}%", 100.0 * e)).collect::<Vec<_>>();
    assert!(
        errors[0].abs() <= 0.02,
        "central ring: {:+.2}% against the reference (every ring's: {:?})",
        100.0 * errors[0],
        all()
    );
    assert_rings_off_centre_within_one_percent(&errors, &reference);
}
