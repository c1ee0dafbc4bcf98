//! Timing of the `fresnel` and `layered` examples, each measured two ways side by side:
//!
//! - `fresnel` at its defaults (640 x 480, 5 samples per pixel, 2 threads) with adaptive ray-tree depth
//!   control and with `--exhaustive`, plus how far apart the two pictures are;
//! - `layered` at its defaults with layer skipping and with `--shade-every-layer` (the slide's loop).
//!
//! The two ways alternate run by run, so a change in the machine's load hits both alike; the median of the
//! runs is reported, with the fastest and slowest. Times are the render only (as in the examples' summary
//! line), not loading the textures.
//!
//! ```sh
//! cargo bench --bench layered_fresnel            # 7 runs of each
//! cargo bench --bench layered_fresnel -- 15      # 15 runs of each
//! ```

use lecture6::cli::{Example, render_example};
use lecture6::compare::difference;
use lecture6::render::{Frame, RenderStats};
use lecture6::scene::Counters;
use lecture6::scenes::{fresnel, layered};
use std::time::Duration;

fn render<E: Example>(args: &[&str]) -> (Frame, RenderStats) {
    let argv = [E::NAME, "--quiet", "--threads", "2"].into_iter().chain(args.iter().copied());
    let parsed = E::try_parse_from(argv).expect("valid bench arguments");
    render_example(&parsed).expect("the example renders")
}

/// One way of rendering an example: its label, its options, and what the runs measured.
struct Way<'a> {
    label: &'a str,
    args: &'a [&'a str],
    times: Vec<Duration>,
    counters: Counters,
    frame: Option<Frame>,
}

impl<'a> Way<'a> {
    fn new(label: &'a str, args: &'a [&'a str]) -> Way<'a> {
        Way { label, args, times: Vec::new(), counters: Counters::default(), frame: None }
    }
    fn median_ms(&self) -> f64 {
        let mut t: Vec<f64> = self.times.iter().map(|d| d.as_secs_f64() * 1e3).collect();
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    }
    fn print(&self) {
        let ms: Vec<f64> = self.times.iter().map(|d| d.as_secs_f64() * 1e3).collect();
        let c = &self.counters;
        let secondary: u64 = c.rays_by_depth[1..].iter().sum();
        println!(
            "  {:<22} median {:>8.1} ms  (min {:.1}, max {:.1}, {} runs)  rays: {:.2} M camera, {:.2} M secondary, \
             {:.2} M shadow, {:.2} M not traced",
            self.label,
            self.median_ms(),
            ms.iter().copied().fold(f64::INFINITY, f64::min),
            ms.iter().copied().fold(0.0, f64::max),
            ms.len(),
            c.rays_by_depth[0] as f64 * 1e-6,
            secondary as f64 * 1e-6,
            c.shadow_rays as f64 * 1e-6,
            c.pruned_rays as f64 * 1e-6,
        );
    }
}

/// Renders the example `runs` times each way, alternating, and prints the two side by side.
fn compare_ways<'a, E: Example>(runs: usize, a: &mut Way<'a>, b: &mut Way<'a>) {
    for _ in 0..runs {
        for way in [&mut *a, &mut *b] {
            let (frame, stats) = render::<E>(way.args);
            way.times.push(stats.elapsed);
            way.counters = stats.counters;
            way.frame = Some(frame);
        }
    }
    println!("{} (640x480, default spp, 2 threads):", E::NAME);
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
    compare_ways::<fresnel::Args>(
        runs,
        &mut Way::new("adaptive", &[]),
        &mut Way::new("--exhaustive", &["--exhaustive"]),
    );
    compare_ways::<layered::Args>(
        runs,
        &mut Way::new("layer skipping", &[]),
        &mut Way::new("--shade-every-layer", &["--shade-every-layer"]),
    );
}
