//! Lines (Bresenham 1965, Pitteway 1967; D3D11 §3.4.3): integer Bresenham in all octants
//! ([`bresenham`]), the float DDA ([`dda`]), the diamond-exit rule in integers
//! ([`diamond`]), the exact references ([`exact`]): the ideal line per major step and a
//! plain rational reading of the diamond rule, and that reading in floats ([`float`]).
//!
//! Bresenham endpoints are pixel addresses: the line from (5, 8) to (9, 11) runs between
//! the centres of those pixels. Diamond-exit endpoints are window coordinates (fractions
//! allowed), snapped to the subpixel grid like triangle vertices.

pub mod bresenham;
pub mod dda;
pub mod diamond;
pub mod exact;
pub mod float;
pub mod planned;

use num_traits::ToPrimitive;

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::geom::Point;

/// A line primitive of a scene.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Line {
    /// Start (a pixel address for Bresenham, window coordinates for diamond-exit).
    pub from: Point,
    /// End.
    pub to: Point,
    /// How it is rasterized.
    pub rule: LineRule,
}

impl Line {
    /// The endpoints as integer pixel addresses, when both are integers within
    /// ±[`MAX_BRESENHAM_COORD`].
    pub fn pixel_endpoints(&self) -> Option<([i64; 2], [i64; 2])> {
        let int = |v: &num_rational::BigRational| {
            v.is_integer()
                .then(|| v.to_integer().to_i64())
                .flatten()
                .filter(|v| v.abs() <= MAX_BRESENHAM_COORD)
        };
        Some((
            [int(&self.from.x)?, int(&self.from.y)?],
            [int(&self.to.x)?, int(&self.to.y)?],
        ))
    }
}

/// Who wins a Bresenham tie: the ideal line exactly halfway between two pixels on the
/// minor axis (the midpoint lies on the line, decision value 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BresenhamTie {
    /// The midpoint form (Pitteway 1967): `d <= 0` chooses E: the minor coordinate stays.
    Stay,
    /// Bresenham's error-term form as textbooks teach it: `e >= 0` steps the minor axis.
    Step,
}

impl BresenhamTie {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BresenhamTie::Stay => "stay",
            BresenhamTie::Step => "step",
        }
    }

    /// Parses a name written by [`BresenhamTie::name`].
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "stay" => Some(BresenhamTie::Stay),
            "step" => Some(BresenhamTie::Step),
            _ => None,
        }
    }
}

/// How a line is rasterized.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LineRule {
    /// Bresenham between pixel centres (integer endpoints), with a tie convention.
    Bresenham(BresenhamTie),
    /// The diamond-exit rule of D3D11, Vulkan and GL (fractional endpoints allowed).
    Diamond,
}

/// The largest |endpoint| of a Bresenham line, in pixels. Bresenham walks every step from
/// the start, so this bounds the run time (2^25 steps at most); its decision values stay
/// below 2^27 and cannot overflow.
pub const MAX_BRESENHAM_COORD: i64 = 1 << 24;

/// Covers `pixel` when it is on the canvas.
pub(crate) fn cover_if_on_canvas<S: CoverageSink + ?Sized>(pixel: [i64; 2], id: u32, target: &Target, sink: &mut S) {
    if let (Ok(x), Ok(y)) = (u32::try_from(pixel[0]), u32::try_from(pixel[1])) {
        if x < target.width && y < target.height {
            sink.cover(x, y, id);
        }
    }
}

/// The walk common to every major-axis algorithm: which axis is major (x when
/// `|dx| >= |dy|`), the step directions and lengths.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Axes {
    /// True when x is the major axis.
    pub x_major: bool,
    /// `|major delta|`: the line has `major_len + 1` pixels.
    pub major_len: i64,
    /// `|minor delta|`.
    pub minor_len: i64,
    /// Direction of travel on the major axis (-1, 0 or 1).
    pub major_sign: i64,
    /// Direction of travel on the minor axis (-1, 0 or 1).
    pub minor_sign: i64,
}

impl Axes {
    /// The axes of the line `from -> to`.
    ///
    /// # Panics
    /// When a coordinate is outside ±[`MAX_BRESENHAM_COORD`], the envelope of every
    /// major-axis walk ([`Line::pixel_endpoints`] and the scene parser check it first).
    pub fn of(from: [i64; 2], to: [i64; 2]) -> Axes {
        assert!(
            from.iter().chain(&to).all(|c| c.abs() <= MAX_BRESENHAM_COORD),
            "line endpoints {from:?} -> {to:?} outside the +-2^24 envelope"
        );
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let x_major = dx.abs() >= dy.abs();
        let (major, minor) = if x_major { (dx, dy) } else { (dy, dx) };
        Axes {
            x_major,
            major_len: major.abs(),
            minor_len: minor.abs(),
            major_sign: major.signum(),
            minor_sign: minor.signum(),
        }
    }

    /// `(major, minor)` of a point.
    pub fn split(&self, p: [i64; 2]) -> (i64, i64) {
        if self.x_major {
            (p[0], p[1])
        } else {
            (p[1], p[0])
        }
    }

    /// The point with these major and minor coordinates.
    pub fn join(&self, major: i64, minor: i64) -> [i64; 2] {
        if self.x_major {
            [major, minor]
        } else {
            [minor, major]
        }
    }
}
