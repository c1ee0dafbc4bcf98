//! `CheckerTexture`: two colours alternating in squares of 1 / `scaling` texture units (the course's first
//! procedural texture, kept for comparison with bitmaps). Its `scaling` multiplies u/v, as "scaling" does
//! everywhere in the workbook; a bitmap's tile size divides them ([`super::BitmapTexture::tile_size`]).

use super::{Tex, Texture};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::floor;
use crate::lesson::ray::Ray;
use std::sync::Arc;

/// A checkerboard of two colours over the surface's u/v (the course's first procedural texture).
#[derive(Clone, Copy, Debug)]
pub struct CheckerTexture {
    /// The colour of the square at the u/v origin and of every second square from it (linear RGB).
    pub color1: Color,
    /// The colour of the other squares (linear RGB).
    pub color2: Color,
    /// Squares per unit of u/v: what u/v are multiplied by (on a plane, `1.0 / 20.0` gives squares of 20
    /// units). A scene file's `scaling` is 5 times this (its squares are 5 / `scaling` units wide).
    pub scaling: f32,
}

impl Texture for CheckerTexture {
    fn get_tex_color(&self, _ray: &Ray, info: &IntersectionInfo) -> Color {
        let (u, v) = self.lookup_uv(info.uv());
        let (x, y) = (floor(u) as i64, floor(v) as i64);
        if (x + y).rem_euclid(2) == 0 { self.color1 } else { self.color2 }
    }

    /// The surface's u/v times `scaling`: one square per unit.
    fn lookup_uv(&self, (u, v): (f32, f32)) -> (f32, f32) {
        (u * self.scaling, v * self.scaling)
    }

    fn into_tex(self: Arc<Self>) -> Tex {
        Tex::Checker(*self)
    }
}
