//! Hostile input: files and values made to crash, hang, exhaust memory, pass as a success or write over
//! what was not named as an output. Each test is one case of a fuzzing campaign (numbered as in its report),
//! run through the example binaries within a time and memory bound (`common::hostile`): every one must be
//! refused with one line naming the file (and the line and property, for a scene file) and exit code 2,
//! leaving an earlier output as it was. The big and special files (decompression bombs, FIFOs, a sparse
//! file of gigabytes) are made here at run time.

use crate::common;

use common::hostile::{Run, black_png, fifo, run_bounded, run_bounded_with, scratch};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

const FOLDER: &str = "hostile-input";

pub(crate) fn dir() -> PathBuf {
    scratch(FOLDER)
}

/// Writes `bytes` to `name` in the scratch folder.
pub(crate) fn file(name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let path = dir().join(name);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(&path, bytes).unwrap();
    path
}

pub(crate) fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// The bundled scene file (the fresnel example's scene), its textures found wherever it is written.
pub(crate) fn scene_text() -> String {
    scene_with("", "")
}

/// The bundled scene with `old` replaced by `new` (which must be there), its textures found wherever it is
/// written.
pub(crate) fn scene_with(old: &str, new: &str) -> String {
    let text = std::fs::read_to_string(common::root().join("examples/data/fresnel.qdmg")).unwrap();
    assert!(text.contains(old), "the bundled scene has no {old:?}");
    let text = text.replacen(old, new, 1);
    text.replace("\"../../textures/", &format!("\"{}/", common::root().join("textures").display()))
}

/// The floor's texture file in the bundled scene.
pub(crate) const FLOOR_TEXTURE: &str = "../../textures/floor_tiles.png";

/// The line of the bundled scene file on which `text` starts.
pub(crate) fn line_of(scene: &str, text: &str) -> usize {
    scene[..scene.find(text).unwrap()].matches('\n').count() + 1
}

/// An output path holding an earlier picture, which a refused run must leave as it is.
fn earlier_output() -> PathBuf {
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    file(&format!("earlier-{}.png", CALLS.fetch_add(1, Ordering::Relaxed)), "an earlier picture")
}

/// Runs `example` with `args` at a small size over an earlier output, which must survive.
pub(crate) fn run(example: &str, args: &[&str]) -> (Run, PathBuf) {
    let output = earlier_output();
    (run_to(example, &output, args), output)
}

/// Runs `example` with `args` at a small size, writing to `output`.
pub(crate) fn run_to(example: &str, output: &Path, args: &[&str]) -> Run {
    let mut all = vec!["--width", "32", "--height", "24", "--spp", "1", "-o", s(output)];
    all.extend_from_slice(args);
    run_bounded(example, &all)
}

/// `example` with `args` is refused in one line naming each of `needles`, its earlier output untouched.
pub(crate) fn refused(example: &str, args: &[&str], needles: &[&str]) {
    let (run, output) = run(example, args);
    run.assert_refused(&format!("{example} {args:?}"), needles);
    assert_eq!(std::fs::read(&output).unwrap(), b"an earlier picture", "{example} {args:?} touched the output");
}

/// The scene file `text`, written as `name`, is refused in one line naming it and each of `needles`.
pub(crate) fn scene_refused(name: &str, text: &str, needles: &[&str]) {
    let path = file(name, text);
    refused("scene_file", &[s(&path)], &[&[name][..], needles].concat());
}

#[test]
fn case_1_a_photon_radius_below_the_scenes_resolution_is_refused() {
    // These panicked in the photon grid (an index of 2^63).
    for (example, radius) in [("fresnel", "1e-20"), ("photon_map", "1e-38"), ("refract", "1e-45")] {
        refused(example, &["--photons", "1000", "--radius", radius], &["photon radius", radius, "smallest"]);
    }
}

/// A decompression bomb: a PNG of 16000 x 16000 grey pixels (256 million, in a 1.6 MB file).
fn bomb() -> PathBuf {
    let path = dir().join("bomb.png");
    if !path.exists() {
        std::fs::write(&path, black_png(16000, 16000)).unwrap();
    }
    path
}

#[test]
fn case_2_a_decompression_bomb_is_refused_from_its_header() {
    let bomb = bomb();
    let budget = &lecture6::lesson::image_file::MAX_IMAGE_PIXELS.to_string();
    // It aborted the process as a scene file's texture, and took 3.76 GB as --texture.
    refused("bitmap_textures", &["--texture", s(&bomb)], &[s(&bomb), budget]);
    let scene = scene_with(FLOOR_TEXTURE, s(&bomb));
    scene_refused("bomb-texture.qdmg", &scene, &[&format!("line {}", line_of(&scene, "\tfile")), budget]);
    // --compare decoded the whole bomb only to report a size mismatch.
    refused("fresnel", &["--compare", s(&bomb)], &[s(&bomb)]);
    // Six cube faces of 8192 x 8192 took 2.6 GB.
    let face = black_png(8192, 8192);
    for name in ["posx", "negx", "posy", "negy", "posz", "negz"] {
        file(&format!("cube-8k/{name}.png"), &face);
    }
    refused("bitmap_textures", &["--env", s(&dir().join("cube-8k"))], &["cube-8k/", budget]);
    // The budget is stated where the images are given.
    let help = run_bounded("bitmap_textures", &["--help"]);
    assert!(help.stdout.matches(budget.as_str()).count() >= 3, "--texture, --env and --compare: {}", help.stdout);
}

#[test]
fn case_3_a_chain_of_10000_layered_shaders_is_refused() {
    let chain = |n: usize, used: bool| {
        let mut text = scene_text();
        for i in 0..n {
            text += &format!("Layered L{i} {{\n layer L{} (1, 1, 1)\n}}\n", i + 1);
        }
        text += &format!("Lambert L{n} {{\n color (0.5, 0.5, 0.5)\n}}\n");
        if used {
            text = text.replacen("shader    glass", "shader    L0", 1);
        }
        text
    };
    // It overflowed the loader's stack.
    let long = chain(10_000, false);
    let line = format!("line {}", line_of(&long, "Layered L32 {"));
    scene_refused("chain.qdmg", &long, &[&line, "at most 32 deep"]);
    // As deep as allowed, used by a node: it renders.
    let path = file("chain-32.qdmg", chain(32, true));
    run("scene_file", &[s(&path)]).0.assert_rendered("32 nested Layered shaders");
}

#[test]
fn case_4_a_fifo_is_refused_without_blocking() {
    let pipe = fifo(&dir().join("pipe.png"));
    let obj = fifo(&dir().join("pipe.obj"));
    let scene = fifo(&dir().join("pipe.qdmg"));
    for (example, option, path) in [
        ("bitmap_textures", "--texture", &pipe),
        ("layered", "--mask", &pipe),
        ("bitmap_textures", "--env", &pipe),
        ("model_transform", "--mesh", &obj),
        ("fresnel", "--compare", &pipe),
    ] {
        refused(example, &[option, s(path)], &[s(path), "FIFO"]);
    }
    refused("scene_file", &[s(&scene)], &[s(&scene), "FIFO"]);
    let texture = scene_with(FLOOR_TEXTURE, s(&pipe));
    scene_refused("fifo-texture.qdmg", &texture, &[&format!("line {}", line_of(&texture, "\tfile")), "FIFO"]);
    let mesh = scene_with(
        "Sphere ball {\n\tO  (0, 30, -30)\n\tR  27\n}",
        &format!("Mesh ball {{\n\tfile \"{}\"\n}}", s(&obj)),
    );
    scene_refused("fifo-mesh.qdmg", &mesh, &[&format!("line {}", line_of(&mesh, "\tfile \"")), "FIFO"]);
}

#[test]
fn case_5_endless_and_giant_files_are_refused_from_their_size() {
    // They grew the memory until the machine ran out, or were read whole before the first line was refused.
    refused("scene_file", &["/dev/zero"], &["/dev/zero", "not a regular file"]);
    refused("model_transform", &["--mesh", "/dev/zero"], &["/dev/zero", "not a regular file"]);
    let sparse = dir().join("sparse.qdmg");
    std::fs::File::create(&sparse).unwrap().set_len(3 << 30).unwrap();
    refused("scene_file", &[s(&sparse)], &[s(&sparse), "3221225472 bytes", "16777216"]);
    let obj = dir().join("sparse.obj");
    std::fs::File::create(&obj).unwrap().set_len(1 << 30).unwrap();
    refused("model_transform", &["--mesh", s(&obj)], &[s(&obj), "134217728"]);
    std::fs::remove_file(sparse).unwrap();
    std::fs::remove_file(obj).unwrap();
}

/// A small copy of a bundled texture at `name` in the scratch folder.
fn texture_copy(name: &str) -> PathBuf {
    let path = dir().join(name);
    std::fs::copy(common::root().join("textures/checker8.png"), &path).unwrap();
    path
}

#[test]
fn case_6_no_output_replaces_an_input() {
    let original = std::fs::read(common::root().join("textures/checker8.png")).unwrap();
    let intact = |path: &Path| assert_eq!(std::fs::read(path).unwrap(), original, "{} was replaced", path.display());
    // The picture over the texture or the mask it reads.
    let t = texture_copy("t.png");
    let r = run_to("bitmap_textures", &t, &["--texture", s(&t)]);
    r.assert_refused("-o over --texture", &[s(&t), "the picture"]);
    intact(&t);
    let m = texture_copy("m.png");
    let r = run_to("layered", &m, &["--mask", s(&m)]);
    r.assert_refused("-o over --mask", &[s(&m), "the picture"]);
    intact(&m);
    // The picture over a texture a scene file names.
    let tex = texture_copy("scene-texture.png");
    let scene = file("own-texture.qdmg", scene_with(FLOOR_TEXTURE, s(&tex)));
    let r = run_to("scene_file", &tex, &[s(&scene)]);
    r.assert_refused("-o over the scene's texture", &[s(&tex)]);
    intact(&tex);
    // --compare's heat map, OUTPUT-diff.png, over a texture of that name.
    let reference = dir().join("reference.png");
    run_to("bitmap_textures", &reference, &[]).assert_rendered("the reference");
    let diff = texture_copy("picture-diff.png");
    let picture = dir().join("picture.png");
    let r = run_to("bitmap_textures", &picture, &["--texture", s(&diff), "--compare", s(&reference)]);
    r.assert_refused("the heat map over --texture", &[s(&diff), "the heat map"]);
    intact(&diff);
}

#[test]
fn case_6_a_link_planted_at_the_temporary_name_is_not_followed() {
    // Another user of a shared folder plants a link to a file of yours at the name the picture is first
    // written to. The old name was `.NAME.PID.tmp`: the child plants it with its own process id.
    let victim = file("victim.txt", "a file of yours");
    let output = dir().join("planted.png");
    let _ = std::fs::remove_file(&output);
    let mut link = [0u8; 4096];
    let prefix = format!("{}/.planted.png.", dir().display());
    link[..prefix.len()].copy_from_slice(prefix.as_bytes());
    let target = std::ffi::CString::new(s(&victim)).unwrap();
    let plant = move || {
        // No allocation here: the pid's digits and ".tmp" are written into the buffer on the stack.
        let mut path = link;
        let mut at = prefix_len(&path);
        let pid = std::process::id();
        let mut digits = [0u8; 10];
        let mut n = 0;
        let mut rest = pid;
        loop {
            digits[n] = b'0' + (rest % 10) as u8;
            n += 1;
            rest /= 10;
            if rest == 0 {
                break;
            }
        }
        for k in (0..n).rev() {
            path[at] = digits[k];
            at += 1;
        }
        path[at..at + 5].copy_from_slice(b".tmp\0");
        // SAFETY: both are NUL-terminated paths.
        #[allow(unsafe_code)] // Sound: see the SAFETY comment.
        unsafe {
            libc::symlink(target.as_ptr(), path.as_ptr().cast())
        };
        Ok(())
    };
    let args = ["--width", "32", "--height", "24", "--spp", "1", "-o", s(&output)];
    let r = run_bounded_with("bitmap_textures", &args, plant);
    r.assert_rendered("a picture with a link planted at the temporary name");
    assert_eq!(std::fs::read(&victim).unwrap(), b"a file of yours", "the picture was written through the link");
    assert!(!std::fs::symlink_metadata(&output).unwrap().file_type().is_symlink(), "the picture is a link");
    image::open(&output).expect("the picture is a PNG");
    for entry in std::fs::read_dir(dir()).unwrap().flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with(".planted.png.") {
            std::fs::remove_file(entry.path()).unwrap();
        }
    }
}

/// The length of the NUL-free prefix of `bytes`.
fn prefix_len(bytes: &[u8]) -> usize {
    bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len())
}

#[test]
fn case_7_numbers_that_are_not_finite_as_32_bit_floats_are_refused() {
    // Each was accepted and gave a degenerate picture (black, white, an object gone) reported as success.
    for (name, old, new, property) in [
        ("light-nan", "pos    (120, 180, 0)", "pos    (nan, 50, -50)", "`pos`"),
        ("yaw", "yaw          0", "yaw          1e39", "`yaw` 1e39"),
        ("centre-nan", "O  (0, 30, -30)", "O  (nan, 30, -30)", "`O`"),
        ("radius", "R  27", "R  1e39", "`R` 1e39"),
        ("plane-y", "y      1", "y      1e39", "`y` 1e39"),
        ("ambient-nan", "ambientLight   (0.1, 0.1, 0.1)", "ambientLight   (0.1, nan, 0.1)", "`ambientLight`"),
        ("light-colour-inf", "color  (1, 1, 1)", "color  (1, 1, inf)", "`color`"),
        ("blend-nan", "floor_mirror  (0.02, 0.02, 0.02)", "floor_mirror  (nan, 0.02, 0.02)", "colour"),
        ("rotate-nan", "Node ball {", "Node ball {\n\trotate (nan, 0, 0)", "`rotate"),
    ] {
        let scene = scene_with(old, new);
        let line = format!("line {}", line_of(&scene, new.lines().last().unwrap().trim()));
        scene_refused(&format!("{name}.qdmg"), &scene, &[&line, property]);
    }
}

#[test]
fn fuzz_finding_a_mirror_or_glass_that_amplifies_light_is_refused() {
    // Found by the fuzz target: the glass's Refr multiplier 1e38 (or 1e10) with `maxTraceDepth 2147483647`
    // hung; a surface that gives back more light than it receives keeps its rays from being pruned.
    let refr = "ior         1.6\n\tmultiplier  0.9";
    for (name, old, new, value) in [
        ("refr-1e10", refr, "ior         1.6\n\tmultiplier  1e10", "`multiplier` 10000000000"),
        (
            "refl-negative",
            "Refl glass_reflection {\n\tmultiplier  0.9",
            "Refl glass_reflection {\n\tmultiplier  -0.5",
            "-0.5",
        ),
    ] {
        let scene = scene_with(old, new) + "GlobalSettings {\n maxTraceDepth 2147483647\n}\n";
        let line = format!("line {}", line_of(&scene, new.lines().last().unwrap().trim()));
        scene_refused(&format!("{name}.qdmg"), &scene, &[&line, value, "[0, 1]"]);
    }
}

#[test]
fn case_8_a_mesh_with_nothing_to_render_is_refused() {
    for (name, obj) in [
        ("no-faces", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
        ("nan-vertex", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"),
        ("degenerate", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
    ] {
        let obj = file(&format!("{name}.obj"), obj);
        let scene = scene_with(
            "Sphere ball {\n\tO  (0, 30, -30)\n\tR  27\n}",
            &format!("Mesh ball {{\n\tfile \"{}\"\n}}", s(&obj)),
        );
        let line = format!("line {}", line_of(&scene, "\tfile \""));
        scene_refused(&format!("mesh-{name}.qdmg"), &scene, &[&line, "no triangles"]);
    }
}

#[test]
fn case_9_a_transform_error_names_values_not_types() {
    // The camera 3.5e38 from the origin printed `invalid transform Affine3A { matrix3: Mat3A {...} ...}`.
    let far = scene_with("position     (0, 60, -120)", "position     (3.5e38, 60, -120)");
    let line = format!("line {}", line_of(&far, "\tposition"));
    scene_refused("far-camera.qdmg", &far, &[&line, "`position`", "3.5e38"]);
    // Scales whose product overflows: the whole transform is refused, in numbers.
    let huge = scene_with("Node ball {", "Node ball {\n\tscale (1e20, 1e20, 1e20)");
    let path = file("huge-scale.qdmg", &huge);
    let (r, _) = run("scene_file", &[s(&path)]);
    r.assert_refused("huge scale", &["huge-scale.qdmg", &format!("line {}", line_of(&huge, "Node ball {")), "1e20"]);
    assert!(!r.stderr.contains("Affine") && !r.stderr.contains("Mat3") && !r.stderr.contains('{'), "{}", r.stderr);
}

#[test]
fn case_10_vertical_tab_empty_bitmap_control_characters_cube_faces_and_glossiness_0() {
    // `\v` is white space in the format: the same picture as a space.
    let spaced = file("spaced.qdmg", scene_text());
    let tabbed = file("vertical-tab.qdmg", scene_with("R  27", "R\u{b}27"));
    let (a, b) = (dir().join("spaced.png"), dir().join("vertical-tab.png"));
    let render = |scene: &Path, out: &Path| {
        let args = ["--width", "32", "--height", "24", "--spp", "1", "-q", "-o", s(out), s(scene)];
        run_bounded("scene_file", &args).assert_rendered(s(scene));
        std::fs::read(out).unwrap()
    };
    assert_eq!(render(&spaced, &a), render(&tabbed, &b), "`R\\v27` is `R 27`");

    // A BMP of 0 x 0 pixels is empty, not too large.
    let mut bmp = b"BM".to_vec();
    for v in [54u32, 0, 54, 40, 0, 0] {
        bmp.extend(v.to_le_bytes());
    }
    bmp.extend([1, 0, 24, 0]);
    bmp.extend([0u8; 24]);
    let empty = file("empty.bmp", &bmp);
    let (r, _) = run("bitmap_textures", &["--texture", s(&empty)]);
    r.assert_refused("a 0x0 BMP", &[s(&empty), "no pixels (0x0)"]);
    assert!(!r.stderr.contains("too large"), "{}", r.stderr);

    // Control characters in what an error echoes are escaped: the line cannot rewrite itself.
    let odd = dir().join("odd\rname\u{b}\u{2028}.png");
    let (r, _) = run("bitmap_textures", &["--texture", s(&odd)]);
    r.assert_refused("a texture name with control characters", &["odd\\rname\\u{b}\\u{2028}.png"]);
    let name = file("control.qdmg", scene_with("R  27", "R  x\r\u{1b}[2Kx"));
    let (r, _) = run("scene_file", &[s(&name)]);
    r.assert_refused("a scene line with control characters", &["control.qdmg", "`x\\r\\u{1b}[2Kx`"]);

    // A FIFO or a folder as a cube face is reported as what it is.
    for (case, make) in [("fifo", true), ("folder", false)] {
        let cube = dir().join(format!("cube-{case}"));
        for face in ["posx", "negx", "posy", "negy", "negz"] {
            std::fs::create_dir_all(&cube).unwrap();
            std::fs::copy(common::root().join("textures/checker8.png"), cube.join(format!("{face}.png"))).unwrap();
        }
        let posz = cube.join("posz.png");
        if posz.is_dir() {
            std::fs::remove_dir(&posz).unwrap();
        }
        if make {
            fifo(&posz);
        } else {
            let _ = std::fs::remove_file(&posz);
            std::fs::create_dir(&posz).unwrap();
        }
        let what = if make { "a FIFO" } else { "a folder" };
        refused("bitmap_textures", &["--env", s(&cube)], &[s(&posz), what]);
    }

    // Glossiness 0 (an unbounded cone) is refused on the command line as in a scene file, in the same words.
    refused("glossy", &["--glossiness", "0"], &["invalid glossiness 0: must be above 0"]);
    let gloss = scene_with("Refl floor_mirror {", "Refl floor_mirror {\n\tglossiness 0");
    let line = format!("line {}", line_of(&gloss, "\tglossiness 0"));
    scene_refused("glossiness-0.qdmg", &gloss, &[&line, "invalid glossiness 0: must be above 0"]);
}
