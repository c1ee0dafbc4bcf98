//! What an example and its window say to each other, and how it goes through the pipe between them: the
//! window ([`Request`]) asks for a render of new options or from a moved camera, for a pixel's ray tree, to
//! save or compare the picture; the example ([`Report`]) sends its options as controls, the pixels as they
//! are drawn, how far the render is, and the answers.
//!
//! Each message is its length (4 bytes, little-endian) and then its fields in order: numbers little-endian,
//! text and lists as their length and then their items, an enum as the number of its variant and then its
//! fields. A few messages of numbers, text and pixels: written here rather than with a serialization
//! crate, which every student's build of the library would compile.

use crate::controls::{Control, Controls, Kind, StepBox};
use std::io::{self, Read, Write};

/// What the window asks of the example.
#[derive(Clone, Debug)]
pub enum Request {
    /// The controls changed: read them as the command line would, and render what they say.
    Options {
        /// The controls as the window shows them.
        controls: Controls,
    },
    /// Move the camera along its own axes (each in -1..=1, times `distance` scene units) and turn it (in
    /// degrees), and draw the quick preview of a moving camera.
    Move {
        /// Towards where the camera looks.
        forward: f32,
        /// Towards the picture's right edge.
        right: f32,
        /// Towards the picture's top edge.
        up: f32,
        /// Degrees to turn; positive turns left.
        yaw: f32,
        /// Degrees to tilt; positive looks up.
        pitch: f32,
        /// Degrees to roll.
        roll: f32,
        /// Scene units per unit of motion.
        distance: f32,
    },
    /// The camera has stopped: render the full picture from where it is.
    Settle {},
    /// Back to the scene's own camera.
    ResetCamera {},
    /// What pixel (x, y) of the picture sees: its ray tree.
    Inspect {
        /// Column, from the left.
        x: u32,
        /// Row, from the top.
        y: u32,
    },
    /// Save the finished picture in the format of the extension `ext` (`png`, `exr`).
    Save {
        /// The file name's extension.
        ext: String,
    },
    /// Compare the finished picture with the reference.
    Compare {},
}

/// What the example tells the window.
#[derive(Clone, Debug)]
pub enum Report {
    /// The first message: the example's name, its options as controls, the interface's scale, and the pixel
    /// whose ray tree to show from the start (`--trace-pixel`).
    Hello {
        /// The example's name (`fresnel`).
        name: String,
        /// Its options as controls.
        controls: Controls,
        /// The interface's scale (`--ui-scale`).
        ui_scale: f32,
        /// `--trace-pixel`'s pixel.
        pixel: Option<(u32, u32)>,
    },
    /// Pixels of the picture shown: the picture is `width` x `height`, and the rectangle at (`x`, `y`) of
    /// `w` x `h` pixels is `rgb`, 8-bit sRGB, row by row.
    Pixels {
        /// The picture's width.
        width: u32,
        /// The picture's height.
        height: u32,
        /// The rectangle's left column.
        x: u32,
        /// The rectangle's top row.
        y: u32,
        /// The rectangle's width.
        w: u32,
        /// The rectangle's height.
        h: u32,
        /// Its pixels.
        rgb: Vec<u8>,
    },
    /// How far the picture is.
    Status {
        /// What the status line says.
        status: Status,
    },
    /// A line to show: a bad value, where a picture was saved, a comparison's figures; empty clears it.
    Message {
        /// The line.
        text: String,
    },
    /// What the pixel the window asked about sees.
    Picked {
        /// Its column.
        x: u32,
        /// Its row.
        y: u32,
        /// The node and shader its first camera ray hits.
        sees: String,
        /// Its ray tree, as `--trace-pixel` prints it.
        tree: String,
    },
    /// The heat map of the comparison, 8-bit RGB, to show instead of the picture.
    HeatMap {
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
        /// Its pixels, row by row.
        rgb: Vec<u8>,
    },
}

/// How far the picture shown is, for the status line.
#[derive(Clone, Debug, Default)]
pub struct Status {
    /// Samples per pixel of what is shown (1 for the coarse pass and the moving preview).
    pub spp: u32,
    /// Tiles of the full-quality picture drawn.
    pub tiles_done: u32,
    /// Tiles of the full-quality picture in all.
    pub tiles_total: u32,
    /// Seconds the render has taken so far (the render's own time once finished).
    pub seconds: f64,
    /// Rays traced for what is shown: once finished, the rays the command line counts.
    pub rays: u64,
    /// Pictures the moving camera showed in the last second, while it moves.
    pub frames_last_second: u32,
    /// The full-quality picture is finished: it can be saved and compared.
    pub finished: bool,
    /// Building or rendering failed: the message.
    pub error: Option<String>,
    /// The camera of the picture shown, once there is a scene.
    pub camera: Option<CameraShown>,
}

/// The camera of the picture shown, as the window shows it.
#[derive(Clone, Debug, Default)]
pub struct CameraShown {
    /// Where it is and where it looks, in one line.
    pub text: String,
    /// The Rust that builds it, to paste into an example's scene.
    pub code: String,
    /// Its distance from the origin (the examples are built around it): what sets the keys' speed.
    pub distance: f32,
    /// Its field of view, in degrees: what sets how far a drag turns it.
    pub fov: f32,
}

/// The largest message read: a picture of the largest size the renderer makes (2^26 pixels, 3 bytes each),
/// and room for the rest.
const MAX_MESSAGE: usize = 3 << 26 | 1 << 20;

/// Writes `message` to `out` and flushes it.
pub fn send<T: Wire>(out: &mut impl Write, message: &T) -> io::Result<()> {
    let mut bytes = Vec::new();
    message.put(&mut bytes);
    out.write_all(&(bytes.len() as u32).to_le_bytes())?;
    out.write_all(&bytes)?;
    out.flush()
}

/// Reads the next message from `input`; an error at the end of the input or a message that makes no sense.
pub fn receive<T: Wire>(input: &mut impl Read) -> io::Result<T> {
    let mut length = [0; 4];
    input.read_exact(&mut length)?;
    let length = u32::from_le_bytes(length) as usize;
    if length > MAX_MESSAGE {
        return Err(malformed(format!("a message of {length} bytes")));
    }
    let mut bytes = vec![0; length];
    input.read_exact(&mut bytes)?;
    let mut rest = bytes.as_slice();
    let message = T::take(&mut rest)?;
    if !rest.is_empty() {
        return Err(malformed(format!("{} bytes after the message", rest.len())));
    }
    Ok(message)
}

fn malformed(what: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, format!("the window's pipe: {what}"))
}

/// A value that goes through the pipe.
pub trait Wire: Sized {
    /// Appends the value's bytes to `out`.
    fn put(&self, out: &mut Vec<u8>);
    /// Reads a value from the front of `input`, advancing it.
    fn take(input: &mut &[u8]) -> io::Result<Self>;
}

/// The first `n` bytes of `input`, taken off it.
fn bytes<'a>(input: &mut &'a [u8], n: usize) -> io::Result<&'a [u8]> {
    if input.len() < n {
        return Err(malformed(format!("{n} bytes wanted, {} left", input.len())));
    }
    let (head, tail) = input.split_at(n);
    *input = tail;
    Ok(head)
}

macro_rules! wire_numbers {
    ($($t:ty),*) => {$(
        impl Wire for $t {
            fn put(&self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
            fn take(input: &mut &[u8]) -> io::Result<Self> {
                let b = bytes(input, size_of::<$t>())?;
                Ok(<$t>::from_le_bytes(b.try_into().expect("as many bytes as the number has")))
            }
        }
    )*};
}

wire_numbers!(u8, u32, u64, f32, f64);

impl Wire for bool {
    fn put(&self, out: &mut Vec<u8>) {
        u8::from(*self).put(out);
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        Ok(u8::take(input)? != 0)
    }
}

impl Wire for String {
    fn put(&self, out: &mut Vec<u8>) {
        (self.len() as u32).put(out);
        out.extend_from_slice(self.as_bytes());
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        let n = u32::take(input)? as usize;
        String::from_utf8(bytes(input, n)?.to_vec()).map_err(|e| malformed(e.to_string()))
    }
}

impl<T: Wire> Wire for Vec<T> {
    fn put(&self, out: &mut Vec<u8>) {
        (self.len() as u32).put(out);
        self.iter().for_each(|item| item.put(out));
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        let n = u32::take(input)? as usize;
        // Each item is at least a byte: a length beyond what is left is a broken message, not an allocation.
        if n > input.len() {
            return Err(malformed(format!("a list of {n} items in {} bytes", input.len())));
        }
        (0..n).map(|_| T::take(input)).collect()
    }
}

impl<T: Wire> Wire for Option<T> {
    fn put(&self, out: &mut Vec<u8>) {
        self.is_some().put(out);
        if let Some(value) = self {
            value.put(out);
        }
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        Ok(if bool::take(input)? { Some(T::take(input)?) } else { None })
    }
}

impl<A: Wire, B: Wire> Wire for (A, B) {
    fn put(&self, out: &mut Vec<u8>) {
        self.0.put(out);
        self.1.put(out);
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        Ok((A::take(input)?, B::take(input)?))
    }
}

/// A struct, field by field: `wire_struct!(Name { field, ... })`.
macro_rules! wire_struct {
    ($name:ident { $($field:ident),* $(,)? }) => {
        impl Wire for $name {
            fn put(&self, out: &mut Vec<u8>) {
                $(self.$field.put(out);)*
            }
            fn take(input: &mut &[u8]) -> io::Result<Self> {
                Ok($name { $($field: Wire::take(input)?),* })
            }
        }
    };
}

/// An enum whose variants have named fields (or none: `Variant {}`), by the number of its variant:
/// `wire_enum!(Name { 0 => Variant { field, ... }, ... })`.
macro_rules! wire_enum {
    ($name:ident { $($tag:literal => $variant:ident { $($field:ident),* $(,)? }),* $(,)? }) => {
        impl Wire for $name {
            fn put(&self, out: &mut Vec<u8>) {
                match self {
                    $($name::$variant { $($field),* } => {
                        ($tag as u8).put(out);
                        $($field.put(out);)*
                    })*
                }
            }
            fn take(input: &mut &[u8]) -> io::Result<Self> {
                match u8::take(input)? {
                    $($tag => Ok($name::$variant { $($field: Wire::take(input)?),* }),)*
                    other => Err(malformed(format!("no {} number {other}", stringify!($name)))),
                }
            }
        }
    };
}

wire_enum!(Request {
    0 => Options { controls },
    1 => Move { forward, right, up, yaw, pitch, roll, distance },
    2 => Settle {},
    3 => ResetCamera {},
    4 => Inspect { x, y },
    5 => Save { ext },
    6 => Compare {},
});

wire_enum!(Report {
    0 => Hello { name, controls, ui_scale, pixel },
    1 => Pixels { width, height, x, y, w, h, rgb },
    2 => Status { status },
    3 => Message { text },
    4 => Picked { x, y, sees, tree },
    5 => HeatMap { width, height, rgb },
});

wire_struct!(Status { spp, tiles_done, tiles_total, seconds, rays, frames_last_second, finished, error, camera });

wire_struct!(CameraShown { text, code, distance, fov });

wire_struct!(StepBox { name, summary, taken });

wire_struct!(Control { long, help, heading, kind, value, optional, placeholder });

impl Wire for Controls {
    fn put(&self, out: &mut Vec<u8>) {
        self.name().to_string().put(out);
        self.controls.put(out);
        self.steps.put(out);
        self.fixed.put(out);
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        let name = String::take(input)?;
        let (controls, steps, fixed) = (Wire::take(input)?, Wire::take(input)?, Wire::take(input)?);
        Ok(Controls::new(&name, controls, steps, fixed))
    }
}

impl Wire for Kind {
    fn put(&self, out: &mut Vec<u8>) {
        match self {
            Kind::Flag => 0u8.put(out),
            Kind::Choice(choices) => {
                1u8.put(out);
                choices.put(out);
            }
            Kind::Integer { min, max } => {
                2u8.put(out);
                min.put(out);
                max.put(out);
            }
            Kind::Real => 3u8.put(out),
            Kind::Text => 4u8.put(out),
        }
    }
    fn take(input: &mut &[u8]) -> io::Result<Self> {
        Ok(match u8::take(input)? {
            0 => Kind::Flag,
            1 => Kind::Choice(Wire::take(input)?),
            2 => Kind::Integer { min: Wire::take(input)?, max: Wire::take(input)? },
            3 => Kind::Real,
            4 => Kind::Text,
            other => return Err(malformed(format!("no Kind number {other}"))),
        })
    }
}
