//! The solution of the exercise in src/fresnel_schlick.rs (the teacher's copy only).

use crate::Vector;

pub fn fresnel(i: Vector, n: Vector, eta1_over_eta2: f32) -> f32 {
    let eta = eta1_over_eta2;
    let f0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
    let cos_i = (-n.dot(i)).clamp(0.0, 1.0);
    let cos = if eta > 1.0 {
        // Leaving the denser medium: the angle of the refracted ray, or total internal reflection.
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    } else {
        cos_i
    };
    f0 + (1.0 - f0) * (1.0 - cos).powi(5)
}
