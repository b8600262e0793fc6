//! Two checks on a scene file's JSON text that serde_json's `Value` cannot make: a key
//! repeated in one object (a `Value` keeps the last one silently), and the bare `NaN` and
//! `Infinity` literals behind a syntax error (JSON has neither; serde_json only gives the
//! position).
//!
//! The duplicate check is a second pass over the text with a [`DeserializeSeed`] that
//! builds nothing: it walks the document, keeps the path of the object it is in (the
//! reader's form, `triangles[2].v`), and stops at the first key an object already holds.
//! Numbers are not read at all.

use std::borrow::Cow;
use std::collections::HashSet;
use std::fmt;

use serde::de::{DeserializeSeed, Deserializer, Error as _, MapAccess, SeqAccess, Visitor};

/// A key repeated in one object.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Duplicate {
    /// The object's path (`triangles[2]`, `clip`; empty for the top level).
    pub(super) path: String,
    /// The repeated key.
    pub(super) key: String,
}

/// The first key repeated in one object of `text`, in document order; `None` when there
/// is none. `text` must already have parsed as JSON (its syntax errors are not reported
/// here).
pub(super) fn first_duplicate(text: &str) -> Option<Duplicate> {
    let mut found = None;
    let mut de = serde_json::Deserializer::from_str(text);
    // The only error the walk raises itself is a duplicate, recorded in `found`; the text
    // parsed before, so no other is expected, and none would be a duplicate.
    let _ = Walk {
        path: String::new(),
        found: &mut found,
    }
    .deserialize(&mut de);
    found
}

/// The path of the child `key` of the object at `path`, as the reader writes it.
fn child(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// The keys seen in one object: a short list searched in order (the schema's objects
/// have at most 13 keys), a hash set once it grows (so a huge object stays linear).
#[derive(Default)]
struct Seen<'de> {
    few: Vec<Cow<'de, str>>,
    many: HashSet<Cow<'de, str>>,
}

impl<'de> Seen<'de> {
    const FEW: usize = 16;

    /// Adds `key`; false when it was already there.
    fn insert(&mut self, key: Cow<'de, str>) -> bool {
        if self.many.is_empty() {
            if self.few.contains(&key) {
                return false;
            }
            if self.few.len() < Self::FEW {
                self.few.push(key);
                return true;
            }
            self.many.extend(self.few.drain(..));
        }
        self.many.insert(key)
    }
}

/// One value of the document at `path`; a repeated key inside it is written to `found`.
struct Walk<'f> {
    path: String,
    found: &'f mut Option<Duplicate>,
}

impl<'de> DeserializeSeed<'de> for Walk<'_> {
    type Value = ();

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Walk<'_> {
    type Value = ();

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any JSON value")
    }

    fn visit_bool<E>(self, _: bool) -> Result<(), E> {
        Ok(())
    }

    fn visit_i64<E>(self, _: i64) -> Result<(), E> {
        Ok(())
    }

    fn visit_u64<E>(self, _: u64) -> Result<(), E> {
        Ok(())
    }

    fn visit_i128<E>(self, _: i128) -> Result<(), E> {
        Ok(())
    }

    fn visit_u128<E>(self, _: u128) -> Result<(), E> {
        Ok(())
    }

    fn visit_f64<E>(self, _: f64) -> Result<(), E> {
        Ok(())
    }

    fn visit_str<E>(self, _: &str) -> Result<(), E> {
        Ok(())
    }

    fn visit_unit<E>(self) -> Result<(), E> {
        Ok(())
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let mut k = 0usize;
        loop {
            let item = Walk {
                path: format!("{}[{k}]", self.path),
                found: &mut *self.found,
            };
            if seq.next_element_seed(item)?.is_none() {
                return Ok(());
            }
            k += 1;
        }
    }

    /// An object: its keys, each checked against the ones before it.
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let mut seen = Seen::default();
        while let Some(key) = map.next_key_seed(KeySeed)? {
            let path = child(&self.path, &key);
            if !seen.insert(key.clone()) {
                *self.found = Some(Duplicate {
                    path: self.path,
                    key: key.into_owned(),
                });
                return Err(A::Error::custom("duplicate key"));
            }
            map.next_value_seed(Walk {
                path,
                found: &mut *self.found,
            })?;
        }
        Ok(())
    }
}

/// An object key, borrowed from the text when it has no escapes.
struct KeySeed;

impl<'de> DeserializeSeed<'de> for KeySeed {
    type Value = Cow<'de, str>;

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Cow<'de, str>, D::Error> {
        deserializer.deserialize_str(self)
    }
}

impl<'de> Visitor<'de> for KeySeed {
    type Value = Cow<'de, str>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an object key")
    }

    fn visit_borrowed_str<E>(self, s: &'de str) -> Result<Cow<'de, str>, E> {
        Ok(Cow::Borrowed(s))
    }

    fn visit_str<E>(self, s: &str) -> Result<Cow<'de, str>, E> {
        Ok(Cow::Owned(s.to_string()))
    }
}

/// The hint for a syntax error at `line`, `column` (serde_json's: 1-based, the column in
/// bytes) of `text` when a bare `NaN` or `Infinity` literal starts there (or one byte
/// before, where serde_json read a sign first); `None` otherwise.
pub(super) fn non_json_literal_hint(text: &str, line: usize, column: usize) -> Option<String> {
    let line_start = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum::<usize>();
    let at = line_start + column.saturating_sub(1);
    let bytes = text.as_bytes();
    let starts = |from: usize, word: &str| bytes.get(from..).is_some_and(|b| b.starts_with(word.as_bytes()));
    let word = [at.saturating_sub(1), at]
        .into_iter()
        .flat_map(|from| {
            ["-NaN", "NaN", "-Infinity", "Infinity"]
                .into_iter()
                .filter(move |w| starts(from, w))
        })
        .next()?;
    Some(format!(
        "{word} is not JSON (JSON has no NaN or infinity); a coordinate is a JSON number or a \
         string holding a decimal or a fraction, e.g. \"1/3\" or \"0.1\", and it must be finite"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dup(text: &str) -> Option<(String, String)> {
        first_duplicate(text).map(|d| (d.path, d.key))
    }

    #[test]
    fn paths_of_repeated_keys() {
        assert_eq!(dup(r#"{"a": 1, "b": 2}"#), None);
        assert_eq!(dup(r#"{"a": 1, "a": 2}"#), Some((String::new(), "a".into())));
        assert_eq!(
            dup(r#"{"t": [{"v": 1}, {"v": 2, "w": {"x": 0, "x": 1}}]}"#),
            Some(("t[1].w".into(), "x".into()))
        );
        // An escaped key is the same key.
        assert_eq!(dup(r#"{"v": 1, "\u0076": 2}"#), Some((String::new(), "v".into())));
        // Numbers of any size, as written, are not objects.
        assert_eq!(dup(r#"{"a": [1e999, -0.1, 12345678901234567890123]}"#), None);
    }

    #[test]
    fn a_large_object_switches_to_a_hash_set() {
        let keys: Vec<String> = (0..40).map(|k| format!("\"k{k}\": {k}")).collect();
        assert_eq!(dup(&format!("{{{}}}", keys.join(","))), None);
        assert_eq!(
            dup(&format!("{{{}, \"k3\": 0}}", keys.join(","))),
            Some((String::new(), "k3".into()))
        );
    }

    #[test]
    fn nan_and_infinity_are_recognised_where_serde_json_stops() {
        for (text, word) in [
            ("[NaN]", "NaN"),
            ("[1,\n -NaN]", "-NaN"),
            ("{\"a\": Infinity}", "Infinity"),
            ("[-Infinity]", "-Infinity"),
        ] {
            let e = serde_json::from_str::<serde_json::Value>(text).unwrap_err();
            let hint = non_json_literal_hint(text, e.line(), e.column());
            assert!(
                hint.is_some_and(|h| h.starts_with(&format!("{word} is not JSON"))),
                "{text}: {e}"
            );
        }
        let e = serde_json::from_str::<serde_json::Value>("[nope]").unwrap_err();
        assert_eq!(non_json_literal_hint("[nope]", e.line(), e.column()), None);
    }
}
