//! Subcommands of the binary, and what they share: the help texts, stdout, and
//! [`Outputs`] (the files a command writes, all or none).

pub mod check;
pub mod clip;
pub mod compare;
pub mod explain;
pub mod flood;
pub mod hunt;
pub mod import;
pub mod plan;
pub mod render;
pub mod run_args;
pub mod trade;
pub mod value_args;

use std::ffi::OsString;
use std::fmt::Display;
use std::fs::{File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

/// `--format`: what a command prints on stdout (`clip`, `compare`, `explain`, `flood`,
/// `plan`, `render`, `trade`). Each command gives the values its own help and order
/// through [`OutputFormat::parser`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum OutputFormat {
    /// Text for people.
    Text,
    /// JSON for programs.
    Json,
}

impl OutputFormat {
    /// The value on the command line: `text` or `json`.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::Text => "text",
            OutputFormat::Json => "json",
        }
    }

    /// `--format`'s parser: these values, in this order (the order `--help` and clap's
    /// errors list them), each with its `--help` line for the command.
    pub fn parser(
        values: [(OutputFormat, &'static str); 2],
    ) -> impl clap::builder::TypedValueParser<Value = OutputFormat> {
        use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
        PossibleValuesParser::new(values.map(|(f, help)| PossibleValue::new(f.name()).help(help))).map(
            move |name: String| {
                values
                    .iter()
                    .map(|&(f, _)| f)
                    .find(|f| f.name() == name)
                    .expect("clap accepts only the possible values")
            },
        )
    }
}

impl Display for OutputFormat {
    /// The value's name, as `--help` shows the default.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The exit codes, at the end of every command's `--help`.
pub const EXIT_CODES: &str = "Exit codes:
  0  success (compare: identical)
  1  an invariant of an exact or integer model was violated (check, check-merge); an
     exact or integer model shows an error (trade); the images differ (compare); no
     convention fits (compare --fit); hunt or hunt-merge found something
  2  bad input: one line on stderr naming the file, field (or option) and value";

/// The `--model` help: every model with its one-line description, from
/// [`rasterproof::model::Model::ALL`] (a new model appears here by itself), then what
/// the exact models mean.
pub fn model_help() -> String {
    let mut s = String::from("The model that renders the scene (default exact-snapped):");
    for m in rasterproof::model::Model::ALL {
        s.push_str(&format!("\n  {:<20} {}", m.name(), m.describe()));
    }
    s.push_str(
        "\n\n\
exact and exact-snapped are exact: no rounding anywhere. Each primitive is scaled to
integers and run in the cheapest arithmetic that provably holds every value it reaches
(i32 ... arbitrary precision; `rasterproof plan` shows which); exact-plain and
exact-snapped-plain are the plain BigRational oracles they equal, slow and simple.
  exact          takes the vertices exactly as the scene file writes them
                 (0.1 is 1/10): the ideal answer.
  exact-snapped  first rounds every vertex to the subpixel grid, as GPUs do
                 (1/256 px for every preset, or the scene's subpixel_bits; ties
                 to even, cts: half away from zero), then computes exactly:
                 the answer the integer models (fixed, scanline) must equal
                 pixel for pixel.
They differ only where snapping moves an edge across a pixel's sample point.",
    );
    s
}

/// `--model NAME`, or the error listing every model.
pub fn parse_model(name: &str) -> Result<rasterproof::model::Model, String> {
    use rasterproof::model::Model;
    Model::from_name(name).ok_or_else(|| {
        let all: Vec<&str> = Model::ALL.iter().map(|m| m.name()).collect();
        format!("--model: unknown model {name:?} (expected one of {})", all.join(", "))
    })
}

/// Reads and parses a scene file, applies `--preset`, and builds its target: the
/// scene's name (its path as given), the scene and the target.
pub fn load_scene(
    path: &Path,
    preset: Option<&str>,
    jobs: usize,
) -> Result<(String, rasterproof::scene::Scene, rasterproof::convention::Target), String> {
    use rasterproof::convention::Preset;
    let name = path.display().to_string();
    let mut scene = rasterproof::scene::read_scene_file(path, &rasterproof::scene::ParseOptions::with_jobs(jobs))
        .map_err(|e| e.to_string())?;
    if let Some(p) = preset {
        scene.preset = Preset::from_name(p)
            .ok_or_else(|| format!("--preset: unknown preset {p:?} (expected one of d3d11, vulkan, gl, cts)"))?;
    }
    let target = scene
        .target()
        .map_err(|e| format!("{name}: {}: {}", e.field, e.message))?;
    Ok((name, scene, target))
}

/// `--preset` and the convention overrides (`compare`, `explain`, `render`, `hunt`): the
/// scene's preset and its own overrides, then these on top.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ConventionArgs {
    /// Override the scene's preset: d3d11, vulkan, gl, cts (the scene's explicit overrides
    /// and the options below still apply on top).
    #[arg(long)]
    pub preset: Option<String>,
    /// Override the tie rule: top-left or bottom-left.
    #[arg(long, value_name = "RULE")]
    pub tie_rule: Option<String>,
    /// Override the subpixel bits (1..=16).
    #[arg(long, value_name = "BITS")]
    pub subpixel_bits: Option<u32>,
    /// Override the snapping rounding: nearest-even, half-away, floor, ceiling,
    /// towards-zero.
    #[arg(long, value_name = "MODE")]
    pub rounding: Option<String>,
    /// Override the sample position: 0.5 (pixel centres) or 0 (pixel corners).
    #[arg(long, value_name = "OFFSET")]
    pub pixel_centre: Option<String>,
}

impl ConventionArgs {
    /// Sets the overrides given on the command line (all but `--preset`) on `o`.
    pub fn apply(&self, o: &mut rasterproof::scene::Overrides) -> Result<(), String> {
        use rasterproof::convention::{PixelCentre, Rounding, TieRule};
        if let Some(t) = &self.tie_rule {
            o.tie_rule = Some(
                TieRule::from_name(t)
                    .ok_or_else(|| format!("--tie-rule: unknown tie rule {t:?} (expected top-left or bottom-left)"))?,
            );
        }
        if let Some(b) = self.subpixel_bits {
            if !(1..=rasterproof::num::MAX_SUBPIXEL_BITS).contains(&b) {
                return Err(format!(
                    "--subpixel-bits: {b} is outside 1..={}",
                    rasterproof::num::MAX_SUBPIXEL_BITS
                ));
            }
            o.subpixel_bits = Some(b);
        }
        if let Some(r) = &self.rounding {
            o.rounding = Some(Rounding::from_name(r).ok_or_else(|| {
                format!(
                    "--rounding: unknown rounding {r:?} (expected nearest-even, half-away, floor, ceiling or towards-zero)"
                )
            })?);
        }
        if let Some(c) = &self.pixel_centre {
            o.pixel_centre = Some(match c.as_str() {
                "0.5" | "1/2" => PixelCentre::Half,
                "0" => PixelCentre::Corner,
                _ => return Err(format!("--pixel-centre: {c:?} is not 0.5 or 0")),
            });
        }
        Ok(())
    }
}

/// Reads a scene as [`load_scene`] does, then applies `args`' overrides.
pub fn load_scene_with(
    path: &Path,
    args: &ConventionArgs,
    jobs: usize,
) -> Result<(String, rasterproof::scene::Scene, rasterproof::convention::Target), String> {
    let (name, mut scene, _) = load_scene(path, args.preset.as_deref(), jobs)?;
    args.apply(&mut scene.overrides)?;
    let target = scene
        .target()
        .map_err(|e| format!("{name}: {}: {}", e.field, e.message))?;
    Ok((name, scene, target))
}

/// A pixel as `X,Y` (`explain`'s pixel, `flood --at`): two integers in `0..=u32::MAX`,
/// spaces around each allowed; `None` for anything else (each command words its own
/// error).
pub fn parse_pixel(text: &str) -> Option<(u32, u32)> {
    let (x, y) = text.split_once(',')?;
    Some((x.trim().parse().ok()?, y.trim().parse().ok()?))
}

/// The files one command run writes, all or none. [`Outputs::stage`] writes each file
/// to a hidden temporary beside its target (same folder, so the final rename never
/// crosses file systems); [`Outputs::commit`] renames them all into place once every one
/// was written. Dropped without a commit (an error on the way out of `run`), it removes
/// its temporaries, so a failing run leaves no output file and no temporary behind.
#[derive(Default)]
pub struct Outputs {
    staged: Vec<Staged>,
}

/// One written temporary and the path it becomes.
struct Staged {
    temp: PathBuf,
    target: PathBuf,
}

impl Outputs {
    /// Nothing staged yet.
    pub fn new() -> Outputs {
        Outputs::default()
    }

    /// Writes `path`'s future content (`what`, e.g. "PNG", for the error) to a temporary
    /// beside it through `write`.
    ///
    /// # Errors
    /// `path` named twice, a folder, without a file name, in a folder that does not
    /// exist or cannot be written, or `write` fails: one line naming `path`.
    pub fn stage<E: Display>(
        &mut self,
        path: &Path,
        what: &str,
        write: impl FnOnce(&mut BufWriter<File>) -> Result<(), E>,
    ) -> Result<(), String> {
        let shown = path.display();
        let fail = |e: &dyn Display| format!("{shown}: cannot write {what}: {e}");
        if self.staged.iter().any(|s| s.target == path) {
            return Err(format!("{shown}: named as two outputs"));
        }
        if path.is_dir() {
            return Err(fail(&"it is a folder"));
        }
        let temp = temporary_beside(path).ok_or_else(|| fail(&"not a file name"))?;
        let file = OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp)
            .map_err(|e| fail(&e))?;
        self.staged.push(Staged {
            temp,
            target: path.to_path_buf(),
        });
        let mut out = BufWriter::new(file);
        write(&mut out).map_err(|e| fail(&e))?;
        out.flush().map_err(|e| fail(&e))
    }

    /// Stages `image` as a PNG at `path` (see [`Outputs::stage`]).
    ///
    /// # Errors
    /// As [`Outputs::stage`].
    pub fn stage_png<P>(&mut self, path: &Path, image: &image::ImageBuffer<P, Vec<u8>>) -> Result<(), String>
    where
        P: image::Pixel<Subpixel = u8> + image::PixelWithColorType,
    {
        self.stage(path, "PNG", |out| image.write_to(out, image::ImageFormat::Png))
    }

    /// Stages `text` at `path` (see [`Outputs::stage`]).
    ///
    /// # Errors
    /// As [`Outputs::stage`].
    pub fn stage_text(&mut self, path: &Path, text: &str) -> Result<(), String> {
        self.stage(path, "file", |out| out.write_all(text.as_bytes()))
    }

    /// Renames every staged file into place.
    ///
    /// # Errors
    /// A rename fails: the files already moved are removed again, with every remaining
    /// temporary, so the run still leaves no output; one line names the path.
    pub fn commit(mut self) -> Result<(), String> {
        let staged = std::mem::take(&mut self.staged);
        for (k, s) in staged.iter().enumerate() {
            if let Err(e) = std::fs::rename(&s.temp, &s.target) {
                for done in &staged[..k] {
                    let _ = std::fs::remove_file(&done.target);
                }
                for rest in &staged[k..] {
                    let _ = std::fs::remove_file(&rest.temp);
                }
                return Err(format!("{}: cannot write: {e}", s.target.display()));
            }
        }
        Ok(())
    }
}

impl Drop for Outputs {
    fn drop(&mut self) {
        for s in &self.staged {
            let _ = std::fs::remove_file(&s.temp);
        }
    }
}

/// `DIR/.NAME.rasterproof-PID-N.tmp` for `DIR/NAME`: hidden, unique within this process
/// (N counts) and between processes (PID); `None` when `path` has no file name.
fn temporary_beside(path: &Path) -> Option<PathBuf> {
    static COUNT: AtomicU32 = AtomicU32::new(0);
    let name = path.file_name()?;
    let n = COUNT.fetch_add(1, Ordering::Relaxed);
    let mut temp = OsString::from(".");
    temp.push(name);
    temp.push(format!(".rasterproof-{}-{n}.tmp", std::process::id()));
    Some(path.with_file_name(temp))
}

/// Writes to stdout through a buffer; a closed pipe (`| head`) ends quietly instead of
/// panicking.
pub fn write_stdout(body: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>) -> Result<(), String> {
    use std::io::Write as _;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    match body(&mut out).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(format!("cannot write to stdout: {e}")),
    }
}

/// Writes one line to stdout (see [`write_stdout`]).
pub fn print_stdout(line: &str) -> Result<(), String> {
    write_stdout(|out| writeln!(out, "{line}"))
}

/// `--semantics NAME` (area coverage).
pub fn parse_semantics(name: &str) -> Result<rasterproof::area::Semantics, String> {
    rasterproof::area::Semantics::from_name(name)
        .ok_or_else(|| format!("--semantics: unknown semantics {name:?} (expected true, accumulated or unclamped)"))
}

/// `--method NAME`: the grey method of that name among those of `bits`-bit levels, or,
/// with no depth given, of 8-bit levels, then 16-bit ones.
pub fn parse_grey_method(
    name: &str,
    bits: Option<u32>,
) -> Result<rasterproof::oracle::compare::fit::grey::GreyMethod, String> {
    use rasterproof::oracle::compare::fit::grey::GreyMethod;
    let found = match bits {
        Some(bits) => GreyMethod::from_name(name, bits),
        None => GreyMethod::from_name(name, 8).or_else(|e8| {
            GreyMethod::from_name(name, 16).map_err(|e16| {
                let list = |e: &str| {
                    e.split_once("expected one of: ")
                        .map(|(_, l)| l.to_string())
                        .unwrap_or_default()
                };
                format!(
                    "no grey method named {name:?} (8-bit levels: {}; 16-bit levels: {}",
                    list(&e8).trim_end_matches(')'),
                    list(&e16)
                )
            })
        }),
    };
    found.map_err(|e| format!("--method: {e}"))
}

/// `--samples N`: the standard pattern of N samples.
pub fn parse_samples(n: usize) -> Result<rasterproof::pattern::SamplePattern, String> {
    rasterproof::pattern::SamplePattern::standard(n).ok_or_else(|| {
        format!("--samples: {n} has no standard pattern (expected 1, 2, 4, 8 or 16; a scene's samples field takes any positions)")
    })
}

/// `--conservative RULE`.
pub fn parse_conservative(name: &str) -> Result<rasterproof::model::ConservativeRule, String> {
    rasterproof::model::ConservativeRule::from_name(name).ok_or_else(|| {
        format!("--conservative: unknown rule {name:?} (expected d3d12-tier1, d3d12-tier2, d3d12-tier3 or vulkan)")
    })
}

/// `--quantization NAME` (area coverage).
pub fn parse_quantization(name: &str) -> Result<rasterproof::area::Quantization, String> {
    rasterproof::area::Quantization::from_name(name).ok_or_else(|| {
        format!("--quantization: unknown quantization {name:?} (expected round, truncate, ftgrays or round16)")
    })
}
