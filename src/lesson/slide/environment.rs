//! The environment as the slides write it (slides "Заден фон", "Интерфейс за заден фон"): the colour a ray
//! that hits nothing sees, from its direction alone. A spherical environment turns the direction into
//! longitude and latitude; a cube map picks the face of the largest component and indexes it with the other
//! two (both as in [`crate::lesson::environment`]); each reads one texel.

use super::bitmap_textures::texel;
use crate::lesson::bitmap::Wrap;
use crate::lesson::color::Color;
use crate::lesson::environment::{CubemapEnvironment, Environment, SphericalEnvironment, cube_face_uv, equirect_uv};
use crate::lesson::math::Vector;
use std::any::Any;

/// The slides' `getEnvironment(dir)`.
pub fn get(environment: &dyn Environment, dir: Vector) -> Color {
    let any = environment as &dyn Any;
    if let Some(spherical) = any.downcast_ref::<SphericalEnvironment>() {
        let (u, v) = equirect_uv(dir);
        return texel(&spherical.bitmap, u, v, (Wrap::Repeat, Wrap::Clamp));
    }
    if let Some(cube) = any.downcast_ref::<CubemapEnvironment>() {
        let (face, u, v) = cube_face_uv(dir);
        return texel(&cube.faces[face as usize], u, v, (Wrap::Clamp, Wrap::Clamp));
    }
    environment.get(dir)
}
