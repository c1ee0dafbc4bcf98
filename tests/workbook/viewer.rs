//! The live viewer's parts that need no window (`cargo test --release --test workbook viewer::`): the
//! controls generated from an example's command line, the steps beyond the slides as check boxes, the
//! moving camera, the render thread, which rebuilds the scene when an option changes and finishes on the
//! picture the command line gives, and the example's side of the window, driven request by request as the
//! window drives it, through the pipe's encoding.

use crate::common;

use common::examples::{
    bitmap_textures, dispersion, environment, fresnel, glossy, layered, model_transform, photon_map, scene_file,
};
use lecture6::Vector;
use lecture6::app::cli::{Cli, Example, controls as controls_of};
use lecture6::instruments::compare::difference;
use lecture6::instruments::progressive::{PREVIEW_PIXELS, preview_settings};
use lecture6::instruments::viewer::ExampleOptions;
use lecture6::instruments::viewer::controls::{Controls, Kind, steps_args};
use lecture6::instruments::viewer::fly::{Motion, as_code, moved};
use lecture6::instruments::viewer::session::Session;
use lecture6::instruments::viewer::wire::{Report, Request, Status, receive, send};
use lecture6::instruments::viewer::worker::{Job, Worker};
use lecture6::lesson::beyond::{Step, Steps};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::{MAX_SPP, RenderSettings};
use std::ffi::OsString;
use std::path::Path;
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
    assert_eq!(kind("adaptive-aa"), Some((Kind::Flag, "false".into())));
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
    // The steps beyond the slides are check boxes of their own.
    for spelled in ["slide", "step", "no-step", "exhaustive"] {
        assert_eq!(kind(spelled), None, "--{spelled} is spelled by the step boxes");
    }
    let names: Vec<&str> = controls.steps.iter().map(|step| step.name.as_str()).collect();
    assert_eq!(names, Step::ALL.map(Step::name), "a box per step");
    assert!(controls.steps.iter().all(|step| step.taken), "the default takes every step");
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
    let given = ["--glossiness", "0.5", "--width", "200", "--seed", "7", "-o", "target/viewer-tests/g.png"];
    let controls = controls_of::<glossy::Options>("glossy", &os(&given)).unwrap();
    let from_controls: Cli<glossy::Options> = parse(&controls).unwrap();
    let direct: Cli<glossy::Options> = common::parse(&given);
    assert_eq!(format!("{from_controls:?}"), format!("{direct:?}"));
    // The steps, however they were spelled, are the same set.
    for given in [&["--exhaustive"][..], &["--slide", "--step", "disc-samples"], &["--no-step", "node-bvh", "--slide"]]
    {
        let controls = controls_of::<glossy::Options>("glossy", &os(given)).unwrap();
        let steps = common::parse::<glossy::Options>(given).steps();
        let ticked: Vec<bool> = controls.steps.iter().map(|step| step.taken).collect();
        assert_eq!(ticked, Step::ALL.map(|step| steps.has(step)), "{given:?}");
        assert_eq!(parse::<glossy::Options>(&controls).unwrap().steps(), steps, "{given:?}: {:?}", controls.args());
    }
}

/// `--slide` clears every step's box and unticking it ticks them all again; each step's box alone gives the
/// steps the command line gives for it: `--no-step NAME` from the default, `--slide --step NAME` from the
/// slides' reading.
#[test]
fn the_step_boxes_spell_the_steps_the_command_line_gives() {
    let mut controls = controls_of::<fresnel::Options>("fresnel", &[]).unwrap();
    let steps_of = |controls: &Controls| parse::<fresnel::Options>(controls).unwrap().steps();
    assert!(!controls.slide() && steps_of(&controls) == Steps::ALL && steps_args(&controls.steps).is_empty());
    controls.set_slide(true);
    assert!(controls.slide() && controls.steps.iter().all(|step| !step.taken));
    assert_eq!(steps_of(&controls), common::parse::<fresnel::Options>(&["--slide"]).steps());
    controls.set_slide(false);
    assert_eq!(steps_of(&controls), Steps::ALL);
    for step in Step::ALL {
        let mut off = controls.clone();
        assert!(off.set_step(step.name(), false));
        assert_eq!(steps_of(&off), common::parse::<fresnel::Options>(&["--no-step", step.name()]).steps());
        assert_eq!(steps_of(&off), Steps::ALL.without(step), "{:?}", off.args());
        let mut on = controls.clone();
        on.set_slide(true);
        on.set_step(step.name(), true);
        assert_eq!(steps_of(&on), common::parse::<fresnel::Options>(&["--slide", "--step", step.name()]).steps());
        assert_eq!(steps_of(&on), Steps::SLIDES.with(step), "{:?}", on.args());
        assert!(!on.slide(), "a step ticked: not the slides' reading");
    }
}

#[test]
fn a_changed_control_changes_the_options_and_a_bad_one_is_the_parsers_error() {
    let mut controls = controls_of::<fresnel::Options>("fresnel", &[]).unwrap();
    controls.get_mut("ior").unwrap().value = "2.42".into();
    controls.set_step(Step::AdaptiveDepth.name(), false);
    controls.get_mut("fresnel").unwrap().value = "exact".into();
    let cli: Cli<fresnel::Options> = parse(&controls).unwrap();
    assert_eq!(cli.example.ior, 2.42);
    assert_eq!(cli.steps(), common::parse::<fresnel::Options>(&["--exhaustive"]).steps());
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

/// What the window knows: what the example's reports said, each through the pipe's encoding.
#[derive(Default)]
struct Window {
    width: u32,
    height: u32,
    rgb: Vec<u8>,
    status: Status,
    messages: Vec<String>,
    picked: Option<(u32, u32, String, String)>,
}

impl Window {
    fn take(&mut self, report: Report) {
        let mut pipe = Vec::new();
        send(&mut pipe, &report).unwrap();
        match receive(&mut pipe.as_slice()).unwrap() {
            Report::Pixels { width, height, x, y, w, h, rgb } => {
                if (self.width, self.height) != (width, height) {
                    (self.width, self.height, self.rgb) = (width, height, vec![0; (width * height * 3) as usize]);
                }
                for (row, pixels) in rgb.chunks(w as usize * 3).enumerate() {
                    let start = ((y as usize + row) * width as usize + x as usize) * 3;
                    self.rgb[start..start + pixels.len()].copy_from_slice(pixels);
                }
                assert_eq!(rgb.len(), (w * h * 3) as usize);
            }
            Report::Status { status } => self.status = status,
            Report::Message { text } => self.messages.push(text),
            Report::Picked { x, y, sees, tree } => self.picked = Some((x, y, sees, tree)),
            other => panic!("unexpected: {other:?}"),
        }
    }

    /// Answers `request` as the example does, and takes in the answer.
    fn ask<O: ExampleOptions>(&mut self, session: &mut Session<O>, request: Request) {
        let mut pipe = Vec::new();
        send(&mut pipe, &request).unwrap();
        session.handle(receive(&mut pipe.as_slice()).unwrap()).into_iter().for_each(|r| self.take(r));
    }

    /// Takes in what the example draws until its picture is finished.
    fn until_finished<O: ExampleOptions>(&mut self, session: &mut Session<O>) {
        let start = Instant::now();
        loop {
            session.painted().into_iter().for_each(|r| self.take(r));
            if self.status.finished {
                return;
            }
            assert!(self.status.error.is_none(), "{:?}", self.status.error);
            assert!(start.elapsed() < Duration::from_secs(300), "the window's picture did not finish");
            std::thread::sleep(Duration::from_millis(10));
        }
    }
}

/// What the window's check boxes change, from the reading it opened on.
#[derive(Clone, Copy, Debug)]
enum Toggle {
    /// `--slide` ticked.
    Slide,
    /// One step's box cleared.
    Off(Step),
}

/// The example `name` opened in the window with small options, then `toggle`d there: the window's
/// picture, its ray count, its scene's steps and the PNG "Save" writes are those of the example run from the
/// command line with the options the toggle stands for.
fn window_renders_as_the_command_line<E: Example>(name: &str, toggle: Toggle, own: &[&str]) {
    let dir = Path::new("target/viewer-tests/toggles");
    std::fs::create_dir_all(dir).unwrap();
    let file = |who: &str| dir.join(format!("{name}-{toggle:?}-{who}.png"));
    let window_png = file("window");
    let _ = std::fs::remove_file(&window_png);
    let small = ["--width", "40", "--height", "30", "--spp", "2"];
    let base: Vec<&str> = small.iter().chain(own).copied().collect();
    let mut opened = base.clone();
    opened.extend(["-o", window_png.to_str().unwrap()]);
    let mut controls = controls_of::<E>(name, &os(&opened)).unwrap();
    let options: Cli<E> = parse(&controls).unwrap();
    let mut session = Session::new(name, options, || {}).unwrap();
    let mut window = Window::default();
    let toggled: Vec<&str> = match toggle {
        Toggle::Slide => {
            controls.set_slide(true);
            vec!["--slide"]
        }
        Toggle::Off(step) => {
            controls.set_step(step.name(), false);
            vec!["--no-step", step.name()]
        }
    };
    window.ask(&mut session, Request::Options { controls });
    assert_eq!(window.messages, [""], "{name} {toggle:?}: the options were refused");
    window.until_finished(&mut session);

    let command: Vec<&str> = base.iter().chain(&toggled).copied().collect();
    let cli = common::parse::<E>(&command);
    let (_, stats) = cli.render().unwrap();
    let cli_png = file("command-line");
    let mut args = command.clone();
    args.extend(["-q", "-o", cli_png.to_str().unwrap()]);
    let out = common::run_example(name, &args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    let written = std::fs::read(common::root().join(&cli_png)).unwrap();

    let what = format!("{name} {toggle:?}, against {args:?}");
    let shown_steps = session.worker.shown.lock().unwrap().scene.as_ref().map(|s| s.steps);
    assert_eq!(shown_steps, Some(cli.steps()), "{what}: the steps rendered");
    assert_eq!(window.status.rays, stats.counters.total(), "{what}: the status line's rays");
    let expected = image::load_from_memory(&written).unwrap().to_rgb8();
    assert_eq!((window.width, window.height), expected.dimensions(), "{what}");
    assert!(window.rgb == expected.as_raw().as_slice(), "{what}: the window's picture differs");
    window.ask(&mut session, Request::Save { ext: "png".into() });
    assert!(window.messages.last().unwrap().starts_with("saved"), "{what}: {:?}", window.messages);
    assert!(std::fs::read(&window_png).unwrap() == written, "{what}: \"Save .png\" wrote another picture");
}

/// `--slide` and each step beyond the slides, toggled alone in the window, render what the command line
/// renders with the same options: the same picture, pixel for pixel, the same rays, the same saved PNG.
/// Each step in an example where it does something.
#[test]
fn each_step_toggled_in_the_window_renders_as_the_command_line() {
    use Toggle::*;
    window_renders_as_the_command_line::<fresnel::Options>("fresnel", Slide, &[]);
    window_renders_as_the_command_line::<fresnel::Options>("fresnel", Off(Step::AdaptiveDepth), &[]);
    window_renders_as_the_command_line::<fresnel::Options>("fresnel", Off(Step::TwoPhaseHit), &[]);
    window_renders_as_the_command_line::<scene_file::Options>("scene_file", Off(Step::NodeTree), &[]);
    window_renders_as_the_command_line::<model_transform::Options>("model_transform", Off(Step::MeshBvh), &[]);
    window_renders_as_the_command_line::<bitmap_textures::Options>("bitmap_textures", Off(Step::TexelFilter), &[]);
    window_renders_as_the_command_line::<glossy::Options>("glossy", Off(Step::StratifiedAa), &[]);
    window_renders_as_the_command_line::<glossy::Options>("glossy", Off(Step::DiscSamples), &[]);
    window_renders_as_the_command_line::<dispersion::Options>("dispersion", Off(Step::HeroWavelengths), &[]);
    let photons = ["--photons", "5000"];
    window_renders_as_the_command_line::<photon_map::Options>("photon_map", Off(Step::PhotonGrid), &photons);
    window_renders_as_the_command_line::<photon_map::Options>("photon_map", Slide, &photons);
    window_renders_as_the_command_line::<layered::Options>("layered", Off(Step::LayerPruning), &[]);
    window_renders_as_the_command_line::<environment::Options>("environment", Off(Step::CameraRelative), &[]);
}

/// Toggling a step in the window changes what it renders: the slides' reading of fresnel traces every ray
/// to the full depth, the default prunes the weak ones. "Save" and "Compare" wait for the new picture.
#[test]
fn a_toggled_step_changes_the_rays_and_save_waits_for_its_picture() {
    // Large enough that the slides' reading takes a while: it is asked about before it can finish.
    let small = ["--width", "320", "--height", "240", "--spp", "4"];
    let mut controls = controls_of::<fresnel::Options>("fresnel", &os(&small)).unwrap();
    let mut session = Session::new("fresnel", parse::<fresnel::Options>(&controls).unwrap(), || {}).unwrap();
    let mut window = Window::default();
    window.until_finished(&mut session);
    let default_rays = window.status.rays;
    controls.set_slide(true);
    window.ask(&mut session, Request::Options { controls });
    let waiting = session.painted().into_iter().find_map(|r| match r {
        Report::Status { status } => Some(status.finished),
        _ => None,
    });
    assert_eq!(waiting, Some(false), "the default reading's picture still counts as the one shown");
    window.ask(&mut session, Request::Save { ext: "png".into() });
    assert_eq!(window.messages.last().map(String::as_str), Some("the picture is not finished yet"));
    window.until_finished(&mut session);
    assert!(window.status.rays > default_rays, "--slide: {} rays, the default {default_rays}", window.status.rays);
}

/// A pixel asked about before the scene is built (`--window --trace-pixel X,Y`) is answered once it is.
#[test]
fn a_pixel_asked_about_at_once_gets_its_tree_once_the_scene_is_built() {
    let args = ["--width", "40", "--height", "30", "--spp", "1", "--slide", "--trace-pixel", "20,15"];
    let cli: Cli<fresnel::Options> = common::parse(&args);
    assert_eq!(cli.pixel(), Some((20, 15)));
    let mut session = Session::new("fresnel", cli, || {}).unwrap();
    let mut window = Window::default();
    window.ask(&mut session, Request::Inspect { x: 20, y: 15 });
    window.until_finished(&mut session);
    session.painted().into_iter().for_each(|r| window.take(r));
    let (x, y, sees, tree) = window.picked.expect("the pixel's tree");
    assert_eq!((x, y), (20, 15));
    assert!(sees.contains("sees node") || sees.contains("sees nothing"), "{sees}");
    assert!(!tree.is_empty());
}

/// The window sends how the keys and the mouse move the camera; the example moves it as [`moved`] does,
/// and shows where it is and the code that builds it.
#[test]
fn the_window_moves_the_examples_camera() {
    let cli: Cli<fresnel::Options> = common::parse(&["--width", "40", "--height", "30", "--spp", "1"]);
    let scene_camera = cli.prepare().unwrap().0.camera;
    let mut session = Session::new("fresnel", cli, || {}).unwrap();
    let mut window = Window::default();
    window.until_finished(&mut session);
    assert_eq!(window.status.camera.as_ref().map(|c| c.code.clone()), Some(as_code(&scene_camera)));
    let motion = Motion { forward: 0.5, yaw: 10.0, ..Motion::default() };
    let Motion { forward, right, up, yaw, pitch, roll } = motion;
    window.ask(&mut session, Request::Move { forward, right, up, yaw, pitch, roll, distance: 20.0 });
    window.ask(&mut session, Request::Settle {});
    window.until_finished(&mut session);
    let expected = moved(&scene_camera, &motion, 20.0);
    assert_eq!(window.status.camera.as_ref().map(|c| c.code.clone()), Some(as_code(&expected)));
    window.ask(&mut session, Request::ResetCamera {});
    window.until_finished(&mut session);
    assert_eq!(window.status.camera.map(|c| c.code), Some(as_code(&scene_camera)));
}
