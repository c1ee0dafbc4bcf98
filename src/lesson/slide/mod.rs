//! The slides' reading of lecture 6 (`--slide`): every topic as the slide writes it, and nothing more.
//!
//! The workbook renders in two readings. The default one adds, beside each slide, steps that make it faster
//! or less noisy (adaptive depth control, the node BVH, bilinear texels, stratified disc samples, hero
//! wavelengths, the photon grid with aimed emission, layer pruning, ...; docs/beyond-the-slides.md lists
//! them and what each buys). This module is the other reading: the code a student writes from the slides,
//! with only what the workbook's guarantees need (the error-bound ray offset of [`Ray::spawn`], no NaN in a
//! frame, a safety cap on recursion). Every example renders through it with `--slide`, and so does a
//! student's copy; `--side-by-side "--slide"` shows what the steps beyond the slides change.
//!
//! | slide | here |
//! |---|---|
//! | Bitmap textures | [`bitmap_textures`]: one texel per look-up |
//! | Model transform | [`model_transform`]: `Node::intersect` through `T^-1`, the loop over the nodes, a mesh's triangles one by one |
//! | Environment | [`environment`]: spherical and cube-map environments, one texel per look-up |
//! | Reflection v0.1 / v0.2 | [`reflection`]: the mirror ray; `raytrace` with `MAX_RAY_DEPTH` ([`raytrace`](self::raytrace::raytrace)) |
//! | Refraction, Fresnel | the workbook's own [`Refraction`](crate::lesson::shader::Refraction) and [`Fresnel`](crate::lesson::texture::Fresnel) texture, which are written as the slides write them |
//! | Layered shader | [`layered`]: the bottom-up loop `res = res * (1 - blend) + layer * blend` |
//! | Glossy reflections | [`glossy`]: random points of the unit disc |
//! | Chromatic dispersion | [`dispersion`]: K passes, each frame times its band's colour |
//! | Photon mapping | [`photon_mapping`]: photons in all directions, the k nearest from a k-d tree ([`kd_tree`]) |
//!
//! The render loop ([`render()`]) and `raytrace` are the slides' too. A shader is shaded by
//! [`shade`]: the workbook's own shaders as the slides write them, a student's own through its
//! [`Shader::shade`], whose `ctx.raytrace` and light loop then run this module's versions.
//!
//! Not supported here, and refused with a message: the instruments that watch the default reading
//! (`--trace-pixel`, `--view`, the window), `--adaptive-aa` and `--show-photons`. A scene file that asks for
//! the course's adaptive anti-aliasing gets five samples in every pixel.

pub mod bitmap_textures;
pub mod dispersion;
pub mod environment;
pub mod glossy;
pub mod kd_tree;
pub mod layered;
pub mod model_transform;
pub mod photon_mapping;
pub mod raytrace;
pub mod reflection;
pub mod render;

pub use raytrace::{light_loop, raytrace, visible};
pub use render::render;

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::{Lambert, Layered, Phong, Reflection, Shader};
use std::any::{Any, TypeId};

/// What the slides' reading keeps beside the scene while it renders: the scene's nodes as its loop meets
/// them, and its own photon map.
pub struct Slides<'a> {
    /// The scene's nodes, each with its geometry's kind ([`model_transform::slide_nodes`]).
    pub nodes: Vec<model_transform::SlideNode<'a>>,
    /// The caustic photon map of the slides' reading, if the scene asks for one.
    pub photon_map: Option<&'a photon_mapping::PhotonMap>,
}

/// The colour a shader gives a hit, in the slides' reading: the workbook's shaders that read a texture or
/// go beyond their slide by default are shaded as their slide writes them; every other shader, a student's
/// included, by its own [`Shader::shade`].
pub fn shade(shader: &dyn Shader, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    // The shader's type is asked once (a call through its trait object) and compared with each of the
    // workbook's; only the one it is is then looked at as that type.
    let any = shader as &dyn Any;
    let kind = any.type_id();
    if kind == TypeId::of::<Lambert>()
        && let Some(lambert) = any.downcast_ref::<Lambert>()
    {
        let diffuse = bitmap_textures::color_of(&lambert.color, ray, info);
        return lambert.shade_with(diffuse, ray, info, ctx);
    }
    if kind == TypeId::of::<Phong>()
        && let Some(phong) = any.downcast_ref::<Phong>()
    {
        let diffuse = bitmap_textures::color_of(&phong.color, ray, info);
        return phong.shade_with(diffuse, ray, info, ctx);
    }
    if kind == TypeId::of::<Reflection>()
        && let Some(mirror) = any.downcast_ref::<Reflection>()
    {
        return reflection::shade(mirror, ray, info, ctx);
    }
    if kind == TypeId::of::<Layered>()
        && let Some(layered) = any.downcast_ref::<Layered>()
    {
        return layered::shade(layered, ray, info, ctx);
    }
    shader.shade(ray, info, ctx)
}
