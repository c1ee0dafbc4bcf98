//! One module per example: each builds its example's scene from its options, step by step. The examples,
//! the regression tests and the benchmarks all build their scenes here, so they render the same thing.

pub mod bitmap_textures;
pub mod dispersion;
pub mod environment;
pub mod fresnel;
pub mod glossy;
pub mod layered;
pub mod model_transform;
pub mod photon_map;
pub mod reflect_v01;
pub mod reflect_v02;
pub mod refract;

use crate::bitmap::{Bitmap, Filter};
use crate::color::Color;
use crate::environment::Environment;
use crate::error::Result;
use crate::geometry::Plane;
use crate::node::Node;
use crate::shader::Lambert;
use crate::texture::{BitmapTexture, CheckerTexture};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The path of a bundled texture (under the workbook's `textures/`, wherever it is run from).
pub fn texture_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("textures").join(name)
}

/// Loads a bundled texture, or the student's own file in its place when `custom` is given.
pub fn load_texture(name: &str, custom: Option<&Path>, filter: Filter) -> Result<BitmapTexture> {
    let path = custom.map_or_else(|| texture_path(name), Path::to_path_buf);
    Ok(BitmapTexture::new(Arc::new(Bitmap::load(&path)?)).with_filter(filter))
}

/// The bundled sky (`textures/sky.hdr`) as an equirectangular environment.
pub fn sky() -> Result<Arc<dyn Environment>> {
    crate::environment::load(&texture_path("sky.hdr"))
}

/// A square floor of `2 * half_size` units at y = 0, in light and dark grey squares of `square` units.
pub fn checker_floor(half_size: f32, square: f32) -> Node {
    let checker = CheckerTexture { color1: Color::gray(0.75), color2: Color::gray(0.18), scaling: 1.0 / square };
    Node::new(Arc::new(Plane::new(0.0, half_size)), Arc::new(Lambert::new(checker)))
}
