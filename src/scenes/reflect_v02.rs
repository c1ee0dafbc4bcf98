//! Scene of the `reflect_v02` example (slide "Reflection v0.2"): the rays carry their `depth`, and a ray
//! deeper than `MAX_RAY_DEPTH` returns black. The scene is `reflect_v01`'s with the two facing mirrors:
//! with the slide's limit of 2 the mirror in front shows the scene once and, inside it, the mirror behind
//! the camera once more, whose own reflection is black. `--max-depth N` shows N nested images, each 20%
//! darker; the rays per depth in the summary grow with it.

use crate::cli::{CommonArgs, Example};
use crate::error::Result;
use crate::scene::{MAX_RAY_DEPTH, Scene};

/// Reflection v0.2: the facing mirrors of v0.1 with a depth limit (`MAX_RAY_DEPTH`, 2 unless `--max-depth`).
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "reflect_v02", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// The fraction of light every mirror reflects.
    #[arg(long, default_value_t = 0.8)]
    pub multiplier: f32,
}

impl Example for Args {
    const NAME: &'static str = "reflect_v02";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let mut scene = super::reflect_v01::mirror_scene(self.multiplier, true)?;
        scene.max_depth = MAX_RAY_DEPTH;
        Ok(scene)
    }
}
