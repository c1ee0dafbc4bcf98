//! The end-of-run report (`lecture6::lesson::diagnostics`): a student's geometry that leaves its hit point
//! off the surface, or returns a NaN or unnormalised normal, a shader that returns NaN, and a shader that
//! reads the ray's wavelength without saying so, are named by the line the render prints; the API page's
//! own cylinder, done right, is not; in both readings, by default and with `--slide`. (That the lines reach the
//! end of the run's output: `reflection_refraction::reflection_v01_*`, whose runaway the report explains.)

use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::lesson::shader::IntoShader;
use lecture6::lesson::spectral::{LAMBDA_MAX, LAMBDA_MIN, SpectralPlan};
use lecture6::prelude::*;

/// The API page's geometry (docs/homework-api.md, "Write a geometry"), the file docs/homework_geometry.rs.
#[path = "../../docs/homework_geometry.rs"]
mod homework_geometry;

use homework_geometry::Cylinder;

/// The cylinder with one mistake a student makes: its hit point as `ray.at(t)` (not put back on the
/// surface), its normal NaN, or its normal not normalised.
#[derive(Clone, Copy)]
enum Mistake {
    AtT,
    NanNormal,
    LongNormal,
}

struct Mistaken(Mistake);

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
fn scene(cylinder: impl Geometry + 'static, shader: impl IntoShader) -> Scene {
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
fn rendered(scene: &Scene) -> RenderStats {
    let stats = render(scene, &settings()).unwrap().1;
    let mut slides = scene.clone();
    slides.steps = lecture6::lesson::beyond::Steps::SLIDES;
    let slide_stats = render(&slides, &settings()).unwrap().1;
    let named = |stats: &RenderStats| -> Vec<String> {
        stats.warnings.iter().map(|l| l.chars().filter(|c| !c.is_ascii_digit() && *c != '.').collect()).collect()
    };
    assert_eq!(named(&slide_stats), named(&stats), "the two readings' reports differ");
    stats
}

/// The one report line that contains `what`.
fn line<'a>(stats: &'a RenderStats, what: &str) -> &'a str {
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
struct Broken;

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
