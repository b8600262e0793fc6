//! Model agreement: two models agree pixel for pixel (fixed == exact-snapped; float against
//! exact, where the differences are the float trade).

use std::collections::BTreeSet;
use std::fmt::Write as _;

use super::explain::explain_sample;
use super::Violation;
use crate::convention::Target;
use crate::coverage::Coverage;
use crate::geom::Triangle;

/// One pixel where two coverages differ.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PixelDiff {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// Owners in the reference.
    pub reference: Vec<u32>,
    /// Owners in the candidate.
    pub candidate: Vec<u32>,
}

/// Every pixel whose owner lists differ, row-major.
pub fn differing_pixels(reference: &Coverage, candidate: &Coverage) -> Vec<PixelDiff> {
    let mut keys: Vec<(u32, u32)> = reference
        .iter()
        .chain(candidate.iter())
        .map(|(x, y, _)| (y, x))
        .collect();
    keys.sort_unstable();
    keys.dedup();
    keys.into_iter()
        .filter_map(|(y, x)| {
            let (a, b) = (reference.owners(x, y), candidate.owners(x, y));
            (a != b).then(|| PixelDiff {
                x,
                y,
                reference: a.to_vec(),
                candidate: b.to_vec(),
            })
        })
        .collect()
}

/// `candidate` equals `reference` pixel for pixel. The violation names the first differing
/// pixel and explains it with the exact edge values of each triangle involved (computed
/// on `triangles`, the form the reference model saw).
pub fn check_agreement(
    reference_name: &str,
    reference: &Coverage,
    candidate_name: &str,
    candidate: &Coverage,
    triangles: &[Triangle],
    target: &Target,
) -> Result<(), Violation> {
    let diffs = differing_pixels(reference, candidate);
    let Some(d) = diffs.first() else {
        return Ok(());
    };
    let mut msg = format!(
        "{} differing pixels; first ({}, {}): {reference_name} {:?}, {candidate_name} {:?}",
        diffs.len(),
        d.x,
        d.y,
        d.reference,
        d.candidate
    );
    // Each id once, ascending (the two owner lists are sorted each, not together).
    let involved: BTreeSet<u32> = d.reference.iter().chain(&d.candidate).copied().collect();
    for id in involved {
        if let Some(t) = triangles.get(id as usize) {
            let _ = write!(msg, "\n  triangle {id}: {}", explain_sample(t, d.x, d.y, target));
        }
    }
    Err(Violation::new("agreement", msg))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::coverage::CoverageSink;
    use crate::geom::Point;

    /// The reference says (0, 0) belongs to triangles 0 and 1, the candidate says 0 alone:
    /// the involved ids are 0, 1 and 0 again, which a plain `dedup` (adjacent repeats only)
    /// keeps as [0, 1, 0]. Each triangle is explained once, in id order.
    #[test]
    fn each_involved_triangle_is_explained_once() {
        let target = Target::new(2, 2, Convention::default()).unwrap();
        let t = |x: i64| {
            Triangle::new(
                Point::from_ints(x, 0),
                Point::from_ints(x + 2, 0),
                Point::from_ints(x, 2),
            )
        };
        let triangles = [t(0), t(1)];
        let mut reference = Coverage::new(2, 2);
        reference.cover(0, 0, 0);
        reference.cover(0, 0, 1);
        let mut candidate = Coverage::new(2, 2);
        candidate.cover(0, 0, 0);
        let v = check_agreement("ref", &reference, "cand", &candidate, &triangles, &target).unwrap_err();
        assert_eq!(v.message.matches("triangle 0:").count(), 1, "{}", v.message);
        assert_eq!(v.message.matches("triangle 1:").count(), 1, "{}", v.message);
        let (zero, one) = (
            v.message.find("triangle 0:").unwrap(),
            v.message.find("triangle 1:").unwrap(),
        );
        assert!(zero < one, "{}", v.message);
    }
}
