//! Every example's default picture against `expected/<example>.png` (see `common::check_expected` for the
//! rule and for `UPDATE_EXPECTED=1`).

#[macro_use]
mod common;

macro_rules! regression {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            common::check_expected::<lecture6::scenes::$name::Args>();
        }
    )*};
}

every_example!(regression);

macro_rules! example_names {
    ($($name:ident),*) => {
        [$(stringify!($name)),*]
    };
}

#[test]
fn every_example_is_checked() {
    let mut on_disk: Vec<String> = std::fs::read_dir(common::root().join("examples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    assert_eq!(on_disk, every_example!(example_names), "tests/common/mod.rs's every_example! is out of date");
}
