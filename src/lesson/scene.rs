//! The scene and the slides' global `raytrace()`.
//!
//! `TraceContext` is what the course's C++ keeps in globals: the scene, the ray-depth limit, the random
//! generator of the pixel being rendered and the ray counters. Shaders receive it and call
//! [`TraceContext::raytrace`] to follow reflected and refracted rays, and [`TraceContext::visible`] for
//! shadow rays (through [`crate::lesson::light::light_loop`], which adds the caustic light of the photon map as well). One context exists
//! per pixel (and wavelength pass) being rendered, so threads never share one.
//!
//! Adaptive ray-tree depth control (the classic Whitted optimisation, beyond the slides): besides the
//! slides' `MAX_RAY_DEPTH`, `raytrace` returns black at once for a ray whose `weight` (the product of the
//! multipliers, blends and Fresnel factors along its path) is below [`Scene::min_ray_weight`]: what such a ray
//! brings back cannot move its pixel by a whole 8-bit level (see [`srgb8_finest_step`]). Glass and mirrors stop
//! recursing as soon as nothing visible is left, instead of always going `max_depth` levels down.

use crate::files::workers::NESTED_CALLS;
use crate::lesson::beyond::{Step, Steps};
use crate::lesson::branching::Shading;
use crate::lesson::camera::Camera;
use crate::lesson::color::{Color, srgb_to_linear};
use crate::lesson::environment::{ConstantEnvironment, Environment, Sky};
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::{Geometry, Hit, IntersectionInfo};
use crate::lesson::light::PointLight;
use crate::lesson::math::{Vector, max_abs};
use crate::lesson::node::{Node, NodeTree, any_of, closest_of, nearest_of};
use crate::lesson::observer::{Observer, Stop};
use crate::lesson::photon_map::{PhotonMap, PhotonSettings};
use crate::lesson::prepared::Preparation;
use crate::lesson::problems::{Problems, Source};
use crate::lesson::ray::{Ray, spawn_point};
use crate::lesson::rng::Rng;
pub use crate::lesson::sampling::PixelSample;
use crate::lesson::shader::{Layer, MAX_SHADES_PER_HIT, Shader, shades_per_hit};
use crate::lesson::spectral::Illuminant;
use crate::lesson::texture::Texture;
use crate::lesson::topic::Recorder;
use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::Arc;

// The slides' raytrace first (the nearest hit, its shader's colour, the shadow rays); the scene after it.
impl<'a> TraceContext<'a> {
    /// The slides' `raytrace(ray)` ("Reflection v0.2"): the colour seen along the ray. Black past the depth
    /// limit (or the [`RECURSION_SAFETY_CAP`]), or when the ray's weight is too small to show (adaptive depth
    /// control, a step); the environment when nothing is hit; otherwise whatever the hit node's shader says.
    /// A ray over its shading point's budget is not traced and brings back its siblings' mean colour
    /// ([`crate::lesson::branching`]). An observer in the context (the ray tree) is told what it does: the
    /// same code makes the picture and the ray tree, compiled once with the reports to the observer and once
    /// without them, for every render but one pixel's.
    #[inline(always)]
    pub fn raytrace(&mut self, ray: &Ray) -> Color {
        if self.observer.is_some() {
            return self.raytrace_watched(ray);
        }
        self.raytrace_unwatched(ray)
    }

    /// `raytrace` with no observer to tell.
    #[inline(never)]
    fn raytrace_unwatched(&mut self, ray: &Ray) -> Color {
        self.trace::<false>(ray)
    }

    /// `raytrace` with an observer to tell.
    #[inline(never)]
    fn raytrace_watched(&mut self, ray: &Ray) -> Color {
        self.trace::<true>(ray)
    }

    /// `raytrace`, telling the observer what it does when `WATCHED`.
    #[inline(always)]
    fn trace<const WATCHED: bool>(&mut self, ray: &Ray) -> Color {
        self.tell::<WATCHED>(|o| o.ray_begins(ray));
        // A student's shader's ray is at least one level deeper than the ray it shades: one made with
        // `Ray::new` (depth 0) cannot restart the count, so the recursion stops at the depth limit whatever
        // the shader does.
        let restarted;
        let ray = if ray.depth < self.shading.least_depth {
            restarted = self.restarted(ray);
            &restarted
        } else {
            ray
        };
        self.check_direction(ray.dir);
        if ray.depth > self.scene.max_depth {
            return self.stop::<WATCHED>(Stop::DepthLimit);
        }
        if ray.depth > RECURSION_SAFETY_CAP {
            self.counters.capped_rays += 1;
            return self.stop::<WATCHED>(Stop::SafetyCap);
        }
        if ray.weight < self.scene.min_ray_weight {
            self.counters.steps_reached[Step::AdaptiveDepth as usize] += 1;
            if self.scene.steps.has(Step::AdaptiveDepth) {
                beyond!(AdaptiveDepth);
                self.counters.pruned_rays += 1;
                return self.stop::<WATCHED>(Stop::WeightCutoff);
            }
        }
        if let Some(shared) = self.shading.share(ray.weight) {
            self.counters.shared_rays += 1;
            self.tell::<WATCHED>(|o| o.ray_ends(shared, Some(Stop::Shared)));
            return shared;
        }
        if !self.within_branch_budget(ray.depth) {
            self.counters.over_budget_rays += 1;
            return self.stop::<WATCHED>(Stop::BranchBudget);
        }
        self.counters.rays_by_depth[(ray.depth as usize).min(15)] += 1;
        let scene = self.scene;
        let (color, stop) = if !scene.steps.has(Step::TwoPhaseHit) {
            self.trace_by_loop::<WATCHED>(ray)
        } else {
            beyond!(TwoPhaseHit);
            match scene.nearest_hit_index(self.node_tree, ray) {
                Some((hit, i)) => self.shade_any_hit::<WATCHED>(i, ray, &hit),
                None => (self.environment(ray), Some(Stop::Missed)),
            }
        };
        self.shading.traced(color);
        self.tell::<WATCHED>(|o| o.ray_ends(color, stop));
        color
    }

    /// `ray`, traced by a student's shader with a depth below its own ray's, at the depth it should have,
    /// counted against the node whose shader traced it (the rare path, out of line).
    #[cold]
    #[inline(never)]
    fn restarted(&mut self, ray: &Ray) -> Ray {
        let scene = self.scene;
        let node = self.shading.node().and_then(|node| scene.nodes.iter().position(|n| std::ptr::eq(n, node)));
        let source = node.map_or(Source::Environment, Source::Node);
        Problems::count(&mut self.counters.problems.restarted_depth, source);
        Ray { depth: self.shading.least_depth, ..*ray }
    }

    /// The colour of the hit `hit` of `ray` on node `i`, any node, with its surface described as its shape
    /// does ([`Node::checked_surface`]), told to the observer, if there is one: what the shader makes of it, or what
    /// the environment shows if the shape cannot find the hit again.
    #[inline(always)]
    fn shade_any_hit<const WATCHED: bool>(&mut self, i: usize, ray: &Ray, hit: &Hit) -> (Color, Option<Stop>) {
        let scene = self.scene;
        let Some((info, unit_normal)) = scene.nodes[i].checked_surface(ray, hit) else {
            return (self.environment(ray), Some(Stop::Missed));
        };
        self.shade_found::<WATCHED>(i, ray, &info, unit_normal)
    }

    /// `raytrace`'s hit as the slide finds it ([`Scene::closest_by_loop`]: every node intersected in full),
    /// shaded as the two-phase hit's is: the usual case without the step [`Step::TwoPhaseHit`], kept out of
    /// the default reading's `raytrace`.
    #[inline(never)]
    fn trace_by_loop<const WATCHED: bool>(&mut self, ray: &Ray) -> (Color, Option<Stop>) {
        let scene = self.scene;
        match scene.closest_by_loop(ray) {
            Some((info, i, unit_normal)) => self.shade_found::<WATCHED>(i, ray, &info, unit_normal),
            None => (self.environment(ray), Some(Stop::Missed)),
        }
    }

    /// The colour of the hit `info` of `ray` on node `i`, any node, told to the observer, if there is one: a
    /// node of the workbook's own shape and shaders is shaded without a shading point of its own
    /// ([`crate::lesson::branching`]).
    #[inline(always)]
    fn shade_found<const WATCHED: bool>(
        &mut self,
        i: usize,
        ray: &Ray,
        info: &IntersectionInfo,
        unit_normal: bool,
    ) -> (Color, Option<Stop>) {
        let scene = self.scene;
        let node = &scene.nodes[i];
        self.tell::<WATCHED>(|o| o.ray_hits(&scene.node_name(node), node.shader.name(), info));
        self.met_dispersion |= ray.wavelength.is_some() && node.shader.is_dispersive();
        if node.is_workbook() {
            return (self.shade_workbook_hit(i, ray, info), None);
        }
        (self.shade_hit(i, ray, info, unit_normal), None)
    }

    /// The colour of the hit `info` of `ray` on node `i`, one of the workbook's own shapes under the
    /// workbook's own shaders ([`Node::is_workbook`]): shaded with no shading point of its own; a NaN or
    /// infinite colour it makes is counted against it.
    #[inline(always)]
    fn shade_workbook_hit(&mut self, i: usize, ray: &Ray, info: &IntersectionInfo) -> Color {
        let outer = (self.shading.workbook, self.shading.non_finite_below);
        (self.shading.workbook, self.shading.non_finite_below) = (true, false);
        let color = self.scene.nodes[i].shader.shade(ray, info, self);
        self.note_non_finite(i, color);
        (self.shading.workbook, self.shading.non_finite_below) = outer;
        color
    }

    /// What a ray that hit nothing sees: the environment, or black.
    #[inline(always)]
    fn environment(&mut self, ray: &Ray) -> Color {
        let color = self.sky.get(ray.dir);
        if !color.is_finite() {
            self.note_environment_non_finite();
        }
        color
    }

    /// Counts an environment colour that was NaN or infinite (the rare path, out of line).
    #[cold]
    #[inline(never)]
    fn note_environment_non_finite(&mut self) {
        Problems::count(&mut self.counters.problems.non_finite, Source::Environment);
    }

    /// A ray not traced, for the reason `stop`: black.
    #[inline(always)]
    fn stop<const WATCHED: bool>(&mut self, stop: Stop) -> Color {
        self.tell::<WATCHED>(|o| o.ray_ends(Color::BLACK, Some(stop)));
        Color::BLACK
    }

    /// Whether the point `to` can be seen from the hit point `from` (a shadow ray).
    #[inline(always)]
    pub fn visible(&mut self, from: &IntersectionInfo, to: Vector) -> bool {
        self.counters.shadow_rays += 1;
        let start = spawn_point(from.ip, from.geometric_normal, from.error, to - from.ip);
        let to_light = to - start;
        let t_max = to_light.length();
        let ray = Ray::new(start, to_light / t_max);
        !self.scene.intersects_through(self.node_tree, &ray, t_max)
    }
}

/// The slide's `MAX_RAY_DEPTH` default ("Reflection v0.2" shows 2); scenes set their own.
pub const MAX_RAY_DEPTH: u32 = 2;

/// A hard limit on the depth of recursion that holds whatever `max_depth` says, even "no limit" (the
/// slide's Reflection v0.1): between two facing mirrors a ray can bounce forever, and each bounce is a
/// nested call of `raytrace`, so without it the program would die of a stack overflow. Rays stopped here
/// return black and are counted in [`Counters::capped_rays`]. It is the depth the renderer's worker threads
/// have the stack for ([`crate::files::workers::NESTED_CALLS`], 1000).
pub const RECURSION_SAFETY_CAP: u32 = NESTED_CALLS;

/// The smallest amount of linear light that moves an 8-bit sRGB value by a whole level: the linear value of
/// the first code above black. The codes are closest together there (the sRGB curve starts with a straight
/// segment and grows steeper after it), so any smaller change, added to any pixel, moves its code by at
/// most one level. A ray whose weight is below this cannot change its pixel by more than one level when what
/// it sees is no brighter than white, the default [`Scene::min_ray_weight`]. What a pruned ray would have
/// seen may be brighter (the sun of an HDR sky), and a sample may prune several rays: the guarantee is a
/// statistical one, which `tests/workbook/layered_fresnel.rs` checks on the examples (within one level of
/// `--exhaustive` on at least 99.9% of pixels).
pub fn srgb8_finest_step() -> f32 {
    srgb_to_linear(1.0 / 255.0)
}

/// Everything a picture shows: the camera, the nodes, the lights, the environment and the settings of the
/// recursion (the slides' global scene).
#[derive(Clone)]
pub struct Scene {
    /// The camera the picture is seen through.
    pub camera: Camera,
    /// The objects, in the order they were added (the ray tree names an unnamed node by its index here).
    pub nodes: Vec<Node>,
    /// The point lights.
    pub lights: Vec<PointLight>,
    /// What rays that hit nothing see; black when `None`.
    pub environment: Option<Arc<dyn Environment>>,
    /// Ambient light added by the diffuse shaders (the course's `ambientLight`).
    pub ambient: Color,
    /// Rays deeper than this return black (the slide's `MAX_RAY_DEPTH`).
    pub max_depth: u32,
    /// Rays whose `weight` is below this return black without being traced (adaptive ray-tree depth
    /// control, the step [`Step::AdaptiveDepth`]). [`srgb8_finest_step`] by default; 0 traces every ray to
    /// `max_depth`, as the render does without the step (`--exhaustive`, `--slide`).
    pub min_ray_weight: f32,
    /// Which steps beyond the slides the render takes ([`crate::lesson::beyond`]): every one by default,
    /// none with `--slide` ([`Steps::SLIDES`]).
    pub steps: Steps,
    /// How the caustic photon map is made (no photons by default).
    pub photons: PhotonSettings,
    /// The spectrum a white light stands for when wavelengths are traced (a dispersive scene): D65 by default.
    pub illuminant: Illuminant,
    /// The caustic photon map, built before rendering ([`PhotonMap::build`]); `None` renders without
    /// caustics.
    pub photon_map: Option<Arc<PhotonMap>>,
    /// What the renderer works out once from the nodes ([`Scene::prepared`]): the node tree; `None` until then.
    preparation: Option<Arc<Preparation>>,
    /// Where the origin of the coordinates the renderer computes with lies in the world the scene was built
    /// in: zero, or the camera's first position once [`Scene::relative_to_camera`] moved the scene.
    world_origin: Vector,
}

impl Scene {
    /// An empty scene seen through `camera`: no nodes or lights, a black environment, no ambient light, the
    /// slide's [`MAX_RAY_DEPTH`], the default adaptive cut-off and no photon map.
    pub fn new(camera: Camera) -> Scene {
        Scene {
            camera,
            nodes: Vec::new(),
            lights: Vec::new(),
            environment: None,
            ambient: Color::BLACK,
            max_depth: MAX_RAY_DEPTH,
            min_ray_weight: srgb8_finest_step(),
            steps: Steps::default(),
            photons: PhotonSettings::default(),
            illuminant: Illuminant::default(),
            photon_map: None,
            preparation: None,
            world_origin: Vector::ZERO,
        }
    }

    /// Adds a node and returns the scene, for building scenes in one expression.
    pub fn add(&mut self, node: Node) -> &mut Scene {
        self.nodes.push(node);
        self
    }

    /// Moves the whole scene so that the camera stands at the origin, when that makes the scene's
    /// coordinates smaller: when the camera is farther from the origin than every corner of every bounded
    /// node is from the camera. Every node is then translated by minus the camera's position (after its
    /// own transform), and so are the lights. The picture does not change, but the coordinates the renderer
    /// computes with become distances from the camera, so a scene far from the origin keeps the precision
    /// of one near it (pbrt-v4's "camera-world" space). A scene around the origin is left as it is, and
    /// costs nothing. Environments depend on directions only and are unaffected. The examples do this
    /// before building the photon map and rendering.
    ///
    /// What a shader sees then is camera-relative too: `info.ip`, `ray.start` and the lights' positions.
    /// Directions and distances are the same as in the world; a shader or texture that needs where a point
    /// is in the world the scene was built in (bands at fixed heights) asks [`Scene::world_position`].
    ///
    /// A step beyond the slides ([`Step::CameraRelative`]): the course always renders in world coordinates;
    /// in f32, a scene moved 1e6 from the origin would then be rounded to 0.0625 units around its hit points.
    /// A scene whose `steps` leave it out is left as it is.
    pub fn relative_to_camera(&mut self) {
        if !self.steps.has(Step::CameraRelative) || !self.is_far_from_the_origin() {
            return;
        }
        beyond!(CameraRelative);
        let camera = self.camera.position;
        for node in &mut self.nodes {
            node.transform = Some(node.transform.unwrap_or_default().translate(-camera));
        }
        for light in &mut self.lights {
            light.position -= camera;
        }
        self.camera.position = Vector::ZERO;
        self.world_origin += camera;
    }

    /// Whether the camera is farther from the origin than from every node's box, which is when
    /// [`Scene::relative_to_camera`] moves the scene (nearer, world coordinates are as precise).
    pub(crate) fn is_far_from_the_origin(&self) -> bool {
        let camera = self.camera.position;
        let corners = self.nodes.iter().filter_map(Node::bounds).flat_map(|b| b.corners());
        max_abs(camera) > corners.map(|c| max_abs(c - camera)).fold(0.0, f32::max)
    }

    /// Where `point`, in the coordinates the renderer computes with (a hit's `info.ip`), lies in the world the
    /// scene was built in: the same point, unless [`Scene::relative_to_camera`] moved the scene to the
    /// camera. A shader asks it as `ctx.scene.world_position(info.ip)`. Its precision is that of the world's
    /// coordinates (f32 rounds a point 1e4 from the origin to about 0.001), which is what a pattern fixed
    /// in the world needs; the renderer's own work stays camera-relative.
    pub fn world_position(&self, point: Vector) -> Vector {
        point + self.world_origin
    }

    /// Checks what can only be checked once the scene is complete: every light is made of numbers (no NaN,
    /// no infinity: [`PointLight::check`]), every node's transform is invertible, and no node's shader shades
    /// more than [`MAX_SHADES_PER_HIT`] shaders at a hit (Layered shaders whose layers share the shaders below
    /// them multiply the work with each level).
    pub fn check(&self) -> Result<()> {
        self.lights.iter().enumerate().try_for_each(|(index, light)| light.check(index))?;
        self.nodes.iter().filter_map(|n| n.transform.as_ref()).try_for_each(|t| t.check())?;
        let mut counted = HashMap::new();
        for node in &self.nodes {
            let shades = shades_per_hit(&node.shader, &mut counted);
            if shades > MAX_SHADES_PER_HIT {
                return Err(Error::parameter(
                    "node",
                    self.node_name(node),
                    format!(
                        "its shader shades {shades} shaders at every hit (the layers of its Layered shaders, theirs \
                         and so on, each as often as a layer names it); a hit may shade at most {MAX_SHADES_PER_HIT}"
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Whether some node's shader depends on the wavelength ([`crate::lesson::shader::Shader::is_dispersive`]):
    /// only then does the renderer trace wavelengths. A shader that reads `ray.wavelength` without saying so
    /// is traced in white light; the end-of-run report names it ([`crate::lesson::diagnostics`]).
    pub fn is_dispersive(&self) -> bool {
        self.nodes.iter().any(|n| n.shader.is_dispersive())
    }

    /// This scene's camera, lights, environment and settings around `nodes` instead of its own, not
    /// prepared and without a photon map.
    pub(crate) fn around(&self, nodes: Vec<Node>) -> Scene {
        Scene {
            camera: self.camera,
            nodes,
            lights: self.lights.clone(),
            environment: self.environment.clone(),
            ambient: self.ambient,
            max_depth: self.max_depth,
            min_ray_weight: self.min_ray_weight,
            steps: self.steps,
            photons: self.photons,
            illuminant: self.illuminant,
            photon_map: None,
            preparation: None,
            world_origin: self.world_origin,
        }
    }

    /// The scene ready to be traced: itself if it was prepared already and its nodes and steps have not
    /// changed since, else a copy prepared for them ([`crate::lesson::prepared`]: the BVH over its nodes, if
    /// it has enough of them and takes that step; its meshes tested as its steps say). The
    /// renderer and the photon tracer trace the prepared scene; preparing it once before both saves the
    /// second preparation.
    pub fn prepared(&self) -> Cow<'_, Scene> {
        match &self.preparation {
            Some(p) if p.describes(&self.nodes, self.steps) => Cow::Borrowed(self),
            _ => {
                let mut scene = self.clone();
                scene.preparation = Some(Arc::new(Preparation::new(&mut scene.nodes, self.steps)));
                Cow::Owned(scene)
            }
        }
    }

    /// The environment as a ray that hits nothing reads it: its case of [`Sky`], its images read as the
    /// scene's steps say ([`Sky::under`]); black when the scene has none.
    pub(crate) fn sky(&self) -> Sky {
        let black = || Sky::Constant(ConstantEnvironment(Color::BLACK));
        self.environment.as_ref().map_or_else(black, |environment| Arc::clone(environment).into_sky().under(self.steps))
    }

    /// The BVH over the nodes, if the scene was prepared with one ([`Scene::prepared`]).
    #[inline(always)]
    fn tree(&self) -> Option<&NodeTree> {
        self.preparation.as_ref().and_then(|p| p.node_tree.as_ref())
    }

    /// The name of a node of this scene: its own ([`Node::named`]), or its geometry and its position in
    /// `nodes` ("Sphere #2").
    pub fn node_name(&self, node: &Node) -> String {
        if let Some(name) = &node.name {
            return name.clone();
        }
        let index = self.nodes.iter().position(|n| std::ptr::eq(n, node));
        format!("{} #{}", node.geometry.name(), index.map_or("?".to_string(), |i| i.to_string()))
    }

    /// The nearest node hit by the ray, and where (the first phase of the two-phase hit, [`Step::TwoPhaseHit`]:
    /// [`Node::hit`] on every node, or on the nodes the node tree leads the ray to).
    #[inline(always)]
    pub fn nearest_hit(&self, ray: &Ray) -> Option<(Hit, &Node)> {
        self.nearest_hit_index(self.tree(), ray).map(|(hit, i)| (hit, &self.nodes[i]))
    }

    /// [`Scene::nearest_hit`], the node given by its index, through the scene's node tree `tree`
    /// ([`Scene::tree`], which a trace context looks up once, not for every ray).
    #[inline(always)]
    fn nearest_hit_index(&self, tree: Option<&NodeTree>, ray: &Ray) -> Option<(Hit, usize)> {
        match tree {
            Some(tree) => tree.nearest_of(&self.nodes, ray),
            None => nearest_of(&self.nodes, ray),
        }
    }

    /// The closest node hit by the ray, and its surface there: the slide's loop over the nodes, each
    /// intersected in full, or, with the step [`Step::TwoPhaseHit`], the nearest
    /// hit found first ([`Scene::nearest_hit`]) and only the winner's surface described ([`Node::surface`]).
    #[inline(always)]
    pub fn closest_hit(&self, ray: &Ray) -> Option<(IntersectionInfo, &Node)> {
        self.checked_closest_hit(ray).map(|(info, i, _)| (info, &self.nodes[i]))
    }

    /// [`Scene::closest_hit`], the node given by its index, and whether the geometry gave a unit normal
    /// ([`Node::checked_surface`]).
    #[inline(always)]
    pub(crate) fn checked_closest_hit(&self, ray: &Ray) -> Option<(IntersectionInfo, usize, bool)> {
        if !self.steps.has(Step::TwoPhaseHit) {
            return self.closest_by_loop(ray);
        }
        beyond!(TwoPhaseHit);
        let (hit, i) = self.nearest_hit_index(self.tree(), ray)?;
        self.nodes[i].checked_surface(ray, &hit).map(|(info, unit_normal)| (info, i, unit_normal))
    }

    /// The slide's closest hit ("Model трансформация"): every node in turn intersected in full
    /// ([`Node::intersect`]), each searched up to the closest hit so far, so that a node added earlier keeps
    /// a tie; the node's index, and whether its geometry gave a unit normal.
    pub(crate) fn closest_by_loop(&self, ray: &Ray) -> Option<(IntersectionInfo, usize, bool)> {
        closest_of(self.nodes.len(), |i, t_max| self.nodes[i].checked_intersect(ray, t_max))
    }

    /// Whether anything is hit by the ray before `t_max`: the slide's loop over the nodes, each intersected
    /// in full, or, with the step [`Step::TwoPhaseHit`], each node's cheaper any-hit test (through the node
    /// tree, with that step).
    #[inline(always)]
    pub fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.intersects_through(self.tree(), ray, t_max)
    }

    /// [`Scene::intersects`], through the scene's node tree `tree` ([`Scene::tree`]).
    #[inline(always)]
    pub(crate) fn intersects_through(&self, tree: Option<&NodeTree>, ray: &Ray, t_max: f32) -> bool {
        if !self.steps.has(Step::TwoPhaseHit) {
            return self.nodes.iter().any(|node| node.intersect(ray, t_max).is_some());
        }
        match tree {
            Some(tree) => tree.intersects(&self.nodes, ray, t_max),
            None => any_of(&self.nodes, ray, t_max),
        }
    }
}

/// Rays traced, for the summary line and for tests that count them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Counters {
    /// Rays passed to `raytrace`, by depth (the last entry counts every depth from there on).
    pub rays_by_depth: [u64; 16],
    /// Shadow rays.
    pub shadow_rays: u64,
    /// Rays not traced because they were deeper than [`RECURSION_SAFETY_CAP`].
    pub capped_rays: u64,
    /// Rays not traced because their weight was below `Scene::min_ray_weight` (not part of the total).
    pub pruned_rays: u64,
    /// Rays not traced because their shading point had used its budget: they were given the mean of their
    /// traced siblings' colours (see [`crate::lesson::branching`]; not part of the total).
    pub shared_rays: u64,
    /// Rays not traced because their branch of the ray tree had traced
    /// [`RAYS_PER_BRANCH`](crate::lesson::branching::RAYS_PER_BRANCH) rays (black; not part of the total).
    pub over_budget_rays: u64,
    /// Camera samples that came back NaN or infinite, counted before the renderer cleans them (see
    /// [`crate::lesson::render::RenderSettings::sample`]): 0 in a sound render, which the tests check.
    pub non_finite_samples: u64,
    /// What went wrong, by node, for the end-of-run report ([`Problems::report`]).
    pub problems: Problems,
    /// For each step beyond the slides whose work depends on the rays, by [`Step`] (`Step as usize`), how
    /// often the render came where that step and the slide's version part, whether it took the step or
    /// not: a ray below the weight adaptive depth control cuts at, a bitmap texture read with a filter of
    /// its own through [`ColorSource::at`](crate::lesson::shader::ColorSource::at), a glossy mirror's disc points drawn by a sampler of its own, a `Layered` shader
    /// shaded. 0 tells that the step changed nothing in this render (the command line notes it).
    pub steps_reached: [u64; Step::ALL.len()],
}

impl Counters {
    /// All rays traced: camera, secondary and shadow rays.
    pub fn total(&self) -> u64 {
        self.rays_by_depth.iter().sum::<u64>() + self.shadow_rays
    }
    /// Adds `other`'s counts to these (the counters of rows rendered in parallel, summed).
    pub fn add(&mut self, other: &Counters) {
        let sum = |a: &mut [u64], b: &[u64]| a.iter_mut().zip(b).for_each(|(a, b)| *a += b);
        sum(&mut self.rays_by_depth, &other.rays_by_depth);
        self.shadow_rays += other.shadow_rays;
        self.capped_rays += other.capped_rays;
        self.pruned_rays += other.pruned_rays;
        self.shared_rays += other.shared_rays;
        self.over_budget_rays += other.over_budget_rays;
        self.non_finite_samples += other.non_finite_samples;
        self.problems.add(&other.problems);
        sum(&mut self.steps_reached, &other.steps_reached);
    }
}

/// The state a shader sees while one pixel is being rendered.
pub struct TraceContext<'a> {
    /// The scene being rendered.
    pub scene: &'a Scene,
    /// The random generator of the current pixel.
    pub rng: Rng,
    /// The camera sample being traced, when the context traces a pixel's samples: the renderer sets it
    /// before each camera ray. `None` (the default) when the rays belong to no pixel (tests, benchmarks).
    pub pixel_sample: Option<PixelSample>,
    /// The rays this context has traced so far.
    pub counters: Counters,
    /// The instrument watching the recursion, if any (the ray tree of `--trace-pixel`): see
    /// [`crate::lesson::observer`]. Shaders never use it; `raytrace`, the light loop and `shade_layer` report
    /// to it.
    pub observer: Option<&'a mut dyn Observer>,
    /// Set when a ray that carries a wavelength hits a node whose shader depends on it: from there on the
    /// path is its wavelength's own (hero-wavelength sampling splits there; see [`crate::lesson::render`]).
    pub met_dispersion: bool,
    /// What `raytrace` keeps of the shaders running, which bounds their rays ([`crate::lesson::branching`]).
    pub(crate) shading: Shading<'a>,
    /// The rays the current branch of the ray tree has traced ([`crate::lesson::branching::RAYS_PER_BRANCH`]).
    pub(crate) branch_rays: u32,
    /// The scene's environment as a ray that hits nothing reads it ([`Scene::sky`]), held here so that its
    /// look-up is a match over the workbook's environments, not a call through a trait object.
    sky: Sky,
    /// The scene's node tree, if it has one ([`Scene::tree`]), found once for every ray the context traces.
    node_tree: Option<&'a NodeTree>,
}

impl<'a> TraceContext<'a> {
    /// A context for tracing rays in `scene`, drawing its random numbers from `rng`; no pixel sample, no observer.
    pub fn new(scene: &'a Scene, rng: Rng) -> TraceContext<'a> {
        TraceContext {
            scene,
            rng,
            pixel_sample: None,
            counters: Counters::default(),
            observer: None,
            met_dispersion: false,
            shading: Shading::camera(),
            branch_rays: 0,
            sky: scene.sky(),
            node_tree: scene.tree(),
        }
    }

    /// Makes the context ready for the camera rays of another pixel (the renderer keeps one context for a
    /// row of pixels, each with its own random stream): their shading point starts afresh.
    pub(crate) fn restart_pixel(&mut self) {
        self.shading = Shading::camera();
    }

    /// One layer of a `Layered` shader (slide "Layered Shader"): what the layer's shader makes of the hit,
    /// times the layer's `weight` there (its blend, times what the layers above it let through). The same as
    /// `layer.shader.shade(ray, info, ctx) * weight`; going through the context lets an instrument show each
    /// layer's share of the colour.
    #[inline(always)]
    pub fn shade_layer(&mut self, layer: &Layer, ray: &Ray, info: &IntersectionInfo, weight: Color) -> Color {
        if self.observer.is_some() {
            return self.shade_layer_watched(layer, ray, info, weight);
        }
        self.begin_layer(ray);
        layer.shader.shade_layer(ray, info, self) * weight
    }

    /// [`TraceContext::shade_layer`], telling the observer where the layer begins and ends (kept out of the
    /// unwatched render's loop).
    #[inline(never)]
    fn shade_layer_watched(&mut self, layer: &Layer, ray: &Ray, info: &IntersectionInfo, weight: Color) -> Color {
        self.observe(|o| o.layer_begins(layer.shader.name(), layer.blend_tex.as_ref().map(Texture::name), ray));
        self.begin_layer(ray);
        let color = layer.shader.shade_layer(ray, info, self);
        self.observe(|o| o.layer_ends(color, weight));
        color * weight
    }

    /// One layer of the shading point begins, seen by `ray`: its rays get a budget of their own
    /// ([`crate::lesson::branching`]).
    #[inline(always)]
    pub(crate) fn begin_layer(&mut self, ray: &Ray) {
        self.shading.begin_layer(ray);
    }

    /// The observer, if there is one, as the recorder of what the techniques compute
    /// ([`crate::lesson::topic::record`]).
    #[inline(always)]
    pub(crate) fn recorder(&mut self) -> Option<&mut dyn Recorder> {
        self.observer.as_deref_mut().map(|o| o as &mut dyn Recorder)
    }

    /// Tells the observer what `report` says when `WATCHED` (the trace that has one); nothing otherwise.
    #[inline(always)]
    fn tell<const WATCHED: bool>(&mut self, report: impl FnOnce(&mut dyn Observer)) {
        if WATCHED {
            self.observe(report);
        }
    }

    /// Tells the observer, if there is one, what `report` says (see [`crate::lesson::observer`]); one test of
    /// an `Option` otherwise.
    #[inline(always)]
    pub(crate) fn observe(&mut self, report: impl FnOnce(&mut dyn Observer)) {
        if let Some(observer) = self.observer.as_deref_mut() {
            report(observer);
        }
    }
}
