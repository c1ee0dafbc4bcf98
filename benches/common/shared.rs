//! What the benchmarks that time work inside their own process share: CPU time from `getrusage`, the
//! median, and the object-count scene.

use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::Color;
use lecture6::lesson::geometry::{Plane, Sphere};
use lecture6::lesson::light::PointLight;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::Scene;
use lecture6::lesson::shader::Lambert;
use std::sync::Arc;
use std::time::Duration;

/// The CPU time (user + system) of this process's waited-for children (`libc::RUSAGE_CHILDREN`), or of the
/// process itself, all its threads (`libc::RUSAGE_SELF`).
#[allow(unsafe_code)] // Sound: see the SAFETY comment.
pub fn cpu_time(who: libc::c_int) -> Duration {
    let mut usage = std::mem::MaybeUninit::<libc::rusage>::uninit();
    // SAFETY: getrusage writes the whole struct when it returns 0.
    let usage = unsafe {
        assert_eq!(libc::getrusage(who, usage.as_mut_ptr()), 0, "getrusage failed");
        usage.assume_init()
    };
    let tv = |t: libc::timeval| Duration::new(t.tv_sec as u64, t.tv_usec as u32 * 1000);
    tv(usage.ru_utime) + tv(usage.ru_stime)
}

/// The median of the values (the upper one of the middle two for an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// N small spheres on a plane, as in the final scene of "Ray Tracing in One Weekend": on a jittered grid
/// over the same 22 x 22 square whatever N, so that the picture stays alike and only the count changes.
pub fn spheres_scene(n: usize) -> Scene {
    let mut scene =
        Scene::new(Camera { position: Vector::new(0.0, 3.0, -16.0), pitch: -12.0, fov: 70.0, ..Camera::default() });
    scene.lights.push(PointLight::new(Vector::new(5.0, 20.0, -10.0), Color::WHITE, 600.0));
    scene.ambient = Color::gray(0.1);
    scene.add(Node::new(Arc::new(Plane::new(0.0, f32::INFINITY)), Arc::new(Lambert::new(Color::gray(0.5)))));
    let side = (n as f64).sqrt().ceil() as usize;
    let spacing = 22.0 / side as f32;
    let radius = 0.3 * spacing;
    let mut rng = Rng::for_keys(&[n as u64]);
    for i in 0..n {
        let (a, b) = ((i % side) as f32, (i / side) as f32);
        let x = -11.0 + spacing * (a + 0.2 + 0.6 * rng.next_f32());
        let z = -11.0 + spacing * (b + 0.2 + 0.6 * rng.next_f32());
        let color = Color::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(x, radius, z), radius)), Arc::new(Lambert::new(color))));
    }
    scene
}
