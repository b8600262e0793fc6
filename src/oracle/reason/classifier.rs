//! The [`Classifier`]: the exact search behind each reason class (the ranking is
//! [`super::decide`]'s), over one comparison's shapes (and, computed when first needed, each
//! primitive's shape under other snappings and its line alternatives).

use std::collections::{HashMap, HashSet};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::{decide, Alternative, Found, Reason, Snapping, Support, DIAMOND_MIRRORED};
use crate::check::triangle_covers;
use crate::clip::Window;
use crate::convention::{AnyTieRule, Convention, PixelCentre, Target, TieRule};
use crate::coverage::CoverageSink;
use crate::fill::polygon::contains_exact_with;
use crate::geom::{FillRule, Point};
use crate::line::{self, BresenhamTie, MAX_BRESENHAM_COORD};
use crate::model::{prepare, Model, Primitives, Shape};
use crate::num::Rounding;
use crate::oracle::evidence::{polygon_at, polygon_inside, shape_distance2, triangle_at, within_float_error, EdgeAt};
use crate::raster::sample_exact;

/// The snappings the search tries: the oracle's own subpixel bits with every other
/// rounding (a renderer that differs in rounding alone), and the others: for each of
/// 1..=16 bits every rounding, then unsnapped (for a snapping oracle). The oracle's own
/// snapping is left out.
fn snappings(own: Option<(u32, Rounding)>) -> (Vec<Snapping>, Vec<Snapping>) {
    let at = |bits: u32| -> Vec<Snapping> {
        Rounding::ALL
            .into_iter()
            .map(|rounding| Snapping {
                bits: Some(bits),
                rounding,
            })
            .filter(|s| own != s.bits.map(|b| (b, s.rounding)))
            .collect()
    };
    let own_group = own.map(|(bits, _)| at(bits)).unwrap_or_default();
    let mut others: Vec<Snapping> = (1..=crate::num::MAX_SUBPIXEL_BITS)
        .filter(|&b| Some(b) != own.map(|o| o.0))
        .flat_map(at)
        .collect();
    if own.is_some() {
        others.push(Snapping {
            bits: None,
            rounding: Rounding::NearestEven,
        });
    }
    (own_group, others)
}

/// The sample offsets the sample-position search tries, in half pixels: (i, j),
/// (i + 1/2, j), (i, j + 1/2), (i + 1/2, j + 1/2), less the oracle's own.
fn sample_offsets(own: PixelCentre) -> Vec<[u8; 2]> {
    let own = match own {
        PixelCentre::Half => [1, 1],
        PixelCentre::Corner => [0, 0],
    };
    [[0, 0], [1, 0], [0, 1], [1, 1]]
        .into_iter()
        .filter(|o| *o != own)
        .collect()
}

/// Collects pixels (a line's, for the line-rule search).
#[derive(Default)]
struct PixelSet(HashSet<[i64; 2]>);

impl CoverageSink for PixelSet {
    fn cover(&mut self, x: u32, y: u32, _id: u32) {
        self.0.insert([i64::from(x), i64::from(y)]);
    }
}

/// The scene with only primitive `id` (keeping the viewport and, unless `unclipped`, the
/// window), so that preparing it gives that primitive's shape alone.
fn single(primitives: &Primitives, id: usize, unclipped: bool) -> Primitives {
    let mut out = Primitives {
        viewport: primitives.viewport.clone(),
        clip: if unclipped { None } else { primitives.clip.clone() },
        ..Primitives::default()
    };
    let (t, l, p) = (
        primitives.triangles.len(),
        primitives.lines.len(),
        primitives.polygons.len(),
    );
    if id < t {
        out.triangles.push(primitives.triangles[id].clone());
    } else if id < t + l {
        out.lines.push(primitives.lines[id - t].clone());
    } else if id < t + l + p {
        out.polygons.push(primitives.polygons[id - t - l].clone());
    } else {
        out.clip_space_triangles
            .push(primitives.clip_space_triangles[id - t - l - p].clone());
    }
    out
}

/// Whether `p` lies in the closed window.
fn in_closed_window(window: &Window, p: &Point) -> bool {
    window
        .half_planes()
        .iter()
        .all(|h| &h.a * &p.x + &h.b * &p.y + &h.c >= BigRational::zero())
}

/// The classifier of one comparison: the oracle's shapes and, computed when first
/// needed, each primitive's shape under other snappings and its line alternatives.
pub struct Classifier<'a> {
    primitives: &'a Primitives,
    target: &'a Target,
    model: Model,
    shapes: &'a [Shape],
    own_grid: Vec<Snapping>,
    other_snappings: Vec<Snapping>,
    offsets: Vec<[u8; 2]>,
    snapped_shapes: HashMap<(usize, Snapping), Option<Shape>>,
    unclipped_shapes: HashMap<usize, Option<Shape>>,
    line_pixels: HashMap<(usize, &'static str), HashSet<[i64; 2]>>,
    /// The pixels of each diamond-exit segment asked about (by its ends and the sample
    /// position), drawn once by the planned engine (equal to the plain reading).
    diamond_pixels: HashMap<(Point, Point, PixelCentre), HashSet<[i64; 2]>>,
    /// [`Classifier::reach2`], per number of bits.
    reach2: Option<Vec<BigRational>>,
}

impl<'a> Classifier<'a> {
    /// A classifier for the oracle `model` (an exact model) whose shapes are `shapes`
    /// (from [`crate::model::PreparedScene::shapes`]).
    pub fn new(primitives: &'a Primitives, target: &'a Target, model: Model, shapes: &'a [Shape]) -> Classifier<'a> {
        let conv = target.convention;
        let own = model.snaps().then_some((conv.subpixel_bits, conv.rounding));
        let (own_grid, other_snappings) = snappings(own);
        Classifier {
            primitives,
            target,
            model,
            shapes,
            own_grid,
            other_snappings,
            offsets: sample_offsets(conv.pixel_centre),
            snapped_shapes: HashMap::new(),
            unclipped_shapes: HashMap::new(),
            line_pixels: HashMap::new(),
            diamond_pixels: HashMap::new(),
            reach2: Self::reach2(primitives, target, model),
        }
    }

    /// The oracle's shapes.
    pub fn shapes(&self) -> &[Shape] {
        self.shapes
    }

    /// Why their answer (`theirs_covers`) for primitive `id` at pixel `(x, y)` differs from
    /// the oracle's, judged alone (as if it were the comparison's only finding; see
    /// [`super::decide`]). (`id` must be a primitive of the scene.)
    pub fn reason(&mut self, id: usize, x: u32, y: u32, theirs_covers: bool) -> Reason {
        let found = self.found(id, x, y, theirs_covers);
        let support = Support::of(&found);
        decide(found, &support)
    }

    /// What the exact searches find for their answer (`theirs_covers`) for primitive `id`
    /// at pixel `(x, y)`: a class that decides alone, or the distance and every
    /// alternative that gives their answer. (`id` must be a primitive of the scene.)
    pub fn found(&mut self, id: usize, x: u32, y: u32, theirs_covers: bool) -> Found {
        let p = sample_exact(x, y, self.target);
        let address = [i64::from(x), i64::from(y)];
        let shapes = self.shapes;
        let shape = &shapes[id];
        if let Some(r) = tie(shape, &p, self.target.convention.tie_rule, theirs_covers) {
            return Found::Decided(r);
        }
        if self.primitives.clip.is_some() {
            if let Some(unclipped) = self.unclipped(id) {
                let covers = self.covers(id, &unclipped, x, y, self.target, false);
                if covers == theirs_covers {
                    return Found::Decided(Reason::Clip {
                        unclipped_covers: covers,
                    });
                }
            }
        }
        if let Some(r) = self.rule(id, x, y, theirs_covers) {
            return Found::Decided(r);
        }
        let distance2 = shape_distance2(shape, &p, address);
        let near = distance2 <= BigRational::one();
        let own_roundings: Vec<Rounding> = self
            .own_grid
            .clone()
            .into_iter()
            .filter(|s| self.may_move_across(id, *s, &distance2) && self.snapping_gives(id, *s, x, y, theirs_covers))
            .map(|s| s.rounding)
            .collect();
        let own_grid = (!own_roundings.is_empty()).then_some(Reason::Snapping {
            bits: Some(self.target.convention.subpixel_bits),
            roundings: own_roundings,
        });
        let mut alternatives: Vec<Alternative> = self
            .offsets
            .clone()
            .into_iter()
            .filter(|o| self.offset_gives(id, *o, x, y, theirs_covers))
            .map(Alternative::SamplePosition)
            .collect();
        if own_grid.is_none() && (self.model.snaps() || !near) {
            for s in self.other_snappings.clone() {
                if self.may_move_across(id, s, &distance2) && self.snapping_gives(id, s, x, y, theirs_covers) {
                    alternatives.push(Alternative::Snapping(s));
                }
            }
        }
        Found::Open {
            tiny: within_float_error(shape, &p, address),
            distance2,
            own_grid,
            alternatives,
        }
    }

    /// The candidate among `candidates` that best explains an extra pixel whose owner
    /// their output does not name (a mask, or the second owner of an ids PNG's double
    /// cover), each judged alone: the first class in order, the nearest within a class;
    /// `None` when there is no candidate.
    pub fn best_extra(&mut self, candidates: &[usize], x: u32, y: u32) -> Option<(usize, Found)> {
        let mut best: Option<(usize, Found, Reason)> = None;
        for &id in candidates {
            let found = self.found(id, x, y, true);
            let r = decide(found.clone(), &Support::of(&found));
            let better = match &best {
                None => true,
                Some((_, _, b)) => match r.class().cmp(&b.class()) {
                    std::cmp::Ordering::Less => true,
                    std::cmp::Ordering::Greater => false,
                    std::cmp::Ordering::Equal => match (r.distance2(), b.distance2()) {
                        (Some(d), Some(e)) => d < e,
                        (Some(_), None) => true,
                        _ => false,
                    },
                },
            };
            if better {
                best = Some((id, found, r));
            }
        }
        best.map(|(id, found, _)| (id, found))
    }

    /// Whether primitive `id` sampled at `offset` (half pixels) gives their answer
    /// (triangles and polygons: a line's pixels follow its own rule, the line-rule
    /// search's).
    fn offset_gives(&mut self, id: usize, [ox, oy]: [u8; 2], x: u32, y: u32, theirs_covers: bool) -> bool {
        let half = |v: u32, o: u8| BigRational::new((2 * i64::from(v) + i64::from(o)).into(), 2.into());
        let p = Point::new(half(x, ox), half(y, oy));
        let rule = self.target.convention.tie_rule;
        let covers = match &self.shapes[id] {
            Shape::Triangle(t) => triangle_covers(t, &p, rule.into()),
            Shape::Polygon(poly) => polygon_inside(poly, &p, rule),
            _ => return false,
        };
        covers == theirs_covers
    }

    /// Whether snapping `s` can move primitive `id`'s boundary across a sample whose
    /// squared distance to the oracle's shape's nearest edge is `distance2`; when not, the
    /// primitive's answer there is the oracle's under `s` too, and the exact test is
    /// skipped. Snapping to `b` bits moves each vertex of the scene's primitive by less
    /// than `2^-b` on each axis, so by at most `√2·2^-b`; the oracle's own snapping (`o`
    /// bits, when its model snaps) by at most `√2·2^-o`. Every point of a triangle's or
    /// polygon's edges moves by at most the largest vertex move, so an edge that crosses
    /// the sample had to pass within `√2 (2^-b + 2^-o)` of it: a sample farther than that
    /// from every edge keeps its answer (its winding number cannot change). Tried always:
    /// lines, the unsnapped alternative, and scenes with a clip window or clip-space
    /// triangles (whose clipped shapes this bound does not cover).
    fn may_move_across(&self, id: usize, s: Snapping, distance2: &BigRational) -> bool {
        let (Some(bits), Some(reach2)) = (s.bits, &self.reach2) else {
            return true;
        };
        !matches!(self.shapes[id], Shape::Triangle(_) | Shape::Polygon(_)) || *distance2 <= reach2[bits as usize]
    }

    /// [`Classifier::may_move_across`]'s bound for each number of bits `b` in
    /// `0..=MAX_SUBPIXEL_BITS`, squared, `2 (2^-b + 2^-o)^2`, computed once; `None` for a
    /// scene with a clip window or clip-space triangles (the bound does not hold there).
    fn reach2(primitives: &Primitives, target: &Target, model: Model) -> Option<Vec<BigRational>> {
        if primitives.clip.is_some() || !primitives.clip_space_triangles.is_empty() {
            return None;
        }
        let step = |b: u32| BigRational::new(BigInt::one(), BigInt::one() << b);
        let own = if model.snaps() {
            step(target.convention.subpixel_bits)
        } else {
            BigRational::zero()
        };
        let reach2 = (0..=crate::num::MAX_SUBPIXEL_BITS)
            .map(|b| {
                let reach = step(b) + &own;
                BigRational::from_integer(2.into()) * &reach * &reach
            })
            .collect();
        Some(reach2)
    }

    /// Whether primitive `id` under snapping `s` gives their answer.
    fn snapping_gives(&mut self, id: usize, s: Snapping, x: u32, y: u32, theirs_covers: bool) -> bool {
        if matches!(self.shapes[id], Shape::Bresenham { .. }) {
            return false; // pixel addresses do not snap
        }
        let Some((shape, target)) = self.snapped(id, s) else {
            return false;
        };
        self.covers(id, &shape, x, y, &target, true) == theirs_covers
    }

    /// Whether `shape` (primitive `id`'s, or an alternative of it) covers pixel `(x, y)`
    /// under `target`'s convention; lines keep pixels in the closed window when `clipped`.
    fn covers(&mut self, id: usize, shape: &Shape, x: u32, y: u32, target: &Target, clipped: bool) -> bool {
        let p = sample_exact(x, y, target);
        let rule = target.convention.tie_rule;
        let kept = !clipped || self.primitives.clip.as_ref().is_none_or(|w| in_closed_window(w, &p));
        match shape {
            Shape::Triangle(t) => triangle_covers(t, &p, rule.into()),
            Shape::Polygon(poly) => polygon_inside(poly, &p, rule),
            Shape::Diamond { from, to } => {
                let key = (from.clone(), to.clone(), target.convention.pixel_centre);
                kept && self
                    .diamond_pixels
                    .entry(key)
                    .or_insert_with(|| {
                        let mut set = PixelSet::default();
                        line::planned::rasterize(from, to, 0, target, &mut set);
                        set.0
                    })
                    .contains(&[i64::from(x), i64::from(y)])
            }
            Shape::Bresenham { tie, .. } => {
                let name = if *tie == BresenhamTie::Stay {
                    "bresenham (stay)"
                } else {
                    "bresenham (step)"
                };
                kept && self.line_alternative(id, name).contains(&[i64::from(x), i64::from(y)])
            }
        }
    }

    fn unclipped(&mut self, id: usize) -> Option<Shape> {
        if let Some(s) = self.unclipped_shapes.get(&id) {
            return s.clone();
        }
        let prepared = prepare(&single(self.primitives, id, true), self.target, self.model).ok();
        let shape = prepared.and_then(|p| p.shapes()).and_then(|s| s.into_iter().next());
        self.unclipped_shapes.insert(id, shape.clone());
        shape
    }

    /// Line conventions and fill rules.
    fn rule(&mut self, id: usize, x: u32, y: u32, theirs_covers: bool) -> Option<Reason> {
        let p = sample_exact(x, y, self.target);
        let kept = self.primitives.clip.as_ref().is_none_or(|w| in_closed_window(w, &p));
        let shapes = self.shapes;
        match &shapes[id] {
            Shape::Polygon(poly) => {
                let other = match poly.fill_rule {
                    FillRule::NonZero => FillRule::EvenOdd,
                    FillRule::EvenOdd => FillRule::NonZero,
                };
                let mut flipped = poly.clone();
                flipped.fill_rule = other;
                let rule = self.target.convention.tie_rule;
                (polygon_inside(&flipped, &p, rule) == theirs_covers).then(|| Reason::FillRule {
                    winding: polygon_at(poly, &p, rule).windings[0],
                    fill_rule: other,
                })
            }
            Shape::Bresenham { tie, .. } => {
                let names: &[&'static str] = match tie {
                    BresenhamTie::Stay => &["bresenham (step)", "dda (f32)", "dda (f64)", "diamond-exit"],
                    BresenhamTie::Step => &["bresenham (stay)", "dda (f32)", "dda (f64)", "diamond-exit"],
                };
                self.line_rules(id, names, [x, y], kept, theirs_covers)
            }
            Shape::Diamond { .. } => self.line_rules(
                id,
                &[
                    "bresenham (stay)",
                    "bresenham (step)",
                    "dda (f32)",
                    "dda (f64)",
                    DIAMOND_MIRRORED,
                ],
                [x, y],
                kept,
                theirs_covers,
            ),
            Shape::Triangle(_) => None,
        }
    }

    fn line_rules(
        &mut self,
        id: usize,
        names: &[&'static str],
        [x, y]: [u32; 2],
        kept: bool,
        theirs_covers: bool,
    ) -> Option<Reason> {
        let pixel = [i64::from(x), i64::from(y)];
        let rules: Vec<&'static str> = names
            .iter()
            .copied()
            .filter(|name| (kept && self.line_alternative(id, name).contains(&pixel)) == theirs_covers)
            .collect();
        (!rules.is_empty()).then_some(Reason::LineRule { rules })
    }

    /// The pixels of line `id` drawn by the convention `name` (on the canvas).
    fn line_alternative(&mut self, id: usize, name: &'static str) -> &HashSet<[i64; 2]> {
        if !self.line_pixels.contains_key(&(id, name)) {
            let pixels = self.draw_alternative(id, name);
            self.line_pixels.insert((id, name), pixels);
        }
        &self.line_pixels[&(id, name)]
    }

    fn draw_alternative(&self, id: usize, name: &str) -> HashSet<[i64; 2]> {
        let mut set = PixelSet::default();
        let target = self.target;
        if let (DIAMOND_MIRRORED, Shape::Diamond { from, to }) = (name, &self.shapes[id]) {
            // Mirrored about y = m / 2 with m = H - 1 + 2c (c the sample offset): row j's
            // sample j + c goes to row H - 1 - j's.
            let m = BigRational::from_integer((i64::from(target.height) - 1).into())
                + target.convention.pixel_centre.offset() * BigRational::from_integer(2.into());
            let mirror = |p: &Point| Point::new(p.x.clone(), &m - &p.y);
            line::planned::rasterize(&mirror(from), &mirror(to), 0, target, &mut set);
            let height = i64::from(target.height);
            return set.0.into_iter().map(|[i, j]| [i, height - 1 - j]).collect();
        }
        let (from, to): ([i64; 2], [i64; 2]) = match &self.shapes[id] {
            Shape::Bresenham { from, to, .. } => (*from, *to),
            Shape::Diamond { from, to } => {
                let pixel = |p: &Point| {
                    let f = |v: &BigRational| {
                        i64::try_from(v.floor().to_integer())
                            .ok()
                            .filter(|v| v.abs() <= MAX_BRESENHAM_COORD)
                    };
                    Some([f(&p.x)?, f(&p.y)?])
                };
                match (pixel(from), pixel(to)) {
                    (Some(a), Some(b)) => (a, b),
                    _ => return set.0,
                }
            }
            _ => return set.0,
        };
        match name {
            "bresenham (stay)" => line::exact::rasterize_bresenham(from, to, BresenhamTie::Stay, 0, target, &mut set),
            "bresenham (step)" => line::exact::rasterize_bresenham(from, to, BresenhamTie::Step, 0, target, &mut set),
            "dda (f32)" => line::dda::rasterize(from, to, line::dda::DdaFloat::F32, 0, target, &mut set),
            "dda (f64)" => line::dda::rasterize(from, to, line::dda::DdaFloat::F64, 0, target, &mut set),
            _ => {
                // diamond-exit between the endpoint pixels' samples
                let c = target.convention.pixel_centre.offset();
                let at = |a: [i64; 2]| {
                    Point::new(
                        BigRational::from_integer(a[0].into()) + &c,
                        BigRational::from_integer(a[1].into()) + &c,
                    )
                };
                line::planned::rasterize(&at(from), &at(to), 0, target, &mut set);
            }
        }
        set.0
    }

    /// Primitive `id` under snapping `s`, and the target it renders with.
    fn snapped(&mut self, id: usize, s: Snapping) -> Option<(Shape, Target)> {
        let target = Target {
            convention: Convention {
                subpixel_bits: s.bits.unwrap_or(self.target.convention.subpixel_bits),
                rounding: s.rounding,
                ..self.target.convention
            },
            ..*self.target
        };
        if !self.snapped_shapes.contains_key(&(id, s)) {
            let model = if s.bits.is_some() {
                Model::ExactSnappedPlain
            } else {
                Model::ExactPlain
            };
            let prepared = prepare(&single(self.primitives, id, false), &target, model).ok();
            let shape = prepared.and_then(|p| p.shapes()).and_then(|v| v.into_iter().next());
            self.snapped_shapes.insert((id, s), shape);
        }
        self.snapped_shapes[&(id, s)].clone().map(|shape| (shape, target))
    }
}

/// The tie search: the sample lies on an edge and another rule gives their answer.
fn tie(shape: &Shape, p: &Point, rule: TieRule, theirs_covers: bool) -> Option<Reason> {
    match shape {
        Shape::Triangle(t) => {
            let at = triangle_at(t, p, rule.into())?;
            if at.edges.iter().any(|e| e.value < BigRational::zero()) {
                return None;
            }
            let zero: Vec<EdgeAt> = at.zero_edges().cloned().collect();
            if zero.is_empty() {
                return None;
            }
            let rules: Vec<AnyTieRule> = AnyTieRule::ALL
                .into_iter()
                .filter(|r| triangle_covers(t, p, *r) == theirs_covers)
                .collect();
            (!rules.is_empty()).then_some(Reason::Tie { edges: zero, rules })
        }
        Shape::Polygon(poly) => {
            if !polygon_at(poly, p, rule).on_boundary {
                return None;
            }
            let rules: Vec<AnyTieRule> = AnyTieRule::ALL
                .into_iter()
                .filter(|r| contains_exact_with(p, poly, *r) == theirs_covers)
                .collect();
            (!rules.is_empty()).then_some(Reason::Tie {
                edges: Vec::new(),
                rules,
            })
        }
        Shape::Bresenham { .. } | Shape::Diamond { .. } => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::geom::Triangle;
    use crate::model::prepare;

    /// The bound of [`Classifier::may_move_across`] is sound: wherever it says a snapping
    /// cannot move the triangle's boundary across a sample, the triangle snapped that way
    /// covers the sample exactly when the oracle's does. Triangles with vertices on a
    /// 1/1000 px grid (far from every coarse grid, so each snapping moves them by nearly
    /// its whole step), every sample of an 8x8 canvas, every snapping the search tries;
    /// under the snapping oracle (its own 8-bit move adds to the bound) and the unsnapped
    /// one.
    #[test]
    fn a_snapping_the_bound_skips_never_changes_the_answer() {
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = |n: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            i64::try_from(seed % u64::try_from(n).unwrap()).unwrap()
        };
        let target = Target::new(8, 8, Convention::default()).unwrap();
        let mut skipped = 0usize;
        for _ in 0..24 {
            let mut v = || {
                Point::new(
                    BigRational::new(next(8000).into(), 1000.into()),
                    BigRational::new(next(8000).into(), 1000.into()),
                )
            };
            let t = Triangle::new(v(), v(), v());
            let primitives = Primitives::from_triangles(&[t]);
            for model in [Model::ExactSnapped, Model::Exact] {
                let Ok(prepared) = prepare(&primitives, &target, model) else {
                    continue;
                };
                let shapes = prepared.shapes().unwrap();
                let mut c = Classifier::new(&primitives, &target, model, &shapes);
                let snappings: Vec<Snapping> = c.own_grid.iter().chain(&c.other_snappings).copied().collect();
                for (x, y) in (0..8).flat_map(|y| (0..8).map(move |x| (x, y))) {
                    let p = sample_exact(x, y, &target);
                    let oracle = c.covers(0, &shapes[0], x, y, &target, true);
                    let d2 = shape_distance2(&shapes[0], &p, [i64::from(x), i64::from(y)]);
                    for &s in &snappings {
                        if !c.may_move_across(0, s, &d2) {
                            skipped += 1;
                            assert!(
                                c.snapping_gives(0, s, x, y, oracle),
                                "{s:?} flips ({x}, {y}) at distance² {d2}"
                            );
                        }
                    }
                }
            }
        }
        assert!(skipped > 10_000, "the bound skipped only {skipped} tests");
    }
}
