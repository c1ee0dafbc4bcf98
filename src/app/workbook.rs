//! What the workbook's examples share that is not a slide's lesson: the bundled textures (under
//! `textures/`, made by `cargo run --bin make-assets`), the sky and a checker floor. A homework built on an
//! example uses them the same way, or its own files in their place. (The scenes that examples share are
//! lessons: they are in [`crate::app::scenes`].)

use crate::files::encoding::{self, Encoding};
use crate::lesson::bitmap::{Bitmap, Filter};
use crate::lesson::color::Color;
use crate::lesson::environment::{self, CubemapEnvironment, Environment};
use crate::lesson::error::Result;
use crate::lesson::geometry::Plane;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::shader::Lambert;
use crate::lesson::texture::{BitmapTexture, CheckerTexture};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The path of a bundled texture (under the workbook's `textures/`, wherever it is run from).
pub fn texture_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("textures").join(name)
}

/// Loads the bundled texture `name` as a colour (an 8- or 16-bit file decoded from sRGB to linear light),
/// bilinearly filtered and repeating.
pub fn texture(name: &str) -> Result<BitmapTexture> {
    load_texture(name, None, Filter::default())
}

/// Loads the bundled texture `name` as data, not as a colour (a roughness, bump or mask map: the codes as
/// they are stored, without the sRGB decoding that [`texture`] applies; see [`BitmapTexture::load_data`]),
/// bilinearly filtered and repeating.
pub fn texture_data(name: &str) -> Result<BitmapTexture> {
    BitmapTexture::load_data(&texture_path(name))
}

// Data textures are read by the workbook's files layer (the encoding of 8-bit codes) on the lesson's types:
// the lesson's bitmap reads colours, as the slide does.
impl Bitmap {
    /// Loads an image file as data (a roughness, bump or mask map), not as a colour: the codes of an 8- or
    /// 16-bit file (PNG, JPEG, BMP) are read as they are stored, code / 255 or code / 65535, without the sRGB
    /// decoding (grey 128 is 0.502, where [`Bitmap::load`] makes it 0.216); floating-point files (HDR, EXR)
    /// are linear already and read as `load` reads them.
    pub fn load_data(path: &Path) -> Result<Bitmap> {
        encoding::reading_as(Encoding::Raw, || Bitmap::load(path))
    }
}

impl BitmapTexture {
    /// Loads the image at `path` as data, not as a colour (a roughness, bump or mask map): its codes as they
    /// are stored, without the sRGB decoding ([`Bitmap::load_data`]).
    pub fn load_data(path: &Path) -> Result<BitmapTexture> {
        Ok(BitmapTexture::new(Arc::new(Bitmap::load_data(path)?)))
    }
}

/// Loads a bundled texture, or the student's own file in its place when `custom` is given.
pub fn load_texture(name: &str, custom: Option<&Path>, filter: Filter) -> Result<BitmapTexture> {
    let path = custom.map_or_else(|| texture_path(name), Path::to_path_buf);
    Ok(BitmapTexture::new(Arc::new(Bitmap::load(&path)?)).with_filter(filter))
}

/// The bundled sky (`textures/sky.hdr`) as an equirectangular environment.
pub fn sky() -> Result<Arc<dyn Environment>> {
    environment::load(&texture_path("sky.hdr"))
}

/// The same sky as six cube faces (`textures/sky_cubemap/`).
pub fn sky_cubemap() -> Result<Arc<dyn Environment>> {
    Ok(Arc::new(CubemapEnvironment::load(&texture_path("sky_cubemap"))?))
}

/// The direction of the bundled sky's sun.
pub fn sun_direction() -> Vector {
    crate::app::assets::sun_direction()
}

/// A square floor of `2 * half_size` units at y = 0, in light and dark grey squares of `square` units.
pub fn checker_floor(half_size: f32, square: f32) -> Node {
    let checker = CheckerTexture { color1: Color::gray(0.75), color2: Color::gray(0.18), scaling: 1.0 / square };
    Node::new(Plane::new(0.0, half_size), Lambert::new(checker))
}
