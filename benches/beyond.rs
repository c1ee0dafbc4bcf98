//! The ledger of the steps beyond the slides: writes `docs/beyond-the-slides.md`.
//!
//! ```sh
//! cargo bench --bench beyond              # the whole ledger, 3 rounds: docs/beyond-the-slides.md
//! cargo bench --bench beyond -- --quick   # 1 round, fewer points: target/beyond-the-slides.md
//! ```
//!
//! One renderer serves both readings: each step beyond the slides is a setting of the scene
//! (`Scene::steps`, `src/lesson/beyond.rs`), and `--slide` leaves them all out. Each step's row measures the
//! renderer with the step against the same renderer without it (`--no-step NAME`, or the scene's `steps`
//! without it), side by side in this one process: in each round every variant runs once, the order
//! alternating from round to round, so that a machine shared with other work slows both alike; each figure
//! is the median over the rounds. Renders run on one thread; CPU time (`getrusage`, user plus system, the
//! whole process) stands beside the wall time, and the comparisons use the CPU time. Where a step leaves the
//! picture as it is, within a few 8-bit levels (an exact step), the ledger gives the time at equal error;
//! where a step changes the noise it gives the error (RMSE of the linear values against a converged
//! reference of another seed) at equal time, and the time at equal error, both interpolated on the log-log
//! curve of the sweep; there a point's time is its rays times its curve's median CPU time per ray, which is
//! steadier on a loaded machine than one point's median (the tables give each point's own). Steps that no
//! example reaches are timed at unit level (the same rays through `Scene::closest_hit` with and without the
//! step) on a scene where they pay. Where the CPU times of the two sides differ by less than a shared
//! machine's noise, the ledger also counts the instructions of one render of each side (this bench run again
//! under `valgrind --tool=callgrind`, when valgrind is installed): a count does not move with the load.
//! Besides the steps, the ledger has rows for what runs beyond the slides without being a step (the guards,
//! and the deviations from the slides' formulas). Lines of code are the non-blank, non-comment lines of the
//! items that implement each step, listed at the end of the ledger.

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;
#[path = "common/shared.rs"]
mod shared;

use clap::Parser;
use lecture6::app::cli::{Cli, Example};
use lecture6::instruments::compare::difference;
use lecture6::instruments::study::{Measurement, cost_at_rmse, rmse_at_time, rmse_linear};
use lecture6::lesson::beyond::{Step, Steps};
use lecture6::lesson::branching::{RAYS_PER_BRANCH, SECONDARY_SPLIT, SPLIT_DEPTH};
use lecture6::lesson::diagnostics::undeclared_dispersion;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::geometry::Mesh;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::photon_map::all_directions::MAX_BATCHES;
use lecture6::lesson::photon_map::{PhotonMap, PhotonStats};
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, RenderStats, render, thread_pool};
use lecture6::prelude::{Camera, Color, Cube, Environment, Material, Scene, Shader, Shape};
use shared::{cpu_time, median, spheres_scene};
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::sync::Arc;
use std::time::Instant;

#[derive(Parser)]
struct Args {
    /// One round and fewer points, written to target/beyond-the-slides.md instead of docs/.
    #[arg(long)]
    quick: bool,
    /// Rounds of every side-by-side measurement (the median is reported) [default: 3, 1 with --quick].
    #[arg(long)]
    rounds: Option<usize>,
    /// Accepted for `cargo bench` compatibility.
    #[arg(long, hide = true)]
    bench: bool,
    /// Renders one example once with the options that follow its name, and nothing else: the render whose
    /// instructions the ledger counts under callgrind ([`instructions`]).
    #[arg(long, hide = true, num_args = 1.., allow_hyphen_values = true)]
    render_once: Vec<String>,
}

/// How a measurement is sized: the full ledger or a quick look.
struct Plan {
    quick: bool,
    rounds: usize,
}

impl Plan {
    /// `full` in the ledger, `quick` with `--quick`.
    fn pick<T>(&self, full: T, quick: T) -> T {
        if self.quick { quick } else { full }
    }
}

// ---------------------------------------------------------------------------------------------------------
// Running the examples

/// Wall and CPU seconds of the code between `start` and `stop`.
struct Clock {
    wall: Instant,
    cpu: std::time::Duration,
}

impl Clock {
    fn start() -> Clock {
        Clock { wall: Instant::now(), cpu: cpu_time(libc::RUSAGE_SELF) }
    }

    fn stop(&self) -> (f64, f64) {
        (self.wall.elapsed().as_secs_f64(), (cpu_time(libc::RUSAGE_SELF) - self.cpu).as_secs_f64())
    }
}

/// One render: its picture, its statistics and what it cost (the photon pass included, scene loading not).
struct Run {
    frame: Frame,
    stats: RenderStats,
    wall: f64,
    cpu: f64,
}

fn parse<E: Example>(args: &[String]) -> Cli<E> {
    Cli::<E>::parse_args("beyond", args).unwrap_or_else(|e| panic!("options {args:?}: {e}"))
}

/// The scene and settings of an example with these options, as its binary prepares them.
fn prepare<E: Example>(args: &[String]) -> (Scene, RenderSettings) {
    parse::<E>(args).prepare().unwrap_or_else(|e| panic!("options {args:?}: {e}"))
}

/// Renders an example with these options, as its binary does, in the reading and with the steps they ask
/// for; the photon map (which `prepare` builds) is built again inside the timed part, so that it counts.
fn run<E: Example>(args: &[String]) -> Run {
    let (mut scene, settings) = prepare::<E>(args);
    let clock = Clock::start();
    if scene.photon_map.is_some() {
        let pool = thread_pool(settings.threads).expect("thread pool");
        let map = pool.install(|| PhotonMap::build(&scene, settings.seed)).expect("photon map");
        scene.photon_map = map.map(Arc::new);
    }
    let (frame, stats) = render(&scene, &settings).unwrap_or_else(|e| panic!("render {args:?}: {e}"));
    let (wall, cpu) = clock.stop();
    Run { frame, stats, wall, cpu }
}

/// An example of the workbook, reached through its file in `examples/`.
struct Ex {
    name: &'static str,
    run: fn(&[String]) -> Run,
    prepare: fn(&[String]) -> (Scene, RenderSettings),
    scene: fn() -> Scene,
}

macro_rules! workbook_examples {
    ($($name:ident),* $(,)?) => {
        vec![$(Ex {
            name: stringify!($name),
            run: run::<examples::$name::Options>,
            prepare: prepare::<examples::$name::Options>,
            scene: || parse::<examples::$name::Options>(&[]).example.scene().expect("scene"),
        }),*]
    };
}

fn example(all: &[Ex], name: &str) -> usize {
    all.iter().position(|e| e.name == name).unwrap_or_else(|| panic!("no example {name}"))
}

fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}

/// Medians over the rounds of one variant's runs, and its last run.
struct Timed {
    wall: f64,
    cpu: f64,
    last: Run,
}

/// Runs every variant `rounds` times, interleaved (in each round every variant once, the order reversed
/// every other round), and returns each variant's medians.
fn side_by_side(plan: &Plan, jobs: &[(&Ex, Vec<String>)]) -> Vec<Timed> {
    interleaved(plan, jobs.len(), |i| (jobs[i].0.run)(&jobs[i].1))
}

/// [`side_by_side`] for `count` variants that `run` renders by their index.
fn interleaved(plan: &Plan, count: usize, run: impl Fn(usize) -> Run) -> Vec<Timed> {
    let mut walls = vec![Vec::new(); count];
    let mut cpus = vec![Vec::new(); count];
    let mut last: Vec<Option<Run>> = (0..count).map(|_| None).collect();
    for round in 0..plan.rounds {
        let order: Vec<usize> = if round % 2 == 0 { (0..count).collect() } else { (0..count).rev().collect() };
        for i in order {
            let r = run(i);
            walls[i].push(r.wall);
            cpus[i].push(r.cpu);
            last[i] = Some(r);
        }
    }
    walls
        .into_iter()
        .zip(cpus)
        .zip(last)
        .map(|((w, c), l)| Timed { wall: median(w), cpu: median(c), last: l.expect("one round at least") })
        .collect()
}

/// The scene with these steps, prepared for them (outside any timed part).
fn with_steps(scene: &Scene, steps: Steps) -> Scene {
    let mut out = scene.clone();
    out.steps = steps;
    out.prepared().into_owned()
}

/// Whether a node of the scene has a `Layered` shader.
fn has_layered(scene: &Scene) -> bool {
    scene.nodes.iter().any(|node| matches!(node.shader, Material::Layered(_)))
}

/// PSNR (dB) and largest difference (8-bit levels) between two pictures as written.
fn psnr(a: &Frame, b: &Frame) -> (f64, u8) {
    let d = difference(&a.to_rgb8(), &b.to_rgb8()).expect("same size");
    (d.psnr, d.max_diff)
}

fn db(psnr: f64) -> String {
    if psnr.is_finite() { format!("{psnr:.1} dB") } else { "identical".to_string() }
}

fn with(base: &[&str], extra: &[&str]) -> Vec<String> {
    strings(&[base, extra].concat())
}

const ONE_THREAD: [&str; 2] = ["--threads", "1"];
const SIZE_320: [&str; 4] = ["--width", "320", "--height", "240"];
const SIZE_160: [&str; 4] = ["--width", "160", "--height", "120"];

// ---------------------------------------------------------------------------------------------------------
// Error against time

/// One curve of a sweep: a label, the options of every point, and the values of the knob.
struct Curve {
    label: &'static str,
    fixed: Vec<String>,
    values: Vec<u32>,
}

/// Renders every curve's points side by side (interleaved over the rounds) and measures each point's error
/// against the reference. The measurements' `seconds` are the median CPU seconds.
fn sweep(plan: &Plan, ex: &Ex, knob: &'static str, curves: &[Curve], reference: &Frame) -> Vec<Vec<Measurement>> {
    let jobs: Vec<(&Ex, Vec<String>)> = curves
        .iter()
        .flat_map(|c| {
            c.values.iter().map(move |v| {
                let mut args = c.fixed.clone();
                args.extend([knob.to_string(), v.to_string()]);
                (ex, args)
            })
        })
        .collect();
    let mut timed = side_by_side(plan, &jobs).into_iter();
    curves
        .iter()
        .map(|c| {
            c.values
                .iter()
                .map(|&value| {
                    let t = timed.next().expect("one per point");
                    Measurement {
                        example: ex.name,
                        label: c.label.to_string(),
                        reference: String::new(),
                        knob,
                        value,
                        seconds: t.cpu,
                        rays: t.last.stats.counters.total(),
                        rmse: rmse_linear(&t.last.frame, reference).expect("same size"),
                        perceptual: None,
                    }
                })
                .collect()
        })
        .collect()
}

/// A reference picture: the example at these options, once.
fn reference(ex: &Ex, args: &[&str]) -> Frame {
    (ex.run)(&strings(args)).frame
}

/// The comparison of a step's curve with the slide's at the slide's point `at` (the example's default
/// count): the step's error at the slide's CPU time, and the step's CPU time at the slide's error.
struct Versus {
    slide_seconds: f64,
    slide_rmse: f64,
    step_rmse: Option<f64>,
    step_seconds: Option<f64>,
}

/// The curve with each point's time replaced by its rays times the curve's median CPU time per ray: on a
/// loaded machine one point's median of a few renders can be off by tens of percent, which moves an
/// equal-time comparison of two close curves more than the curves differ; the cost of a ray of one curve
/// (its sampler, its filter) is measured over all its points.
fn modeled(curve: &[Measurement]) -> Vec<Measurement> {
    let per_ray = per_ray_cost(curve);
    curve.iter().map(|m| Measurement { seconds: m.rays as f64 * per_ray, ..m.clone() }).collect()
}

/// The median over a curve's points of the CPU seconds per ray.
fn per_ray_cost(curve: &[Measurement]) -> f64 {
    median(curve.iter().map(|m| m.seconds / m.rays as f64).collect())
}

/// The step's curve against the slide's at the slide's point `at`, both [`modeled`].
fn versus(slide: &[Measurement], step: &[Measurement], at: u32) -> Versus {
    let (slide, step) = (modeled(slide), modeled(step));
    versus_measured(&slide, &step, at)
}

/// The step's curve against the slide's at the slide's point `at`, with the times as measured.
fn versus_measured(slide: &[Measurement], step: &[Measurement], at: u32) -> Versus {
    let point = slide.iter().find(|m| m.value == at).expect("the anchor is on the slide's curve");
    let mut by_time = step.to_vec();
    by_time.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
    Versus {
        slide_seconds: point.seconds,
        slide_rmse: point.rmse,
        step_rmse: rmse_at_time(&by_time, point.seconds),
        step_seconds: cost_at_rmse(step, point.rmse, |m| m.seconds),
    }
}

impl Versus {
    /// "error at equal time" and "time at equal error", as one sentence.
    fn describe(&self, step: &str, slide: &str, step_curve: &[Measurement]) -> String {
        let slowest = step_curve.iter().max_by(|a, b| a.seconds.total_cmp(&b.seconds)).expect("a curve");
        let fastest = step_curve.iter().min_by(|a, b| a.seconds.total_cmp(&b.seconds)).expect("a curve");
        let error = match self.step_rmse {
            Some(e) => format!(
                "at the CPU time of {slide} ({:.3} s) RMSE {:.4} against {:.4} ({})",
                self.slide_seconds,
                e,
                self.slide_rmse,
                if e <= self.slide_rmse {
                    format!("{:.2}x less error", self.slide_rmse / e)
                } else {
                    format!("{:.2}x more error", e / self.slide_rmse)
                }
            ),
            None if self.slide_seconds > slowest.seconds => format!(
                "{slide} takes {:.3} s for RMSE {:.4}; {step}'s slowest point takes {:.3} s for RMSE {:.4}",
                self.slide_seconds, self.slide_rmse, slowest.seconds, slowest.rmse
            ),
            None => format!(
                "{slide} takes {:.3} s for RMSE {:.4}; {step}'s fastest point takes {:.3} s for RMSE {:.4}",
                self.slide_seconds, self.slide_rmse, fastest.seconds, fastest.rmse
            ),
        };
        let time = match self.step_seconds {
            Some(t) => format!(
                "{step} reaches that RMSE in {t:.3} s ({:.2}x the speed{})",
                self.slide_seconds / t,
                if (0.95..=1.05).contains(&(self.slide_seconds / t)) { ": nothing measurable" } else { "" }
            ),
            None if fastest.rmse < self.slide_rmse => format!(
                "{step}'s fastest point is already below that RMSE ({:.4} in {:.3} s, {:.1}x the speed at least)",
                fastest.rmse,
                fastest.seconds,
                self.slide_seconds / fastest.seconds
            ),
            None => format!("{step} does not reach that RMSE within its swept points"),
        };
        format!("{error}; {time}")
    }
}

fn curve_table(out: &mut String, knob: &str, curves: &[(&str, &[Measurement])]) {
    writeln!(out, "| curve | {knob} | CPU s | rays | RMSE |").unwrap();
    writeln!(out, "|---|---:|---:|---:|---:|").unwrap();
    for (label, curve) in curves {
        for m in curve.iter() {
            writeln!(
                out,
                "| {label} | {} | {:.3} | {:.2} M | {:.5} |",
                m.value,
                m.seconds,
                m.rays as f64 / 1e6,
                m.rmse
            )
            .unwrap();
        }
    }
    out.push('\n');
}

// ---------------------------------------------------------------------------------------------------------
// Unit-level timing

/// The camera rays through the pixel centres of a `w` x `h` picture of the scene.
fn camera_rays(scene: &Scene, w: u32, h: u32) -> Vec<Ray> {
    let camera = scene.camera.frame(w, h);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5))
        .collect()
}

/// Median CPU nanoseconds per ray of each of `fs` over the rays, the variants in turn over the rounds (3 at
/// least: a round is short), each repeated `repeat` times within a round so that it lasts long enough to time.
fn per_ray(plan: &Plan, rays: &[Ray], repeat: usize, fs: &[&dyn Fn(&Ray) -> u64]) -> Vec<f64> {
    let mut times = vec![Vec::new(); fs.len()];
    for round in 0..plan.rounds.max(3) {
        let order: Vec<usize> = if round % 2 == 0 { (0..fs.len()).collect() } else { (0..fs.len()).rev().collect() };
        for i in order {
            let clock = Clock::start();
            let mut sum = 0u64;
            for _ in 0..repeat {
                for ray in rays {
                    sum = sum.wrapping_add(fs[i](ray));
                }
            }
            std::hint::black_box(sum);
            times[i].push(clock.stop().1 / (repeat * rays.len()) as f64 * 1e9);
        }
    }
    times.into_iter().map(median).collect()
}

/// The closest hit of the ray in the scene, as its steps find it: the distance and the node's index.
fn closest(scene: &Scene, ray: &Ray) -> Option<(f32, usize)> {
    scene.closest_hit(ray).map(|(info, node)| {
        (info.distance, scene.nodes.iter().position(|n| std::ptr::eq(n, node)).expect("a node of the scene"))
    })
}

/// Whether two closest hits are the same: both misses, or the same node at the same distance (within
/// 1e-5 of it, relative).
fn same_hit(a: Option<(f32, usize)>, b: Option<(f32, usize)>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some((ta, na)), Some((tb, nb))) => na == nb && (ta - tb).abs() <= 1e-5 * ta.abs().max(tb.abs()),
        _ => false,
    }
}

// ---------------------------------------------------------------------------------------------------------
// Lines of code

/// What implements a step: whole files (without their tests), items (found by the start of their first
/// line, up to the end of their braces), or the lines of a file that contain a word.
enum Code {
    File(&'static str),
    Items(&'static str, &'static [&'static str]),
    Lines(&'static str, &'static str),
}

fn is_code(line: &str) -> bool {
    let t = line.trim();
    !t.is_empty() && !t.starts_with("//")
}

fn source(path: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The code lines of an item that starts at line `start`: up to where its braces close (or its `;`).
fn item_lines(lines: &[&str], start: usize) -> usize {
    let mut depth = 0i32;
    let mut count = 0;
    for line in &lines[start..] {
        if is_code(line) {
            count += 1;
        }
        let code = line.split("//").next().unwrap_or_default();
        depth += code.matches('{').count() as i32 - code.matches('}').count() as i32;
        if depth <= 0 && (code.contains('}') || code.trim_end().ends_with(';')) {
            break;
        }
    }
    count
}

fn lines_of(code: &Code) -> usize {
    match code {
        Code::File(path) => source(path)
            .lines()
            .take_while(|l| !l.trim_start().starts_with("#[cfg(test)]"))
            .filter(|l| is_code(l))
            .count(),
        Code::Items(path, items) => {
            let text = source(path);
            let lines: Vec<&str> = text.lines().collect();
            items
                .iter()
                .map(|item| {
                    let start = lines
                        .iter()
                        .position(|l| {
                            let t = l.trim_start();
                            let t = t.strip_prefix("pub(crate) ").or_else(|| t.strip_prefix("pub ")).unwrap_or(t);
                            t.starts_with(item)
                        })
                        .unwrap_or_else(|| panic!("{path}: no item starts with {item:?}: update the ledger's list"));
                    item_lines(&lines, start)
                })
                .sum()
        }
        Code::Lines(path, word) => source(path).lines().filter(|l| is_code(l) && l.contains(word)).count(),
    }
}

fn describe_code(code: &Code) -> String {
    match code {
        Code::File(path) => format!("`{path}` (all but its tests)"),
        Code::Items(path, items) => {
            format!("`{path}`: {}", items.iter().map(|i| format!("`{i}`")).collect::<Vec<_>>().join(", "))
        }
        Code::Lines(path, word) => format!("`{path}`: the lines that mention `{word}`"),
    }
}

// ---------------------------------------------------------------------------------------------------------
// The steps

/// One row of the ledger: a step of [`Step::ALL`], or something that runs beyond the slides without being
/// a step.
struct Row {
    step: String,
    slide: &'static str,
    measured: String,
    buys: String,
    verdict: String,
    code: Vec<Code>,
}

/// A step's name in the ledger: its number in [`Step::ALL`], its name on the command line and what it is.
fn title(step: Step, what: &str) -> String {
    let number = Step::ALL.iter().position(|&s| s == step).expect("a step") + 1;
    format!("{number}. `{}`: {what}", step.name())
}

const KEPT_FOR_SPEED: &str = "kept for speed";
const KEPT_FOR_NOISE: &str = "kept for noise";
const KEPT_AS_GUARD: &str = "kept as a guard (its row shows the scene where it pays)";
const NOT_A_STEP: &str = "a deviation from the slide, not a step";
/// The verdict of a step whose figures show no gain beyond the noise on any scene measured: such a step
/// leaves the code.
const BUYS_NOTHING: &str = "to be removed: buys nothing beyond the noise";

/// A gain smaller than this factor is not told from the noise of a shared machine.
const NOISE: f64 = 1.05;

/// The verdict of a step that changes the noise: kept if, at the slide's CPU time, its error is lower by
/// more than [`NOISE`], or it reaches the slide's error in less time by more than that.
fn noise_verdict(v: &Versus, step_curve: &[Measurement]) -> String {
    let fastest = step_curve.iter().min_by(|a, b| a.seconds.total_cmp(&b.seconds)).expect("a curve");
    let less_error = v.step_rmse.is_some_and(|e| e * NOISE <= v.slide_rmse);
    let less_time = v.step_seconds.is_some_and(|t| t * NOISE <= v.slide_seconds)
        || (v.step_seconds.is_none() && fastest.rmse < v.slide_rmse && fastest.seconds * NOISE <= v.slide_seconds);
    if less_error || less_time { KEPT_FOR_NOISE.to_string() } else { BUYS_NOTHING.to_string() }
}

/// The geometric mean of the values.
fn geometric_mean(values: impl IntoIterator<Item = f64>) -> f64 {
    let (sum, count) = values.into_iter().fold((0.0, 0), |(s, n), v| (s + v.ln(), n + 1));
    (sum / count as f64).exp()
}

/// The scene moved by `offset`: every node, the camera and the lights.
fn moved(scene: &Scene, offset: Vector) -> Scene {
    let mut out = scene.clone();
    for node in &mut out.nodes {
        node.transform = Some(node.transform.unwrap_or_default().translate(offset));
    }
    out.camera.position += offset;
    for light in &mut out.lights {
        light.position += offset;
    }
    out
}

/// A picture of the scene at 160 x 120, one sample per pixel, its photon map built for it as it is.
fn picture(scene: &Scene) -> Frame {
    let settings =
        RenderSettings { width: 160, height: 120, spp: 1, threads: Some(1), progress: false, ..Default::default() };
    let mut scene = scene.clone();
    scene.photon_map = PhotonMap::build(&scene, settings.seed).expect("photon map").map(Arc::new);
    render(&scene, &settings).expect("render").0
}

/// The share of pixels that differ by more than 8 levels in some channel.
fn changed_pixels(a: &Frame, b: &Frame) -> f64 {
    let d = difference(&a.to_rgb8(), &b.to_rgb8()).expect("same size");
    d.large_pixels as f64 / d.pixels as f64
}

/// The instructions of one render of the example with these options, counted by callgrind: this bench run
/// again under `valgrind --tool=callgrind` with `--render-once`, which prints the total it collected. The
/// count includes the bench's start and the scene's loading, the same for both sides of a comparison.
/// `None` when valgrind cannot be run.
fn instructions(name: &str, args: &[String]) -> Option<u64> {
    let exe = std::env::current_exe().ok()?;
    let out = Command::new("valgrind")
        .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
        .arg(exe)
        .arg("--render-once")
        .arg(name)
        .args(args)
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    String::from_utf8_lossy(&out.stderr)
        .lines()
        .find_map(|l| l.split("Collected :").nth(1).and_then(|n| n.trim().parse().ok()))
}

fn main() {
    let args = Args::parse();
    let all = every_example!(workbook_examples);
    if let Some((name, options)) = args.render_once.split_first() {
        (all[example(&all, name)].run)(options);
        return;
    }
    let plan = Plan { quick: args.quick, rounds: args.rounds.unwrap_or(if args.quick { 1 } else { 3 }) };
    let started = Instant::now();
    let mut rows = Vec::new();
    let mut details = String::new();
    let readings = slide_against_default(&plan, &all, &mut rows, &mut details);
    two_phase_nearest_hit(&plan, &all, &mut rows, &mut details);
    node_bvh(&plan, &mut rows, &mut details);
    mesh_bvh(&plan, &all, &mut rows);
    bitmap_filtering(&plan, &all, &mut rows, &mut details);
    stratified_pixels(&plan, &all, &mut rows, &mut details);
    disc_samples(&plan, &all, &mut rows, &mut details);
    hero_wavelengths(&plan, &all, &mut rows, &mut details);
    photon_map(&plan, &all, &mut rows, &mut details);
    details.push_str(&kept_section(CAUSTIC_REFERENCE));
    details.push_str(&kept_section(PROGRESSIVE_CAUSTIC));
    layer_pruning(&plan, &all, &mut rows, &mut details);
    camera_relative(&all, &mut rows, &mut details);
    progressive_caustic(&mut rows);
    branching_bound(&readings, &mut rows, &mut details);
    end_of_run_report(&plan, &all, &readings, &mut rows, &mut details);
    deviations(&mut rows);
    write_ledger(&plan, &rows, &readings.table, &details, started.elapsed().as_secs_f64());
}

/// The heading of the section on the caustic against its independent reference, written from the figures of
/// `benches/caustic_rings.rs` (the reference light tracer, `benches/caustic_reference.rs`, takes far longer
/// than this ledger): the ledger keeps it as it finds it.
const CAUSTIC_REFERENCE: &str = "## The caustic against an independent light tracer\n";

/// The heading of the section on the progressive caustic, written from the figures of
/// `benches/caustic_convergence.rs` (its renders of 64 passes take longer than this ledger): the ledger
/// keeps it as it finds it, and its row quotes the section's line that starts with `What it buys: `.
const PROGRESSIVE_CAUSTIC: &str = "## The progressive caustic\n";

/// The progressive caustic's row (a render setting, `photon_passes`, whose first choice, one pass, is the
/// slide's): its figures from its section (see [`PROGRESSIVE_CAUSTIC`]).
fn progressive_caustic(rows: &mut Vec<Row>) {
    let section = kept_section(PROGRESSIVE_CAUSTIC);
    let line = |prefix: &str| section.lines().find_map(|l| l.strip_prefix(prefix)).map(str::to_string);
    let missing = "not measured: run `cargo bench --features study --bench caustic_convergence`".to_string();
    rows.push(Row {
        step: "The progressive caustic (`src/lesson/photon_map/progressive.rs`; the render setting `photon_passes`, `--photon-passes N`)".into(),
        slide: "one photon map: the k nearest photons within the maximum radius",
        measured: "photon_map against the independent light tracer's rings (section \"The progressive caustic\"): passes of 400,000 photons against one map of more photons, 640x480 at 4 spp, 1 thread".into(),
        buys: line("What it buys: ").unwrap_or_else(|| missing.clone()),
        verdict: line("Verdict: ").unwrap_or(missing),
        code: vec![
            Code::File("src/lesson/photon_map/progressive.rs"),
            Code::Items(
                "src/lesson/render.rs",
                &[
                    "fn render_photon_passes",
                    "fn photon_passes_pixel",
                    "fn photon_pass",
                    "struct PassAverage",
                    "impl PassAverage",
                    "struct PassesProgress",
                    "impl Progress for PassesProgress",
                    "fn add_pass",
                ],
            ),
        ],
    });
}

/// The section of the ledger now in `docs/beyond-the-slides.md` that starts with `heading`, up to the next
/// section; empty if there is none.
fn kept_section(heading: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/beyond-the-slides.md");
    let doc = std::fs::read_to_string(path).unwrap_or_default();
    let Some(start) = doc.find(heading) else { return String::new() };
    let section = &doc[start..];
    let end = section[heading.len()..].find("\n## ").map_or(section.len(), |i| heading.len() + i + 1);
    section[..end].to_string()
}

/// What the runs of every example in both readings give the other rows: the table of `--slide` against
/// the default, each example's default CPU time, and the rays each reading's branching bound shared.
struct Readings {
    table: String,
    default_cpu: Vec<(&'static str, f64)>,
    /// Per example: the rays, and the rays the bound shared, of the default and of `--slide`.
    shared: Vec<(&'static str, [u64; 4])>,
}

/// `--slide` against the default on every example, and `--exhaustive` against the default (step 1) from the
/// same runs.
fn slide_against_default(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) -> Readings {
    eprintln!("every example: default, --exhaustive, --slide");
    let mut readings = Readings { table: String::new(), default_cpu: Vec::new(), shared: Vec::new() };
    let table = &mut readings.table;
    writeln!(
        table,
        "| example | default: wall / CPU s | rays | `--slide`: wall / CPU s | rays | `--slide` / default, CPU | PSNR between |"
    )
    .unwrap();
    writeln!(table, "|---|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut adaptive_table = String::new();
    writeln!(adaptive_table, "| example | default CPU s | rays | `--exhaustive` CPU s | rays | time saved | PSNR between | largest difference |").unwrap();
    writeln!(adaptive_table, "|---|---:|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut adaptive_best: Option<(&str, f64, f64, u64, u64)> = None;
    let mut adaptive_worst_level = 0u8;
    for ex in all {
        let base = [&ONE_THREAD[..], &SIZE_320[..]].concat();
        let jobs = [(ex, strings(&base)), (ex, with(&base, &["--exhaustive"])), (ex, with(&base, &["--slide"]))];
        let [default, exhaustive, slide]: [Timed; 3] = side_by_side(plan, &jobs).try_into().ok().expect("three");
        let rays = |t: &Timed| t.last.stats.counters.total();
        let (p, _) = psnr(&default.last.frame, &slide.last.frame);
        writeln!(
            table,
            "| {} | {:.3} / {:.3} | {:.2} M | {:.3} / {:.3} | {:.2} M | {:.2}x | {} |",
            ex.name,
            default.wall,
            default.cpu,
            rays(&default) as f64 / 1e6,
            slide.wall,
            slide.cpu,
            rays(&slide) as f64 / 1e6,
            slide.cpu / default.cpu,
            db(p)
        )
        .unwrap();
        readings.default_cpu.push((ex.name, default.cpu));
        let shared = |t: &Timed| t.last.stats.counters.shared_rays;
        readings.shared.push((ex.name, [rays(&default), shared(&default), rays(&slide), shared(&slide)]));
        if rays(&default) != rays(&exhaustive) {
            let (p, level) = psnr(&default.last.frame, &exhaustive.last.frame);
            adaptive_worst_level = adaptive_worst_level.max(level);
            writeln!(
                adaptive_table,
                "| {} | {:.3} | {:.2} M | {:.3} | {:.2} M | {:.0}% | {} | {level} |",
                ex.name,
                default.cpu,
                rays(&default) as f64 / 1e6,
                exhaustive.cpu,
                rays(&exhaustive) as f64 / 1e6,
                100.0 * (1.0 - default.cpu / exhaustive.cpu),
                db(p)
            )
            .unwrap();
            let saved = exhaustive.cpu / default.cpu;
            if adaptive_best.is_none_or(|b| saved > b.2 / b.1) {
                adaptive_best = Some((ex.name, default.cpu, exhaustive.cpu, rays(&default), rays(&exhaustive)));
            }
        }
    }
    let (name, d_cpu, e_cpu, d_rays, e_rays) = adaptive_best.expect("some example prunes rays");
    rows.push(Row {
        step: title(Step::AdaptiveDepth, "adaptive ray-tree depth control"),
        slide: "`raytrace` with `MAX_RAY_DEPTH` only",
        measured: "every example, `--exhaustive` (`--no-step adaptive-depth`) against the default, 320x240, 1 thread".into(),
        buys: format!(
            "the same picture within {adaptive_worst_level} level(s) in the worst pixel; at equal error, {:.2}x less CPU time on {name} ({d_cpu:.3} s against {e_cpu:.3} s, {:.2} M rays against {:.2} M)",
            e_cpu / d_cpu,
            d_rays as f64 / 1e6,
            e_rays as f64 / 1e6
        ),
        verdict: if e_cpu / d_cpu >= NOISE { KEPT_FOR_SPEED } else { BUYS_NOTHING }.to_string(),
        code: vec![
            Code::Items("src/lesson/scene.rs", &["fn srgb8_finest_step"]),
            Code::Lines("src/lesson/scene.rs", "min_ray_weight"),
            Code::Lines("src/lesson/scene.rs", "pruned_rays"),
            Code::Lines("src/lesson/ray.rs", "weight"),
        ],
    });
    writeln!(details, "## 1. Adaptive ray-tree depth control\n\nThe examples whose ray count changes with `--exhaustive` (the others trace the same rays):\n\n{adaptive_table}").unwrap();
    readings
}

/// Step 2: the two-phase nearest hit against the slide's loop of full intersects: at unit level on each
/// example's camera rays, and the whole examples, timed with three times the rounds and their instructions
/// counted.
fn two_phase_nearest_hit(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("two-phase nearest hit");
    // The two differ by a few percent, less than the load of a shared machine moves one render: more rounds.
    let more = Plan { quick: plan.quick, rounds: 3 * plan.rounds };
    let mut unit_table = String::new();
    writeln!(unit_table, "| example | nodes | two-phase ns/ray | loop ns/ray | loop / two-phase | same hits |")
        .unwrap();
    writeln!(unit_table, "|---|---:|---:|---:|---:|---:|").unwrap();
    let mut whole_table = String::new();
    writeln!(
        whole_table,
        "| example | two-phase CPU s | loop CPU s | loop / two-phase, CPU | two-phase instructions | loop instructions | loop / two-phase, instructions |"
    )
    .unwrap();
    writeln!(whole_table, "|---|---:|---:|---:|---:|---:|---:|").unwrap();
    let base = [&ONE_THREAD[..], &SIZE_320[..]].concat();
    let no_step = ["--no-step", Step::TwoPhaseHit.name()];
    let (mut unit_ratios, mut cpu_ratios, mut instruction_ratios) = (Vec::new(), Vec::new(), Vec::new());
    for ex in all {
        let (scene, _) = (ex.prepare)(&strings(&SIZE_320));
        let two_phase = with_steps(&scene, Steps::ALL);
        let by_loop = with_steps(&scene, Steps::ALL.without(Step::TwoPhaseHit));
        let rays = camera_rays(&scene, 320, 240);
        let same = rays.iter().filter(|r| same_hit(closest(&two_phase, r), closest(&by_loop, r))).count();
        let t = per_ray(
            &more,
            &rays,
            10,
            &[&|r| two_phase.closest_hit(r).is_some() as u64, &|r| by_loop.closest_hit(r).is_some() as u64],
        );
        unit_ratios.push(t[1] / t[0]);
        writeln!(
            unit_table,
            "| {} | {} | {:.1} | {:.1} | {:.2}x | {:.3}% |",
            ex.name,
            scene.nodes.len(),
            t[0],
            t[1],
            t[1] / t[0],
            100.0 * same as f64 / rays.len() as f64
        )
        .unwrap();
        let jobs = [(ex, strings(&base)), (ex, with(&base, &no_step))];
        let [with_step, without]: [Timed; 2] = side_by_side(&more, &jobs).try_into().ok().expect("two");
        cpu_ratios.push((ex.name, without.cpu / with_step.cpu));
        let counts = (instructions(ex.name, &strings(&base)), instructions(ex.name, &with(&base, &no_step)));
        let (i_with, i_without) = match counts {
            (Some(a), Some(b)) => {
                instruction_ratios.push((ex.name, b as f64 / a as f64));
                (format!("{:.1} M", a as f64 / 1e6), format!("{:.1} M", b as f64 / 1e6))
            }
            _ => ("not counted".to_string(), "not counted".to_string()),
        };
        writeln!(
            whole_table,
            "| {} | {:.3} | {:.3} | {:.3}x | {i_with} | {i_without} | {} |",
            ex.name,
            with_step.cpu,
            without.cpu,
            without.cpu / with_step.cpu,
            instruction_ratios.last().filter(|r| r.0 == ex.name).map_or("".to_string(), |r| format!("{:.3}x", r.1))
        )
        .unwrap();
    }
    let range = |v: &[f64]| (v.iter().copied().fold(f64::INFINITY, f64::min), v.iter().copied().fold(0.0, f64::max));
    let (unit_lo, unit_hi) = range(&unit_ratios);
    let cpu_mean = geometric_mean(cpu_ratios.iter().map(|r| r.1));
    let cpu_faster = cpu_ratios.iter().filter(|r| r.1 > 1.0).count();
    let (cpu_lo, cpu_hi) = range(&cpu_ratios.iter().map(|r| r.1).collect::<Vec<_>>());
    let instructions_figure = if instruction_ratios.len() == all.len() {
        let mean = geometric_mean(instruction_ratios.iter().map(|r| r.1));
        let (lo, hi) = range(&instruction_ratios.iter().map(|r| r.1).collect::<Vec<_>>());
        let fewer = instruction_ratios.iter().filter(|r| r.1 > 1.0).count();
        Some((
            mean,
            format!(
                "; instructions of one render (callgrind): the loop takes {lo:.3}x to {hi:.3}x the two-phase hit's (geometric mean {mean:.3}x; more on {fewer} of {})",
                instruction_ratios.len()
            ),
        ))
    } else {
        None
    };
    // Kept only if the instructions (which the load does not move) and the CPU time agree that it gains.
    let verdict = match &instructions_figure {
        Some((mean, _)) if *mean >= 1.01 && cpu_mean >= 1.0 => KEPT_FOR_SPEED,
        None if cpu_mean >= NOISE => KEPT_FOR_SPEED,
        _ => BUYS_NOTHING,
    };
    rows.push(Row {
        step: title(Step::TwoPhaseHit, "the two-phase nearest hit (`Geometry::hit`, then `surface` of the winner)"),
        slide: "`Node::intersect` on every node, the full hit description each time",
        measured: format!(
            "every example with and without `--no-step two-phase-hit`: whole renders at 320x240 ({} rounds) and their instructions; `Scene::closest_hit` on the camera rays at 320x240",
            more.rounds
        ),
        buys: format!(
            "the same closest hits; whole renders: the loop takes {cpu_lo:.3}x to {cpu_hi:.3}x the two-phase hit's CPU time (geometric mean {cpu_mean:.3}x; more on {cpu_faster} of {}){}; unit level: {unit_lo:.2}x to {unit_hi:.2}x per camera ray",
            cpu_ratios.len(),
            instructions_figure.as_ref().map_or(String::new(), |f| f.1.clone())
        ),
        verdict: verdict.to_string(),
        code: vec![
            Code::Items("src/lesson/geometry/mod.rs", &["struct Hit", "impl Hit", "fn hit(", "fn surface("]),
            Code::Items(
                "src/lesson/node.rs",
                &["fn hit(", "fn hit_transformed", "fn surface(", "fn nearest_hit_linear", "const TIE", "fn tie"],
            ),
            Code::Items("src/lesson/scene.rs", &["fn nearest_hit", "fn closest_hit"]),
        ],
    });
    writeln!(details, "## 2. The two-phase nearest hit\n\nEach example rendered as it is and with `--no-step two-phase-hit` (every node's full `intersect`, the slide's loop), 320x240, one thread, medians of {} rounds; and one render of each under callgrind, whose instruction count does not move with the machine's load (it includes the bench's start and the scene's loading, alike on both sides).\n\n{whole_table}\nAt unit level: `Scene::closest_hit` on each example's camera rays through the pixel centres, the scene with and without the step. The per-geometry `hit`/`surface` pairs are not counted in the lines.\n\n{unit_table}", more.rounds).unwrap();
}

/// Step 3: the node BVH against the loop over the nodes, on N spheres.
fn node_bvh(plan: &Plan, rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("node BVH");
    let mut bvh_table = String::new();
    writeln!(bvh_table, "| spheres | BVH ns/ray | loop ns/ray | loop / BVH | same hits |").unwrap();
    writeln!(bvh_table, "|---:|---:|---:|---:|---:|").unwrap();
    let counts: Vec<usize> = plan.pick(vec![10, 100, 1000, 10000], vec![10, 100, 1000]);
    let mut bvh_figures = Vec::new();
    for &n in &counts {
        let scene = spheres_scene(n);
        let tree = with_steps(&scene, Steps::ALL);
        let by_loop = with_steps(&scene, Steps::ALL.without(Step::NodeTree));
        let rays = camera_rays(&scene, 160, 120);
        let same = rays.iter().filter(|r| same_hit(closest(&tree, r), closest(&by_loop, r))).count();
        let repeat = (20_000 / n).clamp(1, 20);
        let t = per_ray(
            plan,
            &rays,
            repeat,
            &[&|r| tree.closest_hit(r).is_some() as u64, &|r| by_loop.closest_hit(r).is_some() as u64],
        );
        writeln!(
            bvh_table,
            "| {n} | {:.0} | {:.0} | {:.1}x | {:.3}% |",
            t[0],
            t[1],
            t[1] / t[0],
            100.0 * same as f64 / rays.len() as f64
        )
        .unwrap();
        bvh_figures.push((n, t[0], t[1]));
    }
    let speedups: Vec<String> = bvh_figures.iter().map(|(n, a, b)| format!("{:.1}x at {n}", b / a)).collect();
    rows.push(Row {
        step: title(Step::NodeTree, "the node BVH (above 8 nodes)"),
        slide: "the loop over the nodes",
        measured: "no example (all have at most 8 nodes); N spheres on a plane, camera rays at 160x120".into(),
        buys: format!(
            "the same closest hits; CPU time per camera ray {} spheres, loop over BVH. No example reaches it",
            speedups.join(", ")
        ),
        verdict: KEPT_AS_GUARD.to_string(),
        code: vec![
            Code::Items(
                "src/lesson/node.rs",
                &["struct NodeTree", "impl NodeTree", "const LINEAR_NODES", "struct Closest", "impl Closest"],
            ),
            Code::Items("src/lesson/scene.rs", &["fn prepared", "fn intersects"]),
        ],
    });
    writeln!(details, "## 3. The node BVH\n\n`Scene::closest_hit` of each camera ray (160x120, pixel centres), the scene with and without the step (`Steps::without(Step::NodeTree)`: the loop over the nodes); \"same hits\" counts the rays whose node and distance agree (a tie within `TIE` may go either way).\n\n{bvh_table}").unwrap();
}

/// Step 4: the mesh BVH against the mesh's box and its triangles one by one, on model_transform.
fn mesh_bvh(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>) {
    eprintln!("mesh BVH");
    let mt = &all[example(all, "model_transform")];
    let (scene, _) = (mt.prepare)(&strings(&SIZE_160));
    let meshes: Vec<&Mesh> = scene
        .nodes
        .iter()
        .filter_map(|n| if let Shape::Mesh { mesh, .. } = &n.geometry { Some(&**mesh) } else { None })
        .collect();
    let triangles: usize = meshes.iter().map(|m| m.triangle_count()).sum();
    let bvh = with_steps(&scene, Steps::ALL);
    let one_by_one = with_steps(&scene, Steps::ALL.without(Step::MeshBvh));
    let rays = camera_rays(&scene, 160, 120);
    let same = rays.iter().filter(|r| same_hit(closest(&bvh, r), closest(&one_by_one, r))).count();
    let t = per_ray(
        plan,
        &rays,
        1,
        &[&|r| bvh.closest_hit(r).is_some() as u64, &|r| one_by_one.closest_hit(r).is_some() as u64],
    );
    let mt_timed = side_by_side(plan, &[(mt, strings(&[&ONE_THREAD[..], &SIZE_320[..]].concat()))]);
    rows.push(Row {
        step: title(Step::MeshBvh, "the mesh BVH with four-wide watertight triangles"),
        slide: "the mesh's bounding box, then its triangles one by one",
        measured: format!(
            "model_transform ({} nodes, {} of them meshes, {triangles} triangles), `Scene::closest_hit` of the camera rays at 160x120 with and without the step",
            scene.nodes.len(),
            meshes.len()
        ),
        buys: format!(
            "{:.3}% of the rays find the same hit; {:.0} ns per camera ray against {:.0} ns: {:.0}x less CPU time at equal error (the whole example: {:.3} CPU s at 320x240). `bvh.rs` also serves the node BVH of step 3",
            100.0 * same as f64 / rays.len() as f64,
            t[0],
            t[1],
            t[1] / t[0],
            mt_timed[0].cpu
        ),
        verdict: if t[1] / t[0] >= NOISE { KEPT_FOR_SPEED } else { BUYS_NOTHING }.to_string(),
        code: vec![
            Code::File("src/lesson/geometry/bvh.rs"),
            Code::File("src/lesson/geometry/triangle4.rs"),
            Code::Items("src/lesson/geometry/mesh.rs", &["fn hit(", "fn intersects("]),
        ],
    });
}

/// Step 5: bilinear texels against one texel per look-up, on bitmap_textures.
fn bitmap_filtering(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("bitmap filtering");
    let bt = &all[example(all, "bitmap_textures")];
    let bt_base = [&ONE_THREAD[..], &SIZE_320[..]].concat();
    let ref_spp = plan.pick("256", "64");
    let ref_bilinear =
        reference(bt, &[&bt_base[..], &["--spp", ref_spp, "--seed", "7", "--filter", "bilinear"]].concat());
    let ref_nearest =
        reference(bt, &[&bt_base[..], &["--spp", ref_spp, "--seed", "7", "--filter", "nearest"]].concat());
    let spps: Vec<u32> = plan.pick(vec![1, 4, 16, 64], vec![1, 4, 16]);
    let curves = |filter: &'static str, label: &'static str| Curve {
        label,
        fixed: with(&bt_base, &["--filter", filter]),
        values: spps.clone(),
    };
    let bilinear = sweep(plan, bt, "--spp", &[curves("bilinear", "bilinear")], &ref_bilinear).remove(0);
    let nearest = sweep(plan, bt, "--spp", &[curves("nearest", "nearest")], &ref_nearest).remove(0);
    let v = versus(&nearest, &bilinear, 4);
    let per_ray = per_ray_cost(&bilinear) / per_ray_cost(&nearest);
    let bias = rmse_linear(&ref_bilinear, &ref_nearest).expect("same size");
    let (bias_psnr, _) = psnr(&ref_bilinear, &ref_nearest);
    rows.push(Row {
        step: title(Step::TexelFilter, "bilinear texel filtering and the sRGB byte table"),
        slide: "one texel per look-up",
        measured: "bitmap_textures, `--filter bilinear|nearest` (nearest is `Filter::under` without the step), 320x240, each against its own converged picture".into(),
        buys: format!(
            "a different picture (the two converged pictures differ by RMSE {bias:.4}, {}): the texture blended between texels instead of stepping from one to the next. Noise: {}. CPU time per ray of bilinear over nearest: {:.2}x",
            db(bias_psnr),
            v.describe("bilinear", "nearest", &modeled(&bilinear)),
            per_ray
        ),
        verdict: noise_verdict(&v, &modeled(&bilinear)),
        code: vec![
            Code::Items("src/lesson/bitmap.rs", &["fn neighbours", "fn wrapped_pair", "enum Texels", "fn sample", "fn filtered", "enum Filter"]),
            Code::Items("src/lesson/color.rs", &["fn srgb8_to_linear_table"]),
        ],
    });
    writeln!(details, "## 5. Bitmap filtering\n\nbitmap_textures at 320x240, each filter against its own converged picture ({ref_spp} spp, another seed): the noise of each. The two converged pictures differ by RMSE {bias:.5} ({}).\n", db(bias_psnr)).unwrap();
    curve_table(details, "spp", &[("bilinear", &bilinear), ("nearest", &nearest)]);
}

/// Step 6: stratified pixel samples against random points of the pixel, each example rendered with and
/// without `--no-step stratified-pixels`.
fn stratified_pixels(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("stratified pixel samples");
    let mut aa_table = String::new();
    writeln!(
        aa_table,
        "| example | spp | stratified RMSE | random RMSE | random / stratified | stratified CPU s | random CPU s |"
    )
    .unwrap();
    writeln!(aa_table, "|---|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut aa_summary = Vec::new();
    let mut least = f64::INFINITY;
    for name in ["bitmap_textures", "model_transform", "fresnel"] {
        let ex = &all[example(all, name)];
        let size = [&ONE_THREAD[..], &SIZE_160[..]].concat();
        let converged = reference(ex, &[&size[..], &["--spp", plan.pick("1024", "256"), "--seed", "7"]].concat());
        for spp in plan.pick(vec![4, 16], vec![4]) {
            let at = with(&size, &["--spp", &spp.to_string()]);
            let random = [at.clone(), strings(&["--no-step", Step::StratifiedAa.name()])].concat();
            let [stratified, random]: [Timed; 2] =
                side_by_side(plan, &[(ex, at), (ex, random)]).try_into().ok().expect("two");
            let err = |t: &Timed| rmse_linear(&t.last.frame, &converged).expect("same size");
            let (s, r) = (err(&stratified), err(&random));
            writeln!(
                aa_table,
                "| {name} | {spp} | {s:.5} | {r:.5} | {:.2}x | {:.3} | {:.3} |",
                r / s,
                stratified.cpu,
                random.cpu
            )
            .unwrap();
            if spp == 4 {
                aa_summary.push(format!("{:.2}x on {name}", r / s));
                least = least.min(r / s);
            }
        }
    }
    rows.push(Row {
        step: title(Step::StratifiedAa, "stratified anti-aliasing (jittered grid / N-rooks)"),
        slide: "random points in the pixel",
        measured:
            "bitmap_textures, model_transform, fresnel at 160x120, with and without `--no-step stratified-pixels`"
                .into(),
        buys: format!(
            "at equal spp (equal rays, equal time) the random points' RMSE is {} the stratified one's, at 4 spp",
            aa_summary.join(", ")
        ),
        verdict: if least >= NOISE { KEPT_FOR_NOISE } else { BUYS_NOTHING }.to_string(),
        code: vec![
            Code::Items("src/lesson/render.rs", &["struct Stratifier", "impl Stratifier"]),
            Code::Items("src/lesson/rng.rs", &["fn shuffled_index"]),
        ],
    });
    writeln!(details, "## 6. Stratified anti-aliasing\n\nEach example rendered as it is and with `--no-step stratified-pixels` (random points of the pixel), 160x120, against the example at {} spp with another seed.\n\n{aa_table}", plan.pick(1024, 256)).unwrap();
}

/// Step 7: stratified and joint disc samples against random points of the disc, on glossy.
fn disc_samples(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("glossy samplers");
    let gl = &all[example(all, "glossy")];
    let gl_base = [&ONE_THREAD[..], &SIZE_160[..], &["--spp", "16"]].concat();
    let gl_ref = reference(
        gl,
        &[
            &ONE_THREAD[..],
            &SIZE_160[..],
            &["--spp", "64", "--glossy-samples", plan.pick("64", "16"), "--sampler", "stratified", "--seed", "7"],
        ]
        .concat(),
    );
    let counts: Vec<u32> = plan.pick(vec![1, 2, 4, 8, 16], vec![1, 4, 8]);
    let sampler =
        |s: &'static str| Curve { label: s, fixed: with(&gl_base, &["--sampler", s]), values: counts.clone() };
    let curves =
        sweep(plan, gl, "--glossy-samples", &[sampler("random"), sampler("stratified"), sampler("joint")], &gl_ref);
    let (random, stratified, joint) = (&curves[0], &curves[1], &curves[2]);
    let joint_versus = versus(random, joint, 4);
    rows.push(Row {
        step: title(Step::DiscSamples, "stratified and joint disc samples"),
        slide: "random points of the unit disc",
        measured: "glossy, `--sampler random|stratified|joint`, 16 spp, 160x120, `--glossy-samples` swept".into(),
        buys: format!(
            "joint (the default): {}. stratified: {}",
            joint_versus.describe("joint", "random", &modeled(joint)),
            versus(random, stratified, 4).describe("stratified", "random", &modeled(stratified))
        ),
        verdict: noise_verdict(&joint_versus, &modeled(joint)),
        code: vec![Code::Items(
            "src/lesson/sampling.rs",
            &[
                "enum DiscSampler",
                "const BLOCK_ORDER_KEY",
                "struct DiscSamples",
                "impl DiscSamples",
                "fn concentric_disc",
                "fn to_unit",
                "fn van_der_corput",
                "fn sobol2",
            ],
        )],
    });
    // Through the pixel centres only (one camera ray per pixel), where the glossy noise is all the noise.
    let centre_ref = reference(
        gl,
        &[
            &ONE_THREAD[..],
            &SIZE_160[..],
            &["--spp", "1", "--glossy-samples", plan.pick("2048", "512"), "--sampler", "stratified", "--seed", "7"],
        ]
        .concat(),
    );
    let centre_base = [&ONE_THREAD[..], &SIZE_160[..], &["--spp", "1"]].concat();
    let centre_counts: Vec<u32> = plan.pick(vec![4, 16, 64, 256], vec![4, 16, 64]);
    let centre = |s: &'static str| Curve {
        label: s,
        fixed: with(&centre_base, &["--sampler", s]),
        values: centre_counts.clone(),
    };
    let centre_curves = sweep(plan, gl, "--glossy-samples", &[centre("random"), centre("stratified")], &centre_ref);
    let centre_versus =
        versus(&centre_curves[0], &centre_curves[1], 16).describe("stratified", "random", &modeled(&centre_curves[1]));
    if let Some(row) = rows.last_mut() {
        row.buys.push_str(&format!(
            ". Through the pixel centres (1 spp, not the example's default), stratified: {centre_versus}"
        ));
    }
    writeln!(details, "## 7. Glossy disc samples\n\nglossy at 160x120, 16 spp, against 64 spp x {} stratified glossy rays with another seed.\n", plan.pick(64, 16)).unwrap();
    curve_table(details, "glossy samples", &[("random", random), ("stratified", stratified), ("joint", joint)]);
    writeln!(
        details,
        "Through the pixel centres (`--spp 1`), against 1 spp x {} stratified glossy rays with another seed:\n",
        plan.pick(2048, 512)
    )
    .unwrap();
    curve_table(details, "glossy samples", &[("random", &centre_curves[0]), ("stratified", &centre_curves[1])]);
}

/// Step 8: hero wavelengths against K passes, on dispersion.
fn hero_wavelengths(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("dispersion");
    let di = &all[example(all, "dispersion")];
    let di_base = [&ONE_THREAD[..], &SIZE_160[..]].concat();
    let di_ref = reference(
        di,
        &[&di_base[..], &["--spectral", "hero", "--wavelengths", "8", "--spp", plan.pick("128", "32"), "--seed", "7"]]
            .concat(),
    );
    let passes = Curve {
        label: "8 passes",
        fixed: with(&di_base, &["--spectral", "passes", "--wavelengths", "8"]),
        values: plan.pick(vec![1, 2, 4, 8], vec![1, 4]),
    };
    let hero = Curve {
        label: "hero",
        fixed: with(&di_base, &["--spectral", "hero"]),
        values: plan.pick(vec![1, 2, 4, 8, 16], vec![1, 4, 8]),
    };
    let sampled = Curve {
        label: "sampled",
        fixed: with(&di_base, &["--spectral", "sampled"]),
        values: plan.pick(vec![1, 2, 4, 8, 16, 32], vec![1, 4, 8]),
    };
    let curves = sweep(plan, di, "--spp", &[passes, hero, sampled], &di_ref);
    let hero_versus = versus(&curves[0], &curves[1], 4);
    let sampled_versus = versus(&curves[0], &curves[2], 4);
    rows.push(Row {
        step: title(Step::HeroWavelengths, "hero-wavelength sampling"),
        slide: "K = 8 wavelength passes",
        measured: "dispersion, `--spectral hero|passes`, 160x120, `--spp` swept, against a converged hero render"
            .into(),
        buys: hero_versus.describe("hero", "8 passes", &modeled(&curves[1])),
        verdict: noise_verdict(&hero_versus, &modeled(&curves[1])),
        code: vec![
            Code::Items(
                "src/lesson/render.rs",
                &["fn wavelength_samples", "fn add_weighted", "fn to_color", "const WAVELENGTH_KEY"],
            ),
            Code::Lines("src/lesson/scene.rs", "met_dispersion"),
        ],
    });
    rows.push(Row {
        step: "8b. `--spectral sampled`: one wavelength per sample (a choice of step 8, not the default)".into(),
        slide: "K = 8 wavelength passes",
        measured: "dispersion, `--spectral sampled|passes`, 160x120, `--spp` swept, against a converged hero render"
            .into(),
        buys: sampled_versus.describe("sampled", "8 passes", &modeled(&curves[2])),
        verdict: noise_verdict(&sampled_versus, &modeled(&curves[2])),
        code: vec![Code::Lines("src/lesson/render.rs", "SpectralPlan::Sampled")],
    });
    writeln!(details, "## 8. Hero wavelengths\n\ndispersion at 160x120 against hero sampling with 8 wavelengths per path at {} spp, another seed (the slide's 8 passes converge to their own 8-band picture, which is part of their error). `sampled` is the other choice of the step: each sample carries one wavelength of its own band (`--spectral sampled`).\n", plan.pick(128, 32)).unwrap();
    curve_table(details, "spp", &[("8 passes", &curves[0]), ("hero", &curves[1]), ("sampled", &curves[2])]);
}

/// Step 9: the photon grid and aimed emission against all-direction emission and the k-d tree, the rest of
/// the render the default's (`--no-step photon-grid`).
fn photon_map(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("photon map");
    let pm = &all[example(all, "photon_map")];
    let pm_base = [&ONE_THREAD[..], &SIZE_160[..], &["--spp", "1"]].concat();
    let pm_ref = reference(
        pm,
        &[&pm_base[..], &["--photons", plan.pick("3200000", "800000"), "--k", "400", "--seed", "7"]].concat(),
    );
    let photons: Vec<u32> = plan.pick(vec![25_000, 100_000, 400_000], vec![25_000, 100_000]);
    let default_curve = Curve { label: "grid + aimed", fixed: strings(&pm_base), values: photons.clone() };
    let no_step = ["--no-step", Step::PhotonGrid.name()];
    let slide_curve = Curve { label: "slide", fixed: with(&pm_base, &no_step), values: photons.clone() };
    let jobs: Vec<(&Ex, Vec<String>)> = [&default_curve, &slide_curve]
        .iter()
        .flat_map(|c| {
            photons.iter().map(move |p| (pm, [c.fixed.clone(), strings(&["--photons", &p.to_string()])].concat()))
        })
        .collect();
    let timed = side_by_side(plan, &jobs);
    let mut pm_table = String::new();
    writeln!(pm_table, "| reading | photons asked | emitted | stored | stored / emitted | trace + build s | render CPU s (all) | RMSE |").unwrap();
    writeln!(pm_table, "|---|---:|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut pm_curves = [Vec::new(), Vec::new()];
    for (i, t) in timed.iter().enumerate() {
        let reading = i / photons.len();
        let stats: PhotonStats = t.last.stats.photons.expect("a photon map");
        let rmse = rmse_linear(&t.last.frame, &pm_ref).expect("same size");
        let value = photons[i % photons.len()];
        writeln!(
            pm_table,
            "| {} | {value} | {} | {} | {:.4} | {:.3} | {:.3} | {rmse:.5} |",
            ["default", "`--no-step photon-grid`"][reading],
            stats.emitted,
            stats.stored,
            stats.stored as f64 / stats.emitted as f64,
            (stats.trace_time + stats.build_time).as_secs_f64(),
            t.cpu
        )
        .unwrap();
        pm_curves[reading].push(Measurement {
            example: "photon_map",
            label: String::new(),
            reference: String::new(),
            knob: "--photons",
            value,
            seconds: t.cpu,
            rays: t.last.stats.counters.total(),
            rmse,
            perceptual: None,
        });
    }
    let without = |steps: &[&str]| (pm.run)(&with(&pm_base, &[&["--photons", "0"][..], steps].concat())).frame;
    let rest = rmse_linear(&without(&[]), &without(&no_step)).expect("same size");
    let estimate = |k: usize| {
        let t = &timed[k];
        let stats = t.last.stats.photons.expect("a photon map");
        (t.last.stats.elapsed.as_secs_f64(), (stats.trace_time + stats.build_time).as_secs_f64(), stats)
    };
    let (d_render, d_build, d_stats) = estimate(1);
    let (s_render, s_build, s_stats) = estimate(photons.len() + 1);
    let grid_versus = versus_measured(&pm_curves[1], &pm_curves[0], photons[1]);
    rows.push(Row {
        step: title(Step::PhotonGrid, "the photon grid, the cone-aimed Fibonacci emission and Russian roulette"),
        slide: "photons in all directions, each followed until it lands or is absorbed, the k nearest from a k-d tree",
        measured: "photon_map, default against `--no-step photon-grid`, 160x120 at 1 spp, `--photons` swept".into(),
        buys: format!(
            "at {} photons asked: {:.3} of the emitted photons stored against {:.4} ({} against {} emitted), trace and build {d_build:.3} s against {s_build:.3} s, render with the estimates {d_render:.3} s against {s_render:.3} s. Caustic error: {}",
            photons[1],
            d_stats.stored as f64 / d_stats.emitted as f64,
            s_stats.stored as f64 / s_stats.emitted as f64,
            d_stats.emitted,
            s_stats.emitted,
            grid_versus.describe("the grid", "the slide", &pm_curves[0])
        ) + &format!(
            " (without photons the two pictures differ by RMSE {rest:.5}: the rest of the difference is the caustic's). Russian roulette, which ends the aimed photons (`emitter.rs`), is part of this step: the slide's photons have none"
        ),
        verdict: noise_verdict(&grid_versus, &pm_curves[0]),
        code: vec![Code::File("src/lesson/photon_map/grid.rs"), Code::File("src/lesson/photon_map/emitter.rs")],
    });
    writeln!(details, "## 9. The photon map\n\nphoton_map at 160x120, one ray through each pixel centre, with and without `--no-step photon-grid`, against the default with {} photons and k = 400, another seed. The CPU time is the whole render's (photon pass, estimates and the rest). Without photons (`--photons 0`) the two pictures differ by RMSE {rest:.5}: the rest of the difference below is the caustic's. The slide's photons are capped at {MAX_BATCHES} batches, so that asking for 400,000 stores fewer.\n\n{pm_table}", plan.pick("3,200,000", "800,000")).unwrap();
}

/// Step 10: layer pruning against every layer bottom to top, on every example with a layered shader, each
/// rendered with and without `--no-step layer-pruning`, by default and with `--exhaustive`.
fn layer_pruning(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("layer pruning");
    let mut layer_table = String::new();
    writeln!(layer_table, "| example | pruned: wall / CPU s | rays | every layer: wall / CPU s | rays | every layer / pruned, CPU | PSNR between | largest difference | with `--exhaustive`: every layer / pruned, CPU |").unwrap();
    writeln!(layer_table, "|---|---:|---:|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut layer_ratios = Vec::new();
    let base = [&ONE_THREAD[..], &SIZE_320[..]].concat();
    let no_step = ["--no-step", Step::LayerPruning.name()];
    for ex in all {
        let (scene, _) = (ex.prepare)(&strings(&base));
        if !has_layered(&scene) {
            continue;
        }
        let jobs = [
            (ex, strings(&base)),
            (ex, with(&base, &no_step)),
            (ex, with(&base, &["--exhaustive"])),
            (ex, with(&base, &[&["--exhaustive"][..], &no_step[..]].concat())),
        ];
        // Small renders, close in cost where the step prunes little: more rounds.
        let more = Plan { quick: plan.quick, rounds: 3 * plan.rounds };
        let [pruned, every, pruned_ex, every_ex]: [Timed; 4] =
            side_by_side(&more, &jobs).try_into().ok().expect("four");
        let (p, level) = psnr(&pruned.last.frame, &every.last.frame);
        let rays = |t: &Timed| t.last.stats.counters.total() as f64 / 1e6;
        writeln!(
            layer_table,
            "| {} | {:.3} / {:.3} | {:.2} M | {:.3} / {:.3} | {:.2} M | {:.2}x | {} | {level} | {:.2}x, {:.2} M rays against {:.2} M |",
            ex.name,
            pruned.wall,
            pruned.cpu,
            rays(&pruned),
            every.wall,
            every.cpu,
            rays(&every),
            every.cpu / pruned.cpu,
            db(p),
            every_ex.cpu / pruned_ex.cpu,
            rays(&every_ex),
            rays(&pruned_ex)
        )
        .unwrap();
        layer_ratios.push((ex.name, every.cpu / pruned.cpu, rays(&every) / rays(&pruned), level));
    }
    let worst_level = layer_ratios.iter().map(|r| r.3).max().unwrap_or(0);
    let paying: Vec<&str> = layer_ratios.iter().filter(|r| r.1 >= NOISE && r.2 >= NOISE).map(|r| r.0).collect();
    rows.push(Row {
        step: title(
            Step::LayerPruning,
            "layer pruning (top-down, skip a layer of no weight: zero blend, or under an opaque layer)",
        ),
        slide: "every layer, bottom to top, each layer's rays passed their full weight",
        measured: "every example with a `Layered` shader, with and without `--no-step layer-pruning`, 320x240".into(),
        buys: format!(
            "the same picture within {worst_level} level(s); every layer over pruning: {}",
            layer_ratios
                .iter()
                .map(|(name, t, r, _)| format!("{t:.2}x the CPU time and {r:.2}x the rays on {name}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        verdict: if paying.is_empty() {
            BUYS_NOTHING.to_string()
        } else {
            format!("{KEPT_FOR_SPEED} (on {})", paying.join(", "))
        },
        code: vec![
            Code::Items("src/lesson/shader/layered.rs", &["fn weights", "fn layer_weight"]),
            Code::Lines("src/lesson/shader/layered.rs", "every_layer"),
        ],
    });
    writeln!(details, "## 10. Layer pruning\n\nEach example with a `Layered` shader rendered as it is and with `--no-step layer-pruning` (every layer bottom to top, as the slide's loop; `Layered::shade_every_layer` asks the same of one shader), and both again with `--exhaustive`; medians of {} rounds.\n\n{layer_table}", 3 * plan.rounds).unwrap();
}

/// The API page's glossy mirror (docs/homework-api.md, "Randomness in a shader"): `n` rays in the glossy
/// cone, each passed the tint's full factor. (The file is a whole homework: its `main` and its own test are
/// not this benchmark's.)
#[allow(dead_code, unused_imports)]
#[path = "../docs/homework_glossy.rs"]
mod homework_glossy;

/// A sky of bright and dark stripes across x, so that what the panels reflect shows.
struct Stripes;

impl Environment for Stripes {
    fn get(&self, dir: Vector) -> Color {
        if (dir.x * 6.0).sin() > 0.0 { Color::new(1.0, 0.95, 0.8) } else { Color::new(0.05, 0.1, 0.3) }
    }
}

/// The branching bound: the API page's N-ray glossy mirror on two facing panels (the scene of
/// tests/workbook/branching.rs), its rays with the bound against the most it would trace without; and the
/// rays the bound shared on the examples.
fn branching_bound(readings: &Readings, rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("branching bound");
    const N: u32 = 8;
    const DEPTH: u32 = 6;
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 0.0, 6.0), Vector::new(3.0, 1.0, -10.0), 70.0));
    for z in [-10.0, 10.0] {
        let glossy = homework_glossy::TintedGlossy { tint: Color::new(0.95, 0.9, 0.8), glossiness: 0.9, n: N };
        let panel = Node::new(Cube::new(Vector::ZERO, 1.0), Arc::new(glossy) as Arc<dyn Shader>);
        scene.add(panel.scale(Vector::new(12.0, 8.0, 0.05)).translate(Vector::new(0.0, 0.0, z)));
    }
    scene.environment = Some(Arc::new(Stripes));
    scene.max_depth = DEPTH;
    let settings =
        RenderSettings { width: 160, height: 120, spp: 1, threads: Some(1), progress: false, ..Default::default() };
    let clock = Clock::start();
    let (_, stats) = render(&scene, &settings).expect("render");
    let (_, cpu) = clock.stop();
    let c = &stats.counters;
    // Without the bound every shading point traces its N rays: the rays of depth d are at most the rays of
    // the camera rays' hits (depth 1, which the bound never limits) times N^(d-1).
    let unbounded: u64 =
        c.rays_by_depth[0] + (1..=DEPTH).map(|d| c.rays_by_depth[1] * (N as u64).pow(d - 1)).sum::<u64>();
    let mut depth_table = String::new();
    writeln!(depth_table, "| depth | rays with the bound | at most without it |").unwrap();
    writeln!(depth_table, "|---:|---:|---:|").unwrap();
    for d in 0..=DEPTH as usize {
        let without = if d == 0 { c.rays_by_depth[0] } else { c.rays_by_depth[1] * (N as u64).pow(d as u32 - 1) };
        writeln!(depth_table, "| {d} | {} | {without} |", c.rays_by_depth[d]).unwrap();
    }
    let runs = branch_budget_runs();
    let budget = branch_budget(&runs);
    let (rays_default, shared_default, rays_slide, shared_slide) =
        readings.shared.iter().fold((0, 0, 0, 0), |a, (_, s)| (a.0 + s[0], a.1 + s[1], a.2 + s[2], a.3 + s[3]));
    rows.push(Row {
        step: "The branching bound (`src/lesson/branching.rs`)".into(),
        slide: "no bound: a shader's N rays at every shading point, N^depth per camera ray",
        measured: format!(
            "the API page's {N}-ray glossy mirror (docs/homework_glossy.rs, each ray its full weight) on two facing panels, depth {DEPTH}, 160x120, 1 spp; and every example in both readings"
        ),
        buys: format!(
            "{:.2} M rays in {cpu:.2} CPU s with the bound (another {:.2} M given their siblings' mean colour instead of traced; {} traced at depth {DEPTH}), against at most {:.0} M without it ({:.0} M at depth {DEPTH}: {N}^{} times the camera rays' {} glossy rays; the bound allows {N} rays at a camera ray's hit, {SECONDARY_SPLIT} per shading point down to depth {SPLIT_DEPTH}, then 1). On the examples it shares no ray: {shared_default} of {:.1} M rays by default, {shared_slide} of {:.1} M with `--slide`. The budget of a branch ({RAYS_PER_BRANCH} rays; section \"The budget of a branch\") bounds the glass and Layered rays the rule lets through: the layered example with `--slide` at depth limit 64, 48x36, {budget}",
            c.total() as f64 / 1e6,
            c.shared_rays as f64 / 1e6,
            c.rays_by_depth[DEPTH as usize],
            unbounded as f64 / 1e6,
            (c.rays_by_depth[1] * (N as u64).pow(DEPTH - 1)) as f64 / 1e6,
            DEPTH - 1,
            c.rays_by_depth[1],
            rays_default as f64 / 1e6,
            rays_slide as f64 / 1e6
        ),
        verdict: format!("{KEPT_AS_GUARD}; not a step: on in both readings"),
        code: vec![Code::File("src/lesson/branching.rs")],
    });
    writeln!(details, "## The branching bound\n\nThe API page's {N}-ray glossy mirror on two panels facing each other, depth limit {DEPTH}, 160x120, one ray per pixel: the rays of each depth with the bound, and the most the same render would trace without it (every shading point tracing its {N} rays, every ray hitting a panel again).\n\n{depth_table}").unwrap();
    writeln!(details, "## The budget of a branch\n\nThe layered example at 48x36, 4 spp, one thread, in the slides' reading (nothing prunes its glass's and its Layered shaders' rays, each of which fits its shading point's budget) at depth limits the command line refuses there, and by default: every ray below the camera's is in the branch of one ray of a camera ray's hit, which traces at most {RAYS_PER_BRANCH}.\n\n{}", budget_table(&runs)).unwrap();
}

/// One render of the section "The budget of a branch": its reading, depth limit, rays, rays past the budget
/// and CPU seconds.
type BudgetRun = (&'static str, u32, u64, u64, f64);

/// The layered example at 48x36, 4 spp, one thread, in both readings at three depth limits.
fn branch_budget_runs() -> Vec<BudgetRun> {
    let mut runs = Vec::new();
    for (reading, args) in [("`--slide`", vec!["--slide".to_string()]), ("default", vec![])] {
        let (scene, _) = parse::<examples::layered::Options>(&args).prepare().expect("the layered example");
        for depth in [8, 64, 1000] {
            let mut scene = scene.clone();
            scene.max_depth = depth;
            let settings = RenderSettings {
                width: 48,
                height: 36,
                spp: 4,
                threads: Some(1),
                progress: false,
                ..Default::default()
            };
            let clock = Clock::start();
            let (_, stats) = render(&scene, &settings).expect("render");
            let (_, cpu) = clock.stop();
            runs.push((reading, depth, stats.counters.total(), stats.counters.over_budget_rays, cpu));
        }
    }
    runs
}

/// The ledger row's words on the budget of a branch.
fn branch_budget(runs: &[BudgetRun]) -> String {
    let find = |reading: &str, depth: u32| runs.iter().find(|r| r.0 == reading && r.1 == depth).expect("a run");
    let (slide, default) = (find("`--slide`", 64), find("default", 64));
    format!(
        "traces {:.2} M rays in {:.2} CPU s ({:.2} M past the budget, black), {:.1} times the default reading's {:.3} M",
        slide.2 as f64 / 1e6,
        slide.4,
        slide.3 as f64 / 1e6,
        slide.2 as f64 / default.2 as f64,
        default.2 as f64 / 1e6
    )
}

/// The table of the section "The budget of a branch".
fn budget_table(runs: &[BudgetRun]) -> String {
    let mut table =
        String::from("| reading | depth limit | rays | past the budget (black) | CPU s |\n|---|---:|---:|---:|---:|\n");
    for (reading, depth, rays, over, cpu) in runs {
        writeln!(table, "| {reading} | {depth} | {rays} | {over} | {cpu:.3} |").unwrap();
    }
    table
}

/// The end-of-run report's cost: its one piece of extra work, the probe for shaders that read the wavelength
/// without saying so ([`undeclared_dispersion`]), timed on each example against its render.
fn end_of_run_report(plan: &Plan, all: &[Ex], readings: &Readings, rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("end-of-run report");
    let mut table = String::new();
    writeln!(table, "| example | probe CPU ms | default render CPU s | share of the render |").unwrap();
    writeln!(table, "|---|---:|---:|---:|").unwrap();
    let mut worst: (f64, &str) = (0.0, "");
    for (ex, &(name, render_cpu)) in all.iter().zip(&readings.default_cpu) {
        let (scene, settings) = (ex.prepare)(&strings(&[&ONE_THREAD[..], &SIZE_320[..]].concat()));
        let (w, h) = (settings.width, settings.height);
        let camera = scene.camera.frame(w, h);
        const REPEAT: usize = 20;
        let times: Vec<f64> = (0..plan.rounds.max(3))
            .map(|_| {
                let clock = Clock::start();
                for _ in 0..REPEAT {
                    std::hint::black_box(undeclared_dispersion(&scene, &camera, w, h));
                }
                clock.stop().1 / REPEAT as f64
            })
            .collect();
        let probe = median(times);
        let share = probe / render_cpu;
        if share > worst.0 {
            worst = (share, name);
        }
        writeln!(table, "| {name} | {:.3} | {render_cpu:.3} | {:.2}% |", 1e3 * probe, 100.0 * share).unwrap();
    }
    rows.push(Row {
        step: "The end-of-run report (`src/lesson/diagnostics.rs`)".into(),
        slide: "no report: a NaN pixel, a self-hit or a shader's undeclared dispersion goes unnoticed",
        measured: "every example at 320x240: the report's extra work, the undeclared-dispersion probe (16x16 rays, each shader once), against the render".into(),
        buys: format!(
            "the source of a NaN, a self-hit or an undeclared dispersion named after the render; it costs at most {:.2}% of a render's CPU time ({})",
            100.0 * worst.0,
            worst.1
        ),
        verdict: format!("{KEPT_AS_GUARD}; not a step: on in both readings"),
        code: vec![Code::File("src/lesson/diagnostics.rs")],
    });
    writeln!(details, "## The end-of-run report\n\nThe probe for shaders that read the wavelength without saying so (`undeclared_dispersion`, run once after every render), timed alone on each example's scene (median of {} rounds of {} calls), against the example's default render (the table of `--slide` against the default).\n\n{table}", plan.rounds.max(3), 20).unwrap();
}

/// What runs beyond the slides' formulas without being a step: the deviations that each file notes.
fn deviations(rows: &mut Vec<Row>) {
    rows.push(Row {
        step: "The Fresnel cosine on leaving glass (`src/lesson/math.rs`, `fresnel`)".into(),
        slide: "Schlick's formula with the cosine of the incoming ray on both sides of the glass",
        measured: "not measured: it has no setting".into(),
        buys: "leaving the denser medium, the cosine of the transmitted angle, as Schlick prescribes, and 1 under total internal reflection, where the slide's cosine lets part of the light be transmitted that cannot be, so a Fresnel glass loses energy".into(),
        verdict: NOT_A_STEP.to_string(),
        code: Vec::new(),
    });
    rows.push(Row {
        step: "The light loop's geometric-normal test (`src/lesson/light.rs`, `light_loop`)".into(),
        slide: "a lamp lights the point when the shading normal faces it",
        measured: "not measured: it has no setting".into(),
        buys: "a lamp is skipped, with no shadow ray, when the shading normal and the surface's own normal disagree about its side (a smooth mesh's interpolated normal near its silhouette), which would light a point that faces away from it".into(),
        verdict: NOT_A_STEP.to_string(),
        code: Vec::new(),
    });
    rows.push(Row {
        step: "Russian roulette in the photon emitter (`src/lesson/photon_map/emitter.rs`)".into(),
        slide: "a photon followed until it lands, is absorbed or reaches the depth limit",
        measured: "with step 9, of which it is part".into(),
        buys: "ends the aimed photons' paths at random, their power raised to keep the estimate unbiased; `--no-step photon-grid` leaves it out with the rest of the step".into(),
        verdict: format!("part of step 9 (`{}`)", Step::PhotonGrid.name()),
        code: Vec::new(),
    });
}

/// The deviations from the slides that are not steps, for the ledger's section "What stays in both readings":
/// (row, where, the slides or the course, why it stays in both readings). `tests/workbook/deviations.rs` checks that
/// every "Deviation" comment of `src/lesson` names a row of it or a step.
const BOTH_READINGS: &[(&str, &str, &str, &str)] = &[
    (
        "robust-offsets",
        "src/lesson/ray.rs (`Ray::spawn`), the reflection and refraction shaders",
        "a new ray starts `1e-6` along the normal or the ray",
        "a fixed offset is too large for a scene at 1e-4 and too small for one at 1e6 (DESIGN: scenes scaled by 1e-4..1e5 and moved 1e6 render the same picture); the offset by the hit's error bound is the guard that makes every reading's picture right at any scale",
    ),
    (
        "centred-aa-pattern",
        "src/lesson/adaptive_aa.rs",
        "the course's five samples centred on (0.3, 0.3) of the pixel",
        "the same pattern moved by 0.2 to centre on the pixel's centre, where the single sample of every other render goes: otherwise the refined pixels shift by 0.2 pixels against the rest",
    ),
    (
        "srgb-output",
        "src/lesson/color.rs, src/lesson/bitmap.rs (the 8-bit table)",
        "the course's program reads and writes the codes as light, with no curve",
        "images are sRGB: without the curve every picture is too dark and every texture too bright; `--encoding raw` renders the course's way. 8-bit texels are decoded by a table of the same curve (the curve, computed once), which is not the filter step's (`texel-filter` changes which texels are read, not how a code becomes light)",
    ),
    (
        "unit-free-direction",
        "src/lesson/environment.rs",
        "`Environment::get` assumes a unit direction",
        "only the direction matters; a shader's unnormalised direction (or a degenerate one) still gives a colour of the image instead of a wrong look-up or a NaN",
    ),
    (
        "ear-clipping",
        "src/lesson/geometry/polygon.rs",
        "the course fan-triangulates a polygon",
        "a fan is wrong for a concave polygon; for a convex one both give the same surface (not the same triangles)",
    ),
    (
        "fov-axis",
        "src/lesson/camera.rs",
        "the course measures `fov` across the diagonal",
        "an option (`--fov-axis`), whose first choice is the course's diagonal: nothing changes unless it is asked for",
    ),
    (
        "blend-clamp",
        "src/lesson/shader/layered.rs",
        "`res = res * (1 - blend) + layer * blend` with any blend",
        "a blend outside [0, 1] (a bright HDR image as a blend texture) would give a layer a negative or larger-than-one weight: light from nothing. Clamped to the range of an opacity; the examples' blends are within it, so their pictures do not change",
    ),
    (
        "glossy-kept-samples",
        "src/lesson/shader/reflection.rs",
        "a sample under the surface must be caught (the slide does not say how)",
        "such a sample is dropped and the average taken over the samples kept; should every one be dropped (grazing angles, low glossiness) the mirror ray is traced, so the surface never turns black",
    ),
    (
        "branching-bound",
        "src/lesson/branching.rs",
        "every ray a shader asks for is traced",
        "two averaging shaders facing each other branch N^depth rays per camera ray (a render that never ends); the core bounds a shading point's rays (section \"The branching bound\"), below the course's default `maxTraceDepth`, so the course's scenes and the examples trace exactly their rays. Glass and Layered shaders, whose rays fit that bound however faint, double their rays at every level when nothing prunes them: each ray of a camera ray's hit traces at most `RAYS_PER_BRANCH` rays below it (section \"The budget of a branch\"), four times the examples' largest branch, so a program of the library's at any depth limit stays bounded",
    ),
    (
        "tile-size",
        "src/lesson/texture/bitmap.rs",
        "the course's `scaling` of a bitmap texture",
        "the same number, named `tile_size` for what it is (a checker's `scaling` multiplies u/v instead); a scene file's `scaling` is read unchanged",
    ),
    (
        "pixel-streams",
        "src/lesson/sampling.rs, src/lesson/rng.rs",
        "the C library's global `rand()`",
        "every random number comes from the pixel's own stream, so a picture is the same byte for byte whatever the thread count (DESIGN: deterministic output)",
    ),
    (
        "wavelength-bands",
        "src/lesson/spectral/mod.rs",
        "each pass one spectral line, weighted by its colour",
        "each pass a band of wavelengths, its colour the integral of the colour-matching functions over the band, so that the K colours add up to the light's colour exactly for any K (white light stays white)",
    ),
    (
        "lamp-side-check",
        "src/lesson/light.rs",
        "the light loop tests the shading normal alone",
        "a lamp is skipped when the shading normal and the surface's own normal disagree about its side (a smooth mesh near its silhouette), where it would light a point that faces away from it",
    ),
    (
        "eta-ratio",
        "src/lesson/math.rs",
        "`refract`'s comment says `ior = eta2 / eta1`",
        "the formula (and its caller, which passes `1 / ior` entering) uses incoming over outgoing; the parameter is named for what the formula needs. Nothing is computed differently",
    ),
];

/// Step 11: camera-relative coordinates against world coordinates, on every example moved far away.
fn camera_relative(all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("camera-relative coordinates");
    let mut far_table = String::new();
    writeln!(
        far_table,
        "| example | RMSE, world coordinates | pixels > 8 levels | RMSE, camera-relative | pixels > 8 levels |"
    )
    .unwrap();
    writeln!(far_table, "|---|---:|---:|---:|---:|").unwrap();
    let mut far_summary = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let offset = Vector::new(1e6, -5e5, 2.5e5);
    let mut left_as_is = 0;
    for ex in all {
        let scene = (ex.scene)();
        let mut relative = scene.clone();
        relative.relative_to_camera();
        left_as_is += (relative.camera.position == scene.camera.position) as usize;
        let canonical = picture(&scene);
        let far = moved(&scene, offset);
        let world = picture(&far);
        let mut relative_scene = far.clone();
        relative_scene.relative_to_camera();
        let relative = picture(&relative_scene);
        let (ew, er) =
            (rmse_linear(&world, &canonical).expect("size"), rmse_linear(&relative, &canonical).expect("size"));
        let (cw, cr) = (changed_pixels(&world, &canonical), changed_pixels(&relative, &canonical));
        far_summary = (far_summary.0.max(ew), far_summary.1.max(er), far_summary.2.max(cw), far_summary.3.max(cr));
        writeln!(far_table, "| {} | {ew:.4} | {:.1}% | {er:.4} | {:.1}% |", ex.name, 100.0 * cw, 100.0 * cr).unwrap();
    }
    rows.push(Row {
        step: title(Step::CameraRelative, "camera-relative coordinates"),
        slide: "world coordinates",
        measured: "every example moved by (1e6, -5e5, 2.5e5), 160x120, 1 spp, against the example in place".into(),
        buys: format!(
            "nothing on the examples as shipped: {left_as_is} of {} are left as they are (they sit around the origin). Moved far away: worst RMSE {:.4} and {:.1}% of the pixels off by more than 8 levels in world coordinates, against {:.4} and {:.1}% camera-relative",
            all.len(),
            far_summary.0,
            100.0 * far_summary.2,
            far_summary.1,
            100.0 * far_summary.3
        ),
        verdict: KEPT_AS_GUARD.to_string(),
        code: vec![Code::Items("src/lesson/scene.rs", &["fn relative_to_camera"]), Code::Lines("src/app/cli/example.rs", "relative_to_camera")],
    });
    writeln!(details, "## 11. Camera-relative coordinates\n\nEach example's scene moved by (1e6, -5e5, 2.5e5) (camera and lights with it), rendered in world coordinates and relative to the camera, against the scene in place.\n\n{far_table}").unwrap();
}

fn write_ledger(plan: &Plan, rows: &[Row], examples_table: &str, details: &str, seconds: f64) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let machine = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("model name").map(|m| m.trim_start_matches([' ', '\t', ':']).to_string()))
        })
        .unwrap_or_else(|| "an unknown CPU".to_string());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let load = std::fs::read_to_string("/proc/loadavg")
        .map(|l| l.split(' ').take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_default();
    let date = std::process::Command::new("date")
        .args(["-u", "+%Y-%m-%d %H:%M UTC"])
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default();
    let mut doc = String::new();
    writeln!(doc, "# Beyond the slides: what each step buys").unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "One renderer reads every example in two ways. `--slide` renders it as the slides write it (every step of `src/lesson/beyond.rs` left out); the default takes, beside each slide's code, the steps below. Each step is a setting: `--no-step NAME` leaves one out of the default, `--step NAME` adds one to `--slide`. Each step's row measures the renderer with the step against the same renderer without it, side by side in one run: the time at equal error for the steps that leave the picture as it is, the error at equal time (and the time at equal error) for the steps that change the noise; and the lines of code the step costs. The verdict says why a step stays (for speed, for noise, or as a guard, its row then showing the scene where it pays) or that it buys nothing beyond the noise. Below the steps, rows for what runs beyond the slides without being a step: the guards that hold in both readings, and the deviations from the slides' formulas.").unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "The glossy split depth and static dispatch are no longer steps: the first reached no example and the core's branching bound now does its job in both readings; the second is how each course type is stored, once, as the node's own value (`src/lesson/shader/material.rs` and its like for shapes, textures and environments), which both readings go through, so there is nothing left to switch.").unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "Written by `cargo bench --bench beyond` ({}), in {:.0} s on {date}: {machine}, {cores} cores shared with other work (load average {load} at the end). Every render runs on one thread; each figure is the median of {} interleaved round(s); \"CPU s\" is user plus system time of the whole process. In the equal-time and equal-error comparisons of a sweep, a point's time is its rays times its curve's median CPU time per ray (steadier on a loaded machine than one point's own median, which the tables give). The bench is `benches/beyond.rs`; its doc comment says how each figure is made.", if plan.quick { "`--quick`" } else { "full" }, seconds, plan.rounds).unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "## The ledger\n").unwrap();
    writeln!(doc, "| step | the slide's version | measured on | what it buys | verdict | lines |").unwrap();
    writeln!(doc, "|---|---|---|---|---|---:|").unwrap();
    for row in rows {
        let lines = match row.code.is_empty() {
            true => String::new(),
            false => row.code.iter().map(lines_of).sum::<usize>().to_string(),
        };
        writeln!(doc, "| {} | {} | {} | {} | {} | {lines} |", row.step, row.slide, row.measured, row.buys, row.verdict)
            .unwrap();
    }
    writeln!(doc).unwrap();
    writeln!(doc, "## `--slide` against the default, every example\n\nAt 320x240, the examples' default samples, one thread, both readings through the one renderer. The two readings differ where the default's steps change the picture: other random numbers (stratified pixel and disc samples, hero wavelengths against 8 passes), bilinear against nearest texels, the photon grid's estimate against the k nearest, and adaptive depth control (within a few levels, see step 1).\n\n{examples_table}").unwrap();
    doc.push_str(details);
    writeln!(doc, "## What stays in both readings\n\nThe deviations from the slides and the course's program that are not steps: each runs under `--slide` as in the default, for the reason given. A comment in `src/lesson` that says \"Deviation\" names its row here (`ledger: NAME`) or the step it belongs to (`tests/workbook/deviations.rs`).\n\n| row | where | the slides or the course | why it stays in both readings |\n|---|---|---|---|").unwrap();
    for (row, place, slides, why) in BOTH_READINGS {
        writeln!(doc, "| `{row}` | {place} | {slides} | {why} |").unwrap();
    }
    writeln!(doc).unwrap();
    writeln!(doc, "## What the lines count\n\nNon-blank lines that are not comments, of the step's own items (code the step shares with the slide's version, such as the layered shader's loop that pruning works in, or the render loop that calls a sampler, is not counted):\n").unwrap();
    for row in rows.iter().filter(|row| !row.code.is_empty()) {
        let parts: Vec<String> = row.code.iter().map(|c| format!("{} ({})", describe_code(c), lines_of(c))).collect();
        writeln!(doc, "- {}: {}", row.step, parts.join("; ")).unwrap();
    }
    let path =
        if plan.quick { root.join("target/beyond-the-slides.md") } else { root.join("docs/beyond-the-slides.md") };
    std::fs::write(&path, doc).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    eprintln!("wrote {}", path.display());
}
