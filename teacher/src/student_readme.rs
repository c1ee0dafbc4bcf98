//! The students' copy's README and docs: the exercises first (the grader's command, the files to edit, how
//! to read a verdict), then the workbook's own README; the teacher's tools and pages left out.
//!
//! The workbook's README opens on `cargo run --release --example fresnel`, which in a copy whose exercises
//! are blanks stops at the first `todo!()`; and it and `docs/exercises.md` speak of the teacher's commands
//! (`teacher/`, the hand-out, `docs/class.md`), which the copy does not hold. The students' README opens on
//! the grader, and what speaks of the teacher's tools is taken out: the README's lines and list items that
//! name them, and the teacher's sections of `docs/exercises.md`.

/// What in a line of the README marks it as the teacher's: their tools' folder, their page, their commands.
const TEACHERS_MARKS: [&str; 4] = ["teacher/", "class.md", "-p teacher", "hand-out"];

/// The sections of `docs/exercises.md` that are the teacher's: handing out, adding an exercise, CI.
pub const TEACHERS_SECTIONS: [&str; 3] = ["## Handing it out", "## Adding an exercise", "## What CI runs"];

/// The students' README: the exercises `handed_out` first, then `workbook_readme` without what names the
/// teacher's tools.
pub fn readme(workbook_readme: &str, handed_out: &[String]) -> String {
    let files: Vec<String> = handed_out
        .iter()
        .map(|name| format!("- `{name}`: [exercises/src/{name}.rs](exercises/src/{name}.rs)"))
        .collect();
    let files =
        if files.is_empty() { "- none: every function is the workbook's own".to_string() } else { files.join("\n") };
    format!(
        "# Lecture 6: your exercises\n\
         \n\
         ```sh\n\
         cargo test --release -p exercises    # grade your exercises: one verdict each\n\
         ```\n\
         \n\
         Your exercises are the slides' functions, one file each; replace each file's `todo!()` with the function\n\
         its comment asks for, then grade again:\n\
         \n\
         {files}\n\
         \n\
         The first grading builds the renderer and the grader, once (about two minutes on two cores); the\n\
         renderer does not depend on your files, so after an edit only they are compiled again, and a verdict\n\
         takes seconds.\n\
         \n\
         The grader draws the workbook's pictures with your functions. To draw one yourself,\n\
         `cargo run --release -p exercises --example draw -- refract` renders the example `refract` with them\n\
         (`out/refract.png`, with any of the example's options after its name), and stops at the `todo!()` of one\n\
         not written yet. The workbook's own `cargo run --release --example refract` does not use them: this copy\n\
         does not hold the workbook's version of your exercises, so it stops at their `todo!()`.\n\
         \n\
         ## Reading a verdict\n\
         \n\
         The grader prints one line per exercise, in the order of the slides, then how many passed:\n\
         \n\
         - `passed`: every fact holds, and the picture of the example that uses it matches `expected/`.\n\
         - `not yet written`: its `todo!()` is still there.\n\
         - `FAILED`: the first fact that does not hold (what was checked, the value expected and yours), or how\n\
         \x20 far the picture is from `expected/` (yours and a heat map of the difference are under\n\
         \x20 `target/exercises/`). A picture uses several exercises: fix the failing facts first.\n\
         - `every fact holds; the picture ... also needs ...`: the picture needs other exercises not written yet,\n\
         \x20 all of them named; write those, and the picture is checked.\n\
         - `not handed out`: not one of yours; the workbook's own function is used. One of yours left out of\n\
         \x20 `HANDED_OUT` in `exercises/src/lib.rs` says that this copy does not hold the workbook's own: put it\n\
         \x20 back, and write it.\n\
         \n\
         More in [docs/exercises.md](docs/exercises.md): each exercise's slide, the facts checked, the time limit.\n\
         \n\
         {}",
        without_teachers_lines(workbook_readme)
    )
}

/// `markdown` without the lines that name the teacher's tools; a list item goes with its continuation
/// lines.
fn without_teachers_lines(markdown: &str) -> String {
    let mut kept = Vec::new();
    let mut dropping_item = false;
    for line in markdown.lines() {
        let continues = dropping_item && line.starts_with("  ") && !line.trim().is_empty();
        if continues {
            continue;
        }
        dropping_item = false;
        if TEACHERS_MARKS.iter().any(|mark| line.contains(mark)) {
            dropping_item = line.trim_start().starts_with("- ");
            continue;
        }
        kept.push(line);
    }
    kept.join("\n") + "\n"
}

/// `markdown` without the sections whose heading line is one of `headings` (each up to the next heading of
/// its level or above).
pub fn without_sections(markdown: &str, headings: &[&str]) -> String {
    let mut kept = Vec::new();
    let mut dropping: Option<usize> = None;
    for line in markdown.lines() {
        let level = line.chars().take_while(|&c| c == '#').count();
        let heading = level > 0 && line[level..].starts_with(' ');
        if heading && dropping.is_some_and(|dropped| level <= dropped) {
            dropping = None;
        }
        if heading && headings.contains(&line.trim_end()) {
            dropping = Some(level);
        }
        if dropping.is_none() {
            kept.push(line);
        }
    }
    kept.join("\n") + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_teachers_list_item_goes_with_its_continuation_and_the_rest_stays() {
        let readme = "# Title\n\n- [docs/a.md](docs/a.md): a\n  and more.\n- [docs/class.md](docs/class.md): the \
                      teacher's\n  tools.\n- [docs/b.md](docs/b.md): b\n\nteacher/   tools\nexercises/ blanks\n";
        assert_eq!(
            without_teachers_lines(readme),
            "# Title\n\n- [docs/a.md](docs/a.md): a\n  and more.\n- [docs/b.md](docs/b.md): b\n\nexercises/ blanks\n"
        );
    }

    #[test]
    fn a_section_goes_up_to_the_next_heading_of_its_level() {
        let doc = "# Doc\n\n## Keep\nA\n\n## Handing it out\nB\n### Deeper\nC\n## Also kept\nD\n";
        assert_eq!(without_sections(doc, &["## Handing it out"]), "# Doc\n\n## Keep\nA\n\n## Also kept\nD\n");
    }
}
