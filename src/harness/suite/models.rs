//! Which models each check of the suite runs on, derived from [`Model::ALL`] by the
//! property of the model's arithmetic that decides membership, so that a new model joins
//! the checks its arithmetic calls for instead of silently staying out of the table.
//! Each list is in the order the checks run (the order of the failures within a case).

use crate::model::Model;
use crate::tri::float::FloatRule;

/// The models under test: every model but the plain oracles ([`Model::is_plain`], the
/// references the others are checked against), in [`Model::ALL`] order.
fn under_test() -> impl DoubleEndedIterator<Item = Model> {
    Model::ALL.into_iter().filter(|&m| !m.is_plain())
}

/// The first model of each arithmetic (exact, integer, float) among those `keep` takes:
/// the invariance checks' samples of each arithmetic.
fn one_per_arithmetic(keep: impl Fn(Model) -> bool) -> Vec<Model> {
    let mut out: Vec<Model> = Vec::new();
    for m in under_test().filter(|&m| keep(m)) {
        if !out.iter().any(|o| o.same_arithmetic(m)) {
            out.push(m);
        }
    }
    out
}

/// The watertightness and agreement invariants on the case's mesh: every model under
/// test but `float64-naive`, which the table has never had a mesh row for (drop the
/// exception to add its rows).
pub(super) fn mesh() -> Vec<Model> {
    under_test().filter(|&m| m != Model::Float64Naive).collect()
}

/// The same on the fine far-from-origin mesh: the float models with the tie rule (the
/// exact and integer models hold there by construction; the naive ones fail everywhere).
pub(super) fn fine_mesh() -> Vec<Model> {
    under_test()
        .filter(|m| m.float_rule() == Some(FloatRule::WithTieRule))
        .collect()
}

/// The models that must hold every invariant ([`super::must_hold`]), the plain oracles
/// aside: the agreement invariant on the case's single triangle.
pub(super) fn must_hold() -> Vec<Model> {
    under_test().filter(|&m| super::must_hold(m)).collect()
}

/// The rotation and winding invariance: one model of each arithmetic, the first that
/// draws the snapped scene (an exact or integer model) or a float model.
pub(super) fn rotation() -> Vec<Model> {
    one_per_arithmetic(|m| m.snaps() || !m.is_exact())
}

/// The whole-pixel translation invariance: one model of each arithmetic that draws the
/// snapped scene (float models are not translation-invariant).
pub(super) fn translation() -> Vec<Model> {
    one_per_arithmetic(Model::snaps)
}

/// The clipped polygon drawn by the planned engines ([`Model::plans`]) against the plain
/// oracle.
pub(super) fn clip_agreement() -> Vec<Model> {
    under_test().filter(|&m| m.plans()).collect()
}

/// The polygon agreement invariant: the must-hold polygon fillers of any polygon (`fixed`
/// triangulates simple polygons only: its own check), the integer filler first, then the
/// planned engines (the reverse of [`Model::ALL`]).
pub(super) fn polygon_agreement() -> Vec<Model> {
    under_test()
        .rev()
        .filter(|&m| super::must_hold(m))
        .filter(|m| !m.triangulates_polygons())
        .collect()
}

/// The diamond-exit agreement: the must-hold models, the integer ones once (the first:
/// they share one walk), the integer walk first, then the planned engines (the reverse
/// of [`Model::ALL`]).
pub(super) fn diamond() -> Vec<Model> {
    let mut out: Vec<Model> = Vec::new();
    for m in under_test().filter(|&m| super::must_hold(m)) {
        if !(m.is_integer() && out.iter().any(|&o| o.is_integer())) {
            out.push(m);
        }
    }
    out.reverse();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(models: Vec<Model>) -> Vec<&'static str> {
        models.into_iter().map(Model::name).collect()
    }

    /// The derived lists are the suite's lists as they were written by hand, in order.
    #[test]
    fn the_lists_are_the_suites() {
        assert_eq!(
            names(mesh()),
            [
                "exact",
                "exact-snapped",
                "fixed",
                "scanline",
                "float32",
                "float64",
                "float32-naive"
            ]
        );
        assert_eq!(names(fine_mesh()), ["float32", "float64"]);
        assert_eq!(names(must_hold()), ["exact", "exact-snapped", "fixed", "scanline"]);
        assert_eq!(names(rotation()), ["exact-snapped", "fixed", "float32"]);
        assert_eq!(names(translation()), ["exact-snapped", "fixed"]);
        assert_eq!(names(clip_agreement()), ["exact", "exact-snapped"]);
        assert_eq!(names(polygon_agreement()), ["scanline", "exact-snapped", "exact"]);
        assert_eq!(names(diamond()), ["fixed", "exact-snapped", "exact"]);
    }
}
