//! # Environment maps (lecture 6, slides "Заден фон", "Интерфейс за заден фон")
//!
//! The slide's code: the spherical and cube-map look-ups of `src/lesson/environment.rs`, one texel each
//! (`Filter::Nearest` in `src/lesson/bitmap.rs`). `--slide` renders this example with the slides' choice of every step
//! beyond them (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change
//! (docs/beyond-the-slides.md).
//!
//! A ray that hits nothing sees the environment, which depends on the ray's direction only. Here a mirror
//! sphere, a red and a blue object stand on a small tiled stage under an HDR sky. Look at:
//! - the sky and the fields behind the stage: the environment seen directly;
//! - the mirror sphere: the whole environment around it, including the sun behind the camera, which is
//!   far brighter than white (an HDR image keeps that);
//! - the shadows: the point light stands where the sky's sun is.
//!
//! Try: `--kind cubemap` (the same sky as six cube faces, made from the spherical image: the objects do not
//! change, but the sky seen directly differs by a few levels at the clouds' edges, since each image samples
//! the sky on its own grid and the background is magnified; see docs/techniques.md), `--env
//! my_panorama.hdr` (any equirectangular image, its centre towards the camera), `--env my_skybox/` (a
//! folder with posx, negx, posy, negy, posz, negz).
//!
//! Homework ideas: rotate the environment by an angle around the vertical axis; light the diffuse objects
//! from the environment (average many environment samples over the hemisphere of the normal).

use lecture6::prelude::*;

/// Which of the two bundled environments to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Kind {
    /// One equirectangular image: direction to longitude and latitude.
    #[default]
    Spherical,
    /// Six cube faces: the largest component of the direction picks the face.
    Cubemap,
}

/// Environment maps: a mirror sphere and diffuse objects under an HDR sky.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// The kind of environment map the bundled sky is read from.
    #[arg(long, value_enum, default_value_t = Kind::Spherical)]
    pub kind: Kind,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let camera = Camera { position: Vector::new(0.0, 24.0, -75.0), pitch: -6.0, fov: 80.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.environment = Some(match self.kind {
            Kind::Spherical => sky()?,
            Kind::Cubemap => sky_cubemap()?,
        });
        scene.max_depth = 4;
        scene.ambient = Color::new(0.12, 0.14, 0.18);
        // The sun, far away in the direction the sky shows it: about unit irradiance at the stage.
        let distance = 5000.0;
        let sun = workbook::sun_direction() * distance;
        scene.lights.push(PointLight::new(sun, Color::new(1.0, 0.92, 0.8), distance * distance));

        scene.add(Node::new(Plane::new(0.0, 60.0), Lambert::new(texture("floor_tiles.png")?.with_tile_size(30.0))));
        // The mirror sphere shows the whole environment around it.
        scene.add(Node::new(Sphere::new(Vector::new(0.0, 20.0, 15.0), 20.0), Reflection::new(0.9)));
        let red = Phong::new(Color::new(0.7, 0.1, 0.08), 0.35, 80.0);
        scene.add(Node::new(Sphere::new(Vector::new(-38.0, 10.0, -5.0), 10.0), red));
        let blue = Lambert::new(Color::new(0.12, 0.25, 0.6));
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 9.0), blue).rotate(30.0, 0.0, 0.0).translate(Vector::new(38.0, 9.0, 0.0)),
        );
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
