//! The size of the slides' reading (`--slide`): the lines of code of the lesson layer that it executes,
//! topic by topic, at most 3,175 in all (the course's own lecture-6 program is 1,486). Comments, blank
//! lines, file loading, input checks, the steps' gates and the end-of-run report are not counted
//! ([`NOT_COUNTED`] names each item); nor is the code of the steps beyond the slides, which `--slide` never
//! reaches (tests/slide_audit.rs). The guards that hold in both readings (the branching bound) and the enums
//! that store the course's types and dispatch them run in both readings too: the table prints them apart
//! ([`ENGINE`]). Every line that `--slide` runs is in one of these tables, by callgrind's record of each
//! example's render ([`every_line_slide_runs_is_in_the_tables`]).
//!
//! Print the table: `cargo test --release --test workbook plain_path -- --nocapture`.
use crate::common::root;
use std::collections::{BTreeMap, BTreeSet};

/// Where the code of a topic is: a file of src/lesson, and the items of it that `--slide` executes (the
/// whole file when none are named). An item is named by the start of its first line.
type Part = (&'static str, &'static [&'static str]);

/// The topics of the slides' reading and their code. The first part of a topic is its core: the slide's
/// version of the technique, in the technique's own file.
const PLAIN_PATH: &[(&str, &[Part])] = &[
    (
        "render loop, camera, raytrace",
        &[
            (
                "scene.rs",
                &[
                    "    pub fn raytrace(",
                    "    fn raytrace_unwatched(",
                    "    fn trace<const WATCHED",
                    "    fn trace_by_loop<",
                    "    fn shade_found<",
                    "    fn shade_workbook_hit(",
                    "    fn environment(",
                    "    fn stop<",
                    "    pub fn visible(",
                ],
            ),
            ("render_settings.rs", &["pub struct RenderSettings", "impl RenderSettings"]),
            (
                "render.rs",
                &[
                    "pub struct Stratifier",
                    "    pub fn new(spp",
                    "    pub fn start_pixel(",
                    "    pub fn offset(",
                    "pub fn render_with_progress(",
                    "pub fn spectral_plan(",
                    "pub struct RenderJob",
                    "    pub fn new(scene",
                    "    pub fn render(&self",
                    "    pub fn refine(",
                    "    pub fn stats(",
                    "    pub fn render_row<",
                    "struct PixelTracer",
                    "    fn new(job",
                    "    fn start_pixel(",
                    "    fn camera_ray(",
                    "    fn samples(",
                    "    fn pixel(",
                ],
            ),
            (
                "camera.rs",
                &[
                    "pub struct Camera ",
                    "impl Default for Camera",
                    "pub fn rotation",
                    "impl FovAxis",
                    "pub struct CameraFrame",
                    "    pub fn frame(",
                    "impl CameraFrame",
                ],
            ),
            ("frame.rs", &["pub struct Frame ", "    pub fn new("]),
            ("sampling.rs", &["pub struct PixelSample"]),
            // The course's adaptive anti-aliasing (an earlier lecture's), which its scene files ask for.
            ("adaptive_aa.rs", &["pub fn refine(", "pub fn refine_pixel(", "pub fn marked(", "pub fn marked_at("]),
            (
                "scene.rs",
                &[
                    "pub struct Scene ",
                    "    pub fn new(camera",
                    "    pub fn add(",
                    "    pub fn check(",
                    "    pub fn is_dispersive(",
                    "    pub fn prepared(",
                    "    pub(crate) fn checked_closest_hit(",
                    "    pub(crate) fn closest_by_loop(",
                    "    pub(crate) fn intersects_through(",
                    "pub struct TraceContext",
                    "    pub fn new(scene",
                    "    pub(crate) fn restart_pixel(",
                ],
            ),
            ("ray.rs", &[]),
            ("rng.rs", &[]),
            ("math.rs", &[]),
            ("color.rs", &[]),
        ],
    ),
    (
        "shading (lectures 2-3): Lambert, Phong, lights",
        &[("shader/lambert.rs", &[]), ("shader/phong.rs", &[]), ("light.rs", &[]), ("shader/mod.rs", &[])],
    ),
    (
        "bitmap textures",
        &[
            ("bitmap.rs", &["    pub fn sample(", "    pub fn sample_recorded(", "    fn filtered<"]),
            (
                "bitmap.rs",
                &[
                    "pub enum Wrap",
                    "    pub fn texel(",
                    "pub enum Filter",
                    "impl Filter",
                    "pub struct Bitmap ",
                    "    pub fn width(",
                    "    pub fn height(",
                    "    pub fn get_pixel(",
                    "fn decode(",
                ],
            ),
            ("texture/mod.rs", &[]),
            (
                "texture/bitmap.rs",
                &[
                    "pub struct BitmapTexture",
                    "    pub fn new(",
                    "    pub fn with_tile_size(",
                    "    pub(super) fn read(",
                    "impl Texture for BitmapTexture",
                ],
            ),
            ("texture/checker.rs", &[]),
        ],
    ),
    (
        "model transform",
        &[
            (
                "node.rs",
                &[
                    "    pub fn intersect(",
                    "    pub(crate) fn checked_intersect(",
                    "    fn intersect_transformed(",
                    "pub(crate) fn closest_of(",
                ],
            ),
            ("geometry/one_by_one.rs", &[]),
            ("transform.rs", &[]),
            (
                "node.rs",
                &[
                    "pub struct Node ",
                    "    pub fn new(",
                    "    pub fn named(",
                    "    fn with_transform",
                    "    pub fn scale(",
                    "    pub fn rotate(",
                    "    pub fn translate(",
                    "    pub fn bounds(",
                ],
            ),
            (
                "geometry/intersection.rs",
                &["pub struct IntersectionInfo", "pub struct TexCoords", "impl TexCoords", "impl IntersectionInfo"],
            ),
            ("geometry/mod.rs", &["pub trait Geometry", "pub struct Aabb", "impl Aabb"]),
            ("geometry/sphere.rs", &[]),
            ("geometry/plane.rs", &[]),
            ("geometry/cube.rs", &[]),
            ("geometry/prism.rs", &[]),
            (
                "geometry/mesh.rs",
                &[
                    "pub struct Mesh ",
                    "fn face_normal(",
                    "    pub fn culled(",
                    "    pub fn slots(",
                    "    fn triangle(",
                    "    fn info(",
                    "    fn surface(",
                    "    fn into_shape(",
                ],
            ),
        ],
    ),
    (
        "environment",
        &[
            (
                "environment.rs",
                &[
                    "impl Environment for SphericalEnvironment",
                    "pub fn equirect_uv",
                    "pub fn cube_face_uv",
                    "impl Environment for CubemapEnvironment",
                ],
            ),
            (
                "environment.rs",
                &[
                    "pub trait Environment",
                    "pub struct ConstantEnvironment",
                    "impl Environment for ConstantEnvironment",
                    "pub struct SphericalEnvironment",
                    "pub enum CubeFace",
                    "pub struct CubemapEnvironment",
                    "    fn look_up(",
                    "impl CubemapEnvironment {",
                ],
            ),
        ],
    ),
    (
        "reflection",
        &[
            ("shader/reflection.rs", &["    fn trace_mirror(", "impl Shader for Reflection"]),
            (
                "shader/reflection.rs",
                &["pub struct Reflection ", "    pub fn mirror(", "impl CausticCaster for Reflection"],
            ),
        ],
    ),
    ("refraction", &[("shader/refraction.rs", &[])]),
    (
        "layered shader",
        &[
            ("shader/layered.rs", &["fn shade_bottom_up(", "impl Shader for Layered"]),
            (
                "shader/layered.rs",
                &[
                    "pub struct Layer ",
                    "impl Layer {",
                    "pub struct Layered ",
                    "    pub fn add_layer(",
                    "    pub fn shade_every_layer(",
                    "    pub fn layers(",
                    "    fn weights(",
                    "impl CausticCaster for Layered",
                ],
            ),
        ],
    ),
    ("Fresnel", &[("texture/fresnel.rs", &[]), ("shader/glass.rs", &[])]),
    (
        "glossy reflections",
        &[
            ("shader/reflection.rs", &["    fn shade_glossy("]),
            (
                "shader/reflection.rs",
                &[
                    "    pub fn glossy(",
                    "    pub fn with_sampler(",
                    "pub struct GlossyCone",
                    "impl GlossyCone",
                    "pub fn glossy_scaling",
                    "pub const SECONDARY_GLOSSY_SAMPLES",
                ],
            ),
            (
                "sampling.rs",
                &[
                    "pub fn random_unit_disc_point",
                    "pub enum DiscSampler",
                    "pub struct DiscSamples",
                    "    pub fn new(sampler",
                    "    pub fn for_pixel_sample(",
                    "    pub fn point(",
                ],
            ),
        ],
    ),
    (
        "chromatic dispersion",
        &[
            ("spectral/mod.rs", &["pub enum SpectralPlan", "impl SpectralPlan"]),
            ("render.rs", &["fn add_weighted(", "fn to_color("]),
            ("spectral/mod.rs", &["pub enum Ior", "impl Ior", "impl From<f32> for Ior", "impl SpectralMode"]),
            (
                "spectral/colour.rs",
                &[
                    "pub const LAMBDA_MIN",
                    "pub const LAMBDA_MAX",
                    "pub enum Illuminant",
                    "impl Illuminant",
                    "fn segment(",
                    "pub fn cie_xyz(",
                    "const SRGB_PRIMARIES",
                    "fn xyz_to_srgb_matrix(",
                    "pub fn xyz_to_linear_srgb(",
                    "const STEPS_PER_NM",
                    "fn cumulative_xyz(",
                    "fn cumulative_rgb(",
                    "fn cumulative_at(",
                    "pub struct Band ",
                    "impl Band ",
                    "pub fn bands(",
                    "pub fn clip_to_gamut(",
                ],
            ),
            ("spectral/cie.rs", &[]),
        ],
    ),
    (
        "photon mapping",
        &[
            ("photon_map/all_directions.rs", &[]),
            ("photon_map/kd_tree.rs", &[]),
            (
                "photon_map/mod.rs",
                &[
                    "pub struct PhotonSettings",
                    "impl Default for PhotonSettings",
                    "pub struct StoredPhoton",
                    "pub struct PhotonStats",
                    "    fn with_lookup(",
                    "    pub fn irradiance(",
                    "    pub fn irradiance_recorded(",
                    "    fn kd_tree_irradiance(",
                    "pub fn arriving_light(",
                ],
            ),
            (
                "photon_map/build.rs",
                &["    pub fn build(", "fn scene_box(", "pub fn min_radius(", "pub fn default_radius("],
            ),
            // The photon tracer's hit: the scene's closest node, described in full.
            ("scene.rs", &["    pub fn closest_hit("]),
        ],
    ),
];

/// What both readings run beside the slides' code, counted apart from it: the enums that store each course
/// type once and dispatch it, and the guards (the branching bound and the end-of-run report's counts).
const ENGINE: &[(&str, &[Part])] = &[
    (
        "the course's types, each stored once, and their one dispatch",
        &[
            ("geometry/shape.rs", &[]),
            ("shader/material.rs", &[]),
            ("texture/tex.rs", &[]),
            ("environment.rs", &["pub enum Sky", "impl Sky", "impl Environment for Sky"]),
            ("scene.rs", &["    pub(crate) fn sky("]),
            ("prepared.rs", &[]),
        ],
    ),
    (
        "guards: the branching bound, a shape's normals",
        &[("branching.rs", &[]), ("node.rs", &["    fn is_unit_normal(", "    pub(crate) fn is_workbook("])],
    ),
    ("the ray tree's hooks, told nothing when none watches", &[("topic.rs", &["pub fn record("])]),
];

/// Whether a line is code: not blank, not a comment.
fn is_code(line: &str) -> bool {
    let line = line.trim();
    !(line.is_empty() || line.starts_with("//"))
}

/// The lines of the item whose first line starts with `start` (up to the brace that closes it, or its `;`).
fn item<'a>(lines: &[&'a str], start: &str, file: &str) -> Vec<&'a str> {
    let first = lines
        .iter()
        .position(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("src/lesson/{file} has no item starting with {start:?}: update PLAIN_PATH"));
    let mut depth = 0i32;
    let mut opened = false;
    for (i, line) in lines[first..].iter().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        depth += code.matches('{').count() as i32 - code.matches('}').count() as i32;
        opened |= code.contains('{');
        if (opened && depth <= 0) || (!opened && code.trim_end().ends_with(';')) {
            return lines[first..=first + i].to_vec();
        }
    }
    lines[first..].to_vec()
}

/// The code lines of a part: the named items, or the whole file less its unit tests.
fn count((file, items): &Part) -> usize {
    let text = std::fs::read_to_string(root().join("src/lesson").join(file)).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let lines = match items {
        [] => {
            let end = lines.iter().position(|l| l.trim() == "#[cfg(test)]").unwrap_or(lines.len());
            lines[..end].to_vec()
        }
        items => items.iter().flat_map(|start| item(&lines, start, file)).collect(),
    };
    lines.into_iter().filter(|l| is_code(l)).count()
}

#[test]
fn the_plain_path_is_at_most_3175_lines_and_each_topics_core_about_150() {
    let mut total = 0;
    println!("{:<48} {:>6} {:>6}", "topic", "core", "lines");
    for (topic, parts) in PLAIN_PATH {
        let lines: usize = parts.iter().map(count).sum();
        let core = count(&parts[0]);
        println!("{topic:<48} {core:>6} {lines:>6}");
        total += lines;
        assert!(core <= 160, "{topic}: the slide's version has {core} lines of code, more than about 150");
    }
    println!("{:<48} {:>6} {total:>6}", "all", "");
    for (what, parts) in ENGINE {
        println!("{what:<48} {:>6} {:>6}", "", parts.iter().map(count).sum::<usize>());
    }
    assert!(total <= 3175, "the slides' reading is {total} lines of code, more than 3,175");
}

/// Each topic's core (the slide's version of the technique, the first part of its topic) is the first thing
/// in its file, where a student opens it: the file's first items are the core's (or the `impl` that holds
/// one; two topics sharing a file, the mirror and the glossy mirror, put both cores first); only the
/// module's doc, its `mod` and `use` lines and comments come before them.
#[test]
fn each_topics_core_is_the_first_thing_in_its_file() {
    // Per file, the top-level items that hold a core's items: an item itself, or the `impl` above a method.
    let mut holders: std::collections::BTreeMap<&str, std::collections::BTreeSet<usize>> = Default::default();
    for (_, parts) in PLAIN_PATH {
        let (file, items) = parts[0];
        let text = std::fs::read_to_string(root().join("src/lesson").join(file)).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for start in items {
            let at = lines.iter().position(|l| l.starts_with(start)).expect("the core's item (checked above)");
            let top_level = |i: &usize| !lines[*i].is_empty() && !lines[*i].starts_with(char::is_whitespace);
            let holder = (0..=at).rev().find(top_level).unwrap();
            holders.entry(file).or_default().insert(holder);
        }
    }
    let mut late = Vec::new();
    for (file, holders) in holders {
        let text = std::fs::read_to_string(root().join("src/lesson").join(file)).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let preamble = |l: &str| {
            let l = l.trim_start_matches("pub ");
            l.is_empty() || ["//", "#", "use ", "mod "].iter().any(|p| l.starts_with(p))
        };
        // The file's top-level items, in order, after its preamble.
        let first = lines.iter().position(|l| !preamble(l)).unwrap();
        let items: Vec<usize> = (first..lines.len())
            .filter(|&i| !lines[i].starts_with(char::is_whitespace) && !preamble(lines[i]))
            .collect();
        // Not the closing lines of an item or of a signature written over several lines.
        let items: Vec<usize> = items.into_iter().filter(|&i| !lines[i].starts_with(['}', ')'])).collect();
        let leading: std::collections::BTreeSet<usize> = items.iter().take(holders.len()).copied().collect();
        if leading != holders {
            let before: Vec<&str> = leading.difference(&holders).map(|&i| lines[i]).collect();
            late.push(format!("src/lesson/{file}: {before:?} before the core"));
        }
    }
    assert!(late.is_empty(), "cores that are not the first thing in their file:\n{}", late.join("\n"));
}

/// What `--slide` runs that the tables do not count, by the count's own rule: reading files (images, meshes,
/// and the mesh's BVH, which the loader builds whether or not the render walks it), checking the input,
/// writing the picture, and the end-of-run report. Named item by item, so that nothing else hides here.
const NOT_COUNTED: &[(&str, &[Part])] = &[
    (
        "loading files",
        &[
            ("bitmap.rs", &["    pub fn load(", "    pub fn from_file(", "    pub fn from_pixels("]),
            (
                "environment.rs",
                &[
                    "pub fn load(",
                    "pub fn load_with_layout(",
                    "    pub fn load(path",
                    "    pub fn load(dir",
                    "    pub fn load_layout(",
                ],
            ),
            (
                "geometry/mesh.rs",
                &["    pub fn load(", "    pub fn load_auto_smooth(", "    pub fn from_parts(", "fn check_indices("],
            ),
            ("geometry/polygon.rs", &["pub fn triangulate("]),
            ("geometry/bvh.rs", &[]),
            ("geometry/triangle4.rs", &["    pub fn new("]),
            ("environment.rs", &["impl CubeFace", "    pub fn new(faces"]),
        ],
    ),
    (
        "checking the input (the caustic's casters: photon options that would do nothing are refused)",
        &[
            ("photon_map/mod.rs", &["    pub fn check("]),
            ("render.rs", &["    pub fn for_scene("]),
            ("shader/layered.rs", &["pub fn shades_per_hit("]),
            ("photon_map/build.rs", &["    pub fn can_have_caustics("]),
            ("photon_map/emitter.rs", &["    fn new(light", "pub fn strength(", "    pub fn new(scene"]),
        ],
    ),
    (
        "the steps' gates: a step asked whether it is taken, and named",
        &[
            ("beyond.rs", &["pub struct Steps", "    pub fn name(", "    const fn bit(", "    pub const fn has("]),
            ("scene.rs", &["    pub fn relative_to_camera("]),
        ],
    ),
    ("writing the picture", &[("frame.rs", &["    pub fn save(", "    pub fn to_rgb8("])]),
    (
        "the summary line and the end-of-run report",
        &[
            ("diagnostics.rs", &[]),
            ("problems.rs", &[]),
            (
                "scene.rs",
                &[
                    "    pub(crate) fn is_far_from_the_origin(",
                    "    pub(crate) fn around(",
                    "pub struct Counters",
                    "impl Counters",
                ],
            ),
            ("spectral/mod.rs", &["impl std::fmt::Display for SpectralPlan"]),
        ],
    ),
];

/// The first and last line (from 1) of each item of a part, with the attributes above it (`#[derive]`
/// code runs as the item's); the whole file less its unit tests when the part names no items.
fn spans((file, items): &Part) -> Vec<(usize, usize)> {
    let text = std::fs::read_to_string(root().join("src/lesson").join(file)).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    if items.is_empty() {
        return vec![(1, lines.iter().position(|l| l.trim() == "#[cfg(test)]").unwrap_or(lines.len()))];
    }
    items
        .iter()
        .map(|start| {
            let body = item(&lines, start, file);
            let first = lines.iter().position(|l| l.starts_with(start)).unwrap();
            let attributes = lines[..first].iter().rev().take_while(|l| l.trim_start().starts_with("#[")).count();
            (first + 1 - attributes, first + body.len())
        })
        .collect()
}

/// The lines of `src/lesson` that ran, by file, in callgrind's record of a run (`--dump-instr=no
/// --compress-strings=no --compress-pos=no`): each cost line's number, in the file that the last `fl=`, `fi=`
/// or `fe=` line named (the `fi=`/`fe=` ones are code inlined from another file, with its own lines).
fn lines_run(record: &str) -> BTreeMap<String, BTreeSet<usize>> {
    let mut ran: BTreeMap<String, BTreeSet<usize>> = BTreeMap::new();
    let mut file = String::new();
    let mut function_file = String::new();
    for line in record.lines() {
        if let Some(name) = ["fl=", "fi=", "fe="].iter().find_map(|p| line.strip_prefix(p)) {
            file = name.split("/src/lesson/").nth(1).unwrap_or("").to_string();
            if line.starts_with("fl=") {
                function_file = file.clone();
            }
        } else if line.starts_with("fn=") {
            file = function_file.clone();
        } else if let Some(number) = line.split(' ').next().and_then(|n| n.parse::<usize>().ok())
            && !file.is_empty()
            && number > 0
        {
            ran.entry(file.clone()).or_default().insert(number);
        }
    }
    ran
}

/// Every line of the lesson that `--slide` runs is in an item the tables count (the slides' code, the
/// engine) or in one they name as not counted ([`NOT_COUNTED`]): each of the workbook's examples (not a
/// student's own in `examples/`) renders with `--slide` at 16x12 under callgrind, whose record of the lines that ran comes from the release profile's line tables
/// (inlined code keeps its own file and line). A `use` line or a constant that a record names (the compiler
/// files some instructions there) is not code that ran. Needs valgrind: where it is not installed the test
/// says it is skipped.
#[test]
fn every_line_slide_runs_is_in_the_tables() {
    if std::process::Command::new("valgrind").arg("--version").output().is_err() {
        eprintln!(
            "skipped: the check of the tables against what --slide runs needs valgrind (apt-get install valgrind)"
        );
        return;
    }
    let dir = root().join("target").join("plain_path");
    std::fs::create_dir_all(&dir).unwrap();
    // Each line that ran, by its file and number, and the examples that ran it.
    let mut ran: BTreeMap<(String, usize), BTreeSet<&str>> = BTreeMap::new();
    macro_rules! names {
        ($($name:ident),*) => { [$(stringify!($name)),*] };
    }
    for example in every_example!(names) {
        let record = dir.join(format!("{example}.callgrind"));
        let mut args = vec!["--slide", "--width", "16", "--height", "12", "--threads", "1"];
        if example == "photon_map" {
            args.extend(["--photons", "20000"]);
        }
        let picture = dir.join(format!("{example}.png"));
        let run = std::process::Command::new("valgrind")
            .args(["--tool=callgrind", "--dump-instr=no", "--compress-strings=no", "--compress-pos=no"])
            .arg(format!("--callgrind-out-file={}", record.display()))
            .arg(crate::common::example_binary(example))
            .args(&args)
            .arg("-o")
            .arg(&picture)
            .current_dir(root())
            .output()
            .expect("run valgrind");
        assert!(run.status.success(), "{example} --slide under callgrind: {}", String::from_utf8_lossy(&run.stderr));
        for (file, lines) in lines_run(&std::fs::read_to_string(&record).unwrap()) {
            for line in lines {
                ran.entry((file.clone(), line)).or_default().insert(example);
            }
        }
    }
    let mut covered: BTreeMap<&str, Vec<(usize, usize)>> = BTreeMap::new();
    for (_, parts) in PLAIN_PATH.iter().chain(ENGINE).chain(NOT_COUNTED) {
        for part in *parts {
            covered.entry(part.0).or_default().extend(spans(part));
        }
    }
    let not_run = ["use ", "pub use ", "const ", "pub const ", "pub(crate) const "];
    let mut sources: BTreeMap<&str, String> = BTreeMap::new();
    let mut missing = Vec::new();
    for ((file, line), examples) in &ran {
        let source = sources
            .entry(file)
            .or_insert_with(|| std::fs::read_to_string(root().join("src/lesson").join(file)).unwrap());
        let code = source.lines().nth(line - 1).map_or("", str::trim);
        if !is_code(code) || not_run.iter().any(|p| code.starts_with(p)) {
            continue;
        }
        let spans = covered.get(file.as_str()).map(Vec::as_slice).unwrap_or(&[]);
        if !spans.iter().any(|&(first, last)| (first..=last).contains(line)) {
            let examples: Vec<&str> = examples.iter().copied().collect();
            missing.push(format!("src/lesson/{file}:{line}: {code}  ({})", examples.join(", ")));
        }
    }
    assert!(missing.is_empty(), "lines that --slide runs outside the tables:\n{}", missing.join("\n"));
}
