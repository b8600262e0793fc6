//! An exact integer DDA: `ceil(v_k / d)` for `v_k = v_0 + k * inc`, advanced one `k` at a
//! time by quotient and remainder (no division per step). The edge walkers of the
//! scanline triangle model and of the polygon filler both run on it; a floor is the ceil
//! of `v - (d - 1)`.

macro_rules! ceil_dda {
    ($(#[$doc:meta])* $name:ident, $t:ty) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub struct $name {
            q: $t,
            r: $t,
            d: $t,
            step_q: $t,
            step_r: $t,
        }

        impl $name {
            /// Starts at `ceil(value / d)`.
            ///
            /// # Panics
            /// When `d <= 0` (a caller bug: the walkers divide by a positive extent).
            #[inline]
            pub fn new(value: $t, inc: $t, d: $t) -> $name {
                assert!(d > 0, "CeilDda needs a positive divisor, got {d}");
                let q = -(-value).div_euclid(d);
                $name {
                    q,
                    r: q * d - value,
                    d,
                    step_q: inc.div_euclid(d),
                    step_r: inc.rem_euclid(d),
                }
            }

            /// The current `ceil(v / d)`.
            #[inline]
            pub fn get(&self) -> $t {
                self.q
            }

            /// Advances to `v + inc`: `v + inc = (q + step_q) d - (r - step_r)`, carrying one
            /// when the remainder goes negative. Without a branch (the carry follows the
            /// slope, which a branch predictor guesses badly): the remainder's sign bit,
            /// spread over the word, is the carry's mask.
            ///
            /// Lane arithmetic (see ARCHITECTURE.md, "Overflow checks"): checked under
            /// debug assertions, wrapping otherwise. No step can overflow while the walked
            /// values fit the type: `q` moves monotonically between `ceil(v / d)` of the
            /// first and last values, `r` stays in `(-d, d)`.
            #[inline]
            pub fn step(&mut self) {
                if cfg!(debug_assertions) {
                    let r = self.r.checked_sub(self.step_r).expect("the walk left its envelope");
                    let carry = r >> (<$t>::BITS - 1);
                    self.r = r + (self.d & carry);
                    self.q = self
                        .q
                        .checked_add(self.step_q - carry)
                        .expect("the walk left its envelope");
                } else {
                    self.r = self.r.wrapping_sub(self.step_r);
                    // all ones when r < 0, else zero
                    let carry = self.r >> (<$t>::BITS - 1);
                    self.r = self.r.wrapping_add(self.d & carry);
                    self.q = self.q.wrapping_add(self.step_q.wrapping_sub(carry));
                }
            }
        }
    };
}

ceil_dda!(
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
    CeilDda,
    i128
);

ceil_dda!(
    /// [`CeilDda`] in i64, for walks whose caller has shown that every value fits: every
    /// `v_k` the walk reaches (one step past the last it reads included) and `d` below
    /// `2^62` in magnitude, so that `q`, `r`, the steps and every sum of them fit too
    /// (`|q| <= |v| / d + 1`, `0 <= r < d`).
    CeilDda64,
    i64
);

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
                    let narrow = |v: i128| i64::try_from(v).unwrap();
                    let mut dda64 = CeilDda64::new(narrow(v0), narrow(inc), narrow(d));
                    for k in 0..12 {
                        let v = v0 + k * inc;
                        assert_eq!(dda.get(), (v + d - 1).div_euclid(d), "v0 {v0} inc {inc} d {d} k {k}");
                        assert_eq!(i128::from(dda64.get()), dda.get(), "i64: v0 {v0} inc {inc} d {d} k {k}");
                        dda.step();
                        dda64.step();
                    }
                }
            }
        }
    }

    /// At the edge of [`CeilDda64`]'s envelope: starts and ends just below `+-2^62`, the
    /// largest divisors and steps a walker makes (`2^46`) and the smallest, against the
    /// i128 walk, which has room to spare.
    #[test]
    fn the_i64_walk_is_exact_up_to_2_to_the_62() {
        let top = (1i128 << 62) - 1;
        for d in [1i128, 2, 3, (1 << 46) - 1, 1 << 46] {
            for inc in [-(1i128 << 46), -d - 1, -1, 0, 1, d + 1, 1 << 46] {
                for v0 in [top - 100 * inc.max(0), -top - 100 * inc.min(0), top / 2, 0] {
                    let mut wide = CeilDda::new(v0, inc, d);
                    let narrow = |v: i128| i64::try_from(v).unwrap();
                    let mut dda64 = CeilDda64::new(narrow(v0), narrow(inc), narrow(d));
                    for k in 0..=100 {
                        let v = v0 + k * inc;
                        assert!(v.abs() <= top);
                        assert_eq!(i128::from(dda64.get()), wide.get(), "v0 {v0} inc {inc} d {d} k {k}");
                        assert_eq!(wide.get(), (v + d - 1).div_euclid(d));
                        wide.step();
                        dda64.step();
                    }
                }
            }
        }
    }
}
