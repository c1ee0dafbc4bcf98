//! # Layered shaders (lecture 6, slides "Комбиниране на шейдъри", "Layered Shader", "Текстури", "Пример за
//! текстура")
//!
//! The slide's code: `shade_bottom_up` in `src/lesson/shader/layered.rs` (the bottom-up loop). `--slide` renders this
//! example with the slides' choice of every step beyond them (`--step NAME` adds one back); `--side-by-side "--slide"`
//! shows what they change (docs/beyond-the-slides.md).
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

use lecture6::prelude::*;

/// Layered materials: a lacquered floor, a masked mirror and two layered spheres.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
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

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        if !(0.0..=1.0).contains(&self.lacquer) {
            return Err(Error::parameter("--lacquer", self.lacquer, "must be between 0 and 1"));
        }
        let camera = Camera { position: Vector::new(0.0, 42.0, -105.0), pitch: -14.0, fov: 80.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 8;
        scene.lights.push(PointLight::new(Vector::new(-90.0, 160.0, -70.0), Color::WHITE, 42000.0));
        scene.environment = Some(sky_cubemap()?);

        // Lacquered wood: diffuse wood, and on top a clear layer that reflects as much as Fresnel says.
        let mut floor = Layered::new();
        floor.add_layer(Lambert::new(texture("wood.png")?.with_tile_size(60.0)), Color::WHITE, None);
        let fresnel = Fresnel::new(IOR, FresnelMode::Exact);
        floor.add_layer(Reflection::new(1.0), Color::gray(self.lacquer), Some(Arc::new(fresnel)));
        floor.shade_every_layer(self.shade_every_layer);
        scene.add(Node::new(Plane::new(0.0, 200.0), floor));

        // The masked mirror: the mask texture is the mirror layer's blend.
        let mask = load_texture("mirror_mask.png", self.mask.as_deref(), Filter::default())?;
        let mut panel = Layered::new();
        panel.add_layer(Lambert::new(texture("floor_tiles.png")?), Color::WHITE, None);
        panel.add_layer(Reflection::new(0.9), Color::WHITE, Some(Arc::new(mask)));
        panel.shade_every_layer(self.shade_every_layer);
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 1.0), panel)
                .scale(Vector::new(56.0, 40.0, 1.5))
                .translate(Vector::new(0.0, 41.0, 75.0)),
        );

        // The slide's layered Fresnel shader: a diffuse base, refraction at 0.3, Fresnel-blended reflection.
        let mut glass = Layered::new();
        glass.add_layer(Lambert::new(Color::new(0.15, 0.35, 0.7)), Color::WHITE, None);
        glass.add_layer(Refraction::new(IOR, 1.0), Color::gray(0.3), None);
        glass.add_layer(Reflection::new(1.0), Color::WHITE, Some(Arc::new(Fresnel::new(IOR, FresnelMode::Schlick))));
        glass.shade_every_layer(self.shade_every_layer);
        scene.add(Node::new(Sphere::new(Vector::new(-38.0, 22.0, 15.0), 22.0), glass));

        // Banded metal: a mirror whose reflection colour comes from a texture.
        let metal = Reflection::mirror(texture("metals.png")?);
        scene.add(Node::new(Sphere::new(Vector::new(38.0, 22.0, 15.0), 22.0), metal));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
