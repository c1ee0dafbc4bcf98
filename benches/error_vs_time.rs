//! Run time versus error for every example with stochastic parts:
//!
//! ```sh
//! cargo bench --features study --bench error_vs_time
//! ```
//!
//! Each curve sweeps one sample-count option of one example (at 320 x 240; dispersion and the photon map,
//! the slowest, at 160 x 120) and measures the median wall time of 3 renders and the error against a converged reference
//! (see `lecture6::instruments::study`). It writes `target/study/error_vs_time.md` (the tables, the Pareto-optimal points,
//! the equal-time error ratios of the three glossy samplers, and the ways of tracing wavelengths at the error
//! and at the time of the slide's 8 passes) and `target/study/error_vs_time.png` (log-log charts of error
//! versus time). References are cached in `target/study/` and rendered again whenever the program is rebuilt.
//! The whole run takes a few minutes on 2 idle cores.
//!
//! `cargo bench --features study --bench error_vs_time -- dispersion` runs only the curves of the examples
//! whose name contains `dispersion` (any word after `--` filters so).
//!
//! To add an example, add its sweeps to `sweeps()`.

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;

use examples::{bitmap_textures, dispersion, glossy, photon_map};
use lecture6::instruments::study::{self, Measurement, Sweep};
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

const SIZE: [&str; 4] = ["--width", "320", "--height", "240"];
const REPEATS: usize = 3;

/// The glossy example's converged reference: 64 x 64 = 4096 glossy rays per pixel, another seed.
const GLOSSY_REFERENCE: [&str; 8] = ["--spp", "64", "--glossy-samples", "64", "--sampler", "stratified", "--seed", "7"];
/// The reference of the pixel-centre curves: one camera ray through each pixel's centre (no anti-aliasing
/// error at all), 2048 glossy rays.
const PIXEL_CENTRE_REFERENCE: [&str; 8] =
    ["--spp", "1", "--glossy-samples", "2048", "--sampler", "stratified", "--seed", "7"];

/// The dispersion example's reference (at 160 x 120: dispersion is the slowest example): hero-wavelength
/// sampling, 8 wavelengths per path at 256 samples per pixel (2048 wavelengths per pixel).
const DISPERSION_REFERENCE: [&str; 8] = ["--spectral", "hero", "--wavelengths", "8", "--spp", "256", "--seed", "7"];
const SMALL: [&str; 4] = ["--width", "160", "--height", "120"];

/// The photon map's reference (at 160 x 120): 6.4 million photons, each estimate from the 400 nearest, so
/// that both its noise (set by k) and its blur (the radius that holds k photons) are below every point's.
const PHOTON_REFERENCE: [&str; 6] = ["--photons", "6400000", "--k", "400", "--seed", "7"];

fn with_size(extra: &[&'static str]) -> Vec<&'static str> {
    SIZE.iter().chain(extra).copied().collect()
}

fn sweeps() -> Vec<Sweep> {
    let glossy_samples = |label: &str, fixed: &[&'static str], values: &[u32], reference: &[&str]| {
        Sweep::new::<glossy::Options>("glossy", label, &with_size(fixed), "--glossy-samples", values, reference)
    };
    let doubling = [1, 2, 4, 8, 16, 32, 64, 128];
    vec![
        Sweep::new::<bitmap_textures::Options>(
            "bitmap_textures",
            "anti-aliasing",
            &with_size(&[]),
            "--spp",
            &[1, 2, 4, 9, 16, 36, 64],
            &["--spp", "1024", "--seed", "7"],
        ),
        // The whole picture against the converged reference: how to share samples between anti-aliasing
        // and the glossy cone (this is where the example's defaults come from).
        Sweep::new::<glossy::Options>(
            "glossy",
            "--glossy-samples 1",
            &with_size(&["--glossy-samples", "1"]),
            "--spp",
            &[1, 4, 16, 64],
            &GLOSSY_REFERENCE,
        ),
        glossy_samples(
            "--spp 4, joint",
            &["--spp", "4", "--sampler", "joint"],
            &[1, 2, 4, 8, 16, 32],
            &GLOSSY_REFERENCE,
        ),
        glossy_samples(
            "--spp 4, random",
            &["--spp", "4", "--sampler", "random"],
            &[1, 2, 4, 8, 16, 32],
            &GLOSSY_REFERENCE,
        ),
        // The example's 16 spp with each of the three samplers: what sharing one set of disc points between
        // a pixel's camera rays gains (the pixel-centre curves below cannot show it: one camera ray per pixel).
        glossy_samples("--spp 16, joint", &["--spp", "16", "--sampler", "joint"], &[1, 2, 4, 8, 16], &GLOSSY_REFERENCE),
        glossy_samples(
            "--spp 16, stratified",
            &["--spp", "16", "--sampler", "stratified"],
            &[1, 2, 4, 8, 16],
            &GLOSSY_REFERENCE,
        ),
        glossy_samples(
            "--spp 16, random",
            &["--spp", "16", "--sampler", "random"],
            &[1, 2, 4, 8, 16],
            &GLOSSY_REFERENCE,
        ),
        // Through the pixel centres only, so that the error is the glossy noise alone: the two samplers.
        glossy_samples("random", &["--spp", "1", "--sampler", "random"], &doubling, &PIXEL_CENTRE_REFERENCE),
        glossy_samples("stratified", &["--spp", "1", "--sampler", "stratified"], &doubling, &PIXEL_CENTRE_REFERENCE),
        // Dispersion: the slide's wavelength passes, spectral sampling (one wavelength per sample), and
        // hero-wavelength sampling (several per path, traced once until the path meets the glass) with 8, 4
        // and 1 wavelengths per path; 1 per path is spectral sampling with the skip alone (a path that misses
        // the glass counts as white light). `benches/dispersion.rs` studies the methods in depth.
        dispersion_sweep("8 passes", &["--spectral", "passes", "--wavelengths", "8"], &[1, 2, 4, 8]),
        dispersion_sweep("16 passes", &["--spectral", "passes", "--wavelengths", "16"], &[1, 2, 4]),
        dispersion_sweep("spectral sampling", &["--spectral", "sampled", "--wavelengths", "1"], &[4, 8, 16, 32, 64]),
        dispersion_sweep("hero, 8 per path", &["--spectral", "hero", "--wavelengths", "8"], &[1, 2, 4, 8, 16]),
        dispersion_sweep("hero, 4 per path", &["--spectral", "hero", "--wavelengths", "4"], &[1, 2, 4, 8, 16, 32]),
        dispersion_sweep("hero, 1 per path", &["--spectral", "hero", "--wavelengths", "1"], &[4, 8, 16, 32, 64]),
        // Caustics: the photon count at three values of k. With k fixed, the estimate's noise stops falling
        // once enough photons are stored (it is set by k) while its blur keeps shrinking: each curve flattens,
        // and the lower envelope of the three is the best pairing of photons and k for the time spent.
        photon_sweep("--k 20", &["--k", "20"]),
        photon_sweep("--k 80", &["--k", "80"]),
        photon_sweep("--k 320", &["--k", "320"]),
    ]
}

/// A sweep of `dispersion`'s `--spp` at 160 x 120 with the wavelength options `fixed`.
fn dispersion_sweep(label: &str, fixed: &[&'static str], values: &[u32]) -> Sweep {
    Sweep::new::<dispersion::Options>(
        "dispersion",
        label,
        &[&SMALL[..], fixed].concat(),
        "--spp",
        values,
        &DISPERSION_REFERENCE,
    )
}

/// A sweep of `photon_map`'s `--photons` at 160 x 120 with the other options in `fixed`, through the pixel
/// centres (`--spp 1`, as its reference) so that the error is the caustic estimate's alone.
fn photon_sweep(label: &str, fixed: &[&'static str]) -> Sweep {
    Sweep::new::<photon_map::Options>(
        "photon_map",
        label,
        &[&SMALL[..], &["--spp", "1"], fixed].concat(),
        "--photons",
        &[50_000, 100_000, 200_000, 400_000, 800_000, 1_600_000],
        &PHOTON_REFERENCE,
    )
}

fn main() {
    // `cargo bench` passes `--bench`; a word after `--` keeps only the examples whose name contains it.
    let filter: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let start = Instant::now();
    let dir = study::output_dir();
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("error_vs_time: cannot create {}: {e}", dir.display());
        std::process::exit(2);
    }
    let mut curves: Vec<Vec<Measurement>> = Vec::new();
    for sweep in
        sweeps().into_iter().filter(|s| filter.is_empty() || filter.iter().any(|f| s.example.contains(f.as_str())))
    {
        let reference_start = Instant::now();
        let reference = sweep.reference_frame(Some(&dir)).unwrap_or_else(|e| fail(&e));
        eprintln!(
            "{} {}: reference ready in {:.1} s; measuring {} points",
            sweep.example,
            sweep.label,
            reference_start.elapsed().as_secs_f64(),
            sweep.values.len()
        );
        let curve = sweep.measure(&reference, REPEATS, Some(study::mean_flip)).unwrap_or_else(|e| fail(&e));
        for m in &curve {
            eprintln!(
                "  {} {:>4}: {:.3} s, RMSE {:.5}, FLIP {:.4}",
                m.knob,
                m.value,
                m.seconds,
                m.rmse,
                m.perceptual.unwrap_or(0.0)
            );
        }
        curves.push(curve);
    }
    let all: Vec<Measurement> = curves.iter().flatten().cloned().collect();
    let mut report = String::from("# Run time versus error\n\n");
    report += &format!(
        "Median wall time of {REPEATS} renders on {} threads; `*` marks the Pareto front (RMSE against time) of \
         each table.\n",
        rayon::current_num_threads()
    );
    report += &study::markdown_table(&all);
    for comparison in &SAMPLER_COMPARISONS {
        report += &sampler_comparison(&curves, comparison);
    }
    report += &wavelength_comparison(&curves);
    let table_path = dir.join("error_vs_time.md");
    std::fs::write(&table_path, &report)
        .unwrap_or_else(|e| fail(&lecture6::Error::file("cannot write", &table_path, e)));
    let chart_path = dir.join("error_vs_time.png");
    draw_chart(&curves, &chart_path).unwrap_or_else(|e| fail(&e));
    println!("{report}");
    println!(
        "error_vs_time: {} renders in {:.1} s -> {}, {}",
        all.len() * REPEATS,
        start.elapsed().as_secs_f64(),
        table_path.display(),
        chart_path.display()
    );
}

fn fail(e: &lecture6::Error) -> ! {
    eprintln!("error_vs_time: error: {e}");
    std::process::exit(2)
}

/// Two curves of the same group compared at equal time: the title, the curve of the sampler measured and
/// the curve of the sampler it is measured against (by label).
struct SamplerComparison {
    title: &'static str,
    measured: &'static str,
    baseline: &'static str,
}

const SAMPLER_COMPARISONS: [SamplerComparison; 4] = [
    SamplerComparison {
        title: "The slide's random disc points against stratified ones, through the pixel centres (the glossy \
                noise alone)",
        measured: "stratified",
        baseline: "random",
    },
    SamplerComparison {
        title: "Joint against the slide's random, whole picture at 16 spp",
        measured: "--spp 16, joint",
        baseline: "--spp 16, random",
    },
    SamplerComparison {
        title: "Joint against stratified, whole picture at 16 spp",
        measured: "--spp 16, joint",
        baseline: "--spp 16, stratified",
    },
    SamplerComparison {
        title: "Stratified against the slide's random, whole picture at 16 spp",
        measured: "--spp 16, stratified",
        baseline: "--spp 16, random",
    },
];

/// The equal-time comparison of two glossy samplers: for each point of the measured curve, the RMSE the
/// baseline curve against the same reference reaches in the same time (interpolated in log-log), divided by
/// the measured RMSE.
fn sampler_comparison(curves: &[Vec<Measurement>], comparison: &SamplerComparison) -> String {
    let SamplerComparison { title, measured, baseline } = comparison;
    if !curves.iter().any(|c| c[0].label == *measured) {
        return String::new();
    }
    let mut out = format!(
        "\n## {title}, at equal time\n\n\
         `{measured}` against `{baseline}`.\n\n\
         | setting | time (s) | RMSE measured | RMSE baseline, same setting (same rays) | ratio at equal rays | \
         RMSE baseline at that time | ratio at equal time |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    // (log-ratio sum, count) over all points, and over those with 4 glossy samples or more (one sample per
    // shading point cannot be stratified on its own).
    let mut all = (0.0, 0);
    let mut stratifiable = (0.0, 0);
    let mut equal_rays = (0.0, 0);
    for new in curves.iter().filter(|c| c[0].label == *measured) {
        let Some(base) = curves.iter().find(|c| c[0].label == *baseline && c[0].same_group(&new[0])) else {
            continue;
        };
        let mut base_by_time = base.clone();
        base_by_time.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
        for m in new {
            let same_setting = base.iter().find(|r| r.value == m.value).map_or(f64::NAN, |r| r.rmse);
            if m.value >= 4 && same_setting.is_finite() {
                equal_rays = (equal_rays.0 + (same_setting / m.rmse).ln(), equal_rays.1 + 1);
            }
            if let Some(r) = study::rmse_at_time(&base_by_time, m.seconds) {
                let ratio = r / m.rmse;
                all = (all.0 + ratio.ln(), all.1 + 1);
                if m.value >= 4 {
                    stratifiable = (stratifiable.0 + ratio.ln(), stratifiable.1 + 1);
                }
                let _ = writeln!(
                    out,
                    "| `{} {}` | {:.3} | {:.5} | {:.5} | {:.2} | {:.5} | {:.2} |",
                    m.knob,
                    m.value,
                    m.seconds,
                    m.rmse,
                    same_setting,
                    same_setting / m.rmse,
                    r,
                    ratio
                );
            }
        }
    }
    for ((sum, count), which) in [
        (all, "at equal time, over all points"),
        (stratifiable, "at equal time, over the points with 4 or more glossy samples"),
        (equal_rays, "at equal rays, over the points with 4 or more glossy samples"),
    ] {
        if count > 0 {
            let _ = writeln!(
                out,
                "\nError ratio (baseline RMSE / measured RMSE) {which} ({count}), geometric mean: **{:.2}**",
                (sum / count as f64).exp()
            );
        }
    }
    out
}

/// The curve and the point that the dispersion curves are measured against: the slide's 8 wavelength passes at
/// 2 samples per pixel, the example's default before hero-wavelength sampling.
const WAVELENGTH_BASELINE: (&str, u32) = ("8 passes", 2);

/// The ways of tracing wavelengths against the slide's 8 passes at 2 spp: what each costs (time and rays) to
/// reach the same error, and what error it has in the same time.
fn wavelength_comparison(curves: &[Vec<Measurement>]) -> String {
    let (label, value) = WAVELENGTH_BASELINE;
    let Some(base) = curves.iter().flatten().find(|m| m.label == label && m.value == value) else {
        return String::new();
    };
    let mut out = format!(
        "\n## Tracing wavelengths: at the error and at the time of `{label}` at `{} {value}`\n\n\
         That point: {:.3} s, {:.2} M rays, RMSE {:.5}, FLIP {:.4}. A ratio below 1 is cheaper (or more \
         accurate) than it.\n\n\
         | curve | time at that RMSE (s) | time ratio | M rays at that RMSE | ray ratio | RMSE at that time | \
         RMSE ratio |\n|---|---:|---:|---:|---:|---:|---:|\n",
        base.knob,
        base.seconds,
        base.rays as f64 * 1e-6,
        base.rmse,
        base.perceptual.unwrap_or(f64::NAN)
    );
    let number = |v: Option<f64>, digits: usize| v.map_or("-".to_string(), |v| format!("{v:.digits$}"));
    // Each curve in the order of its knob, which is the order of rising cost.
    for curve in curves.iter().filter(|c| c[0].same_group(base)) {
        let seconds = study::cost_at_rmse(curve, base.rmse, |m| m.seconds);
        let rays = study::cost_at_rmse(curve, base.rmse, |m| m.rays as f64);
        let rmse = study::rmse_at_time(curve, base.seconds);
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} |",
            curve[0].label,
            number(seconds, 3),
            number(seconds.map(|s| s / base.seconds), 2),
            number(rays.map(|r| r * 1e-6), 2),
            number(rays.map(|r| r / base.rays as f64), 2),
            number(rmse, 5),
            number(rmse.map(|e| e / base.rmse), 2),
        );
    }
    out + "\n(- : the curve does not reach that error, or does not span that time.)\n"
}

/// One error of a measurement, as plotted.
type Metric = fn(&Measurement) -> f64;

/// Log-log charts of error against time: one column per group of comparable curves (an example against
/// one reference), RMSE above and mean FLIP below, one line per curve.
fn draw_chart(curves: &[Vec<Measurement>], path: &Path) -> lecture6::Result<()> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, lecture6::instruments::font::DEJAVU_SANS_MONO)
        .map_err(|_| {
            lecture6::Error::file("cannot read font", Path::new("src/instruments/font/DejaVuSansMono.ttf"), "invalid")
        })?;
    let mut groups: Vec<Vec<&Vec<Measurement>>> = Vec::new();
    for curve in curves {
        match groups.iter_mut().find(|g| g[0][0].same_group(&curve[0])) {
            Some(group) => group.push(curve),
            None => groups.push(vec![curve]),
        }
    }
    let (w, h) = (560 * groups.len() as u32, 820u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    let chart_error = |e: &dyn std::fmt::Display| lecture6::Error::file("cannot draw chart", path, e.to_string());
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| chart_error(&e))?;
        let panels = root.split_evenly((2, groups.len()));
        let metrics: [(&str, Metric); 2] =
            [("RMSE (linear)", |m| m.rmse), ("mean FLIP", |m| m.perceptual.unwrap_or(f64::NAN))];
        for (row, (name, metric)) in metrics.into_iter().enumerate() {
            for (col, group) in groups.iter().enumerate() {
                let panel = &panels[row * groups.len() + col];
                let points = group.iter().flat_map(|c| c.iter());
                let (t_min, t_max) =
                    points.clone().fold((f64::MAX, 0f64), |(a, b), m| (a.min(m.seconds), b.max(m.seconds)));
                let (e_min, e_max) = points
                    .map(metric)
                    .filter(|v| v.is_finite() && *v > 0.0)
                    .fold((f64::MAX, 0f64), |(a, b), v| (a.min(v), b.max(v)));
                let first = &group[0][0];
                let caption = format!("{}, {name} against {}", first.example, without_size(&first.reference));
                let mut chart = ChartBuilder::on(panel)
                    .caption(caption, ("sans-serif", 11))
                    .margin(10)
                    .x_label_area_size(36)
                    .y_label_area_size(60)
                    .build_cartesian_2d(
                        (t_min * 0.8..t_max * 1.25).log_scale(),
                        (e_min * 0.8..e_max * 1.25).log_scale(),
                    )
                    .map_err(|e| chart_error(&e))?;
                chart
                    .configure_mesh()
                    .x_labels(6)
                    .y_labels(8)
                    .x_label_formatter(&|v| short(*v))
                    .y_label_formatter(&|v| short(*v))
                    .x_desc(format!("render time (s), {}", size_of(first)))
                    .y_desc(name)
                    .label_style(("sans-serif", 12))
                    .draw()
                    .map_err(|e| chart_error(&e))?;
                for (i, curve) in group.iter().enumerate() {
                    let color = Palette99::pick(i).to_rgba();
                    let series: Vec<(f64, f64)> = curve.iter().map(|m| (m.seconds, metric(m))).collect();
                    chart
                        .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))
                        .map_err(|e| chart_error(&e))?
                        .label(format!("{} ({})", curve[0].label, curve[0].knob))
                        .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], color.stroke_width(2)));
                    chart
                        .draw_series(series.into_iter().map(|p| Circle::new(p, 3, color.filled())))
                        .map_err(|e| chart_error(&e))?;
                }
                chart
                    .configure_series_labels()
                    .position(SeriesLabelPosition::UpperRight)
                    .label_font(("sans-serif", 11))
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .draw()
                    .map_err(|e| chart_error(&e))?;
            }
        }
        root.present().map_err(|e| chart_error(&e))?;
    }
    let img = image::RgbImage::from_raw(w, h, buffer).expect("the chart buffer matches its size");
    lecture6::files::output::save_atomically(path, |file| img.write_to(file, image::ImageFormat::Png))
}

/// A tick label with two significant digits.
fn short(v: f64) -> String {
    let digits = (1 - v.abs().log10().floor() as i32).max(0) as usize;
    format!("{v:.digits$}")
}

/// The picture size of a measurement, from its reference's options.
fn size_of(m: &Measurement) -> String {
    let option = |name: &str| m.reference.split(name).nth(1).and_then(|r| r.split_whitespace().next()).unwrap_or("?");
    format!("{} x {}", option("--width"), option("--height"))
}

/// Options without the picture size.
fn without_size(options: &str) -> String {
    let mut words = options.split_whitespace();
    let mut kept = Vec::new();
    while let Some(word) = words.next() {
        if word == "--width" || word == "--height" {
            words.next();
        } else {
            kept.push(word);
        }
    }
    kept.join(" ")
}
