//! The shape of the lesson (`src/lesson`): a layered house. Its files import one another (by every form a
//! path takes in code: `use`, `super::`, `self::`, `crate::lesson::` written inline, and a folder's
//! `mod.rs` naming its children's items by their module, `grid::Found`) only in the slides'
//! recursion (`raytrace` calls a shader, which calls `raytrace`, and the light loop): one circle of files
//! that import each other, of at most 9 files, with no geometry, texture, image, environment, photon-map,
//! camera, render-loop, observer or diagnostics file in it. And the lesson stays a size a student can read:
//! at most 7,575 lines of code (not blank, not a comment), counting the files outside `src/lesson` that it
//! imports (the image files, the OBJ loader, the atomic output), as a student reads them with it.
//!
//! Print the circle: `cargo test --release --test workbook house -- --nocapture`.

use crate::common::{root, rust_files};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The module path of a file under the folder `base` (`src/lesson`, or `src` for the whole crate): in the
/// lesson, `shader/mod.rs` is `["shader"]`, `shader/layered.rs` `["shader", "layered"]`.
fn module_of(file: &Path, base: &Path) -> Vec<String> {
    let relative = file.strip_prefix(base).unwrap().with_extension("");
    let mut parts: Vec<String> = relative.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The paths a `use` tree names (`a::{b, c::d}` is `a::b` and `a::c::d`), each as its segments.
fn paths_of(tree: &str) -> Vec<Vec<String>> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree);
        return vec![path.split("::").map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect()];
    };
    let prefix: Vec<String> =
        tree[..open].split("::").map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect();
    let inner = &tree[open + 1..tree.rfind('}').unwrap()];
    let (mut depth, mut start, mut out) = (0, 0, Vec::new());
    let mut branches = Vec::new();
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                branches.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    branches.push(&inner[start..]);
    for branch in branches.into_iter().filter(|b| !b.trim().is_empty()) {
        for path in paths_of(branch) {
            out.push(prefix.iter().cloned().chain(path).collect());
        }
    }
    out
}

/// The file a path names among `modules`, which are keyed by their path below the crate's module `base`
/// (`["lesson"]` for the lesson's files, `[]` for the whole crate's), for a file whose own module is `here`:
/// `crate::lesson::shader::Lambert` is `shader/mod.rs` (the longest prefix that is a module), `super::Aabb`
/// in `geometry/sphere.rs` is `geometry/mod.rs`, and a path that starts with a child module of `here`
/// (`progressive::Pass` or `use grid::Found` in `photon_map/mod.rs`) is that child's file. `None` for a path
/// outside `base` or naming its own `mod.rs`.
fn target<'a>(
    path: &[String],
    here: &[String],
    modules: &'a BTreeMap<Vec<String>, PathBuf>,
    base: &[&str],
) -> Option<&'a PathBuf> {
    let below_base = path.len() > base.len() && path[1..=base.len()].iter().zip(base).all(|(a, b)| a == b);
    let absolute: Vec<String> = match path.first().map(String::as_str) {
        Some("crate") if below_base => path[1 + base.len()..].to_vec(),
        Some("super") => {
            let supers = path.iter().take_while(|s| *s == "super").count();
            let base = &here[..here.len().saturating_sub(supers)];
            base.iter().chain(&path[supers..]).cloned().collect()
        }
        Some("self") => here.iter().chain(&path[1..]).cloned().collect(),
        Some(child) if modules.contains_key(&[here, &[child.to_string()]].concat()) => {
            here.iter().chain(path).cloned().collect()
        }
        _ => return None,
    };
    (1..=absolute.len()).rev().find_map(|k| modules.get(&absolute[..k]))
}

/// The paths a file's code names (comments are not read), each as its segments: those of its `use`
/// statements, over as many lines as they take, and those written inline ([`inline_paths`]). Re-exports
/// (`pub use`) only when `reexports` is true.
fn paths_in(text: &str, reexports: bool) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let mut statement: Option<(String, bool)> = None;
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("").trim();
        let reexport = code.starts_with("pub use ") || code.starts_with("pub(crate) use ");
        let code_use = code.strip_prefix("pub(crate) ").or_else(|| code.strip_prefix("pub ")).unwrap_or(code);
        if statement.is_none() && code_use.starts_with("use ") {
            statement = Some((String::new(), reexport));
        }
        if let Some((so_far, reexport)) = statement.as_mut() {
            so_far.push_str(code_use);
            if let Some(whole) = so_far.strip_suffix(';') {
                if reexports || !*reexport {
                    paths.extend(paths_of(whole.trim_start_matches("use ")));
                }
                statement = None;
            }
            continue;
        }
        paths.extend(inline_paths(code));
    }
    paths
}

/// For every file of the lesson, the files of the lesson it imports, by every form a path can take in its
/// code: `use crate::lesson::...`, `use super::...` and `use self::...` statements, and paths written inline
/// (`crate::lesson::render::MAX_SPP`, `super::Texture`). A folder's `mod.rs` that re-exports its children's
/// items (`pub use`) hands their names on without using them: not an import.
fn imports() -> BTreeMap<PathBuf, BTreeSet<PathBuf>> {
    let lesson = root().join("src/lesson");
    let files = rust_files(&lesson);
    let modules: BTreeMap<Vec<String>, PathBuf> =
        files.iter().map(|f| (module_of(f, &lesson), f.clone())).filter(|(m, _)| !m.is_empty()).collect();
    let mut graph = BTreeMap::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let here = module_of(file, &lesson);
        let paths = paths_in(&text, !file.ends_with("mod.rs"));
        let mut targets: BTreeSet<PathBuf> =
            paths.iter().filter_map(|path| target(path, &here, &modules, &["lesson"]).cloned()).collect();
        targets.remove(file);
        graph.insert(file.clone(), targets);
    }
    graph
}

/// The paths written inline in a line of code: every `a::b` that does not continue a path before it
/// (`crate::lesson::a::b`, `super::a`, `grid::Found`), each as its segments, up to the first character that
/// cannot continue a path. Which of them name a file of the lesson is [`target`]'s to say.
fn inline_paths(code: &str) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("::") {
        let start = rest[..at].rfind(|c: char| !(c.is_alphanumeric() || c == '_')).map_or(0, |i| i + 1);
        let before = rest[..start].chars().last();
        let tail = &rest[start..];
        let end = tail.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')).unwrap_or(tail.len());
        if start < at && before != Some(':') {
            paths.push(tail[..end].split("::").filter(|s| !s.is_empty()).map(str::to_string).collect());
        }
        rest = &tail[end.max(at - start + 2)..];
    }
    paths
}

/// The circles of files that import each other (the strongly connected components of the import graph,
/// Tarjan's algorithm), largest first.
fn circles(graph: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<Vec<PathBuf>> {
    struct Search<'a> {
        graph: &'a BTreeMap<PathBuf, BTreeSet<PathBuf>>,
        index: BTreeMap<&'a PathBuf, usize>,
        low: BTreeMap<&'a PathBuf, usize>,
        stack: Vec<&'a PathBuf>,
        circles: Vec<Vec<PathBuf>>,
    }
    impl<'a> Search<'a> {
        fn visit(&mut self, v: &'a PathBuf) {
            let n = self.index.len();
            self.index.insert(v, n);
            self.low.insert(v, n);
            self.stack.push(v);
            for w in &self.graph[v] {
                if !self.index.contains_key(w) {
                    self.visit(w);
                    self.low.insert(v, self.low[v].min(self.low[w]));
                } else if self.stack.contains(&w) {
                    self.low.insert(v, self.low[v].min(self.index[w]));
                }
            }
            if self.low[v] == self.index[v] {
                let at = self.stack.iter().rposition(|w| *w == v).unwrap();
                self.circles.push(self.stack.split_off(at).into_iter().cloned().collect());
            }
        }
    }
    let mut search =
        Search { graph, index: BTreeMap::new(), low: BTreeMap::new(), stack: Vec::new(), circles: Vec::new() };
    for v in graph.keys() {
        if !search.index.contains_key(v) {
            search.visit(v);
        }
    }
    let mut circles = search.circles;
    circles.sort_by_key(|c| std::cmp::Reverse(c.len()));
    circles
}

/// The files no circle may hold: the geometry, the textures and images, the environments, the photon map,
/// the camera, the render loop, the observer and the diagnostics sit below or above the slides' recursion.
const NEVER_IN_A_CIRCLE: &[&str] = &[
    "geometry/",
    "texture/",
    "bitmap.rs",
    "environment.rs",
    "photon_map/",
    "camera.rs",
    "render.rs",
    "render_settings.rs",
    "adaptive_aa.rs",
    "observer.rs",
    "diagnostics.rs",
    "problems.rs",
];

#[test]
fn the_only_circle_of_the_lessons_files_is_the_slides_recursion() {
    let graph = imports();
    assert!(graph.values().map(BTreeSet::len).sum::<usize>() > 80, "too few imports found: the parser is broken");
    let name = |f: &PathBuf| f.strip_prefix(root().join("src/lesson")).unwrap().display().to_string();
    let circles: Vec<Vec<String>> =
        circles(&graph).into_iter().filter(|c| c.len() > 1).map(|c| c.iter().map(name).collect()).collect();
    for circle in &circles {
        println!("a circle of {} files: {}", circle.len(), circle.join(", "));
    }
    assert!(circles.len() <= 1, "{} circles of files in src/lesson: {circles:?}", circles.len());
    let largest = circles.first().cloned().unwrap_or_default();
    assert!(largest.len() <= 9, "{} files of src/lesson import each other: {}", largest.len(), largest.join(", "));
    for file in &largest {
        assert!(
            !NEVER_IN_A_CIRCLE.iter().any(|kind| file.starts_with(kind)),
            "{file} is in the circle of the slides' recursion: {}",
            largest.join(", ")
        );
    }
}

/// A circle of files that import each other is found: the test above can fail.
#[test]
fn a_circle_of_imports_is_found() {
    let file = |name: &str| PathBuf::from(name);
    let graph = BTreeMap::from([
        (file("a"), BTreeSet::from([file("b")])),
        (file("b"), BTreeSet::from([file("c")])),
        (file("c"), BTreeSet::from([file("a"), file("d")])),
        (file("d"), BTreeSet::new()),
    ]);
    assert_eq!(circles(&graph)[0].len(), 3);
    assert_eq!(paths_of("crate::lesson::{a::B, c::{d, e as f}}").len(), 3);
    let inline = inline_paths("let x = crate::lesson::render::MAX_SPP + super::Texture::y(self::z) + grid::f();");
    let expected = [
        vec!["crate", "lesson", "render", "MAX_SPP"],
        vec!["super", "Texture", "y"],
        vec!["self", "z"],
        vec!["grid", "f"],
    ];
    assert_eq!(inline, expected);
    // A child module's path, in a folder's `mod.rs`, names the child's file.
    let modules = BTreeMap::from([
        (vec!["photon_map".to_string()], file("m")),
        (vec!["photon_map".to_string(), "grid".to_string()], file("g")),
    ]);
    let path = |p: &str| p.split("::").map(str::to_string).collect::<Vec<_>>();
    let target = |p: &str, here: &str| target(&path(p), &path(here), &modules, &["lesson"]);
    assert_eq!(target("grid::Found", "photon_map"), Some(&file("g")));
    assert_eq!(target("super::Found", "photon_map::grid"), Some(&file("m")));
    assert_eq!(target("crate::lesson::photon_map::grid::f", "camera"), Some(&file("g")));
    assert_eq!(target("std::f32", "photon_map"), None);
}

/// The files outside `src/lesson` that the lesson imports (`crate::files::obj`, `crate::app::parameter_ranges`),
/// and those that they import in turn, by every form a path takes in code: a student reads them with the
/// lesson, so their lines count as its.
fn imported_from_outside() -> BTreeSet<PathBuf> {
    let src = root().join("src");
    let lesson = src.join("lesson");
    // The library's modules (not the binaries' own files), keyed by their path in the crate.
    let modules: BTreeMap<Vec<String>, PathBuf> = rust_files(&src)
        .into_iter()
        .filter(|f| !f.ends_with("main.rs") && !f.starts_with(src.join("bin")))
        .map(|f| (module_of(&f, &src), f))
        .filter(|(m, _)| !m.is_empty() && m[0] != "lib")
        .collect();
    let mut outside = BTreeSet::new();
    let mut queue = rust_files(&lesson);
    while let Some(file) = queue.pop() {
        let here = module_of(&file, &src);
        for path in paths_in(&std::fs::read_to_string(&file).unwrap(), true) {
            if let Some(found) = target(&path, &here, &modules, &[]).filter(|f| !f.starts_with(&lesson))
                && outside.insert(found.clone())
            {
                queue.push(found.clone());
            }
        }
    }
    outside
}

/// Lines of code: not blank, not a comment.
fn lines_of_code(file: &Path) -> usize {
    let text = std::fs::read_to_string(file).unwrap();
    text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with("//")).count()
}

#[test]
fn the_lesson_is_at_most_7575_lines_of_code() {
    let own: usize = rust_files(&root().join("src/lesson")).iter().map(|f| lines_of_code(f)).sum();
    let outside = imported_from_outside();
    let imported: usize = outside.iter().map(|f| lines_of_code(f)).sum();
    let names: Vec<String> =
        outside.iter().map(|f| f.strip_prefix(root()).unwrap().to_string_lossy().replace('\\', "/")).collect();
    println!("src/lesson: {own} lines of code, and {imported} in the {} files it imports: {names:?}", names.len());
    let lines = own + imported;
    assert!(lines <= 7575, "the lesson has {lines} lines of code, more than 7,575");
}
