//! Bad input gives one line naming the file or value and exit code 2; nothing panics, and an earlier output
//! is never destroyed.
//!
//! Every bad file (missing, empty, truncated, of the wrong format, or claiming an absurd size) of every kind
//! the examples read (textures, OBJ meshes, equirectangular and cube-map environments), every output path
//! that cannot be written, and every impossible value goes through [`rejected`], which runs the example
//! binary with an earlier picture at its output path and checks all of that.

use crate::common;

use common::run_example;

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A scratch folder for this file's inputs and outputs.
fn scratch() -> PathBuf {
    let dir = common::root().join("target").join("bad-input");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes `bytes` to the scratch file `name` and returns its path as a string.
fn file(name: &str, bytes: &[u8]) -> String {
    let path = scratch().join(name);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).unwrap();
    }
    std::fs::write(&path, bytes).unwrap();
    path.to_str().unwrap().to_owned()
}

/// The first bytes of a valid PNG: the signature and an IHDR chunk for a `width` x `height` RGB image.
fn png_header(width: u32, height: u32) -> Vec<u8> {
    let png = {
        let mut bytes = Vec::new();
        let img = image::RgbImage::from_pixel(width.min(4), height.min(4), image::Rgb([200, 100, 50]));
        img.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png).unwrap();
        bytes
    };
    // Signature (8) + IHDR length and type (8) + IHDR data (13) + CRC (4); rewrite the size and the CRC.
    let mut head = png[..33].to_vec();
    head[16..20].copy_from_slice(&width.to_be_bytes());
    head[20..24].copy_from_slice(&height.to_be_bytes());
    let crc = crc32(&head[12..29]);
    head[29..33].copy_from_slice(&crc.to_be_bytes());
    head
}

/// The CRC-32 of PNG chunks (ISO 3309, polynomial 0xedb88320).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xedb8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// A small valid PNG.
fn png() -> Vec<u8> {
    let mut bytes = Vec::new();
    let img = image::RgbImage::from_pixel(8, 4, image::Rgb([200, 100, 50]));
    img.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png).unwrap();
    bytes
}

/// Runs `example` with `args` (and a small size) writing to a file that holds an earlier picture: the run
/// must exit with code 2 and print one line that contains `needle` (the file or the value at fault) and no
/// panic, and the earlier picture must be untouched.
fn rejected(example: &str, args: &[&str], needle: &str) {
    // Each call has its own file: the tests run in parallel.
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let earlier = scratch().join(format!("earlier-{}.png", CALLS.fetch_add(1, Ordering::Relaxed)));
    std::fs::write(&earlier, b"an earlier picture").unwrap();
    let mut all = vec!["-o", earlier.to_str().unwrap()];
    for (option, value) in [("--width", "16"), ("--height", "12"), ("--spp", "1")] {
        if !args.contains(&option) {
            all.extend([option, value]);
        }
    }
    all.extend_from_slice(args);
    let out = run_example(example, &all);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{example} {args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{example} {args:?}: not one line: {err}");
    assert!(err.contains(needle) && !err.contains("panicked"), "{example} {args:?}: {err} does not name {needle}");
    assert_eq!(std::fs::read(&earlier).unwrap(), b"an earlier picture", "{example} {args:?} touched the output");
}

#[test]
fn a_missing_texture_is_one_line_naming_the_file() {
    let out = run_example("bitmap_textures", &["--texture", "no/such/picture.png", "-o", "target/bad-input/x.png"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("no/such/picture.png") && !err.contains("panicked"), "{err}");
}

#[test]
fn a_file_that_is_not_an_image_is_one_line_naming_it() {
    let out = run_example("bitmap_textures", &["--texture", "Cargo.toml", "-o", "target/bad-input/y.png"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(err.contains("Cargo.toml") && err.trim_end().lines().count() == 1, "{err}");
}

#[test]
fn impossible_values_are_rejected() {
    for (args, needle) in [
        (&["--spp", "0"][..], "'0' for '--spp <SPP>': 0 is not in 1..=65536"),
        (&["--width", "0"][..], "'0' for '--width <WIDTH>'"),
        (&["--width", "100000", "--height", "100000"][..], "image size 100000x100000"),
        (&["--threads", "0"][..], "'0' for '--threads <THREADS>'"),
        (&["--filter", "cubic"][..], "cubic"),
    ] {
        let out = run_example("bitmap_textures", args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(err.contains(needle) && !err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn a_failed_render_keeps_the_earlier_output() {
    let dir = common::root().join("target").join("bad-input");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("keep.png");
    std::fs::write(&path, b"earlier picture").unwrap();
    let out = run_example("bitmap_textures", &["--texture", "missing.png", "-o", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&path).unwrap(), b"earlier picture");
    // An output the image writer cannot produce fails without touching the file either.
    let bad_ext = dir.join("keep.txt");
    std::fs::write(&bad_ext, b"notes").unwrap();
    let out = run_example("bitmap_textures", &["--width", "8", "--height", "8", "-o", bad_ext.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&bad_ext).unwrap(), b"notes");
}

#[test]
fn the_summary_line_reports_the_render() {
    let out = run_example("bitmap_textures", &["--width", "64", "--height", "48", "-o", "target/bad-input/ok.png"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let line = String::from_utf8_lossy(&out.stdout);
    assert!(line.starts_with("bitmap_textures: 64x48, 4 spp,") && line.contains("Mrays/s"), "{line}");
}

#[test]
fn impossible_glossy_values_are_rejected() {
    for (args, needle) in [
        (&["--glossiness", "1.5"][..], "glossiness 1.5"),
        (&["--glossiness=-0.1"][..], "glossiness -0.1"),
        (&["--glossiness", "NaN"][..], "glossiness NaN"),
        (&["--glossy-samples", "0"][..], "glossy samples 0"),
    ] {
        let out = run_example("glossy", args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(err.contains(needle) && err.trim_end().lines().count() == 1, "{args:?}: {err}");
    }
    // An unknown sampler is clap's error, which lists the samplers there are.
    let out = run_example("glossy", &["--sampler", "sobol"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(err.contains("sobol") && err.contains("stratified") && !err.contains("panicked"), "{err}");
}

#[test]
fn bad_texture_files_are_one_line_naming_the_file() {
    let truncated = png()[..40].to_vec();
    for path in [
        file("empty.png", b""),
        file("truncated.png", &truncated),
        file("text.png", b"this is not a picture\n"),
        file("header-only.png", &png_header(8, 4)),
        // A header claiming 2^31 x 2^31 pixels: refused before anything that size is allocated.
        file("absurd.png", &png_header(1 << 31, 1 << 31)),
        file("huge.png", &png_header(100_000, 100_000)),
    ] {
        rejected("bitmap_textures", &["--texture", &path], &path);
        rejected("layered", &["--mask", &path], &path);
    }
}

#[test]
fn bad_obj_files_are_one_line_naming_the_file() {
    for path in [
        "no/such/mesh.obj".to_owned(),
        file("empty.obj", b""),
        file("truncated.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2"),
        file("cut-number.obj", b"v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n"),
        file("picture.obj", &png()),
        file("nan.obj", b"v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"),
        file("inf.obj", b"v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"),
    ] {
        rejected("model_transform", &["--mesh", &path], &path);
    }
}

#[test]
fn bad_environment_files_are_one_line_naming_the_file() {
    let truncated = png()[..40].to_vec();
    for path in [file("empty.hdr", b""), file("truncated-env.png", &truncated), file("text.exr", b"not an image")] {
        rejected("bitmap_textures", &["--env", &path], &path);
    }
    // Cube maps: a folder with every face but one good, the bad face named.
    for (case, bad) in [("empty-face", b"".to_vec()), ("truncated-face", truncated), ("text-face", b"text".to_vec())] {
        for face in ["posx", "negx", "posy", "negy", "posz", "negz"] {
            file(&format!("{case}/{face}.png"), &png());
        }
        let bad_face = file(&format!("{case}/negy.png"), &bad);
        let dir = scratch().join(case);
        rejected("bitmap_textures", &["--env", dir.to_str().unwrap()], &bad_face);
    }
    let missing = scratch().join("five-faces");
    for face in ["posx", "negx", "posy", "negy", "posz"] {
        file(&format!("five-faces/{face}.png"), &png());
    }
    rejected("bitmap_textures", &["--env", missing.to_str().unwrap()], "negz");
}

#[test]
fn an_unwritable_output_is_one_line_naming_it() {
    // The folder cannot be made (a file stands where it should be), or the output is a folder.
    let blocker = file("blocker", b"a file, not a folder");
    let folder = scratch().join("folder.png");
    std::fs::create_dir_all(&folder).unwrap();
    let folder = folder.to_str().unwrap().to_owned();
    for output in [format!("{blocker}/picture.png"), scratch().to_str().unwrap().to_owned(), folder] {
        let out = run_example("bitmap_textures", &["--width", "16", "--height", "12", "-o", &output]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{output}: {err}");
        assert!(err.contains(&output) && err.trim_end().lines().count() == 1 && !err.contains("panicked"), "{err}");
    }
    assert_eq!(std::fs::read(&blocker).unwrap(), b"a file, not a folder");
}

#[test]
fn impossible_common_values_are_rejected_for_every_example() {
    for example in [
        "bitmap_textures",
        "dispersion",
        "environment",
        "fresnel",
        "glossy",
        "layered",
        "model_transform",
        "photon_map",
        "reflect_v01",
        "reflect_v02",
        "refract",
    ] {
        for (args, needle) in [
            (&["--spp", "0"][..], "'0' for '--spp <SPP>': 0 is not in 1..=65536"),
            (&["--width", "0"][..], "'0' for '--width <WIDTH>'"),
            (&["--height", "0"][..], "'0' for '--height <HEIGHT>'"),
            (&["--width", "4294967295", "--height", "4294967295"][..], "image size 4294967295x4294967295"),
            (&["--width", "70000", "--height", "70000"][..], "image size 70000x70000"),
            (&["--threads", "0"][..], "'0' for '--threads <THREADS>'"),
            (&["--wavelengths", "0"][..], "'0' for '--wavelengths <WAVELENGTHS>'"),
            (&["--width", "-5"][..], "-5"),
            (&["--spp", "many"][..], "many"),
            (&["--spectral", "rainbow"][..], "rainbow"),
        ] {
            rejected(example, args, needle);
        }
    }
}

#[test]
fn impossible_glass_is_rejected() {
    for (args, needle) in [
        (&["--glass", "abbe", "--nd", "0"][..], "n_d 0"),
        (&["--glass", "abbe", "--nd=-1.5"][..], "n_d -1.5"),
        (&["--glass", "abbe", "--nd", "NaN"][..], "n_d NaN"),
        (&["--glass", "abbe", "--nd", "inf"][..], "n_d inf"),
        (&["--glass", "abbe", "--abbe", "0"][..], "V_d 0"),
        (&["--glass", "abbe", "--abbe=-20"][..], "V_d -20"),
        (&["--glass", "opal"][..], "opal"),
    ] {
        rejected("dispersion", args, needle);
    }
}

#[test]
fn impossible_ior_multipliers_and_kinds_are_rejected() {
    for (example, args, needle) in [
        ("refract", &["--ior", "0"][..], "ior 0"),
        ("refract", &["--ior=-1.5"][..], "ior -1.5"),
        ("refract", &["--ior", "NaN"][..], "ior NaN"),
        ("refract", &["--ior", "inf"][..], "ior inf"),
        ("reflect_v01", &["--multiplier", "1.5"][..], "multiplier 1.5"),
        ("reflect_v01", &["--multiplier=-0.2"][..], "multiplier -0.2"),
        ("reflect_v02", &["--multiplier", "NaN"][..], "multiplier NaN"),
        ("environment", &["--kind", "cylinder"][..], "cylinder"),
        ("fresnel", &["--ior", "0"][..], "ior 0"),
        ("fresnel", &["--ior=-1.33"][..], "ior -1.33"),
        ("fresnel", &["--ior", "NaN"][..], "ior NaN"),
        ("fresnel", &["--fresnel", "approximate"][..], "approximate"),
        ("layered", &["--lacquer", "1.5"][..], "lacquer 1.5"),
        ("layered", &["--lacquer=-0.5"][..], "lacquer -0.5"),
        ("layered", &["--lacquer", "NaN"][..], "lacquer NaN"),
        ("glossy", &["--glossiness", "1.5"][..], "glossiness 1.5"),
        ("glossy", &["--glossiness=-0.1"][..], "glossiness -0.1"),
        ("glossy", &["--glossiness", "NaN"][..], "glossiness NaN"),
        ("glossy", &["--glossy-samples", "0"][..], "glossy samples 0"),
        ("photon_map", &["--ior", "0"][..], "n_d 0"),
        ("photon_map", &["--ior=-1.5"][..], "n_d -1.5"),
        ("photon_map", &["--abbe", "0"][..], "V_d 0"),
        ("photon_map", &["--radius", "0"][..], "photon radius 0"),
        ("photon_map", &["--radius=-2"][..], "photon radius -2"),
        ("photon_map", &["--radius", "NaN"][..], "photon radius NaN"),
        ("photon_map", &["--k", "0"][..], "photon k 0"),
        ("photon_map", &["--photons", "4000000000"][..], "photon count 4000000000"),
        ("photon_map", &["--photon-passes", "0"][..], "photon passes 0"),
        ("photon_map", &["--photon-passes", "70000"][..], "photon passes 70000"),
        ("photon_map", &["--slide", "--photon-passes", "2"][..], "--photon-passes 2: needs the step photon-grid"),
        ("bitmap_textures", &["--radius", "inf"][..], "photon radius inf"),
    ] {
        rejected(example, args, needle);
    }
}
