//! `--slide`, the slides' reading (every step beyond the slides left out, src/lesson/beyond.rs): every example
//! renders through it, and its picture is
//! close to the default one: at 160x120 and the example's own spp, a PSNR of at least 24 dB against the
//! default picture (or, where the default picture is noisier than that from one seed to another, at most
//! 2 dB below that seed-to-seed PSNR), and a mean brightness within 5%. docs/beyond-the-slides.md says why
//! the two readings differ where they do.

use crate::common::{examples, render, root, run_example};
use lecture6::app::cli::Example;
use lecture6::instruments::compare::difference;
use lecture6::lesson::frame::Frame;

const SIZE: [&str; 4] = ["--width", "160", "--height", "120"];

/// The mean of every channel of every pixel, in linear light.
fn mean(frame: &Frame) -> f64 {
    let sum: f64 = frame.pixels.iter().map(|c| c.to_array().iter().map(|&v| v as f64).sum::<f64>()).sum();
    sum / (3 * frame.pixels.len()) as f64
}

fn check<E: Example>(name: &str) {
    let with = |extra: &[&str]| render::<E>(&[&SIZE[..], extra].concat());
    let (default, slide, other_seed) = (with(&[]), with(&["--slide"]), with(&["--seed", "2"]));
    let d = difference(&slide.to_rgb8(), &default.to_rgb8()).unwrap();
    let noise = difference(&other_seed.to_rgb8(), &default.to_rgb8()).unwrap();
    let floor = if noise.psnr < 24.0 { noise.psnr - 2.0 } else { 24.0 };
    assert!(
        d.psnr >= floor,
        "{name}: --slide against the default: PSNR {:.2} dB, below {floor:.2} dB (seed against seed {:.2} dB)",
        d.psnr,
        noise.psnr
    );
    let (m_default, m_slide) = (mean(&default), mean(&slide));
    assert!(
        (m_slide - m_default).abs() <= 0.05 * m_default,
        "{name}: mean {m_slide:.5} with --slide, {m_default:.5} by default: more than 5% apart"
    );
}

macro_rules! slide_tests {
    ($($name:ident),*) => {
        $(
            #[test]
            fn $name() {
                check::<examples::$name::Options>(stringify!($name));
            }
        )*
    };
}

every_example!(slide_tests);

/// A student's homework, the API page's (docs/homework_scene.rs, with a shader of the student's own, which
/// the slides' reading shades through its `shade` and whose rays go through the slides' `raytrace`), renders
/// with `--slide` as close to its default picture as the examples do.
#[test]
fn a_students_homework_renders_with_slide() {
    check::<crate::homework::homework_scene::Options>("homework");
}

/// A student's copy of an example takes `--slide` too, and `--side-by-side "--slide"` puts the two readings
/// side by side.
#[test]
fn a_copy_renders_with_slide_and_side_by_side() {
    let out = root().join("target").join("slide");
    let picture = out.join("fresnel-side-by-side.png");
    let output =
        run_example("fresnel", &[&SIZE[..], &["--side-by-side", "--slide", "-o", picture.to_str().unwrap()]].concat());
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("PSNR"), "no comparison printed: {stdout}");
    let image = image::open(&picture).unwrap();
    assert_eq!(image.width(), 3 * 160, "A | B | difference");
}

/// One renderer serves both readings: the instruments that watch it work under `--slide` too, and a choice
/// that needs a step `--slide` leaves out is refused, naming the option and the step.
#[test]
fn the_instruments_work_in_the_slides_reading() {
    for args in [&["--trace-pixel", "10,10"][..], &["--view", "normals"], &["--spp", "1", "--adaptive-aa"]] {
        let out = root().join("target").join("slide").join("instrument.png");
        let output =
            run_example("fresnel", &[&SIZE[..], &["--slide", "-q", "-o", out.to_str().unwrap()], args].concat());
        assert!(output.status.success(), "{args:?}: {}", String::from_utf8_lossy(&output.stderr));
    }
    let output = run_example("dispersion", &[&SIZE[..], &["--slide", "-q", "--spectral", "hero"]].concat());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--spectral") && stderr.contains("hero-wavelengths"), "{stderr}");
}
