//! The shape fields of a scene: `triangles`, `lines`, `polygons`, `clip_space_triangles`,
//! the clipping fields `viewport` and `clip`, and the sample pattern `samples`.

use super::json::{Map, Value};
use num_rational::BigRational;
use num_traits::Signed;

use super::reader::{kind, show, Reader};
use super::MAX_TRIANGLES;
use crate::clip::homogeneous::{ClipVertex, DepthRange, NdcY, Viewport};
use crate::clip::Window;
use crate::convention::Preset;
use crate::fill::polygon::{locate_exact, Location};
use crate::geom::Rgb;
use crate::geom::{FillRule, Point, Polygon, Triangle};
use crate::interp::values::Varyings;
use crate::line::{BresenhamTie, Line, LineRule, MAX_BRESENHAM_COORD};
use crate::pattern::{PatternError, SamplePattern, MAX_SAMPLES, STANDARD_COUNTS};
use crate::scene::{SceneError, SceneTriangle, VertexValues};

/// A line's values: every declared varying's channels at `from`, then at `to`.
type EndValues = [Vec<BigRational>; 2];

impl Reader<'_> {
    pub(super) fn triangles(&self, v: &Value, varyings: &Varyings) -> Result<Vec<SceneTriangle>, SceneError> {
        self.each(v, "triangles", MAX_TRIANGLES, |t, at| self.triangle(t, at, varyings))
    }

    fn triangle(&self, v: &Value, at: &str, varyings: &Varyings) -> Result<SceneTriangle, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err(
                at,
                format!("expected an object with \"v\", found {} {}", kind(v), show(v)),
            ));
        };
        self.known_fields(obj, at, &["v", "colors", "varyings", "w"])?;
        let [a, b, c] = self
            .triangle_vertices(obj, at, "a vertex is [x, y]")?
            .map(|[x, y]| Point::new(x, y));
        let colours = match obj.get("colors") {
            None => None,
            Some(cv) => Some(self.colours(cv, &format!("{at}.colors"))?),
        };
        let w = self.window_w(obj, at, varyings)?;
        let values = self
            .vertex_values(obj, at, varyings)?
            .map(|values| Box::new(VertexValues { w, values }));
        Ok(SceneTriangle {
            triangle: Triangle::new(a, b, c).into(),
            colours,
            values,
        })
    }

    /// The field `v` of a triangle object at `at`: exactly 3 vertices of `D` coordinates
    /// each (`shape` says which, for the error).
    fn triangle_vertices<const D: usize>(
        &self,
        obj: &Map,
        at: &str,
        shape: &str,
    ) -> Result<[[BigRational; D]; 3], SceneError> {
        let vf = format!("{at}.v");
        let verts = self.array(
            obj.get("v").ok_or_else(|| self.err(&vf, "missing (required)".into()))?,
            &vf,
        )?;
        if verts.len() != 3 {
            return Err(self.err(
                &vf,
                format!("a triangle needs exactly 3 vertices, found {}", verts.len()),
            ));
        }
        let mut out = Vec::with_capacity(3);
        for (i, p) in verts.iter().enumerate() {
            let pf = format!("{vf}[{i}]");
            let coords = self.array(p, &pf)?;
            if coords.len() != D {
                return Err(self.err(&pf, format!("{shape}, found {} values", coords.len())));
            }
            let values = coords
                .iter()
                .enumerate()
                .map(|(k, c)| self.coordinate(c, &format!("{pf}[{k}]")))
                .collect::<Result<Vec<_>, _>>()?;
            out.push(<[BigRational; D]>::try_from(values).expect("D coordinates checked"));
        }
        Ok(out.try_into().expect("three vertices checked"))
    }

    /// The lines, each with its ends' values where the scene declares varyings.
    pub(super) fn lines(&self, v: &Value, varyings: &Varyings) -> Result<Vec<(Line, Option<EndValues>)>, SceneError> {
        self.each(v, "lines", MAX_TRIANGLES, |l, at| {
            let line = self.line(l, at)?;
            let values = match l {
                Value::Object(obj) => self.vertex_values(obj, at, varyings)?,
                _ => None, // line() refused it
            };
            Ok((line, values))
        })
    }

    fn line(&self, v: &Value, at: &str) -> Result<Line, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err(
                at,
                format!(
                    "expected an object with \"from\" and \"to\", found {} {}",
                    kind(v),
                    show(v)
                ),
            ));
        };
        self.known_fields(obj, at, &["from", "to", "rule", "tie", "varyings"])?;
        let from = self.point(obj.get("from"), &format!("{at}.from"))?;
        let to = self.point(obj.get("to"), &format!("{at}.to"))?;
        let rule_name = match obj.get("rule") {
            None => "bresenham",
            Some(r) => self.string(r, &format!("{at}.rule"))?,
        };
        let tie = match obj.get("tie") {
            None => BresenhamTie::Stay,
            Some(t) => {
                let name = self.string(t, &format!("{at}.tie"))?;
                BresenhamTie::from_name(name).ok_or_else(|| {
                    self.err(
                        &format!("{at}.tie"),
                        format!("unknown tie {name:?} (expected stay or step)"),
                    )
                })?
            }
        };
        let rule = match rule_name {
            "bresenham" => LineRule::Bresenham(tie),
            "diamond" => {
                if obj.contains_key("tie") {
                    return Err(self.err(
                        &format!("{at}.tie"),
                        "only Bresenham lines have a tie convention".into(),
                    ));
                }
                LineRule::Diamond
            }
            other => {
                return Err(self.err(
                    &format!("{at}.rule"),
                    format!("unknown rule {other:?} (expected bresenham or diamond)"),
                ))
            }
        };
        if let LineRule::Bresenham(_) = rule {
            for (end, p) in [("from", &from), ("to", &to)] {
                for (axis, c) in [(0, &p.x), (1, &p.y)] {
                    let field = format!("{at}.{end}[{axis}]");
                    if !c.is_integer() {
                        return Err(self.err(&field, format!(
                            "{} is not an integer: a Bresenham line joins pixel addresses (use \"rule\": \"diamond\" for fractional endpoints)",
                            crate::num::exact::exact_text(c)
                        )));
                    }
                    if c.abs() > BigRational::from_integer(MAX_BRESENHAM_COORD.into()) {
                        return Err(self.err(
                            &field,
                            format!(
                                "{} is outside +-2^24, the Bresenham envelope (it walks every step)",
                                crate::num::exact::exact_text(c)
                            ),
                        ));
                    }
                }
            }
        }
        Ok(Line { from, to, rule })
    }

    fn colours(&self, v: &Value, at: &str) -> Result<[Rgb; 3], SceneError> {
        let list = self.array(v, at)?;
        if list.len() != 3 {
            return Err(self.err(at, format!("expected 3 colours (one per vertex), found {}", list.len())));
        }
        let mut out = [[0u8; 3]; 3];
        for (i, c) in list.iter().enumerate() {
            let cf = format!("{at}[{i}]");
            let rgb = self.array(c, &cf)?;
            if rgb.len() != 3 {
                return Err(self.err(&cf, format!("a colour is [r, g, b], found {} values", rgb.len())));
            }
            for (ch, value) in rgb.iter().enumerate() {
                let f = format!("{cf}[{ch}]");
                out[i][ch] = value
                    .as_u64()
                    .and_then(|n| u8::try_from(n).ok())
                    .ok_or_else(|| self.err(&f, format!("{} is not an integer in 0..=255", show(value))))?;
            }
        }
        Ok(out)
    }

    pub(super) fn polygons(&self, v: &Value) -> Result<Vec<Polygon>, SceneError> {
        self.each(v, "polygons", MAX_TRIANGLES, |p, at| self.polygon(p, at))
    }

    /// Counts `n` more polygon or clip-window vertices at `at` against the scene's limit
    /// ([`super::MAX_SCENE_VERTICES`] or the caller's), before they are read.
    fn count_vertices(&self, n: usize, at: &str) -> Result<(), SceneError> {
        let total = self.vertices.get().saturating_add(n);
        if total > self.vertex_limit {
            return Err(self.err(
                at,
                format!(
                    "{n} vertices make {total} polygon and clip-window vertices in the scene, at most {}",
                    self.vertex_limit
                ),
            ));
        }
        self.vertices.set(total);
        Ok(())
    }

    fn contour(&self, v: &Value, at: &str) -> Result<Vec<Point>, SceneError> {
        let list = self.array(v, at)?;
        if list.len() < 3 {
            return Err(self.err(
                at,
                format!("a polygon contour needs at least 3 vertices, found {}", list.len()),
            ));
        }
        self.count_vertices(list.len(), at)?;
        list.iter()
            .enumerate()
            .map(|(i, p)| self.point(Some(p), &format!("{at}[{i}]")))
            .collect()
    }

    fn polygon(&self, v: &Value, at: &str) -> Result<Polygon, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err(
                at,
                format!("expected an object with \"v\", found {} {}", kind(v), show(v)),
            ));
        };
        self.known_fields(obj, at, &["v", "holes", "fill_rule"])?;
        let vf = format!("{at}.v");
        let outline = self.contour(
            obj.get("v").ok_or_else(|| self.err(&vf, "missing (required)".into()))?,
            &vf,
        )?;
        let mut holes = Vec::new();
        if let Some(h) = obj.get("holes") {
            let hf = format!("{at}.holes");
            for (k, hole) in self.array(h, &hf)?.iter().enumerate() {
                holes.push(self.contour(hole, &format!("{hf}[{k}]"))?);
            }
        }
        let fill_rule = match obj.get("fill_rule") {
            None => FillRule::NonZero,
            Some(r) => {
                let name = self.string(r, &format!("{at}.fill_rule"))?;
                FillRule::from_name(name).ok_or_else(|| {
                    self.err(
                        &format!("{at}.fill_rule"),
                        format!("unknown fill rule {name:?} (expected nonzero or even-odd)"),
                    )
                })?
            }
        };
        // A hole entirely outside the outline is a mistake; one vertex decides that (a
        // hole crossing the outline is subtracted where it overlaps it).
        for (k, hole) in holes.iter().enumerate() {
            let p = &hole[0];
            if locate_exact(p, &outline) == Location::Outside {
                return Err(self.err(
                    &format!("{at}.holes[{k}][0]"),
                    format!("{p} lies outside the outline {vf}"),
                ));
            }
        }
        Ok(Polygon {
            outline,
            holes,
            fill_rule,
        })
    }

    pub(super) fn clip_space_triangles(
        &self,
        v: &Value,
        varyings: &Varyings,
    ) -> Result<Vec<[ClipVertex; 3]>, SceneError> {
        self.each(v, "clip_space_triangles", MAX_TRIANGLES, |t, at| {
            let Value::Object(obj) = t else {
                return Err(self.err(
                    at,
                    format!("expected an object with \"v\", found {} {}", kind(t), show(t)),
                ));
            };
            self.known_fields(obj, at, &["v", "varyings"])?;
            let v = self.triangle_vertices(obj, at, "a clip-space vertex is [x, y, z, w]")?;
            let [a0, a1, a2] = self.vertex_values(obj, at, varyings)?.unwrap_or_default();
            let [p0, p1, p2] = v;
            Ok([(p0, a0), (p1, a1), (p2, a2)].map(|(pos, attrs)| ClipVertex { pos, attrs }))
        })
    }

    pub(super) fn viewport(&self, v: &Value, width: u32, height: u32, preset: Preset) -> Result<Viewport, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err("viewport", format!("expected an object, found {} {}", kind(v), show(v))));
        };
        self.known_fields(obj, "viewport", &["x", "y", "width", "height", "ndc_y", "depth"])?;
        let number = |key: &str, default: u32| match obj.get(key) {
            None => Ok(BigRational::from_integer(default.into())),
            Some(v) => self.coordinate(v, &format!("viewport.{key}")),
        };
        let (x, y, w, h) = (
            number("x", 0)?,
            number("y", 0)?,
            number("width", width)?,
            number("height", height)?,
        );
        for (key, value) in [("width", &w), ("height", &h)] {
            if !value.is_positive() {
                return Err(self.err(
                    &format!("viewport.{key}"),
                    format!("{} is not positive", crate::num::exact::exact_text(value)),
                ));
            }
        }
        let (default_y, default_depth) = crate::scene::preset_ndc(preset);
        let y_axis = match obj.get("ndc_y") {
            None => default_y,
            Some(v) => match self.string(v, "viewport.ndc_y")? {
                "down" => NdcY::Down,
                "up" => NdcY::Up,
                other => return Err(self.err("viewport.ndc_y", format!("unknown {other:?} (expected up or down)"))),
            },
        };
        let depth = match obj.get("depth") {
            None => default_depth,
            Some(v) => match self.string(v, "viewport.depth")? {
                "zero-to-one" => DepthRange::ZeroToOne,
                "minus-one-to-one" => DepthRange::MinusOneToOne,
                other => {
                    return Err(self.err(
                        "viewport.depth",
                        format!("unknown {other:?} (expected zero-to-one or minus-one-to-one)"),
                    ))
                }
            },
        };
        Ok(Viewport::new(x, y, w, h, y_axis, depth).expect("positive sides checked"))
    }

    pub(super) fn clip(&self, v: &Value) -> Result<Window, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err(
                "clip",
                format!(
                    "expected an object with \"rect\" or \"convex\", found {} {}",
                    kind(v),
                    show(v)
                ),
            ));
        };
        self.known_fields(obj, "clip", &["rect", "convex"])?;
        match (obj.get("rect"), obj.get("convex")) {
            (Some(r), None) => {
                let list = self.array(r, "clip.rect")?;
                if list.len() != 4 {
                    return Err(self.err(
                        "clip.rect",
                        format!("expected [xmin, ymin, xmax, ymax], found {} values", list.len()),
                    ));
                }
                let c = |k: usize| self.coordinate(&list[k], &format!("clip.rect[{k}]"));
                Window::rect(c(0)?, c(1)?, c(2)?, c(3)?).map_err(|e| self.err("clip.rect", e.to_string()))
            }
            (None, Some(c)) => {
                let list = self.array(c, "clip.convex")?;
                self.count_vertices(list.len(), "clip.convex")?;
                let points = list
                    .iter()
                    .enumerate()
                    .map(|(i, p)| self.point(Some(p), &format!("clip.convex[{i}]")))
                    .collect::<Result<Vec<_>, _>>()?;
                Window::convex(points).map_err(|e| self.err("clip.convex", e.to_string()))
            }
            _ => Err(self.err("clip", "expected exactly one of \"rect\" and \"convex\"".into())),
        }
    }

    /// `samples`: the count of a standard pattern (1, 2, 4, 8, 16), or a list of positions
    /// `[x, y]`, each an exact fraction of the pixel from its top-left corner.
    pub(super) fn samples(&self, v: &Value) -> Result<SamplePattern, SceneError> {
        if let Value::Number(_) = v {
            let n = self.integer(v, "samples")?;
            return usize::try_from(n)
                .ok()
                .and_then(SamplePattern::standard)
                .ok_or_else(|| {
                    let counts: Vec<String> = STANDARD_COUNTS.iter().map(ToString::to_string).collect();
                    self.err(
                        "samples",
                        format!(
                            "{n} has no standard pattern (standard counts: {}); give the positions as a list of [x, y] instead",
                            counts.join(", ")
                        ),
                    )
                });
        }
        let positions = self.each(v, "samples", MAX_SAMPLES, |p, at| {
            let point = self.point(Some(p), at)?;
            Ok([point.x, point.y])
        })?;
        SamplePattern::custom(positions).map_err(|e| {
            let at = match &e {
                PatternError::Outside { index, axis, .. } => {
                    format!("samples[{index}][{}]", if *axis == 'x' { 0 } else { 1 })
                }
                PatternError::Duplicate { second, .. } => format!("samples[{second}]"),
                PatternError::Empty | PatternError::TooMany(_) => "samples".to_string(),
            };
            self.err(&at, e.to_string())
        })
    }
}
