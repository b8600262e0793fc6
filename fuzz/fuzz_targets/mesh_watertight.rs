//! Watertight meshes and invariance (the watertight and invariance checkers): a rectangle cut into
//! a grid of 1 to 3 x 1 to 3 cells, every interior vertex moved within its cell (and
//! every boundary vertex along its side) by less than 1/16 of a cell, each cell split
//! along either diagonal:
//!
//! 1. `exact` and `exact-snapped` cover every sample inside the rectangle (after the tie
//!    rule's ε move) exactly once and nothing outside (`check_watertight`), so no pixel
//!    twice (`check_no_double_cover`); `fixed` and `scanline` equal `exact-snapped`. The moves keep
//!    every triangle's orientation (each coordinate difference moves by at most 1/8 of a
//!    cell, snapping by at most 1/16 more at 3 or more subpixel bits), so this is exact.
//! 2. A triangle of the mesh under rotation and winding reversal covers the same pixels
//!    (`check_rotation_and_winding`), and a translation by whole pixels moves its pixels
//!    (`check_translation`, under the roundings it holds for: nearest-even, floor,
//!    ceiling), in each of those models.
//! 3. The float models render the mesh without panicking (their gaps and double covers
//!    are the measured trade, not a failure); the coverage picture, its legend and ASCII
//!    grid and `explain_sample` are written.
//!
//! `Debug` is the input struct (Rust).

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, PresetChoice};
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::check::{
    check_no_double_cover, check_rotation_and_winding, check_translation, check_watertight, explain_sample,
};
use rasterproof::convention::{Rounding, Target};
use rasterproof::coverage::picture::Scale;
use rasterproof::coverage::IdRun;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render_triangles, Model};

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    /// Cells across and down, `1 + n % 3`.
    cols: u8,
    rows: u8,
    /// A cell's side in half pixels, `2 + n % 5` (1 to 3 px).
    cell: [u8; 2],
    /// The rectangle's top-left corner, half pixels, `n % 8`.
    origin: [u8; 2],
    /// Each vertex's move, row-major over the (cols + 1) x (rows + 1) grid; in
    /// 1/256ths of a sixteenth of the cell: `(m % 255 - 127) / 128 / 16` cells.
    moves: Vec<[u8; 2]>,
    /// Per cell, which diagonal (bit k of the cell's index, repeated).
    diagonals: u16,
    preset: PresetChoice,
    /// Subpixel bits, `3 + n % 14` (3..=16).
    bits: u8,
    corner: bool,
    /// The translation, `n % 7 - 3` pixels each way, and which triangle is checked.
    shift: [u8; 2],
    pick: u8,
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

impl Input {
    /// The mesh and its outline (the rectangle's corners).
    fn mesh(&self) -> (Vec<Triangle>, Vec<Point>) {
        let (cols, rows) = (1 + usize::from(self.cols % 3), 1 + usize::from(self.rows % 3));
        let (cw, ch) = (2 + i64::from(self.cell[0] % 5), 2 + i64::from(self.cell[1] % 5));
        let (ox, oy) = (i64::from(self.origin[0] % 8), i64::from(self.origin[1] % 8));
        let mv = |k: usize, axis: usize| -> i64 {
            let m = self.moves.get(k).map_or(127, |m| i64::from(m[axis] % 255));
            m - 127 // -127..=127, in 1/(128 * 16) cells
        };
        // Coordinates in units of 1 / (2 * 128 * 16) px: a cell is cw * 2048 units.
        let unit = 2 * 128 * 16;
        let vertex = |i: usize, j: usize| -> Point {
            let k = j * (cols + 1) + i;
            let (ii, jj) = (i64::try_from(i).expect("small"), i64::try_from(j).expect("small"));
            let mut x = (ox + ii * cw) * 128 * 16;
            let mut y = (oy + jj * ch) * 128 * 16;
            // Interior vertices move both ways, boundary ones along their side only.
            if i != 0 && i != cols {
                x += mv(k, 0) * cw;
            }
            if j != 0 && j != rows {
                y += mv(k, 1) * ch;
            }
            Point::new(q(x, unit), q(y, unit))
        };
        let mut mesh = Vec::new();
        for j in 0..rows {
            for i in 0..cols {
                let (a, b, c, d) = (vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1));
                if self.diagonals >> ((j * cols + i) % 16) & 1 == 0 {
                    mesh.push(Triangle::new(a.clone(), b, c.clone()));
                    mesh.push(Triangle::new(a, c, d));
                } else {
                    mesh.push(Triangle::new(a, b.clone(), d.clone()));
                    mesh.push(Triangle::new(b, c, d));
                }
            }
        }
        let outline = vec![vertex(0, 0), vertex(cols, 0), vertex(cols, rows), vertex(0, rows)];
        (mesh, outline)
    }
}

fuzz_target!(|input: Input| {
    let mut conv = convention(input.preset, None, input.corner);
    conv.subpixel_bits = 3 + u32::from(input.bits % 14);
    let target = Target::new(14, 14, conv).expect("valid");
    let (mesh, outline) = input.mesh();
    let exact_models = [Model::Exact, Model::ExactSnapped, Model::Fixed, Model::Scanline];
    let render = |m: Model| render_triangles(&mesh, &target, m).expect("small coordinates are in every envelope");
    // The two exact meshes (as written, snapped) checked sample by sample; the integer
    // models equal the snapped one, so they are watertight too.
    let snapped = render(Model::ExactSnapped);
    for (m, c) in [
        (Model::Exact, render(Model::Exact)),
        (Model::ExactSnapped, snapped.clone()),
    ] {
        if let Err(v) = check_watertight(&mesh, &outline, &c, &target) {
            panic!("{m}: {v}\n{}", c.to_ascii());
        }
        check_no_double_cover(&c).unwrap_or_else(|v| panic!("{m}: {v}"));
    }
    for m in [Model::Fixed, Model::Scanline] {
        assert_eq!(render(m), snapped, "{m} differs from exact-snapped on the mesh");
    }
    let t = &mesh[usize::from(input.pick) % mesh.len()];
    let (dx, dy) = (i64::from(input.shift[0] % 7) - 3, i64::from(input.shift[1] % 7) - 3);
    let translation_holds = matches!(
        conv.rounding,
        Rounding::NearestEven | Rounding::Floor | Rounding::Ceiling
    );
    for m in exact_models {
        check_rotation_and_winding(t, &target, m).unwrap_or_else(|v| panic!("{v}"));
        if translation_holds {
            check_translation(t, &target, dx, dy, m).unwrap_or_else(|v| panic!("{v}"));
        }
    }
    for m in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
        let _ = render(m);
    }
    let c = snapped;
    let runs = [IdRun {
        name: "triangles",
        count: mesh.len(),
    }];
    let _ = c.picture(Scale::new(2, 14, 14).expect("a small scale"));
    let _ = c.legend(&runs, Scale::ONE);
    let _ = explain_sample(t, u32::from(input.pick) % 14, u32::from(input.shift[0]) % 14, &target);
});
