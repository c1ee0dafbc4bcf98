//! The one place that lists the workbook's own shapes, shaders, textures and environments, and dispatches
//! them: nothing else in the lesson asks a value's concrete type.
//!
//! The slides call a node's geometry, shader and texture, and the environment, through their interfaces
//! (virtual calls in the course's C++, trait objects here). When a scene is prepared ([`Scene::prepared`](crate::lesson::scene::Scene::prepared)),
//! each node's shape and shader, and the environment, are looked at once: the workbook's own types
//! (`Sphere`, `Plane`, a `Mesh`; `Lambert`, `Phong`, a perfect `Reflection`, `Refraction`, a `Layered` of
//! these; `BitmapTexture`, `CheckerTexture`, `Fresnel`; the cube map, spherical and constant environments)
//! become the cases of an enum, which `raytrace` matches on, so the compiler sees the whole shading of a hit
//! as one piece of code. Anything else (a student's own shape, shader, texture or environment, a glossy
//! mirror) is one more case, `Dyn`, called through its trait object: a new type works the moment it
//! compiles. A node's transform wraps its shape's case (`Shape::Transformed`). pbrt-v4 dispatches its closed set of shapes and materials the same way.
//!
//! The cases follow the scene's [`Steps`]: without [`Step::TexelFilter`] a bitmap texture or environment is
//! read one texel at a time, without [`Step::MeshBvh`] a mesh is tested triangle by triangle, without
//! [`Step::LayerPruning`] a `Layered` shader shades every layer. A course shader reached through its trait
//! object (a student's shader that wraps one, or the ray tree's watched path) follows them the same way,
//! through `ctx` ([`ColorSource::at`]).
//!
//! Knowing a node's types buys one more thing: a node of the workbook's own shape under the workbook's own
//! shaders needs none of the bookkeeping that `raytrace` keeps for a student's shader (its branching
//! budget, the check for rays that find their own surface; [`crate::lesson::branching`]), since those
//! shaders stay within their budget and those shapes describe their hits exactly.
//!
//! Nothing is computed differently: each case calls the same function of its type that the trait object
//! would (`Lambert::shade_with` with the colour of its texture, `Sphere::hit`, `BitmapTexture::get_tex_color`,
//! the same Layered loops), so a picture is the same bit for bit either way (`tests/workbook/beyond.rs`
//! renders every example both ways).

use crate::lesson::beyond::{Step, Steps};
use crate::lesson::color::Color;
use crate::lesson::environment::{ConstantEnvironment, CubemapEnvironment, Environment, SphericalEnvironment};
use crate::lesson::geometry::{Geometry, Hit, IntersectionInfo, Mesh, Plane, Sphere};
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::{
    ColorSource, Lambert, Layer, LayerShading, Layered, Phong, Reflection, Refraction, Shader, shade_bottom_up,
    shade_pruned,
};
use crate::lesson::texture::{BitmapTexture, CheckerTexture, Fresnel, Texture};
use crate::lesson::transform::Transform;
use std::any::Any;
use std::collections::HashMap;
use std::sync::Arc;

/// A node's geometry: one of the workbook's shapes, a mesh tested triangle by triangle (without
/// [`Step::MeshBvh`]), or any other geometry through its trait object; under a transform, the same case
/// inside [`Shape::Transformed`].
#[derive(Clone)]
pub(crate) enum Shape {
    Sphere(Sphere),
    Plane(Plane),
    /// A mesh whose triangles are tested one by one ([`Mesh::hit_one_by_one`]).
    MeshOneByOne(Arc<Mesh>),
    /// Any other geometry (a student's own, a mesh with its BVH) through its trait object.
    Dyn(Arc<dyn Geometry>),
    /// A shape under the node's transform: the ray taken to the shape's canonical space, the hit brought
    /// back ([`Node::intersect`]).
    Transformed(Box<Shape>, Transform),
}

impl Shape {
    /// The shape of `node` under `steps`.
    pub(crate) fn of(node: &Node, steps: Steps) -> Shape {
        match node.transform {
            Some(t) => Shape::Transformed(Box::new(Shape::of_geometry(&node.geometry, steps)), t),
            None => Shape::of_geometry(&node.geometry, steps),
        }
    }

    /// The shape of a geometry, without a transform.
    fn of_geometry(geometry: &Arc<dyn Geometry>, steps: Steps) -> Shape {
        if !steps.has(Step::MeshBvh) {
            let any: Arc<dyn Any + Send + Sync> = geometry.clone();
            if let Ok(mesh) = any.downcast::<Mesh>() {
                return Shape::MeshOneByOne(mesh);
            }
        }
        let any = &**geometry as &dyn Any;
        match (any.downcast_ref::<Sphere>(), any.downcast_ref::<Plane>()) {
            (Some(sphere), _) => Shape::Sphere(*sphere),
            (_, Some(plane)) => Shape::Plane(*plane),
            _ => Shape::Dyn(geometry.clone()),
        }
    }

    /// Whether this is one of the workbook's own shapes that describe their hits exactly (a sphere or a
    /// plane without a transform; a mesh is checked as any other shape is).
    pub(crate) fn is_workbook(&self) -> bool {
        matches!(self, Shape::Sphere(_) | Shape::Plane(_))
    }

    /// [`Node::hit`] of the node whose shape this is.
    #[inline(always)]
    pub(crate) fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        match self {
            Shape::Sphere(sphere) => sphere.hit(ray, t_max),
            Shape::Plane(plane) => plane.hit(ray, t_max),
            Shape::MeshOneByOne(mesh) => mesh.hit_one_by_one(ray, t_max),
            Shape::Dyn(geometry) => geometry.hit(ray, t_max),
            Shape::Transformed(shape, t) => transformed_hit(shape, t, ray, t_max),
        }
    }

    /// [`Node::intersects`] of the node whose shape this is.
    #[inline(always)]
    pub(crate) fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        match self {
            Shape::Sphere(sphere) => sphere.intersects(ray, t_max),
            Shape::Plane(plane) => plane.intersects(ray, t_max),
            Shape::MeshOneByOne(mesh) => mesh.hit_one_by_one(ray, t_max).is_some(),
            Shape::Dyn(geometry) => geometry.intersects(ray, t_max),
            Shape::Transformed(shape, t) => transformed_intersects(shape, t, ray, t_max),
        }
    }

    /// [`Node::intersect`] of the node whose shape this is (the slide's whole hit, for its loop over the
    /// nodes), and whether its normal is of unit length.
    #[inline(always)]
    pub(crate) fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(IntersectionInfo, bool)> {
        match self {
            Shape::Sphere(sphere) => sphere.intersect(ray, t_max).map(|info| (info, true)),
            Shape::Plane(plane) => plane.intersect(ray, t_max).map(|info| (info, true)),
            Shape::MeshOneByOne(..) => self.hit(ray, t_max).and_then(|hit| self.surface(ray, &hit)),
            Shape::Dyn(geometry) => geometry.intersect(ray, t_max).map(|info| (info, Node::is_unit_normal(&info))),
            Shape::Transformed(shape, t) => transformed_intersect(shape, t, ray, t_max),
        }
    }

    /// The surface at `hit` ([`Node::checked_surface`]), and whether its normal is of unit length (as the
    /// geometry describes it, before a transform): the workbook's sphere and plane describe theirs so by
    /// construction (a normalised offset from the centre, the plane's axis), so only another shape's is
    /// checked.
    #[inline(always)]
    pub(crate) fn surface(&self, ray: &Ray, hit: &Hit) -> Option<(IntersectionInfo, bool)> {
        match self {
            Shape::Sphere(_) | Shape::Plane(_) => self.workbook_surface(ray, hit).map(|info| (info, true)),
            Shape::MeshOneByOne(mesh) => mesh.surface(ray, hit).map(|info| (info, Node::is_unit_normal(&info))),
            Shape::Dyn(geometry) => geometry.surface(ray, hit).map(|info| (info, Node::is_unit_normal(&info))),
            Shape::Transformed(shape, t) => transformed_surface(shape, t, ray, hit),
        }
    }

    /// The surface at `hit` if this is one of the workbook's own shapes (which find theirs always); `None`
    /// for another.
    #[inline(always)]
    pub(crate) fn workbook_surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        match self {
            Shape::Sphere(sphere) => sphere.surface(ray, hit),
            Shape::Plane(plane) => plane.surface(ray, hit),
            Shape::MeshOneByOne(_) | Shape::Dyn(_) | Shape::Transformed(..) => None,
        }
    }
}

/// [`Shape::hit`] through a transform, kept out of the loop over the nodes, so that a scene of
/// untransformed nodes does not prepare every ray for a transform it never applies.
#[inline(never)]
fn transformed_hit(shape: &Shape, t: &Transform, ray: &Ray, t_max: f32) -> Option<Hit> {
    shape.hit(&t.ray_to_canonical(ray), t_max)
}

/// [`Shape::intersects`] through a transform, out of the loop as [`transformed_hit`].
#[inline(never)]
fn transformed_intersects(shape: &Shape, t: &Transform, ray: &Ray, t_max: f32) -> bool {
    shape.intersects(&t.ray_to_canonical(ray), t_max)
}

/// [`Shape::surface`] through a transform.
fn transformed_surface(shape: &Shape, t: &Transform, ray: &Ray, hit: &Hit) -> Option<(IntersectionInfo, bool)> {
    shape.surface(&t.ray_to_canonical(ray), hit).map(|(info, unit_normal)| (t.info_to_world(&info), unit_normal))
}

/// [`Shape::intersect`] through a transform, out of the loop as [`transformed_hit`].
#[inline(never)]
fn transformed_intersect(shape: &Shape, t: &Transform, ray: &Ray, t_max: f32) -> Option<(IntersectionInfo, bool)> {
    shape.intersect(&t.ray_to_canonical(ray), t_max).map(|(info, unit_normal)| (t.info_to_world(&info), unit_normal))
}

/// What a ray that hits nothing sees: one of the workbook's environments, black, or any other through its
/// trait object.
#[derive(Clone)]
pub(crate) enum Sky {
    Black,
    Constant(ConstantEnvironment),
    Cubemap(CubemapEnvironment),
    Spherical(SphericalEnvironment),
    Dyn(Arc<dyn Environment>),
}

impl Sky {
    /// The sky of a scene whose environment is `environment`, under `steps`.
    pub(crate) fn of(environment: &Option<Arc<dyn Environment>>, steps: Steps) -> Sky {
        let Some(environment) = environment else {
            return Sky::Black;
        };
        let any = &**environment as &dyn Any;
        if let Some(constant) = any.downcast_ref::<ConstantEnvironment>() {
            Sky::Constant(*constant)
        } else if let Some(cubemap) = any.downcast_ref::<CubemapEnvironment>() {
            Sky::Cubemap(cubemap.clone().with_filter(cubemap.filter.under(steps)))
        } else if let Some(spherical) = any.downcast_ref::<SphericalEnvironment>() {
            Sky::Spherical(spherical.clone().with_filter(spherical.filter.under(steps)))
        } else {
            Sky::Dyn(environment.clone())
        }
    }

    /// The colour seen in the direction `dir`, as the environment's [`Environment::get`] gives it.
    #[inline(always)]
    pub(crate) fn get(&self, dir: Vector) -> Color {
        match self {
            Sky::Black => Color::BLACK,
            Sky::Constant(constant) => constant.get(dir),
            Sky::Cubemap(cubemap) => cubemap.get(dir),
            Sky::Spherical(spherical) => spherical.get(dir),
            Sky::Dyn(environment) => environment.get(dir),
        }
    }
}

/// A texture, or the constant colour a shader has instead of one.
#[derive(Clone)]
pub(crate) enum Tex {
    Color(Color),
    Bitmap(BitmapTexture),
    Checker(CheckerTexture),
    Fresnel(Fresnel),
    Dyn(Arc<dyn Texture>),
}

impl Tex {
    fn of_texture(texture: &Arc<dyn Texture>, steps: Steps) -> Tex {
        let any = &**texture as &dyn Any;
        if let Some(bitmap) = any.downcast_ref::<BitmapTexture>() {
            Tex::Bitmap(bitmap.clone().with_filter(bitmap.filter.under(steps)))
        } else if let Some(checker) = any.downcast_ref::<CheckerTexture>() {
            Tex::Checker(*checker)
        } else if let Some(fresnel) = any.downcast_ref::<Fresnel>() {
            Tex::Fresnel(*fresnel)
        } else {
            Tex::Dyn(texture.clone())
        }
    }

    fn of(source: &ColorSource, steps: Steps) -> Tex {
        match source {
            ColorSource::Color(c) => Tex::Color(*c),
            ColorSource::Texture(texture) => Tex::of_texture(texture, steps),
        }
    }

    /// The colour at the hit, as [`ColorSource::get`] gives it.
    #[inline(always)]
    pub(crate) fn get(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        match self {
            Tex::Color(c) => *c,
            Tex::Bitmap(bitmap) => bitmap.get_tex_color(ray, info),
            Tex::Checker(checker) => checker.get_tex_color(ray, info),
            Tex::Fresnel(fresnel) => fresnel.get_tex_color(ray, info),
            Tex::Dyn(texture) => texture.get_tex_color(ray, info),
        }
    }
}

/// How many shaders one hit of `shader` shades ([`crate::lesson::shader::MAX_SHADES_PER_HIT`]): 1, and for a
/// `Layered` 1 more than its layers' shaders together, each as often as a layer names it (saturating). Each
/// shader is counted once and its count kept in `counted`, by address (the shaders must live as long as it
/// does), so that Layered shaders sharing their layers' shaders are counted in time linear in their layers;
/// the count recurses through a list, not the stack, so a chain of thousands of Layered shaders is counted
/// too. A student's shader counts 1: what it calls cannot be seen.
pub fn shades_per_hit(shader: &Arc<dyn Shader>, counted: &mut HashMap<usize, u64>) -> u64 {
    let address = |shader: &Arc<dyn Shader>| Arc::as_ptr(shader) as *const () as usize;
    let mut todo = vec![shader.clone()];
    while let Some(top) = todo.last().cloned() {
        let layers = (&*top as &dyn Any).downcast_ref::<Layered>().map_or(&[][..], Layered::layers);
        let uncounted = layers.iter().map(|layer| &layer.shader).filter(|s| !counted.contains_key(&address(s)));
        let uncounted: Vec<_> = uncounted.cloned().collect();
        if uncounted.is_empty() {
            let shades = layers.iter().fold(1u64, |n, layer| n.saturating_add(counted[&address(&layer.shader)]));
            counted.insert(address(&top), shades);
            todo.pop();
        } else {
            todo.extend(uncounted);
        }
    }
    counted[&address(shader)]
}

/// A node's shader: one of the workbook's single shaders, one of its `Layered` shaders made of them, or
/// any other through its trait object.
#[derive(Clone)]
pub(crate) enum Material {
    Single(Surface),
    Layered(Box<[MaterialLayer]>, bool),
}

/// A shader that is not made of layers: one of the workbook's, or any other (a glossy mirror, a `Layered`
/// inside a layer, a student's) through its trait object. A `Layered` material's layers are these, so that
/// the whole Layered loop is one piece of code, with no call back into the enum for each layer.
#[derive(Clone)]
pub(crate) enum Surface {
    Lambert(Lambert, Tex),
    Phong(Phong, Tex),
    /// A perfect mirror (a glossy one is `Dyn`: its many rays cost far more than the call).
    Mirror(Reflection, Tex),
    Refraction(Refraction),
    Dyn(Arc<dyn Shader>),
}

/// One layer of a [`Material::Layered`]: its shader and how opaque it is.
#[derive(Clone)]
pub(crate) struct MaterialLayer {
    surface: Surface,
    blend: Color,
    blend_tex: Option<Tex>,
}

impl Material {
    /// The material of `shader` under `steps`.
    pub(crate) fn of(shader: &Arc<dyn Shader>, steps: Steps) -> Material {
        match (&**shader as &dyn Any).downcast_ref::<Layered>() {
            Some(layered) => {
                let layers = layered.layers().iter().map(|layer| MaterialLayer::of(layer, steps)).collect();
                Material::Layered(layers, layered.shades_every_layer() || !steps.has(Step::LayerPruning))
            }
            None => Material::Single(Surface::of(shader, steps)),
        }
    }

    /// Whether every shader of it is one of the workbook's own (its textures may be a student's).
    pub(crate) fn is_workbook(&self) -> bool {
        match self {
            Material::Single(surface) => !matches!(surface, Surface::Dyn(_)),
            Material::Layered(layers, _) => layers.iter().all(|l| !matches!(l.surface, Surface::Dyn(_))),
        }
    }

    /// The colour the shader gives the hit, as its [`Shader::shade`] would.
    #[inline(always)]
    pub(crate) fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        match self {
            Material::Single(surface) => surface.shade(ray, info, ctx),
            Material::Layered(layers, true) => every_layer(layers, ray, info, ctx),
            Material::Layered(layers, false) => shade_pruned(layers, ray, info, ctx),
        }
    }
}

/// The slide's Layered loop over a prepared material's layers ([`shade_bottom_up`]), kept out of line: the
/// default reading's `raytrace`, which inlines the pruned loop, stays as small as it was.
#[inline(never)]
fn every_layer(layers: &[MaterialLayer], ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    shade_bottom_up(layers, ray, info, ctx)
}

impl Surface {
    /// The surface shader of `shader`: one of the workbook's, or its trait object.
    fn of(shader: &Arc<dyn Shader>, steps: Steps) -> Surface {
        let any = &**shader as &dyn Any;
        if let Some(lambert) = any.downcast_ref::<Lambert>() {
            Surface::Lambert(lambert.clone(), Tex::of(&lambert.color, steps))
        } else if let Some(phong) = any.downcast_ref::<Phong>() {
            Surface::Phong(phong.clone(), Tex::of(&phong.color, steps))
        } else if let Some(mirror) = any.downcast_ref::<Reflection>().filter(|m| m.glossiness >= 1.0) {
            Surface::Mirror(mirror.clone(), Tex::of(&mirror.multiplier, steps))
        } else if let Some(refraction) = any.downcast_ref::<Refraction>() {
            Surface::Refraction(*refraction)
        } else {
            Surface::Dyn(shader.clone())
        }
    }

    /// The colour the shader gives the hit, as its [`Shader::shade`] would.
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        match self {
            Surface::Lambert(lambert, color) => lambert.shade_with(color.get(ray, info), ray, info, ctx),
            Surface::Phong(phong, color) => phong.shade_with(color.get(ray, info), ray, info, ctx),
            Surface::Mirror(mirror, multiplier) => mirror.shade_perfect(multiplier.get(ray, info), ray, info, ctx),
            Surface::Refraction(refraction) => refraction.shade(ray, info, ctx),
            Surface::Dyn(shader) => shader.shade(ray, info, ctx),
        }
    }
}

impl MaterialLayer {
    fn of(layer: &Layer, steps: Steps) -> MaterialLayer {
        MaterialLayer {
            surface: Surface::of(&layer.shader, steps),
            blend: layer.blend,
            blend_tex: layer.blend_tex.as_ref().map(|texture| Tex::of_texture(texture, steps)),
        }
    }
}

impl LayerShading for MaterialLayer {
    #[inline(always)]
    fn blend(&self, ray: &Ray, info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {
        match &self.blend_tex {
            Some(tex) => self.blend * tex.get(ray, info),
            None => self.blend,
        }
    }
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, weight: Color, ctx: &mut TraceContext) -> Color {
        ctx.begin_layer(ray);
        self.surface.shade(ray, info, ctx) * weight
    }
}
