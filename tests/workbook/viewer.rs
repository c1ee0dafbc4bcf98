//! The live viewer's parts that need no window (`cargo test --release --features viewer --test workbook viewer::`):
//! the controls generated from an example's command line, the moving camera, and the render thread, which
//! rebuilds the scene when an option changes and finishes on the picture the command line gives.

#![cfg(feature = "viewer")]

use crate::common;

use common::examples::{fresnel, glossy, scene_file};
use lecture6::Vector;
use lecture6::app::cli::{Cli, Example, controls as controls_of};
use lecture6::instruments::compare::difference;
use lecture6::instruments::progressive::{PREVIEW_PIXELS, preview_settings};
use lecture6::instruments::viewer::ExampleOptions;
use lecture6::instruments::viewer::controls::{Controls, Kind};
use lecture6::instruments::viewer::fly::{Motion, as_code, moved};
use lecture6::instruments::viewer::worker::{Job, Worker};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::{MAX_SPP, RenderSettings};
use std::ffi::OsString;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

fn os(args: &[&str]) -> Vec<OsString> {
    args.iter().map(OsString::from).collect()
}

/// The options the controls spell, read back as the window reads them.
fn parse<E: Example>(controls: &Controls) -> Result<Cli<E>, String> {
    Cli::<E>::from_controls(controls)
}

#[test]
fn every_option_becomes_a_control_of_its_kind() {
    let controls = controls_of::<fresnel::Options>("fresnel", &os(&["--ior", "2.4"])).unwrap();
    let control = |long: &str| controls.controls.iter().find(|c| c.long == long);
    let kind = |long: &str| control(long).map(|c| (c.kind.clone(), c.value.clone()));
    assert_eq!(kind("ior"), Some((Kind::Real, "2.4".into())));
    assert_eq!(kind("fresnel"), Some((Kind::Choice(vec!["schlick".into(), "exact".into()]), "schlick".into())));
    assert_eq!(kind("exhaustive"), Some((Kind::Flag, "false".into())));
    assert_eq!(kind("env").map(|k| k.0), Some(Kind::Text));
    // Whole numbers within the range their parser takes.
    let spp_range = Kind::Integer { min: 1.0, max: MAX_SPP as f64 };
    assert_eq!(kind("spp"), Some((spp_range, String::new())), "--spp not given: the example's default");
    assert_eq!(kind("width").map(|k| k.0), Some(Kind::Integer { min: 1.0, max: u32::MAX as f64 }));
    // --max-depth stops at the recursion's safety cap, where every ray stops anyway.
    let depth_range = Kind::Integer { min: 0.0, max: lecture6::lesson::scene::RECURSION_SAFETY_CAP as f64 };
    assert_eq!(kind("max-depth").map(|k| k.0), Some(depth_range));
    // An option without a default may stay empty, and says what empty means.
    let spp = control("spp").unwrap();
    assert!(spp.optional && spp.placeholder == fresnel::Options::DEFAULT_SPP.to_string(), "{spp:?}");
    let seed = control("seed").unwrap();
    assert!(!seed.optional && seed.value == "1", "{seed:?}");
    let spectral = control("spectral").unwrap();
    assert!(spectral.optional && spectral.value.is_empty() && matches!(spectral.kind, Kind::Choice(_)));
    assert_eq!(spectral.placeholder, "hero");
    for absent in ["window", "output", "help", "quiet", "compare", "trace-pixel", "view", "side-by-side", "threads"] {
        assert_eq!(kind(absent), None, "--{absent} is the window's, not a control");
    }
    let own = controls.controls.iter().position(|c| c.long == "ior").unwrap();
    assert!(controls.controls[own].heading.is_none() && controls.controls.iter().any(|c| c.heading.is_some()));
}

#[test]
fn empty_optional_controls_leave_the_defaults_and_negative_numbers_reach_their_checks() {
    let mut controls = controls_of::<fresnel::Options>("fresnel", &[]).unwrap();
    let cli: Cli<fresnel::Options> = parse(&controls).unwrap();
    assert_eq!((cli.common.spp, cli.common.wavelengths, cli.common.spectral), (None, None, None));
    assert_eq!(cli.prepare().unwrap().1.spp, fresnel::Options::DEFAULT_SPP);
    assert!(!controls.args().iter().any(|a| a == "--spp" || a == "--spectral"), "{:?}", controls.args());

    controls.get_mut("spp").unwrap().value = "9".into();
    assert_eq!(parse::<fresnel::Options>(&controls).unwrap().prepare().unwrap().1.spp, 9);
    controls.get_mut("spp").unwrap().value = "-1".into();
    let error = parse::<fresnel::Options>(&controls).unwrap_err();
    assert!(error.contains("-1") && error.contains("--spp"), "{error}");
    controls.get_mut("spp").unwrap().value.clear();
    controls.get_mut("ior").unwrap().value = "-1".into();
    let cli: Cli<fresnel::Options> = parse(&controls).unwrap();
    let error = cli.prepare().map(|_| ()).unwrap_err().to_string();
    assert!(error.contains("--ior") && error.contains("-1"), "{error}");
}

#[test]
fn controls_spell_the_command_line_they_came_from() {
    let given = ["--glossiness", "0.5", "--exhaustive", "--width", "200", "--seed", "7"];
    let controls = controls_of::<glossy::Options>("glossy", &os(&given)).unwrap();
    let from_controls: Cli<glossy::Options> = parse(&controls).unwrap();
    let direct: Cli<glossy::Options> = common::parse(&given);
    assert_eq!(format!("{from_controls:?}"), format!("{direct:?}"));
}

#[test]
fn a_changed_control_changes_the_options_and_a_bad_one_is_the_parsers_error() {
    let mut controls = controls_of::<fresnel::Options>("fresnel", &[]).unwrap();
    controls.get_mut("ior").unwrap().value = "2.42".into();
    controls.get_mut("exhaustive").unwrap().value = "true".into();
    controls.get_mut("fresnel").unwrap().value = "exact".into();
    let cli: Cli<fresnel::Options> = parse(&controls).unwrap();
    assert_eq!(cli.example.ior, 2.42);
    assert!(cli.common.exhaustive);
    assert_eq!(format!("{:?}", cli.example.fresnel), "Exact");
    controls.get_mut("width").unwrap().value = "wide".into();
    let error = parse::<fresnel::Options>(&controls).unwrap_err();
    assert!(error.contains("wide") && error.contains("--width"), "{error}");
}

#[test]
fn the_camera_moves_along_its_own_axes() {
    let camera = Camera { position: Vector::new(1.0, 2.0, 3.0), yaw: 90.0, ..Camera::default() };
    // Yaw 90 turns the view from +Z to -X.
    let forward = moved(&camera, &Motion { forward: 1.0, ..Motion::default() }, 10.0);
    assert!((forward.position - Vector::new(-9.0, 2.0, 3.0)).length() < 1e-4, "{:?}", forward.position);
    let right = moved(&camera, &Motion { right: 1.0, ..Motion::default() }, 2.0);
    assert!((right.position - Vector::new(1.0, 2.0, 5.0)).length() < 1e-4, "{:?}", right.position);
    let turned = moved(&camera, &Motion { yaw: 100.0, pitch: 120.0, ..Motion::default() }, 1.0);
    assert_eq!((turned.yaw, turned.pitch, turned.position), (-170.0, 89.0, camera.position));
    assert!(Motion::default().is_still() && !Motion { roll: 1.0, ..Motion::default() }.is_still());
    let code = as_code(&camera);
    assert!(code.contains("Vector::new(1.00, 2.00, 3.00)") && code.contains("yaw: 90.0"), "{code}");
}

#[test]
fn the_moving_preview_is_at_most_320_by_240() {
    let at = |width, height| {
        let s = preview_settings(&RenderSettings { width, height, spp: 9, ..RenderSettings::default() });
        (s.width, s.height, s.spp)
    };
    assert_eq!(at(640, 480), (320, 240, 1));
    assert_eq!(at(320, 240), (320, 240, 1));
    assert_eq!(at(1920, 1080), (320, 180, 1));
    let (w, h, _) = at(1001, 999);
    assert!(w * h <= PREVIEW_PIXELS && w * h > PREVIEW_PIXELS / 2);
}

/// Waits until the render thread has finished a picture, and takes it.
fn finished(worker: &Worker) -> Frame {
    let start = Instant::now();
    loop {
        if let Some((frame, _)) = worker.shown.lock().unwrap().finished.take() {
            return frame;
        }
        assert!(start.elapsed() < Duration::from_secs(120), "the render thread finished nothing");
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn job<E: Example>(cli: &Cli<E>, camera: Option<Camera>, rebuild: bool) -> Job {
    let build = cli.clone();
    Job {
        rebuild: rebuild.then(|| Box::new(move || build.prepare()) as _),
        camera,
        film: cli.film(),
        preview: false,
        cancel: Arc::new(AtomicBool::new(false)),
    }
}

#[test]
fn the_render_thread_rebuilds_the_scene_for_new_options_and_ends_on_the_plain_render() {
    let mut worker = Worker::start(Some(2), || {}).unwrap();
    let small = ["--width", "64", "--height", "48", "--spp", "2"];
    let first: Cli<fresnel::Options> = common::parse(&small);
    worker.submit(job(&first, None, true));
    assert!(finished(&worker) == first.render().unwrap().0);

    // A new IOR: the scene is built again.
    let mut args = small.to_vec();
    args.extend(["--ior", "2.4"]);
    let second: Cli<fresnel::Options> = common::parse(&args);
    worker.submit(job(&second, None, true));
    let frame = finished(&worker);
    assert!(frame == second.render().unwrap().0, "the picture of the new options");
    let change = difference(&frame.to_rgb8(), &first.render().unwrap().0.to_rgb8()).unwrap();
    assert!(change.large_pixels * 50 > change.pixels, "the glass of the new IOR looks the same: {change}");

    // A moved camera keeps the scene (the job does not rebuild it).
    let camera = Camera { position: Vector::new(0.0, 60.0, -100.0), pitch: -35.0, fov: 90.0, ..Camera::default() };
    worker.submit(job(&second, Some(camera), false));
    let moved = finished(&worker);
    let (mut scene, settings) = second.prepare().unwrap();
    scene.camera = camera;
    assert!(moved == lecture6::lesson::render::render(&scene, &settings).unwrap().0);
}

#[test]
fn the_window_shows_the_picture_exposed_and_tone_mapped_as_the_options_say() {
    let mut worker = Worker::start(Some(2), || {}).unwrap();
    let args = ["--width", "64", "--height", "48", "--spp", "1", "--exposure", "-1", "--tonemap", "reinhard"];
    let cli: Cli<fresnel::Options> = common::parse(&args);
    worker.submit(job(&cli, None, true));
    let frame = finished(&worker);
    let shown = worker.shown.lock().unwrap().rgb.clone();
    assert_eq!(shown, cli.film().develop(frame.clone(), false).to_rgb8().into_raw(), "the picture a PNG would hold");
    // Exposure -1 and Reinhard both darken: the window shows less light than the raw frame would.
    let sum = |bytes: &[u8]| bytes.iter().map(|&b| b as u64).sum::<u64>();
    assert!(sum(&shown) < sum(&frame.to_rgb8().into_raw()), "the window ignored the exposure");
}

#[test]
fn the_render_thread_takes_the_frame_size_a_scene_file_sets() {
    // The fresnel scene file at its own small size, from a folder as deep as its own (its textures are
    // named relative to it).
    let text = std::fs::read_to_string(common::root().join("examples/data/fresnel.qdmg")).unwrap();
    let small = format!("{text}\nGlobalSettings {{\n frameWidth 40\n frameHeight 30\n}}\n");
    let path = common::temp_file("viewer-tests", "small.qdmg", &small);
    // No --spp: the file's own anti-aliasing.
    let cli: Cli<scene_file::Options> = common::parse(&[path.to_str().unwrap(), "--quiet"]);
    let mut worker = Worker::start(Some(2), || {}).unwrap();
    worker.submit(job(&cli, None, true));
    let frame = finished(&worker);
    assert_eq!((frame.width, frame.height), (40, 30));
    assert!(frame == cli.render().unwrap().0, "the picture the command line gives");
    let settings = worker.shown.lock().unwrap().settings.unwrap();
    assert!((settings.width, settings.height) == (40, 30) && settings.adaptive_aa, "{settings:?}");
}
