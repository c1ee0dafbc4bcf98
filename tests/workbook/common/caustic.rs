//! The caustic of the `photon_map` example measured in rings, against the independent light tracer's rings
//! (`benches/caustic_reference.rs`, its values in `benches/results/caustic_reference.tsv`): reading the
//! reference, and the same rings measured on the renderer's photon map, by its estimate or by binning its
//! photons. Shared by the test `caustic_reference` and the bench `caustic_rings`.

use lecture6::lesson::math::Vector;
use lecture6::lesson::photon_map::{PhotonMap, StoredPhoton};
use lecture6::lesson::scene::Scene;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::path::Path;
use std::sync::Arc;

/// The committed reference's file, from the package root.
pub const REFERENCE: &str = "benches/results/caustic_reference.tsv";

/// One ring of the reference: its radii and the irradiance in it, with the standard error of that value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ring {
    pub inner: f64,
    pub outer: f64,
    pub irradiance: f64,
    pub standard_error: f64,
}

impl Ring {
    fn area(&self) -> f64 {
        PI * (self.outer * self.outer - self.inner * self.inner)
    }
}

/// The reference: the rings around the caustic's centre on the floor (x, z), in world coordinates.
#[derive(Clone, Debug)]
pub struct Reference {
    pub centre: (f64, f64),
    pub rings: Vec<Ring>,
}

/// Reads the reference: a `# centre X Y Z` line, then after the column names one ring per line (inner and
/// outer radius, irradiance, standard error), tab-separated.
pub fn read_reference(path: &Path) -> Reference {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let number = |s: &str, line: usize| -> f64 {
        s.trim().parse().unwrap_or_else(|e| panic!("{}:{line}: {s:?}: {e}", path.display()))
    };
    let mut centre = None;
    let mut rings = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if let Some(rest) = line.strip_prefix("# centre") {
            let xyz: Vec<f64> = rest.split_whitespace().map(|s| number(s, i + 1)).collect();
            centre = Some((xyz[0], xyz[2]));
        } else if !line.starts_with('#') && !line.starts_with("inner") {
            let v: Vec<f64> = line.split('\t').map(|s| number(s, i + 1)).collect();
            assert_eq!(v.len(), 4, "{}:{}: four columns", path.display(), i + 1);
            rings.push(Ring { inner: v[0], outer: v[1], irradiance: v[2], standard_error: v[3] });
        }
    }
    Reference { centre: centre.unwrap_or_else(|| panic!("{}: no `# centre` line", path.display())), rings }
}

/// Points of a ring spread evenly over its area, about `spacing` apart along its circles: two circles at
/// the radii that halve its area twice, each starting at its own angle (golden-ratio steps).
fn ring_points(ring: &Ring, index: usize, spacing: f64) -> Vec<(f64, f64)> {
    const GOLDEN: f64 = 0.618_033_988_749_894_8;
    let mut points = Vec::new();
    for stratum in 0..2 {
        let fraction = (stratum as f64 + 0.5) / 2.0;
        let r = (ring.inner * ring.inner + fraction * (ring.outer * ring.outer - ring.inner * ring.inner)).sqrt();
        let count = ((2.0 * PI * r / spacing).ceil() as usize).max(8);
        let start = ((2 * index + stratum) as f64 * GOLDEN).fract();
        points.extend((0..count).map(|j| {
            let angle = 2.0 * PI * (start + j as f64 / count as f64);
            (r * angle.cos(), r * angle.sin())
        }));
    }
    points
}

/// The renderer's caustic on the reference's rings: the map's estimate (the floor's normal, up) averaged
/// over points spread evenly over each ring's area, about `spacing` apart. `scene` is the scene the map was
/// built for (its coordinates may be the camera's).
pub fn estimated_rings(map: &PhotonMap, scene: &Scene, reference: &Reference, spacing: f64) -> Vec<f64> {
    let origin = scene.world_position(Vector::ZERO);
    let (cx, cz) = reference.centre;
    reference
        .rings
        .par_iter()
        .enumerate()
        .map(|(i, ring)| {
            let points = ring_points(ring, i, spacing);
            let sum: f64 = points
                .iter()
                .map(|&(x, z)| {
                    let p = Vector::new((cx + x) as f32, 0.0, (cz + z) as f32) - origin;
                    let e = map.irradiance(p, Vector::Y);
                    (e.r() + e.g() + e.b()) as f64 / 3.0
                })
                .sum();
            sum / points.len() as f64
        })
        .collect()
}

/// The progressive caustic on the reference's rings: the mean over `passes` passes of each pass's estimate
/// ([`estimated_rings`]), pass 1 the map of `seed`, the others their own maps
/// ([`PhotonMap::build_pass`]), one at a time, as a render of `--photon-passes` builds them.
pub fn progressive_rings(scene: &Scene, reference: &Reference, passes: u32, seed: u64, spacing: f64) -> Vec<f64> {
    let first = Arc::new(PhotonMap::build(scene, seed).expect("valid settings").expect("the glass casts a caustic"));
    let mut sum = estimated_rings(&first, scene, reference, spacing);
    for pass in 2..=passes {
        let map = PhotonMap::build_pass(scene, &first, seed, pass).expect("valid settings").expect("a caustic");
        let values = estimated_rings(&map, scene, reference, spacing);
        sum.iter_mut().zip(values).for_each(|(s, v)| *s += v);
    }
    sum.iter().map(|s| s / passes as f64).collect()
}

/// The renderer's photons binned in the reference's rings, with no gathering at all: the power of the
/// photons that landed on the floor in each ring over its area.
pub fn binned_rings(photons: &[StoredPhoton], scene: &Scene, reference: &Reference) -> Vec<f64> {
    let origin = scene.world_position(Vector::ZERO);
    let (cx, cz) = reference.centre;
    let width = reference.rings[0].outer - reference.rings[0].inner;
    let mut power = vec![0.0; reference.rings.len()];
    for photon in photons.iter().filter(|p| p.dir.y < 0.0) {
        // Within the rings' disc, seen from above, photons land on the floor only (the wall stands far behind).
        let p = photon.position + origin;
        let ring = ((p.x as f64 - cx).hypot(p.z as f64 - cz) / width) as usize;
        if let Some(sum) = power.get_mut(ring) {
            *sum += (photon.power.r() + photon.power.g() + photon.power.b()) as f64 / 3.0;
        }
    }
    power.iter().zip(&reference.rings).map(|(p, ring)| p / ring.area()).collect()
}

/// Each ring's relative error against the reference.
pub fn relative_errors(values: &[f64], reference: &Reference) -> Vec<f64> {
    values.iter().zip(&reference.rings).map(|(v, ring)| v / ring.irradiance - 1.0).collect()
}
