//! Differential testing of another renderer (`rasterproof hunt`): scenes drawn from the
//! suite's families, rendered by their renderer and compared with the oracle; every
//! distinct failure shrunk with their renderer in the loop to a minimal scene, with its
//! explanation and a ready-to-paste Rust test.
//!
//! Their renderer is any `Fn(&Scene) -> Result<Theirs, Failure>`: an external program
//! ([`super::program::Program`]) or a Rust closure.
//!
//! At scale, as `check` runs: one [`Shard`] of the cases (N machines run disjoint cases
//! and together exactly the unsharded hunt's), within a time budget (the cases that ran
//! are the first of the shard's, in order), into a [`HuntReport`] written as JSON
//! ([`HuntReport::to_json`]) or JUnit XML ([`HuntReport::junit`]).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::Mutex;
use std::time::{Duration, Instant};

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
use crate::harness::suite::report::{json_object as object, json_value as j, xml_escape};
use crate::harness::suite::Shard;
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
    /// The shard to run: the cases `k` of `0..cases` with `k mod N == K - 1` (case `k`'s
    /// scene is the same in every shard; [`Shard::WHOLE`] runs them all).
    pub shard: Shard,
    /// No case starts once this much time has passed since the hunt started (the running
    /// ones finish, and what was found is still shrunk); `None`: no limit.
    pub budget: Option<Duration>,
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
            shard: Shard::WHOLE,
            budget: None,
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

    /// For file and test names: `missing_pixel_tie_triangles`.
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
    /// The configuration it ran with (its shard, budget, convention and oracle model).
    pub config: HuntConfig,
    /// The cases asked for: the shard's cases among `0..config.cases`.
    pub requested: u64,
    /// Cases run: the first `cases` of the shard's, in order (all of them unless the
    /// time budget stopped the hunt).
    pub cases: u64,
    /// Whether the time budget stopped the hunt before every requested case ran.
    pub stopped_by_time: bool,
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

/// Runs the hunt: the scenes of `config.shard`'s cases among `0..config.cases` rendered by
/// `render` on `jobs` threads, each compared with the oracle; every distinct signature's
/// first case shrunk. `tick` is called once per case (a progress bar).
///
/// With `config.budget`, no case starts once the budget has passed: the running ones
/// finish, and the cases that ran are the first of the shard's, in order (a case is
/// claimed, in order, only while the budget lasts, and every claimed case runs), so a
/// time-limited hunt's counts and findings are those of a shorter hunt. What was found is
/// shrunk whatever the budget.
///
/// ```
/// use rasterproof::harness::suite::Shard;
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
/// // Shard 2 of 3: cases 1, 4, 7, 10, 13; a zero budget runs none of them.
/// let shard = HuntConfig { shard: Shard::new(2, 3).unwrap(), ..config.clone() };
/// assert_eq!(hunt(&shard, &honest, 2, &|| {}).unwrap().cases, 5);
/// let none = HuntConfig { budget: Some(std::time::Duration::ZERO), ..shard };
/// let report = hunt(&none, &honest, 1, &|| {}).unwrap();
/// assert_eq!((report.requested, report.cases, report.stopped_by_time), (5, 0, true));
/// ```
///
/// # Errors
/// A scene could not be generated.
pub fn hunt<R>(config: &HuntConfig, render: &R, jobs: usize, tick: &(dyn Fn() + Sync)) -> Result<HuntReport, String>
where
    R: Fn(&Scene) -> Result<Theirs, Failure> + Sync,
{
    let requested = config.shard.case_count(config.cases);
    let deadline = config.budget.and_then(|b| Instant::now().checked_add(b));
    // The next of the shard's cases to claim (its index among them), and whether claiming
    // has ended (the budget passed, or a scene could not be generated). Claims are made
    // under the lock, in order, so the claimed cases are always the first `next`.
    let claims: Mutex<(u64, bool)> = Mutex::new((0, false));
    let claim = || -> Option<u64> {
        let mut c = claims.lock().expect("no panics hold it");
        if c.1 || c.0 >= requested {
            return None;
        }
        if deadline.is_some_and(|d| Instant::now() >= d) {
            c.1 = true;
            return None;
        }
        let k = config.shard.case_at(c.0)?;
        c.0 += 1;
        Some(k)
    };
    let results: Mutex<Vec<CaseResult>> = Mutex::new(Vec::new());
    let error: Mutex<Option<String>> = Mutex::new(None);
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            s.spawn(|| {
                while let Some(k) = claim() {
                    let scene = match generate_scene(config, k) {
                        Ok(s) => s,
                        Err(e) => {
                            *error.lock().expect("no panics hold it") = Some(e);
                            claims.lock().expect("no panics hold it").1 = true;
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
                }
            });
        }
    });
    if let Some(e) = error.into_inner().expect("no panics hold it") {
        return Err(e);
    }
    let mut results = results.into_inner().expect("no panics hold it");
    results.sort_by_key(|r| r.0);
    let cases = results.len() as u64;
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
        config: config.clone(),
        requested,
        cases,
        stopped_by_time: cases < requested,
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

/// The `format` of a hunt report ([`HuntReport::to_json`]).
pub const REPORT_FORMAT: &str = "rasterproof hunt report";

/// The schema version of a hunt report ([`HuntReport::to_json`]).
pub const REPORT_VERSION: u64 = 1;

/// What their renderer did with a finding's minimal scene, in one word.
fn verdict_name(v: &Verdict) -> &'static str {
    match v {
        Verdict::Same => "same",
        Verdict::Differs(_) => "differs",
        Verdict::Failed(_) => "failed",
        Verdict::Refused(_) => "refused",
    }
}

impl HuntReport {
    /// The convention every scene stated, as a JSON object: `{"preset", "tie_rule",
    /// "pixel_centre", "subpixel_bits", "rounding"}`.
    fn convention_json(&self) -> String {
        let c = self.config.overrides.apply(self.config.preset);
        object(&[
            ("preset", j(c.preset.name())),
            ("tie_rule", j(c.tie_rule.name())),
            ("pixel_centre", j(c.pixel_centre.name())),
            ("subpixel_bits", j(&c.subpixel_bits)),
            ("rounding", j(c.rounding.name())),
        ])
    }

    /// The report as a JSON document (schema version [`REPORT_VERSION`]; also in README's
    /// `hunt` section), `renderer` naming what was hunted (`hunt --cmd`'s command): one
    /// object, one field a line in this order, each finding on a line of its own, ending in
    /// a newline.
    ///
    /// - `format` (`"rasterproof hunt report"`), `version` (1), `rasterproof` (the version
    ///   that ran it), `cmd` (`renderer`), `seed`;
    /// - `shard`: `{"k": K, "n": N}` (`{"k": 1, "n": 1}`: the whole run);
    /// - `cases` (the whole run's, `0..cases`), `cases_requested` (the shard's among them),
    ///   `cases_run` (the first of the shard's, in order), `stopped_by_time` (the budget
    ///   stopped the hunt before every requested case ran);
    /// - `families` (names), `canvas`, `float32_exact`, `shrink_runs` (the runs allowed
    ///   per shrink), `time_budget_ms` (`null`: none), `convention` (`{"preset",
    ///   "tie_rule", "pixel_centre", "subpixel_bits", "rounding"}`), `model` (the oracle:
    ///   `exact-snapped` or `exact`);
    /// - `counts`: `{"same", "differ", "failed", "refused"}` over the cases run;
    /// - `findings`, by first case: `{"signature"` ([`Signature::describe`]), `"slug"`
    ///   ([`Signature::slug`]), `"first_case"`, `"cases"` (how many showed it),
    ///   `"primitives"` (of the minimal scene), `"scene"` (the minimal scene: the JSON
    ///   object [`Scene::to_json`] writes), `"shrink_runs"` (renderer runs the shrink
    ///   took), `"minimal_verdict"` (`differs`, `failed`, or `same` / `refused` when the
    ///   minimal scene no longer fails)`}`.
    ///
    /// ```
    /// use rasterproof::oracle::hunt::{hunt, HuntConfig};
    /// use rasterproof::oracle::program::{Failure, FailureKind};
    /// // A renderer that always fails: one finding.
    /// let broken = |_: &rasterproof::scene::Scene| {
    ///     Err(Failure { kind: FailureKind::Exit, message: "exit status 3".to_string() })
    /// };
    /// let config = HuntConfig { cases: 3, shrink_runs: 4, ..HuntConfig::default() };
    /// let report = hunt(&config, &broken, 1, &|| {}).unwrap();
    /// let v: serde_json::Value = serde_json::from_str(&report.to_json("broken")).unwrap();
    /// assert_eq!(v["format"], "rasterproof hunt report");
    /// assert_eq!(v["counts"]["failed"], 3);
    /// assert_eq!(v["findings"][0]["signature"], "non-zero exit");
    /// assert!(v["findings"][0]["scene"]["triangles"].is_array());
    /// ```
    pub fn to_json(&self, renderer: &str) -> String {
        let c = &self.config;
        let findings: Vec<String> = self
            .findings
            .iter()
            .map(|f| {
                let scene = serde_json::from_str::<serde_json::Value>(&f.minimal.to_json())
                    .map_or_else(|_| j(&f.minimal.to_json()), |v| j(&v));
                object(&[
                    ("signature", j(&f.signature.describe())),
                    ("slug", j(&f.signature.slug())),
                    ("first_case", j(&f.case)),
                    ("cases", j(&f.cases)),
                    ("primitives", j(&primitive_count(&f.minimal))),
                    ("scene", scene),
                    ("shrink_runs", j(&f.runs)),
                    ("minimal_verdict", j(verdict_name(&f.verdict))),
                ])
            })
            .collect();
        let findings = if findings.is_empty() {
            "[]".to_string()
        } else {
            format!("[\n    {}\n  ]", findings.join(",\n    "))
        };
        let families: Vec<&str> = c.families.iter().map(|f| f.name()).collect();
        let fields: [(&str, String); 19] = [
            ("format", j(REPORT_FORMAT)),
            ("version", j(&REPORT_VERSION)),
            ("rasterproof", j(env!("CARGO_PKG_VERSION"))),
            ("cmd", j(renderer)),
            ("seed", j(&c.seed)),
            (
                "shard",
                object(&[("k", j(&c.shard.index())), ("n", j(&c.shard.count()))]),
            ),
            ("cases", j(&c.cases)),
            ("cases_requested", j(&self.requested)),
            ("cases_run", j(&self.cases)),
            ("stopped_by_time", j(&self.stopped_by_time)),
            ("families", j(&families)),
            ("canvas", j(&c.canvas)),
            ("float32_exact", j(&c.float32_exact)),
            ("shrink_runs", j(&c.shrink_runs)),
            (
                "time_budget_ms",
                c.budget.map_or_else(|| "null".to_string(), |b| j(&b.as_millis())),
            ),
            ("convention", self.convention_json()),
            ("model", j(c.model.name())),
            (
                "counts",
                object(&[
                    ("same", j(&self.same)),
                    ("differ", j(&self.differing)),
                    ("failed", j(&self.failed)),
                    ("refused", j(&self.refused)),
                ]),
            ),
            ("findings", findings),
        ];
        let body: Vec<String> = fields
            .iter()
            .map(|(key, value)| format!("  {}: {value}", j(key)))
            .collect();
        format!("{{\n{}\n}}\n", body.join(",\n"))
    }

    /// The report as JUnit XML, `renderer` naming what was hunted: one `<testsuite
    /// name="rasterproof hunt">` in a `<testsuites>`, with the seed, shard, cases, budget
    /// stop, convention, model and `renderer` as properties; one `<testcase
    /// classname="rasterproof.hunt" name="SIGNATURE">` per finding (by first case), holding
    /// a `<failure>` whose message is the signature and whose text gives the first case,
    /// how many cases showed it, and the minimal scene; then one passing `<testcase
    /// name="identical to the oracle">` whose `<system-out>` carries the counts. Every
    /// text is escaped for XML.
    ///
    /// ```
    /// use rasterproof::oracle::hunt::{hunt, HuntConfig};
    /// use rasterproof::oracle::program::{Failure, FailureKind};
    /// let broken = |_: &rasterproof::scene::Scene| {
    ///     Err(Failure { kind: FailureKind::Exit, message: "exit <3> & more".to_string() })
    /// };
    /// let config = HuntConfig { cases: 2, shrink_runs: 4, ..HuntConfig::default() };
    /// let xml = hunt(&config, &broken, 1, &|| {}).unwrap().junit("a < b");
    /// assert!(xml.contains("<testsuite name=\"rasterproof hunt\" tests=\"2\" failures=\"1\""));
    /// assert!(xml.contains("value=\"a &lt; b\""));
    /// assert!(xml.contains("exit &lt;3&gt; &amp; more"));
    /// assert_eq!(xml.matches("<testcase ").count(), 2);
    /// ```
    pub fn junit(&self, renderer: &str) -> String {
        let c = &self.config;
        let failures = self.findings.len();
        let counts = format!(
            "tests=\"{}\" failures=\"{failures}\" errors=\"0\" skipped=\"0\"",
            failures + 1
        );
        let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(x, "<testsuites name=\"rasterproof hunt\" {counts}>");
        let _ = writeln!(x, "  <testsuite name=\"rasterproof hunt\" {counts}>");
        x.push_str("    <properties>\n");
        for (name, value) in [
            ("rasterproof", env!("CARGO_PKG_VERSION").to_string()),
            ("cmd", renderer.to_string()),
            ("seed", c.seed.to_string()),
            ("shard", c.shard.to_string()),
            ("cases", c.cases.to_string()),
            ("cases_requested", self.requested.to_string()),
            ("cases_run", self.cases.to_string()),
            ("stopped_by_time", self.stopped_by_time.to_string()),
            ("convention", c.overrides.apply(c.preset).to_string()),
            ("model", c.model.name().to_string()),
        ] {
            let _ = writeln!(
                x,
                "      <property name=\"{name}\" value=\"{}\"/>",
                xml_escape(&value, true)
            );
        }
        x.push_str("    </properties>\n");
        for f in &self.findings {
            let description = f.signature.describe();
            let _ = writeln!(
                x,
                "    <testcase classname=\"rasterproof.hunt\" name=\"{}\">",
                xml_escape(&description, true)
            );
            let message = format!("{description}: {} cases, first case {}", f.cases, f.case);
            let mut text = format!(
                "{description}\nfirst case: {} ({} cases showed it)\nminimal scene ({} primitives, {}x{}, {} shrink runs):\n{}",
                f.case,
                f.cases,
                primitive_count(&f.minimal),
                f.minimal.width,
                f.minimal.height,
                f.runs,
                f.minimal.to_json()
            );
            if let Verdict::Failed(failure) = &f.verdict {
                let _ = write!(text, "\ntheir renderer on the minimal scene: {failure}");
            }
            let _ = writeln!(
                x,
                "      <failure type=\"finding\" message=\"{}\">{}</failure>",
                xml_escape(&message, true),
                xml_escape(&text, false)
            );
            x.push_str("    </testcase>\n");
        }
        let mut out = format!(
            "{} identical, {} differ, {} failed, {} refused by the oracle, of {} cases run ({} requested)",
            self.same, self.differing, self.failed, self.refused, self.cases, self.requested
        );
        if self.stopped_by_time {
            out.push_str("; stopped by the time budget");
        }
        x.push_str("    <testcase classname=\"rasterproof.hunt\" name=\"identical to the oracle\">\n");
        let _ = writeln!(x, "      <system-out>{}</system-out>", xml_escape(&out, false));
        x.push_str("    </testcase>\n");
        x.push_str("  </testsuite>\n</testsuites>\n");
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A report of no case is still a whole document: every field, empty findings.
    #[test]
    fn an_empty_report_has_every_field() {
        let config = HuntConfig {
            cases: 4,
            shard: Shard::new(3, 3).unwrap(),
            budget: Some(Duration::from_millis(1500)),
            ..HuntConfig::default()
        };
        let never = |_: &Scene| -> Result<Theirs, Failure> { unreachable!("no case runs") };
        let report = hunt(
            &HuntConfig {
                budget: Some(Duration::ZERO),
                ..config.clone()
            },
            &never,
            1,
            &|| {},
        )
        .unwrap();
        let report = HuntReport { config, ..report };
        let v: serde_json::Value = serde_json::from_str(&report.to_json("r \"q\"")).unwrap();
        let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
        for key in [
            "format",
            "version",
            "rasterproof",
            "cmd",
            "seed",
            "shard",
            "cases",
            "cases_requested",
            "cases_run",
            "stopped_by_time",
            "families",
            "canvas",
            "float32_exact",
            "shrink_runs",
            "time_budget_ms",
            "convention",
            "model",
            "counts",
            "findings",
        ] {
            assert!(keys.contains(&key), "{key}: {keys:?}");
        }
        assert_eq!(keys.len(), 19);
        assert_eq!(v["cmd"], "r \"q\"");
        assert_eq!(v["shard"], serde_json::json!({"k": 3, "n": 3}));
        assert_eq!((&v["cases_requested"], &v["cases_run"]), (&1.into(), &0.into()));
        assert_eq!(v["time_budget_ms"], 1500);
        assert_eq!(v["stopped_by_time"], true);
        let x = report.junit("r \"q\"");
        assert!(
            x.contains("value=\"r &quot;q&quot;\"") && x.contains("stopped by the time budget"),
            "{x}"
        );
        assert_eq!(x.matches("<testcase ").count(), 1);
    }
}
