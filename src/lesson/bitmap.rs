//! `Bitmap` (slide "Bitmap текстури"): an image held in linear light, with nearest and bilinear look-ups and
//! wrapping. Used by [`BitmapTexture`](crate::lesson::texture::BitmapTexture) and by the environments.
//!
//! 8-bit files (PNG, JPEG, BMP) hold sRGB-encoded values. They are kept as they are, 4 bytes a texel, and
//! each texel read is decoded to linear light through a 256-entry table: a quarter of the memory of float
//! texels, so a large texture stays in the cache, and the same linear values as decoding on load. Bilinear
//! filtering mixes the decoded (linear) values. Floating point files (Radiance HDR, OpenEXR) are linear
//! already, keep values above 1 and are stored as floats, as are 16-bit files (decoded on load).
//!
//! The pixel budget: the images held in memory at once, all of them together (textures, environments, the
//! `--compare` reference), may have at most [`MAX_IMAGE_PIXELS`] pixels. A file is opened as an
//! [`ImageFile`], which reads only its header and takes its pixels from the budget before anything is
//! decoded, so that a small file that claims a huge picture (a 250 KB PNG of 16000 x 16000 pixels) is
//! refused at once instead of filling the memory. Every [`Bitmap`] gives its pixels back when it is dropped.

use crate::lesson::color::{Color, srgb_to_linear, srgb8_to_linear_table};
use crate::lesson::error::{Error, Result};
use crate::lesson::input;
use crate::lesson::math::floor;
use glam::Vec3A;
use std::fs::File;
use std::io::{BufReader, Seek};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The most pixels the images held in memory at once may have together: 2^26 = 67,108,864, an 8192 x 8192
/// picture, or an 8192 x 4096 panorama with room to spare for textures. At 4 bytes a pixel for 8-bit files
/// and 16 for floating-point ones that is 256 MiB to 1 GiB.
pub const MAX_IMAGE_PIXELS: u64 = 1 << 26;

/// The most bytes a decoder may allocate (its output included): a floating-point RGBA picture of the whole
/// budget. A second guard, behind the header check, for a file whose decoder finds more than its header said.
const MAX_DECODER_BYTES: u64 = MAX_IMAGE_PIXELS * 16;

/// Pixels of the images held in memory now, in this process (see [`PixelCharge`]).
static HELD_PIXELS: AtomicU64 = AtomicU64::new(0);

/// A share of the pixel budget, held by an image in memory and given back when it is dropped.
#[derive(Debug)]
pub struct PixelCharge(u64);

impl PixelCharge {
    /// Takes `pixels` from the budget, unless that would take it past [`MAX_IMAGE_PIXELS`].
    fn reserve(pixels: u64) -> Option<PixelCharge> {
        let fits = |held: u64| held.checked_add(pixels).filter(|&total| total <= MAX_IMAGE_PIXELS);
        HELD_PIXELS.fetch_update(Ordering::SeqCst, Ordering::SeqCst, fits).ok().map(|_| PixelCharge(pixels))
    }

    /// Counts `pixels` made in memory rather than read from a file: they count against the files read
    /// after them, but are never refused.
    fn count(pixels: u64) -> PixelCharge {
        HELD_PIXELS.fetch_add(pixels, Ordering::SeqCst);
        PixelCharge(pixels)
    }
}

impl Clone for PixelCharge {
    /// A copy of an image holds as many pixels again.
    fn clone(&self) -> PixelCharge {
        PixelCharge::count(self.0)
    }
}

impl Drop for PixelCharge {
    fn drop(&mut self) {
        HELD_PIXELS.fetch_sub(self.0, Ordering::SeqCst);
    }
}

/// The width and height a BMP file's header states, if `format` is BMP and the header can be read.
fn bmp_header_size(mut file: &File, format: image::ImageFormat) -> Option<(i64, i64)> {
    use std::io::Read;
    if format != image::ImageFormat::Bmp {
        return None;
    }
    let mut head = [0u8; 26];
    file.rewind().ok()?;
    file.read_exact(&mut head).ok()?;
    let u16_at = |i: usize| u16::from_le_bytes([head[i], head[i + 1]]) as i64;
    let i32_at = |i: usize| i32::from_le_bytes([head[i], head[i + 1], head[i + 2], head[i + 3]]) as i64;
    // After the 14-byte file header: the DIB header's size, then the width and height (16-bit in the
    // 12-byte OS/2 header, 32-bit in the others; a negative height is a picture stored top down).
    Some(if i32_at(14) == 12 { (u16_at(18), u16_at(20)) } else { (i32_at(18), i32_at(22).abs()) })
}

/// An image file whose header has been read: its size is known and its pixels are taken from the budget
/// ([`MAX_IMAGE_PIXELS`]), but nothing is decoded yet. [`ImageFile::decode`] reads the picture.
#[derive(Debug)]
pub struct ImageFile {
    path: PathBuf,
    file: File,
    format: image::ImageFormat,
    width: u32,
    height: u32,
    charge: PixelCharge,
}

impl ImageFile {
    /// Opens the image file at `path` (a regular file, see [`input::open`]) and reads the size from its
    /// header; the format is detected from its contents, or else its extension. A picture of no pixels,
    /// or one that does not fit in what is left of the budget, is refused here.
    pub fn open(path: &Path) -> Result<ImageFile> {
        let (file, _) = input::open(path, "cannot open image")?;
        let fail = |e: image::ImageError| Error::file("cannot read image", path, e);
        let mut reader = image::ImageReader::new(BufReader::new(&file));
        if let Ok(format) = image::ImageFormat::from_path(path) {
            reader.set_format(format);
        }
        let reader = reader.with_guessed_format().map_err(|e| fail(e.into()))?;
        let format = reader.format().ok_or_else(|| {
            Error::file("cannot read image", path, "not an image format the renderer reads (PNG, JPEG, BMP, HDR, EXR)")
        })?;
        let (width, height) = reader.into_dimensions().map_err(|e| match bmp_header_size(&file, format) {
            // The BMP decoder calls a size of zero "too large".
            Some((w, h)) if w == 0 || h == 0 => {
                Error::file("cannot use image", path, format!("it has no pixels ({w}x{h})"))
            }
            _ => fail(e),
        })?;
        if width == 0 || height == 0 {
            return Err(Error::file("cannot use image", path, format!("it has no pixels ({width}x{height})")));
        }
        let pixels = width as u64 * height as u64;
        let charge = PixelCharge::reserve(pixels).ok_or_else(|| {
            let held = HELD_PIXELS.load(Ordering::SeqCst);
            Error::file(
                "cannot load image",
                path,
                format!(
                    "it is {width}x{height} = {pixels} pixels; the images of a run may hold at most {MAX_IMAGE_PIXELS} \
                     pixels together, and {held} are held already"
                ),
            )
        })?;
        Ok(ImageFile { path: path.to_path_buf(), file, format, width, height, charge })
    }

    /// Width and height in pixels, as the header says.
    pub fn dimensions(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Decodes the picture; its share of the budget comes with it, to be held as long as the picture is.
    /// The decoder may not make a picture of another size than the header's.
    pub fn decode(mut self) -> Result<(image::DynamicImage, PixelCharge)> {
        let path = &self.path;
        let fail = |e: image::ImageError| Error::file("cannot decode image", path, e);
        self.file.rewind().map_err(|e| fail(e.into()))?;
        let mut reader = image::ImageReader::with_format(BufReader::new(&self.file), self.format);
        let mut limits = image::Limits::default();
        limits.max_image_width = Some(self.width);
        limits.max_image_height = Some(self.height);
        limits.max_alloc = Some(MAX_DECODER_BYTES);
        reader.limits(limits);
        let image = reader.decode().map_err(fail)?;
        Ok((image, self.charge))
    }
}

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
    #[inline(always)]
    fn texel(self, i: i64, n: usize) -> usize {
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
    /// 8-bit sRGB codes (the fourth byte is padding), decoded through `table`.
    Srgb8 { codes: Vec<[u8; 4]>, table: &'static [f32; 256] },
}

#[derive(Clone, Debug)]
pub struct Bitmap {
    width: usize,
    height: usize,
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
        Bitmap { width, height, texels: Texels::Linear(pixels), _charge: charge }
    }

    /// Loads an image file; the format is detected from its contents. Its size is checked against the
    /// pixel budget before it is decoded (see [`ImageFile`]).
    pub fn load(path: &Path) -> Result<Bitmap> {
        Bitmap::from_file(ImageFile::open(path)?)
    }

    /// Decodes an opened image file.
    pub fn from_file(file: ImageFile) -> Result<Bitmap> {
        let (img, charge) = file.decode()?;
        let (width, height) = (img.width() as usize, img.height() as usize);
        use image::DynamicImage as D;
        let texels = match img {
            // Floating-point images (Radiance HDR, OpenEXR) hold linear light already.
            D::ImageRgb32F(_) | D::ImageRgba32F(_) => {
                Texels::Linear(img.into_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0)).sanitized()).collect())
            }
            // 16-bit integer images are sRGB-encoded.
            D::ImageLuma16(_) | D::ImageLumaA16(_) | D::ImageRgb16(_) | D::ImageRgba16(_) => Texels::Linear(
                img.into_rgb32f().pixels().map(|p| Color(Vec3A::from_array(p.0.map(srgb_to_linear)))).collect(),
            ),
            // 8-bit images are sRGB-encoded: kept so, decoded through a 256-entry table when read.
            _ => Texels::Srgb8 {
                codes: img.into_rgb8().pixels().map(|p| [p[0], p[1], p[2], 0]).collect(),
                table: srgb8_to_linear_table(),
            },
        };
        Ok(Bitmap { width, height, texels, _charge: charge })
    }

    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixel at column `x`, row `y` (row 0 is the top).
    pub fn get_pixel(&self, x: usize, y: usize) -> Color {
        let i = y * self.width + x;
        match &self.texels {
            Texels::Linear(pixels) => pixels[i],
            Texels::Srgb8 { codes, table } => decode(codes[i], table),
        }
    }

    /// The colour at texture coordinates (u, v): u runs left to right and v top to bottom across the image,
    /// one image per unit; outside [0, 1) the `wrap` mode decides.
    pub fn sample(&self, u: f32, v: f32, filter: Filter, wrap: (Wrap, Wrap)) -> Color {
        // The storage is chosen once per look-up, not once per texel.
        match &self.texels {
            Texels::Linear(pixels) => self.filtered(u, v, filter, wrap, |i| pixels[i]),
            Texels::Srgb8 { codes, table } => self.filtered(u, v, filter, wrap, |i| decode(codes[i], table)),
        }
    }

    /// [`Bitmap::sample`], with `texel(i)` the linear colour of the texel at index `i` (row by row).
    #[inline(always)]
    fn filtered(&self, u: f32, v: f32, filter: Filter, wrap: (Wrap, Wrap), texel: impl Fn(usize) -> Color) -> Color {
        // NaN coordinates (a degenerate hit) read the first texel rather than index out of range.
        let x = if u.is_finite() { u * self.width as f32 } else { 0.0 };
        let y = if v.is_finite() { v * self.height as f32 } else { 0.0 };
        let at = |i: usize, j: usize| texel(j * self.width + i);
        match filter {
            Filter::Nearest => {
                at(wrap.0.texel(floor(x) as i64, self.width), wrap.1.texel(floor(y) as i64, self.height))
            }
            Filter::Bilinear => {
                // Texel centres sit at half-integer coordinates.
                let (fx, fy) = (x - 0.5, y - 0.5);
                let (x0, y0) = (floor(fx), floor(fy));
                let (tx, ty) = (fx - x0, fy - y0);
                let (x0, y0) = (x0 as i64, y0 as i64);
                let (i0, i1) = (wrap.0.texel(x0, self.width), wrap.0.texel(x0 + 1, self.width));
                let (j0, j1) = (wrap.1.texel(y0, self.height), wrap.1.texel(y0 + 1, self.height));
                let top = at(i0, j0) * (1.0 - tx) + at(i1, j0) * tx;
                let bottom = at(i0, j1) * (1.0 - tx) + at(i1, j1) * tx;
                top * (1.0 - ty) + bottom * ty
            }
        }
    }
}

/// The linear colour of an 8-bit sRGB texel.
#[inline(always)]
fn decode(code: [u8; 4], table: &[f32; 256]) -> Color {
    Color::new(table[code[0] as usize], table[code[1] as usize], table[code[2] as usize])
}
