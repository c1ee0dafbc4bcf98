//! The lesson: the slides' code. Nothing here imports the instruments or the application.

/// `exercise!(name(arguments));`, the first line of each slide function a graded exercise covers. Built for
/// the exercises (feature `exercises`), it returns the student's answer when that exercise is handed out
/// (see [`exercise_hooks`]); in the plain build it is nothing at all.
macro_rules! exercise {
    ($hook:ident($($argument:expr),* $(,)?)) => {
        #[cfg(feature = "exercises")]
        if let Some(answer) = $crate::lesson::exercise_hooks::answers().and_then(|a| a.$hook($($argument),*)) {
            return answer;
        }
    };
}

pub use crate::files::{error, image_file, input};

#[macro_use]
pub mod beyond;
pub mod adaptive_aa;
pub mod bitmap;
pub mod branching;
pub mod camera;
pub mod color;
pub mod diagnostics;
pub mod environment;
#[cfg(feature = "exercises")]
pub mod exercise_hooks;
pub mod frame;
pub mod geometry;
pub mod helper_ranges;
pub mod light;
pub mod math;
pub mod node;
pub mod observer;
pub mod photon_map;
pub mod prepared;
pub mod problems;
pub mod ray;
pub mod render;
pub mod render_settings;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod shader;
pub mod spectral;
pub mod texture;
pub mod topic;
pub mod transform;

/// The last segment of a type's path, without generic arguments: `Reflection` for
/// `lecture6::lesson::shader::reflection::Reflection`. What the ray tree calls shaders, textures and geometry
/// by default (their `name`).
pub fn type_label<T: ?Sized>() -> &'static str {
    let name = std::any::type_name::<T>();
    let name = name.split('<').next().unwrap_or(name);
    name.rsplit("::").next().unwrap_or(name)
}
