//! Flood fill (seed 002): hand-derived goldens on small pictures drawn as ASCII, the span
//! fill against the BFS oracle and two references written here (seed 002's recursion,
//! literally, and a union-find labelling), as properties on noise, mazes and thin
//! diagonal lines; and the sizes recursion cannot reach (4096x4096).

use crate::common;
use crate::raster;

use common::config;
use image::{Rgba, RgbaImage};
use proptest::prelude::*;
use proptest::sample::Index;
use raster::{checkerboard, diagonals, from_ascii, maze, maze_cells, noise, Diagonal, PASSAGE, WALL};
use rasterproof::fill::flood::{bfs_region, flood_fill, span_region, Connectivity, Region};

use Connectivity::{Eight, Four};

const A: Rgba<u8> = Rgba([20, 40, 60, 255]);
/// A with one less alpha: a different colour, as far as exact equality goes.
const A2: Rgba<u8> = Rgba([20, 40, 60, 254]);
const B: Rgba<u8> = Rgba([200, 100, 0, 255]);
/// Not in any generated image.
const MARK: Rgba<u8> = Rgba([1, 2, 3, 4]);

/// `.` is A, `#` is B, `'` is A2.
fn picture(rows: &[&str]) -> RgbaImage {
    from_ascii(rows, |c| match c {
        '.' => A,
        '#' => B,
        '\'' => A2,
        other => panic!("no colour for {other:?}"),
    })
}

/// The pixels marked `x` in a drawing of the same size.
fn mask(rows: &[&str]) -> Region {
    let height = u32::try_from(rows.len()).unwrap();
    let width = u32::try_from(rows[0].len()).unwrap();
    Region::from_fn(width, height, |x, y| rows[y as usize].as_bytes()[x as usize] == b'x')
}

fn span(img: &RgbaImage, seed: (u32, u32), c: Connectivity) -> Region {
    span_region(img, seed, c).unwrap()
}

fn bfs(img: &RgbaImage, seed: (u32, u32), c: Connectivity) -> Region {
    bfs_region(img, seed, c).unwrap()
}

/// Both algorithms give `count` pixels (and the same region).
fn assert_count(img: &RgbaImage, seed: (u32, u32), c: Connectivity, count: usize) {
    let (s, b) = (span(img, seed, c), bfs(img, seed, c));
    assert_eq!(s.len(), count, "span, seed {seed:?} {c}: {s:?}");
    assert_eq!(b.len(), count, "bfs, seed {seed:?} {c}: {b:?}");
    assert_eq!(s, b);
}

// ---------------------------------------------------------------------------------------
// Goldens, counted by hand.

/// A diamond of # that is 8-connected but 4-disconnected (each # touches the next only at
/// a corner), around a plus of 5 dots:
///
/// ```text
///   x: 01234
///   y0 ..#..    the 8 #: (2,0) (1,1) (3,1) (0,2) (4,2) (1,3) (3,3) (2,4)
///   y1 .#.#.    inside dots: (2,1) (1,2) (2,2) (3,2) (2,3): 5
///   y2 #...#    outside dots: 3 in each corner ((0,0) (1,0) (0,1) ...): 12
///   y3 .#.#.
///   y4 ..#..
/// ```
///
/// Four from (2,2): the plus; (2,1)'s neighbours up/left/right are #: 5. Eight: (2,1)
/// touches (1,0) and (3,0) diagonally, (2,3) touches (1,4) and (3,4), so every dot:
/// 25 - 8 = 17. Four from (0,0): its corner, 3; eight: 17. Four from (2,0): (2,0) alone
/// (its neighbours are dots); eight: the 8 # of the diamond.
#[test]
fn golden_diamond_leaks_only_diagonally() {
    let img = picture(&["..#..", ".#.#.", "#...#", ".#.#.", "..#.."]);
    assert_count(&img, (2, 2), Four, 5);
    assert_eq!(
        span(&img, (2, 2), Four),
        mask(&["     ", "  x  ", " xxx ", "  x  ", "     "])
    );
    assert_count(&img, (2, 2), Eight, 17);
    assert_count(&img, (0, 0), Four, 3);
    assert_eq!(
        span(&img, (0, 0), Four),
        mask(&["xx   ", "x    ", "     ", "     ", "     "])
    );
    assert_count(&img, (0, 0), Eight, 17);
    assert_count(&img, (4, 4), Four, 3);
    assert_count(&img, (2, 0), Four, 1);
    assert_count(&img, (2, 0), Eight, 8);
    assert_eq!(
        span(&img, (2, 0), Eight),
        mask(&["  x  ", " x x ", "x   x", " x x ", "  x  "])
    );
}

/// The main diagonal of a 5x5 square. Four: the dots split into the triangle above
/// (x > y: 4 + 3 + 2 + 1 = 10) and the one below (10); eight: (1,0) touches (0,1) at a
/// corner, so all 20 dots. The diagonal itself: 1 pixel (four), 5 (eight).
#[test]
fn golden_diagonal_line() {
    let img = picture(&["#....", ".#...", "..#..", "...#.", "....#"]);
    assert_count(&img, (1, 0), Four, 10);
    assert_eq!(
        span(&img, (4, 0), Four),
        mask(&[" xxxx", "  xxx", "   xx", "    x", "     "])
    );
    assert_count(&img, (0, 4), Four, 10);
    assert_count(&img, (1, 0), Eight, 20);
    assert_count(&img, (2, 2), Four, 1);
    assert_count(&img, (2, 2), Eight, 5);
}

/// U-turns, which a span fill must follow back up: a "U" (the seed at the top of the left
/// arm, 9 - 2 = 7 dots), an upside-down comb (4 teeth of 2 + a bar of 7 = 15 dots; each
/// # column is 2 pixels and the columns are 2 apart, so 2 either way), and a serpentine
/// (7 + 1 + 7 + 1 + 7 = 23 dots from the middle row; the # rows are 6 each, 2 rows apart).
#[test]
fn golden_u_turns() {
    let u = picture(&[".#.", ".#.", "..."]);
    for c in Connectivity::ALL {
        assert_count(&u, (0, 0), c, 7);
        assert_count(&u, (1, 1), c, 2);
    }
    let comb = picture(&[".#.#.#.", ".#.#.#.", "......."]);
    for c in Connectivity::ALL {
        assert_count(&comb, (6, 0), c, 15);
        assert_count(&comb, (3, 1), c, 2);
    }
    let serpentine = picture(&[".......", "######.", ".......", ".######", "......."]);
    for c in Connectivity::ALL {
        assert_count(&serpentine, (3, 2), c, 23);
        assert_count(&serpentine, (0, 4), c, 23);
        assert_count(&serpentine, (0, 1), c, 6);
        assert_count(&serpentine, (6, 3), c, 6);
    }
}

/// Colours are compared exactly, alpha included: `'` is A with alpha 254. In the row
/// `..'..` the seed (0,0) has 2 pixels either way; the middle pixel is 1. In the 3x3
/// picture the ' cross splits the four corner dots apart (four: 1 each); eight: the
/// corners touch no other dot diagonally either (their diagonal neighbour is the centre
/// ', not a dot), so still 1. The cross is 5 either way.
#[test]
fn golden_alpha_counts() {
    let row = picture(&["..'.."]);
    for c in Connectivity::ALL {
        assert_count(&row, (0, 0), c, 2);
        assert_count(&row, (4, 0), c, 2);
        assert_count(&row, (2, 0), c, 1);
    }
    let cross = picture(&[".'.", "'''", ".'."]);
    for c in Connectivity::ALL {
        assert_count(&cross, (0, 0), c, 1);
        assert_count(&cross, (1, 1), c, 5);
    }
}

/// Degenerate sizes: a single pixel, a single row or column, and the edges of the image.
#[test]
fn golden_thin_images() {
    assert_count(&picture(&["."]), (0, 0), Eight, 1);
    assert_count(&picture(&["...#..."]), (6, 0), Four, 3);
    let column = picture(&[".", ".", "#", "."]);
    assert_count(&column, (0, 0), Eight, 2);
    assert_count(&column, (0, 3), Four, 1);
    let img = picture(&["....."]);
    assert!(span_region(&img, (5, 0), Four).is_err());
    assert!(bfs_region(&img, (0, 1), Eight).is_err());
    let err = span_region(&img, (5, 0), Four).unwrap_err();
    assert_eq!(
        err.to_string(),
        "seed (5, 0) is outside the 5x1 image (x must be in 0..5, y in 0..1)"
    );
}

/// `flood_fill` recolours the diamond's inside (5 pixels, above) and nothing else; filling
/// with the region's own colour changes nothing and still reports 5.
#[test]
fn golden_flood_fill_recolours() {
    let before = picture(&["..#..", ".#.#.", "#...#", ".#.#.", "..#.."]);
    let mut img = before.clone();
    assert_eq!(flood_fill(&mut img, (2, 2), Four, MARK).unwrap(), 5);
    let inside = mask(&["     ", "  x  ", " xxx ", "  x  ", "     "]);
    for (x, y, px) in img.enumerate_pixels() {
        let want = if inside.contains(x, y) {
            MARK
        } else {
            *before.get_pixel(x, y)
        };
        assert_eq!(*px, want, "({x}, {y})");
    }
    let mut same = before.clone();
    assert_eq!(flood_fill(&mut same, (2, 2), Eight, A).unwrap(), 17);
    assert_eq!(same, before);
    assert!(flood_fill(&mut same, (0, 5), Four, MARK).is_err());
    assert_eq!(same, before);
}

// ---------------------------------------------------------------------------------------
// References written here.

/// Seed 002's brute force, literally: "is the current point's colour the seed point's
/// colour? no -> stop; yes -> recolour it and restart for every neighbour". Recursion as
/// deep as the region is long: small images only (<= 24x24, at most 576 frames).
fn seed002_recursive(img: &mut RgbaImage, x: i64, y: i64, old: Rgba<u8>, new: Rgba<u8>, eight: bool) {
    assert_ne!(old, new, "recolouring with the same colour would never stop");
    let (Ok(ux), Ok(uy)) = (u32::try_from(x), u32::try_from(y)) else {
        return;
    };
    if ux >= img.width() || uy >= img.height() || *img.get_pixel(ux, uy) != old {
        return;
    }
    img.put_pixel(ux, uy, new);
    let four = [(0, -1), (0, 1), (-1, 0), (1, 0)];
    let corners = [(-1, -1), (1, -1), (-1, 1), (1, 1)];
    let all: Vec<(i64, i64)> = if eight {
        four.iter().chain(&corners).copied().collect()
    } else {
        four.to_vec()
    };
    for (dx, dy) in all {
        seed002_recursive(img, x + dx, y + dy, old, new, eight);
    }
}

/// The region as the pixels seed 002's recursion recolours with [`MARK`] (never in the
/// generated images, so it differs from the seed's colour).
fn recursive_region(img: &RgbaImage, seed: (u32, u32), c: Connectivity) -> Region {
    assert!(img.width() <= 24 && img.height() <= 24, "recursion depth");
    let old = *img.get_pixel(seed.0, seed.1);
    assert!(img.pixels().all(|p| *p != MARK));
    let mut painted = img.clone();
    seed002_recursive(&mut painted, seed.0.into(), seed.1.into(), old, MARK, c == Eight);
    Region::from_fn(img.width(), img.height(), |x, y| {
        painted.get_pixel(x, y) != img.get_pixel(x, y)
    })
}

/// Union-find over every pixel: join each pixel with its right and lower neighbour (and,
/// for eight, its two lower diagonal neighbours) when the colours are equal; the region
/// is the seed's set. No queue, no spans: an independent definition of the component.
fn union_find_region(img: &RgbaImage, seed: (u32, u32), c: Connectivity) -> Region {
    let (w, h) = (img.width() as usize, img.height() as usize);
    let mut parent: Vec<usize> = (0..w * h).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let colour = |x: usize, y: usize| img.get_pixel(u32::try_from(x).unwrap(), u32::try_from(y).unwrap());
    let mut join = |a: (usize, usize), b: (usize, usize)| {
        if colour(a.0, a.1) == colour(b.0, b.1) {
            let (ra, rb) = (root(&mut parent, a.1 * w + a.0), root(&mut parent, b.1 * w + b.0));
            parent[ra] = rb;
        }
    };
    for y in 0..h {
        for x in 0..w {
            if x + 1 < w {
                join((x, y), (x + 1, y));
            }
            if y + 1 < h {
                join((x, y), (x, y + 1));
                if c == Eight && x + 1 < w {
                    join((x, y), (x + 1, y + 1));
                }
                if c == Eight && x > 0 {
                    join((x, y), (x - 1, y + 1));
                }
            }
        }
    }
    let target = root(&mut parent, seed.1 as usize * w + seed.0 as usize);
    Region::from_fn(img.width(), img.height(), |x, y| {
        root(&mut parent, y as usize * w + x as usize) == target
    })
}

// ---------------------------------------------------------------------------------------
// Strategies.

/// Noise over 2 or 3 colours (A, B, and A2 which differs from A only in alpha).
fn noise_image(max_side: u32) -> impl Strategy<Value = RgbaImage> {
    (1..=max_side, 1..=max_side, 2usize..=3).prop_flat_map(|(w, h, colours)| {
        proptest::collection::vec(0..colours, (w * h) as usize).prop_map(move |indices| {
            let palette = [A, B, A2];
            RgbaImage::from_fn(w, h, |x, y| palette[indices[(y * w + x) as usize]])
        })
    })
}

/// A random maze (depth-first carving) with up to 12 extra openings (loops).
fn maze_image(max_side: u32) -> impl Strategy<Value = RgbaImage> {
    (1..=max_side, 1..=max_side, 0usize..12, any::<u64>()).prop_map(|(w, h, openings, seed)| maze(w, h, openings, seed))
}

/// Up to 10 thin diagonal lines of B or A2 over A: where four and eight differ.
fn diagonal_image(max_side: u32) -> impl Strategy<Value = RgbaImage> {
    (1..=max_side, 1..=max_side).prop_flat_map(move |(w, h)| {
        let line = (0..w, 0..h, any::<bool>(), any::<bool>(), 1..=max_side, any::<bool>()).prop_map(
            |(x, y, right, down, len, b)| Diagonal {
                x,
                y,
                dx: if right { 1 } else { -1 },
                dy: if down { 1 } else { -1 },
                len,
                colour: if b { B } else { A2 },
            },
        );
        proptest::collection::vec(line, 0..10).prop_map(move |lines| diagonals(w, h, A, &lines))
    })
}

fn any_image(max_side: u32) -> impl Strategy<Value = RgbaImage> {
    prop_oneof![noise_image(max_side), maze_image(max_side), diagonal_image(max_side)]
}

fn pick(img: &RgbaImage, x: &Index, y: &Index) -> (u32, u32) {
    let pick = |i: &Index, n: u32| u32::try_from(i.index(n as usize)).unwrap();
    (pick(x, img.width()), pick(y, img.height()))
}

proptest! {
    #![proptest_config(config("proptest-regressions/flood.txt"))]

    /// The span fill equals the BFS oracle, four and eight, on every image family; the
    /// region holds the seed, is listed row-major, and `len` counts it.
    #[test]
    fn span_equals_bfs(img in any_image(48), x in any::<Index>(), y in any::<Index>()) {
        let seed = pick(&img, &x, &y);
        for c in Connectivity::ALL {
            let (s, b) = (span(&img, seed, c), bfs(&img, seed, c));
            prop_assert_eq!(&s, &b, "seed {:?} {}", seed, c);
            prop_assert!(s.contains(seed.0, seed.1));
            let pixels: Vec<(u32, u32)> = s.iter().collect();
            prop_assert_eq!(pixels.len(), s.len());
            prop_assert!(pixels.windows(2).all(|p| (p[0].1, p[0].0) < (p[1].1, p[1].0)));
        }
    }

    /// Every 4-connected region lies inside the 8-connected one of the same seed.
    #[test]
    fn four_is_inside_eight(img in any_image(48), x in any::<Index>(), y in any::<Index>()) {
        let seed = pick(&img, &x, &y);
        let (four, eight) = (span(&img, seed, Four), span(&img, seed, Eight));
        prop_assert!(four.is_subset_of(&eight), "four {:?}\neight {:?}", four, eight);
        prop_assert!(four.len() <= eight.len());
    }

    /// Seed 002's recursion (test-only, small images) and a union-find labelling agree
    /// with the oracle.
    #[test]
    fn oracle_equals_seed002_recursion_and_union_find(img in any_image(24), x in any::<Index>(), y in any::<Index>()) {
        let seed = pick(&img, &x, &y);
        for c in Connectivity::ALL {
            let oracle = bfs(&img, seed, c);
            prop_assert_eq!(&oracle, &recursive_region(&img, seed, c), "recursion, seed {:?} {}", seed, c);
            prop_assert_eq!(&oracle, &union_find_region(&img, seed, c), "union-find, seed {:?} {}", seed, c);
        }
    }

    /// `flood_fill` returns the region's size and recolours exactly the region; with the
    /// seed's own colour it changes nothing.
    #[test]
    fn flood_fill_recolours_exactly_the_region(img in any_image(32), x in any::<Index>(), y in any::<Index>(), eight in any::<bool>()) {
        let seed = pick(&img, &x, &y);
        let c = if eight { Eight } else { Four };
        let region = bfs(&img, seed, c);
        let mut painted = img.clone();
        prop_assert_eq!(flood_fill(&mut painted, seed, c, MARK).unwrap(), region.len());
        for (px, py, p) in painted.enumerate_pixels() {
            let want = if region.contains(px, py) { MARK } else { *img.get_pixel(px, py) };
            prop_assert_eq!(*p, want);
        }
        let mut same = img.clone();
        let own = *img.get_pixel(seed.0, seed.1);
        prop_assert_eq!(flood_fill(&mut same, seed, c, own).unwrap(), region.len());
        prop_assert_eq!(same, img);
    }
}

/// The passages of a maze without extra openings are one region of `2 * cells - 1`
/// pixels (a spanning tree of the cells: `cells` cell pixels, `cells - 1` opened walls),
/// four or eight; the generator in tests/common/raster.rs promises it, checked here
/// before the large tests rely on it.
#[test]
fn maze_passages_are_one_tree() {
    for (w, h, seed) in [(3, 3, 1), (9, 7, 2), (24, 24, 3), (41, 18, 4)] {
        let img = maze(w, h, 0, seed);
        let (cw, ch) = maze_cells(w, h);
        let cells = (cw * ch) as usize;
        let passages = img.pixels().filter(|p| **p == PASSAGE).count();
        assert_eq!(passages, 2 * cells - 1);
        for c in Connectivity::ALL {
            assert_count(&img, (1, 1), c, 2 * cells - 1);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Sizes seed 002's recursion cannot reach: 16M pixels, on the default test thread stack.

const BIG: u32 = 4096;

/// One colour everywhere: the region is the whole image, from the middle and a corner.
#[test]
fn no_stack_overflow_on_one_4096_square_region() {
    let img = RgbaImage::from_pixel(BIG, BIG, A);
    for (seed, c) in [((BIG / 2, BIG / 2), Four), ((BIG - 1, 0), Eight)] {
        assert_eq!(span(&img, seed, c).len(), (BIG * BIG) as usize);
    }
    assert_eq!(bfs(&img, (0, BIG - 1), Four).len(), (BIG * BIG) as usize);
}

/// A 4096x4096 maze: 2047 x 2047 cells, so `2 * 2047^2 - 1 = 8_380_417` passage pixels
/// in one region (span and BFS agree, four and eight); the walls agree too.
#[test]
fn no_stack_overflow_on_a_4096_maze() {
    let img = maze(BIG, BIG, 0, 42);
    assert_eq!(maze_cells(BIG, BIG), (2047, 2047));
    for c in Connectivity::ALL {
        let s = span(&img, (1, 1), c);
        assert_eq!(s.len(), 8_380_417);
        assert_eq!(s, bfs(&img, (1, 1), c), "{c}");
    }
    assert_eq!(*img.get_pixel(0, 0), WALL);
    assert_eq!(span(&img, (0, 0), Four), bfs(&img, (0, 0), Four));
}

/// A 4096x4096 checkerboard: four-connected every square is alone; eight-connected each
/// colour is one region of half the pixels, every run one pixel long (the span stack's
/// worst case).
#[test]
fn checkerboard_4096_is_two_diagonal_regions() {
    let img = checkerboard(BIG, BIG, A, B);
    assert_eq!(span(&img, (7, 9), Four).len(), 1);
    let eight = span(&img, (7, 9), Eight);
    assert_eq!(eight.len(), (BIG * BIG / 2) as usize);
    assert!(eight.contains(0, 0) && !eight.contains(1, 0) && eight.contains(BIG - 1, BIG - 1));
}

/// Noise at 70% A: above the site-percolation threshold (0.593 for four), so one large
/// region spans the image; span equals BFS.
#[test]
fn large_noise_span_equals_bfs() {
    let img = noise(1024, 1024, &[A, B], &[7, 3], 9);
    let seed = img.enumerate_pixels().find(|p| *p.2 == A).map(|p| (p.0, p.1)).unwrap();
    for c in Connectivity::ALL {
        let s = span(&img, seed, c);
        assert_eq!(s, bfs(&img, seed, c), "{c}");
    }
}
