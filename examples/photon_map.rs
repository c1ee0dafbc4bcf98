//! # Caustics by photon mapping (lecture 6, slides "Caustics", "Photon Mapping", "Пример за photon map")
//!
//! Light concentrated by refraction and reflection: a glass sphere focuses a point light into a bright spot
//! inside its own shadow, and a small mirror throws a bright patch onto the floor ("слънчево зайче").
//! Shadow rays cannot find this light (they would have to know which way to go through the glass), so
//! before rendering, photons are shot from the light at the glass and the mirror, followed through them and
//! stored where they land on the floor; the floor's shader then turns the k nearest photons into light.
//!
//! Look at:
//! - the caustic in the sphere's shadow: much brighter than the lit floor, with a soft halo (spherical
//!   aberration: the sphere's rim focuses closer than its centre);
//! - the mirror's spot: the shape of the mirror, stretched across the floor;
//! - `--photons 0`: the same picture without a photon map, where both are missing;
//! - `--show-photons`: the photons themselves, one dot each, like the slide's last picture.
//!
//! Try: `--photons 20000` (blotchy) and `--photons 1000000` (smooth); `--k 10` versus `--k 300`;
//! `--radius 0.5` versus `--radius 8` (noise against blur); `--ior 1.33` (water focuses farther away);
//! `--abbe 8 --spectral sampled --spp 16` (a dispersive glass: photons carry wavelengths and the caustic
//! gets coloured fringes).
//!
//! Homework ideas: store photons that land without a specular bounce in a second (global) map and add
//! colour bleeding; a caustic from a glass cube; project the photons' hit points to find where the camera
//! should look.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::photon_map::Args>()
}
