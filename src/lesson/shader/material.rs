//! [`Material`]: a node's or a layer's shader, stored once, as the node's own value. The course calls a
//! node's shader through its interface (a virtual call in its C++, [`Shader`] here); the workbook keeps the
//! shaders it ships as the cases of an enum, so that the shading of a hit is one piece of code the compiler
//! sees whole, and any other shader (a student's own) as one more case, [`Material::Own`], called through
//! its trait object: a new shader works the moment it compiles.
//!
//! A shader becomes its case by its own [`Shader::into_material`], which the workbook's shaders override and
//! every other shader inherits: nothing asks a value's type. This is the one place that lists the cases.

use super::{CausticCaster, Lambert, Layered, Phong, Reflection, Refraction, Shader};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;
use std::sync::Arc;

/// A shader as a node or a layer stores it: one of the workbook's, or any other through its trait object.
#[derive(Clone)]
pub enum Material {
    /// A diffuse surface.
    Lambert(Lambert),
    /// A diffuse surface with highlights.
    Phong(Phong),
    /// A mirror, perfect or glossy.
    Reflection(Reflection),
    /// A refracting surface.
    Refraction(Refraction),
    /// Layers blended over each other (shared between nodes and layers).
    Layered(Arc<Layered>),
    /// Any other shader, through its trait object.
    Own(Arc<dyn Shader>),
}

impl Material {
    /// Whether every shader of it is one of the workbook's own that stays within its budget of rays and
    /// spawns them with [`Ray::spawn`]: a diffuse surface, a perfect mirror, a refraction, or a `Layered` of
    /// these. `raytrace` shades such a node without the bookkeeping of [`crate::lesson::branching`].
    #[inline(always)]
    pub(crate) fn is_workbook(&self) -> bool {
        match self {
            Material::Lambert(_) | Material::Phong(_) | Material::Refraction(_) => true,
            Material::Reflection(mirror) => mirror.glossiness >= 1.0,
            Material::Layered(layered) => layered.is_workbook(),
            Material::Own(_) => false,
        }
    }
}

impl Material {
    /// The colour the shader gives the hit: the one dispatch of a node's or a layer's shader. `IN_LAYER` is
    /// the dispatch of a layer's shader ([`Material::shade_layer`]), where a `Layered` among the layers is
    /// shaded by a call, so that the dispatch does not call itself and the compiler can make the shading of
    /// a hit, its layers included, one piece of code.
    #[inline(always)]
    fn dispatch<const IN_LAYER: bool>(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        match self {
            Material::Lambert(lambert) => lambert.shade(ray, info, ctx),
            Material::Phong(phong) => phong.shade(ray, info, ctx),
            Material::Reflection(mirror) => mirror.shade(ray, info, ctx),
            Material::Refraction(refraction) => refraction.shade(ray, info, ctx),
            Material::Layered(layered) if IN_LAYER => shade_nested(layered, ray, info, ctx),
            Material::Layered(layered) => layered.shade(ray, info, ctx),
            Material::Own(shader) => shader.shade(ray, info, ctx),
        }
    }

    /// The colour a layer's shader gives the hit (what [`Shader::shade`] gives).
    #[inline(always)]
    pub(crate) fn shade_layer(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.dispatch::<true>(ray, info, ctx)
    }
}

/// A `Layered` shader among the layers of another, shaded by a call ([`Material::dispatch`]).
#[inline(never)]
fn shade_nested(layered: &Layered, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    layered.shade(ray, info, ctx)
}

impl Shader for Material {
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.dispatch::<false>(ray, info, ctx)
    }

    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        match self {
            Material::Lambert(lambert) => lambert.caustic_caster(),
            Material::Phong(phong) => phong.caustic_caster(),
            Material::Reflection(mirror) => mirror.caustic_caster(),
            Material::Refraction(refraction) => refraction.caustic_caster(),
            Material::Layered(layered) => layered.caustic_caster(),
            Material::Own(shader) => shader.caustic_caster(),
        }
    }

    fn is_dispersive(&self) -> bool {
        match self {
            Material::Lambert(lambert) => lambert.is_dispersive(),
            Material::Phong(phong) => phong.is_dispersive(),
            Material::Reflection(mirror) => mirror.is_dispersive(),
            Material::Refraction(refraction) => refraction.is_dispersive(),
            Material::Layered(layered) => layered.is_dispersive(),
            Material::Own(shader) => shader.is_dispersive(),
        }
    }

    fn texture(&self) -> Option<&dyn Texture> {
        match self {
            Material::Lambert(lambert) => lambert.texture(),
            Material::Phong(phong) => phong.texture(),
            Material::Reflection(mirror) => mirror.texture(),
            Material::Refraction(refraction) => refraction.texture(),
            Material::Layered(layered) => layered.texture(),
            Material::Own(shader) => shader.texture(),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Material::Lambert(lambert) => lambert.name(),
            Material::Phong(phong) => phong.name(),
            Material::Reflection(mirror) => mirror.name(),
            Material::Refraction(refraction) => refraction.name(),
            Material::Layered(layered) => layered.name(),
            Material::Own(shader) => shader.name(),
        }
    }

    fn into_material(self: Arc<Self>) -> Material {
        Arc::unwrap_or_clone(self)
    }
}

/// Anything that can be a node's or a layer's shader: a shader, a shader shared with other nodes
/// (`Arc<Reflection>`, `Arc<dyn Shader>`), or a [`Material`].
pub trait IntoShader {
    /// The shader as a node or a layer stores it.
    fn into_shader(self) -> Material;
}

impl<S: Shader> IntoShader for S {
    fn into_shader(self) -> Material {
        Arc::new(self).into_material()
    }
}

impl<S: Shader> IntoShader for Arc<S> {
    fn into_shader(self) -> Material {
        self.into_material()
    }
}

impl IntoShader for Arc<dyn Shader> {
    fn into_shader(self) -> Material {
        self.into_material()
    }
}
