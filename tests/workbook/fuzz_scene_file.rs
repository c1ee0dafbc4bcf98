//! A fuzz target for the scene-file reader: a scene file, mutated at random (numbers replaced by NaN,
//! infinities and values past the 32-bit floats, tokens, lines and bytes deleted, doubled, swapped or
//! inserted, control characters, blocks appended that name FIFOs, `/dev/zero`, folders, empty, degenerate
//! or giant files, or nest shaders deeply), is given to the `scene_file` example, which must render it or
//! refuse it with one line and exit code 2, within a time and memory bound (`common::hostile`): never a
//! panic, an abort, a hang, a raw control character on the terminal, or an earlier output destroyed.
//!
//! Two scenes are mutated: the bundled one (`examples/data/fresnel.qdmg`) and one that uses every element
//! the reader knows. Each test runs a few cases, so that `cargo test` stays quick; `PROPTEST_CASES=N` runs
//! N of each (docs/tests.md gives the long run's command and result). A failure is shrunk to its smallest
//! mutation and kept in `fuzz_scene_file.proptest-regressions`, which is replayed first on every run.

use crate::common;

use crate::hostile_files::{encoded, float_picture, gradient};
use common::hostile::{black_png, fifo, run_bounded, scratch};
use proptest::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Cases per test when `PROPTEST_CASES` does not say: a few seconds of `cargo test`.
const QUICK_CASES: u32 = 12;

fn config() -> ProptestConfig {
    let mut config = ProptestConfig { max_shrink_iters: 200, ..ProptestConfig::default() };
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = QUICK_CASES;
    }
    config
}

fn dir() -> PathBuf {
    scratch("fuzz-scene-file")
}

/// The hostile files and folders a mutation can name, made once per run.
struct Hostile {
    meshes: Vec<String>,
    images: Vec<String>,
    folders: Vec<String>,
}

fn hostile() -> &'static Hostile {
    static FILES: OnceLock<Hostile> = OnceLock::new();
    FILES.get_or_init(|| {
        let dir = dir().join("files");
        std::fs::create_dir_all(&dir).unwrap();
        let write = |name: &str, bytes: &[u8]| {
            let path = dir.join(name);
            std::fs::write(&path, bytes).unwrap();
            path.display().to_string()
        };
        let pipe = |name: &str| fifo(&dir.join(name)).display().to_string();
        let folder = dir.join("a-folder.png");
        std::fs::create_dir_all(&folder).unwrap();
        let folder = folder.display().to_string();
        let mut zero_bmp = b"BM".to_vec();
        for v in [54u32, 0, 54, 40, 0, 0] {
            zero_bmp.extend(v.to_le_bytes());
        }
        zero_bmp.extend([1, 0, 24, 0]);
        zero_bmp.extend([0u8; 24]);
        let cube_with_fifo = dir.join("cube-with-fifo");
        std::fs::create_dir_all(&cube_with_fifo).unwrap();
        for face in ["posx", "negx", "posy", "negy", "negz"] {
            std::fs::write(cube_with_fifo.join(format!("{face}.png")), black_png(4, 4)).unwrap();
        }
        fifo(&cube_with_fifo.join("posz.png"));
        let common = |files: &mut Vec<String>| {
            files.extend([pipe("pipe"), "/dev/zero".into(), folder.clone(), write("empty", b"")]);
            files.push(dir.join("missing").display().to_string());
        };
        let mut meshes = vec![
            write("no-faces.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
            write("degenerate.obj", b"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
            write("nan.obj", b"v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"),
            write("bad-index.obj", b"v 0 0 0\nf 1 2 9\n"),
            write("picture.obj", &black_png(4, 4)),
            // The second round (`hostile_files.rs`): faces coming back to their corners, polylines only, a
            // byte-order mark, Latin-1 bytes, an index past the end on a later line.
            write(
                "repeated-corners.obj",
                format!("v 0 0 0\nv 1 0 0\nv 0 1 0\nf{}\n", " 1 2 3".repeat(20_000)).as_bytes(),
            ),
            write("polylines.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nl 1 2 3 4 1\n"),
            write("bom.obj", b"\xef\xbb\xbfv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            write("latin-1.obj", b"# caf\xe9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 -9\n"),
        ];
        common(&mut meshes);
        let jpeg = encoded(gradient(64, 64), image::ImageFormat::Jpeg);
        let hdr = encoded(float_picture(0.5), image::ImageFormat::Hdr);
        let bmp = encoded(gradient(64, 64), image::ImageFormat::Bmp);
        let mut images = vec![
            write("zero.bmp", &zero_bmp),
            write("bomb.png", &black_png(16000, 16000)),
            write("cut.png", &black_png(64, 64)[..60]),
            write("text.png", b"not a picture"),
            // The second round: truncated, non-finite, another Radiance signature, a BMP cut short.
            write("cut.jpg", &jpeg[..jpeg.len() / 2]),
            write("nan.exr", &encoded(float_picture(f32::NAN), image::ImageFormat::OpenExr)),
            write("inf.exr", &encoded(float_picture(f32::INFINITY), image::ImageFormat::OpenExr)),
            write("rgbe.hdr", &[&b"#?RGBE\n"[..], &hdr[b"#?RADIANCE\n".len()..]].concat()),
            write("cut.bmp", &bmp[..bmp.len() / 2]),
        ];
        common(&mut images);
        let mut folders = vec![cube_with_fifo.display().to_string(), dir.join("bomb.png").display().to_string()];
        common(&mut folders);
        Hostile { meshes, images, folders }
    })
}

/// A scene with every element the reader knows, for the mutations to reach every property.
fn every_element_scene() -> String {
    let textures = common::root().join("textures");
    format!(
        r#"GlobalSettings {{
	frameWidth 64
	frameHeight 48
	ambientLight (0.1, 0.1, 0.1)
	maxTraceDepth 6
	wantAA on
	lightPos (0, 200, -100)
	lightIntensity 20000
}}
Camera {{
	position (0, 40, -90)
	yaw 5
	pitch -15
	roll 1
	fov 70
	aspectRatio 1.333
}}
PointLight {{
	pos (60, 120, -40)
	color (1, 0.9, 0.8)
	power 30000
}}
Plane floor {{
	y 0
	limit 200
}}
Sphere ball {{
	O (0, 10, 0)
	R 10
}}
Cube box {{
	O (25, 5, 10)
	halfSide 5
}}
Mesh pot {{
	file "{textures}/teapot_low.obj"
	faceted false
	backfaceCulling true
	autoSmooth true
}}
CheckerTexture checker {{
	color1 (0.8, 0.8, 0.8)
	color2 (0.1, 0.1, 0.1)
	scaling 5
}}
BitmapTexture wood {{
	file "{textures}/wood.png"
	scaling 40
	assumedGamma 2.2
}}
Fresnel fresnel {{
	ior 1.5
}}
Lambert floor {{
	texture checker
}}
Phong wood {{
	color (0.6, 0.4, 0.2)
	texture wood
	specularExponent 40
	specularMultiplier 0.3
}}
Refl mirror {{
	multiplier 0.9
}}
Refl glossy {{
	multiplier 0.8
	glossiness 0.9
	numSamples 4
}}
Refr glass_refraction {{
	ior 1.5
	multiplier 0.95
}}
Layered glass {{
	layer glass_refraction (1, 1, 1)
	layer mirror (1, 1, 1) fresnel
}}
Layered lacquer {{
	layer wood (1, 1, 1)
	layer glossy (0.2, 0.2, 0.2)
}}
Node {{
	geometry floor
	shader floor
}}
Node {{
	geometry ball
	shader glass
}}
Node {{
	geometry box
	shader lacquer
	rotate (30, 0, 0)
}}
Node {{
	geometry pot
	shader mirror
	scale (8, 8, 8)
	rotate (0, 10, 0)
	translate (-25, 0, 10)
}}
CubemapEnvironment {{
	folder "{textures}/sky_cubemap"
	layout opengl
}}
"#,
        textures = textures.display()
    )
}

/// The bundled scene, its textures found wherever it is written.
fn bundled_scene() -> String {
    let text = std::fs::read_to_string(common::root().join("examples/data/fresnel.qdmg")).unwrap();
    text.replace("\"../../textures/", &format!("\"{}/", common::root().join("textures").display()))
}

/// One change to a scene file's text.
#[derive(Clone, Debug)]
enum Mutation {
    /// The `nth` number of the file (counting around) becomes `with`.
    Number {
        nth: usize,
        with: String,
    },
    /// The `nth` white-space separated token becomes `with`.
    Token {
        nth: usize,
        with: String,
    },
    DeleteLine(usize),
    DuplicateLine(usize),
    SwapLines(usize, usize),
    /// `text` inserted at byte `at` (counting around, moved back to a character boundary).
    Insert {
        at: usize,
        text: String,
    },
    /// The file cut at byte `at`.
    Truncate(usize),
    /// A block added at the end.
    Append(String),
}

fn hostile_number() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => prop::sample::select(vec![
            "nan",
            "-nan",
            "inf",
            "-inf",
            "infinity",
            "1e309",
            "-1e309",
            "1e39",
            "-1e39",
            "3.5e38",
            "1e38",
            "1e19",
            "1e18",
            "-1e18",
            "1e-45",
            "1e-320",
            "0",
            "-0",
            "0.0",
            "1",
            "-1",
            "2147483647",
            "2147483648",
            "-2147483649",
            "99999999999999999999",
            "0x10",
            "1e",
            ".",
            "-",
            "",
            "abc",
            "1,5",
            "(1,2)",
            "\"3\"",
        ])
        .prop_map(String::from),
        2 => any::<f64>().prop_map(|v| format!("{v:e}")),
        1 => any::<f32>().prop_map(|v| v.to_string()),
        1 => any::<i64>().prop_map(|v| v.to_string()),
    ]
}

fn fragment() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => prop::sample::select(vec![
            "{",
            "}",
            "\n}\n",
            "\n{\n",
            "//",
            "#",
            "/*",
            "\n/*\n",
            "\n*/\n",
            "\"",
            "\u{b}",
            "\r",
            "\t",
            "\u{2028}",
            "\u{0}",
            "\u{1b}[2K",
            "\u{feff}",
            "é",
            " ",
            "\n",
            "randfloat(0, 1)",
            "NULL",
            "Layered",
            "layer",
        ])
        .prop_map(String::from),
        1 => Just("x".repeat(1100)),
        3 => "[ -~\\t\\n\\r\\x0b\\x00-\\x1f\\u{80}-\\u{9f}\\u{2028}]{1,12}",
    ]
}

/// A block that names a hostile file, nests shaders deeply or asks for the extreme.
fn block() -> impl Strategy<Value = String> {
    let h = hostile();
    let chain = |n: usize, used: bool| {
        let mut text: String = (0..n).map(|i| format!("Layered C{i} {{\n layer C{} (1, 1, 1)\n}}\n", i + 1)).collect();
        text += &format!("Lambert C{n} {{\n color (0.5, 0.5, 0.5)\n}}\n");
        if used {
            text += "Sphere chained {\n O (0, 5, 0)\n R 4\n}\nNode {\n geometry chained\n shader C0\n}\n";
        }
        text
    };
    prop_oneof![
        prop::sample::select(h.meshes.clone()).prop_map(|file| format!(
            "Mesh fuzzed {{\n file \"{file}\"\n}}\nSphere s2 {{\n}}\nLambert l2 {{\n}}\nNode {{\n geometry fuzzed\n shader l2\n}}\n"
        )),
        prop::sample::select(h.images.clone()).prop_map(|file| format!(
            "BitmapTexture fuzzed {{\n file \"{file}\"\n}}\nLambert fuzzed {{\n texture fuzzed\n}}\n"
        )),
        prop::sample::select(h.folders.clone())
            .prop_map(|folder| format!("CubemapEnvironment {{\n folder \"{folder}\"\n}}\n")),
        (0usize..80, any::<bool>()).prop_map(move |(n, used)| chain(n, used)),
        Just("Layered self {\n layer self (1, 1, 1)\n}\n".to_string()),
        Just("GlobalSettings {\n maxTraceDepth 2147483647\n}\n".to_string()),
        Just("PointLight {\n pos (0, 1e18, 0)\n color (1e38, 1e38, 1e38)\n power 1e17\n}\n".to_string()),
        Just("Refl g {\n glossiness 0.01\n numSamples 2147483647\n}\n".to_string()),
        Just("Camera {\n position (1e18, -1e18, 1e18)\n fov 0.0001\n}\n".to_string()),
        Just("RectLight {\n}\nHeightfield h {\n}\nConst c {\n}\n".to_string()),
        hostile_number().prop_map(|v| format!("Sphere tiny {{\n R {v}\n}}\nNode {{\n geometry tiny\n shader glass\n}}\n")),
    ]
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), hostile_number()).prop_map(|(nth, with)| Mutation::Number { nth, with }),
        2 => (any::<usize>(), prop_oneof![hostile_number(), fragment()])
            .prop_map(|(nth, with)| Mutation::Token { nth, with }),
        1 => any::<usize>().prop_map(Mutation::DeleteLine),
        1 => any::<usize>().prop_map(Mutation::DuplicateLine),
        1 => (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        2 => (any::<usize>(), fragment()).prop_map(|(at, text)| Mutation::Insert { at, text }),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        2 => block().prop_map(Mutation::Append),
    ]
}

/// The byte ranges of the parts of `text` for which `part` holds, maximal runs of its characters.
fn runs(text: &str, part: impl Fn(char) -> bool) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices().chain([(text.len(), ' ')]) {
        match (part(c) && i < text.len(), start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                out.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// `at`, counted around `text`, moved back to a character boundary.
fn boundary(text: &str, at: usize) -> usize {
    let mut at = at % (text.len() + 1);
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

fn apply(text: &mut String, m: &Mutation) {
    let replace = |text: &mut String, spans: Vec<(usize, usize)>, nth: usize, with: &str| {
        if !spans.is_empty() {
            let (a, b) = spans[nth % spans.len()];
            text.replace_range(a..b, with);
        }
    };
    let mut lines: Vec<String> = text.split('\n').map(String::from).collect();
    let n = lines.len();
    match m {
        Mutation::Number { nth, with } => {
            let numbers = runs(text, |c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'));
            let numbers = numbers.into_iter().filter(|&(a, b)| text[a..b].contains(|c: char| c.is_ascii_digit()));
            replace(text, numbers.collect(), *nth, with);
            return;
        }
        Mutation::Token { nth, with } => return replace(text, runs(text, |c| !c.is_whitespace()), *nth, with),
        Mutation::Insert { at, text: t } => return text.insert_str(boundary(text, *at), t),
        Mutation::Truncate(at) => return text.truncate(boundary(text, *at)),
        Mutation::Append(block) => return text.push_str(block),
        Mutation::DeleteLine(i) => _ = lines.remove(i % n),
        Mutation::DuplicateLine(i) => lines.insert(i % n, lines[i % n].clone()),
        Mutation::SwapLines(a, b) => lines.swap(a % n, b % n),
    }
    *text = lines.join("\n");
}

/// Renders the scene `text` mutated by `mutations` (with `--skip-unsupported` if `skip`) and checks what
/// happened.
fn check(seed: &str, text: &str, mutations: &[Mutation], skip: bool) -> Result<(), TestCaseError> {
    static CASES: AtomicUsize = AtomicUsize::new(0);
    let mut text = text.to_string();
    for m in mutations {
        apply(&mut text, m);
    }
    let case = CASES.fetch_add(1, Ordering::Relaxed);
    let scene = dir().join(format!("{seed}-{case}.qdmg"));
    std::fs::write(&scene, &text).unwrap();
    let output = dir().join(format!("{seed}-{case}.png"));
    std::fs::write(&output, "an earlier picture").unwrap();
    let (scene_arg, output_arg) = (scene.to_str().unwrap(), output.to_str().unwrap());
    let mut args = vec![scene_arg, "--width", "32", "--height", "24", "--spp", "1", "-o", output_arg];
    if skip {
        args.push("--skip-unsupported");
    }
    let run = run_bounded("scene_file", &args);
    let what = format!("{} ({mutations:?})", scene.display());
    prop_assert!(!run.hung, "{what}: hung, killed after {:?}", run.elapsed);
    prop_assert!(matches!(run.code, Some(0 | 2)), "{what}: ended with {:?}: {}", run.code, run.stderr);
    let err = &run.stderr;
    prop_assert!(!err.contains("panicked"), "{what}: {err}");
    prop_assert!(
        !err.chars().any(|c| c != '\n' && (c.is_control() || matches!(c, '\u{2028}' | '\u{2029}'))),
        "{what}: {err:?}"
    );
    // Every line is a warning or note naming the file and its line, or the one error line.
    let warning = format!("{scene_arg}:");
    for line in err.lines() {
        let known = line.starts_with(&warning)
            || line.starts_with("scene_file: note: ")
            || line.starts_with("scene_file: error: ");
        prop_assert!(known, "{what}: a line of stderr that is neither a warning nor the error: {line:?}");
    }
    let errors: Vec<&str> = err.lines().filter(|l| l.starts_with("scene_file: error: ")).collect();
    if run.code == Some(2) {
        prop_assert_eq!(errors.len(), 1, "{}: {:?}", what, err);
        prop_assert!(err.trim_end().ends_with(errors[0]), "{what}: the error is not the last line: {err:?}");
        prop_assert!(errors[0].contains(scene_arg), "{what}: the error does not name the scene file: {err:?}");
        prop_assert_eq!(std::fs::read(&output).unwrap(), b"an earlier picture".to_vec(), "{}: output touched", what);
    } else {
        prop_assert!(errors.is_empty(), "{what}: {err}");
        let size = image::ImageReader::open(&output).and_then(|r| r.with_guessed_format()).map(|r| r.into_dimensions());
        prop_assert!(matches!(size, Ok(Ok((32, 24)))), "{what}: the picture is not a 32x24 image: {size:?}");
    }
    std::fs::remove_file(&scene).unwrap();
    std::fs::remove_file(&output).unwrap();
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn the_bundled_scene_mutated_renders_or_is_refused_in_one_line(
        mutations in prop::collection::vec(mutation(), 1..5),
        skip in any::<bool>(),
    ) {
        check("bundled", &bundled_scene(), &mutations, skip)?;
    }

    #[test]
    fn a_scene_of_every_element_mutated_renders_or_is_refused_in_one_line(
        mutations in prop::collection::vec(mutation(), 1..5),
        skip in any::<bool>(),
    ) {
        check("every-element", &every_element_scene(), &mutations, skip)?;
    }
}

#[test]
fn mutations_change_what_they_say() {
    let mut text = "Sphere s {\n R 2.5\n O (1, 2, 3)\n}\n".to_string();
    apply(&mut text, &Mutation::Number { nth: 1, with: "nan".into() });
    assert_eq!(text, "Sphere s {\n R 2.5\n O (nan, 2, 3)\n}\n");
    apply(&mut text, &Mutation::Token { nth: 1, with: "t".into() });
    assert_eq!(text, "Sphere t {\n R 2.5\n O (nan, 2, 3)\n}\n");
    apply(&mut text, &Mutation::SwapLines(1, 2));
    assert_eq!(text, "Sphere t {\n O (nan, 2, 3)\n R 2.5\n}\n");
    apply(&mut text, &Mutation::DeleteLine(1));
    apply(&mut text, &Mutation::DuplicateLine(1));
    assert_eq!(text, "Sphere t {\n R 2.5\n R 2.5\n}\n");
    apply(&mut text, &Mutation::Insert { at: 7, text: "\u{b}".into() });
    apply(&mut text, &Mutation::Truncate(10));
    assert_eq!(text, "Sphere \u{b}t ");
    assert!(Path::new(&hostile().images[1]).exists());
}
