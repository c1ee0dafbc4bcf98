//! Photon-mapping speed: photons traced per second, search grid build time and caustic-estimate (k-nearest-
//! neighbour lookup) time, on the `photon_map` example's scene. A plain program (no benchmark framework, so
//! nothing heavy is compiled): each figure is the median of several runs.
//!
//! ```sh
//! cargo bench --bench photon_map                 # the example's defaults
//! cargo bench --bench photon_map -- --photons 1000000 --k 100
//! ```

#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;

use examples::photon_map::Options;
use lecture6::app::cli::Cli;
use lecture6::lesson::math::Vector;
use lecture6::lesson::photon_map::{Emitter, PhotonMap, StoredPhoton, trace_photons};
use lecture6::lesson::render::thread_pool;
use lecture6::lesson::rng::Rng;
use std::time::{Duration, Instant};

/// Runs of each measurement; the median is reported.
const RUNS: usize = 5;
/// Estimates per lookup run.
const LOOKUPS: usize = 200_000;

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

fn time<T>(mut f: impl FnMut() -> T) -> (Duration, T) {
    let mut result = None;
    let times = (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            result = Some(f());
            start.elapsed()
        })
        .collect();
    (median(times), result.expect("at least one run"))
}

/// Where the estimates are made, and the normal there: `count` points of the floor spread over the
/// 150 x 150 square in front of the camera (mostly far from any photon, as most pixels are), or, for
/// `in_caustics`, the positions of stored photons (where every estimate gathers its k photons).
fn query_points(count: usize, photons: &[StoredPhoton], in_caustics: bool) -> Vec<(Vector, Vector)> {
    let mut rng = Rng::for_keys(&[7]);
    (0..count)
        .map(|_| {
            if in_caustics {
                let p = &photons[rng.below(photons.len() as u32) as usize];
                (p.position, -p.dir)
            } else {
                (Vector::new(150.0 * (rng.next_f32() - 0.5), 0.0, 150.0 * (rng.next_f32() - 0.5) + 25.0), Vector::Y)
            }
        })
        .collect()
}

fn main() {
    // `cargo bench` passes `--bench`; everything else is the example's own options.
    let argv = std::env::args().skip(1).filter(|a| a != "--bench");
    let args = Cli::<Options>::parse_args("photon_map", argv).unwrap_or_else(|e| e.exit());
    let (mut scene, _) = args.prepare().unwrap_or_else(|e| panic!("{e}"));
    scene.photon_map = None;
    let settings = scene.photons;
    let seed = args.common.seed;
    let emitter = Emitter::new(&scene, settings.count, seed).expect("the scene has caustic casters");

    for threads in [Some(1), None] {
        let pool = thread_pool(threads).expect("thread pool");
        let (t, photons) = time(|| pool.install(|| trace_photons(&scene, &emitter, seed)));
        println!(
            "trace {} photons ({} stored), {} thread(s): {:.1} ms, {:.3} M photons/s",
            settings.count,
            photons.len(),
            pool.current_num_threads(),
            t.as_secs_f64() * 1e3,
            settings.count as f64 * 1e-6 / t.as_secs_f64()
        );
    }

    let photons = trace_photons(&scene, &emitter, seed);
    let radius = settings.max_radius.expect("the example sets its radius");
    let (t, map) = time(|| PhotonMap::new(photons.clone(), settings.k, radius, false).expect("map"));
    println!("photon grid of {} photons: built in {:.2} ms", map.photons().len(), t.as_secs_f64() * 1e3);

    for (what, in_caustics) in [("anywhere on the floor", false), ("in the caustics", true)] {
        let points = query_points(LOOKUPS, map.photons(), in_caustics);
        let (t, sum) = time(|| points.iter().map(|&(p, n)| map.irradiance(p, n).r()).sum::<f32>());
        println!(
            "estimate (k = {}, radius {radius}) {what}: {:.3} us per lookup (checksum {sum:.1})",
            settings.k,
            t.as_secs_f64() * 1e6 / LOOKUPS as f64
        );
    }
}
