//! How to render a scene ([`RenderSettings`]) and the limits the renderer holds every render to: what the
//! render loop (`render.rs`) and the course's adaptive anti-aliasing (`adaptive_aa.rs`) both read.

use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
pub use crate::lesson::frame::MAX_SPP;
use crate::lesson::photon_map::MAX_PHOTON_PASSES;
use crate::lesson::scene::Counters;
use crate::lesson::spectral::{MAX_WAVELENGTHS, SpectralMode};

/// The largest frame the renderer accepts, in pixels (64 Mpx, 1 GiB of linear colour).
pub const MAX_PIXELS: u64 = 1 << 26;

/// The most worker threads the renderer starts.
pub const MAX_THREADS: usize = 1024;

/// How to render a scene.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    /// Width of the picture in pixels.
    pub width: u32,
    /// Height of the picture in pixels.
    pub height: u32,
    /// Anti-aliasing samples per pixel.
    pub spp: u32,
    /// Worker threads; `None` uses every core.
    pub threads: Option<usize>,
    /// Seed of every random choice; the same seed gives the same picture.
    pub seed: u64,
    /// Show a progress bar on stderr (only when stderr is a terminal). The command line draws it
    /// (`render::render_with_progress`); `render::render` itself shows none.
    pub progress: bool,
    /// For a dispersive scene, the wavelength passes (the slide's K) or, with hero-wavelength sampling, the
    /// wavelengths each path carries; ignored by other scenes and by spectral sampling.
    pub wavelengths: u32,
    /// How a dispersive scene is traced: K wavelength passes, one wavelength per sample, or hero wavelengths.
    pub spectral: SpectralMode,
    /// The course's adaptive anti-aliasing after the single sample of each pixel (see
    /// `adaptive_aa`); needs `spp` 1.
    pub adaptive_aa: bool,
    /// The largest a sample's brightest channel may be (`--clamp-sample`); brighter samples are scaled down
    /// to it, hue kept. It tames fireflies (a glossy surface that now and then reflects a small, very bright
    /// sun) at the price of bias: the clamped light is lost. `None`, the default, keeps every sample as is.
    pub max_sample: Option<f32>,
    /// The passes of a progressive caustic (`--photon-passes`): each traces a photon map of its own and
    /// renders the picture with it, later passes gathering within a shrinking radius, and the passes'
    /// pictures are averaged (see [`crate::lesson::photon_map::PhotonMap::build_pass`]). 1, the default, is
    /// the slide's one photon map; a scene without a photon map renders once whatever it says.
    pub photon_passes: u32,
}

impl Default for RenderSettings {
    fn default() -> RenderSettings {
        RenderSettings {
            width: 640,
            height: 480,
            spp: 1,
            threads: None,
            seed: 1,
            progress: false,
            wavelengths: SpectralMode::default().default_wavelengths(),
            spectral: SpectralMode::default(),
            adaptive_aa: false,
            max_sample: None,
            photon_passes: 1,
        }
    }
}

impl RenderSettings {
    /// A traced sample as it goes into a pixel's average: NaN and negative channels zeroed (see
    /// [`Color::sanitized`]) and, with [`RenderSettings::max_sample`], scaled down to that brightness. A
    /// sample that came back NaN or infinite is counted in `counters` before it is cleaned.
    pub fn sample(&self, c: Color, counters: &mut Counters) -> Color {
        if !c.is_finite() {
            counters.non_finite_samples += 1;
        }
        let c = c.sanitized();
        match self.max_sample {
            Some(max) if c.max_channel() > max => c * (max / c.max_channel()),
            _ => c,
        }
    }

    /// Rejects sizes and counts that make no sense or would exhaust memory.
    pub fn check(&self) -> Result<()> {
        if self.width == 0 || self.height == 0 {
            return Err(Error::parameter("image size", format!("{}x{}", self.width, self.height), "must not be zero"));
        }
        if self.width as u64 * self.height as u64 > MAX_PIXELS {
            return Err(Error::parameter(
                "image size",
                format!("{}x{}", self.width, self.height),
                format!("more than {MAX_PIXELS} pixels"),
            ));
        }
        if !(1..=MAX_SPP).contains(&self.spp) {
            return Err(Error::parameter("samples per pixel", self.spp, format!("must be 1 to {MAX_SPP}")));
        }
        if !(1..=MAX_WAVELENGTHS).contains(&self.wavelengths) {
            return Err(Error::parameter(
                "wavelength passes",
                self.wavelengths,
                format!("must be 1 to {MAX_WAVELENGTHS}"),
            ));
        }
        if self.adaptive_aa && self.spp != 1 {
            return Err(Error::parameter(
                "samples per pixel",
                self.spp,
                "adaptive anti-aliasing starts from one sample per pixel",
            ));
        }
        if let Some(max) = self.max_sample
            && !(max.is_finite() && max > 0.0)
        {
            return Err(Error::parameter("--clamp-sample", max, "must be a positive number"));
        }
        if !(1..=MAX_PHOTON_PASSES).contains(&self.photon_passes) {
            return Err(Error::parameter(
                "photon passes",
                self.photon_passes,
                format!("must be 1 to {MAX_PHOTON_PASSES}"),
            ));
        }
        if let Some(threads) = self.threads
            && !(1..=MAX_THREADS).contains(&threads)
        {
            return Err(Error::parameter("thread count", threads, format!("must be 1 to {MAX_THREADS}")));
        }
        Ok(())
    }
}
