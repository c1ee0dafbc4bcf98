//! The application: the command line, the scenes the examples share, the workbook's files, the course's
//! scene files.

pub mod assets;
pub mod cli;
pub mod limits;
pub mod parameter_ranges;
pub mod scene_file;
pub mod scenes;
pub mod workbook;
