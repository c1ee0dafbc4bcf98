//! The viewer's window: the picture in the middle, the example's options on the left, the camera and the
//! status line below. egui redraws the window when the render thread has painted something or a key is
//! held, and otherwise sleeps.
//!
//! Keys (while no text field has the focus): W/S forward and back, A/D left and right, R/F up and down,
//! the arrow keys turn and Q/E roll; dragging the mouse over the picture looks around; a click shows what
//! the pixel sees.

use super::controls::{Control, Controls, Kind};
use super::fly::{Motion, as_code, moved};
use super::worker::{Job, Worker};
use crate::camera::Camera;
use crate::cli::{Cli, Example};
use crate::compare;
use crate::error::Result;
use crate::progressive::preview_settings;
use crate::render::RenderSettings;
use eframe::egui;
use std::ffi::OsString;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

/// The camera counts as still this long after the last key or drag; then the picture refines.
const SETTLE: Duration = Duration::from_millis(150);

/// Degrees the arrow keys turn the camera per second.
const TURN_RATE: f32 = 60.0;

/// Opens the window and runs it until it is closed. Fails when the window cannot be opened (no display).
pub fn open<E: Example>(name: &str, cli: Cli<E>, args: &[OsString]) -> std::result::Result<(), String> {
    let controls = Controls::new::<E>(name, args).map_err(|e| e.to_string())?;
    let name = name.to_string();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1180.0, 720.0])
            .with_title(format!("{name} (lecture 6)")),
        ..Default::default()
    };
    let title = name.clone();
    eframe::run_native(
        &title,
        options,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let app = Viewer::new(name, cli, controls, move || ctx.request_repaint()).map_err(|e| e.to_string())?;
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| e.to_string())
}

/// The window's state.
struct Viewer<E: Example> {
    name: String,
    controls: Controls,
    /// The options of the picture shown (the last valid ones).
    cli: Cli<E>,
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
    /// What the last clicked pixel sees.
    pixel: String,
}

impl<E: Example> Viewer<E> {
    fn new(name: String, cli: Cli<E>, controls: Controls, repaint: impl Fn() + Send + Sync + 'static) -> Result<Self> {
        let worker = Worker::start(cli.common.threads, repaint)?;
        let mut viewer = Viewer {
            name,
            controls,
            cli,
            worker,
            camera: None,
            speed: 0.0,
            moving_since: None,
            texture: None,
            heat_map: None,
            message: String::new(),
            pixel: String::new(),
        };
        viewer.rebuild();
        Ok(viewer)
    }

    fn settings(&self) -> RenderSettings {
        RenderSettings { progress: false, ..self.cli.settings() }
    }

    fn submit(&mut self, rebuild: bool, preview: bool) {
        let cli = self.cli.clone();
        let settings = self.settings();
        self.heat_map = None;
        self.worker.submit(Job {
            rebuild: rebuild.then(|| Box::new(move || cli.prepare_scene()) as _),
            camera: self.camera,
            settings,
            preview: preview.then(|| preview_settings(&settings)),
            cancel: Arc::new(AtomicBool::new(false)),
        });
    }

    /// The options changed: parse them as the command line would and render the new scene.
    fn rebuild(&mut self) {
        match self.controls.parse::<E>() {
            Ok(cli) => match cli.settings().check() {
                Ok(()) => {
                    self.cli = cli;
                    self.message.clear();
                    self.submit(true, false);
                }
                Err(e) => self.message = e.to_string(),
            },
            Err(e) => self.message = crate::cli::one_line(&e.to_string()),
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
        ui.horizontal(|ui| {
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
                        let path = self.cli.output_path(&self.name).with_extension(ext);
                        self.message = match frame.save(&path) {
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
            ui.label(&self.message);
        });
        if !self.pixel.is_empty() {
            ui.monospace(&self.pixel);
        }
    }

    /// Shows the heat map of the difference from the reference (`--compare`'s, or `expected/<name>.png`)
    /// instead of the picture, or the picture again.
    fn toggle_compare(&mut self, ctx: &egui::Context, frame: &crate::render::Frame) {
        if self.heat_map.take().is_some() {
            return;
        }
        let reference = self
            .cli
            .common
            .compare
            .clone()
            .unwrap_or_else(|| std::path::Path::new("expected").join(format!("{}.png", self.name)));
        let heat = compare::load_reference(&reference).and_then(|expected| {
            let actual = frame.to_rgb8();
            let d = compare::difference(&actual, &expected)?;
            Ok((compare::heat_map(&actual, &expected)?, d))
        });
        match heat {
            Ok((heat, d)) => {
                let size = [heat.width() as usize, heat.height() as usize];
                let image = egui::ColorImage::from_rgb(size, heat.as_raw());
                self.heat_map = Some(ctx.load_texture("heat map", image, egui::TextureOptions::NEAREST));
                self.message = format!("compared with {}: {d}", reference.display());
            }
            Err(e) => self.message = e.to_string(),
        }
    }

    /// Describes what pixel (x, y) of the picture sees.
    fn inspect(&mut self, x: u32, y: u32) {
        let shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
        let Some(scene) = shown.scene.clone() else { return };
        if x >= shown.width || y >= shown.height {
            return;
        }
        let i = (y as usize * shown.width as usize + x as usize) * 3;
        let rgb = [shown.rgb[i], shown.rgb[i + 1], shown.rgb[i + 2]];
        let linear = shown.finished.as_ref().map(|(frame, _)| frame.get(x, y));
        drop(shown);
        let size = self.cli.settings();
        let ray = scene.camera.frame(size.width, size.height).get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
        let mut text = format!("pixel ({x}, {y}): sRGB ({}, {}, {})", rgb[0], rgb[1], rgb[2]);
        if let Some(c) = linear {
            text += &format!(", linear ({:.4}, {:.4}, {:.4})", c.r(), c.g(), c.b());
        }
        text += &match scene.closest_hit(&ray) {
            Some((info, node)) => {
                let index = scene.nodes.iter().position(|n| std::ptr::eq(n, node)).unwrap_or_default();
                let (p, n, (u, v)) = (info.ip, info.normal, info.uv());
                format!(
                    "; hits node {index} at ({:.3}, {:.3}, {:.3}), distance {:.3}, normal ({:.3}, {:.3}, {:.3}), u/v ({:.3}, \
                     {:.3})",
                    p.x, p.y, p.z, info.distance, n.x, n.y, n.z, u, v
                )
            }
            None => "; hits nothing (the environment)".to_string(),
        };
        self.pixel = text;
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
            && let Some(pos) = response.interact_pointer_pos()
        {
            let p = (pos - response.rect.min) / scale;
            let size = self.cli.settings();
            let (w, h) = (size.width, size.height);
            let (x, y) = ((p.x.max(0.0) as u32).min(w - 1), (p.y.max(0.0) as u32).min(h - 1));
            self.inspect(x, y);
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
            let mut changed = false;
            egui::ComboBox::from_id_salt(&label).selected_text(control.value.as_str()).show_ui(ui, |ui| {
                for choice in choices {
                    changed |= ui.selectable_value(&mut control.value, choice.clone(), choice).changed();
                }
            });
            changed
        }
        Kind::Integer { min } => number_ui(ui, &label, &mut control.value, *min, true),
        Kind::Real => number_ui(ui, &label, &mut control.value, f64::NEG_INFINITY, false),
        Kind::Text => {
            ui.label(&label);
            ui.add(egui::TextEdit::singleline(&mut control.value).hint_text("default").desired_width(140.0))
                .lost_focus()
        }
    });
    if !control.help.is_empty() {
        row.response.on_hover_text(&control.help);
    }
    row.inner
}

/// A number as a drag value (or, while it has no value, a text field); `integer` rounds it.
fn number_ui(ui: &mut egui::Ui, label: &str, value: &mut String, min: f64, integer: bool) -> bool {
    ui.label(label);
    match value.trim().parse::<f64>() {
        Ok(mut number) => {
            let speed = if integer { 0.1 } else { (number.abs() * 0.005).max(0.001) };
            let drag = egui::DragValue::new(&mut number).speed(speed).range(min..=f64::INFINITY);
            let drag = if integer { drag.max_decimals(0) } else { drag.max_decimals(4) };
            let changed = ui.add(drag).changed();
            if changed {
                *value = if integer { format!("{}", number.round()) } else { format!("{number}") };
            }
            let cleared = min >= 0.0 && integer && ui.small_button("x").on_hover_text("back to the default").clicked();
            if cleared {
                value.clear();
            }
            changed || cleared
        }
        Err(_) => ui.add(egui::TextEdit::singleline(value).hint_text("default").desired_width(60.0)).lost_focus(),
    }
}

impl<E: Example> eframe::App for Viewer<E> {
    fn update(&mut self, ctx: &egui::Context, _frame: &mut eframe::Frame) {
        egui::SidePanel::left("options").resizable(true).default_width(300.0).show(ctx, |ui| self.side_panel(ui));
        egui::TopBottomPanel::bottom("status").show(ctx, |ui| {
            self.camera_panel(ui);
            self.status_line(ui);
        });
        egui::CentralPanel::default().show(ctx, |ui| self.picture(ui));
    }
}
