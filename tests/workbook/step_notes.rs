//! The note after a render for a step given with `--step`, `--no-step` or `--exhaustive` that changed nothing
//! in it: the note never says so of a step that changed the picture, and it says so where the render never
//! came where the step acts (the student's `--slide --step adaptive-depth` on a Layered scene, a scene without
//! a mesh).

use crate::common::hostile::scratch;
use crate::common::run_example;
use lecture6::lesson::beyond::Step;

/// The examples the notes are checked on: a Layered scene, glossy mirrors, a texture, a glass.
const EXAMPLES: [&str; 4] = ["layered", "glossy", "bitmap_textures", "fresnel"];

/// Renders `example` at 40x30 with `args` into a file of its own; returns the picture's bytes and what the
/// run printed on stderr.
fn render(example: &str, args: &[&str], file: &str) -> (Vec<u8>, String) {
    let output = scratch("step-notes").join(format!("{example}-{file}.png"));
    let size = ["--width", "40", "--height", "30", "-o", output.to_str().unwrap()];
    let out = run_example(example, &[&size[..], args].concat());
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{example} {args:?}: {err}");
    (std::fs::read(&output).unwrap(), err)
}

/// For each step of each example, taken alone on top of `base` (`--slide`) or left out of it (the default):
/// where the run notes that `option step` changed nothing, its picture is byte for byte `base`'s. Returns
/// the notes, each with its example.
fn each_step_alone(base: &[&str], option: &str) -> Vec<(String, String)> {
    let mut notes = Vec::new();
    for example in EXAMPLES {
        let (plain, _) = render(example, base, &format!("base{}", base.len()));
        for step in Step::ALL {
            let args = [base, &[option, step.name()][..]].concat();
            let (picture, err) = render(example, &args, &format!("{option}-{}", step.name()));
            let given = format!("{option} {}", step.name());
            let noted = err.lines().find(|line| line.contains(&format!("note: {given} changed nothing")));
            if let Some(note) = noted {
                assert!(
                    picture == plain,
                    "{example}: {given} was noted as changing nothing, but it changed the picture: {note}"
                );
                notes.push((example.to_string(), note.to_string()));
            }
        }
    }
    notes
}

#[test]
fn a_step_noted_as_changing_nothing_under_the_slides_changes_nothing() {
    let notes = each_step_alone(&["--slide"], "--step");
    let noted = |example: &str, what: &str| notes.iter().any(|(e, note)| e == example && note.contains(what));
    // The student's case: adaptive depth on a Layered scene prunes nothing without layer pruning.
    assert!(
        noted("layered", "--step adaptive-depth changed nothing in this render: no ray's weight fell"),
        "{notes:?}"
    );
    assert!(noted("layered", "only with the step layer-pruning"), "{notes:?}");
    assert!(noted("glossy", "--step mesh-bvh changed nothing in this render: the scene has no mesh"), "{notes:?}");
    // A step that acts is not noted: the glossy mirrors draw their disc points with their own sampler.
    assert!(!noted("glossy", "--step disc-samples"), "{notes:?}");
}

#[test]
fn a_step_noted_as_changing_nothing_left_out_of_the_default_changes_nothing() {
    let notes = each_step_alone(&[], "--no-step");
    let noted = |example: &str, what: &str| notes.iter().any(|(e, note)| e == example && note.contains(what));
    assert!(noted("bitmap_textures", "--no-step photon-grid changed nothing in this render"), "{notes:?}");
    assert!(!noted("bitmap_textures", "--no-step texel-filter"), "{notes:?}");
}

#[test]
fn a_step_added_to_the_default_is_noted() {
    let (_, err) = render("layered", &["--step", "layer-pruning", "--exhaustive"], "default-step");
    assert!(err.contains("note: --step layer-pruning changed nothing: the default reading takes every step"), "{err}");
    // --exhaustive is --no-step adaptive-depth, and on this scene it does change the picture.
    assert!(!err.contains("--exhaustive changed nothing"), "{err}");
}
