//! `BitmapTexture` (slide "Bitmap текстури"): a diffuse texture read from an image file. The hit's u/v are
//! divided by `scaling` (the course's convention: one copy of the image per `scaling` units of u/v, so a
//! plane whose u/v are world coordinates gets one tile per `scaling` world units), then wrapped in each
//! direction and filtered.

use super::Texture;
use crate::lesson::bitmap::{Bitmap, Filter, Wrap};
use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use std::path::Path;
use std::sync::Arc;

#[derive(Clone, Debug)]
pub struct BitmapTexture {
    pub bitmap: Arc<Bitmap>,
    /// Texture units per copy of the image.
    pub scaling: f32,
    pub filter: Filter,
    /// Wrapping of u and of v.
    pub wrap: (Wrap, Wrap),
}

impl BitmapTexture {
    /// A bilinear, repeating texture of the image, one copy per unit of u/v.
    pub fn new(bitmap: Arc<Bitmap>) -> BitmapTexture {
        BitmapTexture { bitmap, scaling: 1.0, filter: Filter::Bilinear, wrap: (Wrap::Repeat, Wrap::Repeat) }
    }
    /// Loads the image at `path`.
    pub fn load(path: &Path) -> Result<BitmapTexture> {
        Ok(BitmapTexture::new(Arc::new(Bitmap::load(path)?)))
    }
    pub fn with_scaling(self, scaling: f32) -> BitmapTexture {
        BitmapTexture { scaling, ..self }
    }
    pub fn with_filter(self, filter: Filter) -> BitmapTexture {
        BitmapTexture { filter, ..self }
    }
    pub fn with_wrap(self, u: Wrap, v: Wrap) -> BitmapTexture {
        BitmapTexture { wrap: (u, v), ..self }
    }
}

impl Texture for BitmapTexture {
    fn get_tex_color(&self, _ray: &Ray, info: &IntersectionInfo) -> Color {
        let (u, v) = info.uv();
        self.bitmap.sample(u / self.scaling, v / self.scaling, self.filter, self.wrap)
    }
}
