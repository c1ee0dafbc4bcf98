//! # Exercise: the caustic light from the nearest photons (slides "Caustics", "Photon Mapping")
//!
//! Photon mapping first shoots many photons from the lamps, follows them through mirrors and glass, and
//! stores where they land on diffuse surfaces. Then, the slide says:
//!
//! > we work as in classic ray tracing, but add the caustics when computing the lighting: we find the K
//! > nearest neighbours of the hit point in the photon map and, from the distances to them, compute how much
//! > light comes from the caustics.
//!
//! The workbook finds the nearest photons (at most k, within a maximum distance) and the radius r of the
//! disc they were gathered from; your function turns them into the light arriving per unit area (the
//! irradiance, which the course's diffuse shaders multiply by their colour, as they do a lamp's):
//!
//! - only photons that arrived on the side the normal faces count: `dot(photon.dir, normal) < 0` (a photon
//!   that landed on the other side of a thin wall does not light this one);
//! - the photons' power is spread over the disc's area, pi r^2. A plain sum over the area blurs sharp
//!   caustics; the workbook weights each photon with Jensen's *cone filter* instead, so nearer photons count
//!   more: a photon at distance d gets the weight `w = 1 - d / (k r)`, with `k = CONE_FILTER_K` (1.1), and
//!   the weighted sum is divided by the filter's own volume:
//!
//!   ```text
//!   E = sum(w * power) / ((1 - 2 / (3 k)) * pi * r^2)
//!   ```
//!
//! No photons give black. The photons come with their squared distance (take its square root for d), and
//! the disc with its squared radius.
//!
//! Facts the grader checks: no photons, no light; a photon at the centre counts fully and one from behind
//! not at all; the weights fall with distance as the cone filter says; photons spread evenly over the disc
//! give their total power over its area (the filter neither makes nor loses light); each channel is its own.
//!
//! Used by every diffuse shader in a scene with caustics; the grader renders `photon_map`.

use crate::{Color, Photon, Vector};

/// The caustic irradiance at a point with unit normal `normal` (facing the viewer), from the nearest
/// `photons`, gathered from a disc of squared radius `radius_squared`.
pub fn irradiance_estimate(photons: &[Photon], radius_squared: f32, normal: Vector) -> Color {
    todo!("photon_estimate")
}
