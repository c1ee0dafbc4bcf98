//! Caustics by photon mapping as the slides write it (slides "Photon Mapping", "Пример за photon map"):
//!
//! 1. many photons are shot from each lamp in all directions and followed through the mirrors and glass
//!    (each surface says what a photon does there: [`scatter_photon`]); those that land on a diffuse surface
//!    after at least one reflection or refraction are stored;
//! 2. the stored photons go into a structure that finds the k nearest neighbours of any point fast: a k-d
//!    tree ([`super::kd_tree`]);
//! 3. a diffuse surface adds the caustic light at a point from the k nearest photons: their power over the
//!    area of the disc that holds them.
//!
//! Chromatic caustics (the slide: every photon carries one wavelength): in a dispersive scene a photon
//! carries a wavelength of one of [`PHOTON_BANDS`] bands, drawn at random, and that band's colour.
//!
//! How many: the scene's photon count is the number of photons *stored*: the lamps shoot photons until the
//! map holds that many (Jensen's rule), or until they have shot [`MAX_BATCHES`] times as many, whichever
//! comes first. Photons carry the lamp's power over the number shot, so the estimate does not depend on
//! how many it took.

use super::kd_tree::KdTree;
use super::model_transform::{SlideNode, closest_hit, slide_nodes};
use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::math::Vector;
use crate::lesson::photon_map::{PHOTON_BANDS, PhotonStats, StoredPhoton, arriving_light, default_radius};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{RECURSION_SAFETY_CAP, Scene};
use crate::lesson::shader::{PhotonScatter, scatter_photon};
use crate::lesson::spectral::Band;
use rayon::prelude::*;
use std::f32::consts::PI;
use std::time::Instant;

/// The most batches of photons the lamps shoot while the map holds fewer than the scene asks for: a scene
/// whose mirrors and glass are tiny seen from the lamps stops there, with fewer photons.
pub const MAX_BATCHES: u32 = 64;

/// Keeps the photons' random streams apart from every other stream.
const PHOTON_STREAM: u64 = 0x534c_4944_4550_4830;

/// The caustic photon map of the slides' reading.
pub struct PhotonMap {
    photons: Vec<StoredPhoton>,
    tree: KdTree,
    k: usize,
    max_radius: f32,
    /// Photons shot and stored, and the time it took.
    pub stats: PhotonStats,
}

impl std::fmt::Debug for PhotonMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PhotonMap").field("stats", &self.stats).finish_non_exhaustive()
    }
}

impl PhotonMap {
    /// The scene's photon map, if its settings ask for photons and some mirror or glass is lit.
    pub fn build(scene: &Scene, seed: u64) -> Result<Option<PhotonMap>> {
        let settings = scene.photons;
        settings.check()?;
        let casters = scene.nodes.iter().any(|node| node.shader.caustic_caster().is_some());
        if settings.count == 0 || !casters || scene.lights.is_empty() {
            return Ok(None);
        }
        let start = Instant::now();
        let nodes = slide_nodes(&scene.nodes);
        let wanted = settings.count as usize;
        let mut photons = Vec::new();
        let mut shot = 0u64;
        for _ in 0..MAX_BATCHES {
            let batch = shot..shot + settings.count as u64;
            photons.par_extend(batch.into_par_iter().filter_map(|i| shoot(scene, &nodes, seed, i)));
            shot += settings.count as u64;
            if photons.len() >= wanted {
                break;
            }
        }
        for photon in &mut photons {
            photon.power = photon.power / shot as f32;
        }
        let trace_time = start.elapsed();
        let start = Instant::now();
        let tree = KdTree::new(photons.iter().map(|photon| photon.position));
        let max_radius = settings.max_radius.unwrap_or_else(|| default_radius(scene, &photons));
        let stats = PhotonStats {
            emitted: shot.min(u32::MAX as u64) as u32,
            stored: photons.len(),
            trace_time,
            build_time: start.elapsed(),
        };
        Ok(Some(PhotonMap { photons, tree, k: settings.k as usize, max_radius, stats }))
    }

    /// The stored photons.
    pub fn photons(&self) -> &[StoredPhoton] {
        &self.photons
    }

    /// The caustic irradiance at the point `p` of a diffuse surface whose normal `n` faces the viewer: the
    /// power of the k nearest photons within the maximum radius that arrived on this side of the surface,
    /// over the area of the disc through the farthest of them (the disc of the maximum radius when fewer
    /// than k lie within it).
    pub fn irradiance(&self, p: Vector, n: Vector) -> Color {
        let max_r2 = self.max_radius * self.max_radius;
        let found = self.tree.nearest(p, self.k, max_r2);
        let r2 = if found.len() < self.k { max_r2 } else { found.iter().fold(0.0, |m, (d2, _)| d2.max(m)) };
        if found.is_empty() || r2 <= 0.0 {
            return Color::BLACK;
        }
        let mut sum = Color::BLACK;
        for (_, i) in found {
            let photon = &self.photons[i as usize];
            if photon.dir.dot(n) < 0.0 {
                sum += photon.power;
            }
        }
        arriving_light(sum / (PI * r2))
    }
}

/// Shoots photon number `index`: from lamp `index % lamps`, in a random direction, carrying 4π times the
/// lamp's intensity times the number of lamps (divided by the photons shot once they are all shot). The
/// photon as stored, if it lands on a diffuse surface after a reflection or refraction.
fn shoot(scene: &Scene, nodes: &[SlideNode], seed: u64, index: u64) -> Option<StoredPhoton> {
    let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, index]);
    let light = &scene.lights[(index % scene.lights.len() as u64) as usize];
    let mut power = light.color * (light.intensity * 4.0 * PI * scene.lights.len() as f32);
    let mut ray = Ray::new(light.position, random_direction(&mut rng));
    if scene.is_dispersive() {
        let band = Band::nth(rng.below(PHOTON_BANDS), PHOTON_BANDS, scene.illuminant);
        ray.wavelength = Some(band.at(rng.next_f32()));
        power = power * band.color() * PHOTON_BANDS as f32;
    }
    loop {
        if ray.depth > scene.max_depth.min(RECURSION_SAFETY_CAP) {
            return None;
        }
        let (info, node) = closest_hit(nodes, &ray)?;
        match scatter_photon(&*node.shader, &ray, &info, &mut rng) {
            PhotonScatter::Land { scale } => {
                return (ray.depth > 0).then(|| StoredPhoton { position: info.ip, dir: ray.dir, power: power * scale });
            }
            PhotonScatter::Continue { dir, filter } => {
                power *= filter;
                ray = ray.spawn(&info, dir, filter.max_channel());
            }
            PhotonScatter::Absorb => return None,
        }
    }
}

/// A direction drawn uniformly from the whole sphere: a random height z in [-1, 1] and a random angle around
/// the z axis (Archimedes: equal heights of the sphere have equal areas).
fn random_direction(rng: &mut Rng) -> Vector {
    let z = 2.0 * rng.next_f32() - 1.0;
    let phi = 2.0 * PI * rng.next_f32();
    let r = (1.0 - z * z).max(0.0).sqrt();
    Vector::new(r * phi.cos(), r * phi.sin(), z)
}
