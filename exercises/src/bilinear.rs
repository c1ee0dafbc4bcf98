//! # Exercise: the bitmap's bilinear filter (slide "Bitmap текстури")
//!
//! A bitmap texture is an image glued onto a surface: the (u, v) of a hit picks a point of the image. That
//! point hardly ever lies at the centre of a pixel of the image (a *texel*). Taking the texel the point falls
//! in (*nearest*) makes a magnified texture blocky. *Bilinear filtering* mixes the four texels around the
//! point instead, each weighted by how near the point is to it, so the colour runs smoothly from one texel
//! to the next.
//!
//! The workbook measures the point in texels: `x = u * width`, `y = v * height`. Texel (i, j), in column i
//! and row j, covers the square `[i, i + 1) x [j, j + 1)`, so its **centre is at (i + 0.5, j + 0.5)**. The
//! four texels around a point are the ones whose centres are its nearest on each side: the point lies in the
//! rectangle of their four centres. Mix them in two steps: along x, the two texels of the upper row by how
//! far the point is from each centre (a point a quarter of the way from the left centre to the right one
//! takes 3/4 of the left texel and 1/4 of the right one), and likewise the lower row; then the two results
//! along y in the same way.
//!
//! `texel(i, j)` gives the colour (in linear light) of the texel in column i, row j, for any whole i and j,
//! also -1 or `width`: it applies the texture's wrap mode (repeat, mirror or clamp) for you.
//!
//! Facts the grader checks: at the centre of a texel the filter returns that texel; halfway between two
//! centres, their average; an image whose colour grows evenly across it (texel(i, j) = a i + b j + c) gives
//! the same even growth between the centres.
//!
//! Used by every bitmap texture and by both environments; the grader renders `bitmap_textures`.

use crate::Color;

/// The colour at the point (x, y), measured in texels, mixed from the four texels around it;
/// `texel(i, j)` is the colour of the texel in column i, row j (any whole numbers: the wrap mode is applied
/// for you).
pub fn bilinear(x: f32, y: f32, texel: impl Fn(i64, i64) -> Color) -> Color {
    todo!("bilinear")
}
