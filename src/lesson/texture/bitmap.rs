//! `BitmapTexture` (slide "Bitmap текстури"): a diffuse texture read from an image file. The hit's u/v are
//! divided by `tile_size` (one copy of the image per `tile_size` units of u/v, so a plane whose u/v are
//! world coordinates gets one tile per `tile_size` world units), then wrapped in each direction and
//! filtered.
//!
//! Deviation from the course: its program and its scene files call the tile size `scaling`. The workbook
//! names it for what it is, because a checker's `scaling` ([`super::CheckerTexture`]) multiplies u/v
//! instead; a scene file's `scaling` is read as the tile size, unchanged (ledger: `tile-size`).

use super::{Tex, Texture};
use crate::lesson::bitmap::{Bitmap, Filter, Wrap};
use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::topic::Recorder;
use std::path::Path;
use std::sync::Arc;

/// A diffuse texture read from an image (slide "Bitmap текстури"): the hit's u/v, divided by `tile_size`,
/// pick its colour.
#[derive(Clone, Debug)]
pub struct BitmapTexture {
    /// The image, in an `Arc` so that several textures can share it.
    pub bitmap: Arc<Bitmap>,
    /// Units of u/v per copy of the image (the course's `scaling`): larger values make the image larger.
    pub tile_size: f32,
    /// How a colour is read between texel centres: nearest or bilinear.
    pub filter: Filter,
    /// Wrapping of u and of v.
    pub wrap: (Wrap, Wrap),
}

impl BitmapTexture {
    /// A bilinear, repeating texture of the image, one copy per unit of u/v.
    pub fn new(bitmap: Arc<Bitmap>) -> BitmapTexture {
        BitmapTexture { bitmap, tile_size: 1.0, filter: Filter::Bilinear, wrap: (Wrap::Repeat, Wrap::Repeat) }
    }
    /// Loads the image at `path` as a colour: an 8- or 16-bit file is decoded from sRGB to linear light
    /// ([`Bitmap::load`]); a map of numbers is read with [`BitmapTexture::load_data`].
    pub fn load(path: &Path) -> Result<BitmapTexture> {
        Ok(BitmapTexture::new(Arc::new(Bitmap::load(path)?)))
    }
    /// The same texture with one copy of the image per `tile_size` units of u/v (larger values make it
    /// larger).
    pub fn with_tile_size(self, tile_size: f32) -> BitmapTexture {
        BitmapTexture { tile_size, ..self }
    }
    /// The old name of [`BitmapTexture::with_tile_size`] (the course's `scaling`), the same number.
    #[deprecated(note = "renamed `with_tile_size`, the same number: units of u/v per copy of the image (a checker's \
                         `scaling` multiplies u/v instead)")]
    pub fn with_scaling(self, scaling: f32) -> BitmapTexture {
        self.with_tile_size(scaling)
    }
    /// The same texture read with `filter`.
    pub fn with_filter(self, filter: Filter) -> BitmapTexture {
        BitmapTexture { filter, ..self }
    }
    /// The same texture with `u` wrapping across and `v` down the image.
    pub fn with_wrap(self, u: Wrap, v: Wrap) -> BitmapTexture {
        BitmapTexture { wrap: (u, v), ..self }
    }

    /// The colour at the hit read through `filter` (the texture's own, or one texel on the slide), the
    /// texels read told to `recorder`.
    pub(super) fn read(&self, info: &IntersectionInfo, filter: Filter, recorder: Option<&mut dyn Recorder>) -> Color {
        let (u, v) = self.lookup_uv(info.uv());
        self.bitmap.sample_recorded(u, v, filter, self.wrap, recorder)
    }
}

impl Texture for BitmapTexture {
    #[inline(always)]
    fn get_tex_color(&self, _ray: &Ray, info: &IntersectionInfo) -> Color {
        let (u, v) = self.lookup_uv(info.uv());
        self.bitmap.sample(u, v, self.filter, self.wrap)
    }

    /// The surface's u/v divided by `tile_size`: one copy of the image per unit.
    #[inline]
    fn lookup_uv(&self, (u, v): (f32, f32)) -> (f32, f32) {
        (u / self.tile_size, v / self.tile_size)
    }

    fn into_tex(self: Arc<Self>) -> Tex {
        Tex::Bitmap(Arc::unwrap_or_clone(self))
    }
}
