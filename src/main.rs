//! `cargo run` with no example named: lists the examples (the workbook's and a student's own, read from
//! `examples/`) and says how to run one. The asset generator is a separate binary that runs only when asked
//! for by name (`cargo run --release --bin make-assets`).

use std::path::Path;

/// An example's title: the first line of its doc comment, without the `//! #` in front.
fn title(source: &str) -> &str {
    source.lines().next().and_then(|l| l.strip_prefix("//!")).map_or("", |l| l.trim_start_matches([' ', '#']))
}

fn main() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut examples: Vec<(String, String)> = std::fs::read_dir(&dir)
        .into_iter()
        .flatten()
        .filter_map(|entry| {
            let path = entry.ok()?.path();
            (path.extension()? == "rs").then_some(())?;
            let source = std::fs::read_to_string(&path).ok()?;
            Some((path.file_stem()?.to_string_lossy().into_owned(), title(&source).to_string()))
        })
        .collect();
    examples.sort();
    println!("The lecture-6 workbook: one example per slide topic. Run one with");
    println!();
    println!("    cargo run --release --example fresnel");
    println!();
    println!("(it writes out/fresnel.png; add `-- --help` for its options). The examples:");
    println!();
    let width = examples.iter().map(|(name, _)| name.len()).max().unwrap_or(0);
    for (name, title) in &examples {
        println!("    {name:width$}  {title}");
    }
    println!();
    println!("Start a homework by copying one: cp examples/fresnel.rs examples/hw1.rs (see README.md).");
}
