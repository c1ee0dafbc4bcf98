//! The solution of the exercise in src/refract.rs (the teacher's copy only).

use crate::Vector;

pub fn refract(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Vector> {
    let eta = eta1_over_eta2;
    let n_dot_i = n.dot(i);
    let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
    if k < 0.0 {
        return None;
    }
    Some(eta * i - (eta * n_dot_i + k.sqrt()) * n)
}
