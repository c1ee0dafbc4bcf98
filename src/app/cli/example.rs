//! An example: its own options and how they become a scene ([`Example`]), and the whole command line of
//! one ([`Cli`]): parsing, the render settings, the scene prepared as the options say, and the render.

use super::options::CommonArgs;
use super::progress::SampleBar;
use crate::app::parameter_ranges::out_of_range;
use crate::files::encoding;
use crate::instruments::tone_mapping::Film;
use crate::lesson::beyond::{Step, Steps};
use crate::lesson::environment;
use crate::lesson::error::{Error, Result};
use crate::lesson::frame::Frame;
use crate::lesson::photon_map::PhotonMap;
use crate::lesson::render::{Progress, RenderSettings, RenderStats, on_workers, render_with_progress};
use crate::lesson::scene::Scene;
use crate::lesson::spectral::SpectralMode;
use clap::parser::ValueSource;
use std::any::TypeId;
use std::path::{Path, PathBuf};
use std::sync::Arc;

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
    /// The name of the pictures the example writes where `--output` does not say: `out/<name>.png`,
    /// `out/<name>-depth.png`, ... By default the example's binary's name, `program` (`fresnel`, or `hw1` for
    /// a student's copy); a scene file's example names them after the file, so that scenes do not overwrite
    /// each other.
    fn picture_name(&self, program: &str) -> String {
        program.to_string()
    }
}

// The whole command line of an example: its own options, then the ones every example shares. (A plain
// comment: a doc comment here would be every example's `--help` description; each example's own is its
// `Options` doc comment.)
#[allow(missing_docs)]
#[derive(clap::Parser, Clone, Debug)]
#[command(version)]
pub struct Cli<E: Example> {
    /// The example's own options.
    #[command(flatten)]
    pub example: E,
    /// The options every example shares.
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
        let matches = matches_within_f32(Self::command_named(name), argv)?;
        <Cli<E> as clap::FromArgMatches>::from_arg_matches(&matches)
    }

    /// The render settings the options alone ask for, before the scene decides what they leave open (a scene
    /// file's frame size and anti-aliasing): [`Cli::prepare`] gives the ones the render uses.
    pub(crate) fn settings(&self) -> RenderSettings {
        let c = &self.common;
        // Without hero wavelengths, the slide's K passes.
        let spectral = match self.steps().has(Step::HeroWavelengths) {
            true => c.spectral.unwrap_or_default(),
            false => SpectralMode::Passes,
        };
        RenderSettings {
            width: c.width.unwrap_or(640),
            height: c.height.unwrap_or(480),
            spp: c.spp.unwrap_or(E::DEFAULT_SPP),
            threads: c.threads,
            seed: c.seed,
            progress: !c.quiet,
            wavelengths: c.wavelengths.unwrap_or(spectral.default_wavelengths()),
            spectral,
            adaptive_aa: c.adaptive_aa,
            max_sample: c.clamp_sample,
            photon_passes: c.photons.photon_passes.unwrap_or(1),
        }
    }

    /// The scene and the render settings exactly as the render uses them: the options' settings, with what
    /// the scene decides where they leave it open (a scene file's frame size and anti-aliasing), the photon
    /// map built, and no progress bar. The instruments (`--trace-pixel`, `--view`, the viewer) and the tests
    /// start here; [`Cli::render`] renders what it returns. This is the one path from the options to a
    /// scene and its settings.
    pub fn prepare(&self) -> Result<(Scene, RenderSettings)> {
        let (scene, settings) = self.prepare_checked(|_, _| Ok(()))?;
        Ok((scene, RenderSettings { progress: false, ..settings }))
    }

    /// [`Cli::prepare`], calling `check` with the scene and the settings once they are known and before any
    /// tracing (the photon map included), and keeping the progress bar the options ask for.
    fn prepare_checked(
        &self,
        check: impl FnOnce(&Scene, &RenderSettings) -> Result<()>,
    ) -> Result<(Scene, RenderSettings)> {
        let mut settings = self.settings();
        settings.check()?;
        self.film().check()?;
        self.check_steps()?;
        // Prepared once, for the photon tracer and the renderer alike.
        let mut scene = self.scene_with_common_options(&mut settings)?.prepared().into_owned();
        settings.check()?;
        check(&scene, &settings)?;
        self.build_photon_map(&mut scene)?;
        Ok((scene, settings))
    }

    /// The example's scene and the settings it decides ([`Example::scene_and_settings`]), with the common
    /// options applied to the scene and checked; the photon map is not built yet.
    pub(super) fn scene_with_common_options(&self, settings: &mut RenderSettings) -> Result<Scene> {
        // Every 8-bit file the scene reads (its textures, `--env`) is read as `--encoding` says.
        encoding::reading_as(self.common.encoding, || self.scene_read(settings))
    }

    /// [`Cli::scene_with_common_options`], its files read as `--encoding` says.
    fn scene_read(&self, settings: &mut RenderSettings) -> Result<Scene> {
        let common = &self.common;
        let mut scene = self.example.scene_and_settings(common, settings)?;
        scene.steps = common.steps();
        if let Some(depth) = common.max_depth {
            if let Some(cap) = common.max_trace_depth()
                && depth > cap
            {
                return Err(Error::parameter(
                    "--max-depth",
                    depth,
                    format!(
                        "at most {cap} with --exhaustive or --slide (without the step adaptive-depth): nothing \
                         prunes the ray tree then, and every glass surface splits a ray in two, so a sample's rays \
                         can double with each level"
                    ),
                ));
            }
            scene.max_depth = depth;
        }
        if let Some(path) = &common.env {
            scene.environment = Some(environment::load_with_layout(path, common.env_layout)?);
        }
        if let Some(illuminant) = common.illuminant {
            scene.illuminant = illuminant;
        }
        if let Some(axis) = common.fov_axis {
            let default = RenderSettings::default();
            scene.camera = scene.camera.with_fov_axis(axis, default.width as f32 / default.height as f32);
        }
        if let Some(fov) = common.fov {
            scene.camera.fov = fov;
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
            let map = on_workers(self.common.threads, |_| PhotonMap::build(scene, self.common.seed))??;
            scene.photon_map = map.map(Arc::new);
        }
        Ok(())
    }

    /// Builds and renders the example's scene as the options say (the path both `main` and the tests use).
    pub fn render(&self) -> Result<(Frame, RenderStats)> {
        self.render_checked(|_, _| Ok(())).map(|(frame, stats, _)| (frame, stats))
    }

    /// [`Cli::render`], calling `check` as [`Cli::prepare_checked`] does: `run` checks there that the
    /// reference fits and says which options change nothing. Returns the settings it rendered with too.
    pub(super) fn render_checked(
        &self,
        check: impl FnOnce(&Scene, &RenderSettings) -> Result<()>,
    ) -> Result<(Frame, RenderStats, RenderSettings)> {
        let (scene, settings) = self.prepare_checked(check)?;
        let bar = settings.progress.then(SampleBar::on_terminal).flatten();
        let progress = bar.as_ref().map(|bar| bar as &dyn Progress);
        let (frame, mut stats) = render_with_progress(&scene, &settings, progress)?;
        stats.warnings.extend(out_of_range(&scene));
        Ok((frame, stats, settings))
    }

    /// The steps beyond the slides the options ask for ([`CommonArgs::steps`]).
    pub fn steps(&self) -> Steps {
        self.common.steps()
    }

    /// Refuses a choice that needs a step the render does not take: `--spectral hero` or `sampled` without
    /// the step hero-wavelengths (under `--slide`, the slide's K passes), and more than one photon pass
    /// without the step photon-grid (under `--slide`, the slide's one photon map).
    fn check_steps(&self) -> Result<()> {
        if let Some(passes) = self.common.photons.photon_passes
            && passes > 1
            && !self.steps().has(Step::PhotonGrid)
        {
            return Err(Error::parameter(
                "--photon-passes",
                passes,
                "needs the step photon-grid, which --slide or --no-step leaves out (the slide's k-d tree finds the \
                 k nearest photons, not every photon within a pass's radius): add --step photon-grid, or render \
                 the slide's one pass",
            ));
        }
        match self.common.spectral {
            Some(mode) if mode != SpectralMode::Passes && !self.steps().has(Step::HeroWavelengths) => {
                Err(Error::parameter(
                    "--spectral",
                    format!("{mode:?}").to_lowercase(),
                    "needs the step hero-wavelengths, which --slide or --no-step leaves out: add --step hero-wavelengths, \
                 or use the slide's --spectral passes",
                ))
            }
            _ => Ok(()),
        }
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
            ("--photon-passes", p.photon_passes.is_some()),
        ]);
        if !photon_options.is_empty() && !scene.can_have_caustics() {
            notes.push(no_effect(&photon_options, "no mirror or glass in this scene casts caustics from a light"));
        } else if scene.photons.count == 0 && photon_options.iter().any(|o| *o != "--photons") {
            notes.push(
                "--k, --radius, --show-photons and --photon-passes change nothing without a photon map: add --photons N"
                    .into(),
            );
        }
        let dispersion_options = given(&[
            ("--wavelengths", c.wavelengths.is_some()),
            ("--spectral", c.spectral.is_some()),
            ("--illuminant", c.illuminant.is_some()),
            ("--gamut", c.gamut.is_some()),
        ]);
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

    /// What happens to the rendered light before it is written: `--exposure`, `--tonemap` and `--gamut`.
    pub fn film(&self) -> Film {
        Film {
            exposure: self.common.exposure,
            tone_map: self.common.tonemap,
            gamut: self.common.gamut.unwrap_or_default(),
            encoding: self.common.encoding,
        }
    }

    /// Where the picture of the example called `name` goes: `--output`, or `out/<picture name>.png` (see
    /// [`Example::picture_name`]); with `--compare`, `out/<picture name>-compared.png`, so that comparing
    /// another version with a reference never replaces the render a student kept at `out/<picture name>.png`;
    /// with `--show-photons`, whose picture shows the photons instead of the caustic light,
    /// `out/<picture name>-photons.png`, for the same reason.
    pub fn output_path(&self, name: &str) -> PathBuf {
        let photons = if self.common.photons.show_photons { "-photons" } else { "" };
        let compared = if self.common.compare.is_some() { "-compared" } else { "" };
        self.output_path_for(name, &format!("{photons}{compared}"))
    }

    /// Where a picture of the example called `name` goes: `--output`, or `out/<picture name><suffix>.png`
    /// (`suffix` is `-depth` for the depth view, `-side-by-side` for `--side-by-side`).
    pub fn output_path_for(&self, name: &str, suffix: &str) -> PathBuf {
        let picture = self.example.picture_name(name);
        self.common.output.clone().unwrap_or_else(|| Path::new("out").join(format!("{picture}{suffix}.png")))
    }
}

/// `command`'s matches of `argv`, every real number given to an option of type `f32` (the example's own, such
/// as `--ior`, and the common ones) within the 32-bit floats: clap reads `1e308` as infinity and `1e-50` as 0
/// without a word, and the option's own check would then refuse a value that was never typed ("invalid
/// --ior inf"). A value out of that range is refused as it was typed; `inf` itself is left to the option.
pub(super) fn matches_within_f32(
    mut command: clap::Command,
    argv: impl IntoIterator<Item = std::ffi::OsString>,
) -> std::result::Result<clap::ArgMatches, clap::Error> {
    let matches = command.try_get_matches_from_mut(argv)?;
    let f32_options = command.get_arguments().filter(|arg| arg.get_value_parser().type_id() == TypeId::of::<f32>());
    let typed = f32_options.filter(|arg| matches.value_source(arg.get_id().as_str()) == Some(ValueSource::CommandLine));
    let mut out_of_range = typed.flat_map(|arg| {
        let values = matches.get_raw(arg.get_id().as_str()).into_iter().flatten().filter_map(|v| v.to_str());
        let long = arg.get_long().map_or_else(|| arg.get_id().to_string(), |long| format!("--{long}"));
        values.filter_map(move |text| Some(format!("invalid value '{text}' for '{long}': {}", beyond_f32(text)?)))
    });
    let first = out_of_range.next();
    drop(out_of_range); // it borrows the command, which makes the error
    if let Some(message) = first {
        return Err(command.error(clap::error::ErrorKind::ValueValidation, message));
    }
    Ok(matches)
}

/// Why the number `text` is not a 32-bit float as it was typed: it is finite and reads as infinity, or is
/// not zero and reads as 0. `None` for a number that is one, for `inf` and for text that is no number.
fn beyond_f32(text: &str) -> Option<String> {
    let value = text.trim().parse::<f32>().ok()?;
    let mantissa = text.split(['e', 'E']).next().unwrap_or_default();
    if value.is_infinite() && !text.to_ascii_lowercase().contains("inf") {
        Some(format!("{text} is beyond the range of the renderer's 32-bit floats (at most ±{:.1e})", f32::MAX))
    } else if value == 0.0 && mantissa.contains(|c: char| c.is_ascii_digit() && c != '0') {
        let smallest = f32::from_bits(1);
        Some(format!(
            "{text} is too small for the renderer's 32-bit floats and would be read as 0 (the smallest is {smallest:.1e})"
        ))
    } else {
        None
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
