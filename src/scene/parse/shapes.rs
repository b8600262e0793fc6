//! Parsing the polygon and clipping fields: `polygons`, `clip_space_triangles`,
//! `viewport`, `clip`.

use num_rational::BigRational;
use num_traits::Signed;
use serde_json::Value;

use super::{kind, show, Parser, MAX_POLYGON_VERTICES};
use crate::clip::homogeneous::{ClipVertex, DepthRange, NdcY, Viewport};
use crate::clip::Window;
use crate::convention::Preset;
use crate::fill::polygon::{locate_exact, Location};
use crate::geom::{FillRule, Point, Polygon};
use crate::scene::SceneError;

impl Parser<'_> {
    pub(super) fn polygons(&self, v: &Value) -> Result<Vec<Polygon>, SceneError> {
        self.each(v, "polygons", |p, at| self.polygon(p, at))
    }

    fn contour(&self, v: &Value, at: &str) -> Result<Vec<Point>, SceneError> {
        let list = self.array(v, at)?;
        if list.len() < 3 {
            return Err(self.err(
                at,
                format!("a polygon contour needs at least 3 vertices, found {}", list.len()),
            ));
        }
        if list.len() > MAX_POLYGON_VERTICES {
            return Err(self.err(
                at,
                format!("{} vertices, at most {MAX_POLYGON_VERTICES} per polygon", list.len()),
            ));
        }
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
        let total = outline.len() + holes.iter().map(Vec::len).sum::<usize>();
        if total > MAX_POLYGON_VERTICES {
            return Err(self.err(
                at,
                format!("{total} vertices in the outline and holes, at most {MAX_POLYGON_VERTICES} per polygon"),
            ));
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

    pub(super) fn clip_space_triangles(&self, v: &Value) -> Result<Vec<[ClipVertex; 3]>, SceneError> {
        self.each(v, "clip_space_triangles", |t, at| {
            let Value::Object(obj) = t else {
                return Err(self.err(
                    at,
                    format!("expected an object with \"v\", found {} {}", kind(t), show(t)),
                ));
            };
            self.known_fields(obj, at, &["v"])?;
            let v = self.triangle_vertices(obj, at, "a clip-space vertex is [x, y, z, w]")?;
            Ok(v.map(|pos| ClipVertex { pos, attrs: Vec::new() }))
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
                if list.len() > MAX_POLYGON_VERTICES {
                    return Err(self.err(
                        "clip.convex",
                        format!("{} vertices, at most {MAX_POLYGON_VERTICES}", list.len()),
                    ));
                }
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
}
