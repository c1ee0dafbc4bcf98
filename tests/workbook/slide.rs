//! `--slide`, the slides' reading (every step beyond the slides left out, src/lesson/beyond.rs): every example
//! renders through it, and its picture is
//! close to the default one: at 160x120 and the example's own spp, a PSNR of at least 24 dB against the
//! default picture (or, where the default picture is noisier than that from one seed to another, at most
//! 2 dB below that seed-to-seed PSNR), and a mean brightness within 5%. docs/beyond-the-slides.md says why
//! the two readings differ where they do.

use crate::common::{examples, parse, render, root, run_example};
use lecture6::app::cli::Example;
use lecture6::instruments::compare::difference;
use lecture6::lesson::beyond::Steps;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::RenderSettings;

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

/// `--slide` traces every ray to the depth limit, as `--exhaustive` does: a depth above 64 is refused with
/// exit 2 for both, given on the command line or by a scene file's `maxTraceDepth` (named with its line).
#[test]
fn slide_refuses_a_depth_that_would_never_end_as_exhaustive_does() {
    for reading in ["--slide", "--exhaustive"] {
        let output = run_example("fresnel", &[&SIZE[..], &[reading, "-q", "--max-depth", "1000"]].concat());
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{reading}: {stderr}");
        assert!(stderr.contains("--max-depth") && stderr.contains("at most 64"), "{reading}: {stderr}");
    }
    let dir = root().join("target").join("slide");
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(root().join("examples/data/fresnel.qdmg")).unwrap();
    let deep = text.replacen("maxTraceDepth  10\n", "maxTraceDepth  100\n", 1);
    assert_ne!(deep, text, "the bundled scene has its GlobalSettings block");
    let file = dir.join("deep.qdmg");
    std::fs::write(&file, deep).unwrap();
    for reading in ["--slide", "--exhaustive"] {
        let output =
            run_example("scene_file", &[file.to_str().unwrap(), "--width", "32", "--height", "24", reading, "-q"]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{reading}: {stderr}");
        assert!(
            stderr.contains("line 9") && stderr.contains("maxTraceDepth") && stderr.contains("at most 64"),
            "{stderr}"
        );
    }
    let output = run_example(
        "scene_file",
        &[
            file.to_str().unwrap(),
            "--width",
            "32",
            "--height",
            "24",
            "-q",
            "-o",
            dir.join("deep.png").to_str().unwrap(),
        ],
    );
    assert!(output.status.success(), "by default the depth is pruned: {}", String::from_utf8_lossy(&output.stderr));
}

/// The progress line counts the slides' reading's samples as it counts the default's: one renderer, one
/// loop (the command line draws it on a terminal).
#[test]
fn slide_reports_its_progress() {
    use lecture6::lesson::render::{Progress, render_with_progress};
    use std::sync::atomic::{AtomicU64, Ordering};
    #[derive(Default)]
    struct Count {
        total: AtomicU64,
        done: AtomicU64,
    }
    impl Progress for Count {
        fn begin(&self, samples: u64) {
            self.total.store(samples, Ordering::Relaxed);
        }
        fn advance(&self, samples: u64) {
            self.done.fetch_add(samples, Ordering::Relaxed);
        }
        fn end(&self) {}
    }
    let (scene, settings) = parse::<examples::fresnel::Options>(&[&SIZE[..], &["--slide"]].concat()).prepare().unwrap();
    assert_eq!(scene.steps, Steps::SLIDES);
    let count = Count::default();
    render_with_progress(&scene, &settings, Some(&count)).unwrap();
    let expected = 160 * 120 * settings.spp as u64;
    assert_eq!((count.total.into_inner(), count.done.into_inner()), (expected, expected));
}

/// A student's shader that wraps one of the course's follows the reading: under `--slide` the wrapped
/// Lambert of a bitmap texture reads one texel, as the Lambert itself does, and so differs from its default
/// picture.
#[test]
fn a_course_shader_wrapped_by_a_students_follows_slide() {
    use lecture6::prelude::*;
    struct Wrapper(Lambert);
    impl Shader for Wrapper {
        fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
            self.0.shade(ray, info, ctx)
        }
    }
    let floor = || Lambert::new(workbook::texture("floor_tiles.png").unwrap().with_tile_size(40.0));
    let scene = |shader: Arc<dyn Shader>, steps: Steps| {
        let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 30.0, -60.0), Vector::ZERO, 60.0));
        scene.add(Node::new(Plane::new(0.0, 200.0), shader));
        scene.lights.push(PointLight::new(Vector::new(0.0, 100.0, -50.0), Color::WHITE, 20000.0));
        scene.steps = steps;
        scene
    };
    let settings = RenderSettings { width: 64, height: 48, spp: 1, ..RenderSettings::default() };
    let picture = |shader: Arc<dyn Shader>, steps| {
        lecture6::lesson::render::render(&scene(shader, steps), &settings).unwrap().0.to_rgb8()
    };
    let wrapped = picture(Arc::new(Wrapper(floor())), Steps::SLIDES);
    assert!(wrapped == picture(Arc::new(floor()), Steps::SLIDES), "the wrapped Lambert ignores --slide");
    assert!(wrapped != picture(Arc::new(Wrapper(floor())), Steps::ALL), "one texel and bilinear agree: no test");
}
