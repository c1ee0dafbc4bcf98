//! Chromatic dispersion: the index of refraction by wavelength, the colours of the wavelength passes, the
//! prism's deviation against Snell's law, and that the renderer traces wavelengths only where they matter.

mod common;

use common::examples::{bitmap_textures, dispersion};
use lecture6::app::cli::Example;
use lecture6::lesson::color::Color;
use lecture6::lesson::environment::{ConstantEnvironment, Environment};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::geometry::{Prism, Sphere};
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::render::{RenderStats, render_with_plan};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::Refraction;
use lecture6::lesson::spectral::{
    Band, Ior, LAMBDA_C, LAMBDA_D, LAMBDA_F, LAMBDA_MAX, LAMBDA_MIN, SpectralPlan, bands, cie_xyz,
};
use std::sync::Arc;

const SMALL: [&str; 4] = ["--width", "96", "--height", "72"];

fn run<E: Example>(args: &[&str]) -> (Frame, RenderStats) {
    common::parse::<E>(args).render().expect("render")
}

fn args_with<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    SMALL.iter().copied().chain(extra.iter().copied()).collect()
}

#[test]
fn band_weights_sum_to_white_for_any_count() {
    for k in [1, 2, 3, 7, 8, 64, 1000] {
        let sum = bands(k).iter().fold([0.0f64; 3], |s, b| std::array::from_fn(|c| s[c] + b.weight[c]));
        for (c, v) in sum.iter().enumerate() {
            assert!((v - 1.0).abs() < 1e-12, "{k} bands: channel {c} sums to {v}");
        }
    }
    // The bands tile the range without gaps.
    let b = bands(8);
    assert_eq!(b[0].lo, LAMBDA_MIN);
    assert_eq!(b[7].hi, LAMBDA_MAX);
    assert!(b.windows(2).all(|w| w[0].hi == w[1].lo));
}

#[test]
fn band_colours_run_from_violet_to_red() {
    let b = bands(8);
    let (first, last) = (b[0].color(), b[7].color());
    assert!(first.b() > first.g() && first.b() > 0.0, "the shortest band is bluish: {first:?}");
    assert!(
        last.r() > 0.0 && last.g() < last.r() * 0.1 && last.b().abs() < last.r() * 0.05,
        "the longest is red: {last:?}"
    );
    // A green band has negative red: monochromatic colours lie outside the sRGB gamut.
    let green = Band::nth(4, 10);
    assert!(green.weight[1] > 0.0 && green.weight[0] < 0.0, "{green:?}");
}

#[test]
fn the_visible_range_holds_nearly_all_of_the_colour_matching_functions() {
    let integrate = |a: f64, b: f64| {
        let n = ((b - a) * 10.0) as usize;
        (0..n).fold([0.0; 3], |s, i| {
            let v = cie_xyz(a + (i as f64 + 0.5) * 0.1);
            std::array::from_fn(|c| s[c] + v[c] * 0.1)
        })
    };
    let (all, visible) = (integrate(360.0, 830.0), integrate(LAMBDA_MIN as f64, LAMBDA_MAX as f64));
    for c in 0..3 {
        let outside = 1.0 - visible[c] / all[c];
        assert!(outside < 0.006, "channel {c}: {:.2}% of the area outside the traced range", outside * 100.0);
    }
    // The fit peaks where the CIE tables do.
    assert!((cie_xyz(555.0)[1] - 1.0).abs() < 0.02, "y-bar at 555 nm: {}", cie_xyz(555.0)[1]);
}

#[test]
fn white_light_through_every_plan_stays_exactly_white() {
    let mut scene = Scene::new(Default::default());
    scene.environment = Some(Arc::new(ConstantEnvironment(Color::WHITE)));
    let mut s = lecture6::lesson::render::RenderSettings { width: 8, height: 6, spp: 5, ..Default::default() };
    for plan in [SpectralPlan::Passes(bands(8)), SpectralPlan::Passes(bands(3)), SpectralPlan::Sampled] {
        let (frame, _) = render_with_plan(&scene, &s, plan.clone()).unwrap();
        assert!(frame.pixels.iter().all(|&p| p == Color::WHITE), "{plan}: {:?}", frame.pixels[0]);
    }
    s.spp = 1;
    let (frame, _) = render_with_plan(&scene, &s, SpectralPlan::Sampled).unwrap();
    assert!(frame.pixels.iter().all(|&p| p == Color::WHITE));
}

#[test]
fn glasses_have_their_catalogue_indices_and_abbe_numbers() {
    // Schott's catalogue: N-BK7 n_d 1.51680, V_d 64.17; SF11 n_d 1.78472, V_d 25.68.
    for (name, ior, n_d, v_d) in [("N-BK7", Ior::N_BK7, 1.5168, 64.17), ("SF11", Ior::SF11, 1.78472, 25.68)] {
        assert!((ior.n_d() - n_d).abs() < 2e-4, "{name}: n_d {}", ior.n_d());
        assert!((ior.abbe_number() - v_d).abs() < 0.3, "{name}: V_d {}", ior.abbe_number());
    }
    // The Cauchy fit reproduces what it is given.
    let glass = Ior::abbe(1.6, 35.0).unwrap();
    assert!((glass.at(Some(LAMBDA_D)) - 1.6).abs() < 1e-6);
    assert!((glass.abbe_number() - 35.0).abs() < 0.05, "{}", glass.abbe_number());
    // Without dispersion the index is n_d at every wavelength, exactly.
    let flat = Ior::abbe(1.6, f32::INFINITY).unwrap();
    assert!(!flat.is_dispersive());
    assert!([LAMBDA_MIN, LAMBDA_F, LAMBDA_C, LAMBDA_MAX].iter().all(|&l| flat.at(Some(l)) == 1.6));
    // Impossible glasses are errors naming the value.
    assert!(Ior::abbe(0.5, 30.0).unwrap_err().to_string().contains("0.5"));
    assert!(Ior::abbe(1.5, -3.0).unwrap_err().to_string().contains("-3"));
    assert!(Ior::abbe(f32::NAN, 30.0).is_err());
}

#[test]
fn shorter_wavelengths_see_a_higher_index() {
    for ior in [Ior::N_BK7, Ior::SF11, Ior::abbe(1.5, 40.0).unwrap(), Ior::abbe(2.4, 10.0).unwrap()] {
        let n: Vec<f32> = (0..=30).map(|i| ior.at(Some(LAMBDA_MIN + 10.0 * i as f32))).collect();
        assert!(n.windows(2).all(|w| w[0] > w[1]), "{ior:?}: {n:?}");
    }
}

/// An environment that shows the direction a ray leaves in, as its colour.
struct DirectionEnvironment;
impl Environment for DirectionEnvironment {
    fn get(&self, dir: Vector) -> Color {
        Color(dir)
    }
}

/// Snell's law at the two faces of a prism of apex angle `apex` for a ray meeting the first face at
/// `theta1` from its normal: the total deviation, degrees.
fn snell_deviation(apex: f64, n: f64, theta1: f64) -> f64 {
    let theta2 = (theta1.to_radians().sin() / n).asin();
    let theta3 = apex.to_radians() - theta2;
    let theta4 = (n * theta3.sin()).asin();
    theta1 + theta4.to_degrees() - apex
}

#[test]
fn the_prism_deviates_each_wavelength_as_snells_law_says() {
    let apex = 60.0f32;
    let glass = Ior::abbe(1.7, 20.0).unwrap();
    let prism = Prism::new(apex, 1.0, 1.0);
    let node = Node::new(Arc::new(prism), Arc::new(Refraction::with_ior(glass, 1.0)))
        .rotate(37.0, 0.0, 0.0)
        .translate(Vector::new(3.0, -2.0, 40.0));
    let transform = node.transform.unwrap();
    let mut scene = Scene::new(Default::default());
    scene.add(node);
    scene.environment = Some(Arc::new(DirectionEnvironment));
    let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[1]));

    // In the prism's own frame: the ray meets the middle of the left face at theta1 from its normal, turned
    // towards the apex, in the plane of the cross-section.
    let (left, _) = prism.apex_face_normals();
    let depth = 1.0 / (0.5 * apex).to_radians().tan();
    let (corner, tip) = (Vector::new(-1.0, 0.0, -0.5 * depth), Vector::new(0.0, 0.0, 0.5 * depth));
    let along = (tip - corner).normalize();
    let aim = 0.5 * (corner + tip);
    let bands8 = bands(8);
    let mut deviations = Vec::new();
    let mut worst = 0.0f64;
    for theta1 in [50.0f32, 55.0, 65.0] {
        for wavelength in [LAMBDA_MIN, bands8[0].centre(), bands8[7].centre(), LAMBDA_MAX] {
            let t = theta1.to_radians();
            let dir = t.cos() * -left + t.sin() * along;
            let world_start = transform.point_to_world(aim - 5.0 * dir);
            let world_dir = (transform.point_to_world(aim) - world_start).normalize();
            let mut ray = lecture6::lesson::ray::Ray::new(world_start, world_dir);
            ray.wavelength = Some(wavelength);
            let out = ctx.raytrace(&ray).0;
            assert!(
                (out.length() - 1.0).abs() < 1e-4,
                "the ray must leave the prism into the environment: {out:?} {:?}",
                ctx.counters
            );
            let traced = world_dir.dot(out).clamp(-1.0, 1.0).acos().to_degrees() as f64;
            let expected = snell_deviation(apex as f64, glass.at(Some(wavelength)) as f64, theta1 as f64);
            assert!(
                (traced - expected).abs() < 0.1,
                "theta1 {theta1}, {wavelength} nm: traced {traced:.4} degrees, Snell {expected:.4}"
            );
            worst = worst.max((traced - expected).abs());
            deviations.push((theta1, wavelength, traced));
        }
    }
    eprintln!("prism: largest difference from Snell's law {worst:.2e} degrees; deviations {deviations:?}");
    // Shorter wavelengths are bent more, at every angle of incidence.
    for w in deviations.chunks(4) {
        assert!(w.windows(2).all(|p| p[0].2 > p[1].2), "{w:?}");
    }
}

#[test]
fn a_scene_without_dispersion_renders_one_pass_whatever_the_wavelength_count() {
    let (one, stats_one) = run::<bitmap_textures::Options>(&args_with(&["--wavelengths", "1"]));
    let (eight, stats_eight) = run::<bitmap_textures::Options>(&args_with(&["--wavelengths", "8"]));
    let (sampled, _) = run::<bitmap_textures::Options>(&args_with(&["--spectral", "sampled"]));
    assert_eq!(stats_eight.spectral, SpectralPlan::White);
    assert_eq!(stats_one.counters, stats_eight.counters, "the same rays");
    assert_eq!(stats_eight.counters.rays_by_depth[0], 96 * 72 * 4, "one camera ray per sample");
    assert!(one == eight && one == sampled, "the same picture");
}

#[test]
fn a_dispersive_scene_traces_every_pass_and_counts_its_rays() {
    let (_, two) = run::<dispersion::Options>(&args_with(&["--wavelengths", "2", "--spp", "1"]));
    let (_, five) = run::<dispersion::Options>(&args_with(&["--wavelengths", "5", "--spp", "1"]));
    let (_, sampled) = run::<dispersion::Options>(&args_with(&["--spectral", "sampled", "--spp", "3"]));
    assert_eq!(two.spectral.passes(), 2);
    assert_eq!(two.counters.rays_by_depth[0], 96 * 72 * 2);
    assert_eq!(five.counters.rays_by_depth[0], 96 * 72 * 5);
    assert_eq!(sampled.spectral, SpectralPlan::Sampled);
    assert_eq!(sampled.counters.rays_by_depth[0], 96 * 72 * 3);
}

#[test]
fn glass_without_dispersion_renders_as_the_constant_index_glass() {
    let flat = ["--glass", "abbe", "--nd", "1.7", "--abbe", "inf", "--spp", "1"];
    let parse = |extra: &[&str]| common::parse::<dispersion::Options>(&args_with(extra));
    let args = parse(&flat);
    let (white, stats) = args.render().unwrap();
    assert_eq!(stats.spectral, SpectralPlan::White, "V_d = inf is not dispersive: one pass");
    // The same scene traced in 8 wavelength passes gives the same picture, bit for bit.
    let scene = args.example.scene().unwrap();
    let (passes, _) = render_with_plan(&scene, &args.settings(), SpectralPlan::Passes(bands(8))).unwrap();
    assert!(white == passes, "V_d = inf traced in 8 passes differs from the white render");
    // A little dispersion does change the picture (so the comparison above could fail).
    let (dispersive, _) = parse(&["--glass", "abbe", "--nd", "1.7", "--abbe", "60", "--spp", "1"]).render().unwrap();
    assert!(white != dispersive);
}

#[test]
fn dispersion_is_identical_for_any_thread_count_and_finite() {
    for mode in ["passes", "sampled"] {
        let a = run::<dispersion::Options>(&args_with(&["--threads", "1", "--spectral", mode])).0;
        let b = run::<dispersion::Options>(&args_with(&["--threads", "2", "--spectral", mode])).0;
        assert!(a == b, "{mode}: the picture changed with the thread count");
        assert!(a.pixels.iter().all(|p| p.is_finite() && p.0.min_element() >= 0.0), "{mode}");
    }
}

#[test]
fn the_gem_shows_colour_where_white_glass_shows_none() {
    // Through dispersive glass some pixels are strongly coloured; through the same glass without
    // dispersion (lit only by white light) none are.
    let chroma = |f: &Frame| f.pixels.iter().map(|p| p.max_channel() - p.0.min_element()).fold(0.0f32, f32::max);
    let dispersive = run::<dispersion::Options>(&args_with(&[])).0;
    let flat = run::<dispersion::Options>(&args_with(&["--glass", "abbe", "--abbe", "inf"])).0;
    assert!(chroma(&flat) < 0.05, "white glass made colour: {}", chroma(&flat));
    assert!(chroma(&dispersive) > 0.5, "dispersive glass made no colour: {}", chroma(&dispersive));
}

#[test]
fn bad_dispersion_options_are_one_line_errors() {
    for (args, names) in [
        (&["--wavelengths", "0"][..], "0"),
        (&["--wavelengths", "100000"][..], "100000"),
        (&["--glass", "abbe", "--abbe=-2"][..], "-2"),
        (&["--glass", "abbe", "--nd", "0.8"][..], "0.8"),
    ] {
        let out = common::run_example("dispersion", &[&["-q", "-o", "target/dispersion-bad.png"][..], args].concat());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(names), "{args:?}: {err}");
    }
}

#[test]
fn a_sphere_of_dispersive_glass_focuses_blue_nearer_than_red() {
    // A camera ray straight through a sphere off its axis comes out bent towards the axis, blue more than red.
    let mut scene = Scene::new(Default::default());
    scene.add(Node::new(
        Arc::new(Sphere::new(Vector::new(0.0, 0.0, 10.0), 2.0)),
        Arc::new(Refraction::with_ior(Ior::SF11, 1.0)),
    ));
    scene.environment = Some(Arc::new(DirectionEnvironment));
    let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[2]));
    let bent = |ctx: &mut TraceContext, wavelength: f32| {
        let mut ray = lecture6::lesson::ray::Ray::new(Vector::new(1.0, 0.0, 0.0), Vector::Z);
        ray.wavelength = Some(wavelength);
        ctx.raytrace(&ray).0.x
    };
    let (blue, red) = (bent(&mut ctx, 450.0), bent(&mut ctx, 650.0));
    assert!(blue < red && red < 0.0, "towards the axis, blue more: blue {blue}, red {red}");
}
