//! Counting a coverage's departures from the exact one: covered (pixel, primitive) pairs
//! collected by a sink, sorted, and walked side by side, so that heavily overlapping
//! workloads (huge triangles) compare in `O(n log n)` without an owner list per pixel.
//! The wrong-pixel count is exactly [`crate::check::differing_pixels`]'s (tested below).

use crate::coverage::CoverageSink;

use super::metric::Metric;

/// Every covered `(pixel, primitive)` pair, as `y << 46 | x << 32 | id`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(crate) struct Pairs(pub(crate) Vec<u64>);

/// The pixel `(x, y)` as a key (canvases are at most 16384 px a side, so both fit 14 bits).
fn pixel_key(x: u32, y: u32) -> u64 {
    (u64::from(y) << 14) | u64::from(x)
}

impl CoverageSink for Pairs {
    #[inline]
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        self.0.push((pixel_key(x, y) << 32) | u64::from(id));
    }

    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        for x in x0..=x1 {
            self.cover(x, y, id);
        }
    }
}

impl Pairs {
    /// Sorted by pixel (row-major), then id.
    pub(crate) fn sorted(mut self) -> Pairs {
        self.0.sort_unstable();
        self
    }

    /// Every `step`-th pair as `(x, y, id)`, at most `limit` of them (samples for the
    /// barycentric and Gouraud measurements, spread over the whole workload).
    pub(crate) fn spread(&self, limit: usize) -> Vec<(u32, u32, u32)> {
        if limit == 0 || self.0.is_empty() {
            return Vec::new();
        }
        let step = self.0.len().div_ceil(limit);
        self.0.iter().step_by(step).map(|&k| unpack(k)).collect()
    }
}

/// The plain oracles' subset: the primitives (of `count`) that cover the corner in the
/// exact answer `corner` (its pairs), in id order, until they cover `pixels` of it.
pub(crate) fn corner_subset(corner: &Pairs, count: usize, pixels: u64) -> Vec<usize> {
    let mut per_id = vec![0u64; count];
    for &k in &corner.0 {
        if let Some(c) = per_id.get_mut(usize::try_from(unpack(k).2).expect("an id")) {
            *c += 1;
        }
    }
    let mut out = Vec::new();
    let mut total = 0;
    for (id, c) in per_id.into_iter().enumerate().filter(|&(_, c)| c > 0) {
        if total >= pixels {
            break;
        }
        total += c;
        out.push(id);
    }
    if out.is_empty() && count > 0 {
        out.push(0);
    }
    out
}

/// `(x, y, id)` of a pair key.
pub(crate) fn unpack(k: u64) -> (u32, u32, u32) {
    let pixel = k >> 32;
    let low = |v: u64, bits: u32| u32::try_from(v & ((1 << bits) - 1)).expect("masked to fit");
    (low(pixel, 14), low(pixel >> 14, 14), low(k, 32))
}

/// How a candidate's pairs depart from the reference's.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Departures {
    /// Pixels the reference or the candidate covers: every wrong pixel is one of them, so
    /// a rate of wrong pixels stays within one per pixel (a million per million).
    pub(crate) covered_pixels: u64,
    /// Pixels whose owner lists differ.
    pub(crate) wrong_pixels: u64,
    /// Samples next to a shared edge (see [`shared_edge_pixels`]), when asked for.
    pub(crate) shared_edge: u64,
    /// Of those, covered by the reference and not at all by the candidate.
    pub(crate) gaps: u64,
    /// Of those, covered twice or more by the candidate.
    pub(crate) doubles: u64,
}

/// Walks two sorted pair lists pixel by pixel. `shared_edge` (a row-major mask of a
/// `side`-wide canvas) turns on the mesh counts.
pub(crate) fn departures(reference: &Pairs, candidate: &Pairs, shared_edge: Option<(&[bool], u32)>) -> Departures {
    let (r, c) = (&reference.0, &candidate.0);
    let (mut i, mut j) = (0, 0);
    let mut d = Departures::default();
    let run = |v: &[u64], at: usize| {
        let p = v[at] >> 32;
        at + v[at..].iter().take_while(|&&k| k >> 32 == p).count()
    };
    while i < r.len() || j < c.len() {
        let pr = r.get(i).map(|k| k >> 32);
        let pc = c.get(j).map(|k| k >> 32);
        let p = match (pr, pc) {
            (Some(a), Some(b)) => a.min(b),
            (Some(a), None) => a,
            (None, Some(b)) => b,
            (None, None) => unreachable!("one list has pairs left"),
        };
        let ri = if pr == Some(p) { run(r, i) } else { i };
        let cj = if pc == Some(p) { run(c, j) } else { j };
        let (ours, theirs) = (&r[i..ri], &c[j..cj]);
        if !ours.is_empty() || !theirs.is_empty() {
            d.covered_pixels += 1;
        }
        if ours != theirs {
            d.wrong_pixels += 1;
        }
        if let Some((mask, side)) = shared_edge {
            let (x, y, _) = unpack(p << 32);
            let at = usize::try_from(u64::from(y) * u64::from(side) + u64::from(x)).expect("canvas index");
            if mask.get(at).copied().unwrap_or(false) {
                d.shared_edge += 1;
                if theirs.is_empty() {
                    d.gaps += 1;
                }
                if theirs.len() >= 2 {
                    d.doubles += 1;
                }
            }
        }
        (i, j) = (ri, cj);
    }
    d
}

/// The samples of a mesh next to a shared edge: pixels the reference covers once whose
/// 4-neighbour is covered by another primitive (where a gap or a double cover can show).
/// Pixels off `side` x `side` are ignored; the mask's own count comes back too.
pub(crate) fn shared_edge_pixels(reference: &Pairs, side: u32) -> (Vec<bool>, u64) {
    let n = usize::try_from(u64::from(side) * u64::from(side)).expect("canvas area");
    let mut owner = vec![u32::MAX; n];
    let index = |x: u32, y: u32| usize::try_from(u64::from(y) * u64::from(side) + u64::from(x)).expect("canvas");
    for &k in &reference.0 {
        let (x, y, id) = unpack(k);
        if x < side && y < side {
            owner[index(x, y)] = id;
        }
    }
    let mut mask = vec![false; n];
    let mut count = 0;
    for y in 0..side {
        for x in 0..side {
            let me = owner[index(x, y)];
            if me == u32::MAX {
                continue;
            }
            let other = |nx: u32, ny: u32| {
                let o = owner[index(nx, ny)];
                o != u32::MAX && o != me
            };
            let near = (x > 0 && other(x - 1, y))
                || (x + 1 < side && other(x + 1, y))
                || (y > 0 && other(x, y - 1))
                || (y + 1 < side && other(x, y + 1));
            if near {
                mask[index(x, y)] = true;
                count += 1;
            }
        }
    }
    (mask, count)
}

/// The metrics of a departure from the reference coverage: wrong pixels, and for meshes gaps and double covers.
pub(crate) fn departure_metrics(d: &Departures, mesh: bool) -> Vec<Metric> {
    let mut out = vec![Metric::Rate {
        name: WRONG_PIXELS,
        count: d.wrong_pixels,
        of: d.covered_pixels,
    }];
    if mesh {
        out.push(Metric::Rate {
            name: GAPS,
            count: d.gaps,
            of: d.shared_edge,
        });
        out.push(Metric::Rate {
            name: DOUBLES,
            count: d.doubles,
            of: d.shared_edge,
        });
    }
    out
}

/// The wrong-pixel metric's name: pixels whose owners differ from the exact answer, per
/// pixel the exact answer or the model covers (a model that floods the canvas where the
/// exact answer covers a few pixels is wrong on at most all of them, not on thousands of
/// times as many).
pub(crate) const WRONG_PIXELS: &str = "wrong pixels";
/// Gaps: samples next to a shared edge that no triangle covers.
pub(crate) const GAPS: &str = "gaps";
/// Double covers: samples next to a shared edge covered twice or more.
pub(crate) const DOUBLES: &str = "double covers";
/// Barycentric sums, in ulps of 1 of the model's float type.
pub(crate) const BARYCENTRIC_ULPS: &str = "barycentric sum error (ulps)";
/// Barycentric sums of an exact or integer model that miss the exact identity.
pub(crate) const BARYCENTRIC_EXACT: &str = "barycentric sums not exact";
/// Gouraud channels off the exact colour (rounded to 0..=255) by one or more.
pub(crate) const GOURAUD: &str = "Gouraud channels off";
/// Line pixels farther than 1/2 px from the ideal line on the minor axis.
pub(crate) const LINE_HALF_PIXEL: &str = "line pixels > 1/2 px off";
/// Line pixels that differ from the exact reference (ties included).
pub(crate) const LINE_REFERENCE: &str = "line pixels off the reference";
/// Clipped vertices outside the window (exactly; a non-finite one counts).
pub(crate) const CLIP_OUTSIDE: &str = "clipped vertices outside";

/// The median and the largest of `values` (0, 0 when empty).
pub(crate) fn median_max(values: &mut [f64]) -> (f64, f64) {
    if values.is_empty() {
        return (0.0, 0.0);
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    let median = if n % 2 == 1 {
        values[n / 2]
    } else {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    };
    (median, values[n - 1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::differing_pixels;
    use crate::coverage::Coverage;

    fn both(cover: &[(u32, u32, u32)]) -> (Pairs, Coverage) {
        let mut p = Pairs::default();
        let mut c = Coverage::new(16, 16);
        for &(x, y, id) in cover {
            p.cover(x, y, id);
            c.cover(x, y, id);
        }
        (p.sorted(), c)
    }

    /// A model that floods a 10x10 canvas where the exact answer covers one pixel is wrong
    /// on 99 of the 100 pixels either covers: 990,000 per million, not 99 million.
    #[test]
    fn a_flood_is_wrong_on_at_most_every_pixel() {
        let (rp, _) = both(&[(0, 0, 0)]);
        let flood: Vec<(u32, u32, u32)> = (0..10).flat_map(|y| (0..10).map(move |x| (x, y, 0))).collect();
        let (cp, _) = both(&flood);
        let metrics = departure_metrics(&departures(&rp, &cp, None), false);
        assert_eq!(metrics[0].per_million(), Some(990_000.0));
    }

    #[test]
    fn wrong_pixels_are_differing_pixels() {
        let reference = [(0, 0, 0), (1, 0, 0), (2, 0, 1), (1, 0, 1), (5, 5, 2), (15, 15, 3)];
        let candidate = [
            (0, 0, 0),
            (1, 0, 1),
            (2, 0, 1),
            (2, 0, 1),
            (6, 5, 2),
            (15, 15, 3),
            (0, 15, 9),
        ];
        let (rp, rc) = both(&reference);
        let (cp, cc) = both(&candidate);
        let d = departures(&rp, &cp, None);
        assert_eq!(d.wrong_pixels, differing_pixels(&rc, &cc).len() as u64);
        assert_eq!(d.wrong_pixels, 5); // (1,0) (2,0) (5,5) (6,5) (0,15)
                                       // Covered by either: the reference's 5 pixels, and the candidate's (6,5) and (0,15).
        assert_eq!(d.covered_pixels, 7);
        assert_eq!(departures(&rp, &rp, None).wrong_pixels, 0);
    }

    #[test]
    fn mesh_counts_gaps_and_doubles_next_to_shared_edges() {
        // Two "triangles" side by side: id 0 on x = 0..=1, id 1 on x = 2..=3, row 0.
        let reference = [(0, 0, 0), (1, 0, 0), (2, 0, 1), (3, 0, 1)];
        let (rp, _) = both(&reference);
        let (mask, n) = shared_edge_pixels(&rp, 16);
        assert_eq!(n, 2, "(1,0) and (2,0) touch the other triangle");
        assert!(mask[1] && mask[2] && !mask[0] && !mask[3]);
        // The candidate misses (1,0) and covers (2,0) twice.
        let (cp, _) = both(&[(0, 0, 0), (2, 0, 0), (2, 0, 1), (3, 0, 1)]);
        let d = departures(&rp, &cp, Some((&mask, 16)));
        assert_eq!((d.shared_edge, d.gaps, d.doubles, d.wrong_pixels), (2, 1, 1, 2));
    }

    #[test]
    fn spread_and_unpack() {
        let (p, _) = both(&[(3, 7, 11), (16 - 1, 16 - 1, u32::MAX - 5)]);
        assert_eq!(p.spread(10), vec![(3, 7, 11), (15, 15, u32::MAX - 5)]);
        assert_eq!(p.spread(1), vec![(3, 7, 11)]);
        let mut v = vec![3.0, 1.0, 2.0, 10.0];
        assert_eq!(median_max(&mut v), (2.5, 10.0));
    }
}
