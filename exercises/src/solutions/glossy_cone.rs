//! The solution of the exercise in src/glossy_cone.rs (the teacher's copy only).

use crate::{Vector, reflect};
use std::f32::consts::FRAC_PI_2;

pub fn glossy_scaling(glossiness: f32) -> f32 {
    ((1.0 - glossiness) * FRAC_PI_2).tan()
}

pub fn glossy_direction(
    incoming: Vector,
    normal: Vector,
    tangent: Vector,
    bitangent: Vector,
    scaling: f32,
    (x, y): (f32, f32),
) -> Option<Vector> {
    let tilted = (normal + x * scaling * tangent + y * scaling * bitangent).normalize();
    let dir = reflect(incoming, tilted);
    (dir.dot(normal) > 0.0).then_some(dir)
}
