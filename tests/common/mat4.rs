//! An exact 4x4 matrix kit for the homogeneous-clipping tests: products and transforms
//! over `BigRational`, and the exact value of a glam `DMat4`, to check glam's f64 results.
//!
//! `tests/it.rs` declares it once, as `crate::mat4` (it stands alone).

#![allow(dead_code)]

use glam::DMat4;
use num_rational::BigRational;
use num_traits::Zero;

/// A 4x4 exact matrix, row-major (`m[row][col]`), acting on column vectors as glam does:
/// `v' = M v`.
pub type Mat4Exact = [[BigRational; 4]; 4];

/// `a b` (apply `b` first), exactly.
pub fn mat_mul_exact(a: &Mat4Exact, b: &Mat4Exact) -> Mat4Exact {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| (0..4).fold(BigRational::zero(), |acc, k| acc + &a[r][k] * &b[k][c]))
    })
}

/// `m v`, exactly.
pub fn transform_exact(m: &Mat4Exact, v: &[BigRational; 4]) -> [BigRational; 4] {
    std::array::from_fn(|r| (0..4).fold(BigRational::zero(), |acc, k| acc + &m[r][k] * &v[k]))
}

/// The exact value of an f64 matrix (`None` if an entry is not finite).
pub fn mat_exact_from_f64(m: &DMat4) -> Option<Mat4Exact> {
    let cols = m.to_cols_array_2d();
    let mut out: Mat4Exact = std::array::from_fn(|_| std::array::from_fn(|_| BigRational::zero()));
    for (c, col) in cols.iter().enumerate() {
        for (r, &x) in col.iter().enumerate() {
            out[r][c] = BigRational::from_float(x)?;
        }
    }
    Some(out)
}

// The examples these functions had as doc tests when they lived in the crate.
#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    #[test]
    fn mat_mul_applies_the_right_factor_first() {
        // translate x by 1 after scaling x by 2: x -> 2x + 1
        let m = |rows: [[i64; 4]; 4]| -> Mat4Exact { rows.map(|r| r.map(q)) };
        let translate = m([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
        let scale = m([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
        assert_eq!(mat_mul_exact(&translate, &scale)[0], [q(2), q(0), q(0), q(1)]);
    }

    #[test]
    fn transform_copies_minus_z_into_w() {
        // A perspective matrix that copies -z into w: (1, 2, -4, 1) -> w = 4.
        let mut m: [[_; 4]; 4] = std::array::from_fn(|r| std::array::from_fn(|c| q(i64::from(r == c))));
        m[3] = [q(0), q(0), q(-1), q(0)];
        assert_eq!(transform_exact(&m, &[q(1), q(2), q(-4), q(1)])[3], q(4));
    }

    #[test]
    fn exact_from_f64_is_row_major() {
        let m = mat_exact_from_f64(&DMat4::from_translation(glam::DVec3::new(0.5, 0.0, 0.0))).unwrap();
        assert_eq!(m[0][3], BigRational::new(1.into(), 2.into())); // row 0, column 3
    }
}
