//! The viewer's window: the picture in the middle, the example's options on the left, the clicked pixel's
//! report at the right or under the options, the camera and the status line below, each where
//! [`crate::layout`] puts it for the window's size. egui redraws the window when the example has sent
//! something or a key is held, and otherwise sleeps.
//!
//! Keys (while no text field has the focus): W/S forward and back, A/D left and right, R/F up and down,
//! the arrow keys turn and Q/E roll; dragging the mouse over the picture looks around; a click shows what
//! the pixel sees: the node and shader it hits and its whole ray tree (see `lecture6::instruments::ray_tree`).
//! Ctrl + and Ctrl - (or the "UI scale" control) scale the whole interface, for a projector.

use crate::layout::{Layout, layout};
use crate::link::{Link, Shown};
use eframe::egui;
use lecture6_viewer_protocol::UI_SCALES;
use lecture6_viewer_protocol::controls::{Control, Controls, Kind};
use lecture6_viewer_protocol::wire::{CameraShown, Request};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The camera counts as still this long after the last key or drag; then the picture refines.
const SETTLE: Duration = Duration::from_millis(150);

/// The window's size at the interface scale 1, in pixels: at another scale it is as many times larger, as
/// large as the screen at most.
const WINDOW_SIZE: [f32; 2] = [1180.0, 720.0];

/// Degrees the arrow keys turn the camera per second.
const TURN_RATE: f32 = 60.0;

/// What the window starts with: the example's name, its controls, the interface's scale and the pixel
/// whose tree it shows first.
pub struct Start {
    /// The example's name.
    pub name: String,
    /// Its options as controls.
    pub controls: Controls,
    /// The interface's scale (`--ui-scale`).
    pub ui_scale: f32,
    /// The pixel to inspect first (`--trace-pixel`).
    pub pixel: Option<(u32, u32)>,
}

/// Opens the window and runs it until it is closed, talking to the example through `link`. Fails when the
/// window cannot be opened (no display).
pub fn open(start: Start, link: Link) -> std::result::Result<(), String> {
    let name = start.name.clone();
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            // eframe makes it no larger than the screen (a projector's 1600 x 1000 at scale 1.5).
            .with_inner_size(WINDOW_SIZE.map(|side| side * start.ui_scale))
            .with_title(format!("{name} (lecture 6)")),
        ..Default::default()
    };
    let title = name.clone();
    eframe::run_native(
        &title,
        native,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            ctx.set_zoom_factor(start.ui_scale);
            Ok(Box::new(Viewer::new(start, link.listen(ctx))))
        }),
    )
    .map_err(|e| e.to_string())
}

/// The window's state.
struct Viewer {
    name: String,
    controls: Controls,
    /// Where requests go to the example.
    link: Link,
    /// What the example sent: the picture, its status, the answers.
    shown: Arc<Mutex<Shown>>,
    /// Scene units per second of the movement keys.
    speed: f32,
    /// When the camera last moved, while it has not yet settled.
    moving_since: Option<Instant>,
    texture: Option<egui::TextureHandle>,
    /// The heat map of the difference from the reference, shown instead of the picture.
    heat_map: Option<egui::TextureHandle>,
    /// The last clicked pixel, marked on the picture, and what it sees.
    picked: Option<Picked>,
    /// The pixel asked about whose answer has not come yet, and the picture it was asked of.
    asked: Option<(u32, u32, u64)>,
    /// How many pictures have been asked for: a clicked pixel's tree traced for an earlier one is stale.
    picture: u64,
    /// The interface's scale: egui's zoom factor.
    ui_scale: f32,
}

impl Viewer {
    fn new(start: Start, link: Link) -> Self {
        let shown = link.shown.clone();
        let mut viewer = Viewer {
            name: start.name,
            controls: start.controls,
            link,
            shown,
            speed: 0.0,
            moving_since: None,
            texture: None,
            heat_map: None,
            picked: None,
            asked: None,
            picture: 0,
            ui_scale: start.ui_scale,
        };
        if let Some((x, y)) = start.pixel {
            viewer.inspect(x, y);
        }
        viewer
    }

    /// Sends `request` to the example.
    fn send(&mut self, request: Request) {
        self.link.send(&request);
    }

    /// Sends a request that renders the picture again: the heat map of the last one goes.
    fn render(&mut self, request: Request) {
        self.heat_map = None;
        self.picture += 1;
        self.send(request);
    }

    /// The options changed: the example reads them as the command line would and renders the new scene (or
    /// says what is wrong with them).
    fn rebuild(&mut self) {
        self.render(Request::Options { controls: self.controls.clone() });
    }

    /// The camera shown, as the example describes it.
    fn current_camera(&self) -> Option<CameraShown> {
        self.shown.lock().ok()?.status.camera.clone()
    }

    /// Moves the camera as the keys held and the drag say (the example moves it and draws the quick
    /// preview while it moves), and asks for the full picture once it settles.
    fn fly(&mut self, ctx: &egui::Context, drag: egui::Vec2, image_width: f32) {
        let Some(camera) = self.current_camera() else { return };
        // Forward, right, up (times the speed), yaw, pitch, roll (degrees).
        let mut motion = [0.0f32; 6];
        if !ctx.wants_keyboard_input() {
            ctx.input(|i| {
                let dt = i.stable_dt.min(0.1);
                let axis = |plus: egui::Key, minus: egui::Key| {
                    (i.key_down(plus) as i32 - i.key_down(minus) as i32) as f32 * dt
                };
                use egui::Key::*;
                motion = [
                    axis(W, S),
                    axis(D, A),
                    axis(R, F),
                    axis(ArrowLeft, ArrowRight) * TURN_RATE,
                    axis(ArrowUp, ArrowDown) * TURN_RATE,
                    axis(E, Q) * TURN_RATE,
                ];
            });
        }
        // Dragging the picture turns the camera by the angle the drag spans on screen.
        let degrees_per_point = camera.fov / image_width.max(1.0) * 0.8;
        motion[3] += drag.x * degrees_per_point;
        motion[4] += drag.y * degrees_per_point;
        if motion.iter().any(|&m| m != 0.0) {
            let [forward, right, up, yaw, pitch, roll] = motion;
            self.render(Request::Move { forward, right, up, yaw, pitch, roll, distance: self.speed });
            self.moving_since = Some(Instant::now());
            ctx.request_repaint();
        } else if let Some(since) = self.moving_since {
            if since.elapsed() >= SETTLE {
                self.moving_since = None;
                self.render(Request::Settle {});
            } else {
                ctx.request_repaint_after(SETTLE);
            }
        }
        if ctx.input(|i| i.keys_down.iter().any(|k| MOVE_KEYS.contains(k))) {
            ctx.request_repaint();
        }
    }

    /// The options and the steps beyond the slides, in a scroll area `height` points high.
    fn side_panel(&mut self, ui: &mut egui::Ui, height: f32) {
        let mut changed = false;
        let scroll = egui::ScrollArea::vertical().id_salt("options").max_height(height).auto_shrink([false, false]);
        scroll.show(ui, |ui| {
            let mut heading: Option<Option<String>> = None;
            for control in &mut self.controls.controls {
                if heading.as_ref() != Some(&control.heading) {
                    ui.separator();
                    ui.strong(control.heading.clone().unwrap_or_else(|| format!("{} options", self.name)));
                    heading = Some(control.heading.clone());
                }
                changed |= control_ui(ui, control);
            }
            ui.separator();
            ui.strong("Steps beyond the slides");
            changed |= steps_ui(ui, &mut self.controls);
        });
        if changed {
            self.rebuild();
        }
    }

    fn camera_panel(&mut self, ui: &mut egui::Ui) {
        let Some(camera) = self.current_camera() else { return };
        if self.speed == 0.0 {
            // Half the camera's distance from the origin per second: the examples are built around it.
            self.speed = (camera.distance * 0.5).max(1.0);
        }
        // One row, whatever the camera: the status band's height is fixed (`crate::layout`).
        ui.horizontal(|ui| {
            ui.monospace(&camera.text).on_hover_text("W/S A/D R/F move, arrows turn, Q/E roll, drag to look");
            if ui.button("Copy as code").clicked() {
                ui.ctx().copy_text(camera.code.clone());
                self.say(format!("copied: {}", camera.code));
            }
            if ui.button("Reset camera").clicked() {
                self.render(Request::ResetCamera {});
            }
            ui.label("speed");
            let step = self.speed * 0.02;
            ui.add(egui::DragValue::new(&mut self.speed).speed(step));
            self.speed = self.speed.max(f32::MIN_POSITIVE);
        });
    }

    fn status_line(&mut self, ui: &mut egui::Ui) {
        let (text, finished, message) = {
            let shown = self.shown.lock().expect("the pipe's reader never panics holding the picture");
            let status = &shown.status;
            let mut text = format!(
                "{}x{}, {} spp, {}/{} tiles, {:.2} s, {:.2} M rays, {:.2} Mrays/s",
                shown.width,
                shown.height,
                status.spp,
                status.tiles_done,
                status.tiles_total,
                status.seconds,
                status.rays as f64 * 1e-6,
                status.rays as f64 * 1e-6 / status.seconds.max(1e-9)
            );
            if self.moving_since.is_some() {
                text += &format!(", moving: {} frames in the last second", status.frames_last_second);
            }
            if let Some(e) = &status.error {
                text = format!("error: {e}");
            }
            (text, status.finished, shown.message.clone())
        };
        ui.horizontal(|ui| {
            ui.label(text);
            ui.add_enabled_ui(finished, |ui| {
                for ext in ["png", "exr"] {
                    if ui.button(format!("Save .{ext}")).clicked() {
                        self.send(Request::Save { ext: ext.to_string() });
                    }
                }
                let compare_label = if self.heat_map.is_some() { "Show picture" } else { "Compare" };
                if ui.button(compare_label).clicked() {
                    // The heat map comes back from the example (`--compare`'s, with its colour bar).
                    if self.heat_map.take().is_none() {
                        self.send(Request::Compare {});
                    }
                }
            });
            ui.separator();
            ui.label("UI scale");
            let scale = egui::DragValue::new(&mut self.ui_scale).speed(0.01).range(UI_SCALES).max_decimals(2);
            if ui.add(scale).changed() {
                ui.ctx().set_zoom_factor(self.ui_scale);
            }
        });
        // Its row stays when there is no message, so that nothing above it moves when one comes.
        ui.add(egui::Label::new(if message.is_empty() { " ".to_string() } else { message }).truncate());
    }

    /// Shows `text` under the status line.
    fn say(&self, text: String) {
        self.shown.lock().expect("the pipe's reader never panics holding the picture").message = text;
    }

    /// Asks what pixel (x, y) of the picture sees: its colour on screen, the node and the shader its first
    /// camera ray hits, and that ray's whole tree as `--trace-pixel` prints it (traced by the example at the
    /// options' full quality, from the camera of the picture shown).
    fn inspect(&mut self, x: u32, y: u32) {
        self.asked = Some((x, y, self.picture));
        self.send(Request::Inspect { x, y });
    }

    /// Asks again for the clicked pixel's tree once the camera has settled or the options changed since it
    /// was traced.
    fn refresh_pixel(&mut self) {
        let stale = self.picked.as_ref().filter(|p| p.picture != self.picture && self.moving_since.is_none());
        if let Some((x, y)) = stale.map(|p| (p.x, p.y))
            && self.asked.is_none_or(|(.., asked_of)| asked_of != self.picture)
        {
            self.inspect(x, y);
        }
    }

    /// The clicked pixel's report, until closed: what it sees and its tree wrapped to the space it has
    /// ([`wrap_tree`]).
    fn pixel_report(&mut self, ui: &mut egui::Ui) {
        let Some(picked) = &self.picked else { return };
        let mut close = false;
        ui.horizontal(|ui| {
            ui.strong("Pixel");
            close = ui.button("Close").clicked();
        });
        ui.label(&picked.sees);
        ui.separator();
        egui::ScrollArea::vertical().id_salt("pixel").auto_shrink([false, false]).show(ui, |ui| {
            let font = egui::TextStyle::Monospace.resolve(ui.style());
            let glyph = ui.fonts_mut(|fonts| fonts.glyph_width(&font, 'x')).max(1.0);
            let columns = (ui.available_width() / glyph).floor().max(1.0) as usize;
            let tree = egui::RichText::new(wrap_tree(&picked.tree, columns)).monospace();
            ui.add(egui::Label::new(tree).extend());
        });
        if close {
            self.picked = None;
        }
    }

    /// Takes what the example sent since the last frame: the picture's new pixels, the heat map of a
    /// comparison, the ray tree of the pixel asked about. Closes the window when the example has ended.
    fn receive(&mut self, ctx: &egui::Context) {
        let mut shown = self.shown.lock().expect("the pipe's reader never panics holding the picture");
        if shown.dirty && shown.width > 0 {
            let image = egui::ColorImage::from_rgb([shown.width as usize, shown.height as usize], &shown.rgb);
            match &mut self.texture {
                Some(texture) => texture.set(image, egui::TextureOptions::NEAREST),
                None => self.texture = Some(ctx.load_texture("picture", image, egui::TextureOptions::NEAREST)),
            }
            shown.dirty = false;
        }
        if let Some(([width, height], rgb)) = shown.heat_map.take() {
            let image = egui::ColorImage::from_rgb([width as usize, height as usize], &rgb);
            self.heat_map = Some(ctx.load_texture("heat map", image, egui::TextureOptions::NEAREST));
        }
        if let Some(mut picked) = shown.picked.take()
            && let Some((x, y, picture)) = self.asked
            && (x, y) == (picked.x, picked.y)
        {
            self.asked = None;
            picked.picture = picture;
            self.picked = Some(picked);
        }
        if shown.ended {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }

    fn picture(&mut self, ui: &mut egui::Ui) {
        let Some(texture) = self.heat_map.as_ref().or(self.texture.as_ref()) else {
            ui.label("building the scene...");
            return;
        };
        let size = texture.size_vec2();
        // Fitted into the central panel, which is the layout's picture area.
        let shown = crate::layout::fitted(size, ui.max_rect());
        let scale = (shown.width() / size.x).max(0.1);
        let image = egui::Image::new(egui::load::SizedTexture::new(texture.id(), size * scale));
        let response = ui.put(shown, image.sense(egui::Sense::click_and_drag()));
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

/// A clicked pixel and what it sees: a line naming the node and shader it hits, and its ray tree.
pub struct Picked {
    /// Its column.
    pub x: u32,
    /// Its row.
    pub y: u32,
    /// The node and shader its first camera ray hits.
    pub sees: String,
    /// Its ray tree, as `--trace-pixel` prints it.
    pub tree: String,
    /// The picture it was traced in (the count of pictures asked for then).
    pub picture: u64,
}

/// How much deeper than its first line a wrapped line's continuation is indented, in characters.
const CONTINUATION: usize = 4;

/// `text` with every line longer than `columns` characters wrapped at spaces, its continuations indented
/// [`CONTINUATION`] characters deeper than the line itself, so that a wrapped line of the tree stays under
/// its ray (nothing is cut off on a projector).
fn wrap_tree(text: &str, columns: usize) -> String {
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

/// The keys that move the camera: held, they keep the window redrawing.
const MOVE_KEYS: [egui::Key; 12] = {
    use egui::Key::*;
    [W, S, A, D, R, F, Q, E, ArrowLeft, ArrowRight, ArrowUp, ArrowDown]
};

/// Draws the steps beyond the slides: `--slide`, which clears them all, and a check box per step (its
/// summary on hover); returns whether they changed.
fn steps_ui(ui: &mut egui::Ui, controls: &mut Controls) -> bool {
    let mut changed = false;
    let mut slide = controls.slide();
    let help = "the slides' reading: none of the steps beyond the slides (untick: all of them)";
    if ui.checkbox(&mut slide, "--slide").on_hover_text(help).changed() {
        controls.set_slide(slide);
        changed = true;
    }
    for step in &mut controls.steps {
        changed |= ui.checkbox(&mut step.taken, step.name.as_str()).on_hover_text(&step.summary).changed();
    }
    changed
}

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

impl Viewer {
    /// The window's layout now: for its size, the status band's height in the current style, the picture's
    /// size and whether a pixel's report is open.
    fn layout(&self, ctx: &egui::Context) -> Layout {
        let style = ctx.style();
        let row = style.spacing.interact_size.y + style.spacing.item_spacing.y;
        let margin = egui::Frame::side_top_panel(&style).total_margin().sum().y;
        let status_height = STATUS_ROWS * row + margin;
        let picture = self.heat_map.as_ref().or(self.texture.as_ref()).map_or(egui::Vec2::ZERO, |t| t.size_vec2());
        layout(ctx.content_rect().size(), status_height, picture, self.picked.is_some())
    }

    /// One frame of the window: what came in, then every panel where [`Viewer::layout`] puts it.
    fn show(&mut self, ctx: &egui::Context) {
        self.receive(ctx);
        // Ctrl + and Ctrl - change the zoom too: the control follows.
        self.ui_scale = ctx.zoom_factor();
        self.refresh_pixel();
        let layout = self.layout(ctx);
        egui::TopBottomPanel::bottom("status").resizable(false).exact_height(layout.status.height()).show(ctx, |ui| {
            self.camera_panel(ui);
            self.status_line(ui);
        });
        let margin = egui::Frame::side_top_panel(&ctx.style()).total_margin().sum();
        let options = egui::SidePanel::left("options").resizable(false).exact_width(layout.options.width());
        options.show(ctx, |ui| match layout.pixel.filter(|_| !layout.pixel_beside) {
            Some(_) => {
                self.side_panel(ui, layout.options.height() - margin.y);
                ui.separator();
                self.pixel_report(ui);
            }
            None => self.side_panel(ui, ui.available_height()),
        });
        if let Some(pixel) = layout.pixel.filter(|_| layout.pixel_beside) {
            let report = egui::SidePanel::right("pixel").resizable(false).exact_width(pixel.width());
            report.show(ctx, |ui| self.pixel_report(ui));
        }
        egui::CentralPanel::default().frame(egui::Frame::NONE).show(ctx, |ui| self.picture(ui));
    }
}

/// The rows of the status band: the camera, the status line and its buttons, a message.
const STATUS_ROWS: f32 = 3.0;

impl eframe::App for Viewer {
    fn update(&mut self, ctx: &egui::Context, _frame: &mut eframe::Frame) {
        self.show(ctx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{Event, Modifiers, PointerButton, Pos2, Rect, pos2, vec2};
    use lecture6_viewer_protocol::controls::StepBox;

    /// A projector's window, 1280 x 720 pixels, at the interface scale `--ui-scale 1.5`.
    const PROJECTOR: (egui::Vec2, f32) = (vec2(1280.0, 720.0), 1.5);

    /// An example's controls as the window gets them: its own options and the common ones (a flag, a choice,
    /// whole and real numbers, a path), then the steps beyond the slides.
    fn controls() -> Controls {
        let control = |long: &str, kind: Kind, value: &str, common: bool| Control {
            long: long.into(),
            help: format!("what --{long} does"),
            heading: common.then(|| "Common options".to_string()),
            kind,
            value: value.into(),
            optional: value.is_empty(),
            placeholder: "5".into(),
        };
        let integer = || Kind::Integer { min: 1.0, max: 100_000.0 };
        let mut all = vec![
            control("ior", Kind::Real, "1.5", false),
            control("fresnel", Kind::Choice(vec!["schlick".into(), "exact".into()]), "schlick", false),
            control("floor", Kind::Text, "", false),
        ];
        for long in ["width", "height", "spp", "max-depth", "seed"] {
            all.push(control(long, integer(), "", true));
        }
        for long in ["exposure", "gamma", "clamp-sample"] {
            all.push(control(long, Kind::Real, "0", true));
        }
        for long in ["no-aa", "stats", "linear"] {
            all.push(control(long, Kind::Flag, "false", true));
        }
        let steps = ["adaptive-depth", "node-bvh", "texel-filter", "stratified", "hero-wavelengths", "photon-grid"]
            .map(|name| StepBox { name: name.into(), summary: format!("what {name} does"), taken: true })
            .to_vec();
        Controls::new("fresnel", all, steps, Vec::new())
    }

    /// The window's state and egui's, driven frame by frame without a display.
    struct Headless {
        viewer: Viewer,
        ctx: egui::Context,
        size: egui::Vec2,
        time: f64,
    }

    impl Headless {
        /// A window of `pixels` at `ui_scale`, showing a 640 x 480 picture, with a pixel's report open.
        fn open((pixels, ui_scale): (egui::Vec2, f32)) -> Headless {
            let start = Start { name: "fresnel".into(), controls: controls(), ui_scale, pixel: None };
            let mut viewer = Viewer::new(start, Link::detached());
            viewer.picked =
                Some(Picked { x: 320, y: 200, sees: "hits glass sphere".into(), tree: tree(12), picture: 0 });
            let ctx = egui::Context::default();
            ctx.set_zoom_factor(ui_scale);
            let mut headless = Headless { viewer, ctx, size: pixels / ui_scale, time: 0.0 };
            headless.example_sends(|shown| {
                (shown.width, shown.height, shown.rgb, shown.dirty) = (640, 480, vec![90; 640 * 480 * 3], true);
            });
            headless.frames(3, Vec::new());
            headless
        }

        /// Runs `count` frames, the first with `events`, a tenth of a second apart (scrolling is animated).
        fn frames(&mut self, count: usize, mut events: Vec<Event>) {
            for _ in 0..count {
                self.time += 0.1;
                let mut input = egui::RawInput {
                    screen_rect: Some(Rect::from_min_size(Pos2::ZERO, self.size)),
                    time: Some(self.time),
                    predicted_dt: 0.1,
                    events: std::mem::take(&mut events),
                    ..Default::default()
                };
                input.viewports.entry(egui::ViewportId::ROOT).or_default().native_pixels_per_point = Some(1.0);
                let _ = self.ctx.run(input, |ctx| self.viewer.show(ctx));
            }
        }

        /// What the example sends, as the link's reader would put it.
        fn example_sends(&mut self, change: impl FnOnce(&mut Shown)) {
            change(&mut self.viewer.shown.lock().unwrap());
        }

        /// A click at `at`: the pointer moved there, pressed and released.
        fn click(&mut self, at: Pos2) {
            let button = |pressed| Event::PointerButton {
                pos: at,
                button: PointerButton::Primary,
                pressed,
                modifiers: Modifiers::NONE,
            };
            self.frames(1, vec![Event::PointerMoved(at)]);
            self.frames(1, vec![button(true)]);
            self.frames(2, vec![button(false)]);
        }

        /// The widget a click at the pointer would click now: its id and where it is.
        fn under_pointer(&self) -> Option<(egui::Id, Rect)> {
            self.ctx.viewport(|viewport| viewport.hits.click.map(|widget| (widget.id, widget.rect)))
        }

        /// The clickable widgets drawn last frame inside `area`, top to bottom.
        fn clickable_in(&self, area: Rect) -> Vec<Rect> {
            let mut found: Vec<Rect> = self.ctx.viewport(|viewport| {
                let widgets = viewport.prev_pass.widgets.layers().flat_map(|(_, widgets)| widgets.iter());
                widgets
                    .filter(|w| {
                        w.sense.senses_click() && w.interact_rect.is_positive() && area.contains_rect(w.interact_rect)
                    })
                    .map(|w| w.rect)
                    .collect()
            });
            found.sort_by(|a, b| a.min.y.total_cmp(&b.min.y));
            found
        }

        /// The steps' boxes, ticked or not.
        fn ticked(&self) -> Vec<bool> {
            self.viewer.controls.steps.iter().map(|step| step.taken).collect()
        }
    }

    /// A ray tree of `rays` rays, each line longer than a side panel is wide.
    fn tree(rays: usize) -> String {
        (0..rays)
            .map(|i| {
                format!(
                    "{}ray {i} (depth {i}) from (0.000, 60.000, -120.000) dir (0.001, -0.412, 0.911), weight 0.8000, \
                     hits glass sphere at distance 69.2005, shader Layered\n",
                    " ".repeat(2 * (i % 6))
                )
            })
            .collect()
    }

    #[test]
    fn on_a_projector_with_every_panel_open_the_picture_is_the_largest_thing() {
        let window = Headless::open(PROJECTOR);
        let layout = window.viewer.layout(&window.ctx);
        assert!(layout.pixel.is_some(), "the pixel's report is open");
        // The picture as drawn: the widget under the pointer at the layout's picture's centre.
        let mut window = window;
        window.frames(1, vec![Event::PointerMoved(layout.picture.center())]);
        let (_, picture) = window.under_pointer().expect("the picture is under the pointer");
        let width = window.size.x;
        assert!(picture.width() >= 0.6 * width, "the picture is {} of {width} points wide", picture.width());
        assert!((picture.width() / picture.height() - 4.0 / 3.0).abs() < 0.01, "{picture:?}");
        // Every other part of the window is smaller, and none covers it.
        let pixel = layout.pixel.unwrap();
        for part in [layout.options, pixel, layout.status] {
            assert!(part.area() < picture.area() && !part.intersects(picture.shrink(1.0)), "{part:?}, {picture:?}");
        }
    }

    #[test]
    fn a_ticked_box_stays_under_the_pointer_and_the_next_click_unticks_it() {
        let mut window = Headless::open(PROJECTOR);
        let layout = window.viewer.layout(&window.ctx);
        // Scrolled down to the steps, as a teacher does, the pointer over the options.
        let over = layout.options.center();
        let wheel = Event::MouseWheel {
            unit: egui::MouseWheelUnit::Point,
            delta: vec2(0.0, -5000.0),
            modifiers: Modifiers::NONE,
        };
        window.frames(1, vec![Event::PointerMoved(over)]);
        window.frames(20, vec![wheel]);
        let boxes = window.clickable_in(layout.options);
        let last = *boxes.last().expect("a box in the options");
        let at = pos2(last.min.x + 6.0, last.center().y);
        let before = window.ticked();
        window.click(at);
        let after = window.ticked();
        let toggled: Vec<usize> = (0..before.len()).filter(|&i| before[i] != after[i]).collect();
        assert_eq!(toggled.len(), 1, "one step toggled: {before:?} -> {after:?}");
        let under = window.under_pointer().expect("a box under the pointer");
        // What the toggle brings: the render starts again, a message, a new picture, the pixel's tree traced
        // again (longer), the status of the new render.
        window.example_sends(|shown| {
            shown.message = "rendering with the steps changed".into();
            shown.status.tiles_total = 300;
            shown.dirty = true;
            shown.picked = Some(Picked { x: 320, y: 200, sees: "hits the floor".into(), tree: tree(40), picture: 0 });
        });
        window.frames(10, Vec::new());
        assert_eq!(window.under_pointer(), Some(under), "the box moved from under the pointer");
        window.click(at);
        assert_eq!(window.ticked(), before, "the next click at the same place unticks the same box");
    }

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
