//! What the instruments that render an example again and again need of its command line, given by the
//! application: the study renders an example from its options ([`study::Subject`]), the live window shows
//! them as controls and builds, renders, saves and compares through them (`viewer::ExampleOptions`). The
//! instruments define what they need and know nothing of the command line; every example gets it here.

use super::example::{Cli, Example};
use crate::instruments::study::{self, Timed};
use crate::lesson::error::{Error, Result};

impl<E: Example> study::Subject for E {
    fn render_timed(args: &[String]) -> Result<Timed> {
        let parsed = Cli::<E>::parse_args("study", args).map_err(|e| {
            let message = e.to_string();
            Error::parameter("study options", args.join(" "), message.lines().next().unwrap_or_default())
        })?;
        let (frame, stats) = parsed.render()?;
        // A caustic render's cost includes the photon pass that runs before it.
        Ok(Timed { frame, seconds: (stats.elapsed + stats.photon_pass()).as_secs_f64(), rays: stats.counters.total() })
    }
}

/// The live window's view of an example's command line.
mod window {
    use super::super::example::{Cli, Example};
    use super::super::run::one_line;
    use crate::instruments::tone_mapping::Film;
    use crate::instruments::viewer::ExampleOptions;
    use crate::instruments::viewer::controls::Controls;
    use crate::lesson::error::Result;
    use crate::lesson::render::RenderSettings;
    use crate::lesson::scene::Scene;
    use std::path::{Path, PathBuf};

    impl<E: Example> ExampleOptions for Cli<E> {
        fn from_controls(controls: &Controls) -> std::result::Result<Self, String> {
            let options =
                Cli::<E>::parse_args(controls.name(), controls.args()).map_err(|e| one_line(&e.to_string()))?;
            options.settings().check().and_then(|()| options.film().check()).map_err(|e| e.to_string())?;
            Ok(options)
        }

        fn prepare(&self) -> Result<(Scene, RenderSettings)> {
            Cli::prepare(self)
        }

        fn film(&self) -> Film {
            Cli::film(self)
        }

        fn threads(&self) -> Option<usize> {
            self.common.threads
        }

        fn output_path(&self, name: &str) -> PathBuf {
            Cli::output_path(self, name)
        }

        fn reference(&self, name: &str) -> PathBuf {
            self.common.compare.clone().unwrap_or_else(|| Path::new("expected").join(format!("{name}.png")))
        }

        fn ui_scale(&self) -> f32 {
            self.common.ui_scale
        }

        fn pixel(&self) -> Option<(u32, u32)> {
            self.common.trace_pixel.map(|p| (p.x, p.y))
        }
    }
}
