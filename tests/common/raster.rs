//! Raster images for the flood-fill tests and benches: random mazes (depth-first carving),
//! noise and thin diagonal lines. Deterministic from a seed (xorshift64* of rng.rs).
//!
//! Include it next to rng.rs, as the benches do:
//! `#[path = "../tests/common/rng.rs"] mod rng;` and
//! `#[path = "../tests/common/raster.rs"] mod raster;` (it uses `crate::rng::Rng`).

#![allow(dead_code)]

use image::{Rgba, RgbaImage};

use crate::rng::Rng;

/// Maze walls.
pub const WALL: Rgba<u8> = Rgba([0, 0, 0, 255]);
/// Maze passages.
pub const PASSAGE: Rgba<u8> = Rgba([255, 255, 255, 255]);

/// A `width` x `height` maze: cells at odd coordinates `(2i + 1, 2j + 1)` for every cell
/// that fits with a wall after it, carved by a randomized depth-first search (explicit
/// stack) into a spanning tree, so the passages are one 4-connected region of
/// `2 * cells - 1` pixels; then `openings` random interior walls between two cells are
/// knocked out, which adds loops. Everything else is wall, a full border included.
pub fn maze(width: u32, height: u32, openings: usize, seed: u64) -> RgbaImage {
    let mut img = RgbaImage::from_pixel(width, height, WALL);
    let (cw, ch) = maze_cells(width, height);
    if cw == 0 || ch == 0 {
        return img;
    }
    let mut rng = Rng(seed | 1);
    let pixel = |c: u32| 2 * c + 1;
    let mut visited = vec![false; cw as usize * ch as usize];
    let start = (0u32, 0u32);
    visited[0] = true;
    img.put_pixel(pixel(0), pixel(0), PASSAGE);
    let mut stack = vec![start];
    while let Some(&(cx, cy)) = stack.last() {
        let mut next = Vec::with_capacity(4);
        for (dx, dy) in [(0i64, -1i64), (0, 1), (-1, 0), (1, 0)] {
            let (nx, ny) = (i64::from(cx) + dx, i64::from(cy) + dy);
            if nx < 0 || ny < 0 || nx >= i64::from(cw) || ny >= i64::from(ch) {
                continue;
            }
            let (nx, ny) = (u32::try_from(nx).unwrap(), u32::try_from(ny).unwrap());
            if !visited[ny as usize * cw as usize + nx as usize] {
                next.push((nx, ny));
            }
        }
        if next.is_empty() {
            stack.pop();
            continue;
        }
        let (nx, ny) = next[usize::try_from(rng.below(next.len() as i64)).unwrap()];
        visited[ny as usize * cw as usize + nx as usize] = true;
        // The wall between the two cells, then the new cell.
        img.put_pixel(cx + nx + 1, cy + ny + 1, PASSAGE);
        img.put_pixel(pixel(nx), pixel(ny), PASSAGE);
        stack.push((nx, ny));
    }
    for _ in 0..openings {
        // A wall pixel between two cells: (odd, even) or (even, odd), inside the border.
        let (x, y) = (rng.range(1, i64::from(2 * cw - 1)), rng.range(1, i64::from(2 * ch - 1)));
        if (x + y) % 2 == 1 {
            img.put_pixel(u32::try_from(x).unwrap(), u32::try_from(y).unwrap(), PASSAGE);
        }
    }
    img
}

/// The number of maze cells across and down a `width` x `height` image.
pub fn maze_cells(width: u32, height: u32) -> (u32, u32) {
    (width.saturating_sub(1) / 2, height.saturating_sub(1) / 2)
}

/// Noise: each pixel `palette[k]` with probability `weights[k] / sum(weights)`.
pub fn noise(width: u32, height: u32, palette: &[Rgba<u8>], weights: &[i64], seed: u64) -> RgbaImage {
    let mut rng = Rng(seed | 1);
    let total: i64 = weights.iter().sum();
    RgbaImage::from_fn(width, height, |_, _| {
        let mut r = rng.below(total);
        for (colour, w) in palette.iter().zip(weights) {
            if r < *w {
                return *colour;
            }
            r -= w;
        }
        unreachable!("weights sum to total")
    })
}

/// A checkerboard: `a` where `x + y` is even, `b` elsewhere.
pub fn checkerboard(width: u32, height: u32, a: Rgba<u8>, b: Rgba<u8>) -> RgbaImage {
    RgbaImage::from_fn(width, height, |x, y| if (x + y) % 2 == 0 { a } else { b })
}

/// One diagonal line: from `(x, y)`, `len` pixels in direction `(dx, dy)` (each ±1),
/// clipped to the image.
#[derive(Debug, Clone, Copy)]
pub struct Diagonal {
    pub x: u32,
    pub y: u32,
    pub dx: i64,
    pub dy: i64,
    pub len: u32,
    pub colour: Rgba<u8>,
}

/// `background` with the diagonals drawn over it in order.
pub fn diagonals(width: u32, height: u32, background: Rgba<u8>, lines: &[Diagonal]) -> RgbaImage {
    let mut img = RgbaImage::from_pixel(width, height, background);
    for line in lines {
        let (mut x, mut y) = (i64::from(line.x), i64::from(line.y));
        for _ in 0..line.len {
            match (u32::try_from(x), u32::try_from(y)) {
                (Ok(px), Ok(py)) if px < width && py < height => img.put_pixel(px, py, line.colour),
                _ => break,
            }
            x += line.dx;
            y += line.dy;
        }
    }
    img
}

/// An image from rows of characters, one colour per character (`key` maps it).
pub fn from_ascii(rows: &[&str], key: impl Fn(char) -> Rgba<u8>) -> RgbaImage {
    let height = u32::try_from(rows.len()).unwrap();
    let width = u32::try_from(rows[0].chars().count()).unwrap();
    assert!(
        rows.iter().all(|r| r.chars().count() == width as usize),
        "ragged picture"
    );
    RgbaImage::from_fn(width, height, |x, y| {
        key(rows[y as usize].chars().nth(x as usize).unwrap())
    })
}
