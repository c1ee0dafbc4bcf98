//! The font the instruments write with: DejaVu Sans Mono, bundled (its licence, `LICENSE-DejaVu.txt`, is
//! beside it), so that captions and charts look the same on every machine and need none of its fonts.

/// DejaVu Sans Mono, as a TrueType file.
pub const DEJAVU_SANS_MONO: &[u8] = include_bytes!("DejaVuSansMono.ttf");
