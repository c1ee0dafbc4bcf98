//! Chromatic dispersion: the index of refraction by wavelength, the colours of the wavelengths (the CIE's
//! tables, the light's spectrum, the gamut), the prism's deviation against Snell's law, and that the renderer
//! traces wavelengths only where they matter (the skip, and hero-wavelength sampling's split).

use crate::common;

use common::examples::{bitmap_textures, dispersion};
use glam::{DMat3, DVec3};
use lecture6::app::cli::Example;
use lecture6::instruments::tone_mapping::Film;
use lecture6::lesson::color::Color;
use lecture6::lesson::environment::{ConstantEnvironment, Environment};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::geometry::{IntersectionInfo, Plane, Prism, Sphere};
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, RenderStats, render, render_with_plan};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::{Refraction, Shader};
use lecture6::lesson::spectral::{
    Band, GamutMapping, Illuminant, Ior, LAMBDA_C, LAMBDA_D, LAMBDA_F, LAMBDA_MAX, LAMBDA_MIN, SpectralPlan, bands,
    cie_xyz, fit_to_gamut, xyz_to_linear_srgb,
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
fn band_weights_add_up_to_the_lights_colour_for_any_count() {
    for illuminant in [Illuminant::D65, Illuminant::EqualEnergy] {
        let white = illuminant.white();
        for k in [1, 2, 3, 7, 8, 64, 1000] {
            let sum = bands(k, illuminant).iter().fold([0.0f64; 3], |s, b| std::array::from_fn(|c| s[c] + b.weight[c]));
            for c in 0..3 {
                assert!((sum[c] - white[c]).abs() < 1e-12, "{illuminant:?}, {k} bands: channel {c} sums to {}", sum[c]);
            }
        }
    }
    // D65 is sRGB's white: luminance normalisation alone makes it (1, 1, 1).
    assert!(Illuminant::D65.white().iter().all(|&v| (v - 1.0).abs() < 1e-12), "{:?}", Illuminant::D65.white());
    // The bands tile the range without gaps.
    let b = bands(8, Illuminant::D65);
    assert_eq!(b[0].lo, LAMBDA_MIN);
    assert_eq!(b[7].hi, LAMBDA_MAX);
    assert!(b.windows(2).all(|w| w[0].hi == w[1].lo));
}

/// The matrix from linear sRGB back to XYZ: the inverse of the renderer's.
fn srgb_to_xyz() -> DMat3 {
    let column = |c: usize| DVec3::from_array(xyz_to_linear_srgb(std::array::from_fn(|k| (k == c) as u8 as f64)));
    DMat3::from_cols(column(0), column(1), column(2)).inverse()
}

/// The CIE 1931 chromaticity (x, y) of a linear sRGB colour.
fn chromaticity(rgb: [f64; 3]) -> [f64; 2] {
    let xyz = srgb_to_xyz() * DVec3::from_array(rgb);
    let sum = xyz.x + xyz.y + xyz.z;
    [xyz.x / sum, xyz.y / sum]
}

#[test]
fn equal_energy_light_has_the_chromaticity_of_a_flat_spectrum() {
    // Illuminant E is x = y = 1/3 over the whole spectrum; the range cut to 400-700 nm moves it by 0.0005.
    let [x, y] = chromaticity(Illuminant::EqualEnergy.white());
    assert!((x - 1.0 / 3.0).abs() < 1e-3 && (y - 1.0 / 3.0).abs() < 1e-3, "({x}, {y})");
    // In sRGB it is a little pink: more red than green, more green than blue, luminance 1.
    let [r, g, b] = Illuminant::EqualEnergy.white();
    assert!(r > 1.15 && g < 1.0 && b < g, "({r}, {g}, {b})");
    assert!(((srgb_to_xyz() * DVec3::new(r, g, b)).y - 1.0).abs() < 1e-12);
}

#[test]
fn the_srgb_matrix_is_the_standards_up_to_the_range_cut() {
    // IEC 61966-2-1's published matrix; the renderer's is derived from the same primaries with the white point
    // that D65 integrates to over 400-700 nm, which differs from the standard's by the range cut.
    let published = [
        [3.240_454_2, -1.537_138_5, -0.498_531_4],
        [-0.969_266_0, 1.876_010_8, 0.041_556_0],
        [0.055_643_4, -0.204_025_9, 1.057_225_2],
    ];
    for (row, published_row) in published.iter().enumerate() {
        for (c, &want) in published_row.iter().enumerate() {
            let got = xyz_to_linear_srgb(std::array::from_fn(|k| (k == c) as u8 as f64))[row];
            assert!(((got - want) / want).abs() < 0.004, "row {row}, column {c}: {got} against {want}");
        }
    }
}

#[test]
fn band_colours_run_from_violet_to_red() {
    let b = bands(8, Illuminant::D65);
    let (first, last) = (b[0].color(), b[7].color());
    assert!(first.b() > first.g() && first.b() > 0.0, "the shortest band is bluish: {first:?}");
    assert!(
        last.r() > 0.0 && last.g() < last.r() * 0.1 && last.b().abs() < last.r() * 0.05,
        "the longest is red: {last:?}"
    );
    // A green band has negative red: monochromatic colours lie outside the sRGB gamut.
    let green = Band::nth(4, 10, Illuminant::D65);
    assert!(green.weight[1] > 0.0 && green.weight[0] < 0.0, "{green:?}");
}

#[test]
fn the_colour_matching_functions_are_the_cie_tables() {
    // Rows of the CIE 1931 2° observer (ISO/CIE 11664-1) at 5 nm, and the linear interpolation between them.
    for (lambda, want) in [
        (380.0, [0.001368, 0.000039, 0.006450]),
        (450.0, [0.336200, 0.038000, 1.772110]),
        (555.0, [0.512050, 1.000000, 0.005750]),
        (600.0, [1.062200, 0.631000, 0.000800]),
        (700.0, [0.011359, 0.004102, 0.000000]),
        (557.5, [0.553275, 0.997500, 0.004825]),
    ] {
        let got = cie_xyz(lambda);
        for c in 0..3 {
            assert!((got[c] - want[c]).abs() < 2e-6, "{lambda} nm, channel {c}: {} against {}", got[c], want[c]);
        }
    }
    assert_eq!(cie_xyz(379.0), [0.0; 3]);
    assert_eq!(cie_xyz(781.0), [0.0; 3]);
}

#[test]
fn the_traced_range_holds_nearly_all_of_the_light() {
    for illuminant in [Illuminant::D65, Illuminant::EqualEnergy] {
        let integrate = |a: f64, b: f64| {
            let n = ((b - a) * 10.0) as usize;
            (0..n).fold([0.0; 3], |s, i| {
                let l = a + (i as f64 + 0.5) * 0.1;
                let v = cie_xyz(l);
                std::array::from_fn(|c| s[c] + v[c] * illuminant.power(l) * 0.1)
            })
        };
        let (all, traced) = (integrate(380.0, 780.0), integrate(LAMBDA_MIN as f64, LAMBDA_MAX as f64));
        for c in 0..3 {
            let outside = 1.0 - traced[c] / all[c];
            assert!(outside < 0.005, "{illuminant:?}, channel {c}: {:.2}% outside the traced range", outside * 100.0);
        }
    }
}

/// A one-pixel render of a white environment seen in the band from `lo` to `hi` nm alone: the band's colour
/// as the renderer adds it up, outside the gamut as it is.
fn seen_in_band(lo: f64, hi: f64, illuminant: Illuminant) -> Color {
    let mut scene = Scene::new(Default::default());
    scene.environment = Some(Arc::new(ConstantEnvironment(Color::WHITE)));
    let settings = RenderSettings { width: 1, height: 1, ..Default::default() };
    let plan = SpectralPlan::Passes(vec![Band::between(lo, hi, illuminant)]);
    render_with_plan(&scene, &settings, plan).unwrap().0.pixels[0]
}

#[test]
fn a_single_wavelength_lands_on_its_cie_chromaticity() {
    // The spectral locus of the CIE 1931 diagram (CIE 015, the chromaticities of the pure wavelengths).
    let locus = [
        (450.0, [0.1566, 0.0177]),
        (480.0, [0.0913, 0.1327]),
        (500.0, [0.0082, 0.5384]),
        (520.0, [0.0743, 0.8338]),
        (550.0, [0.3016, 0.6923]),
        (580.0, [0.5125, 0.4866]),
        (600.0, [0.6270, 0.3725]),
        (650.0, [0.7260, 0.2740]),
    ];
    for illuminant in [Illuminant::D65, Illuminant::EqualEnergy] {
        for (lambda, [x, y]) in locus {
            let c = seen_in_band(lambda - 0.05, lambda + 0.05, illuminant);
            let [gx, gy] = chromaticity(c.to_array().map(f64::from));
            assert!((gx - x).abs() < 5e-4 && (gy - y).abs() < 5e-4, "{lambda} nm: ({gx:.4}, {gy:.4}), CIE ({x}, {y})");
            // Every pure wavelength lies outside the sRGB gamut: the frame keeps its negative channel.
            assert!(c.0.min_element() < 0.0, "{lambda} nm: {c:?}");
        }
    }
}

#[test]
fn colours_outside_the_gamut_are_mapped_as_documented_and_kept_in_exr() {
    let raw = seen_in_band(519.0, 521.0, Illuminant::D65) * 1000.0;
    let frame = Frame { width: 1, height: 1, pixels: vec![raw] };
    // clip, the default: negative channels become 0, the others stay.
    let clipped = Film::default().develop(frame.clone(), false).pixels[0];
    let expected = raw.to_array().map(|v| v.max(0.0));
    assert_eq!(clipped.to_array().map(|v| v.max(0.0)), expected);
    assert_eq!(
        frame.to_rgb8().get_pixel(0, 0).0,
        Frame { pixels: vec![Color::new(expected[0], expected[1], expected[2])], ..frame.clone() }
            .to_rgb8()
            .get_pixel(0, 0)
            .0
    );
    assert_eq!(GamutMapping::Clip.apply(raw).to_array(), expected);
    // fit: grey of the same luminance mixed in.
    let fitted = Film { gamut: GamutMapping::Fit, ..Film::default() }.develop(frame.clone(), false).pixels[0];
    assert_eq!(fitted, fit_to_gamut(raw));
    assert!(fitted.0.min_element() >= 0.0 && (fitted.luminance() - raw.luminance()).abs() < 1e-3 * raw.luminance());
    // A linear output keeps the colour as it is, and an EXR file holds its negative channel.
    assert_eq!(Film { gamut: GamutMapping::Fit, ..Film::default() }.develop(frame.clone(), true).pixels[0], raw);
    let dir = common::root().join("target").join("dispersion");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("outside-the-gamut.exr");
    frame.save(&path).unwrap();
    let read = image::open(&path).unwrap().to_rgb32f();
    assert_eq!(read.get_pixel(0, 0).0, raw.to_array(), "the EXR file holds the unmapped colour");
    assert!(raw.r() < 0.0, "520 nm has negative red: {raw:?}");
}

/// A surface that says it depends on the wavelength but looks white in every one: the renderer must split
/// its paths, and the split must still add up to the light's colour.
struct WavelengthBlind;
impl Shader for WavelengthBlind {
    fn shade(&self, _ray: &Ray, _info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {
        Color::WHITE
    }
    fn is_dispersive(&self) -> bool {
        true
    }
}

#[test]
fn white_light_through_every_plan_stays_exactly_white() {
    let white_scene = |dispersive_wall: bool, illuminant: Illuminant| {
        let mut scene = Scene::new(Default::default());
        scene.environment = Some(Arc::new(ConstantEnvironment(Color::WHITE)));
        scene.illuminant = illuminant;
        if dispersive_wall {
            // The wall fills the left half of the picture: those paths split, the others do not.
            scene.add(
                Node::new(Plane::new(0.0, 1000.0), WavelengthBlind).rotate(0.0, 0.0, 90.0).translate(Vector::X * -0.01),
            );
        }
        scene
    };
    let mut s = RenderSettings { width: 8, height: 6, spp: 5, ..Default::default() };
    for spp in [5, 1] {
        s.spp = spp;
        for illuminant in [Illuminant::D65, Illuminant::EqualEnergy] {
            let [r, g, b] = illuminant.white();
            let white = Color::new(r as f32, g as f32, b as f32);
            for plan in [
                SpectralPlan::Passes(bands(8, illuminant)),
                SpectralPlan::Passes(bands(3, illuminant)),
                SpectralPlan::Sampled,
                SpectralPlan::Hero { per_path: 8 },
                SpectralPlan::Hero { per_path: 3 },
            ] {
                for wall in [false, true] {
                    let (frame, _) = render_with_plan(&white_scene(wall, illuminant), &s, plan.clone()).unwrap();
                    assert!(
                        frame.pixels.iter().all(|&p| p == white),
                        "{illuminant:?}, {plan}, wall {wall}, spp {spp}: {:?}",
                        frame.pixels
                    );
                }
            }
        }
    }
    // D65 is sRGB's white: exactly (1, 1, 1).
    let (frame, _) =
        render_with_plan(&white_scene(true, Illuminant::D65), &s, SpectralPlan::Hero { per_path: 8 }).unwrap();
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
    let bands8 = bands(8, Illuminant::D65);
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
    let passes =
        |k: &str| run::<dispersion::Options>(&args_with(&["--spectral", "passes", "--wavelengths", k, "--spp", "1"]));
    let (_, two) = passes("2");
    let (_, eight) = passes("8");
    let (_, sampled) = run::<dispersion::Options>(&args_with(&["--spectral", "sampled", "--spp", "3"]));
    let (_, hero) = run::<dispersion::Options>(&args_with(&["--spectral", "hero", "--wavelengths", "8", "--spp", "1"]));
    let pixels = 96 * 72;
    assert_eq!(two.spectral.passes(), 2);
    assert_eq!(two.counters.rays_by_depth[0], pixels * 2);
    assert_eq!(eight.counters.rays_by_depth[0], pixels * 8);
    assert_eq!(sampled.spectral, SpectralPlan::Sampled);
    assert_eq!(sampled.counters.rays_by_depth[0], pixels * 3);
    // Hero sampling: every camera path is traced once, and again for each of its 7 other wavelengths only
    // where it met the glass.
    assert_eq!(hero.spectral, SpectralPlan::Hero { per_path: 8 });
    let again = hero.counters.rays_by_depth[0] - pixels;
    assert_eq!(again % 7, 0, "{again}");
    let split = again / 7;
    assert!(split > pixels / 10 && split < pixels * 9 / 10, "{split} of {pixels} paths split");
    assert!(
        hero.counters.total() < eight.counters.total(),
        "{} against {}",
        hero.counters.total(),
        eight.counters.total()
    );
}

#[test]
fn hero_paths_that_meet_no_dispersive_glass_are_those_of_the_white_render() {
    // A scene with nothing dispersive traced with the hero plan anyway: every path counts as white light,
    // so the picture and the rays are those of the white render, bit for bit.
    let (scene, settings) = common::parse::<bitmap_textures::Options>(&args_with(&[])).prepare().unwrap();
    let (white, white_stats) = render(&scene, &settings).unwrap();
    let (hero, hero_stats) = render_with_plan(&scene, &settings, SpectralPlan::Hero { per_path: 8 }).unwrap();
    assert!(white == hero, "the hero plan changed a scene without dispersion");
    assert_eq!(white_stats.counters, hero_stats.counters);
    // The dispersion example: every pixel whose paths all missed the glass (one camera ray per sample) is
    // the pixel of the same scene traced in white light; the others split and differ.
    let cli = common::parse::<dispersion::Options>(&args_with(&["--spectral", "hero", "--spp", "2"]));
    let (scene, settings) = cli.prepare().unwrap();
    let (white, _) = render_with_plan(&scene, &settings, SpectralPlan::White).unwrap();
    let (mut missed, mut split) = (0, 0);
    for y in 0..settings.height {
        for (x, trace) in lecture6::lesson::render::render_row(&scene, &settings, y, 0..settings.width)
            .unwrap()
            .into_iter()
            .enumerate()
        {
            if trace.counters.rays_by_depth[0] == settings.spp as u64 {
                missed += 1;
                assert_eq!(trace.color, white.get(x as u32, y), "pixel ({x}, {y}) met no glass");
            } else {
                split += 1;
            }
        }
    }
    assert!(missed > 1000 && split > 1000, "{missed} pixels missed the glass, {split} split");
}

/// The column (x) of the centre of the light brighter than `floor` in row `y`, from column `x0` to `x1`.
fn centre_of_light(frame: &Frame, y: u32, (x0, x1): (u32, u32), channel: impl Fn(Color) -> f32, floor: f32) -> f32 {
    let (mut sum, mut moment) = (0.0, 0.0);
    for x in x0..x1 {
        let v = (channel(frame.get(x, y)) - floor).max(0.0);
        sum += v;
        moment += v * x as f32;
    }
    moment / sum
}

#[test]
fn the_rainbow_keeps_its_colour_order_and_place_in_every_mode() {
    // The prism's spectrum of the slit, at 160 x 120: where single wavelengths land (the example's scene seen
    // in a 2 nm band alone), and where each channel of the whole spectrum's picture lies, in three rows.
    let cli = common::parse::<dispersion::Options>(&["--width", "160", "--height", "120", "--spp", "4"]);
    let (scene, settings) = cli.prepare().unwrap();
    let (rows, columns) = ([45, 60, 75], (11, 42));
    let luminance = |c: Color| c.luminance();
    let arc = |lambda: f64| {
        let plan = SpectralPlan::Passes(vec![Band::between(lambda - 1.0, lambda + 1.0, Illuminant::D65)]);
        let (frame, _) = render_with_plan(&scene, &settings, plan).unwrap();
        rows.map(|y| {
            let peak = (columns.0..columns.1).map(|x| frame.get(x, y).luminance()).fold(0.0, f32::max);
            centre_of_light(&frame, y, columns, luminance, 0.5 * peak)
        })
    };
    let (violet, green, red) = (arc(450.0), arc(540.0), arc(650.0));
    for k in 0..3 {
        // Violet is bent the most: it lands farthest from where the slit is seen straight, on the left.
        assert!(violet[k] + 3.0 < green[k] && green[k] + 1.0 < red[k], "row {}: {violet:?} {green:?} {red:?}", rows[k]);
    }
    let mut centres = Vec::new();
    for plan in
        [SpectralPlan::Passes(bands(8, Illuminant::D65)), SpectralPlan::Hero { per_path: 8 }, SpectralPlan::Sampled]
    {
        let (frame, _) = render_with_plan(&scene, &RenderSettings { spp: 16, ..settings }, plan.clone()).unwrap();
        for (k, &y) in rows.iter().enumerate() {
            let [r, g, b] =
                [Color::r, Color::g, Color::b].map(|channel| centre_of_light(&frame, y, columns, channel, 0.5));
            assert!(b < g && g < r, "{plan}, row {y}: blue {b}, green {g}, red {r}");
            assert!(
                violet[k] - 1.0 < b && r < red[k] + 1.0,
                "{plan}, row {y}: {b}..{r} outside {}..{}",
                violet[k],
                red[k]
            );
            centres.push([r, g, b]);
        }
    }
    // The two modes that sample the spectrum continuously put the colours in the same places, to a pixel; the
    // 8 passes, which draw it as 8 copies of the slit, to two and a half (the shortest band, 400-437.5 nm,
    // is traced at 418.75 nm alone).
    let (passes, hero, sampled) = (&centres[0..3], &centres[3..6], &centres[6..9]);
    for k in 0..3 {
        for c in 0..3 {
            assert!(
                (hero[k][c] - sampled[k][c]).abs() < 1.0,
                "row {}: hero {:?}, sampled {:?}",
                rows[k],
                hero[k],
                sampled[k]
            );
            assert!(
                (hero[k][c] - passes[k][c]).abs() < 2.5,
                "row {}: hero {:?}, passes {:?}",
                rows[k],
                hero[k],
                passes[k]
            );
        }
    }
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
    let plan = SpectralPlan::Passes(bands(8, Illuminant::D65));
    let (passes, _) = render_with_plan(&scene, &args.prepare().unwrap().1, plan).unwrap();
    assert!(white == passes, "V_d = inf traced in 8 passes differs from the white render");
    // A little dispersion does change the picture (so the comparison above could fail).
    let (dispersive, _) = parse(&["--glass", "abbe", "--nd", "1.7", "--abbe", "60", "--spp", "1"]).render().unwrap();
    let d = lecture6::instruments::compare::difference(&white.to_rgb8(), &dispersive.to_rgb8()).unwrap();
    assert!(d.large_pixels > 0, "Abbe number 60 left no visible colour fringe: {d}");
}

#[test]
fn dispersion_is_identical_for_any_thread_count_and_finite() {
    for mode in ["passes", "sampled", "hero"] {
        let a = run::<dispersion::Options>(&args_with(&["--threads", "1", "--spectral", mode])).0;
        let b = run::<dispersion::Options>(&args_with(&["--threads", "2", "--spectral", mode])).0;
        assert!(a == b, "{mode}: the picture changed with the thread count");
        // Colours outside the gamut keep their negative channels in the frame; none is NaN or infinite.
        assert!(a.pixels.iter().all(|p| p.is_finite()), "{mode}");
        assert!(a.pixels.iter().any(|p| p.0.min_element() < 0.0), "{mode}: no colour outside the gamut");
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
        (&["--illuminant", "d50"][..], "d50"),
        (&["--gamut", "wrap"][..], "wrap"),
        (&["--spectral", "heroic"][..], "heroic"),
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
