//! # Refraction (lecture 6, slides "Refract", "Refraction 0.2")
//!
//! The slide's code: `src/lesson/shader/refraction.rs` (`Refraction`, which the workbook renders as the slide
//! writes it). `--slide` renders this example with it alone; `--side-by-side "--slide"` shows what the steps beyond
//! the slides change (docs/beyond-the-slides.md).
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

use lecture6::prelude::*;

/// Refraction: a glass sphere and a glass slab bending the view of a checker wall.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// Index of refraction of the glass (air is 1).
    #[arg(long, default_value_t = 1.5)]
    pub ior: f32,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        if !(self.ior.is_finite() && self.ior > 0.0) {
            return Err(Error::parameter("--ior", self.ior, "must be a positive number"));
        }
        let camera = Camera { position: Vector::new(0.0, 28.0, -70.0), pitch: -12.0, fov: 70.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.environment = Some(sky()?);
        // Enough for a ray to pass through both objects: in and out of each.
        scene.max_depth = 8;
        scene.ambient = Color::gray(0.15);
        scene.lights.push(PointLight::new(Vector::new(-60.0, 200.0, -80.0), Color::new(1.0, 0.96, 0.9), 60000.0));
        scene.add(checker_floor(150.0, 10.0));

        // The wall: a thin box 120 units square, 65 units behind the objects, in squares of 10 units.
        let checker =
            CheckerTexture { color1: Color::new(0.85, 0.8, 0.6), color2: Color::new(0.1, 0.3, 0.45), scaling: 12.0 };
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 1.0), Lambert::new(checker))
                .scale(Vector::new(60.0, 60.0, 1.0))
                .translate(Vector::new(0.0, 45.0, 80.0)),
        );

        // One glass for both objects, shared.
        let glass = Arc::new(Refraction::new(self.ior, 0.95));
        scene.add(Node::new(Sphere::new(Vector::new(-22.0, 16.0, 15.0), 16.0), glass.clone()));
        // The slab: a glass plate 28 x 32 x 6, turned 40 degrees and standing just above the floor.
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 1.0), glass)
                .scale(Vector::new(14.0, 16.0, 3.0))
                .rotate(40.0, 0.0, 0.0)
                .translate(Vector::new(24.0, 16.5, 15.0)),
        );
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
