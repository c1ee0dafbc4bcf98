//! Run time versus error: the instrument that says how many samples a stochastic effect needs.
//!
//! A [`Sweep`] renders one example at rising values of one sample-count option (`--spp`,
//! `--glossy-samples`, ...), each with the others held fixed, and measures the wall time of each render and
//! its error against a converged reference: the same example at a very high sample count and another seed,
//! rendered once and cached under `target/study/`. The errors are the RMSE of the linear values and, with
//! the `study` feature, the mean of NVIDIA's FLIP perceptual metric on the 8-bit sRGB pictures a viewer sees
//! (through the `nv-flip` crate, which compiles FLIP's C++ with the system compiler; FLIP models how
//! visible a difference is at a given viewing distance, so noise in dark or busy regions counts less than
//! in a flat bright one).
//!
//! `benches/error_vs_time.rs` runs the study of every stochastic example and writes a Markdown table and a
//! log-log chart, with the equal-time and equal-error comparisons of the ways to do the same thing (glossy
//! samplers; wavelength passes against per-path spectral sampling). Another example joins it with one more [`Sweep::new`] there; a test
//! (`tests/workbook/study.rs`) checks on a tiny picture that the error really falls as the sample count rises.

use crate::lesson::error::{Error, Result};
use crate::lesson::frame::Frame;
use crate::lesson::rng::mix64;
use std::path::{Path, PathBuf};

/// A render and what it cost.
pub struct Timed {
    /// The rendered picture, in linear light.
    pub frame: Frame,
    /// Wall time of the render itself (parsing and scene building excluded), in seconds.
    pub seconds: f64,
    /// Rays traced: camera, secondary and shadow rays (a cost that does not depend on the machine's load).
    pub rays: u64,
}

/// Renders an example from its command-line options; what a [`Sweep`] calls for every point.
pub type RenderFn = fn(&[String]) -> Result<Timed>;

/// What a study renders: an example, named by its options type, rendered from its command-line options
/// exactly as its binary would render them. The application implements it for every example (its
/// `Example` trait), so a sweep names the example it studies: `Sweep::new::<glossy::Options>(...)`.
pub trait Subject {
    /// Renders the example with the options `args` (a caustic render's time includes its photon pass).
    fn render_timed(args: &[String]) -> Result<Timed>;
}

/// One curve of the study: an example, the options every point shares, and the values of the one
/// sample-count option that is swept.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// The example's name (`glossy`): the file in `examples/` and the name of its cached reference.
    pub example: &'static str,
    /// What the curve is called in the table and the chart.
    pub label: String,
    /// Options of every point (size, fixed sample counts, sampler, ...).
    pub fixed: Vec<String>,
    /// The option swept, e.g. `--glossy-samples`.
    pub knob: &'static str,
    /// The values the knob takes, one render each.
    pub values: Vec<u32>,
    /// The options of the reference (added to `fixed`; later options win, as clap reads them).
    pub reference: Vec<String>,
    render: RenderFn,
}

fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}

impl Sweep {
    /// A sweep of the example `E`, called `example`: `fixed` options for every render, `knob` taking each of `values`, and a
    /// reference rendered with `fixed` followed by `reference`.
    pub fn new<E: Subject>(
        example: &'static str,
        label: &str,
        fixed: &[&str],
        knob: &'static str,
        values: &[u32],
        reference: &[&str],
    ) -> Sweep {
        Sweep {
            example,
            label: label.to_string(),
            fixed: strings(fixed),
            knob,
            values: values.to_vec(),
            reference: strings(reference),
            render: E::render_timed,
        }
    }

    /// The options of the point where the knob is `value`.
    pub fn point_args(&self, value: u32) -> Vec<String> {
        override_options(&self.fixed, &[self.knob.to_string(), value.to_string(), "--quiet".to_string()])
    }

    /// The options of the reference render: the fixed ones, overridden by the reference's.
    pub fn reference_args(&self) -> Vec<String> {
        let mut reference = self.reference.clone();
        reference.push("--quiet".to_string());
        override_options(&self.fixed, &reference)
    }

    /// The reference picture: read from `cache_dir` when an earlier run of the same program left it there,
    /// else rendered (this is the slow step) and stored. The cache key holds the example, the reference
    /// options and the modification time of the running program, so a rebuilt renderer never compares
    /// against a stale reference.
    pub fn reference_frame(&self, cache_dir: Option<&Path>) -> Result<Frame> {
        let args = self.reference_args();
        let Some(dir) = cache_dir else {
            return (self.render)(&args).map(|timed| timed.frame);
        };
        let path = dir.join(format!("{}-{:016x}.exr", self.example, cache_key(self.example, &args)));
        if let Ok(img) = image::open(&path) {
            let img = img.to_rgb32f();
            let pixels = img.pixels().map(|p| crate::Color::new(p[0], p[1], p[2])).collect();
            return Ok(Frame { width: img.width(), height: img.height(), pixels });
        }
        let frame = (self.render)(&args)?.frame;
        frame.save(&path)?;
        Ok(frame)
    }

    /// Renders every point `repeats` times and measures it against `reference`. The time of a point is the
    /// median of its repeats (the machine may be busy with other work); the error is that of the first
    /// repeat (every repeat gives the same picture).
    pub fn measure(
        &self,
        reference: &Frame,
        repeats: usize,
        metric: Option<PerceptualMetric>,
    ) -> Result<Vec<Measurement>> {
        self.values
            .iter()
            .map(|&value| {
                let mut reference_options = self.reference_args();
                reference_options.retain(|a| a != "--quiet");
                let reference_options = reference_options.join(" ");
                let args = self.point_args(value);
                let first = (self.render)(&args)?;
                let mut times = vec![first.seconds];
                for _ in 1..repeats {
                    times.push((self.render)(&args)?.seconds);
                }
                times.sort_by(f64::total_cmp);
                let frame = first.frame;
                Ok(Measurement {
                    example: self.example,
                    label: self.label.clone(),
                    reference: reference_options,
                    knob: self.knob,
                    value,
                    seconds: times[times.len() / 2],
                    rays: first.rays,
                    rmse: rmse_linear(&frame, reference)?,
                    perceptual: metric.map(|m| m(&frame, reference)),
                })
            })
            .collect()
    }
}

/// `base` followed by `overrides`, without the options of `base` that `overrides` gives again (with their
/// values), since an example accepts each option once.
fn override_options(base: &[String], overrides: &[String]) -> Vec<String> {
    let mut out = Vec::with_capacity(base.len() + overrides.len());
    let mut skipping = false;
    for arg in base {
        if arg.starts_with('-') && arg.parse::<f64>().is_err() {
            skipping = overrides.contains(arg);
        }
        if !skipping {
            out.push(arg.clone());
        }
    }
    out.extend(overrides.iter().cloned());
    out
}

/// A perceptual error of a picture against a reference (0 = indistinguishable).
pub type PerceptualMetric = fn(&Frame, &Frame) -> f64;

fn cache_key(example: &str, args: &[String]) -> u64 {
    let program_time = std::env::current_exe()
        .and_then(std::fs::metadata)
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
        .map_or(0, |d| d.as_nanos() as u64);
    let text = format!("{example} {} {}", args.join(" "), env!("CARGO_PKG_VERSION"));
    text.bytes().fold(mix64(program_time), |h, b| mix64(h ^ b as u64))
}

/// Where the study keeps its references and writes its results: `target/study/` of the workbook (or of
/// `CARGO_TARGET_DIR`).
pub fn output_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"), PathBuf::from)
        .join("study")
}

/// One point of a sweep.
#[derive(Clone, Debug)]
pub struct Measurement {
    /// The example's name (see [`Sweep::example`]).
    pub example: &'static str,
    /// The curve's label (see [`Sweep::label`]).
    pub label: String,
    /// All the options that made the reference (measurements against different references do not compare).
    pub reference: String,
    /// The option swept (see [`Sweep::knob`]).
    pub knob: &'static str,
    /// The knob's value at this point.
    pub value: u32,
    /// Median wall time of the render, in seconds.
    pub seconds: f64,
    /// Rays traced by the render.
    pub rays: u64,
    /// RMSE of the linear values against the reference, over all channels.
    pub rmse: f64,
    /// The perceptual error (mean FLIP), when a metric was given.
    pub perceptual: Option<f64>,
}

/// The root-mean-square difference of two frames' linear values, over all channels. Both must have the same
/// size.
pub fn rmse_linear(a: &Frame, b: &Frame) -> Result<f64> {
    if (a.width, a.height) != (b.width, b.height) {
        return Err(Error::parameter(
            "image size",
            format!("{}x{}", a.width, a.height),
            format!("the reference is {}x{}", b.width, b.height),
        ));
    }
    let sum: f64 = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| (p.0 - q.0).to_array().iter().map(|&d| (d as f64).powi(2)).sum::<f64>())
        .sum();
    Ok((sum / (3 * a.pixels.len().max(1)) as f64).sqrt())
}

/// The mean FLIP error of `test` against `reference` as 8-bit sRGB pictures, for a viewer at FLIP's default
/// distance (0.7 m from a 0.7 m wide 4K monitor, 67 pixels per degree).
#[cfg(feature = "study")]
pub fn mean_flip(test: &Frame, reference: &Frame) -> f64 {
    let to_flip = |f: &Frame| nv_flip::FlipImageRgb8::with_data(f.width, f.height, f.to_rgb8().as_raw());
    let map = nv_flip::flip(to_flip(reference), to_flip(test), nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    nv_flip::FlipPool::from_image(&map).mean() as f64
}

impl Measurement {
    /// Whether two measurements can be compared: the same example against the same reference.
    pub fn same_group(&self, other: &Measurement) -> bool {
        self.example == other.example && self.reference == other.reference
    }
}

/// For each measurement, whether it is on the Pareto front of its group (the same example against the same
/// reference): no other measurement of the group is both faster and more accurate (by RMSE).
pub fn pareto_front(measurements: &[Measurement]) -> Vec<bool> {
    measurements
        .iter()
        .map(|m| {
            !measurements.iter().any(|o| {
                o.same_group(m)
                    && o.seconds <= m.seconds
                    && o.rmse <= m.rmse
                    && (o.seconds < m.seconds || o.rmse < m.rmse)
            })
        })
        .collect()
}

/// The error a curve (measurements in order of rising time) would have at `seconds`, interpolated linearly
/// in log(time)-log(error); `None` outside the curve's time range.
pub fn rmse_at_time(curve: &[Measurement], seconds: f64) -> Option<f64> {
    curve.windows(2).find_map(|w| {
        let (a, b) = (&w[0], &w[1]);
        let (lo, hi) = (a.seconds.min(b.seconds), a.seconds.max(b.seconds));
        if !(lo..=hi).contains(&seconds) {
            return None;
        }
        if hi == lo {
            return Some(a.rmse.min(b.rmse));
        }
        let t = (seconds.ln() - a.seconds.ln()) / (b.seconds.ln() - a.seconds.ln());
        Some((a.rmse.ln() + t * (b.rmse.ln() - a.rmse.ln())).exp())
    })
}

/// What a curve (measurements in order of rising cost) would cost to reach the error `rmse`, by `cost` (the
/// time, or the rays), interpolated linearly in log(cost)-log(error) between the first two neighbouring
/// points whose errors bracket it; `None` if no two do.
pub fn cost_at_rmse(curve: &[Measurement], rmse: f64, cost: fn(&Measurement) -> f64) -> Option<f64> {
    curve.windows(2).find_map(|w| {
        let (a, b) = (&w[0], &w[1]);
        let (lo, hi) = (a.rmse.min(b.rmse), a.rmse.max(b.rmse));
        if !(lo..=hi).contains(&rmse) {
            return None;
        }
        if hi == lo {
            return Some(cost(a).min(cost(b)));
        }
        let t = (rmse.ln() - a.rmse.ln()) / (b.rmse.ln() - a.rmse.ln());
        Some((cost(a).ln() + t * (cost(b).ln() - cost(a).ln())).exp())
    })
}

/// The measurements as Markdown tables, one per group (example and reference), Pareto-optimal points marked.
pub fn markdown_table(measurements: &[Measurement]) -> String {
    let front = pareto_front(measurements);
    let mut out = String::new();
    for (k, m) in measurements.iter().enumerate() {
        if k == 0 || !m.same_group(&measurements[k - 1]) {
            out += &format!(
                "\n`{}` against the reference `{}`:\n\n\
                 | curve | setting | time (s) | M rays | RMSE (linear) | mean FLIP | Pareto |\n\
                 |---|---|---:|---:|---:|---:|:---:|\n",
                m.example, m.reference
            );
        }
        let flip = m.perceptual.map_or("-".to_string(), |f| format!("{f:.4}"));
        out += &format!(
            "| {} | `{} {}` | {:.3} | {:.2} | {:.5} | {} | {} |\n",
            m.label,
            m.knob,
            m.value,
            m.seconds,
            m.rays as f64 * 1e-6,
            m.rmse,
            flip,
            if front[k] { "*" } else { "" }
        );
    }
    out
}
