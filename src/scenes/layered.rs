//! Scene of the `layered` example (slides "Комбиниране на шейдъри", "Layered Shader", "Текстури", "Пример за
//! текстура"): materials made of layers, and textures that drive properties other than the diffuse colour.
//!
//! - The floor is lacquered wood, as on the slide: a diffuse wood layer under a clear, slightly reflective
//!   lacquer layer whose blend is a `Fresnel` texture, so the lacquer shows at grazing angles and hardly
//!   where the floor faces the camera. `--lacquer` scales that blend (0 is bare wood).
//! - The panel at the back is the slide's texture example: a mask texture is the blend of a mirror layer
//!   over a textured diffuse layer, so the mirror shows only where the mask is white.
//! - The left sphere is the slide's "Fresnel shader with layers": a diffuse layer, a refraction layer at
//!   blend 0.3 and a reflection layer blended by the Fresnel texture.
//! - The right sphere is banded metal: a mirror whose colour (`Reflection::multiplier`) comes from a texture,
//!   a texture driving the reflection colour.
//!
//! `--shade-every-layer` runs the slide's loop, which shades every layer everywhere; the picture is the
//! same and only the time differs (the layers under the panel's mirror, and its mirror where the mask is
//! black, are skipped otherwise).

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::environment::CubemapEnvironment;
use crate::error::{Error, Result};
use crate::geometry::{Cube, Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Layered, Reflection, Refraction};
use crate::texture::{Fresnel, FresnelMode};
use std::path::PathBuf;
use std::sync::Arc;

/// Layered materials: a lacquered floor, a masked mirror and two layered spheres.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "layered", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// A mask image of your own (PNG, JPEG, BMP, HDR, EXR) for the panel: white is mirror, black is tiles,
    /// grey a mix.
    #[arg(long, value_name = "FILE")]
    pub mask: Option<PathBuf>,
    /// Strength of the floor's lacquer, from 0 (bare wood) to 1: the blend colour of the lacquer layer,
    /// multiplied by its Fresnel texture.
    #[arg(long, default_value_t = 1.0)]
    pub lacquer: f32,
    /// Shade every layer at every point, as the slide's loop does (the same picture, more work): compare the
    /// time with and without it.
    #[arg(long)]
    pub shade_every_layer: bool,
}

/// Index of refraction of the lacquer, the clear coat and the glass (all about that of ordinary glass).
const IOR: f32 = 1.5;

impl Example for Args {
    const NAME: &'static str = "layered";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        if !(0.0..=1.0).contains(&self.lacquer) {
            return Err(Error::parameter("--lacquer", self.lacquer, "must be between 0 and 1"));
        }
        let every_layer = self.shade_every_layer;
        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 42.0, -105.0),
            pitch: -14.0,
            fov: 80.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 8;
        scene.lights.push(PointLight::new(Vector::new(-90.0, 160.0, -70.0), Color::WHITE, 42000.0));
        scene.environment = Some(Arc::new(CubemapEnvironment::load(&super::texture_path("sky_cubemap"))?));

        // Lacquered wood: diffuse wood, and on top a clear layer that reflects as much as Fresnel says.
        let wood = super::load_texture("wood.png", None, Default::default())?.with_scaling(60.0);
        let mut floor = Layered::new();
        floor.add_layer(Arc::new(Lambert::new(wood)), Color::WHITE, None);
        floor.add_layer(
            Arc::new(Reflection::new(1.0)),
            Color::gray(self.lacquer),
            Some(Arc::new(Fresnel::new(IOR, FresnelMode::Exact))),
        );
        floor.shade_every_layer(every_layer);
        scene.add(Node::new(Arc::new(Plane::new(0.0, 200.0)), Arc::new(floor)));

        // The masked mirror: the mask texture is the mirror layer's blend.
        let tiles = super::load_texture("floor_tiles.png", None, Default::default())?;
        let mask = super::load_texture("mirror_mask.png", self.mask.as_deref(), Default::default())?;
        let mut panel = Layered::new();
        panel.add_layer(Arc::new(Lambert::new(tiles)), Color::WHITE, None);
        panel.add_layer(Arc::new(Reflection::new(0.9)), Color::WHITE, Some(Arc::new(mask)));
        panel.shade_every_layer(every_layer);
        scene.add(
            Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), Arc::new(panel))
                .scale(Vector::new(56.0, 40.0, 1.5))
                .translate(Vector::new(0.0, 41.0, 75.0)),
        );

        // The slide's layered Fresnel shader: a diffuse base, refraction at 0.3, Fresnel-blended reflection.
        let mut glass = Layered::new();
        glass.add_layer(Arc::new(Lambert::new(Color::new(0.15, 0.35, 0.7))), Color::WHITE, None);
        glass.add_layer(Arc::new(Refraction::new(IOR, 1.0)), Color::gray(0.3), None);
        glass.add_layer(
            Arc::new(Reflection::new(1.0)),
            Color::WHITE,
            Some(Arc::new(Fresnel::new(IOR, FresnelMode::Schlick))),
        );
        glass.shade_every_layer(every_layer);
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-38.0, 22.0, 15.0), 22.0)), Arc::new(glass)));

        // Banded metal: a mirror whose reflection colour comes from a texture.
        let metals = super::load_texture("metals.png", None, Default::default())?;
        let metal = Reflection::mirror(metals);
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(38.0, 22.0, 15.0), 22.0)), Arc::new(metal)));
        Ok(scene)
    }
}
