//! Hostile input, third round: faults while writing (a closed or full stdout, signals, names at the file
//! system's limit), refused runs that must leave nothing, the options' corners, and scenes and meshes made
//! from the formats' grammars. One test per failure class, each run through the example binaries (within
//! the bounds of `common::hostile` where the run is refused), as in `hostile_input.rs`; the comment of each
//! says what the code before it did.

use crate::common;
use crate::hostile_input::{dir, s};

use std::path::PathBuf;
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
