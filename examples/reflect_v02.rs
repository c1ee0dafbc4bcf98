//! # Reflection v0.2 (lecture 6, slide "Reflection v0.2")
//!
//! The slide's code: `TraceContext::raytrace` in `src/lesson/scene.rs` (`MAX_RAY_DEPTH`) and the mirror ray of
//! `src/lesson/shader/reflection.rs`. `--slide` renders this example with the slides' choice of every step beyond them
//! (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! Every ray carries its `depth`: camera rays 0, each reflection one more; a ray deeper than
//! `MAX_RAY_DEPTH` (2, as on the slide) returns black. Two mirrors face each other, one in front of the
//! camera and one behind it. Look at:
//! - the mirror in front: the scene once (depth 1), and inside it the mirror behind the camera (depth 2),
//!   whose own reflection is black: the limit;
//! - the summary line: the rays traced, which grow with the limit.
//!
//! Try: `--max-depth 1`, `--max-depth 8` (a tunnel of nested frames, each 20% darker), `--multiplier 1.0`.
//!
//! Homework ideas: instead of black past the limit, return the environment; give each mirror a depth limit
//! of its own. (The renderer already stops a ray whose `weight`, the product of the multipliers on its way,
//! is too small to change its pixel by an 8-bit level: compare the time and the rays with `--exhaustive`.)

use lecture6::prelude::*;

/// Reflection v0.2: the facing mirrors of v0.1 with a depth limit (`MAX_RAY_DEPTH`, 2 unless `--max-depth`).
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// The fraction of light every mirror reflects.
    #[arg(long, default_value_t = 0.8)]
    pub multiplier: f32,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        // `reflect_v01`'s scene, always with the two mirrors facing each other around the camera.
        let mut scene = scenes::mirror_room(self.multiplier, true)?;
        scene.max_depth = MAX_RAY_DEPTH;
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
