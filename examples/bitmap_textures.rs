//! # Bitmap textures (lecture 6, slide "Bitmap текстури")
//!
//! Diffuse textures read from image files colour a floor, two spheres and a cube. Look at:
//! - the floor: one image, repeated every 40 units (`scaling`), fading with distance;
//! - the planet: a 2:1 map wrapped once around a sphere (u = longitude, v = latitude);
//! - the checker sphere: an 8 x 8 image magnified, so `--filter nearest` shows blocks and `--filter
//!   bilinear` blends them;
//! - the cube: every face maps the wood image once.
//!
//! Try: `--filter nearest`, `--wrap mirror`, `--texture my_photo.jpg`.
//!
//! Homework ideas: add a `--scaling` option for the floor; implement trilinear filtering (mip-maps) and
//! compare the far floor with `--spp 1`.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::bitmap_textures::Args>()
}
