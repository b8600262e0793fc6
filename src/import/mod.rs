//! Geometry users already hold, turned into a scene exactly as its floats read:
//! RenderDoc's mesh-viewer CSV export of post-transform positions ([`renderdoc`]) and raw
//! little-endian f32 position buffers with an optional index buffer ([`raw`]). What
//! `rasterproof import` runs.
//!
//! - **Exact.** A float in a buffer is its exact dyadic value ([`exact_f32`]: `0.1f32` is
//!   `13421773/134217728`, not `1/10`). A number printed as text (the CSV) is the f32 that
//!   text rounds to (Rust's correctly rounded `str::parse::<f32>`), then exactly that
//!   f32: RenderDoc prints a float with limited digits, and the f32 the GPU held is the
//!   nearest one to the text. [`renderdoc::CsvOptions::exact_decimal`] keeps the text's
//!   decimal exactly instead.
//! - **Clip space** becomes the scene's `clip_space_triangles` with its `viewport`;
//!   **window space** (raw buffers only) its `triangles`. The scene is built by
//!   [`Scene::new`] and written by [`Scene::to_json`], so it parses back to the same scene.
//! - **The viewport as the API states it** ([`ApiViewport`], [`scene_viewport`]): D3D and
//!   Vulkan give its top-left corner in a y-down window, as the scene does; OpenGL's
//!   `glViewport` gives its lower-left corner in a y-up window, mirrored here into the
//!   scene's y-down image of the canvas height; a Vulkan viewport of negative height
//!   (VK_KHR_maintenance1) is the same rectangle seen with NDC y up.
//!
//! References: RenderDoc's documentation, "Buffer Viewer / Mesh Viewer" (renderdoc.org/docs,
//! window/buffer_viewer), and its export code (qrenderdoc BufferViewer.cpp,
//! `BufferViewer::exportData`); the viewport transforms of the Direct3D 11 functional
//! specification ("Viewport"), the Vulkan specification ("Controlling the Viewport") and
//! the OpenGL 4.6 core specification (§13.8.1, "Controlling the Viewport").

use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::clip::homogeneous::{ClipVertex, NdcY, Viewport};
use crate::convention::{Preset, MAX_CANVAS};
use crate::geom::Triangle;
use crate::num::exact::{dyadic, exact_text};
use crate::scene::parse::MAX_TRIANGLES;
use crate::scene::{preset_ndc, Scene};

pub mod raw;
pub mod renderdoc;

/// Bad import input: which file, and where in it, what value, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImportError {
    /// The file (or the option, `--viewport`), as the user named it.
    pub source: String,
    /// What is wrong, starting with where: `row 7, SV_Position.w: "nan" is not a finite
    /// number`.
    pub message: String,
}

impl ImportError {
    /// An error of `source`.
    pub fn new(source: &str, message: impl Into<String>) -> ImportError {
        ImportError {
            source: source.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.source, self.message)
    }
}

impl std::error::Error for ImportError {}

/// The exact value of a finite f32 (`None` for NaN and the infinities): its integer
/// significand over a power of two, by [`dyadic`]. No rounding: every finite f32 is a
/// dyadic rational.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::import::exact_f32;
/// assert_eq!(exact_f32(0.1), Some(BigRational::new(13421773.into(), 134217728.into())));
/// assert_eq!(exact_f32(-3.0), Some(BigRational::from_integer((-3).into())));
/// assert_eq!(exact_f32(f32::NAN), None);
/// ```
pub fn exact_f32(f: f32) -> Option<BigRational> {
    if !f.is_finite() {
        return None;
    }
    let bits = f.to_bits();
    let biased = (bits >> 23) & 0xff;
    let fraction = bits & 0x7f_ffff;
    // value = significand * 2^exponent: subnormals have no hidden bit and exponent -149.
    let (significand, exponent) = if biased == 0 {
        (fraction, -149)
    } else {
        (fraction | 0x80_0000, i32::try_from(biased).expect("8 bits") - 150)
    };
    let mut significand = BigInt::from(significand);
    if bits >> 31 == 1 {
        significand = -significand;
    }
    Some(if exponent >= 0 {
        BigRational::from_integer(significand << exponent.unsigned_abs())
    } else {
        dyadic(&significand, exponent.unsigned_abs())
    })
}

/// A viewport as the API states it (D3D's `TopLeftX, TopLeftY, Width, Height`, Vulkan's
/// `x, y, width, height`, `glViewport(x, y, w, h)`), its numbers exact.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApiViewport {
    /// Left edge, pixels.
    pub x: BigRational,
    /// D3D and Vulkan: the top edge (y down); GL: the bottom edge (y up).
    pub y: BigRational,
    /// Width, pixels.
    pub width: BigRational,
    /// Height, pixels (negative only for Vulkan's flipped viewport).
    pub height: BigRational,
}

impl ApiViewport {
    /// The whole canvas: `0, 0, width, height`.
    pub fn canvas(width: u32, height: u32) -> ApiViewport {
        let int = |v: u32| BigRational::from_integer(v.into());
        ApiViewport {
            x: int(0),
            y: int(0),
            width: int(width),
            height: int(height),
        }
    }

    /// `X,Y,W,H`, each an exact decimal or fraction, spaces around each allowed; `None`
    /// for anything else.
    pub fn parse(text: &str) -> Option<ApiViewport> {
        let parts: Vec<BigRational> = text
            .split(',')
            .map(|p| crate::num::parse_rational(p.trim()).ok())
            .collect::<Option<_>>()?;
        let [x, y, width, height]: [BigRational; 4] = parts.try_into().ok()?;
        Some(ApiViewport { x, y, width, height })
    }

    /// `X,Y,W,H` as exact text.
    pub fn text(&self) -> String {
        [&self.x, &self.y, &self.width, &self.height].map(exact_text).join(",")
    }
}

/// The scene's [`Viewport`] (y down, its top edge and a positive height, which NDC y is
/// at the top, the depth range) for the API viewport `api` under `preset`, on a canvas
/// `canvas_height` pixels high. The preset decides the API: `vulkan` (NDC y down, depth
/// `0..1`), `gl` (NDC y up, depth `-1..1`, the viewport's y measured up from the bottom
/// of the window), `d3d11` and `cts` (NDC y up, depth `0..1`, y measured down from the
/// top).
///
/// - D3D: `y_win = TopLeftY + (1 - y_ndc) H / 2`, y down: the scene's own form.
/// - Vulkan: `y_win = y + (1 + y_ndc) h / 2`, y down. With `h < 0` (VK_KHR_maintenance1)
///   that is `(y + h) + (1 - y_ndc) |h| / 2`: top `y + h`, height `|h|`, NDC y up.
/// - GL: `y_gl = y + (1 + y_ndc) h / 2` counts up from the bottom row; the scene's image is
///   the framebuffer seen top row first (as RenderDoc's texture viewer shows it, and
///   `glReadPixels`' rows reversed), so `y_win = H_canvas - y_gl = (H_canvas - y - h) +
///   (1 - y_ndc) h / 2`: top `H_canvas - y - h`, NDC y up.
///
/// ```
/// use rasterproof::clip::homogeneous::NdcY;
/// use rasterproof::convention::Preset;
/// use rasterproof::import::{scene_viewport, ApiViewport};
/// // glViewport(0, 2, 8, 4) on a 10 px high window: its top edge is row 10 - 2 - 4 = 4.
/// let vp = scene_viewport(&ApiViewport::parse("0,2,8,4").unwrap(), Preset::Gl, 10).unwrap();
/// assert_eq!((vp.y.to_string(), vp.y_axis), ("4".to_string(), NdcY::Up));
/// // A flipped Vulkan viewport (y = 8, height -8) is 0..8 with NDC y up.
/// let vp = scene_viewport(&ApiViewport::parse("0,8,8,-8").unwrap(), Preset::Vulkan, 8).unwrap();
/// assert_eq!((vp.y.to_string(), vp.height.to_string(), vp.y_axis), ("0".to_string(), "8".to_string(), NdcY::Up));
/// ```
///
/// # Errors
/// A width that is not positive, or a height that is not positive (negative allowed
/// under `vulkan` only, zero never): one sentence with the value.
pub fn scene_viewport(api: &ApiViewport, preset: Preset, canvas_height: u32) -> Result<Viewport, String> {
    let (ndc_y, depth) = preset_ndc(preset);
    if !api.width.is_positive() {
        return Err(format!("the width {} is not positive", exact_text(&api.width)));
    }
    let flipped = preset == Preset::Vulkan && api.height.is_negative();
    if api.height.is_zero() || (api.height.is_negative() && !flipped) {
        return Err(format!(
            "the height {} is not positive (a negative height flips the viewport under vulkan only)",
            exact_text(&api.height)
        ));
    }
    let (top, height, y_axis) = if flipped {
        (&api.y + &api.height, -&api.height, NdcY::Up)
    } else if preset == Preset::Gl {
        let canvas = BigRational::from_integer(canvas_height.into());
        (canvas - &api.y - &api.height, api.height.clone(), ndc_y)
    } else {
        (api.y.clone(), api.height.clone(), ndc_y)
    };
    Viewport::new(api.x.clone(), top, api.width.clone(), height, y_axis, depth)
        .ok_or_else(|| "the viewport is empty".to_string())
}

/// Where the imported primitives go: the canvas, the preset, and for clip space the
/// viewport as the API states it (`None`: the whole canvas).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImportTarget {
    /// Canvas width, `1..=MAX_CANVAS`.
    pub width: u32,
    /// Canvas height, `1..=MAX_CANVAS`.
    pub height: u32,
    /// The preset: the scene's, and the API whose viewport and clip-space conventions
    /// apply ([`scene_viewport`]).
    pub preset: Preset,
    /// The viewport (clip space only); `None` is the whole canvas.
    pub viewport: Option<ApiViewport>,
}

impl ImportTarget {
    /// The canvas checked: each side in `1..=MAX_CANVAS`.
    ///
    /// # Errors
    /// A side out of range, naming the option (`--width`) and the value.
    pub fn check_canvas(&self) -> Result<(), ImportError> {
        for (option, side) in [("--width", self.width), ("--height", self.height)] {
            if !(1..=MAX_CANVAS).contains(&side) {
                return Err(ImportError::new(option, format!("{side} is outside 1..={MAX_CANVAS}")));
            }
        }
        Ok(())
    }

    /// The API viewport in force: the given one or the whole canvas.
    pub fn api_viewport(&self) -> ApiViewport {
        self.viewport
            .clone()
            .unwrap_or_else(|| ApiViewport::canvas(self.width, self.height))
    }

    /// The scene's viewport ([`scene_viewport`]).
    ///
    /// # Errors
    /// As [`scene_viewport`], from `--viewport`.
    pub fn scene_viewport(&self) -> Result<Viewport, ImportError> {
        scene_viewport(&self.api_viewport(), self.preset, self.height)
            .map_err(|e| ImportError::new("--viewport", format!("{}: {e}", self.api_viewport().text())))
    }

    /// A scene of clip-space triangles on this canvas, under this preset and viewport.
    ///
    /// # Errors
    /// A bad canvas or viewport ([`ImportTarget::check_canvas`],
    /// [`ImportTarget::scene_viewport`]).
    pub fn clip_scene(&self, triangles: Vec<[ClipVertex; 3]>) -> Result<Scene, ImportError> {
        self.check_canvas()?;
        let viewport = self.scene_viewport()?;
        let mut scene = Scene::new(self.width, self.height, Vec::new());
        scene.preset = self.preset;
        scene.clip_space_triangles = triangles;
        scene.viewport = Some(viewport);
        Ok(scene)
    }

    /// A scene of window-space triangles on this canvas, under this preset.
    ///
    /// # Errors
    /// A bad canvas, or a viewport given (it applies to clip space only).
    pub fn window_scene(&self, triangles: Vec<Triangle>) -> Result<Scene, ImportError> {
        self.check_canvas()?;
        if let Some(vp) = &self.viewport {
            return Err(ImportError::new(
                "--viewport",
                format!(
                    "{}: a viewport maps clip space; window-space positions are already pixels",
                    vp.text()
                ),
            ));
        }
        let mut scene = Scene::new(self.width, self.height, triangles);
        scene.preset = self.preset;
        Ok(scene)
    }

    /// `clip space, preset d3d11, viewport 0,0,8,8` (or `window space, preset d3d11`).
    fn describe(&self, clip: bool) -> String {
        if clip {
            format!(
                "clip space, preset {}, viewport {}",
                self.preset.name(),
                self.api_viewport().text()
            )
        } else {
            format!("window space, preset {}", self.preset.name())
        }
    }
}

/// An imported scene and the one-line account of where it came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Imported {
    /// The scene: `clip_space_triangles` and `viewport`, or `triangles`.
    pub scene: Scene,
    /// `mesh.csv: 2 triangles from rows 2-7, columns SV_Position.x .y .z .w (...); clip
    /// space, preset d3d11, viewport 0,0,8,8`.
    pub summary: String,
}

/// The most vertices one import reads: three per triangle of the scene limit.
pub const MAX_VERTICES: usize = 3 * MAX_TRIANGLES;

/// `1 triangle`, `2 triangles`: `n` and the noun, `many` unless `n` is 1.
fn counted(n: impl Into<u64>, one: &str, many: &str) -> String {
    let n = n.into();
    format!("{n} {}", if n == 1 { one } else { many })
}

/// Clip-space vertices in threes (the count is a multiple of 3), as `clip_space_triangles`.
fn clip_triangles(vertices: Vec<[BigRational; 4]>) -> Vec<[ClipVertex; 3]> {
    let mut out = Vec::with_capacity(vertices.len() / 3);
    let mut it = vertices.into_iter().map(|pos| ClipVertex { pos, attrs: Vec::new() });
    while let (Some(a), Some(b), Some(c)) = (it.next(), it.next(), it.next()) {
        out.push([a, b, c]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_of_f32_is_exact() {
        for f in [
            0.0f32,
            -0.0,
            1.0,
            0.1,
            -2.5e-40,
            f32::MIN_POSITIVE,
            f32::MAX,
            f32::MIN,
            1.0e-45,
        ] {
            assert_eq!(exact_f32(f), BigRational::from_float(f), "{f:e}");
        }
        assert_eq!(exact_f32(f32::INFINITY), None);
    }

    #[test]
    fn a_d3d_viewport_keeps_its_top() {
        let vp = scene_viewport(&ApiViewport::parse("1, 2.5, 8, 4").unwrap(), Preset::D3d11, 100).unwrap();
        assert_eq!((vp.y.to_string(), vp.y_axis), ("5/2".to_string(), NdcY::Up));
        assert!(scene_viewport(&ApiViewport::parse("0,8,8,-8").unwrap(), Preset::D3d11, 8).is_err());
        assert!(ApiViewport::parse("0,0,8").is_none());
    }
}
