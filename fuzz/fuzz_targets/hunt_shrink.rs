//! `hunt`'s machinery (`oracle::hunt`) against renderers that are wrong in a known way,
//! written here as closures, on the scenes `hunt` itself generates (the proptest
//! strategies of `strategy`, drawn by `generate_scene` from a seed and a case index):
//!
//! 1. `generate_scene` gives a scene that writes and parses back unchanged, on the canvas
//!    asked for; with `float32_exact`, every coordinate is an f32.
//! 2. The honest renderer (the oracle itself) is judged `Same` (or `Refused`), never
//!    `Differs`, and shows no signature.
//! 3. A wrong renderer (the oracle under the other tie rule, without snapping, missing
//!    its last primitive, or failing on scenes of more than one primitive): every
//!    signature of its verdict survives `shrink` (the minimal scene still shows it, has
//!    at most the original's primitives and canvas, and the shrink kept to its budget);
//!    `rust_test` of the finding names the signature and embeds the minimal scene.
//! 4. `hunt` over one case from this seed with the wrong renderer: the counts add up,
//!    every finding's minimal scene still shows its signature, and the report's JSON and
//!    JUnit XML are written.
//!
//! `Debug` is the input struct (Rust).

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use rasterproof::convention::{Preset, TieRule};
use rasterproof::model::{render, Model};
use rasterproof::oracle::hunt::{
    generate_scene, hunt, judge, pixel_kinds, primitive_count, rust_test, shrink, signatures, HuntConfig, HuntFinding,
    HuntVerdict, SceneFamily,
};
use rasterproof::oracle::renderer::program::{FailureKind, RenderFailure};
use rasterproof::oracle::{Format, Theirs};
use rasterproof::scene::{parse_scene, Scene};

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Wrong {
    /// The oracle under the other tie rule.
    OtherTieRule,
    /// The oracle without snapping (`exact` where `exact-snapped` is asked).
    Unsnapped,
    /// The oracle, missing the scene's last primitive.
    DropsTheLast,
    /// Exits non-zero on any scene of more than one primitive.
    FailsOnMany,
}

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    seed: u64,
    case: u16,
    family: u8,
    /// Canvas side `4 + canvas % 5`: `judge` explains every differing pixel exactly, so a
    /// wrong renderer's verdict costs per pixel (a 12 px polygon scene took a minute).
    canvas: u8,
    gl: bool,
    float32_exact: bool,
    wrong: Wrong,
    /// Renderer runs per shrink, `4 + budget % 16`.
    budget: u8,
}

fn honest(scene: &Scene) -> Result<Theirs, RenderFailure> {
    let target = scene.target().expect("a generated scene has a valid target");
    let coverage = render(&scene.primitives(), &target, Model::ExactSnapped).map_err(|e| RenderFailure {
        kind: FailureKind::BadOutput,
        message: e.to_string(),
    })?;
    Ok(Theirs::from_coverage(&coverage, Format::Ids))
}

fn wrong_render(wrong: Wrong, scene: &Scene) -> Result<Theirs, RenderFailure> {
    let failed = |message: String| RenderFailure {
        kind: FailureKind::Exit,
        message,
    };
    match wrong {
        Wrong::OtherTieRule => {
            let mut other = scene.clone();
            let rule = scene.target().expect("valid").convention.tie_rule;
            other.overrides.tie_rule = Some(match rule {
                TieRule::TopLeft => TieRule::BottomLeft,
                TieRule::BottomLeft => TieRule::TopLeft,
            });
            honest(&other)
        }
        Wrong::Unsnapped => {
            let target = scene.target().expect("valid");
            let coverage = render(&scene.primitives(), &target, Model::Exact).map_err(|e| failed(e.to_string()))?;
            Ok(Theirs::from_coverage(&coverage, Format::Ids))
        }
        Wrong::DropsTheLast => {
            let mut fewer = scene.clone();
            if fewer.polygons.pop().is_none() && fewer.lines.pop().is_none() {
                fewer.triangles.pop();
            }
            honest(&fewer)
        }
        Wrong::FailsOnMany => {
            if primitive_count(scene) > 1 {
                Err(failed(format!("{} primitives", primitive_count(scene))))
            } else {
                honest(scene)
            }
        }
    }
}

fuzz_target!(|input: Input| {
    let family = SceneFamily::ALL[usize::from(input.family) % SceneFamily::ALL.len()];
    let config = HuntConfig {
        cases: 1,
        seed: input.seed,
        families: vec![family],
        canvas: 4 + u32::from(input.canvas % 5),
        preset: if input.gl { Preset::Gl } else { Preset::D3d11 },
        float32_exact: input.float32_exact,
        shrink_runs: 4 + usize::from(input.budget % 16),
        ..HuntConfig::default()
    };
    let scene = generate_scene(&config, u64::from(input.case)).expect("hunt's generator draws a scene");

    // 1. A scene file like any other.
    assert_eq!((scene.width, scene.height), (config.canvas, config.canvas));
    let text = scene.to_json();
    let back = parse_scene(&text, "generated.json").unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(back.to_json(), text);
    if input.float32_exact {
        let mut again = scene.clone();
        rasterproof::oracle::hunt::float32_exact(&mut again);
        assert_eq!(again.to_json(), text, "float32_exact is idempotent on its own output");
    }

    // 2. The oracle is not a finding.
    let verdict = judge(&scene, honest(&scene), config.model);
    assert!(
        matches!(verdict, HuntVerdict::Same | HuntVerdict::Refused(_)),
        "the oracle differs from itself:\n{text}"
    );
    assert!(signatures(&verdict).is_empty());

    // 3. Every signature of a wrong renderer survives the shrink.
    let verdict = judge(&scene, wrong_render(input.wrong, &scene), config.model);
    for signature in signatures(&verdict) {
        let mut keeps =
            |s: &Scene| signatures(&judge(s, wrong_render(input.wrong, s), config.model)).contains(&signature);
        let (minimal, runs) = shrink(&scene, &mut keeps, config.shrink_runs, None);
        assert!(
            keeps(&minimal),
            "the minimal scene lost {}:\n{}",
            signature.describe(),
            minimal.to_json()
        );
        assert!(primitive_count(&minimal) <= primitive_count(&scene));
        assert!(minimal.width <= scene.width && minimal.height <= scene.height);
        assert!(
            runs <= config.shrink_runs,
            "{runs} runs for a budget of {}",
            config.shrink_runs
        );
        let verdict = judge(&minimal, wrong_render(input.wrong, &minimal), config.model);
        let finding = HuntFinding {
            kinds: pixel_kinds(&verdict, &signature),
            signature: signature.clone(),
            case: u64::from(input.case),
            cases: 1,
            original: scene.clone(),
            minimal: minimal.clone(),
            verdict,
            runs,
            renderer_calls: runs,
        };
        let test = rust_test(&finding, 1, config.model);
        assert!(test.contains(&signature.slug()), "{test}");
        assert!(test.contains(minimal.to_json().trim()), "{test}");
    }

    // 4. A whole hunt of two cases.
    let render_with = |s: &Scene| wrong_render(input.wrong, s);
    let report = hunt(&render_with, &config, 1, &|| {}).expect("hunt's generator draws every scene");
    assert_eq!(
        report.same + report.differing + report.failed + report.refused,
        report.cases
    );
    for f in &report.findings {
        let shows = signatures(&judge(&f.minimal, wrong_render(input.wrong, &f.minimal), config.model));
        assert!(
            shows.contains(&f.signature),
            "{}:\n{}",
            f.signature.describe(),
            f.minimal.to_json()
        );
    }
    let json = report.to_json("closure");
    assert!(is_json_object(&json), "{json}");
    assert!(report.junit("closure").starts_with("<?xml"));
});

/// The report is one JSON object (a light check without a JSON dependency here: the
/// crate's own tests read its fields).
fn is_json_object(text: &str) -> bool {
    let t = text.trim();
    t.starts_with('{') && t.ends_with('}')
}
