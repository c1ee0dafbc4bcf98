//! Every example's default picture against `expected/<example>.png` (see `common::check_expected` for the
//! rule and for `UPDATE_EXPECTED=1`).

use crate::common;

macro_rules! regression {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            common::check_expected::<common::examples::$name::Options>(stringify!($name));
        }
    )*};
}

every_example!(regression);

macro_rules! example_names {
    ($($name:ident),*) => {
        [$(stringify!($name)),*]
    };
}

/// The workbook's examples, by name: the registry must hold exactly these (a student's own files in
/// `examples/` are not the workbook's and are not checked).
const WORKBOOK: [&str; 12] = [
    "bitmap_textures",
    "model_transform",
    "environment",
    "reflect_v01",
    "reflect_v02",
    "refract",
    "layered",
    "fresnel",
    "glossy",
    "dispersion",
    "photon_map",
    "scene_file",
];

#[test]
fn the_registry_holds_the_workbooks_examples() {
    assert_eq!(every_example!(example_names), WORKBOOK, "tests/workbook/common/examples.rs is out of date");
}

#[test]
fn every_registered_example_has_its_file_and_expected_picture() {
    for name in every_example!(example_names) {
        for path in [format!("examples/{name}.rs"), format!("expected/{name}.png")] {
            assert!(common::root().join(&path).is_file(), "{path} is missing");
        }
    }
}

#[test]
fn every_expected_picture_belongs_to_a_registered_example() {
    let names = every_example!(example_names);
    for entry in std::fs::read_dir(common::root().join("expected")).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        assert!(names.contains(&stem.as_str()), "{} belongs to no example of the registry", path.display());
    }
}
