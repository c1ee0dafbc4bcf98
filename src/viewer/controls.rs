//! The side panel's controls, generated from the example's command line: every option of its clap command
//! (the example's own and the common ones) becomes a control of the kind its definition asks for: a flag a
//! check box, an option with possible values a choice, a number a drag value, anything else a text field.
//! The controls hold the option values as the command line spells them, so a change is turned back into
//! an argument list and parsed by the example's own parser: what the window renders is exactly what the
//! same options give on the command line, and a bad value gets the command line's message.

use crate::cli::{Cli, Example};
use clap::ArgAction;
use std::any::TypeId;
use std::ffi::OsString;

/// Options that make no sense as a control: the window is already open, and saving, comparing and
/// printing are the window's buttons.
const NOT_CONTROLS: [&str; 6] = ["help", "version", "window", "output", "quiet", "compare"];

/// What kind of value an option takes.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// A flag: present or not.
    Flag,
    /// One of the listed values.
    Choice(Vec<String>),
    /// A whole number; `min` is the smallest its type holds (0 for unsigned counts).
    Integer { min: f64 },
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
    pub kind: Kind,
    /// The value as the command line spells it: "" when the option is not given (it has no default),
    /// "true" or "false" for a flag.
    pub value: String,
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
    pub controls: Vec<Control>,
}

/// The kind of value the option `arg` takes.
fn kind_of(arg: &clap::Arg) -> Kind {
    if matches!(arg.get_action(), ArgAction::SetTrue) {
        return Kind::Flag;
    }
    let choices: Vec<String> = arg.get_possible_values().iter().map(|v| v.get_name().to_string()).collect();
    if !choices.is_empty() {
        return Kind::Choice(choices);
    }
    let id = arg.get_value_parser().type_id();
    let unsigned =
        [TypeId::of::<u8>(), TypeId::of::<u16>(), TypeId::of::<u32>(), TypeId::of::<u64>(), TypeId::of::<usize>()];
    let signed = [TypeId::of::<i32>(), TypeId::of::<i64>()];
    if unsigned.iter().any(|t| id == *t) {
        Kind::Integer { min: 0.0 }
    } else if signed.iter().any(|t| id == *t) {
        Kind::Integer { min: f64::NEG_INFINITY }
    } else if id == TypeId::of::<f32>() || id == TypeId::of::<f64>() {
        Kind::Real
    } else {
        Kind::Text
    }
}

impl Controls {
    /// The controls of the example called `name`, holding the values of the command line `args` (without
    /// the program name).
    pub fn new<E: Example>(name: &str, args: &[OsString]) -> Result<Controls, clap::Error> {
        let mut command = Cli::<E>::command_named(name);
        let argv = std::iter::once(OsString::from(name)).chain(args.iter().cloned());
        let matches = command.try_get_matches_from_mut(argv)?;
        let controls = command
            .get_arguments()
            .filter(|arg| !NOT_CONTROLS.contains(&arg.get_id().as_str()))
            .filter_map(|arg| {
                let long = arg.get_long()?.to_string();
                let value = matches
                    .get_raw(arg.get_id().as_str())
                    .and_then(|mut values| values.next())
                    .map(|v| v.to_string_lossy().into_owned())
                    .unwrap_or_default();
                let help = arg.get_help().map(|h| h.to_string()).unwrap_or_default();
                let help = help.split(". ").next().unwrap_or_default().trim_end_matches('.').to_string();
                let heading = arg.get_help_heading().map(str::to_string);
                Some(Control { long, help, heading, kind: kind_of(arg), value })
            })
            .collect::<Vec<_>>();
        // Each heading's options together, in the order the headings first appear (`--spp`, whose
        // default the example sets, comes last in the command).
        let headings: Vec<Option<String>> = controls.iter().map(|c| c.heading.clone()).collect();
        let mut controls = controls;
        controls.sort_by_key(|c| headings.iter().position(|h| *h == c.heading));
        Ok(Controls { name: name.to_string(), controls })
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

    /// The options the controls spell, parsed by the example's own parser.
    pub fn parse<E: Example>(&self) -> Result<Cli<E>, clap::Error> {
        Cli::<E>::parse_args(&self.name, self.args())
    }

    /// The control of the option `--long`.
    pub fn get_mut(&mut self, long: &str) -> Option<&mut Control> {
        self.controls.iter_mut().find(|c| c.long == long)
    }
}
