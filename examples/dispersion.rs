//! # Chromatic dispersion (lecture 6, slides "Хроматично пречупване (дисперсия)", "Симулиране на хроматично пречупване")
//!
//! Glass bends short wavelengths more than long ones: its index of refraction falls with the wavelength
//! (the Abbe number V_d says how fast; small is strong). A ray of white light is really many rays, one per
//! wavelength, and each takes its own path. The slide's method traces the frame once per wavelength (K
//! passes) and adds the frames, each multiplied by the colour of its wavelength.
//!
//! Look at:
//! - the prism on the left: through it the bright white slit of the environment is spread into a spectrum,
//!   violet bent most, red least;
//! - the glass sphere on the right: the slit seen through it is fringed with colour;
//! - `--wavelengths 3` or `4`: the spectrum falls apart into separate copies of the slit, one per pass;
//!   `--spectral sampled --spp 32` instead gives every sample its own wavelength: a smooth spectrum, with
//!   some colour noise.
//!
//! Try: `--glass n-bk7` (a crown glass: about a quarter of the spread), `--glass abbe --nd 1.785 --abbe 10`,
//! `--glass abbe --abbe inf` (no dispersion: one white slit, traced in one pass), `--env textures/sky.hdr`
//! (the glass in another environment).
//!
//! Homework ideas: draw the spectrum on a diffuse wall with photons that carry a wavelength; make the
//! sphere a brilliant-cut gem from planes; weight the passes by the Planck spectrum of a warm light.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::dispersion::Args>()
}
