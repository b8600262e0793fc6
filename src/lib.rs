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
//! let coverage = render_triangles(Model::Fixed, &mesh, &target).unwrap();
//! assert_eq!(coverage.covered_pixels(), 16);
//! assert_eq!(coverage.double_covered().count(), 0);
//! ```
//!
//! ## Entry points
//!
//! | to | call |
//! |---|---|
//! | render a scene file with a model | [`scene::parse_scene`], then [`model::render`]`(model, &scene.primitives(), &target)` |
//! | render these triangles | [`model::render_triangles`] |
//! | prepare once, draw many times (benchmarks, a colour picture) | [`model::prepare`], [`model::PreparedScene::draw`] |
//! | one triangle, polygon or line in one arithmetic | `tri::{exact, fixed, scanline, float}::rasterize*`, `fill::polygon`, `line::*` |
//! | where a pixel's sample sits; which pixels a box covers | [`raster`] |
//! | check an invariant on any coverage | `check::check_*` |
//! | clip exactly or in floats | [`clip`] |
//! | compare another renderer's output with the exact answer, explain each difference | [`oracle::compare()`], [`oracle::Theirs`] |
//! | explain one pixel of a scene | [`oracle::explain_pixel`] |
//! | every model's speed and error side by side, by coordinate magnitude (feature `trade`) | `trade::run`, `trade::Report` |
//!
//! The layers and the pipeline a scene takes from file to coverage are drawn in
//! ARCHITECTURE.md at the top of the repository.
//!
//! ## Features
//! - `proptest`: the strategies in `strategy` (random triangles, spade meshes, tie-heavy
//!   inputs) for your own property tests, and `harness`: the counterexample search for
//!   your own rasterizer and the invariant suite behind `rasterproof check` (run on a
//!   rayon thread pool, sharded, into a report: `harness::suite::Plan`).
//! - `cli` (default): the `rasterproof` command; implies `proptest`.

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

pub mod check;
pub mod clip;
pub mod convention;
pub mod coverage;
pub mod edge;
pub mod fill;
pub mod geom;
#[cfg(feature = "proptest")]
pub mod harness;
pub mod interp;
pub mod line;
pub mod model;
pub mod num;
pub mod oracle;
pub mod raster;
pub mod scene;
#[cfg(feature = "proptest")]
pub mod strategy;
#[cfg(feature = "trade")]
pub mod trade;
pub mod tri;

// The README's Rust example runs as a doc test.
#[cfg(all(doctest, feature = "proptest"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
