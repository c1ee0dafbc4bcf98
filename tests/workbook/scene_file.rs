//! The course's scene files (`.qdmg`): every element and property of the lecture-6 vocabulary, the error
//! rows of the format's section 5, the transform order, relative paths and the legacy light keys, all with
//! scene files written here; and the fresnel example's scene in the format against `expected/fresnel.png`.

use crate::common;

use common::examples::scene_file as scene_file_example;

use lecture6::Vector;
use lecture6::app::scene_file::{LoadOptions, SceneFile, load};
use lecture6::instruments::compare::difference;
use lecture6::lesson::color::Color;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::shader::Shader;
use lecture6::lesson::texture::{BitmapTexture, CheckerTexture, Tex};
use std::path::PathBuf;

const FOLDER: &str = "scene-file-tests";

fn write(name: &str, text: &str) -> PathBuf {
    common::temp_file(FOLDER, name, text)
}

fn load_text(name: &str, text: &str) -> lecture6::Result<SceneFile> {
    load(&write(name, text), &LoadOptions::default())
}

fn loaded(name: &str, text: &str) -> SceneFile {
    load_text(name, text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The error of a scene that must not load: one line, naming the file.
fn error(name: &str, text: &str) -> String {
    let e = load_text(name, text).err().unwrap_or_else(|| panic!("{name} loaded")).to_string();
    assert!(e.contains(name) && !e.contains('\n'), "{e}");
    e
}

const CAMERA: &str = "Camera {\n position (0, 0, -10)\n}\n";

/// The first hit of a ray from `start` along `dir` in the scene.
fn hit(file: &SceneFile, start: Vector, dir: Vector) -> Option<lecture6::lesson::geometry::IntersectionInfo> {
    file.scene.closest_hit(&Ray::new(start, dir.normalize())).map(|(h, _)| h)
}

fn near(a: Vector, b: Vector) -> bool {
    (a - b).abs().max_element() < 1e-3
}

#[test]
fn the_fresnel_scene_file_renders_the_fresnel_example() {
    let file = load(&common::root().join("examples/data/fresnel.qdmg"), &LoadOptions::default()).unwrap();
    assert!(file.warnings.is_empty(), "{:?}", file.warnings);
    assert_eq!((file.width, file.height), (640, 480));
    // The fresnel example's 5 samples per pixel.
    let settings = RenderSettings { width: file.width, height: file.height, spp: 5, ..Default::default() };
    let (frame, _) = render(&file.scene, &settings).unwrap();
    let expected = image::open(common::root().join("expected/fresnel.png")).unwrap().to_rgb8();
    let d = difference(&frame.to_rgb8(), &expected).unwrap();
    assert!(d.within_regression_tolerance(), "{d}");
}

#[test]
fn the_scene_file_example_renders_its_expected_picture_and_refuses_bad_files_in_one_line() {
    common::check_expected::<scene_file_example::Options>("scene_file");
    // The same file through the example with `--spp 5` is the fresnel example's picture.
    let frame = common::render::<scene_file_example::Options>(&["--spp", "5"]);
    let expected = image::open(common::root().join("expected/fresnel.png")).unwrap().to_rgb8();
    let d = difference(&frame.to_rgb8(), &expected).unwrap();
    assert!(d.within_regression_tolerance(), "{d}");
    // The file's frame size unless an option overrides it.
    let small = common::render::<scene_file_example::Options>(&["--width", "64", "--height", "48"]);
    assert_eq!((small.width, small.height), (64, 48));
    let bad = write("bad-class.qdmg", "Camera {\n position (0, 0, 0)\n}\nRectLight {\n}\n");
    let out = common::run_example("scene_file", &[bad.to_str().unwrap(), "-o", "target/scene-file-tests/bad.png"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(err.contains("line 4") && err.contains("RectLight") && err.trim_end().lines().count() == 1, "{err}");
    assert!(!common::root().join("target/scene-file-tests/bad.png").exists());
}

#[test]
fn global_settings_merge_and_set_frame_depth_ambient_and_anti_aliasing() {
    let file = loaded(
        "settings.qdmg",
        &format!(
            "GlobalSettings {{\n frameWidth 320\n frameHeight 200\n maxTraceDepth 7\n}}\n\
             GlobalSettings {{\n frameHeight 240\n ambientLight (0.1, 0.2, 0.3)\n wantAA off\n numThreads 2\n\
             saturation 0.5\n wantPrepass on\n numPaths 5\n}}\n{CAMERA}"
        ),
    );
    assert_eq!((file.width, file.height), (320, 240), "a later block overrides only its own keys");
    assert_eq!(file.scene.max_depth, 7);
    assert_eq!(file.scene.ambient, Color::new(0.1, 0.2, 0.3));
    assert!(!file.adaptive_aa);
    let defaults = loaded("defaults.qdmg", CAMERA);
    assert_eq!((defaults.width, defaults.height, defaults.scene.max_depth), (640, 480, 4));
    assert!(defaults.adaptive_aa && defaults.scene.ambient == Color::BLACK && defaults.scene.lights.is_empty());
}

#[test]
fn the_camera_looks_where_its_angles_say() {
    let file = loaded(
        "camera.qdmg",
        "Camera {\n position (1, 2, 3)\n yaw 90\n pitch 10\n roll 5\n fov 60\n aspectRatio 1.33333\n}\n",
    );
    let c = &file.scene.camera;
    assert_eq!((c.position, c.yaw, c.pitch, c.roll, c.fov), (Vector::new(1.0, 2.0, 3.0), 90.0, 10.0, 5.0, 60.0));
    // Yaw 90 turns the view to the left, towards -X: the centre ray.
    let frame = c.frame(64, 48);
    let centre = frame.get_screen_ray(32.0, 24.0).dir;
    let expected = Vector::new(-(10f32.to_radians().cos()), 10f32.to_radians().sin(), 0.0);
    assert!(near(centre, expected), "{centre}");
    // The last Camera wins, with a warning; an aspect ratio unlike the frame's is a warning.
    let file = loaded(
        "two-cameras.qdmg",
        "Camera {\n position (0, 0, 0)\n}\nCamera {\n position (0, 5, 0)\n aspectRatio 2\n}\n",
    );
    assert_eq!(file.scene.camera.position, Vector::new(0.0, 5.0, 0.0));
    assert!(file.warnings.iter().any(|w| w.contains(":4:") && w.contains("second Camera")), "{:?}", file.warnings);
    assert!(file.warnings.iter().any(|w| w.contains("aspectRatio 2")), "{:?}", file.warnings);
}

#[test]
fn geometries_read_their_properties() {
    let text = format!(
        "{CAMERA}Lambert white {{\n color (1, 1, 1)\n}}\n\
         Plane p {{\n y -2\n limit 3\n}}\nSphere s {{\n O (0, 5, 0)\n R 2\n}}\nCube c {{\n O (10, 0, 0)\n halfSide 1.5\n}}\n\
         Node {{\n geometry p\n shader white\n}}\nNode {{\n geometry s\n shader white\n}}\nNode {{\n geometry c\n shader white\n}}\n"
    );
    let file = loaded("geometries.qdmg", &text);
    assert_eq!(file.scene.nodes.len(), 3);
    let down = -Vector::Y;
    assert!(near(hit(&file, Vector::new(0.5, 0.0, 0.5), down).unwrap().ip, Vector::new(0.5, -2.0, 0.5)));
    assert!(hit(&file, Vector::new(3.5, 0.0, 0.0), down).is_none(), "the plane stops at |x| = limit");
    assert!(near(hit(&file, Vector::new(0.0, 10.0, 0.0), down).unwrap().ip, Vector::new(0.0, 7.0, 0.0)));
    assert!(near(hit(&file, Vector::new(10.0, 10.0, 0.0), down).unwrap().ip, Vector::new(10.0, 1.5, 0.0)));
    // Defaults: the unit sphere at the origin, the cube of half side 0.5, the plane y = 0 without limit.
    let text = format!(
        "{CAMERA}Lambert w {{\n}}\nSphere s {{\n}}\nCube c {{\n}}\nPlane p {{\n}}\n\
         Node {{\n geometry s\n shader w\n}}\nNode {{\n geometry c\n shader w\n translate (5, 0, 0)\n}}\n\
         Node {{\n geometry p\n shader w\n translate (0, -3, 0)\n}}\n"
    );
    let file = loaded("geometry-defaults.qdmg", &text);
    assert!(near(hit(&file, Vector::new(0.0, 10.0, 0.0), down).unwrap().ip, Vector::new(0.0, 1.0, 0.0)));
    assert!(near(hit(&file, Vector::new(5.0, 10.0, 0.0), down).unwrap().ip, Vector::new(5.0, 0.5, 0.0)));
    assert!(near(hit(&file, Vector::new(1e5, 10.0, 0.0), down).unwrap().ip, Vector::new(1e5, -3.0, 0.0)));
}

#[test]
fn meshes_read_faceted_auto_smooth_and_backface_culling() {
    // A tent without normals, facing -Z (its corners wind counter-clockwise seen from -Z).
    write("tent.obj", "v -1 -1 1\nv 0 -1 0\nv 0 1 0\nv -1 1 1\nv 1 -1 1\nv 1 1 1\nf 4 3 2 1\nf 3 6 5 2\n");
    let scene = |props: &str| {
        format!("{CAMERA}Lambert w {{\n}}\nMesh m {{\n file tent.obj\n{props}}}\nNode {{\n geometry m\n shader w\n}}\n")
    };
    let front = (Vector::new(-0.5, 0.0, -5.0), Vector::Z);
    let back = (Vector::new(-0.5, 0.0, 5.0), -Vector::Z);
    let file = loaded("mesh-default.qdmg", &scene(""));
    let h = hit(&file, front.0, front.1).unwrap();
    assert!(h.normal.dot(h.geometric_normal) > 1.0 - 1e-6, "no normals in the file: faceted");
    assert!(hit(&file, back.0, back.1).is_none(), "backfaceCulling is on by default");
    let file = loaded("mesh-smooth.qdmg", &scene(" autoSmooth on\n backfaceCulling off\n useKDTree off\n"));
    let h = hit(&file, front.0, front.1).unwrap();
    assert!(h.normal.dot(h.geometric_normal) < 0.999, "autoSmooth interpolates normals");
    assert!(hit(&file, back.0, back.1).is_some(), "backfaceCulling off sees the back");
    let file = loaded("mesh-faceted.qdmg", &scene(" autoSmooth on\n faceted true\n"));
    let h = hit(&file, front.0, front.1).unwrap();
    assert!(h.normal.dot(h.geometric_normal) > 1.0 - 1e-6, "faceted wins over autoSmooth");
    assert!(error("mesh-nofile.qdmg", &scene("").replace(" file tent.obj\n", "")).contains("`file`"));
}

#[test]
fn shaders_and_textures_render_with_their_properties() {
    // One row of spheres, each with another shader, over a checker floor with a bitmap; all must render.
    image::RgbImage::from_fn(4, 4, |x, _| image::Rgb([x as u8 * 60, 128, 200]))
        .save(common::root().join("target").join(FOLDER).join("tex.png"))
        .unwrap();
    let text = "GlobalSettings {\n frameWidth 64\n frameHeight 48\n ambientLight (0.2, 0.2, 0.2)\n}\n\
        Camera {\n position (0, 2, -12)\n}\nPointLight {\n pos (0, 10, -5)\n color (1, 0.9, 0.8)\n power 200\n}\n\
        CheckerTexture check {\n color1 (1, 1, 1)\n color2 (0, 0, 0)\n scaling 5\n}\n\
        BitmapTexture bmp {\n file tex.png\n scaling 2\n assumedGamma 2.2\n}\nFresnel fr {\n ior 1.5\n}\n\
        Lambert floor {\n texture check\n}\nLambert lam {\n color (0.8, 0.2, 0.2)\n}\n\
        Phong ph {\n texture bmp\n specularExponent 40\n specularMultiplier 0.6\n}\n\
        Refl mirror {\n multiplier 0.8\n}\nRefl glossy {\n multiplier 0.9\n glossiness 0.8\n numSamples 4\n}\n\
        Refr glass {\n ior 1.5\n multiplier 0.95\n}\n\
        Layered layered {\n layer lam (1, 1, 1)\n layer glass, (0.5, 0.5, 0.5), NULL\n layer mirror (1, 1, 1) fr\n}\n\
        Plane ground {\n y -1\n}\nSphere ball {\n}\n\
        Node {\n geometry ground\n shader floor\n}\n\
        Node {\n geometry ball\n shader lam\n translate (-6, 0, 0)\n}\nNode {\n geometry ball\n shader ph\n translate (-3.5, 0, 0)\n}\n\
        Node {\n geometry ball\n shader mirror\n translate (-1, 0, 0)\n}\nNode {\n geometry ball\n shader glossy\n translate (1.5, 0, 0)\n}\n\
        Node {\n geometry ball\n shader glass\n translate (4, 0, 0)\n}\nNode {\n geometry ball\n shader layered\n translate (6.5, 0, 0)\n}\n";
    let file = loaded("shaders.qdmg", text);
    assert!(file.warnings.is_empty(), "{:?}", file.warnings);
    assert_eq!((file.scene.nodes.len(), file.scene.lights.len()), (7, 1));
    assert_eq!(file.scene.lights[0].color, Color::new(1.0, 0.9, 0.8));
    let settings =
        RenderSettings { width: file.width, height: file.height, adaptive_aa: file.adaptive_aa, ..Default::default() };
    let (frame, _) = render(&file.scene, &settings).unwrap();
    assert!(frame.pixels.iter().all(|p| p.is_finite()));
    // The file's `scaling` keeps the format's meaning: the bitmap's is its tile size as it is, the checker's
    // is 5 times its squares per unit.
    let texture_of = |node: usize| {
        let texture = file.scene.nodes[node].shader.texture().map(|t| t as &dyn std::any::Any).unwrap();
        texture.downcast_ref::<Tex>().expect("a shader's texture is stored as a `Tex`").clone()
    };
    assert!(matches!(texture_of(2), Tex::Bitmap(BitmapTexture { tile_size: 2.0, .. })));
    assert!(matches!(texture_of(0), Tex::Checker(CheckerTexture { scaling: 1.0, .. })));
    // The checker's squares are 5 / scaling = 1 unit wide: the floor alternates at x = 0 and x = 1.
    let floor_at = |x: f32| {
        let ray = Ray::new(Vector::new(x, 0.5, -20.0), Vector::new(0.0, -1.5, 15.0).normalize());
        let (info, node) = file.scene.closest_hit(&ray).unwrap();
        assert!(near(info.ip, Vector::new(x, -1.0, -5.0)), "the floor at {}", info.ip);
        let mut ctx =
            lecture6::lesson::scene::TraceContext::new(&file.scene, lecture6::lesson::rng::Rng::for_keys(&[1]));
        (info.uv().0, node.shader.shade(&ray, &info, &mut ctx))
    };
    let (a, b) = (floor_at(0.5).1, floor_at(1.5).1);
    assert!(
        a.max_channel() > 0.05 && b.max_channel() == 0.0 || b.max_channel() > 0.05 && a.max_channel() == 0.0,
        "{a:?} {b:?}"
    );
}

#[test]
fn assumed_gamma_decodes_the_stored_values() {
    std::fs::create_dir_all(common::root().join("target").join(FOLDER)).unwrap();
    image::RgbImage::from_pixel(2, 2, image::Rgb([128, 128, 128]))
        .save(common::root().join("target").join(FOLDER).join("grey.png"))
        .unwrap();
    let colour = |gamma: &str| {
        let text = format!(
            "{CAMERA}BitmapTexture t {{\n file grey.png\n{gamma}}}\nLambert l {{\n texture t\n}}\nPlane p {{\n}}\n\
             Node {{\n geometry p\n shader l\n}}\nGlobalSettings {{\n ambientLight (1, 1, 1)\n}}\n"
        );
        let file = loaded("gamma.qdmg", &text);
        let ray = Ray::new(Vector::new(0.3, 1.0, 0.3), -Vector::Y);
        let (info, node) = file.scene.closest_hit(&ray).unwrap();
        let mut ctx =
            lecture6::lesson::scene::TraceContext::new(&file.scene, lecture6::lesson::rng::Rng::for_keys(&[1]));
        node.shader.shade(&ray, &info, &mut ctx).r()
    };
    let stored = 128.0 / 255.0;
    // Without a gamma the texture is data: the stored code, not the sRGB decoding's 0.216.
    assert_eq!(format!("{:.3}", colour("")), "0.502", "no gamma: the stored value");
    assert_eq!(format!("{:.3}", colour(" assumedGamma 1\n")), "0.502", "gamma 1: the stored value");
    assert!((colour("") - stored).abs() < 1e-3, "no gamma: the stored value {}", colour(""));
    assert!((colour(" assumedGamma 2.2\n") - lecture6::lesson::color::srgb_to_linear(stored)).abs() < 1e-3);
    assert!((colour(" assumedGamma 1.5\n") - stored.powf(1.5)).abs() < 1e-3);
}

#[test]
fn node_transforms_compose_in_file_order_with_translate_last() {
    let node = |lines: &str| {
        let text = format!("{CAMERA}Lambert w {{\n}}\nSphere s {{\n}}\nNode {{\n geometry s\n shader w\n{lines}}}\n");
        let file = loaded("transform.qdmg", &text);
        let t = file.scene.nodes[0].transform.expect("a transform");
        t.point_to_world(Vector::X)
    };
    // Yaw 90 maps +X to +Z (the course's convention); scale (2, 1, 1) after it leaves z alone.
    assert!(near(node(" rotate (90, 0, 0)\n scale (2, 1, 1)\n"), Vector::new(0.0, 0.0, 1.0)));
    // Scaled first, then rotated: the doubled x becomes z.
    assert!(near(node(" scale (2, 1, 1)\n rotate (90, 0, 0)\n"), Vector::new(0.0, 0.0, 2.0)));
    // Translate applies last wherever it stands, and only the last one counts.
    let moved = Vector::new(0.0, 0.0, 2.0) + Vector::new(1.0, 2.0, 3.0);
    assert!(near(node(" translate (9, 9, 9)\n scale (2, 1, 1)\n translate (1, 2, 3)\n rotate (90, 0, 0)\n"), moved));
    // Within one rotate line: pitch about X first, then yaw about Y, then roll about Z.
    // +X: pitch 90 leaves it, yaw 90 makes it +Z, roll 90 leaves +Z.
    assert!(near(node(" rotate (90, 90, 90)\n"), Vector::new(0.0, 0.0, 1.0)));
    // Roll 90 maps +X to -Y; pitch 90 maps +Y to -Z.
    assert!(near(node(" rotate (0, 0, 90)\n"), Vector::new(0.0, -1.0, 0.0)));
    assert!(near(node(" rotate (0, 0, 90)\n rotate (0, 90, 0)\n"), Vector::new(0.0, 0.0, 1.0)));
}

#[test]
fn relative_paths_resolve_against_the_scene_files_folder() {
    let dir = common::root().join("target").join(FOLDER).join("nested/deeper");
    std::fs::create_dir_all(&dir).unwrap();
    write("shared.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let text = format!("{CAMERA}Mesh m {{\n file \"../../shared.obj\"   # a triangle\n}}\n");
    std::fs::write(dir.join("scene.qdmg"), &text).unwrap();
    load(&dir.join("scene.qdmg"), &LoadOptions::default()).unwrap();
    // The same file one folder higher cannot find it: the error names the file and the line.
    std::fs::write(dir.parent().unwrap().join("scene.qdmg"), &text).unwrap();
    let e = load(&dir.parent().unwrap().join("scene.qdmg"), &LoadOptions::default()).err().unwrap().to_string();
    assert!(e.contains("line 5") && e.contains("shared.obj") && e.contains("not found"), "{e}");
}

#[test]
fn the_lecture_6_light_keys_become_a_point_light_with_a_note() {
    let text = format!("GlobalSettings {{\n lightPos (1, 20, 3)\n lightIntensity 5000\n}}\n{CAMERA}");
    let file = loaded("legacy.qdmg", &text);
    assert_eq!(file.scene.lights.len(), 1);
    let l = &file.scene.lights[0];
    assert_eq!((l.position, l.color, l.intensity), (Vector::new(1.0, 20.0, 3.0), Color::WHITE, 5000.0));
    assert!(file.warnings.iter().any(|w| w.contains(":2: note:") && w.contains("lightPos")), "{:?}", file.warnings);
}

#[test]
fn unknown_properties_odd_bools_and_duplicate_names_are_warnings_with_their_line() {
    let text = format!(
        "{CAMERA}Lambert a {{\n color (1, 0, 0)\n colour (0, 1, 0)\n color (0, 0, 1)\n}}\nLambert a {{\n color (0, 1, 0)\n}}\n\
         Sphere s {{\n}}\nMesh m {{\n file tri.obj\n faceted False\n}}\nNode {{\n geometry s\n shader a\n shadowTransparency 0.5\n}}\n"
    );
    write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let file = loaded("warnings.qdmg", &text);
    let has = |needle: &str| file.warnings.iter().any(|w| w.contains(needle));
    assert!(has(":6: warning: property `colour`"), "{:?}", file.warnings);
    assert!(has(":7: warning: property `color`"), "the second `color` line is not read: {:?}", file.warnings);
    assert!(has(":9: warning: a shader called `a` is already defined at line 4"), "{:?}", file.warnings);
    assert!(has(":16: warning: `faceted False` reads as true"), "{:?}", file.warnings);
    assert!(has(":21: warning: property `shadowTransparency`"), "{:?}", file.warnings);
    // The first `a`, and its first `color` line, win.
    let ray = Ray::new(Vector::new(0.0, 0.0, -5.0), Vector::Z);
    let (info, node) = file.scene.closest_hit(&ray).unwrap();
    let mut scene = file.scene.clone();
    scene.ambient = Color::WHITE;
    let mut ctx = lecture6::lesson::scene::TraceContext::new(&scene, lecture6::lesson::rng::Rng::for_keys(&[1]));
    assert_eq!(node.shader.shade(&ray, &info, &mut ctx), Color::new(1.0, 0.0, 0.0));
}

#[test]
fn comments_quotes_and_line_numbers_follow_the_course() {
    let text = "// a comment\n# another\n/* a block comment\n   Nonsense {\n*/ closed here\nCamera {   // the camera\n\
                position \"(0, 1, 2)\"  # quoted\n fov 5 /* radius */\n}\n/* never closed\n";
    let file = loaded("comments.qdmg", text);
    assert_eq!(file.scene.camera.position, Vector::new(0.0, 1.0, 2.0));
    assert_eq!(file.scene.camera.fov, 5.0);
    assert!(file.warnings.iter().any(|w| w.contains(":10: warning: the block comment")), "{:?}", file.warnings);
}

#[test]
fn every_error_row_of_the_format_is_one_line_with_its_line_number() {
    let e = load(&common::root().join("target/no/such/scene.qdmg"), &LoadOptions::default()).err().unwrap().to_string();
    assert!(e.contains("scene.qdmg") && e.contains("No such file"), "{e}");
    write("tri2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let long = format!("{CAMERA}Lambert a {{\n color ({}1, 0, 0)\n}}\n", " ".repeat(300));
    let cases: Vec<(&str, String, &str)> = vec![
        ("unknown-class", format!("{CAMERA}Lamberd a {{\n}}\n"), "line 4: unknown object class `Lamberd`"),
        ("glued-brace", format!("{CAMERA}Lambert a{{\n}}\n"), "line 4: expected a block header"),
        ("four-tokens", format!("{CAMERA}Lambert a b {{\n}}\n"), "line 4: expected a block header"),
        ("outside", format!("{CAMERA}color (1, 1, 1)\n"), "line 4: expected a block header"),
        ("stray-brace", format!("{CAMERA}}}\n"), "line 4: expected a block header"),
        ("no-value", format!("{CAMERA}Mesh m {{\n faceted\n}}\n"), "line 5: `faceted` has no value"),
        (
            "nested",
            format!("{CAMERA}Node a {{\n Lambert b {{\n }}\n}}\n"),
            "line 5: `Lambert b {` opens a block inside `Node` opened at line 4: that block has no `}`",
        ),
        ("unfinished", format!("{CAMERA}Lambert a {{\n color (1, 1, 1)\n"), "unfinished object definition"),
        ("bad-number", format!("{CAMERA}Sphere s {{\n R abc\n}}\n"), "line 5: `R`: invalid number"),
        ("short-colour", format!("{CAMERA}Lambert a {{\n color (1, 1)\n}}\n"), "line 5: `color`: invalid color"),
        (
            "bad-int",
            format!("GlobalSettings {{\n frameWidth wide\n}}\n{CAMERA}"),
            "line 2: `frameWidth`: invalid integer",
        ),
        (
            "short-triple",
            format!("{CAMERA}Sphere s {{\n}}\nLambert w {{\n}}\nNode {{\n geometry s\n shader w\n scale (1, 2)\n}}\n"),
            "line 11: `scale`: expected three double values",
        ),
        (
            "out-of-range",
            format!("{CAMERA}Refr g {{\n ior 11\n}}\n"),
            "line 5: `ior` 11: value outside the allowed bounds",
        ),
        ("pitch-range", "Camera {\n position (0, 0, 0)\n pitch 91\n}\n".into(), "line 3: `pitch` 91"),
        (
            "undefined-ref",
            format!("{CAMERA}Sphere s {{\n}}\nNode {{\n geometry s\n shader nothing\n}}\n"),
            "line 8: shader `nothing` not defined",
        ),
        (
            "other-namespace",
            format!("{CAMERA}Plane floor {{\n}}\nNode {{\n geometry floor\n shader floor\n}}\n"),
            "line 8: shader `floor` not defined",
        ),
        ("missing-position", "Camera {\n fov 60\n}\n".into(), "line 3: required property `position`"),
        ("missing-mesh-file", format!("{CAMERA}Mesh m {{\n}}\n"), "line 5: required property `file`"),
        ("missing-bitmap-file", format!("{CAMERA}BitmapTexture t {{\n}}\n"), "line 5: required property `file`"),
        ("missing-folder", format!("{CAMERA}CubemapEnvironment {{\n}}\n"), "line 5: required property `folder`"),
        (
            "missing-geometry",
            format!("{CAMERA}Lambert w {{\n}}\nNode {{\n shader w\n}}\n"),
            "line 8: required property `geometry`",
        ),
        ("missing-pos", format!("{CAMERA}PointLight {{\n power 5\n}}\n"), "line 6: required property `pos`"),
        ("no-camera", "GlobalSettings {\n}\n".into(), "there is no Camera block"),
        ("missing-file", format!("{CAMERA}Mesh m {{\n file nothing.obj\n}}\n"), "line 5: required file not found"),
        ("undecodable-image", format!("{CAMERA}BitmapTexture t {{\n file tri2.obj\n}}\n"), "line 5: cannot"),
        ("bad-obj", format!("{CAMERA}Mesh m {{\n file bad-obj.obj\n}}\n"), "line 5: cannot read mesh"),
        ("missing-face", format!("{CAMERA}CubemapEnvironment {{\n folder .\n}}\n"), "line 5: cannot find cube face"),
        ("frame-size", format!("GlobalSettings {{\n frameWidth 4000\n}}\n{CAMERA}"), "line 2: `frameWidth` 4000"),
        ("frame-zero", format!("GlobalSettings {{\n frameHeight 0\n}}\n{CAMERA}"), "line 2: `frameHeight` 0"),
        (
            "zero-scale",
            format!(
                "{CAMERA}Sphere s {{\n}}\nLambert w {{\n}}\nNode {{\n geometry s\n shader w\n scale (1, 0, 1)\n}}\n"
            ),
            "line 11: `scale",
        ),
        (
            "zero-bitmap-scaling",
            format!("{CAMERA}BitmapTexture t {{\n file ../../textures/wood.png\n scaling 0\n}}\n"),
            "line 6: BitmapTexture `scaling` must not be 0",
        ),
        (
            "zero-glossiness",
            format!("{CAMERA}Refl r {{\n glossiness 0\n}}\n"),
            "line 5: invalid glossiness 0: must be above 0",
        ),
        ("long-value", long, "line 5: the value of `color` is longer than 255"),
        ("long-line", format!("{CAMERA}# {}\n", "x".repeat(1100)), "line 4: the line is longer than 1023"),
        ("long-name", format!("{CAMERA}Lambert {} {{\n}}\n", "n".repeat(64)), "line 4: the name is longer than 63"),
        ("macro", format!("{CAMERA}Sphere s {{\n R randfloat(1, 2)\n}}\n"), "line 5: the random-number macros"),
        (
            "layer-syntax",
            format!("{CAMERA}Lambert w {{\n}}\nLayered l {{\n layer w 1 1 1\n}}\n"),
            "line 7: expected `layer SHADER (r, g, b) [TEXTURE]`",
        ),
        (
            "layer-glued",
            format!("{CAMERA}Lambert w {{\n}}\nFresnel f {{\n}}\nLayered l {{\n layer w (1,1,1),f\n}}\n"),
            "line 9: expected `layer",
        ),
        ("layer-cycle", format!("{CAMERA}Layered l {{\n layer l (1, 1, 1)\n}}\n"), "contains itself"),
        (
            "later-lecture",
            format!("{CAMERA}CsgMinus floor {{\n left a\n right b\n}}\nNode {{\n geometry floor\n}}\n"),
            "line 4: `CsgMinus` (constructive solid geometry) belongs to a later lecture",
        ),
    ];
    write("bad-obj.obj", "v 0 0 0\nv 1 0\nf 1 2 3\n");
    for (name, text, expected) in cases {
        let e = error(&format!("{name}.qdmg"), &text);
        assert!(e.contains(expected), "{name}: expected '{expected}' in: {e}");
    }
}

#[test]
fn elements_of_later_lectures_can_be_skipped_with_a_warning() {
    let text = format!(
        "{CAMERA}RectLight {{\n xSubd 2\n ySubd 2\n}}\nBumps b {{\n strength 1\n}}\nConst c {{\n}}\nLambert w {{\n}}\n\
         Sphere s {{\n}}\nLayered l {{\n layer w (1, 1, 1)\n layer c (1, 1, 1)\n}}\n\
         Node {{\n geometry s\n shader l\n bump b\n}}\nNode {{\n geometry s\n shader c\n}}\n"
    );
    assert!(error("later.qdmg", &text).contains("`RectLight` (area lights)"));
    let file =
        load(&write("later.qdmg", &text), &LoadOptions { skip_unsupported: true, max_trace_depth: None }).unwrap();
    assert_eq!(file.scene.nodes.len(), 1, "the node shaded by the skipped Const is skipped too");
    let has = |needle: &str| file.warnings.iter().any(|w| w.contains(needle));
    assert!(
        has(":4: warning: `RectLight`") && has(":8: warning: `Bumps`") && has(":11: warning: `Const`"),
        "{:?}",
        file.warnings
    );
    assert!(has(":19: warning: shader `c` was skipped"), "{:?}", file.warnings);
    assert!(has(":24: warning: bump mapping"), "{:?}", file.warnings);
}

#[test]
fn an_unused_element_of_a_later_lecture_is_skipped_with_a_warning_and_a_used_one_is_refused() {
    // As in the course's testmesh.qdmg: a BumpTexture that no node uses.
    let scene = |bump_use: &str| {
        format!(
            "{CAMERA}BumpTexture bumps {{\n strength 15\n}}\nLambert white {{\n}}\nLambert dull {{\n{bump_use}}}\n\
             Sphere ball {{\n}}\nNode {{\n geometry ball\n shader white\n}}\n"
        )
    };
    let file = loaded("unused-bump.qdmg", &scene(""));
    assert_eq!(file.scene.nodes.len(), 1);
    let warning = file.warnings.iter().find(|w| w.contains("BumpTexture")).expect("a warning");
    assert!(warning.contains("unused-bump.qdmg:4: warning:") && warning.contains("no node uses it"), "{warning}");
    assert_eq!(file.warnings.len(), 1, "{:?}", file.warnings);
    // Used by a shader that no node uses: still unused.
    assert!(loaded("unused-bump-shader.qdmg", &scene(" texture bumps\n")).warnings[0].contains("no node uses it"));
    // Used by the shader of a node: refused, naming the line.
    let used = scene(" texture bumps\n").replace("shader white", "shader dull");
    let e = error("used-bump.qdmg", &used);
    assert!(e.contains("line 4: `BumpTexture` (bump mapping) belongs to a later lecture"), "{e}");
    // A Node's own `bump`, as in the course's bumpmap.qdmg.
    let e = error("node-bump.qdmg", &scene("").replace("shader white", "shader white\n bump bumps"));
    assert!(e.contains("line 4: `BumpTexture`"), "{e}");
}

#[test]
fn a_cube_map_in_the_course_layout_is_read_by_default_and_opengl_on_request() {
    let dir = common::root().join("textures/sky_cubemap");
    let text = |layout: &str| format!("{CAMERA}CubemapEnvironment {{\n folder {}\n{layout}}}\n", dir.display());
    let course = loaded("cube-course.qdmg", &text(""));
    let opengl = loaded("cube-opengl.qdmg", &text(" layout opengl\n"));
    let reference = lecture6::lesson::environment::load(&dir).unwrap();
    let (a, b) = (course.scene.environment.unwrap(), opengl.scene.environment.unwrap());
    let side = Vector::new(1.0, 0.2, 0.3);
    let behind = Vector::new(0.3, -0.2, -1.0);
    let same = |x: Color, y: Color| (x - y).0.abs().max_element() < 1e-5;
    assert!(same(b.get(behind), reference.get(behind)));
    assert!(same(a.get(side), reference.get(side)), "only negz differs");
    assert!(!same(a.get(behind), reference.get(behind)), "negz is turned in the course's layout");
    assert!(same(a.get(behind), reference.get(Vector::new(-0.3, 0.2, -1.0))), "by 180 degrees");
}

/// A scene file's pictures are named after it (`beer.qdmg` -> `out/beer.png`, its views `out/beer-VIEW.png`),
/// so that the course's scenes do not overwrite each other; `-o` still says where; the bundled default file
/// keeps the example's own name.
#[test]
fn a_scene_files_picture_is_named_after_it() {
    let dir = common::root().join("target").join(FOLDER).join("named");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let text = format!("GlobalSettings {{\n frameWidth 40\n frameHeight 30\n}}\n{CAMERA}");
    let file = dir.join("little room.qdmg");
    std::fs::write(&file, text).unwrap();
    let run = |args: &[&str]| {
        let out = std::process::Command::new(common::example_binary("scene_file"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let file = file.to_str().unwrap();
    assert!(run(&[file]).contains("-> out/little room.png"));
    assert!(run(&[file, "--view", "depth"]).contains("-> out/little room-depth.png"));
    run(&[file, "-o", "elsewhere.png"]);
    run(&["--width", "8", "--height", "6"]);
    let size = |name: &str| image::image_dimensions(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(size("out/little room.png"), (40, 30));
    assert_eq!(size("out/little room-depth.png"), (40, 30), "the view has the file's own size");
    assert_eq!(size("elsewhere.png"), (40, 30));
    assert_eq!(size("out/scene_file.png"), (8, 6), "the bundled file keeps the example's name");
    let written = std::fs::read_dir(dir.join("out")).unwrap().count();
    assert_eq!(written, 3, "nothing else in out/");
}

#[test]
fn nodes_keep_the_files_names_in_the_ray_tree_and_the_report() {
    use lecture6::instruments::ray_tree::{self, PixelPos};
    use lecture6::lesson::diagnostics::Problems;
    use lecture6::lesson::scene::Counters;
    let text = format!(
        "{CAMERA}PointLight {{\n pos (0, 0, -10)\n power 100\n}}\nSphere s {{\n R 1\n}}\n\
         Lambert chalk {{\n color (1, 1, 1)\n}}\nNode ball {{\n geometry s\n shader chalk\n}}\n\
         Node {{\n geometry s\n shader chalk\n translate (0, 30, 0)\n}}\n"
    );
    let file = loaded("names.qdmg", &text);
    let names: Vec<String> = file.scene.nodes.iter().map(|n| file.scene.node_name(n)).collect();
    // The named node keeps its name; the unnamed one is called by its shape and place.
    assert_eq!(names, ["ball", "Sphere #1"]);
    let settings = RenderSettings { width: 32, height: 24, spp: 1, ..Default::default() };
    let traced = ray_tree::trace(&file.scene, &settings, PixelPos { x: 16, y: 12 }).unwrap();
    let tree = traced.tree.to_text(0);
    assert!(tree.contains("hits ball at distance") && !tree.contains("Sphere #0"), "{tree}");
    // The end-of-run report names it the same way: a normal counted as not of unit length on it.
    let mut counters = Counters::default();
    counters.problems.bad_normals.insert(0, 1);
    let report = Problems::report(&counters, &file.scene);
    assert!(report.iter().any(|l| l.ends_with(": ball (Lambert) (1)")), "{report:?}");
}
