//! # Bitmap textures (lecture 6, slide "Bitmap текстури")
//!
//! The slide's code: `Bitmap::sample` with `Filter::Nearest` in `src/lesson/bitmap.rs` (one texel per look-up).
//! `--slide` renders this example with the slides' choice of every step beyond them (`--step NAME` adds one back);
//! `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! Diffuse textures read from image files colour a floor, two spheres and a cube. Look at:
//! - the floor: one image, repeated every 40 units (`with_tile_size`), fading with distance;
//! - the planet: a 2:1 map wrapped once around a sphere (u = longitude, v = latitude);
//! - the checker sphere: an 8 x 8 image magnified, so `--filter nearest` shows blocks and `--filter
//!   bilinear` blends them;
//! - the cube: every face maps the wood image once.
//!
//! Try: `--filter nearest`, `--wrap mirror`, `--texture my_photo.jpg`.
//!
//! Homework ideas: add a `--tile-size` option for the floor; implement trilinear filtering (mip-maps) and
//! compare the far floor with `--spp 1`.

use lecture6::prelude::*;

/// Bitmap textures: a tiled floor, a planet, a magnified checker and a wooden cube under a point light.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// How texels are filtered: nearest shows each texel as a block, bilinear blends neighbours.
    #[arg(long, value_enum, default_value_t = Filter::Bilinear)]
    pub filter: Filter,
    /// How texture coordinates outside [0, 1) wrap (both directions).
    #[arg(long, value_enum, default_value_t = Wrap::Repeat)]
    pub wrap: Wrap,
    /// An image of your own (PNG, JPEG, BMP, HDR, EXR) to put on the spheres and the cube (the images of a
    /// run may have 67108864 pixels together, see --env).
    #[arg(long, value_name = "FILE")]
    pub texture: Option<PathBuf>,
}

impl Options {
    /// The bundled texture `name`, or the student's image `own` (read once, shared by every object that
    /// shows it) in its place, filtered and wrapped as asked.
    fn load(&self, name: &str, own: Option<&Arc<Bitmap>>) -> Result<BitmapTexture> {
        let texture = match own {
            Some(bitmap) => BitmapTexture::new(bitmap.clone()).with_filter(self.filter),
            None => load_texture(name, None, self.filter)?,
        };
        Ok(texture.with_wrap(self.wrap, self.wrap))
    }
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        // The student's image is decoded once: it counts once against the pixel budget.
        let own = self.texture.as_deref().map(Bitmap::load).transpose()?.map(Arc::new);
        let own = own.as_ref();
        let camera = Camera { position: Vector::new(0.0, 48.0, -95.0), pitch: -20.0, fov: 75.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.12);
        scene.lights.push(PointLight::new(Vector::new(-60.0, 160.0, -90.0), Color::WHITE, 38000.0));

        // The floor keeps the bundled tiles, so a student's own image is judged on the objects.
        let floor = self.load("floor_tiles.png", None)?.with_tile_size(40.0);
        scene.add(Node::new(Plane::new(0.0, 200.0), Lambert::new(floor)));

        // A 2:1 world map wrapped once around a sphere: u is the longitude, v the latitude.
        let planet = self.load("world.png", own)?;
        scene.add(Node::new(Sphere::new(Vector::new(-42.0, 20.0, 25.0), 20.0), Phong::new(planet, 0.25, 40.0)));

        // An 8 x 8 checker image, magnified: the filter decides whether its texels show as blocks.
        let checker = self.load("checker8.png", own)?.with_tile_size(0.5);
        scene.add(Node::new(Sphere::new(Vector::new(0.0, 20.0, 25.0), 20.0), Lambert::new(checker)));

        let wood = self.load("wood.png", own)?;
        scene.add(Node::new(Cube::new(Vector::new(42.0, 16.0, 25.0), 16.0), Lambert::new(wood)));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
