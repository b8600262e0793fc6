//! Differential testing of another renderer (`rasterproof hunt`): scenes drawn from the
//! suite's families, rendered by their renderer and compared with the oracle; every
//! distinct failure shrunk with their renderer in the loop to a minimal scene, with its
//! explanation and a ready-to-paste Rust test.
//!
//! Their renderer is any `Fn(&Scene) -> Result<Theirs, Failure>`: an external program
//! ([`super::program::Program`]) or a Rust closure.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::atomic::{AtomicU64, Ordering};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use super::compare::{compare, PixelKind, Report};
use super::fit::Candidate;
use super::program::Failure;
use super::reason::ReasonClass;
use super::theirs::Theirs;
use crate::convention::{AnyTieRule, PixelCentre, Preset, TieRule};
use crate::geom::{Point, Polygon, Triangle};
use crate::line::{BresenhamTie, Line, LineRule};
use crate::model::Model;
use crate::scene::{Overrides, Scene};
use crate::strategy::polygon::any_polygon;
use crate::strategy::{delaunay_mesh, diamond_line, pixel_line, tie_heavy_mesh, triangle, Scale};

/// A family of generated scenes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Family {
    /// A tie-heavy mesh: vertices on pixel centres, corners and snapping ties.
    Mesh,
    /// A Delaunay mesh of random points on the 1/256 px grid.
    Delaunay,
    /// Random triangles of every size (pixel, medium, sliver, huge, tie-heavy).
    Triangles,
    /// Slivers: a third vertex a few subpixels off the line through the other two.
    Slivers,
    /// Triangles with vertices far off the canvas (up to the integer envelope).
    Huge,
    /// A Delaunay mesh on a fine 2^-16 px grid.
    Fine,
    /// Bresenham and diamond-exit lines.
    Lines,
    /// Polygons: simple, with holes, tangled, stellated, tie-heavy.
    Polygons,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 8] = [
        Family::Mesh,
        Family::Delaunay,
        Family::Triangles,
        Family::Slivers,
        Family::Huge,
        Family::Fine,
        Family::Lines,
        Family::Polygons,
    ];

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Family::Mesh => "mesh",
            Family::Delaunay => "delaunay",
            Family::Triangles => "triangles",
            Family::Slivers => "slivers",
            Family::Huge => "huge",
            Family::Fine => "fine",
            Family::Lines => "lines",
            Family::Polygons => "polygons",
        }
    }

    /// Parses a name written by [`Family::name`].
    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }

    /// Triangles, lines and polygons of this family on a `canvas` x `canvas` target.
    fn strategy(self, canvas: u32) -> BoxedStrategy<(Vec<Triangle>, Vec<Line>, Vec<Polygon>)> {
        let side = i64::from(canvas);
        let tris = |s: BoxedStrategy<Triangle>| {
            proptest::collection::vec(s, 1..4)
                .prop_map(|t| (t, Vec::new(), Vec::new()))
                .boxed()
        };
        let mesh =
            |s: BoxedStrategy<crate::strategy::Mesh>| s.prop_map(|m| (m.triangles, Vec::new(), Vec::new())).boxed();
        match self {
            Family::Mesh => mesh(tie_heavy_mesh(canvas, 12)),
            Family::Delaunay => mesh(delaunay_mesh([0, 0], side, 8, 12)),
            Family::Triangles => tris(crate::strategy::any_triangle(canvas)),
            Family::Slivers => tris(triangle(Scale::Sliver, canvas)),
            Family::Huge => tris(triangle(Scale::Huge, canvas)),
            Family::Fine => mesh(delaunay_mesh([0, 0], side, 16, 12)),
            Family::Lines => (
                proptest::collection::vec(pixel_line(side, 2), 0..3),
                proptest::collection::vec(diamond_line(canvas), 0..3),
            )
                .prop_map(|(b, d)| {
                    let bresenham = b.into_iter().map(|(a, b)| Line {
                        from: Point::from_ints(a[0], a[1]),
                        to: Point::from_ints(b[0], b[1]),
                        rule: LineRule::Bresenham(BresenhamTie::Stay),
                    });
                    (Vec::new(), bresenham.chain(d).collect(), Vec::new())
                })
                .boxed(),
            Family::Polygons => proptest::collection::vec(any_polygon(canvas, 8), 1..3)
                .prop_map(|p| (Vec::new(), Vec::new(), p))
                .boxed(),
        }
    }
}

/// How a hunt runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HuntConfig {
    /// How many scenes.
    pub cases: u64,
    /// Seed of the scene generator (same seed, same scenes).
    pub seed: u64,
    /// The families, case `k` drawing from `families[k % len]`.
    pub families: Vec<Family>,
    /// Canvas side of every scene.
    pub canvas: u32,
    /// The convention every scene states: a preset and overrides.
    pub preset: Preset,
    /// The overrides.
    pub overrides: Overrides,
    /// The oracle: `exact-snapped`, or `exact` for a renderer that does not snap.
    pub model: Model,
    /// Round every coordinate to the nearest f32 (for programs that read floats).
    pub float32_exact: bool,
    /// Runs of their renderer allowed per shrink.
    pub shrink_runs: usize,
}

impl Default for HuntConfig {
    fn default() -> Self {
        HuntConfig {
            cases: 200,
            seed: 0,
            families: Family::ALL.to_vec(),
            canvas: 16,
            preset: Preset::D3d11,
            overrides: Overrides::default(),
            model: Model::ExactSnapped,
            float32_exact: false,
            shrink_runs: 400,
        }
    }
}

/// The scene of case `k`: the same config and `k` always give the same scene.
///
/// # Errors
/// A strategy rejected every value it drew (the message names the family).
pub fn generate_scene(config: &HuntConfig, k: u64) -> Result<Scene, String> {
    let family = config.families[usize::try_from(k % config.families.len() as u64).expect("small")];
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&config.seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&k.to_le_bytes());
    bytes[16] = 0x48; // 'H': not the suite's streams
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes));
    let (triangles, lines, polygons) = family
        .strategy(config.canvas)
        .new_tree(&mut runner)
        .map_err(|e| format!("hunt: family {}: {e}", family.name()))?
        .current();
    let mut scene = Scene::new(config.canvas, config.canvas, triangles);
    scene.lines = lines;
    scene.polygons = polygons;
    scene.preset = config.preset;
    scene.overrides = config.overrides;
    if config.float32_exact {
        float32_exact(&mut scene);
    }
    Ok(scene)
}

/// Every window-space coordinate of `scene`, mutably (triangles, line ends, polygons).
fn coordinates(scene: &mut Scene) -> Vec<&mut BigRational> {
    let mut out: Vec<&mut BigRational> = Vec::new();
    for t in &mut scene.triangles {
        for v in &mut t.triangle.v {
            out.push(&mut v.x);
            out.push(&mut v.y);
        }
    }
    for l in &mut scene.lines {
        for v in [&mut l.from, &mut l.to] {
            out.push(&mut v.x);
            out.push(&mut v.y);
        }
    }
    for p in &mut scene.polygons {
        for v in p.outline.iter_mut().chain(p.holes.iter_mut().flatten()) {
            out.push(&mut v.x);
            out.push(&mut v.y);
        }
    }
    out
}

/// Rounds every coordinate to the nearest f32, exactly (so a program reading f32 sees the
/// scene the oracle sees).
pub fn float32_exact(scene: &mut Scene) {
    for v in coordinates(scene) {
        if let Some(f) = crate::num::exact::nearest_f32(v) {
            if let Some(exact) = BigRational::from_float(f) {
                *v = exact;
            }
        }
    }
}

/// What their renderer did with one scene.
#[derive(Debug, Clone)]
pub enum Verdict {
    /// Identical to the oracle.
    Same,
    /// Different: the comparison.
    Differs(Box<Report>),
    /// Their renderer failed.
    Failed(Failure),
    /// The oracle refused the scene (it is outside the model's envelope): not their fault.
    Refused(String),
}

/// Compares their output (or failure) on `scene` with `model`'s.
pub fn judge(scene: &Scene, theirs: Result<Theirs, Failure>, model: Model) -> Verdict {
    let theirs = match theirs {
        Ok(t) => t,
        Err(f) => return Verdict::Failed(f),
    };
    let Some(target) = scene.target() else {
        return Verdict::Refused("invalid canvas or convention".to_string());
    };
    match compare(&scene.primitives(), &target, model, &theirs) {
        Ok(r) if r.identical() => Verdict::Same,
        Ok(r) => Verdict::Differs(Box::new(r)),
        Err(e) => Verdict::Refused(e.to_string()),
    }
}

/// A distinct failure: what hunt deduplicates by.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Signature {
    /// A differing pixel: its kind, the reason class, the primitive kind (`triangles`,
    /// `lines`, `polygons`, or `none` when no primitive explains it).
    Pixel(PixelKind, ReasonClass, String),
    /// Their renderer failed this way.
    Failure(super::program::FailureKind),
}

impl Signature {
    /// In words: `missing pixel, tie, triangles`.
    pub fn describe(&self) -> String {
        match self {
            Signature::Pixel(kind, class, primitive) => format!("{} pixel, {}, {primitive}", kind.name(), class.name()),
            Signature::Failure(kind) => kind.name().to_string(),
        }
    }

    /// For file and test names: `missing-tie-triangles`.
    pub fn slug(&self) -> String {
        self.describe()
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect::<String>()
            .split('_')
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join("_")
    }
}

/// Every signature a verdict shows (none for `Same` and `Refused`).
pub fn signatures(verdict: &Verdict) -> Vec<Signature> {
    let mut out = Vec::new();
    match verdict {
        Verdict::Differs(r) => {
            for p in &r.pixels {
                for f in &p.findings {
                    let kind = f
                        .primitive
                        .as_deref()
                        .and_then(|n| n.split('[').next())
                        .unwrap_or("none")
                        .to_string();
                    out.push(Signature::Pixel(p.kind, f.reason.class(), kind));
                }
            }
        }
        Verdict::Failed(f) => out.push(Signature::Failure(f.kind)),
        Verdict::Same | Verdict::Refused(_) => {}
    }
    out.sort();
    out.dedup();
    out
}

/// A distinct failure, shrunk.
#[derive(Debug, Clone)]
pub struct HuntFinding {
    /// What it is.
    pub signature: Signature,
    /// The first case that showed it.
    pub case: u64,
    /// How many cases showed it.
    pub cases: u64,
    /// That case's scene.
    pub original: Scene,
    /// The scene after shrinking: no step of the shrinker keeps the failure.
    pub minimal: Scene,
    /// Their verdict on the minimal scene.
    pub verdict: Verdict,
    /// Runs of their renderer the shrink took.
    pub runs: usize,
}

/// What a hunt found.
#[derive(Debug, Clone)]
pub struct HuntReport {
    /// Cases run.
    pub cases: u64,
    /// Identical to the oracle.
    pub same: u64,
    /// Differing.
    pub differing: u64,
    /// Their renderer failed.
    pub failed: u64,
    /// The oracle refused the scene.
    pub refused: u64,
    /// Every distinct failure, by its first case.
    pub findings: Vec<HuntFinding>,
}

/// One case's scene, signatures and outcome (0 same, 1 differs, 2 failed, 3 refused).
type CaseResult = (u64, Scene, Vec<Signature>, u8);

/// Runs the hunt: `config.cases` scenes rendered by `render` on `jobs` threads, each
/// compared with the oracle; every distinct signature's first case shrunk. `tick` is called
/// once per case (a progress bar).
///
/// ```
/// use rasterproof::model::{render, Model};
/// use rasterproof::oracle::hunt::{hunt, HuntConfig};
/// use rasterproof::oracle::{Format, Theirs};
/// // A renderer that is the oracle itself finds nothing.
/// let honest = |s: &rasterproof::scene::Scene| {
///     let c = render(Model::ExactSnapped, &s.primitives(), &s.target().unwrap()).unwrap();
///     Ok(Theirs::from_coverage(&c, Format::Json))
/// };
/// let config = HuntConfig { cases: 16, ..HuntConfig::default() };
/// let report = hunt(&config, &honest, 1, &|| {}).unwrap();
/// assert!(report.findings.is_empty());
/// assert_eq!(report.same + report.refused, 16);
/// ```
///
/// # Errors
/// A scene could not be generated.
pub fn hunt<R>(config: &HuntConfig, render: &R, jobs: usize, tick: &(dyn Fn() + Sync)) -> Result<HuntReport, String>
where
    R: Fn(&Scene) -> Result<Theirs, Failure> + Sync,
{
    let next = AtomicU64::new(0);
    let results: std::sync::Mutex<Vec<CaseResult>> = std::sync::Mutex::new(Vec::new());
    let error: std::sync::Mutex<Option<String>> = std::sync::Mutex::new(None);
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            s.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k >= config.cases {
                    break;
                }
                let scene = match generate_scene(config, k) {
                    Ok(s) => s,
                    Err(e) => {
                        *error.lock().expect("no panics hold it") = Some(e);
                        break;
                    }
                };
                let verdict = judge(&scene, render(&scene), config.model);
                let outcome = match &verdict {
                    Verdict::Same => 0,
                    Verdict::Differs(_) => 1,
                    Verdict::Failed(_) => 2,
                    Verdict::Refused(_) => 3,
                };
                let sigs = signatures(&verdict);
                results
                    .lock()
                    .expect("no panics hold it")
                    .push((k, scene, sigs, outcome));
                tick();
            });
        }
    });
    if let Some(e) = error.into_inner().expect("no panics hold it") {
        return Err(e);
    }
    let mut results = results.into_inner().expect("no panics hold it");
    results.sort_by_key(|r| r.0);
    let mut counts = [0u64; 4];
    let mut first: BTreeMap<Signature, (u64, Scene, u64)> = BTreeMap::new();
    for (k, scene, sigs, outcome) in results {
        counts[usize::from(outcome)] += 1;
        for sig in sigs {
            first.entry(sig).or_insert_with(|| (k, scene.clone(), 0)).2 += 1;
        }
    }
    let mut findings = Vec::new();
    for (signature, (case, original, cases)) in first {
        let mut keeps = |s: &Scene| signatures(&judge(s, render(s), config.model)).contains(&signature);
        let (minimal, runs) = shrink(&original, &mut keeps, config.shrink_runs);
        let verdict = judge(&minimal, render(&minimal), config.model);
        findings.push(HuntFinding {
            signature,
            case,
            cases,
            original,
            minimal,
            verdict,
            runs,
        });
    }
    findings.sort_by_key(|f| (f.case, f.signature.clone()));
    Ok(HuntReport {
        cases: config.cases,
        same: counts[0],
        differing: counts[1],
        failed: counts[2],
        refused: counts[3],
        findings,
    })
}

/// How many primitives a scene has.
pub fn primitive_count(s: &Scene) -> usize {
    s.triangles.len() + s.lines.len() + s.polygons.len() + s.clip_space_triangles.len()
}

/// Simpler values for a coordinate, simplest first: 0, the integer towards zero, the
/// value rounded towards zero to coarser grids (1/2 .. 1/256 px), one pixel nearer zero,
/// half of it.
fn simpler(v: &BigRational) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(), v.trunc()];
    for bits in 1..=8u32 {
        let k = BigRational::from_integer(BigInt::from(1u32 << bits));
        out.push((v * &k).trunc() / &k);
    }
    if v.abs() >= BigRational::from_integer(1.into()) {
        out.push(v - BigRational::from_integer(if v.is_positive() { 1 } else { -1 }.into()));
    }
    out.push(v / BigRational::from_integer(2.into()));
    let mut seen = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
}

/// The scene moved by whole pixels (`-dx`, `-dy`) on a `width` x `height` canvas.
fn moved(s: &Scene, dx: i64, dy: i64, width: u32, height: u32) -> Scene {
    let mut out = s.clone();
    out.width = width;
    out.height = height;
    let (fx, fy) = (
        BigRational::from_integer(dx.into()),
        BigRational::from_integer(dy.into()),
    );
    let mut cs = coordinates(&mut out);
    for (k, c) in cs.iter_mut().enumerate() {
        **c -= if k % 2 == 0 { &fx } else { &fy };
    }
    out
}

/// Shrinks `scene` while `keeps` holds: drops primitives (and the clip window), crops the
/// canvas (to the differing pixels' box when `keeps` accepts it, then halves, then one
/// pixel at a time from each side), and moves each coordinate to simpler values; repeats
/// until no step keeps the failure or `budget` runs are spent. Returns the smallest scene
/// and the runs used.
pub fn shrink(scene: &Scene, keeps: &mut dyn FnMut(&Scene) -> bool, budget: usize) -> (Scene, usize) {
    let mut best = scene.clone();
    let mut runs = 0;
    let mut attempt = |candidate: &Scene, runs: &mut usize| -> bool {
        if *runs >= budget {
            return false;
        }
        *runs += 1;
        keeps(candidate)
    };
    loop {
        let mut changed = false;
        // Drop primitives, last first.
        for kind in 0..3 {
            let len = match kind {
                0 => best.triangles.len(),
                1 => best.lines.len(),
                _ => best.polygons.len(),
            };
            for i in (0..len).rev() {
                let mut c = best.clone();
                match kind {
                    0 => drop(c.triangles.remove(i)),
                    1 => drop(c.lines.remove(i)),
                    _ => drop(c.polygons.remove(i)),
                }
                if primitive_count(&c) > 0 && attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                }
            }
        }
        if best.clip.is_some() {
            let mut c = best.clone();
            c.clip = None;
            if attempt(&c, &mut runs) {
                best = c;
                changed = true;
            }
        }
        // Crop: halves, then a pixel from each side (moving the scene for left and top).
        if best.clip.is_none() {
            let (w, h) = (best.width, best.height);
            let crops = [
                (0, 0, w.div_ceil(2), h),
                (i64::from(w / 2), 0, w - w / 2, h),
                (0, 0, w, h.div_ceil(2)),
                (0, i64::from(h / 2), w, h - h / 2),
                (0, 0, w - 1, h),
                (1, 0, w - 1, h),
                (0, 0, w, h - 1),
                (0, 1, w, h - 1),
            ];
            for (dx, dy, cw, ch) in crops {
                if cw == 0 || ch == 0 || (cw, ch) == (best.width, best.height) {
                    continue;
                }
                let c = moved(&best, dx, dy, cw, ch);
                if attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                    break;
                }
            }
        }
        // Simpler coordinates.
        let n = coordinates(&mut best.clone()).len();
        for k in 0..n {
            let value = coordinates(&mut best.clone())[k].clone();
            for v in simpler(&value) {
                let mut c = best.clone();
                *coordinates(&mut c)[k] = v;
                if attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                    break;
                }
            }
        }
        if !changed || runs >= budget {
            return (best, runs);
        }
    }
}

/// A Rust `#[test]` that pastes into a project's tests: the minimal scene, the oracle's
/// owners of every pixel where their renderer differed (asserted: they hold), and where to
/// call their renderer.
pub fn rust_test(f: &HuntFinding, n: usize, model: Model) -> String {
    let model_path = match model {
        Model::Exact => "Exact",
        _ => "ExactSnapped",
    };
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
        "    let oracle = rasterproof::model::render(rasterproof::model::Model::{model_path}, &scene.primitives(), &target).unwrap();"
    );
    match &f.verdict {
        Verdict::Differs(r) => {
            s.push_str("    // The oracle's owners where their renderer differed:\n");
            for p in &r.pixels {
                let ids: Vec<String> = p.ours.iter().map(u32::to_string).collect();
                let classes: Vec<&str> = p.findings.iter().map(|f| f.reason.class().name()).collect();
                let _ = writeln!(
                    s,
                    "    assert_eq!(oracle.owners({}, {}), &[{}][..]); // theirs: {} ({}: {})",
                    p.x,
                    p.y,
                    ids.join(", "),
                    if p.theirs.covered {
                        format!("{:?}", p.theirs.ids)
                    } else {
                        "uncovered".to_string()
                    },
                    p.kind.name(),
                    classes.join(", ")
                );
            }
        }
        Verdict::Failed(failure) => {
            let _ = writeln!(s, "    // Their renderer failed on this scene: {failure}");
            s.push_str("    let _ = oracle;\n");
        }
        Verdict::Same | Verdict::Refused(_) => s.push_str("    let _ = oracle;\n"),
    }
    s.push_str("    // Render `scene` with your renderer here and assert it equals `oracle`.\n}\n");
    s
}

/// The convention a fit names, as scene overrides and the oracle model, when hunt can
/// state it in a scene file: a top-left or bottom-left rule and 1..=16 bits (the oracle
/// `exact-snapped`) or no snapping (`exact`).
pub fn hunt_convention(c: &Candidate) -> Option<(Overrides, Model)> {
    let tie_rule = match c.tie_rule {
        AnyTieRule::TopLeft => TieRule::TopLeft,
        AnyTieRule::BottomLeft => TieRule::BottomLeft,
        _ => return None,
    };
    let mut o = Overrides {
        tie_rule: Some(tie_rule),
        pixel_centre: Some(c.pixel_centre),
        ..Overrides::default()
    };
    match c.snapping.bits {
        None => Some((o, Model::Exact)),
        Some(0) => None,
        Some(b) => {
            o.subpixel_bits = Some(b);
            o.rounding = Some(c.snapping.rounding);
            Some((o, Model::ExactSnapped))
        }
    }
}

/// The fit hunt prefers among exact ones: one it can state ([`hunt_convention`]), at the
/// usual 8 bits or else the most bits, nearest-even, pixel centre 0.5, top-left.
pub fn preferred(exact: &[Candidate]) -> Option<Candidate> {
    exact
        .iter()
        .copied()
        .filter(|c| hunt_convention(c).is_some())
        .min_by_key(|c| {
            let bits = c
                .snapping
                .bits
                .map_or(17, |b| if b == 8 { 0 } else { 17 - i64::from(b) });
            (
                bits,
                c.snapping.rounding != crate::num::Rounding::NearestEven,
                c.pixel_centre != PixelCentre::Half,
                c.tie_rule != AnyTieRule::TopLeft,
            )
        })
}
