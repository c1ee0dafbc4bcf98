//! `--window`: without the viewer's program (`lecture6-viewer`, beside the examples) it says in one line how
//! to build it; with it but no display (none set, or one that cannot be reached) it says so in one line
//! (`no display: ...`). Either way it exits with code 2 and no panic. `cargo test` builds no viewer, so it
//! checks the first message; after `cargo build --release -p lecture6-viewer` the same tests check the second
//! (`.ci/run` runs both).

use crate::common;

use common::example_binary;
use std::process::Command;

/// What an example says when the viewer's program is not built.
const NO_VIEWER: &str = "fresnel: --window needs the viewer, built once with `cargo build";

/// Whether the viewer's program is built beside the examples the tests run.
fn viewer_built() -> bool {
    let examples = example_binary("fresnel");
    let profile_dir = examples.parent().and_then(|p| p.parent()).expect("target/<profile>");
    profile_dir.join(format!("lecture6-viewer{}", std::env::consts::EXE_SUFFIX)).is_file()
}

/// Runs `fresnel --window` with `DISPLAY` set to `display` (unset for `None`) and no Wayland display, and
/// checks that it fails in one line saying `expected`, or, in a build without the viewer, how to get it.
fn fails_in_one_line(display: Option<&str>, expected: &str) {
    let mut command = Command::new(example_binary("fresnel"));
    command.args(["--window", "--width", "32", "--height", "24"]).env_remove("WAYLAND_DISPLAY");
    match display {
        Some(display) => command.env("DISPLAY", display),
        None => command.env_remove("DISPLAY"),
    };
    let out = command.current_dir(common::root()).output().expect("run the example");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "one line: {stderr}");
    let expected = if viewer_built() { expected } else { NO_VIEWER };
    assert!(stderr.starts_with(expected), "expected '{expected}': {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn without_a_display_the_window_fails_in_one_clear_line() {
    fails_in_one_line(None, "fresnel: no display: DISPLAY is not set");
}

#[test]
fn a_display_that_cannot_be_reached_fails_in_one_clear_line() {
    // A display number no X server listens on.
    fails_in_one_line(Some(":4095"), "fresnel: no display: cannot open a window on DISPLAY=:4095: ");
}

/// Whether `program` runs here (found on the PATH).
fn installed(program: &str) -> bool {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path).any(|dir| dir.join(program).is_file())
}

/// An X server of its own, `Xvfb` on a display nobody uses, with one screen of `width` x `height`; stopped
/// when dropped.
struct VirtualScreen {
    server: std::process::Child,
    display: String,
}

impl VirtualScreen {
    fn start(width: u32, height: u32) -> VirtualScreen {
        let number = (90..200).find(|n| !std::path::Path::new(&format!("/tmp/.X{n}-lock")).exists()).unwrap();
        let display = format!(":{number}");
        let screen = format!("{width}x{height}x24");
        let server = Command::new("Xvfb")
            .args([display.as_str(), "-screen", "0", &screen, "-nolisten", "tcp"])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("start Xvfb");
        let socket = format!("/tmp/.X11-unix/X{number}");
        let start = std::time::Instant::now();
        while !std::path::Path::new(&socket).exists() {
            assert!(start.elapsed().as_secs() < 20, "Xvfb did not start on {display}");
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        VirtualScreen { server, display }
    }

    /// The whole screen as it is now (ImageMagick's `import`).
    fn screenshot(&self, path: &std::path::Path) -> image::RgbImage {
        let out = Command::new("import")
            .args(["-display", &self.display, "-window", "root", path.to_str().unwrap()])
            .output()
            .expect("run import");
        assert!(out.status.success(), "import: {}", String::from_utf8_lossy(&out.stderr));
        image::open(path).unwrap().to_rgb8()
    }
}

impl Drop for VirtualScreen {
    fn drop(&mut self) {
        let _ = self.server.kill();
        let _ = self.server.wait();
    }
}

/// The distance between the lines of text in the columns `xs` of `shot` (the median distance from the top
/// of one line's ink to the next's), and how many lines there are.
fn line_pitch(shot: &image::RgbImage, xs: std::ops::Range<u32>, ys: std::ops::Range<u32>) -> (u32, usize) {
    let inked = |y: u32| xs.clone().any(|x| shot.get_pixel(x, y).0.iter().all(|&c| c > 110));
    let tops: Vec<u32> = ys.filter(|&y| y > 0 && inked(y) && !inked(y - 1)).collect();
    let mut gaps: Vec<u32> = tops.windows(2).map(|w| w[1] - w[0]).collect();
    gaps.sort_unstable();
    (gaps.get(gaps.len() / 2).copied().unwrap_or(0), tops.len())
}

/// On a projector's 1600 x 1000 screen (Xvfb), `--window --ui-scale 1.5 --trace-pixel X,Y` opens on the
/// pixel's ray tree with its lines 1.5 times as far apart as at `--ui-scale 1`: the projector scale reaches the
/// tree panel; and the window takes the whole screen. The screenshots stay in `target/window-tests/`. Skipped, saying so, where `Xvfb`,
/// ImageMagick's `import` or the window's program is missing.
#[test]
fn the_interface_scale_reaches_the_ray_tree_at_1600_by_1000() {
    let missing: Vec<&str> = ["Xvfb", "import"].into_iter().filter(|p| !installed(p)).collect();
    if !missing.is_empty() || !viewer_built() {
        let viewer = if viewer_built() { "" } else { " (and cargo build --release -p lecture6-viewer)" };
        eprintln!("skipped: the screenshot test needs {missing:?}{viewer} (apt-get install xvfb imagemagick)");
        return;
    }
    let dir = common::root().join("target/window-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let mut pitches = Vec::new();
    for scale in ["1", "1.5"] {
        let screen = VirtualScreen::start(1600, 1000);
        let args = ["--window", "--width", "320", "--height", "240", "--spp", "1", "--trace-pixel", "160,120"];
        let mut example = Command::new(example_binary("fresnel"))
            .args(args)
            .args(["--ui-scale", scale])
            .env("DISPLAY", &screen.display)
            .env_remove("WAYLAND_DISPLAY")
            .current_dir(common::root())
            .spawn()
            .unwrap();
        // The tree shows once the scene is built and the pixel traced: wait for its lines.
        let shot_path = dir.join(format!("ui-scale-{scale}.png"));
        let start = std::time::Instant::now();
        // A busy machine may show the window before its layout settles (a frame at another scale, the tree
        // half drawn): the measure is taken once two screenshots in a row agree.
        let mut previous = None;
        let (pitch, lines, right) = loop {
            std::thread::sleep(std::time::Duration::from_millis(500));
            let shot = screen.screenshot(&shot_path);
            assert_eq!(shot.dimensions(), (1600, 1000));
            // The window's right and bottom edges; the tree is in a column of its own at the right where the
            // window has room for one, else under the options at the left, above the status band (the
            // window's layout, viewer/src/layout.rs): its lines are counted in both places.
            let right = (0..1600).rev().find(|&x| (0..1000).any(|y| shot.get_pixel(x, y).0 != [0, 0, 0])).unwrap_or(0);
            let bottom = (0..1000).rev().find(|&y| (0..1600).any(|x| shot.get_pixel(x, y).0 != [0, 0, 0])).unwrap_or(0);
            let beside = line_pitch(&shot, right.saturating_sub(380)..right.saturating_sub(20), 0..1000);
            let under = line_pitch(&shot, 8..right / 5, bottom / 2..bottom * 7 / 8);
            let (pitch, lines) = if under.1 > beside.1 { under } else { beside };
            let settled = previous == Some((pitch, lines, right));
            if (lines >= 12 && settled) || start.elapsed().as_secs() > 90 {
                break (pitch, lines, right);
            }
            previous = Some((pitch, lines, right));
        };
        let _ = example.kill();
        let _ = example.wait();
        // The window closes when its example has gone: wait for it before the screen goes.
        let start = std::time::Instant::now();
        let closing = dir.join("closing.png");
        while start.elapsed().as_secs() < 10 && screen.screenshot(&closing).pixels().any(|p| p.0 != [0, 0, 0]) {
            std::thread::sleep(std::time::Duration::from_millis(200));
        }
        assert!(lines >= 12, "--ui-scale {scale}: no ray tree on the screen ({lines} lines): {}", shot_path.display());
        pitches.push(pitch as f32);
        // At 1.5 the window of 1180 x 720 pixels would be 1770 x 1080: it takes the whole screen instead.
        let expected_right = if scale == "1" { 1179 } else { 1599 };
        assert_eq!(right, expected_right, "--ui-scale {scale}: the window's right edge");
    }
    let ratio = pitches[1] / pitches[0];
    assert!((1.3..=1.7).contains(&ratio), "the tree's lines {pitches:?} px apart: scaled by {ratio}, not 1.5");
}
