//! The line invariants: Bresenham pixels lie within 1/2 pixel of the ideal line on the minor
//! axis, one per major step, endpoints included, 8-connected, none twice; they equal the
//! exact reference except at exact ties, where they follow the convention; `a -> b` and
//! `b -> a` differ only at ties. The integer diamond-exit model equals the exact reading.

use super::{differing_pixels, Violation};
use crate::convention::Target;
use crate::line::exact::{ideal, resolve, IdealLine};
use crate::line::{bresenham, Axes, BresenhamTie, Line, LineRule};
use crate::model::{render, Model, Primitives};
use crate::num::exact::exact_text;

fn fail(invariant: &'static str, message: String) -> Result<(), Violation> {
    Err(Violation::new(invariant, message))
}

/// The model-independent pixel invariants of a line from pixel `from` to pixel `to`:
/// `max(|dx|, |dy|) + 1` pixels, the first `from`, the last `to`, one per step of the major
/// axis in order, consecutive pixels 8-connected, no pixel twice, and each within 1/2 pixel
/// of the ideal line on the minor axis (checked in exact rationals).
pub fn check_line_pixels(from: [i64; 2], to: [i64; 2], pixels: &[[i64; 2]]) -> Result<(), Violation> {
    let line = ideal(from, to);
    let n = line.steps.len();
    let name = "line pixels";
    if pixels.len() != n {
        return fail(
            name,
            format!(
                "{from:?} -> {to:?}: {} pixels, expected max(|dx|, |dy|) + 1 = {n}",
                pixels.len()
            ),
        );
    }
    if pixels.first() != Some(&from) || pixels.last() != Some(&to) {
        return fail(
            name,
            format!(
                "{from:?} -> {to:?}: endpoints not included: first {:?}, last {:?}",
                pixels[0],
                pixels[n - 1]
            ),
        );
    }
    for (k, (p, step)) in pixels.iter().zip(&line.steps).enumerate() {
        let (major, minor) = line.axes.split(*p);
        if major != step.major {
            return fail(
                name,
                format!(
                    "{from:?} -> {to:?}: pixel {k} {p:?} is not on major step {}",
                    step.major
                ),
            );
        }
        if !step.candidates.contains(&minor) {
            return fail(
                name,
                format!(
                    "{from:?} -> {to:?}: pixel {k} {p:?} is {} from the ideal line (minor {}), more than 1/2",
                    exact_text(&(&step.minor - num_rational::BigRational::from_integer(minor.into()))),
                    exact_text(&step.minor)
                ),
            );
        }
        if k > 0 {
            let q = pixels[k - 1];
            if (p[0] - q[0]).abs().max((p[1] - q[1]).abs()) != 1 {
                return fail(
                    name,
                    format!("{from:?} -> {to:?}: pixels {q:?} and {p:?} are not 8-connected"),
                );
            }
        }
    }
    // No pixel twice: each pixel sits on its own major step, and the steps' major
    // coordinates are distinct, so the loop above already rules repeats out.
    Ok(())
}

/// `pixels` equal the exact reference for `tie` (the one candidate within 1/2 of the ideal
/// line, or at an exact tie the convention's choice). The violation names the step, the
/// exact ideal position and the candidates.
pub fn check_line_reference(
    from: [i64; 2],
    to: [i64; 2],
    tie: BresenhamTie,
    pixels: &[[i64; 2]],
) -> Result<(), Violation> {
    let line = ideal(from, to);
    let expected = resolve(&line, tie);
    match expected.iter().zip(pixels).position(|(e, p)| e != p) {
        None if expected.len() == pixels.len() => Ok(()),
        None => fail(
            "line reference",
            format!(
                "{from:?} -> {to:?}: {} pixels, reference has {}",
                pixels.len(),
                expected.len()
            ),
        ),
        Some(k) => fail(
            "line reference",
            format!(
                "{from:?} -> {to:?} ({}): step {k} drew {:?}, reference {:?}; ideal minor {} (candidates {:?})",
                tie.name(),
                pixels[k],
                expected[k],
                exact_text(&line.steps[k].minor),
                line.steps[k].candidates
            ),
        ),
    }
}

/// How `a -> b` and `b -> a` differ.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SymmetryReport {
    /// Exact ties of the ideal line (steps with two candidates).
    pub ties: usize,
    /// Pixels of `a -> b` that `b -> a` does not draw: each at a tie.
    pub differing: Vec<[i64; 2]>,
}

/// Bresenham `a -> b` versus `b -> a`: they may differ only at exact ties of the ideal
/// line. Reports which pixels differ; a difference at a non-tie is the violation.
pub fn check_line_symmetry(from: [i64; 2], to: [i64; 2], tie: BresenhamTie) -> Result<SymmetryReport, Violation> {
    let forward = bresenham::pixels(from, to, tie);
    let mut backward = bresenham::pixels(to, from, tie);
    backward.reverse();
    let line: IdealLine = ideal(from, to);
    let ties = line.steps.iter().filter(|s| s.candidates.len() == 2).count();
    let mut differing = Vec::new();
    for (k, (f, b)) in forward.iter().zip(&backward).enumerate() {
        if f != b {
            if line.steps[k].candidates.len() != 2 {
                return Err(Violation::new(
                    "line symmetry",
                    format!(
                        "{from:?} <-> {to:?}: step {k} differs ({f:?} vs {b:?}) where the ideal line is no tie ({})",
                        exact_text(&line.steps[k].minor)
                    ),
                ));
            }
            differing.push(*f);
        }
    }
    Ok(SymmetryReport { ties, differing })
}

/// How many pixels of `pixels` (one per major step, as the DDA draws them) are not within
/// 1/2 pixel of the ideal line on the minor axis: the float models' departures.
pub fn line_departures(from: [i64; 2], to: [i64; 2], pixels: &[[i64; 2]]) -> usize {
    let line = ideal(from, to);
    let axes: Axes = line.axes;
    pixels
        .iter()
        .zip(&line.steps)
        .filter(|(p, step)| {
            let (major, minor) = axes.split(**p);
            major != step.major || !step.candidates.contains(&minor)
        })
        .count()
        + line.steps.len().abs_diff(pixels.len())
}

/// A diamond-exit line drawn by `model` equals its plain oracle ([`Model::reference`]:
/// the exact reading on the snapped line for `fixed` and `exact-snapped`, on the line as
/// written for `exact`), pixel for pixel. Lines of other rules are Ok.
pub fn check_diamond_agreement(line: &Line, model: Model, target: &Target) -> Result<(), Violation> {
    if line.rule != LineRule::Diamond {
        return Ok(());
    }
    let primitives = Primitives {
        lines: vec![line.clone()],
        ..Primitives::default()
    };
    let render = |m| render(&primitives, target, m).map_err(|e| Violation::new("diamond agreement", e.to_string()));
    let reference = model.reference();
    let (exact, theirs) = (render(reference)?, render(model)?);
    match differing_pixels(&exact, &theirs).first() {
        None => Ok(()),
        Some(d) => fail(
            "diamond agreement",
            format!(
                "{} -> {}: pixel ({}, {}): {reference} {:?}, {model} {:?}",
                line.from, line.to, d.x, d.y, d.reference, d.candidate
            ),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A line drawn one pixel off: the explanation names the pixels it has at its ends,
    /// as values (not as Rust's `Some(..)`).
    #[test]
    fn missing_endpoints_are_named_by_their_pixels() {
        let shifted = [[1, 0], [2, 0], [3, 0], [4, 0]];
        let v = check_line_pixels([0, 0], [3, 0], &shifted).unwrap_err();
        assert!(
            v.to_string()
                .contains("[0, 0] -> [3, 0]: endpoints not included: first [1, 0], last [4, 0]"),
            "{v}"
        );
    }
}
