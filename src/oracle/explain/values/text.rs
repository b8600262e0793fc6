//! An explained pixel's values for people (text) and programs (JSON):
//! [`ValueExplanation::to_text`], [`ValueExplanation::to_json`].

use std::fmt::Write as _;

use num_rational::BigRational;
use serde_json::{json, Value};

use super::{ChannelValue, Derivation, SampleValue, ValueExplanation};
use crate::geom::Point;
use crate::interp::envelope::ROUNDINGS;
use crate::interp::values::Interpolation;
use crate::num::exact::{exact_text, pair_text};
use crate::oracle::compare::values::{TheirValue, ValueClass};

/// An f32 and its bits: `3.9172366e0 (0x407ab4f2)`.
fn f32_text(f: f32) -> String {
    format!("{f:e} (0x{:08x})", f.to_bits())
}

/// An envelope's bound for people: `1.234e-6`, or why there is none.
fn bound_text(bound: Option<f64>) -> String {
    bound.map_or_else(|| "none (f32 bounds nothing here)".to_string(), |b| format!("{b:.3e}"))
}

/// A list of exact numbers: `(1/2, -3, 0)`.
fn list_text(values: &[BigRational]) -> String {
    let texts: Vec<String> = values.iter().map(exact_text).collect();
    format!("({})", texts.join(", "))
}

/// The interpolation's formula in symbols, with where it is defined.
fn definition(interpolation: Interpolation, segment: bool) -> &'static str {
    match (interpolation, segment) {
        (Interpolation::Smooth, false) => {
            "smooth: f = sum mu_i f_i / w_i / sum mu_i / w_i = sum b_i f_i / sum b_i (OpenGL 4.6 equation (14.9))"
        }
        (Interpolation::NoPerspective, false) => "noperspective: f = sum mu_i f_i (OpenGL 4.6 equation (14.10))",
        (Interpolation::Flat, _) => "flat: the provoking vertex's value (OpenGL 4.6 section 13.4)",
        (_, true) => {
            "along a segment: f = (1 - t) f0 + t f1, t the point's projection onto it (OpenGL 4.6 section 14.5.1)"
        }
    }
}

impl Derivation {
    /// For people: the vertices, then the barycentrics and weights at the point.
    fn text(&self, primitive: &str, out: &mut String) {
        match self {
            Derivation::Triangle(t) => {
                let vertices: Vec<String> = t
                    .vertices
                    .iter()
                    .enumerate()
                    .map(|(i, (p, w))| match p {
                        Some(p) => format!("vertex {i} at {}, w {}", pair_text(&p.x, &p.y), exact_text(w)),
                        None => format!("vertex {i} at infinity (w 0)"),
                    })
                    .collect();
                let _ = writeln!(out, "  {primitive}: {}", vertices.join("; "));
                if let (Some(b), Some(inv_w)) = (&t.b, t.inverse_w()) {
                    let _ = writeln!(
                        out,
                        "  homogeneous barycentrics b, solving b0 h0 + b1 h1 + b2 h2 = (x, y, 1) with h_i = (x_i w_i, y_i w_i, w_i):\n    b = {}; 1/w = b0 + b1 + b2 = {}",
                        list_text(b),
                        exact_text(&inv_w)
                    );
                }
                if let Some(mu) = t.window_barycentrics() {
                    let _ = writeln!(out, "  window barycentrics mu_i = b_i w_i: {}", list_text(&mu));
                }
                if let Some(weights) = t.weights() {
                    let _ = writeln!(
                        out,
                        "  perspective-correct weights b_i / (b0 + b1 + b2): {}",
                        list_text(&weights)
                    );
                }
            }
            Derivation::Segment(s) => {
                let [a, b] = &s.ends;
                let _ = writeln!(
                    out,
                    "  {primitive}: from {} to {}",
                    pair_text(&a.x, &a.y),
                    pair_text(&b.x, &b.y)
                );
                if let Some(t) = &s.t {
                    let _ = writeln!(
                        out,
                        "  t = (p - from) . (to - from) / |to - from|^2 = {}",
                        exact_text(t)
                    );
                }
            }
        }
    }

    /// For programs.
    fn json(&self) -> Value {
        let list = |v: &[BigRational]| v.iter().map(exact_text).collect::<Vec<_>>();
        match self {
            Derivation::Triangle(t) => json!({
                "kind": "triangle",
                "vertices": t.vertices.iter().map(|(p, w)| json!({
                    "window": p.as_ref().map(|p| [exact_text(&p.x), exact_text(&p.y)]),
                    "w": exact_text(w),
                })).collect::<Vec<_>>(),
                "homogeneous_barycentrics": t.b.as_ref().map(|b| list(b)),
                "inverse_w": t.inverse_w().as_ref().map(exact_text),
                "window_barycentrics": t.window_barycentrics().as_ref().map(|m| list(m)),
                "weights": t.weights().as_ref().map(|w| list(w)),
            }),
            Derivation::Segment(s) => json!({
                "kind": "segment",
                "ends": s.ends.iter().map(|p| [exact_text(&p.x), exact_text(&p.y)]).collect::<Vec<_>>(),
                "t": s.t.as_ref().map(exact_text),
            }),
        }
    }
}

impl ChannelValue {
    /// For people: the formula, the envelope and the centroid's range (when `full`; else
    /// only the exact value), the exact value's nearest f32, theirs and its distance.
    fn text(&self, full: bool, out: &mut String) {
        if full {
            let _ = writeln!(out, "  channel {}: {}", self.channel, self.formula);
        } else {
            let _ = writeln!(out, "  channel {}: exact {}", self.channel, exact_text(&self.exact));
        }
        let nearest = self.nearest.map_or_else(|| "beyond f32's range".to_string(), f32_text);
        let _ = writeln!(out, "    nearest f32 {nearest}");
        match self.theirs {
            Some(TheirValue::F32(f)) => {
                let steps = self.steps.map_or_else(
                    || "no distance in f32 steps".to_string(),
                    |s| match s {
                        0 => "0 f32 steps".to_string(),
                        s => format!("{s:+} f32 steps"),
                    },
                );
                let _ = writeln!(out, "    theirs {}: {steps}", f32_text(f));
            }
            Some(TheirValue::Level(l)) => {
                let allowed = self.levels.map_or_else(String::new, |(lo, hi)| match lo == hi {
                    true => format!(" (the rule allows level {lo})"),
                    false => format!(" (the rule allows levels {lo} to {hi})"),
                });
                let _ = writeln!(out, "    theirs level {l}{allowed}");
            }
            None => {}
        }
        if !full {
            return;
        }
        let _ = writeln!(
            out,
            "    f32 envelope ({ROUNDINGS} roundings): near {}, far {}",
            bound_text(self.envelope.near),
            bound_text(self.envelope.far)
        );
        if let Some((lo, hi, bound)) = &self.centroid_range {
            let _ = writeln!(
                out,
                "    centroid range (any point of the pixel inside the primitive): [{}, {}], far envelope at its corners {}",
                exact_text(lo),
                exact_text(hi),
                bound_text(*bound)
            );
        }
    }

    /// For programs.
    fn json(&self) -> Value {
        json!({
            "channel": self.channel,
            "vertex_values": self.vertex_values.iter().map(exact_text).collect::<Vec<_>>(),
            "formula": self.formula,
            "exact": exact_text(&self.exact),
            "nearest_f32": self.nearest,
            "nearest_f32_bits": self.nearest.map(|f| format!("0x{:08x}", f.to_bits())),
            "theirs": self.theirs.map(TheirValue::json),
            "theirs_bits": match self.theirs {
                Some(TheirValue::F32(f)) => Some(format!("0x{:08x}", f.to_bits())),
                _ => None,
            },
            "f32_steps": self.steps,
            "levels": self.levels.map(|(lo, hi)| [lo, hi]),
            "envelope": {"near": self.envelope.near, "far": self.envelope.far},
            "centroid_range": self.centroid_range.as_ref().map(|(lo, hi, bound)| json!({
                "least": exact_text(lo),
                "greatest": exact_text(hi),
                "bound": bound,
            })),
        })
    }
}

impl SampleValue {
    /// Why the sample shows its primitive, in words.
    fn why(&self) -> String {
        match self.owners.as_slice() {
            [] => "no primitive covers it".to_string(),
            [_] => "the only primitive covering it".to_string(),
            many => {
                let ids: Vec<String> = many.iter().map(u32::to_string).collect();
                format!(
                    "the highest id of its owners {} (the last drawn: what a renderer without a depth test writes)",
                    ids.join(", ")
                )
            }
        }
    }

    /// Whether it is judged, or why not, in words.
    fn judged_text(&self) -> Option<String> {
        self.theirs.as_ref()?;
        Some(match (self.class, &self.shown) {
            (Some(c), _) => format!(
                "class {}{}: {}",
                c.name(),
                if c.is_off() { " (off)" } else { "" },
                c.meaning()
            ),
            (None, None) => {
                "not judged: no primitive covers the sample (coverage is compare --as ids's question)".to_string()
            }
            (None, Some(_)) => "not judged: the sample has no exact value".to_string(),
        })
    }
}

impl ValueExplanation {
    /// For people: the varying, then each sample: its primitive and why, the point, the
    /// derivation, each channel's formula, exact value, nearest f32, theirs, distance and
    /// envelope, and its class. A sample whose value is an earlier sample's (the same
    /// primitive at the same point) names that sample instead of deriving it again.
    pub fn to_text(&self) -> String {
        let v = &self.varying;
        let samples = self
            .pattern
            .as_ref()
            .map_or_else(String::new, |p| format!(", {p} samples"));
        let mut s = format!(
            "pixel ({}, {}){samples}: values of {:?} ({}, {}, {} channel{}), provoking vertex {}; coverage of model {}",
            self.x,
            self.y,
            v.name,
            v.interpolation.name(),
            v.sampling.name(),
            v.channels,
            if v.channels == 1 { "" } else { "s" },
            self.provoking.name(),
            self.model
        );
        match &self.read_as {
            Some(read_as) => {
                let _ = writeln!(s, "; theirs read as {read_as}");
            }
            None => s.push('\n'),
        }
        let mut seen: Vec<(u32, &Point, usize)> = Vec::new();
        for sample in &self.samples {
            s.push('\n');
            let place = sample.position.as_ref().map_or_else(String::new, |p| {
                format!("sample {} at {p} of the pixel: ", sample.index)
            });
            let Some(shown) = &sample.shown else {
                let _ = writeln!(s, "{place}not covered (model {})", self.model);
                theirs_only(sample, &mut s);
                continue;
            };
            let _ = writeln!(
                s,
                "{place}shows {} (id {}), {}",
                shown.primitive,
                shown.id,
                sample.why()
            );
            let earlier = seen
                .iter()
                .find(|(id, p, _)| *id == shown.id && **p == shown.point)
                .map(|&(.., k)| k);
            match earlier {
                Some(k) => {
                    let _ = writeln!(
                        s,
                        "  the same value as sample {k}: the same primitive at the same point"
                    );
                }
                None => {
                    let _ = writeln!(s, "  taken at {}", shown.at);
                    if let Some(d) = &shown.derivation {
                        let segment = matches!(d, Derivation::Segment(_));
                        let _ = writeln!(s, "  {}", definition(v.interpolation, segment));
                        d.text(&shown.primitive, &mut s);
                    }
                    seen.push((shown.id, &shown.point, sample.index));
                }
            }
            match &shown.channels {
                Ok(channels) => {
                    for c in channels {
                        c.text(earlier.is_none(), &mut s);
                    }
                }
                Err(e) => {
                    let _ = writeln!(s, "  no value: {e}");
                    theirs_only(sample, &mut s);
                    continue;
                }
            }
            if let Some(judged) = sample.judged_text() {
                let _ = writeln!(s, "  {judged}");
            }
        }
        s
    }
}

/// Their channels at a sample without an exact value, and why it is not judged.
fn theirs_only(sample: &SampleValue, s: &mut String) {
    if let Some(theirs) = &sample.theirs {
        let texts: Vec<String> = theirs
            .iter()
            .map(|t| match t {
                TheirValue::F32(f) => f32_text(*f),
                TheirValue::Level(l) => format!("level {l}"),
            })
            .collect();
        let _ = writeln!(s, "  theirs [{}]", texts.join(", "));
    }
    if let Some(judged) = sample.judged_text() {
        let _ = writeln!(s, "  {judged}");
    }
}

impl ValueExplanation {
    /// For programs: `{"x", "y", "varying": {"name", "channels", "interpolation",
    /// "sampling"}, "provoking_vertex", "model", "pattern", "read_as", "samples": [{"index",
    /// "position", "owners", "shown": null or {"id", "primitive", "why", "at", "point",
    /// "derivation", "no_value", "channels": [{"channel", "vertex_values", "formula",
    /// "exact", "nearest_f32", "nearest_f32_bits", "theirs", "theirs_bits", "f32_steps",
    /// "levels", "envelope": {"near", "far"}, "centroid_range"}]}, "theirs", "class",
    /// "off", "meaning"}]}` (schema in docs/oracle.md).
    pub fn to_json(&self) -> Value {
        let v = &self.varying;
        let samples: Vec<Value> = self
            .samples
            .iter()
            .map(|sample| {
                let shown = sample.shown.as_ref().map(|sh| {
                    let (channels, no_value) = match &sh.channels {
                        Ok(c) => (c.iter().map(ChannelValue::json).collect::<Vec<_>>(), None),
                        Err(e) => (Vec::new(), Some(e.name())),
                    };
                    json!({
                        "id": sh.id,
                        "primitive": sh.primitive,
                        "why": sample.why(),
                        "at": sh.at,
                        "point": [exact_text(&sh.point.x), exact_text(&sh.point.y)],
                        "derivation": sh.derivation.as_ref().map(Derivation::json),
                        "no_value": no_value,
                        "channels": channels,
                    })
                });
                json!({
                    "index": sample.index,
                    "position": sample.position,
                    "owners": sample.owners,
                    "shown": shown,
                    "theirs": sample.theirs.as_ref().map(|t| t.iter().map(|c| c.json()).collect::<Vec<_>>()),
                    "class": sample.class.map(ValueClass::name),
                    "off": sample.class.map(ValueClass::is_off),
                    "meaning": sample.class.map(ValueClass::meaning),
                })
            })
            .collect();
        json!({
            "x": self.x,
            "y": self.y,
            "varying": {
                "name": v.name,
                "channels": v.channels,
                "interpolation": v.interpolation.name(),
                "sampling": v.sampling.name(),
            },
            "provoking_vertex": self.provoking.name(),
            "model": self.model.name(),
            "pattern": self.pattern,
            "read_as": self.read_as,
            "samples": samples,
        })
    }
}
