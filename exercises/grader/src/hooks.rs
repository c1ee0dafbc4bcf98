//! How the workbook's renderer asks for a student's answer. Built for the exercises (the workbook's feature
//! `exercises`), each slide function an exercise covers asks the answers the program registered (the
//! exercises' `src/answers.rs`), each of which asks its [`Hook`] ([`answer`]); the grader draws a picture
//! around the blanks ([`drawing_around_blanks`]) or with the workbook's own functions
//! ([`drawing_with_the_workbooks_own`]), and its own tests list the functions a picture asks for
//! ([`drawing_and_listing_hooks`]). It lives here, beside the exercises, so that the workbook's lesson holds
//! the slides' code and nothing else.

use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// One function a slide function hands over to an exercise: whether the student's is still a blank, found
/// so while the renderer draws around blanks ([`drawing_around_blanks`]).
pub struct Hook {
    /// The student's function panicked with `todo!()`: the workbook's own is used from then on, when the
    /// renderer draws around blanks.
    blank: AtomicBool,
    /// The blank was met during the current [`drawing_around_blanks`].
    met: AtomicBool,
    /// The text of its `todo!()`, once met.
    text: Mutex<String>,
}

impl Hook {
    /// A hook whose function has not been found blank.
    pub const fn new() -> Hook {
        Hook { blank: AtomicBool::new(false), met: AtomicBool::new(false), text: Mutex::new(String::new()) }
    }
}

impl Default for Hook {
    fn default() -> Hook {
        Hook::new()
    }
}

/// Whether the renderer draws around blanks now (see [`drawing_around_blanks`]).
static AROUND_BLANKS: AtomicBool = AtomicBool::new(false);

/// Whether every hook answers with the workbook's own function now (see [`drawing_with_the_workbooks_own`]).
static WORKBOOKS_OWN: AtomicBool = AtomicBool::new(false);

/// Whether every hook answers with the workbook's own function and notes who asked, now (see
/// [`drawing_and_listing_hooks`]).
static LISTING: AtomicBool = AtomicBool::new(false);

/// The functions of the workbook's hooks asked during the current [`drawing_and_listing_hooks`].
static ASKED: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());

/// The hooks met blank during the current [`drawing_around_blanks`].
static MET: Mutex<Vec<&'static Hook>> = Mutex::new(Vec::new());

/// The student's answer `student()` for an exercise handed out (`handed_out`), `None` for one that is not.
/// Normally a blank's `todo!()` panics out of the render; within [`drawing_around_blanks`] it is caught,
/// remembered, and answered with the workbook's own function (`None`) from then on, so that the render
/// goes on and meets every other blank it needs.
pub fn answer<T>(hook: &'static Hook, handed_out: bool, student: impl FnOnce() -> T) -> Option<T> {
    if LISTING.load(Relaxed) {
        // The student's function is a closure defined in the answer's method: its type names that method.
        let asker = std::any::type_name_of_val(&student);
        let mut asked = ASKED.lock().unwrap_or_else(|e| e.into_inner());
        if !asked.contains(&asker) {
            asked.push(asker);
        }
        return None;
    }
    if !handed_out || WORKBOOKS_OWN.load(Relaxed) {
        return None;
    }
    if !AROUND_BLANKS.load(Relaxed) {
        return Some(student());
    }
    if hook.blank.load(Relaxed) {
        note_met(hook);
        return None;
    }
    match catch_unwind(AssertUnwindSafe(student)) {
        Ok(answer) => Some(answer),
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let Some(text) = message.strip_prefix("not yet implemented") else { resume_unwind(payload) };
            *hook.text.lock().unwrap_or_else(|e| e.into_inner()) = text.strip_prefix(": ").unwrap_or(text).to_string();
            hook.blank.store(true, Relaxed);
            note_met(hook);
            None
        }
    }
}

/// Remembers that `hook` was met blank in this drawing (once).
fn note_met(hook: &'static Hook) {
    if !hook.met.swap(true, Relaxed) {
        MET.lock().unwrap_or_else(|e| e.into_inner()).push(hook);
    }
}

/// Runs `draw` (a render) with every blank it meets answered by the workbook's own function, and returns
/// what it returned with the texts of the `todo!()`s of the blanks it met (`"cube_map"`,
/// `"glossy_disc: concentric_disc"`), in the order met: the grader names every exercise a picture needs in
/// one run. One drawing at a time.
pub fn drawing_around_blanks<T>(draw: impl FnOnce() -> T) -> (T, Vec<String>) {
    let result = while_set(&AROUND_BLANKS, draw);
    let met = std::mem::take(&mut *MET.lock().unwrap_or_else(|e| e.into_inner()));
    let texts = met
        .iter()
        .map(|hook| {
            hook.met.store(false, Relaxed);
            hook.text.lock().unwrap_or_else(|e| e.into_inner()).clone()
        })
        .collect();
    (result, texts)
}

/// Runs `draw` (a render) with the workbook's own function for every exercise, handed out or not, and
/// returns what it returned: the picture the workbook draws without the student's functions, to compare
/// theirs with. One drawing at a time.
pub fn drawing_with_the_workbooks_own<T>(draw: impl FnOnce() -> T) -> T {
    while_set(&WORKBOOKS_OWN, draw)
}

/// Runs `draw` (a render) with the workbook's own function for every exercise, as
/// [`drawing_with_the_workbooks_own`] does, and returns what it returned with the type names of the student's
/// functions the hooks were asked for, in the order first asked (each a closure in the workbook's hook
/// method: `<exercises::answers::Students as lecture6::lesson::exercise_hooks::Answers>::refract::{{closure}}`):
/// which exercises a picture uses. One drawing at a time.
pub fn drawing_and_listing_hooks<T>(draw: impl FnOnce() -> T) -> (T, Vec<&'static str>) {
    let result = while_set(&LISTING, draw);
    (result, std::mem::take(&mut *ASKED.lock().unwrap_or_else(|e| e.into_inner())))
}

/// Runs `f` with `flag` set, and clears it afterwards, also when `f` panics.
fn while_set<T>(flag: &'static AtomicBool, f: impl FnOnce() -> T) -> T {
    struct Clear(&'static AtomicBool);
    impl Drop for Clear {
        fn drop(&mut self) {
            self.0.store(false, Relaxed);
        }
    }
    flag.store(true, Relaxed);
    let _clear = Clear(flag);
    f()
}
