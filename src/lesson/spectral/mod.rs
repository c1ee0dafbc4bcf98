//! Chromatic dispersion (slides "Хроматично пречупване (дисперсия)", "Симулиране на хроматично пречупване"):
//! the index of refraction depends on the wavelength, so white light splits into colours.
//!
//! What this module provides:
//! - [`Ior`]: an index of refraction that may depend on the wavelength: a constant, the slide's Abbe-number
//!   description (a Cauchy fit `n(λ) = A + B / λ²` through n_d at the helium d line, 587.6 nm, with
//!   `n_F - n_C = (n_d - 1) / V_d` between the hydrogen F and C lines, 486.1 and 656.3 nm), or a real glass
//!   by its Sellmeier coefficients ([`Ior::N_BK7`], [`Ior::SF11`]).
//! - The colour of a band of wavelengths ([`Band`], in [`colour`]): the light's spectrum ([`Illuminant`]: D65 or
//!   equal energy) times the CIE 1931 colour-matching functions (the CIE's tables, [`cie`]), integrated over
//!   the band, normalised by the light's luminance and converted to linear sRGB. With D65, sRGB's white, the
//!   colours of the bands add up to exactly (1, 1, 1): a white surface seen in every band stays white.
//!   Colours outside the sRGB gamut are shown as [`GamutMapping`] says.
//! - [`SpectralPlan`]: how the renderer spends its rays on wavelengths ([`SpectralMode`], `--spectral`):
//!   - `passes`, the slide's method: K frames, one per wavelength, added, each multiplied by the colour of its
//!     wavelength;
//!   - `sampled` (spectral sampling): one pass in which each anti-aliasing sample of a pixel carries its own
//!     band of the spectrum;
//!   - `hero` (hero-wavelength sampling, Wilkie et al., "Hero Wavelength Spectral Sampling", EGSR 2014): each
//!     camera path carries several wavelengths spread evenly over the spectrum and is traced once while they
//!     agree; where it meets a dispersive surface it splits, and each wavelength is traced on its own. A path
//!     that never meets one (most of a picture) costs one ray whatever the number of wavelengths.
//!
//!   A scene without dispersive materials gets one white pass whatever the mode.
//!
//! Deviations from the slide: each pass stands for a *band* of wavelengths (its colour is the integral of the
//! colour-matching functions over the band, traced at the band's centre) rather than one spectral line, so
//! that the K colours add up to the light's colour exactly for any K (ledger: `wavelength-bands`).

pub mod cie;
pub mod colour;

pub use colour::{
    Band, GamutMapping, Illuminant, LAMBDA_MAX, LAMBDA_MIN, bands, cie_xyz, clip_to_gamut, fit_to_gamut,
    xyz_to_linear_srgb,
};

use crate::lesson::error::{Error, Result};

/// What the renderer does about wavelengths for one render.
#[derive(Clone, Debug, PartialEq)]
pub enum SpectralPlan {
    /// White light: one pass, rays carry no wavelength (nothing in the scene is dispersive).
    White,
    /// One pass per band, each traced at the band's centre.
    Passes(Vec<Band>),
    /// One pass; sample s of a pixel traces a wavelength in its own band out of spp.
    Sampled,
    /// One pass; each sample's path carries `per_path` wavelengths, and splits where it meets dispersive glass.
    Hero {
        /// The wavelengths each camera path carries.
        per_path: u32,
    },
}

impl SpectralPlan {
    /// The plan for a scene: white light when nothing in it is dispersive, else what `mode` asks for, with
    /// `wavelengths` passes (or wavelengths per path) of a light of the spectrum `illuminant`.
    pub fn new(dispersive: bool, mode: SpectralMode, wavelengths: u32, illuminant: Illuminant) -> SpectralPlan {
        match (dispersive, mode) {
            (false, _) => SpectralPlan::White,
            (true, SpectralMode::Passes) => SpectralPlan::Passes(bands(wavelengths, illuminant)),
            (true, SpectralMode::Sampled) => SpectralPlan::Sampled,
            (true, SpectralMode::Hero) => SpectralPlan::Hero { per_path: wavelengths },
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
    #[inline(always)]
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

/// How a dispersive scene spends its rays on wavelengths (`--spectral`). The default is the one the
/// error-versus-time study of the dispersion example found best for its picture (see `docs/measurements.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SpectralMode {
    /// The slide's method: `--wavelengths` K full passes, one per band, added with the bands' colours.
    Passes,
    /// Spectral sampling: one pass in which every anti-aliasing sample of a pixel carries its own band of
    /// the spectrum (spp bands per pixel, wavelength jittered within the band).
    Sampled,
    /// Hero-wavelength sampling: every anti-aliasing sample carries `--wavelengths` wavelengths, evenly spread;
    /// its path is traced once, and again for each of the other wavelengths only if it meets dispersive glass.
    #[default]
    Hero,
}

impl SpectralMode {
    /// The `--wavelengths` of a render that does not say: the slide's 8 passes; 4 wavelengths per path for
    /// hero sampling (at 4 samples per pixel the best of the study at the cost of the slide's 8 passes x 2).
    pub fn default_wavelengths(self) -> u32 {
        match self {
            SpectralMode::Passes => 8,
            SpectralMode::Sampled => 1,
            SpectralMode::Hero => 4,
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
            SpectralPlan::Hero { per_path } => write!(f, "{per_path} hero wavelengths per path"),
        }
    }
}
