//! Photons as the slides shoot them (slides "Photon Mapping", "Пример за photon map"), the map's first choice
//! (without the step [`Step::PhotonGrid`](crate::lesson::beyond::Step::PhotonGrid)):
//!
//! 1. many photons are shot from each lamp in all directions and followed through the mirrors and glass
//!    (each surface says what a photon does there: [`scatter_photon`]); those that land on a diffuse surface
//!    after at least one reflection or refraction are stored;
//! 2. the stored photons go into a structure that finds the k nearest neighbours of any point fast: a k-d
//!    tree ([`super::kd_tree`]), which [`super::PhotonMap::irradiance`] asks.
//!
//! Chromatic caustics (the slide: every photon carries one wavelength): in a dispersive scene a photon
//! carries a wavelength of one of [`PHOTON_BANDS`] bands, drawn at random, and that band's colour.
//!
//! How many: the scene's photon count is the number of photons *stored*: the lamps shoot photons until the
//! map holds that many (Jensen's rule), or until they have shot [`MAX_BATCHES`] times as many, whichever
//! comes first. Photons carry the lamp's power over the number shot, so the estimate does not depend on
//! how many it took.

use super::{PHOTON_BANDS, StoredPhoton};
use crate::lesson::color::Color;
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{RECURSION_SAFETY_CAP, Scene};
use crate::lesson::shader::{PhotonScatter, scatter_photon};
use crate::lesson::spectral::Band;
use rayon::prelude::*;
use std::f32::consts::PI;

/// The most batches of photons the lamps shoot while the map holds fewer than the scene asks for: a scene
/// whose mirrors and glass are tiny seen from the lamps stops there, with fewer photons.
pub const MAX_BATCHES: u32 = 64;

/// Keeps the photons' random streams apart from every other stream.
const PHOTON_STREAM: u64 = 0x534c_4944_4550_4830;

/// Shoots photons from the lamps in all directions until `count` are stored (or [`MAX_BATCHES`] times that
/// many are shot), on the current rayon pool: the stored photons, in the order of their indices whatever the
/// number of threads, and how many were shot.
pub fn shoot_photons(scene: &Scene, count: u32, seed: u64) -> (Vec<StoredPhoton>, u64) {
    let mut photons = Vec::new();
    let mut shot = 0u64;
    let dispersive = scene.is_dispersive();
    for _ in 0..MAX_BATCHES {
        let batch = shot..shot + count as u64;
        photons.par_extend(batch.into_par_iter().filter_map(|i| shoot(scene, dispersive, seed, i)));
        shot += count as u64;
        if photons.len() >= count as usize {
            break;
        }
    }
    for photon in &mut photons {
        photon.power = photon.power / shot as f32;
    }
    (photons, shot)
}

/// Shoots photon number `index`: from lamp `index % lamps`, in a random direction, carrying 4π times the
/// lamp's intensity times the number of lamps (divided by the photons shot once they are all shot). The
/// photon as stored, if it lands on a diffuse surface after a reflection or refraction. A photon of a
/// `dispersive` scene carries a wavelength.
fn shoot(scene: &Scene, dispersive: bool, seed: u64, index: u64) -> Option<StoredPhoton> {
    let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, index]);
    let light = &scene.lights[(index % scene.lights.len() as u64) as usize];
    let mut power = light.color * (light.intensity * 4.0 * PI * scene.lights.len() as f32);
    let mut ray = Ray::new(light.position, random_direction(&mut rng));
    if dispersive {
        let band = Band::nth(rng.below(PHOTON_BANDS), PHOTON_BANDS, scene.illuminant);
        ray.wavelength = Some(band.at(rng.next_f32()));
        power = power * band.color() * PHOTON_BANDS as f32;
    }
    follow(scene, ray, power, &mut rng, false)
}

/// Follows a photon sent along `ray` with `power` through the mirrors and glass (each surface says what a
/// photon does there: [`scatter_photon`]) until it lands on a diffuse surface, is absorbed or passes the
/// scene's depth limit: the photon as stored, if it landed after at least one reflection or refraction. With
/// `roulette` (Russian roulette, part of the step [`Step::PhotonGrid`](crate::lesson::beyond::Step::PhotonGrid))
/// a bounce lets it go on with the probability of its colour's largest channel, its power divided by that.
pub(crate) fn follow(
    scene: &Scene,
    mut ray: Ray,
    mut power: Color,
    rng: &mut Rng,
    roulette: bool,
) -> Option<StoredPhoton> {
    loop {
        if ray.depth > scene.max_depth.min(RECURSION_SAFETY_CAP) {
            return None;
        }
        let (info, node) = scene.closest_hit(&ray)?;
        match scatter_photon(&node.shader, &ray, &info, rng) {
            PhotonScatter::Land { scale } => {
                return (ray.depth > 0).then(|| StoredPhoton { position: info.ip, dir: ray.dir, power: power * scale });
            }
            PhotonScatter::Continue { dir, filter } => {
                let survival = if roulette { filter.max_channel().min(1.0) } else { 1.0 };
                if roulette && (survival.is_nan() || rng.next_f32() >= survival) {
                    return None;
                }
                power = power * filter / survival;
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
