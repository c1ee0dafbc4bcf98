//! One of the workbook's examples drawn with your functions (each exercise handed out):
//!
//! ```sh
//! cargo run --release -p exercises --example draw -- refract            # writes out/refract.png
//! cargo run --release -p exercises --example draw -- fresnel --spp 4    # any of the example's options
//! ```
//!
//! It runs the example as its own binary does (`cargo run --release --example refract`), with the same options
//! and the same picture, but with your functions registered with the renderer first. A function not written
//! yet stops it at its `todo!()`; the grader (`cargo test --release -p exercises`) draws around those.

use std::process::ExitCode;

fn main() -> ExitCode {
    exercises::answers::register();
    exercise_grader::draw::main()
}
