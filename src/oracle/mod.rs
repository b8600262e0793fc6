//! The oracle for other implementations: compare another renderer's output with the exact
//! answer and explain every differing pixel ([`compare`](mod@compare): one shape for every kind of
//! answer, one sample, every sample index, grey levels, conservative coverage, and the fits
//! of a convention, sample positions or a grey method; the reason classes in [`reason`]),
//! explain one pixel of a scene ([`explain_pixel`]), read their output ([`Theirs`]: a mask
//! PNG, an ids PNG, `render`'s JSON or a grey PNG), run another renderer as a program, once
//! per scene or staying alive across scenes ([`renderer`]), and hunt for its failures with a
//! shrinker in the loop (`hunt`, feature `proptest`).
//!
//! The CLI's `compare` and `explain` are thin layers over these functions.

mod candidate;
pub mod compare;
pub mod evidence;
pub mod explain;
#[cfg(feature = "proptest")]
pub mod hunt;
pub mod reason;
pub mod renderer;
pub mod svg;
pub mod theirs;

pub use compare::fit::{fit, Candidate, Fit, FitReport};
pub use compare::{
    compare, judge, CompareError, CompareOptions, CompareReport, Comparison, DiffPixel, Judgement, PixelFinding,
    PixelKind, Question, Relation, SizeMismatch,
};
pub use explain::{explain_pixel, ModelAt, PixelExplanation, PrimitiveAt};
pub use reason::{Reason, ReasonClass, Snapping};
pub use theirs::{Background, Format, GreyImage, TheirPixel, Theirs, TheirsError, ValueImage, ValueSamples};
