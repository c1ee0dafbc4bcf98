//! Every warning the README and docs/ quote is one the program prints: its words are the words of a string
//! in the library's source (`src/`), so a quote cannot drift from the message it shows when the message
//! changes, nor be written from memory.
//!
//! A quote is a code span (or a line of a code block) that begins with `warning: ` or `note: `, or holds
//! `: warning: ` or `: note: ` after the program's name. What a message fills in is written as a placeholder
//! in capitals (`NODE`) or shown as a number, and `...` leaves words out: the quote is cut at those, and each
//! piece left (its punctuation at either end aside) must stand in one string of the source, between two of
//! its `{}` holes. The values a message shows from one run (a node's name) belong outside the quote.

use crate::common::root;
use std::path::{Path, PathBuf};

/// The documents whose quotes are checked: the README and docs/.
fn documents() -> Vec<PathBuf> {
    let mut out = vec![root().join("README.md")];
    for entry in std::fs::read_dir(root().join("docs")).unwrap().flatten() {
        if entry.path().extension().is_some_and(|e| e == "md") {
            out.push(entry.path());
        }
    }
    out.sort();
    out
}

/// The Rust files under `dir`, folders included.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The string literals of Rust source `code`, as the program holds them: escapes read, a line continued by
/// a backslash joined without its line break and the next line's indent. Comments and character literals
/// are skipped, so that a quote in a doc comment or a `'"'` is not taken for a string.
fn literals(code: &str) -> Vec<String> {
    let chars: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '/' if chars.get(i + 1) == Some(&'/') => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            '/' if chars.get(i + 1) == Some(&'*') => {
                i += 2;
                while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                    i += 1;
                }
                i += 2;
            }
            // A character literal: 'x' or '\x' (a lifetime has no closing quote there).
            '\'' if chars.get(i + 2) == Some(&'\'') => i += 3,
            '\'' if chars.get(i + 1) == Some(&'\\') && chars.get(i + 3) == Some(&'\'') => i += 4,
            'r' if matches!(chars.get(i + 1), Some('"' | '#')) && (i == 0 || !chars[i - 1].is_alphanumeric()) => {
                let hashes = chars[i + 1..].iter().take_while(|&&c| c == '#').count();
                let start = i + 1 + hashes;
                if chars.get(start) != Some(&'"') {
                    i += 1;
                    continue;
                }
                let closing: Vec<char> = std::iter::once('"').chain(std::iter::repeat_n('#', hashes)).collect();
                let mut end = start + 1;
                while end < chars.len() && !chars[end..].starts_with(&closing) {
                    end += 1;
                }
                out.push(chars[start + 1..end].iter().collect());
                i = end + closing.len();
            }
            '"' => {
                let mut text = String::new();
                i += 1;
                while i < chars.len() && chars[i] != '"' {
                    if chars[i] == '\\' {
                        i += 1;
                        match chars.get(i) {
                            Some('\n') => {
                                while chars.get(i + 1).is_some_and(|c| c.is_whitespace()) {
                                    i += 1;
                                }
                            }
                            Some('n') => text.push('\n'),
                            Some('t') => text.push('\t'),
                            Some(&c) => text.push(c),
                            None => {}
                        }
                    } else {
                        text.push(chars[i]);
                    }
                    i += 1;
                }
                out.push(text);
                i += 1;
            }
            _ => i += 1,
        }
    }
    out
}

/// The runs of fixed text of a format string: its text between its `{...}` holes, `{{` and `}}` read as
/// braces.
fn fixed_runs(literal: &str) -> Vec<String> {
    let mut runs = vec![String::new()];
    let mut chars = literal.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '{' if chars.peek() == Some(&'{') => {
                chars.next();
                runs.last_mut().unwrap().push('{');
            }
            '}' if chars.peek() == Some(&'}') => {
                chars.next();
                runs.last_mut().unwrap().push('}');
            }
            '{' => {
                for c in chars.by_ref() {
                    if c == '}' {
                        break;
                    }
                }
                runs.push(String::new());
            }
            _ => runs.last_mut().unwrap().push(c),
        }
    }
    runs.into_iter().map(|r| r.split_whitespace().collect::<Vec<_>>().join(" ")).filter(|r| !r.is_empty()).collect()
}

/// The fixed text of every string in the library's source.
fn source_runs() -> Vec<String> {
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    files.iter().flat_map(|f| literals(&std::fs::read_to_string(f).unwrap())).flat_map(|l| fixed_runs(&l)).collect()
}

/// What follows `warning: ` or `note: ` in `text`, if it quotes one.
fn quoted_message(text: &str) -> Option<&str> {
    let text = text.trim();
    for kind in ["warning: ", "note: "] {
        if let Some(rest) = text.strip_prefix(kind) {
            return Some(rest);
        }
        if let Some(at) = text.find(&format!(": {kind}")) {
            return Some(&text[at + 2 + kind.len()..]);
        }
    }
    None
}

/// The warnings and notes `markdown` quotes, each with its line, its line breaks read as spaces.
fn quotes(markdown: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut prose = String::new();
    let mut prose_lines = Vec::new();
    let mut fenced = false;
    for (n, line) in markdown.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            out.extend(quoted_message(line).map(|q| (n + 1, q.to_string())));
        } else {
            prose.push_str(line);
            prose.push(' ');
            prose_lines.extend(std::iter::repeat_n(n + 1, line.len() + 1));
        }
    }
    // Code spans: the text between a backtick and the next one, across line breaks.
    let mut ticks = prose.match_indices('`').map(|(i, _)| i);
    while let (Some(open), Some(close)) = (ticks.next(), ticks.next()) {
        let span = prose[open + 1..close].split_whitespace().collect::<Vec<_>>().join(" ");
        out.extend(quoted_message(&span).map(|q| (prose_lines[open], q.to_string())));
    }
    out
}

/// The pieces of the quoted message `quote` that no string of the source holds: `quote` cut at `...`, at
/// placeholders in capitals and at numbers, each piece without its punctuation at either end.
fn unsourced(quote: &str, runs: &[String]) -> Vec<String> {
    let placeholder = |w: &str| {
        let w = w.trim_matches(|c: char| !c.is_alphanumeric());
        !w.is_empty()
            && (w.chars().all(|c| c.is_ascii_uppercase() || c == '_')
                || w.chars().all(|c| c.is_ascii_digit() || c == '.'))
    };
    let mut pieces = Vec::new();
    for part in quote.split("...") {
        let mut piece = Vec::new();
        for word in part.split_whitespace() {
            if placeholder(word) {
                pieces.push(piece.join(" "));
                piece.clear();
            } else {
                piece.push(word);
            }
        }
        pieces.push(piece.join(" "));
    }
    let edge = |c: char| c.is_whitespace() || ",;:.()%".contains(c);
    pieces
        .iter()
        .map(|p| p.trim_matches(edge).to_string())
        .filter(|p| p.chars().any(char::is_alphanumeric))
        .filter(|p| !runs.iter().any(|r| r.contains(p.as_str())))
        .collect()
}

#[test]
fn every_warning_the_docs_quote_is_one_the_program_prints() {
    let runs = source_runs();
    let mut wrong = Vec::new();
    let mut found = 0;
    for document in documents() {
        let name = document.strip_prefix(root()).unwrap().display().to_string();
        for (line, quote) in quotes(&std::fs::read_to_string(&document).unwrap()) {
            found += 1;
            for piece in unsourced(&quote, &runs) {
                wrong.push(format!("{name}:{line}: \"{piece}\" (in `{quote}`)"));
            }
        }
    }
    // The API page quotes three of the end-of-run report's lines: a check that finds none checks nothing.
    assert!(found >= 3, "only {found} quoted warnings found in the README and docs/");
    assert!(wrong.is_empty(), "quoted words that no string of src/ holds:\n{}", wrong.join("\n"));
}

#[test]
fn a_quote_the_program_never_prints_is_found() {
    let runs = source_runs();
    // The API page's quote of the self-hit line before it was corrected: the program's line begins "rays
    // started off the surface found it again".
    let old = "rays hit the surface they left ... (self-intersection ...): NODE";
    assert_eq!(unsourced(old, &runs), ["rays hit the surface they left"]);
    // Its pieces are the source's words, its placeholder and numbers left out.
    let right = "rays started off the surface found it again, ... (black; self-intersection): ...: NODE";
    assert!(unsourced(right, &runs).is_empty(), "{:?}", unsourced(right, &runs));
    // Words the quote adds to a message's string are found too.
    let added = "a geometry returned a normal that is not of unit length, or NaN (normalise it first)";
    assert_eq!(
        unsourced(added, &runs),
        ["a geometry returned a normal that is not of unit length, or NaN (normalise it first"]
    );
    let md = "A line (`warning: a\n  b`) and\n```\nhw1: warning: c 12 d\n```\n";
    assert_eq!(quotes(md), [(4, "c 12 d".to_string()), (1, "a b".to_string())]);
}
