//! # rasterproof
//!
//! An exact-arithmetic reference rasterizer and a property-tested verification harness for
//! 2D rasterization. It computes, with no rounding error anywhere, which pixels a scene
//! covers under a stated convention, carries the classic algorithms in exact, integer and
//! float forms side by side, and checks their invariants.
//!
//! ## Conventions
//!
//! - Window space: x right, y down, origin top-left; pixel (i, j) is `[i, i+1) x [j, j+1)`,
//!   sampled at `(i + 1/2, j + 1/2)` (or `(i, j)`, D3D9 style).
//! - Scene numbers are exact rationals (`0.1` is 1/10).
//! - Hardware-style models snap vertices to a 2^-S pixel grid (S = 8 by default),
//!   round-to-nearest, ties to even (or half away from zero, as the Khronos CTS does; or
//!   floor, ceiling, towards zero).
//! - Edge function `E(p) = (p.x - a.x)(b.y - a.y) - (p.y - a.y)(b.x - a.x)`; triangles of
//!   either winding are oriented so the interior is `E > 0`; zero-area triangles cover
//!   nothing.
//! - Tie rule: a sample with `E == 0` is inside only on an inclusive edge; top-left (D3D11
//!   §3.4.2.1) or bottom-left (GL seen in a y-down image). Top-left is "the sample moved
//!   right by ε and down by ε²".
//! - Presets: `d3d11`, `vulkan`, `gl`, `cts` ([`convention::Preset`]).
//!
//! ## Quick start
//!
//! ```
//! use rasterproof::convention::{Preset, Target};
//! use rasterproof::geom::{Point, Triangle};
//! use rasterproof::model::{render_triangles, Model};
//! // Two triangles sharing the diagonal of a 4x4 square: every pixel is owned once.
//! let (a, b, c, d) = (Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(4, 4), Point::from_ints(0, 4));
//! let mesh = [Triangle::new(a.clone(), b, c.clone()), Triangle::new(a, c, d)];
//! let target = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
//! let coverage = render_triangles(&mesh, &target, Model::Fixed).unwrap();
//! assert_eq!(coverage.covered_pixels(), 16);
//! assert_eq!(coverage.double_covered().count(), 0);
//! ```
//!
//! ## Entry points: one function per operation
//!
//! | to | call | feature |
//! |---|---|---|
//! | read a scene file (exact numbers, errors naming file, field, value) | [`parse_scene`] (text), [`scene::parse_scene_with`] (bytes, with [`scene::ParseOptions`]: threads, a vertex bound), [`scene::read_scene_file`] (a file) | |
//! | render it with a model | [`render`]`(&scene.primitives(), &target, model)` ([`render_triangles`] for a list of triangles; [`prepare`] once and [`PreparedScene::render`] many times) | |
//! | its exact area coverage (anti-aliasing) | [`model::render_area`] | |
//! | its coverage at every sample of a pattern (multisampling) | [`model::render_samples`] | |
//! | its conservative coverage (must and may sets) | [`model::render_conservative`] | |
//! | plan it: per primitive, the cheapest arithmetic proven exact | [`plan_scene`] | |
//! | compare another renderer's output ([`Theirs`]) with the exact answer, every differing pixel classified | [`compare()`] (one sample), [`oracle::compare::samples::compare_samples`], [`oracle::compare::grey::compare_grey`], [`oracle::compare::conservative::compare_conservative`]; any of them: [`oracle::judge`] | |
//! | explain one pixel exactly (sample, edges, values, flags) | [`explain_pixel`] | |
//! | fit the convention another renderer follows | [`fit()`]; per sample index and position: [`oracle::compare::fit::samples::fit_samples`]; a grey method: [`oracle::compare::fit::grey::fit_grey`] | |
//! | run another renderer as a process, once per scene or kept alive | [`oracle::renderer`] | |
//! | hunt: scenes another renderer (a closure `Fn(&Scene) -> Result<Theirs, _>`) gets wrong, shrunk | [`hunt()`] | `proptest` |
//! | test your own triangle rasterizer (a closure) against the oracle | [`find_counterexample`] | `proptest` |
//! | check an invariant on any coverage | `check::check_*` ([`check`]) | |
//! | run the invariant suite (what `rasterproof check` runs) | [`harness::suite::SuiteConfig::run`] | `proptest` |
//! | every model's speed and error side by side | `trade::run` | `trade` |
//! | one primitive in one arithmetic | `tri::{exact, planned, fixed, scanline, float}`, `line::*`, `fill::polygon::*` | |
//! | where a pixel's sample sits; which pixels a box covers | [`raster`] | |
//! | clip exactly or in floats | [`clip`], [`clip::arithmetic::Clipper`] | |
//! | turn RenderDoc's mesh CSV or raw f32 position buffers into a scene, exactly | [`import::renderdoc::import_csv`], [`import::raw::import_raw`] | |
//!
//! Every entry point takes its arguments in one order: the input (the scene's primitives
//! and the target, then their output or renderer where there is one), then the options
//! (the model, a configuration), then where the output goes (a sink, a progress callback);
//! results are returned. Every comparison takes `(primitives, target, theirs, options)` and
//! returns a report with one surface, [`oracle::Comparison`]: `identical()`, its counts by
//! class, text, JSON and, where one exists, HTML. One verb per operation: a primitive is *rasterized*
//! (`tri::*::rasterize`, `line::*::rasterize`, `fill::polygon::rasterize*`), a scene is
//! *rendered* with a model.
//!
//! The types these take and return are re-exported here too: [`Model`], [`Target`],
//! [`Preset`], [`Point`], [`Triangle`], [`Polygon`], [`Scene`], [`Primitives`],
//! [`Coverage`], [`CoverageSink`], [`Violation`].
//!
//! The layers and the pipeline a scene takes from file to coverage are drawn in
//! ARCHITECTURE.md at the top of the repository.
//!
//! ## Features
//! - `proptest`: the strategies in `strategy` (random triangles, spade meshes, tie-heavy
//!   inputs) for your own property tests; `harness`: the counterexample search for your
//!   own rasterizer and the invariant suite behind `rasterproof check`; the hunt
//!   (`oracle::hunt`). The suite's and the hunt's cases run on scoped threads
//!   (`harness::runner`); rayon, in every build, maps a scene's primitives on threads
//!   ([`chunks`]).
//! - `trade`: the trade (`trade`) and its pictures (plotters); implies `proptest`.
//! - `cli` (default): the `rasterproof` command (clap, indicatif, ctrlc); implies
//!   `trade`. A crate that only tests its own rasterizer depends on rasterproof with
//!   `default-features = false, features = ["proptest"]`.

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

pub mod area;
pub mod check;
pub mod chunks;
pub mod clip;
pub mod convention;
pub mod coverage;
pub mod edge;
pub mod fill;
pub mod geom;
#[cfg(feature = "proptest")]
pub mod harness;
pub mod import;
pub mod interp;
pub mod line;
pub mod model;
pub mod num;
pub mod oracle;
pub mod pattern;
pub mod raster;
pub mod scene;
#[cfg(feature = "proptest")]
pub mod strategy;
#[cfg(feature = "trade")]
pub mod trade;
pub mod tri;

pub use check::Violation;
pub use convention::{Preset, Target};
pub use coverage::{Coverage, CoverageSink};
pub use geom::{Point, Polygon, Triangle};
#[cfg(feature = "proptest")]
pub use harness::{find_counterexample, HarnessConfig};
pub use model::plan::plan_scene;
pub use model::{prepare, render, render_area, render_samples, render_triangles, Model, PreparedScene, Primitives};
#[cfg(feature = "proptest")]
pub use oracle::hunt::{hunt, HuntConfig};
pub use oracle::{compare, explain_pixel, fit, Theirs};
pub use scene::{parse_scene, Scene};

// The README's Rust example runs as a doc test.
#[cfg(all(doctest, feature = "proptest"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
