//! # Glossy reflections (lecture 6, slides "Грапави (glossy) отражения" to "Резултати (2)")
//!
//! A rough mirror reflects a cone of rays instead of one. The renderer tilts the face-forwarded normal by a
//! point of the unit disc scaled by `tan((1 - glossiness) * pi/2)`, reflects about the tilted normal, drops
//! rays that go under the surface and averages the rest. Look at:
//! - the three spheres, glossiness 0.95, 0.80 and 0.50 from left to right: the floor's tiles and the clouds
//!   stay crisp in the first and melt into an average colour in the last;
//! - the red ball and the wooden box between them: reflections of near things stay sharper than those of
//!   far things (the cone widens with distance);
//! - the noise: `--glossy-samples 2` shows what too few samples do, `--sampler random` the slide's
//!   independent disc points (noisier at the same time than the default `stratified`).
//!
//! Try: `--glossiness 0.9`, `--glossy-samples 64 --spp 1`, `--sampler random --compare expected/glossy.png`,
//! `--env textures/sky_cubemap`.
//!
//! Homework ideas: make the glossiness a texture (a scratched or fingerprinted mirror); importance-sample a
//! Phong lobe instead of tilting the normal; trace fewer rays where the ray's `weight` is small.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::glossy::Args>()
}
