//! The instruments: what makes the lesson visible.

pub mod compare;
pub mod debug_view;
pub mod font;
pub mod progressive;
pub mod ray_tree;
pub mod side_by_side;
pub mod study;
#[cfg(feature = "viewer")]
pub mod viewer;
