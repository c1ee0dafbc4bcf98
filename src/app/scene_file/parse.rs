//! The lexical layer of `.qdmg` files (format spec, section 1): lines, comments, blocks and property lines,
//! each kept with its line number.

use super::values::is_space;

/// The course's 25 element classes (spec 3.0).
pub const CLASSES: [&str; 25] = [
    "GlobalSettings",
    "Camera",
    "PointLight",
    "RectLight",
    "Plane",
    "Sphere",
    "Cube",
    "CsgPlus",
    "CsgAnd",
    "CsgMinus",
    "Mesh",
    "Heightfield",
    "Node",
    "Lambert",
    "Phong",
    "Refl",
    "Refr",
    "Layered",
    "Const",
    "CheckerTexture",
    "BitmapTexture",
    "Fresnel",
    "BumpTexture",
    "Bumps",
    "CubemapEnvironment",
];

/// Lines the course reads whole; longer ones it splits silently, this loader refuses them.
pub const MAX_LINE: usize = 1023;
/// The longest name the course stores.
pub const MAX_NAME: usize = 63;
/// The longest property value the course stores.
pub const MAX_VALUE: usize = 255;

/// One property line of a block: its name, its raw value (quotes removed, spec 1.5) and its line.
#[derive(Clone, Debug)]
pub struct Property {
    /// The property's name, as written (`color`).
    pub name: String,
    /// Its value, as written after the name (quotes removed, spec 1.5).
    pub value: String,
    /// The line it is on (the first line is 1).
    pub line: usize,
}

/// One block: `Class [name] { ... }`.
#[derive(Clone, Debug)]
pub struct Block {
    /// The block's class (`Sphere`, `Lambert`, ...): one of [`CLASSES`].
    pub class: String,
    /// `None` for an unnamed block, which nothing can refer to.
    pub name: Option<String>,
    /// The line of the header.
    pub line: usize,
    /// The line of the closing `}` (where the course reports missing required properties).
    pub end_line: usize,
    /// The block's property lines, in the order written.
    pub properties: Vec<Property>,
}

/// A syntax error: the line and what is wrong there.
#[derive(Clone, Debug)]
pub struct SyntaxError {
    /// The line of the error (the first line is 1).
    pub line: usize,
    /// What is wrong there, in one line.
    pub message: String,
}

/// The block header `tokens` are, if they are one: `Class {` or `Class name {` with a class the course knows.
fn header<'t>(tokens: &[&'t str]) -> Option<(&'t str, Option<&'t str>)> {
    let (class, name) = match *tokens {
        [class, "{"] => (class, None),
        [class, name, "{"] => (class, Some(name)),
        _ => return None,
    };
    CLASSES.contains(&class).then_some((class, name))
}

/// The value `value` if it is one number written with a decimal comma (`0,9`), which the course reads as
/// the number before the comma (`0`): C's `scanf` stops at the comma.
fn decimal_comma(value: &str) -> Option<&str> {
    let (whole, fraction) = value.split_once(',')?;
    let whole = whole.strip_prefix(['+', '-']).unwrap_or(whole);
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    (digits(whole) && digits(fraction)).then_some(value)
}

/// Splits a scene file's text into blocks. `warnings` receives the line-numbered warnings of this layer
/// (a file that ends inside a block comment, a number written with a decimal comma). Lines end at `\n`,
/// or at `\r` in a file without a `\n` (the line ends of classic Mac OS).
pub fn parse(text: &str, warnings: &mut Vec<(usize, String)>) -> Result<Vec<Block>, SyntaxError> {
    let mut blocks = Vec::new();
    let mut open: Option<Block> = None;
    let mut comment_from: Option<usize> = None;
    let err = |line: usize, message: String| Err(SyntaxError { line, message });
    let mut count = 0;
    let end_of_line = if text.contains('\n') { '\n' } else { '\r' };
    for (index, raw) in text.split(end_of_line).enumerate() {
        let line = index + 1;
        count = line;
        if raw.trim_end_matches('\r').len() > MAX_LINE {
            return err(line, format!("the line is longer than {MAX_LINE} characters"));
        }
        if comment_from.is_some() {
            // A block comment closes at a line starting with `*/` in its first column; that line is ignored.
            if raw.starts_with("*/") {
                comment_from = None;
            }
            continue;
        }
        let cut = [raw.find("//"), raw.find('#')].into_iter().flatten().min().unwrap_or(raw.len());
        let content = raw[..cut].trim_matches(is_space);
        if content.is_empty() {
            continue;
        }
        if content.starts_with("/*") {
            comment_from = Some(line);
            continue;
        }
        if content.contains("randfloat(") || content.contains("randint(") {
            return err(line, "the random-number macros randfloat() and randint() are not supported".into());
        }
        let tokens: Vec<&str> = content.split(is_space).filter(|t| !t.is_empty()).collect();
        match &mut open {
            None => {
                let (class, name) = match (header(&tokens), &tokens[..]) {
                    (Some(header), _) => header,
                    (None, &[class, "{"] | &[class, _, "{"]) => {
                        return err(line, format!("unknown object class `{class}`"));
                    }
                    _ => {
                        return err(
                            line,
                            format!("expected a block header `Class {{` or `Class name {{`, found `{content}`"),
                        );
                    }
                };
                if name.is_some_and(|n| n.len() > MAX_NAME) {
                    return err(line, format!("the name is longer than {MAX_NAME} characters"));
                }
                open = Some(Block {
                    class: class.into(),
                    name: name.map(Into::into),
                    line,
                    end_line: line,
                    properties: Vec::new(),
                });
            }
            Some(block) => {
                if tokens == ["}"] {
                    block.end_line = line;
                    blocks.extend(open.take());
                    continue;
                }
                if tokens.len() == 1 {
                    return err(line, format!("`{}` has no value (a property line needs one)", tokens[0]));
                }
                if header(&tokens).is_some() {
                    return err(
                        line,
                        format!(
                            "`{content}` opens a block inside `{}` opened at line {}: that block has no `}}` before it",
                            block.class, block.line
                        ),
                    );
                }
                let name = tokens[0];
                let rest = content[name.len()..].trim_start_matches(is_space);
                let value = match rest.strip_prefix('"').and_then(|r| r.strip_suffix('"')) {
                    Some(inner) if rest.len() >= 2 => inner,
                    _ => rest,
                };
                if value.len() > MAX_VALUE {
                    return err(line, format!("the value of `{name}` is longer than {MAX_VALUE} characters"));
                }
                if let Some(number) = decimal_comma(value) {
                    let point = number.replace(',', ".");
                    warnings.push((
                        line,
                        format!(
                            "`{name} {number}` has a decimal comma: it reads as {}, the number before the comma; \
                             write `{point}`",
                            &number[..number.find(',').unwrap_or(0)]
                        ),
                    ));
                }
                block.properties.push(Property { name: name.into(), value: value.into(), line });
            }
        }
    }
    if let Some(block) = open {
        return err(
            count,
            format!("unfinished object definition: `{}` opened at line {} has no `}}`", block.class, block.line),
        );
    }
    if let Some(from) = comment_from {
        warnings.push((from, "the block comment opened here never closes (with `*/` at the start of a line): the rest of the file is ignored".into()));
    }
    Ok(blocks)
}
