//! Triangle meshes: the BVH finds exactly the hit brute force finds, rays through shared edges and
//! vertices never slip through, and bad, empty or degenerate OBJ files are handled without a panic or a NaN.

use crate::common;
use common::random_unit;

use lecture6::lesson::geometry::mesh::intersect_triangle;
use lecture6::lesson::geometry::{Geometry, Mesh};
use lecture6::lesson::math::Vector;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::rng::Rng;

fn teapot() -> Mesh {
    Mesh::load(&common::root().join("textures/teapot_low.obj")).expect("bundled teapot")
}

fn brute_force(mesh: &Mesh, ray: &Ray) -> Option<f32> {
    mesh.triangles().iter().filter_map(|t| intersect_triangle(ray, t, f32::INFINITY)).min_by(f32::total_cmp)
}

/// Random triangles of every size and orientation, overlapping each other.
fn soup(rng: &mut Rng, n: usize) -> Mesh {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for i in 0..n as u32 {
        let centre = (Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5) * 10.0;
        let size = 0.05 + 2.0 * rng.next_f32() * rng.next_f32();
        positions.extend((0..3).map(|_| centre + random_unit(rng) * size));
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    Mesh::new(&positions, &triangles).unwrap()
}

#[test]
fn the_bvh_finds_the_same_closest_hit_as_brute_force() {
    let mut rng = Rng::for_keys(&[3]);
    for mesh in [teapot(), soup(&mut rng, 600)] {
        let b = mesh.bounds().unwrap();
        let (centre, radius) = (b.center(), (b.max - b.min).length());
        let mut hits = 0;
        for i in 0..3000 {
            // Rays from outside towards the mesh, and from inside its box in any direction.
            let start = if i % 2 == 0 {
                centre + random_unit(&mut rng) * radius
            } else {
                b.min + (b.max - b.min) * Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32())
            };
            let target = b.min + (b.max - b.min) * Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
            let ray = Ray::new(start, (target - start).normalize());
            let bvh = mesh.intersect(&ray, f32::INFINITY);
            assert_eq!(bvh.map(|h| h.distance), brute_force(&mesh, &ray), "ray {i}: {ray:?}");
            // The any-hit query agrees, also when the segment ends before the hit.
            assert_eq!(mesh.intersects(&ray, f32::INFINITY), bvh.is_some());
            if let Some(h) = bvh {
                hits += 1;
                assert!(!mesh.intersects(&ray, h.distance * 0.999) || brute_force_before(&mesh, &ray, h.distance));
                assert!(h.ip.is_finite() && h.normal.is_finite() && h.uv().0.is_finite() && h.uv().1.is_finite());
                assert!((h.normal.length() - 1.0).abs() < 1e-5 && (h.geometric_normal.length() - 1.0).abs() < 1e-5);
                assert!(h.error > 0.0 && (ray.at(h.distance) - h.ip).abs().max_element() < 1e-3 * radius);
            }
        }
        assert!(hits > 600, "only {hits} hits: the test would prove little");
    }
}

/// The two teapots of the mesh benchmark (`cargo bench --bench mesh`), the bundled 9,120-triangle one and
/// the 102,080-triangle one it writes, on rays like its incoherent ones (from a sphere around the mesh to
/// points in its box): the BVH finds brute force's closest hit, with the same triangle's surface, and the
/// same answer to the any-hit query.
#[test]
fn the_bvh_finds_brute_forces_hits_on_both_benchmark_teapots() {
    let fine = common::temp_file("mesh", "teapot-100k.obj", &lecture6::app::assets::teapot::obj(40));
    let meshes = [(common::root().join("textures/teapot.obj"), 2000), (fine, 200)];
    let mut rng = Rng::for_keys(&[11]);
    for (path, rays) in meshes {
        let mesh = Mesh::load(&path).unwrap();
        let triangles = mesh.triangles();
        let b = mesh.bounds().unwrap();
        let radius = 0.75 * (b.max - b.min).length();
        let mut hits = 0;
        for i in 0..rays {
            let start = b.center() + random_unit(&mut rng) * radius;
            let target = b.min + (b.max - b.min) * Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
            let ray = Ray::new(start, (target - start).normalize());
            let closest = triangles
                .iter()
                .filter_map(|t| Some((intersect_triangle(&ray, t, f32::INFINITY)?, t)))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let found = mesh.intersect(&ray, f32::INFINITY);
            assert_eq!(found.map(|h| h.distance), closest.map(|c| c.0), "{}, ray {i}: {ray:?}", path.display());
            assert_eq!(mesh.intersects(&ray, f32::INFINITY), closest.is_some());
            if let (Some(h), Some((_, tri))) = (found, closest) {
                hits += 1;
                let face = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
                assert!(h.geometric_normal.dot(face).abs() > 0.999, "{}, ray {i}: another triangle", path.display());
            }
        }
        assert!(hits > rays / 3, "only {hits} hits: the test would prove little");
    }
}

fn brute_force_before(mesh: &Mesh, ray: &Ray, t: f32) -> bool {
    mesh.triangles().iter().any(|tri| intersect_triangle(ray, tri, t * 0.999).is_some())
}

/// A closed sphere: an icosahedron with every face split into four, `levels` times.
fn icosphere(levels: u32) -> (Vec<Vector>, Vec<[u32; 3]>) {
    let g = (1.0 + 5f32.sqrt()) / 2.0;
    let mut v: Vec<Vector> = [
        (-1.0, g, 0.0),
        (1.0, g, 0.0),
        (-1.0, -g, 0.0),
        (1.0, -g, 0.0),
        (0.0, -1.0, g),
        (0.0, 1.0, g),
        (0.0, -1.0, -g),
        (0.0, 1.0, -g),
        (g, 0.0, -1.0),
        (g, 0.0, 1.0),
        (-g, 0.0, -1.0),
        (-g, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vector::new(x, y, z).normalize())
    .collect();
    let mut f: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut midpoint = |a: u32, b: u32, v: &mut Vec<Vector>| {
            *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                v.push(((v[a as usize] + v[b as usize]) * 0.5).normalize());
                v.len() as u32 - 1
            })
        };
        f = f
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) = (midpoint(a, b, &mut v), midpoint(b, c, &mut v), midpoint(c, a, &mut v));
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }
    (v, f)
}

#[test]
fn rays_through_shared_edges_and_vertices_never_slip_through() {
    let (positions, triangles) = icosphere(3);
    let mesh = Mesh::new(&positions, &triangles).unwrap();
    assert_eq!(mesh.triangle_count(), 1280);
    // Aim at every vertex, at points along every edge, from inside (the centre, and off-centre) and from
    // outside: a closed surface must be hit every time.
    let mut targets: Vec<Vector> = positions.clone();
    for t in &triangles {
        for k in 0..3 {
            let (a, b) = (positions[t[k] as usize], positions[t[(k + 1) % 3] as usize]);
            targets.extend([0.5f32, 0.25, 1.0 / 3.0].map(|s| a + (b - a) * s));
        }
    }
    let mut misses = 0;
    let mut rays = 0;
    for &target in &targets {
        for start in [Vector::ZERO, Vector::new(0.1, -0.2, 0.05), target * 3.0, Vector::new(2.0, 2.5, -3.0)] {
            let ray = Ray::new(start, (target - start).normalize());
            // From outside, only targets facing the start: a line through a point on the silhouette may
            // touch the surface there and nowhere else.
            if start.length() > 1.0 && ray.dir.dot(target) > -0.2 {
                continue;
            }
            rays += 1;
            if mesh.intersect(&ray, f32::INFINITY).is_none() || !mesh.intersects(&ray, f32::INFINITY) {
                misses += 1;
            }
        }
    }
    assert_eq!(misses, 0, "{misses} of {rays} rays slipped through the closed mesh");
    // Axis-aligned rays exactly through the vertices and edges of a flat grid of unit squares, each cut
    // along its diagonal: the points are exact in floating point, so they lie exactly on the edges.
    let n = 8u32;
    let grid: Vec<Vector> = (0..=n).flat_map(|j| (0..=n).map(move |i| Vector::new(i as f32, j as f32, 0.0))).collect();
    let quads: Vec<[u32; 3]> = (0..n)
        .flat_map(|j| (0..n).map(move |i| j * (n + 1) + i))
        .flat_map(|k| [[k, k + 1, k + n + 2], [k, k + n + 2, k + n + 1]])
        .collect();
    let flat = Mesh::new(&grid, &quads).unwrap();
    for j in 1..4 * n {
        for i in 1..4 * n {
            let (x, y) = (i as f32 * 0.25, j as f32 * 0.25);
            for dir in [-Vector::Z, Vector::Z] {
                let ray = Ray::new(Vector::new(x, y, -dir.z * 5.0), dir);
                let hit =
                    flat.intersect(&ray, f32::INFINITY).unwrap_or_else(|| panic!("slipped through at ({x}, {y})"));
                assert_eq!(hit.distance, 5.0);
            }
        }
    }
}

#[test]
fn a_missing_or_malformed_obj_is_an_error_naming_the_file() {
    let err = Mesh::load(std::path::Path::new("no/such/mesh.obj")).unwrap_err().to_string();
    assert!(err.contains("no/such/mesh.obj") && !err.contains('\n'), "{err}");
    for (name, text) in [
        ("bad-vertex.obj", "v 1 2 x\nv 0 0 0\nv 1 0 0\nf 1 2 3\n"),
        ("bad-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
        ("bad-normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n"),
    ] {
        let path = common::temp_file("mesh-tests", name, text);
        let err = Mesh::load(&path).err().unwrap_or_else(|| panic!("{name} was accepted")).to_string();
        assert!(err.contains(name) && !err.contains('\n'), "{err}");
    }
}

#[test]
fn empty_and_degenerate_meshes_give_no_hits_and_no_nans() {
    let cases = [
        ("empty.obj", "", 0),
        ("comments.obj", "# nothing here\no empty\n", 0),
        ("points.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 2\n", 0),
        ("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nvn 0 0 0\nf 1//1 2//1 3//1\nf 1//1 2//1 4//1\n", 1),
    ];
    let mut rng = Rng::for_keys(&[5]);
    for (name, text, count) in cases {
        let mesh = Mesh::load(&common::temp_file("mesh-tests", name, text)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(mesh.triangle_count(), count, "{name}");
        assert_eq!(mesh.bounds().is_some(), count > 0, "{name}");
        for _ in 0..200 {
            let ray = Ray::new(random_unit(&mut rng) * 3.0, random_unit(&mut rng));
            if let Some(h) = mesh.intersect(&ray, f32::INFINITY) {
                // Only the good triangle of `mixed.obj` can be hit; its zero normal falls back to the face's.
                assert!(h.normal.is_finite() && (h.normal.length() - 1.0).abs() < 1e-5, "{name}: {h:?}");
                assert!(h.ip.is_finite() && h.distance.is_finite(), "{name}: {h:?}");
            }
        }
        // A ray straight at the good triangle of `mixed.obj`.
        let ray = Ray::new(Vector::new(0.2, 0.2, -1.0), Vector::Z);
        assert_eq!(mesh.intersect(&ray, f32::INFINITY).map(|h| h.normal.z.abs()), (count > 0).then_some(1.0), "{name}");
    }
}

#[test]
fn normals_and_uvs_come_from_the_file_and_faceted_uses_the_face() {
    let text = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
                vn -0.6 0 0.8\nvn 0.6 0 0.8\nf 1/1/1 2/2/2 3/3/2 4/4/1\n";
    let path = common::temp_file("mesh-tests", "quad.obj", text);
    let mesh = Mesh::load(&path).unwrap();
    assert_eq!(mesh.triangle_count(), 2);
    let ray = Ray::new(Vector::new(0.5, 0.25, -2.0), Vector::Z);
    let h = mesh.intersect(&ray, f32::INFINITY).unwrap();
    let (u, v) = h.uv();
    assert!((u - 0.75).abs() < 1e-6 && (v - 0.625).abs() < 1e-6, "u/v {u} {v}");
    // Halfway from x = -1 to x = 1 at x = 0.5: three quarters of the way from the left normal to the right.
    let expected = (Vector::new(-0.6, 0.0, 0.8) * 0.25 + Vector::new(0.6, 0.0, 0.8) * 0.75).normalize();
    assert!(h.normal.dot(expected) > 1.0 - 1e-6, "{}", h.normal);
    // The face normal, turned to the side of the shading normal.
    assert_eq!(h.geometric_normal, Vector::Z);
    let faceted = Mesh::load(&path).unwrap().with_faceted(true).intersect(&ray, f32::INFINITY).unwrap();
    assert_eq!(faceted.normal, Vector::Z);
    assert_eq!(h.distance, 2.0);
}

#[test]
fn model_transform_reports_a_bad_mesh_in_one_line() {
    let out = common::run_example("model_transform", &["--mesh", "no/such/model.obj", "-o", "target/mesh-tests/x.png"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no/such/model.obj") && err.trim_end().lines().count() == 1 && !err.contains("panicked"),
        "{err}"
    );
    let empty = common::temp_file("mesh-tests", "nothing.obj", "# no triangles\n");
    let out =
        common::run_example("model_transform", &["--mesh", empty.to_str().unwrap(), "-o", "target/mesh-tests/y.png"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("nothing.obj") && err.contains("no triangles"), "{err}");
}

#[test]
fn a_students_mesh_is_scaled_to_fit() {
    // A tiny tetrahedron far from the origin renders in place of the teapots.
    let path = common::temp_file(
        "mesh-tests",
        "tetra.obj",
        "v 1000 1000 1000\nv 1000.01 1000 1000\nv 1000 1000.01 1000\nv 1000 1000 1000.01\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    );
    let with = common::render::<common::examples::model_transform::Options>(&[
        "--mesh",
        path.to_str().unwrap(),
        "--width",
        "160",
        "--height",
        "120",
        "--spp",
        "1",
    ]);
    let without = common::render::<common::examples::model_transform::Options>(&[
        "--width", "160", "--height", "120", "--spp", "1",
    ]);
    let changed = with.pixels.iter().zip(&without.pixels).filter(|(a, b)| a != b).count();
    assert!(changed > 1000, "only {changed} pixels changed: the mesh did not take the teapots' place");
    assert!(with.pixels.iter().all(|c| c.is_finite()));
}
