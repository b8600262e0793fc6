//! The trade (feature `trade`): every model's speed and error side by side, on one
//! seeded set of workloads, at coordinate magnitudes from 0 to 2^30 px. What `rasterproof
//! trade` prints and draws; [`run`] is the whole computation, [`TradeReport`] its result
//! (JSON, Markdown, pictures).
//!
//! - **Workloads** ([`Family`]): triangles (pixel-sized, medium, huge, sliver; a tie-heavy
//!   and a random spade mesh), lines (Bresenham with integer endpoints, diamond-exit with
//!   tie-heavy ones), polygons (simple, any), clipping (segments against rectangles,
//!   polygons against convex windows). Each is built at the origin on a square canvas from
//!   the crate's proptest strategies with a fixed seed, then **placed** at each magnitude
//!   `M`: every coordinate plus `(M, M)` exactly, so that its canvas-sized window is
//!   `[M, M + side)^2`.
//! - **Speed**: drawing the prepared workload at the origin into a
//!   [`crate::coverage::CountBuffer`] (as `cargo bench --features bench --bench models` times it), every
//!   contender in turn, round-robin over the repetitions in one process (so machine noise
//!   hits all alike); median, min and max of Mpix/s (covered pixels of the exact answer
//!   per second; clipping: primitives per second), the ratio to the family's baseline
//!   (`fixed`; the exact clipper), and the median of prepare-and-draw from the exact
//!   scene (the conversion every model pays, snapping, the planner's setup).
//! - **Error at magnitude `M`**, counted exactly against the planned exact engine on the
//!   same scene (`exact` for the models that do not snap, `exact-snapped` for those that
//!   do). How each contender meets a window at `M`, whose pixels no canvas reaches beyond
//!   2^14 ([`Placement`]):
//!   - every model that can refuse (all but the exact ones, whose envelope is unbounded)
//!     is first *prepared* on the placed workload, so that it refuses exactly what it
//!     would refuse there (the integer envelope, 2^21 px at 8 bits; Bresenham endpoints
//!     beyond 2^24; the float range);
//!   - exact and integer models then draw the workload at the origin: their answer is the
//!     same at every whole-pixel translation (exact arithmetic; the translation
//!     invariant, tested in `tests/properties.rs`; the integer models equal
//!     `exact-snapped` inside the envelope), and so is their cost (the planned engine
//!     and `fixed` compute relative to each primitive's first sample);
//!   - float models compute with the placed coordinates: triangles by the float
//!     rasterizer of [`crate::tri::float`] run over the window at `M` (`far`: its loop
//!     with `M` added to each sample, exact in f64, then rounded to the model's type as
//!     the model rounds its canvas samples; equal to the model's own output on a canvas,
//!     tested at 2^13), barycentrics and Gouraud colours at the placed samples, the DDA
//!     and the clippers on the placed inputs.
//!
//! The plain oracles (`exact-plain`, `exact-snapped-plain`, 10^3 to 10^4 pixels a
//! second) run on a small subset of each workload: the primitives that cover a 32x32
//! corner, in order, until about 1000 of its pixels.
//!
//! The family `area` ([`area`]) trades anti-aliased area coverage the same way: glyphs at
//! 9 to 200 px per em, an abutting mesh and slivers; the planned exact engine against
//! f32 accumulation, FreeType's 24.8 integers and 4 x 4 supersampling; per pixel the
//! absolute coverage error against the exact value.
//!
//! The family `values` ([`values`]) trades interpolated attribute values at covered pixel
//! centres: the plain definition and the planned path against f32 plane equations
//! anchored at the origin or at vertex 0, f32 barycentrics, an f64 plane and a fixed-point
//! Gouraud DDA, at canvas offsets 0 to 2^24 px and attribute scales 2^0 to 2^32 (its own
//! magnitudes, [`Axis`]); per value the f32 steps from the correctly rounded value and
//! the wrong UNORM8 levels.

pub mod area;
mod clipping;
mod exact_only;
mod far;
mod lines;
mod measure;
mod metric;
mod plot;
mod polygons;
mod predicate_map;
mod report;
mod speed;
mod triangles;
pub mod values;
mod workloads;

use std::fmt;

pub use metric::Metric;
pub use plot::Picture;
pub use predicate_map::{Decision, MapPanel, PredicateMap};
pub use report::{
    Axis, Cell, Onset, Outcome, Placement, PlanSummary, SpeedEntry, SpeedOutcome, TradeReport, WorkloadReport,
};

/// A family of workloads (`--family`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Family {
    /// Triangles: pixel-sized, medium, huge, sliver; a tie-heavy and a random mesh.
    Triangles,
    /// Bresenham and diamond-exit lines.
    Lines,
    /// Polygon fills: simple and any (self-intersecting) polygons.
    Polygons,
    /// Cohen-Sutherland and Sutherland-Hodgman, exact, f64 and f32.
    Clipping,
    /// Anti-aliased area coverage: glyphs, an abutting mesh, slivers ([`area`]).
    Area,
    /// Interpolated attribute values at covered pixel centres: exact, planned, float and
    /// fixed-point interpolators ([`values`]).
    Values,
}

impl Family {
    /// Every family, in report order.
    pub const ALL: [Family; 6] = [
        Family::Triangles,
        Family::Lines,
        Family::Polygons,
        Family::Clipping,
        Family::Area,
        Family::Values,
    ];

    /// The name on the command line and in the report.
    pub fn name(self) -> &'static str {
        match self {
            Family::Triangles => "triangles",
            Family::Lines => "lines",
            Family::Polygons => "polygons",
            Family::Clipping => "clipping",
            Family::Area => "area",
            Family::Values => "values",
        }
    }

    /// Parses [`Family::name`].
    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A coordinate magnitude: the window's origin, `M` px from the origin on both axes.
///
/// # Guarantees
/// `M <= 2^40` ([`Magnitude::MAX`]), so every sample `M + i + 1/2` of a window is exact in
/// f64 and every placed coordinate fits f32.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Magnitude(u64);

impl Magnitude {
    /// The largest magnitude accepted, 2^40 px.
    pub const MAX: u64 = 1 << 40;

    /// The issue's magnitudes: 0, 2^10, 2^16, 2^20, 2^23, 2^24, 2^30 px.
    pub const DEFAULT: [Magnitude; 7] = [
        Magnitude(0),
        Magnitude(1 << 10),
        Magnitude(1 << 16),
        Magnitude(1 << 20),
        Magnitude(1 << 23),
        Magnitude(1 << 24),
        Magnitude(1 << 30),
    ];

    /// `px` pixels; `None` above [`Magnitude::MAX`].
    pub fn new(px: u64) -> Option<Magnitude> {
        (px <= Magnitude::MAX).then_some(Magnitude(px))
    }

    /// In pixels.
    pub fn px(self) -> u64 {
        self.0
    }

    /// In pixels, as an i64 (exact: at most 2^40).
    pub fn px_i64(self) -> i64 {
        i64::try_from(self.0).expect("magnitudes are at most 2^40")
    }

    /// `0`, `2^k` for a power of two, else the decimal number of pixels.
    pub fn label(self) -> String {
        match self.0 {
            0 => "0".into(),
            m if m.is_power_of_two() => format!("2^{}", m.trailing_zeros()),
            m => m.to_string(),
        }
    }

    /// Parses `0`, `2^k` or a number of pixels (`1024`).
    ///
    /// # Errors
    /// Not a number, or above 2^40: the message names the value.
    pub fn parse(text: &str) -> Result<Magnitude, String> {
        let t = text.trim();
        let px = match t.strip_prefix("2^") {
            Some(k) => k
                .parse::<u32>()
                .ok()
                .filter(|&k| k <= 40)
                .map(|k| 1u64 << k)
                .ok_or_else(|| format!("{t:?}: expected 2^k with k in 0..=40"))?,
            None => t
                .parse::<u64>()
                .map_err(|_| format!("{t:?}: expected a number of pixels (1024) or a power of two (2^10)"))?,
        };
        Magnitude::new(px).ok_or_else(|| format!("{t:?}: above the largest magnitude, 2^40 px"))
    }

    /// Parses a comma-separated list (sorted, repeats dropped).
    ///
    /// ```
    /// use rasterproof::trade::Magnitude;
    /// let m = Magnitude::parse_list("2^24,0, 1024").unwrap();
    /// assert_eq!(m.iter().map(|m| m.label()).collect::<Vec<_>>(), ["0", "2^10", "2^24"]);
    /// assert!(Magnitude::parse_list("2^41").is_err());
    /// ```
    ///
    /// # Errors
    /// An empty list or a bad entry (see [`Magnitude::parse`]).
    pub fn parse_list(text: &str) -> Result<Vec<Magnitude>, String> {
        let mut out = text
            .split(',')
            .filter(|s| !s.trim().is_empty())
            .map(Magnitude::parse)
            .collect::<Result<Vec<_>, _>>()?;
        if out.is_empty() {
            return Err(format!("{text:?}: no magnitude given"));
        }
        out.sort_unstable();
        out.dedup();
        Ok(out)
    }
}

impl fmt::Display for Magnitude {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

/// What one trade run measures.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Config {
    /// Small workloads and few repetitions: well under a minute (CI runs it).
    pub quick: bool,
    /// The workloads' seed.
    pub seed: u64,
    /// The families to run, in report order.
    pub families: Vec<Family>,
    /// The magnitudes, ascending.
    pub magnitudes: Vec<Magnitude>,
}

impl Config {
    /// The full run: every family at the default magnitudes, seed 1.
    pub fn full() -> Config {
        Config {
            quick: false,
            seed: 1,
            families: Family::ALL.to_vec(),
            magnitudes: Magnitude::DEFAULT.to_vec(),
        }
    }

    /// The quick run: as [`Config::full`] with small workloads.
    pub fn quick() -> Config {
        Config {
            quick: true,
            ..Config::full()
        }
    }

    /// The sizes this run uses.
    pub(crate) fn sizes(&self) -> Sizes {
        if self.quick {
            Sizes {
                canvas: 128,
                count: 1,
                repetitions: 3,
                min_pass_seconds: 0.002,
                plain_pixels: 150,
                samples: 400,
                area_subset: 12,
            }
        } else {
            Sizes {
                canvas: 512,
                count: 10,
                repetitions: 7,
                min_pass_seconds: 0.02,
                plain_pixels: 1000,
                samples: 4000,
                area_subset: 12,
            }
        }
    }
}

/// A run's sizes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sizes {
    /// The canvas side (and the window's), px.
    pub(crate) canvas: u32,
    /// Workload sizes are multiples of this.
    pub(crate) count: usize,
    /// Timed repetitions per contender.
    pub(crate) repetitions: usize,
    /// A timed pass repeats the workload until it lasts at least this long.
    pub(crate) min_pass_seconds: f64,
    /// The plain oracles' subset: at least this many covered pixels.
    pub(crate) plain_pixels: u64,
    /// Barycentric and Gouraud samples per workload and magnitude.
    pub(crate) samples: usize,
    /// The side of the area family's subset window, px.
    pub(crate) area_subset: u32,
}

/// Runs the trade: every workload of `config`'s families, its speed, its plan and its
/// errors at every magnitude, then the predicate map. `progress` hears one line per
/// workload as it starts.
///
/// ```no_run
/// use rasterproof::trade::{run, Config};
/// let report = run(&Config::quick(), &mut |line| eprintln!("{line}"));
/// println!("{}", report.to_markdown());
/// ```
pub fn run(config: &Config, progress: &mut dyn FnMut(&str)) -> TradeReport {
    let sizes = config.sizes();
    let mut workloads = Vec::new();
    for &family in &config.families {
        let reports = match family {
            Family::Triangles => triangles::run(config, &sizes, progress),
            Family::Lines => lines::run(config, &sizes, progress),
            Family::Polygons => polygons::run(config, &sizes, progress),
            Family::Clipping => clipping::run(config, &sizes, progress),
            Family::Area => area::run(config, &sizes, progress),
            Family::Values => values::run(config, &sizes, progress),
        };
        workloads.extend(reports);
    }
    progress("predicate map");
    let map = PredicateMap::compute(predicate_map::MAP_MAGNITUDE);
    TradeReport {
        config: config.clone(),
        canvas: sizes.canvas,
        repetitions: sizes.repetitions,
        workloads,
        predicate_map: map,
    }
}
