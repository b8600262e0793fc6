//! `rasterproof import`: geometry users already hold, as a scene file, exactly as its
//! floats read: RenderDoc's mesh-viewer CSV export of post-transform positions
//! ([`rasterproof::import::renderdoc::import_csv`]) or raw little-endian f32 position
//! buffers ([`rasterproof::import::raw::import_raw`]). The scene goes to `-o FILE` (all
//! or nothing) or stdout; a one-line summary goes to stderr.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rasterproof::convention::Preset;
use rasterproof::import::raw::{import_raw, IndexType, Layout, RawFile, Space};
use rasterproof::import::renderdoc::{import_csv, CsvOptions};
use rasterproof::import::{ApiViewport, ImportTarget};

use super::Outputs;

/// What `import` was asked to do.
#[derive(clap::Args)]
#[command(group(clap::ArgGroup::new("input").required(true).args(["csv", "raw"])))]
pub struct Options {
    /// RenderDoc's mesh-viewer CSV export of post-transform positions (the VS Out or GS Out
    /// table, "Export to CSV"): a header row `VTX, IDX, SV_Position.x, ...`, one row per
    /// vertex, rows in threes a triangle list. Each value is the f32 its text rounds to,
    /// exactly (see --exact-decimal).
    csv: Option<PathBuf>,
    /// Canvas width, pixels (1..=16384).
    #[arg(long)]
    width: u32,
    /// Canvas height, pixels (1..=16384).
    #[arg(long)]
    height: u32,
    /// The viewport as the API states it (clip space): d3d11, cts and vulkan: X,Y the
    /// top-left corner, y down (vulkan: a negative H is VK_KHR_maintenance1's flipped
    /// viewport); gl: glViewport's X,Y, the lower-left corner, y up. Exact decimals or
    /// fractions. Default: the whole canvas, 0,0,WIDTH,HEIGHT.
    #[arg(long, value_name = "X,Y,W,H", allow_hyphen_values = true)]
    viewport: Option<String>,
    /// The API whose conventions apply, and the scene's preset: d3d11 (NDC y up, depth
    /// 0..1), vulkan (NDC y down, depth 0..1; Vulkan captures), gl (NDC y up, depth -1..1,
    /// y origin at the bottom), cts (as d3d11).
    #[arg(long, default_value = "d3d11")]
    preset: String,
    /// The CSV position's name: its columns are NAME.x, NAME.y, NAME.z, NAME.w (any case).
    /// Default: the first of SV_Position, gl_Position, gl_PerVertex.gl_Position, POSITION
    /// the header has.
    #[arg(long, value_name = "NAME", conflicts_with = "raw")]
    position: Option<String>,
    /// Read each CSV value's decimal text exactly (0.1 is 1/10) instead of the f32 it
    /// rounds to (0.1 is 13421773/134217728, the float RenderDoc printed as 0.1).
    #[arg(long, conflicts_with = "raw")]
    exact_decimal: bool,
    /// A raw vertex buffer of little-endian f32 positions, instead of a CSV.
    #[arg(long, value_name = "FILE")]
    raw: Option<PathBuf>,
    /// Floats per vertex of --raw: 2, 3 or 4 (clip space: 2 is x y with z 0, w 1; 3 is
    /// x y z with w 1). Default 4.
    #[arg(long, value_name = "2|3|4", requires = "raw")]
    components: Option<u32>,
    /// Bytes from one vertex of --raw to the next. Default: 4 x components (packed).
    #[arg(long, value_name = "BYTES", requires = "raw")]
    stride: Option<u64>,
    /// Byte offset of the first vertex in --raw. Default 0.
    #[arg(long, value_name = "BYTES", requires = "raw")]
    offset: Option<u64>,
    /// How many vertices --raw holds. Default: every whole vertex from the offset to the
    /// end of the file.
    #[arg(long, value_name = "N", requires = "raw")]
    count: Option<u64>,
    /// An index buffer for --raw (a triangle list: indices in threes); without one the
    /// vertices themselves are taken in threes.
    #[arg(long, value_name = "FILE", requires = "raw")]
    index: Option<PathBuf>,
    /// The size of --index's indices: u16 or u32 (little-endian).
    #[arg(long, value_name = "u16|u32", requires = "index")]
    index_type: Option<String>,
    /// What --raw's positions are: clip (x, y, z, w in clip space, mapped through the
    /// viewport: the scene's clip_space_triangles) or window (x, y in pixels, x right,
    /// y down: the scene's triangles). Default clip.
    #[arg(long, value_name = "window|clip", requires = "raw")]
    space: Option<String>,
    /// Write the scene file here instead of stdout (all or nothing: a failing run writes
    /// no file).
    #[arg(short = 'o', long = "out", value_name = "SCENE.json")]
    out: Option<PathBuf>,
}

/// Imports as `o` asks, writes the scene and prints the summary on stderr; exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let preset = Preset::from_name(&o.preset).ok_or_else(|| {
        format!(
            "--preset: unknown preset {:?} (expected one of d3d11, vulkan, gl, cts)",
            o.preset
        )
    })?;
    let viewport =
        match &o.viewport {
            None => None,
            Some(text) => Some(ApiViewport::parse(text).ok_or_else(|| {
                format!("--viewport: {text:?} is not X,Y,W,H (four exact numbers separated by commas)")
            })?),
        };
    let target = ImportTarget {
        width: o.width,
        height: o.height,
        preset,
        viewport,
    };
    let imported = match (&o.csv, &o.raw) {
        (Some(csv), _) => {
            let name = csv.display().to_string();
            let file = File::open(csv).map_err(|e| format!("{name}: cannot read: {e}"))?;
            let options = CsvOptions {
                position: o.position.clone(),
                exact_decimal: o.exact_decimal,
            };
            import_csv(BufReader::new(file), &name, &options, &target).map_err(|e| e.to_string())?
        }
        (None, Some(raw)) => import_raw_files(o, raw, &target)?,
        (None, None) => return Err("give a CSV file or --raw FILE".into()),
    };
    let json = imported.scene.to_json();
    match &o.out {
        Some(path) => {
            let mut outputs = Outputs::new();
            outputs.stage_text(path, &json)?;
            outputs.commit()?;
        }
        None => super::write_stdout(|out| out.write_all(json.as_bytes()))?,
    }
    eprintln!("{}", imported.summary);
    Ok(ExitCode::SUCCESS)
}

/// `--raw` and its options.
fn import_raw_files(o: &Options, raw: &Path, target: &ImportTarget) -> Result<rasterproof::import::Imported, String> {
    let components = o.components.unwrap_or(4);
    let layout = Layout {
        components,
        stride: o.stride.unwrap_or(4 * u64::from(components)),
        offset: o.offset.unwrap_or(0),
        count: o.count,
    };
    let space = match o.space.as_deref() {
        None | Some("clip") => Space::Clip,
        Some("window") => Space::Window,
        Some(other) => return Err(format!("--space: {other:?} is not window or clip")),
    };
    let vertices = open(raw)?;
    let index = match &o.index {
        None => None,
        Some(path) => {
            let kind = match o.index_type.as_deref() {
                None => return Err("--index: give the index size with --index-type u16 or u32".into()),
                Some(name) => {
                    IndexType::from_name(name).ok_or_else(|| format!("--index-type: {name:?} is not u16 or u32"))?
                }
            };
            Some((open(path)?, kind))
        }
    };
    import_raw(vertices, &layout, index, space, target).map_err(|e| e.to_string())
}

/// A file opened for reading, with its name and length.
fn open(path: &Path) -> Result<RawFile<File>, String> {
    let name = path.display().to_string();
    let file = File::open(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let len = file.metadata().map_err(|e| format!("{name}: cannot read: {e}"))?.len();
    Ok(RawFile {
        name,
        len,
        reader: file,
    })
}
