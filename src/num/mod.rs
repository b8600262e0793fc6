//! Numbers: exact rationals read without f64 ([`exact`]), fixed-point subpixels with one
//! documented envelope ([`fixed`]), and precision planning ([`plan`]): the cheapest
//! integer width that is provably exact for a scene's bounds.

pub mod dda;
pub mod exact;
pub mod fixed;
pub mod plan;

pub use exact::{parse_rational, NumberError, Rounding};
pub use fixed::{EnvelopeError, SubPixel, FIXED_ENVELOPE_BITS, MAX_SUBPIXEL_BITS};
