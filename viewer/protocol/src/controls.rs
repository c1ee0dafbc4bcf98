//! The side panel's controls: one per option of the example's command line (its own and the common ones), of
//! the kind its definition asks for: a flag a check box, an option with possible values a choice, a number a
//! drag value, anything else a text field. The application makes them from the example's command line; the
//! controls hold the option values as the command line spells them, so a change is turned back into an
//! argument list ([`Controls::args`]) that the application reads with the example's own parser: what the
//! window renders is exactly what the same options give on the command line, and a bad value gets the
//! command line's message.

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

/// The controls of one example, in the order of its `--help`.
#[derive(Clone, Debug)]
pub struct Controls {
    name: String,
    /// The example's options, in the order of its `--help`.
    pub controls: Vec<Control>,
}

impl Controls {
    /// The controls of the example called `name`, from its options in the order of its command: each
    /// heading's options are put together, in the order the headings first appear (`--spp`, whose default
    /// the example sets, comes last in the command), as `--help` shows them.
    pub fn new(name: &str, controls: Vec<Control>) -> Controls {
        let headings: Vec<Option<String>> = controls.iter().map(|c| c.heading.clone()).collect();
        let mut controls = controls;
        controls.sort_by_key(|c| headings.iter().position(|h| *h == c.heading));
        Controls { name: name.to_string(), controls }
    }

    /// The name of the example whose options these are.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The command line the controls spell (without the program name): every option that has a value.
    pub fn args(&self) -> Vec<String> {
        let mut args = Vec::new();
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

    /// The control of the option `--long`.
    pub fn get_mut(&mut self, long: &str) -> Option<&mut Control> {
        self.controls.iter_mut().find(|c| c.long == long)
    }
}
