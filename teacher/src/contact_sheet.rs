//! The contact sheet: one HTML page of the class, each student's picture beside the reference and the
//! heat map of their difference, with the numbers of the gradebook, the end-of-run report the example
//! printed, and, for a submission that did not build or finish, why. Without a reference, the picture and
//! the report are there to be graded by eye. The page needs no network: the pictures are files beside it.

use crate::class::{REFERENCE_PICTURE, Row};
use html_escape::{encode_double_quoted_attribute as attribute, encode_text as text};
use std::fmt::Write;
use std::path::Path;

/// Writes the contact sheet of `rows` to `index.html` in the folder `out` (which holds the pictures and
/// logs the rows name); `title` heads it, `has_reference` says whether there is a reference to show.
pub fn write(rows: &[Row], title: &str, has_reference: bool, out: &Path) -> Result<(), String> {
    let mut page = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>");
    let _ = write!(page, "{}</title>\n<style>\n", text(title));
    page.push_str(
        "body{font-family:sans-serif;background:#1e1e1e;color:#ddd;margin:1em}\n\
         section{background:#2a2a2a;margin:0 0 12px;padding:8px}\nh2{margin:0 0 6px;font-size:18px}\n\
         .row{display:flex;flex-wrap:wrap;gap:8px}\nfigure{margin:0}\nfigure img{width:320px;display:block}\n\
         figcaption{font-size:12px}\n.bad{color:#f88}\n.warn{color:#fc6}\npre{white-space:pre-wrap;font-size:12px;\
         max-width:60em;margin:4px 0}\ntable{border-collapse:collapse;font-size:12px}\ntd{padding:1px 6px;\
         vertical-align:top}\n</style></head><body>\n",
    );
    let _ = writeln!(page, "<h1>{}</h1>", text(title));
    for row in rows {
        page.push_str(&section(row, has_reference, out));
    }
    page.push_str("</body></html>\n");
    let path = out.join("index.html");
    std::fs::write(&path, page).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// One student's section.
fn section(row: &Row, has_reference: bool, out: &Path) -> String {
    let mut html = String::new();
    let _ = writeln!(html, "<section id=\"{}\"><h2>{}</h2>", attribute(&row.id), text(&row.student));
    if let Some(Err(error)) = row.built.as_ref().map(|b| &b.program) {
        let _ = writeln!(html, "<p class=\"bad\">does not build: <code>{}</code></p>", text(error));
    }
    if let Some(run) = &row.run {
        let mut line = format!("ran {:.2} s", run.seconds);
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
        // What the example printed: its summary line and its end-of-run report, to grade by eye.
        let printed = std::fs::read_to_string(out.join(row.run_log())).unwrap_or_default();
        let shown: String = printed.lines().take(40).collect::<Vec<_>>().join("\n");
        let _ =
            writeln!(html, "<pre>{}</pre><a href=\"{}\">the whole output</a>", text(&shown), attribute(&row.run_log()));
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
