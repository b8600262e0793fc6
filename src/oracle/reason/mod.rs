//! Why another renderer decided a pixel differently for one primitive: the reason classes
//! and the exact search behind each.
//!
//! For a (pixel, primitive) pair where their answer differs from the oracle's, the
//! classes are tried in this order and the first that explains their answer is the
//! reason:
//! 1. `tie`: the sample lies exactly on an edge (`E == 0`) and another tie rule
//!    ([`AnyTieRule`]; for polygons the two the polygon engines implement) gives their
//!    answer. Names the edges, their sides and every rule that agrees with them.
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
//! 4. `snapping`: the primitive snapped with another rounding ([`Rounding::ALL`]) at the
//!    oracle's subpixel bits, or else with the fewest other bits (1..=16) and any rounding,
//!    or else not snapped at all, gives their answer. Names the bits and every rounding
//!    that does at those bits.
//! 5. `near-edge`: none of the above, and the sample lies within 1 px of an edge of the
//!    primitive (the exact distance): the error band of float or low-precision arithmetic.
//! 6. `gross`: farther than 1 px from every edge: a real bug (a wrong id, a wrong
//!    transform, a missing primitive).
//!
//! This module holds the classes and reasons ([`ReasonClass`], [`Reason`], [`Snapping`])
//! and the names the reasons use; the searches are the [`Classifier`]'s
//! (`classifier`, re-exported here).

mod classifier;

pub use classifier::Classifier;

use num_rational::BigRational;

use super::evidence::EdgeAt;
use crate::convention::AnyTieRule;
use crate::geom::FillRule;
use crate::line::{BresenhamTie, Line, LineRule};
use crate::model::Primitives;
use crate::num::Rounding;

/// The class of a reason, in the order they are tried.
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
    /// Another snapping gives their answer.
    Snapping,
    /// Within 1 px of an edge.
    NearEdge,
    /// Farther than 1 px from every edge.
    Gross,
}

impl ReasonClass {
    /// Every class, in order.
    pub const ALL: [ReasonClass; 7] = [
        ReasonClass::Tie,
        ReasonClass::Clip,
        ReasonClass::LineRule,
        ReasonClass::FillRule,
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
            Reason::Snapping { .. } => ReasonClass::Snapping,
            Reason::NearEdge { .. } => ReasonClass::NearEdge,
            Reason::Gross { .. } => ReasonClass::Gross,
        }
    }

    /// The distance it carries (near-edge, gross), for ranking.
    fn distance2(&self) -> Option<&BigRational> {
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
