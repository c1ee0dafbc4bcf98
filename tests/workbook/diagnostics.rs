//! The end-of-run report (`lecture6::lesson::diagnostics`): a student's geometry that leaves its hit point
//! off the surface, or returns a NaN or unnormalised normal, a shader that returns NaN, and a shader that
//! reads the ray's wavelength without saying so, are named by the line the render prints; the API page's
//! own cylinder, done right, is not; in both readings, by default and with `--slide`. (That the lines reach the
//! end of the run's output: `reflection_refraction::reflection_v01_*`, whose runaway the report explains.)

use lecture6::lesson::beyond::Steps;
use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::lesson::shader::IntoShader;
use lecture6::lesson::spectral::{LAMBDA_MAX, LAMBDA_MIN, SpectralPlan};
use lecture6::prelude::*;

/// The API page's geometry (docs/homework-api.md, "Write a geometry"), the file docs/homework_geometry.rs.
#[path = "../../docs/homework_geometry.rs"]
mod homework_geometry;

pub(crate) use homework_geometry::Cylinder;

/// The cylinder with one mistake a student makes: its hit point as `ray.at(t)` (not put back on the
/// surface), its normal NaN, or its normal not normalised.
#[derive(Clone, Copy)]
pub(crate) enum Mistake {
    AtT,
    NanNormal,
    LongNormal,
}

pub(crate) struct Mistaken(pub(crate) Mistake);

impl Geometry for Mistaken {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        let info = Cylinder.intersect(ray, t_max)?;
        Some(match self.0 {
            Mistake::AtT => IntersectionInfo { ip: ray.at(info.distance), ..info },
            Mistake::NanNormal => IntersectionInfo { normal: Vector::ZERO.normalize(), ..info },
            Mistake::LongNormal => IntersectionInfo { normal: info.normal * 2.0, ..info },
        })
    }

    fn bounds(&self) -> Option<Aabb> {
        Cylinder.bounds()
    }
}

/// A mirror cylinder, stretched and turned, seen from far enough that `ray.at(t)` is off its surface by
/// more than the hit's error bound, beside a mirror ball; a striped sky.
pub(crate) fn scene(cylinder: impl Geometry + 'static, shader: impl IntoShader) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 40.0, -300.0), Vector::ZERO, 12.0));
    scene.add(Node::new(cylinder, shader).named("pillar").scale(Vector::new(8.0, 20.0, 8.0)).rotate(20.0, 0.0, 30.0));
    scene.add(Node::new(Sphere::new(Vector::new(25.0, 0.0, 0.0), 8.0), Reflection::new(0.9)));
    scene.environment = Some(workbook::sky().unwrap());
    scene
}

/// The settings the scenes here are rendered with.
fn settings() -> RenderSettings {
    RenderSettings { width: 160, height: 120, spp: 1, ..RenderSettings::default() }
}

/// The scene rendered by default; rendered in the slides' reading too (`--slide`), whose report must name the
/// same nodes and shaders for the same problems (the counts may differ: the two readings trace other rays).
pub(crate) fn rendered(scene: &Scene) -> RenderStats {
    let stats = render(scene, &settings()).unwrap().1;
    let mut slides = scene.clone();
    slides.steps = Steps::SLIDES;
    let slide_stats = render(&slides, &settings()).unwrap().1;
    let named = |stats: &RenderStats| -> Vec<String> {
        stats.warnings.iter().map(|l| l.chars().filter(|c| !c.is_ascii_digit() && *c != '.').collect()).collect()
    };
    assert_eq!(named(&slide_stats), named(&stats), "the two readings' reports differ");
    stats
}

/// The one report line that contains `what`.
pub(crate) fn line<'a>(stats: &'a RenderStats, what: &str) -> &'a str {
    let lines: Vec<_> = stats.warnings.iter().filter(|l| l.contains(what)).collect();
    assert_eq!(lines.len(), 1, "one line about {what}: {:?}", stats.warnings);
    lines[0]
}

#[test]
fn the_pages_cylinder_renders_without_a_word() {
    let stats = rendered(&scene(Cylinder, Reflection::new(0.9)));
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    assert!(stats.counters.rays_by_depth[1] > 1000, "the mirror cylinder reflects: {:?}", stats.counters);
}

#[test]
fn a_hit_point_left_at_ray_at_t_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::AtT), Reflection::new(0.9)));
    let line = line(&stats, "self-intersection");
    assert!(line.contains("pillar (Reflection)"), "{line}");
    assert!(!line.contains("Sphere"), "{line}");
    // The course's mirror spawns its rays: the advice is the geometry's fix, not the shader's.
    assert!(line.contains("IntersectionInfo::with_error") && !line.contains("spawn"), "{line}");
}

#[test]
fn a_nan_normal_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::NanNormal), Reflection::new(0.9)));
    assert!(line(&stats, "not of unit length, or NaN").contains("pillar (Reflection)"), "{:?}", stats.warnings);
}

#[test]
fn a_normal_not_normalised_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::LongNormal), Lambert::new(Color::WHITE)));
    assert!(line(&stats, "not of unit length").contains("pillar (Lambert)"), "{:?}", stats.warnings);
}

/// A shader that returns NaN, as `0.0 / 0.0` in a student's formula would.
pub(crate) struct Broken;

impl Shader for Broken {
    fn shade(&self, _: &Ray, _: &IntersectionInfo, _: &mut TraceContext) -> Color {
        Color::gray(f32::NAN)
    }
}

#[test]
fn a_nan_colour_is_counted_and_named_where_it_was_made() {
    // The NaN is made by the pillar and seen in the mirror ball too: only the pillar made it.
    let stats = rendered(&scene(Cylinder, Broken));
    let line = line(&stats, "NaN or infinite");
    assert!(line.starts_with(&format!("{} sample(s)", stats.counters.non_finite_samples)), "{line}");
    assert!(line.contains("made by the shader of pillar (Broken)") && !line.contains("Sphere"), "{line}");
}

/// A texture that gives NaN, as `0.0 / 0.0` in a student's formula would.
struct BrokenTexture;

impl Texture for BrokenTexture {
    fn get_tex_color(&self, _: &Ray, _: &IntersectionInfo) -> Color {
        Color::gray(f32::NAN)
    }
}

#[test]
fn a_nan_made_on_the_workbooks_own_sphere_is_named_there() {
    // A Lambert sphere coloured by a student's texture is one of the workbook's own nodes (its shape and
    // shader are the workbook's), which the renderer shades without a shading point of its own: the NaN
    // it makes is still counted against it, and not against the mirror ball that sees it.
    let mut scene = scene(Cylinder, Reflection::new(0.9));
    scene.nodes[0] =
        Node::new(Sphere::new(Vector::new(-25.0, 0.0, 0.0), 8.0), Lambert::new(BrokenTexture)).named("ball");
    scene.lights.push(PointLight::new(Vector::new(0.0, 100.0, -100.0), Color::WHITE, 20000.0));
    let stats = rendered(&scene);
    let line = line(&stats, "NaN or infinite");
    assert!(line.contains("made by the shader of ball (Lambert)") && !line.contains("Sphere"), "{line}");
}

/// The colour of a ray's wavelength as a student's shader or texture might make it: blue at the short end of
/// the visible spectrum, red at the long end, white in white light.
fn spectrum(ray: &Ray) -> Color {
    match ray.wavelength {
        Some(lambda) => {
            let t = (lambda - LAMBDA_MIN) / (LAMBDA_MAX - LAMBDA_MIN);
            Color::new(t, 0.2, 1.0 - t)
        }
        None => Color::WHITE,
    }
}

/// A shader of a student's own that reads the ray's wavelength, and says so or not.
struct Spectrum {
    says_so: bool,
}

impl Shader for Spectrum {
    fn shade(&self, ray: &Ray, _: &IntersectionInfo, _: &mut TraceContext) -> Color {
        spectrum(ray)
    }
    fn is_dispersive(&self) -> bool {
        self.says_so
    }
}

/// A texture of a student's own that reads the ray's wavelength, and says so or not.
struct SpectrumTexture {
    says_so: bool,
}

impl Texture for SpectrumTexture {
    fn get_tex_color(&self, ray: &Ray, _: &IntersectionInfo) -> Color {
        spectrum(ray)
    }
    fn is_dispersive(&self) -> bool {
        self.says_so
    }
}

/// `scene` with ambient light, so that a matte surface shows its colour (a shader that gives black in every
/// wavelength where it is tried cannot be caught).
fn lit(mut scene: Scene) -> Scene {
    scene.ambient = Color::gray(0.3);
    scene
}

/// The pillar's shaders that read the wavelength, saying so or not, and the name the report gives the
/// pillar: the student's shader itself, a `Layered` shader holding it over a matte base, and a `Lambert` of
/// the student's texture (which asks the texture).
fn reading_the_wavelength(says_so: bool) -> [(Arc<dyn Shader>, &'static str); 3] {
    let mut layered = Layered::new();
    layered.add_layer(Lambert::new(Color::gray(0.5)), Color::WHITE, None).add_layer(
        Spectrum { says_so },
        Color::gray(0.5),
        None,
    );
    [
        (Arc::new(Spectrum { says_so }), "pillar (Spectrum)"),
        (Arc::new(layered), "pillar (Layered)"),
        (Arc::new(Lambert::new(SpectrumTexture { says_so })), "pillar (Lambert)"),
    ]
}

/// The student's mistake: a shader (or the texture of one) that reads `ray.wavelength` but keeps the default
/// `is_dispersive`, false. The scene is traced in white light, so the shader shows nothing of the spectrum;
/// the report says so and names the pillar, not the mirror ball that sees it, in the default reading and in
/// the slides'.
#[test]
fn a_shader_that_reads_the_wavelength_without_saying_so_is_named() {
    for (shader, name) in reading_the_wavelength(false) {
        let scene = lit(scene(Cylinder, shader));
        let stats = rendered(&scene);
        assert_eq!(stats.spectral, SpectralPlan::White, "{name}: traced in white light");
        let line = line(&stats, "is_dispersive");
        assert!(line.contains(name) && !line.contains("Sphere"), "{name}: {line}");
    }
}

/// Done right, the same shaders are traced in wavelengths and nothing is reported: the Lambert of a texture
/// that says it reads the wavelength is dispersive without a word of its own.
#[test]
fn a_shader_that_says_it_reads_the_wavelength_is_traced_in_wavelengths_without_a_word() {
    for (shader, name) in reading_the_wavelength(true) {
        let scene = lit(scene(Cylinder, shader));
        assert!(scene.is_dispersive(), "{name}");
        let stats = rendered(&scene);
        assert_ne!(stats.spectral, SpectralPlan::White, "{name}");
        assert!(stats.warnings.is_empty(), "{name}: {:?}", stats.warnings);
    }
}

/// `scene` rendered at `settings` with every node's shape and shader hidden behind a type the renderer does not
/// know (so that every hit is weighed by the energy check, as a student's shader's is), checked for energy gains:
/// none at all, on any hit, and no line of the report about one. Returns how many hits were weighed.
fn weighed_without_a_gain(what: &str, scene: &Scene, settings: &RenderSettings) -> u64 {
    let (_, stats) = render(&crate::common::hidden::through_trait_objects(scene), settings).unwrap();
    let gains = &stats.counters.problems.energy_gains;
    assert!(gains.iter().all(|g| g.gained == 0), "{what}: {gains:?}");
    assert!(!stats.warnings.iter().any(|l| l.contains("more light")), "{what}: {:?}", stats.warnings);
    gains.iter().map(|g| g.hits).sum()
}

/// No false alarm: the energy check finds no gain in any of the workbook's examples or the API page's
/// homeworks (docs/homework_scene.rs, docs/homework_glossy.rs, the cylinder of docs/homework_geometry.rs as a
/// mirror), every node weighed, by default and with `--slide`; it weighs glass, glossy mirrors, Fresnel-blended
/// Layered shaders, dispersive glass and photon-lit floors among them (those examples must have weighed hits).
#[test]
fn the_energy_check_finds_no_gain_in_the_workbooks_examples_or_the_pages_homeworks() {
    use crate::branching::homework_glossy;
    use crate::common::{examples, parse};
    use crate::homework::homework_scene;
    for reading in [&[][..], &["--slide"]] {
        let args = [&["--width", "80", "--height", "60", "--spp", "1"][..], reading].concat();
        let mut weighed = Vec::new();
        macro_rules! weigh {
            ($($name:ident),*) => {$(
                let (scene, settings) = parse::<examples::$name::Options>(&args).prepare().unwrap();
                let hits = weighed_without_a_gain(stringify!($name), &scene, &settings);
                println!("{}{reading:?}: {hits} hits weighed", stringify!($name));
                weighed.push((stringify!($name), hits));
            )*};
        }
        every_example!(weigh);
        for name in ["layered", "fresnel", "glossy", "dispersion", "photon_map"] {
            assert!(weighed.iter().any(|&(n, hits)| n == name && hits > 0), "{name}{reading:?}: {weighed:?}");
        }
        let (scene, settings) = parse::<homework_scene::Options>(&args).prepare().unwrap();
        assert!(weighed_without_a_gain("homework_scene", &scene, &settings) > 0, "{reading:?}");
        let (scene, settings) = parse::<homework_glossy::Options>(&args).prepare().unwrap();
        assert!(weighed_without_a_gain("homework_glossy", &scene, &settings) > 0, "{reading:?}");
        let mut pillar = self::scene(Cylinder, Reflection::new(0.9));
        pillar.steps = if reading.is_empty() { Steps::default() } else { Steps::SLIDES };
        weighed_without_a_gain("homework_geometry", &pillar, &settings);
    }
}

/// No false alarm on the course's scene files either: each `.qdmg` of the course's repository's `data/`
/// folder (GitHub anrieff/quaddamage, where `QUADDAMAGE_DATA` points; skipped without it), with
/// `--skip-unsupported`, rendered at 80x60 with every node weighed, by default and with `--slide`.
#[test]
fn the_energy_check_finds_no_gain_in_the_courses_scene_files() {
    use crate::common::{examples::scene_file, parse};
    let Some(data) = std::env::var_os("QUADDAMAGE_DATA").map(std::path::PathBuf::from).filter(|d| d.is_dir()) else {
        eprintln!("skipped: QUADDAMAGE_DATA does not name the course's data/ folder");
        return;
    };
    let mut files = Vec::new();
    let mut folders = vec![data];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "qdmg") {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(!files.is_empty(), "no scene file under QUADDAMAGE_DATA");
    for file in &files {
        for reading in [&[][..], &["--slide"]] {
            let small = ["--width", "80", "--height", "60", "--spp", "1", "--skip-unsupported"];
            let args = [&[file.to_str().unwrap()][..], &small, reading].concat();
            let (scene, settings) = parse::<scene_file::Options>(&args).prepare().unwrap();
            let hits = weighed_without_a_gain(&file.display().to_string(), &scene, &settings);
            println!("{}{reading:?}: {hits} hits weighed", file.display());
        }
    }
}
