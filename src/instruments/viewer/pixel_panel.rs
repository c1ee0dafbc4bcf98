//! The viewer's panel of a clicked pixel: the node and shader its first camera ray hits and that ray's whole
//! tree, the text `--trace-pixel X,Y` prints ([`crate::instruments::ray_tree`]), traced at the options' full
//! quality from the camera shown. The tree's lines are wrapped to the panel's width, each wrapped line
//! indented under its own start so that the tree's shape still shows (nothing is cut off on a projector),
//! and the tree is traced again when the picture shown is of another scene: the camera moved or an option
//! changed.

use super::worker::Shown;
use crate::instruments::ray_tree::{self, PixelPos, TraceFormat};
use crate::lesson::color::to_srgb8;
use crate::lesson::render::thread_pool;
use crate::lesson::scene::Scene;
use eframe::egui;
use std::sync::{Arc, Mutex};

/// How much deeper than its first line a wrapped line's continuation is indented, in characters.
const CONTINUATION: usize = 4;

/// A clicked pixel and what it sees.
pub struct Picked {
    /// The pixel's column, from the left.
    pub x: u32,
    /// The pixel's row, from the top.
    pub y: u32,
    /// One line naming its colour and the node and shader it hits.
    sees: String,
    /// Its ray tree, as `--trace-pixel` prints it.
    tree: String,
    /// The scene the tree was traced in: when the picture shown is of another, the tree is traced again.
    scene: Option<Arc<Scene>>,
}

impl Picked {
    /// Traces pixel (x, y) of the picture `shown` is of, in the example called `name`; `None` when there is
    /// no scene yet or the pixel is outside the picture.
    pub fn trace(name: &str, shown: &Mutex<Shown>, x: u32, y: u32) -> Option<Picked> {
        let shown = shown.lock().expect("the render thread never panics holding the picture");
        let (Some(scene), Some(settings)) = (shown.scene.clone(), shown.settings) else { return None };
        if x >= shown.width || y >= shown.height {
            return None;
        }
        let film = shown.film;
        drop(shown);
        // On a pool's thread: a deep ray tree needs its stack.
        let traced = thread_pool(Some(1))
            .and_then(|pool| pool.install(|| ray_tree::trace(&scene, &settings, PixelPos { x, y })));
        let (sees, tree) = match traced {
            Ok(trace) => {
                let first_hit = trace.tree.roots.first().and_then(|&root| trace.tree.rays[root].hit.clone());
                let sees = match first_hit {
                    Some(hit) => {
                        format!("sees node {}, shader {}, at distance {:.3}", hit.node, hit.shader, hit.distance)
                    }
                    None => "sees nothing: the environment".to_string(),
                };
                let [r, g, b] = to_srgb8(film.developed(trace.color, false));
                let tree = ray_tree::describe(name, PixelPos { x, y }, &trace, 0, TraceFormat::Text);
                (format!("shown as sRGB ({r}, {g}, {b}): {sees}"), tree.unwrap_or_else(|e| e.to_string()))
            }
            Err(e) => (e.to_string(), String::new()),
        };
        Some(Picked { x, y, sees: format!("pixel ({x}, {y}), {sees}"), tree, scene: Some(scene) })
    }

    /// Whether the picture `shown` is of another scene than the one the tree was traced in.
    pub fn is_stale(&self, shown: &Mutex<Shown>) -> bool {
        let shown = shown.lock().expect("the render thread never panics holding the picture");
        match (&self.scene, &shown.scene) {
            (Some(traced), Some(now)) => !Arc::ptr_eq(traced, now),
            _ => false,
        }
    }

    /// The panel beside the picture; returns whether it was closed.
    pub fn show(&self, ctx: &egui::Context) -> bool {
        let mut close = false;
        egui::SidePanel::right("pixel").resizable(true).default_width(520.0).show(ctx, |ui| {
            ui.horizontal(|ui| {
                ui.strong("Pixel");
                close = ui.button("Close").clicked();
            });
            ui.label(&self.sees);
            ui.separator();
            egui::ScrollArea::vertical().auto_shrink([false, false]).show(ui, |ui| {
                let font = egui::TextStyle::Monospace.resolve(ui.style());
                let glyph = ui.fonts_mut(|fonts| fonts.glyph_width(&font, 'x')).max(1.0);
                let columns = (ui.available_width() / glyph).floor().max(1.0) as usize;
                let tree = egui::Label::new(egui::RichText::new(wrap_tree(&self.tree, columns)).monospace()).extend();
                ui.add(tree);
            });
        });
        close
    }
}

/// `text` with every line longer than `columns` characters wrapped at spaces, its continuations indented
/// four characters deeper than the line itself, so that a wrapped line of the tree stays under
/// its ray.
pub fn wrap_tree(text: &str, columns: usize) -> String {
    let mut out = String::new();
    for line in text.lines() {
        let indent = " ".repeat(line.len() - line.trim_start().len());
        let deeper = format!("{indent}{}", " ".repeat(CONTINUATION));
        let options = textwrap::Options::new(columns)
            .initial_indent(&indent)
            .subsequent_indent(&deeper)
            .break_words(true)
            .word_splitter(textwrap::WordSplitter::NoHyphenation);
        for wrapped in textwrap::wrap(line.trim_start(), options) {
            out.push_str(&wrapped);
            out.push('\n');
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every wrapped line fits, no character but the spaces it breaks at is lost, and a continuation is
    /// indented deeper than the line it continues: the tree's shape stays.
    #[test]
    fn wrapped_tree_lines_fit_and_keep_their_indentation() {
        let tree = "camera ray (depth 0) from (0.000, 60.000, -120.000) dir (0.001, -0.412, 0.911), weight 1.0000\n  \
                    hits glass sphere at distance 69.2005, shader Layered\n    + layer Reflection, blend Fresnel: \
                    0.0479 times (its weight gives 0.8000, times 0.0625 shared with the other 15 rays)\n";
        for columns in [24, 40, 80] {
            let wrapped = wrap_tree(tree, columns);
            assert!(wrapped.lines().all(|l| l.chars().count() <= columns), "{columns}:\n{wrapped}");
            let words = |t: &str| t.split_whitespace().collect::<String>();
            assert_eq!(words(&wrapped), words(tree), "{columns}");
            let indent = |l: &str| l.len() - l.trim_start().len();
            let lines: Vec<&str> = wrapped.lines().collect();
            let third = lines.iter().position(|l| l.trim_start().starts_with('+')).unwrap();
            assert!(indent(lines[third + 1]) > indent(lines[third]), "{columns}:\n{wrapped}");
        }
        assert_eq!(wrap_tree(tree, 200), tree, "short lines stay as they are");
    }
}
