//! Why another renderer decided a pixel differently for one primitive: the reason classes
//! and the exact search behind each.
//!
//! For a (pixel, primitive) pair where their answer differs from the oracle's, the class
//! is the most plausible exact explanation, not merely the first that fits. Some classes
//! decide alone, in this order:
//! 1. `tie`: the sample lies exactly on an edge (`E == 0`) and another tie rule
//!    ([`AnyTieRule`], for triangles and polygons alike) gives their answer. Names the
//!    edges (of a triangle), their sides and every rule that agrees with them.
//! 2. `clip`: the scene has a clip window and the unclipped primitive gives their answer
//!    (they did not clip, or clipped differently).
//! 3. `line-rule` (lines): another line convention gives their answer: the other
//!    Bresenham tie, the f32 / f64 DDA, diamond-exit (for Bresenham lines, between the
//!    endpoint pixels' samples) or Bresenham between the endpoints' pixels (for diamond
//!    lines), or for diamond lines the diamond mirrored in y: D3D11's test area (bottom
//!    corner in, top corner out) read in a y-up window such as GL's, which in the y-down
//!    image puts the top corner in and the bottom corner out.
//!    `fill-rule` (polygons): the other fill rule gives their answer; names the winding
//!    number of the moved sample.
//!
//! Otherwise the exact searches collect every alternative that gives their answer
//! ([`Alternative`]): the primitive snapped with another rounding at the oracle's own
//! subpixel bits (a snapping model only), with 1..=16 bits and any rounding, not snapped
//! at all (a snapping model only), and for triangles and polygons the sample at another
//! offset in the pixel (`sample-position`: (i, j), (i + 1/2, j), (i, j + 1/2) or
//! (i + 1/2, j + 1/2), the oracle's own left out; a line's pixels follow its own rule,
//! which `line-rule` searches). Then, in this order:
//! 4. `snapping` at the oracle's own bits with another rounding, when one gives their
//!    answer: the grid the user said their renderer uses, rounding aside.
//! 5. `near-edge` when the exact distance `d` from the sample to the nearest edge is
//!    *tiny* ([`within_float_error`]): `d <= 2^-20 M^2 / L`, `M` the largest coordinate
//!    magnitude of that edge and the sample (at least 1 px), `L` the edge's length. That is
//!    8 units in the last place of a float32 at `M^2` (float32 has 24 significant bits,
//!    so an ulp at `v` is at most `2^-23 v`), divided by `L`: how far the edge moves when
//!    its edge function `A x + B y + C`, whose terms reach `M^2` (`C = x0 y1 - x1 y0`),
//!    is evaluated in float32 with a few roundings. A difference that close is the
//!    ordinary error of float arithmetic, and any other explanation that also fits it
//!    (a coarse grid, a moved sample, which flip pixels up to 1/16..1/2 px away) is a
//!    coincidence. Magnitude-relative rather than a fixed threshold, because float error
//!    grows with the coordinates: 1/64 px would call every coarse-grid difference near a
//!    small canvas's origin float error, and miss float32's error far from it.
//! 6. the alternative that explains the most findings of the whole comparison (ties:
//!    snapping to 4 or more bits, the fewest first; to 1..=3 bits; unsnapped; a sample
//!    position),
//!    when it explains at least 3/4 of the comparison's findings that reach this step (a
//!    renderer with one defect is explained by it everywhere; an alternative that fits
//!    only some pixels, as a moved sample or a coarse grid fits about half of a float
//!    renderer's differences, is a coincidence) and, for a sample position, one of the
//!    findings it explains lies 1/16 px or more from its edge (a sample moved by half a
//!    pixel flips verdicts up to half a pixel from an edge, so its differences spread
//!    over that band; when all lie nearer than 1/16 px, a smaller error, such as a
//!    fixed-point edge walk's drift, is the cause), or when the sample is farther than 1 px from every edge (it
//!    beats `gross`). `sample-position` names the offsets that give their answer;
//!    `snapping` the bits and every rounding that does at those bits.
//!    Under an unsnapped oracle model (`exact`, `exact-plain`: the user says their
//!    renderer does not snap) no snapping alternative is collected within 1 px of an
//!    edge: snapping never beats `near-edge` there.
//! 7. `near-edge`: none of the above, and the sample lies within 1 px of an edge of the
//!    primitive (the exact distance): the error band of float or low-precision arithmetic.
//! 8. `gross`: farther than 1 px from every edge: a real bug (a wrong id, a wrong
//!    transform, a missing primitive).
//!
//! Every finding also carries the exact distance from the sample to the primitive's
//! nearest edge, whatever its class.
//!
//! This module holds the classes and reasons ([`ReasonClass`], [`Reason`], [`Snapping`],
//! [`Alternative`], [`Found`]), the ranking of step 4 to 8 ([`Support`], [`decide`]) and
//! the names the reasons use; the searches are the [`Classifier`]'s (`classifier`,
//! re-exported here).

mod classifier;

pub use classifier::Classifier;

use std::collections::HashMap;

use num_rational::BigRational;
use num_traits::One;

pub use super::evidence::within_float_error;
use super::evidence::EdgeAt;
use crate::convention::AnyTieRule;
use crate::geom::FillRule;
use crate::line::{BresenhamTie, Line, LineRule};
use crate::model::Primitives;
use crate::num::Rounding;

/// The class of a reason, in report order (the order of the module docs, except that
/// `sample-position` and `snapping` are ranked by the comparison's findings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ReasonClass {
    /// The sample lies on an edge; another tie rule gives their answer.
    Tie,
    /// The unclipped primitive gives their answer.
    Clip,
    /// Another line convention gives their answer.
    LineRule,
    /// The other fill rule gives their answer.
    FillRule,
    /// Another sample position in the pixel gives their answer.
    SamplePosition,
    /// Another snapping gives their answer.
    Snapping,
    /// Within 1 px of an edge.
    NearEdge,
    /// Farther than 1 px from every edge.
    Gross,
}

impl ReasonClass {
    /// Every class, in order.
    pub const ALL: [ReasonClass; 8] = [
        ReasonClass::Tie,
        ReasonClass::Clip,
        ReasonClass::LineRule,
        ReasonClass::FillRule,
        ReasonClass::SamplePosition,
        ReasonClass::Snapping,
        ReasonClass::NearEdge,
        ReasonClass::Gross,
    ];

    /// Its name in reports (`tie`, `near-edge`, ...).
    pub fn name(self) -> &'static str {
        match self {
            ReasonClass::Tie => "tie",
            ReasonClass::Clip => "clip",
            ReasonClass::LineRule => "line-rule",
            ReasonClass::FillRule => "fill-rule",
            ReasonClass::SamplePosition => "sample-position",
            ReasonClass::Snapping => "snapping",
            ReasonClass::NearEdge => "near-edge",
            ReasonClass::Gross => "gross",
        }
    }
}

/// A snapping another renderer may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Snapping {
    /// Subpixel bits; `None`: not snapped at all.
    pub bits: Option<u32>,
    /// The rounding (meaningless when not snapped).
    pub rounding: Rounding,
}

impl Snapping {
    /// `4 subpixel bits, floor` or `unsnapped`.
    pub fn describe(&self) -> String {
        match self.bits {
            Some(b) => format!("{b} subpixel bits, {}", self.rounding.name()),
            None => "unsnapped".to_string(),
        }
    }
}

/// Why their answer for one primitive at one pixel differs from the oracle's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Reason {
    /// The sample lies exactly on `edges` (triangles: the edges with `E == 0`; polygons:
    /// none named, the sample is on the outline); each of `rules` gives their answer.
    Tie {
        /// The edges through the sample (triangles).
        edges: Vec<EdgeAt>,
        /// The tie rules that agree with them.
        rules: Vec<AnyTieRule>,
    },
    /// The primitive without the clip window gives their answer.
    Clip {
        /// Whether the unclipped primitive covers the pixel.
        unclipped_covers: bool,
    },
    /// Each of `rules` (line conventions, by name) gives their answer.
    LineRule {
        /// `bresenham (step)`, `dda (f32)`, `diamond-exit`, ...
        rules: Vec<&'static str>,
    },
    /// The polygon under `fill_rule` gives their answer.
    FillRule {
        /// The winding number of the moved sample around the outline.
        winding: i64,
        /// The rule that agrees with them.
        fill_rule: FillRule,
    },
    /// Sampled at each of `offsets` (in half pixels from the pixel's corner: `[0, 0]` is
    /// (i, j), `[1, 1]` is (i + 1/2, j + 1/2)) the primitive gives their answer.
    SamplePosition {
        /// The offsets, in half pixels, that give their answer.
        offsets: Vec<[u8; 2]>,
    },
    /// Snapped with `bits` subpixel bits and any of `roundings` (or unsnapped) the
    /// primitive gives their answer; `bits` is the fewest that do.
    Snapping {
        /// The fewest subpixel bits that explain it; `None`: only the unsnapped primitive.
        bits: Option<u32>,
        /// The roundings that do at those bits.
        roundings: Vec<Rounding>,
    },
    /// Within 1 px of an edge: the squared distance.
    NearEdge {
        /// The squared distance to the nearest edge, exactly.
        distance2: BigRational,
    },
    /// Farther than 1 px from every edge: the squared distance to the nearest (`None`
    /// when no primitive is near the pixel, or the id names no primitive of the scene).
    Gross {
        /// The squared distance to the nearest edge, exactly.
        distance2: Option<BigRational>,
    },
}

impl Reason {
    /// The class.
    pub fn class(&self) -> ReasonClass {
        match self {
            Reason::Tie { .. } => ReasonClass::Tie,
            Reason::Clip { .. } => ReasonClass::Clip,
            Reason::LineRule { .. } => ReasonClass::LineRule,
            Reason::FillRule { .. } => ReasonClass::FillRule,
            Reason::SamplePosition { .. } => ReasonClass::SamplePosition,
            Reason::Snapping { .. } => ReasonClass::Snapping,
            Reason::NearEdge { .. } => ReasonClass::NearEdge,
            Reason::Gross { .. } => ReasonClass::Gross,
        }
    }

    /// The distance it carries (near-edge, gross), for ranking.
    pub(crate) fn distance2(&self) -> Option<&BigRational> {
        match self {
            Reason::NearEdge { distance2 }
            | Reason::Gross {
                distance2: Some(distance2),
            } => Some(distance2),
            _ => None,
        }
    }
}

/// One primitive's kind (a scene field) and index in it, from its id.
pub fn primitive_name(primitives: &Primitives, id: u32) -> Option<String> {
    let mut k = usize::try_from(id).ok()?;
    for (name, n) in [
        ("triangles", primitives.triangles.len()),
        ("lines", primitives.lines.len()),
        ("polygons", primitives.polygons.len()),
        ("clip_space_triangles", primitives.clip_space_triangles.len()),
    ] {
        if k < n {
            return Some(format!("{name}[{k}]"));
        }
        k -= n;
    }
    None
}

/// The line-rule search's name for D3D11's diamond test area read in a y-up window (GL's):
/// in the y-down image its top corner is in and its bottom corner out.
pub const DIAMOND_MIRRORED: &str = "diamond-exit (mirrored in y: a y-up window's corners)";

/// A line of the scene, for the line-rule search's names (Bresenham or diamond-exit).
pub fn line_rule_name(line: &Line) -> &'static str {
    match line.rule {
        LineRule::Bresenham(BresenhamTie::Stay) => "bresenham (stay)",
        LineRule::Bresenham(BresenhamTie::Step) => "bresenham (step)",
        LineRule::Diamond => "diamond-exit",
    }
}

/// A sample offset in half pixels as `(i + 1/2, j)`.
pub fn offset_text([ox, oy]: [u8; 2]) -> String {
    let part = |axis: &str, o: u8| {
        if o == 0 {
            axis.to_string()
        } else {
            format!("{axis} + 1/2")
        }
    };
    format!("({}, {})", part("i", ox), part("j", oy))
}

/// One way their renderer may differ that the exact searches can test at a sample: a
/// snapping or a sample position (see the module docs, step 6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Alternative {
    /// The primitive snapped so.
    Snapping(Snapping),
    /// The sample at this offset in the pixel, in half pixels.
    SamplePosition([u8; 2]),
}

impl Alternative {
    /// The tie-break between alternatives that explain as many findings: snapping to 4
    /// or more bits (the fewest first), then to 1..=3 bits (the fewest first), unsnapped,
    /// and last sample positions; within bits, [`Rounding::ALL`]'s order. Grids of 1..=3
    /// bits are coarser than renderers use, so where a finer grid fits as many findings it
    /// is the plausible one; where a snapping fits every finding a moved sample fits, it
    /// is the nearer explanation (a sample moved by half a pixel flips verdicts up to half
    /// a pixel from an edge, a grid of `b` bits up to about `2^-b`).
    fn rank(&self) -> (u8, u32, usize) {
        match self {
            Alternative::SamplePosition([x, y]) => (3, u32::from(*x) * 2 + u32::from(*y), 0),
            Alternative::Snapping(s) => {
                let r = Rounding::ALL.iter().position(|r| *r == s.rounding).unwrap_or(0);
                match s.bits {
                    Some(b) if b >= 4 => (0, b, r),
                    Some(b) => (1, b, r),
                    None => (2, 0, 0),
                }
            }
        }
    }
}

/// What the exact searches found for one finding before the comparison's other findings
/// are known.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Found {
    /// A class that decides alone (tie, clip, line-rule, fill-rule; gross for an id that
    /// names no primitive).
    Decided(Reason),
    /// Otherwise: the evidence for steps 4 to 8 of the module docs.
    Open {
        /// The squared distance from the sample to the nearest edge, exactly.
        distance2: BigRational,
        /// That distance is within float32's error ([`within_float_error`]).
        tiny: bool,
        /// Snapping at the oracle's own bits with another rounding, when one gives their
        /// answer.
        own_grid: Option<Reason>,
        /// Every other alternative that gives their answer.
        alternatives: Vec<Alternative>,
    },
}

/// How many findings of a comparison each alternative explains (step 6 of the module
/// docs): every [`Found::Open`] finding without an own-grid snapping counts.
#[derive(Debug, Clone, Default)]
pub struct Support {
    /// Per alternative: the findings it explains and the largest squared distance among
    /// them.
    counts: HashMap<Alternative, (usize, BigRational)>,
    findings: usize,
}

impl Support {
    /// Counts one finding.
    pub fn add(&mut self, found: &Found) {
        if let Found::Open {
            own_grid: None,
            alternatives,
            tiny,
            distance2,
        } = found
        {
            if *tiny && *distance2 <= BigRational::one() {
                return;
            }
            self.findings += 1;
            for a in alternatives {
                let e = self.counts.entry(*a).or_insert_with(|| (0, distance2.clone()));
                e.0 += 1;
                if *distance2 > e.1 {
                    e.1 = distance2.clone();
                }
            }
        }
    }

    /// The support of one finding alone.
    pub fn of(found: &Found) -> Support {
        let mut s = Support::default();
        s.add(found);
        s
    }
}

/// The reason of one finding, given what the comparison's findings support (steps 4 to 8
/// of the module docs).
pub fn decide(found: Found, support: &Support) -> Reason {
    let (distance2, tiny, own_grid, alternatives) = match found {
        Found::Decided(r) => return r,
        Found::Open {
            distance2,
            tiny,
            own_grid,
            alternatives,
        } => (distance2, tiny, own_grid, alternatives),
    };
    if let Some(r) = own_grid {
        return r;
    }
    let near = distance2 <= BigRational::one();
    if near && tiny {
        return Reason::NearEdge { distance2 };
    }
    let count = |a: &Alternative| support.counts.get(a).map_or(0, |c| c.0);
    // A sample position: some finding it explains lies 1/16 px or more from the edge.
    let spread = |a: &Alternative| match a {
        Alternative::SamplePosition(_) => support
            .counts
            .get(a)
            .is_some_and(|c| &c.1 * BigRational::from_integer(256.into()) >= BigRational::one()),
        Alternative::Snapping(_) => true,
    };
    let best = alternatives
        .iter()
        .max_by(|a, b| count(a).cmp(&count(b)).then(b.rank().cmp(&a.rank())))
        .copied();
    if let Some(best) = best.filter(|a| !near || (4 * count(a) >= 3 * support.findings && spread(a))) {
        return match best {
            Alternative::SamplePosition(_) => Reason::SamplePosition {
                offsets: alternatives
                    .iter()
                    .filter_map(|a| match a {
                        Alternative::SamplePosition(o) => Some(*o),
                        Alternative::Snapping(_) => None,
                    })
                    .collect(),
            },
            Alternative::Snapping(s) => Reason::Snapping {
                bits: s.bits,
                roundings: match s.bits {
                    Some(b) => alternatives
                        .iter()
                        .filter_map(|a| match a {
                            Alternative::Snapping(t) if t.bits == Some(b) => Some(t.rounding),
                            _ => None,
                        })
                        .collect(),
                    None => Vec::new(),
                },
            },
        };
    }
    if near {
        Reason::NearEdge { distance2 }
    } else {
        Reason::Gross {
            distance2: Some(distance2),
        }
    }
}
