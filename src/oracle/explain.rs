//! Explaining one pixel of a scene: its exact sample, every nearby primitive's exact
//! evidence as written and as snapped, and which models cover it ([`explain_pixel`]); its
//! interpolated values, exactly, against another renderer's ([`values::explain_values`]).

pub mod values;

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::compare::{evidence, evidence_at, pixel_box_holds};
use super::evidence::{distance_text, shape_distance2};
use super::reason::primitive_name;
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::model::{prepare, render_samples, Model, ModelError, Primitives};
use crate::num::exact::{decimal_pair_text, pair_text};
use crate::pattern::SamplePattern;
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

impl PrimitiveAt {
    /// For people: its name, id and nearest edge, then its evidence (as written, and
    /// snapped when snapping moves it), each line starting with `indent`.
    fn text(&self, indent: &str) -> String {
        let mut s = format!(
            "{indent}{} (id {}): nearest edge {}\n",
            self.primitive, self.id, self.distance
        );
        match &self.snapped {
            None => {
                let _ = writeln!(s, "{indent}  as written = snapped: {}", self.as_written);
            }
            Some(snapped) => {
                let _ = writeln!(s, "{indent}  as written: {}", self.as_written);
                let _ = writeln!(s, "{indent}  snapped:    {snapped}");
            }
        }
        s
    }

    /// For programs: `{id, primitive, as_written, snapped (null when equal), distance}`.
    fn to_json(&self) -> Value {
        json!({"id": self.id, "primitive": self.primitive, "as_written": self.as_written,
               "snapped": self.snapped, "distance": self.distance})
    }
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
        .filter(|m| !m.is_plain())
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
            s.push('\n');
            s.push_str(&p.text(""));
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
        let primitives: Vec<Value> = self.primitives.iter().map(PrimitiveAt::to_json).collect();
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

/// One sample of a pixel under a pattern, explained.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampleAt {
    /// Its index in the pattern.
    pub index: usize,
    /// Its position in the pixel, exact text.
    pub position: String,
    /// The sample as a point, exact text, and in decimals.
    pub point: String,
    /// The primitives near it, with their evidence at it (as written, and snapped when
    /// snapping moves them) and their nearest edge (snapped).
    pub primitives: Vec<PrimitiveAt>,
}

/// The owners of each sample index of one pixel, in index order.
pub type SampleOwners = Vec<Vec<u32>>;

/// A pixel under a pattern of several samples: every sample's evidence and what every
/// model decides at each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SamplesExplanation {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The pattern, named.
    pub pattern: String,
    /// Each sample.
    pub samples: Vec<SampleAt>,
    /// Per model (the plain oracles aside), the owners at each sample index, or why the
    /// model refuses the scene under the pattern.
    pub models: Vec<(Model, Result<SampleOwners, ModelError>)>,
}

/// Explains every sample of `pattern` in pixel `(x, y)` (`None` when the pixel is off the
/// canvas or the scene has lines, which have no samples).
///
/// ```
/// use rasterproof::oracle::explain::explain_samples;
/// use rasterproof::pattern::SamplePattern;
/// use rasterproof::scene::parse_scene;
/// // The half plane x < 1/2 of pixel (0, 0): of the standard 4x samples, 0 and 2.
/// let scene = parse_scene(r#"{"width": 1, "height": 1, "triangles": [{"v": [[-4, -4], [0.5, -4], [0.5, 4]]}]}"#, "s.json").unwrap();
/// let four = SamplePattern::standard(4).unwrap();
/// let why = explain_samples(&scene.primitives(), &scene.target().unwrap(), &four, 0, 0).unwrap();
/// assert_eq!(why.samples[1].position, "(7/8, 3/8)");
/// let fixed = why.models.iter().find(|(m, _)| m.name() == "fixed").unwrap();
/// assert_eq!(fixed.1.as_ref().unwrap(), &vec![vec![0], vec![], vec![0], vec![]]);
/// assert!(why.to_text().contains("sample 2 at (1/8, 5/8)"));
/// ```
pub fn explain_samples(
    primitives: &Primitives,
    target: &Target,
    pattern: &SamplePattern,
    x: u32,
    y: u32,
) -> Option<SamplesExplanation> {
    if x >= target.width || y >= target.height || !primitives.lines.is_empty() {
        return None;
    }
    let shapes = |model: Model| prepare(primitives, target, model).ok().and_then(|p| p.shapes());
    let (written, snapped) = (shapes(Model::ExactPlain), shapes(Model::ExactSnappedPlain));
    let mut samples = Vec::new();
    for s in 0..pattern.len() {
        let p = pattern.sample(x, y, s);
        let mut near = Vec::new();
        if let (Some(written), Some(snapped)) = (&written, &snapped) {
            for (k, (w, sn)) in written.iter().zip(snapped).enumerate() {
                if !pixel_box_holds(w, x, y, target) && !pixel_box_holds(sn, x, y, target) {
                    continue;
                }
                let id = u32::try_from(k).expect("ids fit u32");
                let as_written = evidence_at(w, &p, target);
                near.push(PrimitiveAt {
                    id,
                    primitive: primitive_name(primitives, id).unwrap_or_default(),
                    snapped: (sn != w).then(|| evidence_at(sn, &p, target)),
                    as_written,
                    distance: distance_text(&shape_distance2(sn, &p, [i64::from(x), i64::from(y)])),
                });
            }
        }
        samples.push(SampleAt {
            index: s,
            position: pattern.position_text(s),
            point: format!("{}{}", pair_text(&p.x, &p.y), decimal_pair_text(&p.x, &p.y)),
            primitives: near,
        });
    }
    let models = Model::ALL
        .into_iter()
        .filter(|m| !m.is_plain())
        .map(|model| {
            let owners = render_samples(primitives, target, pattern, model)
                .map(|c| (0..pattern.len()).map(|s| c.owners(x, y, s).to_vec()).collect());
            (model, owners)
        })
        .collect();
    Some(SamplesExplanation {
        x,
        y,
        pattern: pattern.to_string(),
        samples,
        models,
    })
}

impl SamplesExplanation {
    /// For people: each sample with its evidence, then a table of the models' owners per
    /// sample index (`-` uncovered).
    pub fn to_text(&self) -> String {
        let mut s = format!("pixel ({}, {}), {} samples\n", self.x, self.y, self.pattern);
        for sample in &self.samples {
            let _ = writeln!(
                s,
                "\nsample {} at {} of the pixel: the point {}",
                sample.index, sample.position, sample.point
            );
            if sample.primitives.is_empty() {
                s.push_str("  no primitive's bounding box (grown by 2 px) holds the pixel\n");
            }
            for p in &sample.primitives {
                s.push_str(&p.text("  "));
            }
        }
        s.push_str("\nmodels, owners at each sample index (- uncovered):\n");
        let _ = write!(s, "  {:<15}", "");
        for k in 0..self.samples.len() {
            let _ = write!(s, " {:>6}", k);
        }
        s.push('\n');
        for (model, owners) in &self.models {
            let _ = write!(s, "  {:<15}", model.name());
            match owners {
                Ok(per_sample) => {
                    for ids in per_sample {
                        let text = if ids.is_empty() {
                            "-".to_string()
                        } else {
                            ids.iter().map(u32::to_string).collect::<Vec<_>>().join(",")
                        };
                        let _ = write!(s, " {text:>6}");
                    }
                    s.push('\n');
                }
                Err(e) => {
                    let _ = writeln!(s, " refuses: {e}");
                }
            }
        }
        s
    }

    /// For programs: `{"x", "y", "pattern", "samples": [{index, position, point,
    /// primitives: [{id, primitive, as_written, snapped, distance}]}], "models": [{model,
    /// owners: [[ids] per sample] (null when refused), error}]}`.
    pub fn to_json(&self) -> Value {
        let samples: Vec<Value> = self
            .samples
            .iter()
            .map(|sample| {
                let primitives: Vec<Value> = sample.primitives.iter().map(PrimitiveAt::to_json).collect();
                json!({"index": sample.index, "position": sample.position, "point": sample.point, "primitives": primitives})
            })
            .collect();
        let models: Vec<Value> = self
            .models
            .iter()
            .map(|(m, owners)| match owners {
                Ok(ids) => json!({"model": m.name(), "owners": ids, "error": null}),
                Err(e) => json!({"model": m.name(), "owners": null, "error": e.to_string()}),
            })
            .collect();
        json!({"x": self.x, "y": self.y, "pattern": self.pattern, "samples": samples, "models": models})
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
