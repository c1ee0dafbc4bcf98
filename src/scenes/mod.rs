//! One module per example: each builds its example's scene from its options, step by step. The examples,
//! the regression tests and the benchmarks all build their scenes here, so they render the same thing.

pub mod bitmap_textures;
pub mod dispersion;
pub mod model_transform;

use crate::bitmap::{Bitmap, Filter};
use crate::error::Result;
use crate::texture::BitmapTexture;
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
