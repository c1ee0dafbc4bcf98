//! An independent reference for the caustic of the `photon_map` example: a light tracer that follows photons
//! from the lamp through the glass ball to the floor and bins their power in rings around the caustic's
//! centre, with no gathering radius at all. It shares none of the renderer's code (its own sphere and plane
//! intersection, Snell's law, Fresnel term and random numbers, in 64-bit floats), so it cannot share the
//! renderer's bugs; `benches/caustic_rings.rs` measures the renderer's photon map on the same rings against it.
//!
//! ```sh
//! cargo bench --bench caustic_reference                        # writes benches/results/caustic_reference.tsv
//! cargo bench --bench caustic_reference -- --photons 20000000  # a quick look (to target/)
//! ```
//!
//! The scene is the example's (`examples/photon_map.rs`), written out here as numbers: a point lamp of
//! intensity 20000 at (5, 120, 95), white; a glass ball of radius 12 at (-22, 19, 20), index 1.5, both of its
//! layers passing all the light (multiplier 1); the floor y = 0, |x|, |z| < 150; at most 6 reflections or
//! refractions before a photon lands (the scene's `max_depth`). The glass is the slides' Fresnel glass: a
//! refraction layer under a mirror layer blended by Schlick's approximation, which at each hit sends a
//! photon on by reflection with the probability R (Schlick's reflectance, with the cosine of the
//! transmitted angle when leaving the glass, and 1 under total internal reflection) and by refraction
//! otherwise, its power unchanged. This tracer does the same physics: R = r0 + (1 - r0)(1 - cos)^5 with
//! r0 = ((n1 - n2) / (n1 + n2))^2, the same choice with that probability.
//!
//! The low wall and the small mirror of the example are left out: they cannot lie on the path of a photon
//! that reaches a ring. Every such path ends with a straight segment from the ball to the floor inside the
//! rings' disc, so it stays within the box around the ball and the disc, and the program checks that this box
//! lies in front of the wall (z < 70) and to the left of the mirror (x < 28 - its half-diagonal).
//!
//! Photons leave the lamp in directions uniformly distributed over the cone of directions in which it sees
//! the ball, each carrying the lamp's intensity times the cone's solid angle over the number of photons.
//! The rings are 0.02 wide, centred on the point where the line from the lamp through the ball's centre
//! meets the floor: the ball and the lamp are symmetric about that line, so the caustic's focus lies on it.
//! Each ring's value is irradiance, the photons' power per unit area of the ring, as the photon map's
//! estimate is. The photons are traced in independent batches; a ring's value is the mean of the batches'
//! and its standard error is their standard deviation over the square root of their number. The batches
//! run in parallel (rayon), each from its own random stream, and count integers: the output is the same
//! for any thread count.

mod common;

use clap::Parser;
use rand_core::{RngCore, SeedableRng};
use rand_pcg::Pcg64Mcg;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// A point or a direction in 64-bit floats.
#[derive(Clone, Copy, Debug, PartialEq)]
struct V3 {
    x: f64,
    y: f64,
    z: f64,
}

const fn v3(x: f64, y: f64, z: f64) -> V3 {
    V3 { x, y, z }
}

impl V3 {
    fn add(self, o: V3) -> V3 {
        v3(self.x + o.x, self.y + o.y, self.z + o.z)
    }
    fn sub(self, o: V3) -> V3 {
        v3(self.x - o.x, self.y - o.y, self.z - o.z)
    }
    fn scale(self, s: f64) -> V3 {
        v3(self.x * s, self.y * s, self.z * s)
    }
    fn dot(self, o: V3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    fn cross(self, o: V3) -> V3 {
        v3(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }
    fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    fn unit(self) -> V3 {
        self.scale(1.0 / self.length())
    }
}

/// The example's lamp, its intensity, the glass ball and its index, and the floor's half side.
const LAMP: V3 = v3(5.0, 120.0, 95.0);
const INTENSITY: f64 = 20000.0;
const BALL: V3 = v3(-22.0, 19.0, 20.0);
const RADIUS: f64 = 12.0;
const IOR: f64 = 1.5;
const FLOOR_HALF_SIDE: f64 = 150.0;
/// The most reflections and refractions before a photon lands (the example's `max_depth`).
const MAX_BOUNCES: u32 = 6;
/// What must not lie in the way: the face of the low wall, and the mirror's centre and half-diagonal
/// (a square of half side 4).
const WALL_Z: f64 = 70.0;
const MIRROR_X: f64 = 28.0;
const MIRROR_HALF_DIAGONAL: f64 = 4.0 * std::f64::consts::SQRT_2;

/// The rings' width.
const RING_WIDTH: f64 = 0.02;

#[derive(Parser)]
struct Args {
    /// Photons traced in all, shared equally by the batches.
    #[arg(long, default_value_t = 2_560_000_000)]
    photons: u64,
    /// Independent batches, for the standard error.
    #[arg(long, default_value_t = 32)]
    batches: u64,
    /// Rings of 0.02 from the centre; by default out to the caustic's edge (see [`shadow_edge`]).
    #[arg(long)]
    rings: Option<usize>,
    /// The random streams' seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Where the ring values go; by default benches/results/caustic_reference.tsv for the default photon
    /// count, target/caustic_reference.tsv for any other.
    #[arg(long)]
    out: Option<PathBuf>,
    /// `cargo bench` passes it.
    #[arg(long, hide = true)]
    bench: bool,
}

/// Where the line from the lamp through the ball's centre meets the floor.
fn centre() -> V3 {
    let axis = BALL.sub(LAMP);
    LAMP.add(axis.scale(-LAMP.y / axis.y))
}

/// The caustic's edge: the distance from the centre to the nearest point of the edge of the ball's shadow
/// on the floor. The light the ball refracts falls around its shadow's centre and fades out towards the
/// shadow's edge; every ring inside it lies within the caustic in every direction. The shadow's edge is
/// where the lamp's rays that graze the ball meet the floor (an ellipse, the floor being oblique to the
/// cone), found by following 3600 of them around the cone.
fn shadow_edge() -> f64 {
    let (cone, centre) = (Cone::new(), centre());
    let sin = (1.0 - cone.cos_max * cone.cos_max).sqrt();
    (0..3600)
        .map(|i| {
            let phi = 2.0 * PI * i as f64 / 3600.0;
            let d = cone
                .axis
                .scale(cone.cos_max)
                .add(cone.across.0.scale(sin * phi.cos()))
                .add(cone.across.1.scale(sin * phi.sin()));
            let at = LAMP.add(d.scale(-LAMP.y / d.y));
            (at.x - centre.x).hypot(at.z - centre.z)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Schlick's reflectance of the glass for a photon meeting it at cosine `cos_in` (against the normal on
/// its own side), going from index `n1` to `n2`; 1 under total internal reflection.
fn schlick(cos_in: f64, n1: f64, n2: f64) -> f64 {
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    let sin_out2 = (n1 / n2).powi(2) * (1.0 - cos_in * cos_in);
    if sin_out2 >= 1.0 {
        return 1.0;
    }
    let cos = if n1 > n2 { (1.0 - sin_out2).sqrt() } else { cos_in };
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

/// Snell's law: the direction of a photon travelling along the unit `d` after it crosses a surface of unit
/// normal `n` (on the photon's side) from index `n1` to `n2`, written as the sum of its part along the
/// surface (the incoming part scaled by n1/n2) and its part along the normal. `None` under total internal
/// reflection.
fn snell(d: V3, n: V3, n1: f64, n2: f64) -> Option<V3> {
    let along = d.sub(n.scale(d.dot(n))).scale(n1 / n2);
    let across2 = 1.0 - along.dot(along);
    (across2 >= 0.0).then(|| along.sub(n.scale(across2.sqrt())).unit())
}

/// The mirror direction of `d` about the unit normal `n`.
fn mirror(d: V3, n: V3) -> V3 {
    d.sub(n.scale(2.0 * d.dot(n)))
}

/// A uniform number in [0, 1) from 53 random bits.
fn uniform(rng: &mut Pcg64Mcg) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// The lamp's cone of directions towards the ball: its axis, two unit vectors across it, and the cosine of
/// its half-angle.
struct Cone {
    axis: V3,
    across: (V3, V3),
    cos_max: f64,
}

impl Cone {
    fn new() -> Cone {
        let to_ball = BALL.sub(LAMP);
        let axis = to_ball.unit();
        let sin = RADIUS / to_ball.length();
        let first = axis.cross(if axis.x.abs() < 0.9 { v3(1.0, 0.0, 0.0) } else { v3(0.0, 1.0, 0.0) }).unit();
        Cone { axis, across: (first, axis.cross(first)), cos_max: (1.0 - sin * sin).sqrt() }
    }

    fn solid_angle(&self) -> f64 {
        2.0 * PI * (1.0 - self.cos_max)
    }

    /// A direction uniformly distributed over the cone: cos(theta) uniform in [cos_max, 1] (equal bands of a
    /// sphere have equal areas), the angle around the axis uniform.
    fn sample(&self, rng: &mut Pcg64Mcg) -> V3 {
        let cos = 1.0 - uniform(rng) * (1.0 - self.cos_max);
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let phi = 2.0 * PI * uniform(rng);
        self.axis.scale(cos).add(self.across.0.scale(sin * phi.cos())).add(self.across.1.scale(sin * phi.sin()))
    }
}

/// The distance along the unit `d` from `o` (outside the ball) to the ball, if the ray meets it.
fn hit_ball_from_outside(o: V3, d: V3) -> Option<f64> {
    let oc = o.sub(BALL);
    let b = oc.dot(d);
    let c = oc.dot(oc) - RADIUS * RADIUS;
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    // The nearer root, written without cancellation: c / (-b + sqrt(disc)).
    let t = c / (-b + disc.sqrt());
    (t > 0.0).then_some(t)
}

/// A point of the ball's surface: `p` put back on it exactly, and the outward normal there.
fn on_ball(p: V3) -> (V3, V3) {
    let n = p.sub(BALL).unit();
    (BALL.add(n.scale(RADIUS)), n)
}

/// Follows one photon from the lamp in the direction `d`: where it lands on the floor (x, z), if it landed
/// after at least one reflection or refraction, within `MAX_BOUNCES` of them.
fn trace(d: V3, rng: &mut Pcg64Mcg) -> Option<(f64, f64)> {
    let t = hit_ball_from_outside(LAMP, d)?;
    let (mut p, mut n) = on_ball(LAMP.add(d.scale(t)));
    let mut d = d;
    let mut inside = false;
    for bounce in 1..=MAX_BOUNCES {
        // At a hit of the ball: n is the outward normal, d arrives.
        let (n_side, n1, n2) = if inside { (n.scale(-1.0), IOR, 1.0) } else { (n, 1.0, IOR) };
        let reflect = uniform(rng) < schlick(-d.dot(n_side), n1, n2);
        d = match reflect {
            true => mirror(d, n_side),
            false => {
                inside = !inside;
                snell(d, n_side, n1, n2).expect("refracted: not under total internal reflection")
            }
        };
        if !inside {
            // Out of a convex ball, the photon never meets it again: it lands on the floor or leaves.
            if d.y >= 0.0 {
                return None;
            }
            let at = p.add(d.scale(-p.y / d.y));
            return (at.x.abs() < FLOOR_HALF_SIDE && at.z.abs() < FLOOR_HALF_SIDE).then_some((at.x, at.z));
        }
        if bounce == MAX_BOUNCES {
            break;
        }
        // Inside, from a point of the surface, the next hit is across the chord: at the distance -2 d.(p - c).
        (p, n) = on_ball(p.add(d.scale(-2.0 * d.dot(p.sub(BALL)))));
    }
    None
}

/// Traces `photons` photons of one random stream and counts those landing in each ring around `centre`.
fn trace_batch(photons: u64, seed: u64, stream: u64, rings: usize, centre: V3) -> Vec<u64> {
    let mut rng = Pcg64Mcg::seed_from_u64(seed ^ stream.wrapping_mul(0x9e37_79b9_7f4a_7c15));
    let cone = Cone::new();
    let mut counts = vec![0u64; rings];
    for _ in 0..photons {
        let Some((x, z)) = trace(cone.sample(&mut rng), &mut rng) else { continue };
        let ring = ((x - centre.x).hypot(z - centre.z) / RING_WIDTH) as usize;
        if let Some(count) = counts.get_mut(ring) {
            *count += 1;
        }
    }
    counts
}

/// Streams of this many photons make up a batch, so that both cores share a batch's work.
const CHUNK: u64 = 1 << 22;

fn main() {
    let args = Args::parse();
    let edge = shadow_edge();
    let rings = args.rings.unwrap_or((edge / RING_WIDTH) as usize);
    assert!(args.batches >= 2 && args.photons >= args.batches && rings > 0, "at least 2 batches of photons, 1 ring");
    let centre = centre();
    let outer = rings as f64 * RING_WIDTH;
    // The box around the ball and the rings' disc holds every last segment of a photon landing in a ring.
    let box_max_x = (BALL.x + RADIUS).max(centre.x + outer);
    let box_max_z = (BALL.z + RADIUS).max(centre.z + outer);
    assert!(
        box_max_z < WALL_Z && box_max_x < MIRROR_X - MIRROR_HALF_DIAGONAL,
        "the rings reach the wall or the mirror"
    );

    let per_batch = args.photons / args.batches;
    let chunks = per_batch.div_ceil(CHUNK);
    let start = Instant::now();
    let cpu_start = common::cpu_time();
    let counts: Vec<Vec<u64>> = (0..args.batches * chunks)
        .into_par_iter()
        .map(|job| {
            let (batch, chunk) = (job / chunks, job % chunks);
            let photons = CHUNK.min(per_batch - chunk * CHUNK);
            trace_batch(photons, args.seed, batch * chunks + chunk, rings, centre)
        })
        .collect();
    let wall = start.elapsed().as_secs_f64();
    let cpu = match (common::cpu_time(), cpu_start) {
        (Some(end), Some(start)) => format!("{:.1}", (end - start).as_secs_f64()),
        _ => "unknown".to_string(),
    };

    // Irradiance per batch and ring: the photons' power over the ring's area.
    let power = INTENSITY * Cone::new().solid_angle() / per_batch as f64;
    let ring_area = |i: usize| PI * RING_WIDTH * RING_WIDTH * (((i + 1) * (i + 1) - i * i) as f64);
    let batches = args.batches as f64;
    let mut table = String::new();
    let command = format!(
        "cargo bench --bench caustic_reference -- --photons {} --batches {} --rings {rings} --seed {}",
        args.photons, args.batches, args.seed
    );
    writeln!(table, "# {command}").unwrap();
    writeln!(
        table,
        "# the photon_map example's caustic, irradiance in rings {RING_WIDTH} wide around the centre \
         below, out to {outer:.2} (the nearest point of the edge of the ball's shadow: {edge:.3}): {} photons \
         in {} batches, {wall:.0} s wall, {cpu} s CPU",
        per_batch * args.batches,
        args.batches
    )
    .unwrap();
    writeln!(table, "# centre {:.9} 0 {:.9}", centre.x, centre.z).unwrap();
    writeln!(table, "inner\touter\tirradiance\tstandard_error").unwrap();
    let mut worst = (0.0, 0);
    let mut landed = 0u64;
    for ring in 0..rings {
        let values: Vec<f64> = (0..args.batches as usize)
            .map(|b| {
                let count: u64 = counts[b * chunks as usize..(b + 1) * chunks as usize].iter().map(|c| c[ring]).sum();
                landed += count;
                count as f64 * power / ring_area(ring)
            })
            .collect();
        let mean = values.iter().sum::<f64>() / batches;
        let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (batches - 1.0);
        let error = (variance / batches).sqrt();
        if error / mean > worst.0 {
            worst = (error / mean, ring);
        }
        let (inner, outer) = (ring as f64 * RING_WIDTH, (ring + 1) as f64 * RING_WIDTH);
        writeln!(table, "{inner:.2}\t{outer:.2}\t{mean:.6e}\t{error:.3e}").unwrap();
    }
    print!("{table}");
    println!(
        "{landed} photons landed in the rings; largest relative standard error {:.3}% (ring {}); {wall:.1} s wall, \
         {cpu} s CPU",
        100.0 * worst.0,
        worst.1
    );

    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let default = Args::parse_from(["caustic_reference"]);
    let path = args.out.unwrap_or_else(|| match (args.photons, args.batches, args.rings, args.seed) {
        p if p == (default.photons, default.batches, default.rings, default.seed) => {
            root.join("benches/results/caustic_reference.tsv")
        }
        _ => root.join("target/caustic_reference.tsv"),
    });
    std::fs::write(&path, table).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    eprintln!("wrote {}", path.display());
}
