//! What the `lookup` and `lookup-value` views show of a pixel (slide "Bitmap текстури", made visible): the
//! texture read that the shader of the surface seen through the pixel's centre actually made, where it read
//! (u and v) and what it got back, rather than where the hit says it should read (`--view uv`).
//!
//! The pixel's centre ray is traced as the render traces a camera ray, with an observer
//! ([`crate::lesson::observer`]) that keeps the first texture look-up the core records at the first hit: the
//! texels a bitmap mixed, which a shader reads through `ColorSource::at` (every shader of the workbook, and a
//! student's that reads its texture as `docs/homework-api.md` shows), and which a `Layered` shader's layers
//! and blend textures read so too. Nothing of it runs in a render: the core records a look-up only for an
//! observer. What the core does not record is not seen: a read through `Texture::get_tex_color` (or
//! `ColorSource::get`) called directly, a checker's, a texture of a student's own, and the Fresnel texture
//! (which reads no u/v); a surface whose shader read only such textures shows as one that read none.

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::observer::{Observer, Stop};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{Scene, TraceContext};
use crate::lesson::topic::{Recorder, Topic};

/// What the shader of a camera ray's hit read first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum FirstRead {
    /// The ray hit nothing.
    Missed,
    /// The hit's shader, called `shader`, read a bitmap first at (u, v) (after the texture's scaling, before
    /// wrapping: one image per unit), which gave `color` (linear light).
    Read {
        /// The hit's shader's name.
        shader: &'static str,
        /// Where the read looked up.
        uv: (f32, f32),
        /// The colour the read returned: its texels' weighted sum.
        color: Color,
    },
    /// The hit's shader, called `shader`, made no read the core records.
    Nothing {
        /// The hit's shader's name.
        shader: &'static str,
    },
}

/// Traces `ray` in the prepared `scene`, drawing its random numbers from a stream keyed by `keys`, and says
/// what the shader of its hit read first.
pub(super) fn first_read(scene: &Scene, ray: &Ray, keys: &[u64]) -> FirstRead {
    let mut watch = Watch::default();
    let mut ctx = TraceContext::new(scene, Rng::for_keys(keys));
    ctx.observer = Some(&mut watch);
    ctx.raytrace(ray);
    drop(ctx);
    match (watch.shader, watch.read) {
        (None, _) => FirstRead::Missed,
        (Some(shader), Some((uv, color))) => FirstRead::Read { shader, uv, color },
        (Some(shader), None) => FirstRead::Nothing { shader },
    }
}

/// The observer of one camera ray's trace: how deep the ray being traced is (1: the camera ray), the shader
/// of the camera ray's hit, and the first look-up recorded while that shader ran (not while a ray it traced
/// was being shaded).
#[derive(Default)]
struct Watch {
    depth: u32,
    shader: Option<&'static str>,
    read: Option<((f32, f32), Color)>,
}

impl Recorder for Watch {
    fn record(&mut self, topic: &Topic) {
        if let (1, Some(_), None, Topic::Texels { u, v, texels }) = (self.depth, self.shader, self.read, topic) {
            let color = texels.iter().fold(Color::BLACK, |sum, t| sum + t.color * t.weight);
            self.read = Some(((*u, *v), color));
        }
    }
}

impl Observer for Watch {
    fn ray_begins(&mut self, _ray: &Ray) {
        self.depth += 1;
    }

    fn ray_hits(&mut self, _node: &str, shader: &'static str, _info: &IntersectionInfo) {
        if self.depth == 1 {
            self.shader = Some(shader);
        }
    }

    fn ray_ends(&mut self, _color: Color, _stop: Option<Stop>) {
        self.depth -= 1;
    }
}
