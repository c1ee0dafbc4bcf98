//! docs/a-rays-trip.md, the walk of a camera ray from `raytrace` to the bitmap_textures floor, is the code's:
//! every function it lists exists in the file it names; every one but the first is called by another one
//! it lists; and no function it lists calls a function of another file of `src/lesson` that is neither in
//! the walk nor in its list of calls off the path. In each reading the walk passes at most 8 files and 13
//! calls between files, a family's dispatch (the `match` over the course's types in `Shape`, `Material`,
//! `Tex`) counted as one call, as the course's virtual call is. The figures, and those that count each
//! dispatch's file as a stop of its own, are printed
//! (`cargo test --release --test workbook walk:: -- --nocapture`).

use crate::common::{root, rust_files};
use std::collections::{BTreeMap, BTreeSet};

/// Names that src/lesson defines and the standard library and glam use for their own methods (a slice's
/// `iter`, a vector's `dot` and `length`): a call of one is not taken for a call into another file.
const SHARED_NAMES: [&str; 3] = ["iter", "dot", "length"];

/// One row of the page's tables: a file of `src/lesson` and a function in it (`Type::name` or `name`).
#[derive(Clone, Debug)]
struct Row {
    file: String,
    function: String,
    /// The reading the row belongs to alone (`--slide` or `default`), or `None` for a row of both.
    only: Option<&'static str>,
}

impl Row {
    /// The function's own name, without its type.
    fn name(&self) -> &str {
        self.function.rsplit("::").next().unwrap()
    }
    /// The type whose `impl` holds the function, if the row names one.
    fn owner(&self) -> Option<&str> {
        self.function.rsplit_once("::").map(|(owner, _)| owner)
    }
}

/// The rows of the page's table under `heading`, whose file and function are the first two backquoted
/// cells.
fn table(page: &str, heading: &str) -> Vec<Row> {
    let start = page.find(heading).unwrap_or_else(|| panic!("the page has no section {heading:?}"));
    let section = &page[start + heading.len()..];
    let section = &section[..section.find("\n## ").unwrap_or(section.len())];
    let mut rows = Vec::new();
    for line in section.lines().filter(|l| l.starts_with('|')) {
        let quoted: Vec<&str> = line.split('`').skip(1).step_by(2).collect();
        if quoted.len() >= 2 && quoted[0].starts_with("src/lesson/") {
            let only = ["--slide", "default"].into_iter().find(|r| line.contains(&format!("| `{r}`")));
            rows.push(Row { file: quoted[0].to_string(), function: quoted[1].to_string(), only });
        }
    }
    assert!(!rows.is_empty(), "no rows under {heading:?}");
    rows
}

/// The name of the function a line defines, if it defines one.
fn defined(line: &str) -> Option<&str> {
    let at = line.find("fn ")?;
    let before = line[..at].trim();
    let qualifiers = ["", "pub", "pub(crate)", "pub(super)", "const", "unsafe", "pub const", "pub(crate) const"];
    if !qualifiers.contains(&before) {
        return None;
    }
    let rest = &line[at + 3..];
    let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_'))?;
    Some(&rest[..end]).filter(|name| !name.is_empty())
}

/// The body of the function `row` names: from its `fn` line to the brace that closes it (or its `;`, a
/// trait's method without a body). Where the file defines several functions of that name, the one inside
/// an `impl` or a trait of the row's type.
fn body(source: &str, row: &Row) -> Option<String> {
    let lines: Vec<&str> = source.lines().collect();
    let mut owner = String::new();
    for (i, line) in lines.iter().enumerate() {
        if line.starts_with("impl") || line.starts_with("pub trait") || line.starts_with("trait") {
            owner = line.to_string();
        }
        let in_owner =
            row.owner().is_none_or(|t| owner.split(|c: char| !(c.is_alphanumeric() || c == '_')).any(|word| word == t));
        if defined(line.trim_start()) != Some(row.name()) || !in_owner {
            continue;
        }
        let mut depth = 0i32;
        let mut opened = false;
        let mut text = String::new();
        for line in &lines[i..] {
            text.push_str(line);
            text.push('\n');
            for c in line.chars() {
                match c {
                    '{' => (depth, opened) = (depth + 1, true),
                    '}' => depth -= 1,
                    // A trait's method without a body.
                    ';' if !opened => return Some(text),
                    _ => {}
                }
            }
            if opened && depth == 0 {
                return Some(text);
            }
        }
    }
    None
}

/// The names a body calls: an identifier followed by `(` (or by a turbofish and then `(`), not a macro.
fn called(body: &str) -> BTreeSet<String> {
    let code: String = body.lines().map(|l| l.split("//").next().unwrap()).collect::<Vec<_>>().join("\n");
    let bytes = code.as_bytes();
    let mut names = BTreeSet::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i] as char;
        if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < bytes.len() && ((bytes[i] as char).is_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let mut j = i;
            if code[j..].starts_with("::<") {
                j = code[j..].find('>').map_or(j, |k| j + k + 1);
            }
            if code[j..].starts_with('(') {
                names.insert(code[start..i].to_string());
            }
        } else {
            i += 1;
        }
    }
    names
}

#[test]
fn the_walk_from_raytrace_to_the_floor_is_the_codes() {
    let page = std::fs::read_to_string(root().join("docs/a-rays-trip.md")).unwrap();
    let walk = table(&page, "## The walk\n");
    let off_path = table(&page, "## Calls off the path\n");
    let lesson = root().join("src/lesson");
    // Where each function of src/lesson is defined, by name.
    let mut files_of: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut sources = BTreeMap::new();
    for path in rust_files(&lesson) {
        let file = path.strip_prefix(root()).unwrap().to_string_lossy().replace('\\', "/");
        let source = std::fs::read_to_string(&path).unwrap();
        for name in source.lines().filter_map(|l| defined(l.trim_start())) {
            files_of.entry(name.to_string()).or_default().insert(file.clone());
        }
        sources.insert(file, source);
    }
    let listed: BTreeSet<&str> = walk.iter().chain(&off_path).map(Row::name).collect();
    let mut callers: BTreeMap<&str, usize> = BTreeMap::new();
    let mut strays = Vec::new();
    for row in walk.iter().chain(&off_path) {
        let source = sources.get(&row.file).unwrap_or_else(|| panic!("{row:?}: no such file"));
        let body = body(source, row).unwrap_or_else(|| panic!("{}: no function {} in it", row.file, row.function));
        if !walk.iter().any(|w| w.function == row.function && w.file == row.file) {
            continue;
        }
        for name in called(&body) {
            let Some(files) = files_of.get(&name).filter(|_| !SHARED_NAMES.contains(&name.as_str())) else {
                continue;
            };
            *callers.entry(listed.get(name.as_str()).copied().unwrap_or("")).or_default() += 1;
            if files.contains(&row.file) {
                continue;
            }
            if !listed.contains(name.as_str()) {
                let files = files.iter().cloned().collect::<Vec<_>>().join(", ");
                strays.push(format!("{} {} calls `{name}` ({files})", row.file, row.function));
            }
        }
    }
    assert!(strays.is_empty(), "calls the walk neither takes nor lists as off the path:\n{}", strays.join("\n"));
    for row in &walk[1..] {
        assert!(callers.contains_key(row.name()), "nothing the walk lists calls step {} {}", row.file, row.function);
    }
    // Each reading's walk: its files, and its calls between files (a step in another file than the one
    // before it), a family's dispatch counted as one call, as the course's virtual call is: the dispatch's
    // steps are left out, so the call goes from the step before them to the course's type after them.
    let is_dispatch = |row: &Row| {
        let source = &sources[&row.file];
        row.owner().is_some_and(|t| source.contains(&format!("pub enum {t} {{")) && source.contains("Own(Arc<dyn"))
    };
    for reading in ["default", "--slide"] {
        let steps: Vec<&Row> = walk.iter().filter(|r| r.only.is_none_or(|only| only == reading)).collect();
        let stops: Vec<&Row> = steps.iter().copied().filter(|r| !is_dispatch(r)).collect();
        let files: BTreeSet<&str> = stops.iter().map(|r| r.file.as_str()).collect();
        let hops = stops.windows(2).filter(|w| w[0].file != w[1].file).count();
        let dispatch_files: BTreeSet<&str> = steps.iter().filter(|r| is_dispatch(r)).map(|r| r.file.as_str()).collect();
        let every_file_hops = steps.windows(2).filter(|w| w[0].file != w[1].file).count();
        println!(
            "the walk, {reading}: {} files, {hops} calls between files, {} steps (with the {} dispatch files as \
             stops of their own: {} files, {every_file_hops} calls)",
            files.len(),
            steps.len(),
            dispatch_files.len(),
            files.len() + dispatch_files.len(),
        );
        assert!(files.len() <= 8 && hops <= 13, "{reading}: {} files and {hops} calls, over 8 and 13", files.len());
    }
}
