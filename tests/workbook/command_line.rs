//! The command line a student meets: `--compare` that never destroys its reference and compares each kind of
//! reference in its own form, caps on every count that multiplies work or memory, negative numbers that
//! reach the check which explains them, options that say when they change nothing, `--help` that shows each
//! example's real defaults, and doc comments that say what the pictures really show.

use crate::common;

use common::examples::{fresnel, photon_map, reflect_v02};
use common::{root, run_example};
use lecture6::instruments::compare::{Difference, heat_map, with_colour_bar};
use lecture6::lesson::rng::shuffled_index;
use std::path::PathBuf;
use std::process::Output;

/// A scratch folder of this file's, one per test so that the tests can run in parallel.
fn scratch(test: &str) -> PathBuf {
    let dir = root().join("target").join("command-line").join(test);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Runs an example at a small size with `args` after the size options.
fn small(example: &str, args: &[&str]) -> Output {
    run_example(example, &[&["--width", "64", "--height", "48"][..], args].concat())
}

/// The run failed with exit code 2 and one line on stderr that contains every one of `needles`, and no panic.
fn assert_refused(out: &Output, needles: &[&str]) {
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "not one line: {err}");
    assert!(!err.contains("panicked"), "{err}");
    for needle in needles {
        assert!(err.contains(needle), "{err} does not say {needle}");
    }
}

#[test]
fn compare_refuses_to_write_over_its_reference() {
    let dir = scratch("over-reference");
    let reference = dir.join("REF.png");
    assert!(small("fresnel", &["-o", reference.to_str().unwrap()]).status.success());
    let before = std::fs::read(&reference).unwrap();
    let r = reference.to_str().unwrap();
    // The same path, the same path spelt another way, and the heat map's path.
    let other_spelling = dir.join("new-folder").join("..").join("REF.png");
    let heat_over_it = dir.join("REF-diff.png");
    std::fs::copy(&reference, &heat_over_it).unwrap();
    for (output, reference) in [
        (r.to_string(), r.to_string()),
        (other_spelling.to_str().unwrap().to_string(), r.to_string()),
        (dir.join("REF.png").to_str().unwrap().to_string(), heat_over_it.to_str().unwrap().to_string()),
    ] {
        let out = small("fresnel", &["--ior", "1.3", "-o", &output, "--compare", &reference]);
        assert_refused(&out, &["refusing to write over the reference"]);
    }
    assert_eq!(std::fs::read(&reference).unwrap(), before, "the reference is untouched");
    assert!(!dir.join("new-folder").exists(), "nothing was written");
}

#[test]
fn a_linear_reference_is_compared_in_linear_light() {
    let dir = scratch("linear-reference");
    for ext in ["exr", "hdr"] {
        let reference = dir.join(format!("f.{ext}"));
        assert!(small("fresnel", &["-o", reference.to_str().unwrap()]).status.success());
        let output = dir.join(format!("again-{ext}.png"));
        let out = small("fresnel", &["-o", output.to_str().unwrap(), "--compare", reference.to_str().unwrap()]);
        let stdout = text(&out.stdout);
        assert!(out.status.success(), "{}", text(&out.stderr));
        // The same render: compared in linear light, within the tolerance (an 8-bit comparison of the linear
        // values said "RMSE 64.8 levels, 3072 of 3072 pixels differ"). OpenEXR keeps the floats exactly;
        // Radiance HDR rounds them to 8-bit mantissas, at most one 8-bit level once encoded.
        assert!(stdout.contains("in linear light: RMSE "), "{stdout}");
        assert!(stdout.contains("; within the regression"), "{stdout}");
        let exact = ["in linear light: RMSE 0.000e0", "max diff 0 levels"];
        let rounded = ["max diff 0 levels", "max diff 1 levels"];
        match ext {
            "exr" => assert!(exact.iter().all(|s| stdout.contains(s)), "{stdout}"),
            _ => assert!(rounded.iter().any(|s| stdout.contains(s)), "{stdout}"),
        }
    }
}

#[test]
fn a_reference_of_another_size_is_refused_before_the_render() {
    let dir = scratch("size");
    let reference = dir.join("small.png");
    assert!(small("fresnel", &["-o", reference.to_str().unwrap()]).status.success());
    let output = dir.join("large.png");
    // A render that would take minutes is refused at once: nothing is written and no summary printed.
    let out = run_example(
        "fresnel",
        &["--width", "3000", "--height", "2000", "--spp", "64", "-o", output.to_str().unwrap()]
            .into_iter()
            .chain(["--compare", reference.to_str().unwrap()])
            .collect::<Vec<_>>(),
    );
    assert_refused(&out, &["small.png", "64x48", "3000x2000"]);
    assert!(text(&out.stdout).is_empty() && !output.exists());
}

#[test]
fn every_count_that_multiplies_work_or_memory_is_capped() {
    for (example, args, needle) in [
        ("fresnel", &["--spp", "4294967295"][..], "1..=65536"),
        ("glossy", &["--glossy-samples", "4000000000"][..], "must be 1 to 4096"),
        ("dispersion", &["--wavelengths", "100000"][..], "1..=1000"),
        ("photon_map", &["--photons", "4000000000"][..], "at most 16777216"),
        ("photon_map", &["--k", "4000000000"][..], "between 1 and 10000"),
        ("fresnel", &["--threads", "100000"][..], "1..=1024"),
        ("fresnel", &["--width", "100000", "--height", "100000"][..], "more than 67108864 pixels"),
    ] {
        let out = run_example(example, &[args, &["-o", "target/command-line/capped.png"]].concat());
        assert_refused(&out, &[needle]);
    }
    // The largest sample count is accepted, and a pixel's samples need no memory that grows with it.
    let cli = common::parse::<fresnel::Options>(&["--width", "1", "--height", "1", "--spp", "65536"]);
    let (frame, _) = cli.render().unwrap();
    assert!(frame.pixels[0].to_array().iter().all(|v| v.is_finite()));
}

#[test]
fn shuffled_indices_are_permutations() {
    for n in (1..70).chain([255, 256, 257, 1000, 65_536]) {
        for key in [0, 1, 0xdead_beef, u32::MAX] {
            let mut seen = vec![false; n as usize];
            for i in 0..n {
                let j = shuffled_index(i, n, key);
                assert!(j < n && !seen[j as usize], "n {n}, key {key}: {i} -> {j} twice or outside");
                seen[j as usize] = true;
            }
        }
    }
    // Different keys give different orders.
    let order = |key| (0..16).map(|i| shuffled_index(i, 16, key)).collect::<Vec<_>>();
    assert_ne!(order(1), order(2));
}

#[test]
fn negative_numbers_reach_the_check_that_explains_them() {
    for (args, needles) in [
        (&["--spp", "-1"][..], &["'-1' for '--spp <SPP>'", "-1 is not in 1..=65536"][..]),
        (&["--width", "-5"][..], &["'-5' for '--width <WIDTH>'", "-5 is not in"][..]),
        (&["--ior", "-1"][..], &["invalid --ior -1: must be a positive number"][..]),
        (&["--max-depth", "-2"][..], &["'-2' for '--max-depth <MAX_DEPTH>'"][..]),
    ] {
        let out = run_example("fresnel", &[args, &["-o", "target/command-line/negative.png"]].concat());
        assert_refused(&out, needles);
        assert!(!text(&out.stderr).contains("unexpected argument"));
    }
}

#[test]
fn options_that_change_nothing_say_so() {
    // The model glass's numbers without the model glass are an error, not silently ignored.
    let out = small("dispersion", &["--nd", "1.5", "--abbe", "10", "-o", "target/command-line/nd.png"]);
    assert_refused(&out, &["--nd 1.5", "--glass abbe"]);
    // Caustic and dispersion options on a scene they cannot change: a note each, and the same picture.
    let dir = scratch("no-effect");
    let output = dir.join("bitmap_textures.png");
    let out = small("bitmap_textures", &["--photons", "100000", "--wavelengths", "3", "-o", output.to_str().unwrap()]);
    let err = text(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("note: --photons changes nothing here: no mirror or glass"), "{err}");
    assert!(err.contains("note: --wavelengths changes nothing here: nothing in this scene is dispersive"), "{err}");
    // Where they do change the picture, no note.
    let out = small("photon_map", &["--photons", "1000", "-o", dir.join("photon_map.png").to_str().unwrap()]);
    assert!(out.status.success() && !text(&out.stderr).contains("note:"), "{}", text(&out.stderr));
}

#[test]
fn help_shows_each_examples_own_defaults() {
    let help = |example: &str| {
        let out = run_example(example, &["--help"]);
        assert!(out.status.success());
        text(&out.stdout)
    };
    let photon_map = help("photon_map");
    assert!(!photon_map.contains("the scene's own"), "{photon_map}");
    let (scene, _) = common::parse::<photon_map::Options>(&[]).prepare().unwrap();
    for value in [scene.photons.count, scene.photons.k, scene.max_depth] {
        assert!(photon_map.contains(&format!("[default: {value}]")), "{value} missing: {photon_map}");
    }
    assert!(photon_map.contains("[default: 4]"), "its own --spp default");
    // Where the caustic and dispersion options change nothing, their headings say so.
    let bitmap = help("bitmap_textures");
    assert!(bitmap.contains("Caustics (photon mapping): no effect here"), "{bitmap}");
    assert!(bitmap.contains("Dispersion: no effect here"), "{bitmap}");
    assert!(help("dispersion").contains("Dispersion (scenes with dispersive glass only):"));
}

#[test]
fn an_example_can_tell_whether_spp_was_given() {
    let cli = common::parse::<fresnel::Options>(&[]);
    assert_eq!(cli.common.spp, None);
    assert_eq!(cli.prepare().unwrap().1.spp, 5, "the example's default");
    assert_eq!(common::parse::<fresnel::Options>(&["--spp", "1"]).common.spp, Some(1));
}

/// The sentence of an example's doc comment (its `//!` lines joined) that holds `phrase`.
fn doc_sentence(example: &str, phrase: &str) -> String {
    let source = std::fs::read_to_string(root().join("examples").join(format!("{example}.rs"))).unwrap();
    let doc: Vec<&str> = source.lines().filter_map(|l| l.strip_prefix("//!")).map(str::trim).collect();
    let doc = doc.join(" ");
    let at = doc.find(phrase).unwrap_or_else(|| panic!("examples/{example}.rs does not say {phrase:?}"));
    doc[at..].split(". ").next().unwrap().to_string()
}

#[test]
fn fresnel_says_at_which_depth_the_sphere_goes_black() {
    // "`--max-depth N` (... the inside of the sphere goes black ...)": check N.
    let sentence = doc_sentence("fresnel", "`--max-depth ");
    assert!(sentence.contains("goes black"), "{sentence}");
    let depth: String = sentence["`--max-depth ".len()..].chars().take_while(char::is_ascii_digit).collect();
    let brightness = |depth: &str| {
        let frame = common::render::<fresnel::Options>(&["--width", "64", "--height", "48", "--max-depth", depth]);
        // The middle of the sphere, which faces the camera.
        let c = frame.get(32, 15);
        c.to_array().iter().sum::<f32>()
    };
    let next = (depth.parse::<u32>().unwrap() + 1).to_string();
    let (black, seen_through) = (brightness(&depth), brightness(&next));
    // Black inside: only the surface's own reflection is left, less than a quarter of what one bounce more
    // shows through the glass (at 64 x 48: 0.09 at depth 1, 0.46 at 2, 0.56 at 3).
    assert!(black < 0.25 * seen_through, "at --max-depth {depth} {black}, one deeper {seen_through}");
}

#[test]
fn photon_map_says_where_the_mirror_throws_its_patch() {
    let sentence = doc_sentence("photon_map", "throws a bright patch onto the ");
    let surface = sentence["throws a bright patch onto the ".len()..].split_whitespace().next().unwrap().to_string();
    // The pixels right of the glass that the photon map brightens, and what they see.
    let (w, h) = (96, 72);
    let size = ["--width", "96", "--height", "72", "--spp", "1"];
    let with = common::render::<photon_map::Options>(&size);
    let without = common::render::<photon_map::Options>(&[&size[..], &["--photons", "0"]].concat());
    let cli = common::parse::<photon_map::Options>(&size);
    let scene = lecture6::app::cli::Example::scene(&cli.example).unwrap();
    let camera = scene.camera.frame(w, h);
    let (mut on_wall, mut on_floor) = (0, 0);
    for y in 0..h {
        for x in w / 2..w {
            let gain = with.get(x, y).to_array().iter().sum::<f32>() - without.get(x, y).to_array().iter().sum::<f32>();
            if gain > 0.3 {
                let (hit, _) = scene.closest_hit(&camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5)).unwrap();
                if (hit.ip.z - photon_map::WALL_Z).abs() < 1.0 {
                    on_wall += 1;
                } else if hit.ip.y.abs() < 1.0 {
                    on_floor += 1;
                }
            }
        }
    }
    let found = if on_wall > on_floor { "wall" } else { "floor" };
    assert_eq!(
        surface, found,
        "the doc says {surface:?}; {on_wall} brightened pixels on the wall, {on_floor} on the floor"
    );
}

#[test]
fn reflect_v02_offers_no_homework_the_renderer_already_does() {
    // The renderer stops rays whose weight cannot change their pixel (adaptive depth control): a homework
    // idea about the weight must point at `--exhaustive`, which switches that off, not ask for it anew.
    let sentence = doc_sentence("reflect_v02", "Homework ideas:");
    let homework = std::fs::read_to_string(root().join("examples/reflect_v02.rs")).unwrap();
    let ideas = &homework[homework.find("Homework ideas:").unwrap()..];
    let ideas = &ideas[..ideas.find("\n\n").unwrap_or(ideas.len())];
    assert!(!ideas.contains("weight") || ideas.contains("--exhaustive"), "{sentence}");
    let scene = lecture6::app::cli::Example::scene(&common::parse::<reflect_v02::Options>(&[]).example).unwrap();
    assert!(scene.min_ray_weight > 0.0, "the renderer cuts weak rays by default");
}

#[test]
fn the_heat_map_scales_to_the_largest_difference_and_shows_its_scale() {
    let a = image::RgbImage::from_pixel(40, 30, image::Rgb([100, 100, 100]));
    let mut b = a.clone();
    b.put_pixel(5, 5, image::Rgb([109, 100, 100]));
    b.put_pixel(6, 5, image::Rgb([103, 100, 100]));
    // A difference of 9 levels is white, one of 3 a third of the way up the ramp (dark red).
    let map = heat_map(&a, &b).unwrap();
    assert_eq!(map.get_pixel(5, 5).0, [255, 255, 255]);
    assert_eq!(map.get_pixel(6, 5).0, [255, 0, 0]);
    assert_eq!(map.get_pixel(0, 0).0, [0, 0, 0]);
    let with_bar = with_colour_bar(&map, 9).unwrap();
    assert_eq!(with_bar.width(), 40);
    assert!(with_bar.height() > 30 + 12, "a colour bar and its caption below the map");
    // The colour bar runs from black to white.
    let bar_row = 31;
    assert!(with_bar.get_pixel(0, bar_row).0.iter().all(|&v| v < 40));
    assert!(with_bar.get_pixel(39, bar_row).0.iter().all(|&v| v > 215));
}

#[test]
fn compare_says_whether_the_render_is_within_the_regression_tolerance() {
    let dir = scratch("verdict");
    let reference = root().join("expected").join("fresnel.png");
    let exact = dir.join("exact.png");
    let out = run_example(
        "fresnel",
        &["--fresnel", "exact", "-o", exact.to_str().unwrap(), "--compare", reference.to_str().unwrap()],
    );
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Schlick against the exact equations: a few levels at the rim, within the tolerance.
    let expected = image::open(&reference).unwrap().to_rgb8();
    let actual = image::open(&exact).unwrap().to_rgb8();
    let d: Difference = lecture6::instruments::compare::difference(&actual, &expected).unwrap();
    let verdict = if d.within_regression_tolerance() { "; within the regression" } else { "; NOT within" };
    assert!(stdout.contains(verdict), "{stdout}");
    assert!(stdout.contains(&format!("max diff {} levels", d.max_diff)), "{stdout}");
    assert!(d.max_diff > 0, "Schlick's approximation differs from the exact equations somewhere");
}

/// Reads a linear picture written by an example.
fn linear(path: &std::path::Path) -> image::Rgb32FImage {
    image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).into_rgb32f()
}

#[test]
fn exposure_scales_the_light_and_tone_mapping_keeps_a_bright_sky_off_white() {
    let dir = scratch("exposure");
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    // The environment's sky is brighter than white; one stop less halves every value that is written.
    for (name, args) in [("plain.exr", &[][..]), ("minus-one.exr", &["--exposure", "-1"][..])] {
        let out = small("environment", &[args, &["--spp", "1", "-o", &path(name)]].concat());
        assert!(out.status.success(), "{}", text(&out.stderr));
    }
    let (plain, darker) = (linear(&dir.join("plain.exr")), linear(&dir.join("minus-one.exr")));
    assert!(plain.pixels().any(|p| p.0.iter().any(|&v| v > 1.0)), "the sky is brighter than white");
    for (p, q) in plain.pixels().zip(darker.pixels()) {
        for c in 0..3 {
            assert_eq!(q[c], p[c] * 0.5, "one stop less is half the light");
        }
    }
    // As a PNG the course's clamp makes the bright sky white; Reinhard's curve keeps every pixel below it.
    for (name, tonemap) in [("clamp.png", "clamp"), ("reinhard.png", "reinhard")] {
        let out = small("environment", &["--spp", "1", "--tonemap", tonemap, "-o", &path(name)]);
        assert!(out.status.success(), "{}", text(&out.stderr));
    }
    let white = |name: &str| {
        let img = image::open(dir.join(name)).unwrap().into_rgb8();
        img.pixels().filter(|p| p.0 == [255, 255, 255]).count()
    };
    assert!(white("clamp.png") > 0 && white("reinhard.png") == 0, "{} {}", white("clamp.png"), white("reinhard.png"));
    // Out-of-range values are refused in one line before anything is rendered.
    assert_refused(
        &small("environment", &["--exposure", "100", "-o", &path("x.png")]),
        &["--exposure 100", "-20 to 20"],
    );
    assert_refused(&small("environment", &["--clamp-sample", "-1", "-o", &path("x.png")]), &["--clamp-sample -1"]);
}

#[test]
fn clamp_sample_caps_every_sample_of_a_glossy_sphere_under_the_sun() {
    let dir = scratch("clamp-sample");
    let output = dir.join("glossy.exr");
    let args = ["--env", "textures/sky.hdr", "--spp", "2", "--clamp-sample", "1"];
    let out = small("glossy", &[&args[..], &["-o", output.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Every sample is at most 1 in every channel, so every pixel, their average, is too.
    let img = linear(&output);
    assert!(img.pixels().all(|p| p.0.iter().all(|&v| v <= 1.0)));
    // Without the clamp the sun's reflections are far brighter than white.
    let unclamped = dir.join("unclamped.exr");
    let out = small("glossy", &[&args[..4], &["-o", unclamped.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(linear(&unclamped).pixels().any(|p| p.0.iter().any(|&v| v > 1.0)));
}

#[test]
fn fov_axis_vertical_keeps_the_height_of_the_picture_when_the_aspect_ratio_changes() {
    // The ray through the middle of the top edge: what the picture shows at its top.
    let top = |args: &[&str], width: u32, height: u32| {
        let (width_text, height_text) = (width.to_string(), height.to_string());
        let size = [&["--width", &width_text, "--height", &height_text][..], args].concat();
        let (scene, _) = common::parse::<fresnel::Options>(&size).prepare().unwrap();
        scene.camera.frame(width, height).get_screen_ray(width as f32 / 2.0, 0.0).dir
    };
    let angle = |a: lecture6::Vector, b: lecture6::Vector| a.cross(b).length().atan2(a.dot(b)).to_degrees();
    // The course's diagonal field of view: at 16:9 the top comes down (the top of the sphere is cut off).
    assert!(angle(top(&[], 640, 480), top(&[], 1920, 1080)) > 3.0);
    // Measured vertically, the top stays where it is at 640 x 480, whatever the width.
    let vertical = ["--fov-axis", "vertical"];
    for (w, h) in [(1920, 1080), (480, 480), (2560, 1080)] {
        let off = angle(top(&[], 640, 480), top(&vertical, w, h));
        assert!(off < 1e-3, "{w}x{h}: {off} degrees");
    }
    // And the picture at 640 x 480 (here 64 x 48, the same aspect ratio) is the course's.
    let plain = common::render::<fresnel::Options>(&["--width", "64", "--height", "48"]);
    for axis in ["vertical", "horizontal"] {
        let other = common::render::<fresnel::Options>(&["--width", "64", "--height", "48", "--fov-axis", axis]);
        let d = lecture6::instruments::compare::difference(&plain.to_rgb8(), &other.to_rgb8()).unwrap();
        assert!(d.max_diff <= 1, "{axis}: {d:?}");
    }
}

#[test]
fn fov_sets_the_angle_from_the_centre_of_the_picture_to_its_corner_or_edge() {
    // The angle between the ray through the picture's centre and the one through (x, y), at 640 x 480.
    let off_centre = |args: &[&str], x: f32, y: f32| {
        let (scene, _) = common::parse::<fresnel::Options>(args).prepare().unwrap();
        let frame = scene.camera.frame(640, 480);
        let (a, b) = (frame.get_screen_ray(320.0, 240.0).dir, frame.get_screen_ray(x, y).dir);
        a.cross(b).length().atan2(a.dot(b)).to_degrees()
    };
    // fresnel's own 90 degrees, and the lecture-6 program's wider framing (its camera scales the image
    // plane by 1.5: 2 atan(1.5) across the diagonal), half of each from the centre to a corner.
    assert!((off_centre(&[], 0.0, 0.0) - 45.0).abs() < 1e-3);
    let course = 2.0 * 1.5f32.atan().to_degrees();
    let wide = off_centre(&["--fov", &course.to_string()], 0.0, 0.0);
    assert!((wide - course / 2.0).abs() < 1e-3, "{wide}");
    // With --fov-axis the angle is measured across that extent: from the centre to the top edge.
    let vertical = off_centre(&["--fov-axis", "vertical", "--fov", "60"], 320.0, 0.0);
    assert!((vertical - 30.0).abs() < 1e-3, "{vertical}");
    // The scene's own angle given again changes nothing.
    let plain = common::render::<fresnel::Options>(&["--width", "64", "--height", "48"]);
    let again = common::render::<fresnel::Options>(&["--width", "64", "--height", "48", "--fov", "90"]);
    assert_eq!(plain.to_rgb8().as_raw(), again.to_rgb8().as_raw());
    // Out of range, as a scene file's `fov`: refused before anything is written.
    for value in ["0", "179.5", "nan", "-30"] {
        let output = scratch("fov").join("refused.png");
        let out = small("fresnel", &["--fov", value, "-o", output.to_str().unwrap()]);
        assert_refused(&out, &[&format!("'{value}' for '--fov <DEGREES>'"), "from 0.0001 to 179 degrees"]);
        assert!(!output.exists());
    }
}

/// README step 3: comparing another version with a reference, without `-o`, keeps the render a student made
/// before at `out/EXAMPLE.png`; the compared picture and its heat map get names of their own.
#[test]
fn compare_without_output_keeps_the_earlier_render() {
    let dir = scratch("keeps-earlier");
    let _ = std::fs::remove_dir_all(dir.join("out"));
    let run = |args: &[&str]| {
        let size = ["--width", "64", "--height", "48", "-q"];
        let out = std::process::Command::new(common::example_binary("fresnel"))
            .args(size.iter().chain(args))
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(out.status.success(), "{args:?}: {}", text(&out.stderr));
    };
    run(&[]);
    let kept = std::fs::read(dir.join("out/fresnel.png")).unwrap();
    let reference = root().join("target/command-line/keeps-earlier-reference.png");
    run(&["--spp", "1", "-o", reference.to_str().unwrap()]);
    run(&["--fresnel", "exact", "--compare", reference.to_str().unwrap()]);
    assert_eq!(std::fs::read(dir.join("out/fresnel.png")).unwrap(), kept, "the earlier render was replaced");
    assert!(dir.join("out/fresnel-compared.png").exists() && dir.join("out/fresnel-compared-diff.png").exists());
}
