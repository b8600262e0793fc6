//! The fast path of the scene reader: one streaming pass of serde_json over the text that
//! reads `triangles` straight into compact exact numbers ([`Compact`]), with no tree, no
//! path string and no big rational per coordinate; every other field is taken as its raw
//! text and read by the schema as before.
//!
//! It declines (`None`) at the first thing it does not read itself: a syntax error, a key
//! written twice, a top level that is not an object, a triangle with an unknown field or
//! the wrong shape, a coordinate [`Compact::parse`] refuses, a string with an escape, a
//! colour that is not plain digits, too many triangles. [`super::parse_scene`] then reads
//! the file the slow way, which gives every error its usual words, so an error is the same
//! whichever path met it. Where the fast path accepts a file it gives the scene the slow
//! path gives (the property test `fast_and_slow_readers_agree` and the fuzz target
//! `scene_parse`).

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{DeserializeSeed, Deserializer, Error as _, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::value::RawValue;

use super::json::{from_raw, Map};
use super::{keys, MAX_TRIANGLES};
use crate::geom::{CompactTriangle, Rgb};
use crate::num::compact::Compact;
use crate::scene::SceneTriangle;

/// The top level of `text` read on the fast path: every field but `triangles` as a tree,
/// and the triangles when the file has the field. `None`: read it the slow way.
pub(super) fn read(text: &str) -> Option<(Map, Option<Vec<SceneTriangle>>)> {
    let mut de = serde_json::Deserializer::from_str(text);
    let (raw, triangles) = Root.deserialize(&mut de).ok()?;
    de.end().ok()?;
    let mut root = Map::new();
    for (key, value) in raw {
        if keys::first_duplicate(value.get()).is_some() {
            return None;
        }
        root.insert(key, from_raw(value, 1).ok()?);
    }
    Some((root, triangles))
}

/// Why the fast path declined (never shown: the slow path reads the file again).
fn decline<E: serde::de::Error>() -> E {
    E::custom("not on the fast path")
}

/// The top-level object.
struct Root;

type RootValue<'de> = (BTreeMap<String, &'de RawValue>, Option<Vec<SceneTriangle>>);

impl<'de> DeserializeSeed<'de> for Root {
    type Value = RootValue<'de>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for Root {
    type Value = RootValue<'de>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a scene object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut raw = BTreeMap::new();
        let mut triangles = None;
        while let Some(key) = map.next_key::<&'de str>()? {
            if key == "triangles" {
                if triangles.is_some() {
                    return Err(decline());
                }
                triangles = Some(map.next_value_seed(Triangles)?);
            } else {
                let value: &'de RawValue = map.next_value()?;
                if raw.insert(key.to_string(), value).is_some() {
                    return Err(decline());
                }
            }
        }
        Ok((raw, triangles))
    }
}

/// The `triangles` array.
struct Triangles;

impl<'de> DeserializeSeed<'de> for Triangles {
    type Value = Vec<SceneTriangle>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Triangles {
    type Value = Vec<SceneTriangle>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of triangles")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(MAX_TRIANGLES));
        while let Some(t) = seq.next_element_seed(TriangleSeed)? {
            if out.len() == MAX_TRIANGLES {
                return Err(decline());
            }
            out.push(t);
        }
        Ok(out)
    }
}

/// One triangle object: `v` and optional `colors`, nothing else.
struct TriangleSeed;

impl<'de> DeserializeSeed<'de> for TriangleSeed {
    type Value = SceneTriangle;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for TriangleSeed {
    type Value = SceneTriangle;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a triangle object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut v = None;
        let mut colours = None;
        while let Some(key) = map.next_key::<&'de str>()? {
            match key {
                "v" if v.is_none() => v = Some(map.next_value_seed(Triple(Pair))?),
                "colors" if colours.is_none() => colours = Some(map.next_value_seed(Triple(Colour))?),
                _ => return Err(decline()),
            }
        }
        let v = v.ok_or_else(decline)?;
        Ok(SceneTriangle {
            triangle: CompactTriangle { v },
            colours,
        })
    }
}

/// An array of exactly three of `S`'s values.
struct Triple<S>(S);

impl<'de, S: DeserializeSeed<'de> + Copy> DeserializeSeed<'de> for Triple<S> {
    type Value = [S::Value; 3];
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de, S: DeserializeSeed<'de> + Copy> Visitor<'de> for Triple<S> {
    type Value = [S::Value; 3];
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("three values")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let a = seq.next_element_seed(self.0)?.ok_or_else(decline)?;
        let b = seq.next_element_seed(self.0)?.ok_or_else(decline)?;
        let c = seq.next_element_seed(self.0)?.ok_or_else(decline)?;
        if seq.next_element::<IgnoredAny>()?.is_some() {
            return Err(decline());
        }
        Ok([a, b, c])
    }
}

/// A vertex `[x, y]`: two exact coordinates.
#[derive(Clone, Copy)]
struct Pair;

impl<'de> DeserializeSeed<'de> for Pair {
    type Value = [Compact; 2];
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Pair {
    type Value = [Compact; 2];
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a vertex")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let x: &'de RawValue = seq.next_element()?.ok_or_else(decline)?;
        let y: &'de RawValue = seq.next_element()?.ok_or_else(decline)?;
        if seq.next_element::<IgnoredAny>()?.is_some() {
            return Err(decline());
        }
        Ok([coordinate(x.get())?, coordinate(y.get())?])
    }
}

/// A coordinate as the slow path reads it: a number's literal text, or a string's
/// contents (without escapes here), read exactly.
fn coordinate<E: serde::de::Error>(raw: &str) -> Result<Compact, E> {
    let text = match raw.as_bytes().first() {
        Some(b'"') if !raw.contains('\\') && raw.len() >= 2 => &raw[1..raw.len() - 1],
        Some(b'-' | b'0'..=b'9') => raw,
        _ => return Err(decline()),
    };
    Compact::parse(text).map_err(|_| decline())
}

/// A colour `[r, g, b]`, each written as plain digits in 0..=255.
#[derive(Clone, Copy)]
struct Colour;

impl<'de> DeserializeSeed<'de> for Colour {
    type Value = Rgb;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Colour {
    type Value = Rgb;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a colour")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut out = [0u8; 3];
        for channel in &mut out {
            let raw: &'de RawValue = seq.next_element()?.ok_or_else(decline)?;
            let text = raw.get();
            if !text.bytes().all(|b| b.is_ascii_digit()) {
                return Err(decline());
            }
            *channel = text.parse().map_err(|_| A::Error::custom("not a channel"))?;
        }
        if seq.next_element::<IgnoredAny>()?.is_some() {
            return Err(decline());
        }
        Ok(out)
    }
}
