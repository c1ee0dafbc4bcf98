use lecture6::prelude::*;

/// A finite cylinder in its canonical form: radius 1 around the y axis, from y = -1 to y = 1, closed by two
/// caps. A node's transform makes any other cylinder of it.
pub struct Cylinder;

impl Geometry for Cylinder {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        let (o, d) = (ray.start, ray.dir); // d is not unit here: the node's transform scales it
        let mut hit: Option<IntersectionInfo> = None;
        // The side, x^2 + z^2 = 1: a t^2 + 2 b t + c = 0, its nearer root first.
        let (a, b, c) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - 1.0);
        let discriminant = b * b - a * c;
        if a > 0.0 && discriminant >= 0.0 {
            for t in [(-b - discriminant.sqrt()) / a, (-b + discriminant.sqrt()) / a] {
                let p = ray.at(t);
                if t > 0.0 && t < t_max && p.y.abs() <= 1.0 {
                    // Put the point back on the surface: ray.at(t) is off it by the rounding of t.
                    let normal = Vector::new(p.x, 0.0, p.z).normalize();
                    let u = 0.5 + normal.x.atan2(normal.z) / std::f32::consts::TAU;
                    let on_surface = Vector::new(normal.x, p.y, normal.z);
                    hit = Some(IntersectionInfo::new(on_surface, normal, t, (u, (p.y + 1.0) / 2.0)));
                    break;
                }
            }
        }
        // The caps, y = 1 and y = -1, where they are nearer than the side.
        for y in [1.0, -1.0] {
            let t = (y - o.y) / d.y;
            let p = ray.at(t);
            if t > 0.0 && t < hit.map_or(t_max, |h| h.distance) && p.x * p.x + p.z * p.z <= 1.0 {
                let uv = ((p.x + 1.0) / 2.0, (p.z + 1.0) / 2.0);
                hit = Some(IntersectionInfo::new(Vector::new(p.x, y, p.z), Vector::new(0.0, y, 0.0), t, uv));
            }
        }
        hit
    }

    fn bounds(&self) -> Option<Aabb> {
        Some(Aabb::new(Vector::splat(-1.0), Vector::splat(1.0)))
    }
}
