//! Every deviation from the slides that the lesson's comments name is accounted for: a comment of
//! `src/lesson` that says "Deviation" (its paragraph, or each item of its list) names a step beyond the slides
//! (`Step::Name` or the step's name, `adaptive-depth`) or a row of the ledger's section "What stays in both
//! readings" (`ledger: NAME`, docs/beyond-the-slides.md), and every row it names exists.

use crate::common::{root, rust_files};
use lecture6::lesson::beyond::Step;

/// The rows of the ledger's section "What stays in both readings": the first cell of each table row.
fn ledger_rows() -> Vec<String> {
    let ledger = std::fs::read_to_string(root().join("docs/beyond-the-slides.md")).unwrap();
    let section = ledger.split("## What stays in both readings").nth(1).expect("the ledger has the section");
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .map(str::to_string)
        .collect()
}

/// The comment paragraphs of `text` that speak of a deviation, with their first line: from a comment line
/// that says "Deviation" to the next line that is not a comment or is an empty one. When that block is a list
/// (an introduction ending in `:`, then items starting with `- `), each item is a paragraph of its own.
fn deviation_paragraphs(text: &str) -> Vec<(usize, String)> {
    fn comment(l: &str) -> Option<&str> {
        let l = l.trim_start();
        l.strip_prefix("//!").or_else(|| l.strip_prefix("///")).map(str::trim)
    }
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if !comment(line).is_some_and(|c| c.contains("Deviation")) {
            continue;
        }
        let block: Vec<&str> = lines[i..].iter().map_while(|l| comment(l)).take_while(|c| !c.is_empty()).collect();
        let mut items: Vec<(usize, String)> = Vec::new();
        for (k, c) in block.iter().enumerate() {
            match items.last_mut() {
                Some((_, item)) if !c.starts_with("- ") => {
                    item.push(' ');
                    item.push_str(c);
                }
                _ => items.push((i + k + 1, c.to_string())),
            }
        }
        found.extend(items.into_iter().filter(|(_, item)| !item.ends_with(':')));
    }
    found
}

/// Whether a paragraph names a step: `Step::Name` or the step's own name.
fn names_a_step(paragraph: &str) -> bool {
    Step::ALL
        .iter()
        .any(|s| paragraph.contains(&format!("Step::{s:?}")) || paragraph.contains(&format!("`{}`", s.name())))
}

/// The ledger rows a paragraph names (`ledger: NAME`).
fn ledger_names(paragraph: &str) -> Vec<String> {
    paragraph
        .split("ledger:")
        .skip(1)
        .filter_map(|rest| rest.trim_start().strip_prefix('`')?.split('`').next())
        .map(str::to_string)
        .collect()
}

#[test]
fn every_deviation_comment_names_a_step_or_a_ledger_row() {
    let rows = ledger_rows();
    assert!(rows.len() >= 10, "the ledger's section has {} rows: its table was not read", rows.len());
    let mut unaccounted = Vec::new();
    let mut checked = 0;
    for file in rust_files(&root().join("src/lesson")) {
        let text = std::fs::read_to_string(&file).unwrap();
        for (line, paragraph) in deviation_paragraphs(&text) {
            checked += 1;
            let names = ledger_names(&paragraph);
            let missing: Vec<&String> = names.iter().filter(|n| !rows.contains(n)).collect();
            let place = format!("{}:{line}", file.strip_prefix(root()).unwrap().display());
            if !missing.is_empty() {
                unaccounted.push(format!("{place}: names ledger rows that do not exist: {missing:?}"));
            } else if names.is_empty() && !names_a_step(&paragraph) {
                unaccounted.push(format!("{place}: names neither a step nor a ledger row: {paragraph}"));
            }
        }
    }
    assert!(checked >= 13, "only {checked} deviation comments found: the search is broken");
    assert!(unaccounted.is_empty(), "{}", unaccounted.join("\n"));
}

/// The check can fail: a deviation that names nothing, or a row the ledger lacks, is found.
#[test]
fn a_deviation_that_names_nothing_is_found() {
    let text = "//! Deviation from the slide: something else.\n//!\n//! Deviations:\n//! - one (ledger: `no-such-row`);\n//! - two (the step `mesh-bvh`).\n";
    let found = deviation_paragraphs(text);
    assert_eq!(found.len(), 3, "{found:?}");
    assert!(ledger_names(&found[0].1).is_empty() && !names_a_step(&found[0].1));
    assert_eq!(ledger_names(&found[1].1), ["no-such-row"]);
    assert!(names_a_step(&found[2].1));
}
