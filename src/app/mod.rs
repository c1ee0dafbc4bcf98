//! The application: the command line, the workbook's files and scenes, the course's scene files.

pub mod assets;
pub mod cli;
pub mod scene_file;
pub mod workbook;
