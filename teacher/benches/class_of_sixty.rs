//! A class of sixty graded as a teacher grades one, at the default time limit: ten of the class test's
//! made-up submissions (`teacher/tests/submissions/`: a correct copy, water, a compile error, a panic, an
//! endless loop, a billion rays a hit, NaN light, a shader that gains light, 20000 samples by default, a
//! memory hog), each copied six times, graded with `--reference examples/refract.rs` at the command's
//! defaults (320 x 240, each example's own samples). It prints the wall-clock time, the processor time of the
//! class command and everything it ran (user and system), the machine's load, and each row's outcome
//! counted; it fails if a row is not what its kind should give.
//!
//!     cargo bench -p teacher --bench class_of_sixty
//!
//! The library is built for the class first, outside the measurement (a class graded once the library is
//! built: docs/class.md). The class and its contact sheet stay in `target/class-of-sixty/`.

#[path = "../tests/submissions/mod.rs"]
mod submissions;

use std::collections::BTreeMap;
use std::process::Command;
use std::time::{Duration, Instant};

/// How many copies of each kind.
const COPIES: usize = 6;

/// The kinds of the class test left out, so that the class is ten students copied six times: one that
/// writes its picture itself and never finishes (three of the kinds already run away), and the glass and
/// the light that the end-of-run report names (their renders are as short as the reference's).
const LEFT_OUT: [&str; 3] = ["mallory", "ken", "lena"];

fn main() {
    // In the target folder, where the contact sheet stays to be looked at.
    let dir = teacher::target_folder(teacher::workbook()).join("class-of-sixty");
    if dir.exists() {
        std::fs::remove_dir_all(&dir).expect("the last run's folder removed");
    }
    let class = dir.join("hw");
    std::fs::create_dir_all(&class).expect("the class's folder");
    let kinds: Vec<(&str, String)> =
        submissions::submissions().into_iter().filter(|(student, _)| !LEFT_OUT.contains(student)).collect();
    for copy in 1..=COPIES {
        for (student, source) in &kinds {
            std::fs::write(class.join(format!("{student}{copy}.rs")), source).expect("a submission");
        }
    }
    let reference = teacher::workbook().join("examples/refract.rs");
    // The library built for the class, outside the measurement: a class of one, the reference alone.
    let warm = dir.join("warm");
    std::fs::create_dir(&warm).expect("a folder");
    std::fs::write(warm.join("alice.rs"), &kinds[0].1).expect("a submission");
    grade(&warm, &reference, &dir.join("warm-graded"));

    let out = dir.join("graded");
    let load = load_average();
    let (start, before) = (Instant::now(), children_cpu());
    grade(&class, &reference, &out);
    let (wall, cpu) = (start.elapsed(), children_cpu() - before);
    let rows = outcomes(&out.join("gradebook.csv"));
    println!(
        "class of {}: {:.1} s wall, {:.1} s CPU (user + system), load average {} before, {} after",
        kinds.len() * COPIES,
        wall.as_secs_f64(),
        cpu.as_secs_f64(),
        load,
        load_average()
    );
    for (outcome, count) in &rows {
        println!("{count:3} x {outcome}");
    }
    println!("contact sheet: {}", out.join("index.html").display());
}

/// Runs the class command on `class` with the reference `reference` at its defaults, into `out`.
fn grade(class: &std::path::Path, reference: &std::path::Path, out: &std::path::Path) {
    let status = Command::new(env!("CARGO_BIN_EXE_class"))
        .arg(class)
        .arg("--reference")
        .arg(reference)
        .arg("--out")
        .arg(out)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("the class command runs");
    assert!(status.success(), "{status:?}");
}

/// Each row's outcome, by its kind: the student's name without its copy's number, then what its `run` (or
/// its build) says, with the numbers that vary taken out; counted. Panics if two copies of a kind differ.
fn outcomes(gradebook: &std::path::Path) -> BTreeMap<String, usize> {
    let mut table = csv::Reader::from_path(gradebook).expect("the gradebook");
    let header: Vec<String> = table.headers().expect("a header").iter().map(String::from).collect();
    let column = |name: &str| header.iter().position(|h| h == name).expect(name);
    let (student, built, run, psnr) = (column("student"), column("built"), column("run"), column("psnr"));
    let mut kinds: BTreeMap<String, String> = BTreeMap::new();
    let mut counted = BTreeMap::new();
    for record in table.records() {
        let record = record.expect("a row");
        let kind = record[student].trim_end_matches(|c: char| c.is_ascii_digit()).to_string();
        // A panic names the copy's file (`dave3.rs`): named by its kind, the copies' outcomes are one.
        let why = record[run].replace(&format!("{}.rs", &record[student]), &format!("{kind}.rs"));
        let outcome = match (&record[built], why.as_str()) {
            ("no", _) => "does not build".to_string(),
            (_, "ok") if &record[psnr] == "99.00" => "ok, the reference's picture".to_string(),
            (_, "ok") => "ok, another picture".to_string(),
            (_, why) => why.split(": ").next().unwrap_or(why).split(" of ").next().unwrap_or(why).to_string(),
        };
        let outcome = format!("{kind}: {outcome}");
        if let Some(earlier) = kinds.insert(kind.clone(), outcome.clone()) {
            assert_eq!(earlier, outcome, "two copies of {kind} were graded differently");
        }
        *counted.entry(outcome).or_insert(0) += 1;
    }
    counted
}

/// The processor time this process's children (and theirs, waited for) have taken, user and system.
fn children_cpu() -> Duration {
    // SAFETY: an all-zero rusage is a valid value, and getrusage writes only into it.
    #[allow(unsafe_code)]
    let usage = unsafe {
        let mut usage: libc::rusage = std::mem::zeroed();
        libc::getrusage(libc::RUSAGE_CHILDREN, &mut usage);
        usage
    };
    let seconds = |t: libc::timeval| Duration::new(t.tv_sec as u64, t.tv_usec as u32 * 1000);
    seconds(usage.ru_utime) + seconds(usage.ru_stime)
}

/// The machine's load average over the last minute, as Linux says it.
fn load_average() -> String {
    let text = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    text.split_whitespace().next().unwrap_or("?").to_string()
}
