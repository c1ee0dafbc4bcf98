//! The solution of the exercise in src/photon_estimate.rs (the teacher's copy only).

use crate::{CONE_FILTER_K, Color, Photon, Vector};
use std::f32::consts::PI;

pub fn irradiance_estimate(photons: &[Photon], radius_squared: f32, normal: Vector) -> Color {
    let filter_radius = CONE_FILTER_K * radius_squared.sqrt();
    let mut sum = Color::ZERO;
    for photon in photons {
        if photon.dir.dot(normal) < 0.0 {
            sum += photon.power * (1.0 - photon.distance_squared.sqrt() / filter_radius);
        }
    }
    sum / ((1.0 - 2.0 / (3.0 * CONE_FILTER_K)) * PI * radius_squared)
}
