//! The renderer's side of `hunt`'s two protocols, for an adapter written in Rust: it gives
//! one function, scene in, image out, and [`adapter_main`] answers both ways of being
//! called: `ADAPTER SCENE.json OUT.png` (once per scene, `hunt --cmd`) and `ADAPTER
//! --serve` (kept alive, `hunt --serve`: one JSON request per line on stdin, one JSON
//! response per line on stdout; [`super::stay_alive`] states the protocol).
//!
//! ```no_run
//! use rasterproof::oracle::renderer::adapter::adapter_main;
//! // A "renderer" that covers nothing: an all-transparent ids PNG of the canvas.
//! fn main() -> std::process::ExitCode {
//!     adapter_main("empty-adapter", std::env::args_os().skip(1).collect(), |scene| {
//!         Ok(image::RgbaImage::new(scene.width, scene.height))
//!     })
//! }
//! ```

use std::ffi::OsString;
use std::path::Path;
use std::process::ExitCode;

use image::{DynamicImage, ImageBuffer};
use serde_json::{json, Value};

use crate::scene::{parse_scene, parse_scene_with, ParseOptions, Scene};

/// What an adapter's `render` gives for a scene: an image, written as a PNG (an ids or
/// mask image of the canvas, an `RgbaImage`; a grey image of its coverage, a `GrayImage`),
/// or a file's bytes written as they are ([`FileBytes`]: a float32 values TIFF).
pub trait AdapterOutput {
    /// Writes it at `out`; the error names the path.
    ///
    /// # Errors
    /// The file cannot be written.
    fn write_at(self, out: &Path) -> Result<(), String>;
}

impl<P: image::Pixel, C> AdapterOutput for ImageBuffer<P, C>
where
    DynamicImage: From<ImageBuffer<P, C>>,
{
    fn write_at(self, out: &Path) -> Result<(), String> {
        write_png(self.into(), out)
    }
}

impl AdapterOutput for DynamicImage {
    fn write_at(self, out: &Path) -> Result<(), String> {
        write_png(self, out)
    }
}

/// A file's bytes, written as they are: what an adapter answering `--as values` renders (a
/// float32 TIFF, `render --values-out`'s layout).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileBytes {
    /// The file.
    pub bytes: Vec<u8>,
    /// Its kind in an error message (`TIFF`).
    pub kind: &'static str,
}

impl AdapterOutput for FileBytes {
    fn write_at(self, out: &Path) -> Result<(), String> {
        std::fs::write(out, self.bytes).map_err(|e| format!("{}: cannot write the {}: {e}", out.display(), self.kind))
    }
}

/// Runs an adapter named `name` on its command-line `args` (without the program name):
/// `SCENE.json OUT.png` renders one scene with `render` and writes the PNG (exit 0, or 2
/// with one line on stderr); `--serve` answers requests until stdin ends (exit 0).
/// `render` turns a scene into the output (an image for the PNG, [`AdapterOutput`]) or
/// says why it cannot.
pub fn adapter_main<I: AdapterOutput>(
    name: &str,
    args: Vec<OsString>,
    mut render: impl FnMut(&Scene) -> Result<I, String>,
) -> ExitCode {
    let result = match args.as_slice() {
        [flag] if flag == "--serve" => serve(name, std::io::stdin().lock(), &mut std::io::stdout(), &mut render),
        [scene, out] => run_once(Path::new(scene), Path::new(out), &mut render),
        _ => Err(format!("usage: {name} SCENE.json OUT.png, or {name} --serve")),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{name}: {message}");
            ExitCode::from(2)
        }
    }
}

/// One scene from the file `scene_path` rendered into `out`: what [`adapter_main`] does
/// with `SCENE.json OUT`, for an adapter that reads its own options first.
///
/// # Errors
/// The scene cannot be read or parsed, `render` refuses it (the message names the scene
/// file), or `out` cannot be written.
pub fn run_once<I: AdapterOutput>(
    scene_path: &Path,
    out: &Path,
    render: &mut impl FnMut(&Scene) -> Result<I, String>,
) -> Result<(), String> {
    let bytes = std::fs::read(scene_path).map_err(|e| format!("{}: cannot read: {e}", scene_path.display()))?;
    let scene = parse_scene_with(&bytes, &scene_path.display().to_string(), &ParseOptions::default())
        .map_err(|e| e.to_string())?;
    let output = render(&scene).map_err(|e| format!("{}: {e}", scene_path.display()))?;
    output.write_at(out)
}

/// `image` as a PNG at `out`.
fn write_png(image: DynamicImage, out: &Path) -> Result<(), String> {
    image
        .save_with_format(out, image::ImageFormat::Png)
        .map_err(|e| format!("{}: cannot write the PNG: {e}", out.display()))
}

/// The stay-alive loop: each request line of `input` answered on `output`, until the
/// input ends. A request it cannot read, a scene `render` refuses and an output it cannot
/// write are each answered `"ok": false` with the reason; the loop goes on.
///
/// # Errors
/// Only when `output` cannot be written (rasterproof is gone).
pub fn serve<I: AdapterOutput>(
    name: &str,
    input: impl std::io::BufRead,
    output: &mut impl std::io::Write,
    render: &mut impl FnMut(&Scene) -> Result<I, String>,
) -> Result<(), String> {
    for line in input.lines() {
        let line = line.map_err(|e| format!("cannot read stdin: {e}"))?;
        if line.trim().is_empty() {
            continue;
        }
        let request: Result<Value, String> =
            serde_json::from_str(&line).map_err(|e| format!("not a JSON request: {e}"));
        let id = request
            .as_ref()
            .ok()
            .and_then(|r| r.get("id").cloned())
            .unwrap_or(Value::Null);
        let answer = match request.and_then(|r| answer(&r, render)) {
            Ok(()) => json!({"id": id, "ok": true}),
            Err(error) => {
                eprintln!("{name}: request {id}: {error}");
                json!({"id": id, "ok": false, "error": error})
            }
        };
        writeln!(output, "{answer}")
            .and_then(|()| output.flush())
            .map_err(|e| format!("cannot answer on stdout: {e}"))?;
    }
    Ok(())
}

/// Renders one request's scene into its `out`.
fn answer<I: AdapterOutput>(
    request: &Value,
    render: &mut impl FnMut(&Scene) -> Result<I, String>,
) -> Result<(), String> {
    let version = request.get("rasterproof").and_then(Value::as_u64);
    if version != Some(u64::from(super::stay_alive::PROTOCOL_VERSION)) {
        return Err(format!(
            "protocol version {}: this adapter speaks {}",
            version.map_or("(none)".to_string(), |v| v.to_string()),
            super::stay_alive::PROTOCOL_VERSION
        ));
    }
    let out = request
        .get("out")
        .and_then(Value::as_str)
        .ok_or("the request has no \"out\" path")?;
    let scene = request.get("scene").ok_or("the request has no \"scene\"")?;
    let scene = parse_scene(&scene.to_string(), "the request's scene").map_err(|e| e.to_string())?;
    render(&scene)?.write_at(Path::new(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The loop by hand: a good request is rendered and answered ok; a line that is not
    /// JSON, a request of another version, a scene the renderer refuses and an invalid
    /// scene are answered `ok: false` with the reason, and the loop goes on.
    #[test]
    fn serve_answers_every_line() {
        let dir = std::env::temp_dir().join(format!("rasterproof-adapter-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let out = dir.join("o.png");
        let scene = r#"{"width": 2, "height": 3, "triangles": []}"#;
        let good =
            json!({"rasterproof": 1, "id": 1, "scene": serde_json::from_str::<Value>(scene).unwrap(), "out": out});
        let refused = json!({"rasterproof": 1, "id": 3, "scene": {"width": 5, "height": 1}, "out": out});
        let invalid = json!({"rasterproof": 1, "id": 4, "scene": {"width": 0}, "out": out});
        let input = format!(
            "{good}\nnot json\n{}\n{refused}\n{invalid}\n",
            json!({"rasterproof": 2, "id": 2})
        );
        let mut output = Vec::new();
        let mut render = |s: &Scene| {
            if s.width == 5 {
                Err("five is too wide".to_string())
            } else {
                Ok(image::RgbaImage::new(s.width, s.height))
            }
        };
        serve("t", input.as_bytes(), &mut output, &mut render).unwrap();
        let answers: Vec<Value> = String::from_utf8(output)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(answers.len(), 5);
        assert_eq!(answers[0], json!({"id": 1, "ok": true}));
        assert_eq!(image::open(&out).unwrap().width(), 2);
        assert_eq!(answers[1]["id"], Value::Null);
        assert!(answers[1]["error"].as_str().unwrap().starts_with("not a JSON request"));
        assert_eq!(answers[2]["ok"], false);
        assert!(answers[2]["error"].as_str().unwrap().contains("protocol version 2"));
        assert_eq!(answers[3], json!({"id": 3, "ok": false, "error": "five is too wide"}));
        assert_eq!(answers[4]["ok"], false);
        assert!(
            answers[4]["error"].as_str().unwrap().contains("width"),
            "{}",
            answers[4]
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
