//! Every example's default picture against `expected/<example>.png` (see `common::check_expected` for the
//! rule and for `UPDATE_EXPECTED=1`).

mod common;

macro_rules! regression {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            common::check_expected::<lecture6::scenes::$name::Args>();
        }
    )*};
}

regression!(
    bitmap_textures,
    dispersion,
    environment,
    fresnel,
    glossy,
    layered,
    model_transform,
    photon_map,
    reflect_v01,
    reflect_v02,
    refract,
);
