//! A test kit for a shader of one's own (not a slide: what a homework's tests use). [`OneHit`] shades one
//! hit without a render: a ray that hits a plane or a sphere at a point and a normal of one's choice, in a
//! scene with the lights, the environment and the ambient light one gives it, through a ready
//! [`TraceContext`]. Three checks a test calls on a shader, each at hits of its own, each returning what it
//! found rather than panicking, so that the test's own assertion decides:
//!
//! - [`check_furnace`]: the energy of its rays, a furnace at one point: under a white sky of 1 in every
//!   direction and no lamp, a shader that reflects or refracts what arrives may return at most that 1 (a sum
//!   of N rays not divided by N, or a factor above 1, returns more);
//! - [`check_mirror_limit`]: the limit of a glossy shader at roughness 0 (or glossiness 1): it is a perfect
//!   mirror, the same colour as a given `Reflection` under a sky whose colour changes with the direction;
//! - [`check_finite`]: no NaN or infinite colour over random hits of planes and spheres, lit and unlit.
//!
//! The kit is built on the library's public API alone (`Scene`, `Node`, `TraceContext::new`,
//! `Scene::closest_hit`, `Shader::shade`): what it shades is what a render shades at that hit, without the
//! end-of-run report around it.

use crate::lesson::camera::Camera;
use crate::lesson::color::Color;
use crate::lesson::environment::{ConstantEnvironment, Environment};
use crate::lesson::geometry::{IntersectionInfo, Plane, Sphere};
use crate::lesson::light::PointLight;
use crate::lesson::math::{OrthonormalBasis, Vector};
use crate::lesson::node::Node;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{Scene, TraceContext};
use crate::lesson::shader::{IntoShader, Shader};
use crate::lesson::transform::Transform;
use std::sync::Arc;

/// How far a check lets a colour pass what it expects, per channel: one 8-bit level at white, 1/255, as
/// the end-of-run report's energy check (a mean of equal colours exceeds each by a few units in the last
/// place, far below it; a sum of N rays exceeds it by up to N).
pub const ONE_LEVEL: f32 = 1.0 / 255.0;

/// The random stream of the kit's shading, apart from the seed a test gives.
const KIT_KEY: u64 = 0x5445_5354_4b49_5400;

/// How deep the rays of a shaded hit may go: a glass ball's way in, through and out, and more.
const KIT_DEPTH: u32 = 10;

/// One hit of a surface, ready to shade without a render: the scene it is in (the surface as its only node,
/// and the lights, environment and ambient light given to it) and the ray that hits it.
#[derive(Clone)]
pub struct OneHit {
    scene: Scene,
    ray: Ray,
}

impl OneHit {
    /// A hit at `point` of the plane through it with the unit normal `normal`, by a ray arriving in the
    /// unit direction `incoming` (against the normal: `incoming.dot(normal) < 0`); the plane's u/v there are
    /// (0, 0). No lamp, a black sky and no ambient light, until given.
    ///
    /// Panics if `incoming` does not arrive against the normal, as a test's assertion would.
    pub fn on_plane(point: Vector, normal: Vector, incoming: Vector) -> OneHit {
        OneHit::on_plane_at(point, normal, incoming, (0.0, 0.0))
    }

    /// [`OneHit::on_plane`], the plane's u/v at the hit being `uv` (they run along two directions in the
    /// plane, a unit of u/v per unit of length).
    pub fn on_plane_at(point: Vector, normal: Vector, incoming: Vector, (u, v): (f32, f32)) -> OneHit {
        // The canonical plane y = 0 turned so that +Y is the normal: pitch tilts it from +Y, yaw turns the
        // tilt about +Y (the course's rotation takes +Y to (sin p sin y, cos p, -sin p cos y)); then moved
        // so that its point (u, 0, v) is `point`.
        let pitch = normal.y.clamp(-1.0, 1.0).acos().to_degrees();
        let yaw = normal.x.atan2(-normal.z).to_degrees();
        let turn = Transform::IDENTITY.rotate(yaw, pitch, 0.0);
        let transform = turn.translate(point - turn.point_to_world(Vector::new(u, 0.0, v)));
        OneHit::of(Node::new(Plane::new(0.0, f32::INFINITY), Chalk), Some(transform), point, normal, incoming)
    }

    /// A hit of the sphere of `radius` around `centre`, where its unit normal is `normal`, by a ray arriving
    /// in the unit direction `incoming` (against the normal). No lamp, a black sky and no ambient light,
    /// until given.
    ///
    /// Panics if `incoming` does not arrive against the normal, as a test's assertion would.
    pub fn on_sphere(centre: Vector, radius: f32, normal: Vector, incoming: Vector) -> OneHit {
        let node = Node::new(Sphere::new(centre, radius), Chalk);
        OneHit::of(node, None, centre + radius * normal, normal, incoming)
    }

    /// The hit of `node`, placed by `transform`, at `point`, arriving along `incoming`.
    fn of(node: Node, transform: Option<Transform>, point: Vector, normal: Vector, incoming: Vector) -> OneHit {
        assert!(
            incoming.dot(normal) < 0.0,
            "OneHit: the ray must arrive against the normal: incoming {incoming} and normal {normal} have a dot \
             product of {}",
            incoming.dot(normal)
        );
        let start = point - incoming;
        let mut scene = Scene::new(Camera::look_at(start, point, 60.0));
        scene.max_depth = KIT_DEPTH;
        scene.add(Node { transform, ..node }.named("surface"));
        OneHit { scene, ray: Ray::new(start, incoming) }
    }

    /// The same hit, with `light` shining on it too.
    pub fn with_light(mut self, light: PointLight) -> OneHit {
        self.scene.lights.push(light);
        self
    }

    /// The same hit, with what rays that hit nothing see.
    pub fn with_environment(mut self, environment: impl Environment) -> OneHit {
        self.scene.environment = Some(Arc::new(environment));
        self
    }

    /// The same hit, with ambient light.
    pub fn with_ambient(mut self, ambient: Color) -> OneHit {
        self.scene.ambient = ambient;
        self
    }

    /// The scene the hit is in (its surface is node 0, named `surface`).
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The ray that hits the surface.
    pub fn ray(&self) -> Ray {
        self.ray
    }

    /// The hit as a shader is given it: the point, the normal, the distance and the u/v.
    pub fn info(&self) -> IntersectionInfo {
        self.scene.closest_hit(&self.ray).expect("the ray of a OneHit hits its surface").0
    }

    /// The colour `shader` gives this hit, its random numbers from the stream of seed 0.
    pub fn shade(&self, shader: impl IntoShader) -> Color {
        self.shade_seeded(shader, 0)
    }

    /// The colour `shader` gives this hit, its random numbers from the stream of `seed` (each seed a shading
    /// of its own, the same on every run): the surface is given the shader, so that its rays that find the
    /// surface again are shaded by it too, and the hit is shaded in a fresh context.
    pub fn shade_seeded(&self, shader: impl IntoShader, seed: u64) -> Color {
        let mut scene = self.scene.clone();
        scene.nodes[0].shader = shader.into_shader();
        let scene = scene.prepared();
        let (info, node) = scene.closest_hit(&self.ray).expect("the ray of a OneHit hits its surface");
        let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[KIT_KEY, seed]));
        node.shader.shade(&self.ray, &info, &mut ctx)
    }
}

/// The stand-in shader of a [`OneHit`]'s surface until a shader is given to it: black.
struct Chalk;

impl Shader for Chalk {
    fn shade(&self, _ray: &Ray, _info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {
        Color::BLACK
    }
}

/// A sky whose colour tells the direction: each channel is 0.5 + 0.5 times the direction's component
/// (x red, y green, z blue), so a ray sent another way brings back another colour.
#[derive(Clone, Copy, Debug)]
pub struct DirectionSky;

impl Environment for DirectionSky {
    fn get(&self, dir: Vector) -> Color {
        Color::new(0.5 + 0.5 * dir.x, 0.5 + 0.5 * dir.y, 0.5 + 0.5 * dir.z)
    }
}

/// What a check found wrong, in one message naming the shader, the hit and the colours.
#[derive(Clone, PartialEq, Eq)]
pub struct CheckFailed(pub String);

impl std::fmt::Display for CheckFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// The message itself, so that `check(..).unwrap()` and a test returning `Result` print it as it is.
impl std::fmt::Debug for CheckFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CheckFailed {}

/// The hits the furnace and the limit are checked at: a plane and a sphere, each hit head-on, at 45° and
/// at 80° from the normal, and what each is called.
fn check_hits() -> Vec<(String, OneHit)> {
    let normal = Vector::new(0.0, 1.0, 0.0);
    let mut hits = Vec::new();
    for degrees in [0.0f32, 45.0, 80.0] {
        let (sin, cos) = degrees.to_radians().sin_cos();
        let incoming = Vector::new(sin, -cos, 0.0);
        hits.push((
            format!("a plane hit {degrees}° from its normal"),
            OneHit::on_plane(Vector::ZERO, normal, incoming),
        ));
        let sphere = OneHit::on_sphere(Vector::new(0.0, -1.0, 0.0), 1.0, normal, incoming);
        hits.push((format!("a sphere hit {degrees}° from its normal"), sphere));
    }
    hits
}

/// A colour as its three linear channels, for a message.
fn rgb(c: Color) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.r(), c.g(), c.b())
}

/// Whether each channel of `color` is at most `limit`'s plus [`ONE_LEVEL`] (false for NaN).
fn within(color: Color, limit: Color) -> bool {
    color.to_array().iter().zip(limit.to_array()).all(|(&c, l)| c <= l + ONE_LEVEL)
}

/// The furnace at one point: under a white sky of 1 in every direction, with no lamp and no ambient light,
/// `shader` is shaded `samples` times (each with random numbers of its own) at each of six hits (a plane and
/// a sphere, head-on, at 45° and at 80°), and fails if a colour passes the 1 that arrived by more than
/// [`ONE_LEVEL`] in a channel: a shader that sends rays and weighs what they bring back returns at most
/// what arrived (a mean of N rays, a mirror's colour of at most 1, a glass's Fresnel split); the naive sum
/// of N rays returns up to N times it, a multiplier above 1 that much more. A shader that glows (light of its
/// own) fails it, as it should fail a furnace.
pub fn check_furnace(shader: impl IntoShader, samples: u32) -> Result<(), CheckFailed> {
    let shader = shader.into_shader();
    for (what, hit) in check_hits() {
        let hit = hit.with_environment(ConstantEnvironment(Color::WHITE));
        for seed in 0..samples as u64 {
            let color = hit.shade_seeded(shader.clone(), seed);
            if !within(color, Color::WHITE) {
                return Err(CheckFailed(format!(
                    "{} returned {} at {what} (seed {seed}) under a white sky of 1 and no lamp: {:.2} times the \
                     light that arrived; a sum of N rays not divided by N, or a factor above 1, gains energy",
                    shader.name(),
                    rgb(color),
                    color.max_channel()
                )));
            }
        }
    }
    Ok(())
}

/// The mirror limit: at each of six hits (a plane and a sphere, head-on, at 45° and at 80°), under
/// [`DirectionSky`] (whose colour tells the direction), `shader` must give the colour `mirror` gives, within
/// [`ONE_LEVEL`] per channel, with each of the first four seeds' random numbers. For a glossy shader at
/// roughness 0 (glossiness 1) and the perfect `Reflection` of its colour: every ray it sends is the mirror's
/// one, and their mean is the mirror's colour.
pub fn check_mirror_limit(shader: impl IntoShader, mirror: impl IntoShader) -> Result<(), CheckFailed> {
    const SEEDS: u64 = 4;
    let (shader, mirror) = (shader.into_shader(), mirror.into_shader());
    for (what, hit) in check_hits() {
        let hit = hit.with_environment(DirectionSky);
        for seed in 0..SEEDS {
            let (mine, theirs) = (hit.shade_seeded(shader.clone(), seed), hit.shade_seeded(mirror.clone(), seed));
            let differ = |a: Color, b: Color| !(within(a, b) && within(b, a));
            if differ(mine, theirs) {
                return Err(CheckFailed(format!(
                    "{} returned {} at {what} (seed {seed}) where the mirror {} returns {}, under a sky whose \
                     colour tells the direction",
                    shader.name(),
                    rgb(mine),
                    mirror.name(),
                    rgb(theirs)
                )));
            }
        }
    }
    Ok(())
}

/// `hits` random hits of planes and spheres (random points within 100 units of the origin, random normals,
/// rays arriving up to 89° from the normal, spheres of radius 0.1 to 10, planes' u/v within 10 of 0), each under
/// [`DirectionSky`] with a lamp and ambient light: fails at the first where `shader` returns a NaN or
/// infinite colour, naming it. The same hits on every run.
pub fn check_finite(shader: impl IntoShader, hits: u32) -> Result<(), CheckFailed> {
    const MAX_ANGLE: f32 = 89.0;
    let shader = shader.into_shader();
    let mut rng = Rng::for_keys(&[KIT_KEY, u64::from(hits)]);
    let mut uniform = |low: f32, high: f32| low + (high - low) * rng.next_f32();
    for i in 0..hits {
        let point = Vector::new(uniform(-100.0, 100.0), uniform(-100.0, 100.0), uniform(-100.0, 100.0));
        // A uniform unit normal, and a ray arriving at most MAX_ANGLE from it, in any plane about it.
        let z = uniform(-1.0, 1.0);
        let phi = uniform(0.0, std::f32::consts::TAU);
        let normal = Vector::new((1.0 - z * z).sqrt() * phi.cos(), (1.0 - z * z).sqrt() * phi.sin(), z);
        let (angle, around) = (uniform(0.0, MAX_ANGLE).to_radians(), uniform(0.0, std::f32::consts::TAU));
        let basis = OrthonormalBasis::new(normal);
        let sideways = basis.tangent * around.cos() + basis.bitangent * around.sin();
        let incoming = (sideways * angle.sin() - normal * angle.cos()).normalize();
        let (surface, hit) = if i % 2 == 0 {
            ("plane", OneHit::on_plane_at(point, normal, incoming, (uniform(-10.0, 10.0), uniform(-10.0, 10.0))))
        } else {
            let radius = uniform(0.1, 10.0);
            ("sphere", OneHit::on_sphere(point - radius * normal, radius, normal, incoming))
        };
        let lamp = PointLight::new(point + 10.0 * normal + 5.0 * sideways, Color::WHITE, 100.0);
        let hit = hit.with_environment(DirectionSky).with_light(lamp).with_ambient(Color::gray(0.1));
        let color = hit.shade_seeded(shader.clone(), u64::from(i));
        if !color.is_finite() {
            return Err(CheckFailed(format!(
                "{} returned {} at random hit {i} of {hits}: a {surface} at {point} with the normal {normal}, the \
                 ray arriving along {incoming}, u/v {:?}",
                shader.name(),
                rgb(color),
                hit.info().uv()
            )));
        }
    }
    Ok(())
}
