//! The class command on a folder of made-up submissions, one of each kind, all copies of
//! `examples/refract.rs` (the teacher's reference): unchanged, a changed scene, not compiling, panicking,
//! looping, a runaway sample count, NaN light, a shader that gains energy, a memory hog. Each row of the
//! gradebook says what happened to that student, and nothing that happened to one stopped another.
//!
//! A second test grades exercise files: a right answer, one that loops forever, one that does not compile.
//!
//! They build real submissions against the workbook (a few seconds each, after one build of the library for
//! the class; the exercises' grader in a handed-out copy, once, in the dev profile) and wait out time
//! limits, so they are run on their own: `cargo test --release -p teacher --test class -- --ignored`
//! (`.ci/run` does). They run one at a time: they share the target folder.

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::sync::Mutex;

/// Held by each test while it runs the class command: cargo builds one package at a time in a target
/// folder, and a build waiting for the other test's would count against its time limit.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Runs the class command on the folder `class` with `options`, its output into `out`.
fn run_class(class: &Path, out: &Path, options: &[&str]) {
    let _alone = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let status = Command::new(env!("CARGO_BIN_EXE_class"))
        .arg(class)
        .args(options)
        .arg("--out")
        .arg(out)
        .status()
        .expect("the class command runs");
    assert!(status.success(), "{status:?}");
}

/// The time limit of each render: long enough for the real ones on a busy machine, the wait of the two
/// that never end.
const TIME_LIMIT: &str = "10";

/// The workbook's refraction example, with `from` replaced by `to` (which must be there), and `more`
/// added at the end.
fn refract_with(from: &str, to: &str, more: &str) -> String {
    let example = std::fs::read_to_string(teacher::workbook().join("examples/refract.rs")).expect("the example");
    assert!(example.contains(from), "examples/refract.rs has no {from:?}");
    format!("{}{more}", example.replacen(from, to, 1))
}

/// A copy of the example whose glass is the shader `name`, defined in `definition`.
fn with_shader(name: &str, definition: &str) -> String {
    refract_with(
        "let glass = Arc::new(Refraction::new(self.ior, 0.95));",
        &format!("let glass = Arc::new({name});"),
        definition,
    )
}

/// The start of the example's `scene`, where a student's first line goes.
const SCENE: &str = "    fn scene(&self) -> Result<Scene> {\n";

/// The submissions, by student.
fn submissions() -> Vec<(&'static str, String)> {
    vec![
        ("alice", refract_with("", "", "")),
        ("bob", refract_with("default_value_t = 1.5", "default_value_t = 1.33", "")),
        ("carol", refract_with("scene.max_depth = 8;", "scene.max_depth = eight;", "")),
        (
            "dave",
            refract_with(
                SCENE,
                &format!(
                    "{SCENE}        if self.ior > 0.0 {{\n            panic!(\"the glass is not ready\");\n        }}\n"
                ),
                "",
            ),
        ),
        (
            "erin",
            refract_with(
                SCENE,
                &format!("{SCENE}        while self.ior > 0.0 {{\n            std::hint::spin_loop();\n        }}\n"),
                "",
            ),
        ),
        (
            "frank",
            with_shader(
                "Runaway",
                "\n/// A mirror averaging a billion rays at every hit.\nstruct Runaway;\n\nimpl Shader for Runaway {\n    \
                 fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {\n        \
                 let normal = faceforward(info.normal, ray.dir);\n        let mut sum = Color::BLACK;\n        \
                 for _ in 0..1_000_000_000u32 {\n            sum += ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), 1.0));\n        \
                 }\n        sum * 1e-9\n    }\n}\n",
            ),
        ),
        (
            "grace",
            with_shader(
                "Dark",
                "\n/// A shader whose light is 0/0.\nstruct Dark;\n\nimpl Shader for Dark {\n    \
                 fn shade(&self, _ray: &Ray, info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {\n        \
                 let nothing = info.distance - info.distance;\n        Color::gray(nothing / nothing)\n    }\n}\n",
            ),
        ),
        (
            "heidi",
            with_shader(
                "Brighter",
                "\n/// A mirror that gives back half as much light again as it receives.\nstruct Brighter;\n\n\
                 impl Shader for Brighter {\n    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {\n        \
                 let normal = faceforward(info.normal, ray.dir);\n        \
                 ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), 1.5)) * 1.5\n    }\n}\n",
            ),
        ),
        (
            "ivan",
            refract_with(
                SCENE,
                &format!(
                    "{SCENE}        let hog = vec![1u8; 3 << 30];\n        if hog[hog.len() - 1] == 0 {{\n            \
                     return Err(Error::parameter(\"--ior\", self.ior, \"never\"));\n        }}\n"
                ),
                "",
            ),
        ),
    ]
}

#[test]
#[ignore = "builds and runs nine submissions (about two minutes): cargo test --release -p teacher --test class -- --ignored"]
fn every_kind_of_submission_gets_its_own_row() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let class = dir.path().join("hw");
    std::fs::create_dir(&class).expect("the class's folder");
    for (student, source) in submissions() {
        std::fs::write(class.join(format!("{student}.rs")), source).expect("a submission");
    }
    let out = dir.path().join("graded");
    let reference = teacher::workbook().join("examples/refract.rs");
    let reference = reference.to_string_lossy();
    let options = [
        "--reference",
        &reference,
        "--width",
        "160",
        "--height",
        "120",
        "--time-limit",
        TIME_LIMIT,
        "--memory-limit",
        "1024",
    ];
    run_class(&class, &out, &options);
    let rows = gradebook(&out.join("gradebook.csv"));
    let row = |student: &str| rows.get(student).unwrap_or_else(|| panic!("no row for {student}"));

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
    // Looping, and a runaway sample count: stopped at the time limit.
    let stopped = format!("stopped at the time limit of {TIME_LIMIT} s");
    assert_eq!(row("erin")["run"], stopped);
    assert_eq!(row("frank")["run"], stopped);
    // NaN light: the end-of-run report's warning.
    assert_eq!(row("grace")["run"], "ok");
    assert!(row("grace")["warnings"].contains("sample(s) came back NaN or infinite"), "{:?}", row("grace"));
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
    let dir = tempfile::tempdir().expect("a temporary folder");
    let class = dir.path().join("exercises");
    let workbook = teacher::workbook();
    let blank = std::fs::read_to_string(workbook.join("exercises/src/refract.rs")).expect("the blank");
    let solution = std::fs::read_to_string(workbook.join("exercises/src/solutions/refract.rs")).expect("the answer");
    let submissions = [
        ("judy/refract.rs", solution),
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
