//! Chromatic dispersion (slides "Хроматично пречупване (дисперсия)", "Симулиране на хроматично пречупване"):
//! the index of refraction depends on the wavelength, so white light splits into colours.
//!
//! What this module provides:
//! - [`Ior`]: an index of refraction that may depend on the wavelength: a constant, the slide's Abbe-number
//!   description (a Cauchy fit `n(λ) = A + B / λ²` through n_d at the helium d line, 587.6 nm, with
//!   `n_F - n_C = (n_d - 1) / V_d` between the hydrogen F and C lines, 486.1 and 656.3 nm), or a real glass
//!   by its Sellmeier coefficients ([`Ior::N_BK7`], [`Ior::SF11`]).
//! - The colour of a band of wavelengths: the CIE 1931 colour-matching functions (the multi-lobe analytic fit of
//!   Wyman, Sloan and Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
//!   JCGT 2013) converted to linear sRGB and integrated over the band. The visible range
//!   [`LAMBDA_MIN`]..[`LAMBDA_MAX`] is cut into equal bands whose colours are normalised so that, per
//!   channel, they sum to exactly 1: a white surface seen in every band stays exactly white.
//! - [`SpectralPlan`]: how the renderer spends its rays on wavelengths. The slide's method renders K frames,
//!   one per wavelength, and adds them, each multiplied by the colour of its wavelength ([`SpectralMode::Passes`]).
//!   Beyond the slide, [`SpectralMode::Sampled`] gives each anti-aliasing sample of a pixel its own band of the
//!   spectrum (a single pass, spectral sampling). A scene without dispersive materials gets one white pass.
//!
//! Deviations from the slide: each pass stands for a *band* of wavelengths (its colour is the integral of the
//! colour-matching functions over the band, traced at the band's centre) rather than one spectral line, so
//! that the K colours add up to white exactly for any K. Monochromatic colours lie outside the sRGB gamut
//! (their weights have negative channels); a pixel that ends up outside it is brought back by
//! [`fit_to_gamut`], which mixes in grey of the same luminance.

use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use std::sync::OnceLock;

/// The shortest wavelength traced, in nanometres. Outside [`LAMBDA_MIN`]..[`LAMBDA_MAX`] each colour-matching
/// function has less than 0.6% of its area (z̄ 0.51%, x̄ 0.11%, ȳ 0.06%; checked in `tests/dispersion.rs`).
pub const LAMBDA_MIN: f32 = 400.0;
/// The longest wavelength traced, in nanometres.
pub const LAMBDA_MAX: f32 = 700.0;
/// The helium d line (yellow), in nanometres: where a glass's n_d is measured.
pub const LAMBDA_D: f32 = 587.6;
/// The hydrogen F line (blue), in nanometres: with the C line, it gives the dispersion n_F - n_C.
pub const LAMBDA_F: f32 = 486.1;
/// The hydrogen C line (red), in nanometres.
pub const LAMBDA_C: f32 = 656.3;
/// The most wavelength passes a render may ask for (bands 0.3 nm wide).
pub const MAX_WAVELENGTHS: u32 = 1000;

/// An index of refraction, possibly depending on the wavelength.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Ior {
    /// The same index at every wavelength.
    Constant(f32),
    /// Cauchy's equation `n(λ) = a + b / λ²`, λ in micrometres.
    Cauchy {
        /// The index the curve tends to at long wavelengths.
        a: f32,
        /// How strongly the index rises towards the blue, in µm².
        b: f32,
    },
    /// Sellmeier's equation `n²(λ) = 1 + Σ b_i λ² / (λ² - c_i)`, λ in micrometres (c_i in µm²).
    Sellmeier {
        /// The strengths b_1, b_2, b_3 of the three terms (no unit).
        b: [f32; 3],
        /// The resonance wavelengths squared c_1, c_2, c_3, in µm².
        c: [f32; 3],
    },
}

impl Ior {
    // The Sellmeier coefficients below are Schott's catalogue digits, kept as published so they can be
    // checked against it (f32 rounds the last ones).
    /// Schott N-BK7, the common borosilicate crown glass (n_d = 1.5168, V_d = 64.17).
    #[allow(clippy::excessive_precision)]
    pub const N_BK7: Ior =
        Ior::Sellmeier { b: [1.03961212, 0.231792344, 1.01046945], c: [0.00600069867, 0.0200179144, 103.560653] };
    /// Schott SF11, a dense flint glass (n_d = 1.7847, V_d = 25.68): nearly four times the dispersion
    /// n_F - n_C of N-BK7.
    #[allow(clippy::excessive_precision)]
    pub const SF11: Ior =
        Ior::Sellmeier { b: [1.73759695, 0.313747346, 1.89878101], c: [0.013188707, 0.0623068142, 155.23629] };

    /// The slide's description of a glass: its index n_d at 587.6 nm and its Abbe number
    /// `V_d = (n_d - 1) / (n_F - n_C)`, fitted by Cauchy's equation. `v_d = f32::INFINITY` is a glass without
    /// dispersion. Fails for an index below 1 or an Abbe number that is not positive.
    pub fn abbe(n_d: f32, v_d: f32) -> Result<Ior> {
        if !(n_d.is_finite() && n_d >= 1.0) {
            return Err(Error::parameter("index of refraction n_d", n_d, "must be a finite number of at least 1"));
        }
        if v_d.is_nan() || v_d <= 0.0 {
            return Err(Error::parameter("Abbe number V_d", v_d, "must be positive (inf for no dispersion)"));
        }
        let inv_sq = |nm: f32| 1.0 / (nm * 1e-3).powi(2);
        let b = (n_d - 1.0) / v_d / (inv_sq(LAMBDA_F) - inv_sq(LAMBDA_C));
        Ok(Ior::Cauchy { a: n_d - b * inv_sq(LAMBDA_D), b })
    }

    /// The index at `wavelength` (nanometres); rays without a wavelength (white light) see n_d.
    pub fn at(&self, wavelength: Option<f32>) -> f32 {
        let um = wavelength.unwrap_or(LAMBDA_D) * 1e-3;
        match *self {
            Ior::Constant(n) => n,
            Ior::Cauchy { a, b } => a + b / (um * um),
            Ior::Sellmeier { b, c } => {
                let l2 = um * um;
                (1.0 + (0..3).map(|i| b[i] * l2 / (l2 - c[i])).sum::<f32>()).sqrt()
            }
        }
    }

    /// n_d, the index at the helium d line.
    pub fn n_d(&self) -> f32 {
        self.at(None)
    }

    /// The Abbe number `(n_d - 1) / (n_F - n_C)`: infinite without dispersion, about 64 for crown glass.
    pub fn abbe_number(&self) -> f32 {
        (self.n_d() - 1.0) / (self.at(Some(LAMBDA_F)) - self.at(Some(LAMBDA_C)))
    }

    /// Whether the index changes with the wavelength, so that the renderer must trace wavelengths.
    pub fn is_dispersive(&self) -> bool {
        match *self {
            Ior::Constant(_) => false,
            Ior::Cauchy { b, .. } => b != 0.0,
            Ior::Sellmeier { .. } => true,
        }
    }
}

impl From<f32> for Ior {
    fn from(n: f32) -> Ior {
        Ior::Constant(n)
    }
}

/// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with different widths left and right of its peak.
fn lobe(lambda: f64, height: f64, peak: f64, sigma_left: f64, sigma_right: f64) -> f64 {
    let t = (lambda - peak) / if lambda < peak { sigma_left } else { sigma_right };
    height * (-0.5 * t * t).exp()
}

/// The CIE 1931 2° colour-matching functions x̄, ȳ, z̄ at `lambda` nanometres (Wyman, Sloan and Shirley's
/// multi-lobe fit, within about 1% of the tabulated functions).
pub fn cie_xyz(lambda: f64) -> [f64; 3] {
    [
        lobe(lambda, 1.056, 599.8, 37.9, 31.0) + lobe(lambda, 0.362, 442.0, 16.0, 26.7)
            - lobe(lambda, 0.065, 501.1, 20.4, 26.2),
        lobe(lambda, 0.821, 568.8, 46.9, 40.5) + lobe(lambda, 0.286, 530.9, 16.3, 31.1),
        lobe(lambda, 1.217, 437.0, 11.8, 36.0) + lobe(lambda, 0.681, 459.0, 26.0, 13.8),
    ]
}

/// CIE XYZ to linear sRGB (D65 primaries; IEC 61966-2-1).
pub fn xyz_to_linear_srgb([x, y, z]: [f64; 3]) -> [f64; 3] {
    [
        3.240_454_2 * x - 1.537_138_5 * y - 0.498_531_4 * z,
        -0.969_266_0 * x + 1.876_010_8 * y + 0.041_556_0 * z,
        0.055_643_4 * x - 0.204_025_9 * y + 1.057_225_2 * z,
    ]
}

/// Steps per nanometre of the cumulative colour table.
const TABLE_STEPS_PER_NM: usize = 4;

/// The linear-sRGB colour-matching functions integrated from [`LAMBDA_MIN`] up to each table step,
/// normalised so that the whole range integrates to (1, 1, 1). Built once (Simpson's rule on each step).
fn cumulative_rgb() -> &'static [[f64; 3]] {
    static TABLE: OnceLock<Vec<[f64; 3]>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let steps = (LAMBDA_MAX - LAMBDA_MIN) as usize * TABLE_STEPS_PER_NM;
        let h = 1.0 / TABLE_STEPS_PER_NM as f64;
        let rgb = |l: f64| xyz_to_linear_srgb(cie_xyz(l));
        let mut table = Vec::with_capacity(steps + 1);
        let mut acc = [0.0f64; 3];
        table.push(acc);
        for i in 0..steps {
            let l0 = LAMBDA_MIN as f64 + i as f64 * h;
            let (a, m, b) = (rgb(l0), rgb(l0 + 0.5 * h), rgb(l0 + h));
            for c in 0..3 {
                acc[c] += h / 6.0 * (a[c] + 4.0 * m[c] + b[c]);
            }
            table.push(acc);
        }
        let total = acc;
        for entry in &mut table {
            for c in 0..3 {
                entry[c] /= total[c];
            }
        }
        table
    })
}

/// The normalised colour-matching integral from [`LAMBDA_MIN`] to `lambda` (clamped to the range).
fn cumulative_at(lambda: f64) -> [f64; 3] {
    let table = cumulative_rgb();
    let x = ((lambda - LAMBDA_MIN as f64) * TABLE_STEPS_PER_NM as f64).clamp(0.0, (table.len() - 1) as f64);
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
    /// The band's colour in linear sRGB: the integral of the colour-matching functions over the band, as a
    /// fraction of their integral over the visible range. Channels may be negative (outside the gamut).
    pub weight: [f64; 3],
}

impl Band {
    /// Band `i` of `n` equal bands across the visible range.
    pub fn nth(i: u32, n: u32) -> Band {
        let width = (LAMBDA_MAX - LAMBDA_MIN) as f64 / n as f64;
        let lo = LAMBDA_MIN as f64 + i as f64 * width;
        // The last band ends exactly at the end of the range, so the weights add up to the whole.
        let hi = if i + 1 == n { LAMBDA_MAX as f64 } else { lo + width };
        let (a, b) = (cumulative_at(lo), cumulative_at(hi));
        Band { lo: lo as f32, hi: hi as f32, weight: std::array::from_fn(|c| b[c] - a[c]) }
    }

    /// The wavelength a pass traces for this band: its centre.
    pub fn centre(&self) -> f32 {
        0.5 * (self.lo + self.hi)
    }

    /// A wavelength at fraction `u` in [0, 1) across the band (spectral sampling jitters within the band).
    pub fn at(&self, u: f32) -> f32 {
        self.lo + u * (self.hi - self.lo)
    }

    /// The band's colour as a (possibly out-of-gamut) `Color`, for display.
    pub fn color(&self) -> Color {
        Color::new(self.weight[0] as f32, self.weight[1] as f32, self.weight[2] as f32)
    }
}

/// The `n` equal bands across the visible range; their weights sum to (1, 1, 1) up to f64 rounding.
pub fn bands(n: u32) -> Vec<Band> {
    (0..n).map(|i| Band::nth(i, n)).collect()
}

/// How a dispersive scene spends its rays on wavelengths (`--spectral`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum SpectralMode {
    /// The slide's method: `--wavelengths` K full passes, one per band, added with the bands' colours.
    #[default]
    Passes,
    /// Spectral sampling: one pass in which every anti-aliasing sample of a pixel carries its own band of
    /// the spectrum (spp bands per pixel, wavelength jittered within the band).
    Sampled,
}

/// What the renderer does about wavelengths for one render.
#[derive(Clone, Debug, PartialEq)]
pub enum SpectralPlan {
    /// White light: one pass, rays carry no wavelength (nothing in the scene is dispersive).
    White,
    /// One pass per band, each traced at the band's centre.
    Passes(Vec<Band>),
    /// One pass; sample s of a pixel traces a wavelength in its own band out of spp.
    Sampled,
}

impl SpectralPlan {
    /// The plan for a scene: white light when nothing in it is dispersive, else what `mode` asks for.
    pub fn new(dispersive: bool, mode: SpectralMode, wavelengths: u32) -> SpectralPlan {
        match (dispersive, mode) {
            (false, _) => SpectralPlan::White,
            (true, SpectralMode::Passes) => SpectralPlan::Passes(bands(wavelengths)),
            (true, SpectralMode::Sampled) => SpectralPlan::Sampled,
        }
    }

    /// How many times the frame is traced.
    pub fn passes(&self) -> u32 {
        match self {
            SpectralPlan::Passes(bands) => bands.len() as u32,
            _ => 1,
        }
    }
}

impl std::fmt::Display for SpectralPlan {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            SpectralPlan::White => write!(f, "white light"),
            SpectralPlan::Passes(bands) if bands.len() == 1 => write!(f, "1 wavelength pass"),
            SpectralPlan::Passes(bands) => write!(f, "{} wavelength passes", bands.len()),
            SpectralPlan::Sampled => write!(f, "one wavelength per sample"),
        }
    }
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
