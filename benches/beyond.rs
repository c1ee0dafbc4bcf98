//! The ledger of the steps beyond the slides: writes `docs/beyond-the-slides.md`.
//!
//! ```sh
//! cargo bench --bench beyond              # the whole ledger, 3 rounds: docs/beyond-the-slides.md
//! cargo bench --bench beyond -- --quick   # 1 round, fewer points: target/beyond-the-slides.md
//! ```
//!
//! Every step that the default reading takes beyond the slides' reading (`--slide`, every step of `src/lesson/beyond.rs` left out) is
//! measured against the slide's version of it, side by side in this one process: in each round every
//! variant runs once, the order alternating from round to round, so that a machine shared with other work
//! slows both alike; each figure is the median over the rounds. Renders run on one thread; CPU time
//! (`getrusage`, user plus system, the whole process) stands beside the wall time, and the comparisons use
//! the CPU time. Where a step leaves the picture as it is, within a few 8-bit levels (an exact step), the
//! ledger gives the time at equal error; where a step changes the noise it gives the error (RMSE of the linear
//! values against a converged reference of another seed) at equal time, and the time at equal error, both
//! interpolated on the log-log curve of the sweep; there a point's time is its rays times its curve's median
//! CPU time per ray, which is steadier on a loaded machine than one point's median (the tables give each
//! point's own). Steps that no example reaches, or that have no switch, are timed at unit level (the same
//! rays through the library's two functions). Lines of code are the non-blank, non-comment lines of the
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
use lecture6::lesson::color::Color;
use lecture6::lesson::dispatch::through_trait_objects;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::geometry::Mesh;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::{Node, NodeTree};
use lecture6::lesson::photon_map::{PhotonMap, PhotonStats};
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, RenderStats, Stratifier, render, thread_pool};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::{GLOSSY_SPLIT_DEPTH, Layered, Reflection, Shader};
use lecture6::lesson::slide;
use shared::{cpu_time, median, spheres_scene};
use std::any::Any;
use std::fmt::Write as _;
use std::path::Path;
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

/// Renders an example with these options, as its binary does (`--slide` through the slides' reading); the
/// photon map of the default reading is built again inside the timed part.
fn run<E: Example>(args: &[String]) -> Run {
    let cli = parse::<E>(args);
    let (mut scene, settings) = cli.prepare().unwrap_or_else(|e| panic!("options {args:?}: {e}"));
    let clock = Clock::start();
    let result = if cli.common.slide {
        slide::render(&scene, &settings)
    } else {
        if scene.photon_map.is_some() {
            let pool = thread_pool(settings.threads).expect("thread pool");
            let map = pool.install(|| PhotonMap::build(&scene, settings.seed)).expect("photon map");
            scene.photon_map = map.map(Arc::new);
        }
        render(&scene, &settings)
    };
    let (frame, stats) = result.unwrap_or_else(|e| panic!("render {args:?}: {e}"));
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

/// Renders a prepared scene through the default reading, timed.
fn run_scene(scene: &Scene, settings: &RenderSettings) -> Run {
    let clock = Clock::start();
    let (frame, stats) = render(scene, settings).expect("render");
    let (wall, cpu) = clock.stop();
    Run { frame, stats, wall, cpu }
}

/// The scene with every `Layered` shader shading every layer, as the slide's loop does.
fn every_layer(scene: &Scene) -> Option<Scene> {
    let mut out = scene.clone();
    let mut found = false;
    for node in &mut out.nodes {
        if let Some(layered) = (&*node.shader as &dyn Any).downcast_ref::<Layered>() {
            let mut every = layered.clone();
            every.shade_every_layer(true);
            node.shader = Arc::new(every);
            found = true;
        }
    }
    found.then_some(out)
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

/// Whether two closest hits are the same: both misses, or the same node at the same distance (within
/// 1e-5 of it, relative).
fn same_hit(a: Option<(f32, *const Node)>, b: Option<(f32, *const Node)>) -> bool {
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

/// One row of the ledger.
struct Row {
    step: &'static str,
    slide: &'static str,
    measured: String,
    buys: String,
    code: Vec<Code>,
}

/// Whether a shader is a glossy mirror, or a layered shader with one among its layers.
fn has_glossy(shader: &dyn Shader) -> bool {
    let any = shader as &dyn Any;
    if let Some(mirror) = any.downcast_ref::<Reflection>() {
        return mirror.glossiness < 1.0;
    }
    any.downcast_ref::<Layered>().is_some_and(|l| l.layers().iter().any(|layer| has_glossy(&*layer.shader)))
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

fn main() {
    let args = Args::parse();
    let plan = Plan { quick: args.quick, rounds: args.rounds.unwrap_or(if args.quick { 1 } else { 3 }) };
    let all = every_example!(workbook_examples);
    let started = Instant::now();
    let mut rows = Vec::new();
    let mut details = String::new();
    let (examples_table, split_table, split_reached) = slide_against_default(&plan, &all, &mut rows, &mut details);
    node_bvh(&plan, &mut rows, &mut details);
    two_phase_nearest_hit(&plan, &all, &mut rows, &mut details);
    mesh_bvh(&plan, &all, &mut rows);
    bitmap_filtering(&plan, &all, &mut rows, &mut details);
    stratified_anti_aliasing(&plan, &all, &mut rows, &mut details);
    disc_samples(&plan, &all, &mut rows, &mut details);
    glossy_split_depth(&mut rows, &mut details, &split_table, &split_reached);
    hero_wavelengths(&plan, &all, &mut rows, &mut details);
    photon_map(&plan, &all, &mut rows, &mut details);
    layer_pruning(&plan, &all, &mut rows, &mut details);
    camera_relative(&all, &mut rows, &mut details);
    static_dispatch(&plan, &all, &mut rows, &mut details);
    write_ledger(&plan, &rows, &examples_table, &details, started.elapsed().as_secs_f64());
}

/// `--slide` against the default on every example, and `--exhaustive` against the default (step 1) from the
/// same runs; returns the examples' table and, for step 8, the table of the glossy examples and those whose
/// depth limit reaches the split.
fn slide_against_default(
    plan: &Plan,
    all: &[Ex],
    rows: &mut Vec<Row>,
    details: &mut String,
) -> (String, String, Vec<&'static str>) {
    eprintln!("every example: default, --exhaustive, --slide");
    let mut examples_table = String::new();
    writeln!(
        examples_table,
        "| example | default: wall / CPU s | rays | `--slide`: wall / CPU s | rays | `--slide` / default, CPU | PSNR between |"
    )
    .unwrap();
    writeln!(examples_table, "|---|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut adaptive_table = String::new();
    writeln!(adaptive_table, "| example | default CPU s | rays | `--exhaustive` CPU s | rays | time saved | PSNR between | largest difference |").unwrap();
    writeln!(adaptive_table, "|---|---:|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut adaptive_best: Option<(&str, f64, f64, u64, u64)> = None;
    let mut adaptive_worst_level = 0u8;
    let mut split_table = String::new();
    let mut split_reached = Vec::new();
    writeln!(
        split_table,
        "| example | glossy mirror | `max_depth` | rays deeper than {GLOSSY_SPLIT_DEPTH} (default) |"
    )
    .unwrap();
    writeln!(split_table, "|---|---|---:|---:|").unwrap();
    for ex in all {
        let base = [&ONE_THREAD[..], &SIZE_320[..]].concat();
        let jobs = [(ex, strings(&base)), (ex, with(&base, &["--exhaustive"])), (ex, with(&base, &["--slide"]))];
        let [default, exhaustive, slide]: [Timed; 3] = side_by_side(plan, &jobs).try_into().ok().expect("three");
        let rays = |t: &Timed| t.last.stats.counters.total();
        let (p, _) = psnr(&default.last.frame, &slide.last.frame);
        writeln!(
            examples_table,
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
        let (scene, _) = (ex.prepare)(&strings(&base));
        let glossy = scene.nodes.iter().any(|n| has_glossy(&*n.shader));
        let deep: u64 = default.last.stats.counters.rays_by_depth[(GLOSSY_SPLIT_DEPTH as usize + 1)..].iter().sum();
        if glossy {
            writeln!(split_table, "| {} | yes | {} | {deep} |", ex.name, scene.max_depth).unwrap();
            if scene.max_depth > GLOSSY_SPLIT_DEPTH {
                split_reached.push(ex.name);
            }
        }
    }
    let (name, d_cpu, e_cpu, d_rays, e_rays) = adaptive_best.expect("some example prunes rays");
    rows.push(Row {
        step: "1. Adaptive ray-tree depth control",
        slide: "`raytrace` with `MAX_RAY_DEPTH` only",
        measured: "every example, `--exhaustive` against the default, 320x240, 1 thread".into(),
        buys: format!(
            "the same picture within {adaptive_worst_level} level(s) in the worst pixel; at equal error, {:.2}x less CPU time on {name} ({d_cpu:.3} s against {e_cpu:.3} s, {:.2} M rays against {:.2} M)",
            e_cpu / d_cpu,
            d_rays as f64 / 1e6,
            e_rays as f64 / 1e6
        ),
        code: vec![
            Code::Items("src/lesson/scene.rs", &["fn srgb8_finest_step"]),
            Code::Lines("src/lesson/scene.rs", "min_ray_weight"),
            Code::Lines("src/lesson/scene.rs", "pruned_rays"),
            Code::Lines("src/lesson/ray.rs", "weight"),
        ],
    });
    writeln!(details, "## 1. Adaptive ray-tree depth control\n\nThe examples whose ray count changes with `--exhaustive` (the others trace the same rays):\n\n{adaptive_table}").unwrap();
    (examples_table, split_table, split_reached)
}

/// Step 2: the node BVH against the loop over the nodes, on N spheres.
fn node_bvh(plan: &Plan, rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("node BVH");
    let mut bvh_table = String::new();
    writeln!(bvh_table, "| spheres | BVH ns/ray | slide's loop ns/ray | loop / BVH | same hits |").unwrap();
    writeln!(bvh_table, "|---:|---:|---:|---:|---:|").unwrap();
    let counts: Vec<usize> = plan.pick(vec![10, 100, 1000, 10000], vec![10, 100, 1000]);
    let mut bvh_figures = Vec::new();
    for &n in &counts {
        let scene = spheres_scene(n);
        let tree = NodeTree::build(&scene.nodes).expect("more nodes than the loop takes");
        let rays = camera_rays(&scene, 160, 120);
        let nodes = &scene.nodes;
        let slide_nodes = slide::model_transform::slide_nodes(nodes);
        let by_tree = |ray: &Ray| {
            tree.nearest_hit(nodes, ray)
                .and_then(|(hit, node)| node.surface(ray, &hit).map(|i| (i.distance, node as *const Node)))
        };
        let by_loop = |ray: &Ray| {
            slide::model_transform::closest_hit(&slide_nodes, ray).map(|(i, node)| (i.distance, node as *const Node))
        };
        let same = rays.iter().filter(|r| same_hit(by_tree(r), by_loop(r))).count();
        let repeat = (20_000 / n).clamp(1, 20);
        let t = per_ray(plan, &rays, repeat, &[&|r| by_tree(r).is_some() as u64, &|r| by_loop(r).is_some() as u64]);
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
        step: "2. The node BVH (above 8 nodes)",
        slide: "the loop over the nodes",
        measured: "no example (all have at most 8 nodes); N spheres on a plane, camera rays at 160x120".into(),
        buys: format!(
            "the same closest hits; CPU time per camera ray {} spheres, loop over BVH. No example reaches it",
            speedups.join(", ")
        ),
        code: vec![
            Code::Items(
                "src/lesson/node.rs",
                &[
                    "struct NodeTree",
                    "impl NodeTree",
                    "const LINEAR_NODES",
                    "const TIE",
                    "fn tie",
                    "struct Closest",
                    "impl Closest",
                ],
            ),
            Code::Items("src/lesson/scene.rs", &["fn prepared", "fn intersects"]),
            Code::Lines("src/lesson/scene.rs", "node_tree"),
        ],
    });
    writeln!(details, "## 2. The node BVH\n\nThe nearest hit of each camera ray (160x120, pixel centres) through `NodeTree::nearest_hit` and `Node::surface`, against `slide::model_transform::closest_hit`; \"same hits\" counts the rays whose node and distance agree (a tie within `TIE` may go either way).\n\n{bvh_table}").unwrap();
}

/// Step 3: the two-phase nearest hit against the slide's `Node::intersect` loop, on the examples' camera rays.
fn two_phase_nearest_hit(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("two-phase nearest hit");
    let mut phase_table = String::new();
    writeln!(
        phase_table,
        "| example | nodes | two-phase ns/ray | slide's loop ns/ray | loop / two-phase | same hits |"
    )
    .unwrap();
    writeln!(phase_table, "|---|---:|---:|---:|---:|---:|").unwrap();
    let mut phase_ratios = Vec::new();
    for ex in all {
        let (scene, _) = (ex.prepare)(&strings(&SIZE_320));
        if scene.nodes.iter().any(|n| (&*n.geometry as &dyn Any).is::<Mesh>()) {
            continue; // a mesh's triangle loop is step 4's
        }
        let rays = camera_rays(&scene, 320, 240);
        let slide_nodes = slide::model_transform::slide_nodes(&scene.nodes);
        let two_phase = |ray: &Ray| scene.closest_hit(ray).map(|(i, node)| (i.distance, node as *const Node));
        let slides = |ray: &Ray| {
            slide::model_transform::closest_hit(&slide_nodes, ray).map(|(i, node)| (i.distance, node as *const Node))
        };
        let same = rays.iter().filter(|r| same_hit(two_phase(r), slides(r))).count();
        let t = per_ray(plan, &rays, 10, &[&|r| two_phase(r).is_some() as u64, &|r| slides(r).is_some() as u64]);
        phase_ratios.push((ex.name, t[1] / t[0]));
        writeln!(
            phase_table,
            "| {} | {} | {:.1} | {:.1} | {:.2}x | {:.3}% |",
            ex.name,
            scene.nodes.len(),
            t[0],
            t[1],
            t[1] / t[0],
            100.0 * same as f64 / rays.len() as f64
        )
        .unwrap();
    }
    let ratios: Vec<f64> = phase_ratios.iter().map(|r| r.1).collect();
    let (lo, hi) = (ratios.iter().copied().fold(f64::INFINITY, f64::min), ratios.iter().copied().fold(0.0, f64::max));
    rows.push(Row {
        step: "3. The two-phase nearest hit (`Geometry::hit`, then `surface` of the winner)",
        slide: "`Node::intersect` on every node, the full hit description each time",
        measured: "the examples without a mesh, camera rays at 320x240, unit level".into(),
        buys: format!(
            "the same closest hits; the slide's loop takes {lo:.2}x to {hi:.2}x the CPU time per camera ray{}{}",
            if hi < 1.05 { ": nothing measurable" } else { "" },
            match ratios.iter().filter(|&&r| r < 0.95).count() {
                0 => String::new(),
                faster => format!(" (the slide's loop is the faster on {faster} of {} examples)", ratios.len()),
            }
        ),
        code: vec![
            Code::Items("src/lesson/geometry/mod.rs", &["struct Hit", "impl Hit", "fn hit(", "fn surface("]),
            Code::Items(
                "src/lesson/node.rs",
                &["fn hit(", "fn hit_transformed", "fn surface(", "fn nearest_hit_linear"],
            ),
            Code::Items("src/lesson/scene.rs", &["fn nearest_hit", "fn closest_hit"]),
        ],
    });
    writeln!(details, "## 3. The two-phase nearest hit\n\n`Scene::closest_hit` (every node's `hit`, then the winner's `surface`) against `slide::model_transform::closest_hit` (every node's full `intersect`), on each example's camera rays through the pixel centres. The per-geometry `hit`/`surface` pairs are not counted in the lines.\n\n{phase_table}").unwrap();
}

/// Step 4: the mesh BVH against the bounding box and every triangle, on model_transform's teapots.
fn mesh_bvh(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>) {
    eprintln!("mesh BVH");
    let mt = &all[example(all, "model_transform")];
    let (scene, _) = (mt.prepare)(&strings(&SIZE_160));
    let meshes: Vec<&Node> = scene.nodes.iter().filter(|n| (&*n.geometry as &dyn Any).is::<Mesh>()).collect();
    let triangles: usize = meshes
        .iter()
        .map(|n| (&*n.geometry as &dyn Any).downcast_ref::<Mesh>().expect("a mesh").triangle_count())
        .sum();
    let rays = camera_rays(&scene, 160, 120);
    let slide_meshes: Vec<_> = slide::model_transform::slide_nodes(&scene.nodes)
        .into_iter()
        .filter(|n| (&*n.node.geometry as &dyn Any).is::<Mesh>())
        .collect();
    let by_bvh = |ray: &Ray| {
        meshes
            .iter()
            .filter_map(|n| n.intersect(ray, f32::INFINITY).map(|i| (i.distance, *n as *const Node)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
    };
    let by_loop = |ray: &Ray| {
        slide_meshes
            .iter()
            .filter_map(|n| {
                slide::model_transform::intersect(n, ray, f32::INFINITY).map(|i| (i.distance, n.node as *const Node))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
    };
    let same = rays.iter().filter(|r| same_hit(by_bvh(r), by_loop(r))).count();
    let t = per_ray(plan, &rays, 1, &[&|r| by_bvh(r).is_some() as u64, &|r| by_loop(r).is_some() as u64]);
    let mt_timed = side_by_side(plan, &[(mt, with(&[&ONE_THREAD[..], &SIZE_320[..]].concat(), &[]))]);
    rows.push(Row {
        step: "4. The mesh BVH with four-wide watertight triangles",
        slide: "the mesh's bounding box, then every triangle",
        measured: format!("model_transform's {} mesh node(s), {triangles} triangles, camera rays at 160x120", meshes.len()),
        buys: format!(
            "{:.3}% of the rays find the same hit; {:.0} ns per camera ray against {:.0} ns: {:.0}x less CPU time at equal error (the whole example: {:.3} CPU s at 320x240). `bvh.rs` also serves the node BVH of step 2",
            100.0 * same as f64 / rays.len() as f64,
            t[0],
            t[1],
            t[1] / t[0],
            mt_timed[0].cpu
        ),
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
        step: "5. Bilinear texel filtering and the sRGB byte table",
        slide: "one texel per look-up",
        measured: "bitmap_textures, `--filter bilinear|nearest`, 320x240, each against its own converged picture".into(),
        buys: format!(
            "a different picture (the two converged pictures differ by RMSE {bias:.4}, {}): the texture blended between texels instead of stepping from one to the next. Noise: {}. CPU time per ray of bilinear over nearest: {:.2}x",
            db(bias_psnr),
            v.describe("bilinear", "nearest", &modeled(&bilinear)),
            per_ray
        ),
        code: vec![
            Code::Items("src/lesson/bitmap.rs", &["fn neighbours", "fn wrapped_pair", "enum Texels", "fn sample", "fn filtered", "fn bilinear", "fn decode", "enum Filter"]),
            Code::Items("src/lesson/color.rs", &["fn srgb8_to_linear_table"]),
        ],
    });
    writeln!(details, "## 5. Bitmap filtering\n\nbitmap_textures at 320x240, each filter against its own converged picture ({ref_spp} spp, another seed): the noise of each. The two converged pictures differ by RMSE {bias:.5} ({}).\n", db(bias_psnr)).unwrap();
    curve_table(details, "spp", &[("bilinear", &bilinear), ("nearest", &nearest)]);
}

/// Step 6: stratified pixel samples against random points of the pixel.
fn stratified_anti_aliasing(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("stratified anti-aliasing");
    let mut aa_table = String::new();
    writeln!(
        aa_table,
        "| example | spp | stratified RMSE | random RMSE | random / stratified | stratified CPU s | random CPU s |"
    )
    .unwrap();
    writeln!(aa_table, "|---|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut aa_summary = Vec::new();
    for name in ["bitmap_textures", "model_transform", "fresnel"] {
        let ex = &all[example(all, name)];
        let size = [&ONE_THREAD[..], &SIZE_160[..]].concat();
        let converged = reference(ex, &[&size[..], &["--spp", plan.pick("1024", "256"), "--seed", "7"]].concat());
        let (scene, _) = (ex.prepare)(&strings(&size));
        for spp in plan.pick(vec![4, 16], vec![4]) {
            let pictures = |stratified: bool| render_aa(&scene, 160, 120, spp, stratified);
            let mut times = [Vec::new(), Vec::new()];
            let mut frames = [None, None];
            for round in 0..plan.rounds {
                for k in if round % 2 == 0 { [0, 1] } else { [1, 0] } {
                    let clock = Clock::start();
                    frames[k] = Some(pictures(k == 0));
                    times[k].push(clock.stop().1);
                }
            }
            let err = |k: usize| rmse_linear(frames[k].as_ref().expect("rendered"), &converged).expect("same size");
            let (s, r) = (err(0), err(1));
            let [ts, tr] = times.map(median);
            writeln!(aa_table, "| {name} | {spp} | {s:.5} | {r:.5} | {:.2}x | {ts:.3} | {tr:.3} |", r / s).unwrap();
            if spp == 4 {
                aa_summary.push(format!("{:.2}x on {name}", r / s));
            }
        }
    }
    rows.push(Row {
        step: "6. Stratified anti-aliasing (jittered grid / N-rooks)",
        slide: "random points in the pixel",
        measured: "bitmap_textures, model_transform, fresnel at 160x120, the same camera-ray loop with each rule"
            .into(),
        buys: format!(
            "at equal spp (equal rays, equal time) the random points' RMSE is {} the stratified one's, at 4 spp",
            aa_summary.join(", ")
        ),
        code: vec![
            Code::Items("src/lesson/render.rs", &["struct Stratifier", "impl Stratifier"]),
            Code::Items("src/lesson/rng.rs", &["fn shuffled_index"]),
        ],
    });
    writeln!(details, "## 6. Stratified anti-aliasing\n\nEach pixel's camera rays through `Stratifier::offset` or through random points of the pixel, each traced by the default `raytrace`, against the example at {} spp with another seed.\n\n{aa_table}", plan.pick(1024, 256)).unwrap();
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
    rows.push(Row {
        step: "7. Stratified and joint disc samples",
        slide: "random points of the unit disc",
        measured: "glossy, `--sampler random|stratified|joint`, 16 spp, 160x120, `--glossy-samples` swept".into(),
        buys: format!(
            "joint (the default): {}. stratified: {}",
            versus(random, joint, 4).describe("joint", "random", &modeled(joint)),
            versus(random, stratified, 4).describe("stratified", "random", &modeled(stratified))
        ),
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

/// Step 8: whether any example reaches the glossy split depth.
fn glossy_split_depth(rows: &mut Vec<Row>, details: &mut String, split_table: &str, split_reached: &[&str]) {
    rows.push(Row {
        step: format!("8. The glossy split depth (one ray below depth {GLOSSY_SPLIT_DEPTH})").leak(),
        slide: "`SECONDARY_GLOSSY_SAMPLES` (2) rays at every depth below the first (the course's own rule, kept in both readings)",
        measured: "every example with a glossy mirror: its depth limit and the rays the default traces deeper than the split".into(),
        buys: if split_reached.is_empty() {
            format!("nothing on any example: no glossy example's `max_depth` exceeds {GLOSSY_SPLIT_DEPTH}, so no ray reaches the split. It guards a scene file with facing glossy mirrors and a deep `maxTraceDepth` against 2^depth rays")
        } else {
            format!("reached on {}", split_reached.join(", "))
        },
        code: vec![Code::Lines("src/lesson/shader/reflection.rs", "GLOSSY_SPLIT_DEPTH"), Code::Lines("src/lesson/shader/reflection.rs", "_ => 1,")],
    });
    writeln!(details, "## 8. The glossy split depth\n\n{split_table}").unwrap();
}

/// Step 9: hero wavelengths against K passes, on dispersion.
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
    let curves = sweep(plan, di, "--spp", &[passes, hero], &di_ref);
    rows.push(Row {
        step: "9. Hero-wavelength sampling",
        slide: "K = 8 wavelength passes",
        measured: "dispersion, `--spectral hero|passes`, 160x120, `--spp` swept, against a converged hero render"
            .into(),
        buys: versus(&curves[0], &curves[1], 4).describe("hero", "8 passes", &modeled(&curves[1])),
        code: vec![
            Code::Items(
                "src/lesson/render.rs",
                &["fn wavelength_samples", "fn add_weighted", "fn to_color", "const WAVELENGTH_KEY"],
            ),
            Code::Lines("src/lesson/scene.rs", "met_dispersion"),
        ],
    });
    writeln!(details, "## 9. Hero wavelengths\n\ndispersion at 160x120 against hero sampling with 8 wavelengths per path at {} spp, another seed (the slide's 8 passes converge to their own 8-band picture, which is part of their error).\n", plan.pick(128, 32)).unwrap();
    curve_table(details, "spp", &[("8 passes", &curves[0]), ("hero", &curves[1])]);
}

/// Step 10: the photon grid and aimed emission against all-direction emission and the k-d tree.
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
    let slide_curve = Curve { label: "slide", fixed: with(&pm_base, &["--slide"]), values: photons.clone() };
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
            ["default", "`--slide`"][reading],
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
    let without = |slide: &[&str]| (pm.run)(&with(&pm_base, &[&["--photons", "0"][..], slide].concat())).frame;
    let rest = rmse_linear(&without(&[]), &without(&["--slide"])).expect("same size");
    let estimate = |k: usize| {
        let t = &timed[k];
        let stats = t.last.stats.photons.expect("a photon map");
        (t.last.stats.elapsed.as_secs_f64(), (stats.trace_time + stats.build_time).as_secs_f64(), stats)
    };
    let (d_render, d_build, d_stats) = estimate(1);
    let (s_render, s_build, s_stats) = estimate(photons.len() + 1);
    rows.push(Row {
        step: "10. The photon grid and the cone-aimed Fibonacci emission",
        slide: "photons in all directions, the k nearest from a k-d tree",
        measured: "photon_map, default against `--slide`, 160x120 at 1 spp, `--photons` swept (the rest of the render is the two readings' too)".into(),
        buys: format!(
            "at {} photons asked: {:.3} of the emitted photons stored against {:.4} ({} against {} emitted), trace and build {d_build:.3} s against {s_build:.3} s, render with the estimates {d_render:.3} s against {s_render:.3} s. Caustic error: {}",
            photons[1],
            d_stats.stored as f64 / d_stats.emitted as f64,
            s_stats.stored as f64 / s_stats.emitted as f64,
            d_stats.emitted,
            s_stats.emitted,
            versus_measured(&pm_curves[1], &pm_curves[0], photons[1]).describe("the grid", "the slide", &pm_curves[0])
        ) + &format!(
            " (without photons the two readings' pictures differ by RMSE {rest:.5}: the rest of the difference is the caustic's)"
        ),
        code: vec![Code::File("src/lesson/photon_map/grid.rs"), Code::File("src/lesson/photon_map/emitter.rs")],
    });
    writeln!(details, "## 10. The photon map\n\nphoton_map at 160x120, one ray through each pixel centre, against the default reading with {} photons and k = 400, another seed. The CPU time is the whole render's (photon pass, estimates and the rest). Without photons (`--photons 0`) the two readings' pictures differ by RMSE {rest:.5}: the rest of the difference below is the caustic's. The slide's photons are capped at {} batches, so that asking for 400,000 stores fewer.\n\n{pm_table}", plan.pick("3,200,000", "800,000"), slide::photon_mapping::MAX_BATCHES).unwrap();
}

/// Step 11: layer pruning against shading every layer, on every example with a layered shader.
fn layer_pruning(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("layer pruning");
    let mut layer_table = String::new();
    writeln!(layer_table, "| example | pruned: wall / CPU s | rays | every layer: wall / CPU s | rays | every layer / pruned, CPU | PSNR between | largest difference | with `--exhaustive`: every layer / pruned, CPU |").unwrap();
    writeln!(layer_table, "|---|---:|---:|---:|---:|---:|---:|---:|---:|").unwrap();
    let mut layer_ratios = Vec::new();
    let mut layer_exhaustive = Vec::new();
    for ex in all {
        let (scene, settings) =
            (ex.prepare)(&[&ONE_THREAD[..], &SIZE_320[..]].concat().iter().map(|s| s.to_string()).collect::<Vec<_>>());
        let Some(every) = every_layer(&scene) else { continue };
        let exhaustive = |s: &Scene| {
            let mut s = s.clone();
            s.min_ray_weight = 0.0;
            s
        };
        let (scene_ex, every_ex) = (exhaustive(&scene), exhaustive(&every));
        let scenes = [&scene, &every, &scene_ex, &every_ex];
        // Small renders, much closer in cost than the load of a shared machine moves them: more rounds.
        let more = Plan { quick: plan.quick, rounds: 3 * plan.rounds };
        let [pruned, all_layers, pruned_ex, all_layers_ex]: [Timed; 4] =
            interleaved(&more, 4, |i| run_scene(scenes[i], &settings)).try_into().ok().expect("four");
        let (p, level) = psnr(&pruned.last.frame, &all_layers.last.frame);
        let rays = |t: &Timed| t.last.stats.counters.total() as f64 / 1e6;
        writeln!(
            layer_table,
            "| {} | {:.3} / {:.3} | {:.2} M | {:.3} / {:.3} | {:.2} M | {:.2}x | {} | {level} | {:.2}x, {:.2} M rays against {:.2} M |",
            ex.name,
            pruned.wall,
            pruned.cpu,
            rays(&pruned),
            all_layers.wall,
            all_layers.cpu,
            rays(&all_layers),
            all_layers.cpu / pruned.cpu,
            db(p),
            all_layers_ex.cpu / pruned_ex.cpu,
            rays(&all_layers_ex),
            rays(&pruned_ex)
        )
        .unwrap();
        layer_exhaustive.push(format!("{:.2}x on {}", all_layers_ex.cpu / pruned_ex.cpu, ex.name));
        layer_ratios.push((ex.name, all_layers.cpu / pruned.cpu, rays(&all_layers) / rays(&pruned)));
    }
    rows.push(Row {
        step: "11. Layer pruning (top-down, skip a layer of no weight: zero blend, or under an opaque layer)",
        slide: "the loop that shades every layer",
        measured: "every example with a `Layered` shader, each such shader with `shade_every_layer(true)` against the default, 320x240".into(),
        buys: format!(
            "the same picture; shading every layer over pruning: {}{}",
            layer_ratios
                .iter()
                .map(|(name, t, r)| format!("{t:.2}x the CPU time and {r:.3}x the rays on {name}"))
                .collect::<Vec<_>>()
                .join(", "),
            if layer_ratios.iter().all(|(_, _, r)| *r < 1.05)
                && layer_ratios.iter().map(|(_, t, _)| t.ln()).sum::<f64>() / (layer_ratios.len() as f64) < 1.05f64.ln()
            {
                ". Nothing measurable on any example: the rays differ by less than 5% and the CPU time by no more than the machine's noise (their geometric mean is below 1.05x)"
            } else {
                ""
            }
        ) + &format!(
            ". It pays only without adaptive depth control (`--exhaustive`, where a hidden layer's rays are traced): {}",
            layer_exhaustive.join(", ")
        ),
        code: vec![
            Code::Items("src/lesson/shader/layered.rs", &["fn weights", "fn layer_weight"]),
            Code::Lines("src/lesson/shader/layered.rs", "every_layer"),
        ],
    });
    writeln!(details, "## 11. Layer pruning\n\nThe scene of each example with a `Layered` shader, rendered as it is and with every layered shader shading every layer (`Layered::shade_every_layer`, what the layered example's `--shade-every-layer` sets), and both again with `--exhaustive`; medians of three times the rounds, since the two differ less than the load of a shared machine moves them.\n\n{layer_table}").unwrap();
}

/// Step 12: camera-relative coordinates against world coordinates, on every example moved far away.
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
        step: "12. Camera-relative coordinates",
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
        code: vec![Code::Items("src/lesson/scene.rs", &["fn relative_to_camera"]), Code::Lines("src/app/cli/example.rs", "relative_to_camera")],
    });
    writeln!(details, "## 12. Camera-relative coordinates\n\nEach example's scene moved by (1e6, -5e5, 2.5e5) (camera and lights with it), rendered in world coordinates and relative to the camera, against the scene in place.\n\n{far_table}").unwrap();
}

/// Step 13: the enum of the workbook's own types against their trait objects, on every example.
fn static_dispatch(plan: &Plan, all: &[Ex], rows: &mut Vec<Row>, details: &mut String) {
    eprintln!("static dispatch");
    let mut table = String::new();
    writeln!(
        table,
        "| example | enum: wall / CPU s | trait objects: wall / CPU s | trait objects / enum, CPU | same picture |"
    )
    .unwrap();
    writeln!(table, "|---|---:|---:|---:|---|").unwrap();
    let mut ratios = Vec::new();
    let mut all_same = true;
    for ex in all {
        let (scene, settings) =
            (ex.prepare)(&[&ONE_THREAD[..], &SIZE_320[..]].concat().iter().map(|s| s.to_string()).collect::<Vec<_>>());
        let hidden = through_trait_objects(&scene);
        let scenes = [&scene, &hidden];
        let more = Plan { quick: plan.quick, rounds: 3 * plan.rounds };
        let [enum_run, dyn_run]: [Timed; 2] =
            interleaved(&more, 2, |i| run_scene(scenes[i], &settings)).try_into().ok().expect("two");
        let same = enum_run.last.frame.pixels == dyn_run.last.frame.pixels;
        all_same &= same;
        let ratio = dyn_run.cpu / enum_run.cpu;
        writeln!(
            table,
            "| {} | {:.3} / {:.3} | {:.3} / {:.3} | {ratio:.2}x | {} |",
            ex.name,
            enum_run.wall,
            enum_run.cpu,
            dyn_run.wall,
            dyn_run.cpu,
            if same { "yes" } else { "no" }
        )
        .unwrap();
        ratios.push((ex.name, ratio));
    }
    let mean = (ratios.iter().map(|(_, r)| r.ln()).sum::<f64>() / ratios.len() as f64).exp();
    rows.push(Row {
        step: "13. Static dispatch of the workbook's own shapes, shaders, textures and environments",
        slide: "a virtual call (a trait object) for every shape, shader, texture and environment, and the bookkeeping of a student's shader (its branching budget, the self-hit check) for every hit",
        measured: "every example, 320x240, 1 thread, against the same scene with every node and the environment behind a type the enum does not know (`dispatch::through_trait_objects`)".into(),
        buys: format!(
            "{}; CPU time through the trait objects over the enum: {} (geometric mean {mean:.2}x)",
            if all_same { "the same picture bit for bit on every example" } else { "A DIFFERENT PICTURE on some example" },
            ratios.iter().map(|(name, r)| format!("{r:.2}x on {name}")).collect::<Vec<_>>().join(", ")
        ),
        code: vec![
            Code::Items("src/lesson/dispatch.rs", &["enum Shape", "impl Shape", "fn node_hit", "fn node_intersects", "enum Sky", "impl Sky", "enum Tex", "impl Tex", "enum Material", "enum Surface", "struct MaterialLayer", "impl Material", "impl Surface", "impl MaterialLayer", "impl LayerShading for MaterialLayer"]),
            Code::Items("src/lesson/prepared.rs", &["struct Preparation", "struct PreparedNode", "impl Preparation", "fn environment_identity", "struct PreparedNodes", "impl NodeHits for PreparedNodes"]),
            Code::Items("src/lesson/branching.rs", &["fn shade_workbook_hit"]),
        ],
    });
    writeln!(details, "## 13. Static dispatch\n\nEach example's scene as it is and with every node's geometry and shader, and the environment, hidden behind a forwarding type of its own (`dispatch::through_trait_objects`), so that the renderer calls them through their trait objects, and keeps a shading point for every hit, as it does for a student's; medians of three times the rounds.\n\n{table}").unwrap();
}

/// The example's picture through the pixels' camera rays, each traced by the default `raytrace`: at the
/// `Stratifier`'s positions, or at random points of the pixel.
fn render_aa(scene: &Scene, w: u32, h: u32, spp: u32, stratified: bool) -> Frame {
    let camera = scene.camera.frame(w, h);
    let mut frame = Frame::new(w, h);
    let mut strata = Stratifier::new(spp);
    for y in 0..h {
        for x in 0..w {
            let mut ctx = TraceContext::new(scene, Rng::for_keys(&[3, x as u64, y as u64]));
            strata.start_pixel(&mut ctx.rng);
            let mut sum = Color::BLACK;
            for s in 0..spp {
                let (dx, dy) =
                    if stratified { strata.offset(s, &mut ctx.rng) } else { (ctx.rng.next_f32(), ctx.rng.next_f32()) };
                sum += ctx.raytrace(&camera.get_screen_ray(x as f32 + dx, y as f32 + dy));
            }
            frame.pixels[(y * w + x) as usize] = sum / spp as f32;
        }
    }
    frame
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
    writeln!(doc, "The workbook renders every example in two readings. `--slide` runs the code as the slides write it (every step of `src/lesson/beyond.rs` left out); the default reading adds, beside each slide, the steps below. Each row measures one step against the slide's version of it, side by side in one run: the time at equal error for the steps that leave the picture as it is, the error at equal time (and the time at equal error) for the steps that change the noise; and the lines of code the step costs. A step that buys nothing measurable on any example says so.").unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "Written by `cargo bench --bench beyond` ({}), in {:.0} s on {date}: {machine}, {cores} cores shared with other work (load average {load} at the end). Every render runs on one thread; each figure is the median of {} interleaved round(s); \"CPU s\" is user plus system time of the whole process. In the equal-time and equal-error comparisons of a sweep, a point's time is its rays times its curve's median CPU time per ray (steadier on a loaded machine than one point's own median, which the tables give). The bench is `benches/beyond.rs`; its doc comment says how each figure is made.", if plan.quick { "`--quick`" } else { "full" }, seconds, plan.rounds).unwrap();
    writeln!(doc).unwrap();
    writeln!(doc, "## The ledger\n").unwrap();
    writeln!(doc, "| step | the slide's version | measured on | what it buys | lines |").unwrap();
    writeln!(doc, "|---|---|---|---|---:|").unwrap();
    for row in rows {
        let lines: usize = row.code.iter().map(lines_of).sum();
        writeln!(doc, "| {} | {} | {} | {} | {lines} |", row.step, row.slide, row.measured, row.buys).unwrap();
    }
    writeln!(doc).unwrap();
    writeln!(doc, "## `--slide` against the default, every example\n\nAt 320x240, the examples' default samples, one thread. The two readings differ where the default's steps change the picture: other random numbers (stratified pixel and disc samples, hero wavelengths against 8 passes), bilinear against nearest texels, the photon grid's estimate against the k nearest, and adaptive depth control (within a few levels, see step 1).\n\n{examples_table}").unwrap();
    doc.push_str(details);
    writeln!(doc, "## What the lines count\n\nNon-blank lines that are not comments, of the step's own items (code the step shares with the slide's version, such as the layered shader's loop that pruning works in, or the render loop that calls a sampler, is not counted):\n").unwrap();
    for row in rows {
        let parts: Vec<String> = row.code.iter().map(|c| format!("{} ({})", describe_code(c), lines_of(c))).collect();
        writeln!(doc, "- {}: {}", row.step, parts.join("; ")).unwrap();
    }
    let path =
        if plan.quick { root.join("target/beyond-the-slides.md") } else { root.join("docs/beyond-the-slides.md") };
    std::fs::write(&path, doc).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    eprintln!("wrote {}", path.display());
}
