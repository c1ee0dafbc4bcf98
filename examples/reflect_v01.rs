//! # Reflection v0.1 (lecture 6, slide "Reflection v0.1")
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

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::reflect_v01::Args>()
}
