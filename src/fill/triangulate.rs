//! Polygon to triangles, on the snapped polygon: a fan for a convex polygon (Luebke),
//! spade's constrained Delaunay triangulation for a simple concave polygon or one with
//! holes. Self-intersecting input is refused with an error that names two edges that meet
//! (fill it with the scanline filler, [`crate::fill::polygon`], instead).
//!
//! Everything spade sees is validated first, exactly (i128 orientation tests): the
//! polygon must be simple — no two edges meet except consecutive edges at their shared
//! vertex, and those do not fold back onto each other — and every hole must lie inside
//! the outline and outside the other holes. spade never decides whether edges cross: it
//! only triangulates what the validation proved simple. Coordinates are integers below
//! 2^29 in magnitude, exact in f64 and well inside spade's coordinate limits. Which
//! triangles are kept is decided exactly too, not by spade's geometry.
//!
//! Nothing is quadratic in the vertices; there is no vertex cap beyond memory (a scene
//! holds at most `scene::parse::MAX_SCENE_VERTICES`):
//! - simplicity: one plane sweep over the vertices (Shamos and Hoey, "Geometric
//!   intersection problems", 1976, with Bentley and Ottmann's event order and vertical
//!   segments, 1979; in `fill/sweep.rs`): the edges the sweep line cuts are kept in an
//!   ordered set, ordered exactly, and only edges that become neighbours there are
//!   compared, O(n log n) for n vertices. Its verdict is the pairwise check's (every pair
//!   of edges, O(n²), kept in the tests as the reference and compared on random polygons
//!   full of touching, overlapping and folded edges); the two edges it names meet at the
//!   point it gives, found at the first vertex in (x, y) order where a problem shows,
//!   which is not always the pair the pairwise check named first;
//! - hole placement: the same sweep finds which contour directly encloses each contour
//!   (the edge just below a contour's first vertex), which names the same misplaced hole,
//!   and the same hole around it, as testing a vertex of each hole against every other
//!   contour did;
//! - the triangles kept: the triangulation's faces are walked from the outside across
//!   their edges, and a face is inside when it lies across an odd number of the polygon's
//!   edges from the outside (inside the outline and outside every hole), O(n); this keeps
//!   exactly the triangles whose centroid has a non-zero winding number about the outline
//!   and zero about every hole (the reference in the tests).

use std::cmp::Ordering;
use std::fmt;

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use crate::fill::sweep::{orient, sweep, Meeting};
use crate::geom::{FixedPolygon, FixedTriangle};
use crate::num::exact::{dyadic, exact_text};
use crate::num::SubPixel;

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
    let contours = prepare(poly);
    if contours.is_empty() {
        return Ok(contours);
    }
    let slices: Vec<&[[i64; 2]]> = contours.iter().map(|c| c.points.as_slice()).collect();
    let nesting = sweep(&slices).map_err(|m| not_simple(&contours, m, poly.bits))?;
    check_holes(&contours, &nesting)?;
    Ok(contours)
}

/// The contours that have area, repeated consecutive vertices merged (and a last vertex
/// equal to the first dropped); none when the outline has no area.
fn prepare(poly: &FixedPolygon) -> Vec<Contour> {
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
        contours.clear();
    }
    contours
}

/// The error for two edges that meet, the sweep's contour positions turned into indices.
fn not_simple(contours: &[Contour], m: Meeting, bits: u32) -> TriangulateError {
    let edge = |(c, edge): (usize, usize)| EdgeRef {
        contour: contours[c].index,
        edge,
    };
    TriangulateError::NotSimple {
        first: edge(m.first),
        second: edge(m.second),
        at: m.at,
        bits,
    }
}

/// Every hole inside the outline and outside the other holes, given each contour with the
/// contour directly enclosing it, enclosers first (the sweep's answer; no two edges
/// meet). A contour lies inside another exactly when that one encloses it, directly or
/// not, so this names the same hole and the same other hole as testing one vertex of
/// each hole against every other contour in order: the first misplaced hole, and the
/// first hole enclosing it. O(contours).
fn check_holes(contours: &[Contour], nesting: &[(usize, Option<usize>)]) -> Result<(), TriangulateError> {
    // Per contour (by position): whether the outline (position 0) encloses it, and the
    // first hole that does.
    let mut in_outline = vec![false; contours.len()];
    let mut first_hole: Vec<Option<usize>> = vec![None; contours.len()];
    for &(c, parent) in nesting {
        if let Some(p) = parent {
            in_outline[c] = p == 0 || in_outline[p];
            let hole = (p != 0).then_some(p);
            first_hole[c] = match (hole, first_hole[p]) {
                (Some(a), Some(b)) => Some(a.min(b)),
                (a, b) => a.or(b),
            };
        }
    }
    for (k, hole) in contours.iter().enumerate().skip(1) {
        if !in_outline[k] {
            return Err(TriangulateError::HoleOutside { hole: hole.index - 1 });
        }
        if let Some(other) = first_hole[k] {
            return Err(TriangulateError::HoleInHole {
                hole: hole.index - 1,
                other: contours[other].index - 1,
            });
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

/// spade's CDT of validated contours, and the grid point of each of its vertices (by
/// vertex index).
type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

fn build_cdt(contours: &[Contour]) -> Result<(Cdt, Vec<[i64; 2]>), TriangulateError> {
    #[allow(clippy::cast_precision_loss)] // |v| <= 2^29: exact in f64
    let to_f64 = |v: i64| v as f64;
    let mut cdt = Cdt::new();
    let mut position = Vec::new();
    for c in contours {
        let mut handles = Vec::with_capacity(c.points.len());
        for p in &c.points {
            let h = cdt
                .insert(Point2::new(to_f64(p[0]), to_f64(p[1])))
                .map_err(|e| TriangulateError::Spade(format!("{e:?}")))?;
            if h.index() != position.len() {
                // Validated vertices are distinct: each insertion is a new vertex.
                return Err(TriangulateError::Spade(format!("vertex {p:?} merged with another")));
            }
            position.push(*p);
            handles.push(h);
        }
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
    Ok((cdt, position))
}

/// spade's CDT of the validated contours, keeping the triangles inside the outline and
/// outside every hole.
fn constrained_delaunay(contours: &[Contour]) -> Result<Vec<[[i64; 2]; 3]>, TriangulateError> {
    let (cdt, position) = build_cdt(contours)?;
    let inside = inside_faces(&cdt);
    Ok(cdt
        .inner_faces()
        .filter(|f| inside[f.fix().index()])
        .map(|f| f.vertices().map(|h| position[h.fix().index()]))
        .collect())
}

/// Which faces of the CDT (by face index) lie inside the polygon: the faces are walked
/// from the outer face across their edges, and a face is inside when an odd number of
/// constraint edges (the polygon's edges) separate it from the outer face. The contours
/// are simple, disjoint closed curves with every hole inside the outline and outside the
/// other holes, so an odd count is exactly inside the outline and outside every hole (the
/// count does not depend on the path). Linear in the faces.
fn inside_faces(cdt: &Cdt) -> Vec<bool> {
    let mut inside: Vec<Option<bool>> = vec![None; cdt.num_all_faces()];
    let mut stack = Vec::new();
    for e in cdt.convex_hull() {
        let e = if e.face().is_outer() { e.rev() } else { e };
        if let Some(face) = e.face().as_inner() {
            let slot = &mut inside[face.fix().index()];
            if slot.is_none() {
                *slot = Some(e.is_constraint_edge());
                stack.push(face);
            }
        }
    }
    while let Some(face) = stack.pop() {
        let here = inside[face.fix().index()] == Some(true);
        for e in face.adjacent_edges() {
            if let Some(next) = e.rev().face().as_inner() {
                let slot = &mut inside[next.fix().index()];
                if slot.is_none() {
                    *slot = Some(here != e.is_constraint_edge());
                    stack.push(next);
                }
            }
        }
    }
    inside.into_iter().map(|k| k == Some(true)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edge::fixed::edge_function_wide;
    use crate::fill::sweep::pair_problem;
    use crate::geom::FillRule;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, FileFailurePersistence};

    /// The pairwise check the sweep replaced: every pair of edges, in order, the first pair
    /// that meets (the reference for the sweep's verdict). The test of one pair is the
    /// sweep's own, [`pair_problem`]; what is compared is which pairs are tried.
    fn check_simple_pairwise(contours: &[Contour], bits: u32) -> Result<(), TriangulateError> {
        let slices: Vec<&[[i64; 2]]> = contours.iter().map(|c| c.points.as_slice()).collect();
        let edges: Vec<(usize, usize)> = slices
            .iter()
            .enumerate()
            .flat_map(|(k, c)| (0..c.len()).map(move |i| (k, i)))
            .collect();
        for (x, &ea) in edges.iter().enumerate() {
            for &eb in &edges[x + 1..] {
                if let Some(at) = pair_problem(&slices, ea, eb) {
                    let edge = |(k, i): (usize, usize)| EdgeRef {
                        contour: contours[k].index,
                        edge: i,
                    };
                    return Err(TriangulateError::NotSimple {
                        first: edge(ea),
                        second: edge(eb),
                        at,
                        bits,
                    });
                }
            }
        }
        Ok(())
    }

    /// The winding number of `p` (scaled by `scale`: the contour's coordinates are
    /// multiplied by it) around a contour, for a point on none of its edges; half-open
    /// crossing rule.
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

    /// The hole placement the nesting replaced, as it was: one vertex per hole against
    /// the outline and every other hole (the reference).
    fn check_holes_winding(contours: &[Contour]) -> Result<(), TriangulateError> {
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

    /// The faces the centroid's winding number keeps, as it was (the reference for
    /// [`inside_faces`]): 3 x the centroid against the contours scaled by 3, exact and
    /// never on an edge (the polygon's edges are edges of the triangulation).
    fn inside_by_winding(cdt: &Cdt, position: &[[i64; 2]], contours: &[Contour]) -> Vec<bool> {
        let mut inside = vec![false; cdt.num_all_faces()];
        for face in cdt.inner_faces() {
            let v = face.vertices().map(|h| position[h.fix().index()]);
            let c3 = [0, 1].map(|k| v.iter().map(|p| i128::from(p[k])).sum::<i128>());
            inside[face.fix().index()] = winding(c3, &contours[0].points, 3) != 0
                && contours[1..].iter().all(|h| winding(c3, &h.points, 3) == 0);
        }
        inside
    }

    fn config(min_cases: u32) -> Config {
        let default = Config::default();
        Config {
            cases: default.cases.max(min_cases),
            failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
                "proptest-regressions/triangulate.txt",
            ))),
            ..default
        }
    }

    /// Points sorted by angle around `centre` (exactly: half-plane, then cross product,
    /// then distance): a star-shaped contour, often simple, on a small grid often
    /// degenerate (collinear with the centre, repeated points).
    fn star(centre: [i64; 2], mut points: Vec<[i64; 2]>) -> Vec<[i64; 2]> {
        let d = |p: [i64; 2]| [p[0] - centre[0], p[1] - centre[1]];
        let half = |v: [i64; 2]| v[1] < 0 || (v[1] == 0 && v[0] < 0);
        points.sort_by(|&p, &q| {
            let (u, v) = (d(p), d(q));
            half(u)
                .cmp(&half(v))
                .then_with(|| 0.cmp(&(i128::from(u[0]) * i128::from(v[1]) - i128::from(u[1]) * i128::from(v[0]))))
                .then_with(|| (u[0] * u[0] + u[1] * u[1]).cmp(&(v[0] * v[0] + v[1] * v[1])))
        });
        points
    }

    /// A contour in the box `origin + [0, size]^2` of the grid: random points in random
    /// order (usually tangled), or sorted around a point of the box (usually simple or
    /// nearly), sometimes reversed.
    fn contour(origin: [i64; 2], size: i64, max: usize) -> BoxedStrategy<Vec<[i64; 2]>> {
        let at = move |p: [i64; 2]| [origin[0] + p[0], origin[1] + p[1]];
        let points = prop::collection::vec(prop::array::uniform2(0..=size), 3..=max)
            .prop_map(move |p| p.into_iter().map(at).collect::<Vec<_>>());
        prop_oneof![
            1 => points.clone(),
            3 => (points, prop::array::uniform2(0..=size), any::<bool>()).prop_map(move |(p, c, rev)| {
                let mut s = star(at(c), p);
                if rev {
                    s.reverse();
                }
                s
            }),
        ]
        .boxed()
    }

    /// The square `[lo, hi]^2` with 0 to 8 more vertices on its sides.
    fn framed_square(lo: i64, hi: i64) -> impl Strategy<Value = Vec<[i64; 2]>> {
        let on_side = (0..4usize, lo..=hi).prop_map(move |(k, t)| match k {
            0 => [t, lo],
            1 => [hi, t],
            2 => [t, hi],
            _ => [lo, t],
        });
        prop::collection::vec(on_side, 0..=8).prop_map(move |mut p| {
            p.extend([[lo, lo], [hi, lo], [hi, hi], [lo, hi]]);
            star([(lo + hi) / 2, (lo + hi) / 2], p)
        })
    }

    /// A hole: a contour of 3 to `max` vertices in a box of side 1 to `side / 2` anywhere
    /// on the grid `0..=side`.
    fn hole(side: i64, max: usize) -> BoxedStrategy<Vec<[i64; 2]>> {
        (prop::array::uniform2(0..=side), 1..=(side / 2).max(1))
            .prop_flat_map(move |(origin, size)| contour(origin, size, max))
            .boxed()
    }

    /// Polygons on small grids (coordinates 0..=6, or 0..=3 where almost everything
    /// touches, or 0..=12), up to 4 contours of 3 to 20 vertices: an outline over the grid
    /// (tangled or star-shaped) with 0 to 3 holes, or the grid's square (with extra
    /// vertices on its sides) with 1 to 3 holes, the holes in smaller boxes anywhere on
    /// the grid (inside, across the outline, in or around each other), or squares and
    /// stars in nested boxes; and, a quarter of the time, up to 80 vertices on 0..=24 with
    /// up to 5 holes. Touching edges, collinear overlaps, vertices on edges, vertical
    /// edges, folds, repeated vertices, holes touching the outline or each other, all the
    /// time.
    fn small_grid_polygon() -> impl Strategy<Value = FixedPolygon> {
        let tangled = prop_oneof![Just(3i64), Just(6i64), Just(6i64), Just(12i64)]
            .prop_flat_map(|side| (contour([0, 0], side, 20), prop::collection::vec(hole(side, 8), 0..=3)));
        let framed = prop_oneof![Just(6i64), Just(12i64)]
            .prop_flat_map(|side| (framed_square(0, side), prop::collection::vec(hole(side, 6), 1..=3)));
        // Squares (or stars) in boxes of random margins, in random order: nested, equal
        // (touching), shifted (crossing); the outline need not be the largest.
        let nested = prop::collection::vec((0i64..=5, -1i64..=1, any::<bool>()), 2..=4)
            .prop_flat_map(|boxes| {
                boxes
                    .into_iter()
                    .map(|(m, shift, plain)| {
                        let (lo, hi) = (m + shift, 12 - m + shift);
                        if plain {
                            framed_square(lo, hi).boxed()
                        } else {
                            contour([lo, lo], hi - lo, 12)
                        }
                    })
                    .collect::<Vec<_>>()
            })
            .prop_map(|mut contours| {
                let holes = contours.split_off(1);
                (contours.remove(0), holes)
            });
        // Larger: up to 80 vertices on 0..=24 and 5 holes, many edges active at once.
        let large = (contour([0, 0], 24, 80), prop::collection::vec(hole(24, 12), 0..=5));
        prop_oneof![tangled, framed, nested, large].prop_map(|(outline, holes)| {
            let mut contours = vec![outline];
            contours.extend(holes);
            FixedPolygon::new(contours, FillRule::NonZero, 4).unwrap()
        })
    }

    proptest! {
        #![proptest_config(config(4096))]

        /// The sweep gives the pairwise check's verdict on every polygon: simple or not,
        /// and when not, names two edges (first before second) that do meet at the point
        /// it gives; on simple polygons the nesting places the holes exactly as the
        /// winding test of one vertex per hole did (same error, same hole, same other).
        #[test]
        fn sweep_agrees_with_the_pairwise_check(poly in small_grid_polygon()) {
            let contours = prepare(&poly);
            if contours.is_empty() {
                return Ok(()); // the outline has no area: nothing to check
            }
            let reference = check_simple_pairwise(&contours, poly.bits);
            let slices: Vec<&[[i64; 2]]> = contours.iter().map(|c| c.points.as_slice()).collect();
            match (sweep(&slices), &reference) {
                (Ok(nesting), Ok(())) => {
                    prop_assert_eq!(nesting.len(), contours.len());
                    prop_assert_eq!(check_holes(&contours, &nesting), check_holes_winding(&contours));
                }
                (Err(m), Err(_)) => {
                    prop_assert!(m.first < m.second, "{:?}", m);
                    prop_assert_eq!(pair_problem(&slices, m.first, m.second), Some(m.at));
                }
                (sweep, reference) => prop_assert!(false, "sweep {:?}, pairwise {:?}", sweep, reference),
            }
            // The same polygon scaled by 2^25 and moved to reach -2^28 (within the envelope
            // |v| <= 2^29): the same verdict and the same pair, exactly.
            let far: Vec<Vec<[i64; 2]>> = contours
                .iter()
                .map(|c| c.points.iter().map(|p| p.map(|v| v * (1 << 25) - (1 << 28))).collect())
                .collect();
            let far_slices: Vec<&[[i64; 2]]> = far.iter().map(Vec::as_slice).collect();
            let (near, far) = (sweep(&slices), sweep(&far_slices));
            prop_assert_eq!(near.as_ref().err().map(|m| (m.first, m.second)), far.as_ref().err().map(|m| (m.first, m.second)));
            prop_assert_eq!(near.ok(), far.ok());
        }
    }

    /// The vertices of a star-shaped contour about the origin, before sorting: 3..=`max`
    /// points at Chebyshev distance `inner..=outer` from it (0 and the direction's own
    /// length allowed when `inner` is 0).
    fn star_points(max: usize, inner: i64, outer: i64) -> impl Strategy<Value = Vec<[i64; 2]>> {
        let point = (prop::array::uniform2(-outer..=outer), inner..=outer).prop_map(move |(d, r)| {
            let len = d[0].abs().max(d[1].abs());
            if len == 0 || inner == 0 {
                d
            } else {
                d.map(|v| v * r / len)
            }
        });
        prop::collection::vec(point, 3..=max)
    }

    proptest! {
        #![proptest_config(config(1024))]

        /// On valid polygons with holes (a star-shaped outline, often concave, and as many
        /// small star-shaped holes near its centre as fit), the faces kept by counting constraint
        /// crossings from the outside are exactly those whose centroid the winding test
        /// keeps.
        #[test]
        fn crossing_parity_keeps_the_faces_the_winding_test_keeps(
            centre in prop::array::uniform2(20i64..=28),
            outline in star_points(24, 12, 20),
            holes in prop::collection::vec((prop::array::uniform2(-10i64..=10), star_points(8, 0, 4)), 0..=8),
        ) {
            let shift = |c: [i64; 2], p: Vec<[i64; 2]>| p.into_iter().map(|q| [c[0] + q[0], c[1] + q[1]]).collect();
            let mut contours = vec![star(centre, shift(centre, outline))];
            for (c, h) in holes {
                let c = [centre[0] + c[0], centre[1] + c[1]];
                contours.push(star(c, shift(c, h)));
                let poly = FixedPolygon::new(contours.clone(), FillRule::NonZero, 4).unwrap();
                let prepared = prepare(&poly);
                let valid = prepared.len() == contours.len()
                    && check_simple_pairwise(&prepared, 4).is_ok()
                    && check_holes_winding(&prepared).is_ok();
                if !valid {
                    contours.pop();
                }
            }
            let poly = FixedPolygon::new(contours, FillRule::NonZero, 4).unwrap();
            let prepared = prepare(&poly);
            if prepared.is_empty() || check_simple_pairwise(&prepared, 4).is_err() {
                return Ok(()); // the outline folded on the grid
            }
            prop_assert!(validate(&poly).is_ok());
            let (cdt, position) = build_cdt(&prepared).unwrap();
            prop_assert_eq!(inside_faces(&cdt), inside_by_winding(&cdt, &position, &prepared));
        }
    }

    fn poly(contours: Vec<Vec<[i64; 2]>>) -> FixedPolygon {
        FixedPolygon::new(contours, FillRule::NonZero, 8).unwrap()
    }

    /// What the sweep names on the classic cases: a pair that meets, found at the first
    /// event where a problem shows; on the bow tie and the spike the pair the pairwise
    /// check named, on the figure eight and the vertex on an edge another (edges 0 and 4,
    /// or 0 and 3, converge on the point they share and become neighbours in the sweep at
    /// (0, 8), before the sweep reaches the edge the pairwise check named).
    #[test]
    fn the_sweep_names_a_meeting_pair() {
        let e = |edge: usize| EdgeRef { contour: 0, edge };
        let h = |edge: usize| EdgeRef { contour: 1, edge };
        let cases = [
            (vec![vec![[0, 0], [8, 8], [8, 0], [0, 8]]], (e(0), e(2), [4, 4])),
            (
                vec![vec![[0, 0], [4, 4], [8, 0], [8, 8], [4, 4], [0, 8]]],
                (e(0), e(4), [4, 4]),
            ),
            (vec![vec![[0, 0], [8, 0], [4, 0], [4, 8]]], (e(0), e(1), [8, 0])),
            (vec![vec![[0, 0], [8, 0], [8, 8], [4, 0], [0, 8]]], (e(0), e(3), [4, 0])),
            (
                vec![
                    vec![[0, 0], [100, 0], [100, 100], [0, 100]],
                    vec![[90, 50], [120, 50], [90, 80]],
                ],
                (e(1), h(0), [100, 50]),
            ),
        ];
        for (c, (first, second, at)) in cases {
            let p = poly(c);
            assert_eq!(
                validate(&p),
                Err(TriangulateError::NotSimple {
                    first,
                    second,
                    at,
                    bits: 8
                }),
                "{p:?}"
            );
            assert!(check_simple_pairwise(&prepare(&p), 8).is_err());
        }
    }

    /// Holes nested and misplaced: the same error as the winding test of one vertex per
    /// hole, in order.
    #[test]
    fn holes_are_placed_as_the_winding_test_placed_them() {
        let square = |a: i64, b: i64| vec![[a, a], [b, a], [b, b], [a, b]];
        let cases = [
            (
                vec![square(0, 100), square(200, 210)],
                TriangulateError::HoleOutside { hole: 0 },
            ),
            (
                vec![square(0, 100), square(10, 60), square(20, 30)],
                TriangulateError::HoleInHole { hole: 1, other: 0 },
            ),
            (
                vec![square(0, 100), square(20, 30), square(10, 60)],
                TriangulateError::HoleInHole { hole: 0, other: 1 },
            ),
            // The outline inside a hole: that hole is outside the outline, and a hole
            // inside the outline is inside that hole too.
            (
                vec![square(10, 60), square(0, 100), square(20, 30)],
                TriangulateError::HoleOutside { hole: 0 },
            ),
            (
                vec![square(10, 60), square(20, 30), square(0, 100)],
                TriangulateError::HoleInHole { hole: 0, other: 1 },
            ),
            // Three deep: the innermost is named with the first hole enclosing it.
            (
                vec![square(0, 100), square(40, 50), square(20, 70), square(10, 80)],
                TriangulateError::HoleInHole { hole: 0, other: 1 },
            ),
        ];
        for (c, expected) in cases {
            let p = poly(c);
            assert_eq!(validate(&p), Err(expected.clone()), "{p:?}");
            assert_eq!(check_holes_winding(&prepare(&p)), Err(expected));
        }
    }
}
