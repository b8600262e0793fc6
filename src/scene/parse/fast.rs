//! The fast path of the scene reader: one streaming pass of serde_json over the text that
//! reads `triangles` straight into compact exact numbers ([`Compact`]), with no tree, no
//! path string and no big rational per coordinate; every other field is taken as its raw
//! text and read by the schema as before.
//!
//! It declines at the first thing it does not read itself: a syntax error, a key written
//! twice, a top level that is not an object, a triangle with an unknown field or the
//! wrong shape, a coordinate [`Compact::parse`] refuses, a string with an escape, a colour
//! that is not plain digits. [`super::parse_scene`] then reads the file the slow way,
//! which gives every error its usual words, so an error is the same whichever path met
//! it. Where the fast path reads a file it gives the scene, or the schema's error, that
//! the slow path gives (the property test `fast_and_slow_readers_agree` and the fuzz
//! target `scene_parse`). Two exceptions bound the memory of a huge file: beyond
//! [`MAX_TRIANGLES`] triangles it stops and the file is refused for that (without the
//! slow path's count of them), and a file it declines that is bigger than
//! [`super::MAX_SLOW_BYTES`] is refused with the line and column where it stopped, since
//! the slow path's tree would cost some ten times the text.

use std::cell::Cell;
use std::collections::BTreeMap;
use std::fmt;

use serde::de::{DeserializeSeed, Deserializer, Error as _, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::value::RawValue;

use super::json::{from_raw, Map};
use super::{keys, MAX_TRIANGLES};

use crate::chunks;
use crate::geom::{CompactTriangle, Rgb};
use crate::num::compact::Compact;
use crate::scene::SceneTriangle;

/// What the fast path made of a text.
pub(super) enum Read {
    /// Every field but `triangles` as a tree, and the triangles when the file has them.
    Fields(Map, Option<Vec<SceneTriangle>>),
    /// More than [`MAX_TRIANGLES`] triangles: read no further.
    TooMany,
    /// Something it does not read itself, at this line and column of the text (`None`:
    /// in a field other than `triangles`): the slow path reads the file.
    Declined(Option<(usize, usize)>),
}

/// The top level of `text` read on the fast path, its triangles on up to `jobs` threads.
///
/// On several threads each thread finds and reads its run of triangles
/// ([`read_split`]), exactly as the one-thread pass reads a triangle. Anything but a
/// scene read that way (a decline, too many triangles, a layout the threads' guesses do
/// not fit) is read again by the one-thread pass, which says where it stopped and why as
/// it always does; so the answer does not depend on `jobs`.
pub(super) fn read(text: &str, jobs: usize) -> Read {
    match (jobs > 1).then(|| read_split(text, jobs)).flatten() {
        Some(read) => read,
        None => read_on(text, None),
    }
}

/// The triangles read by `jobs` threads at once, each run from a guess of where an element
/// of the array begins, straight into its place in the scene's vector; the rest of the
/// document read with an empty array in their place. `None` (read another way) unless
/// every step held:
/// - the array is the value of a key `"triangles"` found by its text;
/// - each run is walked from its guess, each element one JSON value read by serde_json,
///   separated by commas and JSON whitespace, and the walk of each run lands exactly on
///   the next run's first element, or ends at the array's `]`;
/// - each run before the one that ends the array holds as many elements as it has `{`
///   bytes (an element is an object, and a triangle's text has no other `{`: no other
///   object, no string with one in it), so the runs fill the vector without a gap;
/// - the document with `[]` in place of the array is read on the fast path, and its
///   top-level `triangles` is that `[]`;
/// - every element is a triangle the fast path reads, and there are at most
///   [`MAX_TRIANGLES`] (and at most as many `{` bytes in the runs' text).
///
/// Then the text is the document read, its array the elements walked, so the scene is the
/// one the one-thread pass reads. The runs are [`RUNS_PER_JOB`] per thread, handed out in
/// turn ([`chunks::map_each`]), so that a thread on a slower core reads fewer of them.
fn read_split(text: &str, jobs: usize) -> Option<Read> {
    let open = array_of_key(text, "\"triangles\"")?;
    let first = skip_space(text, open + 1);
    let count = jobs.saturating_mul(RUNS_PER_JOB);
    let mut starts = vec![first];
    for k in 1..count {
        let cut = first + (text.len() - first) / count * k;
        match element_after(text, cut) {
            Some(s) if s > starts[starts.len() - 1] => starts.push(s),
            _ => {}
        }
    }
    let runs: Vec<(usize, Option<usize>)> = (0..starts.len())
        .map(|k| (starts[k], starts.get(k + 1).copied()))
        .collect();
    // A run holds at most as many elements as `{` bytes: each run gets that many places.
    let bounds = chunks::map(&runs, jobs, |_, &(start, next)| {
        count_braces(&text.as_bytes()[start..next.unwrap_or(text.len())])
    });
    let places: usize = bounds.iter().sum();
    if places > MAX_TRIANGLES {
        return None;
    }
    let mut triangles: Vec<SceneTriangle> = chunks::defaults(places, jobs);
    let mut rest = triangles.as_mut_slice();
    let mut slots = Vec::with_capacity(runs.len());
    for (&run, &bound) in runs.iter().zip(&bounds) {
        let (mine, others) = rest.split_at_mut(bound);
        slots.push((run, mine));
        rest = others;
    }
    let walked = chunks::map_each(slots, jobs, |((start, next), places)| walk(text, start, next, places));
    // The runs up to the one that ends the array; those before it full.
    let mut read = 0;
    let mut close = None;
    for (run, &bound) in walked.into_iter().zip(&bounds) {
        let (elements, end) = run?;
        read += elements;
        if end.is_some() {
            close = end;
            break;
        }
        (elements == bound).then_some(())?;
    }
    let close = close?;
    triangles.truncate(read);
    let spliced = format!("{}[]{}", &text[..open], &text[close + 1..]);
    let placeholder = spliced[open..].as_ptr() as usize;
    let Read::Fields(root, Some(empty)) = read_on(&spliced, Some(placeholder)) else {
        return None;
    };
    debug_assert!(empty.is_empty());
    Some(Read::Fields(root, Some(triangles)))
}

/// The `{` bytes of `bytes`, counted in blocks of 64 whose sums fit a byte (so the sum
/// cannot overflow, and adding without the overflow check lets the compiler use vector
/// code: some 5x the speed of counting byte by byte).
fn count_braces(bytes: &[u8]) -> usize {
    let blocks = bytes.chunks_exact(64);
    let tail = blocks.remainder().iter().filter(|&&b| b == b'{').count();
    tail + blocks
        .map(|block| usize::from(block.iter().fold(0u8, |n, &b| n.wrapping_add(u8::from(b == b'{')))))
        .sum::<usize>()
}

/// The runs of triangles per thread of [`read_split`].
const RUNS_PER_JOB: usize = 8;

/// Where the array after `key` (`"key"`, then `:`, then `[`, JSON whitespace between)
/// opens, at its first such occurrence in the text.
fn array_of_key(text: &str, key: &str) -> Option<usize> {
    let at = text.find(key)?;
    let colon = skip_space(text, at + key.len());
    (text.as_bytes().get(colon) == Some(&b':')).then_some(())?;
    let open = skip_space(text, colon + 1);
    (text.as_bytes().get(open) == Some(&b'[')).then_some(open)
}

/// The first `{` at or after `from` whose previous byte other than JSON whitespace is a
/// comma: a guess at where an element of an array of objects begins.
fn element_after(text: &str, from: usize) -> Option<usize> {
    let bytes = text.as_bytes();
    let mut at = from;
    loop {
        let brace = at + bytes.get(at..)?.iter().position(|&b| b == b'{')?;
        let before = bytes[..brace].iter().rposition(|&b| !is_space(b))?;
        if bytes[before] == b',' {
            return Some(brace);
        }
        at = brace + 1;
    }
}

/// The elements from `start` on, each a triangle read by [`TriangleSeed`] (serde_json reads
/// it as one JSON value) into the next of `places`, then JSON whitespace and a comma or
/// the array's `]`: up to `next` (the next run's first element; the walk must land on it)
/// or the `]`. How many elements were read, and the `]`'s index if met; `None` where
/// anything else is met, or a run has more elements than places.
fn walk(text: &str, start: usize, next: Option<usize>, places: &mut [SceneTriangle]) -> Option<(usize, Option<usize>)> {
    let mut read = 0;
    let mut at = start;
    if text.as_bytes().get(at) == Some(&b']') {
        // An empty array (only the first run can start anywhere but at a `{`).
        return Some((0, Some(at)));
    }
    loop {
        if Some(at) == next {
            return Some((read, None));
        }
        if next.is_some_and(|n| at > n) {
            return None;
        }
        let mut values = serde_json::Deserializer::from_str(text.get(at..)?).into_iter::<FastTriangle>();
        *places.get_mut(read)? = values.next()?.ok()?.0;
        read += 1;
        let after = skip_space(text, at + values.byte_offset());
        match text.as_bytes().get(after)? {
            b',' => at = skip_space(text, after + 1),
            b']' => return Some((read, Some(after))),
            _ => return None,
        }
    }
}

/// JSON whitespace.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r')
}

/// The first index at or after `at` that is not JSON whitespace (or the text's length).
fn skip_space(text: &str, at: usize) -> usize {
    let bytes = text.as_bytes();
    at + bytes
        .get(at..)
        .map_or(0, |rest| rest.iter().take_while(|&&b| is_space(b)).count())
}

/// The one-thread pass of [`read`]; with `placeholder` (the address of an empty array in
/// `text`), the top-level `triangles` must be that array, whose elements were read apart
/// ([`read_split`]).
fn read_on(text: &str, placeholder: Option<usize>) -> Read {
    let too_many = Cell::new(false);
    let mut de = serde_json::Deserializer::from_str(text);
    let at = |e: serde_json::Error| Some((e.line(), e.column()));
    let root = Root {
        too_many: &too_many,
        placeholder,
    };
    let (raw, triangles) = match root.deserialize(&mut de) {
        Ok(read) => read,
        Err(_) if too_many.get() => return Read::TooMany,
        Err(e) => return Read::Declined(at(e)),
    };
    if let Err(e) = de.end() {
        return Read::Declined(at(e));
    }
    let mut root = Map::new();
    for (key, value) in raw {
        if keys::first_duplicate(value.get()).is_some() {
            return Read::Declined(None);
        }
        match from_raw(value, 1) {
            Ok(tree) => root.insert(key, tree),
            Err(_) => return Read::Declined(None),
        };
    }
    Read::Fields(root, triangles)
}

/// Why the fast path declined (never shown: the slow path reads the file again).
fn decline<E: serde::de::Error>() -> E {
    E::custom("not on the fast path")
}

/// The top-level object.
struct Root<'a> {
    too_many: &'a Cell<bool>,
    /// Where the top-level `triangles` must be an empty array put in place of the one
    /// read apart: its address.
    placeholder: Option<usize>,
}

type RootValue<'de> = (BTreeMap<String, &'de RawValue>, Option<Vec<SceneTriangle>>);

impl<'de> DeserializeSeed<'de> for Root<'_> {
    type Value = RootValue<'de>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for Root<'_> {
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
                if let Some(address) = self.placeholder {
                    let value: &'de RawValue = map.next_value()?;
                    if value.get() != "[]" || value.get().as_ptr() as usize != address {
                        return Err(decline());
                    }
                    triangles = Some(Vec::new());
                    continue;
                }
                triangles = Some(map.next_value_seed(Triangles {
                    too_many: self.too_many,
                })?);
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

/// The `triangles` array; `too_many` is set when it holds more than [`MAX_TRIANGLES`].
struct Triangles<'a> {
    too_many: &'a Cell<bool>,
}

impl<'de> DeserializeSeed<'de> for Triangles<'_> {
    type Value = Vec<SceneTriangle>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Triangles<'_> {
    type Value = Vec<SceneTriangle>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of triangles")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(MAX_TRIANGLES));
        while let Some(t) = seq.next_element_seed(TriangleSeed)? {
            if out.len() == MAX_TRIANGLES {
                self.too_many.set(true);
                return Err(decline());
            }
            out.push(t);
        }
        Ok(out)
    }
}

/// A triangle read by [`TriangleSeed`], for serde_json's stream of values (which says where
/// each ends).
struct FastTriangle(SceneTriangle);

impl<'de> serde::Deserialize<'de> for FastTriangle {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        TriangleSeed.deserialize(d).map(FastTriangle)
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
            values: None,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse::{parse_scene, parse_scene_with, ParseOptions};
    use crate::scene::{Scene, SceneError};

    /// [`parse_scene_with`] on `jobs` threads.
    fn parse_scene_parallel(text: &str, source: &str, jobs: usize) -> Result<Scene, SceneError> {
        parse_scene_with(text.as_bytes(), source, &ParseOptions::with_jobs(jobs))
    }

    /// A scene of `n` triangles, `sep` between them, `before` and `after` the array.
    fn scene(n: usize, sep: &str, before: &str, after: &str) -> String {
        let t: Vec<String> = (0..n)
            .map(|k| format!("{{\"v\": [[{k}, 0.5], [\"{k}/3\", 7], [1, 2]]}}"))
            .collect();
        format!(
            "{{{before}\"width\": 64, \"height\": 64, \"triangles\": [{}]{after}}}",
            t.join(sep)
        )
    }

    /// A plain scene, compact or pretty-printed, is cut in parallel (not by the fallbacks)
    /// and read as on one thread.
    #[test]
    fn a_plain_array_is_cut_in_parallel() {
        for sep in [",", ", ", ",\n    ", " ,\r\n\t"] {
            for n in [0, 1, 2, 3, 10, 101] {
                let text = scene(n, sep, "", ", \"preset\": \"vulkan\"");
                for jobs in [2, 3, 8] {
                    assert!(
                        matches!(read_split(&text, jobs), Some(Read::Fields(..))),
                        "{n} triangles, {sep:?}, {jobs} jobs"
                    );
                    assert_eq!(parse_scene_parallel(&text, "s", jobs), parse_scene(&text, "s"));
                }
            }
        }
    }

    /// Where a guess goes wrong the cut is refused, and the scene is still the one read on
    /// one thread: the key's text inside a string before the real key, the key in another
    /// field, elements that are not objects, a missing comma, a trailing comma, a second
    /// `triangles`.
    #[test]
    fn a_wrong_guess_is_refused_and_read_another_way() {
        let cases = [
            scene(20, ",", "\"name\": \"\\\"triangles\\\": [\", ", ""),
            scene(20, ",", "\"extra\": {\"triangles\": [{\"v\": 1}]}, ", ""),
            scene(20, ",", "", ", \"triangles\": []"),
            scene(6, ", 7,", "", ""),
            scene(6, " ", "", ""),
            scene(6, ",", "", "").replace("]]}]", "]]},]"),
        ];
        for text in &cases {
            for jobs in [2, 3] {
                assert_eq!(
                    parse_scene_parallel(text, "s", jobs).map_err(|e| e.to_string()),
                    parse_scene(text, "s").map_err(|e| e.to_string()),
                    "{text}"
                );
            }
        }
        // The key inside another field first: the guess is that field's array, refused.
        assert!(read_split(&cases[1], 2).is_none());
        assert!(read_split(&cases[2], 2).is_none());
    }

    /// The braces are counted in blocks of 64 and a tail: every length around the block
    /// size, braces at the block's first and last byte, and blocks full of them (64, the
    /// most a block's byte sum holds), against a count byte by byte.
    #[test]
    fn braces_are_counted_in_blocks() {
        for len in [0, 1, 63, 64, 65, 127, 128, 129, 640, 1000] {
            for every in [1, 2, 3, 63, 64, 1000] {
                let bytes: Vec<u8> = (0..len).map(|k| if k % every == 0 { b'{' } else { b'[' }).collect();
                let plain = bytes.iter().filter(|&&b| b == b'{').count();
                assert_eq!(count_braces(&bytes), plain, "{len} bytes, a brace every {every}");
            }
        }
        assert_eq!(count_braces(&[b'{'; 64 * 5 + 7]), 64 * 5 + 7);
    }

    /// A text with more `{` bytes after the array's start than [`MAX_TRIANGLES`] is not
    /// cut (its places would cost memory for triangles it may not have): it is read on one
    /// thread, to the same answer.
    #[test]
    fn more_braces_than_triangles_allowed_are_read_on_one_thread() {
        let braces = "{".repeat(MAX_TRIANGLES);
        let text = format!(
            "{{\"width\": 8, \"height\": 8, \"triangles\": [{{\"v\": [[0, 0], [4, 0], [0, 4]]}}], \"name\": \"{braces}\"}}"
        );
        assert!(read_split(&text, 2).is_none());
        assert_eq!(
            parse_scene_parallel(&text, "s", 2).map_err(|e| e.to_string()),
            parse_scene(&text, "s").map_err(|e| e.to_string())
        );
        // One brace fewer: cut.
        let text = text.replacen(&braces, &braces[1..], 1);
        assert!(
            matches!(read_split(&text, 2), Some(Read::Fields(..))),
            "the cut's places fit"
        );
    }
}
