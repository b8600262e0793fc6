//! `render --ids-out` (the ids PNG format in docs/cli.md): the file read back with
//! the `image` crate holds, pixel by pixel, what the coverage says: `id + 1` little-endian
//! in R, G, B, alpha 255 for one owner, the highest id with alpha 254 for several, zero
//! where uncovered.

use std::path::Path;

use assert_cmd::Command;
use rasterproof::model::{render, Model};
use rasterproof::scene::{parse_scene_with, ParseOptions};

use crate::tempdir;

/// Triangle 0 covers the lower-left half, triangle 1 the upper-right half, triangle 2 a
/// band across both (so some pixels have two owners), on an 8x6 canvas.
const SCENE: &str = r#"{"width": 8, "height": 6, "triangles": [
  {"v": [[0,0],[8,6],[0,6]]},
  {"v": [[0,0],[8,0],[8,6]]},
  {"v": [[0,2],[8,2],[8,4]]}
]}"#;

fn text(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn ids_png_reads_back_as_the_coverage() {
    let dir = tempdir::Dir::new("ids-png");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, SCENE).unwrap();
    let ids = dir.path().join("ids.png");
    let run = Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["render", text(&scene), "--model", "fixed", "--ids-out", text(&ids)])
        .output()
        .unwrap();
    let out = String::from_utf8(run.stdout).unwrap();
    assert!(run.status.success(), "{out}{}", String::from_utf8_lossy(&run.stderr));
    assert!(
        out.contains(&format!("wrote {} (ids, unscaled)", ids.display())),
        "{out}"
    );

    let png = image::open(&ids).unwrap();
    assert_eq!(png.color(), image::ColorType::Rgba8);
    let png = png.to_rgba8();
    assert_eq!(png.dimensions(), (8, 6));

    let parsed = parse_scene_with(SCENE.as_bytes(), "s.json", &ParseOptions::default()).unwrap();
    let target = parsed.target().unwrap();
    let coverage = render(&parsed.primitives(), &target, Model::Fixed).unwrap();
    let mut several = 0;
    for (x, y, p) in png.enumerate_pixels() {
        let [r, g, b, a] = p.0;
        let value = u32::from(r) | u32::from(g) << 8 | u32::from(b) << 16;
        match coverage.owners(x, y) {
            [] => assert_eq!(p.0, [0, 0, 0, 0], "({x},{y})"),
            [id] => assert_eq!((value, a), (id + 1, 255), "({x},{y})"),
            many => {
                several += 1;
                assert_eq!((value, a), (many.last().unwrap() + 1, 254), "({x},{y})");
            }
        }
    }
    assert!(several > 0, "the scene has pixels with several owners");
    assert!(coverage.covered_pixels() == 48, "the two halves tile the canvas");
}

#[test]
fn json_on_stdout_is_streamed_unchanged() {
    let dir = tempdir::Dir::new("ids-json");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, SCENE).unwrap();
    let run = Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["render", text(&scene), "--model", "fixed", "--format", "json"])
        .output()
        .unwrap();
    assert!(run.status.success());
    let parsed = parse_scene_with(SCENE.as_bytes(), "s.json", &ParseOptions::default()).unwrap();
    let coverage = render(&parsed.primitives(), &parsed.target().unwrap(), Model::Fixed).unwrap();
    assert_eq!(String::from_utf8(run.stdout).unwrap(), coverage.to_json() + "\n");
}
