//! The course's shaders' parameters that lie outside the range they take: lines the command line adds to the
//! end-of-run report of [`crate::lesson::diagnostics`] (and [`crate::app::cli::render_and_report`] to a
//! homework's test).
//!
//! A mirror's or a glass's `multiplier` is the fraction of the light its ray passes ("Reflection v0.1": 0.8,
//! "20% loss of energy"), a layer's `blend` an opacity (slide "Layered Shader": 0 transparent, 1 opaque) and
//! a glossy mirror's `glossiness` lies above 0 and at most 1 (slide "Грапави (glossy) отражения"). Outside
//! those ranges nothing fails: a multiplier of 9 makes its rays carry nine times the light that arrived (a
//! glass renders white), a blend of 1.5 is clamped to 1 (ledger: `blend-clamp`), a glossiness of 1.2 turns
//! the cone inside out. The energy check of [`crate::lesson::branching`] weighs a student's shader at each
//! hit; the course's shaders' parameters are fixed when the scene is built, so they are read once, from the
//! scene, after the render: no ray pays for it. A parameter a texture gives is read where it is
//! used and is not checked here.

use crate::lesson::color::Color;
use crate::lesson::scene::Scene;
use crate::lesson::shader::{ColorSource, Layered, Material, Shader};
use std::collections::HashSet;
use std::sync::Arc;

/// The report's line on multipliers outside [0, 1].
pub(crate) const MULTIPLIERS: &str = "a mirror's or a glass's multiplier is outside 0 to 1, the fraction of the light \
     its ray passes: above 1 its rays carry more light than arrived (a glass renders white), below 0 they take \
     light away; give it the fraction its surface passes";

/// The report's line on layer blends outside [0, 1].
pub(crate) const BLENDS: &str = "a Layered shader's blend is outside 0 to 1, the range of an opacity, and was \
     clamped to it (the layer shows as if its blend were 0 or 1); give each channel a value from 0 to 1";

/// The report's line on glossiness outside (0, 1].
pub(crate) const GLOSSINESS: &str = "a glossy mirror's glossiness is outside its range, above 0 and at most 1 \
     (Reflection::glossy refuses it): the cone, tan((1 - glossiness) * pi/2), is unbounded or turned inside \
     out; give it a value in that range";

/// One report line for each kind of parameter out of range in the course's shaders of `scene`'s nodes,
/// naming each node and its shader, where in the shader the parameter is and its value; nothing for a
/// scene whose course shaders are all in range.
pub fn out_of_range(scene: &Scene) -> Vec<String> {
    let mut kinds: [(&str, Vec<String>); 3] = [(MULTIPLIERS, vec![]), (BLENDS, vec![]), (GLOSSINESS, vec![])];
    for node in &scene.nodes {
        let mut found: [Vec<String>; 3] = Default::default();
        let mut seen = HashSet::new();
        walk(&node.shader, "its", &mut seen, &mut found);
        for ((_, lines), found) in kinds.iter_mut().zip(found) {
            if !found.is_empty() {
                lines.push(format!("{} ({}): {}", scene.node_name(node), node.shader.name(), found.join(", ")));
            }
        }
    }
    kinds
        .into_iter()
        .filter(|(_, nodes)| !nodes.is_empty())
        .map(|(what, nodes)| format!("{what}: {}", nodes.join("; ")))
        .collect()
}

/// Notes in `found` (multipliers, blends, glossiness) the parameters out of range of `shader`, which is
/// `whose` ("its", "layer 1's"): a Layered shader's layers and their shaders, each Layered once (`seen`: a
/// graph of shared layers is walked once, not once per path through it).
fn walk(shader: &Material, whose: &str, seen: &mut HashSet<usize>, found: &mut [Vec<String>; 3]) {
    match shader {
        Material::Reflection(mirror) => {
            if let ColorSource::Color(m) = &mirror.multiplier
                && !in_unit_range(*m)
            {
                found[0].push(format!("{whose} Reflection multiplier {}", color(*m)));
            }
            if !(mirror.glossiness > 0.0 && mirror.glossiness <= 1.0) {
                found[2].push(format!("{whose} Reflection glossiness {}", mirror.glossiness));
            }
        }
        Material::Refraction(glass) if !(0.0..=1.0).contains(&glass.multiplier) => {
            found[0].push(format!("{whose} Refraction multiplier {}", glass.multiplier));
        }
        Material::Layered(layered) if seen.insert(Arc::as_ptr(layered) as usize) => layers(layered, whose, seen, found),
        _ => {}
    }
}

/// [`walk`] over the layers of `layered`, which is `whose`.
fn layers(layered: &Layered, whose: &str, seen: &mut HashSet<usize>, found: &mut [Vec<String>; 3]) {
    for (i, layer) in layered.layers().iter().enumerate() {
        let this = if whose == "its" { format!("layer {i}'s") } else { format!("{whose} layer {i}'s") };
        if !in_unit_range(layer.blend) {
            found[1].push(format!("{this} blend {}", color(layer.blend)));
        }
        walk(&layer.shader, &this, seen, found);
    }
}

/// Whether every channel of `c` lies in [0, 1].
fn in_unit_range(c: Color) -> bool {
    c.0.cmpge(glam::Vec3A::ZERO).all() && c.0.cmple(glam::Vec3A::ONE).all()
}

/// "(0.5, 1.5, 1)": a colour as the report shows it.
fn color(c: Color) -> String {
    format!("({}, {}, {})", c.0.x, c.0.y, c.0.z)
}
