//! `--print-defaults`: one line of the settings an example takes when no option is given, printed before
//! its render, for the class command (docs/class.md), which lists where a student's program differs from the
//! teacher's. They are read from the program as built, not from its source: its samples per pixel, its size
//! and its ray depth as its scene sets them, and the default of each of its own options (`--ior 1.5`), so a
//! default of 20000 samples shows even when the class renders every program with `--spp 4`.
//!
//! ```text
//! fresnel: defaults: --spp 5, --width 640, --height 480, --max-depth 8, --ior 1.5
//! ```

use super::example::{Cli, Example};

/// What comes between the program's name and its defaults on the line [`defaults_line`] prints.
pub const DEFAULTS_MARK: &str = ": defaults: ";

/// The line of `E`'s defaults, for the example named `name`: `NAME: defaults: --spp 5, --width 640, ...`,
/// each setting as its option and its value, `, ` between them. The samples, size and depth are the ones
/// its scene decides (a scene file's own); where its scene cannot be built without options, they are the
/// options' defaults, and its depth is left out.
pub fn defaults_line<E: Example>(name: &str) -> String {
    let mut settings = Vec::new();
    if let Ok(defaults) = Cli::<E>::parse_args(name, std::iter::empty::<std::ffi::OsString>()) {
        let mut render = defaults.settings();
        let depth = defaults.scene_with_common_options(&mut render).ok().map(|scene| scene.max_depth);
        settings.push(("--spp".to_string(), render.spp.to_string()));
        settings.push(("--width".to_string(), render.width.to_string()));
        settings.push(("--height".to_string(), render.height.to_string()));
        if let Some(depth) = depth {
            settings.push(("--max-depth".to_string(), depth.to_string()));
        }
    }
    let own = E::augment_args(clap::Command::new(name.to_string()));
    for arg in own.get_arguments() {
        let values: Vec<String> = arg.get_default_values().iter().map(|v| v.to_string_lossy().into_owned()).collect();
        if let (Some(long), false) = (arg.get_long(), values.is_empty()) {
            settings.push((format!("--{long}"), values.join(" ")));
        }
    }
    let listed: Vec<String> = settings.into_iter().map(|(option, value)| format!("{option} {value}")).collect();
    format!("{name}{DEFAULTS_MARK}{}", listed.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::camera::Camera;
    use crate::lesson::error::Result;
    use crate::lesson::scene::Scene;

    /// An example with an option of its own and a deep scene.
    #[derive(clap::Args, Clone, Debug)]
    struct Deep {
        /// An index of refraction.
        #[arg(long, default_value_t = 1.33)]
        ior: f32,
        /// An option without a default.
        #[arg(long)]
        label: Option<String>,
    }

    impl Example for Deep {
        const DEFAULT_SPP: u32 = 20_000;

        fn scene(&self) -> Result<Scene> {
            let mut scene = Scene::new(Camera::default());
            scene.max_depth = 12;
            Ok(scene)
        }
    }

    #[test]
    fn the_defaults_are_the_programs_own_whatever_the_command_line() {
        assert_eq!(
            defaults_line::<Deep>("hw1"),
            "hw1: defaults: --spp 20000, --width 640, --height 480, --max-depth 12, --ior 1.33"
        );
    }
}
