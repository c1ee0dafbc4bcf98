//! The instruments as commands of an example: `--trace-pixel`, `--view` and `--side-by-side`. Each takes the
//! example's scene and render settings exactly as the render itself would ([`Cli::prepare`]: a scene file's
//! own frame size and anti-aliasing included), hands them to its instrument, writes what it makes and returns
//! the lines to print.

use super::example::{Cli, Example, matches_within_f32};
use crate::files::output::{check_output, save_atomically};
use crate::instruments::debug_view::{DebugView, Legend, render_view_with};
use crate::instruments::ray_tree::{self, PixelPos, TraceFormat};
use crate::instruments::side_by_side::{Panel, a_b_difference};
use crate::lesson::error::{Error, Result};
use crate::lesson::input;
use crate::lesson::photon_map::radius_scale;
use crate::lesson::render::RenderStats;
use clap::ValueEnum;
use std::ffi::OsString;
use std::time::Instant;

/// `--trace-pixel`: renders only `pixel` of the example's picture, recording its rays, and describes the
/// tree of the camera ray `--trace-sample` of it (the pixel's colour is the mean of its samples' colours).
pub fn trace_pixel<E: Example>(name: &str, args: &Cli<E>, pixel: PixelPos) -> Result<String> {
    let (scene, settings) = args.prepare()?;
    let trace = ray_tree::trace(&scene, &settings, pixel)?;
    let mut text =
        ray_tree::describe(name, pixel, &trace, args.common.trace_sample as usize, args.common.trace_format)?;
    let starts = &trace.tree.photon_passes;
    if !starts.is_empty() && args.common.trace_format == TraceFormat::Text {
        let ends = starts.iter().skip(1).copied().chain([trace.tree.roots.len()]);
        let ranges: Vec<String> = starts.iter().zip(ends).map(|(a, b)| format!("{a}-{}", b.max(a + 1) - 1)).collect();
        let passes = starts.len() as u32;
        text.push_str(&format!(
            "{name}: progressive caustic: {passes} photon passes, each with a photon map of its own, the pixel \
             rendered in each; their camera rays are numbered {} (pass by pass; --trace-sample picks one). Pass \
             i >= 2 gathers every photon within r_i of the point, r_(i+1)^2 = r_i^2 (i + 2/3) / (i + 1), from r_1 = \
             the radius of pass 1's disc there: the last pass's r_{passes} = {:.4} r_1\n",
            ranges.join(", "),
            radius_scale(passes)
        ));
    }
    Ok(text)
}

/// `--view`: draws the example's debug view and writes it to `--output`, or `out/NAME-VIEW.png` (a heat view
/// with its legend in a strip below it); returns the lines to print (its size, where it went, and its scale).
pub fn write_view<E: Example>(name: &str, args: &Cli<E>, view: DebugView) -> Result<String> {
    let label = view.to_possible_value().map_or(String::new(), |v| v.get_name().to_string());
    if let Some(max) = args.common.legend_max
        && !view.is_heat()
    {
        return Err(Error::parameter(
            "--legend-max",
            max,
            format!("the view {label} has no legend: only rays, shadow-rays and depth-reached have one"),
        ));
    }
    let path = args.output_path_for(name, &format!("-{label}"));
    check_output(&path, Some(image::ImageFormat::Png))?;
    let (scene, settings) = args.prepare()?;
    // The scene's files have been read: the view may not replace one of them.
    input::check_not_an_input(&path, "the debug view")?;
    let start = Instant::now();
    let legend = Legend { max: args.common.legend_max, ui_scale: args.common.ui_scale };
    let picture = render_view_with(&scene, &settings, view, legend)?;
    save_atomically(&path, |file| picture.picture.write_to(file, image::ImageFormat::Png))?;
    let (width, height) = picture.picture.dimensions();
    let size = if height > settings.height {
        format!("{width}x{} and its legend below, {width}x{height} in all", settings.height)
    } else {
        format!("{width}x{height}")
    };
    Ok(format!(
        "{name}: view {label}, {size}, {:.3} s -> {}\n{name}: scale: {}\n",
        start.elapsed().as_secs_f64(),
        path.display(),
        picture.scale
    ))
}

/// What a render cost, as a side-by-side caption says it: its time, from the start of the photon pass when the
/// scene has a photon map (the slide's photons in all directions and k-d tree against the grid is most of the
/// difference between two readings of `photon_map`), and its rays.
pub fn render_cost(stats: &RenderStats) -> String {
    let rays = stats.counters.total() as f64 * 1e-6;
    let photon_pass = stats.photon_pass();
    if stats.photons.is_none() {
        return format!("{:.2} s, {rays:.2} M rays", stats.elapsed.as_secs_f64());
    }
    format!(
        "{:.2} s ({:.2} s photon pass, {:.2} s render), {rays:.2} M rays",
        (photon_pass + stats.elapsed).as_secs_f64(),
        photon_pass.as_secs_f64(),
        stats.elapsed.as_secs_f64()
    )
}

/// The example's options `args` (without the program name) with `--side-by-side` and its value taken out.
fn without_side_by_side(args: &[OsString]) -> Vec<OsString> {
    let mut out = Vec::new();
    let mut skip_value = false;
    for arg in args {
        if std::mem::take(&mut skip_value) {
            continue;
        }
        match arg.to_str() {
            Some("--side-by-side") => skip_value = true,
            Some(a) if a.starts_with("--side-by-side=") => {}
            _ => out.push(arg.clone()),
        }
    }
    out
}

/// The options `--side-by-side` refuses in B's OPTIONS: each writes elsewhere, or makes something else
/// than a render.
const NOT_IN_B: [&str; 7] =
    ["--output", "--compare", "--trace-pixel", "--view", "--side-by-side", "--window", "--help"];

/// `--side-by-side`: renders the example `name` with its options `args` (as given on the command line,
/// without the program name) and again with the options `alternative` (split at white space) added after
/// them, where they win; writes A | B | difference to `--output` or `out/NAME-side-by-side.png` and returns
/// the lines to print.
pub fn side_by_side<E: Example>(name: &str, args: &[OsString], alternative: &str) -> Result<String> {
    let base = without_side_by_side(args);
    let alt: Vec<OsString> = alternative.split_whitespace().map(OsString::from).collect();
    // B is one panel of the one picture: options that write elsewhere or replace the render have no place.
    for word in alternative.split_whitespace() {
        let option = word.split('=').next().unwrap_or(word);
        let short_output = option.starts_with("-o") && !option.starts_with("--");
        if short_output || NOT_IN_B.contains(&option) {
            return Err(Error::parameter(
                "--side-by-side",
                alternative,
                format!("`{option}` cannot be one of B's options: B is rendered into the one side-by-side picture"),
            ));
        }
    }
    let parse = |extra: &[OsString]| -> Result<Cli<E>> {
        let argv = std::iter::once(OsString::from(name)).chain(base.iter().cloned()).chain(extra.iter().cloned());
        let matches = matches_within_f32(Cli::<E>::command_named(name).args_override_self(true), argv)
            .and_then(|m| <Cli<E> as clap::FromArgMatches>::from_arg_matches(&m));
        matches.map_err(|e| Error::parameter("--side-by-side", alternative, e.to_string().lines().next().unwrap_or("")))
    };
    let (a, b) = (parse(&[])?, parse(&alt)?);
    let path = a.output_path_for(name, "-side-by-side");
    check_output(&path, Some(image::ImageFormat::Png))?;
    // B's frame size is known from its options and its scene before anything is traced: a B of another
    // size than A is refused before either is rendered.
    let mut b_settings = b.settings();
    b_settings.check()?;
    b.scene_with_common_options(&mut b_settings)?;
    let b_size = (b_settings.width, b_settings.height);
    let words = |args: &[OsString]| args.iter().map(|a| a.to_string_lossy()).collect::<Vec<_>>().join(" ");
    let base_text = if base.is_empty() { "(its defaults)".to_string() } else { words(&base) };
    let panel = |label: &str, args: &Cli<E>, options: &str| -> Result<Panel> {
        let (frame, stats, _) = args.render_checked(|_, settings| {
            if (settings.width, settings.height) != b_size {
                return Err(Error::parameter(
                    "--side-by-side",
                    alternative,
                    format!(
                        "changes the picture's size ({}x{} to {}x{}): A and B cannot be compared",
                        settings.width, settings.height, b_size.0, b_size.1
                    ),
                ));
            }
            // The inputs have been read: the picture may not replace one.
            input::check_not_an_input(&path, "the side-by-side picture")
        })?;
        Ok(Panel {
            // Each panel as its options would write it to a PNG: exposed, gamut and tone mapped.
            image: args.film().develop(frame, false).to_rgb8(),
            caption: format!("{label}: {name} {options}\n{}", render_cost(&stats)),
        })
    };
    let pa = panel("A", &a, &base_text)?;
    let pb = panel("B", &b, &format!("{base_text} + {alternative}"))?;
    let (picture, diff) = a_b_difference(pa, pb, a.common.ui_scale)?;
    save_atomically(&path, |file| picture.write_to(file, image::ImageFormat::Png))?;
    Ok(format!(
        "{name}: A | B | difference, {}x{} -> {}\n{name}: A - B: {diff}\n",
        picture.width(),
        picture.height(),
        path.display()
    ))
}
