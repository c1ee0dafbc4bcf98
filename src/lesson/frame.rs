//! The picture a render makes: a frame of linear colours, and how it is written to a file (8-bit sRGB for
//! PNG, linear floats for EXR and HDR). The renderer ([`crate::lesson::render`]) fills it.

use crate::lesson::color::{Color, to_srgb8};
use crate::lesson::error::{Error, Result};
use crate::lesson::input;
use rayon::prelude::*;
use std::io::BufWriter;
use std::path::Path;
use tempfile::NamedTempFile;

/// A rendered picture in linear light, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The linear colours, row by row from the top: pixel (x, y) is at `y * width + x`.
    pub pixels: Vec<Color>,
}

impl Frame {
    /// A black frame. Its pixels are written in parallel (on the current rayon pool), so that the memory of a
    /// large frame is first touched, page by page, by every thread rather than by one.
    pub fn new(width: u32, height: u32) -> Frame {
        let mut pixels = Vec::new();
        pixels.par_extend(rayon::iter::repeat_n(Color::BLACK, width as usize * height as usize));
        Frame { width, height, pixels }
    }
    /// The linear colour of pixel (x, y), (0, 0) being the top-left corner.
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.pixels[(y * self.width + x) as usize]
    }
    /// The frame encoded as 8-bit sRGB, row by row in parallel (on the current rayon pool): the encoding would
    /// otherwise be a serial step after the parallel render.
    pub fn to_rgb8(&self) -> image::RgbImage {
        let w = self.width as usize;
        let mut bytes = vec![0u8; self.pixels.len() * 3];
        bytes.par_chunks_mut(3 * w).zip(self.pixels.par_chunks(w)).for_each(|(out, row)| {
            for (rgb, &c) in out.chunks_exact_mut(3).zip(row) {
                rgb.copy_from_slice(&to_srgb8(c));
            }
        });
        image::RgbImage::from_raw(self.width, self.height, bytes).expect("frame size matches its pixels")
    }
    /// The frame as linear floats.
    pub fn to_rgb32f(&self) -> image::Rgb32FImage {
        let values = self.pixels.iter().flat_map(|c| c.to_array()).collect();
        image::Rgb32FImage::from_raw(self.width, self.height, values).expect("frame size matches its pixels")
    }

    /// Writes the frame: `.png` as 8-bit sRGB, `.exr` and `.hdr` as linear floats. The image goes to a
    /// temporary file beside the target first and is renamed over it only when complete, so a failure never
    /// destroys an earlier picture (see [`save_atomically`]).
    pub fn save(&self, path: &Path) -> Result<()> {
        let format = output_format(path)?;
        save_atomically(path, |file| match format {
            image::ImageFormat::Png => self.to_rgb8().write_to(file, format),
            _ => self.to_rgb32f().write_to(file, format),
        })
    }
}

/// True for the files that keep linear light, floats above 1 included (`.exr`, `.hdr`); PNG and the other
/// 8-bit formats hold sRGB-encoded values from 0 to 1.
pub fn keeps_linear_light(path: &Path) -> bool {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    matches!(ext.as_deref(), Some("exr" | "hdr"))
}

/// The format a picture written to `path` has, from its extension: `.png`, `.exr` or `.hdr`.
pub fn output_format(path: &Path) -> Result<image::ImageFormat> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("png") => Ok(image::ImageFormat::Png),
        Some("exr") => Ok(image::ImageFormat::OpenExr),
        Some("hdr") => Ok(image::ImageFormat::Hdr),
        _ => Err(Error::file("cannot write image", path, "the name must end in .png, .exr or .hdr")),
    }
}

/// Checks, before any work, that a picture can be written to `path` as [`save_atomically`] writes it: its
/// name names `format` when one is given (an 8-bit picture such as a debug view is PNG only) or one of
/// [`output_format`]'s; what is there already is a regular file that may be written (a FIFO, a device
/// node or a read-only file is refused: the rename would replace it with a regular file, or change the
/// mode a read-only file was given); and its folder exists or can be made, and takes a new file (probed
/// with a temporary file, removed at once).
pub fn check_output(path: &Path, format: Option<image::ImageFormat>) -> Result<()> {
    let refuse = |reason: String| Error::file("cannot write image", path, reason);
    let named = output_format(path)?;
    if let Some(format) = format.filter(|&f| f != named) {
        let ext = format.extensions_str()[0];
        return Err(refuse(format!("this picture is written as {format:?} only: its name must end in .{ext}")));
    }
    if let Ok(metadata) = std::fs::metadata(path) {
        if !metadata.is_file() {
            return Err(refuse(format!(
                "it is {}; a picture is written only as a regular file",
                input::kind(metadata.file_type())
            )));
        }
        if metadata.permissions().readonly() {
            return Err(refuse("it is read-only; make it writable, or write elsewhere with -o".into()));
        }
    }
    let dir = match path.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(dir) => {
            std::fs::create_dir_all(dir).map_err(|e| Error::file("cannot create the folder for", path, e))?;
            dir
        }
        None => Path::new("."),
    };
    tempfile::Builder::new().prefix(".probe.").tempfile_in(dir).map(drop).map_err(|e| {
        Error::file("cannot write image", path, format!("its folder '{}' takes no new file: {e}", dir.display()))
    })
}

/// Writes a file through `write`, which is given a temporary file in the folder of `path` (made if needed):
/// a new file with a random name, created exclusively, so that it is never a file that exists already nor a
/// link planted at a name someone could guess. It is renamed over `path` only when it is complete, so a
/// failure never destroys an earlier file (the temporary file is removed).
pub fn save_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<NamedTempFile>) -> image::ImageResult<()>,
) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::file("cannot write image", path, e);
    let dir = match path.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(dir) => {
            std::fs::create_dir_all(dir).map_err(|e| Error::file("cannot create the folder for", path, e))?;
            dir
        }
        None => Path::new("."),
    };
    let name = path.file_name().map(|n| n.to_string_lossy()).unwrap_or_default();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // Readable as any new file is (0o666 less the umask), not only by its owner as temporary files are.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let mut file = BufWriter::new(builder.tempfile_in(dir).map_err(|e| fail(&e))?);
    write(&mut file).map_err(|e| fail(&e))?;
    let file = file.into_inner().map_err(|e| fail(e.error()))?;
    file.persist(path).map_err(|e| fail(&e.error))?;
    Ok(())
}
