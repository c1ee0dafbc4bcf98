//! The workbook's own pictures and meshes: every file under `textures/` is made here, procedurally and
//! deterministically, and written by `cargo run --release --bin make-assets`. Nothing is downloaded.
//! A test checks that the files under `textures/` are what this code makes.
//!
//! Most textures are 8-bit sRGB PNGs ([`ASSETS`]); the environments are linear-light Radiance HDR images
//! ([`HDR_ASSETS`]), so that the sun can be brighter than white; the meshes are Wavefront OBJ text ([`MESHES`]).

mod sky;
pub mod teapot;

pub use sky::{SkyFunction, sky_equirect, sky_face, sun_direction};

use crate::lesson::rng::mix64;
use image::{Rgb, Rgb32FImage, RgbImage};
use std::f32::consts::PI;

/// One file under `textures/`: its name and how to draw it.
pub struct Asset {
    /// Its path under `textures/` (`wood.png`).
    pub name: &'static str,
    /// Draws the texture as 8-bit sRGB.
    pub draw: fn() -> RgbImage,
}

/// Every generated texture.
pub const ASSETS: &[Asset] = &[
    Asset { name: "floor_tiles.png", draw: floor_tiles },
    Asset { name: "wood.png", draw: wood },
    Asset { name: "world.png", draw: world },
    Asset { name: "checker8.png", draw: checker8 },
    Asset { name: "mirror_mask.png", draw: mirror_mask },
    Asset { name: "metals.png", draw: metals },
];

/// One linear-light file under `textures/`, written as Radiance HDR: its name and how to draw it.
pub struct HdrAsset {
    /// Its path under `textures/` (`sky.hdr`, `sky_cubemap/posx.hdr`).
    pub name: &'static str,
    /// Draws the image in linear light.
    pub draw: fn() -> Rgb32FImage,
}

/// Every generated HDR image: the sky as one equirectangular image and as a cube map made from it.
pub const HDR_ASSETS: &[HdrAsset] = &[
    HdrAsset { name: "sky.hdr", draw: sky_equirect },
    HdrAsset { name: "sky_cubemap/posx.hdr", draw: sky_face::<0> },
    HdrAsset { name: "sky_cubemap/negx.hdr", draw: sky_face::<1> },
    HdrAsset { name: "sky_cubemap/posy.hdr", draw: sky_face::<2> },
    HdrAsset { name: "sky_cubemap/negy.hdr", draw: sky_face::<3> },
    HdrAsset { name: "sky_cubemap/posz.hdr", draw: sky_face::<4> },
    HdrAsset { name: "sky_cubemap/negz.hdr", draw: sky_face::<5> },
];

/// One mesh under `textures/`: its name and its OBJ text.
pub struct MeshAsset {
    /// Its path under `textures/` (`teapot.obj`).
    pub name: &'static str,
    /// Makes the mesh's Wavefront OBJ text.
    pub write: fn() -> String,
}

/// Every generated mesh: the Utah teapot at two resolutions (see [`crate::app::assets::teapot`]).
pub const MESHES: &[MeshAsset] = &[
    MeshAsset { name: "teapot_low.obj", write: crate::app::assets::teapot::low_resolution_obj },
    MeshAsset { name: "teapot.obj", write: crate::app::assets::teapot::high_resolution_obj },
];

/// A pseudo-random value in [0, 1) for an integer lattice point.
fn lattice(seed: u64, x: i64, y: i64, z: i64) -> f32 {
    let h = mix64(mix64(mix64(seed ^ x as u64) ^ y as u64) ^ z as u64);
    (h >> 40) as f32 / (1u64 << 24) as f32
}

fn smooth(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

fn lerp(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

/// Value noise in [0, 1) at a 3D point; lattice coordinates wrap with the given periods (0 = no wrap), so
/// 2D textures made from it tile seamlessly.
fn value_noise(seed: u64, p: [f32; 3], period: [i64; 3]) -> f32 {
    let cell = p.map(|v| v.floor());
    let f = [0, 1, 2].map(|i| smooth(p[i] - cell[i]));
    let corner = |dx: i64, dy: i64, dz: i64| {
        let c = [cell[0] as i64 + dx, cell[1] as i64 + dy, cell[2] as i64 + dz];
        let w = [0, 1, 2].map(|i| if period[i] > 0 { c[i].rem_euclid(period[i]) } else { c[i] });
        lattice(seed, w[0], w[1], w[2])
    };
    let x00 = lerp(corner(0, 0, 0), corner(1, 0, 0), f[0]);
    let x10 = lerp(corner(0, 1, 0), corner(1, 1, 0), f[0]);
    let x01 = lerp(corner(0, 0, 1), corner(1, 0, 1), f[0]);
    let x11 = lerp(corner(0, 1, 1), corner(1, 1, 1), f[0]);
    lerp(lerp(x00, x10, f[1]), lerp(x01, x11, f[1]), f[2])
}

/// Fractal sum of `octaves` layers of value noise, each twice the frequency and half the amplitude of the
/// one before; in [0, 1).
fn fbm(seed: u64, p: [f32; 3], period: [i64; 3], octaves: u32) -> f32 {
    let (mut sum, mut amp, mut norm, mut freq) = (0.0, 1.0, 0.0, 1.0);
    for o in 0..octaves {
        let q = p.map(|v| v * freq);
        let per = period.map(|n| n * freq as i64);
        sum += amp * value_noise(seed.wrapping_add(o as u64), q, per);
        norm += amp;
        amp *= 0.5;
        freq *= 2.0;
    }
    sum / norm
}

fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [0, 1, 2].map(|i| lerp(a[i], b[i], t.clamp(0.0, 1.0)))
}

fn to_rgb(c: [f32; 3]) -> Rgb<u8> {
    Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8))
}

/// Floor tiles: a 4 x 4 block of stone tiles of slightly different tints with mottled surfaces and grout
/// lines; tiles seamlessly.
pub fn floor_tiles() -> RgbImage {
    const N: u32 = 512;
    const TILES: u32 = 4;
    let tile = N / TILES;
    RgbImage::from_fn(N, N, |x, y| {
        let (tx, ty) = (x / tile, y / tile);
        let (lx, ly) = (x % tile, y % tile);
        let edge = lx.min(ly).min(tile - 1 - lx).min(tile - 1 - ly) as f32;
        let (u, v) = (x as f32 / N as f32, y as f32 / N as f32);
        let grain = fbm(11, [u * 16.0, v * 16.0, 0.0], [16, 16, 0], 5);
        if edge < 3.0 {
            let g = 0.30 + 0.08 * grain;
            return to_rgb([g, g * 0.97, g * 0.92]);
        }
        let tint = lattice(7, tx as i64, ty as i64, 0);
        let base = mix([0.78, 0.70, 0.58], [0.62, 0.52, 0.42], tint);
        let veins = fbm(5, [u * 6.0, v * 6.0, tint * 10.0], [6, 6, 0], 4);
        let vein = (1.0 - ((veins - 0.5).abs() * 18.0).min(1.0)) * 0.18;
        let bevel = (edge / 8.0).min(1.0) * 0.12 + 0.88;
        let c = mix(base, [0.95, 0.92, 0.86], vein).map(|v| v * (0.85 + 0.3 * grain) * bevel);
        to_rgb(c)
    })
}

/// Wood: planks along u with growth rings and fine grain; tiles seamlessly.
pub fn wood() -> RgbImage {
    const N: u32 = 512;
    const PLANKS: u32 = 4;
    RgbImage::from_fn(N, N, |x, y| {
        let (u, v) = (x as f32 / N as f32, y as f32 / N as f32);
        let plank = (v * PLANKS as f32).floor();
        let pv = v * PLANKS as f32 - plank;
        // Each plank is cut from a different log: its own ring centre and offset.
        let off = lattice(3, plank as i64, 0, 0);
        let warp = fbm(17, [u * 4.0, pv * 2.0, plank], [4, 0, 0], 4);
        let r = ((pv - 0.5 - off * 0.8) * 9.0).abs() + warp * 2.5 + (2.0 * PI * (u + off)).sin() * 0.3;
        let rings = (r * 2.0).fract();
        let ring = smooth((rings * 2.0 - 1.0).abs());
        let grain = fbm(23, [u * 64.0, pv * 4.0, plank], [64, 0, 0], 3);
        let light = [0.72, 0.50, 0.30];
        let dark = [0.45, 0.27, 0.14];
        let mut c = mix(dark, light, ring * 0.8 + grain * 0.4 - 0.1);
        let seam = (pv.min(1.0 - pv) * N as f32 / PLANKS as f32) < 1.5;
        if seam {
            c = c.map(|v| v * 0.45);
        }
        to_rgb(c.map(|v| v * (0.9 + 0.2 * off)))
    })
}

/// A planet in equirectangular projection (2:1, longitude across, latitude down): oceans, coasts,
/// lowlands, mountains and ice caps from 3D noise on the sphere, so there is no seam at the date line.
pub fn world() -> RgbImage {
    const W: u32 = 1024;
    const H: u32 = 512;
    RgbImage::from_fn(W, H, |x, y| {
        let lon = (x as f32 + 0.5) / W as f32 * 2.0 * PI;
        let lat = PI * 0.5 - (y as f32 + 0.5) / H as f32 * PI;
        let p = [lat.cos() * lon.cos(), lat.sin(), lat.cos() * lon.sin()];
        let q = p.map(|v| v * 2.2 + 8.0);
        let height = fbm(42, q, [0; 3], 7);
        let moisture = fbm(99, q.map(|v| v * 1.7), [0; 3], 4);
        let polar = lat.abs() / (PI * 0.5);
        let sea = 0.52;
        let c = if polar + (height - 0.5) * 0.4 > 0.86 {
            [0.93, 0.95, 0.97]
        } else if height < sea {
            let depth = (sea - height) / sea;
            mix([0.16, 0.45, 0.62], [0.05, 0.16, 0.38], depth * 2.5)
        } else {
            let h = (height - sea) / (1.0 - sea);
            let land = mix([0.20, 0.45, 0.15], [0.70, 0.62, 0.35], (1.0 - moisture) * 1.6 - 0.3);
            let land = mix(land, [0.45, 0.38, 0.30], h * 2.5 - 0.5);
            mix(land, [0.85, 0.85, 0.85], h * 4.0 - 2.6)
        };
        to_rgb(c)
    })
}

/// An 8 x 8 checker of two colours: so small that every texel is visible when magnified, which shows
/// the difference between nearest and bilinear filtering.
pub fn checker8() -> RgbImage {
    RgbImage::from_fn(8, 8, |x, y| if (x + y) % 2 == 0 { Rgb([230, 225, 210]) } else { Rgb([40, 90, 160]) })
}

/// The blend mask of the `layered` example's panel (slide "Пример за текстура"): white where the panel is a
/// mirror, black where its textured lower layer shows. One disc or ring in each cell of a 4 x 4 grid (the
/// grid of `floor_tiles`), alternating like a checkerboard, with edges one texel soft.
pub fn mirror_mask() -> RgbImage {
    const N: u32 = 256;
    const CELLS: u32 = 4;
    let cell = (N / CELLS) as f32;
    RgbImage::from_fn(N, N, |x, y| {
        let (dx, dy) = ((x as f32 + 0.5) % cell - cell * 0.5, (y as f32 + 0.5) % cell - cell * 0.5);
        let d = dx.hypot(dy);
        // Coverage of "inside radius r", soft over one texel.
        let inside = |r: f32| (r * cell - d + 0.5).clamp(0.0, 1.0);
        let ring = (x / cell as u32 + y / cell as u32) % 2 == 1;
        let m = if ring { inside(0.40) - inside(0.26) } else { inside(0.36) };
        to_rgb([m; 3])
    })
}

/// The reflection colours of the `layered` example's metal sphere (a texture driving a property other than
/// the diffuse colour): bands of gold, silver and copper across v, brushed along u, with dark grooves between
/// them. The colours are the metals' reflectances at normal incidence.
pub fn metals() -> RgbImage {
    const N: u32 = 256;
    const BANDS: u32 = 8;
    let gold = [1.0, 0.89, 0.61];
    let silver = [0.98, 0.97, 0.95];
    let copper = [0.98, 0.82, 0.76];
    RgbImage::from_fn(N, N, |x, y| {
        let (u, v) = (x as f32 / N as f32, y as f32 / N as f32);
        let band = (v * BANDS as f32).floor() as u32;
        let bv = v * BANDS as f32 - band as f32;
        let metal = [gold, silver, copper][(band % 3) as usize];
        let brushed = 0.9 + 0.1 * fbm(31, [u * 64.0, v * 2.0, band as f32], [64, 0, 0], 3);
        let groove = bv.min(1.0 - bv) * ((N / BANDS) as f32) < 2.0;
        to_rgb(metal.map(|c| if groove { 0.25 } else { c * brushed }))
    })
}
