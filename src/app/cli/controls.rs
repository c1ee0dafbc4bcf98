//! The live window's controls made from an example's command line: every option of its clap command
//! (the example's own and the common ones) becomes a [`Control`] of the kind its definition asks for: a
//! flag a check box, an option with possible values a choice, a whole number a drag value within the range
//! its parser takes, a real number a drag value, anything else a text field. The window reads a changed
//! control back through the example's own parser ([`ExampleOptions::from_controls`], implemented in
//! `instruments.rs` beside this file).
//!
//! [`ExampleOptions::from_controls`]: crate::instruments::viewer::ExampleOptions::from_controls

use super::example::{Cli, Example};
use crate::instruments::viewer::controls::{Control, Controls, Kind, StepBox};
use crate::lesson::beyond::Step;
use clap::ArgAction;
use clap::error::ErrorKind;
use clap::parser::ValueSource;
use std::any::TypeId;
use std::ffi::OsString;

/// Options (by their ids) that make no sense as a control: the window is already open; saving, comparing
/// and printing are the window's buttons (the defaults are printed for the class command only); a click on
/// the picture traces a pixel; debug views and side by side pictures are files the command line writes; the
/// render threads are started once, with the window; the interface's scale is the window's own control. The steps beyond the slides are check boxes of their
/// own ([`Controls::steps`]) in place of the options that spell them.
const NOT_CONTROLS: [&str; 19] = [
    "help",
    "version",
    "window",
    "output",
    "quiet",
    "print_defaults",
    "compare",
    "trace_pixel",
    "trace_sample",
    "trace_format",
    "view",
    "legend_max",
    "side_by_side",
    "threads",
    "ui_scale",
    "slide",
    "step",
    "no_step",
    "exhaustive",
];

/// Options (by their ids) that are no controls but keep the value given on the command line in the window
/// ([`Controls::fixed`]).
const FIXED: [&str; 4] = ["output", "compare", "threads", "ui_scale"];

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

/// The controls of the example `E` called `name`, holding the values of the command line `args` (without the
/// program name).
pub fn controls<E: Example>(name: &str, args: &[OsString]) -> Result<Controls, clap::Error> {
    let mut command = Cli::<E>::command_named(name);
    let argv = std::iter::once(OsString::from(name)).chain(args.iter().cloned());
    let matches = command.try_get_matches_from_mut(argv)?;
    let steps = <Cli<E> as clap::FromArgMatches>::from_arg_matches(&matches)?.steps();
    let steps = Step::ALL
        .into_iter()
        .map(|step| StepBox { name: step.name().into(), summary: step.summary().into(), taken: steps.has(step) })
        .collect();
    let fixed = command
        .get_arguments()
        .filter(|arg| FIXED.contains(&arg.get_id().as_str()))
        .filter(|arg| matches.value_source(arg.get_id().as_str()) == Some(ValueSource::CommandLine))
        .flat_map(|arg| {
            let long = format!("--{}", arg.get_long().unwrap_or_default());
            let values = matches.get_raw(arg.get_id().as_str()).into_iter().flatten();
            values.flat_map(move |v| [long.clone(), v.to_string_lossy().into_owned()])
        })
        .collect();
    let controls: Vec<Control> = command
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
        .collect();
    Ok(Controls::new(name, controls, steps, fixed))
}
