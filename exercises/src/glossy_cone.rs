//! # Exercise: the direction of a glossy reflection (slide "Симулиране на грапави отражения", steps 3-6)
//!
//! A rough surface reflects the light from one direction into a cone of directions, wider the rougher the
//! surface: its glossiness runs from 0 (matte) to 1 (a perfect mirror). The slide simulates the cone by
//! tracing many reflections, each about the normal tilted at random:
//!
//! > 1. Find a pair of vectors perpendicular to the normal.
//! > 2. Generate a random 2D vector in the unit disc.
//! > 3. Stretch it according to the glossiness parameter, by some non-linear formula that makes it zero
//! >    for glossiness = 1 and multiplies it by infinity for 0. An example of such a formula:
//! >    `scaling = tan((1 - glossiness) * pi/2)`.
//! > 4. Use the resulting x, y as multipliers of the vectors from step 1.
//! > 5. Add these two offsets to the normal vector and normalise the result again: that is the tilted
//! >    normal.
//! > 6. Trace an ordinary reflection with the modified normal. Here we must take care that the reflected
//! >    ray is valid: it may go under the surface of the material!
//! > 7. Repeat steps 2..6 many times and average the results.
//!
//! The workbook does step 1 (two unit vectors, `tangent` and `bitangent`, perpendicular to the normal and
//! to each other), step 2 ([`glossy_disc`](crate::glossy_disc)) and step 7. Write step 3,
//! [`glossy_scaling`], and steps 4-6, [`glossy_direction`]: reflect the incoming direction about the tilted
//! normal ([`reflect`](crate::reflect) is given) and return `None` when the reflected ray does not leave the
//! surface, i.e. when its dot product with the (untilted) normal is not positive; the workbook then drops
//! that ray from the average.
//!
//! Facts the grader checks: the slide's scaling at glossiness 1, 0.95, 0.8 and 0.5; the centre of the disc
//! gives the mirror direction; a tilt by (1/2, 0) along the tangent of a floor seen from straight above
//! gives the direction the slide's steps give; the directions have unit length and leave the surface; a
//! tilt that sends the ray under the surface gives `None`.
//!
//! Used by the glossy Reflection shader; the grader renders `glossy`.

use crate::Vector;

/// Step 3: how far a point of the unit disc tilts the normal, as a tangent, for a surface of this
/// glossiness (1 a perfect mirror, 0 matte).
pub fn glossy_scaling(glossiness: f32) -> f32 {
    todo!("glossy_cone: glossy_scaling")
}

/// Steps 4-6: the reflection of the unit `incoming` direction about the unit `normal` (facing it) tilted by
/// the disc point (x, y) times `scaling` along `tangent` and `bitangent`; `None` when it goes under the
/// surface.
pub fn glossy_direction(
    incoming: Vector,
    normal: Vector,
    tangent: Vector,
    bitangent: Vector,
    scaling: f32,
    (x, y): (f32, f32),
) -> Option<Vector> {
    todo!("glossy_cone: glossy_direction")
}
