//! # Scene files (the course's `.qdmg` format)
//!
//! From lecture 6 on, the course describes scenes in text files instead of code: blocks such as
//! `Camera { ... }`, `Sphere ball { ... }`, `Lambert red { ... }` and `Node { geometry ball shader red }`.
//! This example renders such a file:
//!
//!     cargo run --release --example scene_file -- examples/data/fresnel.qdmg
//!
//! A scene file's picture is named after it (`beer.qdmg` renders to `out/beer.png`; `-o` says otherwise);
//! the bundled `examples/data/fresnel.qdmg`, the default, renders to `out/scene_file.png`.
//!
//! The frame size, the camera, the lights, the environment and the ray depth come from the file
//! (`GlobalSettings`, `Camera`, `PointLight`, `CubemapEnvironment`); `--width`, `--height`, `--env` and
//! `--max-depth` override them. Without `--spp` the file's `wantAA` decides: the course's adaptive
//! anti-aliasing (one sample per pixel, five where neighbours differ) or one sample; `--spp N` (even
//! `--spp 1`) takes N stratified samples everywhere instead. Relative paths in the file are relative to the
//! file's folder.
//! Warnings (unknown properties, as in the course) go to stderr with their line numbers.
//!
//! Look at: `examples/data/fresnel.qdmg`, the `fresnel` example's scene written in the course's format;
//! `--spp 5` renders the `fresnel` example's picture.
//!
//! Try: change the glass's `ior` in the file; add a `Node` with a `Cube`, `rotate` and `scale` it (the
//! order of those lines matters, see the format's section 3.3); render the course's own scene files
//! (`--skip-unsupported` renders the elements of later lectures' scenes that the workbook knows).
//!
//! Homework ideas: write your homework's scene as a file; add a `Const` shader to the loader.

use lecture6::app::cli::{CommonArgs, print_stderr};
use lecture6::app::scene_file::{self, LoadOptions};
use lecture6::lesson::render::RenderSettings;
use lecture6::prelude::*;

/// The scene file rendered when none is given: the `fresnel` example's scene.
const DEFAULT_FILE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/data/fresnel.qdmg");

/// Renders a scene file of the course's format (.qdmg).
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// The scene file.
    #[arg(value_name = "FILE.qdmg", default_value = DEFAULT_FILE)]
    pub file: PathBuf,
    /// Skip the elements of later lectures (RectLight, CSG, Heightfield, Const, bump maps) with a warning,
    /// instead of refusing the file, so that the rest renders.
    #[arg(long)]
    pub skip_unsupported: bool,
}

impl Options {
    /// The file, its `maxTraceDepth` refused above `max_trace_depth`.
    fn load(&self, max_trace_depth: Option<u32>) -> Result<scene_file::SceneFile> {
        scene_file::load(&self.file, &LoadOptions { skip_unsupported: self.skip_unsupported, max_trace_depth })
    }
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 1;

    fn scene(&self) -> Result<Scene> {
        Ok(self.load(None)?.scene)
    }

    /// The file's frame size and anti-aliasing, where the options leave them open; its warnings on stderr.
    fn scene_and_settings(&self, common: &CommonArgs, settings: &mut RenderSettings) -> Result<Scene> {
        let file = self.load(common.max_trace_depth())?;
        if !common.quiet {
            for w in &file.warnings {
                print_stderr(&format!("{w}\n"))?;
            }
        }
        settings.width = common.width.unwrap_or(file.width);
        settings.height = common.height.unwrap_or(file.height);
        // Without --spp the file's `wantAA` decides; --spp N (even 1) takes N samples in every pixel instead.
        if common.spp.is_none() {
            settings.adaptive_aa |= file.adaptive_aa;
        }
        Ok(file.scene)
    }

    /// The file's name: `beer.qdmg` renders to `out/beer.png` (and its views to `out/beer-depth.png`, ...).
    /// The bundled `examples/data/fresnel.qdmg`, given or not, keeps the example's own name,
    /// `out/scene_file.png`, so that it does not overwrite the `fresnel` example's picture.
    fn picture_name(&self, program: &str) -> String {
        let bundled = std::fs::canonicalize(&self.file).ok() == std::fs::canonicalize(DEFAULT_FILE).ok();
        match self.file.file_stem() {
            Some(stem) if !bundled => stem.to_string_lossy().into_owned(),
            _ => program.to_string(),
        }
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
