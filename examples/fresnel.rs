//! # Fresnel (lecture 6, slides "Fresnel", "Fresnel Texture", "Let's build a Fresnel Shader (with layers!)")
//!
//! The course's own lecture-6 scene: a glass sphere (IOR 1.6) over a tiled floor that reflects a little.
//! The glass is a `Layered` shader: a refraction layer under a reflection layer whose blend is the `Fresnel`
//! texture. Look at:
//! - the sphere's middle, which faces the camera: mostly refraction (the floor, upside down), reflecting
//!   only a few percent;
//! - its rim, where the ray meets the surface at a grazing angle: mostly reflection of the sky;
//! - the floor: 2% of it is a mirror, enough to show a faint reflection of the sphere.
//!
//! Try: `--fresnel exact` (the exact equations instead of Schlick's approximation: compare with
//! `--compare expected/fresnel.png`), `--ior 1.33` (water), `--ior 2.42` (diamond), `--max-depth 2` (the
//! slide's depth: the inside of the sphere goes black), `--exhaustive` (trace every ray to the full depth:
//! the same picture, slower).
//!
//! Homework ideas: a texture that drives the IOR; a coloured glass (a refraction multiplier per channel);
//! plot the reflectance against the angle for both modes.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::fresnel::Args>()
}
