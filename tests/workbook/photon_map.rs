//! Caustics by photon mapping: the power the photons carry matches the light on analytic setups (a mirror, a
//! glass sphere, the Fresnel glass, overlapping casters, a half-mirror layer), the caustic estimate matches
//! the irradiance of a mirror's virtual light, the glass sphere's caustic outshines the lit floor, and a scene
//! without casters or `--photons 0` renders exactly as without a photon map.

use crate::common;

use common::examples::{bitmap_textures, photon_map};
use lecture6::app::cli::Example;
use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::{Color, to_srgb8};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::geometry::{Geometry, Plane, Sphere};
use lecture6::lesson::light::PointLight;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::photon_map::{PhotonMap, PhotonSettings};
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::render;
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::{CausticCaster, PhotonScatter};
use lecture6::lesson::shader::{Lambert, Layered, Reflection, Refraction, Shader};
use lecture6::lesson::spectral::Ior;
use lecture6::lesson::texture::{Fresnel, FresnelMode};
use std::f64::consts::PI;
use std::sync::Arc;

const INTENSITY: f32 = 1000.0;

/// A scene with one white point light at `light` and the given nodes, mapping `photons` photons.
fn scene(light: Vector, photons: u32, nodes: Vec<Node>) -> Scene {
    let mut scene = Scene::new(Camera::default());
    scene.lights.push(PointLight::new(light, Color::WHITE, INTENSITY));
    scene.max_depth = 30;
    scene.photons = PhotonSettings { count: photons, k: 100, max_radius: Some(1.0), show: false };
    scene.nodes = nodes;
    scene
}

fn node(geometry: impl Geometry + 'static, shader: impl Shader + 'static) -> Node {
    Node::new(Arc::new(geometry), Arc::new(shader))
}

fn build(scene: &Scene) -> PhotonMap {
    PhotonMap::build(scene, 1).expect("valid settings").expect("the scene has casters")
}

/// The power of all stored photons (red channel; the light is white).
fn stored_power(map: &PhotonMap) -> f64 {
    map.photons().iter().map(|p| p.power.r() as f64).sum()
}

fn assert_close(actual: f64, expected: f64, tolerance: f64, what: &str) {
    let error = (actual - expected).abs() / expected;
    assert!(error <= tolerance, "{what}: {actual} instead of {expected} ({:.3}% off)", 100.0 * error);
}

/// The solid angle of the square |x|, |z| <= a seen from distance d above its centre.
fn square_solid_angle(a: f64, d: f64) -> f64 {
    4.0 * (a * a / (a * a + d * d)).asin()
}

/// The solid angle of a sphere of radius r seen from distance d.
fn sphere_solid_angle(r: f64, d: f64) -> f64 {
    2.0 * PI * (1.0 - (1.0 - (r / d) * (r / d)).sqrt())
}

/// A 2 x 2 mirror on the floor, the light 10 above it, a diffuse ceiling at 20.
fn mirror_scene(photons: u32, mirror: impl Shader + 'static) -> Scene {
    scene(
        Vector::new(0.0, 10.0, 0.0),
        photons,
        vec![node(Plane::new(0.0, 1.0), mirror), node(Plane::new(20.0, f32::INFINITY), Lambert::new(Color::gray(0.5)))],
    )
}

#[test]
fn a_mirror_stores_the_power_sent_to_it_times_its_reflectance() {
    let map = build(&mirror_scene(100_000, Reflection::new(0.9)));
    let expected = 0.9 * INTENSITY as f64 * square_solid_angle(1.0, 10.0);
    assert_close(stored_power(&map), expected, 0.01, "power reflected onto the ceiling");
    // Every photon landed on the ceiling, inside the mirror's reflection (the square |x|, |z| <= 3).
    assert!(map.photons().iter().all(|p| p.position.y == 20.0 && p.position.x.abs().max(p.position.z.abs()) <= 3.0));
}

#[test]
fn the_caustic_estimate_is_the_irradiance_of_the_mirrors_virtual_light() {
    // The mirror's image of the light is 10 below the floor, 30 below the ceiling. Each estimate gathers 400
    // photons: its noise is then a few per cent.
    let mut scene = mirror_scene(100_000, Reflection::new(0.9));
    scene.photons.k = 400;
    let map = build(&scene);
    let down = Vector::new(0.0, -1.0, 0.0);
    let (mut sum_estimate, mut sum_exact) = (0.0, 0.0);
    for i in -3..=3 {
        for j in -3..=3 {
            let (x, z) = (0.5 * i as f64, 0.5 * j as f64);
            let d2 = x * x + z * z + 900.0;
            let exact = 0.9 * INTENSITY as f64 * (30.0 / d2.sqrt()) / d2;
            let estimate = map.irradiance(Vector::new(x as f32, 20.0, z as f32), down).r() as f64;
            assert_close(estimate, exact, 0.1, &format!("irradiance at ({x}, 20, {z})"));
            (sum_estimate, sum_exact) = (sum_estimate + estimate, sum_exact + exact);
        }
    }
    assert_close(sum_estimate, sum_exact, 0.02, "mean irradiance");
    // From the other side of the ceiling, nothing arrives.
    assert!(map.irradiance(Vector::new(0.0, 20.0, 0.0), Vector::Y).is_black());
}

/// A glass sphere of radius 1 at the origin, the light 5 above it, inside a large diffuse sphere that
/// catches every photon.
fn glass_scene(glass: impl Shader + 'static, more: Vec<Node>) -> Scene {
    let mut nodes = vec![
        node(Sphere::new(Vector::ZERO, 1.0), glass),
        node(Sphere::new(Vector::ZERO, 100.0), Lambert::new(Color::gray(0.5))),
    ];
    nodes.extend(more);
    scene(Vector::new(0.0, 5.0, 0.0), 50_000, nodes)
}

#[test]
fn a_glass_sphere_passes_the_power_sent_to_it_times_its_transmission_twice() {
    let map = build(&glass_scene(Refraction::new(1.5, 0.8), vec![]));
    let expected = 0.8 * 0.8 * INTENSITY as f64 * sphere_solid_angle(1.0, 5.0);
    assert_close(stored_power(&map), expected, 0.01, "power through the glass");
}

/// The slides' glass: a refraction layer under a mirror layer blended by the Fresnel texture.
fn fresnel_glass() -> Layered {
    let mut glass = Layered::new();
    glass.add_layer(Arc::new(Refraction::new(1.5, 1.0)), Color::WHITE, None);
    glass.add_layer(
        Arc::new(Reflection::new(1.0)),
        Color::WHITE,
        Some(Arc::new(Fresnel::new(1.5, FresnelMode::Schlick))),
    );
    glass
}

#[test]
fn fresnel_glass_neither_gains_nor_loses_light() {
    // Every photon is reflected or refracted, never absorbed: all the power sent at the sphere lands.
    let map = build(&glass_scene(fresnel_glass(), vec![]));
    let expected = INTENSITY as f64 * sphere_solid_angle(1.0, 5.0);
    assert_close(stored_power(&map), expected, 0.005, "power around the Fresnel glass");
    // Some photons were reflected: they land above the sphere's equator.
    assert!(map.photons().iter().any(|p| p.position.y > 0.0));
}

#[test]
fn a_caster_behind_another_is_not_counted_twice() {
    // A second glass sphere below the first, seen from the light entirely behind it: its cone lies inside
    // the first one's, so the light sent into both cones is that of the first alone.
    let behind = node(Sphere::new(Vector::new(0.0, -5.0, 0.0), 1.5), Refraction::new(1.5, 1.0));
    let map = build(&glass_scene(Refraction::new(1.5, 1.0), vec![behind]));
    let expected = INTENSITY as f64 * sphere_solid_angle(1.0, 5.0);
    assert_close(stored_power(&map), expected, 0.005, "power through two glass spheres");
}

#[test]
fn a_half_mirror_layer_reflects_half_the_light() {
    // A Layered surface: diffuse below, a perfect mirror blended at 50% on top. Photons choose a layer at
    // random; those that land on the diffuse layer straight from the light are not caustics.
    let mut half_mirror = Layered::new();
    half_mirror.add_layer(Arc::new(Lambert::new(Color::gray(0.5))), Color::WHITE, None);
    half_mirror.add_layer(Arc::new(Reflection::new(1.0)), Color::gray(0.5), None);
    let map = build(&mirror_scene(100_000, half_mirror));
    let expected = 0.5 * INTENSITY as f64 * square_solid_angle(1.0, 10.0);
    assert_close(stored_power(&map), expected, 0.015, "power reflected by the half mirror");
}

#[test]
fn a_layered_surface_sends_photons_on_in_proportion_to_its_blends() {
    // Diffuse below, a mirror with a coloured blend on top: the mirror's weight is the blend, the diffuse
    // layer's the rest. On average a photon must go on with the mirror's weight, and must land with the
    // power of all the light arriving (the diffuse layer's weight is applied when it is shaded).
    let blend = Color::new(0.2, 0.5, 0.8);
    let mut surface = Layered::new();
    surface.add_layer(Arc::new(Lambert::new(Color::gray(0.5))), Color::WHITE, None);
    surface.add_layer(Arc::new(Reflection::new(1.0)), blend, None);
    let ray = Ray::new(Vector::new(0.3, 5.0, 0.1), Vector::new(0.1, -1.0, 0.2).normalize());
    let info = Plane::new(0.0, f32::INFINITY).intersect(&ray, f32::INFINITY).unwrap();
    let mut rng = Rng::for_keys(&[5]);
    let samples = 200_000;
    let (mut landed, mut reflected) = (0.0, Color::BLACK);
    for _ in 0..samples {
        match surface.scatter_photon(&ray, &info, &mut rng) {
            PhotonScatter::Land { scale } => landed += scale as f64,
            PhotonScatter::Continue { dir, filter } => {
                assert!((dir.y - -ray.dir.y).abs() < 1e-6, "not a mirror reflection: {dir}");
                reflected += filter;
            }
            PhotonScatter::Absorb => panic!("nothing absorbs here"),
        }
    }
    assert_close(landed / samples as f64, 1.0, 0.01, "landed power");
    let reflected = reflected / samples as f32;
    for (got, want) in reflected.to_array().into_iter().zip(blend.to_array()) {
        assert_close(got as f64, want as f64, 0.01, "reflected power");
    }
}

#[test]
fn dispersive_glass_passes_white_light_in_coloured_photons() {
    // A dense flint: photons get wavelengths and band colours, but together they are as white as the light.
    let glass =
        lecture6::lesson::shader::fresnel_glass(Ior::SF11, lecture6::lesson::texture::FresnelMode::Schlick, 1.0);
    let map = build(&glass_scene(glass, vec![]));
    let expected = INTENSITY as f64 * sphere_solid_angle(1.0, 5.0);
    for channel in 0..3 {
        let power: f64 = map.photons().iter().map(|p| p.power.to_array()[channel] as f64).sum();
        assert_close(power, expected, 0.02, &format!("power in channel {channel}"));
    }
    assert!(
        map.photons().iter().any(|p| p.power.0.min_element() < 0.5 * p.power.0.max_element()),
        "no coloured photon"
    );
}

/// Where the world point `p` of the `photon_map` scene lies in `prepared`, the scene as the examples render
/// it (which `Scene::relative_to_camera` may have moved so that the camera stands at the origin).
fn in_prepared_scene(prepared: &Scene, p: Vector) -> Vector {
    let world = common::parse::<photon_map::Options>(&[]).example.scene().unwrap();
    p + (prepared.camera.position - world.camera.position)
}

/// The largest relative difference between the channels of the caustic estimates on a grid of the floor
/// around the glass sphere's focus.
fn caustic_chroma(args: &[&str]) -> f32 {
    use photon_map::{GLASS_CENTER, LIGHT};
    let axis = GLASS_CENTER - LIGHT;
    let scene = common::parse::<photon_map::Options>(args).prepare().unwrap().0;
    let focus = in_prepared_scene(&scene, GLASS_CENTER + axis * (GLASS_CENTER.y / -axis.y));
    let map = scene.photon_map.as_ref().unwrap();
    let mut chroma: f32 = 0.0;
    for i in -8..=8 {
        for j in -8..=8 {
            let e = map.irradiance(focus + Vector::new(i as f32, 0.0, j as f32), Vector::Y);
            if e.max_channel() > 0.5 {
                chroma = chroma.max(1.0 - e.0.min_element() / e.max_channel());
            }
        }
    }
    chroma
}

#[test]
fn a_dispersive_sphere_makes_a_chromatic_caustic() {
    let white = caustic_chroma(&["--photons", "100000"]);
    assert!(white < 1e-6, "a white caustic has colour {white}");
    let coloured = caustic_chroma(&["--photons", "100000", "--abbe", "12"]);
    assert!(coloured > 0.3, "the dispersive caustic is hardly coloured: {coloured}");
}

/// The colour seen from the camera where it looks at the point `p` of the floor.
fn seen_at(scene: &Scene, p: Vector) -> Color {
    let ray = Ray::new(scene.camera.position, (p - scene.camera.position).normalize());
    let (info, _) = scene.closest_hit(&ray).expect("the floor is there");
    assert!((info.ip - p).length() < 0.01, "the camera does not see {p} but {}", info.ip);
    TraceContext::new(scene, Rng::for_keys(&[1])).raytrace(&ray)
}

#[test]
fn the_caustic_under_the_glass_sphere_outshines_the_lit_floor_beside_it() {
    use photon_map::{GLASS_CENTER, GLASS_RADIUS, LIGHT};
    // The sphere's axis from the light meets the floor in the middle of its shadow, where it focuses.
    let axis = GLASS_CENTER - LIGHT;
    let focus = GLASS_CENTER + axis * (GLASS_CENTER.y / -axis.y);
    // Beside it, across the light's direction, three radii away, and one checker square (25) further back,
    // on a square of the same colour as the focus's: directly lit floor.
    let across = Vector::new(axis.z, 0.0, -axis.x).normalize();
    let beside = focus + across * (3.0 * GLASS_RADIUS) + Vector::new(0.0, 0.0, 25.0);
    let with_map = common::parse::<photon_map::Options>(&[]).prepare().unwrap().0;
    let without = common::parse::<photon_map::Options>(&["--photons", "0"]).prepare().unwrap().0;
    assert!(with_map.photon_map.is_some() && without.photon_map.is_none());

    let (focus, beside) = (in_prepared_scene(&with_map, focus), in_prepared_scene(&with_map, beside));
    let (caustic, lit) = (seen_at(&with_map, focus).luminance(), seen_at(&with_map, beside).luminance());
    assert!(caustic > 2.0 * lit, "caustic {caustic}, lit floor beside it {lit}");
    // Without photons the same point lies in the sphere's shadow.
    let shadow = seen_at(&without, focus).luminance();
    assert!(shadow < 0.5 * lit, "shadow {shadow}, lit floor {lit}");
}

const SMALL: [&str; 4] = ["--width", "160", "--height", "120"];

fn args_with(extra: &[&'static str]) -> Vec<&'static str> {
    SMALL.iter().copied().chain(extra.iter().copied()).collect()
}

#[test]
fn no_photons_renders_exactly_as_without_a_photon_map() {
    let zero = common::render::<photon_map::Options>(&args_with(&["--photons", "0"]));
    let args = common::parse::<photon_map::Options>(&SMALL);
    let mut scene = args.example.scene().unwrap();
    scene.relative_to_camera();
    assert!(scene.photon_map.is_none() && scene.photons.count > 0);
    let (plain, _) = render(&scene, &args.prepare().unwrap().1).unwrap();
    assert!(zero == plain, "--photons 0 changed the picture");
    // The caustic only adds light: no pixel gets darker, and the caustic's pixels get visibly brighter.
    let with_map = common::render::<photon_map::Options>(&SMALL);
    let pairs = || with_map.pixels.iter().zip(&plain.pixels);
    assert!(pairs().all(|(w, p)| (w.0 - p.0).min_element() >= 0.0), "the photon map darkened a pixel");
    let brighter = pairs().filter(|(w, p)| to_srgb8(**w) != to_srgb8(**p)).count();
    assert!(brighter * 100 > with_map.pixels.len(), "only {brighter} pixels show a caustic");
}

#[test]
fn a_scene_without_caustic_casters_builds_no_map_and_renders_as_before() {
    let args = common::parse::<bitmap_textures::Options>(&["--photons", "100000"]);
    let scene = args.prepare().unwrap().0;
    assert_eq!(scene.photons.count, 100_000);
    assert!(scene.photon_map.is_none(), "a photon map without casters");
    let with = common::render::<bitmap_textures::Options>(&args_with(&["--photons", "100000"]));
    let without = common::render::<bitmap_textures::Options>(&SMALL);
    assert!(with == without, "asking for photons changed a scene without caustics");
}

#[test]
fn the_photon_map_and_picture_are_the_same_for_any_thread_count() {
    let one = common::render::<photon_map::Options>(&args_with(&["--threads", "1", "--photons", "50000"]));
    let two = common::render::<photon_map::Options>(&args_with(&["--threads", "2", "--photons", "50000"]));
    assert!(one == two, "the picture changed with the thread count");
    // Another seed draws other photons: the noise of the caustic moves, the caustic's light stays.
    let other_seed = common::render::<photon_map::Options>(&args_with(&["--seed", "2", "--photons", "50000"]));
    let moved = one.pixels.iter().zip(&other_seed.pixels).filter(|(a, b)| to_srgb8(**a) != to_srgb8(**b)).count();
    assert!(moved * 100 > one.pixels.len(), "the seed did not reach the photons: {moved} pixels changed");
    let total = |f: &Frame| f.pixels.iter().map(|c| c.luminance() as f64).sum::<f64>();
    let (a, b) = (total(&one), total(&other_seed));
    assert!((a - b).abs() < 0.01 * a, "another seed changed the light: {a} against {b}");
}

#[test]
fn show_photons_draws_dots_where_photons_landed() {
    let scene = common::parse::<photon_map::Options>(&["--show-photons"]).prepare().unwrap().0;
    let map = scene.photon_map.as_ref().unwrap();
    let photon = map.photons()[0];
    let dot = map.irradiance(photon.position, -photon.dir);
    assert!(dot.max_channel() > 100.0, "no dot on a photon: {dot:?}");
    // Far from every photon (the camera's side of the floor, behind the sphere's shadow), no dot.
    assert!(map.irradiance(Vector::new(60.0, 0.0, -60.0), Vector::Y).is_black());
    // In the picture, the dots are white where the estimate is a soft caustic.
    let white = |f: &Frame| f.pixels.iter().filter(|c| c.0.min_element() >= 1.0).count();
    let dots = common::render::<photon_map::Options>(&args_with(&["--show-photons"]));
    let estimate = common::render::<photon_map::Options>(&SMALL);
    assert!(white(&dots) > white(&estimate) + 20, "{} white pixels, {} without dots", white(&dots), white(&estimate));
}

/// `--show-photons` draws the photons, not the caustic: without `-o` its picture has a name of its own, and the
/// picture the example wrote before stays as it was.
#[test]
fn show_photons_writes_a_picture_of_its_own_name() {
    let dir = common::root().join("target/photon-map-tests/show-photons");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let run = |extra: &[&str]| {
        let args = ["--width", "48", "--height", "36", "--photons", "2000", "-q"];
        let out = std::process::Command::new(common::example_binary("photon_map"))
            .args(args.iter().chain(extra))
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(out.status.success(), "{extra:?}: {}", String::from_utf8_lossy(&out.stderr));
    };
    run(&[]);
    let kept = std::fs::read(dir.join("out/photon_map.png")).unwrap();
    run(&["--show-photons"]);
    assert_eq!(std::fs::read(dir.join("out/photon_map.png")).unwrap(), kept, "--show-photons replaced the picture");
    let dots = image::open(dir.join("out/photon_map-photons.png")).unwrap().to_rgb8();
    assert_ne!(dots.as_raw(), image::load_from_memory(&kept).unwrap().to_rgb8().as_raw(), "no dots drawn");
    let cli = common::parse::<photon_map::Options>(&["--show-photons", "--compare", "x.png"]);
    assert_eq!(cli.output_path("photon_map"), std::path::Path::new("out/photon_map-photons-compared.png"));
}

#[test]
fn impossible_photon_settings_are_one_line_naming_the_value() {
    for (args, needle) in [
        (&["--k", "0"][..], "photon k 0"),
        (&["--radius=-1"][..], "photon radius -1"),
        (&["--radius", "NaN"][..], "photon radius NaN"),
        (&["--photons", "100000000"][..], "photon count 100000000"),
        (&["--ior", "0"][..], "index of refraction n_d 0"),
    ] {
        let out = common::run_example("photon_map", &[args, &["-o", "target/bad-input/photons.png"]].concat());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle) && err.trim_end().lines().count() == 1 && !err.contains("panicked"), "{err}");
    }
}

/// The photon grid (the step beyond the slides that `PhotonMap::new` sorts photons into) finds exactly the
/// photons a scan of all of them finds: every photon within the largest radius when k asks for all of them,
/// the k nearest when it asks for fewer, at points inside, at the edge of and outside the photons' box, for
/// photons on a surface (a plane, as on the workbook's floors) and in a volume, at several radii.
#[test]
fn the_photon_grid_finds_what_a_scan_of_every_photon_finds() {
    use lecture6::lesson::photon_map::StoredPhoton;
    use lecture6::lesson::topic::{Recorder, Topic};
    /// The indices of the photons an estimate found, in order.
    struct Found(Vec<usize>);
    impl Recorder for Found {
        fn record(&mut self, topic: &Topic) {
            if let Topic::Photons { photons, .. } = topic {
                self.0 = photons.iter().map(|p| p.index).collect();
                self.0.sort();
            }
        }
    }
    let mut rng = Rng::for_keys(&[7]);
    let mut random = |scale: f32| (rng.next_f32() - 0.5) * scale;
    for flat in [true, false] {
        let photons: Vec<StoredPhoton> = (0..3000)
            .map(|_| StoredPhoton {
                position: Vector::new(random(20.0), if flat { 1.0 } else { random(20.0) }, random(20.0)),
                dir: Vector::NEG_Y,
                power: Color::WHITE,
            })
            .collect();
        for (max_radius, k) in [(0.5, 3000), (1.5, 3000), (1.5, 5), (3.0, 40)] {
            let map = PhotonMap::new(photons.clone(), k, max_radius, false).unwrap();
            for _ in 0..100 {
                let p = Vector::new(random(26.0), if flat { 1.0 + random(4.0) } else { random(26.0) }, random(26.0));
                let mut found = Found(Vec::new());
                map.irradiance_recorded(p, Vector::Y, Some(&mut found));
                // Squared distances as the grid adds them up, nearest first, ties by index.
                let d2 = |q: Vector| (q - p).x.powi(2) + (q - p).y.powi(2) + (q - p).z.powi(2);
                let mut scan: Vec<(f32, usize)> = (photons.iter().enumerate())
                    .map(|(i, photon)| (d2(photon.position), i))
                    .filter(|&(d2, _)| d2 <= max_radius * max_radius)
                    .collect();
                scan.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
                let mut nearest: Vec<usize> = scan.iter().take(k as usize).map(|&(_, i)| i).collect();
                nearest.sort();
                assert_eq!(found.0, nearest, "around {p} within {max_radius}, k {k}");
            }
        }
    }
}

/// The progressive caustic (`--photon-passes`): the same picture on one thread and on two; each pass after
/// the first adds a caustic of its own (the picture is not the first pass's); and with a dispersive glass
/// (`--abbe 8`) every pass's photons carry their wavelengths' colours, so the caustic stays coloured.
#[test]
fn the_progressive_caustic_is_the_same_on_any_thread_count_and_keeps_the_caustics_colours() {
    let small = ["--width", "80", "--height", "60", "--spp", "1", "--photons", "40000"];
    let with = |extra: &[&str]| common::render::<photon_map::Options>(&[&small[..], extra].concat());
    let one = with(&["--photon-passes", "4", "--threads", "1"]);
    let two = with(&["--photon-passes", "4", "--threads", "2"]);
    assert!(one.pixels == two.pixels, "4 passes: the picture depends on the thread count");
    assert!(one.pixels != with(&["--threads", "2"]).pixels, "4 passes render the first pass's picture");
    // How far the caustic's red and blue part: zero for the white caustic of a glass without dispersion.
    let hue = |frame: &Frame| frame.pixels.iter().map(|c| (c.r() - c.b()).abs() as f64).sum::<f64>();
    let chromatic = with(&["--photon-passes", "3", "--abbe", "8", "--spectral", "passes", "--wavelengths", "8"]);
    assert!(chromatic.pixels.iter().all(|c| c.is_finite()), "a pixel of the chromatic caustic is not finite");
    let white = with(&["--photon-passes", "3", "--spectral", "passes", "--wavelengths", "8"]);
    assert!(
        hue(&chromatic) > 2.0 * hue(&white),
        "the dispersive glass's caustic is no more coloured than the white one's: {} against {}",
        hue(&chromatic),
        hue(&white)
    );
}

/// The progressive caustic's radii shrink as Knaus and Zwicker write them, r_(i+1)^2 = r_i^2 (i + alpha) /
/// (i + 1), so as pass^(-1/6) for alpha = 2/3; pass 1 keeps the render's seed and every other pass has one of
/// its own.
#[test]
fn the_progressive_radius_shrinks_as_knaus_and_zwicker_write_it_and_each_pass_has_its_own_seed() {
    use lecture6::lesson::photon_map::{ALPHA, pass_seed, radius_scale};
    assert_eq!(radius_scale(1), 1.0);
    let mut r2 = 1.0f64;
    for pass in 1..200u32 {
        let (i, next) = (pass as f64, radius_scale(pass + 1) as f64);
        r2 *= (i + ALPHA) / (i + 1.0);
        assert!((next * next - r2).abs() <= 1e-6 * r2, "pass {}: {next} against {}", pass + 1, r2.sqrt());
    }
    let ratio = radius_scale(1024) as f64 / radius_scale(16) as f64;
    assert!((ratio - 64f64.powf(-1.0 / 6.0)).abs() < 0.01 * ratio, "{ratio}");
    assert_eq!(pass_seed(7, 1), 7);
    let seeds: std::collections::HashSet<u64> = (1..100).map(|pass| pass_seed(7, pass)).collect();
    assert_eq!(seeds.len(), 99);
    assert_ne!(pass_seed(7, 2), pass_seed(8, 2));
}
