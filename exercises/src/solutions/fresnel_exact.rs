//! The solution of the exercise in src/fresnel_exact.rs (the teacher's copy only).

use crate::Vector;

pub fn fresnel_exact(i: Vector, n: Vector, eta1_over_eta2: f32) -> f32 {
    let eta = eta1_over_eta2;
    let cos_i = (-n.dot(i)).clamp(0.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // The equations divided through by n2: n1 / n2 = eta.
    let rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (rs * rs + rp * rp)
}
