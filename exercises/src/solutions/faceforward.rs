//! The solution of the exercise in src/faceforward.rs (the teacher's copy only).

use crate::Vector;

pub fn faceforward(n: Vector, i: Vector) -> Vector {
    if n.dot(i) > 0.0 { -n } else { n }
}
