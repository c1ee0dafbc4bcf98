//! # Exercise: the inverse of the model transform (slides "Model трансформация")
//!
//! A node's transform T carries its geometry from the canonical space (a unit sphere at the origin, a cube
//! with sides along the axes) into the world. Intersecting the transformed object with a ray is hard; the
//! slide's way out is to move the ray instead:
//!
//! ```text
//! intersect(o * T, r) = intersect(o, r * T^-1)
//! ```
//!
//! so every transformed node needs T^-1, computed once when the scene is built.
//!
//! T is affine: it maps a point p to `M p + t`, with M its 3x3 linear part (`matrix3`) and t its
//! `translation`. Undoing it means first taking away t and then undoing M:
//!
//! ```text
//! T^-1(p) = M^-1 (p - t) = M^-1 p - M^-1 t
//! ```
//!
//! so T^-1 has the linear part `M^-1` and the translation `-(M^-1 t)`. For M^-1, write M by its columns
//! a, b, c (`x_axis`, `y_axis`, `z_axis`). Its determinant is `det = a . (b x c)`, and the **rows** of M^-1
//! are `(b x c) / det`, `(c x a) / det` and `(a x b) / det` (check it: the row `(b x c) / det` times the
//! column a gives 1, times b or c gives 0). glam's `Mat3A::from_cols` builds a matrix from its columns and
//! `transpose` turns rows into columns. Write it yourself: do not call glam's `inverse()`.
//!
//! T may be any sequence of steps (the slide's scale, then rotate, then translate, but also a rotation after
//! a translation, or a second scale), so undo the whole matrix, not the three steps one by one. The
//! workbook refuses singular transforms (a zero scale) before it asks for an inverse.
//!
//! Facts the grader checks: T^-1 (T p) = p for the slide's example (scale (2, 1.5, 0.9), rotate
//! (0.8, 0.1, 0.2), translate (3.3, 0, 18.1)) and others; a translation is undone by the opposite one, a
//! scale by its reciprocal, a rotation by its transpose.
//!
//! Used by every transformed node; the grader renders `model_transform`.

use glam::Affine3A;

/// The inverse of the affine transform `t`: `inverse(t) * t` is the identity.
pub fn inverse(t: Affine3A) -> Affine3A {
    todo!("transform_inverse")
}
