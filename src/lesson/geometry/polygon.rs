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
//! A face that comes back to a corner it has already visited (`f 1 2 3 1 2 3 ...`, or two corners at one
//! position) is not a simple polygon, and ear clipping, which expects one, can take cubic time on it. It is
//! first cut, in linear time, into the loops that run from a corner back to it ([`simple_loops`]); each
//! loop is triangulated on its own, and a loop that repeats one already cut is dropped.
//!
//! Deviation from the course: the course fan-triangulates; for convex polygons both give the same surface
//! (though not the same triangles) (ledger: `ear-clipping`).

use crate::lesson::math::{Vector, gamma, max_abs};
use std::collections::{HashMap, HashSet};

/// The corners of a planar polygon, cut into triangles: index triples into `corners`, each wound as the
/// polygon is. A triangle (three corners) is returned as it is; a degenerate polygon (all corners on a
/// line) gives no triangles, and neither do three corners on a line within a larger polygon. A polygon
/// that visits a position more than once is cut into its loops first ([`simple_loops`]): the work is
/// bounded by that of triangulating simple polygons of as many corners in all.
pub fn triangulate(corners: &[Vector]) -> Vec<[usize; 3]> {
    if corners.len() == 3 {
        return vec![[0, 1, 2]];
    }
    let mut triangles = Vec::new();
    for loop_ in simple_loops(corners) {
        let points: Vec<Vector> = loop_.iter().map(|&i| corners[i]).collect();
        triangles.extend(triangulate_simple(&points).into_iter().map(|t| t.map(|k| loop_[k])));
    }
    triangles
}

/// The position of a corner as a hashable key: its coordinates' bits, with -0 taken as +0.
fn position_key(v: Vector) -> [u32; 3] {
    [v.x, v.y, v.z].map(|c| (c + 0.0).to_bits())
}

/// The closed walk around `corners` cut into loops that visit no position twice, each as indices into
/// `corners` in the walk's order, in time linear in the number of corners: whenever the walk comes back
/// to a position it is still on, the corners since that position close a loop, which is taken out. Loops
/// of fewer than three corners, which cover nothing, are dropped, and so is a loop that repeats one taken
/// out before (the same positions in the same cyclic order): `f 1 2 3 1 2 3` is one triangle. A polygon
/// whose corners are all at different positions is one loop, as it is.
pub fn simple_loops(corners: &[Vector]) -> Vec<Vec<usize>> {
    let mut path: Vec<usize> = Vec::with_capacity(corners.len());
    let mut on_path: HashMap<[u32; 3], usize> = HashMap::with_capacity(corners.len());
    let mut loops = Vec::new();
    for (i, &corner) in corners.iter().enumerate() {
        let key = position_key(corner);
        match on_path.get(&key) {
            Some(&at) => {
                let closed: Vec<usize> = path.drain(at..).collect();
                for &j in &closed[1..] {
                    on_path.remove(&position_key(corners[j]));
                }
                // The walk goes on from the corner it came back to.
                path.push(closed[0]);
                loops.push(closed);
            }
            None => {
                on_path.insert(key, path.len());
                path.push(i);
            }
        }
    }
    loops.push(path);
    let mut seen = HashSet::new();
    loops.retain(|l| {
        if l.len() < 3 {
            return false;
        }
        // The loop's positions, starting from its smallest key: the same for every rotation of it.
        let keys: Vec<[u32; 3]> = l.iter().map(|&i| position_key(corners[i])).collect();
        let start = (0..keys.len()).min_by_key(|&k| keys[k]).unwrap_or(0);
        seen.insert([&keys[start..], &keys[..start]].concat())
    });
    loops
}

/// [`triangulate`] for a polygon that visits no position twice.
fn triangulate_simple(corners: &[Vector]) -> Vec<[usize; 3]> {
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
