//! The instruments: what makes the lesson visible, and how its light becomes the picture that is shown
//! ([`tone_mapping`]).

pub mod compare;
pub mod debug_view;
pub mod font;
pub mod progressive;
pub mod ray_tree;
pub mod side_by_side;
pub mod study;
pub mod test_kit;
pub mod tone_mapping;
pub mod viewer;
