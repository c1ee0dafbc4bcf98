//! What a slide's technique computes at the point being shaded, told to an instrument that asks (the ray
//! tree of `--trace-pixel`, through [`crate::lesson::observer`]): the Fresnel texture's reflectance (slide
//! "Fresnel"), the texels a bitmap texture mixes and their weights (slide "Bitmap текстури"), the photons of
//! a photon map's estimate (slide "Photon Mapping").
//!
//! The technique's code says it with one call, [`record`], at the line where it has the values; with no
//! recorder (every render but one pixel's) the call is nothing: the values are not even put together.
//!
//! Not on the slides: the course's renderer shows none of this; it is what lets the ray tree say what the
//! topic computed at each hit.

use crate::lesson::color::Color;

/// One technique's values at the point being shaded.
#[derive(Clone, Debug, PartialEq)]
pub enum Topic {
    /// The Fresnel texture (slide "Fresnel"): the fraction of the light reflected where the ray meets the
    /// surface.
    Fresnel {
        /// The reflectance, 0 to 1: the texture's grey value.
        reflectance: f32,
        /// n1 / n2, the ratio of the indices on the ray's side and across the surface (below 1 entering).
        eta: f32,
        /// The cosine of the angle between the ray and the normal.
        cos: f32,
        /// The exact Fresnel equations, or Schlick's approximation (the slide's).
        exact: bool,
    },
    /// A bitmap's look-up (slide "Bitmap текстури"): where it read the image, and the texels it mixed.
    Texels {
        /// The coordinates it looked up, one image per unit (before wrapping).
        u: f32,
        /// See `u`.
        v: f32,
        /// The texels read: one (nearest, the slide's) or the four around the point (bilinear).
        texels: Vec<Texel>,
    },
    /// The photon map's estimate of the caustic light (slide "Photon Mapping").
    Photons {
        /// How many nearest photons the estimate asks for.
        k: usize,
        /// The radius of the disc the photons' power is spread over: through the farthest of the k nearest,
        /// or the largest radius when fewer lie within it.
        radius: f32,
        /// The largest distance at which photons count.
        max_radius: f32,
        /// The photons found (in no order).
        photons: Vec<PhotonSeen>,
    },
}

/// A texel a bitmap look-up read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texel {
    /// Its column (0 at the left) and row (0 at the top), after wrapping.
    pub x: usize,
    /// See `x`.
    pub y: usize,
    /// Its weight in the colour read: 1 for the nearest texel, the bilinear weights otherwise (they add up
    /// to 1).
    pub weight: f32,
    /// Its linear colour.
    pub color: Color,
}

/// A photon a photon map's estimate found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonSeen {
    /// Its index among the map's photons.
    pub index: usize,
    /// Its distance from the point being shaded.
    pub distance: f32,
    /// Its power.
    pub power: Color,
    /// How much its power counts: 1 on the slide, the cone filter's weight with the photon grid, 0 for a
    /// photon that arrived from the other side of the surface.
    pub weight: f32,
}

/// Whoever is told what a technique computed: the ray tree, through the observer hook.
pub trait Recorder {
    /// A technique computed `topic` at the point being shaded.
    fn record(&mut self, _topic: &Topic) {}
}

/// The record call of a technique: tells `recorder`, if there is one, what `topic` puts together; without
/// one, nothing is done.
#[inline(always)]
pub fn record(recorder: Option<&mut dyn Recorder>, topic: impl FnOnce() -> Topic) {
    if let Some(recorder) = recorder {
        recorder.record(&topic());
    }
}
