//! # Exercise: `refract`, with total internal reflection (slides "Reflection & Refraction", "Refract")
//!
//! Snell's law: a ray passing from a medium of index n1 into one of index n2 bends so that
//!
//! ```text
//! sin(theta1) / sin(theta2) = v1 / v2 = n2 / n1
//! ```
//!
//! with theta1 the angle between the normal and the incoming ray, theta2 the angle between the normal and the
//! refracted ray. The slide's code:
//!
//! ```text
//! // ior = eta2 / eta1
//! inline Vector refract(const Vector& i, const Vector& n, float ior)
//! {
//!     float NdotI = (float) (i * n);
//!     float k = 1 - (ior * ior) * (1 - NdotI * NdotI);
//!     if (k < 0.0f) // Check for total inner reflection
//!         return Vector(0, 0, 0);
//!     return ior * i - (ior * NdotI + sqrt(k)) * n;
//! }
//! ```
//!
//! `i` is the unit incoming direction and `n` the unit normal turned to face it (`dot(i, n) <= 0`). The
//! workbook differs from the slide in two places:
//!
//! - the ratio: the slide's comment says `ior = eta2 / eta1`, but its formula (and its caller, which passes
//!   `1 / ior` when the ray enters the glass) needs **eta1 / eta2**, the index of the medium the ray comes
//!   from over the one it enters. The argument is named for what the formula needs: entering glass of index
//!   1.5 from air, it is 1 / 1.5; leaving the glass, 1.5.
//! - total internal reflection: where `k < 0` no ray passes (leaving a denser medium at a grazing angle) and
//!   the slide returns the zero vector; here, return `None`. Otherwise return `Some` of the refracted
//!   direction.
//!
//! Facts the grader checks: a ray along the normal passes straight on; Snell's law holds between the two
//! angles; the refracted ray has unit length, lies in the plane of `i` and `n` and goes through the
//! surface; past the critical angle there is no refracted ray.
//!
//! Used by the Refraction shader; the grader renders `refract`.

use crate::Vector;

/// The refraction of the unit incoming direction `i` through a surface with unit normal `n` facing it, where
/// `eta1_over_eta2` is the index of the medium the ray comes from over the index of the one it enters;
/// `None` on total internal reflection.
pub fn refract(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Vector> {
    todo!("refract")
}
