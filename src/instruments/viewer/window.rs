//! The viewer's window: the picture in the middle, the example's options on the left, the camera and the
//! status line below. egui redraws the window when the render thread has painted something or a key is
//! held, and otherwise sleeps.
//!
//! Keys (while no text field has the focus): W/S forward and back, A/D left and right, R/F up and down,
//! the arrow keys turn and Q/E roll; dragging the mouse over the picture looks around; a click shows what
//! the pixel sees: the node and shader it hits and its whole ray tree ([`super::pixel_panel`]).

use super::ExampleOptions;
use super::controls::{Control, Controls, Kind};
use super::fly::{Motion, as_code, moved};
use super::pixel_panel::Picked;
use super::worker::{Job, Worker};
use crate::files::output::keeps_linear_light;
use crate::instruments::compare::{self, Reference};
use crate::lesson::camera::Camera;
use crate::lesson::error::Result;
use eframe::egui;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

/// The camera counts as still this long after the last key or drag; then the picture refines.
const SETTLE: Duration = Duration::from_millis(150);

/// Degrees the arrow keys turn the camera per second.
const TURN_RATE: f32 = 60.0;

/// Opens the window and runs it until it is closed. Fails when the window cannot be opened (no display).
pub fn open<O: ExampleOptions>(name: &str, options: O, controls: Controls) -> std::result::Result<(), String> {
    let name = name.to_string();
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1180.0, 720.0])
            .with_title(format!("{name} (lecture 6)")),
        ..Default::default()
    };
    let title = name.clone();
    eframe::run_native(
        &title,
        native,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let app = Viewer::new(name, options, controls, move || ctx.request_repaint()).map_err(|e| e.to_string())?;
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| e.to_string())
}

/// The window's state.
struct Viewer<O: ExampleOptions> {
    name: String,
    controls: Controls,
    /// The options of the picture shown (the last valid ones).
    options: O,
    worker: Worker,
    /// The camera the window moved to; `None` while it is the scene's own.
    camera: Option<Camera>,
    /// Scene units per second of the movement keys.
    speed: f32,
    /// When the camera last moved, while it has not yet settled.
    moving_since: Option<Instant>,
    texture: Option<egui::TextureHandle>,
    /// The heat map of the difference from the reference, shown instead of the picture.
    heat_map: Option<egui::TextureHandle>,
    /// What the last action said (a bad option value, a saved file).
    message: String,
    /// The last clicked pixel, marked on the picture, and what it sees.
    picked: Option<Picked>,
}

impl<O: ExampleOptions> Viewer<O> {
    fn new(name: String, options: O, controls: Controls, repaint: impl Fn() + Send + Sync + 'static) -> Result<Self> {
        let worker = Worker::start(options.threads(), repaint)?;
        let mut viewer = Viewer {
            name,
            controls,
            options,
            worker,
            camera: None,
            speed: 0.0,
            moving_since: None,
            texture: None,
            heat_map: None,
            message: String::new(),
            picked: None,
        };
        viewer.rebuild();
        Ok(viewer)
    }

    fn submit(&mut self, rebuild: bool, preview: bool) {
        let options = self.options.clone();
        self.heat_map = None;
        self.worker.submit(Job {
            rebuild: rebuild.then(|| Box::new(move || options.prepare()) as _),
            camera: self.camera,
            film: self.options.film(),
            preview,
            cancel: Arc::new(AtomicBool::new(false)),
        });
    }

    /// The options changed: parse them as the command line would and render the new scene.
    fn rebuild(&mut self) {
        match O::from_controls(&self.controls) {
            Ok(options) => {
                self.options = options;
                self.message.clear();
                self.submit(true, false);
            }
            Err(e) => self.message = e,
        }
    }

    /// The camera shown: the one the window moved to, or the scene's.
    fn current_camera(&self) -> Option<Camera> {
        self.camera.or_else(|| self.worker.shown.lock().ok()?.scene_camera)
    }

    /// Moves the camera as the keys held and the drag say, and renders the quick preview while it moves,
    /// the full picture once it settles.
    fn fly(&mut self, ctx: &egui::Context, drag: egui::Vec2, image_width: f32) {
        let Some(camera) = self.current_camera() else { return };
        let mut motion = Motion::default();
        if !ctx.wants_keyboard_input() {
            ctx.input(|i| {
                let dt = i.stable_dt.min(0.1);
                let axis = |plus: egui::Key, minus: egui::Key| {
                    (i.key_down(plus) as i32 - i.key_down(minus) as i32) as f32 * dt
                };
                use egui::Key::*;
                motion.forward = axis(W, S);
                motion.right = axis(D, A);
                motion.up = axis(R, F);
                motion.yaw = axis(ArrowLeft, ArrowRight) * TURN_RATE;
                motion.pitch = axis(ArrowUp, ArrowDown) * TURN_RATE;
                motion.roll = axis(E, Q) * TURN_RATE;
            });
        }
        // Dragging the picture turns the camera by the angle the drag spans on screen.
        let degrees_per_point = camera.fov / image_width.max(1.0) * 0.8;
        motion.yaw += drag.x * degrees_per_point;
        motion.pitch += drag.y * degrees_per_point;
        if !motion.is_still() {
            self.camera = Some(moved(&camera, &motion, self.speed));
            self.moving_since = Some(Instant::now());
            self.submit(false, true);
            ctx.request_repaint();
        } else if let Some(since) = self.moving_since {
            if since.elapsed() >= SETTLE {
                self.moving_since = None;
                self.submit(false, false);
            } else {
                ctx.request_repaint_after(SETTLE);
            }
        }
        if ctx.input(|i| i.keys_down.iter().any(|k| MOVE_KEYS.contains(k))) {
            ctx.request_repaint();
        }
    }

    fn side_panel(&mut self, ui: &mut egui::Ui) {
        let mut changed = false;
        egui::ScrollArea::vertical().show(ui, |ui| {
            let mut heading: Option<Option<String>> = None;
            for control in &mut self.controls.controls {
                if heading.as_ref() != Some(&control.heading) {
                    ui.separator();
                    ui.strong(control.heading.clone().unwrap_or_else(|| format!("{} options", self.name)));
                    heading = Some(control.heading.clone());
                }
                changed |= control_ui(ui, control);
            }
        });
        if changed {
            self.rebuild();
        }
    }

    fn camera_panel(&mut self, ui: &mut egui::Ui) {
        let Some(camera) = self.current_camera() else { return };
        if self.speed == 0.0 {
            // Half the camera's distance from the origin per second: the examples are built around it.
            self.speed = (camera.position.length() * 0.5).max(1.0);
        }
        ui.horizontal_wrapped(|ui| {
            let p = camera.position;
            ui.monospace(format!(
                "camera ({:.2}, {:.2}, {:.2}) yaw {:.1} pitch {:.1} roll {:.1} fov {:.1}",
                p.x, p.y, p.z, camera.yaw, camera.pitch, camera.roll, camera.fov
            ));
            if ui.button("Copy as code").clicked() {
                ui.ctx().copy_text(as_code(&camera));
                self.message = format!("copied: {}", as_code(&camera));
            }
            if ui.button("Reset camera").clicked() {
                self.camera = None;
                self.submit(false, false);
            }
            ui.label("speed");
            let step = self.speed * 0.02;
            ui.add(egui::DragValue::new(&mut self.speed).speed(step));
            self.speed = self.speed.max(f32::MIN_POSITIVE);
            ui.label("W/S A/D R/F move, arrows turn, Q/E roll, drag to look");
        });
    }

    fn status_line(&mut self, ui: &mut egui::Ui) {
        let (status, finished) = {
            let shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
            let secs = shown.elapsed.as_secs_f64();
            let mut status = format!(
                "{}x{}, {} spp, {}/{} tiles, {:.2} s, {:.2} Mrays/s",
                shown.width,
                shown.height,
                shown.spp,
                shown.tiles_done,
                shown.tiles_total,
                secs,
                shown.rays as f64 * 1e-6 / secs.max(1e-9)
            );
            if self.moving_since.is_some() {
                let recent = shown.previews.iter().filter(|t| t.elapsed() < Duration::from_secs(1)).count();
                status += &format!(", moving: {recent} frames in the last second");
            }
            if let Some(e) = &shown.error {
                status = format!("error: {e}");
            }
            (status, shown.finished.as_ref().map(|(frame, _)| frame.clone()))
        };
        ui.horizontal(|ui| {
            ui.label(status);
            ui.add_enabled_ui(finished.is_some(), |ui| {
                for ext in ["png", "exr"] {
                    if ui.button(format!("Save .{ext}")).clicked()
                        && let Some(frame) = &finished
                    {
                        let path = self.options.output_path(&self.name).with_extension(ext);
                        let picture = self.options.film().develop(frame.clone(), keeps_linear_light(&path));
                        self.message = match picture.save(&path) {
                            Ok(()) => format!("saved {}", path.display()),
                            Err(e) => e.to_string(),
                        };
                    }
                }
                let compare_label = if self.heat_map.is_some() { "Show picture" } else { "Compare" };
                if ui.button(compare_label).clicked()
                    && let Some(frame) = &finished
                {
                    self.toggle_compare(ui.ctx(), frame);
                }
            });
        });
        if !self.message.is_empty() {
            ui.label(&self.message);
        }
    }

    /// Shows the heat map of the difference from the reference (`--compare`'s, or `expected/<name>.png`)
    /// instead of the picture, or the picture again. The comparison is `--compare`'s: the same figures, the
    /// same heat map with its colour bar.
    fn toggle_compare(&mut self, ctx: &egui::Context, frame: &crate::lesson::frame::Frame) {
        if self.heat_map.take().is_some() {
            return;
        }
        let reference = self.options.reference(&self.name);
        let comparison = Reference::load(&reference).and_then(|expected| {
            expected.check_size(&reference, frame.width, frame.height)?;
            compare::compare(&self.options.film().develop(frame.clone(), keeps_linear_light(&reference)), &expected)
        });
        match comparison {
            Ok(comparison) => {
                let heat = &comparison.heat_map;
                let size = [heat.width() as usize, heat.height() as usize];
                let image = egui::ColorImage::from_rgb(size, heat.as_raw());
                self.heat_map = Some(ctx.load_texture("heat map", image, egui::TextureOptions::NEAREST));
                self.message = format!("compared with {}: {comparison}", reference.display());
            }
            Err(e) => self.message = e.to_string(),
        }
    }

    /// Traces pixel (x, y) of the picture shown and shows its panel.
    fn inspect(&mut self, x: u32, y: u32) {
        self.picked = Picked::trace(&self.name, &self.worker.shown, x, y);
    }

    /// The clicked pixel's panel, beside the picture, until closed; its tree traced again once the camera
    /// has settled or the options changed.
    fn pixel_panel(&mut self, ctx: &egui::Context) {
        let stale = self.picked.as_ref().filter(|p| self.moving_since.is_none() && p.is_stale(&self.worker.shown));
        if let Some((x, y)) = stale.map(|p| (p.x, p.y)) {
            self.inspect(x, y);
        }
        if self.picked.as_ref().is_some_and(|picked| picked.show(ctx)) {
            self.picked = None;
        }
    }

    fn picture(&mut self, ui: &mut egui::Ui) {
        {
            let mut shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
            if shown.dirty && shown.width > 0 {
                let image = egui::ColorImage::from_rgb([shown.width as usize, shown.height as usize], &shown.rgb);
                match &mut self.texture {
                    Some(texture) => texture.set(image, egui::TextureOptions::NEAREST),
                    None => self.texture = Some(ui.ctx().load_texture("picture", image, egui::TextureOptions::NEAREST)),
                }
                shown.dirty = false;
            }
        }
        let Some(texture) = self.heat_map.as_ref().or(self.texture.as_ref()) else {
            ui.label("building the scene...");
            return;
        };
        let size = texture.size_vec2();
        let available = ui.available_size();
        let scale = (available.x / size.x).min(available.y / size.y).max(0.1);
        let image = egui::Image::new(egui::load::SizedTexture::new(texture.id(), size * scale));
        let response = ui.add(image.sense(egui::Sense::click_and_drag()));
        let drag = if response.dragged() { response.drag_delta() } else { egui::Vec2::ZERO };
        if response.clicked()
            && self.heat_map.is_none()
            && let Some(pos) = response.interact_pointer_pos()
        {
            // The texture is the picture, pixel for pixel.
            let p = (pos - response.rect.min) / scale;
            let (w, h) = (size.x as u32, size.y as u32);
            let (x, y) = ((p.x.max(0.0) as u32).min(w - 1), (p.y.max(0.0) as u32).min(h - 1));
            self.inspect(x, y);
        }
        if let Some(picked) = self.picked.as_ref().filter(|_| self.heat_map.is_none()) {
            let centre = response.rect.min + egui::vec2(picked.x as f32 + 0.5, picked.y as f32 + 0.5) * scale;
            let ring = egui::Stroke::new(1.5, egui::Color32::from_rgb(255, 0, 255));
            ui.painter().circle_stroke(centre, (2.0 * scale).max(5.0), ring);
        }
        self.fly(ui.ctx(), drag, size.x * scale);
    }
}

/// The keys that move the camera: held, they keep the window redrawing.
const MOVE_KEYS: [egui::Key; 12] = {
    use egui::Key::*;
    [W, S, A, D, R, F, Q, E, ArrowLeft, ArrowRight, ArrowUp, ArrowDown]
};

/// Draws one option's control; returns whether its value changed.
fn control_ui(ui: &mut egui::Ui, control: &mut Control) -> bool {
    let label = format!("--{}", control.long);
    let row = ui.horizontal(|ui| match &control.kind {
        Kind::Flag => {
            let mut set = control.is_set();
            let changed = ui.checkbox(&mut set, &label).changed();
            control.value = set.to_string();
            changed
        }
        Kind::Choice(choices) => {
            ui.label(&label);
            let shown = |value: &str| if value.is_empty() { control.placeholder.clone() } else { value.to_string() };
            let mut changed = false;
            let mut value = control.value.clone();
            egui::ComboBox::from_id_salt(&label).selected_text(shown(&value)).show_ui(ui, |ui| {
                // An option without a default can be left unset again.
                let unset = control.optional.then(String::new);
                for choice in unset.iter().chain(choices) {
                    changed |= ui.selectable_value(&mut value, choice.clone(), shown(choice)).changed();
                }
            });
            control.value = value;
            changed
        }
        Kind::Integer { min, max } => number_ui(ui, &label, control, *min..=*max, true),
        Kind::Real => number_ui(ui, &label, control, f64::NEG_INFINITY..=f64::INFINITY, false),
        Kind::Text => {
            ui.label(&label);
            let hint = control.placeholder.clone();
            ui.add(egui::TextEdit::singleline(&mut control.value).hint_text(hint).desired_width(140.0)).lost_focus()
        }
    });
    if !control.help.is_empty() {
        row.response.on_hover_text(&control.help);
    }
    row.inner
}

/// A number as a drag value within `range` (`integer` rounds it), or, while it has no value, a text field
/// showing what the option's default is. An option without a default can be emptied again.
fn number_ui(
    ui: &mut egui::Ui,
    label: &str,
    control: &mut Control,
    range: std::ops::RangeInclusive<f64>,
    integer: bool,
) -> bool {
    ui.label(label);
    let value = &mut control.value;
    // The text field stays while it has the focus, even once what is typed reads as a number.
    let field_id = ui.make_persistent_id(label);
    let typing = ui.memory(|m| m.has_focus(field_id));
    match value.trim().parse::<f64>() {
        Ok(mut number) if !typing => {
            let speed = if integer { 0.1 } else { (number.abs() * 0.005).max(0.001) };
            // A value typed in counts once it is entered, not at every key (typing 1.8 would render 1 first).
            let drag = egui::DragValue::new(&mut number).speed(speed).range(range).update_while_editing(false);
            let drag = if integer { drag.max_decimals(0) } else { drag.max_decimals(4) };
            let changed = ui.add(drag).changed();
            if changed {
                *value = if integer { format!("{}", number.round()) } else { format!("{number}") };
            }
            let cleared = control.optional
                && ui
                    .small_button("x")
                    .on_hover_text(format!("back to the default ({})", control.placeholder))
                    .clicked();
            if cleared {
                value.clear();
            }
            changed || cleared
        }
        _ => {
            let field =
                egui::TextEdit::singleline(value).id(field_id).hint_text(&control.placeholder).desired_width(60.0);
            ui.add(field).lost_focus()
        }
    }
}

impl<O: ExampleOptions> eframe::App for Viewer<O> {
    fn update(&mut self, ctx: &egui::Context, _frame: &mut eframe::Frame) {
        egui::SidePanel::left("options").resizable(true).default_width(300.0).show(ctx, |ui| self.side_panel(ui));
        egui::TopBottomPanel::bottom("status").show(ctx, |ui| {
            self.camera_panel(ui);
            self.status_line(ui);
        });
        self.pixel_panel(ctx);
        egui::CentralPanel::default().show(ctx, |ui| self.picture(ui));
    }
}
