//! One of the workbook's examples drawn with the student's functions, by name: the body of
//! `cargo run --release -p exercises --example draw -- refract`, which registers them first.

use lecture6::app::cli::run_as;
use std::process::ExitCode;

/// Runs the example named by the first argument, with the rest as its options, as its own binary does
/// (`out/<name>.png`); an unknown name is refused with the list of names.
pub fn main() -> ExitCode {
    let mut argv = std::env::args_os().skip(1);
    let name = argv.next().map(|name| name.to_string_lossy().into_owned()).unwrap_or_default();
    macro_rules! by_name {
        ($($example:ident),*) => {
            match name.as_str() {
                $(stringify!($example) => run_as::<crate::examples::$example::Options>(&name, argv.collect()),)*
                _ => {
                    let names = [$(stringify!($example)),*].join(", ");
                    eprintln!(
                        "draw: error: {name:?} is not one of the workbook's examples ({names}): \
                         `cargo run --release -p exercises --example draw -- refract`"
                    );
                    ExitCode::from(2)
                }
            }
        };
    }
    every_example!(by_name)
}
