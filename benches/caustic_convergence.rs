//! The caustic's error against time: the `photon_map` example's caustic against its independent reference
//! (`benches/caustic_reference.rs`, rings in `benches/results/caustic_reference.tsv`), for the fixed gathering
//! (one photon map, more photons) and for the progressive caustic (`--photon-passes`, more passes of the
//! example's photon count).
//!
//! ```sh
//! cargo bench --features study --bench caustic_convergence          # writes target/study/caustic_convergence.{md,png}
//! cargo bench --features study --bench caustic_convergence -- --passes 1,4 --photons 400000 --seeds 1
//! ```
//!
//! Each point's time is the CPU time (user plus system, this process) of the example's whole render at its
//! default settings (640 x 480, 4 spp) on one thread, with that photon count or that number of passes: the
//! photon maps, the estimates and the rest of the picture. Its errors are measured on the caustic itself, on
//! the reference's rings (each ring's estimate averaged over points about 0.2 apart, as the test
//! `caustic_reference` measures it): the RMS of the rings' relative errors over the caustic's region (every
//! ring out to where its light falls to a hundredth of the centre's, each weighted by its area), and the
//! error of its brightest ring, the central one (0-0.02). The errors of one seed are noisy, so each is the
//! root mean square over `--seeds` renders of their own seeds. The fixed gathering's photon counts stop at the
//! most a map may hold (`MAX_PHOTONS`).

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;
// Shared with the test `caustic_reference` and the other caustic bench, each of which uses part of it.
#[allow(dead_code)]
#[path = "../tests/workbook/common/caustic.rs"]
mod caustic;
mod common;

use caustic::{REFERENCE, Reference, progressive_rings, read_reference, relative_errors};
use clap::Parser;
use examples::photon_map::Options;
use lecture6::app::cli::Cli;
use lecture6::lesson::photon_map::MAX_PHOTONS;
use plotters::prelude::*;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::Path;

#[derive(Parser)]
struct Args {
    /// Pass counts of the progressive caustic (the example's photon count each).
    #[arg(long, value_delimiter = ',', default_value = "1,4,16,64")]
    passes: Vec<u32>,
    /// Photon counts of the fixed gathering (one map); the last is the most a map may hold.
    #[arg(long, value_delimiter = ',', default_value = "400000,1600000,6400000,16777216")]
    photons: Vec<u32>,
    /// Seeds (1, 2, ...) per point; each error is the root mean square over them. The central ring is one
    /// small disc, whose error over a few seeds is itself noisy: 8 seeds, not 4, to fit its slope.
    #[arg(long, default_value_t = 8)]
    seeds: u64,
    /// Estimates along each ring's circles are this far apart.
    #[arg(long, default_value_t = 0.2)]
    spacing: f64,
    /// `cargo bench` passes it.
    #[arg(long, hide = true)]
    bench: bool,
}

/// The rings of the caustic's region: those whose light is at least this fraction of the central ring's.
const BRIGHT: f64 = 0.01;

/// One point of a curve.
struct Point {
    curve: &'static str,
    /// Passes, or photons of the one map.
    knob: u32,
    cpu: f64,
    region: f64,
    central: f64,
}

fn main() {
    let args = Args::parse();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut reference = read_reference(&root.join(REFERENCE));
    let bright = reference.rings.iter().take_while(|r| r.irradiance >= BRIGHT * reference.rings[0].irradiance).count();
    reference.rings.truncate(bright);
    let mut points = Vec::new();
    for &passes in &args.passes {
        points.push(measure(&args, &reference, "progressive", passes, &photon_options(None, passes)));
    }
    for &photons in &args.photons {
        points.push(measure(&args, &reference, "fixed", photons, &photon_options(Some(photons), 1)));
    }
    let out = root.join("target/study");
    std::fs::create_dir_all(&out).expect("target/study");
    let report = report(&points, &reference);
    print!("{report}");
    std::fs::write(out.join("caustic_convergence.md"), &report).expect("the report");
    draw(&points, &out.join("caustic_convergence.png")).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("wrote {}", out.join("caustic_convergence.{md,png}").display());
}

/// The example's options for a point: its photon count (the example's own when `None`) and passes.
fn photon_options(photons: Option<u32>, passes: u32) -> Vec<String> {
    let mut options = vec!["--photon-passes".to_string(), passes.to_string()];
    if let Some(photons) = photons {
        options.extend(["--photons".to_string(), photons.min(MAX_PHOTONS).to_string()]);
    }
    options
}

/// One point: the render's CPU time on one thread (seed 1), and the errors on the rings over the seeds.
fn measure(args: &Args, reference: &Reference, curve: &'static str, knob: u32, options: &[String]) -> Point {
    let parse = |extra: &[&str]| {
        let argv = options.iter().map(String::as_str).chain(extra.iter().copied());
        Cli::<Options>::parse_args("photon_map", argv).unwrap_or_else(|e| e.exit())
    };
    let start = common::cpu_time().expect("the CPU time");
    let (frame, _) = parse(&["--threads", "1", "--quiet"]).render().unwrap_or_else(|e| panic!("{e}"));
    let cpu = (common::cpu_time().expect("the CPU time") - start).as_secs_f64();
    assert!(frame.pixels.iter().all(|c| c.is_finite()), "{curve} {knob}: a pixel is not finite");
    let (mut region, mut central) = (0.0, 0.0);
    for seed in 1..=args.seeds {
        let (scene, settings) = parse(&["--seed", &seed.to_string()]).prepare().unwrap_or_else(|e| panic!("{e}"));
        let values = progressive_rings(&scene, reference, settings.photon_passes, seed, args.spacing);
        let errors = relative_errors(&values, reference);
        let area = |i: usize| PI * (reference.rings[i].outer.powi(2) - reference.rings[i].inner.powi(2));
        let total: f64 = (0..errors.len()).map(area).sum();
        region += errors.iter().enumerate().map(|(i, e)| e * e * area(i)).sum::<f64>() / total;
        central += errors[0] * errors[0];
    }
    let n = args.seeds as f64;
    let point = Point { curve, knob, cpu, region: (region / n).sqrt(), central: (central / n).sqrt() };
    eprintln!(
        "{curve} {knob}: {:.2} CPU s, region RMS {:.3}%, central ring {:.3}%",
        point.cpu,
        100.0 * point.region,
        100.0 * point.central
    );
    point
}

/// One error of a point.
type Metric = fn(&Point) -> f64;

/// The least-squares slope of log(error) against log(CPU time) over `points`.
fn slope(points: &[&Point], error: Metric) -> f64 {
    let xy: Vec<(f64, f64)> = points.iter().map(|p| (p.cpu.ln(), error(p).ln())).collect();
    let n = xy.len() as f64;
    let (mx, my) = (xy.iter().map(|p| p.0).sum::<f64>() / n, xy.iter().map(|p| p.1).sum::<f64>() / n);
    let sxy: f64 = xy.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xy.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// A curve's error at CPU time `t`, interpolated on its log-log polyline; `None` outside the curve's times.
fn error_at(curve: &[&Point], t: f64, error: Metric) -> Option<f64> {
    curve.windows(2).find(|w| w[0].cpu <= t && t <= w[1].cpu).map(|w| {
        let f = (t.ln() - w[0].cpu.ln()) / (w[1].cpu.ln() - w[0].cpu.ln());
        (error(w[0]).ln() + f * (error(w[1]).ln() - error(w[0]).ln())).exp()
    })
}

fn report(points: &[Point], reference: &Reference) -> String {
    let mut out = String::new();
    let outer = reference.rings.last().expect("rings").outer;
    writeln!(
        out,
        "| curve | passes x photons | CPU s | CPU / one pass | region RMS (0-{outer:.2}) | central ring (0-0.02) |"
    )
    .unwrap();
    writeln!(out, "|---|---|---:|---:|---:|---:|").unwrap();
    let base = points.iter().find(|p| p.curve == "progressive" && p.knob == 1).map_or(f64::NAN, |p| p.cpu);
    for p in points {
        let budget = match p.curve {
            "progressive" => format!("{} x 400000", p.knob),
            _ => format!("1 x {}", p.knob),
        };
        writeln!(
            out,
            "| {} | {budget} | {:.2} | {:.1}x | {:.3}% | {:.3}% |",
            p.curve,
            p.cpu,
            p.cpu / base,
            100.0 * p.region,
            100.0 * p.central
        )
        .unwrap();
    }
    let curve = |name: &str| points.iter().filter(|p| p.curve == name).collect::<Vec<_>>();
    let (progressive, fixed) = (curve("progressive"), curve("fixed"));
    let from_four: Vec<&Point> = progressive.iter().copied().filter(|p| (4..=64).contains(&p.knob)).collect();
    if from_four.len() >= 2 {
        writeln!(
            out,
            "\nFitted log-log slope of the progressive caustic's error against CPU time, 4 to 64 passes: region {:.3}, central ring {:.3}.",
            slope(&from_four, |p| p.region),
            slope(&from_four, |p| p.central)
        )
        .unwrap();
    }
    if fixed.len() >= 2 {
        writeln!(
            out,
            "Fixed gathering, the same fit over its photon counts: region {:.3}, central ring {:.3}.",
            slope(&fixed, |p| p.region),
            slope(&fixed, |p| p.central)
        )
        .unwrap();
    }
    let t = 16.0 * base;
    let most = fixed.iter().max_by(|a, b| a.cpu.total_cmp(&b.cpu));
    if let (Some(e), Some(most)) = (error_at(&progressive, t, |p| p.central), most) {
        let fixed_error = error_at(&fixed, t, |p| p.central);
        let (f, how) = match fixed_error {
            Some(f) => (f, "at the same time".to_string()),
            None => (
                most.central,
                format!(
                    "at its most photons ({}, {:.1}x the one-pass time; it cannot spend more)",
                    most.knob,
                    most.cpu / base
                ),
            ),
        };
        writeln!(
            out,
            "At 16x the one-pass CPU time ({t:.1} s): the progressive caustic's central ring {:.3}%, the fixed gathering's {:.3}% {how}: {:.2}x.",
            100.0 * e,
            100.0 * f,
            e / f
        )
        .unwrap();
    }
    out
}

/// Error against CPU time, log-log: region RMS on the left, central ring on the right, both curves on each.
fn draw(points: &[Point], path: &Path) -> lecture6::Result<()> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, lecture6::instruments::font::DEJAVU_SANS_MONO)
        .map_err(|_| {
            lecture6::Error::file("cannot read font", Path::new("src/instruments/font/DejaVuSansMono.ttf"), "invalid")
        })?;
    let (w, h) = (1120u32, 440u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    let chart_error = |e: &dyn std::fmt::Display| lecture6::Error::file("cannot draw chart", path, e.to_string());
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| chart_error(&e))?;
        let panels = root.split_evenly((1, 2));
        let metrics: [(&str, Metric); 2] = [
            ("caustic region, RMS relative error", |p| p.region),
            ("central ring (0-0.02), relative error", |p| p.central),
        ];
        for (panel, (name, metric)) in panels.iter().zip(metrics) {
            let (t_min, t_max) = points.iter().fold((f64::MAX, 0f64), |(a, b), p| (a.min(p.cpu), b.max(p.cpu)));
            let (e_min, e_max) = points.iter().map(metric).fold((f64::MAX, 0f64), |(a, b), v| (a.min(v), b.max(v)));
            let mut chart = ChartBuilder::on(panel)
                .caption(format!("photon_map: {name}"), ("sans-serif", 13))
                .margin(12)
                .x_label_area_size(36)
                .y_label_area_size(60)
                .build_cartesian_2d((t_min * 0.8..t_max * 1.25).log_scale(), (e_min * 0.8..e_max * 1.25).log_scale())
                .map_err(|e| chart_error(&e))?;
            chart
                .configure_mesh()
                .x_labels(8)
                .y_labels(8)
                .x_label_formatter(&|v| format!("{v:.1}"))
                .y_label_formatter(&|v| format!("{:.2}%", 100.0 * v))
                .x_desc("CPU time of the render (s), 640 x 480, 4 spp, 1 thread")
                .y_desc("error against the light tracer")
                .label_style(("sans-serif", 12))
                .draw()
                .map_err(|e| chart_error(&e))?;
            for (i, (curve, label)) in
                [("progressive", "progressive: passes of 400000"), ("fixed", "fixed gathering: photons")]
                    .into_iter()
                    .enumerate()
            {
                let color = Palette99::pick(i).to_rgba();
                let series: Vec<(f64, f64)> =
                    points.iter().filter(|p| p.curve == curve).map(|p| (p.cpu, metric(p))).collect();
                chart
                    .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))
                    .map_err(|e| chart_error(&e))?
                    .label(label)
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], color.stroke_width(2)));
                chart
                    .draw_series(series.into_iter().map(|p| Circle::new(p, 3, color.filled())))
                    .map_err(|e| chart_error(&e))?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .label_font(("sans-serif", 12))
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()
                .map_err(|e| chart_error(&e))?;
        }
        root.present().map_err(|e| chart_error(&e))?;
    }
    let img = image::RgbImage::from_raw(w, h, buffer).expect("the chart buffer matches its size");
    lecture6::files::output::save_atomically(path, |file| img.write_to(file, image::ImageFormat::Png))
}
