//! The command line every example shares, and the one function that runs an example end to end:
//! parse the options, build the scene, render, write the picture, compare it with a reference if asked,
//! and print one summary line. The regression tests go through [`Cli::render`], the same path.
//!
//! Errors in user input print one line naming the file or value and exit with code 2 (as clap does for
//! unknown options, whose message is put on one line too), never a panic.

use crate::instruments::compare::{self, Reference};
use crate::instruments::debug_view::{DebugView, write_view};
use crate::instruments::ray_tree::{PixelPos, TraceFormat, trace_pixel};
use crate::instruments::side_by_side::side_by_side;
use crate::lesson::camera::FovAxis;
use crate::lesson::environment::{self, CubemapLayout};
use crate::lesson::error::{Error, Result};
use crate::lesson::photon_map::{PhotonArgs, PhotonMap};
use crate::lesson::render::{
    Frame, MAX_SPP, MAX_THREADS, RenderSettings, RenderStats, keeps_linear_light, render, save_atomically, thread_pool,
};
use crate::lesson::scene::{RECURSION_SAFETY_CAP, Scene};
use crate::lesson::spectral::{MAX_WAVELENGTHS, SpectralMode, SpectralPlan};
use crate::lesson::tone_mapping::{Film, ToneMap};
use clap::builder::RangedI64ValueParser;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

/// The help heading of the options every example shares (set on each option, so that an example's own
/// options, listed after them, keep the plain "Options" heading).
const COMMON: &str = "Common options";

/// The help heading of the options that change only scenes with dispersive materials.
const DISPERSION: &str = "Dispersion (scenes with dispersive glass only)";
/// The heading of the options that change how the picture is exposed and framed.
const PICTURE: &str = "Exposure and framing";

/// What the help of an option whose default the scene sets says until the scene is known (see
/// [`help_command`], which puts the example's own default there).
const SCENE_DEFAULT: &str = "[default: the scene's own]";

/// A parser for a whole number in `range`, whose error names the range: `--spp -1` says "-1 is not in
/// 1..=65536" (with every option allowed to take negative numbers, see [`Cli::command_named`]).
pub fn whole_number<T>(range: std::ops::RangeInclusive<i64>) -> RangedI64ValueParser<T>
where
    T: TryFrom<i64> + Clone + Send + Sync + 'static,
    <T as TryFrom<i64>>::Error: std::error::Error + Send + Sync + 'static,
{
    RangedI64ValueParser::<T>::new().range(range)
}

// Options every example accepts. (A plain comment: a doc comment here would become every example's `--help`
// description, which is its `Options` doc comment.)
#[derive(clap::Args, Clone, Debug)]
pub struct CommonArgs {
    /// Image width in pixels. [default: 640, or a scene file's own]
    #[arg(long, value_parser = whole_number::<u32>(1..=u32::MAX as i64), help_heading = COMMON)]
    pub width: Option<u32>,
    /// Image height in pixels. [default: 480, or a scene file's own]
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
    /// Maximum ray depth (the slides' MAX_RAY_DEPTH): deeper rays return black. [default: the scene's own]
    #[arg(long, value_parser = whole_number::<u32>(0..=u32::MAX as i64), help_heading = COMMON)]
    pub max_depth: Option<u32>,
    /// Trace every ray down to the maximum depth. By default a ray too weak to change its pixel by a whole
    /// 8-bit level (its weight, the product of the multipliers, blends and Fresnel factors along its path, is
    /// below the finest sRGB step) is not traced: adaptive ray-tree depth control.
    #[arg(long, help_heading = COMMON)]
    pub exhaustive: bool,
    /// Seed of every random choice; the same seed gives the same picture, byte for byte.
    #[arg(long, default_value_t = 1, help_heading = COMMON)]
    pub seed: u64,
    /// Where to write the picture: .png is 8-bit sRGB, .exr and .hdr are linear floating point.
    /// [default: out/EXAMPLE.png]
    #[arg(long, short, help_heading = COMMON)]
    pub output: Option<PathBuf>,
    /// Print nothing but errors: no progress bar, no summary.
    #[arg(long, short, help_heading = COMMON)]
    pub quiet: bool,
    /// Compare the picture with a reference (checked before the render): print RMSE, PSNR, the largest
    /// difference and whether it is within the regression tests' tolerance, and write a heat map of the
    /// difference, scaled to the largest one, next to the output (OUTPUT-diff.png). An 8-bit reference
    /// (.png) is compared in 8-bit sRGB, a linear one (.exr, .hdr) in linear light too.
    #[arg(long, value_name = "REFERENCE", help_heading = COMMON)]
    pub compare: Option<PathBuf>,
    /// Your own environment for rays that hit nothing, replacing the scene's: an equirectangular image file
    /// (its centre faces +Z, where the default camera looks) or a folder holding six cube faces posx, negx,
    /// posy, negy, posz, negz (.png, .jpg, .bmp, .hdr or .exr).
    #[arg(long, value_name = "FILE|FOLDER", help_heading = COMMON)]
    pub env: Option<PathBuf>,
    /// How the faces of an `--env` cube-map folder are oriented: `opengl`, the default, is the layout of
    /// skyboxes made for OpenGL and Direct3D and of the workbook's own `textures/sky_cubemap`; `course` is the
    /// course's cube maps, whose negz face is turned by 180°.
    #[arg(long, value_enum, default_value_t = CubemapLayout::OpenGl, help_heading = COMMON)]
    pub env_layout: CubemapLayout,
    /// Wavelength passes K (the slide's method): the frame is traced K times, once per band of the
    /// spectrum, and the passes are added with the bands' colours. [default: 8]
    #[arg(long, value_parser = whole_number::<u32>(1..=MAX_WAVELENGTHS as i64), help_heading = DISPERSION)]
    pub wavelengths: Option<u32>,
    /// How the wavelengths are traced: `passes` (K wavelength passes, the slide's method) or `sampled` (one
    /// pass; every anti-aliasing sample carries its own band of the spectrum). [default: passes]
    #[arg(long, value_enum, help_heading = DISPERSION)]
    pub spectral: Option<SpectralMode>,
    #[command(flatten)]
    pub photons: PhotonArgs,
    /// Print the tree of rays behind pixel X,Y (from the top left) instead of rendering: each ray's kind,
    /// start, direction, what it hits, the shader and layer that sent it, its weight, its colour and why it
    /// stopped, and how the colours add up to the pixel's.
    #[arg(long, value_name = "X,Y", help_heading = COMMON)]
    pub trace_pixel: Option<PixelPos>,
    /// Which camera ray of the pixel --trace-pixel shows (numbered from 0).
    #[arg(long, default_value_t = 0, value_name = "N", help_heading = COMMON)]
    pub trace_sample: u32,
    /// How --trace-pixel prints the tree: `text` (indented) or `json`.
    #[arg(long, value_enum, default_value_t = TraceFormat::Text, help_heading = COMMON)]
    pub trace_format: TraceFormat,
    /// Write a false-colour debug view instead of the shaded picture (to --output, or out/EXAMPLE-VIEW.png)
    /// and print its scale: the normals, u/v or distance of what each pixel sees, or a heat map of the rays,
    /// the shadow rays or the deepest ray traced per pixel.
    #[arg(long, value_enum, help_heading = COMMON)]
    pub view: Option<DebugView>,
    /// Render the example twice, with its options and with OPTIONS added (e.g. "--fresnel exact"), and write
    /// one picture A | B | difference heat map with captions (to --output, or out/EXAMPLE-side-by-side.png).
    #[arg(long, value_name = "OPTIONS", allow_hyphen_values = true, help_heading = COMMON)]
    pub side_by_side: Option<String>,
    /// Open a window that shows the picture building up, with the options as controls and a camera that
    /// moves (needs `--features viewer`).
    #[arg(long, help_heading = COMMON)]
    pub window: bool,
    /// Exposure in stops: the picture is multiplied by 2^EV before it is written (-1 halves the light). For
    /// HDR skies that come out white.
    #[arg(long, value_name = "EV", default_value_t = 0.0, help_heading = PICTURE)]
    pub exposure: f32,
    /// How light above 1 fits a PNG: clamp (the course's: white above 1) or reinhard (compresses highlights,
    /// darker overall). EXR and HDR output keep linear light.
    #[arg(long, value_enum, default_value_t = ToneMap::Clamp, help_heading = PICTURE)]
    pub tonemap: ToneMap,
    /// Scale down every sample brighter than MAX in any channel to MAX: tames fireflies (a glossy sphere
    /// under a bright sun), at the price of bias: the clamped light is lost.
    #[arg(long, value_name = "MAX", help_heading = PICTURE)]
    pub clamp_sample: Option<f32>,
    /// Which extent of the picture stays when the aspect ratio changes: diagonal (the course's: a wider
    /// picture shows less at the top), vertical or horizontal. The picture at 640 x 480 is the same for all
    /// three. [default: the scene's own]
    #[arg(long, value_enum, help_heading = PICTURE)]
    pub fov_axis: Option<FovAxis>,
}

/// An example: its own options (a `clap::Args` struct) and how they turn into a scene. The options every
/// example shares ([`CommonArgs`]) and the command itself come from [`Cli`]; an example states only what is
/// its own:
///
/// ```no_run
/// use lecture6::prelude::*;
///
/// /// A red ball.
/// #[derive(clap::Args, Clone, Debug)]
/// pub struct Options {
///     /// The ball's radius.
///     #[arg(long, default_value_t = 10.0)]
///     radius: f32,
/// }
///
/// impl Example for Options {
///     const DEFAULT_SPP: u32 = 4;
///
///     fn scene(&self) -> Result<Scene> {
///         let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 10.0, -50.0), Vector::ZERO, 60.0));
///         scene.lights.push(PointLight::new(Vector::new(-30.0, 60.0, -40.0), Color::WHITE, 5000.0));
///         scene.add(Node::new(Sphere::new(Vector::ZERO, self.radius), Lambert::new(Color::new(0.8, 0.1, 0.1))));
///         Ok(scene)
///     }
/// }
///
/// fn main() -> ExitCode {
///     run::<Options>()
/// }
/// ```
pub trait Example: clap::Args + Clone + Send + Sync + 'static {
    /// Samples per pixel when `--spp` is not given.
    const DEFAULT_SPP: u32;
    /// Builds the scene the options describe. Bad files or values are errors, not panics.
    fn scene(&self) -> Result<Scene>;
    /// Builds the scene as [`Example::scene`] does, and sets the render settings that the scene decides
    /// where the common options leave them open (a scene file's frame size and anti-aliasing). By default
    /// the settings are the options'.
    fn scene_and_settings(&self, _common: &CommonArgs, _settings: &mut RenderSettings) -> Result<Scene> {
        self.scene()
    }
}

// The whole command line of an example: its own options, then the ones every example shares. (A plain
// comment: a doc comment here would be every example's `--help` description; each example's own is its
// `Options` doc comment.)
#[derive(clap::Parser, Clone, Debug)]
#[command(version)]
pub struct Cli<E: Example> {
    #[command(flatten)]
    pub example: E,
    #[command(flatten)]
    pub common: CommonArgs,
}

impl<E: Example> Cli<E> {
    /// The example's command, named `name` (its binary), its `--help` showing the example's own `--spp`
    /// default. Every option that takes a value takes a negative number too (`--ior -1` reaches the
    /// example's own check, which says why it is wrong, instead of being taken for an unknown option).
    pub fn command_named(name: &str) -> clap::Command {
        let spp_help = |arg: clap::Arg| {
            let help = arg.get_help().map(ToString::to_string).unwrap_or_default();
            arg.help(format!("{help} [default: {}]", E::DEFAULT_SPP))
        };
        <Cli<E> as clap::CommandFactory>::command()
            .name(name.to_string())
            .bin_name(name.to_string())
            .mut_arg("spp", spp_help)
            .mut_args(|arg| {
                let takes_value = arg.get_action().takes_values();
                arg.allow_negative_numbers(takes_value)
            })
    }

    /// Parses the options `args` (without the program name) as the example's binary would.
    pub fn parse_args<I, T>(name: &str, args: I) -> std::result::Result<Cli<E>, clap::Error>
    where
        I: IntoIterator<Item = T>,
        T: Into<std::ffi::OsString> + Clone,
    {
        let argv = std::iter::once(std::ffi::OsString::from(name)).chain(args.into_iter().map(Into::into));
        let matches = Self::command_named(name).try_get_matches_from(argv)?;
        <Cli<E> as clap::FromArgMatches>::from_arg_matches(&matches)
    }

    /// The render settings the options ask for.
    pub fn settings(&self) -> RenderSettings {
        let c = &self.common;
        RenderSettings {
            width: c.width.unwrap_or(640),
            height: c.height.unwrap_or(480),
            spp: c.spp.unwrap_or(E::DEFAULT_SPP),
            threads: c.threads,
            seed: c.seed,
            progress: !c.quiet,
            wavelengths: c.wavelengths.unwrap_or(RenderSettings::default().wavelengths),
            spectral: c.spectral.unwrap_or_default(),
            adaptive_aa: c.adaptive_aa,
            max_sample: c.clamp_sample,
        }
    }

    /// Builds the example's scene as the options say, ready to render: the scene's own settings overridden
    /// by the common options, and its caustic photon map built (in parallel, on `--threads` threads) if it
    /// needs one.
    pub fn prepare_scene(&self) -> Result<Scene> {
        self.prepare_scene_and_settings(&mut self.settings())
    }

    /// [`Cli::prepare_scene`], letting the scene set what the options leave open in `settings` (see
    /// [`Example::scene_and_settings`]).
    pub fn prepare_scene_and_settings(&self, settings: &mut RenderSettings) -> Result<Scene> {
        let mut scene = self.scene_and_settings(settings)?;
        self.build_photon_map(&mut scene)?;
        Ok(scene)
    }

    /// The example's scene with the common options applied and checked, and the settings it decides; the
    /// photon map is not built yet.
    fn scene_and_settings(&self, settings: &mut RenderSettings) -> Result<Scene> {
        let common = &self.common;
        let mut scene = self.example.scene_and_settings(common, settings)?;
        if let Some(depth) = common.max_depth {
            scene.max_depth = depth;
        }
        if let Some(path) = &common.env {
            scene.environment = Some(environment::load_with_layout(path, common.env_layout)?);
        }
        if common.exhaustive {
            scene.min_ray_weight = 0.0;
        }
        if let Some(axis) = common.fov_axis {
            let default = RenderSettings::default();
            scene.camera = scene.camera.with_fov_axis(axis, default.width as f32 / default.height as f32);
        }
        scene.check()?;
        scene.relative_to_camera();
        common.photons.apply(&mut scene.photons);
        scene.photons.check()?;
        Ok(scene)
    }

    /// Builds the scene's caustic photon map, if it asks for one.
    fn build_photon_map(&self, scene: &mut Scene) -> Result<()> {
        if scene.photons.count > 0 {
            let map = thread_pool(self.common.threads)?.install(|| PhotonMap::build(scene, self.common.seed))?;
            scene.photon_map = map.map(Arc::new);
        }
        Ok(())
    }

    /// Builds and renders the example's scene as the options say (the path both `main` and the tests use).
    pub fn render(&self) -> Result<(Frame, RenderStats)> {
        self.render_checked(|_, _| Ok(())).map(|(frame, stats, _)| (frame, stats))
    }

    /// [`Cli::render`], calling `check` with the scene and the settings once they are known and before any
    /// tracing (the photon map included): `run` checks there that the reference fits and says which
    /// options change nothing. Returns the settings it rendered with too.
    fn render_checked(
        &self,
        check: impl FnOnce(&Scene, &RenderSettings) -> Result<()>,
    ) -> Result<(Frame, RenderStats, RenderSettings)> {
        let mut settings = self.settings();
        settings.check()?;
        self.film().check()?;
        let mut scene = self.scene_and_settings(&mut settings)?;
        settings.check()?;
        check(&scene, &settings)?;
        self.build_photon_map(&mut scene)?;
        let (frame, stats) = render(&scene, &settings)?;
        Ok((frame, stats, settings))
    }

    /// The options given on the command line that change nothing in `scene`: caustic options in a scene
    /// without a photon map, dispersion options in a scene without dispersive materials. Each as one note.
    pub fn options_without_effect(&self, scene: &Scene) -> Vec<String> {
        let (c, p) = (&self.common, &self.common.photons);
        let mut notes = Vec::new();
        let photon_options = given(&[
            ("--photons", p.photons.is_some()),
            ("--k", p.k.is_some()),
            ("--radius", p.radius.is_some()),
            ("--show-photons", p.show_photons),
        ]);
        if !photon_options.is_empty() && !scene.casts_caustics() {
            notes.push(no_effect(&photon_options, "no mirror or glass in this scene casts caustics from a light"));
        } else if scene.photons.count == 0 && photon_options.iter().any(|o| *o != "--photons") {
            notes.push("--k, --radius and --show-photons change nothing without a photon map: add --photons N".into());
        }
        let dispersion_options =
            given(&[("--wavelengths", c.wavelengths.is_some()), ("--spectral", c.spectral.is_some())]);
        if !dispersion_options.is_empty() && !scene.is_dispersive() {
            notes.push(no_effect(
                &dispersion_options,
                "nothing in this scene is dispersive, so it is traced once in white light",
            ));
        } else if c.wavelengths.is_some() && c.spectral == Some(SpectralMode::Sampled) {
            notes.push("--wavelengths changes nothing with --spectral sampled: every sample has its own band".into());
        }
        notes
    }

    /// What happens to the rendered light before it is written: `--exposure` and `--tonemap`.
    pub fn film(&self) -> Film {
        Film { exposure: self.common.exposure, tone_map: self.common.tonemap }
    }

    /// Where the picture of the example called `name` goes.
    pub fn output_path(&self, name: &str) -> PathBuf {
        self.common.output.clone().unwrap_or_else(|| Path::new("out").join(format!("{name}.png")))
    }
}

/// The names of the options that were given, from (name, given) pairs.
fn given<'a>(options: &[(&'a str, bool)]) -> Vec<&'a str> {
    options.iter().filter(|(_, given)| *given).map(|(name, _)| *name).collect()
}

/// The note that `options` change nothing, and why.
fn no_effect(options: &[&str], why: &str) -> String {
    let verb = if options.len() == 1 { "changes" } else { "change" };
    format!("{} {verb} nothing here: {why}", options.join(", "))
}

/// The name of the running example: its binary's file name (`fresnel`, or `hw1` for a student's copy).
fn program_name() -> String {
    std::env::args_os()
        .next()
        .and_then(|arg0| Path::new(&arg0).file_stem().map(|s| s.to_string_lossy().into_owned()))
        .unwrap_or_else(|| "example".to_string())
}

/// Runs an example end to end (parse the options, build the scene, render, write the picture, compare it
/// with a reference if asked, print one summary line): the whole `main` of every example. The example's
/// name, which names its default output `out/<name>.png`, is its binary's.
pub fn run<E: Example>() -> ExitCode {
    let name = program_name();
    let argv: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let args = match Cli::<E>::parse_args(&name, argv.iter().cloned()) {
        Ok(args) => args,
        // --help shows the defaults the example's scene sets; --help and --version print to stdout and succeed.
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelp => {
            let argv = std::iter::once(std::ffi::OsString::from(&name)).chain(argv);
            match help_command::<E>(&name).try_get_matches_from(argv) {
                Err(help) => help.exit(),
                Ok(_) => e.exit(),
            }
        }
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            eprintln!("{name}: {}", one_line(&e.to_string()));
            return ExitCode::from(2);
        }
    };
    if args.common.window {
        return open_window(&name, args, argv);
    }
    // Everything runs on `--threads` threads: the scene's loading and the picture's encoding are parallel
    // too (the render builds its own pool of the same size).
    match thread_pool(args.common.threads).and_then(|pool| pool.install(|| run_parsed(&name, &args))) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: error: {e}");
            ExitCode::from(2)
        }
    }
}

/// `--window`: the live viewer, with the options as given on the command line.
#[cfg(feature = "viewer")]
fn open_window<E: Example>(name: &str, args: Cli<E>, argv: Vec<std::ffi::OsString>) -> ExitCode {
    crate::instruments::viewer::run(name, args, argv)
}

/// `--window` in a build without the viewer: say how to get it.
#[cfg(not(feature = "viewer"))]
fn open_window<E: Example>(name: &str, _args: Cli<E>, _argv: Vec<std::ffi::OsString>) -> ExitCode {
    eprintln!("{name}: --window needs the viewer: cargo run --release --features viewer --example {name} -- --window");
    ExitCode::from(2)
}

/// A clap error message on one line: its lines joined, without the usage and the pointer to --help.
pub(crate) fn one_line(message: &str) -> String {
    let keep = |l: &&str| !(l.is_empty() || l.starts_with("Usage:") || l.starts_with("For more information"));
    message.lines().map(str::trim).filter(keep).collect::<Vec<_>>().join(" ")
}

/// The example's command for `--help`: the defaults its scene sets written into the help of the options
/// that depend on the scene, and the headings of the caustic and dispersion options saying whether they
/// change this scene. (A scene that needs options to build, such as a scene file, keeps the plain help.)
fn help_command<E: Example>(name: &str) -> clap::Command {
    let command = Cli::<E>::command_named(name);
    let Ok(defaults) = Cli::<E>::parse_args(name, std::iter::empty::<std::ffi::OsString>()) else {
        return command;
    };
    let Ok(scene) = defaults.scene_and_settings(&mut defaults.settings()) else {
        return command;
    };
    let with_default = |value: String| {
        move |arg: clap::Arg| {
            let help = arg.get_help().map(ToString::to_string).unwrap_or_default();
            arg.help(help.replace(SCENE_DEFAULT, &format!("[default: {value}]")))
        }
    };
    let photons = &scene.photons;
    let radius = match photons.max_radius {
        Some(r) => r.to_string(),
        None => format!("{:.3}, 1/100 of the scene's size", crate::lesson::photon_map::default_radius(&scene, &[])),
    };
    let caustics = if !scene.casts_caustics() {
        "Caustics (photon mapping): no effect here, no mirror or glass in this scene casts caustics"
    } else if photons.count == 0 {
        "Caustics (photon mapping): off in this scene unless --photons N"
    } else {
        "Caustics (photon mapping)"
    };
    let dispersion = if scene.is_dispersive() {
        DISPERSION
    } else {
        "Dispersion: no effect here at the defaults, nothing in this scene is dispersive"
    };
    let mut command = command
        .mut_arg("max_depth", with_default(scene.max_depth.to_string()))
        .mut_arg("photons", with_default(photons.count.to_string()))
        .mut_arg("k", with_default(photons.k.to_string()))
        .mut_arg("radius", with_default(radius))
        .mut_arg("fov_axis", with_default(format!("{:?}", scene.camera.fov_axis).to_lowercase()));
    for id in ["photons", "k", "radius", "show_photons"] {
        command = command.mut_arg(id, |arg| arg.help_heading(caustics));
    }
    for id in ["wavelengths", "spectral"] {
        command = command.mut_arg(id, |arg| arg.help_heading(dispersion));
    }
    command
}

/// Fails unless writing the picture to `output` (and its heat map to `heat_map`) leaves the reference
/// `reference` as it is: `-o REF.png --compare REF.png` would overwrite the reference with the render and
/// report a perfect match.
fn check_not_the_reference(reference: &Path, output: &Path, heat_map: &Path) -> Result<()> {
    let same_file = |a: &Path, b: &Path| matches!((resolved(a), resolved(b)), (Some(a), Some(b)) if a == b);
    for (what, path) in [("the picture", output), ("the heat map", heat_map)] {
        if same_file(reference, path) {
            return Err(Error::file(
                "refusing to write over the reference",
                reference,
                format!("{what} would go to {}; write the render elsewhere with -o", path.display()),
            ));
        }
    }
    Ok(())
}

/// The absolute path a file would have once written, links followed: each component of the path that
/// exists is resolved as the file system has it, the rest (a folder `save` would create) as written.
fn resolved(path: &Path) -> Option<PathBuf> {
    let mut resolved = PathBuf::new();
    for component in std::path::absolute(path).ok()?.components() {
        match component {
            std::path::Component::ParentDir => {
                resolved.pop();
            }
            std::path::Component::CurDir => {}
            part => {
                resolved.push(part);
                if let Ok(real) = std::fs::canonicalize(&resolved) {
                    resolved = real;
                }
            }
        }
    }
    Some(resolved)
}

fn run_parsed<E: Example>(name: &str, args: &Cli<E>) -> Result<()> {
    if let Some(pixel) = args.common.trace_pixel {
        print!("{}", trace_pixel(name, args, pixel)?);
        return Ok(());
    }
    if let Some(alternative) = &args.common.side_by_side {
        let given: Vec<_> = std::env::args_os().skip(1).collect();
        print!("{}", side_by_side::<E>(name, &given, alternative)?);
        return Ok(());
    }
    if let Some(view) = args.common.view {
        print!("{}", write_view(name, args, view)?);
        return Ok(());
    }
    let output = args.output_path(name);
    let stem = output.file_stem().map(|s| s.to_string_lossy()).unwrap_or_default();
    let heat_path = output.with_file_name(format!("{stem}-diff.png"));
    // The reference is read, and checked against the output paths, before anything is rendered.
    let reference = match &args.common.compare {
        Some(path) => {
            check_not_the_reference(path, &output, &heat_path)?;
            Some((path, Reference::load(path)?))
        }
        None => None,
    };
    let quiet = args.common.quiet;
    let (frame, stats, settings) = args.render_checked(|scene, settings| {
        if let Some((path, reference)) = &reference {
            reference.check_size(path, settings.width, settings.height)?;
        }
        if !quiet {
            for note in args.options_without_effect(scene) {
                eprintln!("{name}: note: {note}");
            }
        }
        Ok(())
    })?;
    // The picture as written: exposed, and tone mapped for an 8-bit file; the comparison sees the same.
    let frame = args.film().develop(frame, keeps_linear_light(&output));
    frame.save(&output)?;
    if !args.common.quiet {
        let rays = stats.counters.total();
        let secs = stats.elapsed.as_secs_f64();
        let spectral = match &stats.spectral {
            SpectralPlan::White => String::new(),
            plan => format!(" ({plan})"),
        };
        println!(
            "{}: {}x{}, {} spp{}{}, {:.3} s, {} threads, {:.2} M rays, {:.2} Mrays/s -> {}",
            name,
            settings.width,
            settings.height,
            settings.spp,
            if settings.adaptive_aa { " + adaptive AA" } else { "" },
            spectral,
            secs,
            stats.threads,
            rays as f64 * 1e-6,
            rays as f64 * 1e-6 / secs.max(1e-9),
            output.display()
        );
        if stats.counters.capped_rays > 0 {
            println!(
                "{}: {} ray(s) bounced past the safety cap of {} and returned black: without a depth limit, facing \
                 mirrors recurse until the stack overflows; that is why Reflection v0.2 adds MAX_RAY_DEPTH",
                name, stats.counters.capped_rays, RECURSION_SAFETY_CAP
            );
        }
        if let Some(p) = &stats.photons {
            let trace = p.trace_time.as_secs_f64();
            println!(
                "{}: photon map: {} photons emitted, {} stored, traced in {:.3} s ({:.2} M photons/s), grid \
                 built in {:.3} s",
                name,
                p.emitted,
                p.stored,
                trace,
                p.emitted as f64 * 1e-6 / trace.max(1e-9),
                p.build_time.as_secs_f64()
            );
        }
    }
    if let Some((path, reference)) = &reference {
        let comparison = compare::compare(&frame, reference)?;
        save_atomically(&heat_path, |tmp| comparison.heat_map.save_with_format(tmp, image::ImageFormat::Png))?;
        println!("compared with {}: {comparison}; heat map -> {}", path.display(), heat_path.display());
    }
    Ok(())
}
