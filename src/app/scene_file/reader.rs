//! Reading the properties of one block (spec 1.7).

use super::loader::Loader;
use super::parse::{Block, Property};
use super::*;
use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::math::Vector;

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

    pub(super) fn float(&mut self, l: &Loader, name: &str, default: f64, min: f64, max: f64) -> Result<f64> {
        let Some(p) = self.raw(name) else { return Ok(default) };
        let (v, _) = values::leading_float(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid number `{}`", p.value)))?;
        if !(min..=max).contains(&v) {
            return Err(l.error(p.line, format!("`{name}` {v}: value outside the allowed bounds [{min}, {max}]")));
        }
        Ok(v)
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

    pub(super) fn triple(&mut self, l: &Loader, name: &str, what: &str) -> Result<Option<[f64; 3]>> {
        let Some(p) = self.raw(name) else { return Ok(None) };
        values::triple(&p.value)
            .map(Some)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid {what} `{}`", p.value)))
    }

    pub(super) fn color(&mut self, l: &Loader, name: &str, default: Color) -> Result<Color> {
        Ok(self.triple(l, name, "color")?.map_or(default, |c| Color::new(c[0] as f32, c[1] as f32, c[2] as f32)))
    }

    pub(super) fn vector(&mut self, l: &Loader, name: &str) -> Result<Option<Vector>> {
        Ok(self.triple(l, name, "vector")?.map(|v| Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)))
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
