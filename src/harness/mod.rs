//! Harnesses built on the checkers (feature `proptest`): the layer above [`crate::check`],
//! [`crate::strategy`] and [`crate::scene`] that draws random cases, runs the checkers on
//! them and reports what failed as scene files.
//!
//! - [`find_counterexample`] ([`search`]): your own triangle rasterizer against the
//!   oracle, the first disagreement shrunk to a minimal scene.
//! - [`suite`]: the invariant suite behind `rasterproof check` — seeded random cases
//!   ([`generate`]), every checker on each ([`run_case`]) and the table of outcomes
//!   ([`Tally`]); at scale, a [`SuiteConfig`] (shard, threads, time budget) run into a
//!   [`SuiteReport`] (JSON, JUnit XML, merged across shards).
//! - [`shrink`]: the one shrinker of a failing scene (drop primitives, crop the canvas,
//!   simpler coordinates, optionally down to a grid step), shared by
//!   [`find_counterexample`] and the hunt ([`crate::oracle::hunt`]).
//! - [`runner`]: numbered cases on scoped threads, their results in index order, a stop
//!   predicate before each case (what a [`SuiteConfig`] runs on; meant for every case loop).

pub mod junit;
pub mod runner;
pub mod search;
pub mod shrink;
pub mod suite;

pub use search::{find_counterexample, Counterexample, HarnessConfig};
pub use suite::{
    generate, must_hold, run_case, Case, CaseRun, CheckOutcome, Row, Shard, Skip, SuiteConfig, SuiteReport, Tally,
};
