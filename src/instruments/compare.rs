//! Image differences: the numbers `--compare` prints, the regression tests' pass/fail rule, and a heat map
//! that shows where two pictures differ.
//!
//! A reference is compared in the form it was saved in: an 8-bit picture (PNG, JPEG, BMP) in 8-bit sRGB, the
//! codes a person looks at; a floating-point one (EXR, HDR, which hold the linear frame) in linear light,
//! and, for the pass/fail rule and the heat map, as the 8-bit sRGB picture it would have been written as.

use crate::instruments::side_by_side::{Panel, compose};
use crate::lesson::color::srgb8_to_linear_table;
use crate::lesson::error::{Error, Result};
use crate::lesson::frame::Frame;
use crate::lesson::image_file::{ImageFile, PixelCharge};
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
    /// How many pixels were compared.
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

    /// The rule the workbook's regression tests apply to every example's picture: at most one pixel in
    /// [`REGRESSION_PIXELS_PER_LARGE`] may differ by more than [`Difference::LARGE`] levels in a channel, and
    /// the RMSE over all channels may be at most [`REGRESSION_MAX_RMSE`] level. A one-pixel-wide change along
    /// an object's silhouette moves hundreds of pixels by far more than 8 levels and fails; the last-bit
    /// differences of `sin`/`pow` between x86-64 C libraries do not.
    pub fn within_regression_tolerance(&self) -> bool {
        self.within(self.pixels / REGRESSION_PIXELS_PER_LARGE, REGRESSION_MAX_RMSE)
    }

    /// One sentence saying whether the difference is within the regression tolerance.
    pub fn verdict(&self) -> String {
        let rule = format!(
            "at most {} pixels over {} levels and an RMSE of at most {} level",
            self.pixels / REGRESSION_PIXELS_PER_LARGE,
            Difference::LARGE,
            REGRESSION_MAX_RMSE
        );
        if self.within_regression_tolerance() {
            format!("within the regression tests' tolerance ({rule})")
        } else {
            format!("NOT within the regression tests' tolerance ({rule})")
        }
    }
}

/// See [`Difference::within_regression_tolerance`].
pub const REGRESSION_PIXELS_PER_LARGE: usize = 5000;
/// See [`Difference::within_regression_tolerance`].
pub const REGRESSION_MAX_RMSE: f64 = 1.0;

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
/// channel differs by `full_scale` levels or more.
pub fn heat_map_scaled(a: &image::RgbImage, b: &image::RgbImage, full_scale: u8) -> Result<image::RgbImage> {
    check_sizes(a, b)?;
    Ok(image::RgbImage::from_fn(a.width(), a.height(), |x, y| {
        let (p, q) = (a.get_pixel(x, y), b.get_pixel(x, y));
        let d = (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0);
        heat_colour(d as f32 / full_scale.max(1) as f32)
    }))
}

/// A heat map of the difference whose scale adapts to it: white is the largest difference found (at least
/// one level), so that a difference of a few levels shows as clearly as one of a hundred.
pub fn heat_map(a: &image::RgbImage, b: &image::RgbImage) -> Result<image::RgbImage> {
    let largest = difference(a, b)?.max_diff;
    heat_map_scaled(a, b, largest)
}

/// The heat map's colour at `t` of its full scale: black, red, yellow, white.
fn heat_colour(t: f32) -> image::Rgb<u8> {
    let t = t.clamp(0.0, 1.0);
    let ramp = |lo: f32| ((t - lo) * 3.0).clamp(0.0, 1.0);
    image::Rgb([ramp(0.0), ramp(1.0 / 3.0), ramp(2.0 / 3.0)].map(|v| (v * 255.0).round() as u8))
}

/// Height of the colour bar under a heat map, in pixels.
pub const COLOUR_BAR_HEIGHT: u32 = 12;

/// The heat map with its colour bar below it: the ramp from 0 to `full_scale` levels, captioned with its
/// scale ([`heat_map_scale`]), so that the picture says what its colours mean.
pub fn with_colour_bar(heat: &image::RgbImage, full_scale: u8) -> Result<image::RgbImage> {
    let caption = format!("difference: {}", heat_map_scale(full_scale));
    compose(&[Panel { image: colour_bar_under(heat), caption }])
}

/// The heat map with the ramp of its colours, from black on the left to white on the right, in a bar below.
pub fn colour_bar_under(heat: &image::RgbImage) -> image::RgbImage {
    ramp_bar_under(heat, |t| heat_colour(t).0)
}

/// `picture` with a colour bar [`COLOUR_BAR_HEIGHT`] pixels high below it, as wide as it: column `x` of the
/// bar shows `ramp((x + 0.5) / width)`, the ramp from 0 on the left to 1 on the right. Every heat map's bar
/// (the differences', the debug views') is drawn here.
pub fn ramp_bar_under(picture: &image::RgbImage, ramp: impl Fn(f32) -> [u8; 3]) -> image::RgbImage {
    let width = picture.width();
    let bar = image::RgbImage::from_fn(width, COLOUR_BAR_HEIGHT, |x, _| {
        image::Rgb(ramp((x as f32 + 0.5) / width.max(1) as f32))
    });
    let mut out = image::RgbImage::new(width, picture.height() + COLOUR_BAR_HEIGHT);
    image::imageops::replace(&mut out, picture, 0, 0);
    image::imageops::replace(&mut out, &bar, 0, picture.height() as i64);
    out
}

/// The one convention of every difference heat map (`--compare`'s and `--side-by-side`'s), in words: black
/// where the pictures agree, white at the largest difference found, `full_scale` levels.
pub fn heat_map_scale(full_scale: u8) -> String {
    format!("black 0 .. white {} levels, the largest difference (in any channel)", full_scale.max(1))
}

/// A picture a render is compared with.
#[derive(Clone, Debug)]
pub enum Reference {
    /// An 8-bit picture (PNG, JPEG, BMP): compared in 8-bit sRGB codes.
    Srgb8(image::RgbImage),
    /// A floating-point picture (EXR, HDR) holding a linear frame: compared in linear light.
    Linear(Frame),
}

impl Reference {
    /// Reads a reference picture: `.exr` and `.hdr` as linear floats, anything else as 8-bit sRGB.
    pub fn load(path: &Path) -> Result<Reference> {
        Ok(Reference::decode(ImageFile::open(path)?, path)?.0)
    }

    /// Decodes the reference picture at `path`, whose header has been read (see [`Reference::load`]): the
    /// reference and its share of the pixel budget, to be held as long as the reference is.
    pub fn decode(file: ImageFile, path: &Path) -> Result<(Reference, PixelCharge)> {
        let (image, charge) = file.decode(f32::MAX)?;
        let reference = if crate::files::output::keeps_linear_light(path) {
            let img = image.into_rgb32f();
            let pixels = img.pixels().map(|p| crate::lesson::color::Color::new(p[0], p[1], p[2])).collect();
            Reference::Linear(Frame { width: img.width(), height: img.height(), pixels })
        } else {
            Reference::Srgb8(image.into_rgb8())
        };
        Ok((reference, charge))
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        match self {
            Reference::Srgb8(img) => img.dimensions(),
            Reference::Linear(frame) => (frame.width, frame.height),
        }
    }

    /// The reference as the 8-bit sRGB picture a person looks at.
    pub fn to_rgb8(&self) -> image::RgbImage {
        match self {
            Reference::Srgb8(img) => img.clone(),
            Reference::Linear(frame) => frame.to_rgb8(),
        }
    }

    /// Fails, naming the reference file, unless a picture of `width` x `height` can be compared with it.
    pub fn check_size(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        check_reference_size(path, self.size(), width, height)
    }
}

/// Fails, naming the reference file at `path` whose picture is `size`, unless a picture of `width` x
/// `height` can be compared with it (checked from the header, before the reference is decoded).
pub fn check_reference_size(path: &Path, (w, h): (u32, u32), width: u32, height: u32) -> Result<()> {
    if (w, h) != (width, height) {
        return Err(Error::file(
            "cannot compare with",
            path,
            format!("it is {w}x{h} and the render would be {width}x{height} (set --width {w} --height {h})"),
        ));
    }
    Ok(())
}

/// How a linear frame differs from a linear reference, in linear light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearDifference {
    /// Root-mean-square difference over all channels.
    pub rmse: f64,
    /// The largest difference of any channel of any pixel.
    pub max_diff: f64,
    /// The reference's mean over all channels: the scale the two numbers above are measured against.
    pub reference_mean: f64,
}

impl std::fmt::Display for LinearDifference {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(
            f,
            "in linear light: RMSE {:.3e}, max diff {:.3e} (the reference's mean is {:.4})",
            self.rmse, self.max_diff, self.reference_mean
        )
    }
}

/// What `--compare` finds: the 8-bit difference (with the regression verdict and the heat map's scale), and
/// for a linear reference the difference in linear light too.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The difference of the two pictures as 8-bit sRGB.
    pub difference: Difference,
    /// The difference in linear light, when the reference keeps it (an `.exr` or `.hdr` file); `None` for an
    /// 8-bit reference.
    pub linear: Option<LinearDifference>,
    /// The heat map, white at the largest difference.
    pub heat_map: image::RgbImage,
}

impl std::fmt::Display for Comparison {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        if let Some(linear) = &self.linear {
            write!(f, "{linear}; as 8-bit sRGB: ")?;
        }
        write!(f, "{}; {}", self.difference, self.difference.verdict())
    }
}

/// Compares a rendered frame with a reference, each in the reference's own form.
pub fn compare(frame: &Frame, reference: &Reference) -> Result<Comparison> {
    let (actual, expected) = (frame.to_rgb8(), reference.to_rgb8());
    let difference = difference(&actual, &expected)?;
    let heat_map = with_colour_bar(&heat_map_scaled(&actual, &expected, difference.max_diff)?, difference.max_diff)?;
    let linear = match reference {
        Reference::Srgb8(_) => None,
        Reference::Linear(expected) => Some(linear_difference(frame, expected)),
    };
    Ok(Comparison { difference, linear, heat_map })
}

/// The difference of two linear frames of the same size (see [`compare`], which checks the sizes).
fn linear_difference(a: &Frame, b: &Frame) -> LinearDifference {
    let (mut sq, mut max_diff, mut sum) = (0f64, 0f64, 0f64);
    for (p, q) in a.pixels.iter().zip(&b.pixels) {
        for (x, y) in p.to_array().into_iter().zip(q.to_array()) {
            let d = (x as f64 - y as f64).abs();
            sq += d * d;
            max_diff = max_diff.max(d);
            sum += y as f64;
        }
    }
    let n = (3 * b.pixels.len()).max(1) as f64;
    LinearDifference { rmse: (sq / n).sqrt(), max_diff, reference_mean: sum / n }
}

/// Loads any reference as the 8-bit sRGB picture it shows (a linear one encoded as the renderer writes
/// its frames).
pub fn load_reference(path: &Path) -> Result<image::RgbImage> {
    Reference::load(path).map(|r| r.to_rgb8())
}
