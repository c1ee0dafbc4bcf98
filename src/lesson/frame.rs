//! The picture a render makes: a frame of linear colours, and how it is written to a file (8-bit sRGB for
//! PNG, linear floats for EXR and HDR). The renderer ([`crate::lesson::render`]) fills it.

use crate::files::output::{output_format, save_atomically};
use crate::lesson::color::{Color, to_srgb8};
use crate::lesson::error::Result;
use rayon::prelude::*;
use std::path::Path;

/// The most anti-aliasing samples per pixel the renderer accepts: far beyond what a picture needs (the
/// examples use 1 to 16; a reference for an error study a few thousand), low enough that a mistyped count
/// is refused at once instead of rendering for days.
pub const MAX_SPP: u32 = 1 << 16;

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
    /// destroys an earlier picture (see [`crate::files::output::save_atomically`]).
    pub fn save(&self, path: &Path) -> Result<()> {
        let format = output_format(path)?;
        save_atomically(path, |file| match format {
            image::ImageFormat::Png => self.to_rgb8().write_to(file, format),
            _ => self.to_rgb32f().write_to(file, format),
        })
    }
}
