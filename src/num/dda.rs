//! An exact integer DDA: `ceil(v_k / d)` for `v_k = v_0 + k * inc`, advanced one `k` at a
//! time by quotient and remainder (no division per step). The edge walkers of the
//! scanline triangle model and of the polygon filler both run on it; a floor is the ceil
//! of `v - (d - 1)`.

/// `ceil(v / d)` for a value `v` that grows by `inc` per step; `d > 0`.
///
/// Invariant: `v = q d - r` with `0 <= r < d`, so `q = ceil(v / d)`.
///
/// ```
/// use rasterproof::num::dda::CeilDda;
/// // v = -7, -4, -1, 2, 5 over d = 3: ceil = -2, -1, 0, 1, 2.
/// let mut dda = CeilDda::new(-7, 3, 3);
/// let mut seen = Vec::new();
/// for _ in 0..5 {
///     seen.push(dda.get());
///     dda.step();
/// }
/// assert_eq!(seen, [-2, -1, 0, 1, 2]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CeilDda {
    q: i128,
    r: i128,
    d: i128,
    step_q: i128,
    step_r: i128,
}

impl CeilDda {
    /// Starts at `ceil(value / d)`.
    ///
    /// # Panics
    /// When `d <= 0` (a caller bug: the walkers divide by a positive extent).
    pub fn new(value: i128, inc: i128, d: i128) -> CeilDda {
        assert!(d > 0, "CeilDda needs a positive divisor, got {d}");
        let q = -(-value).div_euclid(d);
        CeilDda {
            q,
            r: q * d - value,
            d,
            step_q: inc.div_euclid(d),
            step_r: inc.rem_euclid(d),
        }
    }

    /// The current `ceil(v / d)`.
    pub fn get(&self) -> i128 {
        self.q
    }

    /// Advances to `v + inc`: `v + inc = (q + step_q) d - (r - step_r)`, carrying one
    /// when the remainder goes negative.
    pub fn step(&mut self) {
        self.q += self.step_q;
        self.r -= self.step_r;
        if self.r < 0 {
            self.r += self.d;
            self.q += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against a direct ceiling division written out with `div_euclid` (a different route:
    /// the floor of `(v + d - 1) / d`), over every small start, increment and divisor.
    #[test]
    fn equals_direct_division() {
        for d in 1..=7i128 {
            for inc in -15..=15i128 {
                for v0 in -20..=20i128 {
                    let mut dda = CeilDda::new(v0, inc, d);
                    for k in 0..12 {
                        let v = v0 + k * inc;
                        assert_eq!(dda.get(), (v + d - 1).div_euclid(d), "v0 {v0} inc {inc} d {d} k {k}");
                        dda.step();
                    }
                }
            }
        }
    }
}
