//! Taking the workbook's own version of a handed-out exercise out of its library, for the students' copy.
//!
//! Each slide function an exercise covers starts with the line `exercise!(hook(arguments));`
//! (`src/lesson/exercise_hooks.rs`), and what follows it in its block is the workbook's own version: the
//! answer. For an exercise handed out, that rest of the block becomes `todo!("<exercise>")`, so the function
//! is the student's alone (the grader and `draw`, built for the exercises, route it to
//! `exercises/src/<exercise>.rs` through `exercises/src/answers.rs`). The statement and its block are found in the file's syntax tree, not by
//! searching its text, and only that stretch of text is replaced: the rest of the file, its comments
//! included, is kept as it was. What only the workbook's own version used goes with it ([`prune`]): the
//! file's private functions no one calls any more (the bilinear filter's neighbour finding) and the imports
//! no one names.

use proc_macro2::LineColumn;
use std::collections::BTreeMap;
use syn::visit::Visit;

/// Which exercise each hook of the renderer belongs to, read from the exercises' `exercises/src/answers.rs`
/// (the text `answers`): the name of each method (the hook's), and the exercise whose switch
/// (`handed_out::REFRACT`) it reads, in lower case.
pub fn hooks(answers: &str) -> BTreeMap<String, String> {
    let mut found = BTreeMap::new();
    for method in answers.split("\n    fn ").skip(1) {
        let name: String = method.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        if let Some((_, rest)) = method.split_once("handed_out::") {
            let switch: String = rest.chars().take_while(|c| c.is_ascii_uppercase() || *c == '_').collect();
            if !switch.is_empty() {
                found.insert(name, switch.to_lowercase());
            }
        }
    }
    found
}

/// The Rust source `source` with the workbook's own version of every function routed to an exercise of
/// `handed_out` taken out (`hooks`: which exercise each hook belongs to), and the exercises it took out, in
/// the order met (each once). Fails when the source cannot be parsed.
pub fn blank(
    source: &str,
    hooks: &BTreeMap<String, String>,
    handed_out: &[String],
) -> syn::Result<(String, Vec<String>)> {
    let file = syn::parse_file(source)?;
    let mut finder = Finder { hooks, handed_out, found: Vec::new() };
    finder.visit_file(&file);
    let lines = LineStarts::new(source);
    let mut out = source.to_string();
    // From the last to the first, so that the offsets of the earlier ones still hold.
    let mut found = finder.found;
    found.sort_by_key(|f| std::cmp::Reverse((f.after.line, f.after.column)));
    let mut exercises = Vec::new();
    for Found { after, close, exercise } in found {
        let (start, end) = (lines.offset(source, after), lines.offset(source, close));
        let indent = line_indent(source, start);
        out.replace_range(start..end, &format!("\n{indent}todo!(\"{exercise}\")\n{}", line_indent(source, end)));
        exercises.push(exercise);
    }
    exercises.reverse();
    exercises.dedup();
    if !exercises.is_empty() {
        out = prune(&out)?;
    }
    Ok((out, exercises))
}

/// `source` without the private functions (free or in an `impl`) and the single-name imports whose name no
/// longer appears in it outside their own definition, one after another until none is left. The file must
/// not declare modules of its own (which could use its private items through `super::`); if it does, it is
/// returned as it is.
pub fn prune(source: &str) -> syn::Result<String> {
    let mut text = source.to_string();
    loop {
        let file = syn::parse_file(&text)?;
        if file.items.iter().any(|item| matches!(item, syn::Item::Mod(m) if m.content.is_none())) {
            return Ok(text);
        }
        let names = identifiers(&text)?;
        let mut finder = Unused { names: &names, found: None };
        finder.visit_file(&file);
        let Some((first, last)) = finder.found else { return Ok(text) };
        let lines = LineStarts::new(&text);
        let mut start = lines.0[first - 1];
        let mut end = lines.0.get(last).copied().unwrap_or(text.len());
        // One blank line between the neighbours, as there was one on each side; none at a block's ends.
        let (before, after) = (&text[..start], &text[end..]);
        if (before.ends_with("\n\n") || before.ends_with("{\n")) && after.starts_with('\n') {
            end += 1;
        } else if before.ends_with("\n\n") && after.trim_start_matches(' ').starts_with('}') {
            start -= 1;
        }
        text.replace_range(start..end, "");
    }
}

/// Where each identifier of `source` occurs (its name and line), doc comments and strings aside.
fn identifiers(source: &str) -> syn::Result<Vec<(String, usize)>> {
    fn walk(tokens: proc_macro2::TokenStream, into: &mut Vec<(String, usize)>) {
        for token in tokens {
            match token {
                proc_macro2::TokenTree::Ident(ident) => into.push((ident.to_string(), ident.span().start().line)),
                proc_macro2::TokenTree::Group(group) => walk(group.stream(), into),
                _ => {}
            }
        }
    }
    let tokens: proc_macro2::TokenStream = source.parse().map_err(syn::Error::from)?;
    let mut found = Vec::new();
    walk(tokens, &mut found);
    Ok(found)
}

/// Finds the first private function or single-name import whose name occurs nowhere outside its own lines:
/// its first and last line (its doc comment and attributes included).
struct Unused<'a> {
    names: &'a [(String, usize)],
    found: Option<(usize, usize)>,
}

impl Unused<'_> {
    /// Notes the item named `name` on the lines `first..=last` if its name occurs nowhere else.
    fn consider(&mut self, name: &str, attrs: &[syn::Attribute], first: usize, last: usize) {
        let first = attrs.iter().map(|a| a.pound_token.span.start().line).min().unwrap_or(first).min(first);
        let used = self.names.iter().any(|(n, line)| n == name && !(first..=last).contains(line));
        if self.found.is_none() && !used {
            self.found = Some((first, last));
        }
    }
}

impl<'ast> Visit<'ast> for Unused<'_> {
    fn visit_item_fn(&mut self, item: &'ast syn::ItemFn) {
        if matches!(item.vis, syn::Visibility::Inherited) && item.sig.ident != "main" {
            let (first, last) = (item.sig.fn_token.span.start().line, item.block.brace_token.span.close().end().line);
            self.consider(&item.sig.ident.to_string(), &item.attrs, first, last);
        }
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        if matches!(item.vis, syn::Visibility::Inherited) {
            let (first, last) = (item.sig.fn_token.span.start().line, item.block.brace_token.span.close().end().line);
            self.consider(&item.sig.ident.to_string(), &item.attrs, first, last);
        }
    }

    fn visit_item_impl(&mut self, item: &'ast syn::ItemImpl) {
        // A trait's methods are called through the trait, whatever their visibility.
        if item.trait_.is_none() {
            syn::visit::visit_item_impl(self, item);
        }
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        let mut tree = &item.tree;
        while let syn::UseTree::Path(path) = tree {
            tree = &path.tree;
        }
        if let syn::UseTree::Name(name) = tree {
            let line = item.use_token.span.start().line;
            self.consider(&name.ident.to_string(), &item.attrs, line, item.semi_token.span.end().line);
        }
    }
}

/// A statement `exercise!(hook(...));` whose rest of block is to go.
struct Found {
    /// Where the statement ends.
    after: LineColumn,
    /// Where its block's closing brace is.
    close: LineColumn,
    /// The exercise its hook belongs to.
    exercise: String,
}

/// Finds the statements `exercise!(hook(...));` of the exercises handed out, in every block of a file.
struct Finder<'a> {
    hooks: &'a BTreeMap<String, String>,
    handed_out: &'a [String],
    found: Vec<Found>,
}

impl<'ast> Visit<'ast> for Finder<'_> {
    fn visit_block(&mut self, block: &'ast syn::Block) {
        for stmt in &block.stmts {
            let syn::Stmt::Macro(statement) = stmt else { continue };
            if !statement.mac.path.is_ident("exercise") {
                continue;
            }
            let Some(proc_macro2::TokenTree::Ident(hook)) = statement.mac.tokens.clone().into_iter().next() else {
                continue;
            };
            let Some(exercise) = self.hooks.get(&hook.to_string()) else { continue };
            if !self.handed_out.contains(exercise) {
                continue;
            }
            let after = match &statement.semi_token {
                Some(semi) => semi.span.end(),
                None => statement.mac.delimiter.span().close().end(),
            };
            self.found.push(Found { after, close: block.brace_token.span.close().start(), exercise: exercise.clone() });
        }
        syn::visit::visit_block(self, block);
    }
}

/// The byte offset of each line's start, to turn the parser's lines and columns (in characters) into
/// offsets.
struct LineStarts(Vec<usize>);

impl LineStarts {
    fn new(source: &str) -> LineStarts {
        LineStarts(std::iter::once(0).chain(source.match_indices('\n').map(|(i, _)| i + 1)).collect())
    }

    /// The byte offset of `at` (line from 1, column in characters from 0) in `source`.
    fn offset(&self, source: &str, at: LineColumn) -> usize {
        let start = self.0[at.line - 1];
        source[start..].char_indices().nth(at.column).map_or(source.len(), |(i, _)| start + i)
    }
}

/// The white space that begins the line holding the byte offset `at`.
fn line_indent(source: &str, at: usize) -> &str {
    let start = source[..at].rfind('\n').map_or(0, |i| i + 1);
    let line = &source[start..];
    &line[..line.len() - line.trim_start_matches([' ', '\t']).len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    const HOOKS: &str = "//! The answers.\n\nimpl Answers for Students {\n    /// [`refract`].\n    \
        fn refract(&self, i: Vector) -> Option<Vector> {\n        static HOOK: Hook = Hook::new();\n        \
        answer(&HOOK, handed_out::REFRACT, || crate::refract::refract(i))\n    }\n\n    /// Schlick.\n    \
        fn fresnel(&self, i: Vector) -> Option<f32> {\n        answer(&HOOK, handed_out::FRESNEL_SCHLICK, || 0.0)\n    \
        }\n}\n";

    #[test]
    fn each_hook_belongs_to_the_exercise_whose_switch_it_reads() {
        let hooks = hooks(HOOKS);
        assert_eq!(hooks.get("refract").map(String::as_str), Some("refract"));
        assert_eq!(hooks.get("fresnel").map(String::as_str), Some("fresnel_schlick"));
        assert_eq!(hooks.len(), 2);
    }

    #[test]
    fn the_rest_of_the_block_after_the_exercise_line_goes_and_everything_else_stays() {
        let source = "/// Refraction { with a brace in a comment.\npub fn refract(i: Vector) -> Option<Vector> {\n    \
            exercise!(refract(i));\n    // The slide's formula.\n    let k = \"}\";\n    Some(i * 2.0)\n}\n\n\
            pub fn fresnel(i: Vector) -> f32 {\n    exercise!(fresnel(i));\n    0.04\n}\n\n\
            pub fn sample(f: Filter) -> f32 {\n    match f {\n        Filter::Near => 1.0,\n        Filter::Bilinear => {\n            \
            exercise!(refract(x));\n            2.0\n        }\n    }\n}\n";
        let handed_out = ["refract".to_string()];
        let (blanked, exercises) = blank(source, &hooks(HOOKS), &handed_out).expect("it parses");
        assert_eq!(exercises, ["refract"]);
        assert_eq!(
            blanked,
            "/// Refraction { with a brace in a comment.\npub fn refract(i: Vector) -> Option<Vector> {\n    \
            exercise!(refract(i));\n    todo!(\"refract\")\n}\n\n\
            pub fn fresnel(i: Vector) -> f32 {\n    exercise!(fresnel(i));\n    0.04\n}\n\n\
            pub fn sample(f: Filter) -> f32 {\n    match f {\n        Filter::Near => 1.0,\n        Filter::Bilinear => {\n            \
            exercise!(refract(x));\n            todo!(\"refract\")\n        }\n    }\n}\n"
        );
        let (untouched, none) = blank(source, &hooks(HOOKS), &[]).expect("it parses");
        assert_eq!((untouched.as_str(), none.len()), (source, 0));
    }

    #[test]
    fn what_only_the_workbooks_own_version_used_goes_with_it() {
        let source = "use std::f32::consts::FRAC_PI_4;\nuse std::f32::consts::PI;\n\n\
            pub fn disc(u: f32) -> f32 {\n    exercise!(refract(u));\n    helper(u) * FRAC_PI_4\n}\n\n\
            /// Only the answer calls it.\n#[inline]\nfn helper(u: f32) -> f32 {\n    deeper(u)\n}\n\n\
            fn deeper(u: f32) -> f32 {\n    u\n}\n\n\
            /// Still called: [`helper`] is only named in a comment.\nfn kept() -> f32 {\n    PI\n}\n\n\
            pub fn other() -> f32 {\n    kept()\n}\n";
        let (blanked, _) = blank(source, &hooks(HOOKS), &["refract".to_string()]).expect("it parses");
        assert_eq!(
            blanked,
            "use std::f32::consts::PI;\n\n\
            pub fn disc(u: f32) -> f32 {\n    exercise!(refract(u));\n    todo!(\"refract\")\n}\n\n\
            /// Still called: [`helper`] is only named in a comment.\nfn kept() -> f32 {\n    PI\n}\n\n\
            pub fn other() -> f32 {\n    kept()\n}\n"
        );
    }
}
