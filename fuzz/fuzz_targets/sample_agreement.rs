//! Sample patterns (multisampling): on any scene (lines dropped) and any pattern (a
//! standard one, or up to 6 positions on the 1/16, 1/3 or 1/2^k grid), every exact and
//! integer model's `render_samples` equals its plain per-sample oracle (`exact-plain`, or
//! `exact-snapped-plain` for the models that snap), sample for sample, or refuses in the
//! ways it may: a snapping model a sample off its subpixel grid (exactly then), `fixed` a
//! polygon it cannot triangulate, an integer model a coordinate beyond its envelope (the
//! single-sample render refuses too, or the move to a sample pushed it past). The count
//! image, the stacked ids image and the masks JSON are written without panicking; the
//! per-sample comparison of the oracle's own stacked image finds nothing.
//!
//! Input: the pattern choice, then the scene (`common::scene`). `Debug` prints both.

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::scene::FuzzScene;
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::model::{render, render_samples, Model, ModelError};
use rasterproof::oracle::compare::samples::{compare_samples, SampleOptions};
use rasterproof::oracle::{Format, Theirs};
use rasterproof::pattern::{SamplePattern, STANDARD_COUNTS};

/// Which pattern.
#[derive(Debug, Clone, Arbitrary)]
enum PatternChoice {
    /// The standard pattern of `STANDARD_COUNTS[k % 5]`.
    Standard(u8),
    /// Positions `(x / 16, y / 16)`, `x, y % 16`.
    Sixteenths(Vec<(u8, u8)>),
    /// Positions `(x / 3, y / 3)`, `x, y % 3`.
    Thirds(Vec<(u8, u8)>),
    /// Positions `(x / 2^k, y / 2^k)`, `k = 1 + bits % 12`.
    Dyadic(u8, Vec<(u16, u16)>),
}

impl PatternChoice {
    fn pattern(&self) -> Option<SamplePattern> {
        let q = |n: u64, d: u64| BigRational::new(BigInt::from(n), BigInt::from(d));
        let custom = |mut p: Vec<[BigRational; 2]>| {
            p.truncate(6);
            p.dedup();
            SamplePattern::custom(p).ok()
        };
        match self {
            PatternChoice::Standard(k) => SamplePattern::standard(STANDARD_COUNTS[usize::from(*k) % 5]),
            PatternChoice::Sixteenths(p) => {
                custom(p.iter().map(|&(x, y)| [q(u64::from(x % 16), 16), q(u64::from(y % 16), 16)]).collect())
            }
            PatternChoice::Thirds(p) => {
                custom(p.iter().map(|&(x, y)| [q(u64::from(x % 3), 3), q(u64::from(y % 3), 3)]).collect())
            }
            PatternChoice::Dyadic(bits, p) => {
                let d = 1u64 << (1 + bits % 12);
                custom(p.iter().map(|&(x, y)| [q(u64::from(x) % d, d), q(u64::from(y) % d, d)]).collect())
            }
        }
    }
}

fuzz_target!(|input: (PatternChoice, FuzzScene)| {
    let (choice, FuzzScene { mut scene }) = input;
    let Some(pattern) = choice.pattern() else { return };
    scene.lines.clear();
    let Ok(target) = scene.target() else { return };
    let primitives = scene.primitives();
    let plain = render_samples(&primitives, &target, &pattern, Model::ExactPlain);
    let snapped = render_samples(&primitives, &target, &pattern, Model::ExactSnappedPlain);
    let (Ok(plain), Ok(snapped)) = (plain, snapped) else {
        // The plain oracles take every scene the parser and prepare accept; prepare may
        // refuse (e.g. clip-space triangles without a viewport never parse, so nothing).
        return;
    };
    let off_grid = (0..pattern.len()).any(|s| pattern.offset_subpixels(s, &target.convention).is_none());
    for model in Model::ALL.into_iter().filter(|m| m.is_exact() && !m.is_plain()) {
        let want = if model.snaps() { &snapped } else { &plain };
        match render_samples(&primitives, &target, &pattern, model) {
            Ok(got) => {
                assert!(!(model.snaps() && off_grid), "{model} took an off-grid pattern");
                assert_eq!(&got, want, "{model} under {pattern}");
            }
            Err(ModelError::SampleOffGrid { .. }) => assert!(model.snaps() && off_grid, "{model}"),
            Err(ModelError::AtSample { error, .. }) => assert!(
                matches!(
                    *error,
                    ModelError::Envelope { .. } | ModelError::PolygonEnvelope { .. } | ModelError::Triangulate { .. } | ModelError::ClipSpace { .. }
                ),
                "{model}: {error}"
            ),
            Err(e) => assert!(render(&primitives, &target, model).is_err(), "{model} refused only under the pattern: {e}"),
        }
    }
    let _ = snapped.to_count_image();
    let _ = snapped.to_json();
    if let Ok(stacked) = snapped.to_stacked_ids_image() {
        let mut png = Vec::new();
        image::DynamicImage::ImageRgba8(stacked)
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .expect("encoding a PNG in memory");
        let theirs = Theirs::read(&png, "stacked.png", Format::Ids, Default::default()).expect("our own PNG reads");
        if let Ok(report) = compare_samples(
            &primitives,
            &target,
            &theirs,
            &SampleOptions {
                pattern: pattern.clone(),
                model: Model::ExactSnapped,
                classify_at_most: Some(4),
            },
        ) {
            assert!(report.identical(), "the oracle's own stacked image differs from it");
        }
    }
});
