//! Cube maps in the OpenGL layout and in the course's (its `negz` turned by 180°): every edge between two
//! faces is seamless when the folder is read in its own layout, and the file checks of environments.

use crate::common;

use lecture6::Vector;
use lecture6::lesson::color::linear_to_srgb;
use lecture6::lesson::environment::{
    CubeFace, CubemapEnvironment, CubemapLayout, Environment, SphericalEnvironment, cube_face_direction,
};
use std::path::{Path, PathBuf};

const SIZE: u32 = 32;

/// A sky that changes smoothly with the direction and differs in every direction.
fn sky(d: Vector) -> [f32; 3] {
    let d = d.normalize();
    [0.5 + 0.45 * d.x, 0.5 + 0.45 * d.y, 0.5 + 0.45 * d.z]
}

/// Writes the six faces of `sky` into `target/<name>/` in `layout`, face `name` getting extension `ext`.
fn write_cubemap(name: &str, layout: CubemapLayout, ext: impl Fn(CubeFace) -> &'static str) -> PathBuf {
    let dir = common::root().join("target").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    for face in CubeFace::ALL {
        let turned = layout == CubemapLayout::Course && face == CubeFace::NegZ;
        let img = image::RgbImage::from_fn(SIZE, SIZE, |i, j| {
            let (i, j) = if turned { (SIZE - 1 - i, SIZE - 1 - j) } else { (i, j) };
            let (u, v) = ((i as f32 + 0.5) / SIZE as f32, (j as f32 + 0.5) / SIZE as f32);
            image::Rgb(sky(cube_face_direction(face, u, v)).map(|c| (linear_to_srgb(c) * 255.0).round() as u8))
        });
        img.save_with_format(dir.join(format!("{}.{}", face.name(), ext(face))), image::ImageFormat::Png).unwrap();
    }
    dir
}

/// The largest colour difference across the twelve edges of the cube: on each edge, directions a couple of
/// texels to either side of it, in the two faces that meet there.
fn worst_seam(env: &dyn Environment) -> f32 {
    let axes = [Vector::X, Vector::Y, Vector::Z];
    let step = 2.0 / SIZE as f32;
    let mut worst = 0.0f32;
    for a in 0..3 {
        for b in a + 1..3 {
            let c = 3 - a - b;
            for (sa, sb) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                for k in 0..=20 {
                    let t = -0.9 + 0.09 * k as f32;
                    let edge = axes[a] * sa + axes[b] * sb + axes[c] * t;
                    let in_a = env.get(edge + axes[a] * (sa * step));
                    let in_b = env.get(edge + axes[b] * (sb * step));
                    worst = worst.max((in_a - in_b).0.abs().max_element());
                }
            }
        }
    }
    worst
}

#[test]
fn both_layouts_are_seamless_when_read_in_their_own_layout() {
    let lower = |_: CubeFace| "png";
    for (name, layout, other) in [
        ("cubemap-opengl", CubemapLayout::OpenGl, CubemapLayout::Course),
        ("cubemap-course", CubemapLayout::Course, CubemapLayout::OpenGl),
    ] {
        let dir = write_cubemap(name, layout, lower);
        let right = worst_seam(&CubemapEnvironment::load_layout(&dir, layout).unwrap());
        // Two texels of a sky whose colours change by 0.45 per unit of direction, plus 8-bit rounding.
        assert!(right < 0.05, "{name}: a seam of {right} in its own layout");
        let wrong = worst_seam(&CubemapEnvironment::load_layout(&dir, other).unwrap());
        assert!(wrong > 0.3, "{name}: read in the other layout, the seams around negz must show ({wrong})");
        // Both layouts show the same sky.
        let env = CubemapEnvironment::load_layout(&dir, layout).unwrap();
        for d in [-Vector::Z, Vector::new(0.3, 0.2, -1.0), Vector::X, Vector::new(-0.2, 0.9, 0.1)] {
            let (got, want) = (env.get(d), sky(d));
            assert!((0..3).all(|i| (got.to_array()[i] - want[i]).abs() < 0.02), "{name} at {d}: {got:?}");
        }
    }
}

#[test]
fn face_files_are_found_whatever_the_case_of_their_extension() {
    let dir = write_cubemap("cubemap-case", CubemapLayout::OpenGl, |f| if f == CubeFace::PosY { "PNG" } else { "Png" });
    let env = CubemapEnvironment::load(&dir).unwrap();
    assert!(worst_seam(&env) < 0.05);
}

fn expect_refused(dir: &Path, what: &str) -> String {
    let e = CubemapEnvironment::load(dir).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.contains(what) && !e.contains('\n'), "expected '{what}': {e}");
    e
}

#[test]
fn faces_that_are_not_square_or_not_of_one_size_are_refused() {
    let dir = write_cubemap("cubemap-wide", CubemapLayout::OpenGl, |_| "png");
    image::RgbImage::new(SIZE * 2, SIZE).save(dir.join("negy.png")).unwrap();
    expect_refused(&dir, "negy.png");
    let dir = write_cubemap("cubemap-sizes", CubemapLayout::OpenGl, |_| "png");
    image::RgbImage::new(SIZE / 2, SIZE / 2).save(dir.join("posz.png")).unwrap();
    expect_refused(&dir, "of one size");
}

#[test]
fn an_equirectangular_image_that_is_not_two_to_one_is_refused() {
    let path = common::root().join("target/cubemap-wide/square.png");
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    image::RgbImage::new(16, 16).save(&path).unwrap();
    let e = SphericalEnvironment::load(&path).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.contains("square.png") && e.contains("2:1") && e.contains("16x16"), "{e}");
    image::RgbImage::new(32, 16).save(&path).unwrap();
    assert!(SphericalEnvironment::load(&path).is_ok());
}
