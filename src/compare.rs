//! Image differences: the numbers `--compare` prints, the regression tests' pass/fail rule, and a heat map
//! that shows where two pictures differ.
//!
//! All metrics compare the 8-bit sRGB pictures a person looks at, except `rmse_linear`, which compares linear
//! light (the error-versus-time studies use it).

use crate::color::srgb8_to_linear_table;
use crate::error::{Error, Result};
use std::path::Path;

/// How two images of the same size differ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Difference {
    /// Root-mean-square difference of the linear values, over all channels.
    pub rmse_linear: f64,
    /// Root-mean-square difference of the 8-bit codes, in levels (0..255).
    pub rmse_8bit: f64,
    /// Peak signal-to-noise ratio of the 8-bit codes in dB (infinite for equal images).
    pub psnr: f64,
    /// The largest difference of any channel of any pixel, in 8-bit levels.
    pub max_diff: u8,
    /// How many pixels differ by more than [`Difference::LARGE`] levels in some channel.
    pub large_pixels: usize,
    pub pixels: usize,
}

impl Difference {
    /// A difference larger than this many 8-bit levels counts as a visible change of the pixel.
    pub const LARGE: u8 = 8;

    /// The regression rule: at most `max_large_pixels` visibly changed pixels and an RMSE of at most
    /// `max_rmse_8bit` levels.
    pub fn within(&self, max_large_pixels: usize, max_rmse_8bit: f64) -> bool {
        self.large_pixels <= max_large_pixels && self.rmse_8bit <= max_rmse_8bit
    }
}

impl std::fmt::Display for Difference {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(
            f,
            "RMSE {:.3} levels (linear {:.5}), PSNR {:.2} dB, max diff {} levels, {} of {} pixels differ by more than {} levels",
            self.rmse_8bit,
            self.rmse_linear,
            self.psnr,
            self.max_diff,
            self.large_pixels,
            self.pixels,
            Difference::LARGE
        )
    }
}

fn check_sizes(a: &image::RgbImage, b: &image::RgbImage) -> Result<()> {
    if a.dimensions() != b.dimensions() {
        return Err(Error::parameter(
            "image size",
            format!("{}x{}", a.width(), a.height()),
            format!("the reference is {}x{}", b.width(), b.height()),
        ));
    }
    Ok(())
}

/// Compares two 8-bit sRGB images of the same size.
pub fn difference(a: &image::RgbImage, b: &image::RgbImage) -> Result<Difference> {
    check_sizes(a, b)?;
    let table = srgb8_to_linear_table();
    let (mut sq8, mut sq_lin, mut max_diff, mut large) = (0f64, 0f64, 0u8, 0usize);
    for (p, q) in a.pixels().zip(b.pixels()) {
        let mut pixel_max = 0;
        for c in 0..3 {
            let d = p[c].abs_diff(q[c]);
            pixel_max = pixel_max.max(d);
            sq8 += (d as f64).powi(2);
            sq_lin += ((table[p[c] as usize] - table[q[c] as usize]) as f64).powi(2);
        }
        max_diff = max_diff.max(pixel_max);
        large += (pixel_max > Difference::LARGE) as usize;
    }
    let n = (a.width() as usize * a.height() as usize).max(1);
    let rmse_8bit = (sq8 / (3 * n) as f64).sqrt();
    Ok(Difference {
        rmse_linear: (sq_lin / (3 * n) as f64).sqrt(),
        rmse_8bit,
        psnr: 20.0 * (255.0 / rmse_8bit).log10(),
        max_diff,
        large_pixels: large,
        pixels: n,
    })
}

/// A heat map of the difference: black where the images agree, through red and yellow to white where a
/// channel differs by 64 levels or more.
pub fn heat_map(a: &image::RgbImage, b: &image::RgbImage) -> Result<image::RgbImage> {
    check_sizes(a, b)?;
    Ok(image::RgbImage::from_fn(a.width(), a.height(), |x, y| {
        let (p, q) = (a.get_pixel(x, y), b.get_pixel(x, y));
        let d = (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0);
        let t = (d as f32 / 64.0).min(1.0);
        let ramp = |lo: f32| ((t - lo) * 3.0).clamp(0.0, 1.0);
        image::Rgb([ramp(0.0), ramp(1.0 / 3.0), ramp(2.0 / 3.0)].map(|v| (v * 255.0).round() as u8))
    }))
}

/// Loads an image to compare against, as 8-bit sRGB.
pub fn load_reference(path: &Path) -> Result<image::RgbImage> {
    image::open(path).map(|img| img.to_rgb8()).map_err(|e| Error::file("cannot read reference image", path, e))
}
