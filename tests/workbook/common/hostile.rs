//! Hostile input for the tests of `tests/workbook/hostile_input.rs` and `tests/workbook/fuzz_scene_file.rs`: running an example
//! binary within a time and memory bound, and making the hostile files (decompression bombs, FIFOs, sparse
//! giants) at run time rather than keeping them in the repository.

use std::ffi::OsStr;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The address space a child may use: far more than any example needs at a small size (about 200 MB), far
/// less than the gigabytes a decompression bomb asks for. An allocation past it fails, and the process
/// aborts: a test sees a signal, not exit code 2.
pub const MEMORY: u64 = 1 << 30;

/// How long a child may run before it counts as hung: far more than any of these runs takes (under a
/// second), so that a loaded machine does not make a test fail.
pub const TIME: Duration = Duration::from_secs(60);

/// What a bounded run did.
#[derive(Debug)]
pub struct Run {
    /// The exit code; `None` when a signal ended the process (an abort, or the kill of a hung one).
    pub code: Option<i32>,
    /// The child was killed because it ran past the time bound.
    pub hung: bool,
    pub stdout: String,
    pub stderr: String,
    pub elapsed: Duration,
}

impl Run {
    /// Fails unless the run was refused as bad input should be: exit code 2, within the bounds, one line on
    /// stderr, no panic and no raw control character, naming each of `needles`.
    pub fn assert_refused(&self, what: &str, needles: &[&str]) {
        assert!(!self.hung, "{what}: hung, killed after {:?}", self.elapsed);
        assert_eq!(self.code, Some(2), "{what}: {self:?}");
        let err = self.stderr.trim_end();
        assert_eq!(err.lines().count(), 1, "{what}: not one line: {err:?}");
        assert!(!err.contains("panicked"), "{what}: {err}");
        assert!(!err.chars().any(|c| c.is_control() || matches!(c, '\u{2028}' | '\u{2029}')), "{what}: {err:?}");
        for needle in needles {
            assert!(err.contains(needle), "{what}: {err:?} does not name {needle:?}");
        }
    }

    /// Fails unless the run succeeded within the bounds.
    pub fn assert_rendered(&self, what: &str) {
        assert!(!self.hung, "{what}: hung, killed after {:?}", self.elapsed);
        assert_eq!(self.code, Some(0), "{what}: {self:?}");
    }
}

/// Runs the example binary `name` with `args` from the package root, with its address space limited to
/// `MEMORY` and killed if it runs longer than `TIME`; `before` is called in the child just before it runs
/// the example (it must not allocate: the parent has other threads).
pub fn run_bounded_with<S: AsRef<OsStr>>(
    name: &str,
    args: &[S],
    before: impl FnMut() -> std::io::Result<()> + Send + Sync + 'static,
) -> Run {
    run_within(MEMORY, name, args, before)
}

/// [`run_bounded`] with the address space limited to `memory` bytes instead of [`MEMORY`] (a user's
/// `ulimit -v`).
pub fn run_bounded_in<S: AsRef<OsStr>>(memory: u64, name: &str, args: &[S]) -> Run {
    run_within(memory, name, args, || Ok(()))
}

/// [`run_bounded_with`], the address space limited to `memory` bytes.
fn run_within<S: AsRef<OsStr>>(
    memory: u64,
    name: &str,
    args: &[S],
    before: impl FnMut() -> std::io::Result<()> + Send + Sync + 'static,
) -> Run {
    use std::os::unix::process::CommandExt;
    let mut command = Command::new(super::example_binary(name));
    command.args(args).current_dir(super::root()).stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped());
    let mut before = before;
    // SAFETY: setrlimit and what `before` does are async-signal-safe system calls; nothing is allocated.
    #[allow(unsafe_code)] // Sound: see the SAFETY comment.
    unsafe {
        command.pre_exec(move || {
            let limit = libc::rlimit { rlim_cur: memory as libc::rlim_t, rlim_max: memory as libc::rlim_t };
            if libc::setrlimit(libc::RLIMIT_AS, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            before()
        });
    }
    let start = Instant::now();
    let mut child = command.spawn().expect("run the example");
    let read = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut pipe) = pipe {
                let _ = pipe.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let stdout = read(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let stderr = read(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let mut hung = false;
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for the example") {
            break status;
        }
        if start.elapsed() > TIME {
            hung = true;
            let _ = child.kill();
            break child.wait().expect("wait for the killed example");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let elapsed = start.elapsed();
    Run {
        code: status.code(),
        hung,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
        elapsed,
    }
}

/// [`run_bounded_with`] with nothing to do in the child first.
pub fn run_bounded<S: AsRef<OsStr>>(name: &str, args: &[S]) -> Run {
    run_bounded_with(name, args, || Ok(()))
}

/// A scratch folder under `target/`, made if needed.
pub fn scratch(name: &str) -> PathBuf {
    let dir = super::root().join("target").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The CRC-32 of PNG chunks (ISO 3309, polynomial 0xedb88320).
pub fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xedb8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// Bits written least significant first, as deflate packs them.
struct Bits {
    bytes: Vec<u8>,
    used: u32,
}

impl Bits {
    /// `count` bits of `value`, least significant first.
    fn put(&mut self, value: u32, count: u32) {
        for i in 0..count {
            if self.used.is_multiple_of(8) {
                self.bytes.push(0);
            }
            *self.bytes.last_mut().unwrap() |= (((value >> i) & 1) as u8) << (self.used % 8);
            self.used += 1;
        }
    }
    /// A Huffman code of `count` bits, which deflate stores most significant bit first.
    fn code(&mut self, code: u32, count: u32) {
        self.put(code.reverse_bits() >> (32 - count), count);
    }
}

/// A zlib stream of `n` zero bytes, in deflate's fixed Huffman codes: one literal zero, then copies of 258
/// bytes at distance 1 (13 bits each), the rest as literals.
fn zlib_zeros(n: u64) -> Vec<u8> {
    let mut bits = Bits { bytes: vec![0x78, 0x01], used: 16 };
    bits.put(1, 1); // the last block
    bits.put(1, 2); // fixed Huffman codes
    let literal_zero = |bits: &mut Bits| bits.code(0x30, 8);
    literal_zero(&mut bits);
    let mut left = n - 1;
    while left >= 258 {
        bits.code(0xc5, 8); // length 258 (symbol 285)
        bits.code(0, 5); // distance 1
        left -= 258;
    }
    for _ in 0..left {
        literal_zero(&mut bits);
    }
    bits.code(0, 7); // end of block (symbol 256)
    let mut bytes = bits.bytes;
    // Adler-32 of n zeros: a stays 1, b adds it n times.
    let adler = (((n % 65521) as u32) << 16) | 1;
    bytes.extend(adler.to_be_bytes());
    bytes
}

/// A PNG chunk: length, type, data, CRC.
fn chunk(kind: &[u8; 4], data: &[u8]) -> Vec<u8> {
    let mut out = (data.len() as u32).to_be_bytes().to_vec();
    let start = out.len();
    out.extend(kind);
    out.extend(data);
    let crc = crc32(&out[start..]);
    out.extend(crc.to_be_bytes());
    out
}

/// A valid PNG of `width` x `height` black 8-bit grey pixels: a few kilobytes of file per million pixels
/// (a decompression bomb, when large).
pub fn black_png(width: u32, height: u32) -> Vec<u8> {
    let mut ihdr = width.to_be_bytes().to_vec();
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 0, 0, 0, 0]); // 8-bit grey, deflate, adaptive filtering, not interlaced
    let data = zlib_zeros(height as u64 * (width as u64 + 1)); // a filter byte before each row
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    png.extend(chunk(b"IHDR", &ihdr));
    png.extend(chunk(b"IDAT", &data));
    png.extend(chunk(b"IEND", &[]));
    png
}

/// Makes a FIFO at `path` (replacing what is there).
pub fn fifo(path: &Path) -> PathBuf {
    let _ = std::fs::remove_file(path);
    let made = Command::new("mkfifo").arg("-m").arg("600").arg(path).status().expect("run mkfifo");
    assert!(made.success(), "mkfifo {}", path.display());
    path.to_path_buf()
}
