//! The contact sheet: one HTML page of the class, to scan on a projector. At its top a summary table, one
//! row per student's example (built, ran, PSNR, warnings, settings unlike the reference's, exercises),
//! failures first, each row a link to the student's entry; below, each entry: the student's picture beside
//! the reference and the heat map of their difference, the numbers of the gradebook, and the first and the
//! last lines of what the program printed side by side (its defaults first, its summary line, end-of-run
//! report or panic last), and, for a submission that did not build or finish, why. Without a reference,
//! the picture and the report are there to be graded by eye. A huge output's cut ([`crate::kept_output`]) is
//! said above its last lines. The page needs no network: the pictures are
//! files beside it. Its colours keep a contrast of at least 4.5:1 (WCAG's AA for text) for every text and
//! link colour on every background of the page (its `STYLE`), and its text is large, for a projector.

use crate::class::{REFERENCE_PICTURE, Row, TimeLimit};
use crate::kept_output::is_cut_line;
use html_escape::{encode_double_quoted_attribute as attribute, encode_text as text};
use std::fmt::Write;
use std::path::Path;

/// How many lines of a program's output each end of it shows: its first (what it set out to do) and its last
/// (how it ended).
const SHOWN_LINES: usize = 12;

/// The page's style: dark text on light backgrounds, which a projector shows best, in large type.
const STYLE: &str = "\
body{font-family:sans-serif;font-size:20px;background:#ffffff;color:#1a1a1a;margin:1em}
a,a:visited{color:#0b4f9c}
section{background:#f3f3f3;margin:0 0 16px;padding:10px}
h2{margin:0 0 8px;font-size:26px}
.row{display:flex;flex-wrap:wrap;gap:10px}
figure{margin:0}
figure img{width:400px;display:block}
figcaption{font-size:18px}
.bad{color:#a30000}
.warn{color:#7a4b00}
.output{display:flex;flex-wrap:wrap;gap:12px}
pre{white-space:pre-wrap;font-size:16px;max-width:46em;margin:4px 0;background:#ffffff;padding:4px}
table{border-collapse:collapse}
th{background:#e2e2e2;text-align:left}
td,th{padding:3px 10px;vertical-align:top;border-bottom:1px solid #999999}
tr.failed td{background:#fde7e7}
tr.warned td{background:#fff3d6}
";

/// Writes the contact sheet of `rows`, whose renders had `time_limit`, to `index.html` in the folder `out`
/// (which holds the pictures and logs the rows name); `title` heads it, `has_reference` says whether there
/// is a reference to show.
pub fn write(rows: &[Row], time_limit: &TimeLimit, title: &str, has_reference: bool, out: &Path) -> Result<(), String> {
    let mut page = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>");
    let _ = write!(page, "{}</title>\n<style>\n{STYLE}</style></head><body>\n", text(title));
    let _ = writeln!(page, "<h1>{}</h1>", text(title));
    let _ = writeln!(page, "<p>Each render on one thread, stopped at {}.</p>", text(&time_limit.describe()));
    let order = worst_first(rows);
    page.push_str(&summary(&order));
    for row in &order {
        page.push_str(&section(row, has_reference, out));
    }
    page.push_str("</body></html>\n");
    let path = out.join("index.html");
    std::fs::write(&path, page).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// How a row went, worst first: it did not build, it did not finish, its exercises were not all passed, it
/// finished with warnings or settings unlike the reference's, or all went well.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Standing {
    NotBuilt,
    NotFinished,
    ExercisesFailed,
    Warned,
    Fine,
}

/// How `row` went.
fn standing(row: &Row) -> Standing {
    let exercises_failed = row.grades.as_ref().is_some_and(|g| g.failure.is_some() || g.passed() < g.verdicts.len());
    if row.built.as_ref().is_some_and(|b| b.program.is_err()) {
        Standing::NotBuilt
    } else if row.run.as_ref().is_some_and(|r| r.outcome.is_err()) {
        Standing::NotFinished
    } else if exercises_failed {
        Standing::ExercisesFailed
    } else if row.run.as_ref().is_some_and(|r| !r.warnings.is_empty())
        || !row.differences.is_empty()
        || matches!(row.score, Some(Err(_)))
    {
        Standing::Warned
    } else {
        Standing::Fine
    }
}

/// The rows worst first ([`Standing`]), then the furthest from the reference (the lowest PSNR), then by
/// student.
fn worst_first(rows: &[Row]) -> Vec<&Row> {
    let psnr = |row: &Row| match &row.score {
        Some(Ok(score)) => score.psnr,
        _ => f64::INFINITY,
    };
    let mut order: Vec<&Row> = rows.iter().collect();
    order.sort_by(|a, b| {
        standing(a).cmp(&standing(b)).then(psnr(a).total_cmp(&psnr(b))).then_with(|| a.student.cmp(&b.student))
    });
    order
}

/// The summary table: one row per row of the class, in the order given, each linking to its entry.
fn summary(rows: &[&Row]) -> String {
    let mut html = String::from(
        "<table class=\"summary\"><tr><th>student</th><th>built</th><th>ran</th><th>PSNR</th><th>warnings</th>\
         <th>settings unlike the reference's</th><th>exercises</th></tr>\n",
    );
    for row in rows {
        let class = match standing(row) {
            Standing::NotBuilt | Standing::NotFinished | Standing::ExercisesFailed => " class=\"failed\"",
            Standing::Warned => " class=\"warned\"",
            Standing::Fine => "",
        };
        let built = match row.built.as_ref().map(|b| &b.program) {
            None => "",
            Some(Ok(_)) => "yes",
            Some(Err(_)) => "no",
        };
        let ran = row.run.as_ref().map_or(String::new(), |r| r.outcome.clone().err().unwrap_or_else(|| "ok".into()));
        let psnr = match &row.score {
            Some(Ok(score)) => format!("{:.2} dB", score.psnr),
            Some(Err(_)) => "not compared".to_string(),
            None => String::new(),
        };
        let warnings = row.run.as_ref().map_or(0, |r| r.warnings.len());
        let exercises = row.grades.as_ref().map_or(String::new(), |g| match &g.failure {
            Some(_) => "not graded".to_string(),
            None => format!("{}/{}", g.passed(), g.verdicts.len()),
        });
        let _ = writeln!(
            html,
            "<tr{class}><td><a href=\"#{}\">{}</a></td><td>{built}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>\
             <td>{}</td></tr>",
            attribute(&row.id),
            text(&row.student),
            text(&ran),
            text(&psnr),
            if warnings == 0 { String::new() } else { warnings.to_string() },
            text(&row.differences.join(", ")),
            text(&exercises)
        );
    }
    html.push_str("</table>\n");
    html
}

/// One student's entry.
fn section(row: &Row, has_reference: bool, out: &Path) -> String {
    let mut html = String::new();
    let _ = writeln!(html, "<section id=\"{}\"><h2>{}</h2>", attribute(&row.id), text(&row.student));
    if let Some(Err(error)) = row.built.as_ref().map(|b| &b.program) {
        let _ = writeln!(html, "<p class=\"bad\">does not build: <code>{}</code></p>", text(error));
    }
    if let Some(run) = &row.run {
        let mut line = format!("ran {:.2} s", run.seconds);
        if let Some(cpu) = run.cpu_seconds {
            let _ = write!(line, " ({cpu:.2} s of processor time)");
        }
        if let Some(rays) = run.rays_millions {
            let _ = write!(line, ", {rays:.2} M rays");
        }
        match &row.score {
            Some(Ok(score)) => {
                let _ = write!(line, ", RMSE {:.3} levels, PSNR {:.2} dB", score.rmse, score.psnr);
            }
            Some(Err(why)) => {
                let _ = write!(line, ", not compared: {why}");
            }
            None => {}
        }
        let _ = writeln!(html, "<p>{}</p>", text(&line));
        if let Err(why) = &run.outcome {
            let _ = writeln!(html, "<p class=\"bad\">{}</p>", text(why));
        }
        for warning in &run.warnings {
            let _ = writeln!(html, "<p class=\"warn\">warning: {}</p>", text(warning));
        }
        if !row.differences.is_empty() {
            let _ = writeln!(
                html,
                "<p class=\"warn\">its defaults, unlike the reference's: {}</p>",
                text(&row.differences.join(", "))
            );
        }
    }
    if row.picture().is_some() || row.run.is_some() {
        html.push_str("<div class=\"row\">");
        let mut figure = |file: Option<String>, caption: &str| {
            if let Some(file) = file {
                let _ = write!(
                    html,
                    "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption>{1}</figcaption></figure>",
                    attribute(&file),
                    text(caption)
                );
            }
        };
        figure(row.picture(), "the student's picture");
        figure(has_reference.then(|| REFERENCE_PICTURE.to_string()), "the reference");
        figure(row.heat_map(), "the difference (black: equal)");
        html.push_str("</div>\n");
        let printed = std::fs::read_to_string(out.join(row.run_log())).unwrap_or_default();
        html.push_str(&printed_ends(&printed));
        let _ = writeln!(html, "<p><a href=\"{}\">the whole output</a></p>", attribute(&row.run_log()));
    }
    if let Some(grades) = &row.grades {
        match &grades.failure {
            Some(why) => {
                let _ = writeln!(html, "<p class=\"bad\">exercises not graded: {}</p>", text(why));
            }
            None => {
                let _ =
                    writeln!(html, "<p>exercises: {} of {} passed</p><table>", grades.passed(), grades.verdicts.len());
                for (name, verdict) in &grades.verdicts {
                    let _ = writeln!(html, "<tr><td><code>{}</code></td><td>{}</td></tr>", text(name), text(verdict));
                }
                html.push_str("</table>\n");
            }
        }
    }
    html.push_str("</section>\n");
    html
}

/// What a program printed, as the entry shows it: all of it when it is short, otherwise its first and its
/// last [`SHOWN_LINES`] lines side by side, with how many lines lie between.
fn printed_ends(printed: &str) -> String {
    let lines: Vec<&str> = printed.lines().collect();
    if lines.len() <= 2 * SHOWN_LINES {
        return format!("<pre>{}</pre>\n", text(&lines.join("\n")));
    }
    let between = &lines[SHOWN_LINES..lines.len() - SHOWN_LINES];
    let before = match between.iter().find(|line| is_cut_line(line)) {
        Some(cut) => format!("{} more lines before them, and a cut: {cut}", between.len() - 1),
        None => format!("{} more lines before them", between.len()),
    };
    format!(
        "<div class=\"output\"><div>its first lines<pre>{}</pre></div><div>its last lines ({})<pre>{}</pre></div>\
         </div>\n",
        text(&lines[..SHOWN_LINES].join("\n")),
        text(&before),
        text(&lines[lines.len() - SHOWN_LINES..].join("\n"))
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::class_package::Built;
    use crate::comparison::Score;
    use crate::exercise_grades::Grades;
    use crate::kept_output::KeptOutput;
    use crate::rendering::Run;
    use std::path::PathBuf;
    use std::time::Duration;

    /// A row of `student` that built (or not, with `error`) and ran as `outcome` says.
    fn row(student: &str, error: Option<&str>, outcome: Result<(), &str>, psnr: f64) -> Row {
        let id = format!("s_{student}");
        let built = Built { program: error.map_or(Ok(PathBuf::from("p")), |e| Err(e.to_string())), seconds: 1.0 };
        let run = error.is_none().then(|| Run {
            outcome: outcome.map_err(String::from),
            seconds: 0.5,
            cpu_seconds: Some(0.4),
            render_seconds: Some(0.3),
            rays_millions: Some(1.0),
            warnings: Vec::new(),
            defaults: Vec::new(),
        });
        let score = run.as_ref().filter(|r| r.outcome.is_ok()).map(|_| Ok(Score { rmse: 1.0, psnr }));
        Row {
            student: student.to_string(),
            source: Some(PathBuf::from(format!("{student}.rs"))),
            id,
            built: Some(built),
            run,
            score,
            differences: Vec::new(),
            grades: None,
        }
    }

    /// The contact sheet of a class in every standing, written into a new folder, and the folder.
    fn sheet() -> (String, tempfile::TempDir) {
        let mut warned = row("heidi", None, Ok(()), 99.0);
        warned.differences.push("--spp 20000 (the reference's 5)".into());
        let mut exercises = row("judy", None, Ok(()), 99.0);
        exercises.grades =
            Some(Grades { verdicts: vec![("refract".into(), "FAILED: wrong".into())], failure: None, seconds: 1.0 });
        let rows = [
            row("alice", None, Ok(()), 99.0),
            row("bob", None, Ok(()), 21.5),
            row("carol", Some("carol.rs:40:27: error[E0425]"), Ok(()), 0.0),
            row("dave", None, Err("panicked at dave.rs:34:13: the glass is not ready"), 0.0),
            warned,
            exercises,
        ];
        let dir = tempfile::tempdir().expect("a temporary folder");
        std::fs::create_dir(dir.path().join("logs")).expect("logs");
        // Bob's program wrote 5 MB of chatter before its summary line: its log keeps both ends.
        let mut chatter = KeptOutput::default();
        chatter.push(b"s_bob: defaults: --spp 5\n");
        for i in 0..200_000 {
            chatter.push(format!("chatter line {i}\n").as_bytes());
        }
        chatter.push(b"s_bob: 320x240, 5 spp, 0.3 s, 1 thread, 1.00 M rays -> a.png\n");
        std::fs::write(dir.path().join("logs/s_bob.run.txt"), chatter.text()).expect("a log");
        let limit = TimeLimit::from_reference(Duration::from_millis(600));
        write(&rows, &limit, "hw1", true, dir.path()).expect("written");
        (std::fs::read_to_string(dir.path().join("index.html")).expect("the sheet"), dir)
    }

    #[test]
    fn the_summary_comes_first_failures_first_each_row_a_link_to_its_entry() {
        let (page, _dir) = sheet();
        let table = page.find("<table class=\"summary\">").expect("a summary table");
        let first_entry = page.find("<section").expect("entries");
        assert!(table < first_entry, "the summary is not at the top");
        let linked: Vec<&str> =
            page[table..first_entry].split("<a href=\"#").skip(1).filter_map(|s| s.split('"').next()).collect();
        let entries: Vec<&str> = page.split("<section id=\"").skip(1).filter_map(|s| s.split('"').next()).collect();
        // Not built, not finished, exercises failed, warned, then the rest by PSNR (bob's 21.5 dB first).
        assert_eq!(linked, ["s_carol", "s_dave", "s_judy", "s_heidi", "s_bob", "s_alice"]);
        assert_eq!(entries, linked, "each summary row links to an entry, in the same order");
        assert!(page.contains("<tr class=\"failed\"><td><a href=\"#s_carol\">carol</a></td><td>no</td>"));
        assert!(page.contains("<td>--spp 20000 (the reference's 5)</td>"), "heidi's settings are not in the summary");
        assert!(page.contains("stopped at 6 s of processor time (10 x the reference's 0.60 s, at least 5 s)"));
    }

    #[test]
    fn a_huge_log_shows_its_first_and_last_lines_and_its_cut() {
        let (page, _dir) = sheet();
        let bob = page.split("<section id=\"s_bob\">").nth(1).expect("bob's entry");
        let bob = bob.split("</section>").next().expect("its end");
        assert!(bob.contains("its first lines<pre>s_bob: defaults: --spp 5\nchatter line 0\n"), "{bob}");
        let last = bob.split("its last lines").nth(1).expect("the last lines");
        let (caption, _) = last.split_once("<pre>").expect("a caption");
        assert!(
            caption.contains("a cut: [... ") && caption.contains(" cut here of "),
            "the cut is not said: {caption}"
        );
        assert!(last.contains("s_bob: 320x240, 5 spp, 0.3 s, 1 thread, 1.00 M rays -&gt; a.png</pre>"), "{last}");
    }

    #[test]
    fn every_text_and_link_colour_has_a_contrast_of_at_least_4_5_on_every_background() {
        let (page, _dir) = sheet();
        let style = page.split("<style>").nth(1).and_then(|s| s.split("</style>").next()).expect("a style");
        let (mut texts, mut backgrounds) = (Vec::new(), Vec::new());
        for declaration in style.split(['{', '}', ';']).filter_map(|d| d.split_once(':')) {
            match declaration {
                ("color", colour) => texts.push(colour.trim()),
                ("background" | "background-color", colour) => backgrounds.push(colour.trim()),
                _ => {}
            }
        }
        assert!(texts.len() >= 4 && backgrounds.len() >= 4, "{texts:?} on {backgrounds:?}");
        for text in &texts {
            for background in &backgrounds {
                let ratio = contrast(text, background);
                assert!(ratio >= 4.5, "{text} on {background}: {ratio:.2}:1");
            }
        }
        // The measure itself: black on white is 21:1, a colour on itself 1:1.
        assert!((contrast("#000000", "#ffffff") - 21.0).abs() < 1e-9 && contrast("#a30000", "#a30000") == 1.0);
    }

    /// WCAG 2's contrast ratio of two colours `#rrggbb`: (L1 + 0.05) / (L2 + 0.05) of their relative
    /// luminances, the lighter's first.
    fn contrast(a: &str, b: &str) -> f64 {
        let luminance = |colour: &str| {
            let hex = colour.strip_prefix('#').filter(|h| h.len() == 6).unwrap_or_else(|| panic!("{colour}"));
            let channel = |i: usize| {
                let c = f64::from(u8::from_str_radix(&hex[i..i + 2], 16).expect("hex")) / 255.0;
                if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
            };
            0.2126 * channel(0) + 0.7152 * channel(2) + 0.0722 * channel(4)
        };
        let (la, lb) = (luminance(a), luminance(b));
        (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
    }
}
