//! The side panel's controls, generated from the example's command line: every option of its clap command
//! (the example's own and the common ones) becomes a control of the kind its definition asks for: a flag a
//! check box, an option with possible values a choice, a number a drag value, anything else a text field.
//! The controls hold the option values as the command line spells them, so a change is turned back into
//! an argument list and parsed by the example's own parser: what the window renders is exactly what the
//! same options give on the command line, and a bad value gets the command line's message.

use crate::app::cli::{Cli, Example};
use clap::ArgAction;
use clap::error::ErrorKind;
use std::any::TypeId;
use std::ffi::OsString;

/// Options (by their ids) that make no sense as a control: the window is already open; saving, comparing
/// and printing are the window's buttons; a click on the picture traces a pixel; debug views and side by
/// side pictures are files the command line writes; the render threads are started once, with the window.
const NOT_CONTROLS: [&str; 12] = [
    "help",
    "version",
    "window",
    "output",
    "quiet",
    "compare",
    "trace_pixel",
    "trace_sample",
    "trace_format",
    "view",
    "side_by_side",
    "threads",
];

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

/// The kind of value the option `arg` of `command` takes; `value` is its current one.
fn kind_of(command: &clap::Command, arg: &clap::Arg, value: &str) -> Kind {
    if matches!(arg.get_action(), ArgAction::SetTrue) {
        return Kind::Flag;
    }
    let choices: Vec<String> = arg.get_possible_values().iter().map(|v| v.get_name().to_string()).collect();
    if !choices.is_empty() {
        return Kind::Choice(choices);
    }
    let id = arg.get_value_parser().type_id();
    let integers = [
        TypeId::of::<u8>(),
        TypeId::of::<u16>(),
        TypeId::of::<u32>(),
        TypeId::of::<u64>(),
        TypeId::of::<usize>(),
        TypeId::of::<i32>(),
        TypeId::of::<i64>(),
    ];
    if integers.iter().any(|t| id == *t) {
        let (min, max) = accepted_range(command, arg, value)
            .map_or((f64::NEG_INFINITY, f64::INFINITY), |(lo, hi)| (lo as f64, hi as f64));
        Kind::Integer { min, max }
    } else if id == TypeId::of::<f32>() || id == TypeId::of::<f64>() {
        Kind::Real
    } else {
        Kind::Text
    }
}

/// The whole numbers the whole-number option `arg` takes, as its parser checks them: the interval around a
/// value it takes (its current `value`, its default, 0 or 1), its ends found by bisection over `i64`.
/// `None` when it takes none of those.
fn accepted_range(command: &clap::Command, arg: &clap::Arg, value: &str) -> Option<(i64, i64)> {
    let long = format!("--{}", arg.get_long()?);
    // Only the option's own value check counts: another option's error (a required one missing) is not its.
    let accepts = |v: i64| match command.clone().try_get_matches_from([command.get_name(), &long, &v.to_string()]) {
        Ok(_) => true,
        Err(e) => !matches!(e.kind(), ErrorKind::ValueValidation | ErrorKind::InvalidValue),
    };
    let defaults = arg.get_default_values().iter().filter_map(|d| d.to_str()?.parse().ok());
    let inside = value.parse().ok().into_iter().chain(defaults).chain([0, 1]).find(|&v| accepts(v))?;
    // The last value from `taken` towards `beyond` that the option takes (`taken` is one).
    let edge = |mut taken: i64, mut beyond: i64| {
        if accepts(beyond) {
            return beyond;
        }
        while taken.abs_diff(beyond) > 1 {
            let middle = ((taken as i128 + beyond as i128) / 2) as i64;
            if accepts(middle) {
                taken = middle;
            } else {
                beyond = middle;
            }
        }
        taken
    };
    Some((edge(inside, i64::MIN), edge(inside, i64::MAX)))
}

/// What the help `help` says an empty value means: the text of its "[default: ...]", or "default".
fn placeholder(help: &str) -> String {
    help.split_once("[default: ")
        .and_then(|(_, rest)| rest.split_once(']'))
        .map_or_else(|| "default".to_string(), |(default, _)| default.to_string())
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
                let full_help = arg.get_help().map(|h| h.to_string()).unwrap_or_default();
                let help = full_help.split(". ").next().unwrap_or_default().trim_end_matches('.').to_string();
                let heading = arg.get_help_heading().map(str::to_string);
                let kind = kind_of(&command, arg, &value);
                let optional = arg.get_default_values().is_empty();
                Some(Control { long, help, heading, kind, value, optional, placeholder: placeholder(&full_help) })
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
