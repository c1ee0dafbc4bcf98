//! Run time versus error for every example with stochastic parts:
//!
//! ```sh
//! cargo bench --features study --bench error_vs_time
//! ```
//!
//! Each curve sweeps one sample-count option of one example at 320 x 240 and measures the median wall time
//! of 3 renders and the error against a converged reference (see `lecture6::study`). It writes
//! `target/study/error_vs_time.md` (the table, the Pareto-optimal points, and the equal-time error ratio of
//! the two glossy samplers) and `target/study/error_vs_time.png` (log-log charts of error versus time).
//! References are cached in `target/study/` and rendered again whenever the program is rebuilt.
//!
//! To add an example, add its sweeps to `sweeps()`.

use lecture6::scenes::{bitmap_textures, glossy};
use lecture6::study::{self, Measurement, Sweep};
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

const SIZE: [&str; 4] = ["--width", "320", "--height", "240"];
const REPEATS: usize = 3;

/// The glossy example's reference: 64 x 64 = 4096 glossy rays per pixel, another seed.
const GLOSSY_REFERENCE: [&str; 6] = ["--spp", "64", "--glossy-samples", "64", "--seed", "7"];

fn with_size(extra: &[&'static str]) -> Vec<&'static str> {
    SIZE.iter().chain(extra).copied().collect()
}

fn sweeps() -> Vec<Sweep> {
    let glossy_samples = |sampler: &'static str, spp: &'static str, values: &[u32]| {
        Sweep::new::<glossy::Args>(
            &format!("{sampler}, --spp {spp}"),
            &with_size(&["--sampler", sampler, "--spp", spp]),
            "--glossy-samples",
            values,
            &GLOSSY_REFERENCE,
        )
    };
    vec![
        Sweep::new::<bitmap_textures::Args>(
            "anti-aliasing",
            &with_size(&[]),
            "--spp",
            &[1, 2, 4, 9, 16, 36, 64],
            &["--spp", "1024", "--seed", "7"],
        ),
        glossy_samples("random", "1", &[1, 2, 4, 8, 16, 32, 64, 128]),
        glossy_samples("stratified", "1", &[1, 2, 4, 8, 16, 32, 64, 128]),
        glossy_samples("random", "4", &[1, 2, 4, 8, 16, 32]),
        glossy_samples("stratified", "4", &[1, 2, 4, 8, 16, 32]),
        Sweep::new::<glossy::Args>(
            "stratified, --glossy-samples 1",
            &with_size(&["--sampler", "stratified", "--glossy-samples", "1"]),
            "--spp",
            &[1, 4, 16, 64],
            &GLOSSY_REFERENCE,
        ),
    ]
}

fn main() {
    // `cargo bench` passes `--bench` (and any filter); the study has no options of its own.
    let start = Instant::now();
    let dir = study::output_dir();
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("error_vs_time: cannot create {}: {e}", dir.display());
        std::process::exit(2);
    }
    let mut curves: Vec<Vec<Measurement>> = Vec::new();
    for sweep in sweeps() {
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
            eprintln!("  {} {:>4}: {:.3} s, RMSE {:.5}, FLIP {:.4}", m.knob, m.value, m.seconds, m.rmse, m.perceptual.unwrap_or(0.0));
        }
        curves.push(curve);
    }
    let all: Vec<Measurement> = curves.iter().flatten().cloned().collect();
    let mut report = String::from("# Run time versus error\n\n");
    report += &format!("320 x 240, median wall time of {REPEATS} renders; `*` marks the Pareto front of each example.\n\n");
    report += &study::markdown_table(&all);
    report += &sampler_comparison(&curves);
    let table_path = dir.join("error_vs_time.md");
    std::fs::write(&table_path, &report).unwrap_or_else(|e| fail(&lecture6::Error::file("cannot write", &table_path, e)));
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

/// The equal-time comparison of the glossy samplers: for each point of a stratified curve, the RMSE the
/// random curve with the same other options reaches in the same time (interpolated in log-log), divided by
/// the stratified RMSE.
fn sampler_comparison(curves: &[Vec<Measurement>]) -> String {
    let mut out = String::from(
        "\n## The slide's random disc points against stratified ones, at equal time\n\n\
         | curve | setting | time (s) | RMSE stratified | RMSE random at that time | ratio |\n|---|---|---:|---:|---:|---:|\n",
    );
    let mut log_sum = 0.0;
    let mut count = 0;
    for stratified in curves.iter().filter(|c| c[0].label.starts_with("stratified, --spp")) {
        let random_label = stratified[0].label.replace("stratified", "random");
        let Some(random) = curves.iter().find(|c| c[0].label == random_label) else { continue };
        let mut random_by_time = random.clone();
        random_by_time.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
        for m in stratified {
            if let Some(r) = study::rmse_at_time(&random_by_time, m.seconds) {
                let ratio = r / m.rmse;
                log_sum += ratio.ln();
                count += 1;
                let _ = writeln!(
                    out,
                    "| {} | `{} {}` | {:.3} | {:.5} | {:.5} | {:.2} |",
                    m.label, m.knob, m.value, m.seconds, m.rmse, r, ratio
                );
            }
        }
    }
    if count > 0 {
        let _ = writeln!(
            out,
            "\nGeometric mean of the ratio over {count} points: **{:.2}** (the random sampler's RMSE over the \
             stratified one's at the same time).",
            (log_sum / count as f64).exp()
        );
    }
    out
}

/// Log-log charts of RMSE and of mean FLIP against time, one line per curve.
fn draw_chart(curves: &[Vec<Measurement>], path: &Path) -> lecture6::Result<()> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, include_bytes!("fonts/DejaVuSansMono.ttf"))
        .map_err(|_| lecture6::Error::file("cannot read font", Path::new("benches/fonts/DejaVuSansMono.ttf"), "invalid"))?;
    let (w, h) = (1200u32, 500u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    let chart_error = |e: &dyn std::fmt::Display| lecture6::Error::file("cannot draw chart", path, e.to_string());
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| chart_error(&e))?;
        let panels = root.split_evenly((1, 2));
        let metrics: [(&str, fn(&Measurement) -> f64); 2] =
            [("RMSE (linear)", |m| m.rmse), ("mean FLIP", |m| m.perceptual.unwrap_or(f64::NAN))];
        for (panel, (name, metric)) in panels.iter().zip(metrics) {
            let points = curves.iter().flatten();
            let (t_min, t_max) = points.clone().fold((f64::MAX, 0f64), |(a, b), m| (a.min(m.seconds), b.max(m.seconds)));
            let (e_min, e_max) = points
                .map(metric)
                .filter(|v| v.is_finite() && *v > 0.0)
                .fold((f64::MAX, 0f64), |(a, b), v| (a.min(v), b.max(v)));
            let mut chart = ChartBuilder::on(panel)
                .caption(format!("{name} versus render time, 320 x 240"), ("sans-serif", 18))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(70)
                .build_cartesian_2d((t_min * 0.8..t_max * 1.25).log_scale(), (e_min * 0.8..e_max * 1.25).log_scale())
                .map_err(|e| chart_error(&e))?;
            chart
                .configure_mesh()
                .x_desc("seconds")
                .y_desc(name)
                .label_style(("sans-serif", 13))
                .draw()
                .map_err(|e| chart_error(&e))?;
            for (i, curve) in curves.iter().enumerate() {
                let color = Palette99::pick(i).to_rgba();
                let series: Vec<(f64, f64)> = curve.iter().map(|m| (m.seconds, metric(m))).collect();
                chart
                    .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))
                    .map_err(|e| chart_error(&e))?
                    .label(format!("{}: {} ({})", curve[0].example, curve[0].label, curve[0].knob))
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], color.stroke_width(2)));
                chart
                    .draw_series(series.into_iter().map(|p| Circle::new(p, 3, color.filled())))
                    .map_err(|e| chart_error(&e))?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::LowerLeft)
                .label_font(("sans-serif", 12))
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()
                .map_err(|e| chart_error(&e))?;
        }
        root.present().map_err(|e| chart_error(&e))?;
    }
    let img = image::RgbImage::from_raw(w, h, buffer).expect("the chart buffer matches its size");
    lecture6::render::save_atomically(path, |tmp| img.save_with_format(tmp, image::ImageFormat::Png))
}
