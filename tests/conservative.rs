//! Conservative rasterization: the must and may sets by hand on small cases, the
//! inclusion invariants between them and every sample pattern on random triangles and
//! meshes, and `compare --conservative` judging images.

use crate::common;

use assert_cmd::Command;
use common::{config, q};
use proptest::prelude::*;
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::Coverage;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render_conservative, render_samples, ConservativeRule, Model, Primitives};
use rasterproof::oracle::compare::conservative::compare_conservative;
use rasterproof::oracle::{Format, Theirs};
use rasterproof::pattern::SamplePattern;
use rasterproof::strategy::{any_triangle, delaunay_mesh, tie_heavy_triangle};

fn pixels(c: &Coverage) -> Vec<(u32, u32)> {
    c.iter().map(|(x, y, _)| (x, y)).collect()
}

fn rule(name: &str) -> ConservativeRule {
    ConservativeRule::from_name(name).unwrap()
}

fn tri(v: [[i64; 2]; 3]) -> Triangle {
    let [a, b, c] = v.map(|[x, y]| Point::from_ints(x, y));
    Triangle::new(a, b, c)
}

/// (0,0) (2,0) (0,2) on a 4x4 canvas. Its area overlaps the squares of pixels (0,0),
/// (1,0), (0,1) (each has interior points with x + y < 2). It only touches (1,1) (at the
/// corner (1,1), on the hypotenuse), (2,0) (at the vertex (2,0)), (0,2) (at (0,2)):
/// D3D leaves those to the implementation (may), Vulkan counts them (must). A 1/256 px
/// band reaches no other pixel: the nearest, (2,1) and (1,2), have their nearest corner
/// on x + y = 3, 1/sqrt 2 px from the hypotenuse. Tier 1's half pixel: pixel (i, j)'s
/// square grown by 1/2 meets the triangle when max(0, i - 1/2) + max(0, j - 1/2) <= 2,
/// which adds (2,1) and (1,2) (exactly 2) and not (3,0) (5/2) or (2,2) (3).
#[test]
fn a_right_triangle_by_hand() {
    let target = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
    let scene = Primitives::from_triangles(&[tri([[0, 0], [2, 0], [0, 2]])]);
    let overlap = vec![(0, 0), (1, 0), (0, 1)];
    let touch = vec![(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (0, 2)];
    let tier2 = render_conservative(&scene, &target, &rule("d3d12-tier2")).unwrap();
    assert_eq!(pixels(&tier2.must), overlap);
    assert_eq!(pixels(&tier2.may), touch);
    let vulkan = render_conservative(&scene, &target, &rule("vulkan")).unwrap();
    assert_eq!(pixels(&vulkan.must), touch);
    assert_eq!(pixels(&vulkan.may), touch);
    let tier1 = render_conservative(&scene, &target, &rule("d3d12-tier1")).unwrap();
    assert_eq!(pixels(&tier1.must), overlap);
    assert_eq!(
        pixels(&tier1.may),
        vec![(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (2, 1), (0, 2), (1, 2)]
    );
    // Inner: only pixel (0,0)'s square [0,1]^2 lies inside (its corner (1,1) on the
    // hypotenuse); grown by 1/256 it leaves the triangle (x < 0), so no pixel must be
    // reported fully covered.
    let (inner_must, inner_may) = render_conservative(&scene, &target, &rule("d3d12-tier3"))
        .unwrap()
        .inner
        .unwrap();
    assert_eq!(pixels(&inner_may), vec![(0, 0)]);
    assert!(pixels(&inner_must).is_empty());
    assert!(tier2.inner.is_none());
}

/// A bigger triangle (0,0) (8,0) (0,8): pixel (1,1)'s square grown by 1/256 is inside
/// (its far corner (2 + 1/256, 2 + 1/256) has x + y = 4 + 1/128 < 8, and its near corner
/// is at 1 - 1/256 > 0), so it must be reported fully covered; pixel (3,3)'s square has
/// its corner (4,4) on the hypotenuse: may, not must.
#[test]
fn inner_coverage_by_hand() {
    let target = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    let scene = Primitives::from_triangles(&[tri([[0, 0], [8, 0], [0, 8]])]);
    let (must, may) = render_conservative(&scene, &target, &rule("d3d12-tier3"))
        .unwrap()
        .inner
        .unwrap();
    assert!(!must.owners(1, 1).is_empty());
    assert!(must.owners(3, 3).is_empty() && !may.owners(3, 3).is_empty());
    assert!(must.owners(0, 0).is_empty(), "grown, it leaves the triangle at x < 0");
    assert!(may.owners(4, 3).is_empty(), "(5, 4) is outside");
    // Inside squares: i + j + 2 <= 8 for the may set; the must set also needs i, j >= 1.
    let count = |lim: i64, from: i64| {
        (from..8)
            .flat_map(|i| (from..8).map(move |j| (i, j)))
            .filter(|(i, j)| i + j + 2 <= lim)
            .count()
    };
    assert_eq!(may.covered_pixels(), count(8, 0));
    assert_eq!(
        must.covered_pixels(),
        count(7, 1),
        "x + y <= 8 - 1/128 for the far corner"
    );
}

/// A triangle of zero area along the row boundary y = 1 from x = 0 to x = 2: no open
/// square meets it, so tier 2 requires one of the pixels it touches (the closed squares
/// of (0,0) (1,0) (2,0) (0,1) (1,1) (2,1)); tier 1 may cull it. An image covering none
/// of them is wrong under tier 2 (vanished), one covering (1,1) is right.
#[test]
fn a_degenerate_triangle_must_not_vanish_under_tier_2() {
    let target = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
    let scene = Primitives::from_triangles(&[tri([[0, 1], [2, 1], [1, 1]])]);
    let tier2 = render_conservative(&scene, &target, &rule("d3d12-tier2")).unwrap();
    assert!(pixels(&tier2.must).is_empty());
    assert_eq!(
        tier2.one_of,
        vec![(0, vec![(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (2, 1)])]
    );
    let tier1 = render_conservative(&scene, &target, &rule("d3d12-tier1")).unwrap();
    assert!(tier1.one_of.is_empty() && pixels(&tier1.must).is_empty());
    let image = |covered: &[(u32, u32)]| {
        let mut c = Coverage::new(4, 4);
        for &(x, y) in covered {
            rasterproof::coverage::CoverageSink::cover(&mut c, x, y, 0);
        }
        Theirs::from_coverage(&c, Format::Mask)
    };
    let nothing = compare_conservative(&scene, &target, &image(&[]), &rule("d3d12-tier2")).unwrap();
    assert_eq!(nothing.vanished, vec![0]);
    assert!(!nothing.identical());
    assert!(
        compare_conservative(&scene, &target, &image(&[(1, 1)]), &rule("d3d12-tier2"))
            .unwrap()
            .identical()
    );
    let far = compare_conservative(&scene, &target, &image(&[(1, 1), (3, 3)]), &rule("d3d12-tier2")).unwrap();
    assert_eq!(far.beyond, vec![(3, 3)]);
    assert!(compare_conservative(&scene, &target, &image(&[]), &rule("d3d12-tier1"))
        .unwrap()
        .identical());
}

fn subset(a: &Coverage, b: &Coverage) -> Result<(), (u32, u32)> {
    match a.iter().find(|(x, y, _)| b.owners(*x, *y).is_empty()) {
        Some((x, y, _)) => Err((x, y)),
        None => Ok(()),
    }
}

/// The pixels where every sample of `c` is covered.
fn all_samples(c: &rasterproof::coverage::samples::SampleCoverage) -> Coverage {
    let full = (1u64 << c.sample_count()) - 1;
    let mut out = Coverage::new(c.width(), c.height());
    for (x, y) in c.covered_pixels() {
        if c.mask(x, y) == full {
            rasterproof::coverage::CoverageSink::cover(&mut out, x, y, 0);
        }
    }
    out
}

/// The pixels where some sample of `c` is covered.
fn any_sample(c: &rasterproof::coverage::samples::SampleCoverage) -> Coverage {
    let mut out = Coverage::new(c.width(), c.height());
    for (x, y) in c.covered_pixels() {
        rasterproof::coverage::CoverageSink::cover(&mut out, x, y, 0);
    }
    out
}

proptest! {
    #![proptest_config(config("proptest-regressions/conservative.txt"))]

    /// For every rule and standard pattern: inner must ⊆ every sample covered ⊆ some
    /// sample covered ⊆ may (the snapped triangle's samples); and, for the rules that keep
    /// every triangle (tiers 2 and 3, the samples of the triangle as given, patterns with
    /// no sample on the pixel's boundary: 1, 2, 4, 8), some sample covered ⊆ must; must ⊆
    /// may; inner may ⊆ may.
    #[test]
    fn the_sets_nest_around_every_sample_pattern(
        tris in prop::collection::vec(prop_oneof![any_triangle(10), tie_heavy_triangle(10)], 1..=3),
        count in prop::sample::select(vec![1usize, 2, 4, 8, 16]),
        name in prop::sample::select(vec!["d3d12-tier1", "d3d12-tier2", "d3d12-tier3", "vulkan"]),
    ) {
        let target = Target::new(10, 10, Preset::D3d11.convention()).unwrap();
        let pattern = SamplePattern::standard(count).unwrap();
        let rule = rule(name);
        for t in &tris {
            let scene = Primitives::from_triangles(std::slice::from_ref(t));
            let sets = render_conservative(&scene, &target, &rule).unwrap();
            let snapped = render_samples(&scene, &target, &pattern, Model::ExactSnapped).unwrap();
            prop_assert_eq!(subset(&sets.must, &sets.may), Ok(()));
            prop_assert_eq!(subset(&all_samples(&snapped), &any_sample(&snapped)), Ok(()));
            prop_assert_eq!(subset(&any_sample(&snapped), &sets.may), Ok(()), "{}", name);
            if let Some((inner_must, inner_may)) = &sets.inner {
                prop_assert_eq!(subset(inner_must, &all_samples(&snapped)), Ok(()), "{}", name);
                prop_assert_eq!(subset(inner_must, inner_may), Ok(()));
                prop_assert_eq!(subset(inner_may, &sets.may), Ok(()));
            }
            if !rule.cull_degenerate && count <= 8 {
                let exact = render_samples(&scene, &target, &pattern, Model::Exact).unwrap();
                prop_assert_eq!(subset(&any_sample(&exact), &sets.must), Ok(()), "{}", name);
            }
        }
    }

    /// Independent of the separating-axis test: a point of a fine grid strictly inside a
    /// pixel's open square and strictly inside the triangle puts the pixel in the must set
    /// of every rule that keeps the triangle; and a pixel in no rule's may set has no
    /// grid point (closed) in the triangle.
    #[test]
    fn a_fine_grid_agrees_with_the_sets(t in any_triangle(6)) {
        let target = Target::new(6, 6, Preset::D3d11.convention()).unwrap();
        let scene = Primitives::from_triangles(std::slice::from_ref(&t));
        let sets = render_conservative(&scene, &target, &rule("d3d12-tier2")).unwrap();
        let [a, b, c] = &t.v;
        let cross = |p: &Point, q: &Point, r: &Point| (&q.x - &p.x) * (&r.y - &p.y) - (&q.y - &p.y) * (&r.x - &p.x);
        let area = cross(a, b, c);
        let zero = q(0, 1);
        for j in 0..6i64 {
            for i in 0..6i64 {
                let mut strictly = false;
                let mut closed = false;
                for gy in 0..=8 {
                    for gx in 0..=8 {
                        let p = Point::new(q(8 * i + gx, 8), q(8 * j + gy, 8));
                        let e = [cross(a, b, &p), cross(b, c, &p), cross(c, a, &p)];
                        let interior = (1..8).contains(&gx) && (1..8).contains(&gy);
                        let sign = |v: &num_rational::BigRational| if area > zero { v > &zero } else { v < &zero };
                        if area != zero && interior && e.iter().all(sign) {
                            strictly = true;
                        }
                        if area != zero && e.iter().all(|v| v == &zero || sign(v)) {
                            closed = true;
                        }
                    }
                }
                let (x, y) = (u32::try_from(i).unwrap(), u32::try_from(j).unwrap());
                if strictly {
                    prop_assert!(!sets.must.owners(x, y).is_empty(), "({}, {})", x, y);
                }
                if closed {
                    prop_assert!(!sets.may.owners(x, y).is_empty(), "({}, {})", x, y);
                }
            }
        }
    }

    /// On a mesh, every pixel where some sample is covered (any model that snaps, any
    /// standard pattern) is in the union of the triangles' may sets.
    #[test]
    fn meshes_stay_inside_their_may_sets(mesh in delaunay_mesh([1, 1], 8, 2, 8)) {
        let target = Target::new(10, 10, Preset::D3d11.convention()).unwrap();
        let scene = Primitives::from_triangles(&mesh.triangles);
        let sets = render_conservative(&scene, &target, &rule("d3d12-tier2")).unwrap();
        for count in [1, 4, 16] {
            let c = render_samples(&scene, &target, &SamplePattern::standard(count).unwrap(), Model::Fixed).unwrap();
            prop_assert_eq!(subset(&any_sample(&c), &sets.may), Ok(()));
        }
    }
}

/// The CLI: `render --conservative` prints the sets, `compare --conservative` judges a
/// mask: the must set itself is right, one pixel fewer is missing, an image beyond the
/// may set is wrong; polygons are refused.
#[test]
fn render_and_compare_conservatively() {
    let dir = crate::tempdir::Dir::new("conservative-cli");
    let scene = dir.path().join("t.json");
    std::fs::write(
        &scene,
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [2, 0], [0, 2]]}]}"#,
    )
    .unwrap();
    let cli = || Command::cargo_bin("rasterproof").unwrap();
    let out = cli()
        .arg("render")
        .arg(&scene)
        .args(["--conservative", "d3d12-tier2"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("##+.\n#+..\n+...\n....\n"), "{text}");
    let mask = |rows: &[&str]| {
        let path = dir.path().join(format!("{}.png", rows.join("_")));
        let img = image::GrayImage::from_fn(4, 4, |x, y| {
            image::Luma([if rows[y as usize].as_bytes()[x as usize] == b'#' {
                255
            } else {
                0
            }])
        });
        img.save(&path).unwrap();
        path
    };
    let judge = |png: &std::path::Path| {
        cli()
            .arg("compare")
            .arg(&scene)
            .arg(png)
            .args(["--as", "mask", "--conservative", "d3d12-tier2"])
            .output()
            .unwrap()
    };
    let right = judge(&mask(&["##..", "#...", "....", "...."]));
    assert_eq!(
        right.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&right.stdout)
    );
    let missing = judge(&mask(&["##..", "....", "....", "...."]));
    assert_eq!(missing.status.code(), Some(1));
    assert!(String::from_utf8(missing.stdout)
        .unwrap()
        .contains("(0, 1) missing: triangles [0] overlap the pixel's square"));
    let beyond = judge(&mask(&["###.", "##..", "#...", "...#"]));
    let beyond = String::from_utf8(beyond.stdout).unwrap();
    assert!(
        beyond.contains("1 beyond the uncertainty region") && beyond.contains("(3, 3) beyond"),
        "{beyond}"
    );
    assert!(beyond.contains("band (may, not must): 3 covered, 0 not"), "{beyond}");
    assert!(
        beyond.contains("(2, 0) band, covered: within the uncertainty region of triangles [0], not overlapped"),
        "{beyond}"
    );
    let poly = dir.path().join("p.json");
    std::fs::write(
        &poly,
        r#"{"width": 4, "height": 4, "polygons": [{"v": [[0, 0], [2, 0], [0, 2]]}]}"#,
    )
    .unwrap();
    let refused = cli()
        .arg("render")
        .arg(&poly)
        .args(["--conservative", "vulkan"])
        .output()
        .unwrap();
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8(refused.stderr)
        .unwrap()
        .contains("polygons: conservative rasterization is defined for triangles"));
    let unknown = cli()
        .arg("render")
        .arg(&scene)
        .args(["--conservative", "tier9"])
        .output()
        .unwrap();
    assert!(String::from_utf8(unknown.stderr)
        .unwrap()
        .contains("--conservative: unknown rule \"tier9\""));
}
