//! Measurements of the dispersion renderer (`cargo bench --bench dispersion`):
//!
//! 1. The skip: a scene with nothing dispersive (`bitmap_textures`) rendered with `--wavelengths 1` and
//!    `--wavelengths 8`, interleaved, median of 5 each. Both must trace the same rays in the same time.
//! 2. K wavelength passes (the slide's method), spectral sampling (one wavelength per anti-aliasing sample)
//!    and hero-wavelength sampling (C wavelengths per sample, one path until it meets the glass) on the
//!    `dispersion` scene at 160 x 120: the rays traced, the time, and the RMSE in linear light against a
//!    reference rendered once with hero sampling at 8 wavelengths x 256 samples per pixel (cached under
//!    `target/dispersion-bench/`), and, to show the reference does not favour one method, its RMSE against
//!    a 32-pass x 32-sample reference.
//!
//! Timings are medians of 3 runs of the render alone (scene building excluded); the ray counts are the
//! load-independent cost.

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;

use examples::{bitmap_textures, dispersion};
use lecture6::app::cli::{Cli, Example};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::RenderStats;
use std::path::Path;

fn render<E: Example>(args: &[&str]) -> (Frame, RenderStats) {
    let argv = std::iter::once("--quiet").chain(args.iter().copied());
    Cli::<E>::parse_args("bench", argv).expect("bench arguments parse").render().expect("render")
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Root-mean-square difference over all channels, in linear light.
fn rmse(a: &Frame, b: &Frame) -> f64 {
    let sum: f64 = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| (p.0 - q.0).to_array().iter().map(|d| (*d as f64).powi(2)).sum::<f64>())
        .sum();
    (sum / (3 * a.pixels.len()) as f64).sqrt()
}

fn load_or_render(path: &Path, args: &[&str]) -> Frame {
    if let Ok(img) = image::open(path) {
        let img = img.to_rgb32f();
        let pixels = img.pixels().map(|p| lecture6::Color::new(p[0], p[1], p[2])).collect();
        return Frame { width: img.width(), height: img.height(), pixels };
    }
    let (frame, stats) = render::<dispersion::Options>(args);
    println!("  rendered {} in {:.1} s", path.display(), stats.elapsed.as_secs_f64());
    frame.save(path).expect("cache the reference");
    frame
}

fn main() {
    println!("## The skip: bitmap_textures (nothing dispersive), 640x480, 4 spp, 5 runs each, interleaved\n");
    let (mut t1, mut t8) = (Vec::new(), Vec::new());
    let (mut rays1, mut rays8) = (0, 0);
    for _ in 0..5 {
        let (_, s) = render::<bitmap_textures::Options>(&["--wavelengths", "1"]);
        t1.push(s.elapsed.as_secs_f64());
        rays1 = s.counters.total();
        let (_, s) = render::<bitmap_textures::Options>(&["--wavelengths", "8"]);
        t8.push(s.elapsed.as_secs_f64());
        rays8 = s.counters.total();
    }
    let (m1, m8) = (median(t1.clone()), median(t8.clone()));
    println!("| --wavelengths | median time | all runs (s) | rays |");
    println!("|---|---|---|---|");
    println!("| 1 | {m1:.3} s | {t1:.3?} | {rays1} |");
    println!("| 8 | {m8:.3} s | {t8:.3?} | {rays8} |");
    println!("\nratio 8 / 1: {:.3}\n", m8 / m1);

    let size = ["--width", "160", "--height", "120"];
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target").join("dispersion-bench");
    std::fs::create_dir_all(&dir).expect("create target/dispersion-bench");
    println!("## K passes, spectral sampling and hero sampling: dispersion, 160x120, RMSE in linear light\n");
    let reference = load_or_render(
        &dir.join("reference-hero-8x256.exr"),
        &[&size[..], &["--spectral", "hero", "--wavelengths", "8", "--spp", "256", "--seed", "7"]].concat(),
    );
    let check = load_or_render(
        &dir.join("reference-passes-32x32.exr"),
        &[&size[..], &["--spectral", "passes", "--wavelengths", "32", "--spp", "32"]].concat(),
    );
    println!("reference (hero, 8 x 256) against 32 passes x 32 spp: RMSE {:.5}\n", rmse(&reference, &check));

    println!("| method | wavelengths x spp | M rays | median time | RMSE |");
    println!("|---|---|---:|---:|---:|");
    let mut rows = Vec::new();
    let configs: Vec<(&str, u32, u32)> = vec![
        ("passes", 4, 2),
        ("passes", 8, 1),
        ("passes", 8, 2),
        ("passes", 8, 4),
        ("passes", 8, 8),
        ("passes", 16, 2),
        ("sampled", 1, 8),
        ("sampled", 1, 16),
        ("sampled", 1, 32),
        ("hero", 8, 1),
        ("hero", 8, 2),
        ("hero", 8, 4),
        ("hero", 8, 8),
        ("hero", 4, 2),
        ("hero", 4, 4),
        ("hero", 4, 8),
        ("hero", 2, 8),
    ];
    for (mode, k, spp) in configs {
        let (k_s, spp_s) = (k.to_string(), spp.to_string());
        let args = [&size[..], &["--spectral", mode, "--wavelengths", &k_s, "--spp", &spp_s]].concat();
        let mut times = Vec::new();
        let mut frame = None;
        let mut rays = 0;
        for _ in 0..3 {
            let (f, s) = render::<dispersion::Options>(&args);
            times.push(s.elapsed.as_secs_f64());
            rays = s.counters.total();
            frame = Some(f);
        }
        let (t, e) = (median(times), rmse(frame.as_ref().unwrap(), &reference));
        println!("| {mode} | {k} x {spp} | {:.2} | {t:.3} s | {e:.5} |", rays as f64 * 1e-6);
        rows.push((mode, k, k * spp, rays, e));
    }
    println!("\nThe same wavelengths per pixel (K x spp or C x spp): RMSE and rays of each method against 8 passes");
    for (_, _, n, rays_p, e_p) in rows.iter().filter(|r| r.0 == "passes" && r.1 == 8) {
        for (mode, k, _, rays, e) in rows.iter().filter(|r| r.0 != "passes" && r.2 == *n) {
            println!(
                "  {n} wavelengths/pixel: {mode} ({k} per path) RMSE {e:.5} ({:.2} of the passes'), rays {:.2} of the \
                 passes'",
                e / e_p,
                *rays as f64 / *rays_p as f64
            );
        }
    }
}
