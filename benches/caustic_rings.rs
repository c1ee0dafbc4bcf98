//! The photon map's caustic on the rings of the independent reference (`benches/caustic_reference.rs`): the
//! `photon_map` example's map built at several photon counts, its estimate averaged over each ring of
//! `benches/results/caustic_reference.tsv`, and each ring's relative error against the reference. Beside
//! it, the same photons binned in the rings with no gathering at all: what the emission and the tracing
//! alone give, so that an error of the estimate and one of the photons can be told apart.
//!
//! ```sh
//! cargo bench --bench caustic_rings                            # 0.4, 1.6 and 6.4 M photons, k = 80
//! cargo bench --bench caustic_rings -- --every-ring            # each ring's error
//! cargo bench --bench caustic_rings -- --photons 400000 --seeds 32 --rings 50 --k 80,20,5
//!                                    # the centre only, 32 maps of their own seeds averaged, 3 values of k
//! cargo bench --bench caustic_rings -- -- --no-step photon-grid  # the example's own options after `--`
//! ```

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;
// Shared with the test `caustic_reference` and the other caustic bench, each of which uses part of it.
#[allow(dead_code)]
#[path = "../tests/workbook/common/caustic.rs"]
mod caustic;
mod common;

use caustic::{REFERENCE, Reference, binned_rings, estimated_rings, read_reference, relative_errors};
use clap::Parser;
use examples::photon_map::Options;
use lecture6::app::cli::Cli;
use lecture6::lesson::photon_map::{PhotonMap, PhotonSettings};
use std::path::Path;
use std::time::Instant;

#[derive(Parser)]
struct Args {
    /// Photon counts to build the map with.
    #[arg(long, value_delimiter = ',', default_value = "400000,1600000,6400000")]
    photons: Vec<u32>,
    /// Photons each estimate gathers; several values re-gather the same photons.
    #[arg(long, value_delimiter = ',', default_value = "80")]
    k: Vec<u32>,
    /// The estimate's maximum radius (the example's: 2).
    #[arg(long, default_value_t = 2.0)]
    radius: f32,
    /// Seeds (1, 2, ...): each builds its own map; the errors are averaged over them.
    #[arg(long, default_value_t = 1)]
    seeds: u64,
    /// Estimates along each ring's circles are this far apart.
    #[arg(long, default_value_t = 0.1)]
    spacing: f64,
    /// Only the first this many rings (the centre's, for a quick look).
    #[arg(long)]
    rings: Option<usize>,
    /// Print every ring's error, not only the summary.
    #[arg(long)]
    every_ring: bool,
    /// `cargo bench` passes it.
    #[arg(long, hide = true)]
    bench: bool,
    /// The example's own options (after `--`).
    #[arg(last = true)]
    example: Vec<String>,
}

/// The summary of one set of ring values: the central ring's error, the largest error of the rings from
/// 0.02 outward and where it is, and their root mean square.
fn summary(errors: &[f64], reference: &Reference) -> String {
    let (worst, at) = errors[1..]
        .iter()
        .enumerate()
        .fold((0.0f64, 0), |(w, at), (i, &e)| if e.abs() > w.abs() { (e, i + 1) } else { (w, at) });
    let rms = (errors[1..].iter().map(|e| e * e).sum::<f64>() / (errors.len() - 1) as f64).sqrt();
    format!(
        "central ring {:+.2}%, next rings {}, rings from 0.02 out: worst {:+.2}% (ring {:.2}-{:.2}), RMS {:.2}%",
        100.0 * errors[0],
        errors[1..5].iter().map(|e| format!("{:+.2}%", 100.0 * e)).collect::<Vec<_>>().join(" "),
        100.0 * worst,
        reference.rings[at].inner,
        reference.rings[at].outer,
        100.0 * rms
    )
}

/// The central ring's error over the seeds: its mean with the standard error of the mean, and the spread
/// from seed to seed.
fn central_spread(runs: &[Vec<f64>]) -> String {
    let n = runs.len() as f64;
    let mean = runs.iter().map(|r| r[0]).sum::<f64>() / n;
    let sd = (runs.iter().map(|r| (r[0] - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    format!(
        "central ring over {n} seeds: {:+.2}% +- {:.2}% (standard error of the mean), {:.2}% from seed to seed",
        100.0 * mean,
        100.0 * sd / n.sqrt(),
        100.0 * sd
    )
}

fn mean_of(runs: &[Vec<f64>]) -> Vec<f64> {
    (0..runs[0].len()).map(|i| runs.iter().map(|r| r[i]).sum::<f64>() / runs.len() as f64).collect()
}

fn main() {
    let args = Args::parse();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut reference = read_reference(&root.join(REFERENCE));
    reference.rings.truncate(args.rings.unwrap_or(usize::MAX).max(5));
    let worst_reference = reference.rings.iter().map(|r| r.standard_error / r.irradiance).fold(0.0, f64::max);
    println!(
        "reference: {} rings of {} out to {}, largest relative standard error {:.3}%",
        reference.rings.len(),
        reference.rings[0].outer,
        reference.rings.last().expect("rings").outer,
        100.0 * worst_reference
    );
    let argv = args.example.iter().map(String::as_str).chain(["--photons", "0"]);
    let cli = Cli::<Options>::parse_args("photon_map", argv).unwrap_or_else(|e| e.exit());
    let (scene, _) = cli.prepare().unwrap_or_else(|e| panic!("{e}"));

    for &photons in &args.photons {
        // Per k: each seed's errors of the estimate; and each seed's errors of the binned photons.
        let mut estimated = vec![Vec::new(); args.k.len()];
        let mut binned = Vec::new();
        for seed in 1..=args.seeds {
            let (start, cpu) = (Instant::now(), common::cpu_time());
            let mut scene = scene.clone();
            scene.photons = PhotonSettings { count: photons, k: args.k[0], max_radius: Some(args.radius), show: false };
            let map = PhotonMap::build(&scene, seed).expect("valid settings").expect("the scene has casters");
            binned.push(relative_errors(&binned_rings(map.photons(), &scene, &reference), &reference));
            for (i, &k) in args.k.iter().enumerate() {
                // The first k is the map's own; the others gather from the same photons.
                let regathered = (i > 0).then(|| PhotonMap::new(map.photons().to_vec(), k, args.radius, false));
                let gathering = regathered.transpose().expect("valid k");
                let values = estimated_rings(gathering.as_ref().unwrap_or(&map), &scene, &reference, args.spacing);
                estimated[i].push(relative_errors(&values, &reference));
            }
            let cpu = match (common::cpu_time(), cpu) {
                (Some(end), Some(start)) => format!("{:.1}", (end - start).as_secs_f64()),
                _ => "unknown".to_string(),
            };
            println!(
                "{photons} photons, seed {seed}: {} stored; map and estimates {:.1} s wall, {cpu} s CPU",
                map.photons().len(),
                start.elapsed().as_secs_f64()
            );
        }
        println!("{photons} photons, binned with no gathering: {}", summary(&mean_of(&binned), &reference));
        if args.seeds > 1 {
            println!("    {}", central_spread(&binned));
        }
        let binned = mean_of(&binned);
        for (k, runs) in args.k.iter().zip(&estimated) {
            let errors = mean_of(runs);
            println!("{photons} photons, k = {k}, radius {}: {}", args.radius, summary(&errors, &reference));
            if args.seeds > 1 {
                println!("    {}", central_spread(runs));
            }
            if args.every_ring {
                println!("    inner\touter\treference\testimate error\tbinned error");
                for ((ring, e), b) in reference.rings.iter().zip(&errors).zip(&binned) {
                    println!(
                        "    {:.2}\t{:.2}\t{:.4e}\t{:+.2}%\t{:+.2}%",
                        ring.inner,
                        ring.outer,
                        ring.irradiance,
                        100.0 * e,
                        100.0 * b
                    );
                }
            }
        }
    }
}
