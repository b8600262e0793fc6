//! The invariant suite as a library (`rasterproof::harness::suite`): what `run_case`
//! checks on generated cases (and what it skips, with the reason), and the table `Tally`
//! renders from hand-built outcomes, with its legend.

use std::collections::BTreeSet;

use num_rational::BigRational;
use rasterproof::check::Violation;
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::harness::suite::{legend, Row, Skip};
use rasterproof::harness::{generate, must_hold, run_case, CaseRun, CheckOutcome, Tally};
use rasterproof::model::Model;
use rasterproof::scene::Scene;

/// Every (invariant, model) row of `rasterproof check --cases 300 --seed 7`, copied from
/// its table.
const TABLE_ROWS: [(&str, &str); 55] = [
    ("agreement (fine mesh)", "float32"),
    ("agreement (fine mesh)", "float64"),
    ("agreement (mesh)", "exact"),
    ("agreement (mesh)", "exact-snapped"),
    ("agreement (mesh)", "fixed"),
    ("agreement (mesh)", "float32"),
    ("agreement (mesh)", "float32-naive"),
    ("agreement (mesh)", "float64"),
    ("agreement (mesh)", "scanline"),
    ("agreement (triangle)", "exact"),
    ("agreement (triangle)", "exact-snapped"),
    ("agreement (triangle)", "fixed"),
    ("agreement (triangle)", "scanline"),
    ("barycentric sum", "exact"),
    ("clip agreement", "exact"),
    ("clip agreement", "exact-snapped"),
    ("clip inside", "sh-f32"),
    ("clip inside", "sh-f64"),
    ("clip inside", "sutherland-hodgman"),
    ("clip raster", "sutherland-hodgman"),
    ("diamond agreement", "diamond"),
    ("diamond agreement", "exact"),
    ("diamond agreement", "exact-snapped"),
    ("integer edge sum", "fixed"),
    ("line pixels", "bresenham/stay"),
    ("line pixels", "bresenham/step"),
    ("line pixels (long)", "dda32"),
    ("line pixels (long)", "dda64"),
    ("line reference", "bresenham/stay"),
    ("line reference", "bresenham/step"),
    ("line symmetry", "bresenham/stay"),
    ("line symmetry", "bresenham/step"),
    ("polygon agreement", "exact"),
    ("polygon agreement", "exact-snapped"),
    ("polygon agreement", "scanline"),
    ("rotation/winding", "exact-snapped"),
    ("rotation/winding", "fixed"),
    ("rotation/winding", "float32"),
    ("segment clip", "cohen-sutherland"),
    ("translation", "exact-snapped"),
    ("translation", "fixed"),
    ("triangulation", "fixed"),
    ("watertight", "exact"),
    ("watertight", "exact-snapped"),
    ("watertight", "fixed"),
    ("watertight", "float32"),
    ("watertight", "float32-naive"),
    ("watertight", "float64"),
    ("watertight", "scanline"),
    ("watertight (4x)", "exact"),
    ("watertight (4x)", "exact-snapped"),
    ("watertight (4x)", "fixed"),
    ("watertight (4x)", "scanline"),
    ("watertight (fine mesh)", "float32"),
    ("watertight (fine mesh)", "float64"),
];

/// One case of each mesh family (k % 3) checks every row of the table, and the exact and
/// integer models hold on all of them; each row is either checked or skipped, once per
/// case.
#[test]
fn run_case_checks_every_row_of_the_table_and_the_must_hold_models_hold() {
    let mut seen = BTreeSet::new();
    let mut families = BTreeSet::new();
    for k in 0..3 {
        let case = generate(7, k).unwrap();
        let run = run_case(&case);
        assert_eq!(run.mesh_family, case.mesh_family);
        families.insert(run.mesh_family);
        assert_eq!(run.float32_sum_ulps.len(), 3, "case {k}: one error per sample");
        assert_eq!(run.float32_sum_skipped, 0, "case {k}");
        let mut rows: Vec<_> = run
            .outcomes
            .iter()
            .map(|o| (o.invariant, o.label))
            .chain(run.skipped.iter().map(|s| (s.invariant, s.label)))
            .collect();
        rows.sort_unstable();
        assert_eq!(rows, TABLE_ROWS, "case {k}: every row once, checked or skipped");
        for o in &run.outcomes {
            seen.insert((o.invariant, o.label));
            if must_hold(o.model) {
                assert_eq!(o.result, Ok(()), "case {k}: {} ({})", o.invariant, o.label);
                assert!(o.repro().is_none());
            }
            assert_eq!(o.scene.preset, case.preset, "case {k}: {} ({})", o.invariant, o.label);
        }
    }
    let expected: BTreeSet<_> = TABLE_ROWS.into_iter().collect();
    assert_eq!(seen, expected);
    assert_eq!(
        families,
        BTreeSet::from(["far-from-origin mesh", "random mesh", "tie-heavy mesh"])
    );
}

/// The legend explains every invariant and model label of the table, and every column.
#[test]
fn the_legend_knows_every_name_in_the_table() {
    for (invariant, label) in TABLE_ROWS {
        assert!(legend::describe(invariant).is_some(), "{invariant}");
        assert!(legend::describe(label).is_some(), "{label}");
    }
    for term in ["cases", "violations", "skipped", "by family", "ulps of 1"] {
        assert!(legend::describe(term).is_some(), "{term}");
    }
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// A simple polygon that snapping to the 1/256 px grid folds: the arrowhead (0,0) (8,0)
/// (4, 1/1000) (4, 1/500) is simple (its last edge, y = x/2000, passes above (4, 1/1000)),
/// but 1/1000 px is 0.256 subpixels and rounds to 0, and 1/500 px is 0.512 and rounds to 1,
/// so the snapped outline (0,0) (8,0) (4,0) (4,1/256) runs back along its own first edge.
/// The triangulation cannot run on it: a skip with its reason, no outcome.
#[test]
fn a_folded_simple_polygon_skips_the_triangulation_with_its_reason() {
    let mut case = generate(7, 0).unwrap();
    case.simple = Polygon::new(
        vec![
            Point::from_ints(0, 0),
            Point::from_ints(8, 0),
            Point::new(q(4, 1), q(1, 1000)),
            Point::new(q(4, 1), q(1, 500)),
        ],
        FillRule::NonZero,
    );
    let run = run_case(&case);
    assert_eq!(
        run.skipped,
        [Skip {
            invariant: "triangulation",
            model: Model::Fixed,
            label: "fixed",
            reason: "snapping folded the polygon (not simple on the subpixel grid)",
        }]
    );
    assert!(run.outcomes.iter().all(|o| o.invariant != "triangulation"));
    // The 8 x 8 square snaps to itself: triangulated and checked.
    case.simple = Polygon::new(
        vec![
            Point::from_ints(0, 0),
            Point::from_ints(8, 0),
            Point::from_ints(8, 8),
            Point::from_ints(0, 8),
        ],
        FillRule::NonZero,
    );
    let run = run_case(&case);
    assert_eq!(run.skipped, []);
    let t: Vec<_> = run.outcomes.iter().filter(|o| o.invariant == "triangulation").collect();
    assert_eq!(t.len(), 1);
    assert_eq!(t[0].result, Ok(()));
}

/// A zero-area triangle has no barycentrics: the exact sum check would pass vacuously, so
/// it is skipped, and the float32 sum error is not measured at its 3 samples (its f32
/// area is 0 too: (0,0) (4,4) (8,8) are exact in f32).
#[test]
fn a_zero_area_triangle_skips_the_barycentric_checks() {
    let mut case = generate(7, 1).unwrap();
    case.triangle = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 4), Point::from_ints(8, 8));
    let run = run_case(&case);
    assert_eq!(
        run.skipped,
        [Skip {
            invariant: "barycentric sum",
            model: Model::Exact,
            label: "exact",
            reason: "the triangle has zero area (no barycentrics)",
        }]
    );
    assert_eq!((run.float32_sum_ulps.len(), run.float32_sum_skipped), (0, 3));
    // The integer sum still runs: the three edge values sum to 0 = twice the area.
    let sum: Vec<_> = run
        .outcomes
        .iter()
        .filter(|o| o.invariant == "integer edge sum")
        .collect();
    assert_eq!(sum.len(), 1);
    assert_eq!(sum[0].result, Ok(()));
}

/// The same seed and case number give the same case; another case number another one.
#[test]
fn generate_is_a_function_of_seed_and_case_number() {
    assert_eq!(generate(11, 4).unwrap(), generate(11, 4).unwrap());
    assert_ne!(generate(11, 4).unwrap(), generate(11, 5).unwrap());
}

fn outcome(model: Model, result: Result<(), Violation>) -> CheckOutcome {
    CheckOutcome {
        invariant: "watertight",
        model,
        label: model.name(),
        result,
        scene: Scene::new(4, 4, Vec::new()),
    }
}

fn gap() -> Result<(), Violation> {
    Err(Violation::new("watertight", "sample (1, 2) covered by no triangle"))
}

fn run(mesh_family: &'static str, outcomes: Vec<CheckOutcome>, ulps: Vec<f64>) -> CaseRun {
    CaseRun {
        mesh_family,
        outcomes,
        skipped: Vec::new(),
        float32_sum_ulps: ulps,
        float32_sum_skipped: 0,
    }
}

/// The legend of a table of watertight rows for fixed and float32-naive, written out: the
/// columns (with the family and ulps lines' terms when those lines are there), the
/// invariant, the models.
fn watertight_legend(families: bool, ulps: bool) -> Vec<&'static str> {
    let mut lines = vec![
        "legend:",
        " columns:",
        "  cases                    cases on which the check ran for that model",
        "  violations               cases on which it failed: fatal for the exact and integer models; float: the trade",
        "  skipped                  cases on which it could not run (reasons above); cases + skipped = the run's cases",
    ];
    if families {
        lines.push("  by family                watertight + agreement (mesh) violations by the case's mesh: random, tie-heavy, far-from-origin");
    }
    if ulps {
        lines.push(
            "  ulps of 1                |l0 + l1 + l2 - 1| of f32 barycentrics, in f32::EPSILON = 2^-23 (f32's step at 1)",
        );
    }
    lines.extend([
        " invariants:",
        "  watertight               a mesh covers each sample inside its outline exactly once, none outside (no gap, overlap)",
        " models:",
        "  fixed                    i64 edge functions in blocks (alias bresenham); polygons triangulated (simple only)",
        "  float32-naive            f32 with the naive w >= 0 test; polygons by the PNPOLY crossing test",
    ]);
    lines
}

/// Two outcomes, the float one failing: a row each, the family count, the error summary,
/// and the run passes (float violations are the measured trade).
#[test]
fn tally_of_a_float_violation_counts_it_and_passes() {
    let mut tally = Tally::new(5);
    tally.add(&run(
        "tie-heavy mesh",
        vec![outcome(Model::Fixed, Ok(())), outcome(Model::Float32Naive, gap())],
        vec![3.0, 1.0, 2.0],
    ));
    let mut expected = vec![
        "rasterproof check: 1 case, seed 5, presets d3d11/gl",
        "invariant                model                cases violations skipped",
        "watertight               fixed                    1          0       0",
        "watertight               float32-naive            1          1       0",
        "mesh violations by family:",
        "  tie-heavy mesh         float32-naive          1",
        "float32 barycentric sum error, ulps of 1 (3 samples): median 2.0, mean 2.0, max 3.0 \
         (the float32 model's measured rounding, not a failure: it grows on thin and far-from-origin \
         triangles, whose f32 edge values cancel; the exact models' sum is exactly 1)",
    ];
    expected.extend(watertight_legend(true, true));
    expected.push("ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant");
    assert_eq!(tally.lines(), expected);
    assert!(tally.passed());
    assert_eq!(tally.to_string(), tally.lines().join("\n") + "\n");
}

/// A second case where `fixed` fails: its row counts two cases and one violation, the
/// families sort by name, and the run fails with one fatal violation.
#[test]
fn tally_of_a_fixed_violation_fails_the_run() {
    let mut tally = Tally::new(5);
    tally.add(&run(
        "tie-heavy mesh",
        vec![outcome(Model::Fixed, Ok(())), outcome(Model::Float32Naive, gap())],
        Vec::new(),
    ));
    let failing = outcome(Model::Fixed, gap());
    assert!(failing.is_fatal());
    let (scene, v) = failing.repro().unwrap();
    assert_eq!((scene.width, v.invariant), (4, "watertight"));
    tally.add(&run("random mesh", vec![failing], Vec::new()));
    let mut expected = vec![
        "rasterproof check: 2 cases, seed 5, presets d3d11/gl",
        "invariant                model                cases violations skipped",
        "watertight               fixed                    2          1       0",
        "watertight               float32-naive            1          1       0",
        "mesh violations by family:",
        "  random mesh            fixed                  1",
        "  tie-heavy mesh         float32-naive          1",
    ];
    expected.extend(watertight_legend(true, false));
    expected.push("FAILED: 1 violations by an exact or integer model (exact, exact-snapped, fixed, scanline)");
    assert_eq!(tally.lines(), expected);
    assert_eq!(tally.fatal(), 1);
    assert!(!tally.passed());
    let row = |label, cases, violations| Row {
        invariant: "watertight",
        label,
        cases,
        violations,
        skipped: 0,
    };
    assert_eq!(
        tally.rows().collect::<Vec<_>>(),
        [row("fixed", 2, 1), row("float32-naive", 1, 1)]
    );
}

/// Skipped checks: a column of the table (a row may be all skipped: 0 cases), one line per
/// (row, reason) under it, sorted; unmeasured float32 sums are counted on the error line.
/// Three cases: the first checks watertight on fixed, the second skips it (and
/// float32-naive's) for a reason, the third skips it for another: 1 case + 2 skipped.
#[test]
fn tally_of_skipped_checks_counts_them_with_their_reasons() {
    let skip = |reason| Skip {
        invariant: "watertight",
        model: Model::Fixed,
        label: "fixed",
        reason,
    };
    let mut tally = Tally::new(9);
    tally.add(&run("random mesh", vec![outcome(Model::Fixed, Ok(()))], vec![1.0]));
    let mut second = run("random mesh", Vec::new(), Vec::new());
    second.skipped = vec![
        skip("the mesh is outside the integer envelope"),
        Skip {
            model: Model::Float32Naive,
            label: "float32-naive",
            ..skip("the mesh does not fit f32")
        },
    ];
    second.float32_sum_skipped = 3;
    tally.add(&second);
    let mut third = run("random mesh", Vec::new(), Vec::new());
    third.skipped = vec![skip("the mesh is empty")];
    tally.add(&third);
    let mut expected = vec![
        "rasterproof check: 3 cases, seed 9, presets d3d11/gl",
        "invariant                model                cases violations skipped",
        "watertight               fixed                    1          0       2",
        "watertight               float32-naive            0          0       1",
        "skipped (the check could not run on the case):",
        "  watertight             fixed                  1: the mesh is empty",
        "  watertight             fixed                  1: the mesh is outside the integer envelope",
        "  watertight             float32-naive          1: the mesh does not fit f32",
        "float32 barycentric sum error, ulps of 1 (1 sample, 3 skipped: the triangle has zero area in f32 or does not fit it): \
         median 1.0, mean 1.0, max 1.0 (the float32 model's measured rounding, not a failure: it grows on thin and \
         far-from-origin triangles, whose f32 edge values cancel; the exact models' sum is exactly 1)",
    ];
    expected.extend(watertight_legend(false, true));
    expected.push("ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant");
    assert_eq!(tally.lines(), expected);
    assert_eq!(
        tally.skip_reasons().collect::<Vec<_>>(),
        [
            ("watertight", "fixed", "the mesh is empty", 1),
            ("watertight", "fixed", "the mesh is outside the integer envelope", 1),
            ("watertight", "float32-naive", "the mesh does not fit f32", 1),
        ]
    );
    assert!(tally.passed());
}

/// A run whose every float32 sum was unmeasurable says so instead of printing no line.
#[test]
fn tally_of_unmeasured_float32_sums_says_so() {
    let mut tally = Tally::new(1);
    let mut only = run("random mesh", vec![outcome(Model::Fixed, Ok(()))], Vec::new());
    only.float32_sum_skipped = 3;
    tally.add(&only);
    assert!(tally.lines().contains(
        &"float32 barycentric sum error: not measured (3 samples skipped: the triangle has zero area in f32 or does not fit it)"
            .to_string()
    ));
    assert!(!tally.lines().iter().any(|l| l.starts_with("  ulps of 1")));
}
