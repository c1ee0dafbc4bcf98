//! `--window`: in a build without the viewer it says in one line how to get it; with the viewer but no
//! display (none set, or one that cannot be reached) it says so in one line (`no display: ...`). Either way
//! it exits with code 2 and no panic. Cargo builds the examples with the features the tests are built with,
//! so `cargo test` checks the first message and `cargo test --features viewer` the second (`.ci/run` runs
//! both).

use crate::common;

use common::example_binary;
use std::process::Command;

/// What a build without the viewer says.
const NO_VIEWER: &str = "fresnel: --window needs the viewer: cargo run --release --features viewer";

/// Runs `fresnel --window` with `DISPLAY` set to `display` (unset for `None`) and no Wayland display, and
/// checks that it fails in one line saying `expected`, or, in a build without the viewer, how to get it.
fn fails_in_one_line(display: Option<&str>, expected: &str) {
    let mut command = Command::new(example_binary("fresnel"));
    command.args(["--window", "--width", "32", "--height", "24"]).env_remove("WAYLAND_DISPLAY");
    match display {
        Some(display) => command.env("DISPLAY", display),
        None => command.env_remove("DISPLAY"),
    };
    let out = command.current_dir(common::root()).output().expect("run the example");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "one line: {stderr}");
    let expected = if cfg!(feature = "viewer") { expected } else { NO_VIEWER };
    assert!(stderr.starts_with(expected), "expected '{expected}': {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn without_a_display_the_window_fails_in_one_clear_line() {
    fails_in_one_line(None, "fresnel: no display: DISPLAY is not set");
}

#[test]
fn a_display_that_cannot_be_reached_fails_in_one_clear_line() {
    // A display number no X server listens on.
    fails_in_one_line(Some(":4095"), "fresnel: no display: cannot open a window on DISPLAY=:4095: ");
}
