//! The models of two real anti-aliasing crates (`area::abglyph`, ab_glyph_rasterizer
//! 0.1.10; `area::zeno`, zeno 0.3.3) against the crates themselves, pixel for pixel.
//!
//! Both crates are dev-dependencies: each test calls them directly, the way their adapters
//! (`adapters/ab-glyph/main.rs`, `adapters/zeno/main.rs`) do (`real_ab_glyph`,
//! `real_zeno`: the same contours in the same order, the same f32 rounding, ab_glyph's
//! widened buffer shifted by whole pixels and cropped, zeno's one path under one rule),
//! and asserts that the model gives the same image: ab_glyph's f32 values bit for bit
//! (and so the adapter's 16-bit levels), zeno's 8-bit levels. The models are written from
//! the crates' source (their arithmetic, operation for operation), not from these runs, so
//! the equality is a check of the port, on:
//!
//! - the FreeType tests' family (`tests/adapters_area.rs`'s generator, same seeds): 16x16,
//!   triangles, tangled polygons, star polygons with holes either way, nonzero and
//!   even-odd, on the 1/64, 1/256 and 1/3 grids, reaching 4 px past the canvas;
//! - a wider family: canvases of 1 to 40 px a side, shapes reaching up to 30 px past
//!   them, the 2^-20 grid too (near-horizontal edges, f32 rounding of every coordinate),
//!   triangles and a polygon together (mixed rules, which zeno refuses);
//! - far-reaching shapes for zeno's reciprocal (coordinates up to 4000 px, where
//!   `0xFFFFFF / d` keeps few bits) and ab_glyph's widening (thousands of columns);
//! - `adapters/scenes/glyph.json`, `glyph-even-odd.json` and `dejavu.json`;
//! - the adapters' executables themselves on the glyph scenes and some random ones;
//! - the refusals: each model refuses what its adapter refuses, with the reason named.

use std::path::Path;
use std::process::Command;

use ab_glyph_rasterizer::{point, Rasterizer};
use num_rational::BigRational;
use num_traits::ToPrimitive;
use rasterproof::area::{abglyph, zeno as zeno_model, AreaShape};
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::model::{area_shapes, Model};
use rasterproof::oracle::GreyImage;
use rasterproof::scene::parse_scene;
use serde_json::{json, Value};

use crate::rng::Rng;
use crate::tempdir;

/// The scene's exact shapes and canvas, as the oracle hands them to a model.
fn shapes(scene: &Value) -> (Vec<AreaShape>, u32, u32) {
    let parsed = parse_scene(&scene.to_string(), "scene").unwrap();
    let target = parsed.target().unwrap();
    let shapes = area_shapes(&parsed.primitives(), &target, Model::Exact).unwrap();
    (shapes, target.width, target.height)
}

/// A scene file of `adapters/scenes/`.
fn fixed(name: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes").join(name);
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// ab_glyph_rasterizer drawing `shapes` as the ab_glyph adapter does: one `Rasterizer`
/// widened to the columns of every point, the scene moved right by whole pixels exactly,
/// each coordinate rounded once to f32, every contour's edges (closed) drawn with
/// `draw_line`, the canvas's columns of `for_each_pixel` cut out. `None` where the
/// adapter refuses (even-odd, more than 2^28 cells).
fn real_ab_glyph(shapes: &[AreaShape], width: u32, height: u32) -> Option<Vec<f32>> {
    if shapes.iter().any(|s| s.fill_rule == FillRule::EvenOdd) {
        return None;
    }
    let (mut lo, mut hi) = (0i64, i64::from(width));
    for p in shapes.iter().flat_map(Polygon::contours).flatten() {
        lo = lo.min(p.x.floor().to_integer().to_i64()?);
        hi = hi.max(p.x.ceil().to_integer().to_i64()?);
    }
    if u64::try_from(hi - lo).ok()? * u64::from(height) > 1 << 28 {
        return None;
    }
    let shift = BigRational::from_integer((-lo).into());
    let (w, h) = (usize::try_from(hi - lo).unwrap(), height as usize);
    let mut rasterizer = Rasterizer::new(w, h);
    for contour in shapes.iter().flat_map(Polygon::contours) {
        let points: Vec<_> = contour
            .iter()
            .map(|p| {
                let v = Point::new(&p.x + &shift, p.y.clone()).to_f32().unwrap();
                point(v.x, v.y)
            })
            .collect();
        for (k, &a) in points.iter().enumerate() {
            rasterizer.draw_line(a, points[(k + 1) % points.len()]);
        }
    }
    let (x0, canvas) = (usize::try_from(-lo).unwrap(), width as usize);
    let mut out = vec![0f32; canvas * h];
    rasterizer.for_each_pixel(|index, a| {
        let (x, y) = (index % w, index / w);
        if x >= x0 && x - x0 < canvas {
            out[y * canvas + x - x0] = a;
        }
    });
    Some(out)
}

/// zeno drawing `shapes` as the zeno adapter does: one path (`MoveTo`, `LineTo`s,
/// `Close` per contour, coordinates rounded once to f32) filled by `Mask` with an explicit
/// size under the shapes' one rule. `None` where the adapter refuses (mixed rules, a
/// coordinate of 4096 px or more).
fn real_zeno(shapes: &[AreaShape], width: u32, height: u32) -> Option<Vec<u8>> {
    let rules: Vec<FillRule> = shapes.iter().map(|s| s.fill_rule).collect();
    let fill = match (rules.contains(&FillRule::NonZero), rules.contains(&FillRule::EvenOdd)) {
        (true, true) => return None,
        (false, true) => zeno::Fill::EvenOdd,
        _ => zeno::Fill::NonZero,
    };
    let mut path = Vec::new();
    for contour in shapes.iter().flat_map(Polygon::contours) {
        for (k, p) in contour.iter().enumerate() {
            let v = p.to_f32().filter(|v| v.x.abs() < 4096.0 && v.y.abs() < 4096.0)?;
            let to = zeno::Point::new(v.x, v.y);
            path.push(if k == 0 {
                zeno::Command::MoveTo(to)
            } else {
                zeno::Command::LineTo(to)
            });
        }
        path.push(zeno::Command::Close);
    }
    let (mask, placement) = zeno::Mask::new(&path).size(width, height).style(fill).render();
    assert_eq!((placement.left, placement.top), (0, 0));
    Some(mask)
}

/// The first pixel where two row-major images differ, for a message.
fn first_difference<T: PartialEq + std::fmt::Debug>(ours: &[T], theirs: &[T], width: u32) -> String {
    let w = width as usize;
    match ours.iter().zip(theirs).position(|(a, b)| a != b) {
        Some(k) => format!(
            "pixel ({}, {}): model {:?}, crate {:?} ({} pixels differ)",
            k % w,
            k / w,
            ours[k],
            theirs[k],
            ours.iter().zip(theirs).filter(|(a, b)| a != b).count()
        ),
        None => format!("lengths {} and {}", ours.len(), theirs.len()),
    }
}

/// What one scene gave: `(ab_glyph drawn, zeno drawn, lit pixels)`.
fn check_scene(name: &str, scene: &Value) -> (bool, bool, usize) {
    let (sh, w, h) = shapes(scene);
    let mut lit = 0;
    let ab = match (abglyph::rasterize(&sh, w, h), real_ab_glyph(&sh, w, h)) {
        (Ok(ours), Some(theirs)) => {
            let (ob, tb): (Vec<u32>, Vec<u32>) = (
                ours.iter().map(|v| v.to_bits()).collect(),
                theirs.iter().map(|v| v.to_bits()).collect(),
            );
            assert!(
                ob == tb,
                "ab_glyph, {name}: {} in {scene}",
                first_difference(&ours, &theirs, w)
            );
            let levels = abglyph::levels(&sh, w, h).unwrap();
            assert_eq!(levels, ours.iter().map(|&a| abglyph::level(a)).collect::<Vec<_>>());
            lit += levels.iter().filter(|&&l| l != 0).count();
            true
        }
        (Err(e), None) => {
            assert!(e.contains("even-odd") || e.contains("2^28"), "ab_glyph, {name}: {e}");
            false
        }
        (ours, theirs) => panic!("ab_glyph, {name}: the model gives {ours:?}, the crate {theirs:?}"),
    };
    let z = match (zeno_model::rasterize(&sh, w, h), real_zeno(&sh, w, h)) {
        (Ok(ours), Some(theirs)) => {
            assert!(
                ours == theirs,
                "zeno, {name}: {} in {scene}",
                first_difference(&ours, &theirs, w)
            );
            lit += ours.iter().filter(|&&l| l != 0).count();
            true
        }
        (Err(e), None) => {
            assert!(e.contains("mix") || e.contains("4096"), "zeno, {name}: {e}");
            false
        }
        (ours, theirs) => panic!("zeno, {name}: the model gives {ours:?}, the crate {theirs:?}"),
    };
    (ab, z, lit)
}

/// Scene `k` of a wider family: a canvas of 1 to 40 px a side, points reaching up to
/// `reach` px past it (0 to 30, or up to 4000 when `far`), on a grid of 1/64, 1/256, 1/3
/// or 2^-20 px: 1 to 5 triangles; a tangled polygon of 3 to 14 points; a star polygon
/// with a star hole running either way; or triangles and a polygon together (whose rule
/// may differ from the triangles').
#[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
fn wide_family(k: u64, far: bool) -> Value {
    let mut rng = Rng(0x51ED_2701_9A3C_44F1 ^ (k + 1).wrapping_mul(0x2545_F491_4F6C_DD1D) ^ u64::from(far));
    let d: i64 = [64, 256, 3, 1 << 20][usize::try_from(rng.below(4)).unwrap()];
    let (w, h) = (rng.range(1, 40), rng.range(1, 40));
    let reach = if far { rng.range(100, 3950) } else { rng.range(0, 30) };
    let on_grid = |v: f64| format!("{}/{d}", (v * d as f64).round() as i64);
    let random_point = |rng: &mut Rng| {
        json!([
            on_grid(rng.range(-reach * 64, (w + reach) * 64) as f64 / 64.0 + rng.below(d) as f64 / d as f64),
            on_grid(rng.range(-reach * 64, (h + reach) * 64) as f64 / 64.0 + rng.below(d) as f64 / d as f64)
        ])
    };
    let rule = if rng.below(2) == 0 { "nonzero" } else { "even-odd" };
    let triangles = |rng: &mut Rng| -> Vec<Value> {
        (0..1 + rng.below(5))
            .map(|_| json!({"v": [random_point(rng), random_point(rng), random_point(rng)]}))
            .collect()
    };
    match rng.below(4) {
        0 => json!({"width": w, "height": h, "triangles": triangles(&mut rng)}),
        1 => {
            let outline: Vec<Value> = (0..3 + rng.below(12)).map(|_| random_point(&mut rng)).collect();
            json!({"width": w, "height": h, "polygons": [{"v": outline, "fill_rule": rule}]})
        }
        2 => {
            let t = triangles(&mut rng);
            let outline: Vec<Value> = (0..3 + rng.below(6)).map(|_| random_point(&mut rng)).collect();
            json!({"width": w, "height": h, "triangles": t, "polygons": [{"v": outline, "fill_rule": rule}]})
        }
        _ => {
            let (cx, cy) = (rng.range(0, w * 64) as f64 / 64.0, rng.range(0, h * 64) as f64 / 64.0);
            let big = if far {
                reach as f64
            } else {
                (w.max(h) as f64) * 0.7 + 1.0
            };
            let star = |n: i64, r_lo: f64, r_hi: f64, rng: &mut Rng| -> Vec<Value> {
                (0..n)
                    .map(|i| {
                        let jitter = (rng.below(1001) as f64 / 1000.0 - 0.5) * std::f64::consts::PI / n as f64;
                        let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64 + jitter;
                        let r = r_lo + (r_hi - r_lo) * rng.below(1001) as f64 / 1000.0;
                        json!([on_grid(cx + r * a.cos()), on_grid(cy + r * a.sin())])
                    })
                    .collect()
            };
            let outline = star(5 + rng.below(9), big * 0.3, big, &mut rng);
            let mut hole = star(3 + rng.below(5), 0.4, big * 0.25, &mut rng);
            if rng.below(2) == 0 {
                hole.reverse();
            }
            json!({"width": w, "height": h, "polygons": [{"v": outline, "holes": [hole], "fill_rule": rule}]})
        }
    }
}

/// The FreeType tests' family (300 scenes): both models equal their crates.
#[test]
fn models_equal_the_crates_on_the_freetype_family() {
    let (mut ab, mut z, mut lit) = (0, 0, 0);
    for k in 0..300 {
        let (a, b, l) = check_scene(&format!("scene {k}"), &crate::adapters_area::scene(k));
        (ab, z, lit) = (ab + usize::from(a), z + usize::from(b), lit + l);
    }
    assert!(
        ab >= 150 && z == 300 && lit > 40_000,
        "{ab} ab_glyph, {z} zeno scenes, {lit} lit"
    );
}

/// The wider family (1500 scenes) and far-reaching shapes (300 scenes): both models
/// equal their crates; zeno refuses exactly the scenes that mix rules.
#[test]
fn models_equal_the_crates_on_wide_and_far_scenes() {
    let (mut ab, mut z, mut lit) = (0, 0, 0);
    for (far, n) in [(false, 1500), (true, 300)] {
        for k in 0..n {
            let (a, b, l) = check_scene(&format!("scene {k} (far: {far})"), &wide_family(k, far));
            (ab, z, lit) = (ab + usize::from(a), z + usize::from(b), lit + l);
        }
    }
    assert!(
        ab >= 900 && z >= 1500 && lit > 100_000,
        "{ab} ab_glyph, {z} zeno scenes, {lit} lit"
    );
}

/// The glyph scenes of `adapters/scenes/`: `glyph.json` and `dejavu.json` (7 glyphs, 1214
/// points) through both, `glyph-even-odd.json` through zeno (ab_glyph refuses it).
#[test]
fn models_equal_the_crates_on_the_glyph_scenes() {
    for name in ["glyph.json", "dejavu.json"] {
        let (ab, z, lit) = check_scene(name, &fixed(name));
        assert!(ab && z && lit > 400, "{name}: {ab} {z} {lit}");
    }
    let (ab, z, lit) = check_scene("glyph-even-odd.json", &fixed("glyph-even-odd.json"));
    assert!(!ab && z && lit > 100, "{ab} {z} {lit}");
}

/// Hand scenes on a 6x6 canvas (`tests/adapters_aa_crates.rs` derives their levels from
/// each crate's method): the unit square (2, 3)-(3, 4) gives 65535 and 255 at its pixel
/// alone; the half pixel below the diagonal gives ab_glyph 0.5 exactly (32768) either way
/// round, zeno 128 one way and 127 the other (its 32-bit reciprocal falls 1/256 px short,
/// and `~` lands on the negative orientation, y down). Plus edges whose two y differ by
/// at most `f32::EPSILON`, which ab_glyph skips (a sliver of height 2^-24 between
/// 1/2 and 1/2 + 2^-24: nothing), and a tiny triangle inside one pixel.
#[test]
fn hand_scenes_give_the_derived_levels() {
    let lit =
        |levels: Vec<u16>| -> Vec<(usize, u16)> { levels.into_iter().enumerate().filter(|(_, l)| *l != 0).collect() };
    let at = 3 * 6 + 2;
    let square = json!({"width": 6, "height": 6, "triangles": [
        {"v": [[2, 3], [3, 3], [3, 4]]}, {"v": [[2, 3], [3, 4], [2, 4]]}]});
    let (sh, w, h) = shapes(&square);
    assert_eq!(lit(abglyph::levels(&sh, w, h).unwrap()), [(at, 65535)]);
    let z = zeno_model::rasterize(&sh, w, h).unwrap();
    assert_eq!(lit(z.into_iter().map(u16::from).collect()), [(at, 255)]);
    for (v, zeno_level) in [
        (json!([[2, 3], [3, 4], [2, 4]]), 128),
        (json!([[2, 3], [2, 4], [3, 4]]), 127),
    ] {
        let (sh, w, h) = shapes(&json!({"width": 6, "height": 6, "triangles": [{"v": v}]}));
        assert_eq!(abglyph::rasterize(&sh, w, h).unwrap()[at], 0.5);
        assert_eq!(lit(abglyph::levels(&sh, w, h).unwrap()), [(at, 32768)]);
        let z = zeno_model::rasterize(&sh, w, h).unwrap();
        assert_eq!(lit(z.into_iter().map(u16::from).collect()), [(at, zeno_level)]);
    }
    let sliver = json!({"width": 4, "height": 4, "polygons": [{"v": [
        ["0", "1/2"], ["3", "1/2"], ["3", "8388609/16777216"], ["0", "8388609/16777216"]]}]});
    let tiny = json!({"width": 4, "height": 4, "triangles": [{"v": [["1/4", "1/4"], ["3/4", "1/4"], ["1/4", "3/4"]]}]});
    for (name, scene) in [("sliver", sliver), ("tiny", tiny)] {
        assert!(check_scene(name, &scene).0, "{name}");
    }
    let (sh, w, h) = shapes(&json!({"width": 4, "height": 4, "polygons": [{"v": [
        ["0", "1/2"], ["3", "1/2"], ["3", "8388609/16777216"], ["0", "8388609/16777216"]]}]}));
    assert!(abglyph::rasterize(&sh, w, h).unwrap().iter().all(|&a| a == 0.0));
}

/// Each model refuses what its adapter refuses, naming the reason: ab_glyph an even-odd
/// shape, a widened buffer of more than 2^28 cells, a coordinate beyond f32; zeno a scene
/// mixing nonzero and even-odd shapes, a coordinate of 4096 px or more (4095.99 is
/// drawn, by both the model and the crate, alike), a path of 2^14 edges or more, a canvas
/// of 2^32 pixels.
#[test]
fn models_refuse_what_their_adapters_refuse() {
    let tri = json!({"v": [[0, 0], [4, 0], [0, 4]]});
    let even_odd = json!({"v": [[0, 0], [4, 0], [0, 4]], "fill_rule": "even-odd"});
    let cases: [(Value, &str, &str); 4] = [
        (json!({"width": 4, "height": 4, "polygons": [even_odd]}), "even-odd", ""),
        (
            json!({"width": 4, "height": 4, "triangles": [tri], "polygons": [even_odd]}),
            "even-odd",
            "mix",
        ),
        (
            json!({"width": 1, "height": 3, "triangles": [{"v": [[0, 0], [134217728, 0], [0, 1]]}]}),
            "2^28",
            "4096",
        ),
        (
            json!({"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4096, 0], [0, 4]]}]}),
            "",
            "4096",
        ),
    ];
    for (scene, ab_word, zeno_word) in cases {
        let (sh, w, h) = shapes(&scene);
        match abglyph::rasterize(&sh, w, h) {
            Err(e) => assert!(!ab_word.is_empty() && e.contains(ab_word), "{scene}: {e}"),
            Ok(_) => assert!(ab_word.is_empty(), "{scene}: ab_glyph drew it"),
        }
        assert_eq!(real_ab_glyph(&sh, w, h).is_none(), !ab_word.is_empty(), "{scene}");
        match zeno_model::rasterize(&sh, w, h) {
            Err(e) => assert!(!zeno_word.is_empty() && e.contains(zeno_word), "{scene}: {e}"),
            Ok(_) => assert!(zeno_word.is_empty(), "{scene}: zeno drew it"),
        }
        assert_eq!(real_zeno(&sh, w, h).is_none(), !zeno_word.is_empty(), "{scene}");
    }
    let just_inside =
        json!({"width": 4, "height": 4, "triangles": [{"v": [["-409599/100", 0], [4, "409599/100"], [0, 4]]}]});
    let (ab, z, _) = check_scene("just inside", &just_inside);
    assert!(ab && z);
    // A coordinate beyond f32: neither model has a number for it.
    let huge = "1".to_string() + &"0".repeat(40);
    let (sh, w, h) = shapes(&json!({"width": 2, "height": 2, "triangles": [{"v": [[0, 0], [1, 0], [0, huge]]}]}));
    assert!(abglyph::rasterize(&sh, w, h).is_err_and(|e| e.contains("f32")));
    assert!(zeno_model::rasterize(&sh, w, h).is_err_and(|e| e.contains("4096")));
    // zeno's envelope: 2^14 edges in one path, a canvas of 2^32 pixels.
    let many: Vec<Value> = (0..5462).map(|_| tri.clone()).collect();
    let (sh, w, h) = shapes(&json!({"width": 4, "height": 4, "triangles": many}));
    assert!(zeno_model::rasterize(&sh, w, h).is_err_and(|e| e.contains("2^14")));
    let (sh, _, _) = shapes(&json!({"width": 4, "height": 4, "triangles": [tri]}));
    assert!(zeno_model::rasterize(&sh, 65536, 65536).is_err_and(|e| e.contains("2^32")));
}

/// The adapters' executables themselves (`--serve`, one process each) on the glyph scenes
/// and 20 random ones: their PNGs' levels are the models' levels (ab_glyph's 16-bit, zeno's
/// 8-bit), and their refusals are the models' refusals.
#[test]
fn models_equal_the_adapters_executables() {
    let dir = tempdir::Dir::new("crates-models");
    let mut scenes: Vec<Value> = ["glyph.json", "dejavu.json", "glyph-even-odd.json"].map(fixed).to_vec();
    scenes.extend((0..10).map(crate::adapters_area::scene));
    scenes.extend((0..10).map(|k| wide_family(k, false)));
    for exe in ["ab-glyph-adapter", "zeno-adapter"] {
        let sub = dir.path().join(exe);
        std::fs::create_dir_all(&sub).unwrap();
        let requests: Vec<Value> = scenes
            .iter()
            .enumerate()
            .map(|(k, s)| json!({"rasterproof": 1, "id": k, "scene": s, "out": sub.join(format!("{k}.png"))}))
            .collect();
        let (answers, _) = crate::adapters_area::serve_answers(Command::new(crate::adapters::example(exe)), &requests);
        for (k, (s, answer)) in scenes.iter().zip(&answers).enumerate() {
            let (sh, w, h) = shapes(s);
            let ours: Result<Vec<u16>, String> = if exe == "ab-glyph-adapter" {
                abglyph::levels(&sh, w, h)
            } else {
                zeno_model::rasterize(&sh, w, h).map(|l| l.into_iter().map(u16::from).collect())
            };
            match ours {
                Ok(levels) => {
                    assert_eq!(answer["ok"], true, "{exe} scene {k}: {answer}");
                    let png = std::fs::read(sub.join(format!("{k}.png"))).unwrap();
                    let theirs = GreyImage::read_png(&png, exe).unwrap();
                    assert!(
                        levels == theirs.levels,
                        "{exe} scene {k}: {}",
                        first_difference(&levels, &theirs.levels, w)
                    );
                }
                Err(e) => assert_eq!(
                    answer["ok"], false,
                    "{exe} scene {k}: the model refuses ({e}), the adapter drew it"
                ),
            }
        }
    }
}
