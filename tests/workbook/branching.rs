//! The core's bound on branching (`lecture6::lesson::branching`): a student's glossy mirror that averages
//! N rays, each passed its full weight, traces a number of rays linear in the depth limit, and converges to
//! the workbook's own glossy mirror; the workbook's shaders never reach the bound.

use lecture6::lesson::beyond::Steps;
use lecture6::lesson::branching::{RAYS_PER_BRANCH, SECONDARY_SPLIT, SPLIT_DEPTH};
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::lesson::sampling::DiscSampler;
use lecture6::prelude::*;

/// The API page's glossy mirror (docs/homework-api.md, "Randomness in a shader"), the file
/// docs/homework_glossy.rs: each ray passed the tint's full factor. The file is a whole homework: its own
/// test (the page's recipe, `homework_glossy::tests`) runs here too.
#[allow(dead_code)] // its `main` is a homework binary's
#[path = "../../docs/homework_glossy.rs"]
pub mod homework_glossy;

use homework_glossy::TintedGlossy;

/// The same mirror passing each of its `n` rays 1/n of the factor instead (the ray it shades is given 1/n
/// of its weight, which its rays inherit).
struct OneNth(TintedGlossy);

impl Shader for OneNth {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.0.shade(&Ray { weight: ray.weight / self.0.n as f32, ..*ray }, info, ctx)
    }
}

/// A sky of bright and dark stripes across x, so that what the panels reflect, and how blurred, shows.
struct Stripes;

impl Environment for Stripes {
    fn get(&self, dir: Vector) -> Color {
        if (dir.x * 6.0).sin() > 0.0 { Color::new(1.0, 0.95, 0.8) } else { Color::new(0.05, 0.1, 0.3) }
    }
}

const N: u32 = 16;
const DEPTH: u32 = 10;
const GLOSSINESS: f32 = 0.9;
const TINT: Color = Color::new(0.95, 0.9, 0.8);

/// Two panels facing each other 20 apart, each a glossy mirror made by `shader`; the camera stands
/// between them, looking at one askew, so that most of the picture is glossy seen in glossy, `DEPTH` deep.
pub fn facing_panels(shader: impl Fn() -> Arc<dyn Shader>) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 0.0, 6.0), Vector::new(3.0, 1.0, -10.0), 70.0));
    for z in [-10.0, 10.0] {
        let panel = Node::new(Cube::new(Vector::ZERO, 1.0), shader());
        scene.add(panel.scale(Vector::new(12.0, 8.0, 0.05)).translate(Vector::new(0.0, 0.0, z)));
    }
    scene.environment = Some(Arc::new(Stripes));
    scene.max_depth = DEPTH;
    scene
}

fn student(one_nth: bool) -> Scene {
    let glossy = || TintedGlossy { tint: TINT, glossiness: GLOSSINESS, n: N };
    facing_panels(|| if one_nth { Arc::new(OneNth(glossy())) } else { Arc::new(glossy()) })
}

fn workbook() -> Scene {
    facing_panels(|| {
        Arc::new(Reflection::glossy(TINT, GLOSSINESS, N).unwrap().with_sampler(DiscSampler::Random)) as Arc<dyn Shader>
    })
}

fn settings(seed: u64) -> RenderSettings {
    RenderSettings { width: 160, height: 120, spp: 1, seed, ..RenderSettings::default() }
}

fn rendered(scene: &Scene, seed: u64) -> (Frame, RenderStats) {
    let (frame, stats) = render(scene, &settings(seed)).unwrap();
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    (frame, stats)
}

#[test]
fn a_full_weight_average_traces_rays_linear_in_the_depth() {
    for steps in [Steps::ALL, Steps::SLIDES] {
        bounded_in(steps);
    }
}

/// The budget of a branch is the library's, not the command line's (which refuses a depth limit above 64
/// without adaptive depth control): the layered example read as the slides write it, with a depth limit of
/// 1000, traces no more rays below its camera rays than `RAYS_PER_BRANCH` for each ray of their hits, within
/// 3 times the rays of the same render at the command line's cap of 64 (1.98 M rays against 1.52 M), and the
/// end-of-run report names the rays past it. Without the budget its glass doubles its rays at every level.
#[test]
fn a_layered_scene_read_as_the_slides_write_it_stays_within_its_budget_at_any_depth() {
    use crate::common::examples::layered;
    let (mut scene, _) = crate::common::parse::<layered::Options>(&["--slide"]).prepare().unwrap();
    let settings = RenderSettings { width: 48, height: 36, spp: 4, ..RenderSettings::default() };
    scene.max_depth = 64;
    let at_the_cap = render(&scene, &settings).unwrap().1.counters.total();
    scene.max_depth = 1000;
    let (_, stats) = render(&scene, &settings).unwrap();
    let c = &stats.counters;
    assert!(c.total() <= 3 * at_the_cap, "{} rays at depth 1000, {at_the_cap} at 64", c.total());
    let below_the_camera: u64 = c.rays_by_depth[1..].iter().sum();
    assert!(below_the_camera <= c.rays_by_depth[1] * RAYS_PER_BRANCH as u64, "{:?}", c.rays_by_depth);
    assert!(c.over_budget_rays > 0 && c.rays_by_depth[15] > 0, "the glass never reached the budget: {c:?}");
    let named = stats.warnings.iter().filter(|w| w.contains(&format!("its budget of {RAYS_PER_BRANCH} rays")));
    assert_eq!(named.count(), 1, "{:?}", stats.warnings);
}

/// The bound holds in either reading: by default and with `--slide` (`steps`).
fn bounded_in(steps: Steps) {
    let in_reading = |mut scene: Scene| {
        scene.steps = steps;
        scene
    };
    let (_, stats) = rendered(&in_reading(student(false)), 1);
    let c = &stats.counters;
    let camera_rays = c.rays_by_depth[0];
    // N rays at the camera ray's hit, SECONDARY_SPLIT per shading point of a ray down to the split depth,
    // one below it: no depth holds more than N * SECONDARY_SPLIT^SPLIT_DEPTH rays per camera ray, and every
    // depth below the split depth holds no more rays than the one above it.
    let widest = (N * SECONDARY_SPLIT.pow(SPLIT_DEPTH)) as u64;
    for depth in 1..=DEPTH as usize {
        assert!(c.rays_by_depth[depth] <= widest * camera_rays, "depth {depth}: {:?}", c.rays_by_depth);
    }
    for depth in SPLIT_DEPTH as usize + 2..=DEPTH as usize {
        assert!(c.rays_by_depth[depth] <= c.rays_by_depth[depth - 1], "depth {depth}: {:?}", c.rays_by_depth);
    }
    assert!(c.shared_rays > 0, "the student's shader was never bounded: {c:?}");
    // It goes DEPTH deep where the workbook's does: nothing is pruned for its weight.
    let (_, own) = rendered(&in_reading(workbook()), 1);
    assert!(c.rays_by_depth[DEPTH as usize] > 0 && own.counters.rays_by_depth[DEPTH as usize] > 0);
    // The workbook's own glossy is bounded by the same rule below the split depth, and by nothing else: its
    // deeper levels hold no more rays than the one above them either.
    assert!(own.counters.shared_rays > 0, "the workbook's glossy was never bounded: {:?}", own.counters);
    for depth in SPLIT_DEPTH as usize + 2..=DEPTH as usize {
        let rays = own.counters.rays_by_depth;
        assert!(rays[depth] <= rays[depth - 1], "the workbook's glossy at depth {depth}: {rays:?}");
    }
}

/// The mean difference of two pictures and its standard error, per channel, over the pixels `(x, y)` for
/// which `within` holds.
fn mean_difference(a: &Frame, b: &Frame, within: impl Fn(u32, u32) -> bool) -> [(f64, f64); 3] {
    std::array::from_fn(|c| {
        let d: Vec<f64> = (0..a.height)
            .flat_map(|y| (0..a.width).map(move |x| (x, y)))
            .filter(|&(x, y)| within(x, y))
            .map(|(x, y)| (a.get(x, y).to_array()[c] - b.get(x, y).to_array()[c]) as f64)
            .collect();
        let n = d.len() as f64;
        let mean = d.iter().sum::<f64>() / n;
        let variance = d.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
        (mean, (variance / n).sqrt())
    })
}

/// Whether two renders estimate the same picture: the whole picture, and each of its 4 x 3 blocks, has a
/// mean difference within 5 standard errors, per channel (39 comparisons: were they the same picture,
/// chance would fail one in about 50,000 seeds; the seeds here are fixed). Measured over six pairs of
/// seeds, the student's full-weight glossy against the workbook's: the largest of the 39 was 1.8 to 3.2
/// standard errors; the 1/N share: 74 to 80.
fn same_picture(a: &Frame, b: &Frame) -> Result<(), String> {
    let (bw, bh) = (a.width / 4, a.height / 3);
    let whole = [(0..a.width, 0..a.height)];
    let blocks = (0..3).flat_map(|j| (0..4).map(move |i| (i * bw..(i + 1) * bw, j * bh..(j + 1) * bh)));
    for (xs, ys) in whole.into_iter().chain(blocks) {
        for (channel, (mean, error)) in
            mean_difference(a, b, |x, y| xs.contains(&x) && ys.contains(&y)).iter().enumerate()
        {
            if mean.abs() > 5.0 * error {
                return Err(format!(
                    "pixels {xs:?} x {ys:?}, channel {channel}: mean difference {mean:.4} +- {error:.4}"
                ));
            }
        }
    }
    Ok(())
}

#[test]
fn a_full_weight_average_converges_to_the_workbooks_glossy() {
    let (own, _) = rendered(&workbook(), 2);
    let (full, _) = rendered(&student(false), 1);
    same_picture(&full, &own).unwrap();
    // The test tells pictures apart: the 1/N share is pruned after two bounces and is darker where
    // glossy sees glossy.
    let (share, _) = rendered(&student(true), 1);
    assert!(same_picture(&share, &own).is_err(), "the 1/N share cannot be told from the workbook's glossy");
}

/// A shader that splits its ray into a reflection and a refraction whose weights add up to the ray's,
/// in one `shade`, as a student's glass would: both rays are traced at every depth.
struct Splitter;

impl Shader for Splitter {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let reflectance = 0.3 + 0.4 * ctx.rng.next_f32();
        let straight = ctx.raytrace(&ray.spawn(info, ray.dir, 1.0 - reflectance));
        let back = ctx.raytrace(&ray.spawn(info, reflect(ray.dir, info.normal), reflectance));
        straight * (1.0 - reflectance) + back * reflectance
    }
}

#[test]
fn a_split_of_the_weight_is_traced_at_every_depth() {
    let mut scene = facing_panels(|| Arc::new(Splitter));
    scene.max_depth = 8;
    let (_, stats) = rendered(&scene, 1);
    assert_eq!(stats.counters.shared_rays, 0, "{:?}", stats.counters);
    assert!(stats.counters.rays_by_depth[8] > 0);
}

/// A floor and a ceiling 20 apart, each the workbook's own plane, untransformed, coloured by `shader`: the
/// renderer knows the shape, and takes the workbook's shortcut for its own shaders on it only when every
/// shader of the node is its own.
fn floor_and_ceiling(shader: impl Fn() -> Arc<dyn Shader>) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::ZERO, Vector::new(3.0, -4.0, 10.0), 70.0));
    for y in [-10.0, 10.0] {
        scene.add(Node::new(Plane::new(y, 1000.0), shader()));
    }
    scene.environment = Some(Arc::new(Stripes));
    scene.max_depth = DEPTH;
    scene
}

#[test]
fn a_students_average_on_the_workbooks_own_shape_is_bounded_too() {
    let glossy = || TintedGlossy { tint: TINT, glossiness: GLOSSINESS, n: N };
    let layered = || {
        let mut layered = Layered::new();
        layered.add_layer(glossy(), Color::WHITE, None);
        Arc::new(layered) as Arc<dyn Shader>
    };
    let widest = (N * SECONDARY_SPLIT.pow(SPLIT_DEPTH)) as u64;
    for (what, scene) in [
        ("alone", floor_and_ceiling(|| Arc::new(glossy()))),
        ("as a layer of the workbook's Layered", floor_and_ceiling(layered)),
    ] {
        let (_, stats) = rendered(&scene, 1);
        let c = &stats.counters;
        assert!(c.shared_rays > 0, "{what}: the student's shader was never bounded: {c:?}");
        for depth in 1..=DEPTH as usize {
            assert!(c.rays_by_depth[depth] <= widest * c.rays_by_depth[0], "{what}, depth {depth}: {c:?}");
        }
        // Floor and ceiling lose few rays: the widest depth comes within a quarter of the bound (unbounded,
        // it would hold N * 16^(DEPTH - 1) rays per camera ray).
        let most = c.rays_by_depth[1..=DEPTH as usize].iter().max().unwrap();
        assert!(4 * most >= 3 * widest * c.rays_by_depth[0], "{what}: {c:?}");
    }
}

/// The API page's glossy mirror with one mistake a student makes: `no_offset`, its rays started on the hit
/// point itself (`Ray { start: info.ip, .. }`, as `Ray::new(info.ip, dir)` would, but keeping the depth), or
/// `no_division`, its rays added up and not divided by their number (the naive sum).
fn mistaken_glossy(
    glossy: &TintedGlossy,
    (no_offset, no_division): (bool, bool),
    ray: &Ray,
    info: &IntersectionInfo,
    ctx: &mut TraceContext,
) -> Color {
    let normal = faceforward(info.normal, ray.dir);
    let cone = lecture6::lesson::shader::GlossyCone::new(ray.dir, normal, glossy.glossiness);
    let mut sum = Color::BLACK;
    for _ in 0..glossy.n {
        let point = lecture6::lesson::sampling::random_unit_disc_point(&mut ctx.rng);
        if let Some(dir) = cone.direction(point) {
            let spawned = ray.spawn(info, dir, glossy.tint.max_channel());
            let start = if no_offset { info.ip } else { spawned.start };
            sum += ctx.raytrace(&Ray { start, ..spawned });
        }
    }
    if no_division { sum * glossy.tint } else { sum * glossy.tint / glossy.n as f32 }
}

/// The student's mirror with its rays started on the surface, not off it.
struct NoOffset(TintedGlossy);

impl Shader for NoOffset {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        mistaken_glossy(&self.0, (true, false), ray, info, ctx)
    }
}

/// The student's mirror adding up its rays, each at the full weight, without dividing by their number.
pub struct NaiveSum(pub TintedGlossy);

impl Shader for NaiveSum {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        mistaken_glossy(&self.0, (false, true), ray, info, ctx)
    }
}

/// A glossy ball on a glossy floor (a sphere too, large), each made by `shader`, under the stripes, in the
/// reading `steps`: curved surfaces, whose hit points lie on either side of the surface by a rounding.
fn ball_on_floor(shader: &dyn Fn() -> Arc<dyn Shader>, steps: Steps) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 10.0, -40.0), Vector::ZERO, 50.0));
    scene.add(Node::new(Sphere::new(Vector::ZERO, 10.0), shader()));
    scene.add(Node::new(Sphere::new(Vector::new(0.0, -1010.0, 0.0), 1000.0), shader()));
    scene.environment = Some(Arc::new(Stripes));
    (scene.max_depth, scene.steps) = (DEPTH, steps);
    scene
}

/// A shader whose rays start on the surface finishes, in either reading, with no more than 3 times the rays
/// of the same shader done right, and the end-of-run report names it and says how to make its rays: a ray
/// that finds the surface it left is not followed.
#[test]
fn a_shader_without_an_offset_finishes_and_is_named_in_both_readings() {
    let glossy = || TintedGlossy { tint: TINT, glossiness: GLOSSINESS, n: N };
    for steps in [Steps::ALL, Steps::SLIDES] {
        let right = ball_on_floor(&|| Arc::new(glossy()), steps);
        let wrong = ball_on_floor(&|| Arc::new(NoOffset(glossy())), steps);
        let (_, right) = render(&right, &settings(1)).unwrap();
        let (_, wrong) = render(&wrong, &settings(1)).unwrap();
        let (a, b) = (right.counters.total(), wrong.counters.total());
        assert!(b <= 3 * a, "{steps:?}: {b} rays without the offset, {a} with it");
        let line = wrong.warnings.iter().find(|l| l.contains("self-intersection"));
        let line =
            line.unwrap_or_else(|| panic!("{steps:?}: no self-hit named ({a} and {b} rays): {:?}", wrong.warnings));
        // The advice is the shader's fix, not the geometry's.
        assert!(line.contains("NoOffset") && line.contains("ray.spawn") && !line.contains("with_error"), "{line}");
        assert_eq!(wrong.warnings.len(), 1, "{:?}", wrong.warnings);
        assert!(right.warnings.is_empty(), "{:?}", right.warnings);
    }
}

/// A mirror of a student's whose reflected ray is made with `Ray::new`, as the slide writes it: at depth 0
/// again, and (with `on_surface`) from the hit point itself, not off the surface.
struct RestartingMirror {
    on_surface: bool,
}

impl Shader for RestartingMirror {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let dir = reflect(ray.dir, faceforward(info.normal, ray.dir));
        let start = if self.on_surface { info.ip } else { ray.spawn(info, dir, 1.0).start };
        ctx.raytrace(&Ray::new(start, dir)) * 0.9
    }
}

/// Between two facing mirrors such a ray would recurse until the stack overflowed (the depth it carries never
/// grows): `raytrace` counts it at the depth it is nested at, so the render ends at the depth limit, in
/// either reading, and the report names the shader and says to use `ray.spawn`.
#[test]
fn a_ray_made_with_ray_new_cannot_restart_the_depth_in_either_reading() {
    for on_surface in [false, true] {
        for steps in [Steps::ALL, Steps::SLIDES] {
            let mut scene = facing_panels(|| Arc::new(RestartingMirror { on_surface }));
            scene.steps = steps;
            let (frame, stats) = render(&scene, &settings(1)).unwrap();
            assert!(frame.pixels.iter().all(|c| c.is_finite()));
            let deepest = stats.counters.rays_by_depth.iter().rposition(|&n| n > 0).unwrap();
            assert!(deepest <= DEPTH as usize, "rays at depth {deepest}: {:?}", stats.counters.rays_by_depth);
            let line = stats.warnings.iter().find(|l| l.contains("Ray::new starts at depth 0"));
            let line = line.unwrap_or_else(|| panic!("{steps:?}: not named: {:?}", stats.warnings));
            assert!(line.contains("RestartingMirror") && line.contains("ray.spawn"), "{line}");
        }
    }
}

/// The naive sum of N rays (each at the full weight, added up, not divided by N) is named by the end-of-run
/// report, with the factor by which it gains (at most N, since each ray brings at most the brightest's
/// colour; N where all its rays see the same stripe), for N = 2, 4 and 8 and a white tint, in either
/// reading; the same mirror done right (the rays' mean) gives no warning.
#[test]
fn the_naive_sum_of_n_rays_is_named_and_the_mean_is_not_in_both_readings() {
    for n in [2, 4, 8] {
        let glossy = || TintedGlossy { tint: Color::WHITE, glossiness: GLOSSINESS, n };
        for steps in [Steps::ALL, Steps::SLIDES] {
            let (_, right) = render(&ball_on_floor(&|| Arc::new(glossy()), steps), &settings(1)).unwrap();
            assert!(right.warnings.is_empty(), "N = {n}, {steps:?}: {:?}", right.warnings);
            let (_, wrong) = render(&ball_on_floor(&|| Arc::new(NaiveSum(glossy())), steps), &settings(1)).unwrap();
            let line = wrong.warnings.iter().find(|l| l.contains("adds up N rays without dividing by N"));
            let line = line.unwrap_or_else(|| panic!("N = {n}, {steps:?}: not named: {:?}", wrong.warnings));
            assert!(line.contains("Sphere #0 (NaiveSum)") && line.contains("Sphere #1 (NaiveSum)"), "{line}");
            let ball = &wrong.counters.problems.energy_gains[0];
            assert!(100 * ball.gained >= ball.hits, "N = {n}, {steps:?}: {ball:?}");
            let n = n as f32;
            assert!(ball.largest > 0.99 * n && ball.largest < 1.001 * n, "N = {n}, {steps:?}: {ball:?}");
            assert!(line.contains(&format!("up to {:.2} times", ball.largest)), "{line}");
        }
    }
}

/// The summary line an example prints says how many rays the branching bound shared (not traced, given their
/// siblings' mean colour), the number the render counted, and says nothing of it when there are none: a scene
/// file of a glossy floor under a glossy ceiling, 2 deep (every ray within its budget) and 12 deep.
#[test]
fn the_summary_line_says_how_many_rays_the_bound_shared_when_any() {
    use crate::common::{examples::scene_file, parse, root, run_example, temp_file};
    let output = root().join("target/branching-test/glossy.png");
    for depth in [2, 12] {
        let scene = format!(
            "GlobalSettings {{\n frameWidth 64\n frameHeight 48\n maxTraceDepth {depth}\n}}\n\
             Camera {{\n position (0, 0, 0)\n pitch -10\n}}\n\
             Plane below {{\n y -5\n}}\nPlane above {{\n y 5\n}}\n\
             Refl glossy {{\n glossiness 0.9\n numSamples 8\n}}\n\
             Node {{\n geometry below\n shader glossy\n}}\nNode {{\n geometry above\n shader glossy\n}}\n"
        );
        let file = temp_file("branching-test", &format!("glossy-{depth}.qdmg"), &scene);
        let args = [file.to_str().unwrap(), "--spp", "1"];
        let (_, stats) = parse::<scene_file::Options>(&args).render().unwrap();
        let shared = stats.counters.shared_rays;
        assert_eq!(shared > 0, depth > 2, "depth {depth}: {shared} rays shared");
        let out = run_example("scene_file", &[&args[..], &["-o", output.to_str().unwrap()]].concat());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let summary = String::from_utf8_lossy(&out.stdout);
        let said = format!(" M rays, {shared} more shared by the branching bound, ");
        assert_eq!(summary.contains(&said), depth > 2, "depth {depth}: {summary}");
        assert_eq!(summary.contains("shared"), depth > 2, "depth {depth}: {summary}");
    }
}

/// The API page's picture of the naive sum, docs/naive-sum.png, is the page's homework (docs/homework_glossy.rs)
/// rendered as it is, its glossy ball the mean of 8 rays, beside the same ball adding up its 8 rays without
/// dividing by 8, which washes it out to white: 200x150 each, 4 samples a pixel, captioned. The picture must be
/// this render within the regression tolerance; `UPDATE_EXPECTED=1` writes it.
#[test]
fn the_pages_picture_of_the_naive_sum_is_what_the_homework_renders() {
    use lecture6::instruments::compare::difference;
    use lecture6::instruments::side_by_side::{Panel, compose};
    let (scene, settings) =
        crate::common::parse::<homework_glossy::Options>(&["--width", "200", "--height", "150"]).prepare().unwrap();
    let (right, right_stats) = render(&scene, &settings).unwrap();
    assert!(right_stats.warnings.is_empty(), "{:?}", right_stats.warnings);
    let mut naive = scene.clone();
    let ball = naive.nodes.iter_mut().find(|n| n.name.as_deref() == Some("glossy ball")).unwrap();
    let Material::Own(glossy) = &ball.shader else { panic!("the homework's ball is a shader of its own") };
    let glossy = (&**glossy as &dyn std::any::Any).downcast_ref::<TintedGlossy>().unwrap();
    let (tint, glossiness, n) = (glossy.tint, glossy.glossiness, glossy.n);
    ball.shader = NaiveSum(TintedGlossy { tint, glossiness, n }).into_shader();
    let (wrong, wrong_stats) = render(&naive, &settings).unwrap();
    assert!(wrong_stats.warnings.iter().any(|l| l.contains("glossy ball (NaiveSum)")), "{:?}", wrong_stats.warnings);
    // The ball is what changes, and it is brighter: the picture shows the sum's gain.
    let mean = |f: &Frame| f.pixels.iter().map(|c| c.luminance()).sum::<f32>() / f.pixels.len() as f32;
    assert!(mean(&wrong) > 1.2 * mean(&right), "{} against {}", mean(&wrong), mean(&right));
    let picture = compose(&[
        Panel { image: right.to_rgb8(), caption: format!("the mean of {n} rays: sum * tint / kept") },
        Panel { image: wrong.to_rgb8(), caption: format!("the naive sum: sum * tint, {n} rays not divided by {n}") },
    ])
    .unwrap();
    let path = crate::common::root().join("docs/naive-sum.png");
    if std::env::var_os("UPDATE_EXPECTED").is_some_and(|v| v == "1") {
        picture.save(&path).unwrap();
        return;
    }
    let page = image::open(&path).unwrap_or_else(|e| panic!("{}: {e} (UPDATE_EXPECTED=1 writes it)", path.display()));
    let d = difference(&picture, &page.to_rgb8()).unwrap();
    assert!(d.within_regression_tolerance(), "docs/naive-sum.png is not the homework's render: {d}");
}

/// A clear coat as the student wrote it: a glossy base of `n` rays averaged, under a mirror ray weighted
/// by Schlick's Fresnel factor (0.04 head-on): two unlike rays, each given the factor its colour is multiplied
/// by.
struct ClearCoat(TintedGlossy);

impl Shader for ClearCoat {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let normal = faceforward(info.normal, ray.dir);
        let fresnel = 0.04 + 0.96 * (1.0 + ray.dir.dot(normal)).powi(5);
        let mirror = ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), fresnel));
        let base = Ray { weight: ray.weight * (1.0 - fresnel), ..*ray };
        mirror * fresnel + self.0.shade(&base, info, ctx) * (1.0 - fresnel)
    }
}

/// A shader that glows: a colour of its own, brighter than white, and no ray or light.
struct Glow;

impl Shader for Glow {
    fn shade(&self, _: &Ray, _: &IntersectionInfo, _: &mut TraceContext) -> Color {
        Color::new(3.0, 2.0, 1.0)
    }
}

/// The energy check leaves correct shaders alone, in either reading: the clear coat (a Fresnel-weighted mirror
/// ray over an N-ray glossy base), a workbook `Layered` of a matte base lit by a lamp under the student's glossy
/// coat (its light loop's light counted, else the lit base under a coat that sees the dark stripes would gain),
/// a shader that glows and a matte surface of albedo 2 (light from nowhere, or a texture brighter than white:
/// no rays to weigh), on a ball over a glossy floor, lit. The ball's hits are weighed where it traces two rays.
#[test]
fn the_energy_check_leaves_correct_shaders_alone_in_both_readings() {
    let glossy = || TintedGlossy { tint: TINT, glossiness: GLOSSINESS, n: 4 };
    let coated = || {
        let mut layered = Layered::new();
        layered.add_layer(Lambert::new(Color::new(0.9, 0.6, 0.3)), Color::WHITE, None).add_layer(
            glossy(),
            Color::gray(0.5),
            None,
        );
        layered
    };
    let shaders: [(&str, Arc<dyn Shader>, bool); 4] = [
        ("clear coat", Arc::new(ClearCoat(glossy())), true),
        ("lit base under a glossy coat", Arc::new(coated()), true),
        ("glow", Arc::new(Glow), false),
        ("albedo 2", Arc::new(Lambert::new(Color::gray(2.0))), false),
    ];
    for (what, shader, weighed) in shaders {
        for steps in [Steps::ALL, Steps::SLIDES] {
            let mut scene = ball_on_floor(&|| Arc::new(glossy()), steps);
            scene.nodes[0].shader = shader.clone().into_shader();
            scene.ambient = Color::gray(0.2);
            scene.lights.push(PointLight::new(Vector::new(-20.0, 40.0, -30.0), Color::WHITE, 3000.0));
            let (_, stats) = render(&scene, &settings(1)).unwrap();
            assert!(stats.warnings.is_empty(), "{what}, {steps:?}: {:?}", stats.warnings);
            let ball = stats.counters.problems.energy_gains.first().copied().unwrap_or_default();
            assert_eq!(ball.gained, 0, "{what}, {steps:?}: {ball:?}");
            assert_eq!(ball.hits > 1000, weighed, "{what}, {steps:?}: {ball:?}");
        }
    }
}
