//! # Chromatic dispersion (lecture 6, slides "Хроматично пречупване (дисперсия)", "Симулиране на хроматично пречупване")
//!
//! The slide's code: the K passes of `src/lesson/render.rs`, each frame times its band's colour
//! (`src/lesson/spectral/mod.rs`). `--slide` renders this example with the slides' choice of every step beyond them
//! (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! Glass bends short wavelengths more than long ones: its index of refraction falls with the wavelength
//! (the Abbe number V_d says how fast; small is strong). A ray of white light is really many rays, one per
//! wavelength, and each takes its own path. The slide's method traces the frame once per wavelength (K
//! passes) and adds the frames, each multiplied by the colour of its wavelength.
//!
//! The colour of a wavelength is the CIE's: the light's spectrum (`--illuminant d65`, daylight and sRGB's
//! own white, so a white light stays white; or `equal-energy`) times the CIE 1931 colour-matching functions,
//! normalised by the light's luminance. A single wavelength is more saturated than any sRGB colour can be:
//! `--gamut clip`, the default, shows it with its negative channels cut to 0; `--gamut fit` mixes in grey of
//! the same luminance (a paler rainbow). `-o out/dispersion.exr` keeps the unmapped values, negative
//! channels included.
//!
//! How the wavelengths are traced (`--spectral`):
//! - `hero`, the default: every anti-aliasing sample carries `--wavelengths` wavelengths (4) spread evenly
//!   over the spectrum, traced as one path until it meets the glass, where it splits and each wavelength is
//!   followed on its own; a path that misses the glass costs one ray. At 4 samples per pixel this is what the
//!   error-versus-time study found best for this picture at the cost of the slide's 8 passes x 2 samples
//!   (16% less error, 31% less perceptual error, 6% fewer rays; see `docs/measurements.md`).
//! - `passes`, the slide's method: `--wavelengths` K frames (8), one per band of the spectrum, each traced at
//!   its band's centre.
//! - `sampled`: every sample carries one wavelength of its own.
//!
//! Look at:
//! - the prism on the left: through it the bright white slit of the environment is spread into a spectrum,
//!   violet bent most, red least;
//! - the glass sphere on the right: the slit seen through it is fringed with colour;
//! - `--spectral passes` (the slide's method): the spectrum drawn as 8 copies of the slit, one per pass;
//!   `--spectral passes --wavelengths 3`: the spectrum falls apart into 3; the default instead samples it
//!   continuously: a smooth spectrum with some colour noise, which `--spp 16` smooths out.
//!
//! Try: `--glass n-bk7` (a crown glass: about a quarter of the spread), `--glass abbe --nd 1.785 --abbe 10`,
//! `--glass abbe --abbe inf` (no dispersion: one white slit, traced in one pass), `--gamut fit`,
//! `--illuminant equal-energy` (a flat spectrum: everything a little pink), `--env textures/sky.hdr` (the
//! glass in another environment).
//!
//! Homework ideas: draw the spectrum on a diffuse wall with photons that carry a wavelength; make the
//! sphere a brilliant-cut gem from planes; weight the wavelengths by the Planck spectrum of a warm light.

use lecture6::app::scenes::dispersion::SlitEnvironment;
use lecture6::prelude::*;

/// Which glass the prism and the sphere are made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Glass {
    /// Schott SF11, a dense flint (n_d 1.785, V_d 25.7), by its Sellmeier coefficients.
    Sf11,
    /// Schott N-BK7, a crown glass (n_d 1.517, V_d 64.2), by its Sellmeier coefficients.
    NBk7,
    /// The slide's model: `--nd` and `--abbe`, fitted by Cauchy's equation.
    Abbe,
}

/// Dispersion: a prism fanning a white slit into a spectrum, and a glass sphere with coloured fringes.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// The glass of the prism and the sphere.
    #[arg(long, value_enum, default_value_t = Glass::Sf11)]
    pub glass: Glass,
    /// Index of refraction at 587.6 nm, for `--glass abbe` only. [default: 1.7847, SF11's]
    #[arg(long)]
    pub nd: Option<f32>,
    /// Abbe number V_d, for `--glass abbe` only: smaller is more dispersive; `inf` is no dispersion.
    /// [default: 25.68, SF11's]
    #[arg(long)]
    pub abbe: Option<f32>,
}

impl Options {
    /// The glass the options ask for. `--nd` and `--abbe` describe the slide's model glass: given with a
    /// catalogue glass, they are an error rather than silently ignored.
    pub fn ior(&self) -> Result<Ior> {
        let model = [("--nd", self.nd), ("--abbe", self.abbe)];
        if self.glass != Glass::Abbe
            && let Some((option, Some(value))) = model.into_iter().find(|(_, value)| value.is_some())
        {
            return Err(Error::parameter(option, value, "applies to --glass abbe only: add --glass abbe"));
        }
        match self.glass {
            Glass::Sf11 => Ok(Ior::SF11),
            Glass::NBk7 => Ok(Ior::N_BK7),
            Glass::Abbe => Ior::abbe(self.nd.unwrap_or(SF11_ND), self.abbe.unwrap_or(SF11_ABBE)),
        }
    }
}

/// `--glass abbe`'s default index: SF11's n_d, at 587.6 nm.
pub const SF11_ND: f32 = 1.7847;
/// `--glass abbe`'s default Abbe number: SF11's V_d.
pub const SF11_ABBE: f32 = 25.68;

/// The wavelength (nm) whose minimum-deviation ray through the prism's centre meets the slit.
pub const SLIT_WAVELENGTH: f32 = 560.0;

/// The prism's apex angle, degrees.
pub const APEX_ANGLE: f32 = 60.0;

/// The angle by which a prism of apex angle `apex` (degrees) and index `n` turns a ray passing it
/// symmetrically (minimum deviation), in degrees: `2 asin(n sin(A/2)) - A`. None if no ray gets through.
pub fn minimum_deviation(apex: f32, n: f32) -> Option<f32> {
    let s = n * (0.5 * apex.to_radians()).sin();
    (s < 1.0).then(|| 2.0 * s.asin().to_degrees() - apex)
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let ior = self.ior()?;
        let mut scene = Scene::new(Camera { position: Vector::ZERO, fov: 60.0, ..Camera::default() });
        scene.max_depth = 5;
        // The slides' glass: refraction under a Fresnel-blended reflection, with the dispersive index.
        let glass = Arc::new(fresnel_glass(ior, FresnelMode::Schlick, 1.0));

        // The prism, left of the view. The ray from the camera to its centre has azimuth `view`; at minimum
        // deviation it crosses the prism parallel to the base, turned by half the deviation, so the base faces
        // the side it bends to. Turning the canonical prism (base towards -Z) by `yaw` puts it there. (An
        // index with no ray through the prism, n sin(A/2) >= 1, leaves the slit straight ahead.)
        let centre = Vector::new(-2.6, 0.0, 10.0);
        let view = centre.x.atan2(centre.z).to_degrees();
        let deviation = minimum_deviation(APEX_ANGLE, ior.at(Some(SLIT_WAVELENGTH))).unwrap_or(0.0);
        let yaw = 90.0 - (view + 0.5 * deviation);
        scene.add(Node::new(Prism::new(APEX_ANGLE, 1.8, 2.4), glass.clone()).rotate(yaw, 0.0, 0.0).translate(centre));

        // The gem: a sphere of the same glass.
        scene.add(Node::new(Sphere::new(Vector::new(2.8, -0.3, 10.0), 2.1), glass));

        // A dark studio with a bright slit, where the prism's central ray leaves it, and a ring of lamps.
        scene.environment = Some(Arc::new(SlitEnvironment {
            azimuth: (view + deviation).to_radians(),
            half_width: 0.4f32.to_radians(),
            bottom: (-8.0f32).to_radians(),
            top: 12.0f32.to_radians(),
            radiance: 6.0,
        }));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
