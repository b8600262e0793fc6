//! euc adapter: draws the interpolated values of one varying of a rasterproof scene with
//! [euc](https://crates.io/crates/euc) 0.5.3, a pure-Rust software renderer, into a
//! float32 TIFF, so that `rasterproof compare SCENE.json OUT.tiff --as values` can judge
//! euc's interpolator and `--fit` name its arithmetic; `--ids-out` writes the coverage of
//! the same draw as an ids PNG, for `compare --as ids`.
//!
//! ```sh
//! cargo build --release --manifest-path adapters/euc/Cargo.toml
//! A=adapters/euc/target/release/rasterproof-euc-adapter
//! $A SCENE.json OUT.tiff [--varying NAME] [--ids-out IDS.png]
//! target/release/rasterproof compare SCENE.json IDS.png --as ids --model exact --fit
//! target/release/rasterproof compare SCENE.json OUT.tiff --as values --model exact --fit
//! ```
//!
//! **What it draws**: the scene's window-space `triangles`, in id order, one
//! `Pipeline::draw` of `Triangles<_, BackfaceCullingDisabled>` per triangle (both windings;
//! no depth test, `DepthStrategy::None`), so that a later triangle overwrites an earlier
//! one, as the oracle's highest id wins. Each vertex carries the chosen varying's channels
//! (`--varying NAME`, default the first) as an `(f32, f32, f32, f32)` vertex output: the
//! exact values rounded once to the nearest f32, missing channels 0. The fragment shader
//! returns that output unchanged. Lines, polygons, clip-space triangles, a clip window and
//! a sample pattern are refused, and so is what euc cannot interpolate: a `flat` varying
//! (euc interpolates every output; it has no provoking vertex) and more than 4 channels
//! (exit 2, one line on stderr naming the field). `sampling` `centroid` and `sample` are
//! drawn as `centre`: with one sample per pixel they are the pixel centre. The scene's
//! preset and overrides are ignored: euc draws as it draws.
//!
//! **How positions map.** euc's `Triangles` rasterizer (src/rasterizer/triangles.rs of
//! 0.5.3) takes each vertex's clip-space position `[x, y, z, w]` from the vertex shader,
//! and maps a target of size `(W_t, H_t)`, y down, pixel `(i, j)`'s centre at
//! `(i + 1/2, j + 1/2)`, to NDC by `ndc_x = (2/W_t) p_x - 1`, `ndc_y = 1 - (2/H_t) p_y`
//! (y up). The adapter's target is a square of side `S`, the smallest power of two at
//! least the canvas's width and height (at most 2^14, the largest canvas), whose top-left
//! `W x H` pixels are the canvas (euc's loop stays in each triangle's bounding box, clamped
//! to the target; pixels outside the canvas are dropped): so `2/S` is a power of two and
//! the window is where the scene says. A vertex at window point `(x, y)` (each the scene's
//! exact number rounded once to the nearest f32) with clip-space `w` (the scene's, rounded
//! to f32; 1 when the triangle gives none) is sent, computed in f32 as a vertex shader
//! would, as
//!
//! ```text
//! ndc_x = x · (2/S) − 1,   ndc_y = 1 − y · (2/S),   position = (ndc_x · w, ndc_y · w, 0, w)
//! ```
//!
//! for a `smooth` varying, and with `w = 1` for a `noperspective` one (euc's barycentrics
//! are perspective-correct in the position's w; with w = 1 they are screen-linear, which is
//! how a euc program gets `noperspective`). `x · (2/S)` is exact; the subtraction is exact
//! when `x · (2/S)` is a multiple of 2^-24 in [0, 2] (f32's step in [-1, 1] is at most
//! 2^-24): for x in [0, S] on the grid of `S · 2^-25` (the 1/256 grid up to S = 2^17); the
//! product by a power-of-two w is exact. The adapter checks each NDC number exactly and
//! says on stderr how many were not exact. A smaller target than the canvas's power of two
//! is not possible, and a larger one costs euc precision (below).
//!
//! **What euc computes** (what `rasterproof::interp::float`'s `homogeneous` models
//! reproduce): each vertex's NDC `(x/w, y/w)`; a triangle with `(b − a) × (c − a)` negative
//! in NDC (clockwise with y up) is drawn as `(c, b, a)`. Then 2D homogeneous rasterization
//! (Olano and Greer 1997): with `c = (x_c, y_c, w_c)`, `ca = a − c`, `cb = b − c`, `n = ca ×
//! cb` (f32, unfused, vek's cross product) and `r = 1 / (n · c)` (vek's dot: `(n_x c_x +
//! n_y c_y) + n_z c_z`), the matrix with rows `cb × c`, `c × ca`, `n`, each entry times `r`,
//! times the NDC matrix `[[2/S, 0, −1], [0, −2/S, 1], [0, 0, 1]]` (vek's column-major
//! product: `(m_0 t_0j + m_1 t_1j) + m_2 t_2j`, unfused) gives `F`; at pixel `(i, j)`,
//! `h = F (i + 1/2, j + 1/2, 1)` (again `(F_0 p_x + F_1 p_y) + F_2`, unfused), the weights
//! `w_a = h_0 / h_2`, `w_b = h_1 / h_2`, `w_c = (1 − w_a) − w_b`, the pixel drawn when each
//! weight lies in [0, 1] (both sides of every edge inclusive: euc has no tie rule), and
//! each channel `fma(v_a, w_a, fma(v_b, w_b, v_c · w_c))` (`Interpolate::lerp3` for `f32`,
//! `f32::mul_add`: fused). These are the perspective-correct barycentrics of the pixel
//! centre, formed once per pixel, not incrementally. The matrix is ill-conditioned when a
//! triangle is small against the target: every NDC number and every entry carries steps of
//! the whole target, so on canvases of 1024 px and more euc's `smooth` values (and from
//! 4096 px its `noperspective` ones) can be far from the exact ones and its coverage can
//! miss or add pixels near edges; the models reproduce those values too
//! (adapters/README.md has the measurements).
//!
//! **Outputs**: the TIFF is the canvas, uncompressed, 32-bit IEEE float samples (the `tiff`
//! crate): one channel grey, two or three RGB (a two-channel varying's blue is 0), four
//! RGBA; a pixel no triangle drew holds 0. `--ids-out IDS.png`: `render --ids-out`'s layout,
//! id + 1 as little-endian 24 bits in R, G, B with alpha 255, alpha 254 where two or more
//! triangles drew the pixel, `0, 0, 0, 0` where none did.
//!
//! Exit status: 0 when the outputs were written; 2 with one line on stderr otherwise.

#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use euc::{DepthStrategy, Pipeline, Target};
use num_rational::BigRational;
use num_traits::One;
use rasterproof::interp::values::Interpolation;
use rasterproof::num::exact::nearest_f32;
use rasterproof::scene::{read_scene_file, ParseOptions, Scene};

/// The name every message starts with.
const NAME: &str = "rasterproof-euc-adapter";

/// The largest side of euc's square target: the largest canvas a scene has.
const MAX_SIDE: usize = 1 << 14;

/// The largest id + 1 the 24 bits of an ids PNG hold.
const MAX_ENCODED: usize = (1 << 24) - 1;

/// A varying's value at a vertex: four f32 channels (euc interpolates a 4-tuple of f32
/// channel by channel).
type Value4 = (f32, f32, f32, f32);

/// One vertex as the vertex shader gets it.
#[derive(Clone, Copy)]
struct Vertex {
    /// Window x and y, f32.
    x: f32,
    y: f32,
    /// The position's w.
    w: f32,
    /// The varying's channels.
    value: Value4,
}

/// The pipeline: one triangle's draw, its id as a uniform.
struct Draw {
    id: usize,
    /// The target's side.
    side: usize,
}

impl Pipeline for Draw {
    type Vertex = Vertex;
    type VsOut = Value4;
    type Pixel = (Value4, usize);

    fn vert(&self, v: &Vertex) -> ([f32; 4], Value4) {
        let (ndc_x, ndc_y) = ndc(v.x, v.y, self.side);
        ([ndc_x * v.w, ndc_y * v.w, 0.0, v.w], v.value)
    }

    fn frag(&self, value: &Value4) -> (Value4, usize) {
        (*value, self.id)
    }

    fn get_depth_strategy(&self) -> DepthStrategy {
        DepthStrategy::None
    }
}

/// Window `(x, y)` in NDC, as the vertex shader computes it in f32 (module docs).
fn ndc(x: f32, y: f32, side: usize) -> (f32, f32) {
    #[allow(clippy::cast_precision_loss)] // at most 2^14: an f32
    let scale = 2.0 / side as f32;
    (x * scale - 1.0, 1.0 - y * scale)
}

/// euc's target: `side x side` as euc sees it, the canvas's pixels kept.
struct Canvas {
    side: usize,
    width: usize,
    height: usize,
    values: Vec<Value4>,
    /// Per pixel: the last id drawn + 1 (0: none) and how many draws wrote it.
    ids: Vec<(usize, u32)>,
}

impl Target for Canvas {
    type Item = (Value4, usize);

    fn size(&self) -> [usize; 2] {
        [self.side, self.side]
    }

    unsafe fn set(&mut self, [x, y]: [usize; 2], (value, id): (Value4, usize)) {
        if x < self.width && y < self.height {
            let at = y * self.width + x;
            self.values[at] = value;
            let (last, count) = &mut self.ids[at];
            *last = id + 1;
            *count += 1;
        }
    }

    unsafe fn get(&self, [x, y]: [usize; 2]) -> (Value4, usize) {
        let at = y * self.width + x;
        (self.values[at], self.ids[at].0.wrapping_sub(1))
    }

    fn clear(&mut self, (value, _): (Value4, usize)) {
        self.values.fill(value);
        self.ids.fill((0, 0));
    }
}

/// The command line.
struct Args {
    scene: PathBuf,
    out: PathBuf,
    varying: Option<String>,
    ids_out: Option<PathBuf>,
}

fn args() -> Result<Args, String> {
    let usage = || format!("usage: {NAME} SCENE.json OUT.tiff [--varying NAME] [--ids-out IDS.png]");
    let mut it = std::env::args_os().skip(1);
    let (mut positional, mut varying, mut ids_out) = (Vec::new(), None, None);
    while let Some(a) = it.next() {
        match a.to_str() {
            Some("--varying") => {
                varying = Some(it.next().and_then(|v| v.into_string().ok()).ok_or_else(usage)?);
            }
            Some("--ids-out") => ids_out = Some(PathBuf::from(it.next().ok_or_else(usage)?)),
            Some(s) if s.starts_with("--") => return Err(usage()),
            _ => positional.push(PathBuf::from(a)),
        }
    }
    let [scene, out] = <[PathBuf; 2]>::try_from(positional).map_err(|_| usage())?;
    Ok(Args {
        scene,
        out,
        varying,
        ids_out,
    })
}

/// The nearest f32 of `q`; an error naming `what` beyond the f32 range.
fn f32_of(q: &BigRational, what: &str) -> Result<f32, String> {
    nearest_f32(q).ok_or_else(|| format!("{what}: beyond the f32 range"))
}

/// The scene drawn by euc: the canvas with its values and ids, and how many NDC numbers
/// were not exact.
fn draw(scene: &Scene, path: &Path, wanted: Option<&str>) -> Result<(Canvas, usize, usize), String> {
    let at = |field: &str| format!("{}: {field}", path.display());
    for (field, present) in [
        ("lines", !scene.lines.is_empty()),
        ("polygons", !scene.polygons.is_empty()),
        ("clip_space_triangles", !scene.clip_space_triangles.is_empty()),
        ("clip", scene.clip.is_some()),
        ("samples", scene.samples.is_some()),
    ] {
        if present {
            return Err(format!(
                "{}: euc draws window-space triangles at one sample per pixel only",
                at(field)
            ));
        }
    }
    if scene.triangles.len() > MAX_ENCODED {
        return Err(format!("{}: more than 2^24 - 1 triangles", at("triangles")));
    }
    let list = &scene.varyings.list;
    if list.is_empty() {
        return Err(format!("{}: the scene declares none", at("varyings")));
    }
    let k = match wanted {
        None => 0,
        Some(name) => list
            .iter()
            .position(|v| v.name == name)
            .ok_or_else(|| format!("{}: no varying named {name:?}", at("varyings")))?,
    };
    let varying = &list[k];
    let offset: usize = list[..k].iter().map(|v| v.channels).sum();
    if varying.channels > 4 {
        return Err(format!(
            "{}: {}; euc's vertex output here holds at most 4",
            at(&format!("varyings[{k}].channels")),
            varying.channels
        ));
    }
    let perspective = match varying.interpolation {
        Interpolation::Smooth => true,
        Interpolation::NoPerspective => false,
        Interpolation::Flat => {
            return Err(format!(
                "{}: flat: euc interpolates every vertex output; it has no flat shading",
                at(&format!("varyings[{k}].interpolation"))
            ))
        }
    };
    let (width, height) = (scene.width as usize, scene.height as usize);
    let side = width.max(height).next_power_of_two();
    if side > MAX_SIDE {
        return Err(format!("{}: a canvas side above 2^14", at("width")));
    }
    let mut canvas = Canvas {
        side,
        width,
        height,
        values: vec![(0.0, 0.0, 0.0, 0.0); width * height],
        ids: vec![(0, 0); width * height],
    };
    let (mut numbers, mut inexact) = (0, 0);
    for (id, t) in scene.triangles.iter().enumerate() {
        let what = format!("triangles[{id}]");
        let tri = t.triangle.to_triangle();
        let values = t.values.as_deref();
        let mut vertices = [Vertex {
            x: 0.0,
            y: 0.0,
            w: 1.0,
            value: (0.0, 0.0, 0.0, 0.0),
        }; 3];
        for (i, v) in vertices.iter_mut().enumerate() {
            v.x = f32_of(&tri.v[i].x, &at(&format!("{what}.v[{i}]")))?;
            v.y = f32_of(&tri.v[i].y, &at(&format!("{what}.v[{i}]")))?;
            if let Some(values) = values {
                if perspective {
                    if let Some(w) = &values.w {
                        v.w = f32_of(&w[i], &at(&format!("{what}.w[{i}]")))?;
                    }
                }
                let mut c = [0f32; 4];
                for (ch, slot) in c.iter_mut().enumerate().take(varying.channels) {
                    *slot = f32_of(
                        &values.values[i][offset + ch],
                        &at(&format!("{what}.varyings.{}[{i}]", varying.name)),
                    )?;
                }
                v.value = (c[0], c[1], c[2], c[3]);
            }
            let (nx, ny) = ndc(v.x, v.y, side);
            for (n, exact) in [
                (nx, exact_ndc(&tri.v[i].x, true, side)),
                (ny, exact_ndc(&tri.v[i].y, false, side)),
            ] {
                numbers += 1;
                if rasterproof::import::exact_f32(n) != Some(exact) {
                    inexact += 1;
                }
            }
        }
        Draw { id, side }.draw::<Triangles<(f32,), BackfaceCullingDisabled>, _>(&vertices, &mut canvas, None);
    }
    Ok((canvas, numbers, inexact))
}

/// The exact NDC of a window coordinate (`x` or `y`).
fn exact_ndc(c: &BigRational, x: bool, side: usize) -> BigRational {
    let scaled = c * BigRational::new(2.into(), side.into());
    if x {
        scaled - BigRational::one()
    } else {
        BigRational::one() - scaled
    }
}

/// The values as a float32 TIFF of the canvas with `channels` channels.
fn tiff(canvas: &Canvas, channels: usize) -> Vec<u8> {
    use tiff::encoder::{colortype, TiffEncoder};
    let stride = if channels == 2 { 3 } else { channels };
    let mut samples = Vec::with_capacity(canvas.values.len() * stride);
    for v in &canvas.values {
        samples.extend_from_slice(&[v.0, v.1, v.2, v.3][..stride]);
    }
    let mut out = std::io::Cursor::new(Vec::new());
    let mut encoder = TiffEncoder::new(&mut out).expect("writing to memory");
    let (w, h) = (
        u32::try_from(canvas.width).expect("a canvas side fits u32"),
        u32::try_from(canvas.height).expect("a canvas side fits u32"),
    );
    let written = match stride {
        1 => encoder.write_image::<colortype::Gray32Float>(w, h, &samples),
        3 => encoder.write_image::<colortype::RGB32Float>(w, h, &samples),
        _ => encoder.write_image::<colortype::RGBA32Float>(w, h, &samples),
    };
    written.expect("a TIFF of the image's own size, in memory");
    out.into_inner()
}

/// The ids PNG of the draw (module docs).
fn ids_image(canvas: &Canvas) -> image::RgbaImage {
    let (w, h) = (
        u32::try_from(canvas.width).expect("a canvas side fits u32"),
        u32::try_from(canvas.height).expect("a canvas side fits u32"),
    );
    image::RgbaImage::from_fn(w, h, |x, y| {
        let (id1, count) = canvas.ids[y as usize * canvas.width + x as usize];
        let b = u32::try_from(id1).expect("ids fit 24 bits").to_le_bytes();
        match count {
            0 => image::Rgba([0, 0, 0, 0]),
            1 => image::Rgba([b[0], b[1], b[2], 255]),
            _ => image::Rgba([b[0], b[1], b[2], 254]),
        }
    })
}

fn run() -> Result<(), String> {
    let args = args()?;
    let scene = read_scene_file(&args.scene, &ParseOptions::default()).map_err(|e| e.to_string())?;
    let (canvas, numbers, inexact) = draw(&scene, &args.scene, args.varying.as_deref())?;
    let k = args.varying.as_deref().map_or(0, |name| {
        scene.varyings.list.iter().position(|v| v.name == name).unwrap_or(0)
    });
    std::fs::write(&args.out, tiff(&canvas, scene.varyings.list[k].channels))
        .map_err(|e| format!("{}: {e}", args.out.display()))?;
    if let Some(ids) = &args.ids_out {
        ids_image(&canvas)
            .save_with_format(ids, image::ImageFormat::Png)
            .map_err(|e| format!("{}: {e}", ids.display()))?;
    }
    eprintln!(
        "{NAME}: euc 0.5.3, {} triangles; {inexact} of {numbers} NDC coordinates not exact in f32",
        scene.triangles.len()
    );
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{NAME}: {message}");
            ExitCode::from(2)
        }
    }
}
