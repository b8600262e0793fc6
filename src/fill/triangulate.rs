//! Polygon to triangles, on the snapped polygon: a fan for a convex polygon (Luebke),
//! spade's constrained Delaunay triangulation for a simple concave polygon or one with
//! holes. Self-intersecting input is refused with an error that names the two edges
//! (fill it with the scanline filler, [`crate::fill::polygon`], instead).
//!
//! Everything spade sees is validated first, exactly (i128 orientation tests): the
//! polygon must be simple — no two edges meet except consecutive edges at their shared
//! vertex, and those do not fold back onto each other — and every hole must lie inside
//! the outline and outside the other holes. Coordinates are integers below 2^29 in
//! magnitude, exact in f64 and well inside spade's coordinate limits. Which triangles are
//! kept is decided exactly too (the centroid's winding number), not by spade.
//!
//! The validation compares every pair of edges (O(n²)); polygons with more than
//! [`MAX_TRIANGULATE_VERTICES`] vertices are refused rather than left to run long.

use std::cmp::Ordering;
use std::fmt;

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use crate::edge::fixed::edge_function_wide;
use crate::geom::{FixedPolygon, FixedTriangle};
use crate::num::exact::{dyadic, exact_text};
use crate::num::SubPixel;

/// The most vertices (outline and holes together) [`triangulate`] accepts.
pub const MAX_TRIANGULATE_VERTICES: usize = 8192;

/// An edge of a polygon: contour 0 is the outline, contour `k` the hole `k - 1`; edge `i`
/// runs from vertex `i` to vertex `i + 1` (the last back to vertex 0), after repeated
/// consecutive vertices were merged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EdgeRef {
    /// The contour.
    pub contour: usize,
    /// The edge within it.
    pub edge: usize,
}

impl fmt::Display for EdgeRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.contour {
            0 => write!(f, "outline edge {}", self.edge),
            k => write!(f, "holes[{}] edge {}", k - 1, self.edge),
        }
    }
}

/// Why a polygon cannot be triangulated.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TriangulateError {
    /// More vertices than [`MAX_TRIANGULATE_VERTICES`].
    TooManyVertices {
        /// How many.
        vertices: usize,
    },
    /// Two edges cross, touch or overlap: the polygon is not simple.
    NotSimple {
        /// One edge.
        first: EdgeRef,
        /// The other.
        second: EdgeRef,
        /// A point they share, in subpixels (rounded towards minus infinity for a
        /// proper crossing).
        at: [i64; 2],
        /// The grid: 2^-bits pixel.
        bits: u32,
    },
    /// A hole outside the outline.
    HoleOutside {
        /// The hole's index.
        hole: usize,
    },
    /// A hole inside another hole.
    HoleInHole {
        /// The inner hole.
        hole: usize,
        /// The hole that contains it.
        other: usize,
    },
    /// spade refused an input that passed validation (a bug to report).
    Spade(String),
}

impl fmt::Display for TriangulateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TriangulateError::TooManyVertices { vertices } => write!(
                f,
                "{vertices} vertices, triangulation takes at most {MAX_TRIANGULATE_VERTICES} (fill it with the scanline model instead)"
            ),
            TriangulateError::NotSimple {
                first,
                second,
                at,
                bits,
            } => {
                let px = |v: i64| exact_text(&dyadic(&v.into(), *bits));
                write!(
                    f,
                    "not a simple polygon: {first} and {second} meet at ({}, {}) px (snapped); only the scanline filler takes self-intersecting polygons (model scanline, exact or exact-snapped)",
                    px(at[0]),
                    px(at[1])
                )
            }
            TriangulateError::HoleOutside { hole } => write!(f, "holes[{hole}] lies outside the outline"),
            TriangulateError::HoleInHole { hole, other } => {
                write!(f, "holes[{hole}] lies inside holes[{other}]")
            }
            TriangulateError::Spade(msg) => write!(f, "spade refused the polygon: {msg}"),
        }
    }
}

impl std::error::Error for TriangulateError {}

/// Triangles whose coverage is exactly the polygon's fill: a fan when the polygon is
/// convex without holes, otherwise spade's constrained Delaunay triangulation with the
/// triangles outside the outline or inside a hole dropped. Zero-area contours (after
/// merging repeated vertices) cover nothing and are ignored.
///
/// ```
/// use rasterproof::fill::triangulate::triangulate;
/// use rasterproof::geom::{FillRule, FixedPolygon};
/// // A 4-vertex convex quad: a fan of 2 triangles. An L-shape (6 vertices): 4 triangles.
/// let quad = FixedPolygon::new(vec![vec![[0, 0], [8, 0], [8, 8], [0, 8]]], FillRule::NonZero, 8).unwrap();
/// assert_eq!(triangulate(&quad).unwrap().len(), 2);
/// let l = FixedPolygon::new(vec![vec![[0, 0], [6, 0], [6, 2], [2, 2], [2, 6], [0, 6]]], FillRule::NonZero, 8).unwrap();
/// assert_eq!(triangulate(&l).unwrap().len(), 4);
/// // A bow tie crosses itself.
/// let bow = FixedPolygon::new(vec![vec![[0, 0], [8, 8], [8, 0], [0, 8]]], FillRule::NonZero, 8).unwrap();
/// assert!(triangulate(&bow).unwrap_err().to_string().contains("not a simple polygon"));
/// ```
pub fn triangulate(poly: &FixedPolygon) -> Result<Vec<FixedTriangle>, TriangulateError> {
    let contours = validate_contours(poly)?;
    let Some(outline) = contours.first().filter(|c| c.index == 0) else {
        return Ok(Vec::new()); // the outline has no area: nothing to cover
    };
    let triangles = if contours.len() == 1 && is_convex(&outline.points) {
        fan(&outline.points)
    } else {
        constrained_delaunay(&contours)?
    };
    Ok(triangles
        .into_iter()
        .map(|t| FixedTriangle {
            v: t.map(|[x, y]| [x, y].map(|c| SubPixel::new(c).expect("polygon vertices are inside the envelope"))),
            bits: poly.bits,
        })
        .collect())
}

/// A contour kept for triangulation: its index (0 outline, k hole k-1) and its vertices
/// with repeated consecutive vertices merged.
#[derive(Debug, Clone)]
struct Contour {
    index: usize,
    points: Vec<[i64; 2]>,
}

/// Checks that `poly` is simple and its holes are properly placed (see the module docs);
/// a polygon whose outline has no area is empty (and then its holes do not matter).
///
/// # Errors
/// The first problem found.
pub fn validate(poly: &FixedPolygon) -> Result<(), TriangulateError> {
    validate_contours(poly).map(|_| ())
}

fn validate_contours(poly: &FixedPolygon) -> Result<Vec<Contour>, TriangulateError> {
    let vertices: usize = poly.contours().iter().map(Vec::len).sum();
    if vertices > MAX_TRIANGULATE_VERTICES {
        return Err(TriangulateError::TooManyVertices { vertices });
    }
    let mut contours = Vec::new();
    for (index, c) in poly.contours().iter().enumerate() {
        let mut points: Vec<[i64; 2]> = Vec::with_capacity(c.len());
        for &p in c {
            if points.last() != Some(&p) {
                points.push(p);
            }
        }
        while points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
        let collinear = points.len() < 3 || points.iter().all(|&p| orient(points[0], points[1], p) == 0);
        if collinear {
            // No area: covers nothing as an outline, removes nothing as a hole.
            continue;
        }
        contours.push(Contour { index, points });
    }
    if contours.first().is_some_and(|c| c.index != 0) {
        // The outline has no area: the polygon (outline minus holes) covers nothing.
        return Ok(Vec::new());
    }
    check_simple(&contours, poly.bits)?;
    check_holes(&contours)?;
    Ok(contours)
}

/// `orient(a, b, c)`: twice the signed area of (a, b, c), in i128 (exact: coordinates
/// are below 2^29, products below 2^61).
fn orient(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i128 {
    // E_{a b}(c) = (c - a) x (b - a) = -((b - a) x (c - a))
    -edge_function_wide(a.map(i128::from), b.map(i128::from), c.map(i128::from))
}

/// Whether `p`, known to be collinear with segment `a b`, lies on it (closed).
fn on_segment(a: [i64; 2], b: [i64; 2], p: [i64; 2]) -> bool {
    (0..2).all(|k| a[k].min(b[k]) <= p[k] && p[k] <= a[k].max(b[k]))
}

/// A point the closed segments `a b` and `c d` share, if any (an endpoint when they touch
/// or overlap; for a proper crossing the rounded-down crossing point, for the message).
fn meet(a: [i64; 2], b: [i64; 2], c: [i64; 2], d: [i64; 2]) -> Option<[i64; 2]> {
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    for (o, p, s, t) in [(o1, c, a, b), (o2, d, a, b), (o3, a, c, d), (o4, b, c, d)] {
        if o == 0 && on_segment(s, t, p) {
            return Some(p);
        }
    }
    let proper = o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0;
    proper.then(|| {
        // a + t (b - a) with t = o3 / (o3 - o4), rounded down: for the message only.
        [0, 1].map(|k| {
            let v = i128::from(a[k]) + ((i128::from(b[k]) - i128::from(a[k])) * o3).div_euclid(o3 - o4);
            i64::try_from(v).expect("between two envelope coordinates")
        })
    })
}

/// No two edges meet, except consecutive edges of a contour at their shared vertex (and
/// those must not fold back along each other).
fn check_simple(contours: &[Contour], bits: u32) -> Result<(), TriangulateError> {
    let mut edges = Vec::new();
    for c in contours {
        let n = c.points.len();
        for i in 0..n {
            edges.push((
                EdgeRef {
                    contour: c.index,
                    edge: i,
                },
                c.points[i],
                c.points[(i + 1) % n],
                n,
            ));
        }
    }
    for (x, &(ea, a, b, n)) in edges.iter().enumerate() {
        for &(eb, c, d, _) in &edges[x + 1..] {
            let adjacent = ea.contour == eb.contour && (eb.edge == ea.edge + 1 || (ea.edge == 0 && eb.edge == n - 1));
            let problem = if adjacent {
                // They share one vertex v; the other ends must not lie on the same ray from it.
                let (v, p, q) = if b == c { (b, a, d) } else { (a, b, c) };
                let folds = orient(v, p, q) == 0 && {
                    let dot = (0..2)
                        .map(|k| (i128::from(p[k]) - i128::from(v[k])) * (i128::from(q[k]) - i128::from(v[k])))
                        .sum::<i128>();
                    dot > 0
                };
                folds.then_some(v)
            } else {
                meet(a, b, c, d)
            };
            if let Some(at) = problem {
                return Err(TriangulateError::NotSimple {
                    first: ea,
                    second: eb,
                    at,
                    bits,
                });
            }
        }
    }
    Ok(())
}

/// The winding number of `p` (scaled by `scale`: the contour's coordinates are multiplied
/// by it) around a contour, for a point on none of its edges; half-open crossing rule.
fn winding(p: [i128; 2], contour: &[[i64; 2]], scale: i128) -> i64 {
    let mut w = 0;
    let n = contour.len();
    for i in 0..n {
        let (a, b) = (contour[i], contour[(i + 1) % n]);
        let (a, b) = (a.map(|v| i128::from(v) * scale), b.map(|v| i128::from(v) * scale));
        let e = edge_function_wide(a, b, p);
        if a[1] <= p[1] && p[1] < b[1] && e < 0 {
            w += 1;
        } else if b[1] <= p[1] && p[1] < a[1] && e > 0 {
            w -= 1;
        }
    }
    w
}

/// Every hole inside the outline and outside the other holes. With no edges meeting, one
/// vertex per hole decides.
fn check_holes(contours: &[Contour]) -> Result<(), TriangulateError> {
    let Some(outline) = contours.first() else {
        return Ok(());
    };
    let wide = |p: [i64; 2]| p.map(i128::from);
    for hole in &contours[1..] {
        let p = wide(hole.points[0]);
        if winding(p, &outline.points, 1) == 0 {
            return Err(TriangulateError::HoleOutside { hole: hole.index - 1 });
        }
        for other in &contours[1..] {
            if other.index != hole.index && winding(p, &other.points, 1) != 0 {
                return Err(TriangulateError::HoleInHole {
                    hole: hole.index - 1,
                    other: other.index - 1,
                });
            }
        }
    }
    Ok(())
}

/// Every turn of a simple contour goes the same way (or straight on).
fn is_convex(points: &[[i64; 2]]) -> bool {
    let n = points.len();
    let turns: Vec<Ordering> = (0..n)
        .map(|i| orient(points[i], points[(i + 1) % n], points[(i + 2) % n]).cmp(&0))
        .collect();
    !(turns.contains(&Ordering::Less) && turns.contains(&Ordering::Greater))
}

/// The fan from vertex 0 (Luebke, "Drawing triangles"), without its zero-area triangles.
fn fan(points: &[[i64; 2]]) -> Vec<[[i64; 2]; 3]> {
    (1..points.len() - 1)
        .map(|i| [points[0], points[i], points[i + 1]])
        .filter(|&[a, b, c]| orient(a, b, c) != 0)
        .collect()
}

/// spade's CDT of the validated contours, keeping the triangles whose centroid is inside
/// the outline and outside every hole.
fn constrained_delaunay(contours: &[Contour]) -> Result<Vec<[[i64; 2]; 3]>, TriangulateError> {
    #[allow(clippy::cast_precision_loss)] // |v| <= 2^29: exact in f64
    let to_f64 = |v: i64| v as f64;
    let mut cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::new();
    for c in contours {
        let handles = c
            .points
            .iter()
            .map(|p| cdt.insert(Point2::new(to_f64(p[0]), to_f64(p[1]))))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| TriangulateError::Spade(format!("{e:?}")))?;
        for i in 0..handles.len() {
            let (a, b) = (handles[i], handles[(i + 1) % handles.len()]);
            if cdt.try_add_constraint(a, b).is_empty() {
                return Err(TriangulateError::Spade(format!(
                    "constraint {} not added",
                    EdgeRef {
                        contour: c.index,
                        edge: i
                    }
                )));
            }
        }
    }
    #[allow(clippy::cast_possible_truncation)] // positions came from i64 below 2^29
    let to_i64 = |v: f64| v as i64;
    let mut out = Vec::new();
    for face in cdt.inner_faces() {
        let v = face.vertices().map(|h| {
            let p = h.position();
            [to_i64(p.x), to_i64(p.y)]
        });
        // 3 x centroid, against the contours scaled by 3: exact, and never on an edge
        // (the polygon's edges are edges of the triangulation).
        let c3 = [0, 1].map(|k| v.iter().map(|p| i128::from(p[k])).sum::<i128>());
        let inside =
            winding(c3, &contours[0].points, 3) != 0 && contours[1..].iter().all(|h| winding(c3, &h.points, 3) == 0);
        if inside {
            out.push(v);
        }
    }
    Ok(out)
}
