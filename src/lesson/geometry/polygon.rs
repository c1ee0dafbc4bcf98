//! Triangulating the polygons of an OBJ file: a face with more than three corners becomes triangles that
//! cover exactly the polygon, whatever its shape.
//!
//! The course (and a simple loader) cuts a polygon into a fan `(a, b, c), (a, c, d), ...`, which is right
//! only for convex polygons: the fan of a non-convex one (an extruded star, a comb) overlaps itself and
//! covers area outside the polygon. Here the polygon is projected onto its own plane (the plane of its
//! Newell normal) and cut by ear clipping, with the `earcut` crate (a port of Mapbox's earcut). Every
//! triangle keeps the polygon's winding, so its face normal points the way the polygon's does (back-face
//! tests and the side a face is lit from stay as the file says).
//!
//! Deviation from the course: the course fan-triangulates; for convex polygons both give the same surface
//! (though not the same triangles).

use crate::lesson::math::{Vector, gamma, max_abs};

/// The corners of a planar polygon, cut into triangles: index triples into `corners`, each wound as the
/// polygon is. A triangle (three corners) is returned as it is; a degenerate polygon (all corners on a
/// line) gives no triangles, and neither do three corners on a line within a larger polygon.
pub fn triangulate(corners: &[Vector]) -> Vec<[usize; 3]> {
    match corners.len() {
        0..=2 => return Vec::new(),
        3 => return vec![[0, 1, 2]],
        _ => {}
    }
    let normal = newell_normal(corners);
    let points: Vec<[f64; 3]> = corners.iter().map(|c| [c.x as f64, c.y as f64, c.z as f64]).collect();
    let mut flat = Vec::with_capacity(points.len());
    if !earcut::utils3d::project3d_to_2d(&points, points.len(), &mut flat) {
        return Vec::new();
    }
    let mut indices: Vec<usize> = Vec::new();
    earcut::Earcut::new().earcut(flat, &[], &mut indices);
    indices
        .chunks_exact(3)
        .filter_map(|t| {
            let [a, b, c] = [t[0], t[1], t[2]];
            let (ab, ac) = (corners[b] - corners[a], corners[c] - corners[a]);
            let n = ab.cross(ac);
            // Ear clipping may cut off three corners that lie on one line (the spine of a comb between
            // its teeth): a sliver with no area but the rounding of its corners, which is dropped. The
            // corners are known to `max_abs` times the f32 epsilon, which bounds the error of the cross
            // product by about that times the lengths of the two edges.
            let magnitude = max_abs(corners[a]).max(max_abs(corners[b])).max(max_abs(corners[c]));
            if n.length() <= gamma(4) * magnitude * (ab.length() + ac.length()) {
                return None;
            }
            Some(if n.dot(normal) < 0.0 { [a, c, b] } else { [a, b, c] })
        })
        .collect()
}

/// The polygon's Newell normal: twice its area times its unit normal, for any planar polygon, convex or
/// not (the sum of the cross products of consecutive corners).
pub fn newell_normal(corners: &[Vector]) -> Vector {
    let origin = corners[0];
    corners.iter().zip(corners.iter().cycle().skip(1)).map(|(&p, &q)| (p - origin).cross(q - origin)).sum()
}
