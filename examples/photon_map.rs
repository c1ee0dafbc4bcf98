//! # Caustics by photon mapping (lecture 6, slides "Caustics", "Photon Mapping", "Пример за photon map")
//!
//! The slide's code: `src/lesson/photon_map/all_directions.rs` and `src/lesson/photon_map/kd_tree.rs` (photons in all
//! directions, the k nearest). `--slide` renders this example with the slides' choice of every step beyond them
//! (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! Light concentrated by refraction and reflection: a glass sphere focuses a point light into a bright spot
//! inside its own shadow, and a small mirror throws a bright patch onto the wall at the back ("слънчево
//! зайче"). Shadow rays cannot find this light (they would have to know which way to go through the glass), so
//! before rendering, photons are shot from the light at the glass and the mirror, followed through them and
//! stored where they land on a diffuse surface; the floor's and the wall's shader then turn the k nearest
//! photons into light.
//!
//! Look at:
//! - the caustic in the sphere's shadow: much brighter than the lit floor, with a soft halo (spherical
//!   aberration: the sphere's rim focuses closer than its centre);
//! - the mirror's spot on the wall: the shape of the mirror, stretched by the angle at which it lands;
//! - `--photons 0`: the same picture without a photon map, where both are missing;
//! - `--show-photons`: the photons themselves, one dot each, like the slide's last picture;
//! - `--photon-passes 16`: the progressive caustic, a step beyond the slide (16 photon maps of their own
//!   seeds, the later ones gathering within a shrinking radius, their pictures averaged): the caustic's
//!   blotches fade and its edge sharpens, in 16 times the time.
//!
//! Try: `--photons 20000` (blotchy) and `--photons 1000000` (smooth); `--k 10` versus `--k 300`;
//! `--radius 0.5` versus `--radius 8` (noise against blur); `--ior 1.33` (water focuses farther away);
//! `--abbe 8 --spectral sampled --spp 16` (a dispersive glass: photons carry wavelengths and the caustic
//! gets coloured fringes).
//!
//! Homework ideas: store photons that land without a specular bounce in a second (global) map and add
//! colour bleeding; a caustic from a glass cube; project the photons' hit points to find where the camera
//! should look.

use lecture6::prelude::*;

/// Caustics by photon mapping: a glass sphere focusing a point light onto the floor, and a small mirror
/// throwing a bright spot.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// Index of refraction n_d of the glass sphere: higher focuses closer to the sphere.
    #[arg(long, default_value_t = 1.5)]
    pub ior: f32,
    /// Abbe number of the glass sphere (the slide's measure of dispersion; 64 for crown glass, 25 for dense
    /// flint). A finite number makes the caustic chromatic: photons carry wavelengths, and the picture is
    /// traced per wavelength (try it with `--spectral sampled --spp 16`). inf: no dispersion.
    #[arg(long, default_value_t = f32::INFINITY)]
    pub abbe: f32,
}

/// Where the light is.
pub const LIGHT: Vector = Vector::new(5.0, 120.0, 95.0);
/// The glass sphere's centre.
pub const GLASS_CENTER: Vector = Vector::new(-22.0, 19.0, 20.0);
/// The glass sphere's radius.
pub const GLASS_RADIUS: f32 = 12.0;
/// The mirror's centre.
pub const MIRROR_CENTER: Vector = Vector::new(28.0, 10.0, 15.0);
/// The point of the wall the mirror throws the light's reflection to.
pub const MIRROR_SPOT: Vector = Vector::new(20.0, 22.0, WALL_Z);
/// The low wall at the back: the z of its face.
pub const WALL_Z: f32 = 70.0;
/// The low wall's height.
pub const WALL_HEIGHT: f32 = 35.0;

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let ior = Ior::abbe(self.ior, self.abbe)?;
        let camera = Camera { position: Vector::new(0.0, 55.0, -100.0), pitch: -22.0, fov: 70.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.06);
        scene.max_depth = 6;
        scene.lights.push(PointLight::new(LIGHT, Color::WHITE, 20000.0));
        // The photon map: photons shot at the glass and the mirror, and how many the estimate gathers, from
        // how far (`--photons`, `--k`, `--radius` change them).
        scene.photons = PhotonSettings { count: 400_000, k: 80, max_radius: Some(2.0), show: false };

        let floor = CheckerTexture { color1: Color::gray(0.7), color2: Color::gray(0.55), scaling: 1.0 / 25.0 };
        scene.add(Node::new(Plane::new(0.0, 150.0), Lambert::new(floor)));

        // The wall: a plane, squeezed to its height and stood up facing the camera. The light is behind it,
        // so its face is in shade: the mirror's spot shows on it.
        let half = 0.5 * WALL_HEIGHT;
        scene.add(
            Node::new(Plane::new(0.0, 80.0), Lambert::new(Color::gray(0.75)))
                .scale(Vector::new(1.0, 1.0, half / 80.0))
                .rotate(0.0, 90.0, 0.0)
                .translate(Vector::new(0.0, half, WALL_Z)),
        );

        // The slides' glass: a refraction layer, and over it a mirror layer blended by the Fresnel texture.
        let glass = fresnel_glass(ior, FresnelMode::Schlick, 1.0);
        scene.add(Node::new(Sphere::new(GLASS_CENTER, GLASS_RADIUS), glass));

        // The law of reflection: the mirror's normal is halfway between the directions to the light and to
        // the spot. A plane's normal is +Y; roll tilts it, yaw turns it about the vertical.
        let normal = ((LIGHT - MIRROR_CENTER).normalize() + (MIRROR_SPOT - MIRROR_CENTER).normalize()).normalize();
        let roll = normal.y.acos().to_degrees();
        let yaw = normal.z.atan2(normal.x).to_degrees();
        scene
            .add(Node::new(Plane::new(0.0, 4.0), Reflection::new(0.9)).rotate(yaw, 0.0, roll).translate(MIRROR_CENTER));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
