//! Image files as the renderer opens them (not a slide's lesson, but what keeps a hostile image from filling
//! the memory): the pixel budget of the images a run holds, and [`ImageFile`], a file whose size has been
//! read from its header and taken from the budget before anything is decoded.
//!
//! The images held in memory at once, all of them together (textures and environments), may have at most
//! [`MAX_IMAGE_PIXELS`] pixels. The `--compare` reference does not count against them
//! ([`ImageFile::open_unbudgeted`]): it is decoded only when its size is the picture's, which has a limit of
//! its own, as the picture itself does not count. A small file that claims a huge picture (a
//! 250 KB PNG of 16000 x 16000 pixels) is refused at once instead of being decoded into gigabytes; a
//! decoder that finds more than its header said is stopped by `image::Limits`. Each image in memory holds a
//! [`PixelCharge`], given back to the budget when it is dropped. The count is kept for the whole process: a
//! run is one process.

use crate::files::error::{Error, Result};
use crate::files::input;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufReader, Seek};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The most pixels the images held in memory at once may have together: 2^26 = 67,108,864, an 8192 x 8192
/// picture, or an 8192 x 4096 panorama with room to spare for textures. At 4 bytes a pixel for 8-bit files
/// and 16 for floating-point ones that is 256 MiB to 1 GiB.
pub const MAX_IMAGE_PIXELS: u64 = 1 << 26;

/// The most bytes a decoder may allocate (its output included): a floating-point RGBA picture of the whole
/// budget. A second guard, behind the header check, for a file whose decoder finds more than its header said.
const MAX_DECODER_BYTES: u64 = MAX_IMAGE_PIXELS * 16;

/// The images held in memory now, in this process (see [`PixelCharge`]), by a number of their own: what each
/// is (a file, or a picture made in memory) and its pixels. A refusal names the ones that hold the budget.
static HELD: Mutex<BTreeMap<u64, (String, u64)>> = Mutex::new(BTreeMap::new());

/// The number of the next image held.
static NEXT_HOLDER: AtomicU64 = AtomicU64::new(0);

/// The images held now, locked (a thread that panicked while holding the lock left them whole).
fn held() -> MutexGuard<'static, BTreeMap<u64, (String, u64)>> {
    HELD.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A share of the pixel budget, held by an image in memory and given back when it is dropped.
#[derive(Debug)]
pub struct PixelCharge {
    pixels: u64,
    holder: u64,
}

impl PixelCharge {
    /// Takes `pixels` from the budget for the image `what`, unless that would take it past
    /// [`MAX_IMAGE_PIXELS`]: then the pixels held already, and the images that hold the most of them.
    fn reserve(pixels: u64, what: String) -> std::result::Result<PixelCharge, (u64, String)> {
        let mut images = held();
        let total = images.values().map(|(_, n)| n).sum::<u64>();
        if total.checked_add(pixels).is_none_or(|sum| sum > MAX_IMAGE_PIXELS) {
            let mut holders: Vec<&(String, u64)> = images.values().filter(|(_, n)| *n > 0).collect();
            holders.sort_by_key(|(_, n)| std::cmp::Reverse(*n));
            let named: Vec<String> = holders.iter().take(3).map(|(what, n)| format!("{n} by {what}")).collect();
            return Err((total, named.join(", ")));
        }
        Ok(PixelCharge::held_by(&mut images, pixels, what))
    }

    /// Counts `pixels` made in memory rather than read from a file: they count against the files read
    /// after them, but are never refused.
    pub(crate) fn count(pixels: u64) -> PixelCharge {
        PixelCharge::held_by(&mut held(), pixels, "an image made in memory".to_string())
    }

    fn held_by(images: &mut BTreeMap<u64, (String, u64)>, pixels: u64, what: String) -> PixelCharge {
        let holder = NEXT_HOLDER.fetch_add(1, Ordering::Relaxed);
        images.insert(holder, (what, pixels));
        PixelCharge { pixels, holder }
    }
}

impl Clone for PixelCharge {
    /// A copy of an image holds as many pixels again.
    fn clone(&self) -> PixelCharge {
        let mut images = held();
        let what = images.get(&self.holder).map_or_else(String::new, |(what, _)| what.clone());
        PixelCharge::held_by(&mut images, self.pixels, what)
    }
}

impl Drop for PixelCharge {
    fn drop(&mut self) {
        held().remove(&self.holder);
    }
}

/// The largest image file read: a floating-point RGBA picture of the whole budget, uncompressed. Some
/// decoders read a file whole before they look at it, so a larger file is refused from its size before
/// anything is read.
pub const MAX_IMAGE_FILE_BYTES: u64 = MAX_DECODER_BYTES;

/// The formats the renderer reads, each with the bytes its files begin with (Radiance files begin with
/// `#?RADIANCE`, or `#?RGBE` as some programs write them). A file is read as the format its first bytes
/// name, whatever its extension says; a file that begins with none of them is refused before it is decoded.
const SIGNATURES: [(&[u8], image::ImageFormat); 6] = [
    (b"\x89PNG\r\n\x1a\n", image::ImageFormat::Png),
    (b"\xff\xd8\xff", image::ImageFormat::Jpeg),
    (b"BM", image::ImageFormat::Bmp),
    (b"#?RADIANCE", image::ImageFormat::Hdr),
    (RGBE_SIGNATURE, image::ImageFormat::Hdr),
    (b"v/1\x01", image::ImageFormat::OpenExr),
];

/// The other signature of Radiance files, which the decoder does not know: such a file is decoded with
/// `#?RADIANCE` in its place.
const RGBE_SIGNATURE: &[u8] = b"#?RGBE";

/// The JPEG end-of-image marker, the last two bytes of a whole JPEG file (zeros may pad it).
const JPEG_END: [u8; 2] = [0xff, 0xd9];

/// The format named by the first bytes of `file`, or why there is none.
fn signature(mut file: &File, size: u64) -> std::result::Result<(image::ImageFormat, &'static [u8]), String> {
    use std::io::Read;
    let mut head = [0u8; 16];
    let mut read = 0;
    while read < head.len() {
        match file.read(&mut head[read..]) {
            Ok(0) => break,
            Ok(n) => read += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e.to_string()),
        }
    }
    let head = &head[..read];
    if let Some(&(magic, format)) = SIGNATURES.iter().find(|(magic, _)| head.starts_with(magic)) {
        return Ok((format, magic));
    }
    if size == 0 {
        return Err("it is empty".to_string());
    }
    let bytes: Vec<String> = head.iter().take(8).map(|b| format!("{b:02x}")).collect();
    Err(format!(
        "not a PNG, JPEG, BMP, Radiance HDR or OpenEXR file: it begins with bytes {}, none of their signatures",
        bytes.join(" ")
    ))
}

/// Fails unless the JPEG file `file` of `size` bytes ends with the end-of-image marker, zeros after it
/// aside: a JPEG cut short decodes without an error, as grey or a repeated pattern where its data ends.
fn check_jpeg_end(mut file: &File, size: u64) -> std::result::Result<(), String> {
    use std::io::{Read, SeekFrom};
    const TAIL: u64 = 4096;
    let mut tail = Vec::new();
    file.seek(SeekFrom::Start(size.saturating_sub(TAIL))).map_err(|e| e.to_string())?;
    file.take(TAIL).read_to_end(&mut tail).map_err(|e| e.to_string())?;
    let end = tail.iter().rposition(|&b| b != 0).map_or(0, |i| i + 1);
    if tail[..end].ends_with(&JPEG_END) {
        return Ok(());
    }
    Err("truncated JPEG: it does not end with the end-of-image marker (ff d9), so its picture is cut short".into())
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

/// The channels of the EXR file `file`, listed, if its header reads and lacks one of R, G and B (the image
/// decoder says only "image does not contain non-deep rgb channels").
fn exr_without_rgb(mut file: &File) -> Option<String> {
    file.rewind().ok()?;
    let meta = exr::meta::MetaData::read_from_buffered(BufReader::new(file), false).ok()?;
    let names: Vec<String> =
        meta.headers.iter().flat_map(|h| h.channels.list.iter().map(|c| c.name.to_string())).collect();
    let has = |name: &str| names.iter().any(|n| n == name);
    (!(has("R") && has("G") && has("B"))).then(|| names.join(", "))
}

/// An image file whose header has been read: its size is known and its pixels are taken from the budget
/// ([`MAX_IMAGE_PIXELS`]), but nothing is decoded yet. [`ImageFile::decode`] reads the picture.
#[derive(Debug)]
pub struct ImageFile {
    path: PathBuf,
    file: File,
    /// The file's bytes with `#?RADIANCE` in place of `#?RGBE`, for a Radiance file that begins so.
    rewritten: Option<Vec<u8>>,
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
        ImageFile::open_budgeted(path, true)
    }

    /// Opens the image file at `path` as [`ImageFile::open`] does, but without taking its pixels from the
    /// budget: for a picture whose size another limit bounds. The `--compare` reference is one: it is decoded
    /// only when its size is the render's, itself at most [`MAX_IMAGE_PIXELS`], and a student who may render
    /// a picture of a size may compare it with a reference of that size, whatever textures the scene holds.
    pub fn open_unbudgeted(path: &Path) -> Result<ImageFile> {
        ImageFile::open_budgeted(path, false)
    }

    /// [`ImageFile::open`], its pixels taken from the budget if `budgeted`.
    fn open_budgeted(path: &Path, budgeted: bool) -> Result<ImageFile> {
        let (file, size) = input::open(path, "cannot open image")?;
        let refuse = |reason: String| Error::file("cannot read image", path, reason);
        if size > MAX_IMAGE_FILE_BYTES {
            return Err(refuse(format!(
                "it is {size} bytes long; an image file may be at most {MAX_IMAGE_FILE_BYTES} bytes (a \
                 floating-point picture of the whole pixel budget)"
            )));
        }
        let (format, magic) = signature(&file, size).map_err(refuse)?;
        if format == image::ImageFormat::Jpeg {
            check_jpeg_end(&file, size).map_err(refuse)?;
        }
        let rewritten = if magic == RGBE_SIGNATURE {
            use std::io::Read;
            let mut bytes = b"#?RADIANCE".to_vec();
            (&file).seek(std::io::SeekFrom::Start(magic.len() as u64)).map_err(|e| refuse(e.to_string()))?;
            (&file).read_to_end(&mut bytes).map_err(|e| refuse(e.to_string()))?;
            Some(bytes)
        } else {
            None
        };
        let fail = |e: image::ImageError| Error::file("cannot read image", path, e);
        (&file).rewind().map_err(|e| fail(e.into()))?;
        let dimensions = match &rewritten {
            Some(bytes) => image::ImageReader::with_format(std::io::Cursor::new(bytes), format).into_dimensions(),
            None => image::ImageReader::with_format(BufReader::new(&file), format).into_dimensions(),
        };
        let (width, height) = dimensions.map_err(|e| match (bmp_header_size(&file, format), exr_without_rgb(&file)) {
            // The BMP decoder calls a size of zero "too large".
            (Some((w, h)), _) if w == 0 || h == 0 => {
                Error::file("cannot use image", path, format!("it has no pixels ({w}x{h})"))
            }
            (_, Some(channels)) => Error::file(
                "cannot use image",
                path,
                format!(
                    "it holds the channels {channels} only (a luminance-only picture?): the workbook reads an EXR's \
                     R, G and B; save it as RGB"
                ),
            ),
            _ => fail(e),
        })?;
        if width == 0 || height == 0 {
            return Err(Error::file("cannot use image", path, format!("it has no pixels ({width}x{height})")));
        }
        let pixels = width as u64 * height as u64;
        let what = format!("'{}'", path.display());
        let charge = if budgeted {
            PixelCharge::reserve(pixels, what).map_err(|(held, holders)| {
                Error::file(
                    "cannot load image",
                    path,
                    format!(
                        "it is {width}x{height} = {pixels} pixels; the images of a run may hold at most \
                         {MAX_IMAGE_PIXELS} pixels together, and {held} are held already ({holders})"
                    ),
                )
            })?
        } else {
            PixelCharge::held_by(&mut held(), 0, what)
        };
        Ok(ImageFile { path: path.to_path_buf(), file, rewritten, format, width, height, charge })
    }

    /// Width and height in pixels, as the header says.
    pub fn dimensions(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Decodes the picture; its share of the budget comes with it, to be held as long as the picture is.
    /// The decoder may not make a picture of another size than the header's.
    /// A picture cut short is refused as truncated, and a floating-point picture must hold finite light of
    /// at most `max_light` (what its user can add up: the renderer's `lesson::bitmap::MAX_IMAGE_LIGHT`): a
    /// NaN, infinite or brighter pixel is refused, naming it.
    pub fn decode(mut self, max_light: f32) -> Result<(image::DynamicImage, PixelCharge)> {
        let path = &self.path;
        let fail = |e: image::ImageError| match e {
            image::ImageError::IoError(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => {
                Error::file("cannot decode image", path, "it is truncated: the file ends before its picture does")
            }
            e => Error::file("cannot decode image", path, e),
        };
        let mut limits = image::Limits::default();
        limits.max_image_width = Some(self.width);
        limits.max_image_height = Some(self.height);
        limits.max_alloc = Some(MAX_DECODER_BYTES);
        let image = match &self.rewritten {
            Some(bytes) => {
                let mut reader = image::ImageReader::with_format(std::io::Cursor::new(bytes), self.format);
                reader.limits(limits);
                reader.decode()
            }
            None => {
                self.file.rewind().map_err(|e| fail(e.into()))?;
                let mut reader = image::ImageReader::with_format(BufReader::new(&self.file), self.format);
                reader.limits(limits);
                reader.decode()
            }
        }
        .map_err(fail)?;
        if let Some((x, y, value)) = first_too_bright(&image, max_light) {
            return Err(Error::file(
                "cannot use image",
                path,
                format!(
                    "pixel ({x}, {y}) is {value:e}: an image must hold finite light of at most {max_light:.2e}, \
                     which the samples of a pixel can add up without passing 32-bit floats' 3.4e38"
                ),
            ));
        }
        Ok((image, self.charge))
    }
}

/// The first pixel (column, row) of a floating-point `image` with a colour channel that is NaN, infinite or
/// brighter than `max_light`, and that value.
fn first_too_bright(image: &image::DynamicImage, max_light: f32) -> Option<(u32, u32, f32)> {
    let (pixels, channels): (&[f32], usize) = match image {
        image::DynamicImage::ImageRgb32F(img) => (img.as_raw(), 3),
        image::DynamicImage::ImageRgba32F(img) => (img.as_raw(), 4),
        _ => return None,
    };
    let width = image.width() as usize;
    pixels.chunks_exact(channels).enumerate().find_map(|(i, p)| {
        let bad = p[..3].iter().find(|c| c.is_nan() || c.abs() > max_light)?;
        Some(((i % width) as u32, (i / width) as u32, *bad))
    })
}
