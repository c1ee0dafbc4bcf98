//! Numerical stress: every example's scene, uniformly scaled and moved far from the origin (camera and
//! lights with it), must render the same picture as the canonical one.
//!
//! The scene is wrapped, node by node, in an extra transform (scale s, then translate by an offset); the
//! camera and the lights move with it, and the lights' intensities grow by s^2 so that the 1/d^2 falloff
//! gives the same irradiance. Pictures are 160 x 120 at one sample per pixel, so a change anywhere is not
//! averaged away.
//!
//! Rule: at most 0.5% of the pixels may differ by more than 8 levels. Acne (a surface shadowing itself) or
//! a light leak changes whole regions, far more than that; the last-ulp movement of silhouettes that f32
//! coordinates near 1e6 cause (their spacing there is 0.0625 scene units, a fifth of a pixel) stays under it.

mod common;

use lecture6::cli::Example;
use lecture6::compare::difference;
use lecture6::math::Vector;
use lecture6::render::{RenderSettings, render};
use lecture6::scene::Scene;

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

fn picture(scene: &Scene) -> image::RgbImage {
    let settings = RenderSettings { width: 160, height: 120, spp: 1, ..RenderSettings::default() };
    let (frame, _) = render(scene, &settings).expect("render");
    assert!(frame.pixels.iter().all(|c| c.is_finite()), "NaN or infinity in the frame");
    frame.to_rgb8()
}

fn check_scales_and_offsets<E: Example>() {
    let args = E::try_parse_from([E::NAME]).unwrap();
    let scene = args.build_scene().unwrap();
    let reference = picture(&scene);
    let cases = [(1e-4, 0.0), (1e-2, 0.0), (1e2, 0.0), (1e5, 0.0), (1.0, 1e6), (1.0, -1e6), (1e2, 1e6)];
    for (s, t) in cases {
        let moved = picture(&transformed(&scene, s, Vector::new(t, -t * 0.5, t * 0.25)));
        let d = difference(&moved, &reference).unwrap();
        assert!(d.large_pixels * 200 <= d.pixels, "{} scaled by {s:e}, moved by {t:e}: {d}", E::NAME);
    }
}

#[test]
fn bitmap_textures_survives_scaling_and_translation() {
    check_scales_and_offsets::<lecture6::scenes::bitmap_textures::Args>();
}
