//! # Refraction (lecture 6, slides "Refract", "Refraction 0.2")
//!
//! A glass surface bends the ray by Snell's law, `refract(i, n, ior)`. Whether the ray enters or leaves is
//! read from the normal before it is face-forwarded; leaving, the ratio of the indices is flipped. Look at:
//! - the glass sphere: the wall behind it upside down and magnified, like through a lens;
//! - the glass slab turned from the camera: the wall shifted sideways but not bent, and black edges where
//!   total internal reflection happens (the slide's shader returns black there);
//! - the black shadows: shadow rays do not pass through glass.
//!
//! Try: `--ior 1.0` (the glass vanishes), `--ior 1.33` (water), `--ior 2.42` (diamond: more black).
//!
//! Homework ideas: tint the glass by how far the ray travels inside it (Beer's law); on total internal
//! reflection, reflect instead of returning black.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::refract::Args>()
}
