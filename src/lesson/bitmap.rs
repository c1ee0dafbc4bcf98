//! `Bitmap` (slide "Bitmap текстури"): an image held in linear light, with nearest and bilinear look-ups and
//! wrapping. Used by [`BitmapTexture`](crate::lesson::texture::BitmapTexture) and by the environments.
//!
//! 8-bit files (PNG, JPEG, BMP) hold sRGB-encoded values. They are kept as they are, 4 bytes a texel, and
//! each texel read is decoded to linear light through a 256-entry table (the course's raw codes, under
//! `--encoding raw`, through a table of their own: [`crate::files::encoding`]): a quarter of the memory of float
//! texels, so a large texture stays in the cache, and the same linear values as decoding on load. Bilinear
//! filtering mixes the decoded (linear) values. Floating point files (Radiance HDR, OpenEXR) are linear
//! already, keep values above 1 and are stored as floats, as are 16-bit files (decoded on load).
//!
//! A file is read through an [`ImageFile`], which checks its size against the pixel budget of the images a
//! run holds before it is decoded; every bitmap holds its share of the budget until it is dropped.

use crate::files::encoding::{self, Encoding};
use crate::lesson::beyond::{Step, Steps};
use crate::lesson::color::{Color, raw8_to_linear_table, srgb_to_linear, srgb8_to_linear_table};
use crate::lesson::error::Result;
use crate::lesson::image_file::{ImageFile, PixelCharge};
use crate::lesson::math::floor;
use crate::lesson::topic::{Recorder, Texel, Topic, record};
use glam::Vec3A;
use std::path::Path;

// The slide's look-up first: the colour at (u, v), nearest or bilinear; the bitmap itself after it.
impl Bitmap {
    /// The colour at texture coordinates (u, v): u runs left to right and v top to bottom across the image,
    /// one image per unit; outside [0, 1) the `wrap` mode decides.
    #[inline(always)]
    pub fn sample(&self, u: f32, v: f32, filter: Filter, wrap: (Wrap, Wrap)) -> Color {
        self.sample_recorded(u, v, filter, wrap, None)
    }

    /// [`Bitmap::sample`], telling `recorder`, if given, the texels it read and their weights
    /// ([`Topic::Texels`]).
    #[inline(always)]
    pub fn sample_recorded(
        &self,
        u: f32,
        v: f32,
        filter: Filter,
        wrap: (Wrap, Wrap),
        recorder: Option<&mut dyn Recorder>,
    ) -> Color {
        // The storage is chosen once per look-up, not once per texel.
        match &self.texels {
            Texels::Linear(pixels) => self.filtered((u, v), filter, wrap, pixels, |c| c, recorder),
            Texels::Codes8 { codes, table } => {
                self.filtered((u, v), filter, wrap, codes, |code| decode(code, table), recorder)
            }
        }
    }

    /// [`Bitmap::sample_recorded`] from the texels `texels` (row by row), `linear` making a linear colour of
    /// one.
    #[inline(always)]
    fn filtered<T: Copy>(
        &self,
        (u, v): (f32, f32),
        filter: Filter,
        wrap: (Wrap, Wrap),
        texels: &[T],
        linear: impl Fn(T) -> Color,
        recorder: Option<&mut dyn Recorder>,
    ) -> Color {
        // NaN coordinates (a degenerate hit) are read as the first texel's (see `Wrap::neighbours`).
        let (x, y) = (u * self.size.0, v * self.size.1);
        let at = |i: usize, j: usize| linear(texels[j * self.width + i]);
        let read = |texels: &[(usize, usize, f32)]| {
            let texels = texels.iter().map(|&(x, y, weight)| Texel { x, y, weight, color: at(x, y) }).collect();
            Topic::Texels { u, v, texels }
        };
        match filter {
            Filter::Nearest => {
                let (i, j) = (wrap.0.texel(floor(x) as i64, self.width), wrap.1.texel(floor(y) as i64, self.height));
                record(recorder, || read(&[(i, j, 1.0)]));
                at(i, j)
            }
            Filter::Bilinear => {
                beyond!(TexelFilter);
                exercise!(bilinear(x, y, &|i, j| at(wrap.0.texel(i, self.width), wrap.1.texel(j, self.height))));
                // Texel centres sit at half-integer coordinates.
                let (i0, i1, tx) = wrap.0.neighbours(x - 0.5, self.width);
                let (j0, j1, ty) = wrap.1.neighbours(y - 0.5, self.height);
                record(recorder, || {
                    let (sx, sy) = (1.0 - tx, 1.0 - ty);
                    read(&[(i0, j0, sx * sy), (i1, j0, tx * sy), (i0, j1, sx * ty), (i1, j1, tx * ty)])
                });
                // The top two texels mixed, then the bottom two, then the two mixes.
                let top = at(i0, j0) * (1.0 - tx) + at(i1, j0) * tx;
                let bottom = at(i0, j1) * (1.0 - tx) + at(i1, j1) * tx;
                top * (1.0 - ty) + bottom * ty
            }
        }
    }
}

/// What happens to texture coordinates outside [0, 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Filter {
    /// The texel the point falls in: blocky when magnified.
    Nearest,
    /// A distance-weighted mix of the four texels around the point.
    #[default]
    Bilinear,
}

impl Filter {
    /// The filter a render that takes `steps` reads with: this one with the step
    /// [`Step::TexelFilter`], the slide's one texel (`Nearest`) without it.
    pub fn under(self, steps: Steps) -> Filter {
        if steps.has(Step::TexelFilter) { self } else { Filter::Nearest }
    }
}

impl Wrap {
    /// Maps an integer texel index into [0, n).
    #[inline(always)]
    pub fn texel(self, i: i64, n: usize) -> usize {
        // Inside the image every mode leaves the index as it is: no division.
        if (0..n as i64).contains(&i) {
            return i as usize;
        }
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

/// How a bitmap holds its texels.
#[derive(Clone, Debug)]
enum Texels {
    /// Linear colours.
    Linear(Vec<Color>),
    /// 8-bit codes (the fourth byte is padding), decoded through `table`.
    Codes8 { codes: Vec<[u8; 4]>, table: &'static [f32; 256] },
}

/// The brightest light an image may hold: the renderer adds the samples of a pixel before it averages them,
/// and [`MAX_SPP`](crate::lesson::frame::MAX_SPP) samples of up to this much light add up to a finite 32-bit number (an environment's light
/// reaches a pixel as it is). 5.2e33, far above any real sky (the sun's disc in an HDR panorama is under
/// 1e6); a Radiance pixel whose exponent byte is 255 (2^119 = 6.6e35 at least) or an EXR texel of 3e38 is
/// beyond it.
pub const MAX_IMAGE_LIGHT: f32 = f32::MAX / crate::lesson::frame::MAX_SPP as f32;

/// An image in linear light, addressed by pixel or sampled by texture coordinates (slide "Bitmap текстури").
#[derive(Clone, Debug)]
pub struct Bitmap {
    width: usize,
    height: usize,
    /// The width and height as floats, for turning texture coordinates into texel coordinates.
    size: (f32, f32),
    texels: Texels,
    /// The texels' share of the pixel budget.
    _charge: PixelCharge,
}

impl Bitmap {
    /// A bitmap from linear pixels in rows from the top. Panics if the sizes disagree or are zero (a
    /// programming error, not user input).
    pub fn from_pixels(width: usize, height: usize, pixels: Vec<Color>) -> Bitmap {
        assert!(width > 0 && height > 0 && pixels.len() == width * height);
        let charge = PixelCharge::count(pixels.len() as u64);
        Bitmap { width, height, size: (width as f32, height as f32), texels: Texels::Linear(pixels), _charge: charge }
    }

    /// Loads an image file; the format is detected from its contents. Its size is checked against the
    /// pixel budget before it is decoded (see [`ImageFile`]).
    pub fn load(path: &Path) -> Result<Bitmap> {
        Bitmap::from_file(ImageFile::open(path)?)
    }

    /// Decodes an opened image file.
    pub fn from_file(file: ImageFile) -> Result<Bitmap> {
        let (img, charge) = file.decode(MAX_IMAGE_LIGHT)?;
        let (width, height) = (img.width() as usize, img.height() as usize);
        let (table, to_linear): (_, fn(f32) -> f32) = match encoding::reading() {
            Encoding::Srgb => (srgb8_to_linear_table(), srgb_to_linear),
            Encoding::Raw => (raw8_to_linear_table(), |code| code),
        };
        use image::DynamicImage as D;
        let texels = match img {
            // Floating-point images (Radiance HDR, OpenEXR) hold linear light already.
            D::ImageRgb32F(_) | D::ImageRgba32F(_) => {
                Texels::Linear(img.into_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0)).sanitized()).collect())
            }
            // 16-bit integer images are encoded as 8-bit ones are.
            D::ImageLuma16(_) | D::ImageLumaA16(_) | D::ImageRgb16(_) | D::ImageRgba16(_) => Texels::Linear(
                img.into_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0.map(to_linear)))).collect(),
            ),
            // 8-bit images are kept as codes, decoded through a 256-entry table when read.
            _ => Texels::Codes8 { codes: img.into_rgb8().pixels().map(|p| [p[0], p[1], p[2], 0]).collect(), table },
        };
        Ok(Bitmap { width, height, size: (width as f32, height as f32), texels, _charge: charge })
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }
    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixel at column `x`, row `y` (row 0 is the top).
    pub fn get_pixel(&self, x: usize, y: usize) -> Color {
        let i = y * self.width + x;
        match &self.texels {
            Texels::Linear(pixels) => pixels[i],
            Texels::Codes8 { codes, table } => decode(codes[i], table),
        }
    }
}

impl Wrap {
    /// The two texels of a row or column of `n` around the coordinate `f` (in texels, their centres at whole
    /// numbers), wrapped, and how far past the first one's centre `f` lies.
    ///
    /// The usual case, two texels side by side inside the image, costs one comparison; `Repeat` wraps the
    /// first with one remainder; the rest is kept out of the look-up ([`Wrap::wrapped_pair`]). Coordinates
    /// beyond 2^30 texels (where a float cannot tell neighbouring texels apart anyway) count as 2^30, and a
    /// NaN (a degenerate hit) as -2^30, which every wrap takes to the first texel.
    #[inline(always)]
    fn neighbours(self, f: f32, n: usize) -> (usize, usize, f32) {
        const LIMIT: f32 = (1u32 << 30) as f32;
        // `max` and `min` return the other operand for a NaN: no NaN gets past them (`clamp` would pass it
        // on, and the conversion below would then have to test for it).
        #[allow(clippy::manual_clamp)]
        let f = f.max(-LIMIT).min(LIMIT);
        // `f as i32` rounds towards zero: one step down where that rounded up gives the floor.
        let i = f as i32;
        let i = i - ((i as f32) > f) as i32;
        let past = f - i as f32;
        let last = n as u32 - 1;
        if (i as u32) < last {
            return (i as usize, i as usize + 1, past);
        }
        if self == Wrap::Repeat {
            // The tile before the first (a tiled floor's negative coordinates) by one addition, any other
            // by `i.rem_euclid(n)`, written out (the library's is not inlined here). The addition costs two
            // instructions more than the division alone, and saves the division's wait.
            let before = i + n as i32;
            let r = if (before as u32) < n as u32 { before } else { i % n as i32 };
            let first = if r < 0 { r + n as i32 } else { r } as u32;
            return (first as usize, if first < last { first as usize + 1 } else { 0 }, past);
        }
        let (first, second) = self.wrapped_pair(i, n);
        (first, second, past)
    }

    /// The texels `i` and `i + 1` of a row or column of `n`, wrapped (the rare case of
    /// [`Wrap::neighbours`]).
    #[cold]
    #[inline(never)]
    fn wrapped_pair(self, i: i32, n: usize) -> (usize, usize) {
        (self.texel(i as i64, n), self.texel(i as i64 + 1, n))
    }
}

/// The linear colour of an 8-bit sRGB texel.
#[inline(always)]
fn decode(code: [u8; 4], table: &[f32; 256]) -> Color {
    Color::new(table[code[0] as usize], table[code[1] as usize], table[code[2] as usize])
}
