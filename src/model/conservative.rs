//! Conservative rasterization of a scene's triangles: the pixels a renderer **must** cover
//! and those it **may** cover, exactly ([`render_conservative`]). A renderer is right when
//! `must ⊆ theirs ⊆ may` (and, for a degenerate triangle that must not vanish, it covers
//! one pixel of those it touches).
//!
//! The rules, from the Direct3D 12 specification ("Conservative Rasterization", the tiers
//! of `D3D12_CONSERVATIVE_RASTERIZATION_TIER`) and Vulkan's
//! `VK_EXT_conservative_rasterization`:
//!
//! - **Overestimation**: a pixel is covered when any part of the primitive overlaps the
//!   pixel's square, judged against the triangle as given (D3D: "conservative with
//!   respect to the original floating point vertex coordinates"). Where an edge or a
//!   corner of the triangle only touches the pixel's edge or corner, D3D leaves the
//!   answer to the implementation (so such a pixel is *may*, not *must*); Vulkan counts
//!   the primitive's edges and the pixel's sides (*must*).
//! - **The uncertainty region**: the snapped triangle (the convention's subpixel grid:
//!   D3D's 16.8 fixed point) swept by a square of half-side `u` (1/2 px for tier 1,
//!   1/256 for tiers 2 and 3; Vulkan's `primitiveOverestimationSize` plus any extra): a
//!   pixel whose square meets it *may* be covered.
//! - **Degenerate triangles** (zero area after snapping): tier 1 and a Vulkan device
//!   without `degenerateTrianglesRasterized` may cull them (nothing *must* be covered);
//!   tiers 2 and 3 must not, and "a degenerate triangle along an edge or corner must
//!   cover at least one pixel" (so when it only touches pixel boundaries, one of the
//!   pixels it touches must be covered).
//! - **Underestimation** (tier 3's `SV_InnerCoverage`, Vulkan's underestimation mode and
//!   `FullyCoveredEXT`): a pixel *may* be reported fully covered when its square lies
//!   inside the triangle as given, and *must* be when its square grown by `u` lies inside
//!   both the triangle as given and the snapped one.
//!
//! Every test is [`crate::tri::conservative`]'s exact geometry.

use std::fmt;

use num_rational::BigRational;
use num_traits::Zero;

use super::Primitives;
use crate::convention::Target;
use crate::coverage::{Coverage, CoverageSink};
use crate::geom::Triangle;
use crate::raster::exact_pixel_range_grown;
use crate::tri::conservative::{pixel_square, ConservativeTriangle};

/// A conservative rasterization rule.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConservativeRule {
    /// Its name as the command line writes it (`d3d12-tier2`, `vulkan`).
    pub name: String,
    /// The half-side of the square swept along the snapped triangle: the uncertainty
    /// region, in pixels.
    pub uncertainty: BigRational,
    /// Whether a pixel the triangle only touches (at an edge or a corner of its square)
    /// must be covered (Vulkan) or may be (D3D).
    pub touching_must: bool,
    /// Whether a triangle of zero area after snapping may be culled.
    pub cull_degenerate: bool,
    /// Whether inner coverage (underestimation) is judged too.
    pub inner: bool,
}

impl ConservativeRule {
    /// D3D12's tier 1, 2 or 3; `None` for another number.
    pub fn d3d12(tier: u32) -> Option<ConservativeRule> {
        let (uncertainty, cull, inner) = match tier {
            1 => (BigRational::new(1.into(), 2.into()), true, false),
            2 => (BigRational::new(1.into(), 256.into()), false, false),
            3 => (BigRational::new(1.into(), 256.into()), false, true),
            _ => return None,
        };
        Some(ConservativeRule {
            name: format!("d3d12-tier{tier}"),
            uncertainty,
            touching_must: false,
            cull_degenerate: cull,
            inner,
        })
    }

    /// Vulkan's `VK_EXT_conservative_rasterization`, overestimation with `size` pixels of
    /// overestimation (`primitiveOverestimationSize` plus the extra asked for), degenerate
    /// triangles culled or rasterized, and underestimation (`FullyCoveredEXT`) judged.
    pub fn vulkan(size: BigRational, degenerates_rasterized: bool) -> ConservativeRule {
        ConservativeRule {
            name: "vulkan".to_string(),
            uncertainty: size,
            touching_must: true,
            cull_degenerate: !degenerates_rasterized,
            inner: true,
        }
    }

    /// A rule by its command-line name: `d3d12-tier1`, `d3d12-tier2`, `d3d12-tier3`, or
    /// `vulkan` (1/256 px of overestimation, degenerates may be culled).
    pub fn from_name(name: &str) -> Option<ConservativeRule> {
        match name {
            "d3d12-tier1" => ConservativeRule::d3d12(1),
            "d3d12-tier2" => ConservativeRule::d3d12(2),
            "d3d12-tier3" => ConservativeRule::d3d12(3),
            "vulkan" => Some(ConservativeRule::vulkan(BigRational::new(1.into(), 256.into()), false)),
            _ => None,
        }
    }
}

impl fmt::Display for ConservativeRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} (uncertainty {} px, touching pixels {}, degenerates {}{})",
            self.name,
            crate::num::exact::exact_text(&self.uncertainty),
            if self.touching_must { "must" } else { "may" },
            if self.cull_degenerate { "may be culled" } else { "kept" },
            if self.inner { ", inner coverage" } else { "" }
        )
    }
}

/// What a conservative renderer must and may cover.
#[derive(Debug, Clone, PartialEq)]
pub struct ConservativeCoverage {
    /// Overestimation: the pixels that must be covered, with the triangles that make them.
    pub must: Coverage,
    /// Overestimation: the pixels that may be covered (`must` among them).
    pub may: Coverage,
    /// Underestimation, when the rule has it: the pixels that must be reported fully
    /// covered, and those that may be.
    pub inner: Option<(Coverage, Coverage)>,
    /// Degenerate triangles that must not vanish but touch pixels only at their
    /// boundaries: `(id, pixels)`, one of which must be covered.
    pub one_of: Vec<(u32, Vec<(u32, u32)>)>,
}

impl ConservativeCoverage {
    /// For programs (`render --conservative --format json`): `{"width", "height", "rule",
    /// "must": [[x, y, [ids]]], "may": [...], "one_of": [[id, [[x, y]]]]}`, and
    /// `"inner_must"`, `"inner_may"` where the rule has underestimation.
    pub fn to_json(&self, rule: &ConservativeRule) -> serde_json::Value {
        let pixels = |c: &Coverage| {
            c.iter()
                .map(|(x, y, ids)| serde_json::json!([x, y, ids]))
                .collect::<Vec<_>>()
        };
        let one_of = |(id, px): &(u32, Vec<(u32, u32)>)| {
            serde_json::json!([id, px.iter().map(|(x, y)| [x, y]).collect::<Vec<_>>()])
        };
        let mut v = serde_json::json!({
            "width": self.must.width(), "height": self.must.height(), "rule": rule.to_string(),
            "must": pixels(&self.must), "may": pixels(&self.may),
            "one_of": self.one_of.iter().map(one_of).collect::<Vec<_>>(),
        });
        if let Some((must, may)) = &self.inner {
            v["inner_must"] = serde_json::json!(pixels(must));
            v["inner_may"] = serde_json::json!(pixels(may));
        }
        v
    }
}

/// Why a scene cannot be rasterized conservatively.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConservativeError(pub String);

impl fmt::Display for ConservativeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ConservativeError {}

/// The must and may sets of `primitives`' triangles under `rule` (see the module docs),
/// snapping with `target`'s convention.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_conservative, ConservativeRule, Primitives};
/// // (0,0) (2,0) (0,2) on 3x3: pixels (0,0) (1,0) (0,1) overlap it; (1,1), (2,0) and
/// // (0,2) only touch it (D3D: may); tier 1's half pixel reaches every pixel but (2,2),
/// // whose square grown by 1/2 starts at x + y = 3.
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(2, 0), Point::from_ints(0, 2));
/// let target = Target::new(3, 3, Convention::default()).unwrap();
/// let scene = Primitives::from_triangles(&[t]);
/// let c = render_conservative(&scene, &target, &ConservativeRule::d3d12(2).unwrap()).unwrap();
/// assert_eq!(c.must.covered_pixels(), 3);
/// assert_eq!(c.may.covered_pixels(), 6);
/// let c = render_conservative(&scene, &target, &ConservativeRule::d3d12(1).unwrap()).unwrap();
/// assert_eq!(c.may.covered_pixels(), 8);
/// ```
///
/// # Errors
/// Lines, polygons, clip-space triangles or a clip window: conservative rasterization is
/// defined for triangles.
pub fn render_conservative(
    primitives: &Primitives,
    target: &Target,
    rule: &ConservativeRule,
) -> Result<ConservativeCoverage, ConservativeError> {
    let others = [
        ("lines", primitives.lines.len()),
        ("polygons", primitives.polygons.len()),
        ("clip_space_triangles", primitives.clip_space_triangles.len()),
        ("clip", usize::from(primitives.clip.is_some())),
    ];
    if let Some((field, _)) = others.iter().find(|(_, n)| *n > 0) {
        return Err(ConservativeError(format!(
            "{field}: conservative rasterization is defined for triangles (D3D12, VK_EXT_conservative_rasterization); this scene has {field}"
        )));
    }
    let (w, h) = (target.width, target.height);
    let mut out = ConservativeCoverage {
        must: Coverage::new(w, h),
        may: Coverage::new(w, h),
        inner: rule.inner.then(|| (Coverage::new(w, h), Coverage::new(w, h))),
        one_of: Vec::new(),
    };
    let zero = BigRational::zero();
    for (id, t) in (0u32..).zip(&primitives.triangles) {
        let snapped_triangle = t.snapped(&target.convention).to_exact();
        let t = &t.to_triangle();
        let (given, snapped) = (
            ConservativeTriangle::new(t),
            ConservativeTriangle::new(&snapped_triangle),
        );
        let culled = rule.cull_degenerate && snapped.is_degenerate();
        let keep_one = !rule.cull_degenerate && snapped.is_degenerate();
        let mut touched = Vec::new();
        let mut must_any = false;
        for (i, j) in pixels_near(t, &snapped_triangle, &rule.uncertainty, target) {
            let (x, y) = (i64::from(i), i64::from(j));
            let square = pixel_square(x, y, &zero);
            let must = !culled && given.meets(&square, rule.touching_must);
            let grown = pixel_square(x, y, &rule.uncertainty);
            let may = must || snapped.meets(&grown, true) || given.meets(&square, true);
            if must {
                out.must.cover(i, j, id);
                must_any = true;
            }
            if may {
                out.may.cover(i, j, id);
            }
            if keep_one && snapped.meets(&square, true) {
                touched.push((i, j));
            }
            if let Some((inner_must, inner_may)) = &mut out.inner {
                if given.contains_square(&square) {
                    inner_may.cover(i, j, id);
                    if given.contains_square(&grown) && snapped.contains_square(&grown) {
                        inner_must.cover(i, j, id);
                    }
                }
            }
        }
        if keep_one && !must_any && !touched.is_empty() {
            out.one_of.push((id, touched));
        }
    }
    Ok(out)
}

/// The canvas pixels whose square grown by `grow` may meet `a` or `b`: those whose grown
/// square meets the bounding box of both.
fn pixels_near(a: &Triangle, b: &Triangle, grow: &BigRational, target: &Target) -> Vec<(u32, u32)> {
    let Some(r) = exact_pixel_range_grown(a.v.iter().chain(b.v.iter()), grow, target) else {
        return Vec::new();
    };
    (r.y0..=r.y1).flat_map(|j| (r.x0..=r.x1).map(move |i| (i, j))).collect()
}
