//! Explaining one pixel of a scene: its exact sample, every nearby primitive's exact
//! evidence as written and as snapped, and which models cover it ([`explain_pixel`]).

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::compare::{evidence, pixel_box_holds};
use super::evidence::{distance_text, shape_distance2};
use super::reason::primitive_name;
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::model::{prepare, Model, ModelError, Primitives};
use crate::num::exact::{decimal_pair_text, pair_text};
use crate::raster::sample_exact;

/// One primitive near the pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PrimitiveAt {
    /// Its id.
    pub id: u32,
    /// Its scene field and index (`triangles[0]`).
    pub primitive: String,
    /// The evidence on the primitive as written (model `exact`).
    pub as_written: String,
    /// The evidence on the snapped primitive (model `exact-snapped`), when the scene's
    /// snapping moves it.
    pub snapped: Option<String>,
    /// The distance from the sample to its nearest edge (snapped), for people.
    pub distance: String,
}

/// What each model says at the pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModelAt {
    /// The model.
    pub model: Model,
    /// The ids covering the pixel, or why the model refuses the scene.
    pub owners: Result<Vec<u32>, ModelError>,
}

/// The explanation of one pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PixelExplanation {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The sample, exact text.
    pub sample: String,
    /// The sample in decimals beside it, for people ([`decimal_pair_text`]): ` = (490.5,
    /// 69.5)`, empty at integer coordinates.
    pub sample_decimal: String,
    /// The primitives whose bounding box (grown by 2 px) holds the sample.
    pub primitives: Vec<PrimitiveAt>,
    /// Every model except the plain oracles (which the planned `exact` and
    /// `exact-snapped` equal, proven by the property tests, and which the evidence above
    /// reads directly).
    pub models: Vec<ModelAt>,
}

/// Records the owners of one pixel.
struct Probe {
    x: u32,
    y: u32,
    ids: Vec<u32>,
}

impl CoverageSink for Probe {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        if (x, y) == (self.x, self.y) {
            self.ids.push(id);
        }
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        if y == self.y && (x0..=x1).contains(&self.x) {
            self.ids.push(id);
        }
    }
}

/// Explains pixel `(x, y)` of `primitives` on `target` (`None` when the pixel is off the
/// canvas).
///
/// ```
/// use rasterproof::oracle::explain_pixel;
/// use rasterproof::scene::parse_scene;
/// let scene = parse_scene(r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#, "s.json").unwrap();
/// let why = explain_pixel(&scene.primitives(), &scene.target().unwrap(), 1, 2).unwrap();
/// // The sample (3/2, 5/2) lies on the hypotenuse, a right edge: outside under top-left.
/// assert!(why.primitives[0].as_written.contains("E=0 (exclusive)"));
/// assert!(why.to_text().contains("fixed"));
/// ```
pub fn explain_pixel(primitives: &Primitives, target: &Target, x: u32, y: u32) -> Option<PixelExplanation> {
    if x >= target.width || y >= target.height {
        return None;
    }
    let shapes = |model: Model| prepare(primitives, target, model).ok().and_then(|p| p.shapes());
    let written = shapes(Model::ExactPlain);
    let snapped = shapes(Model::ExactSnappedPlain);
    let p = sample_exact(x, y, target);
    let mut out = Vec::new();
    if let (Some(written), Some(snapped)) = (&written, &snapped) {
        for (k, (w, s)) in written.iter().zip(snapped).enumerate() {
            if !pixel_box_holds(w, x, y, target) && !pixel_box_holds(s, x, y, target) {
                continue;
            }
            let id = u32::try_from(k).expect("ids fit u32");
            let as_written = evidence(w, x, y, target);
            let snapped_text = evidence(s, x, y, target);
            out.push(PrimitiveAt {
                id,
                primitive: primitive_name(primitives, id).unwrap_or_default(),
                snapped: (s != w).then_some(snapped_text),
                as_written,
                distance: distance_text(&shape_distance2(s, &p, [i64::from(x), i64::from(y)])),
            });
        }
    }
    let models = Model::ALL
        .into_iter()
        .filter(|m| !matches!(m, Model::ExactPlain | Model::ExactSnappedPlain))
        .map(|model| ModelAt {
            model,
            owners: prepare(primitives, target, model).map(|prepared| {
                let mut probe = Probe { x, y, ids: Vec::new() };
                prepared.render(target, &mut probe);
                probe.ids.sort_unstable();
                probe.ids
            }),
        })
        .collect();
    Some(PixelExplanation {
        x,
        y,
        sample: pair_text(&p.x, &p.y),
        sample_decimal: decimal_pair_text(&p.x, &p.y),
        primitives: out,
        models,
    })
}

fn owners(ids: &[u32]) -> String {
    if ids.is_empty() {
        "not covered".to_string()
    } else {
        let v: Vec<String> = ids.iter().map(u32::to_string).collect();
        format!("covered by {}", v.join(", "))
    }
}

impl PixelExplanation {
    /// For people.
    pub fn to_text(&self) -> String {
        let mut s = format!(
            "pixel ({}, {}): sample {}{}\n",
            self.x, self.y, self.sample, self.sample_decimal
        );
        if self.primitives.is_empty() {
            s.push_str("no primitive's bounding box (grown by 2 px) holds the sample\n");
        }
        for p in &self.primitives {
            let _ = writeln!(s, "\n{} (id {}): nearest edge {}", p.primitive, p.id, p.distance);
            match &p.snapped {
                None => {
                    let _ = writeln!(s, "  as written = snapped: {}", p.as_written);
                }
                Some(snapped) => {
                    let _ = writeln!(s, "  as written: {}", p.as_written);
                    let _ = writeln!(s, "  snapped:    {snapped}");
                }
            }
        }
        s.push_str("\nmodels:\n");
        for m in &self.models {
            let said = match &m.owners {
                Ok(ids) => owners(ids),
                Err(e) => format!("refuses the scene: {e}"),
            };
            let _ = writeln!(s, "  {:<15} {said}", m.model.name());
        }
        s
    }

    /// For programs: `{"x", "y", "sample", "primitives": [{id, primitive, as_written,
    /// snapped (null when equal), distance}], "models": [{model, owners (null when
    /// refused), error}]}`.
    pub fn to_json(&self) -> Value {
        let primitives: Vec<Value> = self
            .primitives
            .iter()
            .map(|p| {
                json!({"id": p.id, "primitive": p.primitive, "as_written": p.as_written,
                       "snapped": p.snapped, "distance": p.distance})
            })
            .collect();
        let models: Vec<Value> = self
            .models
            .iter()
            .map(|m| match &m.owners {
                Ok(ids) => json!({"model": m.model.name(), "owners": ids, "error": null}),
                Err(e) => json!({"model": m.model.name(), "owners": null, "error": e.to_string()}),
            })
            .collect();
        json!({"x": self.x, "y": self.y, "sample": self.sample, "primitives": primitives, "models": models})
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;

    #[test]
    fn every_model_and_nearby_primitive_is_named() {
        let scene = parse_scene(
            r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}, {"v": [[6, 6], [7, 6], [7, 7]]}],
                "lines": [{"from": [0, 7], "to": [7, 7]}]}"#,
            "s.json",
        )
        .unwrap();
        let target = scene.target().unwrap();
        let why = explain_pixel(&scene.primitives(), &target, 1, 1).unwrap();
        assert_eq!(why.sample, "(3/2, 3/2)");
        assert_eq!(why.sample_decimal, " = (1.5, 1.5)");
        // The far small triangle and the line at y = 7 are more than 2 px away.
        let ids: Vec<u32> = why.primitives.iter().map(|p| p.id).collect();
        assert_eq!(ids, [0]);
        assert_eq!(why.models.len(), Model::ALL.len() - 2);
        for m in &why.models {
            assert_eq!(m.owners.as_ref().unwrap(), &vec![0], "{}", m.model.name());
        }
        assert!(explain_pixel(&scene.primitives(), &target, 8, 0).is_none());
        let line = explain_pixel(&scene.primitives(), &target, 3, 7).unwrap();
        assert!(line.primitives.iter().any(|p| p.primitive == "lines[0]"));
    }
}
