//! Progressive photon mapping (a step beyond the slides, the render setting `photon_passes`, whose first
//! choice, one pass, is the slide's photon map; docs/beyond-the-slides.md, "The progressive caustic"): the
//! probabilistic formulation of Knaus and Zwicker ("Progressive Photon Mapping: A Probabilistic Approach",
//! 2011).
//!
//! One photon map's caustic has an error that more photons shrink but do not remove: its estimate spreads
//! the photons over a disc, which blurs the caustic where its light changes fastest, and its photons share
//! one emission lattice, whose random shift comes from the seed. The progressive caustic renders the picture
//! in passes, each with a photon map of its own, traced with its own seed ([`pass_seed`]), and averages the
//! passes' pictures. Pass 1 is the plain estimate (the k nearest within the maximum radius). Pass i >= 2
//! gathers every photon within its own radius r_i of the shaded point, cone-filtered and normalised to that
//! disc, with r_(i+1)^2 = r_i^2 (i + alpha) / (i + 1) ([`radius_scale`], [`ALPHA`]): the discs shrink slowly
//! enough that each pass still finds photons, so the average's noise and its blur both go to zero.
//!
//! r_1, the radius the shrinking starts from, is each shaded point's own: the radius of the disc pass 1's
//! estimate uses at that point (through the k-th nearest photon of the first map, or the maximum radius where
//! fewer lie within it). A single global radius would be far wider than the k nearest's disc in the bright
//! focus, and would blur it for many passes. The first map stays alive through the passes to give it; a pass's
//! map lives only while its pass renders, so memory does not grow with the number of passes.

use super::*;
use crate::lesson::rng::key_of;
use crate::lesson::scene::Scene;
use std::sync::Arc;

/// Knaus and Zwicker's alpha: how much of a pass's disc's area the next pass keeps, (i + alpha) / (i + 1).
/// 2/3 is their choice for surfaces.
pub const ALPHA: f64 = 2.0 / 3.0;

/// The most passes a progressive caustic may be asked for.
pub const MAX_PHOTON_PASSES: u32 = 1 << 16;

/// Why more than one pass needs the step photon-grid.
pub const NEEDS_THE_GRID: &str = "more than one needs the step photon-grid (the slide's k-d tree finds the k nearest photons, not every photon within a pass's radius): add --step photon-grid";

/// Keeps the seeds of the passes apart from the seeds a user gives.
const PASS_KEY: u64 = 0x5050_4d5f_5041_5353;

/// The seed of pass `pass` (counted from 1) of a render seeded with `seed`: the seed itself for pass 1 (the
/// one-pass render is today's), a seed drawn from (seed, pass) for the others.
pub fn pass_seed(seed: u64, pass: u32) -> u64 {
    if pass <= 1 { seed } else { key_of(&[seed, PASS_KEY, pass as u64]) }
}

/// r_i / r_1 for pass `pass` (counted from 1): the square root of the product of (j + alpha) / (j + 1)
/// for j from 1 to pass - 1. It falls as pass^((alpha - 1) / 2): pass^(-1/6) for alpha = 2/3.
pub fn radius_scale(pass: u32) -> f32 {
    let area: f64 = (1..pass.max(1)).map(|j| (j as f64 + ALPHA) / (j as f64 + 1.0)).product();
    area.sqrt() as f32
}

impl PhotonMap {
    /// The photon map of pass `pass` (counted from 1) of a progressive caustic whose first pass's map is
    /// `first`, for a render seeded with `seed`: the scene's photons traced anew with [`pass_seed`], the
    /// estimate gathering within the pass's radius. `None` when the scene builds no map.
    pub fn build_pass(scene: &Scene, first: &Arc<PhotonMap>, seed: u64, pass: u32) -> Result<Option<PhotonMap>> {
        first.check_passes(pass)?;
        let Some(mut map) = PhotonMap::build(scene, pass_seed(seed, pass))? else {
            return Ok(None);
        };
        if pass > 1 {
            map.pass = Some(Pass { first: Arc::clone(first), area_scale: radius_scale(pass).powi(2) });
        }
        Ok(Some(map))
    }

    /// Refuses more than one pass of the slide's k-d tree, which finds the k nearest photons, not every photon
    /// within a radius (the number of passes is [`RenderSettings::check`](crate::lesson::render::RenderSettings::check)'s).
    pub fn check_passes(&self, passes: u32) -> Result<()> {
        match (passes > 1, &self.lookup) {
            (true, Lookup::KdTree(_)) => Err(Error::parameter("photon passes", passes, NEEDS_THE_GRID)),
            _ => Ok(()),
        }
    }

    /// A later pass's estimate at `p` (normal `n`): every photon of this map within r_i, r_i^2 the pass's
    /// share of r_1^2, the disc of the first map's estimate at `p`.
    pub(super) fn pass_irradiance(
        &self,
        grid: &PhotonGrid,
        pass: &Pass,
        p: Vector,
        n: Vector,
        recorder: Option<&mut dyn Recorder>,
    ) -> Color {
        // `build_pass` makes later passes of a grid's map only.
        let Lookup::Grid(first_grid) = &pass.first.lookup else {
            return Color::BLACK;
        };
        FOUND.with_borrow_mut(|found| {
            // Where the first map has no photon within the maximum radius, its disc is the maximum radius's.
            let first_r2 = pass.first.nearest_disc(first_grid, p, found).unwrap_or(self.max_radius * self.max_radius);
            let r2 = first_r2 * pass.area_scale;
            if r2 <= 0.0 {
                return Color::BLACK;
            }
            grid.within(p, r2, found);
            self.cone_filtered(found, n, r2, recorder)
        })
    }
}
