//! The invariant suite as a library (`rasterproof::harness::suite`): what `run_case`
//! checks on generated cases, and the table `Tally` renders from hand-built outcomes.

use std::collections::BTreeSet;

use rasterproof::check::Violation;
use rasterproof::harness::{generate, must_hold, run_case, CaseRun, Outcome, Tally};
use rasterproof::model::Model;
use rasterproof::scene::Scene;

/// Every (invariant, model) row of `rasterproof check --cases 300 --seed 7`, copied from
/// its table.
const TABLE_ROWS: [(&str, &str); 41] = [
    ("agreement (fine mesh)", "float32"),
    ("agreement (fine mesh)", "float64"),
    ("agreement (mesh)", "exact-snapped"),
    ("agreement (mesh)", "fixed"),
    ("agreement (mesh)", "float32"),
    ("agreement (mesh)", "float32-naive"),
    ("agreement (mesh)", "float64"),
    ("agreement (mesh)", "scanline"),
    ("agreement (triangle)", "fixed"),
    ("agreement (triangle)", "scanline"),
    ("barycentric sum", "exact"),
    ("clip inside", "sh-f32"),
    ("clip inside", "sh-f64"),
    ("clip inside", "sutherland-hodgman"),
    ("clip raster", "sutherland-hodgman"),
    ("diamond agreement", "diamond"),
    ("integer edge sum", "fixed"),
    ("line pixels", "bresenham/stay"),
    ("line pixels", "bresenham/step"),
    ("line pixels (long)", "dda32"),
    ("line pixels (long)", "dda64"),
    ("line reference", "bresenham/stay"),
    ("line reference", "bresenham/step"),
    ("line symmetry", "bresenham/stay"),
    ("line symmetry", "bresenham/step"),
    ("polygon agreement", "scanline"),
    ("rotation/winding", "exact-snapped"),
    ("rotation/winding", "fixed"),
    ("rotation/winding", "float32"),
    ("segment clip", "cohen-sutherland"),
    ("translation", "exact-snapped"),
    ("translation", "fixed"),
    ("triangulation", "fixed"),
    ("watertight", "exact-snapped"),
    ("watertight", "fixed"),
    ("watertight", "float32"),
    ("watertight", "float32-naive"),
    ("watertight", "float64"),
    ("watertight", "scanline"),
    ("watertight (fine mesh)", "float32"),
    ("watertight (fine mesh)", "float64"),
];

/// One case of each mesh family (k % 3) checks every row of the table, and the exact and
/// integer models hold on all of them.
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

/// The same seed and case number give the same case; another case number another one.
#[test]
fn generate_is_a_function_of_seed_and_case_number() {
    assert_eq!(generate(11, 4).unwrap(), generate(11, 4).unwrap());
    assert_ne!(generate(11, 4).unwrap(), generate(11, 5).unwrap());
}

fn outcome(model: Model, result: Result<(), Violation>) -> Outcome {
    Outcome {
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

/// Two outcomes, the float one failing: a row each, the family count, the error summary,
/// and the run passes (float violations are the measured trade).
#[test]
fn tally_of_a_float_violation_counts_it_and_passes() {
    let mut tally = Tally::new(5);
    tally.add(&CaseRun {
        mesh_family: "tie-heavy mesh",
        outcomes: vec![outcome(Model::Fixed, Ok(())), outcome(Model::Float32Naive, gap())],
        float32_sum_ulps: vec![3.0, 1.0, 2.0],
    });
    assert_eq!(
        tally.lines(),
        [
            "rasterproof check: 1 cases, seed 5, presets d3d11/gl",
            "invariant                model                cases violations",
            "watertight               fixed                    1          0",
            "watertight               float32-naive            1          1",
            "mesh violations by family:",
            "  tie-heavy mesh         float32-naive          1",
            "float32 barycentric sum error, ulps of 1 (3 samples): median 2.0, mean 2.0, max 3.0",
            "ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant",
        ]
    );
    assert!(tally.passed());
    assert_eq!(tally.to_string(), tally.lines().join("\n") + "\n");
}

/// A second case where `fixed` fails: its row counts two cases and one violation, the
/// families sort by name, and the run fails with one fatal violation.
#[test]
fn tally_of_a_fixed_violation_fails_the_run() {
    let mut tally = Tally::new(5);
    tally.add(&CaseRun {
        mesh_family: "tie-heavy mesh",
        outcomes: vec![outcome(Model::Fixed, Ok(())), outcome(Model::Float32Naive, gap())],
        float32_sum_ulps: Vec::new(),
    });
    let failing = outcome(Model::Fixed, gap());
    assert!(failing.is_fatal());
    let (scene, v) = failing.repro().unwrap();
    assert_eq!((scene.width, v.invariant), (4, "watertight"));
    tally.add(&CaseRun {
        mesh_family: "random mesh",
        outcomes: vec![failing],
        float32_sum_ulps: Vec::new(),
    });
    assert_eq!(
        tally.lines(),
        [
            "rasterproof check: 2 cases, seed 5, presets d3d11/gl",
            "invariant                model                cases violations",
            "watertight               fixed                    2          1",
            "watertight               float32-naive            1          1",
            "mesh violations by family:",
            "  random mesh            fixed                  1",
            "  tie-heavy mesh         float32-naive          1",
            "FAILED: 1 violations by an exact or integer model (exact, exact-snapped, fixed, scanline)",
        ]
    );
    assert_eq!(tally.fatal(), 1);
    assert!(!tally.passed());
    assert_eq!(
        tally.rows().collect::<Vec<_>>(),
        [("watertight", "fixed", 2, 1), ("watertight", "float32-naive", 1, 1)]
    );
}
