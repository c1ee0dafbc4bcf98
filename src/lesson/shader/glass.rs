//! The glass of the slide "Let's build a Fresnel Shader (with layers!)": a refraction layer at the bottom and
//! a reflection layer on top whose blend is the [`Fresnel`] texture, so the two share the light as the
//! Fresnel equations say: little reflection where the glass faces the viewer, much at grazing angles, and
//! all of it under total internal reflection (where the Fresnel texture gives 1).

use super::{Layered, Reflection, Refraction};
use crate::lesson::color::Color;
use crate::lesson::spectral::Ior;
use crate::lesson::texture::{Fresnel, FresnelMode};
use std::sync::Arc;

/// Fresnel glass of index `ior` (a number, or a dispersive [`Ior`]), its reflectance by `mode` (Schlick's
/// approximation, as on the slide, or the exact equations), and both layers passing the fraction
/// `multiplier` of the light (1 is clear glass).
pub fn fresnel_glass(ior: impl Into<Ior>, mode: FresnelMode, multiplier: f32) -> Layered {
    let ior = ior.into();
    let mut glass = Layered::new();
    glass.add_layer(Refraction::with_ior(ior, multiplier), Color::WHITE, None);
    glass.add_layer(Reflection::new(multiplier), Color::WHITE, Some(Arc::new(Fresnel::with_ior(ior, mode))));
    glass
}
