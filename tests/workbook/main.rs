//! The workbook's integration tests, one module per subject (one test binary, so that a first
//! `cargo test` links the library into one program instead of one per file; docs/building.md has the
//! figures). The list of what each module checks is docs/tests.md. Run one subject with a filter, e.g.
//! `cargo test --release --test workbook dispersion::`.

#[macro_use]
mod common;

mod adaptive_aa;
mod assets;
mod bad_input;
mod beyond;
mod branching;
mod captions;
mod caustic_reference;
mod command_line;
mod course_look;
mod cubemap_layout;
mod data_texture;
mod determinism;
mod deviations;
mod diagnostics;
mod dispersion;
mod edge_cases;
mod environment;
mod fuzz_scene_file;
mod glossy;
mod helper_parameters;
mod homework;
mod hostile_files;
mod hostile_input;
mod hostile_third;
mod house;
mod inspect;
mod layered_fresnel;
mod layers;
mod lookup;
mod math;
mod mesh;
mod output;
mod paths;
mod photon_map;
mod plain_path;
mod polygon;
mod progressive;
mod properties;
mod quoted_warnings;
mod reflection_refraction;
mod regression;
mod sampling;
mod scene_file;
mod shader_kit;
mod silent_mistakes;
mod slide;
mod smooth_mesh;
mod step_notes;
mod stress;
mod study;
mod template;
mod transform;
mod viewer;
mod walk;
mod window;
