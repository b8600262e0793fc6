//! `--values`: one varying's interpolated values, drawn by the GPU into an `Rgba32Float`
//! target and written as a float32 TIFF, so that `rasterproof compare SCENE.json OUT.tiff
//! --as values [--fit]` judges the GPU's interpolator (the contract of
//! adapters/osmesa/values.py, through Vulkan instead of OpenGL).
//!
//! ```sh
//! $A --values [--varying NAME] [--fault affine|provoking|centroid] [--samples 4] [--clip] (SCENE.json OUT.tiff | --serve)
//! ```
//!
//! **What it draws**: the scene's window-space `triangles`, in id order, in one draw call
//! of a triangle list, no culling, no depth, no blending (the last triangle drawn wins a
//! pixel, as the oracle's highest id does). Each vertex carries the chosen varying
//! (`--varying NAME`, default the scene's first) as a `vec4<f32>`: each exact value
//! rounded once to the nearest f32 (ties to even), missing channels 0. The shaders pass
//! it through unchanged:
//!
//! ```wgsl
//! struct Out { @builtin(position) position: vec4<f32>, @location(0) QUALIFIER value: vec4<f32> };
//! @vertex fn vs(@location(0) position: vec4<f32>, @location(1) value: vec4<f32>) -> Out { return Out(position, value); }
//! @fragment fn fs(@location(0) QUALIFIER value: vec4<f32>) -> @location(0) vec4<f32> { return value; }
//! ```
//!
//! with QUALIFIER `@interpolate(perspective|linear, center|centroid|sample)` for `smooth`
//! and `noperspective` at `centre`, `centroid` or `sample`, and `@interpolate(flat)` for
//! `flat` (SPIR-V `Flat`: the provoking vertex, Vulkan's default, the first).
//!
//! **Provoking vertex**: WebGPU has no provoking-vertex mode (its `flat` is the first
//! vertex). For a `flat` varying in a scene whose `provoking_vertex` is `last`, each
//! triangle's vertices are rotated to (v2, v0, v1): the last comes first, the winding is
//! kept (a cyclic rotation), and coverage, which depends on neither, is unchanged. Smooth
//! and noperspective varyings are drawn in the scene's order.
//!
//! **Faults** (`--fault`, deliberate bugs, so that `compare` and `hunt --as values` can be
//! seen naming them on a real GPU): `affine` draws a `smooth` varying `linear` (no
//! perspective correction); `provoking` takes the other provoking vertex of a `flat`
//! varying; `centroid` draws a `centroid` varying at the `center` (visible with
//! `--samples` above 1 only: with one sample, the centroid is the centre).
//!
//! **Positions, exactly**: each window coordinate is rounded once to the nearest f32 (the
//! adapter says on stderr how many were not f32-exact). The target is W' x H' (each a
//! power of two, at least the canvas's and the vertices' extent) with its top-left
//! corner at the canvas's origin: unlike the ids mode, the canvas is never moved, since
//! an interpolator's plane may be anchored at the framebuffer's origin (llvmpipe's is),
//! and moving the canvas would move that anchor. A vertex at a negative coordinate, or
//! one beyond the largest target (the device's `max_texture_dimension_2d`, and
//! 256 MiB per target), is refused, unless `--clip`, which draws into the canvas's own
//! target and lets the GPU clip (its clipper's float arithmetic then becomes part of what
//! is judged). A vertex at window point (x, y) with clip-space w is sent as the clip-space
//! position (w·ndc_x, w·ndc_y, 0, w) with ndc_x = x·(2/W') − 1, ndc_y = 1 − y·(2/H'): each
//! computed exactly (`BigRational`) and rounded once to f32. With x and y f32 and w a
//! power of two it is exact: ndc is exact as the ids mode shows (x·(2/W') a power-of-two
//! scaling; the subtraction exact when x is a multiple of W'·2^-25), and w·ndc a
//! power-of-two scaling. The GPU's divide then gives ndc back exactly (x·(1/w), 1/w a
//! power of two, or x/w: both exact), and the viewport transform (wgpu-hal's Vulkan
//! viewport `(0, H', W', −H')`, the `VK_KHR_maintenance1` flip) gives
//! `x_f = (W'/2)·ndc_x + W'/2 = x` and `y_f = (−H'/2)·ndc_y + H'/2 = y` exactly. So y is the scene's y, down, with
//! the origin at the top left, in the framebuffer as in the scene: nothing is flipped.
//! w reaches the GPU as the position's fourth component, exact when it is an f32 (the
//! scene's w rounded once otherwise). The adapter says how many position numbers were not
//! exact in f32.
//!
//! **Samples** (`--samples N`): N = 1 writes the W x H values image. N > 1 draws into
//! N-sample `Rgba32Float` targets (WebGPU does not guarantee multisampling for this
//! format: the adapter asks for `Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` and
//! offers the counts the adapter reports for it; lavapipe offers 1 and 4) and writes a
//! **stacked TIFF**: width W, height N·H, sample s's values in rows [s·H, (s+1)·H), read
//! by a compute pass (`textureLoad(t, p, s)`). Every image (one sample or stacked) is read
//! this way, bit for bit.
//!
//! **What lavapipe computes** (Mesa 22.3.6): `compare --fit` names `origin-plane fma
//! as-given rcp f32 y-down` with 0 differing values at canvas offsets 0 to 2^14:
//! llvmpipe's setup and interpolation (`lp_state_setup.c`, `lp_bld_interp.c`), which
//! lavapipe shares, in the scene's y-down coordinates, with Vulkan's first provoking
//! vertex. llvmpipe's reordering of a clockwise triangle for a first provoking vertex,
//! (v0, v2, v1), keeps vertex 0 as the anchor and gives the same bits as the order as
//! given, so a scene whose `provoking_vertex` is `first` fits `ccw` too; one whose
//! `provoking_vertex` is `last` fits `as-given` alone (the adapter never asks Vulkan for
//! the last provoking vertex, so no GL-style (v1, v0, v2) reordering happens).
//!
//! At 4 samples, a `smooth` varying at `sample` or `centroid` is not perspective-correct
//! on lavapipe: the plane of value/w is evaluated at the sample (or centroid) point but
//! the plane of 1/w at the pixel centre, so every channel is off by the factor
//! W(sample)/W(centre), W the plane of 1/w (where the three w differ; at a partly covered
//! pixel the centre may lie outside the triangle, where W is small or negative). `noperspective` at
//! `sample` and `centroid` (Direct3D's rule: the first covered sample when not all are)
//! and every varying at `centre` are right.
//!
//! **The TIFF**: uncompressed, 32-bit IEEE float samples (the `tiff` crate, as
//! `rasterproof render --values-out` writes it): one channel grey, two or three RGB (a
//! two-channel varying's blue is 0), four RGBA. Uncovered pixels are 0.
//!
//! **Refused** (exit 2 naming the file and field, or `ok: false` under `--serve`): what
//! the ids mode refuses (lines, polygons, a clip window, clip-space triangles, a custom
//! or mismatched sample pattern); a scene without `varyings`, a `--varying` it does not
//! declare, a varying of more than 4 channels (`varyings[k].channels`), a value or a
//! clip-space number beyond f32's range (`triangles[k].varyings.NAME[i]`,
//! `triangles[k].w[i]`); the scene parser already refuses w <= 0 and a wrong channel
//! count, naming the field.
//!
//! **Stay-alive** (`--values --serve`): one scene per request line as in the ids mode
//! (protocol version 1), each written as the TIFF at the request's `out`; a request whose
//! `as` is given and is not `values` is answered `ok: false`. `hunt --as values --cmd
//! '$A --values {scene} {out}'` runs it once per scene.

use std::collections::HashMap;
use std::ffi::OsString;
use std::ops::Range;
use std::path::Path;
use std::process::ExitCode;

use num_rational::BigRational;
use num_traits::One;
use rasterproof::interp::values::{Interpolation, ProvokingVertex, Sampling, Varying};
use rasterproof::num::exact::nearest_f32;
use rasterproof::oracle::renderer::adapter::{run_once, serve, FileBytes};
use rasterproof::scene::Scene;

use super::{Gpu, Options, NAME};

/// The values target's format.
pub const VALUES_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

/// The largest values target, in bytes (all samples): 256 MiB.
const MAX_TARGET_BYTES: u64 = 1 << 28;

/// One vertex: the clip-space position and the value, eight f32.
const VERTEX_BYTES: u64 = 32;

/// The read-back: one invocation per canvas pixel and sample, its value into the
/// stacked image's place. `TEXTURE` is `texture_2d` (one sample: `s` is the mip level 0)
/// or `texture_multisampled_2d`.
const READ_SHADER: &str = r"
struct Params { w: u32, h: u32, unused0: u32, unused1: u32 };

@group(0) @binding(0) var values: TEXTURE<f32>;
@group(0) @binding(1) var<storage, read_write> out: array<vec4<f32>>;
@group(0) @binding(2) var<uniform> params: Params;

@compute @workgroup_size(8, 8, 1)
fn main(@builtin(global_invocation_id) g: vec3<u32>) {
    if (g.x >= params.w || g.y >= params.h) {
        return;
    }
    out[(g.z * params.h + g.y) * params.w + g.x] = textureLoad(values, vec2<i32>(i32(g.x), i32(g.y)), i32(g.z));
}
";

/// The draw, with `QUALIFIER` the varying's `@interpolate(...)`.
const DRAW_SHADER: &str = r"
struct Out {
    @builtin(position) position: vec4<f32>,
    @location(0) QUALIFIER value: vec4<f32>,
};

@vertex
fn vs(@location(0) position: vec4<f32>, @location(1) value: vec4<f32>) -> Out {
    return Out(position, value);
}

@fragment
fn fs(@location(0) QUALIFIER value: vec4<f32>) -> @location(0) vec4<f32> {
    return value;
}
";

/// `--fault`: a deliberate bug.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// A `smooth` varying drawn `linear`.
    Affine,
    /// The other provoking vertex of a `flat` varying.
    Provoking,
    /// A `centroid` varying drawn at the `center`.
    Centroid,
}

impl Fault {
    /// The fault named `name`.
    pub fn parse(name: &str) -> Option<Fault> {
        match name {
            "affine" => Some(Fault::Affine),
            "provoking" => Some(Fault::Provoking),
            "centroid" => Some(Fault::Centroid),
            _ => None,
        }
    }
}

/// `--values` and its options.
#[derive(Clone, Debug, Default)]
pub struct ValuesOptions {
    /// `--varying NAME`: the varying drawn (default the scene's first).
    pub varying: Option<String>,
    /// `--fault`.
    pub fault: Option<Fault>,
}

/// The sample counts (of 1, 2, 4, 8, 16) the device offers for `Rgba32Float` targets.
pub fn sample_counts(gpu: &Gpu) -> Vec<u32> {
    let features = gpu.adapter.get_texture_format_features(VALUES_FORMAT);
    let specific = gpu
        .device
        .features()
        .contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);
    [1, 2, 4, 8, 16]
        .into_iter()
        .filter(|&n| n == 1 || specific && features.flags.sample_count_supported(n))
        .collect()
}

/// `--values`: one scene from a file to a TIFF, or the stay-alive loop.
pub fn values_main(args: Vec<OsString>, options: Options, values: ValuesOptions) -> ExitCode {
    let mut renderer: Option<Result<ValuesRenderer, String>> = None;
    let mut render = |scene: &Scene| -> Result<FileBytes, String> {
        let r =
            renderer.get_or_insert_with(|| Gpu::new().and_then(|g| ValuesRenderer::new(g, &options, values.clone())));
        match r {
            Ok(r) => r.render(scene).map(|bytes| FileBytes { bytes, kind: "TIFF" }),
            Err(e) => Err(e.clone()),
        }
    };
    let result = match args.as_slice() {
        [flag] if flag == "--serve" => serve(NAME, std::io::stdin().lock(), &mut std::io::stdout(), &mut render),
        [scene, out] => run_once(Path::new(scene), Path::new(out), &mut render),
        _ => Err(format!(
            "usage: {NAME} --values [--varying NAME] [--fault affine|provoking|centroid] [--samples N] [--clip] (SCENE.json OUT.tiff | --serve)"
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{NAME}: {message}");
            ExitCode::from(2)
        }
    }
}

/// The varying drawn: its channels' range in a vertex's values, and itself.
struct Chosen {
    range: Range<usize>,
    varying: Varying,
}

/// The scene's varying `wanted` (or its first), when a vec4 holds it.
fn choose(scene: &Scene, wanted: Option<&str>) -> Result<Chosen, String> {
    if scene.varyings.list.is_empty() {
        return Err("varyings: the scene declares none (--values draws a varying)".into());
    }
    let (k, (varying, range)) = scene
        .varyings
        .ranges()
        .enumerate()
        .find(|(_, (v, _))| wanted.is_none_or(|w| v.name == w))
        .ok_or_else(|| format!("varyings: no varying named {:?}", wanted.unwrap_or_default()))?;
    if varying.channels > 4 {
        return Err(format!(
            "varyings[{k}].channels: {}; a vec4 holds at most 4",
            varying.channels
        ));
    }
    Ok(Chosen {
        range,
        varying: varying.clone(),
    })
}

/// The WGSL qualifier that draws `varying` (with `fault`).
fn qualifier(varying: &Varying, fault: Option<Fault>) -> String {
    let interpolation = match (varying.interpolation, fault) {
        (Interpolation::Flat, _) => return "@interpolate(flat)".into(),
        (Interpolation::Smooth, Some(Fault::Affine)) | (Interpolation::NoPerspective, _) => "linear",
        (Interpolation::Smooth, _) => "perspective",
    };
    let sampling = match (varying.sampling, fault) {
        (Sampling::Centre, _) | (Sampling::Centroid, Some(Fault::Centroid)) => "center",
        (Sampling::Centroid, _) => "centroid",
        (Sampling::Sample, _) => "sample",
    };
    format!("@interpolate({interpolation}, {sampling})")
}

/// The scene placed in its target: the target's sides and the vertex data.
struct Placed {
    /// The target's width W' and height H', powers of two; its origin is the canvas's.
    width: u32,
    height: u32,
    /// Three vertices per triangle: the clip-space position and the value (vec4 each).
    vertices: Vec<[f32; 8]>,
    /// Window coordinates that were not f32-exact.
    rounded: usize,
    /// Clip-space numbers (w·ndc, w) that were not exact in f32.
    unmapped: usize,
}

/// The exact f32 of `q`, or the nearest; `what` names it when it is beyond f32's range.
fn to_f32(q: &BigRational, what: impl FnOnce() -> String, inexact: &mut usize) -> Result<f32, String> {
    let f = nearest_f32(q)
        .filter(|f| f.is_finite())
        .ok_or_else(|| format!("{}: {q} does not fit f32", what()))?;
    if BigRational::from_float(f).as_ref() != Some(q) {
        *inexact += 1;
    }
    Ok(f)
}

/// Rounds the vertices to f32, sizes the target (origin at the canvas's) and maps each
/// vertex to its clip-space position; the chosen varying's values rounded to f32.
fn place(scene: &Scene, chosen: &Chosen, rotate: bool, limits: (u32, u32), clip: bool) -> Result<Placed, String> {
    let (max_side, samples) = limits;
    let mut rounded = 0;
    let mut points = Vec::with_capacity(scene.triangles.len() * 3);
    for (k, t) in scene.triangles().iter().enumerate() {
        for (j, p) in t.v.iter().enumerate() {
            let x = to_f32(&p.x, || format!("triangles[{k}].v[{j}][0]"), &mut rounded)?;
            let y = to_f32(&p.y, || format!("triangles[{k}].v[{j}][1]"), &mut rounded)?;
            points.push([x, y]);
        }
    }
    let fits = |w: u32, h: u32| {
        w <= max_side && h <= max_side && u64::from(w) * u64::from(h) * 16 * u64::from(samples) <= MAX_TARGET_BYTES
    };
    // The extent of the canvas and the vertices, in whole pixels (f64 holds every f32 and
    // its floor and ceiling exactly).
    let (mut lo, mut hi) = ([0f64; 2], [f64::from(scene.width), f64::from(scene.height)]);
    for xy in &points {
        for c in 0..2 {
            lo[c] = lo[c].min(f64::from(xy[c]).floor());
            hi[c] = hi[c].max(f64::from(xy[c]).ceil());
        }
    }
    let side = |v: f64| -> u32 {
        // A whole number: exact as u64, saturated to u32.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let n = u32::try_from(v as u64).unwrap_or(u32::MAX);
        n.max(1).checked_next_power_of_two().unwrap_or(u32::MAX)
    };
    let (mut width, mut height) = (side(hi[0]), side(hi[1]));
    if lo[0] < 0.0 || lo[1] < 0.0 || !fits(width, height) {
        (width, height) = (side(f64::from(scene.width)), side(f64::from(scene.height)));
        if !fits(width, height) {
            return Err(format!(
                "the {}x{} canvas needs a {width}x{height} target at {samples} sample(s), beyond the largest this adapter draws values into ({max_side} px a side, {} MiB)",
                scene.width,
                scene.height,
                MAX_TARGET_BYTES >> 20
            ));
        }
        if !clip {
            return Err(format!(
                "a vertex lies outside the largest target this adapter can draw values into with its origin at the canvas's (the vertices span [{}, {}] x [{}, {}]; {max_side} px a side, {} MiB): the GPU would clip it in floating point; --clip lets it",
                lo[0],
                hi[0],
                lo[1],
                hi[1],
                MAX_TARGET_BYTES >> 20
            ));
        }
    }
    let two_over_w = BigRational::new(2.into(), width.into());
    let two_over_h = BigRational::new(2.into(), height.into());
    let one = BigRational::one();
    let name = &chosen.varying.name;
    let order = if rotate { [2, 0, 1] } else { [0, 1, 2] };
    let mut unmapped = 0;
    let mut vertices = Vec::with_capacity(points.len());
    for (k, t) in scene.triangles.iter().enumerate() {
        let values = t
            .values
            .as_ref()
            .ok_or_else(|| format!("triangles[{k}]: no varyings"))?;
        for j in order {
            let [x, y] = points[3 * k + j];
            let w = values.w.as_ref().map_or(&one, |w| &w[j]);
            let x = BigRational::from_float(x).expect("finite");
            let y = BigRational::from_float(y).expect("finite");
            let ndc_x = &x * &two_over_w - &one;
            let ndc_y = &one - &y * &two_over_h;
            let mut vertex = [0f32; 8];
            vertex[0] = to_f32(
                &(w * ndc_x),
                || format!("triangles[{k}].v[{j}]: w·ndc_x"),
                &mut unmapped,
            )?;
            vertex[1] = to_f32(
                &(w * ndc_y),
                || format!("triangles[{k}].v[{j}]: w·ndc_y"),
                &mut unmapped,
            )?;
            vertex[3] = to_f32(w, || format!("triangles[{k}].w[{j}]"), &mut unmapped)?;
            let mut ignored = 0;
            for (c, q) in values.values[j][chosen.range.clone()].iter().enumerate() {
                vertex[4 + c] = to_f32(q, || format!("triangles[{k}].varyings.{name}[{j}][{c}]"), &mut ignored)?;
            }
            vertices.push(vertex);
        }
    }
    Ok(Placed {
        width,
        height,
        vertices,
        rounded,
        unmapped,
    })
}

/// The values target, made again when a scene needs a larger one.
struct Target {
    width: u32,
    height: u32,
    view: wgpu::TextureView,
}

/// The device, the pipelines (one draw per qualifier) and the target reused across scenes.
struct ValuesRenderer {
    gpu: Gpu,
    samples: u32,
    clip: bool,
    options: ValuesOptions,
    draw_layout: wgpu::PipelineLayout,
    read_layout: wgpu::BindGroupLayout,
    read: wgpu::ComputePipeline,
    draws: HashMap<String, wgpu::RenderPipeline>,
    target: Option<Target>,
    max_side: u32,
}

impl ValuesRenderer {
    /// The read pipeline for `options` on `gpu`, or why it cannot draw them.
    fn new(gpu: Gpu, options: &Options, values: ValuesOptions) -> Result<ValuesRenderer, String> {
        let name = gpu.adapter.get_info().name;
        let counts = sample_counts(&gpu);
        if !counts.contains(&options.samples) {
            return Err(format!(
                "this adapter ({name}) offers {counts:?} samples for Rgba32Float targets, not {}",
                options.samples
            ));
        }
        let device = &gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let multisampled = options.samples > 1;
        let texture = if multisampled {
            "texture_multisampled_2d"
        } else {
            "texture_2d"
        };
        let read_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("read values"),
            source: wgpu::ShaderSource::Wgsl(READ_SHADER.replace("TEXTURE", texture).into()),
        });
        let read_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("read values"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: false },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
            ],
        });
        let read_pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("read values"),
            bind_group_layouts: &[Some(&read_layout)],
            immediate_size: 0,
        });
        let read = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("read values"),
            layout: Some(&read_pipeline_layout),
            module: &read_module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        let draw_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("draw values"),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("wgpu refused the read pipeline: {e}"));
        }
        let max_side = device.limits().max_texture_dimension_2d;
        Ok(ValuesRenderer {
            gpu,
            samples: options.samples,
            clip: options.clip,
            options: values,
            draw_layout,
            read_layout,
            read,
            draws: HashMap::new(),
            target: None,
            max_side,
        })
    }

    /// The draw pipeline of `qualifier`, made at its first use.
    fn draw(&mut self, qualifier: &str) -> Result<wgpu::RenderPipeline, String> {
        if let Some(p) = self.draws.get(qualifier) {
            return Ok(p.clone());
        }
        let device = &self.gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("draw values"),
            source: wgpu::ShaderSource::Wgsl(DRAW_SHADER.replace("QUALIFIER", qualifier).into()),
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("draw values"),
            layout: Some(&self.draw_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: VERTEX_BYTES,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4],
                })],
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: None,
            multisample: wgpu::MultisampleState {
                count: self.samples,
                mask: !0,
                alpha_to_coverage_enabled: false,
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: VALUES_FORMAT,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("wgpu refused the draw pipeline ({qualifier}): {e}"));
        }
        self.draws.insert(qualifier.to_string(), pipeline.clone());
        Ok(pipeline)
    }

    /// The target of at least `width` x `height`.
    fn target(&mut self, width: u32, height: u32) -> wgpu::TextureView {
        if self
            .target
            .as_ref()
            .is_none_or(|t| t.width < width || t.height < height)
        {
            // The union of the old target and the new one, unless that is too large.
            let (mut w, mut h) = self
                .target
                .as_ref()
                .map_or((width, height), |t| (t.width.max(width), t.height.max(height)));
            if u64::from(w) * u64::from(h) * 16 * u64::from(self.samples) > MAX_TARGET_BYTES {
                (w, h) = (width, height);
            }
            let (width, height) = (w, h);
            let view = self
                .gpu
                .device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some("values"),
                    size: wgpu::Extent3d {
                        width,
                        height,
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: self.samples,
                    dimension: wgpu::TextureDimension::D2,
                    format: VALUES_FORMAT,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor::default());
            self.target = Some(Target { width, height, view });
        }
        self.target.as_ref().expect("just made").view.clone()
    }

    /// One scene: the values TIFF (stacked per sample when `--samples` is above 1).
    fn render(&mut self, scene: &Scene) -> Result<Vec<u8>, String> {
        if let Some(e) = self.gpu.lost.lock().ok().and_then(|s| s.clone()) {
            return Err(e);
        }
        refuse_unsupported(scene, self.samples)?;
        let chosen = choose(scene, self.options.varying.as_deref())?;
        let fault = self.options.fault;
        let mut provoking = scene.varyings.provoking;
        if fault == Some(Fault::Provoking) {
            provoking = match provoking {
                ProvokingVertex::First => ProvokingVertex::Last,
                ProvokingVertex::Last => ProvokingVertex::First,
            };
        }
        let rotate = chosen.varying.interpolation == Interpolation::Flat && provoking == ProvokingVertex::Last;
        let placed = place(scene, &chosen, rotate, (self.max_side, self.samples), self.clip)?;
        if placed.rounded > 0 || placed.unmapped > 0 {
            eprintln!(
                "{NAME}: note: {} coordinate(s) are not f32-exact (rounded to the nearest f32); {} clip-space number(s) are not exact in f32 (rounded)",
                placed.rounded, placed.unmapped
            );
        }
        let qualifier = qualifier(&chosen.varying, fault);
        let device = self.gpu.device.clone();
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let read = self.draw_and_read(scene, &placed, &qualifier);
        let oom = pollster::block_on(memory.pop());
        let invalid = pollster::block_on(validation.pop());
        if let Some(e) = oom.or(invalid) {
            return Err(format!("wgpu error: {e}"));
        }
        let uncaptured = self.gpu.uncaptured.lock().ok().and_then(|mut s| s.take());
        if let Some(e) = self.gpu.lost.lock().ok().and_then(|s| s.clone()).or(uncaptured) {
            return Err(e);
        }
        tiff(
            &read?,
            chosen.varying.channels,
            scene.width,
            scene.height * self.samples,
        )
    }

    /// Draws the placed scene and reads back four f32 per canvas pixel and sample.
    fn draw_and_read(&mut self, scene: &Scene, placed: &Placed, qualifier: &str) -> Result<Vec<f32>, String> {
        let samples = self.samples;
        let (w, h) = (scene.width, scene.height);
        let bytes = u64::from(w) * u64::from(h) * u64::from(samples) * 16;
        if bytes > self.gpu.device.limits().max_storage_buffer_binding_size {
            return Err(format!(
                "the read-back of {w}x{h} pixels at {samples} samples ({bytes} bytes) exceeds the device's storage buffer limit"
            ));
        }
        let draw = self.draw(qualifier)?;
        let view = self.target(placed.width, placed.height);
        let device = &self.gpu.device;
        let queue = &self.gpu.queue;
        let vertex_bytes: Vec<u8> = placed
            .vertices
            .iter()
            .flat_map(|v| v.iter().flat_map(|f| f.to_le_bytes()))
            .collect();
        let vertices = (!vertex_bytes.is_empty()).then(|| {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("vertices"),
                size: vertex_bytes.len() as u64,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            queue.write_buffer(&buffer, 0, &vertex_bytes);
            buffer
        });
        let params = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("params"),
            size: 16,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let param_words: Vec<u8> = [w, h, 0, 0].iter().flat_map(|v| v.to_le_bytes()).collect();
        queue.write_buffer(&params, 0, &param_words);
        let out = super::ReadOut::new(device, bytes);
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("read values"),
            layout: &self.read_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: out.storage.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: params.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(NAME) });
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("draw values"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            // The viewport is the placed W' x H' at the target's top-left corner (the
            // target may be larger when an earlier scene needed more).
            #[allow(clippy::cast_precision_loss)] // powers of two up to the device's limit: exact
            let (pw, ph) = (placed.width as f32, placed.height as f32);
            pass.set_viewport(0.0, 0.0, pw, ph, 0.0, 1.0);
            pass.set_scissor_rect(0, 0, w, h);
            if let Some(buffer) = &vertices {
                pass.set_pipeline(&draw);
                pass.set_vertex_buffer(0, buffer.slice(..));
                let count = u32::try_from(placed.vertices.len()).map_err(|_| "too many vertices")?;
                pass.draw(0..count, 0..1);
            }
        }
        Ok(out
            .read(device, queue, encoder, (&self.read, &bind_group), (w, h, samples))?
            .into_iter()
            .map(f32::from_le_bytes)
            .collect())
    }
}

/// Refuses what the values mode does not draw: primitives other than window-space
/// triangles, and a sample pattern other than the standard one of `samples`.
fn refuse_unsupported(scene: &Scene, samples: u32) -> Result<(), String> {
    super::refuse_other_primitives(scene)?;
    if let Some(pattern) = &scene.samples {
        if !pattern.is_standard() {
            return Err(format!(
                "samples: the scene states a custom sample pattern ({pattern}); a GPU draws its standard positions only"
            ));
        }
        if u32::try_from(pattern.len()).ok() != Some(samples) {
            return Err(format!(
                "samples: the scene states {} samples per pixel; this adapter was started with --samples {samples}",
                pattern.len()
            ));
        }
    }
    Ok(())
}

/// The read-back (four f32 per pixel, `rows` rows of `width`) as a float32 TIFF of
/// `channels` channels: grey, RGB (two channels: blue is 0, as drawn) or RGBA.
fn tiff(rgba: &[f32], channels: usize, width: u32, rows: u32) -> Result<Vec<u8>, String> {
    use tiff::encoder::{colortype, TiffEncoder};
    let stride = match channels {
        1 => 1,
        2 | 3 => 3,
        _ => 4,
    };
    let samples: Vec<f32> = rgba.chunks_exact(4).flat_map(|p| p[..stride].iter().copied()).collect();
    let mut out = std::io::Cursor::new(Vec::new());
    let mut encoder = TiffEncoder::new(&mut out).map_err(|e| format!("cannot write the TIFF: {e}"))?;
    match stride {
        1 => encoder.write_image::<colortype::Gray32Float>(width, rows, &samples),
        3 => encoder.write_image::<colortype::RGB32Float>(width, rows, &samples),
        _ => encoder.write_image::<colortype::RGBA32Float>(width, rows, &samples),
    }
    .map_err(|e| format!("cannot write the TIFF: {e}"))?;
    Ok(out.into_inner())
}
