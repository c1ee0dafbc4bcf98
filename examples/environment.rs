//! # Environment maps (lecture 6, slides "Заден фон", "Интерфейс за заден фон")
//!
//! A ray that hits nothing sees the environment, which depends on the ray's direction only. Here a mirror
//! sphere, a red and a blue object stand on a small tiled stage under an HDR sky. Look at:
//! - the sky and the fields behind the stage: the environment seen directly;
//! - the mirror sphere: the whole environment around it, including the sun behind the camera, which is
//!   far brighter than white (an HDR image keeps that);
//! - the shadows: the point light stands where the sky's sun is.
//!
//! Try: `--kind cubemap` (the same sky as six cube faces: the picture should not change), `--env
//! my_panorama.hdr` (any equirectangular image, its centre towards the camera), `--env my_skybox/` (a
//! folder with posx, negx, posy, negy, posz, negz).
//!
//! Homework ideas: rotate the environment by an angle around the vertical axis; light the diffuse objects
//! from the environment (average many environment samples over the hemisphere of the normal).

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::environment::Args>()
}
