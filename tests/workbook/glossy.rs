//! Glossy reflections: glossiness 1 is the mirror, no reflected ray goes under the surface, and the cone of
//! reflections is centred on the mirror direction.

use crate::common;

use common::examples::glossy;
use lecture6::Color;
use lecture6::app::cli::Example;
use lecture6::lesson::branching::SPLIT_DEPTH;
use lecture6::lesson::camera::Camera;
use lecture6::lesson::environment::Environment;
use lecture6::lesson::geometry::Plane;
use lecture6::lesson::math::{Vector, reflect};
use lecture6::lesson::node::Node;
use lecture6::lesson::render::{RenderJob, RenderSettings, render, spectral_plan};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::sampling::{DiscSampler, DiscSamples};
use lecture6::lesson::scene::Scene;
use lecture6::lesson::shader::{GlossyCone, IntoShader, Reflection, SECONDARY_GLOSSY_SAMPLES};
use std::sync::{Arc, Mutex};

fn small(spp: u32) -> RenderSettings {
    RenderSettings { width: 96, height: 72, spp, threads: Some(2), ..RenderSettings::default() }
}

#[test]
fn glossiness_one_is_the_mirror_exactly() {
    let args = common::parse::<glossy::Options>(&["--glossiness", "1", "--glossy-samples", "50"]);
    let glossy_scene = args.example.scene().unwrap();
    let mut mirror_scene = glossy_scene.clone();
    let spheres = mirror_scene.nodes.len() - 3;
    for node in &mut mirror_scene.nodes[spheres..] {
        node.shader = Reflection::new(0.85).into_shader();
    }
    let (a, stats_a) = render(&glossy_scene, &small(4)).unwrap();
    let (b, stats_b) = render(&mirror_scene, &small(4)).unwrap();
    assert!(a == b, "glossiness 1 must trace exactly the mirror ray");
    assert_eq!(stats_a.counters, stats_b.counters, "glossiness 1 must trace one ray per hit, not 50");
}

/// An environment that remembers the direction of every ray that reaches it.
struct Recorder(Mutex<Vec<Vector>>);

impl Environment for Recorder {
    fn get(&self, dir: Vector) -> Color {
        self.0.lock().unwrap().push(dir);
        Color::WHITE
    }
}

#[test]
fn no_glossy_ray_goes_under_the_surface() {
    for (glossiness, sampler) in
        [(0.8, DiscSampler::Stratified), (0.3, DiscSampler::Random), (0.02, DiscSampler::Stratified)]
    {
        // A glossy floor seen from just above it, every camera ray going down to it: a ray that reaches the
        // sky going down can only be a reflection that went under the floor.
        let recorder = Arc::new(Recorder(Mutex::new(Vec::new())));
        let mut scene =
            Scene::new(Camera { position: Vector::new(0.0, 1.0, 0.0), pitch: -40.0, fov: 60.0, ..Camera::default() });
        scene.environment = Some(recorder.clone());
        let num_samples = 8;
        let floor = Reflection::glossy(Color::WHITE, glossiness, num_samples).unwrap().with_sampler(sampler);
        scene.add(Node::new(Arc::new(Plane::new(0.0, f32::INFINITY)), Arc::new(floor)));
        // The render's pixels alone (`render_rect`): after a render, the end-of-run report's check of
        // undeclared dispersion traces a few rays of its own, which the recorder would count too.
        let settings = small(1);
        let job = RenderJob::new(&scene, &settings, spectral_plan(&scene, &settings)).unwrap();
        let mut pixels = vec![Color::BLACK; (settings.width * settings.height) as usize];
        let counters = job.render_rect(0..settings.width, 0..settings.height, &mut pixels);
        let dirs = recorder.0.lock().unwrap();
        let under = dirs.iter().filter(|d| d.y < 0.0).count();
        assert_eq!(under, 0, "glossiness {glossiness}: {under} of {} rays went under the floor", dirs.len());
        let [camera_rays, reflected, ..] = counters.rays_by_depth;
        assert_eq!(dirs.len() as u64, reflected, "every camera ray must hit the floor");
        assert!(reflected > 0, "glossiness {glossiness}: no reflected ray at all");
        if glossiness < 0.1 {
            // Most normals tilted this far send the ray under the floor: those samples are dropped.
            assert!(reflected < camera_rays * num_samples as u64 / 2, "glossiness {glossiness}: too few rejected");
        }
    }
}

#[test]
fn rejected_directions_are_exactly_those_under_the_surface() {
    let mut rng = Rng::for_keys(&[42]);
    let mut kept = 0;
    let mut dropped = 0;
    for _ in 0..2000 {
        let n = Vector::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, rng.next_f32() - 0.5).normalize();
        let mut i = Vector::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, rng.next_f32() - 0.5).normalize();
        if i.dot(n) > 0.0 {
            i = -i;
        }
        let cone = GlossyCone::new(i, n, rng.next_f32());
        let disc = DiscSamples::new(DiscSampler::Random, &mut rng);
        for k in 0..4 {
            match cone.direction(disc.point(k, &mut rng)) {
                Some(d) => {
                    assert!(d.dot(n) > 0.0, "a kept direction goes under the surface");
                    assert!((d.length() - 1.0).abs() < 1e-5, "a kept direction is not unit: {}", d.length());
                    kept += 1;
                }
                None => dropped += 1,
            }
        }
    }
    assert!(kept > 0 && dropped > 0, "kept {kept}, dropped {dropped}");
}

#[test]
fn the_mean_glossy_direction_is_the_mirror_direction() {
    let n = Vector::Y;
    let mut rng = Rng::for_keys(&[3]);
    for glossiness in [0.99f32, 0.95] {
        for incidence in [0.0f32, 45.0, 70.0] {
            let a = incidence.to_radians();
            let i = Vector::new(a.sin(), -a.cos(), 0.0);
            let mirror = reflect(i, n);
            let cone = GlossyCone::new(i, n, glossiness);
            let disc = DiscSamples::new(DiscSampler::Stratified, &mut rng);
            let (mut sum, mut spread) = (Vector::ZERO, 0.0f32);
            let count = 4096;
            for k in 0..count {
                let d = cone.direction(disc.point(k, &mut rng)).expect("a narrow cone stays above the surface");
                sum += d;
                spread += d.angle_between(mirror);
            }
            let mean_angle = (sum / count as f32).normalize().angle_between(mirror).to_degrees();
            let spread = (spread / count as f32).to_degrees();
            // The samples do spread (about 1 degree at 0.99, 5 at 0.95), but their mean stays on the mirror.
            assert!(spread > 0.5, "glossiness {glossiness}: the cone does not spread ({spread} degrees)");
            assert!(
                mean_angle < 0.05 * spread,
                "glossiness {glossiness}, incidence {incidence}: mean {mean_angle} degrees off the mirror (spread {spread})"
            );
        }
    }
}

#[test]
fn secondary_glossy_bounces_trace_two_rays() {
    // A glossy floor under a glossy ceiling: every reflection off the floor (depth 1) hits the ceiling, which
    // must trace exactly SECONDARY_GLOSSY_SAMPLES rays for it, not num_samples.
    let mut scene =
        Scene::new(Camera { position: Vector::new(0.0, 5.0, 0.0), pitch: -50.0, fov: 40.0, ..Camera::default() });
    for y in [0.0, 10.0] {
        let mirror = Reflection::glossy(Color::gray(0.9), 0.95, 16).unwrap();
        scene.add(Node::new(Arc::new(Plane::new(y, f32::INFINITY)), Arc::new(mirror)));
    }
    let (_, stats) = render(&scene, &small(1)).unwrap();
    let [camera_rays, depth1, depth2, ..] = stats.counters.rays_by_depth;
    assert_eq!(depth1, 16 * camera_rays, "the first bounce traces num_samples rays");
    assert_eq!(depth2, SECONDARY_GLOSSY_SAMPLES as u64 * depth1, "a secondary bounce traces 2 rays");
}

#[test]
fn facing_white_glossy_mirrors_trace_rays_in_proportion_to_the_depth() {
    // Two white glossy mirrors facing each other: their rays keep the full weight, so adaptive depth control
    // never prunes them. Splitting every bounce in two would trace 2^depth rays per camera ray (a hang for a
    // scene file's `maxTraceDepth 60`); below the core's SPLIT_DEPTH each bounce traces one ray, the other
    // shares its colour (the branching bound).
    let mut scene =
        Scene::new(Camera { position: Vector::new(0.0, 5.0, 0.0), pitch: -50.0, fov: 40.0, ..Camera::default() });
    for y in [0.0, 10.0] {
        let mirror = Reflection::glossy(Color::WHITE, 0.98, 4).unwrap();
        scene.add(Node::new(Arc::new(Plane::new(y, f32::INFINITY)), Arc::new(mirror)));
    }
    scene.max_depth = 14;
    let settings = RenderSettings { width: 8, height: 6, spp: 1, threads: Some(2), ..RenderSettings::default() };
    let (_, stats) = render(&scene, &settings).unwrap();
    let rays = stats.counters.rays_by_depth;
    let split = SPLIT_DEPTH as usize;
    assert_eq!(rays[1], 4 * rays[0], "every camera ray hits the floor and traces num_samples rays");
    assert_eq!(rays[split + 1], SECONDARY_GLOSSY_SAMPLES as u64 * rays[split], "the last split doubles the rays");
    for depth in split + 2..=14 {
        assert!(rays[depth] > 0, "depth {depth} is never reached: {rays:?}");
        assert_eq!(rays[depth], rays[depth - 1], "depth {depth} still splits: {rays:?}");
    }
}

#[test]
fn adaptive_depth_control_never_prunes_glossy_samples() {
    // Each sample carries the mirror's full weight: were it given its 1/2048 share, the reflections of the
    // spheres in each other (depth 1, weight below the finest sRGB step) would be pruned and turn black.
    let args = ["--width", "40", "--height", "30", "--spp", "1", "--glossy-samples", "2048"];
    let adaptive = common::render::<glossy::Options>(&args);
    let exhaustive = common::render::<glossy::Options>(&[&args[..], &["--exhaustive"]].concat());
    assert!(adaptive == exhaustive, "adaptive depth control changed the glossy picture");
}

#[test]
fn glossy_mirrors_scatter_photons_into_their_cone() {
    use lecture6::lesson::geometry::{IntersectionInfo, TexCoords};
    use lecture6::lesson::ray::Ray;
    use lecture6::lesson::shader::CausticCaster;
    use lecture6::lesson::shader::PhotonScatter;
    let info = IntersectionInfo {
        ip: Vector::ZERO,
        normal: Vector::Y,
        geometric_normal: Vector::Y,
        distance: 1.0,
        error: 0.0,
        tex_coords: TexCoords::new(0.0, 0.0),
    };
    let ray = Ray::new(Vector::new(-1.0, 1.0, 0.0), Vector::new(1.0, -1.0, 0.0).normalize());
    let mirror_dir = reflect(ray.dir, Vector::Y);
    let mut rng = Rng::for_keys(&[5]);
    let scatter = |shader: &Reflection, rng: &mut Rng| match shader.scatter_photon(&ray, &info, rng) {
        PhotonScatter::Continue { dir, filter } => {
            assert_eq!(filter, Color::gray(0.9));
            assert!(dir.y > 0.0, "a photon went under the mirror");
            dir
        }
        other => panic!("a mirror must pass photons on, not {other:?}"),
    };
    let perfect = Reflection::new(0.9);
    assert_eq!(scatter(&perfect, &mut rng), mirror_dir);
    let glossy = Reflection::glossy(Color::gray(0.9), 0.8, 16).unwrap();
    let angles: Vec<f32> =
        (0..1000).map(|_| scatter(&glossy, &mut rng).angle_between(mirror_dir).to_degrees()).collect();
    // Tilting the normal by at most atan(tan(0.1 pi)) = 18 degrees turns the reflection by at most 36.
    assert!(angles.iter().all(|&a| a <= 36.0 + 1e-3), "a photon left the cone");
    let mean = angles.iter().sum::<f32>() / angles.len() as f32;
    assert!(mean > 5.0, "glossy photons do not spread: mean {mean} degrees off the mirror");
}
