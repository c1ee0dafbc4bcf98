//! The scene with every node's geometry and shader, and the environment, hidden behind a type of the test's
//! own, so that it is traced as a student's own types are, through their trait objects (the cases `Own` of
//! `Shape`, `Material` and `Sky`).

use lecture6::lesson::color::Color;
use lecture6::lesson::environment::Environment;
use lecture6::lesson::geometry::{Aabb, Geometry, Hit, IntersectionInfo, IntoGeometry, Shape};
use lecture6::lesson::math::Vector;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::{CausticCaster, IntoShader, Material, Shader};
use lecture6::lesson::texture::Texture;
use std::sync::Arc;

/// The scene with every node's geometry and shader, and the environment, each behind a [`Hidden`].
pub fn through_trait_objects(scene: &Scene) -> Scene {
    let mut hidden = scene.clone();
    for node in &mut hidden.nodes {
        node.geometry = Hidden(node.geometry.clone()).into_geometry();
        node.shader = Hidden(node.shader.clone()).into_shader();
    }
    hidden.environment = scene.environment.clone().map(|e| Arc::new(Hidden(e)) as Arc<dyn Environment>);
    hidden
}

/// A value under a type of its own, which forwards every call to it.
struct Hidden<T>(T);

impl Geometry for Hidden<Shape> {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.0.intersect(ray, t_max)
    }
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        self.0.hit(ray, t_max)
    }
    fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        self.0.surface(ray, hit)
    }
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.0.intersects(ray, t_max)
    }
    fn bounds(&self) -> Option<Aabb> {
        self.0.bounds()
    }
    fn name(&self) -> &'static str {
        self.0.name()
    }
}

impl Environment for Hidden<Arc<dyn Environment>> {
    fn get(&self, dir: Vector) -> Color {
        self.0.get(dir)
    }
}

impl Shader for Hidden<Material> {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.0.shade(ray, info, ctx)
    }
    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        self.0.caustic_caster()
    }
    fn is_dispersive(&self) -> bool {
        self.0.is_dispersive()
    }
    fn texture(&self) -> Option<&dyn Texture> {
        self.0.texture()
    }
    fn name(&self) -> &'static str {
        self.0.name()
    }
}
