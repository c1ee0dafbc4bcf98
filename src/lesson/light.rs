//! Point lights and shadow rays (lectures 2-3). A point light of `intensity` I at distance d gives
//! I / d^2 (times its colour) to a surface facing it, if nothing stands in between.

use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::observer::LightTerm;
use crate::lesson::scene::TraceContext;

/// A point light (lectures 2-3): light from one point, falling off with the square of the distance.
#[derive(Clone, Copy, Debug)]
pub struct PointLight {
    /// Where the light is, in world space.
    pub position: Vector,
    /// The light's colour, in linear RGB; `intensity` scales it.
    pub color: Color,
    /// The course's light "power": irradiance at distance 1 is `color * intensity`.
    pub intensity: f32,
}

impl PointLight {
    /// A light at `position` (world space) of the given colour and intensity.
    pub fn new(position: Vector, color: Color, intensity: f32) -> PointLight {
        PointLight { position, color, intensity }
    }

    /// Fails when the light's position, colour or intensity holds a NaN or an infinity, naming the light by
    /// its `index` in the scene's lights (as the ray tree does) and its values: such a light makes every
    /// surface it reaches NaN, and the end-of-run report would name those surfaces' shaders, not the light.
    /// [`crate::lesson::scene::Scene::check`] asks it of every light before a render.
    pub fn check(&self, index: usize) -> Result<()> {
        let (at, colour, intensity) = (self.position, self.color.0, self.intensity);
        let what = format!("{index} (a point light at {at}, colour {colour}, intensity {intensity})");
        match at.is_finite() && colour.is_finite() && intensity.is_finite() {
            true => Ok(()),
            false => Err(Error::parameter("light", what, "its position, colour and intensity must be finite")),
        }
    }
}

/// What the light loop gathers at a surface point (see [`light_loop`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// The irradiance the point receives: ambient light, the lamps that reach it (each times the cosine of
    /// its angle to the normal) and the caustic light of the photon map. A diffuse shader multiplies it by
    /// its colour.
    pub irradiance: Color,
    /// The sum of what the shader's `each_lamp` returned for the lamps that reach the point: light it adds
    /// as it is, such as Phong's highlight. Black for a shader that adds nothing.
    pub highlights: Color,
}

/// The light loop of the diffuse shaders (Lambert, Phong, and any new one) at the hit point, whose
/// face-forwarded shading normal is `n`. Its irradiance is the sum of
///
/// - the scene's ambient light,
/// - for every lamp that reaches the point (a shadow ray says so), its irradiance times the cosine of its
///   angle to the normal; a lamp behind the surface costs no shadow ray,
/// - the caustic light of the photon map, if the scene has one (slide "Photon Mapping"): light that reaches
///   the point through mirrors and glass, which shadow rays cannot find.
///
/// For each lamp that reaches the point it also calls `each_lamp(to_light, irradiance)`, with the unit
/// direction to the lamp and its irradiance before the cosine, and adds what it returns to the
/// [`Lighting::highlights`]: the light that depends on where the lamp is (Phong's highlight). A shader that
/// takes its light from here gets caustics without asking.
///
/// Deviation from the slides: a lamp is skipped, with no shadow ray, when the shading normal and the
/// surface's own normal disagree about which side it is on (a smooth mesh's interpolated normal near its
/// silhouette): the slides' loop tests the shading normal alone, and such a lamp would light a point that
/// faces away from it (ledger: `lamp-side-check`).
#[inline(always)]
pub fn light_loop(
    ctx: &mut TraceContext,
    info: &IntersectionInfo,
    n: Vector,
    mut each_lamp: impl FnMut(Vector, Color) -> Color,
) -> Lighting {
    let scene = ctx.scene;
    let mut irradiance = scene.ambient;
    let mut highlights = Color::BLACK;
    if !scene.ambient.is_black() {
        ctx.observe(|o| o.light_found(LightTerm::Ambient, scene.ambient));
    }
    for (index, light) in scene.lights.iter().enumerate() {
        let to_light = light.position - info.ip;
        let dist2 = to_light.length_squared();
        let l = to_light / dist2.sqrt();
        if n.dot(l) <= 0.0 || info.geometric_normal.dot(l) * info.geometric_normal.dot(n) <= 0.0 {
            continue;
        }
        let visible = ctx.visible(info, light.position);
        let shadow_ray = LightTerm::Lamp { index, from: info.ip, dir: l, visible };
        if visible {
            let lamp = light.color * (light.intensity / dist2);
            let direct = lamp * n.dot(l);
            irradiance += direct;
            let highlight = each_lamp(l, lamp);
            highlights += highlight;
            ctx.observe(|o| {
                o.light_found(shadow_ray, direct);
                if !highlight.is_black() {
                    o.light_found(LightTerm::Highlight { index }, highlight);
                }
            });
        } else {
            ctx.observe(|o| o.light_found(shadow_ray, Color::BLACK));
        }
    }
    if let Some(map) = &scene.photon_map {
        let caustic = map.irradiance_recorded(info.ip, n, ctx.recorder());
        irradiance += caustic;
        ctx.observe(|o| o.light_found(LightTerm::Photons, caustic));
    }
    // What the shader has to make its colour of (the end-of-run report's energy check).
    ctx.shading.lit(irradiance + highlights);
    Lighting { irradiance, highlights }
}

/// The irradiance a diffuse surface receives at the hit point (see [`light_loop`]).
#[inline]
pub fn diffuse_light(ctx: &mut TraceContext, info: &IntersectionInfo, n: Vector) -> Color {
    light_loop(ctx, info, n, |_, _| Color::BLACK).irradiance
}
