//! The ray-triangle test of the mesh ([`Mesh`](super::Mesh)), four triangles at a time. Not on the slides,
//! which test one triangle at a time; the arithmetic is the same, lane by lane.
//!
//! - The test: the watertight test of Woop, Benthin and Wald ("Watertight Ray/Triangle Intersection",
//!   JCGT 2013). The vertices are moved into a frame where the ray runs along +z from the origin
//!   ([`ShearedRay`]), and the 2D edge functions decide the hit. Every vertex is transformed the same way
//!   whichever triangle it belongs to, and an edge function that rounds to exactly zero is recomputed in
//!   double precision, edge by edge (the paper and pbrt recompute all three, which lets two neighbours
//!   evaluate their shared edge differently), so a ray through a shared edge or vertex always hits one of
//!   the triangles around it: no cracks. A hit closer than the bound on the rounding error of its `t`
//!   (pbrt-v4, section 6.8.6) is rejected, so a shadow or reflected ray never finds the triangle it starts
//!   on.
//! - Four at once: a [`Triangle4`] stores four triangles coordinate by coordinate (lane `i` of each
//!   `Vec4` belongs to triangle `i`), so each step of the test is one SIMD operation for all four (glam's
//!   `Vec4`: SSE2 on x86_64, plain scalar code on other targets). Lane `i` performs exactly the operations
//!   the one-triangle test would, in the same order, so the hits are the same to the last bit. The BVH
//!   leaves of a mesh hold whole `Triangle4`s; a lane with no triangle has NaN corners, which every
//!   comparison of the test rejects.

use crate::lesson::math::Vector;
use crate::lesson::math::gamma;
use crate::lesson::ray::Ray;
use glam::{BVec4A, Vec4};

/// Triangles in a [`Triangle4`].
pub const LANES: usize = 4;

/// Four triangles, coordinate by coordinate; see the module documentation.
#[derive(Clone, Copy, Debug)]
pub struct Triangle4 {
    /// `corners[v][k]`: coordinate `k` (x, y, z) of corner `v` of the four triangles.
    corners: [[Vec4; 3]; 3],
}

impl Triangle4 {
    /// Up to four triangles; the lanes left over hold none.
    pub fn new(triangles: &[[Vector; 3]]) -> Triangle4 {
        assert!(triangles.len() <= LANES, "a Triangle4 holds at most {LANES} triangles");
        let mut corners = [[Vec4::NAN; 3]; 3];
        for (lane, tri) in triangles.iter().enumerate() {
            for (v, corner) in tri.iter().enumerate() {
                (0..3).for_each(|k| corners[v][k][lane] = corner[k]);
            }
        }
        Triangle4 { corners }
    }

    /// The triangle in `lane`, or `None` when the lane holds none.
    pub fn get(&self, lane: usize) -> Option<[Vector; 3]> {
        let tri = self.corners.map(|c| Vector::new(c[0][lane], c[1][lane], c[2][lane]));
        (!tri[0].is_nan()).then_some(tri)
    }
}

/// The ray in the frame of the watertight test: translated to the origin, its largest direction component
/// made the z axis, and sheared so that it runs along +z. Made once per ray.
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay {
    /// The ray's start, each coordinate in all four lanes.
    start: [Vec4; 3],
    /// The axes that become x, y and z of the sheared frame (z: the direction's largest component).
    axes: [usize; 3],
    /// The shear, in all four lanes: a point relative to the start goes to
    /// (p[kx] - sx p[kz], p[ky] - sy p[kz], sz p[kz]).
    sx: Vec4,
    sy: Vec4,
    sz: Vec4,
    /// |dir[kz]|: turns the sheared z (in units of the ray parameter) back into lengths, for the error bounds.
    z_length: f32,
}

/// What [`ShearedRay::hit`] found in the four lanes of a [`Triangle4`].
#[derive(Clone, Copy, Debug)]
pub struct Hits4 {
    /// Bit `i` is set when triangle `i` is hit within the `t_max` the test was given.
    pub lanes: u32,
    /// The ray parameter of each lane's hit.
    t: Vec4,
    /// The scaled parameter and determinant the range test compares (the hit is at `t_scaled / det`).
    t_scaled: Vec4,
    det: Vec4,
    /// The three edge functions and 1 / det: the barycentric coordinates are `e_i / det`.
    edges: [Vec4; 3],
    inv_det: Vec4,
}

impl Hits4 {
    /// No lane hit.
    const NONE: Hits4 = Hits4 {
        lanes: 0,
        t: Vec4::ZERO,
        t_scaled: Vec4::ZERO,
        det: Vec4::ZERO,
        edges: [Vec4::ZERO; 3],
        inv_det: Vec4::ZERO,
    };

    /// Lanes hit, in order (none for a miss).
    pub fn lanes(&self) -> impl Iterator<Item = usize> + use<> {
        let mut bits = self.lanes;
        std::iter::from_fn(move || {
            let lane = (bits != 0).then(|| bits.trailing_zeros() as usize)?;
            bits &= bits - 1;
            Some(lane)
        })
    }

    /// Whether the hit in `lane` passes the range test for a smaller `t_max` (a closer hit found since):
    /// exactly the test the one-triangle version would have made with it.
    pub fn before(&self, lane: usize, t_max: f32) -> bool {
        let (t_scaled, det) = (self.t_scaled[lane], self.det[lane]);
        if det > 0.0 { t_scaled < t_max * det } else { t_scaled > t_max * det }
    }

    /// The ray parameter and the barycentric coordinates of the hit in `lane`.
    pub fn get(&self, lane: usize) -> (f32, [f32; 3]) {
        (self.t[lane], self.edges.map(|e| e[lane] * self.inv_det[lane]))
    }
}

impl ShearedRay {
    /// The sheared frame of `ray`, made once before the ray meets any triangles.
    pub fn new(ray: &Ray) -> ShearedRay {
        let d = ray.dir;
        let abs = d.abs();
        let kz = if abs.x > abs.y {
            if abs.x > abs.z { 0 } else { 2 }
        } else if abs.y > abs.z {
            1
        } else {
            2
        };
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        // Keep the winding (and so the sign of the edge functions) of a right-handed frame.
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        ShearedRay {
            start: [0, 1, 2].map(|k| Vec4::splat(ray.start[k])),
            axes: [kx, ky, kz],
            sx: Vec4::splat(d[kx] / d[kz]),
            sy: Vec4::splat(d[ky] / d[kz]),
            sz: Vec4::splat(1.0 / d[kz]),
            z_length: d[kz].abs(),
        }
    }

    /// Corner `corner` of the four triangles in the sheared frame: x, y, z.
    #[inline(always)]
    fn transform(&self, corner: &[Vec4; 3]) -> [Vec4; 3] {
        let [kx, ky, kz] = self.axes;
        let relative = |k: usize| corner[k] - self.start[k];
        let z = relative(kz);
        [relative(kx) - self.sx * z, relative(ky) - self.sy * z, self.sz * z]
    }

    /// The watertight test of the four triangles: which are hit with a ray parameter in (0, `t_max`).
    #[inline(always)]
    pub fn hit(&self, tris: &Triangle4, t_max: f32) -> Hits4 {
        let [a, b, c] = tris.corners.each_ref().map(|corner| self.transform(corner));
        let edges = [edge(b, c), edge(c, a), edge(a, b)];
        let [e0, e1, e2] = edges;
        let zero = Vec4::ZERO;
        // Inside when no edge function is negative or none is positive (the ray may meet either side).
        let negative = e0.cmplt(zero) | e1.cmplt(zero) | e2.cmplt(zero);
        let positive = e0.cmpgt(zero) | e1.cmpgt(zero) | e2.cmpgt(zero);
        let det = e0 + e1 + e2;
        let t_scaled = e0 * a[2] + e1 * b[2] + e2 * c[2];
        // t = t_scaled / det in (0, t_max), tested without the division; a NaN (a degenerate ray, an empty
        // lane) fails every comparison, so it is a miss.
        let limit = Vec4::splat(t_max) * det;
        let front = det.cmpgt(zero) & t_scaled.cmpgt(zero) & t_scaled.cmplt(limit);
        let back = det.cmplt(zero) & t_scaled.cmplt(zero) & t_scaled.cmpgt(limit);
        let candidates = (!(negative & positive) & (front | back)).bitmask();
        if candidates == 0 {
            return Hits4::NONE;
        }
        let inv_det = Vec4::ONE / det;
        let t = t_scaled * inv_det;
        // Reject hits within the rounding error of t (pbrt-v4, section 6.8.6).
        let max_abs = |k: usize| a[k].abs().max(b[k].abs()).max(c[k].abs());
        let (max_x, max_y, max_z) = (max_abs(0), max_abs(1), max_abs(2));
        let delta_z = Vec4::splat(gamma(3)) * max_z;
        // The shear's rounding in x and y scales with the lengths involved, so z enters as a length, not in
        // units of the ray parameter: a direction that is not of unit length (a ray brought into the
        // canonical space of a node scaled by 1e4) must not inflate these bounds until every hit is rejected.
        let max_z_length = max_z * self.z_length;
        let delta_x = Vec4::splat(gamma(5)) * (max_x + max_z_length);
        let delta_y = Vec4::splat(gamma(5)) * (max_y + max_z_length);
        let delta_e = Vec4::splat(2.0) * (Vec4::splat(gamma(2)) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let max_e = e0.abs().max(e1.abs()).max(e2.abs());
        let delta_t = Vec4::splat(3.0)
            * (Vec4::splat(gamma(3)) * max_e * max_z + delta_e * max_z + delta_z * max_e)
            * inv_det.abs();
        let lanes = candidates & t.cmpgt(delta_t).bitmask();
        Hits4 { lanes, t, t_scaled, det, edges, inv_det }
    }
}

/// The edge function of the edge from `p` to `q` in each lane (twice the signed area of the origin, `p`
/// and `q` in the sheared frame's xy plane). Where it rounds to exactly zero it is recomputed in double
/// precision, where the products are exact. The decision depends on the edge alone, so the two triangles
/// that share an edge always compute the same value (with opposite signs), and a ray cannot pass between
/// them.
#[inline(always)]
fn edge(p: [Vec4; 3], q: [Vec4; 3]) -> Vec4 {
    let mut e = p[0] * q[1] - p[1] * q[0];
    let exact_zero: BVec4A = e.cmpeq(Vec4::ZERO);
    if exact_zero.any() {
        for lane in (0..LANES).filter(|&lane| exact_zero.test(lane)) {
            let [px, py, qx, qy] = [p[0], p[1], q[0], q[1]].map(|v| v[lane] as f64);
            e[lane] = (px * qy - py * qx) as f32;
        }
    }
    e
}

/// The watertight ray-triangle test on one triangle: the ray parameter of the hit in (0, `t_max`), if
/// any. The mesh uses exactly this test; it is public so that tests can compare the BVH with brute force.
pub fn intersect_triangle(ray: &Ray, tri: &[Vector; 3], t_max: f32) -> Option<f32> {
    let hits = ShearedRay::new(ray).hit(&Triangle4::new(&[*tri]), t_max);
    hits.lanes().next().map(|lane| hits.get(lane).0)
}
