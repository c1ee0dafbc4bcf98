//! The solution of the exercise in src/transform_inverse.rs (the teacher's copy only).

use glam::{Affine3A, Mat3A};

pub fn inverse(t: Affine3A) -> Affine3A {
    let m = t.matrix3;
    let (a, b, c) = (m.x_axis, m.y_axis, m.z_axis);
    let det = a.dot(b.cross(c));
    // The rows of the inverse, built as columns and turned.
    let inverse = Mat3A::from_cols(b.cross(c) / det, c.cross(a) / det, a.cross(b) / det).transpose();
    Affine3A { matrix3: inverse, translation: -(inverse * t.translation) }
}
