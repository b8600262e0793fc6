//! The oracle for other implementations: compare another renderer's output with the exact
//! answer and explain every differing pixel ([`compare()`], the reason classes in
//! [`reason`]), fit the convention their image follows ([`fit()`]), explain one pixel of a scene ([`explain_pixel`]), read their output
//! ([`Theirs`]: a mask PNG, an ids PNG or `render`'s JSON), run another renderer as a
//! program, once per scene ([`program::Program`]) or staying alive across scenes
//! ([`stay_alive::StayAlive`]), both a [`program::Renderer`], and hunt for its failures with a shrinker in the loop
//! (`hunt`, feature `proptest`).
//!
//! The CLI's `compare` and `explain` are thin layers over these functions.

pub mod adapter;
mod candidate;
pub mod compare;
pub mod conservative;
pub mod evidence;
pub mod explain;
pub mod fit;
pub mod grey;
#[cfg(feature = "proptest")]
pub mod hunt;
pub mod program;
pub mod reason;
pub mod samples;
pub mod stay_alive;
pub mod svg;
pub mod theirs;

pub use compare::{compare, CompareError, CompareReport, DiffPixel, PixelFinding, PixelKind, Relation, SizeMismatch};
pub use explain::{explain_pixel, ModelAt, PixelExplanation, PrimitiveAt};
pub use fit::{fit, Candidate, Fit, FitError, FitReport};
pub use reason::{Reason, ReasonClass, Snapping};
pub use theirs::{Background, Format, TheirPixel, Theirs, TheirsError};
