//! Mesh benchmark: BVH build time and ray throughput of [`Mesh`] on any OBJ file.
//!
//! ```sh
//! cargo bench --bench mesh                       # textures/teapot.obj and a 102,080-triangle teapot
//! cargo bench --bench mesh -- --mesh FILE.obj    # any mesh
//! ```
//!
//! For each mesh: the BVH build (median of 5), then closest-hit throughput with 1 and 2 threads for
//! (a) primary rays: 640 x 480 pinhole camera aimed at the bounding-box centre from the +z side, raised by
//! atan(5/12), up +y, vertical field of view 53.13 degrees, at the smallest distance that frames all eight
//! box corners; (b) incoherent rays: origins uniform on a sphere of radius 1.5 x half the box diagonal around
//! the centre, aimed at points uniform in the box; (c) shadow rays (any hit) from the primary hits to a point
//! light above and to the side. Each figure is the median of 5 runs and is printed with its hit count.
//!
//! Rates are given by the wall clock and by CPU time (rays per second that each thread actually ran, read
//! from /proc on Linux): on a machine shared with other work the wall clock understates what the code does,
//! the CPU time does not.
//!
//! `--dump-rays DIR` also writes, for each mesh, its triangles and the three sets of rays to
//! `DIR/NAME.rays`, so that another ray tracer can be timed on exactly the same work (see
//! `benches/embree/embree_bench.c`). The file is little-endian: the 8 bytes `L6RAYS1\0`; the triangle
//! count `n` (u32) and `9 n` f32 (the corners, in the order the BVH stores them); then for the primary,
//! incoherent and shadow rays in turn, the ray count `m` (u32), how many of them this BVH finds a hit for
//! (u32), and `7 m` f32 (start x y z, direction x y z, and the largest ray parameter, infinite except for
//! shadow rays, which end at the light).

use clap::Parser;
use lecture6::lesson::geometry::bvh::Bvh;
use lecture6::lesson::geometry::triangle4::LANES;
use lecture6::lesson::geometry::{Aabb, Geometry, Mesh};
use lecture6::lesson::math::Vector;
use lecture6::lesson::ray::{Ray, spawn_point};
use lecture6::lesson::rng::Rng;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Parser)]
struct Args {
    /// The OBJ file to measure [default: the bundled teapot and a ~100,000-triangle teapot under target/].
    #[arg(long, value_name = "FILE")]
    mesh: Option<PathBuf>,
    /// Runs of each measurement (the median is reported).
    #[arg(long, default_value_t = 5)]
    runs: usize,
    /// Also write each mesh's triangles and rays to DIR/NAME.rays (see the module documentation).
    #[arg(long, value_name = "DIR", hide = true)]
    dump_rays: Option<PathBuf>,
    /// Accepted for `cargo bench` compatibility.
    #[arg(long, hide = true)]
    bench: bool,
}

const WIDTH: usize = 640;
const HEIGHT: usize = 480;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The primary rays of the benchmark's camera (see the module documentation).
fn primary_rays(b: &Aabb) -> Vec<Ray> {
    let c = b.center();
    let back = Vector::new(0.0, 5.0, 12.0) / 13.0;
    let forward = -back;
    let up = (Vector::Y - forward * forward.dot(Vector::Y)).normalize();
    let right = forward.cross(up);
    let tan_v = (53.13f32.to_radians() * 0.5).tan();
    let tan_h = tan_v * WIDTH as f32 / HEIGHT as f32;
    // The camera sits at c + d * back; a corner p is in view when its offsets across are within the
    // field of view at its depth d - (p - c).back.
    let d = b
        .corners()
        .iter()
        .map(|&p| {
            let q = p - c;
            q.dot(back) + (q.dot(right).abs() / tan_h).max(q.dot(up).abs() / tan_v)
        })
        .fold(0.0f32, f32::max);
    let eye = c + back * d;
    (0..HEIGHT)
        .flat_map(|y| (0..WIDTH).map(move |x| (x, y)))
        .map(|(x, y)| {
            let sx = (2.0 * (x as f32 + 0.5) / WIDTH as f32 - 1.0) * tan_h;
            let sy = (1.0 - 2.0 * (y as f32 + 0.5) / HEIGHT as f32) * tan_v;
            Ray::new(eye, (forward + right * sx + up * sy).normalize())
        })
        .collect()
}

/// Incoherent rays (see the module documentation).
fn incoherent_rays(b: &Aabb, n: usize) -> Vec<Ray> {
    let c = b.center();
    let radius = 1.5 * 0.5 * (b.max - b.min).length();
    let mut rng = Rng::for_keys(&[7]);
    (0..n)
        .map(|_| {
            let z = 1.0 - 2.0 * rng.next_f32();
            let phi = 2.0 * std::f32::consts::PI * rng.next_f32();
            let s = (1.0 - z * z).max(0.0).sqrt();
            let start = c + radius * Vector::new(s * phi.cos(), s * phi.sin(), z);
            let target = b.min + (b.max - b.min) * Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
            Ray::new(start, (target - start).normalize())
        })
        .collect()
}

/// The CPU time used so far by all threads of this process, in seconds (Linux: the sum of every thread's
/// run time from /proc; `None` elsewhere).
fn cpu_seconds() -> Option<f64> {
    let mut ns = 0u64;
    for task in std::fs::read_dir("/proc/self/task").ok()? {
        let stat = std::fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        ns += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(ns as f64 * 1e-9)
}

/// A throughput: Mrays/s by the wall clock, and per second of CPU time given to each thread (which is
/// what the threads achieve while they run, whatever else the machine is doing), and the count of rays
/// for which `f` said yes.
struct Rate {
    wall: f64,
    cpu: Option<f64>,
    count: usize,
}

impl std::fmt::Display for Rate {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{:6.2} Mrays/s", self.wall)?;
        if let Some(cpu) = self.cpu {
            write!(f, " (CPU time: {cpu:6.2})")?;
        }
        Ok(())
    }
}

/// Runs `f` over all rays `runs` times with `threads` threads; the median rates and the count.
fn measure(rays: &[Ray], threads: usize, runs: usize, f: impl Fn(&Ray) -> bool + Sync) -> Rate {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
    let mut count = 0;
    let (mut wall, mut cpu) = (Vec::new(), Vec::new());
    for _ in 0..runs {
        let (start, cpu_start) = (Instant::now(), cpu_seconds());
        count = pool.install(|| rays.par_chunks(1024).map(|c| c.iter().filter(|r| f(r)).count()).sum());
        wall.push(start.elapsed().as_secs_f64());
        cpu.extend(cpu_start.zip(cpu_seconds()).map(|(a, b)| (b - a) / threads as f64));
    }
    let mrays = rays.len() as f64 * 1e-6;
    Rate { wall: mrays / median(wall), cpu: (!cpu.is_empty()).then(|| mrays / median(cpu)), count }
}

/// A set of rays for `--dump-rays`: the rays, each ray's largest parameter, and whether it hits.
type RaySet<'a> = (&'a [Ray], &'a dyn Fn(&Ray) -> f32, &'a dyn Fn(&Ray) -> bool);

/// Writes the mesh's triangles and the ray sets to `file` (the format is in the module documentation).
fn dump_rays(file: &Path, mesh: &Mesh, sets: [RaySet; 3]) {
    let mut bytes = b"L6RAYS1\0".to_vec();
    let mut put = |values: &[f32]| values.iter().for_each(|v| bytes.extend(v.to_le_bytes()));
    let triangles = mesh.triangles();
    put(&[f32::from_bits(triangles.len() as u32)]);
    triangles.iter().flatten().for_each(|v| put(&v.to_array()));
    for (rays, t_max, hit) in sets {
        let hits = rays.iter().filter(|r| hit(r)).count();
        put(&[f32::from_bits(rays.len() as u32), f32::from_bits(hits as u32)]);
        rays.iter().for_each(|r| put(&[&r.start.to_array()[..], &r.dir.to_array(), &[t_max(r)]].concat()));
    }
    let written = file.parent().map_or(Ok(()), std::fs::create_dir_all).and_then(|()| std::fs::write(file, bytes));
    if let Err(e) = written {
        eprintln!("mesh: cannot write {}: {e}", file.display());
    }
}

fn bench(path: &Path, runs: usize, dump: Option<&Path>) -> Result<(), lecture6::Error> {
    let mesh = Mesh::load(path)?;
    let b = mesh.bounds().ok_or_else(|| lecture6::Error::file("cannot benchmark mesh", path, "it has no triangles"))?;
    let boxes: Vec<Aabb> = mesh.triangles().iter().map(|t| Aabb::from_points(*t)).collect();
    let build = median(
        (0..runs)
            .map(|_| {
                let start = Instant::now();
                std::hint::black_box(Bvh::build_in_groups(&boxes, LANES));
                start.elapsed().as_secs_f64()
            })
            .collect(),
    );
    println!(
        "{}: {} triangles, BVH of {} nodes built in {:.2} ms",
        path.display(),
        mesh.triangle_count(),
        mesh.bvh().node_count(),
        build * 1e3
    );
    let primary = primary_rays(&b);
    let incoherent = incoherent_rays(&b, primary.len());
    let light = b.center() + Vector::new(-0.6, 1.0, 0.8) * (b.max - b.min).length();
    let shadow: Vec<Ray> = primary
        .iter()
        .filter_map(|r| mesh.intersect(r, f32::INFINITY))
        .map(|info| {
            let start = spawn_point(info.ip, info.geometric_normal, info.error, light - info.ip);
            Ray::new(start, (light - start).normalize())
        })
        .collect();
    let dist = |r: &Ray| (light - r.start).length();
    let closest = |r: &Ray| mesh.intersect(r, f32::INFINITY).is_some();
    let any = |r: &Ray| mesh.intersects(r, dist(r));
    if let Some(dir) = dump {
        let file = dir.join(path.with_extension("rays").file_name().expect("a mesh file has a name"));
        let infinite = |_: &Ray| f32::INFINITY;
        dump_rays(
            &file,
            &mesh,
            [(&primary, &infinite, &closest), (&incoherent, &infinite, &closest), (&shadow, &dist, &any)],
        );
        println!("  rays written to {}", file.display());
    }
    for threads in [1, 2] {
        let p = measure(&primary, threads, runs, closest);
        let i = measure(&incoherent, threads, runs, closest);
        let s = measure(&shadow, threads, runs, any);
        println!("  {threads} thread(s): primary    {p}, {} of {} hit", p.count, primary.len());
        println!("  {threads} thread(s): incoherent {i}, {} of {} hit", i.count, incoherent.len());
        println!("  {threads} thread(s): shadow     {s}, {} of {} occluded", s.count, shadow.len());
    }
    Ok(())
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let meshes = match &args.mesh {
        Some(path) => vec![path.clone()],
        None => {
            let root = Path::new(env!("CARGO_MANIFEST_DIR"));
            let fine = root.join("target").join("teapot-100k.obj");
            if !fine.exists() {
                let write = |file: &mut std::io::BufWriter<_>| {
                    std::io::Write::write_all(file, lecture6::app::assets::teapot::obj(40).as_bytes())
                        .map_err(image::ImageError::IoError)
                };
                if let Err(e) = lecture6::files::output::save_atomically(&fine, write) {
                    eprintln!("mesh: error: {e}");
                    return std::process::ExitCode::from(2);
                }
            }
            vec![root.join("textures").join("teapot.obj"), fine]
        }
    };
    for path in &meshes {
        if let Err(e) = bench(path, args.runs.max(1), args.dump_rays.as_deref()) {
            eprintln!("mesh: error: {e}");
            return std::process::ExitCode::from(2);
        }
    }
    std::process::ExitCode::SUCCESS
}
