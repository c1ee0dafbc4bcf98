//! What a ray hit (the course's `IntersectionInfo`): the point, the normals, the distance, the error bound of
//! the point and the texture coordinates. Every shape describes its hits with it, and a spawned ray starts
//! from it (`Ray::spawn`).

use crate::lesson::math::{Vector, gamma, max_abs};

/// What a ray hit (the course's `IntersectionInfo`).
///
/// A shape makes one with [`IntersectionInfo::new`] (and [`IntersectionInfo::with_geometric_normal`] when
/// its shading normal differs from the surface's own, [`IntersectionInfo::with_tex_coords`] when its u/v
/// are worth computing only when read). Shaders and textures read u/v with [`IntersectionInfo::uv`].
#[derive(Clone, Copy, Debug)]
pub struct IntersectionInfo {
    /// The hit point, in the coordinates the renderer computes with: in a scene far from the origin, which
    /// the examples move to the camera
    /// (`Scene::relative_to_camera`), relative to the
    /// camera's position. A shader that needs the point in the world the scene was built in (a pattern fixed
    /// in the world) asks `ctx.scene.world_position(info.ip)`
    /// (`Scene::world_position`).
    pub ip: Vector,
    /// The unit shading normal, pointing out of the object (not face-forwarded).
    pub normal: Vector,
    /// The unit normal of the surface itself (differs from `normal` on smoothly shaded meshes); used to
    /// offset secondary rays.
    pub geometric_normal: Vector,
    /// The ray parameter of the hit: its distance from the ray's start when the ray direction is unit.
    pub distance: f32,
    /// An absolute bound on the rounding error of `ip`, in each coordinate.
    pub error: f32,
    /// The texture coordinates, or what they are computed from: read them with [`IntersectionInfo::uv`].
    pub tex_coords: TexCoords,
}

/// The texture coordinates of a hit, as the shape gives them: the coordinates themselves
/// ([`TexCoords::new`]), or up to three numbers and the function that makes u/v of them
/// ([`TexCoords::deferred`]), for a shape whose u/v cost more than the shaders that never read them should
/// pay (the sphere's take two inverse trigonometric functions; glass and mirrors ignore them). Either way
/// [`TexCoords::get`] gives the same u/v.
#[derive(Clone, Copy, Debug)]
pub struct TexCoords {
    args: [f32; 3],
    /// `None` when `args` hold (u, v) themselves: reading them then costs no call.
    compute: Option<UvFunction>,
}

/// How a shape makes u/v of up to three numbers (see [`TexCoords::deferred`]).
pub type UvFunction = fn([f32; 3]) -> (f32, f32);

impl TexCoords {
    /// The coordinates (u, v).
    pub fn new(u: f32, v: f32) -> TexCoords {
        TexCoords { args: [u, v, 0.0], compute: None }
    }

    /// Coordinates that `compute(args)` gives, computed only when read.
    pub fn deferred(args: [f32; 3], compute: UvFunction) -> TexCoords {
        TexCoords { args, compute: Some(compute) }
    }

    /// (u, v).
    #[inline]
    pub fn get(&self) -> (f32, f32) {
        match self.compute {
            None => (self.args[0], self.args[1]),
            Some(compute) => compute(self.args),
        }
    }
}

impl IntersectionInfo {
    /// A hit at ray parameter `distance` on the point `ip`, with the unit outward `normal` (used for both
    /// shading and offsetting) and texture coordinates `uv`. The error bound is that of a point lying on the
    /// surface up to the rounding of a few operations on coordinates no larger than its own,
    /// `gamma(3) * max|ip|`: right for a hit re-projected onto the surface (snapped onto a plane or a face,
    /// or moved onto a sphere along its normal) and for one computed from exact parameters. A shape whose hit
    /// point carries more error says so with [`IntersectionInfo::with_error`].
    pub fn new(ip: Vector, normal: Vector, distance: f32, uv: (f32, f32)) -> IntersectionInfo {
        IntersectionInfo {
            ip,
            normal,
            geometric_normal: normal,
            distance,
            error: gamma(3) * max_abs(ip),
            tex_coords: TexCoords::new(uv.0, uv.1),
        }
    }

    /// The texture coordinates (u, v) of the hit (computed here if the shape deferred them).
    #[inline]
    pub fn uv(&self) -> (f32, f32) {
        self.tex_coords.get()
    }

    /// The same hit with texture coordinates given as [`TexCoords`] (deferred ones, say).
    pub fn with_tex_coords(self, tex_coords: TexCoords) -> IntersectionInfo {
        IntersectionInfo { tex_coords, ..self }
    }

    /// The same hit with a larger (or smaller, when the shape knows better) absolute error bound on `ip`.
    pub fn with_error(self, error: f32) -> IntersectionInfo {
        IntersectionInfo { error, ..self }
    }

    /// The same hit with its own surface normal, when the shading normal differs (an interpolated normal).
    pub fn with_geometric_normal(self, geometric_normal: Vector) -> IntersectionInfo {
        IntersectionInfo { geometric_normal, ..self }
    }
}
