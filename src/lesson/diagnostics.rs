//! What went wrong in a render, by node: the end-of-run report every render prints (beyond the slides).
//!
//! A mistake in a student's geometry or shader rarely stops a render; it shows as black or speckled
//! surfaces, or as nothing at all. `raytrace` counts, per node, what it can see go wrong while it traces
//! ([`TraceContext::raytrace`](crate::lesson::scene::TraceContext::raytrace)), at the cost of a few comparisons per ray:
//! - a colour that came back NaN or infinite, at the deepest shading point that made it (the first one
//!   whose rays all came back finite), or from the environment;
//! - a ray that found the surface it left again, right where it left it (the same node, closer than
//!   `sqrt(EPSILON)` times the point's coordinates, and the same face of a mesh or, on another shape,
//!   crossed from the side the ray left, see [`crate::lesson::branching`]): the shader's mistake if the ray
//!   started on the hit point itself (not made with `Ray::spawn`) or if the shape is one of the workbook's
//!   (which put their hit points on the surface), else the geometry's (a hit point off its surface by more
//!   than its error bound);
//! - a shader that returned more light than its rays and its light loop brought it (the energy check of
//!   [`crate::lesson::branching`]: a sum of N rays not divided by N);
//! - a normal that is not of unit length, or NaN, as the geometry returned it ([`Node::surface`](crate::lesson::node::Node::surface));
//! - a course helper's parameter a shader passed outside the range it takes (a glossiness outside (0, 1]
//!   given to `GlossyCone::new`, see [`crate::lesson::helper_ranges`]), with the worst value;
//! - a ray a shader traced in a direction that is not of unit length (its squared length off by more than
//!   four times the normal check's tolerance, which a reflection about a normal that passes that check never
//!   is; a NaN direction is left to the NaN check);
//!
//! and [`Problems::report`] turns the counts into one line each, naming the node and its shader. (A course
//! shader's parameter outside the range it takes, read from the scene and not from a ray, is the command
//! line's line after these: `crate::app::parameter_ranges`.)
//!
//! One mistake no ray shows: a shader whose colour depends on the ray's wavelength must say so
//! ([`Shader::is_dispersive`]), or the renderer traces its scene in white light (every ray's `wavelength`
//! is `None`) and never splits a path where it is hit. The renderer cannot see a shader read
//! `ray.wavelength`, and trying a shader at a few points cannot prove that it never does, so what it is
//! told is what it traces. After a render, [`undeclared_dispersion`] checks each shader that says "not
//! dispersive" at one point of its node: it traces the node alone, in white light and at both ends of the
//! visible spectrum, and a shader that gives them different colours is named in the report.

use crate::lesson::branching::RAYS_PER_BRANCH;
use crate::lesson::camera::CameraFrame;
use crate::lesson::color::Color;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{Counters, RECURSION_SAFETY_CAP, Scene, TraceContext};
use crate::lesson::shader::{Material, Shader};
use crate::lesson::spectral::{LAMBDA_MAX, LAMBDA_MIN};
use std::collections::{BTreeMap, HashSet};

pub use crate::lesson::problems::{Gains, Problems, Source};
use std::collections::BTreeSet;
use std::sync::Arc;

impl Problems {
    /// The end-of-run report of a render with these counters: one line for each kind of problem, naming
    /// the nodes (and their shaders) it came from, most frequent first; nothing for a sound render.
    pub fn report(counters: &Counters, scene: &Scene) -> Vec<String> {
        let problems = &counters.problems;
        let node = |i: usize| match scene.nodes.get(i) {
            Some(n) => format!("{} ({})", scene.node_name(n), n.shader.name()),
            None => format!("node #{i}"),
        };
        let mut lines = Vec::new();
        if counters.non_finite_samples > 0 {
            let sources = listed(&problems.non_finite, |s| match *s {
                Source::Node(i) => format!("the shader of {}", node(i)),
                Source::Environment => "the environment".to_string(),
            });
            lines.push(format!(
                "{} sample(s) came back NaN or infinite and were shown as black; made by {sources}; each count is of the \
                 NaN or infinite colours that source made, and one sample can carry several of them",
                counters.non_finite_samples
            ));
        }
        if !problems.restarted_depth.is_empty() {
            let sources = listed(&problems.restarted_depth, |s| match *s {
                Source::Node(i) => format!("the shader of {}", node(i)),
                Source::Environment => "a shader outside the scene's nodes".to_string(),
            });
            lines.push(format!(
                "rays were traced with a depth below the ray that made them (Ray::new starts at depth 0) and were \
                 counted at their real depth, so the recursion still stops at the depth limit; make them with \
                 ray.spawn(info, dir, attenuation), which is one level deeper and off the surface: {sources}"
            ));
        }
        let gains = problems.energy_gains.iter().enumerate().filter(|(_, g)| g.gained > 0 && 100 * g.gained >= g.hits);
        let gaining: BTreeMap<usize, u64> = gains.map(|(i, g)| (i, g.gained)).collect();
        // A direction made from a normal that is not of unit length is the normal's fault, named on its own line.
        let long = problems.long_directions.iter().filter(|(i, _)| !problems.bad_normals.contains_key(i));
        let directions: BTreeMap<usize, u64> = long.map(|(&i, &n)| (i, n)).collect();
        // A ray started off one of the workbook's shapes, which bound their hit points, that finds it again was
        // started elsewhere by its shader: the advice is the shader's, not the geometry's.
        let workbooks = |&(i, _): &(usize, u64)| scene.nodes.get(i).is_some_and(|n| n.geometry.bounds_its_hit_points());
        let (started_elsewhere, off_surface): (BTreeMap<_, _>, BTreeMap<_, _>) =
            problems.self_hits.clone().into_iter().partition(workbooks);
        for (counts, what, energy) in [
            (&problems.unspawned_rays, UNSPAWNED_RAYS, false),
            (&started_elsewhere, STARTED_ELSEWHERE, false),
            (&off_surface, SELF_HITS, false),
            (&gaining, ENERGY_GAINS, true),
            (&problems.bad_normals, BAD_NORMALS, false),
            (&directions, LONG_DIRECTIONS, false),
        ] {
            if !counts.is_empty() {
                lines.push(format!(
                    "{what}: {}",
                    listed(counts, |&i| match problems.energy_gains.get(i).filter(|_| energy) {
                        Some(g) => {
                            let share = 100.0 * g.gained as f64 / g.hits as f64;
                            format!("{}, up to {:.2} times, on {share:.0}% of its hits", node(i), g.largest)
                        }
                        None => node(i),
                    })
                ));
            }
        }
        if !problems.glossiness_out_of_range.is_empty() {
            let calls = problems.glossiness_out_of_range.iter();
            let calls = calls.map(|(&i, n)| format!("{} ({} calls, the worst {})", node(i), n.calls, n.worst));
            lines.push(format!("{GLOSSINESS_OUT_OF_RANGE}: {}", calls.collect::<Vec<_>>().join(", ")));
        }
        if !problems.undeclared_dispersion.is_empty() {
            let nodes: Vec<String> = problems.undeclared_dispersion.iter().map(|&i| node(i)).collect();
            lines.push(format!(
                "a shader gives rays of different wavelengths different colours, but its is_dispersive() says it \
                 does not depend on them, so this scene was traced in white light (ray.wavelength None) and no path \
                 was split there: return true from Shader::is_dispersive (a Layered shader asks its layers, and \
                 the texture a shader names asks Texture::is_dispersive): {}",
                nodes.join(", ")
            ));
        }
        if counters.over_budget_rays > 0 {
            lines.push(format!(
                "{} ray(s) were not traced (black): their branch of the ray tree (a ray of the camera ray's hit \
                 and every ray below it) had traced its budget of {RAYS_PER_BRANCH} rays; shaders whose rays do \
                 not shrink in weight (glass, Layered) double them at every level when nothing prunes them \
                 (--slide, --exhaustive): lower the depth limit, or take the step adaptive-depth",
                counters.over_budget_rays
            ));
        }
        if counters.capped_rays > 0 {
            lines.push(format!(
                "{} ray(s) bounced past the safety cap of {RECURSION_SAFETY_CAP} and returned black: without a depth \
                 limit, facing mirrors recurse until the stack overflows; that is why Reflection v0.2 adds \
                 MAX_RAY_DEPTH",
                counters.capped_rays
            ));
        }
        lines
    }
}

/// The report's line on rays a shader started on the hit point itself that found their own surface.
const UNSPAWNED_RAYS: &str = "rays a shader started on the hit point itself found the surface they left, right where \
     they left it, and were not followed (black; self-intersection): make them with ray.spawn(info, dir, \
     attenuation), which starts them off the surface, not Ray::new(info.ip, dir)";

/// The report's line on rays started off the surface that found it again: the geometry's hit point is off it.
const SELF_HITS: &str = "rays started off the surface found it again, right where they left it, and were not \
     followed (black; self-intersection): the geometry's hit point lies off its surface by more than its error \
     bound; put it back on the surface, or widen the bound with IntersectionInfo::with_error";

/// The report's line on rays started off one of the workbook's shapes that found it again: the shader's ray.
const STARTED_ELSEWHERE: &str = "rays a shader started off the surface found it again, right where they left it, \
     and were not followed (black; self-intersection): the shape puts its hit point on its surface within its \
     error bound, so the shader started the ray elsewhere or turned it after starting it; make it with \
     ray.spawn(info, dir, attenuation) from this hit's info, in the direction it is traced";

/// The report's line on shaders that passed `GlossyCone::new` a glossiness out of its range at run time.
const GLOSSINESS_OUT_OF_RANGE: &str = "a shader passed GlossyCone::new a glossiness outside its range, above 0 and \
     at most 1 (a value computed at each hit, a texture's, unclamped): the cone, tan((1 - glossiness) * pi/2), is \
     unbounded or turned inside out; clamp it to the range before the call";

/// The report's line on shaders that return more light than their rays and light loop brought them.
const ENERGY_GAINS: &str = "a shader returned more light than its brightest ray and its light loop brought it, in \
     some channel, on 1% of its hits or more: most likely it adds up N rays without dividing by N; return their \
     mean (the sum over N), each ray still made with the full attenuation";

/// The report's line on normals that are not of unit length.
const BAD_NORMALS: &str = "a geometry returned a normal that is not of unit length, or NaN (normalise it)";

/// The report's line on rays a shader traced in a direction that is not of unit length.
const LONG_DIRECTIONS: &str = "a shader traced rays whose direction is not of unit length, which throws off the \
     cosines, reflections and distances along them (normalise the direction before ray.spawn(info, dir, attenuation))";

/// How many probe rays across, and how many down, [`undeclared_dispersion`] aims over the picture.
pub const PROBE_RAYS: u32 = 16;

/// The random stream of [`undeclared_dispersion`]'s probes, the same for each of their wavelengths.
const PROBE_KEY: u64 = 0x5052_4f42_4500_0000;

/// The nodes of `scene`, seen through `camera` in a picture of `width` x `height`, whose shader says it does
/// not depend on the wavelength ([`Shader::is_dispersive`]) but gives rays of different wavelengths different
/// colours. Each such shader is tried once, at the first of its nodes that one of a grid of
/// [`PROBE_RAYS`]² camera rays over the picture hits: that ray is traced into the node alone (so that
/// nothing else it sees can bring a wavelength's colour), in white light and at [`LAMBDA_MIN`] and
/// [`LAMBDA_MAX`], with the same random numbers, by the scene's own steps. A node none of the rays hits is
/// not tried, nor a point of
/// a shader other than the one tried, and a shader that gives the same colour in every wavelength there
/// (black, where no light reaches it) is not caught: the check finds the mistake, it cannot prove its
/// absence.
pub fn undeclared_dispersion(scene: &Scene, camera: &CameraFrame, width: u32, height: u32) -> BTreeSet<usize> {
    let step = |size: u32, i: u32| (i as f32 + 0.5) * size as f32 / PROBE_RAYS as f32;
    let rays: Vec<Ray> = (0..PROBE_RAYS)
        .flat_map(|y| (0..PROBE_RAYS).map(move |x| (x, y)))
        .map(|(x, y)| camera.get_screen_ray(step(width, x), step(height, y)))
        .collect();
    let mut tried = HashSet::new();
    let mut found = BTreeSet::new();
    for (i, node) in scene.nodes.iter().enumerate() {
        // A shader shared between nodes is tried once: a student's, or a Layered, by its address.
        let shared = match &node.shader {
            Material::Own(shader) => Some(Arc::as_ptr(shader) as *const () as usize),
            Material::Layered(layered) => Some(Arc::as_ptr(layered) as usize),
            _ => None,
        };
        if node.shader.is_dispersive() || shared.is_some_and(|shader| tried.contains(&shader)) {
            continue;
        }
        let alone = scene.around(vec![node.clone()]);
        let alone = alone.prepared();
        let Some(ray) = rays.iter().find(|ray| alone.intersects(ray, f32::INFINITY)) else {
            continue;
        };
        tried.extend(shared);
        let colour = |wavelength: Option<f32>| {
            TraceContext::new(&alone, Rng::for_keys(&[PROBE_KEY])).raytrace(&Ray { wavelength, ..*ray })
        };
        let white = colour(None);
        if [LAMBDA_MIN, LAMBDA_MAX].into_iter().any(|lambda| differs(colour(Some(lambda)), white)) {
            found.insert(i);
        }
    }
    found
}

/// Whether two colours differ, both being numbers (a NaN colour is the NaN check's business).
fn differs(a: Color, b: Color) -> bool {
    a != b && a.is_finite() && b.is_finite()
}

/// "A (12), B (3)": the entries of `counts`, most frequent first, each named by `name`.
fn listed<K>(counts: &BTreeMap<K, u64>, name: impl Fn(&K) -> String) -> String {
    let mut entries: Vec<_> = counts.iter().collect();
    entries.sort_by(|a, b| b.1.cmp(a.1));
    entries.iter().map(|(k, n)| format!("{} ({n})", name(k))).collect::<Vec<_>>().join(", ")
}
