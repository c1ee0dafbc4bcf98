//! The files a run reads, the threads it runs on and the errors it reports: not a slide's lesson, the layer
//! below it. Every file a scene is read from is checked before it is opened ([`input`]), every image is
//! charged to the run's pixel budget from its header before it is decoded ([`image_file`]) and read as its
//! codes mean ([`encoding`]), every picture is written whole or not at all ([`output`]), the worker threads
//! have the stack the recursion needs ([`workers`]), and every error a user can cause names the file or the
//! value at fault in one line ([`error`]). The lesson re-exports them under its own name
//! (`lecture6::lesson::error`, ...), as they always were.

pub mod encoding;
pub mod error;
pub mod image_file;
pub mod input;
pub(crate) mod obj;
pub mod output;
pub mod workers;
