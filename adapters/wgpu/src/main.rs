//! wgpu adapter: renders a rasterproof scene's triangles on a real GPU through wgpu
//! (Vulkan, Metal or D3D12; Mesa's lavapipe, a Vulkan driver on the CPU, in CI) and writes
//! the ids PNG (`render --ids-out`'s layout), so that `rasterproof compare SCENE.json
//! OUT.png --as ids` and `hunt --serve` can judge the GPU's rasterizer.
//!
//! ```sh
//! cargo build --release --manifest-path adapters/wgpu/Cargo.toml
//! A=adapters/wgpu/target/release/rasterproof-wgpu-adapter
//! $A --info
//! $A SCENE.json OUT.png && target/release/rasterproof compare SCENE.json OUT.png --as ids --preset vulkan
//! target/release/rasterproof hunt --serve "$A --serve" --preset vulkan --float32-exact --family mesh,delaunay,slivers,fine
//! ```
//!
//! Arguments: `[--samples N] [--conservative] [--clip] (SCENE.json OUT.png | --serve)`, or `--info`
//! alone; or `--values [--varying NAME] [--fault affine|provoking|centroid] [--samples N]
//! [--clip] (SCENE.json OUT.tiff | --serve)`: one varying's interpolated values as a
//! float32 TIFF instead of the ids PNG, for `rasterproof compare SCENE.json OUT.tiff --as
//! values [--fit]` (the `values` module says what it draws, how positions, y and w reach
//! the GPU exactly, and what lavapipe's interpolator was found to be). With `--serve` it stays alive and takes one scene per line on stdin (the
//! stay-alive protocol of `rasterproof::oracle::renderer::stay_alive`, through
//! `rasterproof::oracle::renderer::adapter`); the device, its pipelines and its render targets are
//! made once per process (the targets again when a scene needs a larger one).
//!
//! **What it draws**: the scene's triangles (ids 0..), in id order, in one draw call of a
//! triangle list (the GPU keeps the API's primitive order for the writes to one pixel, so
//! the last writer is the highest id): no culling (both windings), no depth or stencil,
//! no blending of the ids. The fragment shader writes two colour attachments: the flat
//! id + 1 into an `R32Uint` target (cleared to 0, uncovered), and 1.0 into an `R16Float`
//! count target with additive blending (`One`, `One`; cleared to 0), which counts the
//! fragments of each pixel (sample); a count of 2 or more is the ids PNG's "several
//! owners" mark, alpha 254. A compute pass reads both (`textureLoad`, per sample) into a
//! storage buffer, which is read back: id + 1 as little-endian 24 bits (R low, G, B high),
//! alpha 255 (one owner) or 254, `0, 0, 0, 0` where nothing covers. The scene's preset,
//! overrides and vertex colours are ignored: the GPU draws as it draws.
//!
//! **Refused** (exit 2, or `ok: false` under `--serve`): lines, polygons, a clip window,
//! clip-space triangles, more than 2^24 - 1 triangles (the ids PNG's 24 bits), a
//! coordinate outside the f32 range, a vertex the target cannot hold (below), a sample
//! count the device does not offer for `R32Uint` and `R16Float` (the message names the
//! ones it does), `--conservative` on an adapter without
//! `Features::CONSERVATIVE_RASTERIZATION` or with `--samples` above 1, and any wgpu error
//! (validation, out of memory, device lost: the message is wgpu's). No adapter: a refusal
//! naming the backends tried (`mesa-vulkan-drivers` provides lavapipe on Debian).
//!
//! **Coordinates, exactly**: a window coordinate must reach the GPU's fixed-point snap
//! unchanged. Each exact coordinate is first rounded once to the nearest f32 (as
//! tiny-skia's adapter does; `hunt --float32-exact` scenes are f32 already: the adapter
//! says on stderr how many were not, and of those that were, how many could not be mapped
//! exactly). The render target is a square of side P, a power of two, placed so that it
//! holds the canvas and every vertex: with `ox = max(0, -floor(min x))`, `oy` likewise,
//! the canvas pixel (x, y) is the target's pixel (x + ox, y + oy), and P is the smallest
//! power of two at least `max(ox + max(W, ceil(max x)), oy + max(H, ceil(max y)))`. An
//! integer translation changes nothing a rasterizer decides (the snap grid, the sample
//! positions and the tie rule all repeat with period 1 px), and no vertex lies outside
//! the viewport, so the GPU never clips (clipping would compute new vertices in floats:
//! another renderer's error than the rasterizer's, so this adapter leaves it out). A scene
//! whose vertices need P above `min(device limit, 8192)` is refused ("beyond the
//! target"), e.g. `hunt`'s `huge` triangles (2^21 px away); hunt such a renderer with
//! `--family mesh,delaunay,slivers,fine`. `--clip` draws such a scene instead, into the
//! canvas's own target (offset 0) with the far vertices outside the view volume: the
//! GPU's clipper becomes part of what is judged (on lavapipe, a pixel 0.0003 px outside
//! an edge of a triangle reaching 10^6 px away, `near-edge`). The viewport is the whole target; a scissor
//! rectangle keeps rasterization to the canvas, whose W x H pixels are read back.
//!
//! The vertex shader is fed `ndc_x = x'·(2/P) − 1` and `ndc_y = 1 − y'·(2/P)` (`x' = x +
//! ox`, `y' = y + oy`, w = 1), computed in f32 on the CPU: `x'·(2/P)` is exact (a power of
//! two); the subtraction is exact when `x'·(2/P)` lies in [1/2, 2] (Sterbenz), and below
//! 1/2 when it is a multiple of 2^-24 (the result lies in [-1, -1/2), where f32's step is
//! 2^-24), that is when x' is a multiple of P·2^-25 (for P = 32, the 2^-20 grid; for P =
//! 8192, 2^-12). The adapter checks each value exactly (`BigRational`) and counts the
//! ones that are not. wgpu's NDC is y up and its framebuffer y down with the origin at
//! the top left (rasterproof's window coordinates are y down too): wgpu-hal's Vulkan
//! backend sets the viewport `(x 0, y P, width P, height −P)` (the `VK_KHR_maintenance1`
//! flip), so the viewport transform gives `x_f = (P/2)·ndc_x + P/2 = x'` and `y_f =
//! (−P/2)·ndc_y + P/2 = y'`: each product is exact (a power of two) and each sum is too,
//! since its exact value x' (y') is an f32 (fused or not). So the GPU snaps x' and y' as
//! written, and target row y' is canvas row y (top row first): nothing is flipped.
//!
//! **Samples** (`--samples N`, default 1): N = 1 writes the W x H ids PNG. N > 1 draws
//! into N-sample targets at the API's standard sample positions (Vulkan's and D3D's: for
//! 4x, in 1/16 px from the pixel centre, y down, samples 0..3 at (−2, −6), (6, −2), (−6,
//! 2), (2, 6); sample 0 at (0.375, 0.125) within the pixel) and writes a **stacked ids
//! PNG**: width W, height N·H, sample s's ids image in rows [s·H, (s+1)·H). WebGPU
//! guarantees 4x for neither `R32Uint` nor blending; the adapter asks for
//! `Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` and offers the counts the adapter
//! reports for both formats (`--info` lists them). A scene that states `samples` must
//! state the standard pattern of the count the adapter was started with (`rasterproof
//! hunt --samples 4` writes it into every scene); a custom pattern is refused.
//!
//! **Conservative** (`--conservative`, one sample only): draws with `PrimitiveState {
//! conservative: true, .. }` when the adapter has `Features::CONSERVATIVE_RASTERIZATION`
//! (Vulkan's `VK_EXT_conservative_rasterization`, overestimation); refused otherwise.
//!
//! **Lavapipe** (Mesa 22.3.6, Debian 12; what the adapter relies on was checked there):
//! adapter "llvmpipe (LLVM 15.0.6, 256 bits)", backend Vulkan, driver "llvmpipe";
//! `subPixelPrecisionBits` 8 (vulkaninfo); `R32Uint` and `R16Float` offer 1 and 4 samples
//! (adapter-specific); standard sample locations; no
//! `VK_EXT_conservative_rasterization`, so no `CONSERVATIVE_RASTERIZATION`.
//!
//! **Backend**: wgpu's environment variables choose it: `WGPU_BACKEND` (e.g. `vulkan`,
//! `metal`, `dx12`), `WGPU_ADAPTER_NAME` (a substring of the adapter's name, e.g.
//! `llvmpipe`), `WGPU_POWER_PREF` (`low`, `high`). Built without GLES: GL has no standard
//! sample positions.
//!
//! **Values on lavapipe**: `compare --fit` names `origin-plane fma as-given rcp f32
//! y-down` bit for bit (llvmpipe's setup and interpolation, with Vulkan's first provoking
//! vertex); `Rgba32Float` offers 1 and 4 samples (adapter-specific).
//!
//! Exit status: 0 when the PNG (or TIFF) was written (or `--info` printed), 2 with one line on
//! stderr otherwise; under `--serve` each refusal is an `"ok": false` answer instead.

#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

mod values;

use std::ffi::OsString;
use std::process::ExitCode;
use std::sync::{Arc, Mutex};

use num_rational::BigRational;
use num_traits::{One, Zero};
use rasterproof::num::exact::nearest_f32;
use rasterproof::oracle::renderer::adapter::adapter_main;
use rasterproof::scene::Scene;

/// The name every message starts with.
const NAME: &str = "rasterproof-wgpu-adapter";

/// The largest id + 1 the 24 bits of an ids PNG hold.
const MAX_ENCODED: u32 = (1 << 24) - 1;

/// The largest target side the adapter draws into (below the device's limit): an 8192²
/// `R32Uint` target is 256 MiB per sample.
const MAX_TARGET: u32 = 8192;

/// The backends this build can use.
const BACKENDS: wgpu::Backends = wgpu::Backends::VULKAN
    .union(wgpu::Backends::METAL)
    .union(wgpu::Backends::DX12);

/// The colour targets' formats.
const IDS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
const COUNT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R16Float;

/// The draw: vertices in NDC (computed exactly on the CPU), the flat id + 1.
const DRAW_SHADER: &str = r"
struct Out {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) id: u32,
};

@vertex
fn vs(@location(0) ndc: vec2<f32>, @location(1) id: u32) -> Out {
    var out: Out;
    out.position = vec4<f32>(ndc, 0.0, 1.0);
    out.id = id;
    return out;
}

struct Targets {
    @location(0) id: u32,
    @location(1) count: f32,
};

@fragment
fn fs(@location(0) @interpolate(flat) id: u32) -> Targets {
    return Targets(id, 1.0);
}
";

/// The read-back: one invocation per canvas pixel and sample; the word is id + 1, with
/// bit 31 set when two or more fragments reached the sample. `TEXTURE` is
/// `texture_2d` (one sample, `SAMPLE` the mip level 0) or `texture_multisampled_2d`.
const READ_SHADER: &str = r"
struct Params { ox: u32, oy: u32, w: u32, h: u32 };

@group(0) @binding(0) var ids: TEXTURE<u32>;
@group(0) @binding(1) var counts: TEXTURE<f32>;
@group(0) @binding(2) var<storage, read_write> words: array<u32>;
@group(0) @binding(3) var<uniform> params: Params;

@compute @workgroup_size(8, 8, 1)
fn main(@builtin(global_invocation_id) g: vec3<u32>) {
    if (g.x >= params.w || g.y >= params.h) {
        return;
    }
    let p = vec2<i32>(i32(g.x + params.ox), i32(g.y + params.oy));
    let s = i32(g.z);
    var word = textureLoad(ids, p, s).r;
    if (textureLoad(counts, p, s).r >= 1.5) {
        word = word | 0x80000000u;
    }
    words[(g.z * params.h + g.y) * params.w + g.x] = word;
}
";

fn main() -> ExitCode {
    // Mesa's device-select layer (an implicit Vulkan layer of mesa-vulkan-drivers) looks
    // for a Wayland or X display to rank the GPUs and prints an error on stderr for each
    // try without one; the adapter chooses its own (`WGPU_ADAPTER_NAME`), so it is off
    // unless the caller set it. (Single-threaded here: nothing else reads the
    // environment yet.)
    if std::env::var_os("NODEVICE_SELECT").is_none() {
        std::env::set_var("NODEVICE_SELECT", "1");
    }
    let mut args: Vec<OsString> = std::env::args_os().skip(1).collect();
    if args.len() == 1 && args[0] == "--info" {
        return match Gpu::new().and_then(|gpu| gpu.info()) {
            Ok(line) => {
                println!("{line}");
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("{NAME}: {e}");
                ExitCode::from(2)
            }
        };
    }
    let options = match Options::take(&mut args) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(values) = options.values.clone() {
        return values::values_main(args, options, values);
    }
    // The device is made at the first scene (so that a bad command line is answered
    // without one), once; a failure to make it refuses every scene with its reason.
    let mut gpu: Option<Result<Renderer, String>> = None;
    adapter_main(NAME, args, |scene| {
        let renderer = gpu.get_or_insert_with(|| Gpu::new().and_then(|g| Renderer::new(g, options.clone())));
        match renderer {
            Ok(r) => r.render(scene),
            Err(e) => Err(e.clone()),
        }
    })
}

/// The command-line options before the scene (or `--serve`).
#[derive(Clone, Debug)]
struct Options {
    /// `--samples N`.
    samples: u32,
    /// `--conservative`.
    conservative: bool,
    /// `--clip`: far vertices handed to the GPU's clipper instead of refused.
    clip: bool,
    /// `--values`: a varying's interpolated values as a float32 TIFF instead of the ids PNG.
    values: Option<values::ValuesOptions>,
}

impl Options {
    /// Takes the options from the front of `args`.
    fn take(args: &mut Vec<OsString>) -> Result<Options, String> {
        let mut options = Options {
            samples: 1,
            conservative: false,
            clip: false,
            values: None,
        };
        let (mut varying, mut fault) = (None, None);
        loop {
            match args.first().and_then(|a| a.to_str()) {
                Some("--samples") => {
                    let n = args.get(1).and_then(|a| a.to_str()).and_then(|a| a.parse::<u32>().ok());
                    options.samples = n
                        .filter(|&n| n >= 1)
                        .ok_or("--samples needs a count (1, 2, 4, 8, 16)")?;
                    args.drain(..2);
                }
                Some("--conservative") => {
                    options.conservative = true;
                    args.remove(0);
                }
                Some("--clip") => {
                    options.clip = true;
                    args.remove(0);
                }
                Some("--values") => {
                    options.values = Some(values::ValuesOptions::default());
                    args.remove(0);
                }
                Some("--varying") => {
                    let name = args.get(1).and_then(|a| a.to_str()).ok_or("--varying needs a name")?;
                    varying = Some(name.to_string());
                    args.drain(..2);
                }
                Some("--fault") => {
                    let name = args.get(1).and_then(|a| a.to_str()).unwrap_or("");
                    fault = Some(
                        values::Fault::parse(name)
                            .ok_or_else(|| format!("--fault {name:?}: one of affine, provoking, centroid"))?,
                    );
                    args.drain(..2);
                }
                _ => break,
            }
        }
        if options.conservative && options.samples > 1 {
            return Err("--conservative draws one sample per pixel: leave out --samples".into());
        }
        match &mut options.values {
            Some(values) => {
                if options.conservative {
                    return Err("--conservative draws ids only: leave it out with --values".into());
                }
                values.varying = varying;
                values.fault = fault;
            }
            None if varying.is_some() || fault.is_some() => {
                return Err("--varying and --fault go with --values".into());
            }
            None => {}
        }
        Ok(options)
    }
}

/// Errors wgpu reports outside an error scope (and device loss): kept, never a panic.
type ErrorSlot = Arc<Mutex<Option<String>>>;

/// The adapter, its device and queue.
struct Gpu {
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// The device's loss, when it happened: every later scene is refused with it.
    lost: ErrorSlot,
    /// An error wgpu reported outside the adapter's error scopes: the scene during which
    /// it came is refused with it.
    uncaptured: ErrorSlot,
}

impl Gpu {
    /// The adapter wgpu's environment variables choose (`WGPU_BACKEND`,
    /// `WGPU_ADAPTER_NAME`, `WGPU_POWER_PREF`), or the default one, and a device with
    /// its limits and the two features this adapter may use.
    fn new() -> Result<Gpu, String> {
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        descriptor.backends = wgpu::Backends::from_env().unwrap_or(BACKENDS) & BACKENDS;
        let backends = descriptor.backends;
        let instance = wgpu::Instance::new(descriptor);
        let adapter = pollster::block_on(choose_adapter(&instance, backends))?;
        let wanted =
            wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES | wgpu::Features::CONSERVATIVE_RASTERIZATION;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some(NAME),
            required_features: adapter.features() & wanted,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| format!("{}: cannot open a device: {e}", adapter.get_info().name))?;
        let (lost, uncaptured): (ErrorSlot, ErrorSlot) = Default::default();
        let slot = uncaptured.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut s) = slot.lock() {
                s.get_or_insert_with(|| format!("wgpu error: {e}"));
            }
        }));
        let slot = lost.clone();
        device.set_device_lost_callback(move |reason, message| {
            if let Ok(mut s) = slot.lock() {
                s.get_or_insert_with(|| format!("the device was lost ({reason:?}): {message}"));
            }
        });
        Ok(Gpu {
            adapter,
            device,
            queue,
            lost,
            uncaptured,
        })
    }

    /// The sample counts (of 1, 2, 4, 8, 16) both colour targets offer, with blending of
    /// the count target: what the adapter reports for the formats (adapter-specific
    /// features included, which the device was asked for when available).
    fn sample_counts(&self) -> Vec<u32> {
        let ids = self.adapter.get_texture_format_features(IDS_FORMAT);
        let count = self.adapter.get_texture_format_features(COUNT_FORMAT);
        let specific = self
            .device
            .features()
            .contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);
        [1, 2, 4, 8, 16]
            .into_iter()
            .filter(|&n| {
                n == 1 || specific && ids.flags.sample_count_supported(n) && count.flags.sample_count_supported(n)
            })
            .collect()
    }

    /// `--info`: one JSON line.
    fn info(&self) -> Result<String, String> {
        let info = self.adapter.get_info();
        let ids = self.adapter.get_texture_format_features(IDS_FORMAT);
        let r32: Vec<u32> = [1, 2, 4, 8, 16]
            .into_iter()
            .filter(|&n| n == 1 || ids.flags.sample_count_supported(n))
            .collect();
        Ok(serde_json::json!({
            "adapter": info.name,
            "backend": info.backend.to_str(),
            "device_type": format!("{:?}", info.device_type),
            "driver": info.driver,
            "driver_info": info.driver_info,
            "r32uint_sample_counts": r32,
            "rgba32float_sample_counts": values::sample_counts(self),
            "sample_counts": self.sample_counts(),
            "adapter_specific_format_features": self.adapter.features().contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES),
            "conservative_rasterization": self.adapter.features().contains(wgpu::Features::CONSERVATIVE_RASTERIZATION),
            "max_texture_dimension_2d": self.device.limits().max_texture_dimension_2d,
        })
        .to_string())
    }
}

/// `WGPU_ADAPTER_NAME`'s adapter (the first whose name contains it, case-insensitively),
/// or the default adapter of `backends`.
async fn choose_adapter(instance: &wgpu::Instance, backends: wgpu::Backends) -> Result<wgpu::Adapter, String> {
    let tried = backends
        .iter_names()
        .map(|(name, _)| name.to_lowercase())
        .collect::<Vec<_>>()
        .join(", ");
    let adapters = instance.enumerate_adapters(backends).await;
    let names: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
    if let Ok(wanted) = std::env::var("WGPU_ADAPTER_NAME") {
        let lower = wanted.to_lowercase();
        return adapters
            .into_iter()
            .find(|a| a.get_info().name.to_lowercase().contains(&lower))
            .ok_or_else(|| format!("WGPU_ADAPTER_NAME={wanted}: no such adapter among {names:?} (backends {tried})"));
    }
    instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::from_env().unwrap_or_default(),
            ..Default::default()
        })
        .await
        .map_err(|e| {
            format!(
                "no GPU adapter found (backends tried: {tried}; {e}); on Debian, mesa-vulkan-drivers and libvulkan1 provide lavapipe, a Vulkan driver on the CPU"
            )
        })
}

/// The render targets of one side, made again when a scene needs a larger one.
struct Targets {
    side: u32,
    ids: wgpu::TextureView,
    counts: wgpu::TextureView,
}

/// The pipelines and the buffers reused across scenes.
struct Renderer {
    gpu: Gpu,
    options: Options,
    draw: wgpu::RenderPipeline,
    read: wgpu::ComputePipeline,
    targets: Option<Targets>,
    /// The largest side the adapter draws into.
    max_side: u32,
}

/// One vertex: NDC position and id + 1.
const VERTEX_BYTES: u64 = 12;

impl Renderer {
    /// The pipelines for `options` on `gpu`, or why it cannot draw them.
    fn new(gpu: Gpu, options: Options) -> Result<Renderer, String> {
        let name = gpu.adapter.get_info().name;
        let counts = gpu.sample_counts();
        if !counts.contains(&options.samples) {
            return Err(format!(
                "this adapter ({name}) offers {counts:?} samples for R32Uint and R16Float targets, not {}",
                options.samples
            ));
        }
        if options.conservative
            && !gpu
                .device
                .features()
                .contains(wgpu::Features::CONSERVATIVE_RASTERIZATION)
        {
            return Err(format!(
                "this adapter ({name}) does not offer conservative rasterization"
            ));
        }
        let device = &gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let draw_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("draw"),
            source: wgpu::ShaderSource::Wgsl(DRAW_SHADER.into()),
        });
        let texture = if options.samples == 1 {
            "texture_2d"
        } else {
            "texture_multisampled_2d"
        };
        let read_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("read"),
            source: wgpu::ShaderSource::Wgsl(READ_SHADER.replace("TEXTURE", texture).into()),
        });
        let draw = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("draw"),
            layout: None,
            vertex: wgpu::VertexState {
                module: &draw_module,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: VERTEX_BYTES,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x2, 1 => Uint32],
                })],
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                cull_mode: None,
                conservative: options.conservative,
                ..Default::default()
            },
            depth_stencil: None,
            multisample: wgpu::MultisampleState {
                count: options.samples,
                mask: !0,
                alpha_to_coverage_enabled: false,
            },
            fragment: Some(wgpu::FragmentState {
                module: &draw_module,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[
                    Some(wgpu::ColorTargetState {
                        format: IDS_FORMAT,
                        blend: None,
                        write_mask: wgpu::ColorWrites::ALL,
                    }),
                    Some(wgpu::ColorTargetState {
                        format: COUNT_FORMAT,
                        blend: Some(wgpu::BlendState {
                            color: wgpu::BlendComponent {
                                src_factor: wgpu::BlendFactor::One,
                                dst_factor: wgpu::BlendFactor::One,
                                operation: wgpu::BlendOperation::Add,
                            },
                            alpha: wgpu::BlendComponent::REPLACE,
                        }),
                        write_mask: wgpu::ColorWrites::ALL,
                    }),
                ],
            }),
            multiview_mask: None,
            cache: None,
        });
        let read = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("read"),
            layout: None,
            module: &read_module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("wgpu refused the pipelines: {e}"));
        }
        let max_side = device.limits().max_texture_dimension_2d.min(MAX_TARGET);
        Ok(Renderer {
            gpu,
            options,
            draw,
            read,
            targets: None,
            max_side,
        })
    }

    /// The targets for a side of at least `side` (a power of two).
    fn targets(&mut self, side: u32) -> &Targets {
        if self.targets.as_ref().is_none_or(|t| t.side < side) {
            let texture = |label, format| {
                self.gpu
                    .device
                    .create_texture(&wgpu::TextureDescriptor {
                        label: Some(label),
                        size: wgpu::Extent3d {
                            width: side,
                            height: side,
                            depth_or_array_layers: 1,
                        },
                        mip_level_count: 1,
                        sample_count: self.options.samples,
                        dimension: wgpu::TextureDimension::D2,
                        format,
                        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                        view_formats: &[],
                    })
                    .create_view(&wgpu::TextureViewDescriptor::default())
            };
            self.targets = Some(Targets {
                side,
                ids: texture("ids", IDS_FORMAT),
                counts: texture("counts", COUNT_FORMAT),
            });
        }
        self.targets.as_ref().expect("just made")
    }

    /// One scene: the ids PNG (stacked per sample when `--samples` is above 1).
    fn render(&mut self, scene: &Scene) -> Result<image::RgbaImage, String> {
        if let Some(e) = self.gpu.lost.lock().ok().and_then(|s| s.clone()) {
            return Err(e);
        }
        refuse_unsupported(scene)?;
        if let Some(pattern) = &scene.samples {
            let asked = self.options.samples;
            if !pattern.is_standard() {
                return Err(format!(
                    "the scene states a custom sample pattern ({pattern}); a GPU draws its standard positions only (no VK_EXT_sample_locations here)"
                ));
            }
            if u32::try_from(pattern.len()).ok() != Some(asked) {
                return Err(format!(
                    "the scene states {} samples per pixel; this adapter was started with --samples {asked}",
                    pattern.len()
                ));
            }
        }
        let placed = place(scene, self.max_side, self.options.clip)?;
        if placed.rounded > 0 || placed.unmapped > 0 {
            eprintln!(
                "{NAME}: note: {} coordinate(s) are not f32-exact (rounded to the nearest f32); {} do not map exactly to NDC (rounded)",
                placed.rounded, placed.unmapped
            );
        }
        let device = self.gpu.device.clone();
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let words = self.draw_and_read(scene, &placed);
        let oom = pollster::block_on(memory.pop());
        let invalid = pollster::block_on(validation.pop());
        if let Some(e) = oom.or(invalid) {
            return Err(format!("wgpu error: {e}"));
        }
        let uncaptured = self.gpu.uncaptured.lock().ok().and_then(|mut s| s.take());
        if let Some(e) = self.gpu.lost.lock().ok().and_then(|s| s.clone()).or(uncaptured) {
            return Err(e);
        }
        let words = words?;
        let (w, h) = (scene.width, scene.height);
        let rows = h
            .checked_mul(self.options.samples)
            .ok_or("the stacked image is too tall")?;
        let mut rgba = Vec::with_capacity(words.len() * 4);
        for word in words {
            let encoded = word & MAX_ENCODED;
            if encoded == 0 {
                rgba.extend_from_slice(&[0, 0, 0, 0]);
            } else {
                let [r, g, b, _] = encoded.to_le_bytes();
                rgba.extend_from_slice(&[r, g, b, if word >> 31 == 1 { 254 } else { 255 }]);
            }
        }
        image::RgbaImage::from_raw(w, rows, rgba).ok_or_else(|| "internal: the read-back's size does not match".into())
    }

    /// Draws the placed scene and reads back one word per canvas pixel and sample.
    fn draw_and_read(&mut self, scene: &Scene, placed: &Placed) -> Result<Vec<u32>, String> {
        let samples = self.options.samples;
        let (w, h) = (scene.width, scene.height);
        let words_len = u64::from(w) * u64::from(h) * u64::from(samples);
        let bytes = words_len * 4;
        if bytes > self.gpu.device.limits().max_storage_buffer_binding_size {
            return Err(format!(
                "the read-back of {w}x{h} pixels at {samples} samples ({bytes} bytes) exceeds the device's storage buffer limit"
            ));
        }
        let side = placed.side;
        let targets = self.targets(side);
        let (ids_view, counts_view) = (targets.ids.clone(), targets.counts.clone());
        let device = &self.gpu.device;
        let vertex_bytes: Vec<u8> = placed.vertices.iter().flat_map(|v| v.iter().copied()).collect();
        let vertices = (!vertex_bytes.is_empty()).then(|| {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("vertices"),
                size: vertex_bytes.len() as u64,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.gpu.queue.write_buffer(&buffer, 0, &vertex_bytes);
            buffer
        });
        let params = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("params"),
            size: 16,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let param_words: Vec<u8> = [placed.ox, placed.oy, w, h]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        self.gpu.queue.write_buffer(&params, 0, &param_words);
        let out = ReadOut::new(device, bytes);
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("read"),
            layout: &self.read.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&ids_view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&counts_view),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: out.storage.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: params.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(NAME) });
        {
            let clear = wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                store: wgpu::StoreOp::Store,
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("draw"),
                color_attachments: &[
                    Some(wgpu::RenderPassColorAttachment {
                        view: &ids_view,
                        depth_slice: None,
                        resolve_target: None,
                        ops: clear,
                    }),
                    Some(wgpu::RenderPassColorAttachment {
                        view: &counts_view,
                        depth_slice: None,
                        resolve_target: None,
                        ops: clear,
                    }),
                ],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            // The viewport is the whole target (the target may be larger than `side`
            // when an earlier scene needed more: the viewport keeps to `side`, whose
            // top-left corner is the target's).
            #[allow(clippy::cast_precision_loss)] // a power of two up to 8192: exact
            let p = side as f32;
            pass.set_viewport(0.0, 0.0, p, p, 0.0, 1.0);
            pass.set_scissor_rect(placed.ox, placed.oy, w, h);
            if let Some(buffer) = &vertices {
                pass.set_pipeline(&self.draw);
                pass.set_vertex_buffer(0, buffer.slice(..));
                let count = u32::try_from(placed.vertices.len()).map_err(|_| "too many vertices")?;
                pass.draw(0..count, 0..1);
            }
        }
        Ok(out
            .read(
                device,
                &self.gpu.queue,
                encoder,
                (&self.read, &bind_group),
                (w, h, samples),
            )?
            .into_iter()
            .map(u32::from_le_bytes)
            .collect())
    }
}

/// Where a read pass writes what it reads of the targets (`storage`) and the buffer it is
/// copied to for mapping (`readback`): both modes read their targets this way.
struct ReadOut {
    storage: wgpu::Buffer,
    readback: wgpu::Buffer,
    bytes: u64,
}

impl ReadOut {
    fn new(device: &wgpu::Device, bytes: u64) -> ReadOut {
        let buffer = |label, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: bytes,
                usage,
                mapped_at_creation: false,
            })
        };
        ReadOut {
            storage: buffer("read", wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC),
            readback: buffer("read-back", wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST),
            bytes,
        }
    }

    /// Ends `encoder` with the read pass (`pipeline` and its bind group, one invocation per
    /// pixel of `w` x `h` and sample), the copy to the read-back buffer; submits it and
    /// gives the words read back.
    fn read(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mut encoder: wgpu::CommandEncoder,
        (pipeline, bind_group): (&wgpu::ComputePipeline, &wgpu::BindGroup),
        (w, h, samples): (u32, u32, u32),
    ) -> Result<Vec<[u8; 4]>, String> {
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("read"),
                timestamp_writes: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, bind_group, &[]);
            pass.dispatch_workgroups(w.div_ceil(8), h.div_ceil(8), samples);
        }
        encoder.copy_buffer_to_buffer(&self.storage, 0, &self.readback, 0, self.bytes);
        queue.submit([encoder.finish()]);
        read_back(device, &self.readback)
    }
}

/// The 4-byte words of `readback` once the GPU has written it (the work submitted):
/// mapped, waited for (at most 60 s), copied out and unmapped.
fn read_back(device: &wgpu::Device, readback: &wgpu::Buffer) -> Result<Vec<[u8; 4]>, String> {
    let slice = readback.slice(..);
    let mapped: Arc<Mutex<Option<Result<(), wgpu::BufferAsyncError>>>> = Arc::new(Mutex::new(None));
    let done = mapped.clone();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        if let Ok(mut d) = done.lock() {
            *d = Some(r);
        }
    });
    device
        .poll(wgpu::PollType::Wait {
            submission_index: None,
            timeout: Some(std::time::Duration::from_secs(60)),
        })
        .map_err(|e| format!("waiting for the GPU: {e}"))?;
    match mapped.lock().map_err(|_| "internal: poisoned")?.take() {
        Some(Ok(())) => {}
        Some(Err(e)) => return Err(format!("cannot read the result back: {e}")),
        None => return Err("the GPU did not finish".into()),
    }
    let words = slice
        .get_mapped_range()
        .map_err(|e| format!("cannot read the result back: {e}"))?
        .chunks_exact(4)
        .map(|b| [b[0], b[1], b[2], b[3]])
        .collect();
    readback.unmap();
    Ok(words)
}

/// Refuses what neither mode draws: primitives other than window-space triangles.
fn refuse_other_primitives(scene: &Scene) -> Result<(), String> {
    let mut refused = Vec::new();
    if !scene.lines.is_empty() {
        refused.push("lines");
    }
    if !scene.polygons.is_empty() {
        refused.push("polygons");
    }
    if scene.clip.is_some() {
        refused.push("a clip window");
    }
    if !scene.clip_space_triangles.is_empty() {
        refused.push("clip-space triangles");
    }
    if refused.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "this adapter draws window-space triangles only; the scene has {}",
            refused.join(", ")
        ))
    }
}

/// Refuses what the adapter does not draw.
fn refuse_unsupported(scene: &Scene) -> Result<(), String> {
    refuse_other_primitives(scene)?;
    if scene.triangles.len() > MAX_ENCODED as usize {
        return Err(format!(
            "{} triangles: the ids PNG holds ids up to {}",
            scene.triangles.len(),
            MAX_ENCODED - 1
        ));
    }
    Ok(())
}

/// A scene placed in its target: the side, the canvas's offset, the vertex data.
struct Placed {
    /// The target's side P, a power of two.
    side: u32,
    /// Where the canvas's top-left corner lies in the target.
    ox: u32,
    oy: u32,
    /// Three vertices per triangle: `ndc_x`, `ndc_y` (f32) and id + 1 (u32), little-endian.
    vertices: Vec<[u8; 12]>,
    /// Coordinates that were not f32-exact.
    rounded: usize,
    /// Coordinates whose NDC value is not exact in f32.
    unmapped: usize,
}

/// Rounds the vertices to f32, places the canvas and every vertex in a power-of-two
/// target of side at most `max_side`, and maps each vertex to NDC. With `clip`, a scene
/// whose vertices need a larger target is drawn into the canvas's own target (offset 0)
/// with the far vertices outside the view volume, for the GPU to clip.
fn place(scene: &Scene, max_side: u32, clip: bool) -> Result<Placed, String> {
    let mut rounded = 0;
    let mut points = Vec::with_capacity(scene.triangles.len() * 3);
    for (k, t) in scene.triangles().iter().enumerate() {
        for (j, p) in t.v.iter().enumerate() {
            let mut xy = [0f32; 2];
            for (c, exact) in [&p.x, &p.y].into_iter().enumerate() {
                let f = nearest_f32(exact)
                    .filter(|f| f.is_finite())
                    .ok_or_else(|| format!("triangles[{k}].v[{j}]: {p} does not fit f32"))?;
                if BigRational::from_float(f).as_ref() != Some(exact) {
                    rounded += 1;
                }
                xy[c] = f;
            }
            points.push((k, xy));
        }
    }
    // The bounding box of the canvas and the vertices, in whole pixels (f64 holds every
    // f32 and its floor and ceiling exactly).
    let (mut lo, mut hi) = ([0f64; 2], [f64::from(scene.width), f64::from(scene.height)]);
    for (_, xy) in &points {
        for c in 0..2 {
            lo[c] = lo[c].min(f64::from(xy[c]).floor());
            hi[c] = hi[c].max(f64::from(xy[c]).ceil());
        }
    }
    let mut span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if span > f64::from(max_side) && clip {
        (lo, span) = ([0.0; 2], f64::from(scene.width.max(scene.height)));
    }
    if scene.width.max(scene.height) > max_side {
        return Err(format!(
            "the {}x{} canvas needs a target larger than the largest this adapter draws into ({max_side}x{max_side} px)",
            scene.width, scene.height
        ));
    }
    if span > f64::from(max_side) {
        return Err(format!(
            "a vertex lies beyond the largest target this adapter draws into ({max_side}x{max_side} px holding the canvas and every vertex; the vertices span [{}, {}] x [{}, {}]): the GPU would clip it in floating point; --clip lets it",
            lo[0], hi[0], lo[1], hi[1]
        ));
    }
    // Whole numbers within 0..=max_side: exact as u32.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let (side, ox, oy) = (
        (span as u32).max(1).next_power_of_two(),
        (-lo[0]) as u32,
        (-lo[1]) as u32,
    );
    let p = BigRational::from_integer(side.into());
    let two_over_p = BigRational::new(2.into(), side.into());
    let mut unmapped = 0;
    let mut vertices = Vec::with_capacity(points.len());
    for (k, xy) in points {
        let mut word = [0u8; 12];
        for (c, offset) in [(0, ox), (1, oy)] {
            let moved = BigRational::from_float(xy[c]).expect("finite") + BigRational::from_integer(offset.into());
            debug_assert!(clip || moved >= BigRational::zero() && moved <= p);
            // ndc_x = x'·(2/P) − 1; ndc_y = 1 − y'·(2/P).
            let exact = if c == 0 {
                &moved * &two_over_p - BigRational::one()
            } else {
                BigRational::one() - &moved * &two_over_p
            };
            let ndc = nearest_f32(&exact)
                .filter(|f| f.is_finite())
                .ok_or_else(|| format!("triangles[{k}]: a vertex's NDC value does not fit f32"))?;
            if BigRational::from_float(ndc).as_ref() != Some(&exact) {
                unmapped += 1;
            }
            word[4 * c..4 * c + 4].copy_from_slice(&ndc.to_le_bytes());
        }
        let id = u32::try_from(k).expect("checked: below 2^24") + 1;
        word[8..].copy_from_slice(&id.to_le_bytes());
        vertices.push(word);
    }
    Ok(Placed {
        side,
        ox,
        oy,
        vertices,
        rounded,
        unmapped,
    })
}
