//! Numbers: exact rationals read without f64 ([`exact`]), fixed-point subpixels with one
//! documented envelope ([`fixed`]), precision planning ([`plan`]): the cheapest
//! integer width that is provably exact for a scene's bounds, and the lane arithmetic the
//! planned engines run in that width ([`lane`]).

pub mod compact;
pub mod dda;
pub mod exact;
pub mod fixed;
pub mod lane;
pub mod plan;
pub mod unorm;

pub use exact::{parse_rational, NumberError, Rounding};
pub use fixed::{EnvelopeError, SubPixel, FIXED_ENVELOPE_BITS, MAX_SUBPIXEL_BITS};

/// The last `n` in `lo..hi` for which `holds(n)`, for a predicate that holds at `lo`, fails
/// at `hi` and changes once between (the tests find a plan's width edge with it).
#[cfg(test)]
pub(crate) fn last_where(lo: i64, hi: i64, holds: impl Fn(i64) -> bool) -> i64 {
    assert!(
        holds(lo) && !holds(hi),
        "the predicate must hold at {lo} and fail at {hi}"
    );
    let (mut lo, mut hi) = (lo, hi);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}
