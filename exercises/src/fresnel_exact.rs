//! # Exercise: the Fresnel equations (slide "Fresnel")
//!
//! The slide: "Fresnel's equations express exactly the ratio Reflected / (Reflected + Refracted). The
//! equations are rather complex, but fortunately Schlick devised a simple approximation that works well in
//! practice." Here are the equations themselves, for light that is not polarised: the average of the
//! reflectances of its two polarisations,
//!
//! ```text
//! rs = (n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t)
//! rp = (n2 cos_i - n1 cos_t) / (n2 cos_i + n1 cos_t)
//! R  = (rs^2 + rp^2) / 2
//! ```
//!
//! where n1 is the index of the medium the ray comes from, n2 of the one it enters, `cos_i` the cosine of
//! the angle of incidence (`-dot(n, i)`, clamped to [0, 1] against rounding) and `cos_t` that of the
//! refracted ray. Snell's law gives the latter: `sin_t^2 = (n1 / n2)^2 * (1 - cos_i^2)`; if that is 1 or
//! more there is no refracted ray (total internal reflection) and R = 1. The function gets only the ratio
//! n1 / n2, as [`fresnel`](crate::fresnel_schlick::fresnel) does: divide the numerators and denominators
//! through by n2.
//!
//! Facts the grader checks: head-on, glass of index 1.5 reflects 0.04; at Brewster's angle (tan = 1.5) the
//! p-polarised part vanishes and R = rs^2 / 2; at a grazing angle and past the critical angle, everything;
//! a ray leaving the glass is reflected as much as one entering along the refracted ray's path (the
//! equations are symmetric); always between 0 and 1.
//!
//! Used by the Fresnel texture in its exact mode, which the lacquer of the `layered` example's floor uses;
//! the grader renders `layered`.

use crate::Vector;

/// The exact Fresnel reflectance of unpolarised light, with the same arguments as
/// [`fresnel`](crate::fresnel_schlick::fresnel): 1 under total internal reflection.
pub fn fresnel_exact(i: Vector, n: Vector, eta1_over_eta2: f32) -> f32 {
    todo!("fresnel_exact")
}
