//! The note after a render for a step beyond the slides that was given (`--step`, `--no-step`,
//! `--exhaustive`) and changed nothing in it, as the notes for the caustic and dispersion options do.
//!
//! What a step could change is read from the render itself: for the steps whose work depends on the rays
//! (adaptive depth, the texel filter, the disc samplers, layer pruning), the counts the render kept of where
//! that step and the slide's version part ([`Counters::steps_reached`]); for the others, from the scene and
//! the settings the render was made of (a node tree above [`LINEAR_NODES`] nodes, a mesh, more than one sample
//! per pixel, something dispersive, a photon map, a camera far from the origin). A step that never came to
//! such a place changed nothing; the note says so and why, when the reason is known.

use super::options::CommonArgs;
use crate::lesson::beyond::Step;
use crate::lesson::bitmap::Filter;
use crate::lesson::environment::Sky;
use crate::lesson::geometry::Shape;
use crate::lesson::math::Vector;
use crate::lesson::node::LINEAR_NODES;
use crate::lesson::render::RenderSettings;
use crate::lesson::scene::{Counters, Scene};
use crate::lesson::shader::Material;
use std::sync::Arc;

/// Why each step can change nothing in a scene, by what the scene and the settings say before a ray is
/// traced; `None` where the scene leaves it to the rays (see [`notes`]).
pub(super) struct Scope([Option<String>; Step::ALL.len()]);

impl Scope {
    /// What `scene`, about to be rendered with `settings`, lets each step change.
    pub(super) fn of(scene: &Scene, settings: &RenderSettings) -> Scope {
        let sky_filters = scene.environment.as_ref().is_some_and(|env| match Arc::clone(env).into_sky() {
            Sky::Spherical(sky, _) => sky.filter != Filter::Nearest,
            Sky::Cubemap(sky, _) => sky.filter != Filter::Nearest,
            Sky::Constant(_) | Sky::Own(_) => false,
        });
        let has_layered = scene.nodes.iter().any(|node| matches!(node.shader, Material::Layered(_)));
        let why = |step| match step {
            Step::TwoPhaseHit if scene.nodes.is_empty() => Some("the scene has no nodes".to_string()),
            Step::NodeTree if scene.nodes.len() <= LINEAR_NODES => Some(format!(
                "the scene has {} node(s), and the tree over the nodes is built only above {LINEAR_NODES}, where \
                 it pays; below, the slide's loop over them is as fast",
                scene.nodes.len()
            )),
            Step::MeshBvh if !scene.nodes.iter().any(|node| matches!(node.geometry, Shape::Mesh { .. })) => {
                Some("the scene has no mesh".to_string())
            }
            Step::StratifiedAa if settings.spp <= 1 => Some(
                "one sample per pixel goes through the pixel's centre: there is nothing to stratify (--spp N)".into(),
            ),
            Step::HeroWavelengths if !scene.is_dispersive() => {
                Some("nothing in this scene is dispersive, so it is traced once in white light".into())
            }
            Step::PhotonGrid if scene.photons.count == 0 || !scene.can_have_caustics() => {
                Some("this scene has no photon map (--photons N, in a scene with a mirror or a glass)".into())
            }
            Step::CameraRelative
                if !scene.is_far_from_the_origin() && scene.world_position(Vector::ZERO) == Vector::ZERO =>
            {
                Some("the camera is nearer the scene than the origin is, where world coordinates are as precise".into())
            }
            Step::TexelFilter if sky_filters => None,
            Step::TexelFilter => Some(
                "no bitmap texture with a filter of its own was read through ColorSource::at (a shader that reads \
                 its texture with get_tex_color reads it through its filter in both readings), and the environment \
                 is not an image read through a filter"
                    .into(),
            ),
            Step::AdaptiveDepth if has_layered && !scene.steps.has(Step::LayerPruning) => Some(format!(
                "no ray's weight fell below the cut-off ({:.4}, the finest 8-bit sRGB step): the slides' Layered loop traces \
                 each layer's rays at the full weight of the ray that hit, so their weights fall below it only with \
                 the step layer-pruning",
                scene.min_ray_weight
            )),
            Step::AdaptiveDepth => Some(format!(
                "no ray's weight fell below the cut-off ({:.4}, the finest 8-bit sRGB step)",
                scene.min_ray_weight
            )),
            Step::DiscSamples => Some(
                "no glossy mirror of the workbook's drew its disc points with a sampler of its own (a shader that \
                 draws its own points is not changed by the step)"
                    .into(),
            ),
            Step::LayerPruning => Some("no Layered shader that may skip layers was shaded".into()),
            _ => None,
        };
        Scope(Step::ALL.map(why))
    }
}

/// The steps whose work the render's rays decide: they changed something when the render came where
/// they and the slide's version part at least once ([`Counters::steps_reached`]).
const BY_THE_RAYS: [Step; 4] = [Step::AdaptiveDepth, Step::TexelFilter, Step::DiscSamples, Step::LayerPruning];

/// One note for each step the options name (`--step`, `--no-step`, `--exhaustive`) that changed nothing
/// in a render of a scene of this `scope` whose rays kept `counters`.
pub(super) fn notes(common: &CommonArgs, scope: &Scope, counters: &Counters) -> Vec<String> {
    let mut notes: Vec<String> = match common.slide {
        true => vec![],
        false => common.step.iter().map(|step| format!("--step {} {ALREADY_TAKEN}", step.name())).collect(),
    };
    let added = common.step.iter().filter(|_| common.slide).map(|&step| (format!("--step {}", step.name()), step));
    let removed = common.no_step.iter().map(|&step| (format!("--no-step {}", step.name()), step));
    let exhaustive = common.exhaustive.then(|| ("--exhaustive".to_string(), Step::AdaptiveDepth));
    for (option, step) in added.chain(removed).chain(exhaustive) {
        let i = step as usize;
        let reached = BY_THE_RAYS.contains(&step) && counters.steps_reached[i] > 0;
        if let Some(why) = scope.0[i].as_deref().filter(|_| !reached) {
            notes.push(format!("{option} changed nothing in this render: {why}"));
        }
    }
    notes
}

/// The note on `--step` without `--slide`.
const ALREADY_TAKEN: &str = "changed nothing: the default reading takes every step; add it to --slide";
