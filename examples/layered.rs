//! # Layered shaders (lecture 6, slides "Комбиниране на шейдъри", "Layered Shader", "Текстури", "Пример за
//! текстура")
//!
//! Materials made of layers, bottom to top, each with a blend (its opacity), and textures that drive more
//! than the colour. Look at:
//! - the floor, lacquered wood: diffuse wood under a clear layer blended by a Fresnel texture, so the lacquer
//!   mirrors the scene at grazing angles, near the horizon, and hardly under the camera;
//! - the panel: a mask texture is the blend of a mirror layer over a tiled diffuse layer, so discs and rings
//!   of mirror are set into the stone;
//! - the left sphere: the slide's Fresnel shader with layers (diffuse, refraction at 0.3, Fresnel reflection);
//! - the right sphere: a mirror whose colour comes from a texture (gold, silver and copper bands).
//!
//! Try: `--lacquer 0` (bare wood), `--mask my_mask.png`, `--shade-every-layer` (the slide's loop: the same
//! picture, slower; compare the times).
//!
//! Homework ideas: a texture that drives the Phong exponent; a scratched lacquer (a texture as the lacquer's
//! blend); a layer with a coloured blend (per-channel opacity).

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::layered::Args>()
}
