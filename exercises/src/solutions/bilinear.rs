//! The solution of the exercise in src/bilinear.rs (the teacher's copy only).

use crate::Color;

pub fn bilinear(x: f32, y: f32, texel: impl Fn(i64, i64) -> Color) -> Color {
    // Texel centres sit at half-integer coordinates.
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (tx, ty) = (fx - x0, fy - y0);
    let (i, j) = (x0 as i64, y0 as i64);
    let top = texel(i, j) * (1.0 - tx) + texel(i + 1, j) * tx;
    let bottom = texel(i, j + 1) * (1.0 - tx) + texel(i + 1, j + 1) * tx;
    top * (1.0 - ty) + bottom * ty
}
