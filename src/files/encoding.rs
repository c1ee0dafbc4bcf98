//! How the codes of an 8-bit picture stand for light, when a file is read and when a picture is written.
//!
//! The correct reading, and the workbook's: 8-bit files (PNG, JPEG, BMP) hold sRGB codes, so a texture is
//! decoded to linear light before it is lit and the linear light of a render is encoded before it is written
//! ([`crate::lesson::color`]). The course's lecture-6 program takes a code over 255 as the light itself, both
//! ways: its floor texture is lit as it is stored, and its frame is written as it was computed (`Color::toRGB32`
//! clamps and scales by 255, with no transfer curve). Lighting in those codes is lighting in the wrong space
//! (a texel lit at half strength comes out at half its code, where half its light is 73% of its code), but it
//! is what the class's pictures show: `--encoding raw` renders them so, the files read and the picture written
//! alike (docs/techniques.md, "The course's look").

use std::cell::Cell;

/// What an 8-bit code means.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    /// sRGB: the code is the sRGB transfer curve of the light (decoded when read, encoded when written).
    #[default]
    Srgb,
    /// The course's lecture-6 convention: the code over 255 is the light itself, with no curve either way.
    Raw,
}

thread_local! {
    /// How the 8-bit files read on this thread are decoded.
    static READING: Cell<Encoding> = const { Cell::new(Encoding::Srgb) };
}

/// Runs `read` with the 8-bit files it reads on this thread taken as `encoding` says, then restores the
/// reading before (also if `read` panics). The command line builds a scene inside it, so that every texture
/// and environment the scene loads is read one way.
pub fn reading_as<T>(encoding: Encoding, read: impl FnOnce() -> T) -> T {
    struct Restore(Encoding);
    impl Drop for Restore {
        fn drop(&mut self) {
            READING.set(self.0);
        }
    }
    let _restore = Restore(READING.replace(encoding));
    read()
}

/// How an 8-bit file read now on this thread is decoded: sRGB unless inside [`reading_as`].
pub fn reading() -> Encoding {
    READING.get()
}
