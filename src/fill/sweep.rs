//! The exact predicates of polygon validation and one plane sweep that decides, in
//! O(n log n) for n edges, whether a polygon's contours are simple and how they nest.
//!
//! **Simplicity** is Shamos and Hoey's sweep ("Geometric intersection problems", FOCS
//! 1976), with the event order and the handling of vertical segments of Bentley and
//! Ottmann ("Algorithms for reporting and counting geometric intersections", 1979): the
//! events are the vertices, in lexicographic order (x, then y), so that a vertical edge
//! runs from its lower to its upper end as if the sweep line were tilted a little; the
//! active edges (those the sweep line cuts) sit in a [`BTreeSet`] ordered exactly along
//! the sweep line. At each event the sweep looks up the point among the active edges (an
//! edge through it that does not end there touches it), checks the two edges of the
//! event's vertex against each other (they may fold back), removes the edges that end
//! there, inserts those that start there, and checks each newly adjacent pair of active
//! edges. Two edges that meet, where the first such meeting lies, are adjacent in the
//! sweep order just before it (any edge between them would meet one of them earlier), so
//! the sweep finds a meeting pair whenever one exists, and the first event with one stops
//! it: O(n) events, each O(log n) (a lookup, at most two removals and insertions).
//!
//! Which pairs count is decided pair by pair by [`pair_problem`], the same test the
//! pairwise check (kept in the tests as the reference) applies to every pair: two edges
//! meet when they share a point, except consecutive edges of a contour at their shared
//! vertex, which only count when they fold back along each other.
//!
//! **Nesting** comes out of the same sweep: when it reaches a contour's first vertex (its
//! lexicographically smallest), the active edge just below that vertex tells which
//! contour directly encloses it: that edge's contour if its inside lies above the edge,
//! else the contour enclosing that edge's contour (known, since that contour was reached
//! earlier).
//!
//! The range envelope: every coordinate is an integer below 2^29 in magnitude (the
//! snapped grid's), so differences are below 2^30, orientation products below 2^61 and
//! the doubled area of a contour of up to 2^40 vertices below 2^101: all exact in i128.

use std::cmp::Ordering;
use std::collections::BTreeSet;
use std::ops::Bound::{Excluded, Unbounded};

use crate::edge::fixed::edge_function_wide;

/// A point on the snapped grid, `[x, y]`, each coordinate below 2^29 in magnitude.
pub(crate) type Pt = [i64; 2];

/// An edge: (contour, edge within it), edge `i` running from vertex `i` to vertex `i + 1`
/// (the last back to vertex 0). The tuple order is the order of the edges contour after
/// contour.
pub(crate) type Edge = (usize, usize);

/// `orient(a, b, c)`: twice the signed area of (a, b, c), positive when `c` lies to the
/// left of `a -> b` (counterclockwise with y up), in i128 (exact: coordinates are below
/// 2^29, products below 2^61).
pub(crate) fn orient(a: Pt, b: Pt, c: Pt) -> i128 {
    // E_{a b}(c) = (c - a) x (b - a) = -((b - a) x (c - a))
    -edge_function_wide(a.map(i128::from), b.map(i128::from), c.map(i128::from))
}

/// Whether `p`, known to be collinear with segment `a b`, lies on it (closed).
pub(crate) fn on_segment(a: Pt, b: Pt, p: Pt) -> bool {
    (0..2).all(|k| a[k].min(b[k]) <= p[k] && p[k] <= a[k].max(b[k]))
}

/// A point the closed segments `a b` and `c d` share, if any (an endpoint when they touch
/// or overlap; for a proper crossing the rounded-down crossing point, for the message).
pub(crate) fn meet(a: Pt, b: Pt, c: Pt, d: Pt) -> Option<Pt> {
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    for (o, p, s, t) in [(o1, c, a, b), (o2, d, a, b), (o3, a, c, d), (o4, b, c, d)] {
        if o == 0 && on_segment(s, t, p) {
            return Some(p);
        }
    }
    let proper = o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0;
    proper.then(|| {
        // a + t (b - a) with t = o3 / (o3 - o4), rounded down; o3 - o4 is not 0 (o3 and
        // o4 have opposite signs) and the point lies between a and b.
        [0, 1].map(|k| {
            let v = i128::from(a[k]) + ((i128::from(b[k]) - i128::from(a[k])) * o3).div_euclid(o3 - o4);
            i64::try_from(v).unwrap_or(a[k])
        })
    })
}

/// The ends of edge `e`: vertex `i` and vertex `i + 1` of its contour.
fn ends(contours: &[&[Pt]], (c, i): Edge) -> (Pt, Pt) {
    let points = contours[c];
    (points[i], points[(i + 1) % points.len()])
}

/// Whether edges `ea` and `eb` (`ea` before `eb` in the edge order, both of contours
/// with no repeated consecutive vertices) make the polygon not simple, and a point they
/// share: any shared point, except for consecutive edges of a contour, which share their
/// common vertex and only count when they fold back (the other ends on one ray from it).
pub(crate) fn pair_problem(contours: &[&[Pt]], ea: Edge, eb: Edge) -> Option<Pt> {
    let ((a, b), (c, d)) = (ends(contours, ea), ends(contours, eb));
    let n = contours[ea.0].len();
    let adjacent = ea.0 == eb.0 && (eb.1 == ea.1 + 1 || (ea.1 == 0 && eb.1 == n - 1));
    if adjacent {
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
    }
}

/// Two edges that meet (`first` before `second` in the edge order) and a point they share.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Meeting {
    /// The earlier edge.
    pub first: Edge,
    /// The later edge.
    pub second: Edge,
    /// A point both contain ([`pair_problem`]'s).
    pub at: Pt,
}

/// Where `p` lies against an active segment `l -> r` (`l` before `r` lexicographically):
/// `Greater` above it, `Less` below, `Equal` on it. A vertical segment is active only
/// while the sweep is on it, so a point against one is on it unless before or after it.
fn side(p: Pt, l: Pt, r: Pt) -> Ordering {
    if l[0] == r[0] {
        if p < l {
            Ordering::Less
        } else if p > r {
            Ordering::Greater
        } else {
            Ordering::Equal
        }
    } else {
        orient(l, r, p).cmp(&0)
    }
}

/// A key of the sweep's ordered set: an active segment (its ends, `l` before `r`
/// lexicographically, and its edge's index in the flat edge list), or a probe just below
/// the segments through a point.
#[derive(Debug, Clone, Copy)]
enum Key {
    Seg { l: Pt, r: Pt, id: usize },
    Below(Pt),
}

/// The order of two active segments along the sweep line: where the later-starting one
/// starts against the other, or by direction when both start at one point (the
/// orientation orders directions within the half-plane of lexicographically increasing
/// directions, vertical last). Ties (only for segments that meet, which the sweep
/// reports before they could be compared) fall back to the edge index, so that the order
/// stays total.
fn seg_cmp((l1, r1, id1): (Pt, Pt, usize), (l2, r2, id2): (Pt, Pt, usize)) -> Ordering {
    if id1 == id2 {
        return Ordering::Equal;
    }
    let o = match l1.cmp(&l2) {
        Ordering::Equal => 0.cmp(&orient(l1, r1, r2)),
        Ordering::Greater => side(l1, l2, r2),
        Ordering::Less => side(l2, l1, r1).reverse(),
    };
    o.then(id1.cmp(&id2))
}

impl Ord for Key {
    fn cmp(&self, other: &Key) -> Ordering {
        // The probe below p is below every segment through p.
        let probe = |p: Pt, l: Pt, r: Pt| match side(p, l, r) {
            Ordering::Equal => Ordering::Less,
            o => o,
        };
        match (*self, *other) {
            (Key::Seg { l, r, id }, Key::Seg { l: l2, r: r2, id: id2 }) => seg_cmp((l, r, id), (l2, r2, id2)),
            (Key::Below(p), Key::Seg { l, r, .. }) => probe(p, l, r),
            (Key::Seg { l, r, .. }, Key::Below(p)) => probe(p, l, r).reverse(),
            (Key::Below(p), Key::Below(q)) => p.cmp(&q),
        }
    }
}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Key) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Key {
    fn eq(&self, other: &Key) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Key {}

/// The contours' edges as one flat list: edge `offsets[c] + i` is edge `i` of contour `c`,
/// and vertex `offsets[c] + i` is vertex `i` (the start of that edge).
struct Flat<'a> {
    contours: &'a [&'a [Pt]],
    offsets: Vec<usize>,
}

impl Flat<'_> {
    fn edge(&self, id: usize) -> Edge {
        let c = self.offsets.partition_point(|&o| o <= id) - 1;
        (c, id - self.offsets[c])
    }

    fn id(&self, (c, i): Edge) -> usize {
        self.offsets[c] + i
    }

    fn point(&self, id: usize) -> Pt {
        let (c, i) = self.edge(id);
        self.contours[c][i]
    }

    /// The edge that ends at vertex `id` (the one before it in its contour).
    fn edge_in(&self, id: usize) -> usize {
        let (c, i) = self.edge(id);
        let n = self.contours[c].len();
        self.id((c, (i + n - 1) % n))
    }

    fn key(&self, id: usize) -> Key {
        let (a, b) = ends(self.contours, self.edge(id));
        let (l, r) = if a < b { (a, b) } else { (b, a) };
        Key::Seg { l, r, id }
    }

    fn problem(&self, x: usize, y: usize) -> Option<Meeting> {
        let (first, second) = (self.edge(x.min(y)), self.edge(x.max(y)));
        pair_problem(self.contours, first, second).map(|at| Meeting { first, second, at })
    }
}

/// The first meeting of a list by the edge order (first edge, then second).
fn earliest(found: &[Meeting]) -> Option<Meeting> {
    found.iter().min_by_key(|m| (m.first, m.second)).copied()
}

/// Sweeps the contours (each with 3 or more vertices, no two consecutive ones equal, not
/// all collinear). Returns, when no two edges meet (see [`pair_problem`]), each contour
/// with the contour that directly encloses it (`None`: none does), in the order the sweep
/// reached them (a contour's encloser comes before it); else a pair of edges that meet,
/// found at the first event (in the sweep's order) where a problem shows, the earliest
/// such pair there.
pub(crate) fn sweep(contours: &[&[Pt]]) -> Result<Vec<(usize, Option<usize>)>, Meeting> {
    let mut offsets = Vec::with_capacity(contours.len() + 1);
    let mut total = 0;
    for c in contours {
        offsets.push(total);
        total += c.len();
    }
    offsets.push(total);
    let flat = Flat { contours, offsets };
    // Twice each contour's signed area: positive when counterclockwise (inside on the left).
    let area: Vec<i128> = contours
        .iter()
        .map(|c| {
            (0..c.len())
                .map(|i| orient([0, 0], c[i], c[(i + 1) % c.len()]))
                .sum::<i128>()
        })
        .collect();
    let mut events: Vec<(Pt, usize)> = (0..total).map(|id| (flat.point(id), id)).collect();
    events.sort_unstable();
    let mut active: BTreeSet<Key> = BTreeSet::new();
    let mut parent: Vec<Option<usize>> = vec![None; contours.len()];
    let mut reached = vec![false; contours.len()];
    let mut nesting = Vec::with_capacity(contours.len());
    let mut g = 0;
    while g < events.len() {
        let (p, v) = events[g];
        if let Some(&(_, w)) = events.get(g + 1).filter(|e| e.0 == p) {
            // Two vertices at one point: their edges meet there (the vertices are not
            // consecutive, or they would have been merged).
            let edges = [flat.edge_in(v), v, flat.edge_in(w), w];
            let found: Vec<Meeting> = (0..4)
                .flat_map(|x| (x + 1..4).map(move |y| (x, y)))
                .filter_map(|(x, y)| flat.problem(edges[x], edges[y]))
                .collect();
            if let Some(m) = earliest(&found) {
                return Err(m);
            }
        }
        g += 1;
        let (e_in, e_out) = (flat.edge_in(v), v);
        let mut found: Vec<Meeting> = flat.problem(e_in, e_out).into_iter().collect();
        // The active segments through p: those that end here are the vertex's own edges;
        // any other touches p.
        let mut ending = Vec::new();
        for &key in active.range((Excluded(Key::Below(p)), Unbounded)) {
            let Key::Seg { l, r, id } = key else { break };
            if side(p, l, r) != Ordering::Equal {
                break;
            }
            if id == e_in || id == e_out {
                ending.push(key);
            } else {
                found.extend([e_in, e_out].into_iter().filter_map(|e| flat.problem(id, e)));
            }
        }
        if let Some(m) = earliest(&found) {
            return Err(m);
        }
        let (c, _) = flat.edge(v);
        if !reached[c] {
            // The contour's first vertex: the active edge just below it says what encloses it.
            reached[c] = true;
            if let Some(&Key::Seg { id, .. }) = active.range(..Key::Below(p)).next_back() {
                let (d, i) = flat.edge(id);
                let (a, b) = ends(contours, (d, i));
                let inside_above = (area[d] > 0) == (a < b);
                parent[c] = if inside_above { Some(d) } else { parent[d] };
            }
            nesting.push((c, parent[c]));
        }
        for key in &ending {
            active.remove(key);
        }
        let mut starting: Vec<Key> = [e_in, e_out]
            .into_iter()
            .map(|e| flat.key(e))
            .filter(|k| matches!(k, Key::Seg { l, .. } if *l == p))
            .collect();
        starting.sort_unstable();
        let id_of = |k: Option<&Key>| match k {
            Some(&Key::Seg { id, .. }) => Some(id),
            _ => None,
        };
        let pairs = match (starting.first(), starting.last()) {
            (Some(&low), Some(&high)) => {
                active.extend(starting.iter().copied());
                let below = id_of(active.range(..low).next_back());
                let above = id_of(active.range((Excluded(high), Unbounded)).next());
                [(below, id_of(Some(&low))), (id_of(Some(&high)), above)]
            }
            _ => {
                let below = id_of(active.range(..Key::Below(p)).next_back());
                let above = id_of(active.range((Excluded(Key::Below(p)), Unbounded)).next());
                [(below, above), (None, None)]
            }
        };
        for (x, y) in pairs {
            if let (Some(x), Some(y)) = (x, y) {
                found.extend(flat.problem(x, y));
            }
        }
        if let Some(m) = earliest(&found) {
            return Err(m);
        }
    }
    Ok(nesting)
}
