//! `--slide` executes only the slides' code: rendered with it, no example reaches a step beyond the slides
//! (src/lesson/beyond.rs), while its default render reaches some. Needs the steps' records:
//! `cargo test --release --features audit-steps --test slide_audit` (one test, so that no other render runs
//! in this process while the records are read).

#[macro_use]
#[path = "workbook/common/mod.rs"]
mod common;

use common::{examples, parse};
use lecture6::app::cli::Example;
use lecture6::lesson::beyond::take_reached;

/// Renders the example at 80x60 with `extra` options, and returns the steps beyond the slides it reached.
fn reached<E: Example>(extra: &[&str]) -> Vec<lecture6::lesson::beyond::Step> {
    take_reached();
    let args = [&["--width", "80", "--height", "60"][..], extra].concat();
    parse::<E>(&args).render().unwrap_or_else(|e| panic!("{args:?}: {e}"));
    take_reached()
}

macro_rules! audit {
    ($($name:ident),*) => {
        let mut failures = Vec::new();
        $(
            let slide = reached::<examples::$name::Options>(&["--slide"]);
            if !slide.is_empty() {
                failures.push(format!("{} --slide reached {slide:?}", stringify!($name)));
            }
            let default = reached::<examples::$name::Options>(&[]);
            if default.is_empty() {
                failures.push(format!("{} reached no step by default: the records do not work", stringify!($name)));
            }
        )*
        assert!(failures.is_empty(), "{}", failures.join("\n"));
    };
}

#[test]
fn slide_reaches_no_step_beyond_the_slides() {
    every_example!(audit);
}
