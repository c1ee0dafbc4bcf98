//! A triangular `Prism`, the shape of the dispersion slide ("Хроматично пречупване"): a dispersive glass
//! prism bends short wavelengths more than long ones and fans white light out into a spectrum.
//!
//! Canonical form: an upright prism, its edges parallel to Y, from y = -`half_height` to `half_height`. Its
//! cross-section in the XZ plane is an isosceles triangle with apex angle `apex_angle` (degrees): the base,
//! 2 `half_base` long, lies along X at the low z; the apex edge is at the high z; the box around the prism is
//! centred on the origin. u follows x across the prism and v follows y up it (on the caps, v follows z).
//!
//! The prism is the intersection of five half-spaces (three side faces, two caps), so it is intersected by
//! clipping the ray against each plane, as the course's cube is by slabs.

use super::{Aabb, Geometry, Hit, IntersectionInfo};
use crate::lesson::math::{Vector, gamma, max_abs};
use crate::lesson::ray::Ray;

/// A triangular prism, upright along Y and centred on the origin (slide "Хроматично пречупване").
#[derive(Clone, Copy, Debug)]
pub struct Prism {
    /// The angle between the two faces light passes through, in degrees (60 for the classic prism).
    pub apex_angle: f32,
    /// Half the length of the base, the side opposite the apex edge (along X).
    pub half_base: f32,
    /// Half the height, along Y: the prism runs from y = -`half_height` to `half_height`.
    pub half_height: f32,
    /// The faces as planes `dot(normal, p) = offset` with outward unit normals: base, left, right, bottom, top.
    planes: [(Vector, f32); 5],
}

impl Prism {
    /// A prism with the given apex angle (degrees, in (0, 180)), half base length and half height.
    pub fn new(apex_angle: f32, half_base: f32, half_height: f32) -> Prism {
        let depth = half_base / (0.5 * apex_angle.to_radians()).tan();
        let (z_base, z_apex) = (-0.5 * depth, 0.5 * depth);
        let left = Vector::new(-depth, 0.0, half_base).normalize();
        let right = Vector::new(depth, 0.0, half_base).normalize();
        let apex = Vector::new(0.0, 0.0, z_apex);
        let planes = [
            (Vector::NEG_Z, -z_base),
            (left, left.dot(apex)),
            (right, right.dot(apex)),
            (Vector::NEG_Y, half_height),
            (Vector::Y, half_height),
        ];
        Prism { apex_angle, half_base, half_height, planes }
    }

    /// The outward unit normals of the two faces that meet at the apex (left, right).
    pub fn apex_face_normals(&self) -> (Vector, Vector) {
        (self.planes[1].0, self.planes[2].0)
    }

    fn depth(&self) -> f32 {
        self.planes[0].1.abs() * 2.0
    }

    /// Clips the ray against the five planes: the entry and exit parameters and the faces they lie on.
    fn clip(&self, ray: &Ray) -> Option<(f32, usize, f32, usize)> {
        let (mut t_in, mut face_in) = (f32::NEG_INFINITY, 0);
        let (mut t_out, mut face_out) = (f32::INFINITY, 0);
        for (i, &(n, offset)) in self.planes.iter().enumerate() {
            let towards = n.dot(ray.dir);
            let inside_by = offset - n.dot(ray.start);
            if towards == 0.0 {
                // Parallel to this face: inside its half-space for the whole ray, or never.
                if inside_by < 0.0 {
                    return None;
                }
                continue;
            }
            let t = inside_by / towards;
            if towards < 0.0 {
                if t > t_in {
                    (t_in, face_in) = (t, i);
                }
            } else if t < t_out {
                (t_out, face_out) = (t, i);
            }
        }
        (t_in <= t_out).then_some((t_in, face_in, t_out, face_out))
    }
}

impl Prism {
    /// The surface at the hit at ray parameter `t` on face `face`.
    fn info(&self, ray: &Ray, t: f32, face: usize) -> IntersectionInfo {
        let (normal, offset) = self.planes[face];
        // Project the hit onto its face, so that only the projection's rounding remains.
        let hit = ray.at(t);
        let ip = hit - (normal.dot(hit) - offset) * normal;
        let depth = self.depth();
        let u = ((ip.x + self.half_base) / (2.0 * self.half_base)).clamp(0.0, 1.0);
        let v = if face >= 3 {
            ((ip.z + 0.5 * depth) / depth).clamp(0.0, 1.0)
        } else {
            ((ip.y + self.half_height) / (2.0 * self.half_height)).clamp(0.0, 1.0)
        };
        IntersectionInfo::new(ip, normal, t, (u, v)).with_error(gamma(7) * (max_abs(ip) + offset.abs()))
    }
}

impl Geometry for Prism {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.hit(ray, t_max).and_then(|hit| self.surface(ray, &hit))
    }

    /// The ray parameter and the face hit; the point, normal and u/v wait for the winner.
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (t_in, face_in, t_out, face_out) = self.clip(ray)?;
        let (t, face) = if t_in > 0.0 { (t_in, face_in) } else { (t_out, face_out) };
        (t > 0.0 && t < t_max).then_some(Hit { part: face as u32, ..Hit::at(t) })
    }

    fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        Some(self.info(ray, hit.distance, hit.part as usize))
    }

    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.clip(ray).is_some_and(|(t_in, _, t_out, _)| {
            let t = if t_in > 0.0 { t_in } else { t_out };
            t > 0.0 && t < t_max
        })
    }

    fn bounds(&self) -> Option<Aabb> {
        let half_depth = 0.5 * self.depth();
        Some(Aabb::new(
            Vector::new(-self.half_base, -self.half_height, -half_depth),
            Vector::new(self.half_base, self.half_height, half_depth),
        ))
    }
}
