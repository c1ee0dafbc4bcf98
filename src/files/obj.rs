//! The OBJ files a mesh is read from (not a slide's lesson): the text as tobj reads it, every face index
//! checked before it does, and tobj's errors with the line they are about.

/// The text of an OBJ file as tobj reads it, and whether it has polylines: without a UTF-8 byte-order mark,
/// with any byte that is not UTF-8 (a Latin-1 letter in a comment or a group name, where the file's numbers
/// never are) replaced by U+FFFD, so that one such byte does not make the whole file unreadable, and with
/// its polylines (`l` lines) made comments: tobj reads them as faces, which would fill the polygon a
/// polyline outlines; a carriage return alone (the line end of classic Mac OS files) ends a line, as a
/// newline does: tobj would read the whole file as its first line. Lines keep their numbers.
pub(crate) fn text(bytes: &[u8]) -> (String, bool) {
    let text = String::from_utf8_lossy(bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes));
    let text = match text.contains('\r') {
        true => std::borrow::Cow::Owned(text.replace("\r\n", "\n").replace('\r', "\n")),
        false => text,
    };
    let is_polyline = |line: &str| {
        let mut words = line.split_ascii_whitespace();
        words.next() == Some("l")
    };
    if !text.lines().any(is_polyline) {
        return (text.into_owned(), false);
    }
    let lines: Vec<String> =
        text.split('\n').map(|line| if is_polyline(line) { format!("#{line}") } else { line.to_string() }).collect();
    (lines.join("\n"), true)
}

/// Checks every index of the faces of the OBJ text `text` (its vertices, texture coordinates and normals)
/// before tobj reads it, and names the line of the first that names an element the file does not have, with
/// how many it has. OBJ indices count from 1, and negative ones back from the last element listed so far.
/// tobj checks vertex indices only once the whole object is read, so it cannot say where, and it drops a
/// normal or texture coordinate index that names nothing (`f 1//1 2//2 3//3` in a file without `vn`), or
/// reads one that counts back past the first, without a word.
pub(crate) fn check_face_indices(text: &str) -> std::result::Result<(), String> {
    const KINDS: [&str; 3] = ["v", "vt", "vn"];
    const NAMES: [(&str, &str); 3] =
        [("vertex", "vertices"), ("texture coordinate", "texture coordinates"), ("normal", "normals")];
    let kind = |line: &str| line.split_ascii_whitespace().next().and_then(|k| KINDS.iter().position(|&x| x == k));
    let mut total = [0i64; 3];
    for slot in text.lines().filter_map(kind) {
        total[slot] += 1;
    }
    let mut so_far = [0i64; 3];
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_ascii_whitespace();
        if words.next() != Some("f") {
            if let Some(slot) = kind(line) {
                so_far[slot] += 1;
            }
            continue;
        }
        for corner in words {
            // An empty index (`1//3`) names nothing; one that is not a number is tobj's to refuse.
            let indices = corner.split('/').take(3).enumerate();
            for (slot, index) in indices.filter_map(|(slot, part)| Some((slot, part.parse::<i64>().ok()?))) {
                let (one, many) = NAMES[slot];
                let line = i + 1;
                if index < 0 && -index > so_far[slot] {
                    return Err(format!(
                        "line {line}: face {one} index {index} counts back past the first: the file has {} {many} \
                         before this line",
                        so_far[slot]
                    ));
                }
                if !(index < 0 || (1..=total[slot]).contains(&index)) {
                    return Err(format!(
                        "line {line}: face {one} index {index}, and the file has {} {many}",
                        total[slot]
                    ));
                }
            }
        }
    }
    Ok(())
}

/// tobj's error for an OBJ file, with the line it stopped at when the error is about one line (tobj reads
/// the file line by line and stops at the first bad one; `consumed` bytes had been read by then).
pub(crate) fn error(bytes: &[u8], consumed: usize, e: tobj::LoadError) -> String {
    use tobj::LoadError::*;
    match e {
        PositionParseError
        | NormalParseError
        | TexcoordParseError
        | FaceParseError
        | UnrecognizedCharacter
        | InvalidPolygon
        | ScalingByZeroError
        | ColorParseError => {
            // The bad line's own newline was read too.
            let line = bytes[..consumed.saturating_sub(1)].iter().filter(|&&b| b == b'\n').count() + 1;
            format!("line {line}: {e}")
        }
        ReadError => format!("{e} (not a text file?)"),
        e => e.to_string(),
    }
}
