//! # Exercise: `faceforward` (slide "Ориентация на повърхнините")
//!
//! The slide, on the orientation of surfaces:
//!
//! > The normals decide what is "outside" and "inside" of a geometry. Outside: `dot(ray, n) < 0`; inside:
//! > `dot(ray, n) > 0`. `faceforward()` turns a normal so that it points "towards us":
//! > `dot(ray, faceforward(ray, n)) < 0`. We will use it in the Phong, Lambert and Refl shaders, but **not**
//! > in the Refr shader!
//!
//! Return `n` or `-n`, whichever faces the incoming direction `i`, so that `dot(i, faceforward(n, i)) <= 0`.
//! Mind the order of the arguments: the workbook's `faceforward(n, i)` takes the normal first (as GLSL's
//! does). Along the surface (`dot(n, i) = 0`) both answers face the ray; return `n`.
//!
//! Facts the grader checks: a ray from above a floor sees the floor's normal as it is, a ray from below
//! sees it turned; the answer is always `n` or `-n`, never anything else.
//!
//! Used by Lambert, Phong and Reflection, and by Refraction and the Fresnel texture once they have read from
//! the normal as it is whether the ray enters or leaves (that is the slide's warning); the grader renders
//! `reflect_v02`.

use crate::Vector;

/// `n` or `-n`, whichever faces the incoming direction `i`: `dot(i, faceforward(n, i)) <= 0`.
pub fn faceforward(n: Vector, i: Vector) -> Vector {
    todo!("faceforward")
}
