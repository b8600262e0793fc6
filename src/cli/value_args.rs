//! What `compare` and `explain` share to read another renderer's output: `--as` with its
//! default by file name, the file read, and the values arguments (`--varying`,
//! `--unorm-rule`), each declared once.

use std::path::Path;

use rasterproof::convention::Target;
use rasterproof::model::Model;
use rasterproof::oracle::compare::values::ValueOptions;
use rasterproof::oracle::{Background, Format, Theirs};
use rasterproof::pattern::SamplePattern;
use rasterproof::scene::Scene;

/// The arguments of a values question (`--as values`), flattened into `compare`'s and
/// `explain`'s options.
#[derive(clap::Args, Debug, Clone)]
pub struct ValueArgs {
    /// With `--as values`: the varying their image holds (default the scene's first);
    /// their first channels are its channels.
    #[arg(long, value_name = "NAME")]
    pub varying: Option<String>,
    /// With `--as values` and a UNORM PNG: the conversion rule their levels follow
    /// (`nearest`: round to nearest, ties to even; `vulkan`: either of the two nearest
    /// levels; `d3d`: within 0.6 of a level's unit).
    #[arg(long = "unorm-rule", default_value = "nearest", value_name = "nearest|vulkan|d3d")]
    pub unorm_rule: String,
}

impl ValueArgs {
    /// `Err` when a values argument is given and the question is not about values.
    pub fn only_for_values(&self, values: bool) -> Result<(), String> {
        if !values && (self.varying.is_some() || self.unorm_rule != "nearest") {
            return Err("--varying and --unorm-rule are for --as values".to_string());
        }
        Ok(())
    }

    /// The values question's options for `scene` (named `name`) drawn under `model`, their
    /// image under `pattern` (the scene's or `--samples`').
    pub fn options(
        &self,
        scene: &Scene,
        name: &str,
        model: Model,
        pattern: Option<SamplePattern>,
        target: &Target,
    ) -> Result<ValueOptions, String> {
        Ok(
            ValueOptions::for_scene(scene, name, model, self.varying.as_deref(), &self.unorm_rule)?
                .with_pattern(pattern, &target.convention),
        )
    }
}

/// `--as FORMAT`, or the default for `theirs`: json for a `.json` file, values for a
/// `.tif` or `.tiff` file, ids otherwise.
pub fn their_format(theirs_as: Option<&str>, theirs: &Path) -> Result<Format, String> {
    let extension = |names: &[&str]| {
        theirs
            .extension()
            .is_some_and(|e| names.iter().any(|n| e.eq_ignore_ascii_case(n)))
    };
    match theirs_as {
        Some(f) => Format::from_name(f)
            .ok_or_else(|| format!("--as: unknown format {f:?} (expected mask, ids, json, grey or values)")),
        None if extension(&["json"]) => Ok(Format::Json),
        None if extension(&["tif", "tiff"]) => Ok(Format::Values),
        None => Ok(Format::Ids),
    }
}

/// Their output at `path`, read as `format` (a mask against `background`), with its name
/// (the path as given) for messages.
pub fn read_theirs(path: &Path, format: Format, background: Background) -> Result<(String, Theirs), String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let theirs = Theirs::read(&bytes, &name, format, background).map_err(|e| e.to_string())?;
    Ok((name, theirs))
}
