//! What a student starting a homework relies on: a copy of an example is an example of its own (its
//! output named after it, the same picture), `cargo run` alone lists the examples instead of rewriting
//! `textures/`, a shader of the student's own gets the caustics through the light loop, and
//! `Camera::look_at` frames what it is told to.

use crate::common;

use common::{example_binary, root};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::prelude::*;
use std::process::Command;

/// A scratch folder of its own for each test, emptied first.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = root().join("target").join("homework-test").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_copied_example_writes_its_own_picture_and_the_same_one() {
    // `cp examples/fresnel.rs examples/hw1.rs` builds a binary called hw1 from the same source: the same
    // binary under another name is what that gives.
    let dir = scratch("copy");
    let hw1 = dir.join(format!("hw1{}", std::env::consts::EXE_SUFFIX));
    // A hard link where the file system allows it: a copy is written through a file descriptor that a test
    // starting a process at the same moment may inherit until its exec, and running the copy then fails
    // with "Text file busy" (ETXTBSY), so after a copy the run is tried again while that lasts.
    if std::fs::hard_link(example_binary("fresnel"), &hw1).is_err() {
        std::fs::copy(example_binary("fresnel"), &hw1).unwrap();
    }
    let small = ["--width", "64", "--height", "48", "--spp", "1"];
    let run = || Command::new(&hw1).args(small).current_dir(&dir).output();
    let mut out = run();
    for _ in 0..100 {
        match &out {
            Err(e) if e.kind() == std::io::ErrorKind::ExecutableFileBusy => {
                std::thread::sleep(std::time::Duration::from_millis(20));
                out = run();
            }
            _ => break,
        }
    }
    let out = out.unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let summary = String::from_utf8_lossy(&out.stdout);
    assert!(summary.starts_with("hw1: 64x48"), "the summary names the copy: {summary}");
    let copy = image::open(dir.join("out").join("hw1.png")).expect("the copy writes out/hw1.png").to_rgb8();
    let original = common::render::<common::examples::fresnel::Options>(&small).to_rgb8();
    assert!(copy == original, "the copy renders another picture");
}

#[test]
fn cargo_run_alone_lists_the_examples_and_writes_nothing() {
    let dir = scratch("list");
    let out = Command::new(env!("CARGO_BIN_EXE_lecture6")).current_dir(&dir).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    macro_rules! listed {
        ($($name:ident),*) => {$(
            assert!(text.contains(stringify!($name)), "{} is not listed:\n{text}", stringify!($name));
        )*};
    }
    every_example!(listed);
    assert!(text.contains("cargo run --release --example"), "{text}");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0, "cargo run wrote files");
}

/// A diffuse shader as a student would write it: white, lit through the light loop, nothing else (`shade`
/// alone: the photons land on it by default).
struct Chalk;

impl Shader for Chalk {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        diffuse_light(ctx, info, faceforward(info.normal, ray.dir))
    }
}

/// A glass ball over a floor of `floor`, lit from straight above; the photon map's caustic lies under it.
fn caustic_scene(floor: impl Shader + 'static) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 30.0, -30.0), Vector::ZERO, 60.0));
    scene.lights.push(PointLight::new(Vector::new(0.0, 60.0, 0.0), Color::WHITE, 3600.0));
    scene.add(Node::new(Plane::new(0.0, 50.0), floor));
    scene.add(Node::new(Sphere::new(Vector::new(0.0, 10.0, 0.0), 5.0), fresnel_glass(1.5, FresnelMode::Schlick, 1.0)));
    scene.photons = PhotonSettings { count: 50_000, k: 50, max_radius: Some(1.0), show: false };
    scene
}

#[test]
fn a_students_diffuse_shader_gets_the_caustics_through_the_light_loop() {
    let under_the_ball = |floor: Box<dyn Fn() -> Scene>| {
        let mut scene = floor();
        scene.photon_map = lecture6::lesson::photon_map::PhotonMap::build(&scene, 1).unwrap().map(Arc::new);
        let map = scene.photon_map.clone().expect("the glass is a caustic caster");
        let ray = Ray::new(Vector::new(0.0, 1.0, 0.0), Vector::new(0.0, -1.0, 0.0));
        let (info, node) = scene.closest_hit(&ray).expect("the floor");
        let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[1]));
        (node.shader.shade(&ray, &info, &mut ctx), map.irradiance(info.ip, Vector::Y))
    };
    let (chalk, caustic) = under_the_ball(Box::new(|| caustic_scene(Chalk)));
    assert!(caustic.max_channel() > 1.0, "the test needs a caustic under the ball: {caustic:?}");
    // Under the ball the lamp is in the ball's shadow: what the chalk shows is the caustic light.
    assert!((chalk.max_channel() - caustic.max_channel()).abs() < 1e-3 * caustic.max_channel(), "{chalk:?}");
    let (lambert, _) = under_the_ball(Box::new(|| caustic_scene(Lambert::new(Color::WHITE))));
    assert_eq!(chalk, lambert, "a white Lambert floor shows the same light");
}

#[test]
fn a_shader_with_only_shade_renders_in_a_scene_with_a_photon_map() {
    let mut scene = caustic_scene(Chalk);
    scene.photon_map = lecture6::lesson::photon_map::PhotonMap::build(&scene, 1).unwrap().map(Arc::new);
    assert!(scene.photon_map.as_ref().is_some_and(|m| !m.photons().is_empty()), "photons landed on the chalk");
    let settings = RenderSettings { width: 64, height: 48, ..Default::default() };
    let (frame, stats) = render(&scene, &settings).unwrap();
    assert_eq!(stats.counters.non_finite_samples, 0);
    // The caustic under the ball is brighter than the floor beside the ball's shadow.
    let brightest = frame.pixels.iter().map(|c| c.max_channel()).fold(0.0, f32::max);
    assert!(brightest > 0.5, "the floor is lit: {brightest}");
}

#[test]
fn look_at_points_the_centre_of_the_picture_at_the_target() {
    let targets = [
        (Vector::new(0.0, 60.0, -120.0), Vector::new(0.0, 30.0, -30.0)),
        (Vector::new(5.0, -3.0, 2.0), Vector::new(-40.0, 7.0, -9.0)),
    ];
    for (from, to) in targets {
        let camera = Camera::look_at(from, to, 70.0);
        let ray = camera.frame(640, 480).get_screen_ray(320.0, 240.0);
        let expected = (to - from).normalize();
        assert!(ray.dir.dot(expected) > 1.0 - 1e-6, "{from} -> {to}: the centre ray goes {}", ray.dir);
        // Upright: the top of the picture is above its bottom.
        let (top, bottom) =
            (camera.frame(640, 480).get_screen_ray(320.0, 0.0), camera.frame(640, 480).get_screen_ray(320.0, 480.0));
        assert!(top.dir.y > bottom.dir.y);
    }
}

/// The homework of the API page (docs/homework-api.md), the file docs/homework_scene.rs, as a student
/// copies it to examples/hw1.rs.
#[path = "../../docs/homework_scene.rs"]
#[allow(dead_code)] // its `main`, which `cargo run --example` calls
pub(crate) mod homework_scene;

/// The band of the API page's `Bands` shader each pixel of `frame` (a render of `scene` at `settings`) shows:
/// `Some(true)` for its colour `a`, `Some(false)` for `b`, `None` where the pixel's centre does not see the
/// bands ball. Fails on a pixel of the ball that is neither band, lit (`band * grey`: its channels over the
/// band's are equal).
fn bands_seen(scene: &Scene, settings: &RenderSettings, frame: &Frame) -> Vec<Option<bool>> {
    let camera = scene.camera.frame(settings.width, settings.height);
    let bands = scene.nodes.iter().position(|n| n.name.as_deref() == Some("bands")).unwrap();
    let (a, b) = (Color::new(0.9, 0.5, 0.1), Color::new(0.1, 0.3, 0.8));
    let is_lit = |c: Color, band: Color| {
        let r = c.0 / band.0;
        r.min_element() > 0.0 && r.max_element() - r.min_element() <= 1e-4 * r.max_element()
    };
    let pixels = (0..settings.height).flat_map(|y| (0..settings.width).map(move |x| (x, y)));
    pixels
        .map(|(x, y)| match scene.closest_hit(&camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5)) {
            Some((_, node)) if std::ptr::eq(node, &scene.nodes[bands]) => {
                let c = frame.get(x, y);
                match (is_lit(c, a), is_lit(c, b)) {
                    (true, _) => Some(true),
                    (_, true) => Some(false),
                    _ => panic!("pixel ({x}, {y}) of the bands ball is {c:?}, neither band lit"),
                }
            }
            _ => None,
        })
        .collect()
}

/// The API page's homework is the file as it is, it renders without NaN, and its own shader shows exactly
/// its two band colours, lit.
#[test]
fn the_api_pages_homework_renders_and_its_own_shader_shows_its_bands() {
    let page = std::fs::read_to_string(root().join("docs/homework-api.md")).unwrap();
    assert!(
        page.contains(include_str!("../../docs/homework_scene.rs")),
        "the page shows docs/homework_scene.rs as it is"
    );
    let cli = common::parse::<homework_scene::Options>(&["--width", "160", "--height", "120", "--spp", "1"]);
    let (scene, settings) = cli.prepare().unwrap();
    let (frame, stats) = render(&scene, &settings).unwrap();
    assert_eq!(stats.counters.non_finite_samples, 0);
    let seen = bands_seen(&scene, &settings, &frame);
    let count = |band| seen.iter().filter(|&&s| s == Some(band)).count();
    assert!(count(true) > 20 && count(false) > 20, "the ball shows {} and {} pixels", count(true), count(false));
}

/// The homework's scene with everything in it moved by `offset` (the camera, the nodes and the lights): the
/// same homework built elsewhere in the world.
fn moved_homework(offset: Vector) -> Scene {
    let mut scene = homework_scene::Options {}.scene().unwrap();
    scene.camera.position += offset;
    scene.nodes = scene.nodes.into_iter().map(|node| node.translate(offset)).collect();
    for light in &mut scene.lights {
        light.position += offset;
    }
    scene
}

/// The page's `Bands`, a pattern fixed in the world (bands of world height), shows the same bands when the
/// whole homework is built 1e4 units from the origin: the renderer then works relative to the camera
/// (`Scene::relative_to_camera`), and the shader asks `world_position` for the height. The bands may differ
/// only on a pixel next to a band boundary (f32 rounds a point 1e4 from the origin to 0.001 units, a pixel of
/// the ball here is about half a unit); a shader reading the camera-relative `info.ip.y` shifts them by the
/// camera's height, 45 units, a quarter of the bands' period past a whole number of periods.
#[test]
fn the_api_pages_bands_stay_in_place_in_a_scene_far_from_the_origin() {
    let settings = RenderSettings { width: 160, height: 120, spp: 1, ..Default::default() };
    let bands_at = |offset: Vector| {
        let mut scene = moved_homework(offset);
        scene.relative_to_camera();
        let (frame, _) = render(&scene, &settings).unwrap();
        (bands_seen(&scene, &settings, &frame), scene)
    };
    let (near, near_scene) = bands_at(Vector::ZERO);
    let offset = Vector::splat(1e4);
    let (far, far_scene) = bands_at(offset);
    assert_eq!(near_scene.world_position(Vector::ZERO), Vector::ZERO, "the homework near the origin stays in place");
    assert_eq!(far_scene.camera.position, Vector::ZERO, "the far homework is rendered relative to its camera");
    let camera = moved_homework(offset).camera.position;
    assert_eq!(far_scene.world_position(Vector::ZERO), camera, "the camera-relative origin is the camera");
    let w = settings.width as usize;
    let at_boundary = |i: usize| {
        let neighbours = [i.checked_sub(1), Some(i + 1), i.checked_sub(w), Some(i + w)];
        neighbours.into_iter().flatten().any(|j| near.get(j).is_some_and(|&n| n.is_some() && n != near[i]))
    };
    let both: Vec<usize> = (0..near.len()).filter(|&i| near[i].is_some() && far[i].is_some()).collect();
    assert!(both.len() > 200, "the ball fills {} pixels in both", both.len());
    let moved: Vec<usize> = both.iter().copied().filter(|&i| near[i] != far[i] && !at_boundary(i)).collect();
    assert!(
        moved.is_empty(),
        "{} of {} pixels show the other band far from the origin, e.g. {:?}",
        moved.len(),
        both.len(),
        moved.first().map(|i| (i % w, i / w))
    );
}

/// The API page shows its geometry and its glossy shader as the files the tests compile and render
/// (`diagnostics.rs` renders the cylinder, `branching.rs` the glossy mirror).
#[test]
fn the_api_pages_geometry_and_shader_are_the_files_the_tests_render() {
    let page = std::fs::read_to_string(root().join("docs/homework-api.md")).unwrap();
    for (file, text) in [
        ("docs/homework_geometry.rs", include_str!("../../docs/homework_geometry.rs")),
        ("docs/homework_glossy.rs", include_str!("../../docs/homework_glossy.rs")),
    ] {
        assert!(page.contains(&format!("```rust\n{text}```")), "the page shows {file} as it is");
    }
}

/// The course's own name for a bitmap's tile size, `scaling`, still compiles, deprecated, and means what it
/// meant, so that a student's code written against it keeps working.
#[test]
#[allow(deprecated)]
fn the_courses_name_for_the_tile_size_still_works() {
    let bitmap = Arc::new(Bitmap::from_pixels(1, 1, vec![Color::WHITE]));
    assert_eq!(BitmapTexture::new(bitmap).with_scaling(40.0).tile_size, 40.0);
}

#[test]
fn a_file_beside_the_calling_source_is_found_before_the_workbooks_textures() {
    // This test's own source file stands in for a student's image beside their example: the call names
    // the folder of the file it is written in, as the compiler names it.
    let beside = root().join("tests").join("workbook").join("homework.rs");
    assert_eq!(texture_path("homework.rs"), beside);
    assert_eq!(texture_path("wood.png"), root().join("textures").join("wood.png"));
    let Err(error) = texture("my_floor.png") else { panic!("a texture that is nowhere was loaded") };
    let message = error.to_string();
    assert!(message.contains(&root().join("tests/workbook/my_floor.png").display().to_string()), "{message}");
    assert!(message.contains(&root().join("textures/my_floor.png").display().to_string()), "{message}");
}
