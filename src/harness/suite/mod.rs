//! The invariant suite behind `rasterproof check`: seeded random cases, every checker of
//! [`crate::check`] on each, and the table of outcomes.
//!
//! Each case ([`generate`]) holds a mesh (random, tie-heavy or far from the origin), a
//! fine far-from-origin mesh, a random triangle, Bresenham, diamond-exit and long DDA
//! lines, polygons (any and simple), clip windows and a segment. [`run_case`] checks on it
//! every invariant of the suite:
//!
//! - barycentrics: exact sums, integer edge sums, the float32 sum error in ulps;
//! - watertight meshes and model agreement (snapped models against the exact model on the
//!   snapped scene, float models against the exact model on the scene as written), on
//!   the meshes and on the single triangle;
//! - invariance under vertex rotation, winding reversal and whole-pixel translation;
//! - lines: Bresenham's pixels, reference and symmetry, diamond-exit agreement, the DDA's
//!   pixels on long lines;
//! - polygon fills (scanline against the oracle) and triangulations;
//! - clipping: exact Sutherland-Hodgman inside the window and rasterizing to
//!   raster(P) ∩ raster(W), exact Cohen-Sutherland, the float Sutherland-Hodgman outputs.
//!
//! A violation by an exact or integer model ([`must_hold`]) is a failure. A violation by a
//! float model is not: it is the measured trade (the float trade invariant: a float
//! model's departures are measured, not forbidden), counted in the table so that its
//! rate can be read off. A check that cannot run on a case (snapping folded the simple
//! polygon, the triangle has zero area, ...) is a [`Skip`] with its reason, counted in
//! the table's `skipped` column, never dropped silently. [`Tally`]
//! accumulates the outcomes and renders the table, its legend ([`legend`]: one line per
//! invariant, model and column) and the summary `rasterproof check` prints.
//!
//! At scale ([`SuiteConfig`]): the cases of one [`Shard`] of the run (a partition by case index,
//! so that N machines run disjoint cases), on several threads, within a time budget, into
//! a [`SuiteReport`] (the table, the findings and every failing case's scene) that is written
//! as JSON or JUnit XML, and that [merges](SuiteReport::merge) with the other shards' into the
//! report of the whole run.
//!
//! ```
//! use rasterproof::harness::{generate, run_case, Tally};
//! let mut tally = Tally::new(7);
//! for k in 0..2 {
//!     let case = generate(7, k).unwrap();
//!     tally.add(&run_case(&case));
//! }
//! assert!(tally.passed());
//! assert_eq!(tally.lines()[0], "rasterproof check: 2 cases, seed 7, presets d3d11/gl");
//! ```

mod cases;
mod checks;
pub mod legend;
mod models;
pub mod report;
mod run;
pub mod shard;
mod tally;

pub use cases::{generate, Case, CANVAS};
pub use checks::run_case;
pub use report::{CaseFailure, FailureGroup, SuiteReport};
pub use run::{Hooks, OnCase, SceneFiles, SuiteConfig, MAX_JOBS};
pub use shard::{Shard, Shards};
pub use tally::{Row, Tally};

use crate::check::Violation;
use crate::model::Model;
use crate::scene::Scene;

/// One checker's verdict on one case.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CheckOutcome {
    /// The invariant, as the table names it (`"watertight"`, `"clip inside"`, ...).
    pub invariant: &'static str,
    /// The model checked.
    pub model: Model,
    /// The model's name in the table: [`Model::name`], or the algorithm's where several
    /// share a model (`"bresenham/stay"`, `"dda32"`, `"sh-f64"`, ...).
    pub label: &'static str,
    /// The checker's verdict.
    pub result: Result<(), Violation>,
    /// What the checker saw as a scene file: its primitives, clip window, canvas and the
    /// case's preset.
    pub scene: Scene,
}

impl CheckOutcome {
    /// When this outcome failed: the scene that reproduces it (what `check --out` writes)
    /// and the violation; `None` when it held.
    pub fn repro(&self) -> Option<(&Scene, &Violation)> {
        self.result.as_ref().err().map(|v| (&self.scene, v))
    }

    /// Whether this outcome fails the run: a violation by a model that [must hold](must_hold).
    pub fn is_fatal(&self) -> bool {
        self.result.is_err() && must_hold(self.model)
    }
}

/// A check that did not run on a case: its row of the table and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Skip {
    /// The invariant, as the table names it.
    pub invariant: &'static str,
    /// The model it would have checked.
    pub model: Model,
    /// The model's name in the table (see [`CheckOutcome::label`]).
    pub label: &'static str,
    /// Why it could not run, e.g. `"snapping folded the polygon"`.
    pub reason: &'static str,
}

/// Every outcome of one case, with what the case measured.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseRun {
    /// The case's mesh family ([`Case::mesh_family`]), for the by-family count.
    pub mesh_family: &'static str,
    /// One outcome per checker run, in the order they ran.
    pub outcomes: Vec<CheckOutcome>,
    /// The checks that could not run on this case, with their reasons: with
    /// [`CaseRun::outcomes`], one entry per row of the table.
    pub skipped: Vec<Skip>,
    /// The float32 barycentric sum errors at the case's samples, in ulps of 1
    /// (`f32::EPSILON`, the spacing of f32 just above 1).
    pub float32_sum_ulps: Vec<f64>,
    /// Samples at which the float32 sum error could not be measured (the triangle has
    /// zero area in f32, or does not fit f32).
    pub float32_sum_skipped: u64,
}

/// Whether `model`'s violations fail the run: the exact and integer models (`exact`,
/// `exact-snapped`, `fixed`, `scanline`) must hold every invariant; the float models'
/// violations are the measured trade.
pub fn must_hold(model: Model) -> bool {
    model.is_exact()
}
