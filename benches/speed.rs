//! Speed of this build against an earlier build of the workbook, side by side in one run, against the
//! course's own C++ program, and the cost of a ray against the number of objects in the scene.
//!
//! ```sh
//! cargo build --release --examples               # this build's example binaries
//! cargo bench --bench speed                      # against commit 49c9843, 3 rounds, 1 and 2 threads
//! cargo bench --bench speed -- --base REV --rounds 5 --examples fresnel,glossy
//! cargo bench --bench speed -- --base REV --threads 1 --no-curve --instructions 320x240
//! cargo bench --bench speed -- --base REV --threads 1 --no-curve --rounds 5 --way "" --way --exhaustive --way --slide
//! cargo bench --bench speed -- --course --course-base --base REV --course-cpp /tmp/qd/qd_O2 --rounds 5
//! cargo bench --bench speed -- --course --course-cpp /tmp/qd/qd_O2 --rounds 5   # the course's figures only
//! ```
//!
//! - The earlier build: the commit `--base` is checked out in a worktree at `target/bench-base` and its
//!   examples built there (into `target/bench-base-target`, so this build's binaries stay as they are); both
//!   are kept for the next run. Nothing of it is committed. (`target/` is `CARGO_TARGET_DIR` when set.)
//! - Every example of both builds (the ones both have) is run at its default settings with each thread count,
//!   its picture written under `target/bench-out/`, once for each `--way` (the options it is given: by
//!   default none, its default settings). The runs are interleaved: in each round every example runs
//!   once in each build, the build that goes first alternating from round to round, so that a machine shared
//!   with other work slows both builds alike. Each figure is the median over the rounds.
//! - CPU time is that of the child process (`getrusage(RUSAGE_CHILDREN)`, user plus system), wall time is
//!   the clock around it, and rays are read from the example's summary line
//!   (`NAME: WxH, S spp, T s, N thread(s), R M rays, X Mrays/s -> PATH`), the only output this relies on.
//!   Rays per CPU second compare the builds even where one traces more rays than the other.
//! - With `--instructions WxH`, every example of both builds is also run once under `valgrind
//!   --tool=callgrind` at that size on one thread, and the instructions of the whole process (loading,
//!   rendering, writing the PNG) are divided by the rays it traced: instructions per ray, which do not move
//!   with the machine's load as CPU time does. The rays are read from the summary line, rounded to 10,000
//!   rays: at 320x240 that is within 0.3% for every example. Without valgrind the table says so and the rest
//!   runs as usual.
//! - The course's figures (`--course`: only these; `--no-examples` skips them). The course's C++ (its
//!   lecture-6 program, built headless by `../shared/bench/course-cpp/build.sh REPO OUTDIR`; `--course-cpp
//!   PATH` or `QD_COURSE_CPP`, else skipped with a line saying so) renders the scene of `fresnel`, framed
//!   wider (its camera scales its image plane by 1.5). In each round it runs once in its own folder, and
//!   this build's `fresnel` once each by default, with `--exhaustive` (every ray traced, as the C++ does) and
//!   with `--slide` (the slides' plain code), each at the C++'s framing (`--fov 112.62`: the same picture,
//!   and with `--exhaustive` the same rays) and at its own, all on one thread at 640x480, 5 spp; the C++
//!   goes first in one round and last in the next (with `--course-base`, the earlier build's `fresnel` runs
//!   its six ways in the same rounds, so that both builds' ratios come from one run). Two ratios per
//!   way: whole-process CPU (getrusage of each; the C++'s includes starting SDL and reading its textures,
//!   the workbook's reading its textures and writing the PNG) and render only, wall against wall (the
//!   C++'s own clock around render(), the workbook's summary-line time; on one thread on an idle core
//!   these equal CPU time, on a loaded one they include waiting for a core, alike for both). The C++
//!   prints no ray count; its 8.03 M rays were counted once with a copy of it that counts them. Then
//!   `fresnel` at 1280x960 on 1 thread and on 2, interleaved: wall time at 1 over wall time at 2.
//! - The object-count curve renders, in this process, N small spheres on a plane (the final scene of "Ray
//!   Tracing in One Weekend" has about 500) on one thread, with the scene's BVH over its nodes (`render`) and
//!   with the slides' loop over every node, and reports the CPU time per ray.

#[path = "common/shared.rs"]
mod shared;

use clap::Parser;
use lecture6::lesson::color::Color;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use shared::{cpu_time, median, spheres_scene};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

#[derive(Parser)]
struct Args {
    /// The earlier build's commit (any revision git knows).
    #[arg(long, default_value = "49c9843")]
    base: String,
    /// Rounds of runs (the median is reported).
    #[arg(long, default_value_t = 3)]
    rounds: usize,
    /// Thread counts each example runs with.
    #[arg(long, value_delimiter = ',', default_value = "1,2")]
    threads: Vec<usize>,
    /// Only these examples [default: all that both builds have].
    #[arg(long, value_delimiter = ',')]
    examples: Vec<String>,
    /// The ways every example runs in both builds, each the options it is given (repeatable:
    /// `--way "" --way --exhaustive --way --slide`) [default: its default settings only].
    #[arg(long, allow_hyphen_values = true)]
    way: Vec<String>,
    /// With `--course`: the earlier build's (`--base`) `fresnel` runs its six ways too, interleaved with this
    /// build's and the C++ in every round, and the table gives both builds' ratios.
    #[arg(long)]
    course_base: bool,
    /// Sphere counts of the object-count curve.
    #[arg(long, value_delimiter = ',', default_value = "1,10,100,1000,10000")]
    spheres: Vec<usize>,
    /// Skip the object-count curve (only the examples).
    #[arg(long)]
    no_curve: bool,
    /// Skip the examples (only the curve).
    #[arg(long)]
    no_examples: bool,
    /// Also count instructions per ray under callgrind, at this size (`320x240`), one thread.
    #[arg(long, value_parser = parse_size)]
    instructions: Option<(u32, u32)>,
    /// The course's own C++ program, built headless (`qd_O2`, beside the `data/` it reads) by
    /// `../shared/bench/course-cpp/build.sh REPO OUTDIR` [default: `QD_COURSE_CPP`, else skipped].
    #[arg(long)]
    course_cpp: Option<PathBuf>,
    /// Only the course's figures: `fresnel` against the course's C++ and `fresnel`'s thread scaling (no
    /// earlier build, no curve).
    #[arg(long)]
    course: bool,
    /// Accepted for `cargo bench` compatibility.
    #[arg(long, hide = true)]
    bench: bool,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once('x').ok_or_else(|| format!("{s:?} is not WIDTHxHEIGHT"))?;
    let number = |v: &str| v.parse::<u32>().map_err(|e| format!("{v:?} in {s:?}: {e}"));
    Ok((number(w)?, number(h)?))
}

fn run(what: &str, cmd: &mut Command) -> std::process::Output {
    let out = cmd.output().unwrap_or_else(|e| panic!("cannot run {what}: {e}"));
    if !out.status.success() {
        panic!("{what} failed: {}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    }
    out
}

/// Cargo's target directory: `CARGO_TARGET_DIR` when the build was run with it, else `target/`, where
/// this build's example binaries are.
fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), |dir| root.join(dir))
}

/// The earlier build's example binaries: the commit checked out and built under `target/`.
fn base_build(root: &Path, rev: &str) -> PathBuf {
    let short = run("git", Command::new("git").current_dir(root).args(["rev-parse", "--short", rev]));
    let short = String::from_utf8_lossy(&short.stdout).trim().to_string();
    let tree = target_dir(root).join("bench-base");
    if !tree.exists() {
        run(
            "git worktree add",
            Command::new("git").current_dir(root).arg("worktree").arg("add").arg("--detach").arg(&tree).arg(&short),
        );
    }
    run("git checkout", Command::new("git").current_dir(&tree).args(["checkout", "--quiet", "--detach", &short]));
    let target = target_dir(root).join("bench-base-target");
    eprintln!("building {short}'s examples in {}", tree.display());
    run(
        "cargo build of the earlier build",
        Command::new(env!("CARGO")).current_dir(&tree).env("CARGO_TARGET_DIR", &target).args([
            "build",
            "--release",
            "--examples",
            "--quiet",
        ]),
    );
    target.join("release/examples")
}

/// Where the benchmark's pictures go: `target/bench-out/`.
fn bench_out(root: &Path) -> PathBuf {
    let dir = target_dir(root).join("bench-out");
    std::fs::create_dir_all(&dir).expect("cannot create target/bench-out");
    dir
}

fn example_names(dir: &Path) -> BTreeSet<String> {
    std::fs::read_dir(dir)
        .map(|entries| {
            entries.filter_map(|e| e.ok()?.path().file_stem()?.to_str().map(String::from)).collect::<BTreeSet<_>>()
        })
        .unwrap_or_default()
}

/// One run of a program: the whole process's CPU seconds and wall seconds, the wall seconds of its render
/// (from its own timer), rays.
struct Sample {
    cpu: f64,
    wall: f64,
    render: f64,
    rays: f64,
}

/// Runs a program to its end: its output, its CPU seconds (user + system, from getrusage of the waited-for
/// children) and the wall seconds around it.
fn timed(what: &str, cmd: &mut Command) -> (std::process::Output, f64, f64) {
    let before = cpu_time(libc::RUSAGE_CHILDREN);
    let start = Instant::now();
    let output = run(what, cmd);
    let wall = start.elapsed().as_secs_f64();
    (output, (cpu_time(libc::RUSAGE_CHILDREN) - before).as_secs_f64(), wall)
}

/// One run of an example with `threads` threads and the `extra` options.
fn run_example(bin: &Path, threads: usize, extra: &[&str], out: &Path) -> Sample {
    let (output, cpu, wall) = timed(
        &bin.display().to_string(),
        Command::new(bin).arg("--threads").arg(threads.to_string()).args(extra).arg("--output").arg(out),
    );
    let (render, rays) = summary_of(bin, &output);
    Sample { cpu, wall, render, rays }
}

/// The render's wall seconds and the rays an example traced, from its summary line.
fn summary_of(bin: &Path, output: &std::process::Output) -> (f64, f64) {
    let stdout = String::from_utf8_lossy(&output.stdout);
    stdout
        .lines()
        .find_map(|line| {
            let fields: Vec<&str> = line.split(", ").collect();
            let secs = fields.iter().find_map(|f| f.strip_suffix(" s")?.parse::<f64>().ok())?;
            let rays = fields.iter().find_map(|f| f.strip_suffix(" M rays")?.parse::<f64>().ok())?;
            Some((secs, rays * 1e6))
        })
        .unwrap_or_else(|| panic!("no time and ray count in the summary of {}: {stdout}", bin.display()))
}

/// Instructions of one run of an example with the `extra` options under callgrind, at `size` on one
/// thread, and the rays it traced.
fn count_instructions(bin: &Path, extra: &[String], (width, height): (u32, u32), out: &Path) -> (f64, f64) {
    let output = run(
        &format!("callgrind of {}", bin.display()),
        Command::new("valgrind")
            .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
            .arg(bin)
            .args(extra)
            .args(["--threads", "1", "--width", &width.to_string(), "--height", &height.to_string(), "--output"])
            .arg(out),
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    let instructions = stderr
        .lines()
        .find_map(|line| line.split("Collected : ").nth(1)?.trim().parse::<f64>().ok())
        .unwrap_or_else(|| panic!("no instruction count from callgrind for {}: {stderr}", bin.display()));
    (instructions, summary_of(bin, &output).1)
}

fn valgrind_available() -> bool {
    Command::new("valgrind").arg("--version").output().is_ok_and(|o| o.status.success())
}

/// Medians of one example in one build at one thread count.
#[derive(Clone, Copy)]
struct Figures {
    cpu: f64,
    wall: f64,
    render: f64,
    rays: f64,
}

fn figures(samples: &[Sample]) -> Figures {
    Figures {
        cpu: median(samples.iter().map(|s| s.cpu).collect()),
        wall: median(samples.iter().map(|s| s.wall).collect()),
        render: median(samples.iter().map(|s| s.render).collect()),
        rays: median(samples.iter().map(|s| s.rays).collect()),
    }
}

/// One example run one way: its label in the tables (`fresnel --slide`), its binary's name and its options.
struct Case {
    label: String,
    name: String,
    args: Vec<String>,
}

/// Every example both builds have (or those `--examples` names), each in every `--way`.
fn cases(args: &Args, names: &[String]) -> Vec<Case> {
    let ways = if args.way.is_empty() { vec![String::new()] } else { args.way.clone() };
    names
        .iter()
        .flat_map(|name| {
            ways.iter().map(move |way| Case {
                label: if way.is_empty() { name.clone() } else { format!("{name} {way}") },
                name: name.clone(),
                args: way.split_whitespace().map(String::from).collect(),
            })
        })
        .collect()
}

fn compare_examples(args: &Args, root: &Path) {
    let base_dir = base_build(root, &args.base);
    let new_dir = target_dir(root).join("release/examples");
    let sources = example_names(&root.join("examples"));
    let mut names: Vec<String> =
        example_names(&base_dir).intersection(&sources).filter(|n| new_dir.join(n).exists()).cloned().collect();
    if !args.examples.is_empty() {
        names.retain(|n| args.examples.contains(n));
    }
    assert!(!names.is_empty(), "no examples to compare: run `cargo build --release --examples` first");
    let cases = cases(args, &names);
    let out_dir = bench_out(root);
    let builds = [("base", &base_dir), ("new", &new_dir)];
    // samples[case][thread count][build]
    let mut samples: Vec<Vec<[Vec<Sample>; 2]>> =
        cases.iter().map(|_| args.threads.iter().map(|_| [Vec::new(), Vec::new()]).collect()).collect();
    for round in 0..args.rounds {
        eprintln!("round {} of {}", round + 1, args.rounds);
        for (e, case) in cases.iter().enumerate() {
            let extra: Vec<&str> = case.args.iter().map(String::as_str).collect();
            for (t, &threads) in args.threads.iter().enumerate() {
                for k in 0..2 {
                    let b = (k + round) % 2;
                    let (label, dir) = builds[b];
                    let out = out_dir.join(format!("{}-{e}-{label}-{threads}t.png", case.name));
                    samples[e][t][b].push(run_example(&dir.join(&case.name), threads, &extra, &out));
                }
            }
        }
    }
    println!("\n## Examples: {} (base) against this build, median of {} interleaved rounds\n", args.base, args.rounds);
    println!(
        "| example | threads | base CPU s | new CPU s | CPU ratio | base wall s | new wall s | base Mrays/CPU s | new Mrays/CPU s | rays/CPU s ratio |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut all = Vec::new();
    for (e, case) in cases.iter().enumerate() {
        let per_thread: Vec<[Figures; 2]> = samples[e].iter().map(|s| [figures(&s[0]), figures(&s[1])]).collect();
        for (t, &threads) in args.threads.iter().enumerate() {
            let [b, n] = per_thread[t];
            let (b_rate, n_rate) = (b.rays / b.cpu / 1e6, n.rays / n.cpu / 1e6);
            println!(
                "| {} | {threads} | {:.3} | {:.3} | {:.2}x | {:.3} | {:.3} | {:.2} | {:.2} | {:.2}x |",
                case.label,
                b.cpu,
                n.cpu,
                b.cpu / n.cpu,
                b.wall,
                n.wall,
                b_rate,
                n_rate,
                n_rate / b_rate
            );
        }
        all.push(per_thread);
    }
    if let (Some(one), Some(two)) =
        (args.threads.iter().position(|&t| t == 1), args.threads.iter().position(|&t| t == 2))
    {
        println!("\n## Thread scaling: wall time at 1 thread over wall time at 2 threads\n");
        println!("| example | base | new |");
        println!("|---|---:|---:|");
        for (case, per_thread) in cases.iter().zip(&all) {
            let scaling = |b: usize| per_thread[one][b].wall / per_thread[two][b].wall;
            println!("| {} | {:.2}x | {:.2}x |", case.label, scaling(0), scaling(1));
        }
    }
    if let Some(size) = args.instructions {
        instruction_table(args, &cases, &builds, &all, size, &out_dir);
    }
}

/// Instructions per ray of every example in both builds (callgrind), beside their CPU time on one thread.
fn instruction_table(
    args: &Args,
    cases: &[Case],
    builds: &[(&str, &PathBuf); 2],
    figures: &[Vec<[Figures; 2]>],
    (width, height): (u32, u32),
    out_dir: &Path,
) {
    println!("\n## Instructions per ray: callgrind, {width}x{height}, one thread, the whole process\n");
    if !valgrind_available() {
        println!("valgrind was not found: no instruction counts.");
        return;
    }
    let one = args.threads.iter().position(|&t| t == 1);
    println!(
        "| example | base M instructions | new M instructions | base M rays | new M rays | base instructions/ray | new instructions/ray | ratio | base CPU s (default size, 1 thread) | new CPU s (default size, 1 thread) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (e, case) in cases.iter().enumerate() {
        let [(bi, br), (ni, nr)] = [0, 1].map(|b| {
            let (label, dir) = builds[b];
            eprintln!("callgrind: {} ({label})", case.label);
            let out = out_dir.join(format!("{}-{e}-{label}-callgrind.png", case.name));
            count_instructions(&dir.join(&case.name), &case.args, (width, height), &out)
        });
        let cpu = |b: usize| one.map_or("-".to_string(), |t| format!("{:.3}", figures[e][t][b].cpu));
        println!(
            "| {} | {:.0} | {:.0} | {:.2} | {:.2} | {:.0} | {:.0} | {:.2}x | {} | {} |",
            case.label,
            bi * 1e-6,
            ni * 1e-6,
            br * 1e-6,
            nr * 1e-6,
            bi / br,
            ni / nr,
            (bi / br) / (ni / nr),
            cpu(0),
            cpu(1)
        );
    }
}

/// Rays the course's C++ traces at 640x480, 5 spp, counted as the workbook counts its own
/// (`Counters::total`): it prints no count, so this was counted once with a copy of it that counts every
/// `raytrace()` past its depth test (6,555,602) and every `visibilityCheck()`, its shadow rays (1,470,873).
/// `fresnel --exhaustive` at the C++'s framing ([`course_fov`]) traces 8.03 M too (as its summary line rounds).
const COURSE_CPP_RAYS: f64 = 8_026_475.0;

/// The lecture-6 program's field of view across the diagonal, in degrees. Its camera is given the 90
/// degrees `fresnel`'s is, but scales its image plane by 1.5, so it shows 2 atan(1.5 tan 45) = 2 atan 1.5
/// degrees: `fresnel --fov` this frames the scene as that program does, the sphere smaller.
fn course_fov() -> f64 {
    (2.0 * 1.5f64.atan()).to_degrees()
}

/// One way `fresnel` runs beside the course's C++: its name in the tables and its options.
struct Way {
    name: String,
    args: Vec<String>,
}

/// `fresnel` the ways the course's C++ is compared with: by default, with every ray traced as the C++
/// traces them (`--exhaustive`) and with the slides' plain code (`--slide`); each at the C++'s framing
/// (`--fov`, [`course_fov`]: the same picture's rays, the ratios issue 34's targets are judged by) and at
/// `fresnel`'s own, closer view (more of the picture is glass: more rays).
fn fresnel_ways() -> Vec<Way> {
    let framings = [vec!["--fov".to_string(), course_fov().to_string()], vec![]];
    framings
        .iter()
        .flat_map(|framing| {
            [None, Some("--exhaustive"), Some("--slide")].map(|way| Way {
                name: format!(
                    "fresnel{}{}",
                    if framing.is_empty() { String::new() } else { format!(" --fov {:.2}", course_fov()) },
                    way.map_or(String::new(), |w| format!(" {w}"))
                ),
                args: framing.iter().cloned().chain(way.map(String::from)).collect(),
            })
        })
        .collect()
}

/// The machine's load average over 1, 5 and 15 minutes, as `/proc/loadavg` gives it.
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map_or("unknown".into(), |l| l.split(' ').take(3).collect::<Vec<_>>().join(" "))
}

/// The course's C++: `--course-cpp`, else `QD_COURSE_CPP`.
fn course_cpp(args: &Args) -> Option<PathBuf> {
    args.course_cpp.clone().or_else(|| std::env::var_os("QD_COURSE_CPP").map(PathBuf::from))
}

/// One run of the course's C++ in its own folder (where its `data/` is), headless: the whole process, with
/// the wall seconds of its render() as `render`, and the CPU seconds of its render() it prints
/// (`render() cpu C s wall W s`).
fn run_course_cpp(bin: &Path) -> (Sample, f64) {
    let (output, cpu, wall) = timed(
        &bin.display().to_string(),
        Command::new(bin)
            .current_dir(bin.parent().expect("a file has a folder"))
            .env("SDL_VIDEODRIVER", "dummy")
            .env("QD_NOROWDISPLAY", "1"),
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    let (render_cpu, render) = stdout
        .lines()
        .find_map(|line| {
            let (c, w) = line.split("render() cpu ").nth(1)?.split_once(" s wall ")?;
            Some((c.parse::<f64>().ok()?, w.trim().strip_suffix(" s")?.parse::<f64>().ok()?))
        })
        .unwrap_or_else(|| panic!("no `render() cpu C s wall W s` from {}: {stdout}", bin.display()));
    (Sample { cpu, wall, render, rays: COURSE_CPP_RAYS }, render_cpu)
}

/// The figures the course's scene is tracked by: `fresnel` against the course's C++, if it is there, and
/// `fresnel`'s thread scaling.
fn course_figures(args: &Args, root: &Path) {
    let fresnel = target_dir(root).join("release/examples/fresnel");
    assert!(fresnel.exists(), "no {}: run `cargo build --release --examples` first", fresnel.display());
    let out_dir = bench_out(root);
    let mut builds = vec![("this build".to_string(), fresnel.clone())];
    if args.course_base {
        builds.insert(0, (format!("{} (base)", args.base), base_build(root, &args.base).join("fresnel")));
    }
    match course_cpp(args) {
        Some(cpp) => against_course_cpp(args, &cpp, &builds, &out_dir),
        None => println!(
            "\nThe course's C++: skipped. Build it with `../shared/bench/course-cpp/build.sh REPO OUTDIR` (REPO: a clone of anrieff/quaddamage) and pass `--course-cpp OUTDIR/qd_O2` or set QD_COURSE_CPP."
        ),
    }
    if let Some(cpp) = course_cpp(args) {
        course_look(&cpp, &fresnel, &out_dir);
    }
    fresnel_threads(args, &fresnel, &out_dir);
}

/// The options that give `fresnel` the course's look: the course's forest and floor from its repository
/// (beside its program, in `data/`), its framing, and its raw codes.
fn course_look_args(data: &Path) -> Vec<String> {
    let env = data.join("env/forest").display().to_string();
    let floor = data.join("floor.bmp").display().to_string();
    ["--fov", &format!("{:.2}", course_fov()), "--env", &env, "--env-layout", "course", "--floor", &floor]
        .map(String::from)
        .to_vec()
}

/// The picture the course's C++ writes (`QD_PPM`, its frame as raw 8-bit codes), and `fresnel` given the
/// course's look ([`course_look_args`]) compared with it: PSNR, with `--slide` and by default, with the
/// course's raw codes and with sRGB.
fn course_look(cpp: &Path, fresnel: &Path, out_dir: &Path) {
    let cpp = cpp.canonicalize().unwrap_or_else(|e| panic!("--course-cpp {}: {e}", cpp.display()));
    let folder = cpp.parent().expect("a file has a folder");
    let ppm = out_dir.join("course-cpp.ppm");
    run(
        "the course's C++",
        Command::new(&cpp)
            .current_dir(folder)
            .env("SDL_VIDEODRIVER", "dummy")
            .env("QD_NOROWDISPLAY", "1")
            .env("QD_PPM", &ppm),
    );
    let reference = out_dir.join("course-cpp.png");
    ppm_to_png(&ppm, &reference);
    println!("\n## The course's look: `fresnel` against the picture the course's C++ writes, 640x480, 5 spp\n");
    println!("| fresnel {} and | PSNR against the course's picture |", course_look_args(Path::new("DATA")).join(" "));
    println!("|---|---:|");
    for way in [["--slide", "--encoding", "raw"], ["--encoding", "raw", ""], ["--slide", "--encoding", "srgb"]] {
        let way: Vec<&str> = way.into_iter().filter(|a| !a.is_empty()).collect();
        let out = out_dir.join("fresnel-course-look.png");
        let output = run(
            "fresnel with the course's look",
            Command::new(fresnel)
                .args(course_look_args(&folder.join("data")))
                .args(&way)
                .arg("--compare")
                .arg(&reference)
                .arg("--output")
                .arg(&out),
        );
        let stdout = String::from_utf8_lossy(&output.stdout);
        let psnr = stdout
            .split("PSNR ")
            .nth(1)
            .and_then(|rest| rest.split(" dB").next())
            .unwrap_or_else(|| panic!("no PSNR from fresnel --compare: {stdout}"));
        println!("| {} | {psnr} dB |", way.join(" "));
    }
    println!(
        "\nThe course's picture: its lecture-6 program's frame, written by the bench build's `QD_PPM` dump as \
         its window shows it. `--slide --encoding raw` renders as that program does but for its anti-aliasing \
         (five fixed points of the pixel, against five random ones) and its red for total internal reflection."
    );
}

/// A binary PPM (P6, 8 bits), as the course's C++ writes it, saved as a PNG.
fn ppm_to_png(ppm: &Path, png: &Path) {
    let bytes = std::fs::read(ppm).unwrap_or_else(|e| panic!("{}: {e}", ppm.display()));
    // The header: "P6", width, height, maximum, each after white space, then one white-space byte.
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        fields.push(String::from_utf8_lossy(&bytes[start..at]).to_string());
    }
    assert_eq!((fields[0].as_str(), fields[3].as_str()), ("P6", "255"), "{}: not an 8-bit P6 PPM", ppm.display());
    let number = |f: &str| f.parse::<u32>().unwrap_or_else(|e| panic!("{}: {f}: {e}", ppm.display()));
    let (width, height) = (number(&fields[1]), number(&fields[2]));
    let pixels = bytes[at + 1..].to_vec();
    image::RgbImage::from_raw(width, height, pixels)
        .unwrap_or_else(|| panic!("{}: fewer pixels than {width}x{height}", ppm.display()))
        .save(png)
        .unwrap_or_else(|e| panic!("{}: {e}", png.display()));
}

/// The course's C++ and `fresnel` the six ways of [`fresnel_ways`] in each build (this one, and with
/// `--course-base` the earlier one), on one thread at 640x480, 5 spp, interleaved: in each round each runs
/// once, the C++ first in one round and last in the next.
fn against_course_cpp(args: &Args, cpp: &Path, builds: &[(String, PathBuf)], out_dir: &Path) {
    let cpp = cpp.canonicalize().unwrap_or_else(|e| panic!("--course-cpp {}: {e}", cpp.display()));
    let ways = fresnel_ways();
    // runs[0] is the C++; then every way of every build.
    let runs: Vec<(usize, usize)> = (0..builds.len()).flat_map(|b| (0..ways.len()).map(move |w| (b, w))).collect();
    let (mut cpp_samples, mut cpp_render_cpu) = (Vec::new(), Vec::new());
    let mut samples: Vec<Vec<Sample>> = runs.iter().map(|_| Vec::new()).collect();
    for round in 0..args.rounds {
        eprintln!("the course's C++ and fresnel: round {} of {}", round + 1, args.rounds);
        let mut order: Vec<usize> = (0..=runs.len()).collect();
        if round % 2 == 1 {
            order.reverse();
        }
        for i in order {
            if i == 0 {
                let (sample, render_cpu) = run_course_cpp(&cpp);
                cpp_samples.push(sample);
                cpp_render_cpu.push(render_cpu);
            } else {
                let (b, w) = runs[i - 1];
                let out = out_dir.join(format!("fresnel-course-{b}-{w}.png"));
                let way: Vec<&str> = ways[w].args.iter().map(String::as_str).collect();
                samples[i - 1].push(run_example(&builds[b].1, 1, &way, &out));
            }
        }
    }
    let c = figures(&cpp_samples);
    let c_render_cpu = median(cpp_render_cpu);
    let figures: Vec<Figures> = samples.iter().map(|s| figures(s)).collect();
    let name = |(b, w): (usize, usize)| {
        if builds.len() == 1 { ways[w].name.clone() } else { format!("{} ({})", ways[w].name, builds[b].0) }
    };
    println!(
        "\n## The course's C++ ({}) against `fresnel`: 640x480, 5 spp, one thread, median of {} interleaved rounds\n",
        cpp.display(),
        args.rounds
    );
    println!("| program | process CPU s | process wall s | render CPU s | render wall s | M rays | M rays/render s |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    println!(
        "| the course's C++ | {:.3} | {:.3} | {c_render_cpu:.3} | {:.3} | {:.2} (counted once) | {:.2} |",
        c.cpu,
        c.wall,
        c.render,
        c.rays * 1e-6,
        c.rays * 1e-6 / c.render
    );
    for (&run, w) in runs.iter().zip(&figures) {
        println!(
            "| {} | {:.3} | {:.3} | - | {:.3} | {:.2} | {:.2} |",
            name(run),
            w.cpu,
            w.wall,
            w.render,
            w.rays * 1e-6,
            w.rays * 1e-6 / w.render
        );
    }
    println!(
        "\n| C++ / this (above 1: the workbook takes less) | whole process, CPU | render only, wall | rays, this / C++ |"
    );
    println!("|---|---:|---:|---:|");
    for (&run, w) in runs.iter().zip(&figures) {
        println!("| {} | {:.2}x | {:.2}x | {:.2} |", name(run), c.cpu / w.cpu, c.render / w.render, w.rays / c.rays);
    }
    println!(
        "\nThe lecture-6 program frames the scene wider than `fresnel` does (its camera scales its image plane by \
         1.5): `--fov {:.2}` renders the picture it renders, and `--exhaustive` then traces the rays it traces \
         (the last column), so that those rows compare the same work; at `fresnel`'s own, closer framing more of \
         the picture is glass. Whole process: CPU (user + system, getrusage) of the whole run. The C++'s: \
         starting SDL (dummy driver), building the scene and reading its textures, render(), showing the frame; \
         it writes no file. The workbook's: reading the sky and the floor's texture, building the scene, \
         rendering, writing the PNG. Render only: the C++'s own clock around render() (it prints its CPU and \
         wall time); the workbook's render time from its summary line, a wall time around the render alone. On \
         one thread on an idle core a render's CPU time is its wall time; in this run the C++'s render() had \
         {:.2} s CPU per wall second (1.00 with a core to itself; below, it waited for one), so the render-only \
         ratio compares wall with wall, both runs interleaved on the same machine. The C++'s rays were counted \
         once with a counting copy of it (it prints none); the workbook's are from its summary line, shadow rays \
         included. Load average at the end: {}.",
        course_fov(),
        c_render_cpu / c.render,
        load_average()
    );
}

/// `fresnel` at 1280x960 on one thread against two, interleaved (the order alternating between rounds):
/// wall time at one thread over wall time at two.
fn fresnel_threads(args: &Args, fresnel: &Path, out_dir: &Path) {
    const SIZE: [&str; 4] = ["--width", "1280", "--height", "960"];
    let mut samples: [Vec<Sample>; 2] = [Vec::new(), Vec::new()];
    for round in 0..args.rounds {
        eprintln!("fresnel at 1280x960, 1 and 2 threads: round {} of {}", round + 1, args.rounds);
        for k in 0..2 {
            let t = (k + round) % 2;
            let out = out_dir.join(format!("fresnel-1280-{}t.png", t + 1));
            samples[t].push(run_example(fresnel, t + 1, &SIZE, &out));
        }
    }
    let [one, two] = samples.map(|s| figures(&s));
    println!(
        "\n## Thread scaling: `fresnel --width 1280 --height 960`, 1 thread against 2, median of {} interleaved rounds\n",
        args.rounds
    );
    println!("| threads | process CPU s | process wall s | render wall s | M rays |");
    println!("|---:|---:|---:|---:|---:|");
    for (threads, f) in [(1, one), (2, two)] {
        println!("| {threads} | {:.3} | {:.3} | {:.3} | {:.2} |", f.cpu, f.wall, f.render, f.rays * 1e-6);
    }
    println!(
        "\nWall time at 1 thread over 2 threads: {:.2}x for the whole process, {:.2}x for the render alone \
         (the target: 1.9x). CPU time at 2 threads over 1: {:.2}x. Two threads scale only as far as the \
         machine has a second core free: load average at the end {}.",
        one.wall / two.wall,
        one.render / two.render,
        two.cpu / one.cpu,
        load_average()
    );
}

const CURVE_WIDTH: u32 = 320;
const CURVE_HEIGHT: u32 = 240;

/// CPU seconds and rays of one render of the scene on one thread, with the node BVH.
fn render_with_tree(scene: &Scene) -> (f64, u64) {
    let settings = RenderSettings { width: CURVE_WIDTH, height: CURVE_HEIGHT, threads: Some(1), ..Default::default() };
    let before = cpu_time(libc::RUSAGE_SELF);
    let (_, stats) = render(scene, &settings).expect("render");
    ((cpu_time(libc::RUSAGE_SELF) - before).as_secs_f64(), stats.counters.total())
}

/// The same, testing every node for every ray (the slides' loop: a scene traced directly, without the
/// renderer's BVH), on this thread, one sample through each pixel's centre.
fn render_linear(scene: &Scene) -> (f64, u64) {
    let camera = scene.camera.frame(CURVE_WIDTH, CURVE_HEIGHT);
    let before = cpu_time(libc::RUSAGE_SELF);
    let mut ctx = TraceContext::new(scene, Rng::for_keys(&[1]));
    let mut sum = Color::BLACK;
    for y in 0..CURVE_HEIGHT {
        for x in 0..CURVE_WIDTH {
            sum += ctx.raytrace(&camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5));
        }
    }
    std::hint::black_box(sum);
    ((cpu_time(libc::RUSAGE_SELF) - before).as_secs_f64(), ctx.counters.total())
}

fn object_count_curve(args: &Args) {
    println!(
        "\n## Object count: N spheres on a plane, {CURVE_WIDTH}x{CURVE_HEIGHT}, 1 spp, one thread, median of {} runs\n",
        args.rounds
    );
    println!(
        "| N | BVH ns/ray | BVH Mrays/CPU s | BVH cost / cost at N=10 | loop ns/ray | loop Mrays/CPU s | loop / BVH |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|");
    let mut at_ten = None;
    for &n in &args.spheres {
        let scene = spheres_scene(n);
        let per_ray = |f: &dyn Fn(&Scene) -> (f64, u64)| {
            median((0..args.rounds).map(|_| f(&scene)).map(|(cpu, rays)| cpu / rays as f64).collect())
        };
        let tree = per_ray(&render_with_tree);
        let linear = per_ray(&render_linear);
        if n == 10 {
            at_ten = Some(tree);
        }
        let relative = at_ten.map_or("-".to_string(), |t| format!("{:.2}x", tree / t));
        println!(
            "| {n} | {:.0} | {:.2} | {relative} | {:.0} | {:.2} | {:.1}x |",
            tree * 1e9,
            1e-6 / tree,
            linear * 1e9,
            1e-6 / linear,
            linear / tree
        );
    }
}

fn main() {
    let args = Args::parse();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    if !args.no_examples && !args.course {
        compare_examples(&args, root);
    }
    if !args.no_examples {
        course_figures(&args, root);
    }
    if !args.no_curve && !args.course {
        object_count_curve(&args);
    }
}
