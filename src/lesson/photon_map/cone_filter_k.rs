/// The cone filter's constant k >= 1 (Jensen's 1.1): the weight of a photon at distance d from the shaded
/// point, in a disc of radius r, is `1 - d / (CONE_FILTER_K * r)`. Written once, in this file, for the
/// workbook's photon map and for the graded exercise (exercises/src/lib.rs includes it), so that the two
/// estimates cannot drift apart.
pub const CONE_FILTER_K: f32 = 1.1;
