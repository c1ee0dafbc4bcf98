//! The side panel's controls: one per option of the example's command line (its own and the common ones), of
//! the kind its definition asks for: a flag a check box, an option with possible values a choice, a number a
//! drag value, anything else a text field. The application makes them from the example's command line; the
//! controls hold the option values as the command line spells them, so a change is turned back into an
//! argument list ([`Controls::args`]) that the application reads with the example's own parser: what the
//! window renders is exactly what the same options give on the command line, and a bad value gets the
//! command line's message.
//!
//! The steps beyond the slides are one set of check boxes ([`Controls::steps`]) in place of the options that
//! spell them (`--slide`, `--step`, `--no-step`, `--exhaustive`): `--slide`, which clears them all, and one
//! per step. [`Controls::args`] spells the set as the command line would ([`steps_args`]).

/// What kind of value an option takes.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// A flag: present or not.
    Flag,
    /// One of the listed values.
    Choice(Vec<String>),
    /// A whole number from `min` to `max`, the range the option's parser takes.
    Integer {
        /// The smallest value the option takes; minus infinity when its range could not be found.
        min: f64,
        /// The largest value the option takes; infinity when its range could not be found.
        max: f64,
    },
    /// A real number.
    Real,
    /// Anything else (a path).
    Text,
}

/// One option as a control: its name on the command line, its help, its kind and its current value.
#[derive(Clone, Debug, PartialEq)]
pub struct Control {
    /// The option's long name, without the dashes.
    pub long: String,
    /// The first line of its help.
    pub help: String,
    /// "Common options", or `None` for the example's own.
    pub heading: Option<String>,
    /// What kind of value the option takes: what control shows it.
    pub kind: Kind,
    /// The value as the command line spells it: "" when the option is not given (it has no default),
    /// "true" or "false" for a flag.
    pub value: String,
    /// The option has no default value of its own: it may be left empty, which leaves the choice to the
    /// example or the scene.
    pub optional: bool,
    /// What an empty value means, as its help says ("[default: 5]" gives "5"), or "default".
    pub placeholder: String,
}

impl Control {
    /// The flag's state.
    pub fn is_set(&self) -> bool {
        self.value == "true"
    }
}

/// One step beyond the slides as a check box: its name (as `--step` and `--no-step` take it), what it does,
/// and whether the render takes it.
#[derive(Clone, Debug, PartialEq)]
pub struct StepBox {
    /// The step's name on the command line (`adaptive-depth`).
    pub name: String,
    /// What the step does, in one line.
    pub summary: String,
    /// The box is ticked: the render takes the step.
    pub taken: bool,
}

/// The controls of one example, in the order of its `--help`.
#[derive(Clone, Debug, PartialEq)]
pub struct Controls {
    name: String,
    /// The example's options, in the order of its `--help`.
    pub controls: Vec<Control>,
    /// The steps beyond the slides, each ticked when the render takes it: `--slide` is all of them clear.
    pub steps: Vec<StepBox>,
    /// The options given on the command line that are no controls but count in the window: where "Save"
    /// writes (`--output`), what "Compare" compares with (`--compare`), the interface's scale. As the
    /// command line spells them.
    pub fixed: Vec<String>,
}

impl Controls {
    /// The controls of the example called `name`, from its options in the order of its command: each
    /// heading's options are put together, in the order the headings first appear (`--spp`, whose default
    /// the example sets, comes last in the command), as `--help` shows them; the `steps` the options take,
    /// and the `fixed` options, kept as given.
    pub fn new(name: &str, controls: Vec<Control>, steps: Vec<StepBox>, fixed: Vec<String>) -> Controls {
        let headings: Vec<Option<String>> = controls.iter().map(|c| c.heading.clone()).collect();
        let mut controls = controls;
        controls.sort_by_key(|c| headings.iter().position(|h| *h == c.heading));
        Controls { name: name.to_string(), controls, steps, fixed }
    }

    /// The name of the example whose options these are.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The command line the controls spell (without the program name): every option that has a value, the
    /// steps ([`steps_args`]) and the fixed options.
    pub fn args(&self) -> Vec<String> {
        let mut args = steps_args(&self.steps);
        args.extend(self.fixed.iter().cloned());
        for c in &self.controls {
            match c.kind {
                Kind::Flag if c.is_set() => args.push(format!("--{}", c.long)),
                Kind::Flag => {}
                _ if c.value.trim().is_empty() => {}
                _ => args.extend([format!("--{}", c.long), c.value.trim().to_string()]),
            }
        }
        args
    }

    /// Whether the `--slide` box is ticked: no step beyond the slides is taken.
    pub fn slide(&self) -> bool {
        self.steps.iter().all(|step| !step.taken)
    }

    /// Ticks the `--slide` box (`on`), which clears every step's, or clears it, which ticks them all again
    /// (the default).
    pub fn set_slide(&mut self, on: bool) {
        self.steps.iter_mut().for_each(|step| step.taken = !on);
    }

    /// Ticks the box of the step called `name` (`on`) or clears it; false when there is no such step.
    pub fn set_step(&mut self, name: &str, on: bool) -> bool {
        let found = self.steps.iter_mut().find(|step| step.name == name);
        found.map(|step| step.taken = on).is_some()
    }

    /// The control of the option `--long`.
    pub fn get_mut(&mut self, long: &str) -> Option<&mut Control> {
        self.controls.iter_mut().find(|c| c.long == long)
    }
}

/// The options that give exactly the steps ticked in `steps`: none when all are (the default); `--slide` and
/// a `--step` for each ticked where they are fewer than the clear ones; else a `--no-step` for each clear one.
pub fn steps_args(steps: &[StepBox]) -> Vec<String> {
    let taken = steps.iter().filter(|step| step.taken).count();
    let spell = |option: &str, step: &StepBox| [option.to_string(), step.name.clone()];
    if taken * 2 < steps.len() {
        let each = steps.iter().filter(|step| step.taken).flat_map(|step| spell("--step", step));
        std::iter::once("--slide".to_string()).chain(each).collect()
    } else {
        steps.iter().filter(|step| !step.taken).flat_map(|step| spell("--no-step", step)).collect()
    }
}
