//! Linear RGB colour (lectures 1-6: `Color`), and the sRGB transfer function used when images are read and
//! written.
//!
//! All shading happens in *linear* light: adding two colours or scaling one by a light's intensity is
//! physically meaningful only there. 8-bit images (textures, the PNG output) store sRGB-encoded values,
//! so bitmap texels are decoded with [`srgb_to_linear`] (through a table of the 256 codes, when each texel is
//! read: see [`crate::lesson::bitmap`]) and the frame is encoded with [`linear_to_srgb`] when written.
//!
//! Deviation from the course: its lecture-6 program applies no curve at all, reading and writing the codes as
//! light; `--encoding raw` renders its way ([`crate::files::encoding`]) (ledger: `srgb-output`).

use glam::Vec3A;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Sub};

/// A linear RGB colour. Components are usually in [0, 1] but may exceed 1 (bright lights, HDR environments).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Color(pub Vec3A);

impl Color {
    /// Black: no light (0, 0, 0).
    pub const BLACK: Color = Color(Vec3A::ZERO);
    /// White: (1, 1, 1), the colour that leaves light unchanged when it multiplies it.
    pub const WHITE: Color = Color(Vec3A::ONE);

    /// A colour from its linear red, green and blue channels (not sRGB-encoded values).
    pub const fn new(r: f32, g: f32, b: f32) -> Color {
        Color(Vec3A::new(r, g, b))
    }
    /// A grey colour with all three channels equal to `v`.
    pub const fn gray(v: f32) -> Color {
        Color(Vec3A::splat(v))
    }
    /// The red channel, linear.
    pub fn r(self) -> f32 {
        self.0.x
    }
    /// The green channel, linear.
    pub fn g(self) -> f32 {
        self.0.y
    }
    /// The blue channel, linear.
    pub fn b(self) -> f32 {
        self.0.z
    }
    /// The channels as `[r, g, b]`, linear.
    pub fn to_array(self) -> [f32; 3] {
        self.0.to_array()
    }
    /// The largest of the three channels: how much a colour can still change a result.
    pub fn max_channel(self) -> f32 {
        self.0.max_element()
    }
    /// Rec. 709 luminance of linear RGB.
    pub fn luminance(self) -> f32 {
        self.0.dot(Vec3A::new(0.2126, 0.7152, 0.0722))
    }
    /// True when no channel is NaN or infinite.
    pub fn is_finite(self) -> bool {
        self.0.is_finite()
    }
    /// True when every channel is exactly zero.
    pub fn is_black(self) -> bool {
        self.0 == Vec3A::ZERO
    }
    /// Replaces NaN and negative channels by zero and infinities by `f32::MAX`, so that one broken sample
    /// can never poison a pixel average.
    pub fn sanitized(self) -> Color {
        // `v >= 0` is false for NaN and for negative channels alike.
        Color(Vec3A::select(self.0.cmpge(Vec3A::ZERO), self.0, Vec3A::ZERO).min(Vec3A::splat(f32::MAX)))
    }
}

impl Add for Color {
    type Output = Color;
    fn add(self, o: Color) -> Color {
        Color(self.0 + o.0)
    }
}
impl AddAssign for Color {
    fn add_assign(&mut self, o: Color) {
        self.0 += o.0;
    }
}
impl Sub for Color {
    type Output = Color;
    fn sub(self, o: Color) -> Color {
        Color(self.0 - o.0)
    }
}
impl Mul for Color {
    type Output = Color;
    fn mul(self, o: Color) -> Color {
        Color(self.0 * o.0)
    }
}
impl MulAssign for Color {
    fn mul_assign(&mut self, o: Color) {
        self.0 *= o.0;
    }
}
impl Mul<f32> for Color {
    type Output = Color;
    fn mul(self, s: f32) -> Color {
        Color(self.0 * s)
    }
}
impl MulAssign<f32> for Color {
    fn mul_assign(&mut self, s: f32) {
        self.0 *= s;
    }
}
impl Div<f32> for Color {
    type Output = Color;
    fn div(self, s: f32) -> Color {
        Color(self.0 / s)
    }
}

/// The sRGB electro-optical transfer function: an encoded value in [0, 1] to linear light.
pub fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.04045 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
}

/// Linear light to an sRGB-encoded value; the input is clamped to [0, 1] first.
pub fn linear_to_srgb(v: f32) -> f32 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    if v <= 0.003_130_8 { v * 12.92 } else { 1.055 * v.powf(1.0 / 2.4) - 0.055 }
}

/// The 256 linear values of the 8-bit sRGB codes, so texture decoding is a table look-up.
pub fn srgb8_to_linear_table() -> &'static [f32; 256] {
    use std::sync::OnceLock;
    static TABLE: OnceLock<[f32; 256]> = OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|i| srgb_to_linear(i as f32 / 255.0)))
}

/// The 256 values of the 8-bit codes read as the course's lecture-6 program reads them: the code over 255
/// as the light itself ([`Encoding::Raw`](crate::files::encoding::Encoding::Raw)).
pub fn raw8_to_linear_table() -> &'static [f32; 256] {
    use std::sync::OnceLock;
    static TABLE: OnceLock<[f32; 256]> = OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|i| i as f32 / 255.0))
}

/// Encodes a linear colour as three 8-bit sRGB codes (round to nearest): a channel's code is the number of
/// codes whose lower edge ([`srgb8_edges`]) it reaches, the same code as [`srgb8_code`] gives, found by a
/// binary search instead of a `powf` per channel.
#[inline]
pub fn to_srgb8(c: Color) -> [u8; 3] {
    let edges = srgb8_edges();
    let [r, g, b] = c.to_array();
    [code_reached(edges, r), code_reached(edges, g), code_reached(edges, b)]
}

/// How many of the `edges` `v` reaches: a binary search of eight steps without branches (the next half is
/// picked by a conditional move), written out so that it is inlined into the loop over a frame's pixels.
/// NaN reaches no edge (code 0), as `linear_to_srgb` maps it to 0.
#[inline(always)]
fn code_reached(edges: &[f32; 255], v: f32) -> u8 {
    // The last edge reached is at `base` or in the `size - 1` after it, if any is reached at all.
    let (mut base, mut size) = (0, edges.len());
    while size > 1 {
        let half = size / 2;
        base = if edges[base + half] <= v { base + half } else { base };
        size -= half;
    }
    (base + usize::from(edges[base] <= v)) as u8
}

/// The 8-bit sRGB code of the linear value `v`, rounded to nearest, by the formula: what [`to_srgb8`] gives.
pub fn srgb8_code(v: f32) -> u8 {
    (linear_to_srgb(v) * 255.0 + 0.5) as u8
}

/// For each code from 1 to 255, the smallest linear value that [`srgb8_code`] encodes to it or above: where
/// the codes step up. Found once by bisection over the floats from 0 to 1 (positive floats are ordered as
/// their bit patterns are), from the formula itself, so that the codes are the formula's.
pub fn srgb8_edges() -> &'static [f32; 255] {
    use std::sync::OnceLock;
    static EDGES: OnceLock<[f32; 255]> = OnceLock::new();
    EDGES.get_or_init(|| {
        std::array::from_fn(|i| {
            let code = i as u8 + 1;
            // Code 0 at 0, 255 at 1: the edge lies above `below` and at or below `at`.
            let (mut below, mut at) = (0f32.to_bits(), 1f32.to_bits());
            while at - below > 1 {
                let mid = below + (at - below) / 2;
                if srgb8_code(f32::from_bits(mid)) >= code { at = mid } else { below = mid }
            }
            f32::from_bits(at)
        })
    })
}
