//! `Bitmap` (slide "Bitmap текстури"): an image held in linear light, with nearest and bilinear look-ups and
//! wrapping. Used by [`BitmapTexture`](crate::texture::BitmapTexture) and by the environments.
//!
//! 8-bit files (PNG, JPEG, BMP) hold sRGB-encoded values and are decoded to linear light on load; floating
//! point files (Radiance HDR, OpenEXR) are linear already and keep values above 1.

use crate::color::{Color, srgb_to_linear, srgb8_to_linear_table};
use crate::error::{Error, Result};
use glam::Vec3A;
use std::path::Path;

/// What happens to texture coordinates outside [0, 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Wrap {
    /// The image tiles the plane.
    #[default]
    Repeat,
    /// Every other tile is mirrored, so neighbouring tiles meet without a seam.
    Mirror,
    /// Coordinates stick to the edge pixels.
    Clamp,
}

/// How a texel is chosen for a point between texel centres.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Filter {
    /// The texel the point falls in: blocky when magnified.
    Nearest,
    /// A distance-weighted mix of the four texels around the point.
    #[default]
    Bilinear,
}

impl Wrap {
    /// Maps an integer texel index into [0, n).
    fn texel(self, i: i64, n: usize) -> usize {
        let n = n as i64;
        (match self {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::Clamp => i.clamp(0, n - 1),
            Wrap::Mirror => {
                let m = i.rem_euclid(2 * n);
                if m < n { m } else { 2 * n - 1 - m }
            }
        }) as usize
    }
}

#[derive(Clone, Debug)]
pub struct Bitmap {
    width: usize,
    height: usize,
    pixels: Vec<Color>,
}

impl Bitmap {
    /// A bitmap from linear pixels in rows from the top. Panics if the sizes disagree or are zero (a
    /// programming error, not user input).
    pub fn from_pixels(width: usize, height: usize, pixels: Vec<Color>) -> Bitmap {
        assert!(width > 0 && height > 0 && pixels.len() == width * height);
        Bitmap { width, height, pixels }
    }

    /// Loads an image file; the format is detected from its contents.
    pub fn load(path: &Path) -> Result<Bitmap> {
        let reader = image::ImageReader::open(path)
            .map_err(|e| Error::file("cannot open image", path, e))?
            .with_guessed_format()
            .map_err(|e| Error::file("cannot read image", path, e))?;
        let img = reader.decode().map_err(|e| Error::file("cannot decode image", path, e))?;
        let (width, height) = (img.width() as usize, img.height() as usize);
        if width == 0 || height == 0 {
            return Err(Error::file("cannot use image", path, "it has no pixels"));
        }
        use image::DynamicImage as D;
        let pixels = match img {
            // Floating-point images (Radiance HDR, OpenEXR) hold linear light already.
            D::ImageRgb32F(_) | D::ImageRgba32F(_) => {
                img.to_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0)).sanitized()).collect()
            }
            // 16-bit integer images are sRGB-encoded.
            D::ImageLuma16(_) | D::ImageLumaA16(_) | D::ImageRgb16(_) | D::ImageRgba16(_) => {
                img.to_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0.map(srgb_to_linear)))).collect()
            }
            // 8-bit images are sRGB-encoded: decode through a 256-entry table.
            _ => {
                let table = srgb8_to_linear_table();
                img.to_rgb8().pixels().map(|p| Color(Vec3A::from_array(p.0.map(|c| table[c as usize])))).collect()
            }
        };
        Ok(Bitmap { width, height, pixels })
    }

    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixel at column `x`, row `y` (row 0 is the top).
    pub fn get_pixel(&self, x: usize, y: usize) -> Color {
        self.pixels[y * self.width + x]
    }

    /// The colour at texture coordinates (u, v): u runs left to right and v top to bottom across the image,
    /// one image per unit; outside [0, 1) the `wrap` mode decides.
    pub fn sample(&self, u: f32, v: f32, filter: Filter, wrap: (Wrap, Wrap)) -> Color {
        // NaN coordinates (a degenerate hit) read the first texel rather than index out of range.
        let x = if u.is_finite() { u * self.width as f32 } else { 0.0 };
        let y = if v.is_finite() { v * self.height as f32 } else { 0.0 };
        match filter {
            Filter::Nearest => {
                let (i, j) = (wrap.0.texel(x.floor() as i64, self.width), wrap.1.texel(y.floor() as i64, self.height));
                self.get_pixel(i, j)
            }
            Filter::Bilinear => {
                // Texel centres sit at half-integer coordinates.
                let (fx, fy) = (x - 0.5, y - 0.5);
                let (x0, y0) = (fx.floor(), fy.floor());
                let (tx, ty) = (fx - x0, fy - y0);
                let (x0, y0) = (x0 as i64, y0 as i64);
                let (i0, i1) = (wrap.0.texel(x0, self.width), wrap.0.texel(x0 + 1, self.width));
                let (j0, j1) = (wrap.1.texel(y0, self.height), wrap.1.texel(y0 + 1, self.height));
                let top = self.get_pixel(i0, j0) * (1.0 - tx) + self.get_pixel(i1, j0) * tx;
                let bottom = self.get_pixel(i0, j1) * (1.0 - tx) + self.get_pixel(i1, j1) * tx;
                top * (1.0 - ty) + bottom * ty
            }
        }
    }
}
