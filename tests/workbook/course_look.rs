//! The course's look (docs/techniques.md, "The course's look"): `--encoding raw` reads and writes 8-bit codes
//! as the course's lecture-6 program does, a course-layout cube map read with the nearest texel takes the
//! course's texel, and `fresnel --floor` puts the course's floor image under the glass. How close the three
//! come to the course's own picture is measured beside its program: `cargo bench --bench speed -- --course`.

use crate::common::examples::fresnel::Options as Fresnel;
use crate::common::examples::scene_file::Options as SceneFile;
use crate::common::{parse, render, root, run_example};
use lecture6::lesson::bitmap::Filter;
use lecture6::lesson::color::{srgb_to_linear, srgb8_code};
use lecture6::lesson::environment::{CubeFace, CubemapEnvironment, CubemapLayout, Environment};
use lecture6::lesson::math::Vector;
use std::path::PathBuf;

/// A folder under `target/` of its own for this test.
fn folder(name: &str) -> PathBuf {
    let dir = root().join("target").join("course-look").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The red code of the top-left pixel of `fresnel` at 8x6 under a grey sky of code 100, exposed at -1 (half
/// the light), with `extra` options: the sky seen as it is read, halved and written.
fn halved_sky_code(extra: &[&str]) -> u8 {
    let dir = folder("encoding");
    let sky = dir.join("grey-sky.png");
    image::RgbImage::from_pixel(16, 8, image::Rgb([100, 100, 100])).save(&sky).unwrap();
    let out = dir.join(format!("sky{}.png", extra.join("")));
    let sky_arg = sky.display().to_string();
    let out_arg = out.display().to_string();
    let mut args = vec!["--width", "8", "--height", "6", "--fov", "112.62", "--env", &sky_arg, "--exposure", "-1"];
    args.extend(["-q", "-o", &out_arg]);
    args.extend(extra);
    let run = run_example("fresnel", &args);
    assert!(run.status.success(), "{args:?}: {}", String::from_utf8_lossy(&run.stderr));
    image::open(&out).unwrap().to_rgb8().get_pixel(0, 0)[0]
}

#[test]
fn encoding_raw_reads_and_writes_a_code_as_the_light_itself() {
    // The course: code 100 is the light 100/255; half of it is written as code 50.
    assert_eq!(halved_sky_code(&["--encoding", "raw"]), 50);
    // sRGB: code 100 is the light 0.127; half of it is sRGB code 73.
    let srgb = srgb8_code(srgb_to_linear(100.0 / 255.0) / 2.0);
    assert_eq!(halved_sky_code(&[]), srgb);
    assert_eq!(halved_sky_code(&["--encoding", "srgb"]), srgb);
    assert_ne!(srgb, 50);
}

/// Six faces of 4x4 texels, each texel of its own colour, in `layout`.
fn numbered_cubemap(layout: CubemapLayout) -> CubemapEnvironment {
    let dir = folder("numbered-cubemap");
    for face in CubeFace::ALL {
        let image =
            image::RgbImage::from_fn(4, 4, |x, y| image::Rgb([(40 * x + 10 * y + 5) as u8, face as u8 * 40, 0]));
        image.save(dir.join(format!("{}.png", face.name()))).unwrap();
    }
    CubemapEnvironment::load_layout(&dir, layout).unwrap()
}

#[test]
fn a_course_layout_cube_map_read_with_the_nearest_texel_takes_the_courses_texel() {
    // Just right of the middle of the +Z face: u = 0.505, v = 0.5. The course's program takes texel
    // floor(u (4 - 1)) = 1 in both directions, the texel the point falls in is floor(u 4) = 2.
    let dir = Vector::new(0.01, 0.0, 1.0);
    let course = numbered_cubemap(CubemapLayout::Course);
    let opengl = numbered_cubemap(CubemapLayout::OpenGl);
    let face = &course.faces[CubeFace::PosZ as usize];
    assert_eq!(course.clone().with_filter(Filter::Nearest).get(dir), face.get_pixel(1, 1));
    assert_eq!(opengl.clone().with_filter(Filter::Nearest).get(dir), face.get_pixel(2, 2));
    // Bilinear filtering, beyond the slides, reads texel centres where they are in both layouts.
    assert_eq!(course.get(dir), opengl.get(dir));
}

#[test]
fn fresnel_takes_its_floor_from_the_command_line() {
    let size = ["--width", "40", "--height", "30", "--spp", "1"];
    let bundled = root().join("textures/floor_tiles.png").display().to_string();
    fn with_floor<'a>(size: &[&'a str], floor: &'a str) -> Vec<&'a str> {
        [size, &["--floor", floor]].concat()
    }
    assert_eq!(render::<Fresnel>(&size), render::<Fresnel>(&with_floor(&size, &bundled)), "the bundled floor, named");
    let other = root().join("textures/wood.png").display().to_string();
    assert_ne!(render::<Fresnel>(&size), render::<Fresnel>(&with_floor(&size, &other)), "another floor shows");
    let missing = root().join("target/course-look/no-such-floor.bmp").display().to_string();
    let Err(error) = parse::<Fresnel>(&with_floor(&size, &missing)).render() else {
        panic!("a missing floor is refused")
    };
    assert!(error.to_string().contains("no-such-floor.bmp"), "{error}");
}

#[test]
fn a_scene_files_assumed_gamma_reads_its_texture_alike_under_either_encoding() {
    // `assumedGamma 2.2` decodes the floor's stored codes with the sRGB curve, as the course does, whichever
    // way `--encoding` read the file: the linear frames agree (the sky is an HDR cube map, read as it is).
    let scene = root().join("examples/data/fresnel.qdmg").display().to_string();
    let frame = |encoding| render::<SceneFile>(&[&scene, "--width", "40", "--height", "30", "--encoding", encoding]);
    let (srgb, raw) = (frame("srgb"), frame("raw"));
    let worst = srgb
        .pixels
        .iter()
        .zip(&raw.pixels)
        .flat_map(|(a, b)| a.to_array().into_iter().zip(b.to_array()).map(|(a, b)| (a - b).abs()))
        .fold(0.0f32, f32::max);
    assert!(worst < 1e-4, "the frames differ by up to {worst}");
}

/// The command a page gives for the course's look: the line that starts it and its continuation lines.
fn course_look_command(page: &str) -> String {
    let text = std::fs::read_to_string(root().join("docs").join(page)).unwrap();
    let start = "cargo run --release --example fresnel -- --slide --fov 112.62";
    let first = text.find(start).unwrap_or_else(|| panic!("docs/{page} gives no course's look command"));
    let mut command = String::new();
    for line in text[first..].lines() {
        command.push_str(line.trim().trim_end_matches('\\').trim());
        command.push(' ');
        if !line.trim_end().ends_with('\\') {
            break;
        }
    }
    command.trim().to_string()
}

#[test]
fn the_teachers_page_gives_the_course_look_in_one_command_that_fresnel_takes() {
    let command = course_look_command("class.md");
    assert_eq!(command, course_look_command("techniques.md"), "the two pages give different commands");
    let args: Vec<&str> = command.split_once(" -- ").unwrap().1.split_whitespace().collect();
    for option in ["--slide", "--env-layout", "--floor", "--encoding"] {
        assert!(args.contains(&option), "{command}");
    }
    // fresnel's own parser takes every option of it (the course's files are only opened when it renders).
    let _ = parse::<Fresnel>(&args);
}
