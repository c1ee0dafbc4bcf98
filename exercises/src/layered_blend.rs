//! # Exercise: a layer's weight in the blend (slides "Комбиниране на шейдъри", "Layered Shader")
//!
//! A Layered shader stacks shaders, listed from the bottom up, each with a blend colour: its opacity per
//! channel, 0 transparent, 1 opaque (the lacquer over wood: the wood is opaque, the lacquer faint). The
//! slide's `shade` blends them from the bottom up:
//!
//! ```text
//! Color res(0.0f, 0.0f, 0.0f);
//! for (int i = 0; i < nrLayers; i++) {
//!     ...
//!     res = res * (Color(1.0f, 1.0f, 1.0f) - blend) + color * blend;
//! }
//! ```
//!
//! The workbook walks the same layers **from the top down**, so that it can skip what cannot be seen (a
//! layer under an opaque one, a layer of zero blend): it keeps `uncovered`, how much of each channel the
//! layers above the current one let through (white above the top layer), shades a layer only if its weight
//! is not zero, adds `color * weight` to the result, and passes `uncovered * (1 - blend)` on to the layer
//! below. Write the weight: how much of the final colour a layer of opacity `blend` contributes, when the
//! layers above it let `uncovered` through.
//!
//! Hint: unroll the slide's loop for two layers, a bottom one (colour c1, blend b1) and a top one (c2, b2):
//! `res = (c1 * b1) * (1 - b2) + c2 * b2`. Which factor multiplies each colour?
//!
//! Facts the grader checks: the top-down weights give the slide's `res` for stacks of random layers; a
//! layer under an opaque one gets no weight; the weights and what is left uncovered add up to white (no
//! light made or lost); every channel is its own.
//!
//! Used by the Layered shader (the glass of the Fresnel slides, lacquer, masks); the grader renders
//! `layered`.

use crate::Color;

/// The weight in the final colour of a layer of opacity `blend`, when the layers above it let `uncovered`
/// through.
pub fn layer_weight(uncovered: Color, blend: Color) -> Color {
    todo!("layered_blend")
}
