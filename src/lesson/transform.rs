//! The model transform (slides "Model трансформация"): T places a canonical shape in the world.
//!
//! T is built by the calls made on it, each applied after the ones before: the slides' order is
//! `.scale(..)`, then `.rotate(..)`, then `.translate(..)`. Rotation angles are degrees, applied as roll
//! (about Z), then pitch (about X), then yaw (about Y), with the same signs as the [`Camera`](crate::lesson::camera).
//!
//! A ray is intersected with a transformed shape by moving the ray into canonical space with T^-1
//! (`intersect(o * T, r) = intersect(o, r * T^-1)`); the hit point goes back by T, the normal by the
//! inverse transpose of T's linear part (so it stays perpendicular under non-uniform scaling), and the ray
//! parameter needs no change, because the canonical ray is T^-1 of the world ray *without* renormalising its
//! direction. u/v are not transformed.

use crate::lesson::camera::rotation;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::{Vector, gamma, max_abs};
use crate::lesson::ray::Ray;
use glam::{Affine3A, Mat3A};

/// A model transform T and its inverse: what places a canonical shape in the world (slide "Model трансформация").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    forward: Affine3A,
    inverse: Affine3A,
    /// The inverse transpose of the linear part, for normals.
    normal_matrix: Mat3A,
    /// The transform only moves (its linear part is the identity): rays and hits are then moved by one
    /// vector addition, and directions and normals stay as they are.
    translation_only: bool,
}

impl Default for Transform {
    fn default() -> Transform {
        Transform::IDENTITY
    }
}

/// The inverse of an affine map (the slide's T^-1, which moves rays into canonical space).
fn inverse(t: Affine3A) -> Affine3A {
    exercise!(transform_inverse(t));
    t.inverse()
}

/// The largest absolute row sum of a matrix: a bound on how much it can grow a coordinate.
fn norm_inf(m: &Mat3A) -> f32 {
    let t = m.transpose();
    t.x_axis.abs().element_sum().max(t.y_axis.abs().element_sum()).max(t.z_axis.abs().element_sum())
}

impl Transform {
    /// The transform that changes nothing: where a chain of `.scale(..)`, `.rotate(..)`, `.translate(..)` starts.
    pub const IDENTITY: Transform = Transform {
        forward: Affine3A::IDENTITY,
        inverse: Affine3A::IDENTITY,
        normal_matrix: Mat3A::IDENTITY,
        translation_only: true,
    };

    fn then(self, step: Affine3A) -> Transform {
        let forward = step * self.forward;
        let inverse = inverse(forward);
        let translation_only = forward.matrix3 == Mat3A::IDENTITY;
        Transform { forward, inverse, normal_matrix: inverse.matrix3.transpose(), translation_only }
    }

    /// Scales by (x, y, z) after what the transform already does.
    pub fn scale(self, s: Vector) -> Transform {
        self.then(Affine3A::from_scale(s.into()))
    }
    /// Rotates by yaw, pitch and roll in degrees after what the transform already does.
    pub fn rotate(self, yaw: f32, pitch: f32, roll: f32) -> Transform {
        self.then(Affine3A::from_mat3(rotation(yaw, pitch, roll).into()))
    }
    /// Moves by `offset` after what the transform already does.
    pub fn translate(self, offset: Vector) -> Transform {
        self.then(Affine3A::from_translation(offset.into()))
    }

    /// The matrix from canonical to world space.
    pub fn matrix(&self) -> Affine3A {
        self.forward
    }

    /// Fails when the transform cannot be inverted (a zero scale) or holds a NaN or infinity, so that a bad
    /// transform is reported when the scene is built rather than turning into NaNs in the picture.
    pub fn check(&self) -> Result<()> {
        let det = self.forward.matrix3.determinant();
        let scale = norm_inf(&self.forward.matrix3);
        if !(det.is_finite() && scale.is_finite() && self.forward.translation.is_finite())
            || det.abs() <= gamma(3) * scale * scale * scale
        {
            // Numbers as `{:?}` writes them: 1e20, not twenty-one digits.
            let v = |v: glam::Vec3A| format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z);
            let m = &self.forward.matrix3;
            let [x, y, z] = [0, 1, 2].map(|i| v(m.row(i)));
            return Err(Error::parameter(
                "transform",
                format!("(rows {x}, {y}, {z}; translation {})", v(self.forward.translation)),
                "it cannot be undone (a zero scale?) or holds a number too large for 32-bit floats",
            ));
        }
        Ok(())
    }

    /// The world ray expressed in canonical space (direction not renormalised, so ray parameters agree).
    pub fn ray_to_canonical(&self, ray: &Ray) -> Ray {
        if self.translation_only {
            return Ray { start: ray.start - self.forward.translation, ..*ray };
        }
        Ray { start: self.inverse.transform_point3a(ray.start), dir: self.inverse.transform_vector3a(ray.dir), ..*ray }
    }

    /// A point from canonical to world space.
    pub fn point_to_world(&self, p: Vector) -> Vector {
        self.forward.transform_point3a(p)
    }

    /// A hit found in canonical space, brought back to world space: position by T, normals by the inverse
    /// transpose (renormalised), the error bound grown by T; distance and u/v unchanged.
    pub fn info_to_world(&self, info: &IntersectionInfo) -> IntersectionInfo {
        if self.translation_only {
            // |M| = 1: the same bound as below, without the matrix products.
            let error =
                (1.0 + gamma(3)) * info.error + gamma(3) * (max_abs(info.ip) + max_abs(self.forward.translation));
            return IntersectionInfo { ip: info.ip + self.forward.translation, error, ..*info };
        }
        let m = &self.forward.matrix3;
        let ip = self.forward.transform_point3a(info.ip);
        // The canonical error box grows by |M| (and by the rounding of that product), plus the rounding of
        // transforming the point itself (pbrt-v4, section 6.8.5).
        let error = (1.0 + gamma(3)) * norm_inf(m) * info.error
            + gamma(3) * (norm_inf(m) * max_abs(info.ip) + max_abs(self.forward.translation));
        IntersectionInfo {
            ip,
            normal: (self.normal_matrix * info.normal).normalize(),
            geometric_normal: (self.normal_matrix * info.geometric_normal).normalize(),
            error,
            ..*info
        }
    }
}
