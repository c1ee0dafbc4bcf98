//! The ray tree as `--trace-pixel` prints it: indented text to read, or JSON for tools.

use super::{PixelPos, RayTree, TermKind, TraceFormat, TracedPixel};
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::math::Vector;
use crate::lesson::observer::LightTerm;
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
                    let _ = writeln!(out, "{pad}  + {layer}{} times", factor(term.factor));
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
        let _ = write!(
            out,
            "\"stop\":{stop},\"color\":{},\"throughput\":{},\"terms\":[",
            json_vec(ray.color.to_array()),
            json_vec(throughput.to_array())
        );
        for (i, term) in ray.terms.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ =
                write!(out, "{{\"factor\":{},\"layer\":{},", json_vec(term.factor.to_array()), json_str(&term.layer));
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
            "{{\"example\":{},\"pixel\":[{},{}],\"sample\":{sample},\"samples\":{},\"pixel_color\":{},\"tree\":{}}}\n",
            json_str(name),
            pixel.x,
            pixel.y,
            tree.roots.len(),
            json_vec(traced.color.to_array()),
            tree.to_json(sample)
        ),
        TraceFormat::Text => format!(
            "{name}: pixel ({}, {}) is {}, the mean of {} camera rays ({} rays and shadow rays in all)\n\
             camera ray {sample} (numbered from 0) returns {}; the shares of the light found on its tree add up \
             to {}:\n{}",
            pixel.x,
            pixel.y,
            rgb(traced.color),
            tree.roots.len(),
            traced.counters.total(),
            rgb(tree.rays[root].color),
            rgb(tree.explained(root, Color::WHITE)),
            tree.to_text(sample)
        ),
    })
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
