//! The class command on a folder of made-up submissions, one of each kind, all copies of
//! `examples/refract.rs` (the teacher's reference): unchanged, a changed scene, not compiling, panicking,
//! looping, a runaway sample count, NaN light from a shader, a shader that gains energy, a memory hog, 20000
//! samples by default, one that writes its picture itself and never finishes, a glass passing 9 times the
//! light and a light of NaN intensity. Each row of the gradebook says what
//! happened to that student, and nothing that happened to one stopped another; the renders are stopped at
//! the default time limit, derived from the reference's own run, and leave no temporary file.
//!
//! A second test grades exercise files: a right answer, one that loops forever, one that does not compile.
//!
//! They build real submissions against the workbook (a few seconds each, after one build of the library for
//! the class; the exercises' grader in a handed-out copy, once, in the release profile) and wait out time
//! limits, so they are run on their own: `cargo test --release -p teacher --test class -- --ignored`
//! (`.ci/run` does). They run one at a time: they share the target folder.

mod submissions;

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::sync::Mutex;

/// Held by each test from start to end: cargo builds one package at a time in a target folder, so a build
/// waiting for the other test's would count against its time limit; and the exercises' test builds its
/// handed-out copy's library in the target folder whose libraries the other test counts.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Takes [`ONE_AT_A_TIME`] for the rest of a test.
fn alone() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner())
}

/// The builds of the library in the workbook's target folder (one file per build: cargo names each by
/// what it was built with).
fn libraries(workbook: &Path) -> Vec<String> {
    let deps = teacher::target_folder(workbook).join("release").join("deps");
    let files = std::fs::read_dir(deps).expect("the target folder's dependencies").flatten();
    let mut names: Vec<String> = files
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| name.starts_with("liblecture6-") && name.ends_with(".rlib"))
        .collect();
    names.sort();
    names
}

/// Runs the class command on the folder `class` with `options`, its output into `out`.
fn run_class(class: &Path, out: &Path, options: &[&str]) {
    let status = Command::new(env!("CARGO_BIN_EXE_class"))
        .arg(class)
        .args(options)
        .arg("--out")
        .arg(out)
        .status()
        .expect("the class command runs");
    assert!(status.success(), "{status:?}");
}

#[test]
#[ignore = "builds and runs thirteen submissions (about two minutes): cargo test --release -p teacher --test class -- --ignored"]
fn every_kind_of_submission_gets_its_own_row() {
    let _alone = alone();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let class = dir.path().join("hw");
    std::fs::create_dir(&class).expect("the class's folder");
    for (student, source) in submissions::submissions() {
        std::fs::write(class.join(format!("{student}.rs")), source).expect("a submission");
    }
    let out = dir.path().join("graded");
    let reference = teacher::workbook().join("examples/refract.rs");
    let reference = reference.to_string_lossy();
    let options =
        ["--reference", &reference, "--width", "160", "--height", "120", "--spp", "4", "--memory-limit", "1024"];
    // The library as the workbook's examples build it: the class builds against that very build.
    let workbook = teacher::workbook();
    let built = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .args(["build", "--release", "--example", "refract", "--manifest-path"])
        .arg(workbook.join("Cargo.toml"))
        .env("CARGO_TARGET_DIR", teacher::target_folder(workbook))
        .status()
        .expect("cargo runs");
    assert!(built.success(), "{built:?}");
    let libraries_before = libraries(workbook);
    run_class(&class, &out, &options);
    let rows = gradebook(&out.join("gradebook.csv"));
    let row = |student: &str| rows.get(student).unwrap_or_else(|| panic!("no row for {student}"));
    // No second build of the library, and no submission left in the workbook's examples.
    assert_eq!(libraries(workbook), libraries_before, "the class built the library again");
    let left = std::fs::read_dir(workbook.join("examples")).expect("the examples").flatten();
    let left: Vec<_> = left.filter(|e| e.path().join("main.rs").exists()).map(|e| e.file_name()).collect();
    assert!(left.is_empty(), "submissions left in the workbook's examples: {left:?}");

    // Unchanged: the reference's picture exactly.
    assert_eq!((row("alice")["run"].as_str(), row("alice")["psnr"].as_str()), ("ok", "99.00"));
    assert_eq!(row("alice")["rmse"], "0.000");
    // A changed scene: a picture, not the reference's.
    assert_eq!(row("bob")["run"], "ok");
    assert!(row("bob")["psnr"].parse::<f64>().expect("a PSNR") < 40.0, "{:?}", row("bob"));
    // Not compiling: the compiler's first error, by the file's name.
    assert_eq!(row("carol")["built"], "no");
    assert!(row("carol")["first_error"].starts_with("carol.rs:"), "{:?}", row("carol"));
    assert!(row("carol")["first_error"].contains("error[E0425]: cannot find value `eight`"), "{:?}", row("carol"));
    assert_eq!(row("carol")["run"], "");
    // Panicking: the panic's message, and where.
    assert!(row("dave")["run"].starts_with("panicked at dave.rs:"), "{:?}", row("dave"));
    assert!(row("dave")["run"].ends_with(": the glass is not ready"), "{:?}", row("dave"));
    // Looping, a runaway sample count, and a write that never ends: stopped at the default time limit, the
    // floor's here (the reference renders 160 x 120 in a fraction of a second), which every row states.
    let limit = &row("alice")["time_limit"];
    assert!(
        limit.starts_with("5 s of processor time (10 x the reference's 0.") && limit.ends_with(" s, at least 5 s)")
    );
    assert!(rows.values().all(|fields| fields["run"].is_empty() || fields["time_limit"] == *limit), "{limit}");
    for student in ["erin", "frank", "mallory"] {
        assert_eq!(row(student)["run"], "stopped at the time limit of 5 s of processor time", "{student}");
        let cpu: f64 = row(student)["cpu_seconds"].parse().expect("its processor time");
        assert!(cpu >= 5.0, "{student} was stopped after {cpu} s of processor time");
    }
    // Mallory was stopped in the middle of writing her picture: no temporary file of it is left.
    let left: Vec<_> = std::fs::read_dir(out.join("pictures"))
        .expect("the pictures")
        .flatten()
        .map(|entry| entry.file_name().to_string_lossy().into_owned())
        .filter(|name| name.starts_with('.') || name.contains("mallory"))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    // Defaults unlike the reference's, read from the programs: Bob's water, Kate's 20000 samples, which the
    // class's --spp 4 hid from her picture.
    assert_eq!(row("bob")["settings"], "--ior 1.33 (the reference's 1.5)");
    assert_eq!(row("kate")["settings"], "--spp 20000 (the reference's 4)");
    assert_eq!((row("kate")["run"].as_str(), row("kate")["psnr"].as_str()), ("ok", "99.00"));
    assert_eq!(row("alice")["settings"], "");
    // NaN light: the end-of-run report's warning.
    assert_eq!(row("grace")["run"], "ok");
    assert!(row("grace")["warnings"].contains("sample(s) came back NaN or infinite"), "{:?}", row("grace"));
    // A glass passing 9 times the light, and a NaN light: each named by what caused it.
    assert_eq!(row("ken")["run"], "ok");
    assert!(
        row("ken")["warnings"].contains("a mirror's or a glass's multiplier is outside 0 to 1"),
        "{:?}",
        row("ken")
    );
    assert!(row("ken")["warnings"].contains("Refraction multiplier 9"), "{:?}", row("ken"));
    let lena = &row("lena")["run"];
    assert!(lena.contains("invalid light 0") && lena.contains("intensity NaN"), "{:?}", row("lena"));
    assert_eq!(row("lena")["settings"], "", "a scene that was not built has no settings to compare");
    // A memory hog: stopped at the memory limit.
    assert!(row("ivan")["run"].starts_with("stopped at the memory limit of 1024 MiB"), "{:?}", row("ivan"));
    // Every row's warnings are the warnings its run printed, one each: the shader that gains energy's too,
    // whatever the end-of-run report finds to say of it.
    assert_eq!(row("heidi")["run"], "ok");
    for (student, fields) in &rows {
        let printed = std::fs::read_to_string(out.join(&fields["log"])).unwrap_or_default();
        let warnings: Vec<&str> =
            printed.lines().filter_map(|l| l.split_once(": warning: ")).map(|(_, w)| w.trim()).collect();
        assert_eq!(fields["warnings"], warnings.join(" | "), "{student}");
    }
    // Every row of the contact sheet, and a picture beside the reference for those that rendered.
    let sheet = std::fs::read_to_string(out.join("index.html")).expect("the contact sheet");
    for (student, fields) in &rows {
        assert!(sheet.contains(&format!("<h2>{student}</h2>")), "{student}");
        assert!(sheet.contains(&format!("\">{student}</a></td>")), "{student} is not in the summary");
        if fields["run"] == "ok" {
            assert!(out.join(&fields["picture"]).exists(), "{student}'s picture");
            assert!(sheet.contains(&format!("src=\"{}\"", fields["picture"])), "{student}'s picture on the sheet");
        }
    }
    assert!(out.join("pictures/reference.png").exists());
}

#[test]
#[ignore = "builds the exercises' grader in a handed-out copy (minutes, once): cargo test --release -p teacher --test class -- --ignored"]
fn exercise_files_are_graded_in_a_handed_out_copy_each_under_its_time_limit() {
    let _alone = alone();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let class = dir.path().join("exercises");
    let workbook = teacher::workbook();
    let blank = std::fs::read_to_string(workbook.join("exercises/src/refract.rs")).expect("the blank");
    let submissions = [
        ("judy/refract.rs", submissions_solution(workbook)),
        ("kim/exercises/src/refract.rs", blank.replace("todo!(\"refract\")", "loop {}")),
        ("lee/src/refract.rs", blank.replace("todo!(\"refract\")", "i * eta1_over_eta2 +")),
    ];
    for (file, source) in submissions {
        let path = class.join(file);
        std::fs::create_dir_all(path.parent().expect("a folder")).expect("the student's folder");
        std::fs::write(path, source).expect("a submission");
    }
    let out = dir.path().join("graded");
    run_class(&class, &out, &["--exercises", "refract", "--exercise-time-limit", "5"]);
    let rows = gradebook(&out.join("gradebook.csv"));
    let row = |student: &str| rows.get(student).unwrap_or_else(|| panic!("no row for {student}"));
    assert_eq!(row("judy")["exercises_passed"], "1/1", "{:?}", row("judy"));
    assert!(row("judy")["refract"].starts_with("passed: every fact holds"), "{:?}", row("judy"));
    assert_eq!(row("kim")["exercises_passed"], "0/1", "{:?}", row("kim"));
    assert!(row("kim")["refract"].starts_with("FAILED: stopped at its time limit of 5 s"), "{:?}", row("kim"));
    assert!(row("lee")["exercises_passed"].starts_with("exercises/src/refract.rs:"), "{:?}", row("lee"));
    assert!(row("lee")["exercises_passed"].contains(": error"), "{:?}", row("lee"));
    // No example, nothing built or run for them.
    assert!(rows.values().all(|fields| fields["built"].is_empty() && fields["run"].is_empty()));
    // Each student's files compiled the exercises' crate and the grader again, and never the library: it
    // does not depend on the students' crate.
    let logs: Vec<String> = std::fs::read_dir(out.join("logs"))
        .expect("the logs")
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().ends_with(".exercises.txt"))
        .map(|e| std::fs::read_to_string(e.path()).expect("a log"))
        .collect();
    assert_eq!(logs.len(), 3);
    for log in &logs {
        assert!(log.contains("Compiling exercises"), "{log}");
        assert!(!log.contains("Compiling lecture6"), "{log}");
    }
    // In that copy, `draw` renders an example with the student's function, and stops at the blank.
    let copy = out.join("grading");
    let draw = |answer: &str| {
        std::fs::write(copy.join("exercises/src/refract.rs"), answer).expect("the student's file");
        Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
            .args(["run", "-q", "--release", "-p", "exercises", "--example", "draw", "--manifest-path"])
            .arg(copy.join("Cargo.toml"))
            .args(["--", "refract", "--width", "32", "--height", "24", "--spp", "1", "--output"])
            .arg(dir.path().join("drawn.png"))
            .env("CARGO_TARGET_DIR", teacher::target_folder(workbook))
            .output()
            .expect("cargo runs")
    };
    let drawn = draw(&submissions_solution(workbook));
    assert!(drawn.status.success(), "{}", String::from_utf8_lossy(&drawn.stderr));
    assert!(dir.path().join("drawn.png").exists());
    let blank_drawn = draw(&blank);
    assert!(!blank_drawn.status.success());
    assert!(String::from_utf8_lossy(&blank_drawn.stderr).contains("not yet implemented: refract"));
}

/// The reference solution of `refract`, a right answer.
fn submissions_solution(workbook: &Path) -> String {
    std::fs::read_to_string(workbook.join("exercises/src/solutions/refract.rs")).expect("the answer")
}

/// The gradebook's rows by student, each as its fields by column.
fn gradebook(path: &Path) -> HashMap<String, HashMap<String, String>> {
    let mut table = csv::Reader::from_path(path).expect("the gradebook");
    let header: Vec<String> = table.headers().expect("a header").iter().map(String::from).collect();
    table
        .records()
        .map(|record| {
            let fields: HashMap<String, String> =
                header.iter().cloned().zip(record.expect("a row").iter().map(String::from)).collect();
            (fields["student"].clone(), fields)
        })
        .collect()
}
