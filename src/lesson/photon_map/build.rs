//! Building a scene's photon map (slide "Photon Mapping"): photons shot from the lights through the scene
//! (the slide's in all directions, [`super::all_directions`], or aimed at the caustic casters with the step
//! [`Step::PhotonGrid`], [`super::Emitter`]), stored where they land, and the radius their estimate gathers
//! over. What needs the scene is here; the map and its estimate ([`PhotonMap`]) need none of it.

use super::*;
use crate::lesson::scene::Scene;
use crate::lesson::shader::Shader;

impl PhotonMap {
    /// Builds the scene's photon map as its `photons` settings and its steps say, on the current rayon
    /// pool: the slide's ([`all_directions`], a k-d tree) or, with [`Step::PhotonGrid`], photons aimed at the
    /// casters in a grid. `None` when the settings ask for no photons or the scene has nothing that casts
    /// caustics.
    pub fn build(scene: &Scene, seed: u64) -> Result<Option<PhotonMap>> {
        let settings = scene.photons;
        settings.check()?;
        if settings.count == 0 {
            return Ok(None);
        }
        let grid = scene.steps.has(Step::PhotonGrid);
        let start = Instant::now();
        let (photons, emitted) = if grid {
            let Some(emitter) = Emitter::new(scene, settings.count, seed) else {
                return Ok(None);
            };
            (trace_photons(&scene.prepared(), &emitter, seed), settings.count as u64)
        } else {
            let casters = scene.nodes.iter().any(|node| node.shader.caustic_caster().is_some());
            if !casters || scene.lights.is_empty() {
                return Ok(None);
            }
            all_directions::shoot_photons(&scene.prepared(), settings.count, seed)
        };
        let trace_time = start.elapsed();
        // A radius below the scene's floor cannot tell photons apart: refused when asked for, and the default
        // raised to it (only in a tiny scene far from the camera).
        let floor = min_radius(scene, &photons);
        let max_radius = match settings.max_radius {
            Some(r) if r < floor => {
                return Err(Error::parameter(
                    "photon radius",
                    format!("{r:e}"),
                    format!(
                        "below {floor:.3e}, the smallest this scene can resolve: its coordinates are 32-bit \
                         floats spaced about {:.1e} apart at its size",
                        floor / CELLS_PER_RADIUS
                    ),
                ));
            }
            Some(r) => r,
            None => default_radius(scene, &photons).max(floor),
        };
        let mut map = PhotonMap::with_lookup(photons, settings.k, max_radius, settings.show, grid)?;
        map.stats.emitted = emitted.min(u32::MAX as u64) as u32;
        map.stats.trace_time = trace_time;
        Ok(Some(map))
    }
}

impl Scene {
    /// Whether a photon map can add light to this scene: some node is a caustic caster (a mirror or glass,
    /// [`crate::lesson::shader::is_caustic_caster`]) and some light shines on it. A question about the
    /// scene's nodes and lights, not a setting: `photons.count` says whether the map is made.
    pub fn can_have_caustics(&self) -> bool {
        crate::lesson::photon_map::Emitter::new(self, 1, 0).is_some()
    }
}

/// The box around the scene's bounded objects (or, if none is bounded, around the photons).
fn scene_box(scene: &Scene, photons: &[StoredPhoton]) -> Aabb {
    let corners: Vec<Vector> = scene.nodes.iter().filter_map(|n| n.bounds()).flat_map(|b| [b.min, b.max]).collect();
    if corners.is_empty() { Aabb::from_points(photons.iter().map(|p| p.position)) } else { Aabb::from_points(corners) }
}

/// The smallest maximum radius a scene can use: four times (the grid's cells per radius) the spacing of
/// 32-bit floats at the scene's largest coordinate (its box's, see [`default_radius`]), so that a cell of the
/// photon grid is at least as wide as the rounding of the positions it sorts. A smaller radius could not
/// tell photons apart; `--radius 1e-20` is refused instead of building a grid of no use.
pub fn min_radius(scene: &Scene, photons: &[StoredPhoton]) -> f32 {
    let bounds = scene_box(scene, photons);
    let largest = bounds.min.abs().max(bounds.max.abs()).max_element();
    if largest.is_finite() { CELLS_PER_RADIUS * largest * f32::EPSILON } else { 0.0 }
}

/// The default maximum radius: 1/100 of the diagonal of the box around the scene's bounded objects (or, if
/// none is bounded, around the photons).
pub fn default_radius(scene: &Scene, photons: &[StoredPhoton]) -> f32 {
    let bounds = scene_box(scene, photons);
    let diagonal = (bounds.max - bounds.min).length();
    // A box of no size holds at most one point: any radius finds it.
    if diagonal.is_finite() && diagonal > 0.0 { diagonal / 100.0 } else { 1.0 }
}
