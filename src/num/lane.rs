//! The lane arithmetic every planned engine is generic over: the [`Lane`] trait (add,
//! subtract, multiply, compare, and a triangle row's inside mask) and its implementations
//! for each [`Width`]'s type, with the SIMD row tests of the machine integers (the `wide`
//! crate), so that one traversal is written once and runs in whatever width
//! [`crate::num::plan`] chose for a primitive; and the scaffold every planned engine keeps
//! a primitive in (`Planned`): its plan, its state in the planned width, and the one
//! dispatch from that width to the engine compiled for it.

use std::fmt;

use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

use super::plan::{Bound, Plan, Width};

/// The arithmetic of a planned engine, implemented by every [`Width`]'s type: the engines
/// are generic over it, so one traversal is written once and runs in each width.
///
/// Only exact operations: the plan guarantees every operand and every result lies within
/// [`Width::limit`], where addition and comparison are exact in each type. The machine
/// integers add with overflow checks when debug assertions are on (tests, fuzzing) and
/// wrap otherwise: the bound is the proof, and a wrong bound is caught by the tests at
/// each width's boundary.
pub trait Lane: Clone + fmt::Debug {
    /// The width this type is.
    const WIDTH: Width;
    /// `v` in this type. The caller has checked `v` against the plan; a value out of range
    /// panics.
    fn from_big(v: &BigInt) -> Self;
    /// `v` in this type, as [`Lane::from_big`] (without a big integer in the machine
    /// widths).
    fn from_i128(v: i128) -> Self {
        Self::from_big(&BigInt::from(v))
    }
    /// Zero.
    fn zero_value() -> Self;
    /// `self + other`.
    fn plus(&self, other: &Self) -> Self;
    /// `self += other`.
    fn add_to(&mut self, other: &Self);
    /// `self - other`.
    fn minus(&self, other: &Self) -> Self;
    /// `self * other` (the plan bounds the product too).
    fn times(&self, other: &Self) -> Self;
    /// `self < other`.
    fn less(&self, other: &Self) -> bool;
    /// `k * self`, for a small count `k` (the plan bounds the product). By addition here;
    /// the machine types multiply.
    fn scaled_by(&self, k: u32) -> Self {
        let mut acc = Self::zero_value();
        for _ in 0..k {
            acc.add_to(self);
        }
        acc
    }
    /// `self >= 0`.
    fn non_negative(&self) -> bool;
    /// Whether all three are `>= 0` (the inside test of a triangle's three edges).
    #[inline(always)]
    fn all_non_negative(v: &[Self; 3]) -> bool {
        v.iter().all(Lane::non_negative)
    }

    /// The row ramp of a triangle's three edges: `ramp[k][i] = i * step[k]` for
    /// `i <= last` (at most [`ROW`] - 1), zero beyond. Every entry is within the plan's
    /// bound when `last` is at most the range's last column (the planned engines bound
    /// `min(ROW - 1, width)` steps).
    #[inline(always)]
    fn ramp(step: &[Self; 3], last: u32) -> [[Self; ROW]; 3] {
        let mut ramp: [[Self; ROW]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| Self::zero_value()));
        for (lanes, step) in ramp.iter_mut().zip(step) {
            let mut at = Self::zero_value();
            for lane in lanes.iter_mut().take(last as usize + 1).skip(1) {
                at.add_to(step);
                *lane = at.clone();
            }
        }
        ramp
    }

    /// The inside samples of one row of at most [`ROW`] pixels as a bit mask: bit `i`
    /// (`i <= last`) is set when all three `row[k] + ramp[k][i] >= 0`. `row` holds the
    /// three edge values at the row's first sample, and every value at the row's samples
    /// up to `last` is within the plan's bound. By one addition per pixel and edge here;
    /// the machine integers test all [`ROW`] lanes at once, without a branch.
    #[inline(always)]
    fn row_mask(row: &[Self; 3], ramp: &[[Self; ROW]; 3], last: u32) -> u32 {
        let mut mask = 0;
        for i in 0..=last {
            let at = usize::try_from(i).expect("a lane index");
            let v: [Self; 3] = std::array::from_fn(|k| row[k].plus(&ramp[k][at]));
            mask |= u32::from(Self::all_non_negative(&v)) << i;
        }
        mask
    }

    /// The masks of `rows + 1` consecutive rows ([`Lane::row_mask`]; `HALF` says that
    /// `last < HALF_ROW`, so that the machine integers need test only half the lanes):
    /// `cover(i, mask)` for row `i` from 0, whose first sample holds `first + i * step_y`;
    /// every value at the rows' samples up to `last` is within the plan's bound. Row by row
    /// here; the machine integers keep each edge's row of lanes in SIMD registers and step
    /// them down by one vector add.
    #[inline(always)]
    fn row_masks<const HALF: bool>(
        first: &[Self; 3],
        step_y: &[Self; 3],
        ramp: &[[Self; ROW]; 3],
        last: u32,
        rows: u32,
        mut cover: impl FnMut(u32, u32),
    ) {
        let mut row = first.clone();
        let mut i = 0;
        loop {
            cover(i, Self::row_mask(&row, ramp, last));
            if i == rows {
                break;
            }
            i += 1;
            for (r, s) in row.iter_mut().zip(step_y) {
                r.add_to(s);
            }
        }
    }
}

/// The pixels of one row mask ([`Lane::row_mask`]): the engines' block side.
pub const ROW: usize = 8;

/// The pixels of a half row ([`Lane::row_masks`] with `HALF`).
pub const HALF_ROW: usize = ROW / 2;

macro_rules! int_lane {
    ($t:ty, $w:expr $(, $simd:item)?) => {
        impl Lane for $t {
            const WIDTH: Width = $w;
            fn from_big(v: &BigInt) -> Self {
                v.try_into().expect("value within the planned width")
            }
            fn from_i128(v: i128) -> Self {
                v.try_into().expect("value within the planned width")
            }
            fn zero_value() -> Self {
                0
            }
            #[inline(always)]
            fn plus(&self, other: &Self) -> Self {
                if cfg!(debug_assertions) {
                    self.checked_add(*other).expect("planned bound exceeded")
                } else {
                    self.wrapping_add(*other)
                }
            }
            #[inline(always)]
            fn add_to(&mut self, other: &Self) {
                *self = self.plus(other);
            }
            #[inline(always)]
            fn minus(&self, other: &Self) -> Self {
                if cfg!(debug_assertions) {
                    self.checked_sub(*other).expect("planned bound exceeded")
                } else {
                    self.wrapping_sub(*other)
                }
            }
            #[inline(always)]
            fn times(&self, other: &Self) -> Self {
                if cfg!(debug_assertions) {
                    self.checked_mul(*other).expect("planned bound exceeded")
                } else {
                    self.wrapping_mul(*other)
                }
            }
            #[inline(always)]
            fn less(&self, other: &Self) -> bool {
                self < other
            }
            #[inline(always)]
            fn scaled_by(&self, k: u32) -> Self {
                self.times(&<$t>::try_from(k).expect("a small count"))
            }
            #[inline(always)]
            fn non_negative(&self) -> bool {
                *self >= 0
            }
            #[inline(always)]
            fn all_non_negative(v: &[Self; 3]) -> bool {
                // the sign bit of the OR is set when any of them is negative
                (v[0] | v[1] | v[2]) >= 0
            }
            $($simd)*
        }
    };
}

/// Under debug assertions, that each row value plus each ramp step up to lane `last` is
/// exact (the SIMD lanes wrap).
macro_rules! check_row {
    ($row:expr, $ramp:expr, $last:expr) => {
        if cfg!(debug_assertions) {
            for (lanes, r) in $ramp.iter().zip($row) {
                for step in lanes.iter().take($last as usize + 1) {
                    r.checked_add(*step).expect("planned bound exceeded");
                }
            }
        }
    };
}

/// The body of the SIMD `row_masks`: `$parts` vectors of `$per` lanes of type `$vt` (all
/// `ROW` lanes, or the first `HALF_ROW`).
macro_rules! row_masks_in {
    ($vt:ty, $per:expr, $parts:expr, $t:ty, $first:ident, $step_y:ident, $ramp:ident, $last:ident, $rows:ident, $cover:ident) => {{
        const PARTS: usize = $parts;
        let mut cover = $cover;
        let mut v: [[$vt; PARTS]; 3] = std::array::from_fn(|k| {
            std::array::from_fn(|part| {
                let steps: [$t; $per] = $ramp[k][part * $per..][..$per].try_into().expect("a part of the ramp");
                <$vt>::splat($first[k]) + <$vt>::new(steps)
            })
        });
        let down: [$vt; 3] = std::array::from_fn(|k| <$vt>::splat($step_y[k]));
        let keep = (2u32 << $last) - 1;
        // the rows' first values, stepped checked (debug assertions only)
        let mut checked = *$first;
        let mut i = 0;
        loop {
            check_row!(&checked, $ramp, $last);
            let mut outside = 0u32;
            for part in 0..PARTS {
                let signs = (v[0][part] | v[1][part] | v[2][part]).move_mask();
                outside |= (signs as u32) << (part * $per);
            }
            cover(i, !outside & keep);
            if i == $rows {
                break;
            }
            i += 1;
            for k in 0..3 {
                for lanes in &mut v[k] {
                    #[allow(clippy::assign_op_pattern)] // i64x4 has no `+=`
                    {
                        *lanes = *lanes + down[k];
                    }
                }
                if cfg!(debug_assertions) {
                    checked[k] = checked[k].checked_add($step_y[k]).expect("planned bound exceeded");
                }
            }
        }
    }};
}

/// [`Lane::row_mask`] in SIMD (the `wide` crate: SSE2 on every x86-64, AVX2 when the
/// build enables it, scalar elsewhere): all [`ROW`] lanes added and tested at once,
/// wrapping, since lanes past `last` may leave the bound and are masked off; the sign
/// bits of `e0 | e1 | e2` are the lanes outside. Under debug assertions the lanes up to
/// `last` are checked for overflow first, as every other lane operation is.
macro_rules! simd_row_mask {
    ($t:ty, $v:ident, $per:expr, $half:ident) => {
        /// As the default, without a loop-carried add or a multiply (SSE2 has no 32-bit
        /// lane multiply: `wide` falls back to one scalar multiply per lane, which made
        /// this a tenth of the peer bench's small triangles): `i * step` is the sum of
        /// `step`, `2 step` and `4 step` over the set bits of `i`, each selected by a
        /// constant mask, then lanes past `last` are zeroed. It wraps only in lanes past
        /// `last`.
        #[inline(always)]
        fn ramp(step: &[Self; 3], last: u32) -> [[Self; ROW]; 3] {
            if cfg!(debug_assertions) {
                for &step in step {
                    for i in 0..=last {
                        #[allow(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]
                        step.checked_mul(i as $t).expect("planned bound exceeded");
                    }
                }
            }
            // lane i of `bit[b]` is all ones when bit b of i is set (`ROW` is 8: three bits)
            let bit: [[$t; ROW]; 3] =
                std::array::from_fn(|b| std::array::from_fn(|i| if i & (1 << b) != 0 { -1 } else { 0 }));
            let keep: [$t; ROW] = std::array::from_fn(|i| if i <= last as usize { -1 } else { 0 });
            let mut ramp = [[0; ROW]; 3];
            for (lanes, &step) in ramp.iter_mut().zip(step) {
                for part in 0..ROW / $per {
                    let at = |v: &[$t; ROW]| wide::$v::new(v[part * $per..][..$per].try_into().expect("a part"));
                    let one = wide::$v::splat(step);
                    let two = one + one;
                    let four = two + two;
                    let v = ((one & at(&bit[0])) + (two & at(&bit[1])) + (four & at(&bit[2]))) & at(&keep);
                    lanes[part * $per..][..$per].copy_from_slice(&v.to_array());
                }
            }
            ramp
        }

        #[inline(always)]
        fn row_mask(row: &[Self; 3], ramp: &[[Self; ROW]; 3], last: u32) -> u32 {
            debug_assert!((last as usize) < ROW, "a row of at most ROW pixels");
            check_row!(row, ramp, last);
            let mut outside = 0u32;
            for part in 0..ROW / $per {
                let lane = |k: usize| {
                    let steps: [$t; $per] = ramp[k][part * $per..][..$per]
                        .try_into()
                        .expect("a part of the ramp");
                    wide::$v::splat(row[k]) + wide::$v::new(steps)
                };
                // move_mask: one bit per lane, its sign bit
                let signs = (lane(0) | lane(1) | lane(2)).move_mask();
                outside |= (signs as u32) << (part * $per);
            }
            !outside & ((2u32 << last) - 1)
        }

        /// Each edge's lanes held in vectors (one of [`HALF_ROW`] lanes when `HALF`) and
        /// stepped down by a vector add, wrapping: under debug assertions each row's
        /// values up to `last` are checked first, as in `row_mask`.
        #[inline(always)]
        fn row_masks<const HALF: bool>(
            first: &[Self; 3],
            step_y: &[Self; 3],
            ramp: &[[Self; ROW]; 3],
            last: u32,
            rows: u32,
            cover: impl FnMut(u32, u32),
        ) {
            if HALF {
                debug_assert!((last as usize) < HALF_ROW, "a row of at most HALF_ROW pixels");
                row_masks_in!(
                    wide::$half,
                    HALF_ROW,
                    1,
                    $t,
                    first,
                    step_y,
                    ramp,
                    last,
                    rows,
                    cover
                );
            } else {
                row_masks_in!(
                    wide::$v,
                    $per,
                    ROW / $per,
                    $t,
                    first,
                    step_y,
                    ramp,
                    last,
                    rows,
                    cover
                );
            }
        }
    };
}

int_lane!(i32, Width::I32, simd_row_mask!(i32, i32x8, 8, i32x4););
int_lane!(i64, Width::I64, simd_row_mask!(i64, i64x4, 4, i64x4););
int_lane!(i128, Width::I128);

macro_rules! float_lane {
    ($t:ty, $w:expr) => {
        impl Lane for $t {
            const WIDTH: Width = $w;
            fn from_big(v: &BigInt) -> Self {
                assert!($w.holds(v), "value {v} beyond the planned width {}", $w);
                // |v| <= 2^53: exact in i64 and then in the float.
                v.to_i64().expect("within 2^53") as $t
            }
            fn from_i128(v: i128) -> Self {
                // The width's limit, 2^24 or 2^53: every integer up to it is exact.
                let limit = 1u128 << <$t>::MANTISSA_DIGITS;
                assert!(
                    v.unsigned_abs() <= limit,
                    "value {v} beyond the planned width {}",
                    $w
                );
                v as $t
            }
            fn zero_value() -> Self {
                0.0
            }
            #[inline(always)]
            fn plus(&self, other: &Self) -> Self {
                self + other
            }
            #[inline(always)]
            fn add_to(&mut self, other: &Self) {
                *self += other;
            }
            #[inline(always)]
            fn minus(&self, other: &Self) -> Self {
                self - other
            }
            #[inline(always)]
            fn times(&self, other: &Self) -> Self {
                self * other
            }
            #[inline(always)]
            fn less(&self, other: &Self) -> bool {
                self < other
            }
            #[inline(always)]
            fn non_negative(&self) -> bool {
                *self >= 0.0
            }
        }
    };
}

float_lane!(f32, Width::F32);
float_lane!(f64, Width::F64);

impl Lane for BigInt {
    const WIDTH: Width = Width::Big;
    fn from_big(v: &BigInt) -> Self {
        v.clone()
    }
    fn zero_value() -> Self {
        Zero::zero()
    }
    fn plus(&self, other: &Self) -> Self {
        self + other
    }
    fn add_to(&mut self, other: &Self) {
        *self += other;
    }
    fn minus(&self, other: &Self) -> Self {
        self - other
    }
    fn times(&self, other: &Self) -> Self {
        self * other
    }
    fn less(&self, other: &Self) -> bool {
        self < other
    }
    fn non_negative(&self) -> bool {
        !self.is_negative()
    }
}
/// What a planned engine keeps per primitive, one type per lane type (a triangle's edges,
/// a segment's values, a polygon's remainders): its setup computes the state exactly, in
/// [`BigInt`], and [`Planned`] converts it once to the width of the plan.
pub(crate) trait LaneState {
    /// The state held in lane type `T`.
    type In<T: Lane>: Clone + fmt::Debug;
    /// The exact state in `T` (every value within the plan's bound, so exact).
    fn convert<T: Lane>(exact: &Self::In<BigInt>) -> Self::In<T>;
}

/// The exact integers a planned engine's setup computes in: `i128` with every operation
/// checked (`None` on overflow, and the setup is redone in [`BigInt`]), or [`BigInt`]
/// (never `None`). One setup, generic over this, so that the machine-integer setup of a
/// small primitive and the big one of any other are the same code.
pub(crate) trait SetupInt: Clone + fmt::Debug + Ord {
    /// `v`.
    fn from_i64(v: i64) -> Self;
    /// `self + o`.
    fn add_exact(&self, o: &Self) -> Option<Self>;
    /// `self - o`.
    fn sub_exact(&self, o: &Self) -> Option<Self>;
    /// `self * o`.
    fn mul_exact(&self, o: &Self) -> Option<Self>;
    /// `|self|`.
    fn abs_exact(&self) -> Option<Self>;
    /// `self < 0`.
    fn below_zero(&self) -> bool;
    /// `self == 0`.
    fn equals_zero(&self) -> bool;
    /// The value as a big integer.
    fn to_big(&self) -> BigInt;
    /// The value in lane type `T` (it is within the plan's bound).
    fn to_lane<T: Lane>(&self) -> T;
    /// `-self`.
    fn neg_exact(&self) -> Option<Self> {
        Self::from_i64(0).sub_exact(self)
    }
    /// `k self`.
    fn mul_count(&self, k: u32) -> Option<Self> {
        self.mul_exact(&Self::from_i64(k.into()))
    }
}

impl SetupInt for i128 {
    #[inline]
    fn from_i64(v: i64) -> Self {
        v.into()
    }
    #[inline]
    fn add_exact(&self, o: &Self) -> Option<Self> {
        self.checked_add(*o)
    }
    #[inline]
    fn sub_exact(&self, o: &Self) -> Option<Self> {
        self.checked_sub(*o)
    }
    #[inline]
    fn mul_exact(&self, o: &Self) -> Option<Self> {
        self.checked_mul(*o)
    }
    #[inline]
    fn abs_exact(&self) -> Option<Self> {
        self.checked_abs()
    }
    #[inline]
    fn below_zero(&self) -> bool {
        *self < 0
    }
    #[inline]
    fn equals_zero(&self) -> bool {
        *self == 0
    }
    fn to_big(&self) -> BigInt {
        BigInt::from(*self)
    }
    fn to_lane<T: Lane>(&self) -> T {
        T::from_i128(*self)
    }
}

impl SetupInt for BigInt {
    fn from_i64(v: i64) -> Self {
        v.into()
    }
    fn add_exact(&self, o: &Self) -> Option<Self> {
        Some(self + o)
    }
    fn sub_exact(&self, o: &Self) -> Option<Self> {
        Some(self - o)
    }
    fn mul_exact(&self, o: &Self) -> Option<Self> {
        Some(self * o)
    }
    fn abs_exact(&self) -> Option<Self> {
        Some(num_traits::Signed::abs(self))
    }
    fn below_zero(&self) -> bool {
        num_traits::Signed::is_negative(self)
    }
    fn equals_zero(&self) -> bool {
        num_traits::Zero::is_zero(self)
    }
    fn to_big(&self) -> BigInt {
        self.clone()
    }
    fn to_lane<T: Lane>(&self) -> T {
        T::from_big(self)
    }
}

/// A state whose setup may run in `i128` ([`SetupInt`]): converted from its `i128`
/// values as from its big ones.
pub(crate) trait LaneStateI128: LaneState {
    /// The exact state in `T` (every value within the plan's bound, so exact).
    fn convert_i128<T: Lane>(exact: &Self::In<i128>) -> Self::In<T>;
}

/// An engine, generic over the lane type, run on a primitive's state in whichever width
/// was planned: [`Planned::run`] matches the width once per primitive and calls the
/// engine compiled for that type, so no dispatch reaches its loops.
pub(crate) trait InWidth<F: LaneState> {
    /// What the run returns.
    type Output;
    /// Runs the engine on `state`, held in `T`.
    fn run<T: Lane>(self, state: &F::In<T>) -> Self::Output;
}

/// A state in the planned width: one arm per [`Width`], the one place besides the width
/// itself and its [`Lane`] implementation that a new width is added to.
#[derive(Debug, Clone)]
enum Lanes<F: LaneState> {
    F32(F::In<f32>),
    I32(F::In<i32>),
    F64(F::In<f64>),
    I64(F::In<i64>),
    I128(F::In<i128>),
    /// Boxed, so that arbitrary precision does not widen the machine widths' primitives.
    Big(Box<F::In<BigInt>>),
}

/// A primitive as every planned engine keeps it: its plan and its state in the planned
/// width.
#[derive(Debug, Clone)]
pub(crate) struct Planned<F: LaneState> {
    plan: Plan,
    lanes: Lanes<F>,
}

impl<F: LaneState> Planned<F> {
    /// `exact` in the cheapest width that holds `bound`.
    pub(crate) fn new(scale: BigInt, bound: Bound, exact: F::In<BigInt>) -> Planned<F> {
        Self::in_width(Plan::new(scale, bound), exact)
    }

    /// `exact` in `width`, or `Err(plan)` (the plan it would have) when `width` cannot
    /// hold `bound`: for the tests and benches that force every width.
    pub(crate) fn forced(scale: BigInt, bound: Bound, exact: F::In<BigInt>, width: Width) -> Result<Planned<F>, Plan> {
        match Plan::forced(scale.clone(), bound.clone(), width) {
            Some(plan) => Ok(Self::in_width(plan, exact)),
            None => Err(Plan::new(scale, bound)),
        }
    }

    fn in_width(plan: Plan, exact: F::In<BigInt>) -> Planned<F> {
        let lanes = match plan.width {
            Width::F32 => Lanes::F32(F::convert(&exact)),
            Width::I32 => Lanes::I32(F::convert(&exact)),
            Width::F64 => Lanes::F64(F::convert(&exact)),
            Width::I64 => Lanes::I64(F::convert(&exact)),
            Width::I128 => Lanes::I128(F::convert(&exact)),
            Width::Big => Lanes::Big(Box::new(exact)),
        };
        Planned { plan, lanes }
    }

    /// `exact`, set up in `i128`, in the cheapest width that holds `bound` (at most
    /// `i128`, which holds every value of the setup).
    pub(crate) fn new_i128(scale: BigInt, bound: Bound, exact: F::In<i128>) -> Planned<F>
    where
        F: LaneStateI128,
    {
        let plan = Plan::new(scale, bound);
        let lanes = match plan.width {
            Width::F32 => Lanes::F32(F::convert_i128(&exact)),
            Width::I32 => Lanes::I32(F::convert_i128(&exact)),
            Width::F64 => Lanes::F64(F::convert_i128(&exact)),
            Width::I64 => Lanes::I64(F::convert_i128(&exact)),
            Width::I128 => Lanes::I128(exact),
            Width::Big => Lanes::Big(Box::new(F::convert_i128(&exact))),
        };
        Planned { plan, lanes }
    }

    /// The plan: scale, bound and width.
    pub(crate) fn plan(&self) -> &Plan {
        &self.plan
    }

    /// Runs `engine` on the state, in the planned width.
    #[inline]
    pub(crate) fn run<E: InWidth<F>>(&self, engine: E) -> E::Output {
        match &self.lanes {
            Lanes::F32(s) => engine.run(s),
            Lanes::I32(s) => engine.run(s),
            Lanes::F64(s) => engine.run(s),
            Lanes::I64(s) => engine.run(s),
            Lanes::I128(s) => engine.run(s),
            Lanes::Big(s) => engine.run(&**s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_add_and_compare() {
        fn check<T: Lane>() {
            let a = T::from_big(&BigInt::from(-5));
            let b = T::from_big(&BigInt::from(5));
            assert!(a.plus(&b).non_negative());
            assert!(!a.non_negative());
            let mut c = T::zero_value();
            c.add_to(&a);
            assert!(!c.non_negative());
        }
        check::<f32>();
        check::<i32>();
        check::<f64>();
        check::<i64>();
        check::<i128>();
        check::<BigInt>();
    }

    /// The SIMD `ramp`, `row_mask` and `row_masks` (whole and half rows) of the machine
    /// integers, and the trait's own loops (i128), against plain loops over the lanes, at
    /// every row length, for steps and rows of both signs, small and near the width's
    /// limit (every value the lanes must hold within it).
    #[test]
    #[allow(clippy::needless_range_loop, clippy::cast_possible_truncation)] // lanes by index, as written
    fn simd_rows_equal_plain_loops() {
        fn check<T: Lane + Copy + PartialEq + TryFrom<i64> + std::ops::Mul<Output = T> + std::ops::Add<Output = T>>(
            magnitude: i64,
        ) where
            <T as TryFrom<i64>>::Error: fmt::Debug,
        {
            let t = |v: i64| T::try_from(v).expect("in the lane type");
            // splitmix64, seeded: values only need to be spread
            let mut state = 11u64;
            let mut next = move |m: i64| {
                state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
                let z = (state ^ (state >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                let z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                i64::try_from((z ^ (z >> 31)) % (2 * m.unsigned_abs() + 1)).expect("small") - m
            };
            for case in 0..400 {
                // steps small enough that 7 across and 2 down from any row value stay in the
                // width
                let m = if case % 2 == 0 { 40 } else { magnitude };
                let step: [T; 3] = std::array::from_fn(|_| t(next(m / 16)));
                let row: [T; 3] = std::array::from_fn(|_| t(next(m / 4)));
                for last in 0..8u32 {
                    let ramp = T::ramp(&step, last);
                    let mut plain_mask = 0u32;
                    for i in 0..ROW {
                        let i_t = t(i64::try_from(i).expect("small"));
                        for k in 0..3 {
                            let want = if i <= last as usize { step[k] * i_t } else { t(0) };
                            assert_eq!(ramp[k][i], want, "ramp lane {i} of {last}, case {case}");
                        }
                        let inside = (0..3).all(|k| (row[k] + step[k] * i_t).non_negative());
                        if i <= last as usize && inside {
                            plain_mask |= 1 << i;
                        }
                    }
                    assert_eq!(T::row_mask(&row, &ramp, last), plain_mask, "row of {last}, case {case}");
                    // three rows stepped down by `down`, against each row's mask from scratch
                    let down: [T; 3] = std::array::from_fn(|_| t(next(m / 16)));
                    let want: Vec<(u32, u32)> = (0..3u32)
                        .map(|i| {
                            let r: [T; 3] = std::array::from_fn(|k| row[k] + down[k] * t(i64::from(i)));
                            (i, T::row_mask(&r, &ramp, last))
                        })
                        .collect();
                    let mut got = Vec::new();
                    T::row_masks::<false>(&row, &down, &ramp, last, 2, |i, mask| got.push((i, mask)));
                    assert_eq!(got, want, "rows of {last}, case {case}");
                    if (last as usize) < HALF_ROW {
                        got.clear();
                        T::row_masks::<true>(&row, &down, &ramp, last, 2, |i, mask| got.push((i, mask)));
                        assert_eq!(got, want, "half rows of {last}, case {case}");
                    }
                }
            }
        }
        check::<i32>(i64::from(i32::MAX));
        check::<i64>(i64::MAX / 2);
        // the trait's loops (no SIMD override)
        check::<i128>(i64::MAX / 2);
    }

    #[test]
    #[should_panic(expected = "planned bound exceeded")]
    fn an_i32_overflow_is_caught_under_debug_assertions() {
        let m = i32::from_big(&BigInt::from(i32::MAX));
        let _ = m.plus(&1);
    }
}
