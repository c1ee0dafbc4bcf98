//! The crate's four layers (src/lib.rs): the files a run reads and writes import nothing from the other three;
//! the lesson imports nothing from the instruments or the application and uses neither the command line's
//! crate (clap) nor the progress bar's (indicatif); the instruments import nothing from the application.
//! Read from the source tree, as `paths.rs` reads it.

use crate::common::{root, rust_files};

/// The code of a Rust file without its comments, each run of white space one space and none around `::`,
/// braces and commas, so that `crate :: app` and a path broken over lines read as one word. String literals stay (a path in a string is no import, but
/// none of the names looked for is in one).
fn code(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    let (mut in_string, mut escaped) = (false, false);
    while let Some(c) = chars.next() {
        if in_string {
            in_string = c != '"' || escaped;
            escaped = c == '\\' && !escaped;
        } else if c == '"' {
            in_string = true;
        } else if c == '\'' {
            // A character literal ('"', '\'', '\u{2028}') is kept whole, so that its quote opens no string;
            // a lifetime ('a) is left as it is.
            let ahead: Vec<char> = chars.clone().take(12).collect();
            let length = match ahead.first() {
                Some('\\') => ahead.iter().skip(2).position(|&c| c == '\'').map(|end| end + 3),
                Some(_) if ahead.get(1) == Some(&'\'') => Some(2),
                _ => None,
            };
            out.push(c);
            for _ in 0..length.unwrap_or(0) {
                out.extend(chars.next());
            }
            continue;
        } else if c == '/' && chars.peek() == Some(&'/') {
            while chars.next_if(|&c| c != '\n').is_some() {}
            continue;
        } else if c == '/' && chars.peek() == Some(&'*') {
            let mut previous = ' ';
            for c in chars.by_ref() {
                if previous == '*' && c == '/' {
                    break;
                }
                previous = c;
            }
            continue;
        }
        if in_string || !c.is_whitespace() {
            out.push(c);
        } else if !out.ends_with(' ') {
            out.push(' ');
        }
    }
    for glue in ["::", "{", "}", ","] {
        out = out.replace(&format!(" {glue}"), glue).replace(&format!("{glue} "), glue);
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Whether `code` (as [`code`] gives it) uses `word` as a whole identifier.
fn uses_word(code: &str, word: &str) -> bool {
    code.match_indices(word)
        .any(|(i, _)| !code[..i].ends_with(is_ident) && !code[i + word.len()..].starts_with(is_ident))
}

/// Whether `code` names the crate's top-level module `module` by a path: `crate::module`, `super::module` (from
/// any depth: no layer has a module of that name of its own), or inside a `use crate::{...}` group.
fn names_module(code: &str, module: &str) -> bool {
    let at = |prefix: &str| {
        code.match_indices(prefix).any(|(i, _)| {
            let rest = &code[i + prefix.len()..];
            rest.starts_with(module) && !rest[module.len()..].starts_with(is_ident) && !code[..i].ends_with(is_ident)
        })
    };
    let in_group = code.match_indices("crate::{").any(|(i, _)| {
        let group = &code[i..code[i..].find(';').map_or(code.len(), |end| i + end)];
        ['{', ','].iter().any(|open| {
            group.match_indices(*open).any(|(j, _)| {
                let rest = &group[j + 1..];
                rest.starts_with(module) && !rest[module.len()..].starts_with(is_ident)
            })
        })
    });
    at("crate::") || at("super::") || in_group
}

/// What the files of the layer under `src/<layer>` use that the layer may not: each as "file: name".
fn violations(layer: &str, words: &[&str], modules: &[&str]) -> Vec<String> {
    let src = root().join("src");
    let mut found = Vec::new();
    for file in rust_files(&src.join(layer)) {
        let name = file.strip_prefix(&src).unwrap().to_string_lossy().replace('\\', "/");
        let code = code(&std::fs::read_to_string(&file).unwrap());
        for word in words.iter().filter(|word| uses_word(&code, word)) {
            found.push(format!("{name}: {word}"));
        }
        for module in modules.iter().filter(|module| names_module(&code, module)) {
            found.push(format!("{name}: crate::{module}"));
        }
    }
    found
}

#[test]
fn the_lesson_uses_no_other_layer_and_no_command_line() {
    let found = violations("lesson", &["clap", "indicatif"], &["app", "instruments"]);
    assert!(found.is_empty(), "the lesson layer uses what lies above it:\n{found:#?}");
}

#[test]
fn the_files_use_no_other_layer() {
    let found = violations("files", &["clap", "indicatif"], &["lesson", "app", "instruments"]);
    assert!(found.is_empty(), "the files layer uses what lies above it:\n{found:#?}");
}

#[test]
fn the_instruments_use_no_application() {
    let found = violations("instruments", &[], &["app"]);
    assert!(found.is_empty(), "the instruments use the application:\n{found:#?}");
}

/// The check finds what it looks for, written any of the ways Rust allows.
#[test]
fn the_check_finds_an_import_however_it_is_written() {
    for import in [
        "use crate::app::cli::Cli;",
        "use crate :: app\n    ::cli;",
        "use super::super::app::cli;",
        "use crate::{lesson::color::Color, app::cli};",
        "fn f() { crate::app::cli::one_line(\"\"); }",
        "let quote = '\"'; use crate::app;",
    ] {
        assert!(names_module(&code(import), "app"), "{import}");
    }
    for not_an_import in ["// use crate::app::cli;", "use crate::apply::x;", "let app = 1;", "use crate::{apps};"] {
        assert!(!names_module(&code(not_an_import), "app"), "{not_an_import}");
    }
    assert!(uses_word(&code("#[derive(clap::ValueEnum)]"), "clap"));
    assert!(!uses_word(&code("/// clap\nfn clapping() {}"), "clap"));
}
