//! The teaching instruments: the ray tree of a pixel (`--trace-pixel`), the debug views (`--view`) and the
//! side-by-side picture (`--side-by-side`), on the workbook's own examples.

use crate::common;

use common::examples::{bitmap_textures, fresnel, glossy, layered, photon_map, reflect_v02, refract, scene_file};
use lecture6::app::cli::Example;
use lecture6::instruments::debug_view::{DebugImage, DebugView, heat, render_view};
use lecture6::instruments::ray_tree::{self, NoteKind, PixelPos, RayKind, RayTree, TermKind, TraceFormat};
use lecture6::instruments::side_by_side::{Panel, compose};
use lecture6::lesson::observer::{LightTerm, Stop};
use lecture6::lesson::photon_map::CONE_FILTER_K;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::shader::IntoShader;
use lecture6::lesson::topic::Topic;
use lecture6::prelude::*;

/// Whether two colours agree to float rounding of sums of a few hundred terms.
fn close(a: Color, b: Color) -> bool {
    (a - b).0.abs().max_element() <= 1e-5 + 1e-4 * a.max_channel().max(b.max_channel())
}

/// Renders the small frame of `args`, then each of `pixels` alone with its ray tree, and checks the trees
/// (see [`check_scene_trees`]).
fn check_trees<E: Example>(args: &[&str], pixels: &[(u32, u32)]) -> Vec<RayTree> {
    let cli = common::parse::<E>(args);
    let (scene, settings) = cli.prepare().unwrap();
    check_scene_trees(&scene, &settings, pixels, &format!("{args:?}"))
}

/// Renders the frame of `scene`, then each of `pixels` alone with its ray tree, and checks that the pixel is
/// the one of the frame, that every camera ray's tree explains the colour the ray brought back (the light
/// terms, the shaders' own colours and the environment seen, times the factors on their way), that every
/// hit's terms add up to what its shader returned, and that the samples' mean is the pixel. Returns the
/// trees.
fn check_scene_trees(scene: &Scene, settings: &RenderSettings, pixels: &[(u32, u32)], what: &str) -> Vec<RayTree> {
    let (frame, _) = render(scene, settings).unwrap();
    let mut trees = Vec::new();
    for &(x, y) in pixels {
        let traced = ray_tree::trace(scene, settings, PixelPos { x, y }).unwrap();
        assert_eq!(traced.color, frame.get(x, y), "{what} pixel ({x}, {y}) alone differs from the frame's");
        let tree = traced.tree;
        // One camera ray per sample (of each pass of a progressive caustic); a pixel that adaptive
        // anti-aliasing refines has five.
        let passes = tree.photon_passes.len().max(1);
        let samples = if settings.adaptive_aa { vec![1, 5] } else { vec![settings.spp as usize * passes] };
        assert!(samples.contains(&tree.roots.len()), "{what} ({x}, {y}): {} camera rays", tree.roots.len());
        let mut mean = Color::BLACK;
        for &root in &tree.roots {
            let explained = tree.explained(root, Color::WHITE);
            let returned = tree.rays[root].color;
            assert!(
                close(explained, returned),
                "{what} ({x}, {y}): the tree explains {explained:?}, the ray returned {returned:?}"
            );
            mean += returned.sanitized();
        }
        mean = mean / tree.roots.len() as f32;
        assert!(close(mean, traced.color), "{what} ({x}, {y}): samples average {mean:?}, pixel is {:?}", traced.color);
        for (id, ray) in tree.rays.iter().enumerate() {
            if ray.hit.is_some() {
                assert!(close(tree.terms_sum(id), ray.color), "{what} ({x}, {y}) ray {id}: terms do not add up");
            }
        }
        trees.push(tree);
    }
    trees
}

/// The shaders' own colours in the trees (colour a shader returned beyond everything it gathered).
fn own_colours(trees: &[RayTree]) -> usize {
    trees.iter().flat_map(|t| &t.rays).flat_map(|r| &r.terms).filter(|t| matches!(t.what, TermKind::Own { .. })).count()
}

fn kinds(tree: &RayTree) -> Vec<RayKind> {
    tree.rays.iter().map(|r| r.kind).collect()
}

fn lights(tree: &RayTree) -> Vec<LightTerm> {
    tree.rays
        .iter()
        .flat_map(|r| &r.terms)
        .filter_map(|t| match t.what {
            TermKind::Light { kind, .. } => Some(kind),
            _ => None,
        })
        .collect()
}

#[test]
fn the_glass_sphere_tree_goes_from_the_camera_through_the_glass_to_the_environment() {
    let trees = check_trees::<fresnel::Options>(&["--width", "640", "--height", "480", "--spp", "2"], &[(320, 200)]);
    let tree = &trees[0];
    let first = tree.roots[0];
    assert_eq!(tree.rays[first].kind, RayKind::Camera);
    assert!(tree.rays[first].hit.as_ref().is_some_and(|h| h.shader == "Layered"));
    assert!(kinds(tree).contains(&RayKind::Refraction) && kinds(tree).contains(&RayKind::Reflection));
    assert!(tree.rays.iter().any(|r| r.stop == Some(Stop::Missed) && r.depth >= 2), "a ray leaves the glass");
    let text = tree.to_text(0);
    assert!(text.contains("layer Reflection, blend Fresnel"), "{text}");
    assert!(text.contains("missed: environment colour"), "{text}");
    assert_eq!(own_colours(&trees), 0, "the glass's colour is all rays:\n{text}");
}

#[test]
fn trees_add_up_with_total_internal_reflection() {
    let pixels: Vec<(u32, u32)> = (0..40).map(|i| (40 + i * 2, 60)).collect();
    let trees = check_trees::<refract::Options>(&["--width", "160", "--height", "120", "--ior", "2.42"], &pixels);
    // Total internal reflection: the refraction traces no ray and returns black.
    let tir = |t: &RayTree| {
        t.rays.iter().any(|r| r.hit.as_ref().is_some_and(|h| h.shader == "Refraction") && r.terms.is_empty())
    };
    assert!(trees.iter().any(tir), "no TIR on the row");
    assert_eq!(own_colours(&trees), 0);
}

#[test]
fn trees_add_up_with_glossy_samples_lamps_and_depth_limits() {
    let trees =
        check_trees::<glossy::Options>(&["--width", "80", "--height", "60"], &[(20, 40), (40, 40), (60, 40), (40, 20)]);
    let samples = |t: &RayTree| kinds(t).iter().filter(|&&k| k == RayKind::Reflection).count();
    assert!(trees.iter().any(|t| samples(t) > 1), "no glossy samples traced");
    assert!(trees.iter().any(|t| t.to_text(0).contains("reflection 2 of ")), "glossy samples are numbered");
    // An average's rays each carry the mirror's full factor as their weight: the 1/N is common to them.
    let text: String = trees.iter().map(|t| t.to_text(0)).collect();
    assert!(text.contains("shared with the other ") && text.contains("not known ray by ray"), "{text}");
    assert!(trees.iter().any(|t| lights(t).iter().any(|l| matches!(l, LightTerm::Lamp { .. }))));
    assert_eq!(own_colours(&trees), 0);
    let trees = check_trees::<reflect_v02::Options>(&["--width", "80", "--height", "60"], &[(40, 30), (20, 30)]);
    assert!(trees.iter().any(|t| t.rays.iter().any(|r| r.stop == Some(Stop::DepthLimit))), "no ray at the depth limit");
}

#[test]
fn trees_add_up_through_layers_and_the_photon_map() {
    let trees = check_trees::<layered::Options>(&["--width", "80", "--height", "60"], &[(40, 30), (20, 45), (60, 20)]);
    assert_eq!(own_colours(&trees), 0);
    let args = ["--width", "80", "--height", "60", "--photons", "20000"];
    let pixels: Vec<(u32, u32)> = (0..8).map(|i| (10 * i, 50)).collect();
    let trees = check_trees::<photon_map::Options>(&args, &pixels);
    assert!(trees.iter().any(|t| lights(t).contains(&LightTerm::Photons)), "no photon estimate in the trees");
    assert_eq!(own_colours(&trees), 0);
}

#[test]
fn the_json_tree_is_one_object_naming_every_ray() {
    let trees = check_trees::<fresnel::Options>(&["--width", "64", "--height", "48", "--spp", "1"], &[(32, 20)]);
    let json = trees[0].to_json(0);
    assert!(json.starts_with('{') && json.ends_with('}'));
    assert_eq!(json.matches("\"kind\":").count(), trees[0].rays.len());
    assert_eq!(json.matches('{').count(), json.matches('}').count());
}

/// A homework shader: a tinted metal, its one ray traced with `ctx.raytrace` and tinted afterwards, as the
/// slide's `raytrace(newRay) * multiplier`. Nothing in it speaks to the ray tree.
struct TintedMirror(Color);

impl Shader for TintedMirror {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        ctx.raytrace(&ray.spawn(info, reflect(ray.dir, n), self.0.max_channel())) * self.0
    }
}

/// A homework shader: a toon diffuse surface whose light from the light loop is cut into three bands, and
/// which shows a dim rim colour where no light reaches.
struct Toon(Color);

impl Shader for Toon {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let light = light_loop(ctx, info, faceforward(info.normal, ray.dir), |_, _| Color::BLACK);
        let band = match light.irradiance.luminance() {
            l if l > 0.6 => 1.0,
            l if l > 0.2 => 0.6,
            _ => 0.25,
        };
        self.0 * band
    }
}

/// A floor, a tinted mirror ball and a toon ball under a lamp and a sky.
fn homework_scene() -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 25.0, -60.0), Vector::new(0.0, 8.0, 0.0), 60.0));
    scene.lights.push(PointLight::new(Vector::new(-30.0, 60.0, -30.0), Color::WHITE, 5000.0));
    scene.ambient = Color::gray(0.05);
    scene.environment = Some(Arc::new(ConstantEnvironment(Color::new(0.3, 0.5, 0.9))));
    scene.add(Node::new(Plane::new(0.0, 200.0), Lambert::new(Color::new(0.8, 0.7, 0.5))));
    scene.add(Node::new(Sphere::new(Vector::new(-12.0, 10.0, 0.0), 10.0), TintedMirror(Color::new(0.9, 0.6, 0.2))));
    scene.add(Node::new(Sphere::new(Vector::new(12.0, 10.0, 0.0), 10.0), Toon(Color::new(0.2, 0.8, 0.3))));
    scene
}

#[test]
fn a_students_own_shaders_get_ray_trees_that_add_up_to_their_pixels() {
    let scene = homework_scene();
    let settings = RenderSettings { width: 80, height: 60, spp: 2, ..RenderSettings::default() };
    let pixels: Vec<(u32, u32)> = (0..20).map(|i| (4 * i, 36)).chain((0..15).map(|j| (58, 4 * j))).collect();
    let trees = check_scene_trees(&scene, &settings, &pixels, "homework");
    // The tinted mirror's ray counts as many times as its tint, channel by channel.
    let mirror_factors: Vec<Color> = trees
        .iter()
        .flat_map(|t| t.rays.iter().filter(|r| r.hit.as_ref().is_some_and(|h| h.shader == "TintedMirror")))
        .flat_map(|r| &r.terms)
        .filter(|t| matches!(t.what, TermKind::Ray(_)))
        .map(|t| t.factor)
        .collect();
    assert!(!mirror_factors.is_empty(), "no pixel of the row sees the mirror");
    for f in mirror_factors {
        assert!(close(f, Color::new(0.9, 0.6, 0.2)), "the tinted reflection counts {f:?} times");
    }
    // The toon ball shows its darkest band even where nothing lights it: that is its own colour.
    let toon = trees.iter().flat_map(|t| &t.rays).filter(|r| r.hit.as_ref().is_some_and(|h| h.shader == "Toon"));
    assert!(toon.count() > 0, "no pixel sees the toon ball");
    // What --trace-pixel prints: the shares add up to the camera ray's colour, and nothing is left unexplained.
    let traced = ray_tree::trace(&scene, &settings, PixelPos { x: 58, y: 36 }).unwrap();
    let text = ray_tree::describe("homework", PixelPos { x: 58, y: 36 }, &traced, 0, TraceFormat::Text).unwrap();
    let root = traced.tree.roots[0];
    let returned = format!("returns rgb({:.4}", traced.tree.rays[root].color.r());
    let explained = format!("add up to rgb({:.4}", traced.tree.explained(root, Color::WHITE).r());
    assert!(text.contains(&returned) && text.contains(&explained), "{text}");
}

/// Draws a view of the glossy scene at 64 x 48 and returns it, after checking its size.
fn view(v: DebugView, extra: &[&str]) -> DebugImage {
    let mut args = vec!["--width", "64", "--height", "48"];
    args.extend(extra);
    let (scene, settings) = common::parse::<glossy::Options>(&args).prepare().unwrap();
    let picture = render_view(&scene, &settings, v).unwrap();
    assert_eq!(picture.image.dimensions(), (64, 48));
    assert!(picture.range.0.is_finite() && picture.range.1.is_finite() && picture.range.0 <= picture.range.1);
    picture
}

#[test]
fn debug_views_have_their_documented_ranges() {
    let normals = view(DebugView::Normals, &[]);
    assert!(normals.range.0 >= -1.0 - 1e-6 && normals.range.1 <= 1.0 + 1e-6, "{:?}", normals.range);
    let uv = view(DebugView::Uv, &[]);
    assert!(uv.range.0 >= 0.0 && uv.range.1 < 1.0, "{:?}", uv.range);
    let depth = view(DebugView::Depth, &[]);
    assert!(depth.range.0 > 0.0 && depth.range.1 > depth.range.0, "{:?}", depth.range);
    assert!(depth.scale.contains(&format!("{:.3}", depth.range.0)), "{}", depth.scale);
    let rays = view(DebugView::Rays, &[]);
    let spp = glossy::Options::DEFAULT_SPP as f32;
    assert!(rays.range.0 >= spp && rays.range.1 > rays.range.0, "{:?}", rays.range);
    assert_eq!(rays.range.0.fract(), 0.0, "ray counts are whole numbers");
    let shadow = view(DebugView::ShadowRays, &[]);
    assert!(shadow.range.0 >= 0.0 && shadow.range.1 < rays.range.1, "{:?}", shadow.range);
    let reached = view(DebugView::DepthReached, &[]);
    assert!(reached.range.0 >= 0.0 && reached.range.1 >= 1.0, "{:?}", reached.range);
}

#[test]
fn the_rays_view_shows_what_adaptive_depth_control_saves() {
    let cli = common::parse::<fresnel::Options>(&["--width", "48", "--height", "36"]);
    let (scene, settings) = cli.prepare().unwrap();
    let adaptive = render_view(&scene, &settings, DebugView::Rays).unwrap();
    let cli = common::parse::<fresnel::Options>(&["--width", "48", "--height", "36", "--exhaustive"]);
    let (scene, settings) = cli.prepare().unwrap();
    let exhaustive = render_view(&scene, &settings, DebugView::Rays).unwrap();
    assert!(exhaustive.range.1 > adaptive.range.1, "{:?} vs {:?}", exhaustive.range, adaptive.range);
}

/// A floor seen from above at an angle, with `shader`, in a frame of `width` x `height` rendered on one thread.
fn floor_scene(shader: impl IntoShader, width: u32, height: u32) -> (Scene, RenderSettings) {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 40.0, -60.0), Vector::new(0.0, 0.0, 20.0), 70.0));
    scene.add(Node::new(Plane::new(0.0, f32::INFINITY), shader));
    (scene, RenderSettings { width, height, threads: Some(1), ..Default::default() })
}

/// A pixel of the `uv` view that sees a surface: the surface's own u/v there, and the view's colour.
type SeenUv = ((f32, f32), [u8; 3]);

/// The `uv` view of the floor with `shader`, and for each pixel whose centre sees the floor, the floor's own
/// u/v there and the view's colour, after checking that the pixels that see nothing are dark blue.
fn floor_uv_view(shader: impl IntoShader) -> (DebugImage, Vec<SeenUv>) {
    let (scene, settings) = floor_scene(shader, 64, 48);
    let view = render_view(&scene, &settings, DebugView::Uv).unwrap();
    let camera = scene.camera.frame(64, 48);
    let mut seen = Vec::new();
    for (x, y, colour) in view.image.enumerate_pixels() {
        match scene.closest_hit(&camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5)) {
            Some((info, _)) => seen.push((info.uv(), colour.0)),
            None => assert_eq!(colour.0, [0, 0, 96], "pixel {x},{y} sees nothing"),
        }
    }
    assert!(seen.len() > 64 * 48 / 3, "the floor fills the lower part of the picture");
    (view, seen)
}

/// The colour the `uv` view gives texture coordinates (u, v): their fractions, as red and green.
fn uv_colour((u, v): (f32, f32)) -> [u8; 3] {
    let code = |t: f32| ((t - t.floor()) * 255.0).round() as u8;
    [code(u), code(v), 0]
}

/// Whether two colours differ by at most `levels` in every channel.
fn within(a: [u8; 3], b: [u8; 3], levels: u8) -> bool {
    (0..3).all(|c| a[c].abs_diff(b[c]) <= levels)
}

/// A texture of a student's own that says nothing of how it maps u/v (`get_tex_color` alone).
struct Stripes;

impl Texture for Stripes {
    fn get_tex_color(&self, _ray: &Ray, info: &IntersectionInfo) -> Color {
        Color::gray(if info.uv().0.rem_euclid(2.0) < 1.0 { 0.2 } else { 0.8 })
    }
}

/// A shader of a student's own that reads no texture it names (`shade` alone).
struct Flat;

impl Shader for Flat {
    fn shade(&self, _ray: &Ray, info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {
        Color::gray(info.uv().0.fract().abs())
    }
}

/// The tile size of the bitmap on the floor in [`the_uv_view_shows_the_coordinates_the_texture_looks_up`].
const TILE: f32 = 7.0;
/// The checker's squares per unit there.
const SQUARES: f32 = 0.25;

/// `--view uv` shows the coordinates the floor's texture looks up, after its scaling: a bitmap's u/v divided
/// by its tile size (also under a layer, the slides' floor), a checker's times its scaling, also when the
/// checker is a layer's blend texture (a painted pattern); a texture or a shader of a student's own that says
/// nothing, or a glass whose only texture is the Fresnel blend (which reads no u/v), gets the surface's own
/// u/v. The scale text names which.
#[test]
fn the_uv_view_shows_the_coordinates_the_texture_looks_up() {
    let bitmap = Arc::new(Bitmap::from_pixels(2, 2, vec![Color::BLACK, Color::WHITE, Color::WHITE, Color::BLACK]));
    let tiles = || BitmapTexture::new(bitmap.clone()).with_tile_size(TILE);
    let mut layered = Layered::new();
    layered.add_layer(Lambert::new(tiles()), Color::WHITE, None);
    layered.add_layer(Reflection::new(0.9), Color::gray(0.02), None);
    let checker = CheckerTexture { color1: Color::BLACK, color2: Color::WHITE, scaling: SQUARES };
    let mut painted = Layered::new();
    painted.add_layer(Lambert::new(Color::gray(0.2)), Color::WHITE, None);
    painted.add_layer(Lambert::new(Color::gray(0.8)), Color::WHITE, Some(Arc::new(checker)));
    type Mapping = fn((f32, f32)) -> (f32, f32);
    // A case: its name, the floor's shader, how its texture maps u/v (`None`: it shows the surface's own),
    // and the words of the scale text that name where the view's u/v come from.
    type Case = (&'static str, Arc<dyn Shader>, Option<Mapping>, &'static str);
    let cases: [Case; 7] = [
        ("bitmap", Arc::new(Lambert::new(tiles())), Some(|(u, v)| (u / TILE, v / TILE)), "(BitmapTexture)"),
        ("layered", Arc::new(layered), Some(|(u, v)| (u / TILE, v / TILE)), "(BitmapTexture)"),
        (
            "checker",
            Arc::new(Phong::new(checker, 0.2, 20.0)),
            Some(|(u, v)| (u * SQUARES, v * SQUARES)),
            "(CheckerTexture)",
        ),
        ("blend texture", Arc::new(painted), Some(|(u, v)| (u * SQUARES, v * SQUARES)), "(CheckerTexture)"),
        ("Fresnel blend", Arc::new(fresnel_glass(1.5, FresnelMode::Schlick, 1.0)), None, "elsewhere (Layered)"),
        ("own texture", Arc::new(Lambert::new(Stripes)), None, "(Stripes)"),
        ("own shader", Arc::new(Flat), None, "elsewhere (Flat)"),
    ];
    for (case, shader, mapping, named) in cases {
        let (view, seen) = floor_uv_view(shader);
        for &(uv, colour) in &seen {
            let looked_up = mapping.map_or(uv, |m| m(uv));
            assert!(within(colour, uv_colour(looked_up), 1), "{case}: {colour:?} at u/v {uv:?}");
        }
        if mapping.is_some() {
            let unscaled = seen.iter().filter(|&&(uv, colour)| !within(colour, uv_colour(uv), 8)).count();
            assert!(unscaled > seen.len() / 2, "{case}: the view shows the unscaled u/v ({unscaled} pixels differ)");
        }
        assert!(view.scale.contains(named), "{case}: {}", view.scale);
    }
}

/// A shader that traces `extra` more rays (straight up, into nothing) where it is hit: on the floor's left
/// third none, in the middle 9, on the right 99, so that a pixel's camera ray and its extra rays are 1, 10 or
/// 100 rays.
struct Fan;

impl Shader for Fan {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let (x, _) = info.uv();
        let extra = if x < -8.0 {
            0
        } else if x < 8.0 {
            9
        } else {
            99
        };
        for _ in 0..extra {
            ctx.raytrace(&ray.spawn(info, Vector::Y, 1.0));
        }
        Color::gray(0.5)
    }
}

/// `--view rays` maps the logarithm of the count to the ramp: over counts from 1 to 100, a pixel of 10 rays
/// (their geometric mean) is mid-ramp, not a tenth of the way. The legend below the view is the ramp's bar
/// with ticks labelled with the counts whose colours the bar shows there, and the view's pixels are the
/// render's pixels. 0 shadow rays are dark blue; the depth reached stays linear.
#[test]
fn the_rays_view_is_on_a_log_scale_with_its_legend() {
    let (w, h) = (320, 120);
    let (scene, settings) = floor_scene(Fan, w, h);
    let rays = render_view(&scene, &settings, DebugView::Rays).unwrap();
    assert_eq!(rays.range, (1.0, 100.0));
    assert!(rays.scale.contains("log scale"), "{}", rays.scale);
    let counts: Vec<u64> = (0..h)
        .flat_map(|y| lecture6::lesson::render::render_row(&scene, &settings, y, 0..w).unwrap())
        .map(|pixel| pixel.counters.total())
        .collect();
    for count in [1, 10, 100] {
        assert!(counts.contains(&count), "no pixel has {count} rays");
    }
    let log_position = |count: f32| count.ln() / 100f32.ln();
    for (i, &count) in counts.iter().enumerate() {
        let colour = rays.image.get_pixel(i as u32 % w, i as u32 / w).0;
        assert!(within(colour, heat(log_position(count as f32)), 1), "{count} rays: {colour:?}");
    }
    assert!(within(heat(log_position(10.0)), heat(0.5), 1), "10 rays are mid-ramp");
    assert!(!within(heat(0.5), heat(9.0 / 99.0), 8), "a linear scale would put them a tenth of the way");
    // The picture is the view with its legend in a strip below: the render's pixels keep their coordinates.
    let picture = &rays.picture;
    assert_eq!(picture.width(), w);
    assert!(picture.height() > h + 12 + 14, "room for the bar, the tick labels and the caption");
    assert!((0..w).all(|x| (0..h).all(|y| picture.get_pixel(x, y) == rays.image.get_pixel(x, y))));
    // The ticks: the ends and the 1-2-5 counts between, labelled with their counts, each where the bar shows
    // its count's colour, with its label drawn under it.
    let values: Vec<f32> = rays.ticks.iter().map(|t| t.value).collect();
    assert_eq!(values, [1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]);
    for tick in &rays.ticks {
        assert_eq!(tick.label, format!("{}", tick.value));
        let bar = picture.get_pixel(tick.x, h + 6).0;
        assert!(within(bar, heat(log_position(tick.value)), 4), "tick {}: bar {bar:?}", tick.label);
        let ink = (tick.x.saturating_sub(8)..(tick.x + 8).min(w))
            .flat_map(|x| (h + 12 + 4..h + 12 + 4 + 16).map(move |y| (x, y)))
            .filter(|&(x, y)| picture.get_pixel(x, y)[0] > 128)
            .count();
        assert!(ink > 5, "tick {} has no label under it", tick.label);
    }
    // No lamp: no shadow rays, shown dark blue (0 has no logarithm).
    let shadow = render_view(&scene, &settings, DebugView::ShadowRays).unwrap();
    assert!(shadow.image.pixels().all(|p| p.0 == [0, 0, 96]), "0 shadow rays are dark blue");
    assert!(shadow.scale.contains("log scale") && shadow.scale.contains("dark blue: none"), "{}", shadow.scale);
    // The depth reached (0 or 1 here) is linear: depth 1 is white.
    let depth = render_view(&scene, &settings, DebugView::DepthReached).unwrap();
    assert!(depth.scale.contains("linear scale"), "{}", depth.scale);
    assert!(depth.image.pixels().any(|p| p.0 == [255, 255, 255]) && depth.ticks.len() == 2, "{:?}", depth.ticks);
}

/// `--view rays` writes the render's picture with the legend strip below it, and says so with the sizes.
#[test]
fn a_heat_view_file_is_the_render_with_its_legend_below() {
    let path = common::root().join("target/inspect/fresnel-rays.png");
    let _ = std::fs::remove_file(&path);
    let cli = common::parse::<fresnel::Options>(&["--width", "96", "--height", "72", "-o", path.to_str().unwrap()]);
    let line = lecture6::app::cli::commands::write_view("fresnel", &cli, DebugView::Rays).unwrap();
    let (width, height) = image::image_dimensions(&path).unwrap();
    assert_eq!(width, 96);
    assert!(height > 72, "no legend strip");
    assert!(line.contains(&format!("96x72 and its legend below, 96x{height} in all")), "{line}");
    assert!(line.contains("log scale"), "{line}");
}

#[test]
fn a_side_by_side_picture_is_a_b_and_the_difference_with_captions() {
    let a = image::RgbImage::from_pixel(100, 60, image::Rgb([200, 10, 10]));
    let b = image::RgbImage::from_pixel(100, 60, image::Rgb([10, 10, 200]));
    let d = image::RgbImage::from_pixel(100, 60, image::Rgb([0, 0, 0]));
    let panels = [("A: one", a), ("B: two", b), ("difference", d)].map(|(c, image)| Panel { image, caption: c.into() });
    let out = compose(&panels).unwrap();
    assert_eq!(out.width(), 300);
    assert!(out.height() > 60, "room for the captions");
    for (i, panel) in panels.iter().enumerate() {
        let left = i as u32 * 100;
        assert_eq!(out.get_pixel(left + 50, 30), panel.image.get_pixel(50, 30));
        let ink = (left..left + 100)
            .flat_map(|x| (60..out.height()).map(move |y| (x, y)))
            .filter(|&(x, y)| out.get_pixel(x, y)[0] > 128);
        assert!(ink.count() > 20, "panel {i} has no caption drawn under it");
    }
}

#[test]
fn side_by_side_of_an_example_writes_three_panels_of_its_size() {
    let path = common::root().join("target/inspect/fresnel-sbs.png");
    let _ = std::fs::remove_file(&path);
    let args: Vec<std::ffi::OsString> =
        ["--width", "64", "--height", "48", "--quiet", "-o", path.to_str().unwrap()].map(Into::into).to_vec();
    lecture6::app::cli::commands::side_by_side::<fresnel::Options>("fresnel", &args, "--fresnel exact").unwrap();
    let out = image::open(&path).unwrap().to_rgb8();
    assert_eq!(out.width(), 3 * 64);
    assert!(out.height() > 48);
    // The difference panel is --compare's heat map: white at the largest difference, and its colour bar
    // (black to white) under it.
    let heat = |x: u32, y: u32| out.get_pixel(2 * 64 + x, y).0;
    assert!((0..64).any(|x| (0..48).any(|y| heat(x, y) == [255, 255, 255])), "no white at the largest difference");
    assert!(heat(0, 48 + 6).iter().all(|&v| v < 40) && heat(63, 48 + 6).iter().all(|&v| v > 215), "no colour bar");
    let bad = lecture6::app::cli::commands::side_by_side::<fresnel::Options>("fresnel", &args, "--width 32");
    assert!(bad.is_err(), "A and B of different sizes cannot be compared");
}

/// A small scene file with its own frame size (not 640 x 480) and the course's adaptive anti-aliasing.
const OWN_SIZE_AND_AA: &str = "GlobalSettings {\n frameWidth 96\n frameHeight 60\n wantAA true\n ambientLight (0.2, 0.2, 0.2)\n}\n\
    Camera {\n position (0, 10, -60)\n pitch -10\n fov 60\n aspectRatio 1.6\n}\n\
    PointLight {\n pos (-30, 60, -40)\n power 5000\n}\nSphere ball {\n R 10\n}\nPlane floor {\n y -10\n}\n\
    Lambert red {\n color (0.9, 0.2, 0.1)\n}\nLambert grey {\n color (0.5, 0.5, 0.5)\n}\n\
    Node {\n geometry ball\n shader red\n}\nNode {\n geometry floor\n shader grey\n}\n";

/// The instruments see the scene file's own frame size and anti-aliasing, exactly as the render: the settings
/// come from one place ([`Cli::prepare`]), the depth view has the file's size, and the ray tree of a pixel
/// the adaptive pass refines holds its five camera rays and gives the rendered pixel's colour.
#[test]
fn the_instruments_use_a_scene_files_own_size_and_anti_aliasing() {
    let file = common::temp_file("inspect", "own-size-and-aa.qdmg", OWN_SIZE_AND_AA);
    let cli = common::parse::<scene_file::Options>(&[file.to_str().unwrap()]);
    let (scene, settings) = cli.prepare().unwrap();
    assert_eq!((settings.width, settings.height, settings.spp, settings.adaptive_aa), (96, 60, 1, true));
    let (frame, _) = cli.render().unwrap();
    assert_eq!((frame.width, frame.height), (96, 60));
    let depth = render_view(&scene, &settings, DebugView::Depth).unwrap();
    assert_eq!(depth.image.dimensions(), (96, 60));
    // Which pixels the adaptive pass refines: those of the single-sample frame that differ from a neighbour.
    let (single, _) = render(&scene, &RenderSettings { adaptive_aa: false, ..settings }).unwrap();
    let marks = lecture6::lesson::adaptive_aa::marked(&single);
    let pixel = |i: usize| (i as u32 % 96, i as u32 / 96);
    let refined = pixel(marks.iter().position(|&m| m).expect("the ball's edge is refined"));
    let plain = pixel(marks.iter().position(|&m| !m).expect("the sky is not"));
    let trees = check_scene_trees(&scene, &settings, &[refined, plain], "own-size-and-aa.qdmg");
    assert_eq!((trees[0].roots.len(), trees[1].roots.len()), (5, 1), "refined {refined:?}, plain {plain:?}");
    // The rays view counts the refined pixel's extra samples too.
    let rays = render_view(&scene, &settings, DebugView::Rays).unwrap();
    assert_eq!(rays.image.dimensions(), (96, 60));
    let single_rays = render_view(&scene, &RenderSettings { adaptive_aa: false, ..settings }, DebugView::Rays).unwrap();
    assert!(rays.range.1 > single_rays.range.1, "{:?} against {:?}", rays.range, single_rays.range);
}

/// The slide's Layered loop covers the layers below with each new one (`res * (1 - blend)`): the tree
/// counts that too, so under `--slide` the glass's and the floor's layers add up without a colour of their
/// own, the refraction layer under the Fresnel mirror counting `1 - F` times.
#[test]
fn trees_add_up_in_the_slides_reading() {
    let pixels = [(32, 20), (30, 26), (10, 44), (50, 40)];
    let trees = check_trees::<fresnel::Options>(&["--width", "64", "--height", "48", "--spp", "1", "--slide"], &pixels);
    assert_eq!(own_colours(&trees), 0, "{}", trees[0].to_text(0));
    let trees = check_trees::<layered::Options>(&["--width", "80", "--height", "60", "--slide"], &[(40, 30), (20, 45)]);
    assert_eq!(own_colours(&trees), 0);
}

/// A student's Fresnel-blended surface of two unlike rays: a mirror ray spawned with its reflectance as the
/// attenuation, and a ray straight through with the rest, each times its attenuation.
struct TwoRays;

const MIRROR_SHARE: f32 = 0.04;

impl Shader for TwoRays {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        let mirror = ctx.raytrace(&ray.spawn(info, reflect(ray.dir, n), MIRROR_SHARE));
        let through = ctx.raytrace(&ray.spawn(info, ray.dir, 1.0 - MIRROR_SHARE));
        mirror * MIRROR_SHARE + through * (1.0 - MIRROR_SHARE)
    }
}

/// A sky whose colour depends on the direction: the two rays bring back unlike colours.
struct Gradient;

impl Environment for Gradient {
    fn get(&self, dir: Vector) -> Color {
        Color::new(0.5 + 0.5 * dir.y, 0.3, 0.5 - 0.5 * dir.y)
    }
}

/// Each ray of a shader counts its own share, which its weight gives (0.04 and 0.96 here), not one factor
/// common to both; where a factor is shared (a glossy average), the tree says so.
#[test]
fn each_ray_shows_its_own_share_from_its_weight() {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 30.0, -60.0), Vector::ZERO, 60.0));
    scene.environment = Some(Arc::new(Gradient));
    scene.add(Node::new(Plane::new(0.0, 200.0), TwoRays));
    let settings = RenderSettings { width: 40, height: 30, spp: 1, ..RenderSettings::default() };
    let trees = check_scene_trees(&scene, &settings, &[(20, 20), (5, 25)], "two rays");
    for tree in &trees {
        let root = &tree.rays[tree.roots[0]];
        let shares: Vec<(Color, f32)> = root
            .terms
            .iter()
            .filter_map(|t| match t.what {
                TermKind::Ray(child) => Some((t.factor, tree.rays[child].color.luminance())),
                _ => None,
            })
            .collect();
        assert_eq!(shares.len(), 2);
        assert!(shares[0].1 != shares[1].1, "the two rays see the same colour: {shares:?}");
        assert!(close(shares[0].0, Color::gray(MIRROR_SHARE)), "the mirror ray counts {:?}", shares[0].0);
        assert!(close(shares[1].0, Color::gray(1.0 - MIRROR_SHARE)), "the ray through counts {:?}", shares[1].0);
        let text = tree.to_text(0);
        assert!(text.contains("+ 0.0400 times\n") && text.contains("+ 0.9600 times\n"), "{text}");
        assert!(!text.contains("shared with"), "{text}");
    }
}

/// The text `--trace-pixel X,Y` prints for the example `E` with `args`, and the pixel's tree.
fn traced<E: Example>(name: &str, args: &[&str], (x, y): (u32, u32)) -> (String, RayTree) {
    let mut all = args.to_vec();
    let pixel = format!("{x},{y}");
    all.extend(["--trace-pixel", &pixel]);
    let cli = common::parse::<E>(&all);
    let text = lecture6::app::cli::commands::trace_pixel(name, &cli, PixelPos { x, y }).unwrap();
    let (scene, settings) = cli.prepare().unwrap();
    (text, ray_tree::trace(&scene, &settings, PixelPos { x, y }).unwrap().tree)
}

/// The topic values of the camera ray's hit in `tree`.
fn topics(tree: &RayTree) -> Vec<Topic> {
    tree.rays[tree.roots[0]]
        .notes
        .iter()
        .filter_map(|n| match &n.what {
            NoteKind::Topic(t) => Some(t.clone()),
            NoteKind::LayerWeight(_) => None,
        })
        .collect()
}

/// The weight the tree gives the layer whose label starts with `label` at the camera ray's hit.
fn layer_weight(tree: &RayTree, label: &str) -> Color {
    let notes = &tree.rays[tree.roots[0]].notes;
    let weights = notes.iter().filter(|n| n.layer.starts_with(label));
    weights.filter_map(|n| if let NoteKind::LayerWeight(w) = n.what { Some(w) } else { None }).next().unwrap()
}

/// At a glass pixel the tree prints the Fresnel reflectance (Schlick's formula of the ratio of the indices
/// and the angle it records) and the weights it gives the layers: the mirror F, the refraction under it
/// 1 - F, in both readings.
#[test]
fn the_tree_prints_the_fresnel_value_and_the_factor_it_becomes() {
    for reading in [&[][..], &["--slide"]] {
        let args = [&["--width", "64", "--height", "48", "--spp", "1"][..], reading].concat();
        let (text, tree) = traced::<fresnel::Options>("fresnel", &args, (32, 20));
        let Some(&Topic::Fresnel { reflectance, eta, cos, exact }) = topics(&tree).first() else {
            panic!("{reading:?}: no Fresnel value at the glass:\n{text}")
        };
        assert!(!exact && (eta - 1.0 / 1.6).abs() < 1e-6, "entering the glass of 1.6: {eta}");
        let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
        assert!((reflectance - (r0 + (1.0 - r0) * (1.0 - cos).powi(5))).abs() < 1e-6, "{reflectance}");
        assert!(text.contains(&format!("Fresnel reflectance {reflectance:.4} (Schlick's approximation")), "{text}");
        assert!(close(layer_weight(&tree, "layer Reflection"), Color::gray(reflectance)), "{reading:?}\n{text}");
        assert!(close(layer_weight(&tree, "layer Refraction"), Color::gray(1.0 - reflectance)), "{reading:?}\n{text}");
        let weight = format!("layer Reflection, blend Fresnel: counts {reflectance:.4} times");
        assert!(text.contains(&weight), "{reading:?}\n{text}");
    }
}

/// At a textured pixel the tree prints u, v and the texels read with their weights: the slide's nearest
/// texel (weight 1) under `--slide`, the four of the default bilinear filter otherwise; their weighted colours
/// are the diffuse colour the light at the floor is multiplied by.
#[test]
fn the_tree_prints_the_texels_a_bitmap_mixed() {
    for (reading, count) in [(&[][..], 4), (&["--slide"][..], 1)] {
        let args = [&["--width", "64", "--height", "48", "--spp", "1"][..], reading].concat();
        let (text, tree) = traced::<bitmap_textures::Options>("bitmap_textures", &args, (32, 45));
        let Some(Topic::Texels { u, v, texels }) = topics(&tree).into_iter().next() else {
            panic!("{reading:?}: no texels at the floor:\n{text}")
        };
        assert_eq!(texels.len(), count, "{reading:?}");
        let total: f32 = texels.iter().map(|t| t.weight).sum();
        assert!((total - 1.0).abs() < 1e-6 && texels.iter().all(|t| t.weight >= 0.0), "{texels:?}");
        let mixed = texels.iter().fold(Color::BLACK, |sum, t| sum + t.color * t.weight);
        let root = &tree.rays[tree.roots[0]];
        let light = root.terms.iter().find(|t| matches!(t.what, TermKind::Light { .. })).unwrap();
        assert!(
            close(mixed, light.factor),
            "{reading:?}: the texels mix to {mixed:?}, the floor is {:?}",
            light.factor
        );
        assert!(text.contains(&format!("bitmap read at u {u:.4}, v {v:.4}")), "{text}");
        for texel in &texels {
            assert!(text.contains(&format!("texel ({}, {}) weight {:.4}", texel.x, texel.y, texel.weight)), "{text}");
        }
    }
}

/// At a caustic pixel the tree prints the photon estimate's k, the radius of its disc and the photons it
/// found; their power, weighted, over the disc's area is the caustic light the floor gets (the slide's k-d
/// tree under `--slide`, the grid's cone filter by default).
#[test]
fn the_tree_prints_the_photon_estimate() {
    for reading in [&[][..], &["--slide"]] {
        let args = [&["--width", "80", "--height", "60", "--spp", "1", "--photons", "40000"][..], reading].concat();
        let (text, tree) = traced::<photon_map::Options>("photon_map", &args, CAUSTIC_PIXEL);
        let Some(Topic::Photons { k, radius, max_radius, photons }) = topics(&tree).into_iter().next() else {
            panic!("{reading:?}: no photon estimate at the floor:\n{text}")
        };
        assert_eq!((k, max_radius), (80, 2.0));
        assert!(photons.iter().filter(|p| p.weight > 0.0).count() > 10, "{reading:?}: not a caustic:\n{text}");
        assert!(radius > 0.0 && radius <= max_radius && photons.len() <= k);
        assert!(photons.iter().all(|p| p.distance <= radius * (1.0 + 1e-6)), "{reading:?}: {photons:?}");
        let sum = photons.iter().fold(Color::BLACK, |sum, p| sum + p.power * p.weight);
        let area = std::f32::consts::PI * radius * radius;
        let filter = if reading.is_empty() { 1.0 - 2.0 / (3.0 * CONE_FILTER_K) } else { 1.0 };
        let root = &tree.rays[tree.roots[0]];
        let caustic = root.terms.iter().find_map(|t| match t.what {
            TermKind::Light { kind: LightTerm::Photons, color } => Some(color),
            _ => None,
        });
        assert!(close(sum / (filter * area), caustic.unwrap()), "{reading:?}: {:?} against {caustic:?}", sum / area);
        assert!(text.contains(&format!("photon estimate: k 80, {} found", photons.len())), "{text}");
        assert!(text.contains(&format!("the disc of radius {radius:.4}")), "{text}");
        let nearest = photons.iter().min_by(|a, b| a.distance.total_cmp(&b.distance)).unwrap();
        assert!(text.contains(&format!("photon {} at distance {:.4}", nearest.index, nearest.distance)), "{text}");
    }
}

/// The ray tree of a progressive caustic's pixel is the picture's: the pixel rendered once per pass, each
/// with its pass's photon map, the passes' colours averaged as the render averages their pictures; the tree
/// says which pass each camera ray is of, and each later pass's estimate gathers within its own radius r_i.
#[test]
fn the_ray_tree_of_a_progressive_caustic_shows_its_passes() {
    let args = ["--width", "80", "--height", "60", "--photons", "20000", "--photon-passes", "3"];
    let cli = common::parse::<photon_map::Options>(&args);
    let (scene, settings) = cli.prepare().unwrap();
    let pixels: Vec<(u32, u32)> = (0..8).map(|i| (10 * i, 50)).chain([CAUSTIC_PIXEL]).collect();
    let trees = check_scene_trees(&scene, &settings, &pixels, &format!("{args:?}"));
    let spp = settings.spp as usize;
    for tree in &trees {
        assert_eq!(tree.photon_passes, vec![0, spp, 2 * spp], "each pass's camera rays, one pass after another");
    }
    // At the caustic pixel, each pass's estimate: pass 1's k nearest, every later pass's photons within r_i.
    let tree = trees.last().unwrap();
    let estimates: Vec<Option<(u32, u32)>> = tree
        .rays
        .iter()
        .flat_map(|r| &r.notes)
        .filter(|note| matches!(note.what, NoteKind::Topic(Topic::Photons { .. })))
        .map(|note| note.photon_pass)
        .collect();
    for pass in 1..=3 {
        assert!(estimates.contains(&Some((pass, 3))), "no photon estimate of pass {pass}: {estimates:?}");
    }
    let traced = ray_tree::trace(&scene, &settings, PixelPos { x: CAUSTIC_PIXEL.0, y: CAUSTIC_PIXEL.1 }).unwrap();
    let (x, y) = CAUSTIC_PIXEL;
    let text = ray_tree::describe("photon_map", PixelPos { x, y }, &traced, 2 * spp, TraceFormat::Text).unwrap();
    assert!(text.contains("the mean of 3 passes of a progressive caustic"), "{text}");
    assert!(text.contains("of photon pass 3 of 3"), "{text}");
    assert!(text.contains("photon estimate, photon pass 3 of 3: every photon within r_3 = "), "{text}");
    // Every pixel of a small render, bit for bit.
    let args = ["--width", "16", "--height", "12", "--photons", "20000", "--photon-passes", "2"];
    let (scene, settings) = common::parse::<photon_map::Options>(&args).prepare().unwrap();
    let (frame, _) = render(&scene, &settings).unwrap();
    for (x, y) in (0..12).flat_map(|y| (0..16).map(move |x| (x, y))) {
        let traced = ray_tree::trace(&scene, &settings, PixelPos { x, y }).unwrap();
        let (tree, picture) = (traced.color.to_array(), frame.get(x, y).to_array());
        assert!(tree.map(f32::to_bits) == picture.map(f32::to_bits), "({x}, {y}): {tree:?} against {picture:?}");
    }
}

/// A pixel of the photon map's floor, at 80 x 60, in the glass sphere's caustic.
const CAUSTIC_PIXEL: (u32, u32) = (24, 37);

/// The ray tree runs the code that made the picture: at every pixel of a small render of every example, in
/// both readings, the colour the pixel's ray tree brings back is the frame's, bit for bit.
#[test]
fn the_ray_tree_of_every_pixel_is_the_pictures() {
    macro_rules! every_pixel {
        ($($name:ident),*) => {$(
            for reading in [&[][..], &["--slide"][..]] {
                let args: Vec<&str> = ["--width", "16", "--height", "12"].iter().chain(reading).copied().collect();
                let (scene, settings) = common::parse::<common::examples::$name::Options>(&args).prepare().unwrap();
                let (frame, _) = render(&scene, &settings).unwrap();
                for (x, y) in (0..12).flat_map(|y| (0..16).map(move |x| (x, y))) {
                    let traced = ray_tree::trace(&scene, &settings, PixelPos { x, y }).unwrap();
                    let (tree, picture) = (traced.color.to_array(), frame.get(x, y).to_array());
                    assert!(
                        tree.map(f32::to_bits) == picture.map(f32::to_bits),
                        "{} {reading:?} ({x}, {y}): the ray tree brings back {tree:?}, the picture has {picture:?}",
                        stringify!($name)
                    );
                }
            }
        )*};
    }
    every_example!(every_pixel);
}
