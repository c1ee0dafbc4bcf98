//! Triangulation of OBJ polygons (non-convex faces cut in their plane), the faceted default for meshes
//! without normals, and the OBJ file errors.

use crate::common;

use lecture6::Vector;
use lecture6::lesson::geometry::polygon::{newell_normal, triangulate};
use lecture6::lesson::geometry::{Geometry, Mesh};
use lecture6::lesson::ray::Ray;

/// A star with `points` tips (radii 1 and 0.4), in the plane z = 0.
fn star(points: usize) -> Vec<Vector> {
    (0..2 * points)
        .map(|i| {
            let a = i as f32 * std::f32::consts::PI / points as f32;
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            Vector::new(r * a.cos(), r * a.sin(), 0.0)
        })
        .collect()
}

/// A comb: a spine along the bottom with `teeth` teeth pointing up, in the plane z = 0.
fn comb(teeth: usize) -> Vec<Vector> {
    let mut c = vec![Vector::new(0.0, 0.0, 0.0), Vector::new(2.0 * teeth as f32 - 1.0, 0.0, 0.0)];
    for k in (0..teeth).rev() {
        let x = 2.0 * k as f32;
        c.extend([Vector::new(x + 1.0, 3.0, 0.0), Vector::new(x, 3.0, 0.0)]);
        if k > 0 {
            c.extend([Vector::new(x, 1.0, 0.0), Vector::new(x - 1.0, 1.0, 0.0)]);
        }
    }
    c
}

/// Whether the point p (in the plane z = 0) lies inside the polygon (even-odd rule).
fn inside(poly: &[Vector], p: Vector) -> bool {
    let mut odd = false;
    for (a, b) in poly.iter().zip(poly.iter().cycle().skip(1)) {
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            odd = !odd;
        }
    }
    odd
}

/// Rotates and moves a polygon of the plane z = 0 into a tilted plane, so that the test is not helped by
/// the polygon lying in a coordinate plane.
fn tilt(p: Vector) -> Vector {
    glam::Mat3A::from_euler(glam::EulerRot::XYZ, 0.7, -0.4, 1.1) * p + Vector::new(3.0, -2.0, 5.0)
}

fn check_polygon(name: &str, poly: &[Vector]) {
    let area = 0.5 * newell_normal(poly).length();
    let tilted: Vec<Vector> = poly.iter().map(|&p| tilt(p)).collect();
    let tris = triangulate(&tilted);
    // A simple polygon of n corners has n - 2 ears (fewer when slivers of corners on one line, such as the
    // comb's spine between its teeth, are dropped).
    assert!(!tris.is_empty() && tris.len() <= poly.len() - 2, "{name}: {} triangles", tris.len());
    let normal = newell_normal(&tilted);
    let mut sum = 0.0;
    for t in &tris {
        let [a, b, c] = t.map(|i| tilted[i]);
        let n = (b - a).cross(c - a);
        assert!(n.dot(normal) > 0.0, "{name}: triangle {t:?} is wound against the polygon");
        sum += 0.5 * n.length();
        // Every triangle lies inside the polygon: its centroid and points near its corners do.
        let [a, b, c] = t.map(|i| poly[i]);
        let centroid = (a + b + c) / 3.0;
        for p in [centroid, a.lerp(centroid, 0.05), b.lerp(centroid, 0.05), c.lerp(centroid, 0.05)] {
            assert!(inside(poly, p), "{name}: triangle {t:?} {:?} reaches outside the polygon at {p}", [a, b, c]);
        }
    }
    assert!((sum - area).abs() <= 1e-4 * area, "{name}: the triangles cover {sum}, the polygon {area}");
}

#[test]
fn star_and_comb_polygons_are_covered_exactly_by_triangles_inside_them() {
    for points in [5, 6, 9] {
        check_polygon(&format!("{points}-point star"), &star(points));
    }
    for teeth in [2, 4, 7] {
        check_polygon(&format!("comb of {teeth} teeth"), &comb(teeth));
    }
    // The fan from the first corner, which the course uses, covers more than the polygon: the test above
    // would catch it.
    let s = star(6);
    let fan: f32 = (1..s.len() - 1).map(|i| 0.5 * (s[i] - s[0]).cross(s[i + 1] - s[0]).length()).sum();
    assert!(fan > 1.2 * 0.5 * newell_normal(&s).length(), "the fan of a star overlaps itself");
}

/// An OBJ file with one face: the polygon `corners`, optionally with a normal at every corner.
fn obj(corners: &[Vector], with_normals: bool) -> String {
    let mut text: String = corners.iter().map(|c| format!("v {} {} {}\n", c.x, c.y, c.z)).collect();
    if with_normals {
        text += "vn 0 0 1\n";
    }
    text += "f";
    for i in 1..=corners.len() {
        text += &if with_normals { format!(" {i}//1") } else { format!(" {i}") };
    }
    text + "\n"
}

#[test]
fn an_obj_polygon_is_hit_only_inside_it() {
    let poly = comb(4);
    let path = common::temp_file("polygon-tests", "comb.obj", &obj(&poly, false));
    let mesh = Mesh::load(&path).unwrap();
    let mut hits = 0;
    for i in 0..70 {
        for j in 0..30 {
            let p = Vector::new(i as f32 * 0.1 + 0.05, j as f32 * 0.1 + 0.05, 0.0);
            let hit = mesh.intersect(&Ray::new(p - Vector::Z, Vector::Z), f32::INFINITY).is_some();
            assert_eq!(hit, inside(&poly, p), "at {p}");
            hits += hit as u32;
        }
    }
    assert!(hits > 0);
}

#[test]
fn a_mesh_without_normals_is_faceted_unless_auto_smooth() {
    // A tent: two triangles meeting at a ridge, no normals in the file.
    let text = "v -1 0 0\nv 0 1 1\nv 0 -1 1\nv 1 0 0\nf 1 2 3\nf 3 2 4\n";
    let path = common::temp_file("polygon-tests", "tent.obj", text);
    let ray = Ray::new(Vector::new(-0.4, 0.0, -2.0), Vector::Z);
    let faceted = Mesh::load(&path).unwrap().intersect(&ray, f32::INFINITY).unwrap();
    let face = faceted.geometric_normal;
    assert!(faceted.normal.dot(face) > 1.0 - 1e-6, "faceted by default: {} vs {face}", faceted.normal);
    let smooth = Mesh::load_auto_smooth(&path, true).unwrap().intersect(&ray, f32::INFINITY).unwrap();
    assert!(smooth.normal.dot(face) < 0.999, "auto smooth interpolates vertex normals: {}", smooth.normal);
    // A file with normals stays smooth, whatever auto_smooth says.
    let tri = [Vector::new(-1.0, -1.0, 0.0), Vector::new(1.0, -1.0, 0.0), Vector::new(0.0, 1.0, 0.0)];
    let text = obj(&tri, false) + "vn 1 0 1\nvn -1 0 1\nvn 0 0 1\n";
    let text = text.replace("f 1 2 3", "f 1//1 2//2 3//3");
    let path = common::temp_file("polygon-tests", "normals.obj", &text);
    let h = Mesh::load(&path).unwrap().intersect(&Ray::new(Vector::new(-0.5, -0.5, -1.0), Vector::Z), 9.0).unwrap();
    assert!(h.normal.x.abs() > 0.05, "the file's normals are used: {}", h.normal);
}

#[test]
fn obj_errors_say_why() {
    let err = |path: &std::path::Path| Mesh::load(path).unwrap_err().to_string();
    // A missing file: the OS error.
    let e = err(std::path::Path::new("no/such/mesh.obj"));
    assert!(e.contains("no/such/mesh.obj") && e.contains("No such file"), "{e}");
    // A malformed one: the line.
    let path = common::temp_file("polygon-tests", "bad.obj", "# a mesh\nv 0 0 0\nv 1 0 0\nv 0 x 0\nf 1 2 3\n");
    let e = err(&path);
    assert!(e.contains("bad.obj") && e.contains("line 4"), "{e}");
    // A folder, an image.
    let folder = common::root().join("textures");
    assert!(err(&folder).contains("folder"), "{}", err(&folder));
    let image = common::root().join("textures/wood.png");
    assert!(err(&image).contains("image"), "{}", err(&image));
}

#[test]
fn a_face_that_comes_back_to_a_corner_is_cut_into_its_loops() {
    use lecture6::lesson::geometry::polygon::simple_loops;
    let p = |x: f32, y: f32| Vector::new(x, y, 0.0);
    // Round one triangle three times: one loop, one triangle.
    let triangle = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)];
    let thrice: Vec<Vector> = triangle.iter().cycle().take(9).copied().collect();
    assert_eq!(simple_loops(&thrice), vec![vec![0, 1, 2]]);
    assert_eq!(triangulate(&thrice).len(), 1);
    // A figure eight through the origin: two squares, each triangulated on its own (the second starts
    // at the first corner, where the walk came back).
    let eight =
        [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.0, 0.0), p(-1.0, 0.0), p(-1.0, -1.0), p(0.0, -1.0)];
    assert_eq!(simple_loops(&eight), vec![vec![0, 1, 2, 3], vec![0, 5, 6, 7]]);
    assert_eq!(triangulate(&eight).len(), 4);
    // A polygon of distinct corners is one loop, as it is.
    assert_eq!(simple_loops(&star(5)), vec![(0..10).collect::<Vec<_>>()]);
}
