//! The solution of the exercise in src/glossy_disc.rs (the teacher's copy only).

use std::f32::consts::FRAC_PI_4;

pub fn random_unit_disc_point(mut random: impl FnMut() -> f32) -> (f32, f32) {
    loop {
        let x = 2.0 * random() - 1.0;
        let y = 2.0 * random() - 1.0;
        if x * x + y * y <= 1.0 {
            return (x, y);
        }
    }
}

pub fn concentric_disc(u: f32, v: f32) -> (f32, f32) {
    let (a, b) = (2.0 * u - 1.0, 2.0 * v - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) =
        if a.abs() > b.abs() { (a, FRAC_PI_4 * (b / a)) } else { (b, 2.0 * FRAC_PI_4 - FRAC_PI_4 * (a / b)) };
    (r * phi.cos(), r * phi.sin())
}
