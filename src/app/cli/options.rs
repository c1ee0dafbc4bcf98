//! The options every example shares (`--width`, `--spp`, `--output`, `--compare`, ...) and the caustic
//! options, as clap reads them; an example's own options come first in its `--help`, these after them.

use crate::files::encoding::Encoding;
use crate::instruments::debug_view::DebugView;
use crate::instruments::ray_tree::{PixelPos, TraceFormat};
use crate::instruments::tone_mapping::ToneMap;
use crate::lesson::beyond::{Step, Steps};
use crate::lesson::camera::{FOV_LIMITS, FovAxis};
use crate::lesson::environment::CubemapLayout;
use crate::lesson::photon_map::PhotonSettings;
use crate::lesson::render::{MAX_SPP, MAX_THREADS};
use crate::lesson::scene::RECURSION_SAFETY_CAP;
use crate::lesson::spectral::{GamutMapping, Illuminant, MAX_WAVELENGTHS, SpectralMode};
use clap::builder::RangedI64ValueParser;
use lecture6_viewer_protocol::UI_SCALES;
use std::path::PathBuf;

/// The help heading of the options every example shares (set on each option, so that an example's own
/// options, listed after them, keep the plain "Options" heading).
const COMMON: &str = "Common options";

/// The help heading of the options that change only scenes with dispersive materials.
pub(super) const DISPERSION: &str = "Dispersion (scenes with dispersive glass only)";
/// The heading of the options that change how the picture is exposed and framed.
const PICTURE: &str = "Exposure and framing";

/// What the help of an option whose default the scene sets says until the scene is known (see
/// [`help_command`], which puts the example's own default there).
pub(super) const SCENE_DEFAULT: &str = "[default: the scene's own]";

/// A parser for a whole number in `range`, whose error names the range: `--spp -1` says "-1 is not in
/// 1..=65536" (with every option allowed to take negative numbers, see [`super::Cli::command_named`]).
pub fn whole_number<T>(range: std::ops::RangeInclusive<i64>) -> RangedI64ValueParser<T>
where
    T: TryFrom<i64> + Clone + Send + Sync + 'static,
    <T as TryFrom<i64>>::Error: std::error::Error + Send + Sync + 'static,
{
    RangedI64ValueParser::<T>::new().range(range)
}

/// The deepest `--max-depth` with `--exhaustive`. Nothing prunes the ray tree then, and every glass surface
/// splits a ray in two, so the rays of a sample can double with each level: the fresnel scene at 80 x 60
/// traces 0.3 M rays at depth 32, 14 M at depth 64, and does not finish in a minute at depth 100.
pub const MAX_EXHAUSTIVE_DEPTH: u32 = 64;

/// Reads `--fov`: degrees within [`FOV_LIMITS`], as a scene file's `fov`; the refusal names the limits.
fn field_of_view(text: &str) -> std::result::Result<f32, String> {
    match text.parse::<f64>() {
        Ok(fov) if FOV_LIMITS.contains(&fov) => Ok(fov as f32),
        Ok(_) => Err(format!(
            "{text} is not a field of view: it must be from {} to {} degrees",
            FOV_LIMITS.start(),
            FOV_LIMITS.end()
        )),
        Err(e) => Err(e.to_string()),
    }
}

/// Reads `--ui-scale`: a number within [`UI_SCALES`]; the refusal names them.
fn interface_scale(text: &str) -> std::result::Result<f32, String> {
    match text.parse::<f32>() {
        Ok(scale) if UI_SCALES.contains(&scale) => Ok(scale),
        Ok(_) => Err(format!("{text} is not from {} to {}", UI_SCALES.start(), UI_SCALES.end())),
        Err(e) => Err(e.to_string()),
    }
}

/// Reads `--max-depth`: a whole number up to [`RECURSION_SAFETY_CAP`], where every ray stops anyway; the
/// refusal says so.
fn ray_depth(text: &str) -> std::result::Result<u32, String> {
    match text.parse::<i64>() {
        Ok(depth) if (0..=RECURSION_SAFETY_CAP as i64).contains(&depth) => Ok(depth as u32),
        Ok(_) => Err(format!(
            "{text} is not in 0..={RECURSION_SAFETY_CAP}: every ray stops at depth {RECURSION_SAFETY_CAP} \
             whatever the limit (the recursion's safety cap, which keeps the stack from overflowing)"
        )),
        Err(e) => Err(e.to_string()),
    }
}

// Options every example accepts. (A plain comment: a doc comment here would become every example's `--help`
// description, which is its `Options` doc comment.)
#[allow(missing_docs)]
#[derive(clap::Args, Clone, Debug)]
pub struct CommonArgs {
    /// Image width in pixels; the picture may have 67108864 pixels at most (2^26, 8192 x 8192).
    /// [default: 640, or a scene file's own]
    #[arg(long, value_parser = whole_number::<u32>(1..=u32::MAX as i64), help_heading = COMMON)]
    pub width: Option<u32>,
    /// Image height in pixels; the picture may have 67108864 pixels at most (2^26, 8192 x 8192).
    /// [default: 480, or a scene file's own]
    #[arg(long, value_parser = whole_number::<u32>(1..=u32::MAX as i64), help_heading = COMMON)]
    pub height: Option<u32>,
    /// Anti-aliasing samples per pixel: 1 shoots through each pixel's centre; a square number uses a jittered
    /// grid, any other count N-rooks stratification.
    #[arg(long, value_parser = whole_number::<u32>(1..=MAX_SPP as i64), help_heading = COMMON)]
    pub spp: Option<u32>,
    /// The course's adaptive anti-aliasing: one sample through each pixel's centre, then four more in every
    /// pixel that differs from a neighbour by more than 0.1 (needs --spp 1).
    #[arg(long, help_heading = COMMON)]
    pub adaptive_aa: bool,
    /// Worker threads [default: all cores]. The picture is the same for any count.
    #[arg(long, value_parser = whole_number::<usize>(1..=MAX_THREADS as i64), help_heading = COMMON)]
    pub threads: Option<usize>,
    /// Maximum ray depth (the slides' MAX_RAY_DEPTH): deeper rays return black. At most 1000, the depth at
    /// which every ray stops anyway; at most 64 with --exhaustive or --slide. [default: the scene's own]
    #[arg(long, value_parser = ray_depth, help_heading = COMMON)]
    pub max_depth: Option<u32>,
    /// Trace every ray down to the maximum depth (`--no-step adaptive-depth`). By default a ray too weak to
    /// change its pixel by a whole 8-bit level (its weight, the product of the multipliers, blends and Fresnel
    /// factors along its path, is below the finest sRGB step) is not traced: adaptive ray-tree depth control.
    #[arg(long, help_heading = COMMON)]
    pub exhaustive: bool,
    /// Render as the slides write it: none of the steps beyond the slides (docs/beyond-the-slides.md): every
    /// ray to the maximum depth (at most 64 then), the loop over the nodes, a mesh's triangles one by one, one
    /// texel per look-up, random points of the pixel and of the unit disc, K wavelength passes, every layer,
    /// photons in all directions and the k nearest from a k-d tree, world coordinates. The guards hold as by
    /// default. Compare the two with `--side-by-side "--slide"`.
    #[arg(long, help_heading = COMMON)]
    pub slide: bool,
    /// Take this step beyond the slides even with --slide (repeat it for more): show one step at a time.
    #[arg(long, value_enum, value_name = "STEP", help_heading = COMMON)]
    pub step: Vec<Step>,
    /// Leave this step beyond the slides out (repeat it for more): what the default gains from it.
    #[arg(long, value_enum, value_name = "STEP", help_heading = COMMON)]
    pub no_step: Vec<Step>,
    /// Seed of every random choice; the same seed gives the same picture, byte for byte.
    #[arg(long, default_value_t = 1, help_heading = COMMON)]
    pub seed: u64,
    /// Where to write the picture: .png is 8-bit sRGB, .exr and .hdr are linear floating point.
    /// [default: out/EXAMPLE.png; with --compare, out/EXAMPLE-compared.png; with --show-photons,
    /// out/EXAMPLE-photons.png]
    #[arg(long, short, help_heading = COMMON)]
    pub output: Option<PathBuf>,
    /// Print, before the render, one line of the settings this example takes when no option is given: its
    /// samples, size and ray depth as its scene sets them, and the defaults of its own options
    /// (`NAME: defaults: --spp 5, --width 640, --height 480, --max-depth 8, --ior 1.5`). The class command
    /// reads it to show where a student's program differs from the reference.
    #[arg(long, help_heading = COMMON)]
    pub print_defaults: bool,
    /// No progress bar, summary, notes or warnings. Errors are still printed, and so is what was asked
    /// for: --compare's result, --trace-pixel's tree, --view's and --side-by-side's lines.
    #[arg(long, short, help_heading = COMMON)]
    pub quiet: bool,
    /// Compare the picture with a reference (checked before the render): print RMSE, PSNR, the largest
    /// difference and whether it is within the regression tests' tolerance, and write a heat map of the
    /// difference, scaled to the largest one, next to the output (OUTPUT-diff.png). Without --output the
    /// picture goes to out/EXAMPLE-compared.png: out/EXAMPLE.png, an earlier render, stays. An 8-bit reference
    /// (.png) is compared in 8-bit sRGB, a linear one (.exr, .hdr) in linear light too. Its size is checked
    /// from its header and must be the picture's; being no larger than the picture, it does not count towards
    /// the budget of the scene's images (see --env).
    #[arg(long, value_name = "REFERENCE", help_heading = COMMON, conflicts_with_all = ["trace_pixel", "view", "side_by_side"])]
    pub compare: Option<PathBuf>,
    /// Your own environment for rays that hit nothing, replacing the scene's: an equirectangular image file
    /// (its centre faces +Z, where the default camera looks) or a folder holding six cube faces posx, negx,
    /// posy, negy, posz, negz (.png, .jpg, .bmp, .hdr or .exr). The images of a run (textures and
    /// environment) may have 67108864 pixels together, 2^26 (an 8192 x 8192 picture): a file over that budget
    /// is refused from its header, before it is decoded.
    #[arg(long, value_name = "FILE|FOLDER", help_heading = COMMON)]
    pub env: Option<PathBuf>,
    /// How the faces of an `--env` cube-map folder are oriented: `opengl`, the default, is the layout of
    /// skyboxes made for OpenGL and Direct3D and of the workbook's own `textures/sky_cubemap`; `course` is the
    /// course's cube maps, whose negz face is turned by 180°.
    #[arg(long, value_enum, default_value_t = CubemapLayout::OpenGl, help_heading = COMMON)]
    pub env_layout: CubemapLayout,
    /// Wavelengths: with `--spectral hero` the wavelengths each camera path carries; with `passes` the passes
    /// K (the slide's method: the frame is traced K times, once per band of the spectrum, and the passes are
    /// added with the bands' colours). [default: 4 per path, 8 passes]
    #[arg(long, value_parser = whole_number::<u32>(1..=MAX_WAVELENGTHS as i64), help_heading = DISPERSION)]
    pub wavelengths: Option<u32>,
    /// How the wavelengths are traced: `hero` (every anti-aliasing sample carries --wavelengths wavelengths,
    /// traced as one path until it meets dispersive glass, where it splits), `passes` (K wavelength passes,
    /// the slide's method) or `sampled` (every sample carries its own band of the spectrum). [default: hero]
    #[arg(long, value_enum, help_heading = DISPERSION)]
    pub spectral: Option<SpectralMode>,
    /// The spectrum of the scene's white light: `d65` (daylight, sRGB's white: white stays white) or
    /// `equal-energy` (the same power at every wavelength: white comes out a little pink). [default: d65]
    #[arg(long, value_enum, help_heading = DISPERSION)]
    pub illuminant: Option<Illuminant>,
    /// How a colour outside the sRGB gamut (a narrow band of the spectrum) is shown: `clip` (negative
    /// channels become 0: saturated) or `fit` (grey of the same luminance mixed in: desaturated). EXR output
    /// keeps the unmapped values, negative channels included. [default: clip]
    #[arg(long, value_enum, help_heading = DISPERSION)]
    pub gamut: Option<GamutMapping>,
    /// The photon-mapping options (`--photons`, `--k`, `--radius`, `--show-photons`, `--photon-passes`).
    #[command(flatten)]
    pub photons: PhotonArgs,
    /// Print the tree of rays behind pixel X,Y (from the top left) instead of rendering: each ray's kind,
    /// start, direction, what it hits, the shader and layer that sent it, its weight, its colour and why it
    /// stopped, and how the colours add up to the pixel's.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true, help_heading = COMMON, conflicts_with = "side_by_side")]
    pub trace_pixel: Option<PixelPos>,
    /// Which camera ray of the pixel --trace-pixel shows (numbered from 0).
    #[arg(long, default_value_t = 0, value_name = "N", help_heading = COMMON)]
    pub trace_sample: u32,
    /// How --trace-pixel prints the tree: `text` (indented) or `json`.
    #[arg(long, value_enum, default_value_t = TraceFormat::Text, help_heading = COMMON)]
    pub trace_format: TraceFormat,
    /// Write a false-colour debug view instead of the shaded picture (to --output, or out/EXAMPLE-VIEW.png)
    /// and print its scale: the normals, texture coordinates (after the texture's scaling) or distance of
    /// what each pixel sees, where its shader read its first texture and what that read returned, or a heat
    /// map of the rays or shadow rays (log scale) or the deepest ray (linear) traced per pixel, with its
    /// legend in a strip below the picture.
    #[arg(long, value_enum, help_heading = COMMON, conflicts_with_all = ["trace_pixel", "side_by_side"])]
    pub view: Option<DebugView>,
    /// The top of a heat view's legend (--view rays, shadow-rays, depth-reached): the count (or depth) shown
    /// white, the scale starting at 1 (or 0). Two views with the same N show the same value in the same
    /// colour: `--view rays --legend-max 2000` with and without --exhaustive. Larger values are white too.
    /// [default: the view's own largest value]
    #[arg(long, value_name = "N", value_parser = whole_number::<u32>(1..=u32::MAX as i64), requires = "view", help_heading = COMMON)]
    pub legend_max: Option<u32>,
    /// Render the example twice, with its options and with OPTIONS added (e.g. "--fresnel exact"), and write
    /// one picture A | B | difference heat map with captions (to --output, or out/EXAMPLE-side-by-side.png).
    /// Each panel is developed as its own options say (--exposure, --tonemap, --gamut).
    /// The heat map is --compare's: black where A and B agree, white at their largest difference, with its
    /// colour bar.
    #[arg(long, value_name = "OPTIONS", allow_hyphen_values = true, help_heading = COMMON)]
    pub side_by_side: Option<String>,
    /// Open a window that shows the picture building up, with the options as controls and a camera that
    /// moves (needs the viewer, built once with `cargo build --release -p lecture6-viewer`). With
    /// --trace-pixel, the window opens on that pixel's ray tree.
    #[arg(long, help_heading = COMMON)]
    pub window: bool,
    /// The size of the text, for a projector: the window's interface and its ray tree, and the captions
    /// --side-by-side and --view write into their pictures, times SCALE (from 0.5 to 4).
    #[arg(long, value_name = "SCALE", value_parser = interface_scale, default_value_t = 1.0, help_heading = COMMON)]
    pub ui_scale: f32,
    /// Exposure in stops: the picture is multiplied by 2^EV before it is written (-1 halves the light). For
    /// HDR skies that come out white.
    #[arg(long, value_name = "EV", default_value_t = 0.0, allow_hyphen_values = true, help_heading = PICTURE)]
    pub exposure: f32,
    /// How light above 1 fits a PNG: clamp (the course's: white above 1) or reinhard (compresses highlights,
    /// darker overall). EXR and HDR output keep linear light.
    #[arg(long, value_enum, default_value_t = ToneMap::Clamp, help_heading = PICTURE)]
    pub tonemap: ToneMap,
    /// What an 8-bit code means, in the files the scene reads and the PNG written: `srgb` (correct: codes
    /// are decoded to light before shading and light encoded after) or `raw` (the course's lecture-6
    /// program: a code over 255 is the light itself, read and written, no curve; its pictures look so).
    #[arg(long, value_enum, default_value_t = Encoding::Srgb, help_heading = PICTURE)]
    pub encoding: Encoding,
    /// Scale down every sample brighter than MAX in any channel to MAX: tames fireflies (a glossy sphere
    /// under a bright sun), at the price of bias: the clamped light is lost.
    #[arg(long, value_name = "MAX", allow_hyphen_values = true, help_heading = PICTURE)]
    pub clamp_sample: Option<f32>,
    /// The camera's field of view in degrees, from 0.0001 to 179, across the picture's diagonal (the course's
    /// convention) or the extent that --fov-axis names: smaller zooms in, larger shows more. [default: the
    /// scene's own]
    #[arg(long, value_name = "DEGREES", value_parser = field_of_view, allow_hyphen_values = true, help_heading = PICTURE)]
    pub fov: Option<f32>,
    /// Which extent of the picture stays when the aspect ratio changes: diagonal (the course's: a wider
    /// picture shows less at the top), vertical or horizontal. The picture at 640 x 480 is the same for all
    /// three. [default: the scene's own]
    #[arg(long, value_enum, help_heading = PICTURE)]
    pub fov_axis: Option<FovAxis>,
}

impl CommonArgs {
    /// The steps beyond the slides the options ask for: none with `--slide`, every one by default, then the
    /// steps `--step` adds and `--no-step` takes away (`--exhaustive` is `--no-step adaptive-depth`).
    pub fn steps(&self) -> Steps {
        let steps = if self.slide { Steps::SLIDES } else { Steps::ALL };
        let steps = self.step.iter().fold(steps, |steps, &step| steps.with(step));
        let steps = self.no_step.iter().fold(steps, |steps, &step| steps.without(step));
        if self.exhaustive { steps.without(Step::AdaptiveDepth) } else { steps }
    }

    /// The deepest ray depth the render can take, if the options cap it: 64 (`MAX_EXHAUSTIVE_DEPTH`) without
    /// adaptive depth control (`--exhaustive`, `--slide`), where nothing prunes the ray tree.
    pub fn max_trace_depth(&self) -> Option<u32> {
        (!self.steps().has(Step::AdaptiveDepth)).then_some(MAX_EXHAUSTIVE_DEPTH)
    }
}

/// The `--help` heading of the photon-mapping options (set per option: a heading set on the whole struct
/// would also cover the options that follow it in an example's own list).
const HEADING: &str = "Caustics (photon mapping)";

// The photon-mapping options every example accepts. (A plain comment, as on `cli::CommonArgs`: a doc comment
// here would become every example's `--help` description.)
#[allow(missing_docs)]
#[derive(clap::Args, Clone, Debug, Default)]
pub struct PhotonArgs {
    /// Photons shot at the mirrors and glass for the caustic photon map; 0 renders without one.
    /// [default: the scene's own]
    #[arg(long, value_name = "N", help_heading = HEADING)]
    pub photons: Option<u32>,
    /// How many nearest photons each caustic estimate gathers. [default: the scene's own]
    #[arg(long, value_name = "K", help_heading = HEADING)]
    pub k: Option<u32>,
    /// The largest distance from a shaded point at which photons count. [default: the scene's own]
    #[arg(long, value_name = "R", allow_hyphen_values = true, help_heading = HEADING)]
    pub radius: Option<f32>,
    /// Draw each stored photon as a dot instead of estimating the caustic light from them. The picture
    /// goes to out/EXAMPLE-photons.png (without --output): the caustic picture at out/EXAMPLE.png stays.
    #[arg(long, help_heading = HEADING)]
    pub show_photons: bool,
    /// Passes of the progressive caustic: each traces a photon map of its own (as many photons, its own
    /// seed) and renders the picture with it, the passes after the first gathering within a radius that
    /// shrinks from pass to pass; the pictures are averaged, so the caustic's noise and blur both fade.
    /// Takes N times as long. Needs the step photon-grid. [default: 1, one photon map]
    #[arg(long, value_name = "N", help_heading = HEADING)]
    pub photon_passes: Option<u32>,
}

impl PhotonArgs {
    /// The scene's photon settings with the options given on the command line.
    pub fn apply(&self, settings: &mut PhotonSettings) {
        settings.count = self.photons.unwrap_or(settings.count);
        settings.k = self.k.unwrap_or(settings.k);
        settings.max_radius = self.radius.or(settings.max_radius);
        settings.show |= self.show_photons;
    }
}
