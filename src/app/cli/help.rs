//! `--help` as the example's scene has it: the defaults its scene sets, and whether the caustic and
//! dispersion options change it.

use super::example::{Cli, Example};
use super::options::{DISPERSION, SCENE_DEFAULT};

/// The example's command for `--help`: the defaults its scene sets written into the help of the options
/// that depend on the scene, and the headings of the caustic and dispersion options saying whether they
/// change this scene. (A scene that needs options to build, such as a scene file, keeps the plain help.)
pub(super) fn help_command<E: Example>(name: &str) -> clap::Command {
    let command = Cli::<E>::command_named(name);
    let Ok(defaults) = Cli::<E>::parse_args(name, std::iter::empty::<std::ffi::OsString>()) else {
        return command;
    };
    let Ok(scene) = defaults.scene_with_common_options(&mut defaults.settings()) else {
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
    let caustics = if !scene.can_have_caustics() {
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
        .mut_arg("fov", with_default(scene.camera.fov.to_string()))
        .mut_arg("fov_axis", with_default(format!("{:?}", scene.camera.fov_axis).to_lowercase()));
    for id in ["photons", "k", "radius", "show_photons"] {
        command = command.mut_arg(id, |arg| arg.help_heading(caustics));
    }
    for id in ["wavelengths", "spectral", "illuminant", "gamut"] {
        command = command.mut_arg(id, |arg| arg.help_heading(dispersion));
    }
    command
}
