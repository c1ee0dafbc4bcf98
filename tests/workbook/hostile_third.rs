//! Hostile input, third round: faults while writing (a closed or full stdout, signals, names at the file
//! system's limit), refused runs that must leave nothing, the options' corners, and scenes and meshes made
//! from the formats' grammars. One test per failure class, each run through the example binaries (within
//! the bounds of `common::hostile` where the run is refused), as in `hostile_input.rs`; the comment of each
//! says what the code before it did.

use crate::common;
use crate::hostile_files::{encoded, float_picture};
use crate::hostile_input::{dir, file, line_of, refused, run_to, s, scene_refused, scene_with};
use common::hostile::{black_png, run_bounded, run_bounded_in};

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The small render every case starts from.
const SMALL: [&str; 6] = ["--width", "32", "--height", "24", "--spp", "1"];

/// A command running the example binary `name` with `args` from the package root.
fn command(name: &str, args: &[&str]) -> Command {
    let mut command = Command::new(common::example_binary(name));
    command.args(args).current_dir(common::root()).stdin(Stdio::null());
    command
}

/// Runs `name` with `args`, its stdout a pipe whose reader has gone away before anything is written.
fn run_with_closed_stdout(name: &str, args: &[&str]) -> Output {
    let mut child = command(name, args).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

/// A file opened for writing on the full device.
fn full_device() -> std::fs::File {
    std::fs::OpenOptions::new().write(true).open("/dev/full").expect("open /dev/full")
}

/// A fresh empty scratch folder `name`.
fn fresh(name: &str) -> PathBuf {
    let folder = dir().join(name);
    let _ = std::fs::remove_dir_all(&folder);
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

#[test]
fn a_closed_stdout_ends_the_run_quietly_and_a_full_one_is_one_line_and_exit_2() {
    // `| head -1` and `> /dev/full` panicked ("failed printing to stdout", exit code 101), and a refused
    // option with stderr on /dev/full exited 101 instead of 2.
    let folder = fresh("closed-stdout");
    let picture = folder.join("picture.png");
    let render = [&SMALL[..], &["-o", s(&picture)]].concat();
    let trace = [&SMALL[..], &["--trace-pixel", "3,3"]].concat();
    for args in [&render[..], &trace[..]] {
        let out = run_with_closed_stdout("fresnel", args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!((out.status.code(), stderr.as_ref()), (Some(0), ""), "{args:?} with stdout closed");
    }
    assert!(picture.exists(), "the picture is written before the summary");
    for args in [&render[..], &trace[..]] {
        let out = command("fresnel", args).stdout(full_device()).stderr(Stdio::piped()).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?} > /dev/full: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?} > /dev/full: {stderr}");
        assert!(stderr.contains("cannot write to 'standard output'") && !stderr.contains("panicked"), "{stderr}");
    }
    for args in [&["--no-such-option"][..], &["--help"][..]] {
        let full = |stdout: bool| if stdout { Stdio::from(full_device()) } else { Stdio::null() };
        let help = args == ["--help"];
        let out = command("fresnel", args).stdout(full(help)).stderr(full(!help)).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?} with its stream on /dev/full");
    }
}

#[test]
fn a_refused_run_makes_no_folder() {
    // `-o a/b/c/x.png` made a/b/c before the checks that then refused the run.
    let folder = fresh("no-folder");
    let picture = folder.join("a/b/c/x.png");
    let refusals: [&[&str]; 3] =
        [&["--env", "no-such-sky.hdr"], &["--view", "normals", "--env", "no-such-sky.hdr"], &["--ior", "-1"]];
    for args in refusals {
        let r = run_to("fresnel", &picture, args);
        assert_eq!(r.code, Some(2), "{args:?}: {r:?}");
        assert!(!folder.join("a").exists(), "{args:?} made a folder and was refused");
    }
    // A folder the save needs is made when the picture is written.
    run_to("fresnel", &picture, &[]).assert_rendered("-o a/b/c/x.png");
    assert!(picture.exists());
    // A file where a folder should be is named.
    let r = run_to("fresnel", &picture.join("y.png"), &[]);
    r.assert_refused("a file as the folder", &["x.png' is a file, not a folder"]);
}

/// A picture's path in `folder` whose name is `bytes` long.
fn named(folder: &Path, bytes: usize, ext: &str) -> PathBuf {
    folder.join(format!("{}.{ext}", "n".repeat(bytes - 1 - ext.len())))
}

#[test]
fn an_output_name_up_to_the_file_systems_limit_is_written() {
    // A name of 244-255 bytes rendered, then failed: the temporary name was 12 bytes longer, and the
    // check before the render probed with a short name.
    let folder = fresh("long-names");
    for args in [&[][..], &["--side-by-side", "--exposure 1"], &["--view", "normals"]] {
        let picture = named(&folder, 255, "png");
        let _ = std::fs::remove_file(&picture);
        run_to("fresnel", &picture, args).assert_rendered(&format!("{args:?} to a name of 255 bytes"));
        assert!(picture.exists(), "{args:?}");
    }
    let reference = named(&folder, 255, "png");
    // --compare's heat map adds `-diff` to the name: 250 bytes make a heat map of 255, which is written.
    let picture = named(&folder, 250, "png");
    run_to("fresnel", &picture, &["--compare", s(&reference)]).assert_rendered("a heat map of 255 bytes");
    assert!(folder.join(format!("{}-diff.png", "n".repeat(246))).exists());
    // 252 bytes would make one of 257: refused before the render, nothing written.
    let picture = named(&folder, 252, "png");
    let r = run_to("fresnel", &picture, &["--compare", s(&reference)]);
    r.assert_refused("a heat map of 257 bytes", &["-diff.png", "no name of 257 bytes"]);
    assert!(!picture.exists());
    let names = std::fs::read_dir(&folder).unwrap().flatten().map(|e| e.file_name().len());
    assert!(names.filter(|&n| n < 250).count() == 0, "a probe or a temporary file was left behind");
}

/// The entries of `folder` whose names end in `.tmp`.
fn temporary_files(folder: &Path) -> Vec<String> {
    let names = std::fs::read_dir(folder).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned());
    names.filter(|n| n.ends_with(".tmp")).collect()
}

#[test]
fn a_signal_while_the_picture_is_written_leaves_no_temporary_file() {
    // INT, TERM or HUP while a large EXR was written left a temporary file of hundreds of megabytes; so did
    // KILL, and no later run removed it.
    use std::os::unix::process::ExitStatusExt;
    for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP, libc::SIGKILL] {
        let folder = fresh(&format!("signal-{signal}"));
        let picture = folder.join("big.exr");
        std::fs::write(&picture, "an earlier picture").unwrap();
        let args = ["--width", "2048", "--height", "1536", "--spp", "1", "-q", "-o", s(&picture)];
        let mut child = command("fresnel", &args).spawn().unwrap();
        // The temporary file exists from when the render is done until it is renamed.
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                panic!("signal {signal}: the render ended ({status}) before its temporary file was seen");
            }
            if !temporary_files(&folder).is_empty() {
                // SAFETY: kill sends a signal to the child's process id, which it cannot outlive unwaited.
                #[allow(unsafe_code)] // Sound: see the SAFETY comment.
                let sent = unsafe { libc::kill(child.id() as libc::pid_t, signal) };
                assert_eq!(sent, 0);
                break child.wait().unwrap();
            }
            std::thread::sleep(std::time::Duration::from_millis(1));
        };
        assert_eq!(status.signal(), Some(signal), "the run ends by the signal");
        assert_eq!(std::fs::read(&picture).unwrap(), b"an earlier picture", "signal {signal}");
        if signal == libc::SIGKILL {
            // Nothing can be done on KILL: the next save to the same path removes what it left.
            assert_eq!(temporary_files(&folder).len(), 1);
            run_to("fresnel", &picture, &[]).assert_rendered("the run after a KILL");
        }
        assert_eq!(temporary_files(&folder), Vec::<String>::new(), "signal {signal}");
    }
}

#[test]
fn obj_normal_and_texture_coordinate_indices_are_checked_as_vertex_indices_are() {
    // Each loaded without a word, its normals or texture coordinates dropped, where a vertex index out of
    // range was refused with its line.
    let vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (name, faces, needles) in [
        ("no-normals.obj", "f 1//1 2//2 3//3\n", &["line 4", "normal index 1", "has 0 normals"][..]),
        ("no-uvs.obj", "f 1/1 2/1 3/1\n", &["line 4", "texture coordinate index 1", "has 0 texture coordinates"]),
        (
            "uv-before-first.obj",
            "vt 0 0\nf 1/-2 2/-1 3/-1\nvt 1 1\n",
            &["line 5", "index -2", "1 texture coordinates before"],
        ),
    ] {
        let obj = file(name, format!("{vertices}{faces}"));
        refused("model_transform", &["--mesh", s(&obj)], &[&[s(&obj)][..], needles].concat());
    }
    // Every index names an element: the mesh renders.
    let obj = file("all-named.obj", format!("{vertices}vt 0 0\nvn 0 0 1\nf 1/1/1 2/-1/1 3/1/-1\n"));
    run_to("model_transform", &dir().join("all-named.png"), &["--mesh", s(&obj)]).assert_rendered("all named");
}

#[test]
fn scene_file_numbers_are_read_in_the_grammar_of_c_strtod() {
    // A hexadecimal float read as 0 (`power 0x1p3` turned the light off); C's strtod and the course read
    // these as the numbers below.
    let render = |name: &str, changes: &[(&str, &str)]| {
        let scene = changes.iter().fold(scene_with("", ""), |text, (old, new)| text.replacen(old, new, 1));
        let path = file(name, &scene);
        let picture = dir().join(format!("{name}.png"));
        run_to("scene_file", &picture, &[s(&path)]).assert_rendered(name);
        std::fs::read(&picture).unwrap()
    };
    let decimal = render("decimal.qdmg", &[("R  27", "R  27"), ("power  45000", "power  45000")]);
    let hexadecimal = render(
        "hexadecimal.qdmg",
        &[
            ("R  27", "R  0x1.bp4"),
            ("power  45000", "power  0XAFC8p0"),
            ("color  (1, 1, 1)", "color  (0x1p0, 0x.8p1, 1)"),
        ],
    );
    assert_eq!(hexadecimal, decimal, "0x1.bp4 is 27, 0XAFC8p0 is 45000, 0x1p0 and 0x.8p1 are 1");
    // `inf` and `nan` are numbers to strtod, and refused by name at their line.
    for (old, new, needle) in
        [("R  27", "R  inf", "inf"), ("power  45000", "power  -nan", "NaN"), ("R  27", "R  0x1p200", "1.6")]
    {
        let scene = scene_with(old, new);
        scene_refused("not-finite.qdmg", &scene, &[&format!("line {}", line_of(&scene, new)), needle]);
    }
}

#[test]
fn side_by_side_writes_each_panel_as_its_own_options_say() {
    // B was A's picture (RMSE 0) under a caption saying `--exposure 3`; `--tonemap` and `--gamut` were
    // dropped the same way, in B's options and in A's.
    let cases: [(&str, &[&str], &str); 4] = [
        ("fresnel", &[], "--exposure 3"),
        ("fresnel", &["--exposure", "2"], "--exposure 0"),
        ("fresnel", &["--tonemap", "reinhard"], "--tonemap clamp"),
        ("dispersion", &[], "--gamut fit"),
    ];
    for (example, a, b) in cases {
        let picture = dir().join("film-side-by-side.png");
        let r = run_to(example, &picture, &[a, &["--side-by-side", b]].concat());
        r.assert_rendered(&format!("{example} {a:?} --side-by-side {b:?}"));
        let rmse = r.stdout.split("A - B: RMSE ").nth(1).and_then(|t| t.split(' ').next()?.parse::<f64>().ok());
        assert!(rmse.is_some_and(|rmse| rmse > 0.0), "{example} {a:?} and {b:?} give one picture: {}", r.stdout);
    }
}

#[test]
fn the_heat_views_need_a_few_bytes_a_pixel() {
    // `--view rays`, `shadow-rays` and `depth-reached` kept every pixel's ray counters, about 320 bytes a
    // pixel: 1.3 GB at 2048 x 2048, an abort under the 1 GiB bound (21.5 GB at the largest size).
    for view in ["rays", "shadow-rays", "depth-reached"] {
        let picture = dir().join(format!("view-{view}.png"));
        let args = ["--view", view, "--width", "2048", "--height", "2048", "--spp", "1", "-q", "-o", s(&picture)];
        run_bounded("fresnel", &args).assert_rendered(&format!("--view {view} at 2048 x 2048"));
    }
}

#[test]
fn finite_values_that_overflow_when_shaded_are_refused_by_line_or_file() {
    // Each was accepted and ended as "N samples came back NaN": a colour or multiplier times the light's
    // power past 3.4e38, and images whose light a pixel's samples cannot add up.
    for (name, old, new) in [
        ("huge-colour", "Lambert tiles {\n\ttexture  tiles", "Phong tiles {\n\tcolor  (3.4e38, 1, 3.4e38)"),
        (
            "huge-specular",
            "Lambert tiles {\n\ttexture  tiles",
            "Phong tiles {\n\ttexture  tiles\n\tspecularMultiplier 3.4e38",
        ),
    ] {
        let scene = scene_with(old, new);
        let last = new.lines().last().unwrap().trim();
        let needles = [format!("line {}", line_of(&scene, last)), "times the scene's brightest light (45000".into()];
        scene_refused(&format!("{name}.qdmg"), &scene, &needles.iter().map(String::as_str).collect::<Vec<_>>());
    }
    // The bound is what the light allows: a colour of 1e30 under this light renders.
    let scene = scene_with("Lambert tiles {\n\ttexture  tiles", "Phong tiles {\n\tcolor  (1e30, 1, 1)");
    let path = file("large-colour.qdmg", &scene);
    run_to("scene_file", &dir().join("large-colour.png"), &[s(&path)]).assert_rendered("a colour of 1e30");
    // An EXR texel of 3e38, and a Radiance pixel whose exponent byte is 255 (2^119 at least).
    let exr = file("3e38.exr", encoded(float_picture(3e38), image::ImageFormat::OpenExr));
    let mut rgbe = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n".to_vec();
    rgbe.extend([[128, 128, 128, 128]; 7].concat());
    rgbe.extend([128, 128, 128, 255]);
    let hdr = file("exponent-255.hdr", rgbe);
    for (image, value) in [(&exr, "pixel (3, 2) is 3e38"), (&hdr, "pixel (3, 1) is 8.5")] {
        for option in ["--env", "--texture"] {
            refused("bitmap_textures", &[option, s(image)], &[s(image), value, "at most 5.19e33"]);
        }
    }
}

#[test]
fn messages_name_the_real_cause_and_help_states_each_limit() {
    // `-o .png` was told "the name must end in .png".
    let r = run_bounded("fresnel", &[&SMALL[..], &["-o", ".png"]].concat());
    r.assert_refused("-o .png", &["'.png'", "the name before its extension is empty"]);
    // An OBJ near 1e19 got "invalid transform (rows ...)", naming neither --mesh nor the file.
    let obj = file("far.obj", "v 1e19 0 0\nv 0 1e19 0\nv 0 0 1e19\nf 1 2 3\n");
    refused("model_transform", &["--mesh", s(&obj)], &["cannot read mesh", s(&obj), "line 1", "beyond ±1e18"]);
    // An OBJ with classic Mac line ends (a CR alone) got "line 1: color parse error".
    let obj = file("classic-mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
    run_to("model_transform", &dir().join("classic-mac.png"), &["--mesh", s(&obj)]).assert_rendered("CR line ends");
    // Values that begin like an option were taken for options ("unexpected argument '-i' found").
    for (option, value, needle) in [
        ("--exposure", "-inf", "invalid --exposure -inf"),
        ("--clamp-sample", "-inf", "invalid --clamp-sample -inf"),
        ("--trace-pixel", "-1,-1", "'-1,-1' is not a pixel"),
        ("--fov", "-5", "-5 is not a field of view"),
        ("--radius", "-1", "invalid photon radius -1"),
    ] {
        refused("fresnel", &[option, value], &[needle]);
    }
    // --help states each limit, by its number.
    let help = run_bounded("fresnel", &["--help"]).stdout.split_whitespace().collect::<Vec<_>>().join(" ");
    let (fov, pixels) = (lecture6::lesson::camera::FOV_LIMITS, lecture6::lesson::render::MAX_PIXELS);
    for limit in [
        format!("At most {}", lecture6::lesson::scene::RECURSION_SAFETY_CAP),
        "at most 64 with --exhaustive".to_string(),
        format!("{pixels} pixels at most (2^{}", pixels.ilog2()),
        format!("from {} to {}", fov.start(), fov.end()),
        "Errors are still printed, and so is what was asked for: --compare's result".to_string(),
        "Each panel is developed as its own options say (--exposure, --tonemap, --gamut)".to_string(),
    ] {
        assert!(help.contains(&limit), "--help does not say {limit:?}");
    }
}

#[test]
fn a_luminance_only_exr_is_refused_saying_so() {
    // Round two's case: "image does not contain non-deep rgb channels".
    use exr::prelude::*;
    let path = dir().join("luminance.exr");
    let channels = SpecificChannels::build().with_channel("Y").with_pixel_fn(|_: Vec2<usize>| (0.5f32,));
    Image::from_channels((8, 4), channels).write().to_file(&path).unwrap();
    for option in ["--env", "--texture"] {
        refused("bitmap_textures", &[option, s(&path)], &[s(&path), "the channels Y only", "R, G and B"]);
    }
}

/// The bundled scene whose floor is shaded by `levels` Layered shaders: the lowest one's two layers are the
/// floor's Lambert and mirror, and each one above has `width` layers that all name the one below it.
fn shared_layers(levels: usize, width: usize) -> String {
    let layer = |shader: &str| format!("\tlayer  {shader}  (0.5, 0.5, 0.5)\n");
    let mut blocks = format!("Layered L0 {{\n{}{}}}\n", layer("tiles"), layer("floor_mirror"));
    for level in 1..levels {
        blocks += &format!("Layered L{level} {{\n{}}}\n", layer(&format!("L{}", level - 1)).repeat(width));
    }
    let node = "Node floor {\n\tgeometry  floor\n\tshader    ";
    scene_with(&format!("{node}floor"), &format!("{blocks}\n{node}L{}", levels - 1))
}

#[test]
fn layered_shaders_that_share_their_layers_do_bounded_work_per_hit() {
    // 31 levels of two layers naming the same Layered shader below shade 2^32 - 1 shaders at every hit: no
    // result in a minute (killed), and with --trace-pixel the ray tree grew past the memory bound.
    let scene = shared_layers(31, 2);
    // L10 shades 2^12 - 1 = 4095 shaders at a hit; L11's first layer makes 4096, its second 8191.
    let line = line_of(&scene, "Layered L11 {") + 2;
    let needles = [format!("line {line}"), "`L11`".into(), "8191".into(), "at most 4096".into()];
    let needles: Vec<&str> = needles.iter().map(String::as_str).collect();
    scene_refused("shared-layers.qdmg", &scene, &needles);
    let path = file("shared-layers.qdmg", &scene);
    let trace = run_bounded("scene_file", &[s(&path), "--width", "32", "--height", "24", "--trace-pixel", "16,20"]);
    trace.assert_refused("--trace-pixel on shared layers", &needles);
    // A scene that reuses a shader in several layers renders: 4 levels of 3 layers shade 94 shaders a hit.
    let path = file("reused-layers.qdmg", shared_layers(4, 3));
    run_to("scene_file", &dir().join("reused-layers.png"), &[s(&path)]).assert_rendered("reused layers");
}

#[test]
fn a_rust_scene_whose_layers_multiply_the_work_is_refused_naming_its_node() {
    // The same graph built with the API hung as the scene file did: Scene::check counted nothing.
    use lecture6::lesson::render::{RenderSettings, render};
    use lecture6::lesson::shader::MAX_SHADES_PER_HIT;
    use lecture6::prelude::*;
    let lambert: Arc<dyn Shader> = Arc::new(Lambert::new(Color::WHITE));
    let doubled = |levels: usize| {
        (0..levels).fold(lambert.clone(), |below, _| {
            let mut level = Layered::new();
            level.add_layer(below.clone(), Color::gray(0.5), None).add_layer(below, Color::gray(0.5), None);
            Arc::new(level) as Arc<dyn Shader>
        })
    };
    let scene_of = |shader: Arc<dyn Shader>| {
        let mut scene = Scene::new(Camera::default());
        scene.add(Node::new(Sphere::new(Vector::new(0.0, 0.0, 5.0), 1.0), shader).named("layered ball"));
        scene
    };
    let settings = RenderSettings { width: 4, height: 3, ..RenderSettings::default() };
    // 11 levels shade 2^12 - 1 = 4095; one layer more over them 4096, the bound; two more 4097.
    let on_top = |extra: &[Arc<dyn Shader>]| {
        let mut top = Layered::new();
        top.add_layer(doubled(11), Color::gray(0.5), None);
        extra.iter().for_each(|shader| _ = top.add_layer(shader.clone(), Color::gray(0.5), None));
        scene_of(Arc::new(top))
    };
    assert_eq!(MAX_SHADES_PER_HIT, 4096);
    render(&on_top(&[]), &settings).expect("4096 shaders a hit are within the bound");
    for scene in [on_top(std::slice::from_ref(&lambert)), scene_of(doubled(31))] {
        let error = render(&scene, &settings).map(|_| ()).expect_err("refused").to_string();
        assert!(error.contains("layered ball") && error.contains("at most 4096"), "{error}");
    }
}

#[test]
fn the_threads_a_memory_cap_allows_share_one_pool_and_more_are_refused_naming_their_stacks() {
    // Under `ulimit -v 4194304`, `--threads 200` was "invalid thread count 200": the run made two pools of
    // 200 threads, each with a stack of 7.8 MiB.
    const ULIMIT_V: u64 = 4 << 30;
    let picture = dir().join("threads.png");
    let threads = |count: &str| {
        run_bounded_in(ULIMIT_V, "fresnel", &[&SMALL[..], &["--threads", count, "-o", s(&picture)]].concat())
    };
    let r = threads("200");
    r.assert_rendered("--threads 200 under a 4 GiB cap");
    assert!(r.stdout.contains("200 threads"), "{}", r.stdout);
    let r = threads("1000");
    r.assert_refused("--threads 1000 under a 4 GiB cap", &["--threads 1000", "7.8 MiB", "stack", "ulimit -v"]);
    // The count it says fits does.
    let fit = r.stderr.split("at most ").last().and_then(|t| t.split(' ').next()?.parse::<usize>().ok());
    let fit = fit.unwrap_or_else(|| panic!("no count that fits: {}", r.stderr));
    assert!(fit >= 200, "{}", r.stderr);
    threads(&fit.to_string()).assert_rendered(&format!("--threads {fit}, the most that fit"));
}

#[test]
fn a_real_number_beyond_32_bit_floats_is_named_as_it_was_typed() {
    // Round two's case: `--ior 1e308` was "invalid --ior inf"; every option read into an f32 turned a
    // number past 3.4e38 into infinity (and one below 1.4e-45 into 0) before its own check saw it.
    for (example, option, value, reason) in [
        ("fresnel", "--ior", "1e308", "beyond the range of the renderer's 32-bit floats"),
        ("refract", "--ior", "-1e39", "beyond the range"),
        ("photon_map", "--abbe", "4e38", "beyond the range"),
        ("dispersion", "--nd", "1e39", "beyond the range"),
        ("glossy", "--glossiness", "1e-50", "would be read as 0"),
        ("layered", "--lacquer", "1e39", "beyond the range"),
        ("reflect_v01", "--multiplier", "1e39", "beyond the range"),
        ("reflect_v02", "--multiplier", "1e39", "beyond the range"),
        ("fresnel", "--exposure", "1e39", "beyond the range"),
        ("fresnel", "--clamp-sample", "1e39", "beyond the range"),
        ("fresnel", "--radius", "1e-60", "would be read as 0"),
    ] {
        refused(example, &[option, value], &[&format!("'{value}' for '{option}'"), reason]);
    }
    refused("fresnel", &["--side-by-side", "--ior 1e39"], &["'1e39' for '--ior'", "beyond the range"]);
    // `inf` is a value of its own, which the option's check judges (`--abbe inf` is a glass that does not
    // disperse).
    let picture = dir().join("abbe-inf.png");
    run_to("dispersion", &picture, &["--glass", "abbe", "--abbe", "inf"]).assert_rendered("--abbe inf");
}

#[test]
fn the_compare_reference_does_not_take_the_pixel_budget_of_the_scenes_images() {
    // A reference of 8192 x 8192 took the whole budget, and the refusal named the sky's first face as if it
    // were too large: "it is 128x128 = 16384 pixels ... and 67108864 are held already". The reference is
    // decoded only at the render's own size, which has its own limit: it no longer counts against the
    // scene's images. Here the scene loads its sky and textures beside it, and the refusal that remains is
    // the reference's size against the render's, from its header.
    let reference = file("largest.png", black_png(8192, 8192));
    let picture = dir().join("largest-compared.png");
    let args = ["--width", "64", "--height", "48", "--spp", "1", "-o", s(&picture), "--compare", s(&reference)];
    let needles = ["cannot compare with", s(&reference), "it is 8192x8192 and the render would be 64x48"];
    let r = run_bounded("fresnel", &args);
    r.assert_refused("--compare with a reference of 8192 x 8192", &needles);
    assert!(!r.stderr.contains("held already"), "{}", r.stderr);
    assert!(!picture.exists());
}
