//! A mesh's triangles one by one, as the course's program tests them at this lecture (slide "Model
//! трансформация": the teapot placed anywhere): the ray against the mesh's bounding box first, then against
//! every triangle (Möller and Trumbore), keeping the closest. The step beyond it is the mesh's BVH with
//! four-wide watertight triangle tests ([`Mesh`]'s [`Geometry::hit`](super::Geometry::hit), the step
//! [`Step::MeshBvh`](crate::lesson::beyond::Step::MeshBvh)); both find the same hits.

use super::{Aabb, Geometry, Hit, Mesh};
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;

impl Mesh {
    /// The mesh's closest hit with ray parameter in (0, `t_max`), testing its triangles one by one after its
    /// box: the triangle (its slot) and the barycentric coordinates, which [`Geometry::surface`] describes.
    pub fn hit_one_by_one(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        if !self.bounds().is_some_and(|b| hits_box(&b, ray, t_max)) {
            return None;
        }
        let mut closest = None;
        let mut t_max = t_max;
        for (slot, triangle) in self.slots() {
            if let Some((t, coords)) = intersect_triangle(ray, &triangle, t_max)
                && !self.culled(slot, ray.dir)
            {
                t_max = t;
                closest = Some(Hit { distance: t, part: slot as u32, coords });
            }
        }
        closest
    }
}

/// Whether the ray meets the box before `t_max` (the slab test).
fn hits_box(b: &Aabb, ray: &Ray, t_max: f32) -> bool {
    let inverse = Vector::ONE / ray.dir;
    let (t0, t1) = ((b.min - ray.start) * inverse, (b.max - ray.start) * inverse);
    let near = t0.min(t1).max_element().max(0.0);
    let far = t0.max(t1).min_element().min(t_max);
    near <= far
}

/// The ray's hit on a triangle (Möller and Trumbore): its parameter in (0, `t_max`) and the barycentric
/// coordinates of the hit point (the weights of the three corners).
fn intersect_triangle(ray: &Ray, [a, b, c]: &[Vector; 3], t_max: f32) -> Option<(f32, [f32; 3])> {
    let (ab, ac) = (*b - *a, *c - *a);
    let p = ray.dir.cross(ac);
    let det = ab.dot(p);
    if det == 0.0 {
        return None; // the ray runs in the triangle's plane
    }
    let to_start = ray.start - *a;
    let u = to_start.dot(p) / det;
    let q = to_start.cross(ab);
    let v = ray.dir.dot(q) / det;
    let t = ac.dot(q) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < t_max).then_some((t, [1.0 - u - v, u, v]))
}
