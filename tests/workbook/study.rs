//! The error-versus-time study measures what it claims: on tiny pictures, the error against the converged
//! reference falls as the sample count rises, and the stratified disc sampler beats the slide's random one.

use crate::common;

use common::examples::{bitmap_textures, glossy};
use lecture6::instruments::study::{Measurement, Sweep, cost_at_rmse, pareto_front, rmse_at_time};

fn rmse_curve(sweep: &Sweep) -> Vec<f64> {
    let reference = sweep.reference_frame(None).unwrap();
    sweep.measure(&reference, 1, None).unwrap().iter().map(|m| m.rmse).collect()
}

fn assert_falls(name: &str, rmse: &[f64]) {
    assert!(rmse.windows(2).all(|w| w[1] < w[0]), "{name}: the error does not fall with the sample count: {rmse:?}");
}

#[test]
fn glossy_error_falls_with_the_sample_count_and_stratified_beats_random() {
    // One pixel-centre sample per pixel, so the error is that of the glossy reflections alone.
    let sweep = |sampler| {
        Sweep::new::<glossy::Options>(
            "glossy",
            sampler,
            &["--width", "64", "--height", "48", "--spp", "1", "--sampler", sampler],
            "--glossy-samples",
            &[1, 4, 16, 64],
            &["--glossy-samples", "1024", "--sampler", "stratified", "--seed", "7"],
        )
    };
    let stratified = rmse_curve(&sweep("stratified"));
    let random = rmse_curve(&sweep("random"));
    assert_falls("stratified", &stratified);
    assert_falls("random", &random);
    // Independent samples: the error falls as 1/sqrt(N), 8 times over 64 times the samples.
    assert!(random[3] < random[0] / 4.0, "random: {random:?}");
    for k in 1..4 {
        assert!(stratified[k] < random[k], "at the same count stratified must be better: {stratified:?} vs {random:?}");
    }
}

#[test]
fn anti_aliasing_error_falls_with_the_sample_count() {
    let sweep = Sweep::new::<bitmap_textures::Options>(
        "bitmap_textures",
        "anti-aliasing",
        &["--width", "80", "--height", "60"],
        "--spp",
        &[1, 4, 16],
        &["--spp", "256", "--seed", "7"],
    );
    assert_falls("bitmap_textures", &rmse_curve(&sweep));
}

fn point(example: &'static str, seconds: f64, rmse: f64) -> Measurement {
    let reference = String::from("--spp 256");
    Measurement {
        example,
        label: String::new(),
        reference,
        knob: "--spp",
        value: 1,
        seconds,
        rmse,
        rays: 0,
        perceptual: None,
    }
}

#[test]
fn the_pareto_front_keeps_only_undominated_points_of_each_group() {
    let other_reference = Measurement { reference: "--spp 1".into(), ..point("a", 0.5, 0.01) };
    let m = [point("a", 1.0, 0.5), point("a", 2.0, 0.6), point("a", 3.0, 0.1), point("b", 9.0, 0.9), other_reference];
    assert_eq!(pareto_front(&m), [true, false, true, true, true]);
}

#[test]
fn errors_are_interpolated_in_log_log() {
    let curve = [point("a", 1.0, 0.1), point("a", 4.0, 0.025)];
    // On a line of slope -1 in log-log, twice the time halves the error.
    let at_2 = rmse_at_time(&curve, 2.0).unwrap();
    assert!((at_2 - 0.05).abs() < 1e-12, "{at_2}");
    assert_eq!(rmse_at_time(&curve, 8.0), None);
}

#[test]
fn costs_are_interpolated_in_log_log_at_an_error() {
    let curve = [point("a", 1.0, 0.1), point("a", 4.0, 0.025), point("a", 8.0, 0.02)];
    // On a line of slope -1 in log-log, half the error takes twice the time.
    let at = cost_at_rmse(&curve, 0.05, |m| m.seconds).unwrap();
    assert!((at - 2.0).abs() < 1e-12, "{at}");
    let at_last = cost_at_rmse(&curve, 0.02, |m| m.seconds).unwrap();
    assert!((at_last - 8.0).abs() < 1e-12, "{at_last}");
    assert_eq!(cost_at_rmse(&curve, 0.01, |m| m.seconds), None, "below the curve's lowest error");
    assert_eq!(cost_at_rmse(&curve, 0.2, |m| m.seconds), None, "above its highest");
}
