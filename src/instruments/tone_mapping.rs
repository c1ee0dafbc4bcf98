//! Exposure and tone mapping: how the linear light of a render becomes the picture that is written.
//!
//! The course has no such step: it clamps every channel to [0, 1] and writes it as it is. That is right
//! for scenes lit by point lights of moderate power, but an HDR environment holds radiances far above 1 (a
//! sky at 2-5, a sun at 50), which then all come out white. Two controls deal with that (a deviation from
//! the course, shared by every example):
//! - [`Film::exposure`] (`--exposure EV`): the picture is multiplied by 2^EV before it is written, as a
//!   camera's exposure would (-1 halves the light, +1 doubles it). It applies to every output, PNG and EXR.
//! - [`ToneMap`] (`--tonemap`): how light above 1 fits an 8-bit PNG. `clamp` is the course's; `reinhard`
//!   compresses highlights smoothly (Reinhard et al. 2002, on the luminance, so hues stay). EXR and HDR
//!   output keep linear light: tone mapping is a choice of display, made when the picture is viewed.
//! - [`GamutMapping`] (`--gamut`): how a colour outside the sRGB gamut (a channel below 0, which only the
//!   colours of narrow bands of the spectrum have; see [`crate::lesson::spectral`]) is shown: its negative
//!   channels clipped, or grey mixed in. It is a choice of display too: EXR output keeps the negative values,
//!   for whoever measures (HDR's RGBE format cannot hold them and writes 0).
//! - [`Encoding`] (`--encoding`): the codes an 8-bit picture is written with: sRGB's, or the course's raw
//!   linear values (see [`crate::files::encoding`]; the same option reads the scene's 8-bit files so).
//!
//! Fireflies (single bright pixels when a glossy surface reflects a small, very bright sun) are a matter of
//! the samples, not of the picture: see [`crate::lesson::render::RenderSettings::max_sample`] (`--clamp-sample`).

use crate::files::encoding::Encoding;
use crate::lesson::color::{Color, srgb_to_linear};
use crate::lesson::error::{Error, Result};
use crate::lesson::frame::Frame;
use crate::lesson::spectral::GamutMapping;
use rayon::prelude::*;

/// How linear light above 1 is fitted into an 8-bit picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ToneMap {
    /// Every channel clamped to 1, as the course does: exact below 1, white above.
    #[default]
    Clamp,
    /// The luminance L becomes L / (1 + L), the colour scaled with it: nothing reaches white, bright skies
    /// keep their clouds; everything is darker, so pair it with a positive `--exposure`.
    Reinhard,
}

/// The largest exposure, in stops, either way: 2^20 is a millionfold.
pub const MAX_EXPOSURE: f32 = 20.0;

/// What happens to a render's linear light before it is written.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Film {
    /// Stops: the picture is multiplied by 2^exposure.
    pub exposure: f32,
    /// How light above 1 fits an 8-bit picture.
    pub tone_map: ToneMap,
    /// How colours outside the sRGB gamut are shown.
    pub gamut: GamutMapping,
    /// The codes of an 8-bit picture: sRGB's, or the course's raw linear values.
    pub encoding: Encoding,
}

impl Film {
    /// Rejects exposures that are not finite or would turn every picture black or white.
    pub fn check(&self) -> Result<()> {
        if !(self.exposure.is_finite() && self.exposure.abs() <= MAX_EXPOSURE) {
            return Err(Error::parameter(
                "--exposure",
                self.exposure,
                format!("must be a number of stops from -{MAX_EXPOSURE} to {MAX_EXPOSURE}"),
            ));
        }
        Ok(())
    }

    /// True when the film leaves every picture as it is written (the course's picture: the 8-bit encoding
    /// clamps every channel to [0, 1], which clips negative channels too).
    pub fn is_neutral(&self) -> bool {
        self.exposure == 0.0
            && self.tone_map == ToneMap::Clamp
            && self.gamut == GamutMapping::Clip
            && self.encoding == Encoding::Srgb
    }

    /// The picture to write: exposed, and gamut and tone mapped unless `linear_output` (an EXR or HDR file,
    /// which keeps light above 1 and outside the gamut for whoever views it). The pixels are changed in
    /// place, in parallel (on the current rayon pool); a neutral film returns the frame as it is.
    pub fn develop(&self, mut frame: Frame, linear_output: bool) -> Frame {
        if !self.is_neutral() {
            frame.pixels.par_iter_mut().for_each(|c| *c = self.developed(*c, linear_output));
        }
        frame
    }

    /// One pixel of [`Film::develop`]'s picture (the live viewer develops its tiles as they come). With
    /// [`Encoding::Raw`], an 8-bit picture's pixel is the light whose sRGB codes are the course's raw ones
    /// (its value, clamped, times 255): the sRGB writer then writes the course's codes.
    pub fn developed(&self, c: Color, linear_output: bool) -> Color {
        let c = c * self.exposure.exp2();
        if linear_output {
            return c;
        }
        let c = tone_mapped(self.gamut.apply(c), self.tone_map);
        match self.encoding {
            Encoding::Srgb => c,
            Encoding::Raw => {
                let raw = |v: f32| srgb_to_linear(if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) });
                Color::new(raw(c.r()), raw(c.g()), raw(c.b()))
            }
        }
    }
}

/// `c` with its highlights fitted as `tone_map` says (clamping itself is left to the 8-bit encoding).
fn tone_mapped(c: Color, tone_map: ToneMap) -> Color {
    match tone_map {
        ToneMap::Clamp => c,
        ToneMap::Reinhard => {
            let luminance = c.luminance();
            if luminance > 0.0 { c * (1.0 / (1.0 + luminance)) } else { c }
        }
    }
}
