//! `Layered` (slides "Комбиниране на шейдъри", "Layered Shader"): a surface made of layers, listed bottom to
//! top, each with its own shader and a blend colour (per-channel opacity: 0 transparent, 1 opaque), optionally
//! multiplied by a blend texture. The slide's loop ([`shade_bottom_up`]) is
//!
//! ```text
//! res = 0;  for each layer, bottom to top:  res = res * (1 - blend) + layer_color * blend
//! ```
//!
//! which gives layer i the weight `blend_i * (1 - blend_{i+1}) * ... * (1 - blend_top)`.
//!
//! Layer pruning, a step beyond the slide ([`Step::LayerPruning`], [`shade_pruned`]): the layers from the top
//! down instead, computing those weights as it goes, shading only the layers whose weight is not zero: a
//! layer with zero blend at this point costs nothing, and under an opaque layer nothing is shaded at all (not
//! even its blend texture is looked up). The result is the slide's, without the work the picture cannot
//! show. Each layer's shader then sees the ray with its weight multiplied by the layer's weight (its largest
//! channel), so reflection and refraction rays below a faint layer are as faint as they look, and adaptive
//! depth control (see [`crate::lesson::scene`]) stops them early. [`Layered::shade_every_layer`] keeps one
//! shader to the slide's loop whatever the steps.
//!
//! Deviation from the slide: a blend (colour times texture) is clamped to [0, 1], the range of an opacity,
//! so a bright HDR image used as a blend texture cannot give a layer a negative or larger-than-one weight
//! (ledger: `blend-clamp`).

use super::{CausticCaster, IntoShader, Material, PhotonScatter, Shader, is_caustic_caster, scatter_photon};
use crate::lesson::beyond::Step;
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::photon_map::strength;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::{Tex, Texture};
use glam::Vec3A;
use std::collections::HashMap;
use std::sync::Arc;

impl Shader for Layered {
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        if !self.every_layer {
            ctx.counters.steps_reached[Step::LayerPruning as usize] += 1;
            if ctx.scene.steps.has(Step::LayerPruning) {
                return shade_pruned(&self.layers, ray, info, ctx);
            }
        }
        shade_bottom_up(&self.layers, ray, info, ctx)
    }

    fn into_material(self: Arc<Self>) -> Material {
        Material::Layered(self)
    }

    fn is_dispersive(&self) -> bool {
        self.layers.iter().any(|l| l.shader.is_dispersive() || l.blend_tex.as_ref().is_some_and(|t| t.is_dispersive()))
    }

    /// A caustic caster when one of its layers is.
    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        self.layers.iter().any(|layer| is_caustic_caster(&layer.shader)).then_some(self as &dyn CausticCaster)
    }

    /// The texture of the first layer, from the bottom up, whose shader reads one: for the slides' floor, a
    /// textured Lambert under a faint reflection, the floor's texture. Where no layer's shader reads a
    /// texture, the first blend texture, from the bottom up, that reads u/v ([`Texture::reads_uv`]): a
    /// pattern painted with a checker as a layer's blend shows the checker's coordinates, and a glass
    /// blended by the Fresnel texture, which reads no u/v, names none.
    fn texture(&self) -> Option<&dyn Texture> {
        let blend = || {
            let blend_textures = self.layers.iter().filter_map(|layer| layer.blend_tex.as_ref());
            blend_textures.map(|t| t as &dyn Texture).find(|t| t.reads_uv())
        };
        self.layers.iter().find_map(|layer| layer.shader.texture()).or_else(blend)
    }
}

/// The slide's Layered loop: every layer from the bottom up, `res = res * (1 - blend) + layer_color * blend`.
#[inline(always)]
fn shade_bottom_up(layers: &[Layer], ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    let mut res = Color::BLACK;
    for layer in layers {
        let blend = Layer::clamp_blend(layer.blend(ray, info, ctx));
        ctx.observe(|o| o.layers_covered(blend));
        res = res * (Color::WHITE - blend) + ctx.shade_layer(layer, ray, info, blend);
    }
    res
}

/// One layer of a [`Layered`] shader: a shader and how opaque it is (slide "Layered Shader").
#[derive(Clone)]
pub struct Layer {
    /// What the layer looks like where it covers the layers below.
    pub shader: Material,
    /// The layer's opacity, per channel: 0 transparent, 1 opaque.
    pub blend: Color,
    /// A texture whose colour multiplies `blend` at each point (the Fresnel texture of the glass); `None`
    /// leaves `blend` as it is.
    pub blend_tex: Option<Tex>,
}

impl Layer {
    /// The layer's opacity at this point: its blend colour times its blend texture, clamped to [0, 1].
    pub fn blend_at(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        Layer::clamp_blend(self.blend * self.blend_tex.as_ref().map_or(Color::WHITE, |t| t.get_tex_color(ray, info)))
    }

    /// A blend clamped to [0, 1], the range of an opacity.
    #[inline(always)]
    pub(crate) fn clamp_blend(blend: Color) -> Color {
        Color(blend.0.clamp(Vec3A::ZERO, Vec3A::ONE))
    }

    /// The layer's opacity at the hit, its blend texture read as the steps of `ctx`'s scene say (and told
    /// to the ray tree): its blend colour times its blend texture, before clamping.
    #[inline(always)]
    fn blend(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        match &self.blend_tex {
            Some(tex) => self.blend * tex.color(ray, info, ctx.scene.steps, ctx.recorder()),
            None => self.blend,
        }
    }
}

/// Layer pruning ([`Step::LayerPruning`]): from the top down, `uncovered` is how much of the layers seen so
/// far lets through, and a layer's weight follows from it and the layer's blend ([`layer_weight`]); a layer
/// of no weight is not shaded, and the loop stops at the first layer that covers everything below it.
#[inline(always)]
fn shade_pruned(layers: &[Layer], ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    beyond!(LayerPruning);
    let mut res = Color::BLACK;
    let mut uncovered = Color::WHITE;
    let mut layer_ray = *ray;
    for layer in layers.iter().rev() {
        let blend = Layer::clamp_blend(layer.blend(ray, info, ctx));
        let weight = layer_weight(uncovered, blend);
        let strength = weight.max_channel();
        if strength > 0.0 {
            layer_ray.weight = ray.weight * strength;
            res += ctx.shade_layer(layer, &layer_ray, info, weight);
        }
        uncovered *= Color::WHITE - blend;
        if uncovered.max_channel() <= 0.0 {
            break;
        }
    }
    res
}

/// The weight in the final colour of a layer of opacity `blend`, when the layers above it let `uncovered`
/// through: the slide's `res = res * (1 - blend) + layer_color * blend`, unrolled from the top down.
#[inline]
pub fn layer_weight(uncovered: Color, blend: Color) -> Color {
    exercise!(layer_weight(uncovered, blend));
    uncovered * blend
}

/// The most layers a `Layered` may have (the slide's `MAX_LAYERS`).
pub const MAX_LAYERS: usize = 32;

/// The most shaders one hit may shade: the node's shader and, for a `Layered`, the shaders of its layers,
/// theirs and so on, each as often as a layer names it (the slide's loop shades every layer). A `Layered` of
/// [`MAX_LAYERS`] layers that are each a `Layered` of as many shades 1,057. Layered shaders whose two layers
/// name one shader of the level below, 31 levels deep, would shade 2^32 - 1 at every hit: such a scene is
/// refused ([`crate::lesson::scene::Scene::check`]) rather than rendered for days.
pub const MAX_SHADES_PER_HIT: u64 = 4096;

/// A surface made of layers, bottom to top, each blended over the ones below (slide "Layered Shader").
#[derive(Clone, Default)]
pub struct Layered {
    layers: Vec<Layer>,
    every_layer: bool,
    /// Whether some layer's shader is not one of the workbook's own that stay within their budget of rays
    /// ([`Material::is_workbook`]).
    own_layer: bool,
}

impl Layered {
    /// A shader with no layers yet; it is black until [`Layered::add_layer`] adds some.
    pub fn new() -> Layered {
        Layered::default()
    }

    /// Adds a layer on top of the others (the slide's `addLayer`): `shader` seen with opacity `blend`, times
    /// the texture `blend_tex` if there is one. Panics past `MAX_LAYERS` (32) layers.
    pub fn add_layer(
        &mut self,
        shader: impl IntoShader,
        blend: Color,
        blend_tex: Option<Arc<dyn Texture>>,
    ) -> &mut Layered {
        assert!(self.layers.len() < MAX_LAYERS, "a Layered shader holds at most {MAX_LAYERS} layers");
        let shader = shader.into_shader();
        self.own_layer |= !shader.is_workbook();
        self.layers.push(Layer { shader, blend, blend_tex: blend_tex.map(Texture::into_tex) });
        self
    }

    /// With `true`, shades every layer at every point with the slide's loop, even a layer of zero blend or one
    /// hidden under an opaque layer, whatever the render's steps. The picture is the same; only the time
    /// differs.
    pub fn shade_every_layer(&mut self, every_layer: bool) -> &mut Layered {
        self.every_layer = every_layer;
        self
    }

    /// The layers, bottom first.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// Whether every layer is shaded at every point ([`Layered::shade_every_layer`]).
    pub fn shades_every_layer(&self) -> bool {
        self.every_layer
    }

    /// Whether every layer's shader is one of the workbook's own ([`Material::is_workbook`]).
    #[inline(always)]
    pub(crate) fn is_workbook(&self) -> bool {
        !self.own_layer
    }

    /// The weight of each layer at this hit, computed from the top down as `shade` does, and the lowest
    /// layer that can be seen (the first one, from the top, that covers everything below it); the layers
    /// under it have no weight.
    fn weights(&self, ray: &Ray, info: &IntersectionInfo) -> ([Color; MAX_LAYERS], usize) {
        let mut weights = [Color::BLACK; MAX_LAYERS];
        let mut uncovered = Color::WHITE;
        let mut bottom = self.layers.len();
        for (i, layer) in self.layers.iter().enumerate().rev() {
            let blend = layer.blend_at(ray, info);
            weights[i] = layer_weight(uncovered, blend);
            uncovered *= Color::WHITE - blend;
            bottom = i;
            if uncovered.max_channel() <= 0.0 {
                break;
            }
        }
        (weights, bottom)
    }
}

impl CausticCaster for Layered {
    /// A photon follows one layer, chosen with probability proportional to the layer's weight (the mean of
    /// its channels); its power is multiplied by the weight over that probability, so on average it carries
    /// exactly what the blend lets through. Landing on a diffuse layer, it is stored with its power over the
    /// probability alone: the map holds the light that arrives, and the diffuse layer's weight is applied
    /// when the layer is shaded.
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, rng: &mut Rng) -> PhotonScatter {
        let (weights, bottom) = self.weights(ray, info);
        let total: f32 = weights[bottom..self.layers.len()].iter().map(|&w| strength(w)).sum();
        if total.is_nan() || total <= 0.0 {
            return PhotonScatter::Absorb;
        }
        let mut pick = rng.next_f32() * total;
        let last = (bottom..self.layers.len()).rev().find(|&i| strength(weights[i]) > 0.0).unwrap_or(bottom);
        let chosen = (bottom..self.layers.len())
            .find(|&i| {
                pick -= strength(weights[i]);
                pick < 0.0
            })
            .unwrap_or(last);
        let probability = strength(weights[chosen]) / total;
        match scatter_photon(&self.layers[chosen].shader, ray, info, rng) {
            PhotonScatter::Land { scale } => PhotonScatter::Land { scale: scale / probability },
            PhotonScatter::Continue { dir, filter } => {
                PhotonScatter::Continue { dir, filter: filter * weights[chosen] / probability }
            }
            PhotonScatter::Absorb => PhotonScatter::Absorb,
        }
    }
}

/// How many shaders one hit of `shader` shades ([`MAX_SHADES_PER_HIT`]): 1, and for a `Layered` 1 more than
/// its layers' shaders together, each as often as a layer names it (saturating). Each `Layered` is counted
/// once and its count kept in `counted`, by address (the shaders must live as long as it does), so that
/// Layered shaders sharing their layers' shaders are counted in time linear in their layers; the count
/// recurses through a list, not the stack, so a chain of thousands of Layered shaders is counted too. A
/// student's shader counts 1: what it calls cannot be seen.
pub fn shades_per_hit(shader: &Material, counted: &mut HashMap<usize, u64>) -> u64 {
    let Material::Layered(top) = shader else {
        return 1;
    };
    let address = |layered: &Arc<Layered>| Arc::as_ptr(layered) as usize;
    let nested = |layered: &Arc<Layered>| -> Vec<Arc<Layered>> {
        let layers = layered.layers.iter().map(|layer| &layer.shader);
        layers.filter_map(|s| if let Material::Layered(l) = s { Some(l.clone()) } else { None }).collect()
    };
    let mut todo = vec![top.clone()];
    while let Some(layered) = todo.last().cloned() {
        let uncounted: Vec<_> = nested(&layered).into_iter().filter(|l| !counted.contains_key(&address(l))).collect();
        if uncounted.is_empty() {
            let shades = layered.layers.iter().fold(1u64, |n, layer| {
                let layer_shades = match &layer.shader {
                    Material::Layered(l) => counted[&address(l)],
                    _ => 1,
                };
                n.saturating_add(layer_shades)
            });
            counted.insert(address(&layered), shades);
            todo.pop();
        } else {
            todo.extend(uncounted);
        }
    }
    counted[&address(top)]
}
