//! The colour of a wavelength (slide "Симулиране на хроматично пречупване": every frame is multiplied by the
//! colour of its wavelength before the frames are added): how light of one band of the spectrum shows in an
//! sRGB picture, computed as colorimetry does it.
//!
//! 1. The light's spectrum. Scenes give their lights and environments in RGB; in a dispersive scene a white
//!    (1, 1, 1) stands for the spectrum of an [`Illuminant`]: CIE D65, sRGB's own white (the default), or
//!    equal energy, the same power at every wavelength.
//! 2. Colour matching. The CIE 1931 2° standard observer's x̄, ȳ, z̄ (the tables of [`super::cie`], 5 nm
//!    apart, interpolated linearly) turn spectral power into XYZ: a band's XYZ is the integral of the
//!    illuminant times x̄, ȳ, z̄ over the band.
//! 3. Luminance normalisation. Every band's XYZ is divided by the Y of the whole traced range
//!    ([`LAMBDA_MIN`]..[`LAMBDA_MAX`]), so the light has luminance 1 and the bands' luminances add up to it.
//!    Nothing is balanced per channel.
//! 4. XYZ to linear sRGB, by the matrix of the sRGB primaries and white point (IEC 61966-2-1), derived as the
//!    standard derives it (SMPTE RP 177: the primaries scaled so that they add up to the white), with the white
//!    point that the D65 table gives over the traced range: D65 light comes out exactly (1, 1, 1). The
//!    range cut to 400-700 nm moves that white point by (-0.00002, +0.00046) in (x, y) from the one of the
//!    whole table (380-780 nm), and the matrix differs from the standard's published digits by 0.13-0.35%
//!    per row. Equal-energy light comes out (1.20, 0.95, 0.91): a flat spectrum is a little pink in sRGB.
//! 5. Gamut. The colour of a narrow band lies outside the sRGB gamut: some channel is negative (green
//!    light has negative red). The renderer keeps those values in its frame (an `.exr` holds them, for
//!    whoever measures); the picture that is shown maps them back as [`GamutMapping`] says.
//!
//! The traced range holds nearly all of the light: outside 400-700 nm lie 0.19% of D65's X, 0.04% of its Y
//! and 0.30% of its Z (0.26%, 0.06% and 0.49% of an equal-energy spectrum's; checked in
//! `tests/workbook/dispersion.rs`).

use super::cie;
use crate::lesson::color::Color;
use glam::{DMat3, DVec3, Vec3A};
use std::sync::OnceLock;

/// The shortest wavelength traced, in nanometres.
pub const LAMBDA_MIN: f32 = 400.0;
/// The longest wavelength traced, in nanometres.
pub const LAMBDA_MAX: f32 = 700.0;

/// The spectrum a white light of the scene stands for, when wavelengths are traced (`--illuminant`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Illuminant {
    /// CIE standard illuminant D65, average daylight: the white of sRGB, so a white light stays white.
    #[default]
    D65,
    /// The same power at every wavelength (CIE illuminant E): in sRGB a little pink, (1.20, 0.95, 0.91).
    EqualEnergy,
}

impl Illuminant {
    /// The relative spectral power at `lambda` nanometres (100 at 560 nm; D65's table interpolated linearly);
    /// 0 outside the tables.
    pub fn power(self, lambda: f64) -> f64 {
        match self {
            Illuminant::D65 => segment(lambda).map_or(0.0, |(i, f)| cie::D65[i] + f * (cie::D65[i + 1] - cie::D65[i])),
            Illuminant::EqualEnergy if segment(lambda).is_some() => 100.0,
            Illuminant::EqualEnergy => 0.0,
        }
    }

    /// The light's colour in linear sRGB, luminance 1: the sum of the colours of all its bands. Exactly
    /// (1, 1, 1) for D65.
    pub fn white(self) -> [f64; 3] {
        *cumulative_rgb(self).last().expect("the table is not empty")
    }
}

/// Where `lambda` falls in the CIE tables: the row before it and the fraction of the way to the next.
fn segment(lambda: f64) -> Option<(usize, f64)> {
    let rows = cie::OBSERVER_1931.len();
    let x = (lambda - cie::START) / cie::STEP;
    (0.0..=(rows - 1) as f64).contains(&x).then(|| {
        let i = (x as usize).min(rows - 2);
        (i, x - i as f64)
    })
}

/// The CIE 1931 2° colour-matching functions x̄, ȳ, z̄ at `lambda` nanometres: the 5 nm tables interpolated
/// linearly; 0 outside 380-780 nm.
pub fn cie_xyz(lambda: f64) -> [f64; 3] {
    segment(lambda).map_or([0.0; 3], |(i, f)| {
        let (a, b) = (cie::OBSERVER_1931[i], cie::OBSERVER_1931[i + 1]);
        std::array::from_fn(|c| a[c] + f * (b[c] - a[c]))
    })
}

/// The chromaticities (x, y) of the sRGB primaries, red, green and blue (IEC 61966-2-1, ITU-R BT.709).
const SRGB_PRIMARIES: [[f64; 2]; 3] = [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]];

/// The matrix from XYZ to linear sRGB: the primaries' XYZ as columns, each scaled so that together they make
/// the white that D65 integrates to over the traced range (SMPTE RP 177), inverted.
fn xyz_to_srgb_matrix() -> &'static DMat3 {
    static MATRIX: OnceLock<DMat3> = OnceLock::new();
    MATRIX.get_or_init(|| {
        let [x, y, z] = *cumulative_xyz(Illuminant::D65).last().expect("the table is not empty");
        let white = DVec3::new(x, y, z) / y;
        let column = |[x, y]: [f64; 2]| DVec3::new(x / y, 1.0, (1.0 - x - y) / y);
        let [red, green, blue] = SRGB_PRIMARIES.map(column);
        let primaries = DMat3::from_cols(red, green, blue);
        let scale = primaries.inverse() * white;
        (primaries * DMat3::from_diagonal(scale)).inverse()
    })
}

/// CIE XYZ to linear sRGB (see the module documentation for the matrix).
pub fn xyz_to_linear_srgb(xyz: [f64; 3]) -> [f64; 3] {
    (*xyz_to_srgb_matrix() * DVec3::from_array(xyz)).to_array()
}

/// Integration steps per nanometre of the cumulative tables: the tables' 5 nm rows fall on steps, so that
/// Simpson's rule is exact on every step (the product of two linear pieces is a parabola).
const STEPS_PER_NM: usize = 4;

/// The illuminant times the colour-matching functions, integrated from [`LAMBDA_MIN`] to every step of the
/// traced range, over the luminance of the whole range (so that the last entry has Y = 1).
fn cumulative_xyz(illuminant: Illuminant) -> Vec<[f64; 3]> {
    let steps = (LAMBDA_MAX - LAMBDA_MIN) as usize * STEPS_PER_NM;
    let h = 1.0 / STEPS_PER_NM as f64;
    let f = |l: f64| cie_xyz(l).map(|v| v * illuminant.power(l));
    let mut table = Vec::with_capacity(steps + 1);
    let mut sum = [0.0f64; 3];
    table.push(sum);
    for i in 0..steps {
        let l0 = LAMBDA_MIN as f64 + i as f64 * h;
        let (a, m, b) = (f(l0), f(l0 + 0.5 * h), f(l0 + h));
        for c in 0..3 {
            sum[c] += h / 6.0 * (a[c] + 4.0 * m[c] + b[c]);
        }
        table.push(sum);
    }
    let luminance = sum[1];
    table.iter().map(|xyz| xyz.map(|v| v / luminance)).collect()
}

/// [`cumulative_xyz`] in linear sRGB, built once per illuminant.
fn cumulative_rgb(illuminant: Illuminant) -> &'static [[f64; 3]] {
    static TABLES: [OnceLock<Vec<[f64; 3]>>; 2] = [OnceLock::new(), OnceLock::new()];
    TABLES[illuminant as usize].get_or_init(|| cumulative_xyz(illuminant).into_iter().map(xyz_to_linear_srgb).collect())
}

/// The colour of the light from [`LAMBDA_MIN`] to `lambda` (clamped to the traced range).
fn cumulative_at(illuminant: Illuminant, lambda: f64) -> [f64; 3] {
    let table = cumulative_rgb(illuminant);
    let x = ((lambda - LAMBDA_MIN as f64) * STEPS_PER_NM as f64).clamp(0.0, (table.len() - 1) as f64);
    let i = (x as usize).min(table.len() - 2);
    let f = x - i as f64;
    std::array::from_fn(|c| table[i][c] + f * (table[i + 1][c] - table[i][c]))
}

/// A band of wavelengths: the part of the spectrum one pass (or one sample) stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// Shortest wavelength of the band, in nanometres.
    pub lo: f32,
    /// Longest wavelength of the band, in nanometres.
    pub hi: f32,
    /// The band's colour in linear sRGB: the colour of the light's power within the band, as a part of the
    /// light whose luminance is 1. Channels may be negative (outside the gamut).
    pub weight: [f64; 3],
}

impl Band {
    /// The band from `lo` to `hi` nanometres of a light of the given spectrum.
    pub fn between(lo: f64, hi: f64, illuminant: Illuminant) -> Band {
        let (a, b) = (cumulative_at(illuminant, lo), cumulative_at(illuminant, hi));
        Band { lo: lo as f32, hi: hi as f32, weight: std::array::from_fn(|c| b[c] - a[c]) }
    }

    /// Band `i` of `n` equal bands across the traced range.
    pub fn nth(i: u32, n: u32, illuminant: Illuminant) -> Band {
        let width = (LAMBDA_MAX - LAMBDA_MIN) as f64 / n as f64;
        let lo = LAMBDA_MIN as f64 + i as f64 * width;
        // The last band ends exactly at the end of the range, so the weights add up to the whole.
        let hi = if i + 1 == n { LAMBDA_MAX as f64 } else { lo + width };
        Band::between(lo, hi, illuminant)
    }

    /// The wavelength a pass traces for this band: its centre.
    pub fn centre(&self) -> f32 {
        0.5 * (self.lo + self.hi)
    }

    /// A wavelength at fraction `u` in [0, 1) across the band (spectral sampling jitters within the band).
    pub fn at(&self, u: f32) -> f32 {
        self.lo + u * (self.hi - self.lo)
    }

    /// The band's colour as a (possibly out-of-gamut) `Color`.
    pub fn color(&self) -> Color {
        Color::new(self.weight[0] as f32, self.weight[1] as f32, self.weight[2] as f32)
    }
}

/// The `n` equal bands across the traced range; their weights add up to the light's [`Illuminant::white`]
/// up to f64 rounding.
pub fn bands(n: u32, illuminant: Illuminant) -> Vec<Band> {
    (0..n).map(|i| Band::nth(i, n, illuminant)).collect()
}

/// How the picture shows a colour outside the sRGB gamut (`--gamut`): the colours of narrow bands of the
/// spectrum have negative channels, and so may a pixel that adds up a few of them (the edge of a rainbow).
/// The renderer's frame keeps them (an `.exr` file holds them); the picture that is shown (a PNG, the
/// viewer) maps them, the same way whatever traced the wavelengths.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum GamutMapping {
    /// Negative channels become 0, the others stay: the usual choice for spectral colours, which keeps the
    /// rainbow saturated (and makes it a little lighter than the light it shows).
    #[default]
    Clip,
    /// Grey of the same luminance is mixed in until no channel is negative: keeps luminance and hue,
    /// desaturates the rainbow.
    Fit,
}

impl GamutMapping {
    /// The colour as the picture shows it.
    pub fn apply(self, c: Color) -> Color {
        match self {
            GamutMapping::Clip => clip_to_gamut(c),
            GamutMapping::Fit => fit_to_gamut(c),
        }
    }
}

/// A colour with its negative channels set to 0.
pub fn clip_to_gamut(c: Color) -> Color {
    Color(c.0.max(Vec3A::ZERO))
}

/// Brings a colour with negative channels (a spectral colour outside the sRGB gamut) back into it by mixing
/// in grey of the same luminance, just enough to lift the lowest channel to zero; keeps its luminance and
/// hue. Colours inside the gamut are returned unchanged; a colour of non-positive luminance becomes black.
pub fn fit_to_gamut(c: Color) -> Color {
    let low = c.0.min_element();
    if low >= 0.0 {
        return c;
    }
    let y = c.luminance();
    if y <= 0.0 {
        return Color::BLACK;
    }
    // c' = y + s (c - y) with s chosen so that the lowest channel is zero.
    let s = y / (y - low);
    (Color::gray(y) + (c - Color::gray(y)) * s).sanitized()
}
