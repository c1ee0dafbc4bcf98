//! # Exercise: a point in the unit disc (slide "Симулиране на грапави отражения", step 2)
//!
//! A glossy mirror tilts its normal at random for each of the rays it averages. The slide's algorithm:
//!
//! > 1. Find a pair of vectors perpendicular to the normal.
//! > 2. **Generate a random 2D vector in the unit disc.**
//! > 3. Stretch it according to the glossiness ...
//!
//! Step 2, in two ways:
//!
//! - [`random_unit_disc_point`]: the slide's, as the course's code does it: by *rejection*. Draw x and y
//!   uniformly in [-1, 1] (from `random()`, which returns uniform numbers in [0, 1): `2 * random() - 1`, x
//!   first) until the point lies in the disc, `x^2 + y^2 <= 1`. Every point of the disc is then equally
//!   likely. (Drawing a random radius and a random angle is not: it crowds the points at the centre.)
//!
//! - [`concentric_disc`]: what the workbook does by default. Independent random points clump and leave
//!   holes, which shows as noise; the workbook takes evenly spread points of the unit square instead and
//!   carries each one to the disc by Shirley and Chiu's *concentric mapping*, which takes the square's
//!   concentric squares to concentric circles and keeps areas, so evenly spread points stay evenly spread.
//!   With `a = 2u - 1` and `b = 2v - 1` (the point in [-1, 1]^2):
//!
//!   ```text
//!   if a = 0 and b = 0:   the centre, (0, 0)
//!   if |a| > |b|:         r = a,  phi = (pi/4) * (b / a)
//!   otherwise:            r = b,  phi = pi/2 - (pi/4) * (a / b)
//!   the point:            (r cos(phi), r sin(phi))
//!   ```
//!
//!   (r may be negative: that turns the point half round, into the opposite quarter of the disc.)
//!
//! Facts the grader checks: every point lies in the disc; the random points fill it evenly (half of the
//! mean squared radius, a quarter of them within radius 1/2, no side preferred); the mapping takes the
//! centre of the square to the centre of the disc, the square's edge to the circle, and keeps areas.
//!
//! `concentric_disc` is in every glossy picture of the workbook; `random_unit_disc_point` in the `glossy`
//! example with `--sampler random` and in the photons a glossy mirror reflects. The grader renders
//! `glossy`.

/// A random point of the unit disc, by rejection from the square [-1, 1]^2; `random()` returns uniform
/// numbers in [0, 1).
pub fn random_unit_disc_point(mut random: impl FnMut() -> f32) -> (f32, f32) {
    todo!("glossy_disc: random_unit_disc_point")
}

/// The point of the unit disc that Shirley and Chiu's concentric mapping takes the point (u, v) of the unit
/// square to.
pub fn concentric_disc(u: f32, v: f32) -> (f32, f32) {
    todo!("glossy_disc: concentric_disc")
}
