//! The gallery: renders every example of the workbook at its defaults and at each variant the "Try:"
//! paragraph of its doc comment names, and writes a contact sheet, `target/gallery/index.html`, with the
//! pictures, their options, times and ray counts. The page needs no network: open it in any browser; each
//! picture links to itself at full size.
//!
//!     cargo run --release --bin gallery                          # every example, full size
//!     cargo run --release --bin gallery -- --width 320 --height 240   # options added to every render
//!
//! A variant that needs a file of your own (`--texture my_photo.jpg`) cannot be rendered here; the page
//! says so, with the error, instead of a picture.

#[path = "../../tests/workbook/common/examples.rs"]
#[macro_use]
mod examples;

use lecture6::app::cli::{Cli, Example};
use lecture6::files::output::save_atomically;
use std::fmt::Write;
use std::path::Path;
use std::process::ExitCode;

/// One picture of the gallery, or why it could not be made.
struct Item {
    options: String,
    result: Result<Rendered, String>,
}

struct Rendered {
    file: String,
    size: (u32, u32),
    seconds: f64,
    rays: u64,
}

/// One example of the gallery: its title (the first line of its doc comment) and its pictures.
struct Entry {
    name: &'static str,
    title: String,
    items: Vec<Item>,
}

/// The options of each variant the doc comment's "Try:" paragraph names (each in backquotes): only what
/// `is_options` takes for the example's options; the paragraph's other quotes (a scene file's keyword, a
/// type) are prose.
fn try_variants(source: &str, is_options: impl Fn(&str) -> bool) -> Vec<String> {
    let doc: Vec<&str> = source.lines().map_while(|l| l.strip_prefix("//!")).map(str::trim).collect();
    let paragraph: Vec<&str> =
        doc.iter().skip_while(|l| !l.starts_with("Try:")).take_while(|l| !l.is_empty()).copied().collect();
    paragraph.join(" ").split('`').skip(1).step_by(2).filter(|quoted| is_options(quoted)).map(str::to_string).collect()
}

/// Whether `text` is a list of options of example `E` called `name`: it starts with one, and the example's
/// command line reads it.
fn is_options_of<E: Example>(name: &str, text: &str) -> bool {
    text.starts_with('-') && Cli::<E>::parse_args(name, text.split_whitespace()).is_ok()
}

/// The example's title: the first line of its doc comment, without the heading mark.
fn title(source: &str) -> String {
    source
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("//!"))
        .map_or("", |l| l.trim_start_matches([' ', '#']))
        .to_string()
}

/// Renders example `E` called `name` with `options` (and `extra`, given to every render) into `dir`.
fn render_item<E: Example>(name: &str, index: usize, options: &str, extra: &[String], dir: &Path) -> Item {
    let args: Vec<String> =
        options.split_whitespace().map(String::from).chain(extra.iter().cloned()).chain(["--quiet".into()]).collect();
    let result = Cli::<E>::parse_args(name, &args).map_err(|e| e.to_string().lines().next().unwrap_or("").to_string());
    let result = result.and_then(|cli| {
        let (frame, stats) = cli.render().map_err(|e| e.to_string())?;
        let file = format!("{name}-{index}.png");
        frame.save(&dir.join(&file)).map_err(|e| e.to_string())?;
        Ok(Rendered {
            file,
            size: (frame.width, frame.height),
            seconds: stats.elapsed.as_secs_f64(),
            rays: stats.counters.total(),
        })
    });
    match &result {
        Ok(r) => println!("{name} {options}: {:.2} s, {:.2} M rays -> {}", r.seconds, r.rays as f64 * 1e-6, r.file),
        Err(e) => println!("{name} {options}: not rendered: {e}"),
    }
    Item { options: if options.is_empty() { "(defaults)".to_string() } else { options.to_string() }, result }
}

/// Every variant of example `E`.
fn render_entry<E: Example>(name: &'static str, source: &str, extra: &[String], dir: &Path) -> Entry {
    let variants = std::iter::once(String::new()).chain(try_variants(source, |text| is_options_of::<E>(name, text)));
    let items = variants.enumerate().map(|(i, options)| render_item::<E>(name, i, &options, extra, dir)).collect();
    Entry { name, title: title(source), items }
}

macro_rules! render_all {
    ($($name:ident),*) => {
        |extra: &[String], dir: &Path| vec![$(
            render_entry::<examples::$name::Options>(
                stringify!($name),
                include_str!(concat!("../../examples/", stringify!($name), ".rs")),
                extra,
                dir,
            )
        ),*]
    };
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The contact sheet.
fn page(entries: &[Entry], extra: &[String]) -> String {
    let mut out = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>lecture6 gallery</title>\n<style>\n\
         body{font-family:sans-serif;background:#1e1e1e;color:#ddd;margin:1em}\nh2{margin:1em 0 .2em}\n\
         .title{color:#aaa;margin:0 0 .5em}\n.row{display:flex;flex-wrap:wrap;gap:10px}\n\
         figure{margin:0;width:320px;background:#2a2a2a;padding:6px}\nfigure img{width:320px;display:block}\n\
         figcaption{font-size:12px;margin-top:4px}\ncode{color:#fc6}\n.error{color:#f88;height:80px}\n</style></head><body>\n\
         <h1>lecture6: every example and its \"Try:\" variants</h1>\n",
    );
    let total: usize = entries.iter().map(|e| e.items.len()).sum();
    let _ = writeln!(
        out,
        "<p>{} examples, {total} renders; options added to every render: <code>{}</code></p>",
        entries.len(),
        html_escape(&extra.join(" "))
    );
    for entry in entries {
        let _ = writeln!(
            out,
            "<h2 id=\"{0}\">{0}</h2><p class=\"title\">{1}</p><div class=\"row\">",
            entry.name,
            html_escape(&entry.title)
        );
        for item in &entry.items {
            let options = html_escape(&item.options);
            match &item.result {
                Ok(r) => {
                    let _ = writeln!(
                        out,
                        "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1} {options}\"></a><figcaption><code>{options}</code><br>\
                         {2}x{3}, {4:.2} s, {5:.2} M rays</figcaption></figure>",
                        r.file,
                        entry.name,
                        r.size.0,
                        r.size.1,
                        r.seconds,
                        r.rays as f64 * 1e-6
                    );
                }
                Err(e) => {
                    let _ = writeln!(
                        out,
                        "<figure><div class=\"error\">not rendered: {}</div><figcaption><code>{options}</code></figcaption></figure>",
                        html_escape(e)
                    );
                }
            }
        }
        out.push_str("</div>\n");
    }
    out.push_str("</body></html>\n");
    out
}

fn main() -> ExitCode {
    let extra: Vec<String> = std::env::args().skip(1).collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    if let Err(e) = std::env::set_current_dir(root) {
        eprintln!("gallery: error: cannot enter {}: {e}", root.display());
        return ExitCode::from(2);
    }
    let dir = Path::new("target").join("gallery");
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("gallery: error: cannot create {}: {e}", dir.display());
        return ExitCode::from(2);
    }
    let entries = every_example!(render_all)(&extra, &dir);
    let index = dir.join("index.html");
    let html = page(&entries, &extra);
    match save_atomically(&index, |file| {
        std::io::Write::write_all(file, html.as_bytes()).map_err(image::ImageError::IoError)
    }) {
        Ok(()) => {
            println!("gallery -> {}", index.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("gallery: error: {e}");
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{examples, is_options_of, title, try_variants};

    #[test]
    fn the_try_paragraph_gives_one_variant_per_quoted_command() {
        let source = "//! # Glass (slides)\n//!\n//! Try: `--ior 1.33` (water), `--max-depth\n//! 2`.\n//!\n//! `--not-this`\nuse x;";
        assert_eq!(try_variants(source, |_| true), ["--ior 1.33", "--max-depth 2"]);
        assert_eq!(title(source), "Glass (slides)");
    }

    /// scene_file's "Try:" paragraph quotes the file's keywords (`ior`, `Node`, `Cube`, ...) in its prose:
    /// no variants of those, only of its one option.
    #[test]
    fn variants_come_only_from_the_examples_own_options() {
        let source = include_str!("../../examples/scene_file.rs");
        let variants = try_variants(source, |text| is_options_of::<examples::scene_file::Options>("scene_file", text));
        assert_eq!(variants, ["--skip-unsupported"]);
        // Every quoted option of fresnel's paragraph is one: none is lost.
        let source = include_str!("../../examples/fresnel.rs");
        let all = try_variants(source, |text| text.starts_with("--"));
        let kept = try_variants(source, |text| is_options_of::<examples::fresnel::Options>("fresnel", text));
        assert!(kept.len() >= 2 && kept == all, "{kept:?} of {all:?}");
        assert!(!is_options_of::<examples::fresnel::Options>("fresnel", "--no-such-option"));
    }
}
