//! Bad input gives one line naming the file or value and exit code 2; nothing panics, and an earlier output
//! is never destroyed.

mod common;

use common::run_example;

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
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
        (&["--spp", "0"][..], "samples per pixel 0"),
        (&["--width", "0"][..], "image size 0x480"),
        (&["--width", "100000", "--height", "100000"][..], "image size 100000x100000"),
        (&["--threads", "0"][..], "thread count 0"),
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
