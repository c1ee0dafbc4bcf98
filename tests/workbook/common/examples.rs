//! The workbook's own examples, the one list of them: each example file is included here as a module, so
//! the regression, determinism, stress and bad-input tests, the benchmarks and the study render the very
//! scene a student reads in `examples/<name>.rs`. `every_example!(m)` expands `m! { name, name, ... }`.
//!
//! A file of the student's own in `examples/` is not in this list: no test renders it or compares its picture
//! (`cargo test` still compiles it, as every example); `tests/workbook/regression.rs` checks that every
//! example listed here exists and has its expected picture.

macro_rules! registry {
    ($($name:ident => $path:literal),* $(,)?) => {
        $(
            #[allow(dead_code)] // each example's `main` is its binary's, not the tests'
            #[path = $path]
            pub mod $name;
        )*

        /// Expands `$test! { name, name, ... }` with every example of the workbook.
        #[allow(unused_macros)]
        macro_rules! every_example {
            ($test:ident) => { $test! { $($name),* } };
        }
    };
}

registry! {
    bitmap_textures => "../../../examples/bitmap_textures.rs",
    model_transform => "../../../examples/model_transform.rs",
    environment => "../../../examples/environment.rs",
    reflect_v01 => "../../../examples/reflect_v01.rs",
    reflect_v02 => "../../../examples/reflect_v02.rs",
    refract => "../../../examples/refract.rs",
    layered => "../../../examples/layered.rs",
    fresnel => "../../../examples/fresnel.rs",
    glossy => "../../../examples/glossy.rs",
    dispersion => "../../../examples/dispersion.rs",
    photon_map => "../../../examples/photon_map.rs",
    scene_file => "../../../examples/scene_file.rs",
}
