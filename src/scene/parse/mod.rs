//! Parsing scene files. This module is the schema (which fields a scene has, their
//! defaults and limits; the shape fields in `parse/shapes.rs`), read through the typed
//! JSON reads of `parse/reader.rs`, whose errors name the field and the value. The format:
//!
//! ```json
//! {
//!   "width": 64, "height": 48,
//!   "preset": "d3d11",
//!   "subpixel_bits": 8, "rounding": "nearest-even", "tie_rule": "top-left", "pixel_centre": 0.5,
//!   "triangles": [
//!     {"v": [[0, 0], ["1/3", 10.25], [40, "7e1"]], "colors": [[255,0,0],[0,255,0],[0,0,255]]}
//!   ],
//!   "lines": [
//!     {"from": [5, 8], "to": [9, 11], "rule": "bresenham", "tie": "stay"},
//!     {"from": ["0.5", 3], "to": [17.25, "9/4"], "rule": "diamond"}
//!   ],
//!   "polygons": [
//!     {"v": [[0, 0], [40, 0], [40, 30], [0, 30]], "holes": [[[10, 10], [20, 10], [15, 20]]], "fill_rule": "nonzero"}
//!   ]
//! }
//! ```
//!
//! Only `width` and `height` are required. Lines: `rule` is `bresenham` (default; integer
//! pixel endpoints within ±2^24, `tie` `stay` (default: the midpoint form of Pitteway 1967,
//! `d <= 0` keeps the minor coordinate) or `step` (the error-term form of Bresenham 1965,
//! `e >= 0` steps the minor axis)) or `diamond` (any endpoints). Polygons: an outline `v`
//! and optional `holes`, each at least 3 vertices, no hole vertex outside the outline,
//! `fill_rule` `nonzero` (default) or `even-odd`; ids after the triangles and lines. A coordinate is a JSON number read exactly as
//! written (`0.1` is 1/10, never an f64) or a string with a decimal or a fraction. Unknown
//! fields are errors (a typo must not silently change the convention), and so is a key
//! repeated in one object (JSON leaves its meaning open; serde_json would keep the last).
//! `NaN` and `Infinity` are not JSON: a bare one is a syntax error, explained as such.
//! Every error names the file, the field path and the value.

use json::{Map, Value};
use num_rational::BigRational;

mod fast;
mod json;
mod keys;
mod reader;
mod shapes;
mod values;

use super::{Overrides, Scene, SceneError, SceneTriangle};
use crate::convention::{PixelCentre, Preset, Rounding, TieRule, MAX_CANVAS};
use crate::num::MAX_SUBPIXEL_BITS;
use reader::{kind, show, Reader};

/// The most triangles a scene may hold (ids must fit u32; memory stays bounded).
pub const MAX_TRIANGLES: usize = 10_000_000;

/// The most polygon and clip-window vertices one scene may hold, every contour of every
/// polygon and the clip window's together. No model's cost is quadratic in a polygon's
/// vertices any more (the plain oracle excepted: pixels x edges, by design), so what
/// limits a polygon is memory: a vertex read from the file is two exact rationals, about
/// 250 bytes, and each model's form of it adds about as much again (docs/cli.md gives the
/// measured figures), so the limit keeps a scene's vertices under a few GB.
pub const MAX_SCENE_VERTICES: usize = 10_000_000;

/// The largest scene text read the slow way (the reference reader, [`parse_scene_slow`],
/// whose tree costs some ten times the text): 64 MiB. A bigger file is read by the fast
/// path alone (see [`parse_scene`]).
pub const MAX_SLOW_BYTES: usize = 64 << 20;

/// The largest scene file: 1 GiB (read whole; a frame of 10^7 triangles with 3-decimal
/// coordinates is about 650 MB).
pub const MAX_SCENE_BYTES: usize = 1 << 30;

/// How a scene is read ([`parse_scene_with`], [`crate::scene::read_scene_file`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParseOptions {
    /// The threads that read the triangles, consecutive triangles on each: the same
    /// scene, or the same error, as on one thread (what `render --jobs` reads a big frame
    /// with). 0 is read as 1.
    pub jobs: usize,
    /// The most polygon and clip-window vertices in all: [`MAX_SCENE_VERTICES`], or a
    /// smaller bound of the caller's (a service that reads scenes from others and wants a
    /// smaller memory bound; a larger value is lowered to [`MAX_SCENE_VERTICES`]).
    pub max_vertices: usize,
}

impl Default for ParseOptions {
    /// One thread, [`MAX_SCENE_VERTICES`].
    fn default() -> ParseOptions {
        ParseOptions {
            jobs: 1,
            max_vertices: MAX_SCENE_VERTICES,
        }
    }
}

impl ParseOptions {
    /// The defaults, on up to `jobs` threads.
    pub fn with_jobs(jobs: usize) -> ParseOptions {
        ParseOptions {
            jobs,
            ..ParseOptions::default()
        }
    }
}

/// Parses a scene file's text; `source` names the file in errors ([`parse_scene_with`]
/// and the default [`ParseOptions`]).
///
/// ```
/// use rasterproof::scene::parse_scene;
/// let s = parse_scene(r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[4,0],["1/3",4]]}]}"#, "a.json").unwrap();
/// assert_eq!(s.triangles.len(), 1);
/// let err = parse_scene(r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[4,"NaN"],[0,4]]}]}"#, "a.json").unwrap_err();
/// assert_eq!(err.to_string(), "a.json: triangles[0].v[1][1]: \"NaN\" is not a finite number (expected a decimal like -12.5 or 1e3, or a fraction like 1/3)");
/// ```
///
/// # Errors
/// The text is not a valid scene: a [`SceneError`] naming `source`, the field and the value.
pub fn parse_scene(text: &str, source: &str) -> Result<Scene, SceneError> {
    parse_text(text, source, &ParseOptions::default())
}

/// Parses a scene file's bytes (UTF-8, at most [`MAX_SCENE_BYTES`]) as `options` ask;
/// `source` names the file in errors.
///
/// ```
/// use rasterproof::scene::{parse_scene, parse_scene_with, ParseOptions};
/// let text = r#"{"width": 8, "height": 8, "polygons": [{"v": [[0,0],[4,0],[0,4]]}, {"v": [[0,0],[4,0],[4,4],[0,4]]}]}"#;
/// // On two threads: the scene of one thread.
/// let two = parse_scene_with(text.as_bytes(), "a.json", &ParseOptions::with_jobs(2)).unwrap();
/// assert_eq!(two, parse_scene(text, "a.json").unwrap());
/// // A vertex bound of the caller's.
/// let six = ParseOptions { max_vertices: 6, ..ParseOptions::default() };
/// let err = parse_scene_with(text.as_bytes(), "a.json", &six).unwrap_err();
/// assert_eq!(err.to_string(), "a.json: polygons[1].v: 4 vertices make 7 polygon and clip-window vertices in the scene, at most 6");
/// ```
///
/// # Errors
/// As [`parse_scene`], and bytes that are too many or not UTF-8.
pub fn parse_scene_with(bytes: &[u8], source: &str, options: &ParseOptions) -> Result<Scene, SceneError> {
    if bytes.len() > MAX_SCENE_BYTES {
        return Err(SceneError {
            source: source.to_string(),
            field: String::new(),
            message: format!(
                "{} bytes, at most {MAX_SCENE_BYTES} (1 GiB) per scene file",
                bytes.len()
            ),
        });
    }
    let text = std::str::from_utf8(bytes).map_err(|e| SceneError {
        source: source.to_string(),
        field: String::new(),
        message: format!("not UTF-8 text ({e})"),
    })?;
    parse_text(text, source, options)
}

/// The scene of `text`, read as `options` ask: the fast path, or the slow one where it
/// declines.
fn parse_text(text: &str, source: &str, options: &ParseOptions) -> Result<Scene, SceneError> {
    let p = Reader::new(source, options.max_vertices.min(MAX_SCENE_VERTICES));
    match fast::read(text, options.jobs) {
        // The schema's error too: the fast path found no syntax error, no repeated key and
        // no triangle it could not read, so the slow path would reach the same one.
        fast::Read::Fields(root, triangles) => return p.scene(&root, triangles),
        fast::Read::TooMany => {
            return Err(p.err(
                "triangles",
                format!("more than {MAX_TRIANGLES} entries, at most {MAX_TRIANGLES}"),
            ))
        }
        fast::Read::Declined(at) if text.len() > MAX_SLOW_BYTES => {
            let at = at.map_or("in a field other than triangles".to_string(), |(line, column)| {
                format!("at line {line}, column {column}")
            });
            return Err(p.err(
                "",
                format!(
                    "{} bytes: the fast reader stopped {at}, and a file this big is not read the slow way \
                     (at most {MAX_SLOW_BYTES} bytes), which names the reason; the fast reader takes triangles \
                     as {{\"v\": [[x, y], [x, y], [x, y]]}} with optional \"colors\", each coordinate a JSON \
                     number or a string without escapes",
                    text.len()
                ),
            ));
        }
        fast::Read::Declined(_) => {}
    }
    let value = read_json(text, &p)?;
    let Value::Object(root) = &value else {
        return Err(p.err("", format!("the top level must be an object, found {}", kind(&value))));
    };
    p.scene(root, None)
}

/// [`parse_scene`] without its fast path: the tree of the whole file read field by field,
/// every coordinate through [`crate::num::parse_rational`]. The reference the fast path is
/// tested against (they give the same scene or the same error for every text); every
/// error [`parse_scene`] reports comes from here.
///
/// # Errors
/// As [`parse_scene`].
pub fn parse_scene_slow(text: &str, source: &str) -> Result<Scene, SceneError> {
    let p = Reader::new(source, MAX_SCENE_VERTICES);
    let value = read_json(text, &p)?;
    let Value::Object(root) = &value else {
        return Err(p.err("", format!("the top level must be an object, found {}", kind(&value))));
    };
    p.scene(root, None)
}

impl Reader<'_> {
    /// The scene of the top-level object `root`; `triangles` when the fast path read them.
    fn scene(&self, root: &Map, triangles: Option<Vec<SceneTriangle>>) -> Result<Scene, SceneError> {
        let p = self;
        p.vertices.set(0);
        p.known_fields(
            root,
            "",
            &[
                "width",
                "height",
                "preset",
                "subpixel_bits",
                "rounding",
                "tie_rule",
                "pixel_centre",
                "triangles",
                "lines",
                "polygons",
                "clip_space_triangles",
                "viewport",
                "clip",
                "samples",
                "varyings",
                "provoking_vertex",
            ],
        )?;
        let width = p.canvas_side(root, "width")?;
        let height = p.canvas_side(root, "height")?;
        let preset = match root.get("preset") {
            None => Preset::D3d11,
            Some(v) => {
                let name = p.string(v, "preset")?;
                Preset::from_name(name).ok_or_else(|| {
                    p.err(
                        "preset",
                        format!("unknown preset {name:?} (expected one of d3d11, vulkan, gl, cts)"),
                    )
                })?
            }
        };
        let overrides = p.overrides(root)?;
        let varyings = p.varyings(root)?;
        let triangles = match (triangles, root.get("triangles")) {
            (Some(read), _) => read,
            (None, None) => Vec::new(),
            (None, Some(v)) => p.triangles(v, &varyings)?,
        };
        if let (false, Some(k)) = (
            varyings.list.is_empty(),
            triangles.iter().position(|t| t.values.is_none()),
        ) {
            // The fast path reads triangles without values; the slow one asks for them.
            let names: Vec<&str> = varyings.list.iter().map(|v| v.name.as_str()).collect();
            return Err(p.err(
                &format!("triangles[{k}].varyings"),
                format!(
                    "missing: the scene declares varyings ({}), so {}",
                    names.join(", "),
                    values::MISSING_TAIL
                ),
            ));
        }
        let (lines, line_values): (Vec<_>, Vec<_>) = match root.get("lines") {
            None => (Vec::new(), Vec::new()),
            Some(v) => p.lines(v, &varyings)?.into_iter().unzip(),
        };
        let line_values: Vec<[Vec<BigRational>; 2]> = line_values.into_iter().flatten().collect();
        let polygons = match root.get("polygons") {
            None => Vec::new(),
            Some(v) => p.polygons(v)?,
        };
        let clip_space_triangles = match root.get("clip_space_triangles") {
            None => Vec::new(),
            Some(v) => p.clip_space_triangles(v, &varyings)?,
        };
        let viewport = match root.get("viewport") {
            None => None,
            Some(v) => Some(p.viewport(v, width, height, preset)?),
        };
        let clip = match root.get("clip") {
            None => None,
            Some(v) => Some(p.clip(v)?),
        };
        let samples = match root.get("samples") {
            None => None,
            Some(v) => Some(p.samples(v)?),
        };
        if triangles.len() + lines.len() + polygons.len() + clip_space_triangles.len() > MAX_TRIANGLES {
            return Err(p.err("", format!("more than {MAX_TRIANGLES} primitives")));
        }
        Ok(Scene {
            width,
            height,
            preset,
            overrides,
            triangles,
            lines,
            line_values,
            polygons,
            clip_space_triangles,
            viewport,
            clip,
            samples,
            varyings,
        })
    }
}

/// The JSON of `text`, refusing what serde_json's `Value` would let through or explain
/// poorly: a key repeated in one object (the object's path and the key), and a bare `NaN`
/// or `Infinity` (the position and what to write instead).
fn read_json(text: &str, p: &Reader<'_>) -> Result<Value, SceneError> {
    let value: Value = json::from_str(text).map_err(|e| {
        let message = match keys::non_json_literal_hint(text, e.line(), e.column()) {
            Some(hint) => format!("malformed JSON: {e}: {hint}"),
            None => format!("malformed JSON: {e}"),
        };
        p.err("", message)
    })?;
    if let Some(d) = keys::first_duplicate(text) {
        return Err(p.err(&d.path, format!("duplicate key {:?}", d.key)));
    }
    Ok(value)
}

impl<'a> Reader<'a> {
    fn new(source: &'a str, vertex_limit: usize) -> Reader<'a> {
        Reader {
            source,
            vertex_limit,
            vertices: std::cell::Cell::new(0),
        }
    }

    fn canvas_side(&self, root: &Map, field: &str) -> Result<u32, SceneError> {
        let v = root
            .get(field)
            .ok_or_else(|| self.err(field, "missing (required)".to_string()))?;
        let n = self.integer(v, field)?;
        if n == 0 || n > u64::from(MAX_CANVAS) {
            return Err(self.err(field, format!("{n} is outside 1..={MAX_CANVAS}")));
        }
        Ok(u32::try_from(n).expect("checked against MAX_CANVAS"))
    }

    fn overrides(&self, root: &Map) -> Result<Overrides, SceneError> {
        let mut o = Overrides::default();
        if let Some(v) = root.get("subpixel_bits") {
            let n = self.integer(v, "subpixel_bits")?;
            if !(1..=u64::from(MAX_SUBPIXEL_BITS)).contains(&n) {
                return Err(self.err("subpixel_bits", format!("{n} is outside 1..={MAX_SUBPIXEL_BITS}")));
            }
            o.subpixel_bits = Some(u32::try_from(n).expect("checked range"));
        }
        if let Some(v) = root.get("rounding") {
            let name = self.string(v, "rounding")?;
            o.rounding = Some(Rounding::from_name(name).ok_or_else(|| {
                self.err(
                    "rounding",
                    format!(
                        "unknown rounding {name:?} (expected nearest-even, half-away, floor, ceiling or towards-zero)"
                    ),
                )
            })?);
        }
        if let Some(v) = root.get("tie_rule") {
            let name = self.string(v, "tie_rule")?;
            o.tie_rule = Some(TieRule::from_name(name).ok_or_else(|| {
                self.err(
                    "tie_rule",
                    format!("unknown tie rule {name:?} (expected top-left or bottom-left)"),
                )
            })?);
        }
        if let Some(v) = root.get("pixel_centre") {
            let c = self.coordinate(v, "pixel_centre")?;
            o.pixel_centre = Some(if c == BigRational::new(1.into(), 2.into()) {
                PixelCentre::Half
            } else if c == BigRational::from_integer(0.into()) {
                PixelCentre::Corner
            } else {
                return Err(self.err("pixel_centre", format!("{} is not 0.5 or 0", show(v))));
            });
        }
        Ok(o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse_scene(text, "s.json").unwrap_err().to_string()
    }

    const TRI: &str = r#"{"v": [[0,0],[4,0],[0,4]]}"#;

    fn scene_with(tri: &str) -> String {
        format!(r#"{{"width": 8, "height": 8, "triangles": [{tri}]}}"#)
    }

    #[test]
    fn numbers_are_read_as_written() {
        let s = parse_scene(
            &scene_with(r#"{"v": [[0.1, 1e2], ["1/3", "-2.5"], [491.407, 3]]}"#),
            "s",
        )
        .unwrap();
        let v = &s.triangles[0].triangle.to_triangle().v;
        assert_eq!(v[0].x, BigRational::new(1.into(), 10.into()));
        assert_eq!(v[0].y, BigRational::from_integer(100.into()));
        assert_eq!(v[1].x, BigRational::new(1.into(), 3.into()));
        assert_eq!(v[2].x, BigRational::new(491_407.into(), 1000.into()));
    }

    #[test]
    fn bad_inputs_name_field_and_value() {
        assert!(err("{").starts_with("s.json: malformed JSON"));
        assert!(err("[]").contains("top level must be an object"));
        assert_eq!(err(r#"{"height": 3}"#), "s.json: width: missing (required)");
        assert_eq!(
            err(r#"{"width": 0, "height": 3}"#),
            "s.json: width: 0 is outside 1..=16384"
        );
        assert_eq!(
            err(r#"{"width": 16385, "height": 3}"#),
            "s.json: width: 16385 is outside 1..=16384"
        );
        assert!(err(r#"{"width": "8", "height": 3}"#).contains("width: expected a non-negative integer, found \"8\""));
        assert!(err(r#"{"width": 8, "height": 8, "preset": "dx9"}"#).contains("preset: unknown preset \"dx9\""));
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,0]]}"#))
            .contains("triangles[0].v: a triangle needs exactly 3 vertices, found 2"));
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,"inf"],[0,4]]}"#))
            .contains("triangles[0].v[1][1]: \"inf\" is not a finite number"));
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,"1/0"],[0,4]]}"#))
            .contains("triangles[0].v[1][1]: \"1/0\" has a zero denominator"));
        assert!(err(&scene_with(
            r#"{"v": [[0,0],[4,0],[0,4]], "colors": [[0,0,0],[0,256,0],[0,0,0]]}"#
        ))
        .contains("triangles[0].colors[1][1]: 256 is not an integer in 0..=255"));
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,0],[0,4]], "colour": []}"#))
            .contains("triangles[0].colour: unknown field"));
        assert!(err(r#"{"width": 8, "height": 8, "tie_rule": "top-right"}"#).contains("tie_rule: unknown tie rule"));
        assert!(
            err(r#"{"width": 8, "height": 8, "subpixel_bits": 17}"#).contains("subpixel_bits: 17 is outside 1..=16")
        );
        assert!(
            err(r#"{"width": 8, "height": 8, "pixel_centre": 0.25}"#).contains("pixel_centre: 0.25 is not 0.5 or 0")
        );
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,0],[0,null]]}"#))
            .contains("triangles[0].v[2][1]: expected a number or a numeric string, found null"));
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,0],[0,1e999]]}"#)).contains("exponent"));
    }

    #[test]
    fn round_trip_through_to_json() {
        let text = r#"{"width": 9, "height": 7, "preset": "gl", "rounding": "half-away", "pixel_centre": 0,
            "triangles": [{"v": [["1/3",0.5],[4,0],[0,"-7/2"]], "colors": [[1,2,3],[4,5,6],[7,8,9]]}, TRI],
            "polygons": [{"v": [[0,0],[10,0],["21/2",10],[0,10]], "holes": [[[1,1],[2,1],[1,"2.5"]]], "fill_rule": "even-odd"},
                         {"v": [[0,0],[3,0],[0,3]]}]}"#
            .replace("TRI", TRI);
        let s = parse_scene(&text, "s").unwrap();
        assert_eq!(s.convention().tie_rule, TieRule::BottomLeft);
        assert_eq!(s.convention().rounding, Rounding::HalfAwayFromZero);
        assert_eq!(s.polygons[0].holes[0][2].y, BigRational::new(5.into(), 2.into()));
        assert_eq!(s.polygons[1].fill_rule, crate::geom::FillRule::NonZero);
        let again = parse_scene(&s.to_json(), "again").unwrap();
        assert_eq!(again, s);
    }

    /// Found by the scene_parse fuzz target: `1e300` parsed, but its exact text (301 digits)
    /// was refused when the written scene was read back.
    #[test]
    fn fuzz_case_01_huge_exponent_round_trip() {
        for coord in ["1e300", "1e-300", "\"0.33333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333\""] {
            let text = scene_with(&format!(r#"{{"v": [[0, 0], [1, 0], [0, {coord}]]}}"#));
            let s = parse_scene(&text, "s").unwrap();
            assert_eq!(parse_scene(&s.to_json(), "again").unwrap(), s, "{coord}");
        }
    }

    /// JSON leaves a repeated key's meaning open and serde_json keeps the last: refused,
    /// naming the object's path and the key, wherever the object is.
    #[test]
    fn duplicate_keys_are_refused_with_their_path() {
        assert_eq!(
            err(r#"{"width": 4, "height": 4, "width": 9}"#),
            "s.json: duplicate key \"width\""
        );
        let tris = format!(r#"{TRI}, {TRI}, {{"v": [[0,0],[4,0],[0,4]], "v": [[0,0],[1,0],[0,1]]}}"#);
        assert_eq!(err(&scene_with(&tris)), "s.json: triangles[2]: duplicate key \"v\"");
        assert_eq!(
            err(r#"{"width": 8, "height": 8, "clip": {"rect": [0, 0, 4, 4], "rect": [0, 0, 8, 8]}}"#),
            "s.json: clip: duplicate key \"rect\""
        );
        // Deeper, inside an array inside an object inside an array.
        assert_eq!(
            err(
                r#"{"width": 8, "height": 8, "lines": [{"from": [0, 0], "to": [1, 1]}, {"from": [0, 0], "to": [1, 1], "rule": "diamond", "rule": "bresenham"}]}"#
            ),
            "s.json: lines[1]: duplicate key \"rule\""
        );
    }

    /// The same key in two different objects (or at two levels) is no duplicate.
    #[test]
    fn a_key_in_two_objects_is_fine() {
        let s = parse_scene(
            r#"{"width": 8, "height": 8, "triangles": [{"v": [[0,0],[4,0],[0,4]]}, {"v": [[1,1],[5,1],[1,5]]}],
                "viewport": {"width": 8, "height": 8}}"#,
            "s",
        )
        .unwrap();
        assert_eq!(s.triangles.len(), 2);
        assert_eq!(
            s.triangles[1].triangle.to_triangle().v[0],
            crate::geom::Point::from_ints(1, 1)
        );
    }

    /// A bare NaN (or Infinity) is not JSON: the error says so, where, and what to write.
    #[test]
    fn a_bare_nan_is_explained() {
        let text = "{\"width\": 8, \"height\": 8,\n \"triangles\": [{\"v\": [[0,0],[4,NaN],[0,4]]}]}";
        // Line 2 is ` "triangles": [{"v": [[0,0],[4,NaN],[0,4]]}]}`: a space, `"triangles"`
        // (11 bytes, to column 12), `: [{` (to 16), `"v"` (to 19), `: ` (to 21), `[[0,0],`
        // (to 28), `[4,` (to 31): NaN starts at column 32.
        assert_eq!(
            err(text),
            "s.json: malformed JSON: expected value at line 2 column 32: NaN is not JSON (JSON has no NaN \
             or infinity); a coordinate is a JSON number or a string holding a decimal or a fraction, \
             e.g. \"1/3\" or \"0.1\", and it must be finite"
        );
        assert!(err(&scene_with(r#"{"v": [[0,0],[4,-Infinity],[0,4]]}"#))
            .contains("-Infinity is not JSON (JSON has no NaN or infinity)"));
        // Other syntax errors keep serde_json's message alone.
        assert_eq!(
            err(r#"{"width": 8, "height": 8, "triangles": [}"#),
            "s.json: malformed JSON: expected value at line 1 column 41"
        );
    }

    #[test]
    fn non_utf8_is_an_error() {
        assert!(parse_scene_with(&[0xff, 0xfe], "b", &ParseOptions::default())
            .unwrap_err()
            .to_string()
            .contains("not UTF-8"));
    }
}
