//! Shared by the integration tests: the registry of the workbook's examples ([`examples`]), rendering an
//! example exactly as `cargo run --example` does, the regression check against `expected/`, and running the
//! example binaries.

#![allow(dead_code)] // each test file uses its own part of this module

use lecture6::app::cli::{Cli, Example};

pub mod caustic;
#[macro_use]
pub mod examples;
pub mod hidden;
pub mod hostile;

use lecture6::instruments::compare::{difference, heat_map};
use lecture6::lesson::diagnostics::Problems;
use lecture6::lesson::frame::Frame;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The package root.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Parses the example's options from `args` as its `main` would.
pub fn parse<E: Example>(args: &[&str]) -> Cli<E> {
    Cli::<E>::parse_args("example", args).unwrap_or_else(|e| panic!("bad test arguments {args:?}: {e}"))
}

/// Parses the example's options from `args` (as its `main` would) and renders it, checking that no camera
/// sample came back NaN or infinite (they are counted before the renderer cleans them).
pub fn render<E: Example>(args: &[&str]) -> Frame {
    let (frame, stats) = parse::<E>(args).render().unwrap_or_else(|e| panic!("{args:?}: {e}"));
    assert_eq!(stats.counters.non_finite_samples, 0, "{args:?}: samples came back NaN or infinite");
    // No problem at all: the energy check counts the hits it weighs, none of which may gain.
    let problems = &stats.counters.problems;
    assert!(problems.energy_gains.iter().all(|g| g.gained == 0), "{args:?}: {:?}", problems.energy_gains);
    let others = Problems { energy_gains: Default::default(), ..problems.clone() };
    assert_eq!(others, Default::default(), "{args:?}: {:?}", stats.warnings);
    // A property of the workbook's own shaders (a student's N-ray shader shares rays below the first bounce).
    assert_eq!(stats.counters.shared_rays, 0, "{args:?}: the workbook's shaders stay within their budget of rays");
    // No example's branch of the ray tree comes near its budget.
    assert_eq!(stats.counters.over_budget_rays, 0, "{args:?}: {:?}", stats.warnings);
    frame
}

/// Renders an example with its default options and compares it with `expected/<name>.png`. On a mismatch the
/// actual picture and a heat map go to `target/regression/`. With `UPDATE_EXPECTED=1` the expected picture
/// is rewritten instead.
pub fn check_expected<E: Example>(name: &str) {
    let actual = render::<E>(&[]).to_rgb8();
    let expected_path = root().join("expected").join(format!("{name}.png"));
    if std::env::var_os("UPDATE_EXPECTED").is_some_and(|v| v == "1") {
        actual.save(&expected_path).expect("write expected image");
        eprintln!("rewrote {}", expected_path.display());
        return;
    }
    let expected = image::open(&expected_path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e} (UPDATE_EXPECTED=1 creates it)", expected_path.display()))
        .to_rgb8();
    let d = difference(&actual, &expected).expect("same size");
    if !d.within_regression_tolerance() {
        let dir = root().join("target").join("regression");
        std::fs::create_dir_all(&dir).expect("create target/regression");
        actual.save(dir.join(format!("{name}.png"))).expect("write actual");
        heat_map(&actual, &expected).unwrap().save(dir.join(format!("{name}-diff.png"))).expect("write heat map");
        panic!("{name} differs from {}: {d}; see target/regression/", expected_path.display());
    }
}

/// Writes `text` to `target/<folder>/<name>` and returns the path: a small input file made by a test.
pub fn temp_file(folder: &str, name: &str, text: &str) -> PathBuf {
    let dir = root().join("target").join(folder);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The path of a built example binary (cargo builds the examples before it runs the tests).
pub fn example_binary(name: &str) -> PathBuf {
    let exe = std::env::current_exe().expect("test binary path");
    let profile_dir = exe.parent().and_then(Path::parent).expect("target/<profile>");
    profile_dir.join("examples").join(format!("{name}{}", std::env::consts::EXE_SUFFIX))
}

/// Runs an example binary with arguments, from the package root.
pub fn run_example(name: &str, args: &[&str]) -> Output {
    Command::new(example_binary(name)).args(args).current_dir(root()).output().expect("run example")
}

/// A direction drawn uniformly from the whole sphere.
pub fn random_unit(rng: &mut lecture6::lesson::rng::Rng) -> lecture6::lesson::math::Vector {
    let z = 1.0 - 2.0 * rng.next_f32();
    let phi = 2.0 * std::f32::consts::PI * rng.next_f32();
    let s = (1.0 - z * z).max(0.0).sqrt();
    lecture6::lesson::math::Vector::new(s * phi.cos(), s * phi.sin(), z)
}

/// The Rust files under `dir`, in order.
pub fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            out.extend(rust_files(&path));
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
    out.sort();
    out
}
