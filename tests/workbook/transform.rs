//! The model transform (slide "Model трансформация"): T * T^-1 is the identity, a scaled sphere has the
//! analytic ellipsoid normal, instancing renders exactly what separate copies render, and a singular
//! transform is an error.

use lecture6::lesson::camera::{Camera, rotation};
use lecture6::lesson::color::Color;
use lecture6::lesson::geometry::{Geometry, IntoGeometry, Mesh, Shape, Sphere};
use lecture6::lesson::light::PointLight;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::Scene;
use lecture6::lesson::shader::{Lambert, Phong, Shader};
use lecture6::lesson::transform::Transform;
use proptest::prelude::*;
use std::sync::Arc;

fn vector(range: std::ops::Range<f32>) -> impl Strategy<Value = Vector> {
    (range.clone(), range.clone(), range).prop_map(|(x, y, z)| Vector::new(x, y, z))
}

fn magnitude() -> impl Strategy<Value = f32> {
    (0.2f32..5.0, any::<bool>()).prop_map(|(m, negative)| if negative { -m } else { m })
}

proptest! {
    #[test]
    fn t_times_t_inverse_is_the_identity(
        scale in (magnitude(), magnitude(), magnitude()),
        angles in vector(-180.0..180.0),
        offset in vector(-100.0..100.0),
        p in vector(-50.0..50.0),
    ) {
        let t = Transform::IDENTITY
            .scale(Vector::new(scale.0, scale.1, scale.2))
            .rotate(angles.x, angles.y, angles.z)
            .translate(offset);
        prop_assert!(t.check().is_ok());
        let world = t.point_to_world(p);
        let back = t.ray_to_canonical(&Ray::new(world, Vector::Z)).start;
        // Scales of 0.2..5 allow a condition number of 25; the rounding is relative to the largest term.
        let tolerance = 25.0 * 8.0 * f32::EPSILON * (p.abs().max_element() + offset.abs().max_element() * 5.0 + 1.0);
        prop_assert!((back - p).abs().max_element() <= tolerance, "{p} -> {world} -> {back}");
        // The world ray's direction comes back, unnormalised, as T's linear part applied to the canonical one.
        let d = t.ray_to_canonical(&Ray::new(world, Vector::new(0.6, 0.0, 0.8))).dir;
        let again = t.matrix().transform_vector3a(d);
        prop_assert!((again - Vector::new(0.6, 0.0, 0.8)).length() < 1e-4, "{again}");
    }
}

#[test]
fn a_scaled_sphere_has_the_analytic_ellipsoid_normal() {
    let (a, b, c) = (2.0f32, 1.5, 0.9);
    let (yaw, pitch, roll) = (35.0, -20.0, 12.0);
    let offset = Vector::new(3.3, 0.0, 18.1);
    let node = Node::new(Arc::new(Sphere::new(Vector::ZERO, 1.0)), Arc::new(Lambert::new(Color::WHITE)))
        .scale(Vector::new(a, b, c))
        .rotate(yaw, pitch, roll)
        .translate(offset);
    let r = rotation(yaw, pitch, roll);
    let mut rng = Rng::for_keys(&[42]);
    let mut hits = 0;
    for _ in 0..2000 {
        let start = offset + Vector::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, -1.0) * 8.0;
        let target = offset + (Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5) * 3.0;
        let ray = Ray::new(start, (target - start).normalize());
        let Some(info) = node.intersect(&ray, f32::INFINITY) else { continue };
        hits += 1;
        // The hit lies on the ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 of the rotated frame...
        let local = r.transpose() * (info.ip - offset);
        let level = (local / Vector::new(a, b, c)).length_squared();
        assert!((level - 1.0).abs() < 1e-4, "{level}");
        // ...at the ray's distance...
        assert!((ray.at(info.distance) - info.ip).length() < 1e-4 * offset.length());
        // ...and the normal is the gradient of that equation, rotated back.
        let analytic = (r * (local / Vector::new(a * a, b * b, c * c))).normalize();
        assert!(info.normal.dot(analytic) > 1.0 - 1e-6, "{} vs {analytic}", info.normal);
        assert!((info.normal.length() - 1.0).abs() < 1e-5);
    }
    assert!(hits > 500, "only {hits} rays hit the ellipsoid");
}

fn scene_with(nodes: Vec<Node>) -> Scene {
    let mut scene = Scene::new(Camera { position: Vector::new(0.0, 6.0, -12.0), pitch: -20.0, ..Camera::default() });
    scene.ambient = Color::gray(0.1);
    scene.lights.push(PointLight::new(Vector::new(-8.0, 20.0, -10.0), Color::WHITE, 600.0));
    scene.nodes = nodes;
    scene
}

#[test]
fn an_instance_renders_the_same_as_a_separate_copy() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("textures/teapot_low.obj");
    let red: Arc<dyn Shader> = Arc::new(Phong::new(Color::new(0.8, 0.2, 0.1), 0.3, 30.0));
    let blue: Arc<dyn Shader> = Arc::new(Lambert::new(Color::new(0.1, 0.3, 0.8)));
    let place = |mesh: Arc<dyn Geometry>| {
        vec![
            Node::new(mesh.clone(), red.clone()).rotate(30.0, 0.0, 0.0).translate(Vector::new(-3.0, 0.0, 0.0)),
            Node::new(mesh, blue.clone()).scale(Vector::new(0.5, 1.2, 0.8)).translate(Vector::new(3.0, 0.0, 2.0)),
        ]
    };
    let shared: Arc<dyn Geometry> = Arc::new(Mesh::load(&path).unwrap());
    let mut instanced = place(shared.clone());
    let same_mesh = |a: &Node, b: &Node| match (&a.geometry, &b.geometry) {
        (Shape::Mesh { mesh: a, .. }, Shape::Mesh { mesh: b, .. }) => Arc::ptr_eq(a, b),
        _ => panic!("both nodes show a mesh"),
    };
    assert!(same_mesh(&instanced[0], &instanced[1]));
    let mut copies = place(Arc::new(Mesh::load(&path).unwrap()));
    copies[1].geometry = Mesh::load(&path).unwrap().into_geometry();
    assert!(!same_mesh(&copies[0], &copies[1]));
    let settings = RenderSettings { width: 96, height: 72, spp: 1, ..RenderSettings::default() };
    let (a, _) = render(&scene_with(std::mem::take(&mut instanced)), &settings).unwrap();
    let (b, _) = render(&scene_with(copies), &settings).unwrap();
    assert!(a == b, "instancing changed the picture");
    // And the picture shows both teapots: not a trivially equal empty frame.
    let lit = a.pixels.iter().filter(|c| c.max_channel() > 0.05).count();
    assert!(lit > 200, "{lit} lit pixels");
}

#[test]
fn a_singular_transform_is_an_error_before_rendering() {
    let sphere = Node::new(Arc::new(Sphere::new(Vector::ZERO, 1.0)), Arc::new(Lambert::new(Color::WHITE)));
    for bad in [
        sphere.clone().scale(Vector::new(1.0, 0.0, 1.0)),
        sphere.clone().scale(Vector::new(1.0, f32::NAN, 1.0)),
        sphere.clone().translate(Vector::new(f32::INFINITY, 0.0, 0.0)),
    ] {
        let err = render(&scene_with(vec![bad]), &RenderSettings { width: 8, height: 8, ..Default::default() })
            .expect_err("a singular transform must be rejected");
        assert!(err.to_string().contains("transform"), "{err}");
    }
    assert!(render(&scene_with(vec![sphere]), &RenderSettings { width: 8, height: 8, ..Default::default() }).is_ok());
}

/// Two transformed nodes with coincident faces, as in the course's hw6/window: a glass pane standing on a
/// bar of its frame (the pane's bottom face and the bar's top face are both at y = 6.5, each reached
/// through its own scale, translation and turn). Rays from inside the pane down through the seam meet both
/// faces at distances that differ only by rounding; the node added first must win every such tie, in the
/// slides' loop over the nodes and in the tree over them, as in the course's loop.
#[test]
fn coincident_faces_go_to_the_node_added_first() {
    use lecture6::lesson::geometry::Cube;
    use lecture6::lesson::node::{NodeTree, nearest_hit_linear};
    let bar = Node::new(Cube::new(Vector::ZERO, 1.5), Lambert::new(Color::new(0.9, 0.3, 0.1)))
        .scale(Vector::new(60.0, 1.0, 1.0))
        .translate(Vector::new(0.0, 5.0, 0.0))
        .rotate(-5.0, 0.0, 0.0);
    let pane = Node::new(Cube::new(Vector::ZERO, 1.5), Lambert::new(Color::WHITE))
        .scale(Vector::new(59.0, 59.0, 0.75))
        .translate(Vector::new(0.0, 95.0, 0.0))
        .rotate(-5.0, 0.0, 0.0);
    // Far-away spheres, so that the scene is large enough for a tree over its nodes.
    let far = (0..8).map(|i| {
        Node::new(Sphere::new(Vector::new(1000.0 + 10.0 * i as f32, 0.0, 0.0), 1.0), Lambert::new(Color::WHITE))
    });
    let mut rng = Rng::for_keys(&[25]);
    for (first, nodes) in [
        ("bar", [vec![bar.clone(), pane.clone()], far.clone().collect()].concat()),
        ("pane", [vec![pane, bar], far.collect()].concat()),
    ] {
        let tree = NodeTree::build(&nodes).expect("enough nodes for a tree");
        let (mut rays, mut ties_lost) = (0, 0);
        for _ in 0..2000 {
            // A point inside the pane just above the seam, and a direction down through it, no more grazing than
            // a camera ray refracted into the pane (the window's line: 12 degrees below the seam).
            let (x, dy) = (rng.next_f32() * 160.0 - 80.0, 0.2 + 0.8 * rng.next_f32());
            let z = -x * 5f32.to_radians().tan() + (rng.next_f32() - 0.5) * 2.0;
            let start = Vector::new(x, 6.5 + 0.5 * rng.next_f32(), z);
            let dir = Vector::new(rng.next_f32() - 0.5, -dy, rng.next_f32() - 0.5).normalize();
            let ray = Ray::new(start, dir);
            let Some((hit, node)) = nearest_hit_linear(&nodes, &ray) else { continue };
            let Some(info) = node.surface(&ray, &hit) else { continue };
            if (info.ip.y - 6.5).abs() > 1e-3
                || nodes[1].intersect(&ray, f32::INFINITY).is_none_or(|h| (h.ip.y - 6.5).abs() > 1e-3)
            {
                continue; // the ray left the pane through another face, or missed the bar
            }
            rays += 1;
            let (_, tree_node) = tree.nearest_hit(&nodes, &ray).expect("the tree finds the hit too");
            if !std::ptr::eq(node, &nodes[0]) || !std::ptr::eq(tree_node, &nodes[0]) {
                ties_lost += 1;
            }
        }
        assert!(rays > 500, "only {rays} rays met the seam");
        assert_eq!(ties_lost, 0, "{first} added first lost {ties_lost} of {rays} ties");
    }
}
