//! Reading property values as the course does (format spec, section 1.6): numbers are C's leading
//! numbers (`scanf`: leading white space skipped, the longest valid prefix taken, the rest ignored),
//! colours and vectors are three numbers with `(`, `)` and `,` read as spaces, and a bool is false only
//! when it is exactly `off`, `false` or `0`.

/// White space as the course reads it: C's `isspace`, which is Rust's ASCII white space and the vertical
/// tab `\v` (spec 1.1).
pub fn is_space(c: char) -> bool {
    c.is_ascii_whitespace() || c == '\u{b}'
}

/// The leading C floating-point number of `s` and what follows it, if `s` starts with one (after white
/// space): `5.`, `.5`, `1e-3`, `-2`, `inf`, `nan`. Hexadecimal floats are not read (no course file has one).
pub fn leading_float(s: &str) -> Option<(f64, &str)> {
    let t = s.trim_start_matches(is_space);
    let b = t.as_bytes();
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let lower = t[i..].to_ascii_lowercase();
    for word in ["infinity", "inf", "nan"] {
        if lower.starts_with(word) {
            let v = if word == "nan" { f64::NAN } else { f64::INFINITY };
            return Some((if b[0] == b'-' { -v } else { v }, &t[i + word.len()..]));
        }
    }
    let digits = |i: &mut usize| {
        let start = *i;
        while b.get(*i).is_some_and(u8::is_ascii_digit) {
            *i += 1;
        }
        *i - start
    };
    let mut mantissa = digits(&mut i);
    if b.get(i) == Some(&b'.') {
        i += 1;
        mantissa += digits(&mut i);
    }
    if mantissa == 0 {
        return None;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let mut j = i + 1 + usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
        if digits(&mut j) > 0 {
            i = j;
        }
    }
    t[..i].parse().ok().map(|v| (v, &t[i..]))
}

/// The leading decimal integer of `s` (`12abc` is 12, `1.9` is 1, `0x10` is 0).
pub fn leading_int(s: &str) -> Option<i64> {
    let t = s.trim_start_matches(is_space);
    let b = t.as_bytes();
    let sign = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let end = sign + b[sign..].iter().take_while(|c| c.is_ascii_digit()).count();
    (end > sign).then(|| t[..end].parse().ok()).flatten()
}

/// Three numbers, as colours, vectors and transform triples are written: `(1, 0.5, 0)`, `1 0.5 0`.
pub fn triple(s: &str) -> Option<[f64; 3]> {
    let spaced: String = s.chars().map(|c| if matches!(c, '(' | ')' | ',') { ' ' } else { c }).collect();
    let (x, rest) = leading_float(&spaced)?;
    let (y, rest) = leading_float(rest)?;
    let (z, _) = leading_float(rest)?;
    Some([x, y, z])
}

/// The course's bool: false only for exactly `off`, `false` or `0`; the second value says whether the
/// spelling is one of the usual ones (`on`, `true`, `1`, `yes` and the three false ones), so that `False`
/// or `no`, which the course reads as true, can be warned about.
pub fn boolean(s: &str) -> (bool, bool) {
    let value = !matches!(s, "off" | "false" | "0");
    (value, matches!(s, "off" | "false" | "0" | "on" | "true" | "1" | "yes"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_read_as_c_reads_them() {
        assert_eq!(leading_float(" 5.").map(|v| v.0), Some(5.0));
        assert_eq!(leading_float(".5x").map(|v| v.0), Some(0.5));
        assert_eq!(leading_float("1e-3").map(|v| v.0), Some(1e-3));
        assert_eq!(leading_float("2e").map(|v| v.0), Some(2.0));
        assert_eq!(leading_float("5,5").map(|v| v.0), Some(5.0));
        assert_eq!(leading_float("-inf").map(|v| v.0), Some(f64::NEG_INFINITY));
        assert_eq!(leading_float("abc"), None);
        assert_eq!(leading_float("."), None);
        assert_eq!(leading_int("12abc"), Some(12));
        assert_eq!(leading_int("1.9"), Some(1));
        assert_eq!(leading_int("0x10"), Some(0));
        assert_eq!(leading_int("-"), None);
        assert_eq!(triple("(278. 273. -800)"), Some([278.0, 273.0, -800.0]));
        assert_eq!(triple("(1 0.5 0"), Some([1.0, 0.5, 0.0]));
        assert_eq!(triple("1,0.5,0 extra"), Some([1.0, 0.5, 0.0]));
        assert_eq!(triple("(1, 2)"), None);
        assert_eq!(boolean("off"), (false, true));
        assert_eq!(boolean("False"), (true, false));
        assert_eq!(boolean("yes"), (true, true));
    }
}
