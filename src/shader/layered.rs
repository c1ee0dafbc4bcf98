//! `Layered` (slides "Комбиниране на шейдъри", "Layered Shader"): a surface made of layers, listed bottom to
//! top, each with its own shader and a blend colour (per-channel opacity: 0 transparent, 1 opaque), optionally
//! multiplied by a blend texture. The slide's loop is
//!
//! ```text
//! res = 0;  for each layer, bottom to top:  res = res * (1 - blend) + layer_color * blend
//! ```
//!
//! which gives layer i the weight `blend_i * (1 - blend_{i+1}) * ... * (1 - blend_top)`. This shader computes
//! those weights first, from the top down, and then shades only the layers whose weight is not zero: a layer
//! with zero blend at this point costs nothing, and under an opaque layer nothing is shaded at all. The
//! result is the slide's, without the work the picture cannot show.

use super::Shader;
use crate::color::Color;
use crate::geometry::IntersectionInfo;
use crate::ray::Ray;
use crate::scene::TraceContext;
use crate::texture::Texture;
use std::sync::Arc;

#[derive(Clone)]
pub struct Layer {
    pub shader: Arc<dyn Shader>,
    pub blend: Color,
    pub blend_tex: Option<Arc<dyn Texture>>,
}

/// The most layers a `Layered` may have (the slide's `MAX_LAYERS`); the weights live on the stack.
pub const MAX_LAYERS: usize = 32;

#[derive(Clone, Default)]
pub struct Layered {
    layers: Vec<Layer>,
}

impl Layered {
    pub fn new() -> Layered {
        Layered::default()
    }

    /// Adds a layer on top of the others (the slide's `addLayer`). Panics past [`MAX_LAYERS`] layers.
    pub fn add_layer(
        &mut self,
        shader: Arc<dyn Shader>,
        blend: Color,
        blend_tex: Option<Arc<dyn Texture>>,
    ) -> &mut Layered {
        assert!(self.layers.len() < MAX_LAYERS, "a Layered shader holds at most {MAX_LAYERS} layers");
        self.layers.push(Layer { shader, blend, blend_tex });
        self
    }

    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }
}

impl Shader for Layered {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        // Weights from the top down; stop at the first layer that covers everything below it.
        let mut weights = [Color::BLACK; MAX_LAYERS];
        let mut uncovered = Color::WHITE;
        let mut bottom = self.layers.len();
        for (i, layer) in self.layers.iter().enumerate().rev() {
            let mut blend = layer.blend;
            if let Some(tex) = &layer.blend_tex {
                blend *= tex.get_tex_color(ray, info);
            }
            weights[i] = uncovered * blend;
            uncovered *= Color::WHITE - blend;
            bottom = i;
            if uncovered.max_channel() <= 0.0 {
                break;
            }
        }
        let mut res = Color::BLACK;
        for (layer, w) in self.layers[bottom..].iter().zip(&weights[bottom..]) {
            let strength = w.max_channel();
            if strength > 0.0 {
                let layer_ray = Ray { weight: ray.weight * strength, ..*ray };
                res += layer.shader.shade(&layer_ray, info, ctx) * *w;
            }
        }
        res
    }

    fn is_dispersive(&self) -> bool {
        self.layers.iter().any(|l| l.shader.is_dispersive() || l.blend_tex.as_ref().is_some_and(|t| t.is_dispersive()))
    }
}
