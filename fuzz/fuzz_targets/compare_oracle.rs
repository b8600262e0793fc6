//! `oracle::compare` on images near the oracle's own, against any scene:
//!
//! 1. The oracle's own output, in each format (mask, ids, JSON), written out as a file (an
//!    RGBA mask PNG, `Coverage::to_ids_image` as a PNG, `Coverage::to_json`), reads back
//!    as the same `Theirs` as `Theirs::from_coverage`; in the input's format `compare`
//!    finds zero differences.
//! 2. That output edited at up to 2 pixels (uncovered, an owner added, replaced, or
//!    doubled; ids beyond the scene's included): `compare` never panics, reports exactly
//!    the pixels where theirs differs from the oracle's in that format (row-major, the
//!    counts `count_differences` gives), each with at least one finding, and its text,
//!    JSON, difference picture and legend are written without panicking.
//! 3. `explain_pixel` at an edited pixel: every model's owners there are the model's
//!    own render's.
//! 4. On small scenes (three flag bits, one scene in 16 by its text, canvas at most 4x4,
//!    at most 2 primitives, no clip-space triangles): `fit` of the oracle's image lists
//!    the scene's own convention among the exact fits (snapped at its bits and rounding
//!    for `exact-snapped`, unsnapped for `exact`).
//!
//! Input: 16 bytes of parameters, then the scene (a scene file when it parses, else
//! structured; `common::scene`). `Debug` prints the parameters decoded and the scene file.

#![no_main]

use std::fmt;

use arbitrary::Arbitrary;
use image::{DynamicImage, Rgba, RgbaImage};
use libfuzzer_sys::fuzz_target;

mod common;
use common::scene::FuzzScene;
use rasterproof::convention::Target;
use rasterproof::coverage::picture::Scale;
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::oracle::compare::count_differences;
use rasterproof::oracle::compare::fit::fit;
use rasterproof::oracle::reason::Snapping;
use rasterproof::oracle::theirs::{Background, Format};
use rasterproof::oracle::{compare, explain_pixel, Theirs};

const FORMATS: [Format; 4] = [Format::Mask, Format::Ids, Format::Json, Format::Grey];
/// The oracle models, the planned ones 3 times in 4 (the plain ones are slow, and
/// `planned_exact` proves them equal).
const MODELS: [Model; 8] = [
    Model::ExactSnapped,
    Model::Exact,
    Model::ExactSnapped,
    Model::Exact,
    Model::ExactSnapped,
    Model::Exact,
    Model::ExactSnappedPlain,
    Model::ExactPlain,
];

#[derive(Arbitrary)]
struct Input {
    params: [u8; 16],
    scene: FuzzScene,
}

/// One pixel's change (at most 2 a run: each differing pixel costs `compare` a search
/// of the reason classes, snapping at 1..=16 bits with every rounding among them): `op % 4` 0 uncover, 1 add owner `op / 4`, 2 replace the owners by
/// it, 3 double the highest owner (or cover with it).
#[derive(Debug, Clone, Copy)]
struct Edit {
    x: u32,
    y: u32,
    op: u8,
}

impl Input {
    fn format(&self) -> Format {
        FORMATS[usize::from(self.params[0] % 4)]
    }

    fn model(&self) -> Model {
        MODELS[usize::from(self.params[1] % 8)]
    }

    /// `fit` renders 1032 conventions: asked for by three bits, and run on one scene in
    /// 16 (by its text, so the same scene always does or does not), so that it takes a
    /// bounded share of the run.
    fn wants_fit(&self) -> bool {
        let sum: u32 = self.scene.scene.to_json().bytes().map(u32::from).sum();
        self.params[1] & 0xe0 == 0xe0 && sum & 15 == 0
    }

    fn edits(&self) -> Vec<Edit> {
        let (w, h) = (self.scene.scene.width, self.scene.scene.height);
        let n = usize::from(self.params[0] / 3 % 3);
        self.params[2..]
            .chunks(2)
            .take(n)
            .map(|c| Edit {
                x: u32::from(c[0]) % w,
                y: u32::from(c[0]) / w % h,
                op: c[1],
            })
            .collect()
    }
}

impl fmt::Debug for Input {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "// format {}, model {}, fit {}",
            self.format().name(),
            self.model(),
            self.wants_fit()
        )?;
        writeln!(f, "// edits {:?}", self.edits())?;
        writeln!(f, "// params {:?}", self.params)?;
        write!(f, "{:?}", self.scene)
    }
}

/// `ours` with the edits applied.
fn edited(ours: &Coverage, edits: &[Edit]) -> Coverage {
    let mut out = Coverage::new(ours.width(), ours.height());
    let (w, h) = (ours.width(), ours.height());
    for y in 0..h {
        for x in 0..w {
            let mut ids = ours.owners(x, y).to_vec();
            for e in edits.iter().filter(|e| (e.x, e.y) == (x, y)) {
                let id = u32::from(e.op / 4);
                match e.op % 4 {
                    0 => ids.clear(),
                    1 => ids.push(id),
                    2 => ids = vec![id],
                    _ => ids.push(ids.last().copied().unwrap_or(id)),
                }
            }
            ids.sort_unstable();
            for id in ids {
                out.cover(x, y, id);
            }
        }
    }
    out
}

fn png(image: DynamicImage) -> Vec<u8> {
    let mut bytes = std::io::Cursor::new(Vec::new());
    image
        .write_to(&mut bytes, image::ImageFormat::Png)
        .expect("PNG encoding in memory");
    bytes.into_inner()
}

/// The oracle's output in `format` as the file a renderer would write.
fn file(ours: &Coverage, format: Format) -> Vec<u8> {
    match format {
        Format::Json => ours.to_json().into_bytes(),
        Format::Ids => png(DynamicImage::ImageRgba8(ours.to_ids_image().expect("ids below 2^24"))),
        Format::Mask => {
            let mask = RgbaImage::from_fn(ours.width(), ours.height(), |x, y| {
                if ours.owners(x, y).is_empty() {
                    Rgba([0, 0, 0, 0])
                } else {
                    Rgba([255, 255, 255, 255])
                }
            });
            png(DynamicImage::ImageRgba8(mask))
        }
        Format::Grey | Format::Values => {
            let grey = image::GrayImage::from_fn(ours.width(), ours.height(), |x, y| {
                image::Luma([if ours.owners(x, y).is_empty() { 0 } else { 255 }])
            });
            png(DynamicImage::ImageLuma8(grey))
        }
    }
}

fn own_output_is_identical(primitives: &Primitives, target: &Target, model: Model, ours: &Coverage, format: Format) {
    for f in FORMATS {
        let read = Theirs::read(&file(ours, f), "own", f, Background::default())
            .unwrap_or_else(|e| panic!("the oracle's own {} file is refused: {e}", f.name()));
        let own = Theirs::from_coverage(ours, f);
        assert_eq!(read, own, "the oracle's own {} file reads back differently", f.name());
    }
    let theirs = Theirs::from_coverage(ours, format);
    let report = compare(primitives, target, &theirs, &model.into()).expect("an exact model and the same canvas");
    let name = format.name();
    assert!(
        report.identical(),
        "the oracle's own {name} output differs: {:?}",
        report.pixels
    );
}

fn edited_output_is_reported(input: &Input, primitives: &Primitives, target: &Target, ours: &Coverage) {
    let (format, model) = (input.format(), input.model());
    let theirs = Theirs::from_coverage(&edited(ours, &input.edits()), format);
    let own = Theirs::from_coverage(ours, format);
    let report = compare(primitives, target, &theirs, &model.into()).expect("an exact model and the same canvas");
    let mut expected = Vec::new();
    for y in 0..target.height {
        for x in 0..target.width {
            if own.pixel(x, y) != theirs.pixel(x, y) {
                expected.push((x, y));
            }
        }
    }
    let reported: Vec<(u32, u32)> = report.pixels.iter().map(|p| (p.x, p.y)).collect();
    assert_eq!(
        reported, expected,
        "compare reports other pixels than those that differ"
    );
    assert_eq!(report.pixels_by_kind(), count_differences(ours, &theirs, None));
    // Every differing pixel is classified (has a finding) unless the comparison is
    // larger than compare's bound; an unclassified pixel has none.
    let all = report.pixels.len() <= rasterproof::oracle::compare::CLASSIFY_AT_MOST;
    for p in &report.pixels {
        assert!(
            p.classified != p.findings.is_empty() && (p.classified || !all),
            "pixel ({}, {}) differs: classified {}, {} findings",
            p.x,
            p.y,
            p.classified,
            p.findings.len()
        );
        assert_eq!(p.ours, ours.owners(p.x, p.y));
    }
    let _ = report.to_text("scene.json", "theirs", 20);
    let _ = report.to_json("scene.json", "theirs").to_string();
    let _ = report.diff_image();
    let _ = report.diff_legend(Scale::ONE);
}

fn explanation_agrees(primitives: &Primitives, target: &Target, x: u32, y: u32) {
    let why = explain_pixel(primitives, target, x, y).expect("the pixel is on the canvas");
    let _ = why.to_text();
    let _ = why.to_json().to_string();
    for m in why.models {
        match (m.owners, render(primitives, target, m.model)) {
            (Ok(owners), Ok(c)) => assert_eq!(owners, c.owners(x, y), "explain and render of {} differ", m.model),
            (Err(a), Err(b)) => assert_eq!(a, b),
            (a, b) => panic!(
                "explain and render of {} disagree on refusing: {a:?} / {:?}",
                m.model,
                b.err()
            ),
        }
    }
}

fn fit_finds_the_convention(primitives: &Primitives, target: &Target, model: Model, ours: &Coverage) {
    let conv = target.convention;
    let snapping = if model.snaps() {
        Snapping {
            bits: Some(conv.subpixel_bits),
            rounding: conv.rounding,
        }
    } else {
        Snapping {
            bits: None,
            rounding: rasterproof::convention::Rounding::NearestEven,
        }
    };
    let report = fit(primitives, target, &Theirs::from_coverage(ours, Format::Json)).expect("fit takes the scene");
    let _ = report.fit_text();
    let own = report
        .exact
        .iter()
        .any(|c| c.snapping == snapping && c.pixel_centre == conv.pixel_centre && c.tie_rule == conv.tie_rule.into());
    assert!(own, "fit misses the scene's own convention {conv}: {:?}", report.exact);
}

fuzz_target!(|input: Input| {
    let scene = &input.scene.scene;
    let target = scene.target().expect("a bounded canvas");
    let primitives = scene.primitives();
    let model = input.model();
    let ours = render(&primitives, &target, model).expect("the exact models take every scene");
    own_output_is_identical(&primitives, &target, model, &ours, input.format());
    edited_output_is_reported(&input, &primitives, &target, &ours);
    if let Some(e) = input.edits().first() {
        explanation_agrees(&primitives, &target, e.x, e.y);
    }
    let count = primitives.triangles.len() + primitives.lines.len() + primitives.polygons.len();
    if input.wants_fit()
        && target.width * target.height <= 16
        && count <= 2
        && primitives.clip_space_triangles.is_empty()
    {
        fit_finds_the_convention(&primitives, &target, model, &ours);
    }
});
