//! Numerical stress: every example's scene, uniformly scaled and moved far from the origin (camera and
//! lights with it), must render the same picture as the canonical one.
//!
//! The scene is wrapped, node by node, in an extra transform (scale s, then translate by an offset); the
//! camera and the lights move with it, and the lights' intensities grow by s^2 so that the 1/d^2 falloff
//! gives the same irradiance. Pictures are 160 x 120 at one sample per pixel, so a change anywhere is not
//! averaged away.
//!
//! Rules, each allowing at most 0.5% of the pixels (96 of 19200) to change:
//! - scaled at the origin, a pixel changes when it differs by more than 8 levels in some channel: the
//!   picture must stay the same (measured: at most 1 pixel for every example and scale);
//! - moved 1e6 from the origin, a pixel changes when it differs by more than 8 levels from every pixel of
//!   the 3 x 3 neighbourhood around it in the canonical picture. The examples then render relative to the
//!   camera (`Scene::relative_to_camera`, which `picture` calls too), but the objects' positions, written at 1e6 in f32,
//!   are rounded to 0.0625 apart, so an edge may move by about a pixel; acne or a light leak changes whole
//!   surfaces and still counts. Measured: 0 pixels for nine examples, 25 for `dispersion` and 52 for
//!   `model_transform`. With the ray offsets switched off every example fails.
//!
//! The photon map is built for each transformed scene, as the examples build it, and its gathering radius
//! (a length) is scaled with the scene; without that, scale 100 changes 731 of the 19200 pixels.

use crate::common;

use lecture6::app::cli::Example;
use lecture6::instruments::compare::{Difference, difference, heat_map};
use lecture6::lesson::math::Vector;
use lecture6::lesson::photon_map::PhotonMap;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::scene::Scene;
use std::sync::Arc;

/// The scene scaled by `s` about the origin, then moved by `offset`.
fn transformed(scene: &Scene, s: f32, offset: Vector) -> Scene {
    let mut out = scene.clone();
    for node in &mut out.nodes {
        node.transform = Some(node.transform.unwrap_or_default().scale(Vector::splat(s)).translate(offset));
    }
    out.camera.position = scene.camera.position * s + offset;
    for light in &mut out.lights {
        light.position = light.position * s + offset;
        light.intensity *= s * s;
    }
    out
}

/// The scene's picture, made as the examples make it: moved relative to the camera, its caustic photon map
/// built for it as it is now.
fn picture(scene: &Scene) -> image::RgbImage {
    let settings = RenderSettings { width: 160, height: 120, spp: 1, ..RenderSettings::default() };
    let mut scene = scene.clone();
    scene.relative_to_camera();
    scene.photon_map = PhotonMap::build(&scene, settings.seed).expect("photon map").map(Arc::new);
    let (frame, stats) = render(&scene, &settings).expect("render");
    assert_eq!(stats.counters.non_finite_samples, 0, "samples came back NaN or infinite");
    frame.to_rgb8()
}

/// How many pixels of `actual` differ by more than `Difference::LARGE` levels in some channel from every
/// pixel of the 3 x 3 neighbourhood around the same place in `reference`: a picture whose edges moved by
/// up to a pixel (f32 positions far from the origin are rounded to a grid) counts nothing, while acne or a
/// light leak, which change the colour of whole surfaces, counts every pixel it touches.
fn pixels_not_found_nearby(actual: &image::RgbImage, reference: &image::RgbImage) -> usize {
    let (w, h) = reference.dimensions();
    let mut count = 0;
    for (x, y, p) in actual.enumerate_pixels() {
        let found = (y.saturating_sub(1)..=(y + 1).min(h - 1)).any(|ny| {
            (x.saturating_sub(1)..=(x + 1).min(w - 1)).any(|nx| {
                let q = reference.get_pixel(nx, ny);
                (0..3).all(|c| p[c].abs_diff(q[c]) <= Difference::LARGE)
            })
        });
        count += !found as usize;
    }
    count
}

/// The scales every example goes through, at the origin.
const SCALES: [f32; 4] = [1e-4, 1e-2, 1e2, 1e5];

/// How far from the origin every example is moved.
const FAR: f32 = 1e6;

/// The cases: every scale at the origin; moved by `FAR` along all three axes at once, both signs; and moved
/// by `FAR` at scale 100.
fn cases() -> Vec<(f32, f32)> {
    SCALES.iter().map(|&s| (s, 0.0)).chain([(1.0, FAR), (1.0, -FAR), (1e2, FAR)]).collect()
}

fn check_scales_and_offsets<E: Example>(example: &str, adjust: impl Fn(&mut Scene, f32)) {
    let scene = common::parse::<E>(&[]).example.scene().unwrap();
    let reference = picture(&scene);
    let mut failures = Vec::new();
    for (s, t) in cases() {
        let mut moved = transformed(&scene, s, Vector::new(t, -t * 0.5, t * 0.25));
        adjust(&mut moved, s);
        let actual = picture(&moved);
        let d = difference(&actual, &reference).unwrap();
        // At the origin the picture must not change; far from it, edges may move by a pixel (see the rule).
        let changed = if t == 0.0 { d.large_pixels } else { pixels_not_found_nearby(&actual, &reference) };
        eprintln!("{example} scaled by {s:e}, moved by {t:e}: {changed} pixels changed; {d}");
        if changed * 200 > d.pixels {
            let dir = common::root().join("target").join("stress");
            std::fs::create_dir_all(&dir).unwrap();
            let name = format!("{example}-s{s:e}-t{t:e}");
            actual.save(dir.join(format!("{name}.png"))).unwrap();
            heat_map(&actual, &reference).unwrap().save(dir.join(format!("{name}-diff.png"))).unwrap();
            failures.push(format!("scaled by {s:e}, moved by {t:e}: {d}"));
        }
    }
    assert!(failures.is_empty(), "{example}: {}", failures.join("; "));
}

/// Scales what the scene holds as a length outside its nodes, camera and lights: the photon map's
/// gathering radius (its k stays). The other examples' options hold no lengths (the dispersion studio's slit
/// and lamps are in the environment, which depends on directions only).
fn scale_lengths(scene: &mut Scene, s: f32) {
    scene.photons.max_radius = scene.photons.max_radius.map(|r| r * s);
}

macro_rules! survives_scaling_and_translation {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            check_scales_and_offsets::<common::examples::$name::Options>(stringify!($name), scale_lengths);
        }
    )*};
}

every_example!(survives_scaling_and_translation);
