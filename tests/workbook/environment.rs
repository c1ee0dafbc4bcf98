//! The environments' conventions (which texel a direction reads), the bundled sky, `--env`, and the errors
//! for missing or unreadable environment files.

use crate::common;

use common::examples::{bitmap_textures, environment as environment_example};
use lecture6::app::assets::{SkyFunction, sun_direction};
use lecture6::app::cli::Example;
use lecture6::instruments::compare::difference;
use lecture6::lesson::bitmap::{Bitmap, Filter};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::Color;
use lecture6::lesson::environment::{
    self, CubeFace, CubemapEnvironment, Environment, SphericalEnvironment, cube_face_direction, cube_face_uv,
    equirect_direction, equirect_uv,
};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::math::Vector;
use lecture6::lesson::rng::Rng;
use std::path::PathBuf;
use std::sync::Arc;

/// A bitmap whose every texel has its own colour: (tag, column, row).
fn labelled(width: usize, height: usize, tag: f32) -> Arc<Bitmap> {
    let pixels = (0..width * height).map(|i| Color::new(tag, (i % width) as f32, (i / width) as f32)).collect();
    Arc::new(Bitmap::from_pixels(width, height, pixels))
}

fn texel(column: usize, row: usize) -> Color {
    Color::new(0.0, column as f32, row as f32)
}

/// Random unit directions, the same on every run.
fn directions(n: usize) -> Vec<Vector> {
    let mut rng = Rng::for_keys(&[4, 2]);
    let mut out = Vec::new();
    while out.len() < n {
        let v = Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) * 2.0 - 1.0;
        if (0.01..=1.0).contains(&v.length_squared()) {
            out.push(v.normalize());
        }
    }
    out
}

fn sky_path() -> PathBuf {
    common::root().join("textures").join("sky.hdr")
}

fn cubemap_path() -> PathBuf {
    common::root().join("textures").join("sky_cubemap")
}

#[test]
fn the_centre_of_the_equirectangular_image_faces_plus_z_unmirrored() {
    // A 4 x 2 image: columns are the quarters -Z..-X, -X..+Z, +Z..+X, +X..-Z; rows the upper and lower half.
    let env = SphericalEnvironment::new(labelled(4, 2, 0.0)).with_filter(Filter::Nearest);
    assert_eq!(env.get(Vector::new(1.0, 1.0, 1.0).normalize()), texel(2, 0), "up, right of +Z");
    assert_eq!(env.get(Vector::new(-1.0, 1.0, 1.0).normalize()), texel(1, 0), "up, left of +Z");
    assert_eq!(env.get(Vector::new(-1.0, -0.2, 1.0).normalize()), texel(1, 1), "down, left of +Z");
    assert_eq!(env.get(Vector::new(1.0, 0.3, -1.0).normalize()), texel(3, 0), "behind, right");
    assert_eq!(env.get(Vector::new(-1.0, -0.3, -1.0).normalize()), texel(0, 1), "behind, left");
    // Bilinear: +Z is the very centre of the image, the average of the four middle texels.
    let bilinear = SphericalEnvironment::new(labelled(4, 2, 0.0));
    assert_eq!(bilinear.get(Vector::Z), Color::new(0.0, 1.5, 0.5));
    // The top row is straight up, the bottom row straight down; the left and right edges meet at -Z.
    assert_eq!(equirect_uv(Vector::Z), (0.5, 0.5));
    assert_eq!(equirect_uv(Vector::X), (0.75, 0.5));
    assert_eq!(equirect_uv(-Vector::X), (0.25, 0.5));
    assert_eq!(equirect_uv(Vector::Y).1, 0.0);
    assert_eq!(equirect_uv(-Vector::Y).1, 1.0);
    assert_eq!(equirect_uv(-Vector::Z).0.fract(), 0.0);
}

#[test]
fn equirectangular_coordinates_round_trip() {
    for d in directions(2000) {
        let (u, v) = equirect_uv(d);
        assert!((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v), "{d}: {u}, {v}");
        let back = equirect_direction(u, v);
        assert!((back - d).length() < 1e-5, "{d} -> ({u}, {v}) -> {back}");
        // Only the direction matters, not its length.
        let (u2, v2) = equirect_uv(d * 37.0);
        assert!((u2 - u).abs() < 1e-6 && (v2 - v).abs() < 1e-6);
    }
}

#[test]
fn each_axis_lands_in_the_middle_of_its_face() {
    for (dir, face) in [
        (Vector::X, CubeFace::PosX),
        (-Vector::X, CubeFace::NegX),
        (Vector::Y, CubeFace::PosY),
        (-Vector::Y, CubeFace::NegY),
        (Vector::Z, CubeFace::PosZ),
        (-Vector::Z, CubeFace::NegZ),
    ] {
        assert_eq!(cube_face_uv(dir), (face, 0.5, 0.5), "{dir}");
    }
    // Up and towards -Z from +X is the top right of posx; looking up, +X is right and +Z the bottom edge.
    assert_eq!(cube_face_uv(Vector::new(1.0, 0.5, -0.5)), (CubeFace::PosX, 0.75, 0.25));
    assert_eq!(cube_face_uv(Vector::new(0.5, 1.0, 0.5)), (CubeFace::PosY, 0.75, 0.75));
    assert_eq!(cube_face_uv(Vector::new(-0.5, -0.5, 1.0)), (CubeFace::PosZ, 0.25, 0.75));
}

#[test]
fn cube_face_coordinates_round_trip() {
    for d in directions(2000) {
        let (face, u, v) = cube_face_uv(d);
        assert!((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v), "{d}: {u}, {v}");
        let back = cube_face_direction(face, u, v);
        assert!((back - d).length() < 1e-5, "{d} -> {face:?} ({u}, {v}) -> {back}");
    }
}

#[test]
fn a_camera_looking_along_an_axis_sees_that_face_as_it_is_drawn() {
    // A square image with a 90° horizontal field of view: the diagonal fov is 2 atan(sqrt 2).
    const N: u32 = 4;
    let fov = 2.0 * 2f32.sqrt().atan().to_degrees();
    let faces = CubeFace::ALL.map(|f| labelled(N as usize, N as usize, f as usize as f32 + 10.0));
    let env = CubemapEnvironment::new(faces).with_filter(Filter::Nearest);
    for (face, yaw, pitch) in [
        (CubeFace::PosZ, 0.0, 0.0),
        (CubeFace::PosX, -90.0, 0.0),
        (CubeFace::NegZ, 180.0, 0.0),
        (CubeFace::NegX, 90.0, 0.0),
        (CubeFace::PosY, 0.0, 90.0),
        (CubeFace::NegY, 0.0, -90.0),
    ] {
        let camera = Camera { yaw, pitch, fov, ..Camera::default() }.frame(N, N);
        for y in 0..N {
            for x in 0..N {
                let ray = camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
                let expected = Color::new(face as usize as f32 + 10.0, x as f32, y as f32);
                assert_eq!(env.get(ray.dir), expected, "{face:?}: camera pixel ({x}, {y})");
            }
        }
    }
}

#[test]
fn the_bundled_sky_has_a_sun_a_blue_sky_and_a_ground() {
    let sky = SphericalEnvironment::load(&sky_path()).unwrap();
    let sun = sky.get(sun_direction());
    assert!(sun.0.min_element() > 20.0, "the sun is far brighter than white: {sun:?}");
    let zenith = sky.get(Vector::Y);
    assert!(zenith.b() > 2.0 * zenith.r() && zenith.max_channel() < 1.0, "{zenith:?}");
    let ground = sky.get(-Vector::Y);
    assert!(ground.g() > ground.b() && ground.max_channel() < 0.5, "{ground:?}");
}

#[test]
fn the_bundled_cubemap_shows_the_same_sky() {
    let sky = SphericalEnvironment::load(&sky_path()).unwrap();
    let cube = CubemapEnvironment::load(&cubemap_path()).unwrap();
    // The faces are resampled from the equirectangular image, so they are a little blurrier: compare on
    // average, and every direction within the contrast of neighbouring texels.
    let (mut sum, mut n, mut worst) = (0.0, 0, 0.0f32);
    for d in directions(4000) {
        let (a, b) = (sky.get(d), cube.get(d));
        let relative = (a.0 - b.0).abs().max_element() / a.max_channel().max(0.05);
        if d.dot(sun_direction()) < 0.99 {
            assert!(relative < 0.3, "{d}: {a:?} vs {b:?}");
            sum += relative;
            worst = worst.max(relative);
            n += 1;
        }
    }
    let mean = sum / n as f32;
    assert!(mean < 0.02, "mean relative difference {mean}");
    assert!(cube.get(sun_direction()).0.min_element() > 20.0);
}

#[test]
fn a_missing_or_unreadable_face_is_an_error_naming_its_file() {
    let dir = common::root().join("target").join("env-test").join("five-faces");
    std::fs::create_dir_all(&dir).unwrap();
    for face in &CubeFace::ALL[..5] {
        std::fs::copy(cubemap_path().join(format!("{}.hdr", face.name())), dir.join(format!("{}.hdr", face.name())))
            .unwrap();
    }
    let _ = std::fs::remove_file(dir.join("negz.png"));
    let err = environment::load(&dir).err().expect("negz is missing").to_string();
    assert!(err.contains("negz") && err.contains("five-faces"), "{err}");

    std::fs::write(dir.join("negz.png"), b"not an image").unwrap();
    let err = environment::load(&dir).err().expect("negz is not an image").to_string();
    assert!(err.contains(&dir.join("negz.png").display().to_string()), "{err}");

    let missing = common::root().join("no-such-sky.hdr");
    let err = environment::load(&missing).err().expect("no such file").to_string();
    assert!(err.contains("no-such-sky.hdr"), "{err}");
}

#[test]
fn env_option_sets_the_environment_of_any_example() {
    let args = ["--width", "32", "--height", "24", "--spp", "1"];
    let scene = common::parse::<bitmap_textures::Options>(&[]).example.scene().unwrap();
    let ray = scene.camera.frame(32, 24).get_screen_ray(0.5, 0.5);
    assert!(scene.closest_hit(&ray).is_none(), "the top-left pixel must see the environment");
    assert_eq!(common::render::<bitmap_textures::Options>(&args).get(0, 0), Color::BLACK);

    for (path, env) in [
        (sky_path(), environment::load(&sky_path()).unwrap()),
        (cubemap_path(), environment::load(&cubemap_path()).unwrap()),
    ] {
        let with_env = [&args[..], &["--env", path.to_str().unwrap()]].concat();
        let frame = common::render::<bitmap_textures::Options>(&with_env);
        assert_eq!(frame.get(0, 0), env.get(ray.dir), "{}", path.display());
    }
}

#[test]
fn a_bad_env_option_is_one_line_naming_the_file() {
    for bad in ["no/such/sky.hdr", "Cargo.toml", "src"] {
        let out = common::run_example("bitmap_textures", &["--env", bad, "-o", "target/bad-input/env.png"]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(bad) && !err.contains("panicked"), "{bad}: {err}");
    }
}

/// `environment --kind cubemap` differs from `--kind spherical` (by up to 25 levels on 2149 pixels at
/// 640 x 480) because each image holds the same sky sampled on its own grid, and the sky seen directly is
/// magnified about five times, so each picture shows its own image's interpolation between texels (the
/// faces, resampled from the equirectangular image, are a little blurrier). Measured against the sky
/// function both images sample, the cube map's picture is about as close as the spherical image's, and
/// the objects, lit by the same light, agree.
#[test]
fn the_two_environment_kinds_are_equally_close_to_the_sky_they_sample() {
    let args = ["--width", "320", "--height", "240", "--spp", "1"];
    let spherical = common::parse::<environment_example::Options>(&args);
    let render = |sky: Arc<dyn Environment>| {
        let mut scene = spherical.example.scene().unwrap();
        scene.environment = Some(sky);
        lecture6::lesson::render::render(&scene, &spherical.prepare().unwrap().1).unwrap().0
    };
    let truth = render(Arc::new(SkyFunction));
    let from_image = render(Arc::new(SphericalEnvironment::load(&sky_path()).unwrap()));
    let from_cube = render(Arc::new(CubemapEnvironment::load(&cubemap_path()).unwrap()));
    let rmse = |a: &Frame, b: &Frame| difference(&a.to_rgb8(), &b.to_rgb8()).unwrap().rmse_8bit;
    let (image_error, cube_error, between) =
        (rmse(&from_image, &truth), rmse(&from_cube, &truth), rmse(&from_cube, &from_image));
    println!(
        "RMSE against the sky function: spherical {image_error:.3}, cube map {cube_error:.3}; between them {between:.3}"
    );
    assert!(image_error > 0.0 && cube_error > 0.0, "an image of the sky cannot equal the function exactly");
    assert!(
        cube_error < 1.5 * image_error,
        "the cube map ({cube_error:.3} levels) is much further from the sky than the spherical image ({image_error:.3})"
    );
    // The lower half holds the stage, the objects and their shadows: the same light, the same picture.
    let lower = |f: &Frame| image::imageops::crop_imm(&f.to_rgb8(), 0, 160, 320, 80).to_image();
    let objects = difference(&lower(&from_cube), &lower(&from_image)).unwrap();
    assert!(objects.within(objects.pixels / 5000, 1.0), "the stage differs: {objects:?}");
}
