//! A finding as a ready-to-paste Rust `#[test]` ([`rust_test`]).

use std::fmt::Write as _;

use super::report::HuntFinding;
use super::verdict::HuntVerdict;
use crate::model::Model;
use crate::oracle::compare::DiffPixel;

/// A Rust `#[test]` that pastes into a project's tests: the minimal scene, the oracle's
/// owners of every pixel where their renderer differed (asserted: they hold), and where to
/// call their renderer.
pub fn rust_test(f: &HuntFinding, n: usize, model: Model) -> String {
    let model_path = model.rust_name();
    let mut s = format!(
        "/// Found by `rasterproof hunt` (case {}): {}.\n#[test]\nfn hunt_finding_{n:02}_{}() {{\n",
        f.case,
        f.signature.describe(),
        f.signature.slug()
    );
    let _ = writeln!(
        s,
        "    let scene = rasterproof::scene::parse_scene(r#\"{}\"#, \"finding-{n:02}.json\").unwrap();",
        f.minimal.to_json().trim()
    );
    s.push_str("    let target = scene.target().unwrap();\n");
    let _ = writeln!(
        s,
        "    let oracle = rasterproof::model::render(&scene.primitives(), &target, rasterproof::model::Model::{model_path}).unwrap();"
    );
    match &f.verdict {
        HuntVerdict::Differs(r) => {
            s.push_str("    // The oracle's owners where their renderer differed:\n");
            for p in &r.pixels {
                let classes: Vec<&str> = p.findings.iter().map(|f| f.reason.class().name()).collect();
                let _ = writeln!(
                    s,
                    "    assert_eq!(oracle.owners({}, {}), &[{}][..]); // theirs: {} ({}: {})",
                    p.x,
                    p.y,
                    ours(p),
                    theirs(p),
                    p.kind.name(),
                    classes.join(", ")
                );
            }
        }
        HuntVerdict::DiffersPerSample(r) => {
            let _ = writeln!(
                s,
                "    // Their renderer differed at {} samples of the {} pattern; the oracle's owners there:",
                r.differing_samples(),
                r.pattern
            );
            let _ = writeln!(
                s,
                "    let samples = rasterproof::model::render_samples(&scene.primitives(), &target, scene.samples.as_ref().unwrap(), rasterproof::model::Model::{model_path}).unwrap();"
            );
            for (k, one) in r.samples.iter().enumerate() {
                for p in &one.pixels {
                    let _ = writeln!(
                        s,
                        "    assert_eq!(samples.owners({}, {}, {k}), &[{}][..]); // sample {k}, theirs: {}",
                        p.x,
                        p.y,
                        ours(p),
                        theirs(p)
                    );
                }
            }
            s.push_str("    let _ = oracle;\n");
        }
        HuntVerdict::Failed(failure) => {
            let _ = writeln!(s, "    // Their renderer failed on this scene: {failure}");
            s.push_str("    let _ = oracle;\n");
        }
        HuntVerdict::Same | HuntVerdict::Refused(_) => s.push_str("    let _ = oracle;\n"),
    }
    s.push_str("    // Render `scene` with your renderer here and assert it equals `oracle`.\n}\n");
    s
}

/// The oracle's owners of a differing pixel, as the test's array literal: `1, 4`.
fn ours(p: &DiffPixel) -> String {
    p.ours.iter().map(u32::to_string).collect::<Vec<_>>().join(", ")
}

/// Their answer at a differing pixel, for the test's comment: `[3]` or `uncovered`.
fn theirs(p: &DiffPixel) -> String {
    if p.theirs.covered {
        format!("{:?}", p.theirs.ids)
    } else {
        "uncovered".to_string()
    }
}
