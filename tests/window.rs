//! `--window`: in a build without the viewer it says in one line how to get it; with the viewer but no
//! display it says so in one line (`no display: ...`). Either way it exits with code 2 and no panic.

mod common;

use common::example_binary;
use std::process::Command;

fn window_without_display() -> std::process::Output {
    Command::new(example_binary("fresnel"))
        .args(["--window", "--width", "32", "--height", "24"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .current_dir(common::root())
        .output()
        .expect("run the example")
}

#[test]
fn the_window_fails_in_one_clear_line() {
    let out = window_without_display();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "one line: {stderr}");
    // The example binary in target/ may be from a build with or without the viewer, whichever ran last.
    let said = ["fresnel: no display: ", "--window needs the viewer: cargo run --release --features viewer"];
    assert!(said.iter().any(|s| stderr.contains(s)), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
