//! # Fresnel (lecture 6, slides "Fresnel", "Fresnel Texture", "Let's build a Fresnel Shader (with layers!)")
//!
//! The slide's code: `src/lesson/texture/fresnel.rs` and `src/lesson/shader/glass.rs` (Schlick's Fresnel texture
//! and the glass in layers). `--slide` renders this example with it alone; `--side-by-side "--slide"` shows what
//! the steps beyond the slides change (docs/beyond-the-slides.md).
//!
//! The course's own lecture-6 scene: a glass sphere (IOR 1.6) over a tiled floor that reflects a little,
//! so the picture and the time can be compared with the course's C++ program. Its camera is the course's,
//! 90 degrees across the diagonal; the lecture-6 program itself shows more than its 90 degrees (it scales
//! its image plane by 1.5): `--fov 112.62` (2 atan 1.5) frames the scene as that program does, the sphere
//! smaller and more of the sky, as the speed bench compares them (docs/speed.md). The glass is a `Layered`
//! shader: a refraction layer under a reflection layer whose blend is the `Fresnel` texture
//! ([`fresnel_glass`] builds it; read `src/lesson/shader/glass.rs`). Look at:
//! - the sphere's middle, which faces the camera: mostly refraction (the floor, upside down), reflecting
//!   only a few percent;
//! - its rim, where the ray meets the surface at a grazing angle: mostly reflection of the sky;
//! - the floor: 2% of it is a mirror, enough to show a faint reflection of the sphere.
//!
//! Try: `--fresnel exact` (the exact equations instead of Schlick's approximation: compare with
//! `--compare expected/fresnel.png`), `--ior 1.33` (water), `--ior 2.42` (diamond), `--max-depth 1` (the
//! ray refracted into the glass is the last one traced, so the inside of the sphere goes black; the slide's
//! depth, 2, is just enough to see through it), `--exhaustive` (trace every ray to the full depth:
//! the same picture, slower).
//!
//! Homework ideas: a texture that drives the IOR; a coloured glass (a refraction multiplier per channel);
//! plot the reflectance against the angle for both modes.

use lecture6::prelude::*;
use std::path::PathBuf;

/// The course's Fresnel scene: a glass sphere over a slightly reflective tiled floor.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// How the glass's reflectance is computed: Schlick's approximation (the slide's) or the exact Fresnel
    /// equations.
    #[arg(long, value_enum, default_value_t = FresnelMode::Schlick)]
    pub fresnel: FresnelMode,
    /// Index of refraction of the glass sphere (water 1.33, glass 1.5, the course's 1.6, diamond 2.42).
    #[arg(long, default_value_t = 1.6)]
    pub ior: f32,
    /// The floor's tiles from this image instead of the bundled `floor_tiles.png`, one tile of it every 100
    /// units (the course's is its repository's `data/floor.bmp`).
    #[arg(long, value_name = "IMAGE")]
    pub floor: Option<PathBuf>,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 5;

    fn scene(&self) -> Result<Scene> {
        if !(self.ior.is_finite() && self.ior > 0.0) {
            return Err(Error::parameter("--ior", self.ior, "must be a positive number"));
        }
        // The course's camera: 120 units back, 60 up, looking 30 degrees down.
        let camera = Camera { position: Vector::new(0.0, 60.0, -120.0), pitch: -30.0, fov: 90.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 10;
        scene.lights.push(PointLight::new(Vector::new(120.0, 180.0, 0.0), Color::WHITE, 45000.0));
        scene.environment = Some(sky_cubemap()?);

        // The floor y = 1: tiles, and over them a mirror layer at blend 0.02.
        let mut floor = Layered::new();
        let tiles = load_texture("floor_tiles.png", self.floor.as_deref(), Filter::default())?;
        floor.add_layer(Lambert::new(tiles.with_tile_size(100.0)), Color::WHITE, None);
        floor.add_layer(Reflection::new(0.9), Color::gray(0.02), None);
        scene.add(Node::new(Plane::new(1.0, 100.0), floor).named("floor"));

        // The glass sphere: refraction under a Fresnel-blended reflection, both passing 90% of the light.
        let glass = fresnel_glass(self.ior, self.fresnel, 0.9);
        scene.add(Node::new(Sphere::new(Vector::new(0.0, 30.0, -30.0), 27.0), glass).named("glass sphere"));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
