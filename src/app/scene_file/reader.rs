//! Reading the properties of one block (spec 1.7).

use super::loader::Loader;
use super::parse::{Block, Property};
use super::*;
use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::math::Vector;

pub(super) use crate::lesson::math::MAX_COORDINATE;

/// Why a number that fits the course's bounds is still refused.
const TOO_LARGE: &str = "not a finite 32-bit number (the renderer's numbers end at 3.4e38)";

/// A number as a message shows it: in exponent form when it is very large or very small (`1e39`, not
/// forty digits).
pub(super) fn shown(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-4..1e16).contains(&v.abs()) { format!("{v:e}") } else { v.to_string() }
}

/// The three numbers of a colour, vector or transform as 32-bit floats, each finite and within ±`bound`
/// when one is given; the reason when one is not.
pub(super) fn checked_triple(v: [f64; 3], bound: Option<f64>) -> std::result::Result<[f32; 3], String> {
    for x in v {
        if x.is_nan() {
            return Err("NaN is not a number".into());
        }
        if !(x as f32).is_finite() {
            return Err(format!("{} is {TOO_LARGE}", shown(x)));
        }
        if let Some(b) = bound
            && !(-b..=b).contains(&x)
        {
            return Err(format!("{} is outside the allowed bounds [{}, {}]", shown(x), shown(-b), shown(b)));
        }
    }
    Ok(v.map(|x| x as f32))
}

/// Reads the properties of one block (spec 1.7): the first line of a name wins, and every line nobody
/// read is a warning when the block is done.
pub(super) struct Reader<'b> {
    pub(super) block: &'b Block,
    pub(super) used: Vec<bool>,
}

impl<'b> Reader<'b> {
    pub(super) fn new(block: &'b Block) -> Reader<'b> {
        Reader { block, used: vec![false; block.properties.len()] }
    }

    /// The first line of the property `name`, marked as read.
    pub(super) fn raw(&mut self, name: &str) -> Option<&'b Property> {
        let k = self.block.properties.iter().position(|p| p.name == name)?;
        self.used[k] = true;
        Some(&self.block.properties[k])
    }

    /// The first line of the property `name`, without marking it.
    pub(super) fn raw_line(&self, name: &str) -> Option<&'b Property> {
        self.block.properties.iter().find(|p| p.name == name)
    }

    /// The line of the property `name` (or of the block, when it has none).
    pub(super) fn line_of(&self, name: &str) -> usize {
        self.raw_line(name).map_or(self.block.line, |p| p.line)
    }

    /// A number within `[min, max]` as the course reads it (spec 1.6), not yet narrowed to the renderer's
    /// 32-bit floats: only for a value that means "no limit" beyond them (a Plane's `limit`).
    pub(super) fn number(&mut self, l: &Loader, name: &str, default: f64, min: f64, max: f64) -> Result<f64> {
        let Some(p) = self.raw(name) else { return Ok(default) };
        let (v, _) = values::leading_float(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid number `{}`", p.value)))?;
        if !(min..=max).contains(&v) {
            let bounds = format!("[{}, {}]", shown(min), shown(max));
            return Err(l.error(p.line, format!("`{name}` {}: value outside the allowed bounds {bounds}", shown(v))));
        }
        Ok(v)
    }

    /// A number within `[min, max]` (spec 1.6) that is also a finite 32-bit float, as the renderer holds it:
    /// `1e39` passes the course's bounds of ±1e120 but would become infinity.
    pub(super) fn float(&mut self, l: &Loader, name: &str, default: f64, min: f64, max: f64) -> Result<f64> {
        let v = self.number(l, name, default, min, max)?;
        if !(v as f32).is_finite() {
            return Err(l.error(self.line_of(name), format!("`{name}` {}: {TOO_LARGE}", shown(v))));
        }
        Ok(v)
    }

    /// A coordinate or a length (a radius, a plane's height): a number within ±[`MAX_COORDINATE`].
    pub(super) fn length(&mut self, l: &Loader, name: &str, default: f64) -> Result<f64> {
        self.float(l, name, default, -MAX_COORDINATE, MAX_COORDINATE)
    }

    pub(super) fn int(&mut self, l: &Loader, name: &str, default: i64, min: i64, max: i64) -> Result<i64> {
        let Some(p) = self.raw(name) else { return Ok(default) };
        let v = values::leading_int(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid integer `{}`", p.value)))?;
        if !(min..=max).contains(&v) {
            return Err(l.error(p.line, format!("`{name}` {v}: value outside the allowed bounds [{min}, {max}]")));
        }
        Ok(v)
    }

    pub(super) fn boolean(&mut self, l: &mut Loader, name: &str, default: bool) -> bool {
        let Some(p) = self.raw(name) else { return default };
        let (v, usual) = values::boolean(&p.value);
        if !usual {
            l.warn(p.line, format!("`{name} {}` reads as true (only `off`, `false` and `0` are false)", p.value));
        }
        v
    }

    /// Three numbers (spec 1.6), each a finite 32-bit float, and within ±`bound` when one is given.
    pub(super) fn triple(
        &mut self,
        l: &Loader,
        name: &str,
        what: &str,
        bound: Option<f64>,
    ) -> Result<Option<[f32; 3]>> {
        let Some(p) = self.raw(name) else { return Ok(None) };
        let v = values::triple(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid {what} `{}`", p.value)))?;
        checked_triple(v, bound).map(Some).map_err(|reason| l.error(p.line, format!("`{name}` {}: {reason}", p.value)))
    }

    /// A colour: three finite numbers (colours have no other bounds, spec 1.6).
    pub(super) fn color(&mut self, l: &Loader, name: &str, default: Color) -> Result<Color> {
        Ok(self.triple(l, name, "color", None)?.map_or(default, |[r, g, b]| Color::new(r, g, b)))
    }

    /// A surface's colour: a colour ([`Reader::color`]) that keeps the light it scales finite
    /// ([`Reader::check_lit`]).
    pub(super) fn surface_color(&mut self, l: &Loader, name: &str, default: Color) -> Result<Color> {
        let color = self.color(l, name, default)?;
        self.check_lit(l, name, &color.0.to_array().map(f64::from))?;
        Ok(color)
    }

    /// Fails unless each of `values`, the value of the property `name` of a surface (a colour's channels, a
    /// multiplier), times the scene's brightest light ([`Loader::brightest_light`]: what a surface a unit
    /// from its lamp gets, the course's measure of a light's power) is a finite 32-bit number: the shaders
    /// multiply the light by these, and a product past 3.4e38 is infinite, then NaN where it meets a zero.
    pub(super) fn check_lit(&self, l: &Loader, name: &str, values: &[f64]) -> Result<()> {
        let light = l.brightest_light;
        match values.iter().find(|&&v| !((v * light) as f32).is_finite()) {
            Some(&v) => Err(l.error(
                self.line_of(name),
                format!(
                    "`{name}` {}: {} times the scene's brightest light ({}, its colour times its power) is {:.2e}, \
                     {TOO_LARGE}",
                    self.raw_line(name).map_or(String::new(), |p| p.value.clone()),
                    shown(v),
                    shown(light),
                    v * light
                ),
            )),
            None => Ok(()),
        }
    }

    /// A position: three coordinates within ±[`MAX_COORDINATE`].
    pub(super) fn vector(&mut self, l: &Loader, name: &str) -> Result<Option<Vector>> {
        Ok(self.triple(l, name, "vector", Some(MAX_COORDINATE))?.map(Vector::from_array))
    }

    /// Reports every line of the block that was not read.
    pub(super) fn finish(self, l: &mut Loader) {
        for (p, used) in self.block.properties.iter().zip(self.used) {
            if !used {
                l.warn(p.line, format!("property `{}` isn't recognized by `{}` (ignored)", p.name, self.block.class));
            }
        }
    }
}
