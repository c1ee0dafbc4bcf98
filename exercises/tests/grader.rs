//! The grader's own tests (with the reference solutions: `--features solutions`): every solution holds its
//! facts; a blank is named and the others still grade; a wrong answer fails with a message that says what
//! was expected, of what, and what came out; and every fact check can fail, on a plausible mistake.

use exercise_grader::grading::{self, Exercise, Verdict, grade};
use exercise_grader::hooks::{Hook, answer, drawing_and_listing_hooks, drawing_with_the_workbooks_own};
use exercise_grader::{facts, report};
use exercises::grading::workbook;
use exercises::{Face, Vector};
use glam::Affine3A;
use lecture6::app::limits::Limits;
use lecture6::lesson::frame::Frame;
use std::process::{Command, Stdio};
use std::time::Duration;

/// A picture check that finds every picture as expected, so that only the facts decide.
fn pictures_as_expected(_example: &str) -> Result<(), String> {
    Ok(())
}

/// The workbook's exercises, with the one named `name` checked by `facts` instead.
fn with(name: &str, facts: impl Fn() -> facts::Facts + 'static) -> Vec<Exercise> {
    let mut exercises = workbook();
    let exercise = exercises.iter_mut().find(|e| e.name == name).expect("an exercise of that name");
    exercise.facts = Box::new(facts);
    exercises
}

/// The renderer's hooks keep one record of the blanks a picture meets, shared by the process: the tests that
/// draw or answer through them run one at a time.
fn serial() -> std::sync::MutexGuard<'static, ()> {
    // The student's functions (here the solutions), as the grader's program registers them.
    exercises::answers::register();
    static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

#[test]
fn every_solution_holds_its_facts() {
    let _serial = serial();
    let exercises = workbook();
    for (exercise, verdict) in exercises.iter().zip(grade(&exercises, &pictures_as_expected)) {
        assert_eq!(verdict, Verdict::Passed { example: exercise.example.to_string() }, "{}", exercise.name);
    }
    assert_eq!(exercises.len(), 11);
}

/// Schlick's f0 for water (1.33) whatever the index asked for: a student who copied a constant.
fn fresnel_of_water(i: Vector, n: Vector, _eta1_over_eta2: f32) -> f32 {
    exercises::fresnel_schlick::fresnel(i, n, 1.0 / 1.33)
}

#[test]
fn a_wrong_fresnel_fails_with_a_message_a_student_understands() {
    let _serial = serial();
    let exercises = with("fresnel_schlick", || facts::fresnel_schlick(&fresnel_of_water));
    let verdicts = grade(&exercises, &pictures_as_expected);
    for (exercise, verdict) in exercises.iter().zip(&verdicts) {
        if exercise.name == "fresnel_schlick" {
            let Verdict::Failed(message) = verdict else { panic!("a wrong Fresnel passed: {verdict:?}") };
            // What was checked, in the student's terms, the value the slide's formula gives, and theirs.
            for part in
                ["Head-on", "entering glass of index 1.5", "f0 = ((1 - 1/1.5) / (1 + 1/1.5))^2", "0.0400", "got 0.0201"]
            {
                assert!(message.contains(part), "the message does not say {part:?}: {message}");
            }
        } else {
            assert!(matches!(verdict, Verdict::Passed { .. }), "{}: {verdict:?}", exercise.name);
        }
    }
    let report = grading::report(&exercises, &verdicts);
    assert!(report.contains("fresnel_schlick    FAILED: Head-on"), "{report}");
    assert!(report.contains("10 of 11 exercises handed out passed"), "{report}");
}

/// A blank exercise, as a student receives it.
fn blank_refract(_i: Vector, _n: Vector, _eta1_over_eta2: f32) -> Option<Vector> {
    todo!("refract")
}

#[test]
fn a_blank_exercise_is_named_and_the_others_still_grade() {
    let _serial = serial();
    let exercises = with("refract", || facts::refract(&blank_refract));
    let verdicts = grade(&exercises, &pictures_as_expected);
    for (exercise, verdict) in exercises.iter().zip(&verdicts) {
        if exercise.name == "refract" {
            assert_eq!(*verdict, Verdict::NotWritten("refract".into()));
        } else {
            assert!(matches!(verdict, Verdict::Passed { .. }), "{}: {verdict:?}", exercise.name);
        }
    }
    let report = grading::report(&exercises, &verdicts);
    assert!(report.contains("refract            not yet written: todo!(\"refract\") is still there"), "{report}");
}

#[test]
fn a_picture_that_needs_a_blank_exercise_waits_for_it_and_one_that_differs_fails() {
    let _serial = serial();
    // `fresnel` renders as if `faceforward` were blank; `glossy` differs; the others are as expected.
    let pictures = |example: &str| match example {
        "fresnel" => todo!("faceforward"),
        "glossy" => Err("the picture of `glossy` is not the expected one".to_string()),
        _ => Ok(()),
    };
    let exercises = workbook();
    let verdicts = grade(&exercises, &pictures);
    for (exercise, verdict) in exercises.iter().zip(&verdicts) {
        let expected = match exercise.example {
            "fresnel" => {
                Verdict::PictureWaits { example: "fresnel".into(), on: vec!["faceforward".into()], taken_out: vec![] }
            }
            "glossy" => Verdict::Failed("every fact holds, but the picture of `glossy` is not the expected one".into()),
            example => Verdict::Passed { example: example.into() },
        };
        assert_eq!(*verdict, expected, "{}", exercise.name);
    }
    assert!(verdicts[2].to_string().contains("leave it out of HANDED_OUT"), "{}", verdicts[2]);
}

/// Two of the renderer's hooks, as the workbook's slide functions call them.
static CUBE_MAP: Hook = Hook::new();
static FACEFORWARD: Hook = Hook::new();

#[test]
fn a_picture_names_every_blank_it_needs_in_one_run() {
    let _serial = serial();
    // `fresnel` meets two blanks, `cube_map` (its sky) and `faceforward`, each many times, as a render does:
    // drawn around them, the picture names both (before, only the first it met, one run at a time).
    let draws = std::sync::atomic::AtomicUsize::new(0);
    let pictures = |example: &str| {
        if example == "fresnel" {
            draws.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            for _ in 0..3 {
                let sky: Option<u32> = answer(&CUBE_MAP, true, || todo!("cube_map"));
                let normal: Option<u32> = answer(&FACEFORWARD, true, || todo!("faceforward"));
                assert_eq!((sky, normal), (None, None), "a blank is answered by the workbook's own function");
            }
        }
        Ok(())
    };
    let exercises = workbook();
    let verdicts = grade(&exercises, &pictures);
    assert_eq!(draws.into_inner(), 1, "each picture is drawn once");
    let fresnel = exercises.iter().position(|e| e.name == "fresnel_schlick").unwrap();
    let on = vec!["cube_map".to_string(), "faceforward".to_string()];
    let waits = Verdict::PictureWaits { example: "fresnel".into(), on, taken_out: vec![] };
    assert_eq!(verdicts[fresnel], waits, "{:?}", verdicts);
    assert!(
        verdicts[fresnel].to_string().contains("needs `cube_map`, `faceforward`, which are"),
        "{}",
        verdicts[fresnel]
    );
    // Outside the grader's drawing, a blank panics as it always did.
    let outside = std::panic::catch_unwind(|| answer(&FACEFORWARD, true, || -> u32 { todo!("faceforward") }));
    assert!(outside.is_err());
}

/// A copy of the workbook in which `refract`'s picture waits on three exercises, `transform_inverse`,
/// `bilinear` and `faceforward`: `blank` ones are not written yet (the others are), `left_out` ones are left
/// out of `HANDED_OUT`, and for `taken_out` ones the copy has not the workbook's own function.
struct StudentsCopy {
    blank: Vec<&'static str>,
    left_out: Vec<&'static str>,
    taken_out: Vec<&'static str>,
}

impl StudentsCopy {
    /// The three exercises `refract`'s picture needs besides its own, in the order its render meets them.
    const CHAIN: [&'static str; 3] = ["transform_inverse", "bilinear", "faceforward"];

    /// The grader's verdicts on this copy: each blank not yet written in its facts, and `refract`'s picture
    /// drawn as the renderer draws it, through the hooks, around the blanks; where the workbook's own
    /// function has been taken out, the render stops at the `todo!()` left in its place.
    fn grade(&self) -> Vec<Verdict> {
        let mut exercises = workbook();
        for exercise in exercises.iter_mut() {
            exercise.taken_out = self.taken_out.contains(&exercise.name);
            exercise.handed_out = !self.left_out.contains(&exercise.name);
            if self.blank.contains(&exercise.name) {
                let name = exercise.name;
                exercise.facts = Box::new(move || todo!("{name}"));
            }
        }
        // The renderer's hooks as a new grading process has them: none found blank yet.
        let hooks: [&'static Hook; 3] = std::array::from_fn(|_| &*Box::leak(Box::new(Hook::new())));
        let pictures = |example: &str| {
            if example == "refract" {
                for (name, hook) in Self::CHAIN.into_iter().zip(hooks) {
                    let (handed_out, blank) = (!self.left_out.contains(&name), self.blank.contains(&name));
                    let answer = answer(hook, handed_out, || if blank { todo!("{name}") } else { 1 });
                    if answer.is_none() && self.taken_out.contains(&name) {
                        todo!("{name}")
                    }
                }
            }
            Ok(())
        };
        grade(&exercises, &pictures)
    }

    /// The verdict on `refract`, and its text.
    fn refract(&self) -> (Verdict, String) {
        let verdicts = self.grade();
        let verdict = verdicts[workbook().iter().position(|e| e.name == "refract").unwrap()].clone();
        let text = verdict.to_string();
        (verdict, text)
    }
}

/// Whether `verdict` has `refract`'s picture waiting on exactly `names`.
fn waits_on(verdict: &Verdict, names: &[&str]) -> bool {
    matches!(verdict, Verdict::PictureWaits { on, .. } if on.iter().map(String::as_str).eq(names.iter().copied()))
}

#[test]
fn each_piece_of_the_graders_advice_changes_the_next_verdict_as_it_says() {
    let _serial = serial();
    let passed = Verdict::Passed { example: "refract".into() };
    let chain = ["bilinear", "transform_inverse", "faceforward"];
    let all = StudentsCopy::CHAIN.to_vec();
    for taken_out in [vec![], all.clone()] {
        // All three blank: the verdict names the whole chain at once, in the order of the slides, in the
        // teacher's workbook (drawn around the blanks) and in a students' copy (where the render stops at the
        // first it meets) alike.
        let (verdict, advice) =
            StudentsCopy { blank: all.clone(), left_out: vec![], taken_out: taken_out.clone() }.refract();
        assert!(waits_on(&verdict, &chain), "{verdict:?}");
        let left = StudentsCopy { blank: vec![], left_out: all.clone(), taken_out: taken_out.clone() };
        if taken_out.is_empty() {
            // "leave them out of HANDED_OUT": followed, the picture is drawn with the workbook's own.
            assert!(advice.contains("(or leave them out of HANDED_OUT"), "{advice}");
            assert_eq!(left.refract().0, passed);
            assert_eq!(left.grade().iter().filter(|v| **v == Verdict::NotHandedOut).count(), 3);
        } else {
            // No advice to leave them out, which would not help here (the picture would wait on them still),
            // and each left out says to put it back.
            assert!(!advice.contains("leave"), "{advice}");
            assert!(advice.contains(": write them, and the picture is checked"), "{advice}");
            assert!(waits_on(&left.refract().0, &chain));
            let verdicts = left.grade();
            assert_eq!(verdicts.iter().filter(|v| **v == Verdict::LeftOutWithoutOwn).count(), 3);
            assert!(Verdict::LeftOutWithoutOwn.to_string().contains("put it back in HANDED_OUT"));
        }
        // "write them": written one at a time, each verdict names the rest, and at the end the picture is
        // checked.
        for written in 1..=3 {
            let blank = StudentsCopy::CHAIN[written..].to_vec();
            let (verdict, _) =
                StudentsCopy { blank: blank.clone(), left_out: vec![], taken_out: taken_out.clone() }.refract();
            let rest: Vec<&str> = chain.into_iter().filter(|name| blank.contains(name)).collect();
            assert!(if rest.is_empty() { verdict == passed } else { waits_on(&verdict, &rest) }, "{verdict:?}");
        }
    }
    // One of the three taken out: the advice to leave out names only the other two, and followed, the
    // picture waits on the third alone; written, it is checked.
    let taken_out = vec!["transform_inverse"];
    let (verdict, advice) =
        StudentsCopy { blank: all.clone(), left_out: vec![], taken_out: taken_out.clone() }.refract();
    assert!(waits_on(&verdict, &chain), "{verdict:?}");
    assert!(advice.contains("or leave `bilinear`, `faceforward` out of HANDED_OUT"), "{advice}");
    assert!(advice.contains("does not hold the workbook's own `transform_inverse`"), "{advice}");
    let left = StudentsCopy { blank: vec!["transform_inverse"], left_out: vec!["bilinear", "faceforward"], taken_out };
    let (verdict, advice) = left.refract();
    assert!(waits_on(&verdict, &["transform_inverse"]), "{verdict:?}");
    assert!(advice.contains(": write it, and the picture is checked"), "{advice}");
    assert_eq!(StudentsCopy { blank: vec![], ..left }.refract().0, passed);
}

#[test]
fn the_pictures_table_lists_the_exercises_each_picture_is_drawn_with() {
    let _serial = serial();
    // Each answer's method in exercises/src/answers.rs (named as the renderer's hook), and the exercise whose
    // switch it reads.
    let answers = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/src/answers.rs")).expect("the answers");
    let exercise_of_hook = |hook: &str| -> String {
        let method =
            answers.split("\n    fn ").find(|f| f.strip_prefix(hook).is_some_and(|rest| rest.starts_with(['(', '<'])));
        let method = method.unwrap_or_else(|| panic!("no answer for the hook {hook}"));
        let switch = method.split_once("handed_out::").expect("a switch").1;
        switch.chars().take_while(|c| c.is_ascii_uppercase() || *c == '_').collect::<String>().to_lowercase()
    };
    let order: Vec<&str> = workbook().iter().map(|e| e.name).collect();
    let mut wrong = Vec::new();
    for (example, table) in grading::PICTURES {
        // At the default settings, as the grader draws it.
        let (_, asked) = drawing_and_listing_hooks(|| render(example, &["--quiet"]));
        let mut used: Vec<String> = asked
            .iter()
            .map(|asker| {
                // `<exercises::answers::Students as lecture6::...::Answers>::bilinear::{{closure}}`: the hook's name.
                let path = asker.split_once("Answers>::").map_or(*asker, |(_, path)| path);
                exercise_of_hook(&path.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>())
            })
            .collect();
        used.sort_by_key(|name| order.iter().position(|o| o == name));
        used.dedup();
        if used != table.to_vec() {
            wrong.push(format!("(\"{example}\", &{used:?}), in the table as {table:?}"));
        }
    }
    assert!(wrong.is_empty(), "the pictures are drawn with other exercises than the table says:\n{}", wrong.join("\n"));
    // Every exercise's own picture is in the table, and uses it.
    for exercise in workbook() {
        assert!(grading::uses(exercise.example).contains(&exercise.name), "{}", exercise.name);
    }
}

#[test]
fn the_hand_out_is_one_list() {
    let _serial = serial();
    assert!(exercises::listed(exercises::EXERCISES, "refract") && !exercises::listed(exercises::EXERCISES, "refrac"));
    assert_eq!(exercises::HANDED_OUT.len(), 11, "the workbook hands out every exercise");
    assert!(workbook().iter().all(|e| e.handed_out == exercises::listed(exercises::HANDED_OUT, e.name)));
}

#[test]
fn an_exercise_that_panics_fails_and_one_not_handed_out_is_skipped() {
    let _serial = serial();
    let mut exercises = with("bilinear", || facts::bilinear(&|_, _, texel| texel(i64::MAX, 0) * 0.0));
    exercises[1].handed_out = false;
    exercises[2].facts = Box::new(|| panic!("index out of bounds"));
    let verdicts = grade(&exercises, &pictures_as_expected);
    assert!(matches!(&verdicts[0], Verdict::Failed(m) if m.contains("centre of texel (2, 1)")), "{:?}", verdicts[0]);
    assert_eq!(verdicts[1], Verdict::NotHandedOut);
    assert_eq!(verdicts[2], Verdict::Failed("it panicked: index out of bounds".into()));
    assert!(!grading::all_passed(&verdicts));
}

/// The workbook's exercises with `refract` looping forever and `faceforward` recursing until its stack
/// overflows, as both the test below and the grading steps it starts see them.
fn with_a_loop_and_a_stack_overflow() -> Vec<Exercise> {
    #[allow(unconditional_recursion)]
    fn deeper(depth: u64) -> u64 {
        std::hint::black_box(deeper(std::hint::black_box(depth + 1))) + 1
    }
    let mut exercises = with("refract", || {
        facts::refract(&|_, _, _| {
            loop {
                std::hint::spin_loop();
            }
        })
    });
    let faceforward = exercises.iter_mut().find(|e| e.name == "faceforward").expect("an exercise of that name");
    faceforward.facts = Box::new(|| facts::faceforward(&|n, _| n * deeper(0) as f32));
    exercises
}

/// A step of `a_looping_exercise_is_stopped_at_its_limit_and_fails`, in a process of its own.
#[test]
#[ignore = "a step of another test, which runs it in a process of its own"]
fn grading_step() {
    grading::run_step_if_asked(&with_a_loop_and_a_stack_overflow(), &pictures_as_expected);
}

#[test]
fn a_looping_exercise_is_stopped_at_its_limit_and_fails() {
    let limits = Limits { time: Duration::from_secs(5), memory: None, output: None };
    let this = std::env::current_exe().expect("the test's own program");
    let child = || {
        let mut command = Command::new(&this);
        command.args(["--exact", "grading_step", "--ignored", "--test-threads", "1"]);
        command.stdout(Stdio::null()).stderr(Stdio::null());
        command
    };
    let exercises = with_a_loop_and_a_stack_overflow();
    let verdicts = grading::grade_isolated(&exercises, &limits, &child);
    for (exercise, verdict) in exercises.iter().zip(&verdicts) {
        match exercise.name {
            "refract" => assert_eq!(
                *verdict,
                Verdict::Failed(
                    "stopped at its time limit of 5 s before its facts were all checked (does it loop forever?)".into()
                )
            ),
            "faceforward" => assert!(
                matches!(verdict, Verdict::Failed(m) if m.contains("crashed (it aborted: a stack overflow")),
                "{verdict:?}"
            ),
            _ => assert!(matches!(verdict, Verdict::Passed { .. }), "{}: {verdict:?}", exercise.name),
        }
    }
}

/// Schlick's reflectance in f64, for a ray `theta_i` from the normal, with the workbook's rule for rays
/// leaving the denser medium: the formula of the facts' table (which holds numbers only, so that the grader a
/// student receives holds no answer).
fn schlick_reference(theta_i: f64, eta: f64) -> f64 {
    let f0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
    let cos_i = theta_i.cos();
    let cos = if eta > 1.0 {
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    } else {
        cos_i
    };
    f0 + (1.0 - f0) * (1.0 - cos).powi(5)
}

/// The exact Fresnel reflectance in f64, for a ray `theta_i` from the normal: the formula of the facts' table.
fn exact_reference(theta_i: f64, eta: f64) -> f64 {
    let cos_i = theta_i.cos();
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (rs * rs + rp * rp)
}

#[test]
fn the_facts_tables_hold_the_formulas_values() {
    let near = |table: f32, formula: f64, what: &str| assert!((table as f64 - formula).abs() < 1e-6, "{what}: {table}");
    for degrees in 0..90 {
        let theta = (degrees as f64).to_radians();
        near(facts::SCHLICK_ENTERING_GLASS[degrees], schlick_reference(theta, 1.0 / 1.5), "Schlick");
        near(facts::EXACT_ENTERING_GLASS[degrees], exact_reference(theta, 1.0 / 1.5), "exact");
    }
    near(facts::SCHLICK_LEAVING_GLASS_AT_30, schlick_reference(30f64.to_radians(), 1.5), "Schlick leaving");
    near(facts::EXACT_AT_BREWSTER, exact_reference(1.5f64.atan(), 1.0 / 1.5), "Brewster");
}

/// Runs a fact check that must fail, and returns its message.
fn fails(check: facts::Facts) -> String {
    check.expect_err("a wrong answer held every fact")
}

#[test]
fn every_fact_check_fails_on_a_plausible_mistake() {
    let _serial = serial();
    use exercises::*;
    // Bilinear without the half-texel offset.
    let message = fails(facts::bilinear(&|x, y, texel| bilinear::bilinear(x + 0.5, y + 0.5, texel)));
    assert!(message.contains("centre of texel (2, 1)"), "{message}");
    // The inverse as the transpose: right for a rotation only.
    let message =
        fails(facts::transform_inverse(&|t| Affine3A { matrix3: t.matrix3.transpose(), translation: -t.translation }));
    assert!(message.contains("scale by (2, 1.5, 0.9)"), "{message}");
    // The cube map with v growing upwards.
    let message = fails(facts::cube_map(&|d| {
        let (face, u, v) = cube_map::cube_face_uv(d);
        (face, u, 1.0 - v)
    }));
    assert!(message.contains("(0, 0.5, 1) should land on PosZ at (u, v) = (0.5, 0.25)"), "{message}");
    // The cube map choosing the face by the largest signed component.
    let message = fails(facts::cube_map(&|d| {
        let (_, u, v) = cube_map::cube_face_uv(d);
        let face = if d.x >= d.y && d.x >= d.z {
            Face::PosX
        } else if d.y >= d.z {
            Face::PosY
        } else {
            Face::PosZ
        };
        (face, u, v)
    }));
    assert!(message.contains("should land in the middle of NegX"), "{message}");
    // The cube map letting x win over a z not much larger.
    let message = fails(facts::cube_map(&|d| {
        let (face, u, v) = cube_map::cube_face_uv(d);
        let a = d.abs();
        let x_wins = a.x >= a.y && a.x < a.z && a.x >= 0.6 * a.z;
        (if x_wins { if d.x >= 0.0 { Face::PosX } else { Face::NegX } } else { face }, u, v)
    }));
    assert!(message.contains("should land on the face of its largest component"), "{message}");
    // faceforward the wrong way round.
    let message = fails(facts::faceforward(&|n, i| -faceforward::faceforward(n, i)));
    assert!(message.contains("sees its normal n = (0, 1, 0) as it is"), "{message}");
    // refract with the slide's comment's ratio (eta2 / eta1).
    let message = fails(facts::refract(&|i, n, eta| refract::refract(i, n, 1.0 / eta)));
    assert!(message.contains("entering glass of index 1.5 at 45 degrees refracts"), "{message}");
    // refract without total internal reflection.
    let message = fails(facts::refract(&|i, n, eta| refract::refract(i, n, eta).or(Some(Vector::ZERO))));
    assert!(message.contains("total internal reflection"), "{message}");
    // The layer weight forgetting the layers above.
    let message = fails(facts::layered_blend(&|_, blend| blend));
    assert!(message.contains("under an opaque one"), "{message}");
    // The slide's Schlick, without the workbook's rule for rays leaving the glass.
    let message = fails(facts::fresnel_schlick(&|i, n, eta| {
        let f0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
        f0 + (1.0 - f0) * (1.0 + n.dot(i)).powi(5)
    }));
    assert!(message.contains("past the critical angle"), "{message}");
    // The exact equations with rs only.
    let message = fails(facts::fresnel_exact(&|i, n, eta| {
        let cos_i = -n.dot(i);
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        ((eta * cos_i - cos_t) / (eta * cos_i + cos_t)).powi(2)
    }));
    assert!(message.contains("Brewster"), "{message}");
    // A random radius and angle: points crowd at the centre.
    let message = fails(facts::glossy_disc(
        &|random| {
            let (r, phi) = (random(), 2.0 * std::f32::consts::PI * random());
            (r * phi.cos(), r * phi.sin())
        },
        &glossy_disc::concentric_disc,
    ));
    assert!(message.contains("From the random numbers 0.5, 0.75"), "{message}");
    let message = fails(facts::glossy_disc(&|random| glossy_disc::random_unit_disc_point(random), &|u, v| {
        let (r, phi) = (u.sqrt(), 2.0 * std::f32::consts::PI * v);
        (r * phi.cos(), r * phi.sin())
    }));
    assert!(message.contains("concentric mapping the centre of the square"), "{message}");
    // A glossy cone that lets rays go under the surface.
    let message = fails(facts::glossy_cone(&glossy_cone::glossy_scaling, &|i, n, t, b, s, (x, y)| {
        Some(reflect(i, (n + x * s * t + y * s * b).normalize()))
    }));
    assert!(message.contains("goes under the surface"), "{message}");
    // A glossy scaling that is linear rather than the slide's tangent.
    let message = fails(facts::glossy_cone(&|g| 1.0 - g, &glossy_cone::glossy_direction));
    assert!(message.contains("tan((1 - glossiness) * pi/2) at glossiness 0.95"), "{message}");
    // The photon estimate without the cone filter: a plain sum over the area.
    let message = fails(facts::photon_estimate(&|photons: &[Photon], r2, n| {
        photons.iter().filter(|p| p.dir.dot(n) < 0.0).map(|p| p.power).sum::<Color>() / (std::f32::consts::PI * r2)
    }));
    assert!(message.contains("counts fully"), "{message}");
}

#[test]
fn the_exercises_types_agree_with_the_workbooks() {
    let _serial = serial();
    use lecture6::lesson::environment::CubeFace;
    let faces = [Face::PosX, Face::NegX, Face::PosY, Face::NegY, Face::PosZ, Face::NegZ];
    for (face, workbook) in faces.into_iter().zip(CubeFace::ALL) {
        assert_eq!(face as usize, workbook as usize);
        assert_eq!(format!("{face:?}"), format!("{workbook:?}"));
    }
}

/// The example called `name` rendered with the options `args`, with the student's functions.
fn render(name: &str, args: &[&str]) -> Frame {
    report::render(name, args).expect("the example renders")
}

/// The example called `name`, rendered small (160x120, 4 samples a pixel).
fn small_render(name: &str) -> Frame {
    render(name, &["--quiet", "--width", "160", "--height", "120", "--spp", "4"])
}

/// Where two frames of one size differ: the first differing pixel and how many do.
fn first_difference(a: &Frame, b: &Frame) -> Option<String> {
    let differing: Vec<usize> = (0..a.pixels.len()).filter(|&i| a.pixels[i] != b.pixels[i]).collect();
    let &first = differing.first()?;
    let (x, y) = (first % a.width as usize, first / a.width as usize);
    Some(format!(
        "{} of {} pixels differ, the first at ({x}, {y}): {:?} against the workbook's {:?}",
        differing.len(),
        a.pixels.len(),
        a.pixels[first],
        b.pixels[first]
    ))
}

/// The photon-estimate exercise's solution draws `photon_map` bit for bit as the workbook's own estimate
/// does: the student's sum is finished by the same function as the workbook's (`arriving_light`), with the
/// same constant (`CONE_FILTER_K`). The other solutions are held to the pictures' tolerance only, by the
/// grader itself: where a slide's formula may be written in more than one order, a correct answer may
/// differ from the workbook's in the last bit.
#[test]
fn the_photon_estimate_solution_draws_photon_map_as_the_workbook_does() {
    let _serial = serial();
    let students = small_render("photon_map");
    let workbooks = drawing_with_the_workbooks_own(|| small_render("photon_map"));
    assert_eq!(students.width, workbooks.width);
    assert_eq!(first_difference(&students, &workbooks), None);
}
