//! A scene file's JSON as a tree whose numbers keep the text they were written as, so
//! that `0.1` reaches the exact reader as the decimal 1/10 and `1e300` as 10^300, never
//! through f64.
//!
//! serde_json reads the document; its `RawValue` (feature `raw_value`) hands over each
//! value's exact text, and objects and arrays are read again from their text, one level
//! at a time. This keeps serde_json's `arbitrary_precision` feature, which would change
//! how numbers behave in every crate of a consumer's build, out of the dependency.

use std::collections::BTreeMap;
use std::fmt;

use serde::de::Error as _;
use serde_json::value::RawValue;

/// The members of an object, by key (a key written twice keeps its last value; the
/// duplicate-key pass refuses such a file before anything is read from the tree).
pub(super) type Map = BTreeMap<String, Value>;

/// A JSON value; a number is its literal text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Value {
    /// `null`.
    Null,
    /// `true` or `false`.
    Bool(bool),
    /// A number, exactly as written (`-0.5e3`).
    Number(String),
    /// A string, unescaped.
    String(String),
    /// An array.
    Array(Vec<Value>),
    /// An object.
    Object(Map),
}

/// Nesting deeper than this is refused, as serde_json's own reader refuses it.
const MAX_DEPTH: usize = 128;

/// The tree of `text`, or serde_json's syntax error (with its line and column).
pub(super) fn from_str(text: &str) -> Result<Value, serde_json::Error> {
    let raw: &RawValue = serde_json::from_str(text)?;
    from_raw(raw, 0)
}

pub(super) fn from_raw(raw: &RawValue, depth: usize) -> Result<Value, serde_json::Error> {
    let text = raw.get().trim();
    Ok(match text.as_bytes().first() {
        Some(b'{' | b'[') if depth >= MAX_DEPTH => {
            return Err(serde_json::Error::custom(format!(
                "recursion limit exceeded ({MAX_DEPTH} levels)"
            )))
        }
        Some(b'{') => {
            let members: BTreeMap<String, &RawValue> = serde_json::from_str(text)?;
            Value::Object(
                members
                    .into_iter()
                    .map(|(k, v)| Ok((k, from_raw(v, depth + 1)?)))
                    .collect::<Result<_, serde_json::Error>>()?,
            )
        }
        Some(b'[') => {
            let items: Vec<&RawValue> = serde_json::from_str(text)?;
            Value::Array(
                items
                    .into_iter()
                    .map(|v| from_raw(v, depth + 1))
                    .collect::<Result<_, _>>()?,
            )
        }
        Some(b'"') => Value::String(serde_json::from_str(text)?),
        Some(b't') => Value::Bool(true),
        Some(b'f') => Value::Bool(false),
        Some(b'n') => Value::Null,
        _ => Value::Number(text.to_string()),
    })
}

impl Value {
    /// The string, if this is one.
    pub(super) fn as_str(&self) -> Option<&str> {
        match self {
            Value::String(s) => Some(s),
            _ => None,
        }
    }

    /// The number, if this is a non-negative integer written without fraction or exponent
    /// that fits u64.
    pub(super) fn as_u64(&self) -> Option<u64> {
        match self {
            Value::Number(n) if n.bytes().all(|b| b.is_ascii_digit()) => n.parse().ok(),
            _ => None,
        }
    }

    /// The items, if this is an array.
    pub(super) fn as_array(&self) -> Option<&Vec<Value>> {
        match self {
            Value::Array(a) => Some(a),
            _ => None,
        }
    }
}

/// Compact JSON, keys in order (what an error message shows of a value).
impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let quoted = |s: &str| serde_json::to_string(s).map_err(|_| fmt::Error);
        match self {
            Value::Null => f.write_str("null"),
            Value::Bool(b) => write!(f, "{b}"),
            Value::Number(n) => f.write_str(n),
            Value::String(s) => f.write_str(&quoted(s)?),
            Value::Array(items) => {
                f.write_str("[")?;
                for (k, v) in items.iter().enumerate() {
                    if k > 0 {
                        f.write_str(",")?;
                    }
                    write!(f, "{v}")?;
                }
                f.write_str("]")
            }
            Value::Object(members) => {
                f.write_str("{")?;
                for (k, (key, v)) in members.iter().enumerate() {
                    if k > 0 {
                        f.write_str(",")?;
                    }
                    write!(f, "{}:{v}", quoted(key)?)?;
                }
                f.write_str("}")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_their_text_and_everything_else_its_value() {
        let v = from_str(
            r#" {"b": [1e300, -0.10, 12345678901234567890123], "a": "x\"y", "c": [true, false, null], "d": {}} "#,
        )
        .unwrap();
        let Value::Object(m) = &v else { panic!("{v:?}") };
        assert_eq!(m.keys().collect::<Vec<_>>(), ["a", "b", "c", "d"]);
        assert_eq!(m["a"], Value::String("x\"y".into()));
        assert_eq!(
            m["b"],
            Value::Array(vec![
                Value::Number("1e300".into()),
                Value::Number("-0.10".into()),
                Value::Number("12345678901234567890123".into())
            ])
        );
        assert_eq!(
            m["c"],
            Value::Array(vec![Value::Bool(true), Value::Bool(false), Value::Null])
        );
        assert_eq!(m["d"], Value::Object(Map::new()));
        assert_eq!(
            v.to_string(),
            r#"{"a":"x\"y","b":[1e300,-0.10,12345678901234567890123],"c":[true,false,null],"d":{}}"#
        );
    }

    #[test]
    fn integers_are_plain_digits_only() {
        let n = |s: &str| Value::Number(s.into()).as_u64();
        assert_eq!(n("4096"), Some(4096));
        assert_eq!(n("18446744073709551615"), Some(u64::MAX));
        assert_eq!(n("18446744073709551616"), None);
        for s in ["4.0", "4e0", "-4", "-0"] {
            assert_eq!(n(s), None, "{s}");
        }
        assert_eq!(Value::String("4".into()).as_u64(), None);
    }

    #[test]
    fn syntax_errors_are_serde_jsons_and_depth_is_bounded() {
        let e = from_str(r#"{"a": [1, }"#).unwrap_err();
        assert_eq!((e.line(), e.column()), (1, 11));
        assert!(from_str("[1] x").is_err());
        let deep = format!("{}{}", "[".repeat(MAX_DEPTH), "]".repeat(MAX_DEPTH));
        assert!(from_str(&deep).is_ok());
        let deeper = format!("{}{}", "[".repeat(MAX_DEPTH + 1), "]".repeat(MAX_DEPTH + 1));
        assert!(from_str(&deeper).unwrap_err().to_string().contains("recursion limit"));
    }
}
