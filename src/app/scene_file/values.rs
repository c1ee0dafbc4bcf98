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
/// space), in the grammar of C's `strtod`: decimal (`5.`, `.5`, `1e-3`, `-2`), hexadecimal (`0x1p3` is 8,
/// `0x.8` is 0.5), `inf`, `infinity` and `nan`. Where a part is incomplete the number ends before it, as in
/// C: `2e` is 2, `0x` is 0 (followed by `x`), `0x1p` is 1.
pub fn leading_float(s: &str) -> Option<(f64, &str)> {
    let t = s.trim_start_matches(is_space);
    let b = t.as_bytes();
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let negative = b.first() == Some(&b'-');
    let lower = t[i..].to_ascii_lowercase();
    for word in ["infinity", "inf", "nan"] {
        if lower.starts_with(word) {
            let v = if word == "nan" { f64::NAN } else { f64::INFINITY };
            return Some((if negative { -v } else { v }, &t[i + word.len()..]));
        }
    }
    if lower.starts_with("0x")
        && let Some((v, length)) = hex_float(&b[i + 2..])
    {
        return Some((if negative { -v } else { v }, &t[i + 2 + length..]));
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

/// The hexadecimal float whose digits begin `b` (after its `0x`), and how many bytes it takes: hexadecimal
/// digits with at most one point among them, then an optional binary exponent (`p`, an optional sign,
/// decimal digits). None if there is no digit. The value is rounded to the nearest `f64` as `strtod` rounds
/// it: the first 61 to 64 bits of the digits are kept exactly, and any nonzero digit after them marks the
/// lowest bit, which is below every bit an `f64` keeps but decides the rounding.
fn hex_float(b: &[u8]) -> Option<(f64, usize)> {
    let (mut mantissa, mut exponent, mut digits, mut inexact, mut point) = (0u64, 0i64, 0, false, false);
    let mut i = 0;
    loop {
        match b.get(i) {
            Some(b'.') if !point => point = true,
            Some(&c) if c.is_ascii_hexdigit() => {
                digits += 1;
                let digit = u64::from((c as char).to_digit(16)?);
                // Four more bits fit while the top four are free.
                if mantissa >> 60 == 0 {
                    mantissa = mantissa * 16 + digit;
                    exponent -= if point { 4 } else { 0 };
                } else {
                    inexact |= digit != 0;
                    exponent += if point { 0 } else { 4 };
                }
            }
            _ => break,
        }
        i += 1;
    }
    if digits == 0 {
        return None;
    }
    if matches!(b.get(i), Some(b'p' | b'P')) {
        let mut j = i + 1 + usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
        let start = j;
        let mut power = 0i64;
        while let Some(&d) = b.get(j).filter(|c| c.is_ascii_digit()) {
            // Past 2^20 every value is 0 or infinite already: the count stops there rather than overflow.
            power = (power * 10 + i64::from(d - b'0')).min(1 << 20);
            j += 1;
        }
        if j > start {
            exponent += if b[i + 1] == b'-' { -power } else { power };
            i = j;
        }
    }
    Some((times_power_of_two((mantissa | u64::from(inexact)) as f64, exponent), i))
}

/// `x` times 2^`exponent`, in steps whose factor is itself an `f64` (2^±1000 at most): exact unless the
/// result leaves the range of `f64`.
fn times_power_of_two(mut x: f64, mut exponent: i64) -> f64 {
    const STEP: i64 = 1000;
    while exponent.abs() > STEP && x != 0.0 && x.is_finite() {
        let step = STEP * exponent.signum();
        x *= 2f64.powi(step as i32);
        exponent -= step;
    }
    x * 2f64.powi(exponent.clamp(-STEP, STEP) as i32)
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
        assert_eq!(leading_float("0x1p3"), Some((8.0, "")));
        assert_eq!(leading_float("-0X.8P+1,"), Some((-1.0, ",")));
        assert_eq!(leading_float("0x1.8 2"), Some((1.5, " 2")));
        assert_eq!(leading_float("0x"), Some((0.0, "x")));
        assert_eq!(leading_float("0x.p1"), Some((0.0, "x.p1")));
        assert_eq!(leading_float("0x1p"), Some((1.0, "p")));
        assert_eq!(leading_float("0x1p-1074"), Some((f64::from_bits(1), "")));
        assert_eq!(leading_float("0x1p1024").map(|v| v.0), Some(f64::INFINITY));
        assert_eq!(leading_float("0x1p-99999999999999999999").map(|v| v.0), Some(0.0));
        // 2^64 + 1: the 1 past the kept bits rounds as strtod rounds it (down, to 2^64); 2^53 + 1 + 2^-60
        // is above the halfway point and rounds up.
        assert_eq!(leading_float("0x10000000000000001").map(|v| v.0), Some(2f64.powi(64)));
        assert_eq!(leading_float("0x20000000000000.1").map(|v| v.0), Some(2f64.powi(53)));
        assert_eq!(leading_float("0x20000000000001.00000000000001").map(|v| v.0), Some(2f64.powi(53) + 2.0));
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
