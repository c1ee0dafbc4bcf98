//! Where the photons come from (slide "Photon Mapping": shoot photons from the lights): each light aims at the
//! caustic casters' bounding spheres, and every photon is followed through mirrors and glass until it lands on
//! a diffuse surface (see the module documentation of [`crate::lesson::photon_map`]).

use super::*;
use crate::lesson::color::Color;
use crate::lesson::math::{OrthonormalBasis, Vector};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::Scene;
use crate::lesson::shader::is_caustic_caster;
use crate::lesson::spectral::{Band, bands};
use rayon::prelude::*;
use std::f32::consts::PI;

/// The set of directions in which one light sees one caustic caster: the cone around its bounding sphere.
#[derive(Clone, Copy, Debug)]
struct Cone {
    light: usize,
    axis: OrthonormalBasis,
    /// 1 - cos of the half-angle, kept as such because the cone of a small, far caster is so narrow that
    /// the cosine itself rounds to 1.
    one_minus_cos: f32,
    solid_angle: f32,
    /// The power the light sends into the cone (the mean of its channels).
    power: f32,
    /// The photons emitted into it, numbered from `first`.
    first: u32,
    count: u32,
    /// A random shift of the cone's lattice, in [0, 1)^2, so that another seed gives other directions.
    shift: (f32, f32),
}

impl Cone {
    /// The cone from `light_pos` around the sphere (`center`, `radius`); all directions if the light is
    /// inside the sphere or the caster is unbounded (`None`).
    fn new(light: usize, light_pos: Vector, sphere: Option<(Vector, f32)>, intensity: f32) -> Cone {
        let (axis, one_minus_cos) = match sphere {
            Some((center, radius)) if (center - light_pos).length() > radius => {
                let d = (center - light_pos).length();
                let sin2 = (radius / d) * (radius / d);
                // 1 - cos = sin^2 / (1 + cos), without cancellation.
                (OrthonormalBasis::new((center - light_pos) / d), sin2 / (1.0 + (1.0 - sin2).sqrt()))
            }
            _ => (OrthonormalBasis::new(Vector::Y), 2.0),
        };
        let solid_angle = 2.0 * PI * one_minus_cos;
        Cone {
            light,
            axis,
            one_minus_cos,
            solid_angle,
            power: intensity * solid_angle,
            first: 0,
            count: 0,
            shift: (0.0, 0.0),
        }
    }

    /// Direction `j` of the cone's `count`: a spherical Fibonacci lattice, spread evenly over the cone's solid
    /// angle (equal steps of cos(theta), golden-ratio steps of the azimuth), shifted by `shift`. An even
    /// spread of photons gives a smoother caustic than independent random directions for the same count.
    fn direction(&self, j: u32) -> Vector {
        const GOLDEN: f64 = 0.618_033_988_749_894_8; // 1 / the golden ratio
        let t = ((j as f32 + self.shift.0) / self.count as f32) * self.one_minus_cos; // 1 - cos(theta)
        let cos = 1.0 - t;
        let sin = (t * (2.0 - t)).max(0.0).sqrt();
        let phi = 2.0 * PI * ((j as f64 * GOLDEN + self.shift.1 as f64).fract() as f32);
        self.axis.to_world(sin * phi.cos(), sin * phi.sin(), cos).normalize()
    }

    /// Whether the unit direction `dir` lies in the cone.
    fn contains(&self, dir: Vector) -> bool {
        // |dir - axis|^2 = 2 (1 - cos): no cancellation for narrow cones.
        0.5 * (dir - self.axis.normal).length_squared() <= self.one_minus_cos
    }
}

/// How much light a colour carries, for sharing photons between cones and choosing between layers: the mean
/// of its channels.
pub fn strength(c: Color) -> f32 {
    (c.r() + c.g() + c.b()) / 3.0
}

/// Where the photons come from: every (light, caustic caster) cone gets a share of the photons in
/// proportion to the power the light sends into it.
#[derive(Clone, Debug)]
pub struct Emitter {
    cones: Vec<Cone>,
    /// For a scene with dispersive materials, the bands of the photons' wavelengths; empty for white light.
    bands: Vec<Band>,
    /// The colour of the scene's light ([`crate::lesson::spectral::Illuminant::white`]), which the wavelength
    /// passes give the caustic estimate as they give every other light.
    white: Color,
}

impl Emitter {
    /// The emitter of `count` photons for a scene, or `None` when nothing can make a caustic: no caster, or
    /// no light.
    pub fn new(scene: &Scene, count: u32, seed: u64) -> Option<Emitter> {
        let spheres: Vec<Option<(Vector, f32)>> = scene
            .nodes
            .iter()
            .filter(|node| is_caustic_caster(&node.shader))
            .map(|node| node.bounds().map(|b| (b.center(), 0.5 * (b.max - b.min).length())))
            .collect();
        let mut cones = Vec::new();
        for (i, light) in scene.lights.iter().enumerate() {
            let intensity = strength(light.color) * light.intensity;
            if !(intensity > 0.0 && intensity.is_finite()) {
                continue;
            }
            cones.extend(spheres.iter().map(|&sphere| Cone::new(i, light.position, sphere, intensity)));
        }
        // A caster too small to see from the light (its cone's solid angle rounds to 0) gets no photons.
        cones.retain(|c| c.power > 0.0);
        if cones.is_empty() {
            return None;
        }
        let total: f64 = cones.iter().map(|c| c.power as f64).sum();
        // Each cone's share, rounded so that the shares add up to `count` (largest remainders).
        let exact: Vec<f64> = cones.iter().map(|c| c.power as f64 / total * count as f64).collect();
        let mut counts: Vec<u32> = exact.iter().map(|&e| e.floor() as u32).collect();
        let mut by_remainder: Vec<usize> = (0..cones.len()).collect();
        by_remainder.sort_by(|&a, &b| (exact[b] - exact[b].floor()).total_cmp(&(exact[a] - exact[a].floor())));
        let missing = count - counts.iter().sum::<u32>();
        by_remainder.iter().take(missing as usize).for_each(|&i| counts[i] += 1);
        let mut first = 0;
        for (k, (cone, n)) in cones.iter_mut().zip(counts).enumerate() {
            let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, u64::MAX - k as u64]);
            (cone.first, cone.count, cone.shift) = (first, n, (rng.next_f32(), rng.next_f32()));
            first += n;
        }
        let bands = if scene.is_dispersive() { bands(PHOTON_BANDS, scene.illuminant) } else { Vec::new() };
        let [r, g, b] = scene.illuminant.white();
        Some(Emitter { cones, bands, white: Color::new(r as f32, g as f32, b as f32) })
    }

    /// Photon number `index`: its ray from the light and its power. In a dispersive scene the photon gets a
    /// wavelength in one of the [`PHOTON_BANDS`] bands of the visible range, and carries the colour of its
    /// band times the number of bands, as a part of the light's colour (divided by it, channel by channel:
    /// the wavelength passes multiply the caustic estimate by the light's colour, as every light), so that
    /// together the photons are as white as the light.
    fn emit(&self, scene: &Scene, index: u32, rng: &mut Rng) -> (Ray, Color) {
        beyond!(PhotonGrid);
        let chosen = self.cones.partition_point(|c| c.first + c.count <= index);
        let cone = &self.cones[chosen];
        let dir = cone.direction(index - cone.first);
        // The light's intensity over the photon density in this direction, summed over all the light's
        // cones that contain it (cones may overlap; each photon then carries its share of the light once).
        let density = self
            .cones
            .iter()
            .enumerate()
            .filter(|&(j, c)| c.light == cone.light && (j == chosen || c.contains(dir)))
            .map(|(_, c)| c.count as f32 / c.solid_angle)
            .sum::<f32>();
        let light = &scene.lights[cone.light];
        let power = light.color * (light.intensity / density);
        if self.bands.is_empty() {
            return (Ray::new(light.position, dir), power);
        }
        // The bands are equal parts of the visible range. Photon j of a cone takes band j mod the number of
        // bands (shifted per cone), so every band gets its share of each cone's photons, evenly spread over
        // the cone, and a uniformly random wavelength within the band.
        let k = self.bands.len() as u32;
        let band = &self.bands[((index - cone.first + (cone.shift.0 * k as f32) as u32) % k) as usize];
        let ray = Ray { wavelength: Some(band.at(rng.next_f32())), ..Ray::new(light.position, dir) };
        let colour = Color(band.color().0 / self.white.0);
        (ray, power * colour * self.bands.len() as f32)
    }

    /// The photons emitted in all.
    pub fn count(&self) -> u32 {
        self.cones.iter().map(|c| c.count).sum()
    }
}

/// Follows photon number `index` from its light until it lands, is absorbed or leaves the scene; the photon
/// as stored, if it landed on a diffuse surface after a reflection or refraction.
fn trace_photon(scene: &Scene, emitter: &Emitter, seed: u64, index: u32) -> Option<StoredPhoton> {
    let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, index as u64]);
    let (ray, power) = emitter.emit(scene, index, &mut rng);
    super::all_directions::follow(scene, ray, power, &mut rng, true)
}

/// Emits the emitter's photons and traces them in parallel (on the current rayon pool); the stored ones, in
/// the order of their indices whatever the number of threads.
pub fn trace_photons(scene: &Scene, emitter: &Emitter, seed: u64) -> Vec<StoredPhoton> {
    (0..emitter.count()).into_par_iter().filter_map(|i| trace_photon(scene, emitter, seed, i)).collect()
}
