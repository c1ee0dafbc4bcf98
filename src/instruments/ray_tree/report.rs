//! The ray tree as `--trace-pixel` prints it: indented text to read, or JSON for tools.

use super::{Note, NoteKind, PixelPos, RayTree, Share, TermKind, TraceFormat, TracedPixel};
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::math::Vector;
use crate::lesson::observer::LightTerm;
use crate::lesson::photon_map::radius_scale;
use crate::lesson::topic::Topic;
use std::fmt::Write;

impl RayTree {
    /// The tree of camera ray `sample` as indented text.
    pub fn to_text(&self, sample: usize) -> String {
        let mut out = String::new();
        if let Some(&root) = self.roots.get(sample) {
            self.write_ray(&mut out, root, Color::WHITE, 0, "");
        }
        out
    }

    /// "reflection 3 of 16" for the third of the sixteen reflections the same shader sent from one hit.
    fn ray_label(&self, parent: Option<usize>, id: usize) -> String {
        let kind = self.rays[id].kind;
        let Some(parent) = parent else {
            return kind.to_string();
        };
        let siblings: Vec<usize> = self.rays[parent]
            .terms
            .iter()
            .filter_map(|t| match t.what {
                TermKind::Ray(child) if self.rays[child].kind == kind => Some(child),
                _ => None,
            })
            .collect();
        match siblings.iter().position(|&c| c == id) {
            Some(i) if siblings.len() > 1 => format!("{kind} {} of {}", i + 1, siblings.len()),
            _ => kind.to_string(),
        }
    }

    fn write_ray(&self, out: &mut String, id: usize, throughput: Color, indent: usize, label: &str) {
        let ray = &self.rays[id];
        let pad = "  ".repeat(indent);
        let label = if label.is_empty() { ray.kind.to_string() } else { label.to_string() };
        let _ = writeln!(
            out,
            "{pad}{label} (depth {}) from {} dir {}, weight {:.4}",
            ray.depth,
            vec3(ray.start),
            vec3(ray.dir),
            ray.weight
        );
        if let Some(hit) = &ray.hit {
            let _ = writeln!(out, "{pad}  hits {} at distance {:.4}, shader {}", hit.node, hit.distance, hit.shader);
        }
        for note in &ray.notes {
            write_note(out, &format!("{pad}  "), note);
        }
        if let Some(stop) = ray.stop {
            let _ = writeln!(out, "{pad}  stops: {stop}");
        }
        let _ =
            writeln!(out, "{pad}  returns {}; its share of the pixel {}", rgb(ray.color), rgb(throughput * ray.color));
        if ray.hit.is_some() && ray.terms.is_empty() {
            let _ = writeln!(out, "{pad}  (its shader traced no ray and found no light)");
        }
        for term in &ray.terms {
            let layer = if term.layer.is_empty() { String::new() } else { format!("{}: ", term.layer) };
            match term.what {
                TermKind::Ray(child) => {
                    let _ = writeln!(out, "{pad}  + {layer}{} times{}", factor(term.factor), share_text(term.share));
                    let child_label = self.ray_label(Some(id), child);
                    self.write_ray(out, child, throughput * term.factor, indent + 2, &child_label);
                }
                TermKind::Light { kind, color } => {
                    let _ = writeln!(
                        out,
                        "{pad}  + {layer}{} times {}: {}; share of the pixel {}",
                        factor(term.factor),
                        light_text(kind),
                        rgb(color),
                        rgb(throughput * term.factor * color)
                    );
                }
                TermKind::Own { color } => {
                    let _ = writeln!(
                        out,
                        "{pad}  + {layer}the shader's own colour, beyond what it gathered: {}; share of the pixel {}",
                        rgb(color),
                        rgb(throughput * term.factor * color)
                    );
                }
            }
        }
    }

    /// The tree of camera ray `sample` as JSON (one object per ray, its terms nested).
    pub fn to_json(&self, sample: usize) -> String {
        let mut out = String::new();
        match self.roots.get(sample) {
            Some(&root) => self.write_json(&mut out, root, Color::WHITE, None),
            None => out.push_str("null"),
        }
        out
    }

    fn write_json(&self, out: &mut String, id: usize, throughput: Color, parent: Option<usize>) {
        let ray = &self.rays[id];
        let _ = write!(
            out,
            "{{\"depth\":{},\"kind\":{},\"start\":{},\"dir\":{},\"weight\":{},\"sent_by\":{},",
            ray.depth,
            json_str(&self.ray_label(parent, id)),
            json_vec(ray.start.to_array()),
            json_vec(ray.dir.to_array()),
            json_num(ray.weight),
            json_str(&ray.sent_by)
        );
        match &ray.hit {
            Some(h) => {
                let _ = write!(
                    out,
                    "\"hit\":{{\"node\":{},\"distance\":{},\"shader\":{}}},",
                    json_str(&h.node),
                    json_num(h.distance),
                    json_str(h.shader)
                );
            }
            None => out.push_str("\"hit\":null,"),
        }
        let stop = ray.stop.map_or("null".to_string(), |s| json_str(&s.to_string()));
        let notes: Vec<String> = ray.notes.iter().map(note_json).collect();
        let _ = write!(
            out,
            "\"stop\":{stop},\"color\":{},\"throughput\":{},\"notes\":[{}],\"terms\":[",
            json_vec(ray.color.to_array()),
            json_vec(throughput.to_array()),
            notes.join(",")
        );
        for (i, term) in ray.terms.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ =
                write!(out, "{{\"factor\":{},\"layer\":{},", json_vec(term.factor.to_array()), json_str(&term.layer));
            if let Some(share) = term.share {
                let own = share.own.map_or("null".to_string(), json_num);
                let _ = write!(out, "\"own_share\":{own},\"common\":{},", json_vec(share.common.to_array()));
            }
            match term.what {
                TermKind::Ray(child) => {
                    out.push_str("\"ray\":");
                    self.write_json(out, child, throughput * term.factor, Some(id));
                }
                TermKind::Light { kind, color } => {
                    let _ = write!(
                        out,
                        "\"light\":{},\"color\":{}",
                        json_str(&light_text(kind)),
                        json_vec(color.to_array())
                    );
                }
                TermKind::Own { color } => {
                    let _ = write!(out, "\"own\":{}", json_vec(color.to_array()));
                }
            }
            out.push('}');
        }
        out.push_str("]}");
    }
}

/// The report of pixel `pixel`, traced with its ray tree recorded (`traced`, from [`trace`](super::trace)): the tree of its
/// camera ray `sample`, as `--trace-pixel` prints it and the viewer shows a clicked pixel.
pub fn describe(
    name: &str,
    pixel: PixelPos,
    traced: &TracedPixel,
    sample: usize,
    format: TraceFormat,
) -> Result<String> {
    let tree = &traced.tree;
    let Some(&root) = tree.roots.get(sample) else {
        return Err(Error::parameter(
            "--trace-sample",
            sample,
            format!("the pixel has {} camera rays (numbered from 0)", tree.roots.len()),
        ));
    };
    Ok(match format {
        TraceFormat::Json => format!(
            "{{\"example\":{},\"pixel\":[{},{}],\"sample\":{sample},\"samples\":{},{}\
             \"pixel_color\":{},\"tree\":{}}}\n",
            json_str(name),
            pixel.x,
            pixel.y,
            tree.roots.len(),
            tree.photon_pass_of(sample)
                .map_or(String::new(), |(pass, passes)| format!("\"photon_pass\":{pass},\"photon_passes\":{passes},")),
            json_vec(traced.color.to_array()),
            tree.to_json(sample)
        ),
        TraceFormat::Text => {
            let (mean, which) = match tree.photon_pass_of(sample) {
                None => (format!("the mean of {} camera rays", tree.roots.len()), String::new()),
                Some((pass, passes)) => (
                    format!(
                        "the mean of {passes} passes of a progressive caustic, each with a photon map of its own, \
                         of {} camera rays in all",
                        tree.roots.len()
                    ),
                    format!(", of photon pass {pass} of {passes}"),
                ),
            };
            format!(
                "{name}: pixel ({}, {}) is {}, {mean} ({} rays and shadow rays in all)\n\
                 camera ray {sample} (numbered from 0{which}) returns {}; the shares of the light found on its tree \
                 add up to {}:\n{}",
                pixel.x,
                pixel.y,
                rgb(traced.color),
                traced.counters.total(),
                rgb(tree.rays[root].color),
                rgb(tree.explained(root, Color::WHITE)),
                tree.to_text(sample)
            )
        }
    })
}

/// What a ray's factor is made of, when the tree says: its own share from its weight, times a part worked out
/// from its shader's colour and shared with its siblings. Nothing when its own share is its whole factor.
fn share_text(share: Option<Share>) -> String {
    let Some(share) = share else {
        return String::new();
    };
    if share.own.is_some() && factor(share.common) == factor(Color::WHITE) {
        return String::new();
    }
    let own = share.own.map_or(String::new(), |own| format!("its weight gives {own:.4}, times "));
    let plural = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
    let mut siblings = Vec::new();
    if share.rays > 0 {
        siblings.push(format!("the other {}", plural(share.rays, "ray")));
    }
    if share.lights > 0 {
        siblings.push(plural(share.lights, "light term"));
    }
    let common = factor(share.common);
    if siblings.is_empty() {
        return format!(" ({own}{common} worked out from its shader's colour)");
    }
    format!(
        " ({own}{common} shared with {} of its shader: worked out from its colour, not known ray by ray)",
        siblings.join(" and ")
    )
}

/// A note at a hit, as lines indented by `pad`.
fn write_note(out: &mut String, pad: &str, note: &Note) {
    let layer = if note.layer.is_empty() { String::new() } else { format!("{}: ", note.layer) };
    let topic = match &note.what {
        NoteKind::LayerWeight(weight) => {
            let _ = writeln!(out, "{pad}{layer}counts {} times in its shader's colour", factor(*weight));
            return;
        }
        NoteKind::Topic(topic) => topic,
    };
    match topic {
        Topic::Fresnel { reflectance, eta, cos, exact } => {
            let formula = if *exact { "the exact Fresnel equations" } else { "Schlick's approximation" };
            let _ = writeln!(
                out,
                "{pad}{layer}Fresnel reflectance {reflectance:.4} ({formula}; n1/n2 {eta:.4}, the ray at cos {cos:.4} \
                 to the normal): the blend it gives its layer"
            );
        }
        Topic::Texels { u, v, texels } => {
            let filter = match texels.len() {
                1 => "the nearest texel (the slide's)".to_string(),
                n => format!("bilinear, the {n} texels around it"),
            };
            let _ = writeln!(out, "{pad}{layer}bitmap read at u {u:.4}, v {v:.4} (one image per unit): {filter}");
            for texel in texels {
                let _ = writeln!(
                    out,
                    "{pad}    texel ({}, {}) weight {:.4}: {}",
                    texel.x,
                    texel.y,
                    texel.weight,
                    rgb(texel.color)
                );
            }
        }
        Topic::Photons { k, radius, max_radius, photons } => {
            let counted = photons.iter().filter(|p| p.weight > 0.0).count();
            let found = photons.len();
            let _ = match note.photon_pass {
                Some((pass, passes)) if pass > 1 => writeln!(
                    out,
                    "{pad}{layer}photon estimate, photon pass {pass} of {passes}: every photon within r_{pass} = \
                     {radius:.4} (r_1, the first map's disc here, times {:.4}); {found} found, {counted} arrived \
                     on this side and count",
                    radius_scale(pass)
                ),
                pass => writeln!(
                    out,
                    "{pad}{layer}photon estimate{}: k {k}, {found} found within the largest radius {max_radius:.4}, \
                     their power spread over the disc of radius {radius:.4}; {counted} arrived on this side and count",
                    pass.map_or(String::new(), |(_, passes)| format!(
                        ", photon pass 1 of {passes} (its disc is r_1, where the later passes' radii start)"
                    ))
                ),
            };
            let mut nearest = photons.clone();
            nearest.sort_by(|a, b| a.distance.total_cmp(&b.distance).then(a.index.cmp(&b.index)));
            for photon in nearest {
                let _ = writeln!(
                    out,
                    "{pad}    photon {} at distance {:.4}: power {}, weight {:.4}",
                    photon.index,
                    photon.distance,
                    rgb(photon.power),
                    photon.weight
                );
            }
        }
    }
}

/// A note as a JSON object.
fn note_json(note: &Note) -> String {
    let what = match &note.what {
        NoteKind::LayerWeight(weight) => format!("\"weight\":{}", json_vec(weight.to_array())),
        NoteKind::Topic(Topic::Fresnel { reflectance, eta, cos, exact }) => format!(
            "\"fresnel\":{{\"reflectance\":{},\"eta\":{},\"cos\":{},\"exact\":{exact}}}",
            json_num(*reflectance),
            json_num(*eta),
            json_num(*cos)
        ),
        NoteKind::Topic(Topic::Texels { u, v, texels }) => {
            let texels: Vec<String> = texels
                .iter()
                .map(|t| {
                    let color = json_vec(t.color.to_array());
                    format!("{{\"x\":{},\"y\":{},\"weight\":{},\"color\":{color}}}", t.x, t.y, json_num(t.weight))
                })
                .collect();
            format!("\"texels\":{{\"u\":{},\"v\":{},\"texels\":[{}]}}", json_num(*u), json_num(*v), texels.join(","))
        }
        NoteKind::Topic(Topic::Photons { k, radius, max_radius, photons }) => {
            let photons: Vec<String> = photons
                .iter()
                .map(|p| {
                    let (distance, weight) = (json_num(p.distance), json_num(p.weight));
                    let power = json_vec(p.power.to_array());
                    format!("{{\"index\":{},\"distance\":{distance},\"power\":{power},\"weight\":{weight}}}", p.index)
                })
                .collect();
            format!(
                "\"photons\":{{\"k\":{k},\"radius\":{},\"max_radius\":{},\"photons\":[{}]}}",
                json_num(*radius),
                json_num(*max_radius),
                photons.join(",")
            )
        }
    };
    format!("{{\"layer\":{},{what}}}", json_str(&note.layer))
}

/// How the tree names light found at a surface.
fn light_text(light: LightTerm) -> String {
    match light {
        LightTerm::Ambient => "ambient light".to_string(),
        LightTerm::Lamp { index, from, dir, visible } => format!(
            "shadow ray to light {index} from {} dir {}: {}",
            vec3(from),
            vec3(dir),
            if visible { "reaches it" } else { "blocked" }
        ),
        LightTerm::Photons => "photon estimate (caustic light)".to_string(),
        LightTerm::Highlight { index } => format!("highlight of light {index}"),
    }
}

fn vec3(v: Vector) -> String {
    format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z)
}

fn rgb(c: Color) -> String {
    format!("rgb({:.4}, {:.4}, {:.4})", c.r(), c.g(), c.b())
}

/// A factor: one number when it is grey (its channels print alike), else its three channels.
fn factor(c: Color) -> String {
    let [r, g, b] = c.to_array().map(|v| format!("{v:.4}"));
    if r == g && g == b { r } else { rgb(c) }
}

fn json_num(v: f32) -> String {
    if v.is_finite() { format!("{v}") } else { "null".to_string() }
}

fn json_vec(v: [f32; 3]) -> String {
    format!("[{},{},{}]", json_num(v[0]), json_num(v[1]), json_num(v[2]))
}

/// A JSON string literal (quotes, backslashes and control characters escaped).
fn json_str(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
