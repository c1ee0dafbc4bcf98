//! The vector helpers of the lecture's "Reflection & Refraction" and "Fresnel" slides, written as on the
//! slides: `faceforward`, `reflect`, `refract`, `fresnel` (Schlick) plus the exact dielectric Fresnel
//! equations, an orthonormal basis (glossy reflections), and floating-point error bounds used to offset
//! secondary rays robustly.
//!
//! Vectors are `glam::Vec3A` (16-byte aligned, SIMD) and called [`Vector`] to match the course's code.

use glam::Vec3A;

/// The course's `Vector` type: three `f32`s, SIMD-aligned.
pub type Vector = Vec3A;

/// Returns `n` or `-n`, whichever faces the incoming direction `i`, so that `dot(i, faceforward(n, i)) <= 0`
/// (slide "Ориентация на повърхнините"). Used by Lambert, Phong and Reflection, **not** by Refraction, which
/// must know whether the ray is entering or leaving.
#[inline(always)]
pub fn faceforward(n: Vector, i: Vector) -> Vector {
    exercise!(faceforward(n, i));
    if n.dot(i) > 0.0 { -n } else { n }
}

/// Mirror reflection of the incoming direction `i` about the normal `n` (slide "Reflect"):
/// `i + 2 * dot(-i, n) * n`. Works whichever side `n` faces; keeps the length of `i`.
#[inline(always)]
pub fn reflect(i: Vector, n: Vector) -> Vector {
    i + 2.0 * (-i).dot(n) * n
}

/// Refraction of the unit incoming direction `i` through a surface with unit normal `n` facing `i`
/// (`dot(i, n) <= 0`), where `ior = eta1 / eta2` is the ratio of the index of the medium the ray comes from
/// to the one it enters (slide "Refract"). Returns `None` on total internal reflection, where the slide
/// returns a zero vector.
///
/// Deviation from the slide: the slide's comment says `ior = eta2 / eta1` but its formula (and its caller,
/// which passes `1 / ior` when entering) uses the incoming-over-outgoing ratio; the name here says what the
/// formula needs (ledger: `eta-ratio`).
#[inline(always)]
pub fn refract(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Vector> {
    exercise!(refract(i, n, eta1_over_eta2));
    let eta = eta1_over_eta2;
    let n_dot_i = n.dot(i);
    let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
    if k < 0.0 {
        return None;
    }
    Some(eta * i - (eta * n_dot_i + k.sqrt()) * n)
}

/// Schlick's approximation of the Fresnel reflectance (slide "Fresnel"), for the unit incoming direction
/// `i`, the normal `n` facing it, and `ior = eta1 / eta2` (the slide's convention: the caller passes
/// `1 / ior` when the ray enters the object). Under total internal reflection it returns 1, which the
/// slide's formula does not: there, the cosine of the *transmitted* angle is used when leaving the denser
/// medium, as Schlick prescribes, so a Fresnel glass never loses energy.
#[inline(always)]
pub fn fresnel(i: Vector, n: Vector, eta1_over_eta2: f32) -> f32 {
    exercise!(fresnel(i, n, eta1_over_eta2));
    let eta = eta1_over_eta2;
    let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
    let cos_i = (-n.dot(i)).clamp(0.0, 1.0);
    let cos = if eta > 1.0 {
        // Leaving the denser medium: Schlick's formula needs the larger of the two angles.
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    } else {
        cos_i
    };
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

/// The exact Fresnel reflectance of a dielectric interface for unpolarised light (the average of the s- and
/// p-polarised reflectances), with the same arguments as [`fresnel`]. Returns 1 under total internal
/// reflection.
#[inline]
pub fn fresnel_exact(i: Vector, n: Vector, eta1_over_eta2: f32) -> f32 {
    exercise!(fresnel_exact(i, n, eta1_over_eta2));
    let eta = eta1_over_eta2;
    let cos_i = (-n.dot(i)).clamp(0.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // With n1/n2 = eta: rs = (n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t), divided through by n2.
    let rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (rs * rs + rp * rp)
}

/// Two unit vectors perpendicular to a unit normal and to each other (step 1 of the glossy-reflection
/// algorithm). Uses the branch-free construction of Duff et al., "Building an Orthonormal Basis, Revisited"
/// (JCGT 2017), which has no singularity anywhere on the sphere.
#[derive(Clone, Copy, Debug)]
pub struct OrthonormalBasis {
    /// First vector perpendicular to `normal` (the local x axis).
    pub tangent: Vector,
    /// Second vector perpendicular to `normal` and to `tangent` (the local y axis).
    pub bitangent: Vector,
    /// The unit normal the basis was built around (the local z axis).
    pub normal: Vector,
}

impl OrthonormalBasis {
    /// The basis around `normal`, which must be of unit length.
    pub fn new(normal: Vector) -> OrthonormalBasis {
        let sign = 1.0f32.copysign(normal.z);
        let a = -1.0 / (sign + normal.z);
        let b = normal.x * normal.y * a;
        let tangent = Vector::new(1.0 + sign * normal.x * normal.x * a, sign * b, -sign * normal.x);
        let bitangent = Vector::new(b, sign + normal.y * normal.y * a, -normal.y);
        OrthonormalBasis { tangent, bitangent, normal }
    }
    /// The vector with coordinates (x, y, z) in this basis.
    pub fn to_world(&self, x: f32, y: f32, z: f32) -> Vector {
        x * self.tangent + y * self.bitangent + z * self.normal
    }
}

/// The largest coordinate or length a scene may give (positions, radii, sizes, a mesh's vertices): the
/// renderer squares distances in 32-bit floats, which end at 3.4e38, so a scene must stay well inside their
/// square root (1.8e19) to be traced at all.
pub const MAX_COORDINATE: f64 = 1e18;

/// Higham's bound on the relative rounding error of `n` successive floating-point operations:
/// `n u / (1 - n u)` with `u` the unit roundoff (half of `f32::EPSILON`). Used to bound the error of a
/// computed hit point, from which the start offset of secondary rays follows (pbrt-v4, section 6.8).
#[inline]
pub const fn gamma(n: u32) -> f32 {
    let nu = n as f32 * (f32::EPSILON * 0.5);
    nu / (1.0 - nu)
}

/// `x.floor()` without the library call it compiles to on a baseline x86-64 (no SSE4.1 rounding), for the
/// hot paths (texel addressing, checker squares, photon grid cells): exact for every float, since from 2^23
/// on every float is a whole number; NaN stays NaN.
#[inline]
pub fn floor(x: f32) -> f32 {
    const WHOLE: f32 = (1u32 << (f32::MANTISSA_DIGITS - 1)) as f32;
    if x.abs() < WHOLE {
        let t = x as i32 as f32;
        if t > x { t - 1.0 } else { t }
    } else {
        x
    }
}

/// The largest absolute coordinate of `v`.
#[inline]
pub fn max_abs(v: Vector) -> f32 {
    v.abs().max_element()
}

/// Moves `p` off a surface with unit normal `n` by at least `error` (the absolute error bound of `p`), to the
/// side that `n` points to, and then by at least one more representable float per coordinate (along the
/// coordinates where `n` is not zero), so the rounding of the addition itself cannot land back on the
/// surface (pbrt-v4's `OffsetRayOrigin`). The offset scales with the hit point's own error bound, so a scene
/// translated to 1e6 or scaled to 1e-4 is treated alike.
///
/// The last step is a unit in the last place of each coordinate or a little more (up to two), added to all
/// three at once instead of stepping each one to the next float: `|q| * EPSILON` is at least the spacing of
/// the floats around `q` (multiplying by a power of two is exact), the smallest positive float is that
/// spacing for zero and subnormal coordinates, and adding at least one spacing moves a float by at least one
/// representable value whichever way it rounds.
#[inline(always)]
pub fn offset_ray_origin(p: Vector, n: Vector, error: f32) -> Vector {
    let d = n.abs().element_sum() * error;
    let q = p + d * n;
    let spacing = (q.abs() * f32::EPSILON).max(Vector::splat(f32::from_bits(1)));
    q + Vector::select(n.cmpeq(Vector::ZERO), Vector::ZERO, spacing.copysign(n))
}
