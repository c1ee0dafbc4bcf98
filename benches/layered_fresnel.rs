//! Timing of the `fresnel` and `layered` examples, each measured two ways side by side:
//!
//! - `fresnel` at its defaults (640 x 480, 5 samples per pixel, 2 threads) with adaptive ray-tree depth
//!   control and with `--exhaustive`, plus how far apart the two pictures are;
//! - `layered` at its defaults with layer skipping and with `--shade-every-layer` (the slide's loop), both
//!   with adaptive depth control and with `--exhaustive`.
//!
//! The two ways alternate run by run, so a change in the machine's load hits both alike; the median of the
//! runs is reported, with the fastest and slowest. Times are the render only (as in the examples' summary
//! line), not loading the textures. Besides the wall-clock time, the CPU time the process used during the
//! render is reported (from `/proc/self/stat`, on Linux): on a machine shared with other work it tells what
//! the render itself cost, and half of it is what the 2-thread wall time would be on an idle machine with
//! perfect scaling.
//!
//! ```sh
//! cargo bench --bench layered_fresnel            # 7 runs of each
//! cargo bench --bench layered_fresnel -- 15      # 15 runs of each
//! ```

mod common;
#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;

use common::cpu_time;

use examples::{fresnel, layered};
use lecture6::app::cli::{Cli, Example};
use lecture6::instruments::compare::difference;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::RenderStats;
use lecture6::lesson::scene::Counters;
use std::time::Duration;

/// Renders with the given options, as the example does; returns the frame, the stats and the CPU time of
/// the whole call (which includes building the scene: see [`load_cpu_time`]).
fn render<E: Example>(args: &[&str]) -> (Frame, RenderStats, Option<Duration>) {
    let parsed = parse::<E>(args);
    let before = cpu_time();
    let (frame, stats) = parsed.render().expect("the example renders");
    let cpu = before.zip(cpu_time()).map(|(b, a)| a.saturating_sub(b));
    (frame, stats, cpu)
}

fn parse<E: Example>(args: &[&str]) -> Cli<E> {
    let argv = ["--quiet", "--threads", "2"].into_iter().chain(args.iter().copied());
    Cli::<E>::parse_args("bench", argv).expect("valid bench arguments")
}

/// The CPU time of building the example's scene (reading its textures), `runs` times in a row.
fn load_cpu_time<E: Example>(runs: usize) -> Option<Duration> {
    let parsed = parse::<E>(&[]);
    let before = cpu_time();
    for _ in 0..runs {
        parsed.example.scene().expect("the scene builds");
    }
    before.zip(cpu_time()).map(|(b, a)| a.saturating_sub(b) / runs as u32)
}

/// One way of rendering an example: its label, its options, and what the runs measured.
struct Way<'a> {
    label: &'a str,
    args: &'a [&'a str],
    times: Vec<Duration>,
    cpu: Vec<Duration>,
    counters: Counters,
    frame: Option<Frame>,
}

impl<'a> Way<'a> {
    fn new(label: &'a str, args: &'a [&'a str]) -> Way<'a> {
        Way { label, args, times: Vec::new(), cpu: Vec::new(), counters: Counters::default(), frame: None }
    }
    fn median_ms(&self) -> f64 {
        median_ms(&self.times)
    }
    fn print(&self) {
        let ms: Vec<f64> = self.times.iter().map(|d| d.as_secs_f64() * 1e3).collect();
        let c = &self.counters;
        let secondary: u64 = c.rays_by_depth[1..].iter().sum();
        println!(
            "  {:<20} wall median {:>7.1} ms (min {:.1}, max {:.1}, {} runs), CPU median {:.0} ms; rays: {:.2} M \
             camera, {:.2} M secondary, {:.2} M shadow, {:.2} M not traced",
            self.label,
            self.median_ms(),
            ms.iter().copied().fold(f64::INFINITY, f64::min),
            ms.iter().copied().fold(0.0, f64::max),
            ms.len(),
            median_ms(&self.cpu),
            c.rays_by_depth[0] as f64 * 1e-6,
            secondary as f64 * 1e-6,
            c.shadow_rays as f64 * 1e-6,
            c.pruned_rays as f64 * 1e-6,
        );
    }
}

/// Renders the example `runs` times each way, alternating, and prints the two side by side.
fn median_ms(times: &[Duration]) -> f64 {
    let mut t: Vec<f64> = times.iter().map(|d| d.as_secs_f64() * 1e3).collect();
    t.sort_by(f64::total_cmp);
    t.get(t.len() / 2).copied().unwrap_or(f64::NAN)
}

fn compare_ways<'a, E: Example>(name: &str, runs: usize, a: &mut Way<'a>, b: &mut Way<'a>) {
    for _ in 0..runs {
        for way in [&mut *a, &mut *b] {
            let (frame, stats, cpu) = render::<E>(way.args);
            way.times.push(stats.elapsed);
            way.cpu.extend(cpu);
            way.counters = stats.counters;
            way.frame = Some(frame);
        }
    }
    let load = load_cpu_time::<E>(runs).map_or(f64::NAN, |d| d.as_secs_f64() * 1e3);
    println!(
        "{} {} (640x480, default spp, 2 threads; CPU times include {load:.0} ms of loading textures):",
        name,
        a.args.join(" ")
    );
    a.print();
    b.print();
    println!("  {} / {}: {:.2}x", b.label, a.label, b.median_ms() / a.median_ms());
    let (fa, fb) = (a.frame.as_ref().unwrap().to_rgb8(), b.frame.as_ref().unwrap().to_rgb8());
    let d = difference(&fa, &fb).expect("same size");
    let within_one =
        fa.pixels().zip(fb.pixels()).filter(|(p, q)| p.0.iter().zip(q.0).all(|(&x, y)| x.abs_diff(y) <= 1));
    println!(
        "  pictures: {:.3}% of pixels within one 8-bit level; {d}",
        100.0 * within_one.count() as f64 / d.pixels as f64
    );
}

fn main() {
    // `cargo bench` passes `--bench`; the only argument this program takes is the number of runs.
    let runs = std::env::args().skip(1).find_map(|a| a.parse().ok()).unwrap_or(7usize);
    compare_ways::<fresnel::Options>(
        "fresnel",
        runs,
        &mut Way::new("adaptive", &[]),
        &mut Way::new("--exhaustive", &["--exhaustive"]),
    );
    compare_ways::<layered::Options>(
        "layered",
        runs,
        &mut Way::new("layer skipping", &[]),
        &mut Way::new("--shade-every-layer", &["--shade-every-layer"]),
    );
    // Without adaptive depth control, the rays of a hidden layer are traced too, not just its shading done.
    compare_ways::<layered::Options>(
        "layered",
        runs,
        &mut Way::new("layer skipping", &["--exhaustive"]),
        &mut Way::new("--shade-every-layer", &["--exhaustive", "--shade-every-layer"]),
    );
}
