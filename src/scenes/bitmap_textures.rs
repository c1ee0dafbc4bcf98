//! Scene of the `bitmap_textures` example (slide "Bitmap текстури"): diffuse textures read from image files.
//!
//! - The floor is a 400 x 400 plane whose u/v are world coordinates; `scaling` 40 puts one copy of the
//!   4 x 4-tile image on every 40 x 40 units, so the image repeats across the floor.
//! - The left sphere wears a planet map once (u = longitude, v = latitude), shaded with Phong.
//! - The middle sphere wears an 8 x 8 checker image, twice around and once from pole to pole: each
//!   texel covers many pixels, so `--filter nearest` shows hard blocks and `--filter bilinear` soft ramps.
//! - The cube wears wood on every face, each face mapped once.
//!
//! `--wrap` chooses what happens outside [0, 1) (the floor and the middle sphere go outside it);
//! `--texture FILE` puts any image on the spheres and the cube.

use crate::bitmap::{Filter, Wrap};
use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::Result;
use crate::geometry::{Cube, Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Phong};
use std::path::PathBuf;
use std::sync::Arc;

/// Bitmap textures: a tiled floor, a planet, a magnified checker and a wooden cube under a point light.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "bitmap_textures", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// How texels are filtered: nearest shows each texel as a block, bilinear blends neighbours.
    #[arg(long, value_enum, default_value_t = Filter::Bilinear)]
    pub filter: Filter,
    /// How texture coordinates outside [0, 1) wrap (both directions).
    #[arg(long, value_enum, default_value_t = Wrap::Repeat)]
    pub wrap: Wrap,
    /// An image of your own (PNG, JPEG, BMP, HDR, EXR) to put on the spheres and the cube.
    #[arg(long, value_name = "FILE")]
    pub texture: Option<PathBuf>,
}

impl Example for Args {
    const NAME: &'static str = "bitmap_textures";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let own = self.texture.as_deref();
        let load = |name| super::load_texture(name, own, self.filter).map(|t| t.with_wrap(self.wrap, self.wrap));

        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 48.0, -95.0),
            pitch: -20.0,
            fov: 75.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.12);
        scene.lights.push(PointLight::new(Vector::new(-60.0, 160.0, -90.0), Color::WHITE, 38000.0));

        // The floor keeps the bundled tiles, so a student's own image is judged on the objects.
        let floor = super::load_texture("floor_tiles.png", None, self.filter)?
            .with_scaling(40.0)
            .with_wrap(self.wrap, self.wrap);
        scene.add(Node::new(Arc::new(Plane::new(0.0, 200.0)), Arc::new(Lambert::new(floor))));

        let planet = load("world.png")?;
        scene.add(Node::new(
            Arc::new(Sphere::new(Vector::new(-42.0, 20.0, 25.0), 20.0)),
            Arc::new(Phong::new(planet, 0.25, 40.0)),
        ));

        let checker = load("checker8.png")?.with_scaling(0.5);
        scene
            .add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 20.0, 25.0), 20.0)), Arc::new(Lambert::new(checker))));

        let wood = load("wood.png")?;
        scene.add(Node::new(Arc::new(Cube::new(Vector::new(42.0, 16.0, 25.0), 16.0)), Arc::new(Lambert::new(wood))));
        Ok(scene)
    }
}
