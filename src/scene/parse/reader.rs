//! A JSON reader for the scene schema: typed reads (strings, integers, exact numbers,
//! arrays, points) whose errors name the file, the field path and the offending value.

use super::json::{Map, Value};
use num_rational::BigRational;

use crate::geom::Point;
use crate::num::parse_rational;
use crate::scene::SceneError;

/// Reads values out of one file's JSON; `source` names the file in every error.
pub(super) struct Reader<'a> {
    pub(super) source: &'a str,
    /// The most polygon and clip-window vertices the scene may hold, all together.
    pub(super) vertex_limit: usize,
    /// How many the scene has so far.
    pub(super) vertices: std::cell::Cell<usize>,
}

/// What kind of JSON value `v` is, for an error ("a string", "an array", ...).
pub(super) fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// A value shown in an error, shortened so a huge value cannot flood the terminal.
pub(super) fn show(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 60 {
        format!("{}...", s.chars().take(60).collect::<String>())
    } else {
        s
    }
}

impl Reader<'_> {
    /// An error at `field` (a path like `triangles[0].v[1]`, empty for the whole file).
    pub(super) fn err(&self, field: &str, message: String) -> SceneError {
        SceneError {
            source: self.source.to_string(),
            field: field.to_string(),
            message,
        }
    }

    /// Refuses any key of `obj` (the object at path `at`) that is not in `known`: a typo
    /// must not silently change the meaning of a file.
    pub(super) fn known_fields(&self, obj: &Map, at: &str, known: &[&str]) -> Result<(), SceneError> {
        for key in obj.keys() {
            if !known.contains(&key.as_str()) {
                let field = if at.is_empty() {
                    key.clone()
                } else {
                    format!("{at}.{key}")
                };
                return Err(self.err(&field, format!("unknown field (expected one of: {})", known.join(", "))));
            }
        }
        Ok(())
    }

    /// A JSON string.
    pub(super) fn string<'v>(&self, v: &'v Value, field: &str) -> Result<&'v str, SceneError> {
        v.as_str()
            .ok_or_else(|| self.err(field, format!("expected a string, found {} {}", kind(v), show(v))))
    }

    /// A non-negative integer written as a JSON number without fraction or exponent.
    pub(super) fn integer(&self, v: &Value, field: &str) -> Result<u64, SceneError> {
        v.as_u64()
            .ok_or_else(|| self.err(field, format!("expected a non-negative integer, found {}", show(v))))
    }

    /// An exact number: a JSON number as written, or a string with a decimal or fraction.
    pub(super) fn coordinate(&self, v: &Value, field: &str) -> Result<BigRational, SceneError> {
        let text = match v {
            // A number keeps the text it was written as (json.rs).
            Value::Number(n) => n.to_string(),
            Value::String(s) => s.clone(),
            _ => {
                return Err(self.err(
                    field,
                    format!("expected a number or a numeric string, found {} {}", kind(v), show(v)),
                ))
            }
        };
        parse_rational(&text).map_err(|e| self.err(field, format!("{} {e}", show(v))))
    }

    /// A JSON array.
    pub(super) fn array<'v>(&self, v: &'v Value, field: &str) -> Result<&'v Vec<Value>, SceneError> {
        v.as_array()
            .ok_or_else(|| self.err(field, format!("expected an array, found {} {}", kind(v), show(v))))
    }

    /// The array at `field`, at most `max` entries, each parsed by `parse` with its own
    /// path (`field[k]`).
    pub(super) fn each<T>(
        &self,
        v: &Value,
        field: &str,
        max: usize,
        parse: impl Fn(&Value, &str) -> Result<T, SceneError>,
    ) -> Result<Vec<T>, SceneError> {
        let list = self.array(v, field)?;
        if list.len() > max {
            return Err(self.err(field, format!("{} entries, at most {max}", list.len())));
        }
        list.iter()
            .enumerate()
            .map(|(k, item)| parse(item, &format!("{field}[{k}]")))
            .collect()
    }

    /// An exact point `[x, y]` at path `at`; `None` (the field is absent) is an error.
    pub(super) fn point(&self, v: Option<&Value>, at: &str) -> Result<Point, SceneError> {
        let v = v.ok_or_else(|| self.err(at, "missing (required)".into()))?;
        let xy = self.array(v, at)?;
        if xy.len() != 2 {
            return Err(self.err(at, format!("a point is [x, y], found {} values", xy.len())));
        }
        Ok(Point::new(
            self.coordinate(&xy[0], &format!("{at}[0]"))?,
            self.coordinate(&xy[1], &format!("{at}[1]"))?,
        ))
    }
}
