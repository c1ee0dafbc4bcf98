//! Invariants of the slides' vector helpers, colour conversions, texture look-ups and the u/v of the
//! canonical shapes.

use lecture6::Color;
use lecture6::lesson::bitmap::{Bitmap, Filter, Wrap};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::{linear_to_srgb, srgb_to_linear, srgb8_code, srgb8_edges, to_srgb8};
use lecture6::lesson::geometry::{Cube, Geometry, Plane, Sphere};
use lecture6::lesson::math::{OrthonormalBasis, Vector, faceforward, reflect};
use lecture6::lesson::ray::Ray;

fn unit(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z).normalize()
}

#[test]
fn reflect_keeps_the_angle_and_the_length() {
    let n = unit(0.2, 1.0, -0.3);
    for i in [unit(1.0, -1.0, 0.0), unit(-0.3, -0.2, 0.9), unit(0.0, -1.0, 0.0)] {
        let r = reflect(i, n);
        assert!((r.length() - 1.0).abs() < 1e-6);
        // Angle of incidence equals angle of reflection, and r lies in the plane of i and n.
        assert!(((-i).dot(n) - r.dot(n)).abs() < 1e-6);
        assert!(i.cross(n).dot(r).abs() < 1e-6);
    }
}

#[test]
fn faceforward_turns_the_normal_towards_the_ray() {
    let n = Vector::Y;
    assert_eq!(faceforward(n, unit(0.0, -1.0, 1.0)), n);
    assert_eq!(faceforward(n, unit(0.0, 1.0, 1.0)), -n);
    assert!(faceforward(-n, unit(0.3, -0.5, 0.1)).dot(unit(0.3, -0.5, 0.1)) < 0.0);
}

#[test]
fn orthonormal_basis_is_orthonormal_everywhere() {
    for n in [Vector::Z, -Vector::Z, Vector::X, unit(1.0, 2.0, 3.0), unit(0.0, 1e-7, -1.0)] {
        let b = OrthonormalBasis::new(n);
        for v in [b.tangent, b.bitangent] {
            assert!((v.length() - 1.0).abs() < 1e-5 && v.dot(n).abs() < 1e-5);
        }
        assert!(b.tangent.dot(b.bitangent).abs() < 1e-5);
    }
}

#[test]
fn srgb_round_trips_every_8_bit_code() {
    for code in 0..=255u8 {
        let linear = srgb_to_linear(code as f32 / 255.0);
        assert_eq!(to_srgb8(Color::gray(linear))[0], code);
    }
    assert!((linear_to_srgb(2.0) - 1.0).abs() < 1e-6);
    assert_eq!(linear_to_srgb(f32::NAN), 0.0);
}

#[test]
fn srgb8_codes_from_the_edges_are_the_formulas() {
    // Every 97th float from 0 to 1 (about 11 million, some in every code), each edge and the float below it,
    // and values outside [0, 1].
    let below_one = 1f32.to_bits();
    let samples = (0..=below_one).step_by(97).map(f32::from_bits);
    let edges = srgb8_edges().iter().flat_map(|&e| [e, f32::from_bits(e.to_bits() - 1)]);
    let outside = [-1.0, -0.0, 1.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN];
    for v in samples.chain(edges).chain(outside) {
        assert_eq!(to_srgb8(Color::gray(v))[0], srgb8_code(v), "linear {v}");
    }
}

#[test]
fn bilinear_filtering_of_a_2x2_image() {
    let px = [Color::gray(0.0), Color::gray(1.0), Color::gray(0.5), Color::gray(0.25)];
    let bmp = Bitmap::from_pixels(2, 2, px.to_vec());
    let clamp = (Wrap::Clamp, Wrap::Clamp);
    // Texel centres return the texel itself.
    assert_eq!(bmp.sample(0.25, 0.25, Filter::Bilinear, clamp), px[0]);
    assert_eq!(bmp.sample(0.75, 0.75, Filter::Bilinear, clamp), px[3]);
    // The centre of the image is the average of the four.
    let mid = bmp.sample(0.5, 0.5, Filter::Bilinear, clamp);
    assert!((mid.r() - 0.4375).abs() < 1e-6);
    // Halfway between the top two texel centres.
    assert!((bmp.sample(0.5, 0.25, Filter::Bilinear, clamp).r() - 0.5).abs() < 1e-6);
    // Nearest picks the texel the point falls in; repeat wraps around.
    assert_eq!(bmp.sample(0.6, 0.1, Filter::Nearest, clamp), px[1]);
    assert_eq!(bmp.sample(1.1, 0.1, Filter::Nearest, (Wrap::Repeat, Wrap::Repeat)), px[0]);
    assert_eq!(bmp.sample(1.1, 0.1, Filter::Nearest, (Wrap::Mirror, Wrap::Mirror)), px[1]);
    // Repeat blends across the seam: halfway between the last and the first column.
    let seam = bmp.sample(0.0, 0.25, Filter::Bilinear, (Wrap::Repeat, Wrap::Repeat));
    assert!((seam.r() - 0.5).abs() < 1e-6);
}

#[test]
fn plane_uv_are_world_x_and_z() {
    let plane = Plane::new(1.0, 100.0);
    let hit = plane.intersect(&Ray::new(Vector::new(3.0, 10.0, -7.0), -Vector::Y), f32::INFINITY).unwrap();
    assert_eq!((hit.uv(), hit.ip.y), ((3.0, -7.0), 1.0));
    assert!((hit.distance - 9.0).abs() < 1e-6);
    // Outside the limit, or parallel to the plane: no hit.
    assert!(plane.intersect(&Ray::new(Vector::new(300.0, 10.0, 0.0), -Vector::Y), f32::INFINITY).is_none());
    assert!(plane.intersect(&Ray::new(Vector::new(0.0, 1.0, 0.0), Vector::X), f32::INFINITY).is_none());
}

#[test]
fn sphere_uv_are_longitude_and_latitude() {
    let s = Sphere::new(Vector::new(0.0, 5.0, 0.0), 2.0);
    let hit_at = |dir: Vector| {
        let start = Vector::new(0.0, 5.0, 0.0) + dir * 10.0;
        s.intersect(&Ray::new(start, -dir), f32::INFINITY).unwrap()
    };
    let uv_at = |dir: Vector| hit_at(dir).uv();
    let top = hit_at(Vector::Y);
    assert!(top.uv().1.abs() < 1e-6 && (top.normal - Vector::Y).length() < 1e-6);
    assert!((uv_at(-Vector::Y).1 - 1.0).abs() < 1e-6);
    let (u, v) = uv_at(-Vector::X);
    assert!(u.min(1.0 - u) < 1e-6 && (v - 0.5).abs() < 1e-6);
    assert!((uv_at(Vector::Z).0 - 0.75).abs() < 1e-6);
    assert!((uv_at(Vector::X).0 - 0.5).abs() < 1e-6);
    assert!((top.distance - 8.0).abs() < 1e-5);
}

#[test]
fn cube_uv_span_each_face() {
    let c = Cube::new(Vector::ZERO, 1.0);
    // Hit the +Z face at x = 0.5, y = -0.5.
    let hit = c.intersect(&Ray::new(Vector::new(0.5, -0.5, 5.0), -Vector::Z), f32::INFINITY).unwrap();
    assert_eq!(hit.normal, Vector::Z);
    let (u, v) = hit.uv();
    assert!((u - 0.75).abs() < 1e-6 && (v - 0.25).abs() < 1e-6);
    // From inside, the exit face and its outward normal.
    let inside = c.intersect(&Ray::new(Vector::ZERO, Vector::X), f32::INFINITY).unwrap();
    assert_eq!((inside.normal, inside.distance), (Vector::X, 1.0));
    // The +X face: u follows z, v follows y.
    let x_face = c.intersect(&Ray::new(Vector::new(5.0, 0.5, -0.5), -Vector::X), f32::INFINITY).unwrap();
    let (u, v) = x_face.uv();
    assert!((u - 0.25).abs() < 1e-6 && (v - 0.75).abs() < 1e-6);
}

#[test]
fn camera_follows_the_course_conventions() {
    let cam = Camera { pitch: -30.0, ..Camera::default() };
    let centre = cam.frame(640, 480).get_screen_ray(320.0, 240.0).dir;
    assert!((centre - unit(0.0, -0.5, 0.75f32.sqrt())).length() < 1e-5, "pitch -30 looks down: {centre}");
    let yawed = Camera { yaw: 90.0, ..Camera::default() }.frame(640, 480).get_screen_ray(320.0, 240.0).dir;
    assert!((yawed + Vector::X).length() < 1e-5, "positive yaw turns left: {yawed}");
    // fov is measured across the diagonal: the corner ray is fov / 2 from the axis.
    let corner = Camera::default().frame(640, 480).get_screen_ray(0.0, 0.0).dir;
    assert!((corner.dot(Vector::Z) - 45f32.to_radians().cos()).abs() < 1e-6);
    assert!(corner.x < 0.0 && corner.y > 0.0, "pixel (0, 0) is the top left");
}

#[test]
fn floor_without_the_library_call_is_the_library_floor() {
    let mut rng = lecture6::lesson::rng::Rng::for_keys(&[3]);
    let specials =
        [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.0f32.powi(23), -(2.0f32.powi(23)), 8388607.5, -8388607.5, 1e30, -1e30];
    let random = (0..10_000).map(|_| f32::from_bits(rng.next_u32())).filter(|x| x.is_finite());
    for x in specials.into_iter().chain(random) {
        assert_eq!(lecture6::lesson::math::floor(x), x.floor(), "floor({x})");
    }
    assert!(lecture6::lesson::math::floor(f32::NAN).is_nan());
}

#[test]
fn a_ray_origin_moves_off_the_surface_by_the_error_and_one_to_two_floats() {
    use lecture6::lesson::math::offset_ray_origin;
    let mut rng = lecture6::lesson::rng::Rng::for_keys(&[4]);
    let mut random = |scale: f32| (rng.next_f32() - 0.5) * scale;
    for i in 0..20_000 {
        let scale = [1e-4, 1.0, 1e6, 1e-30][i % 4];
        let p = Vector::new(random(scale), if i % 5 == 0 { 0.0 } else { random(scale) }, random(scale));
        let n = match i % 7 {
            0 => Vector::Y,
            1 => -Vector::X,
            _ => Vector::new(random(2.0), random(2.0), random(2.0)).normalize(),
        };
        let error = [0.0, 1e-7 * scale, random(scale).abs()][i % 3];
        let q = offset_ray_origin(p, n, error);
        let moved = p + n.abs().element_sum() * error * n;
        for k in 0..3 {
            let (a, b) = (moved[k], q[k]);
            if n[k] == 0.0 {
                assert_eq!(b, a, "{p} {n} {error}");
            } else {
                let steps = [a.next_up(), a.next_up().next_up(), a.next_down(), a.next_down().next_down()];
                let allowed = if n[k] > 0.0 { &steps[..2] } else { &steps[2..] };
                assert!(allowed.contains(&b), "axis {k}: {a} -> {b} along {n}");
            }
        }
    }
}
