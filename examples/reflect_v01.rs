//! # Reflection v0.1 (lecture 6, slide "Reflection v0.1")
//!
//! The slide's code: `TraceContext::raytrace` in `src/lesson/scene.rs` and the mirror ray of
//! `src/lesson/shader/reflection.rs`. `--slide` renders this example with the slides' choice of every step beyond them
//! (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! A mirror sends the ray on in the direction `reflect(i, n) = i + 2 * dot(-i, n) * n` and multiplies what
//! it sees by 0.8 ("20% loss of energy"). There is no depth limit. Look at:
//! - the two mirror spheres: each shows the other, and in it itself again, each image 20% darker;
//! - the floor and the sky in them, bent by the curved surface.
//!
//! Try: `--mirrors` (two mirrors facing each other around the camera: the rays that meet them square-on
//! bounce for ever; the renderer's safety cap stops them and a line explains why v0.2 needs a depth
//! limit), `--multiplier 1.0` (a perfect mirror).
//!
//! Homework ideas: colour the mirrors (a multiplier per channel); count how deep the deepest ray went.

use lecture6::prelude::*;

/// Reflection v0.1: mirrors with 20% loss per bounce and no depth limit.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// Put two large mirrors facing each other around the camera: the runaway recursion of v0.1.
    #[arg(long)]
    pub mirrors: bool,
    /// The fraction of light every mirror reflects (the slide's 0.8: "20% loss of energy").
    #[arg(long, default_value_t = 0.8)]
    pub multiplier: f32,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        // Two mirror spheres (`Reflection`, src/lesson/shader/reflection.rs) and a red ball on a checker floor.
        let mut scene = scenes::mirror_room(self.multiplier, self.mirrors)?;
        // The slide's v0.1 has no depth limit (only the renderer's safety cap remains), and no adaptive depth
        // control either: a ray keeps bouncing however faint it has become, which is the danger it shows.
        scene.max_depth = u32::MAX;
        scene.min_ray_weight = 0.0;
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
