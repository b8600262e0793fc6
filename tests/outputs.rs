//! Output files are all or nothing: a failing `render` or `flood` leaves no output file and
//! no temporary behind (issue 10, item 1); a run that succeeds leaves exactly its outputs.

use std::path::Path;

use assert_cmd::Command;

use crate::tempdir;

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

fn text(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The names in `dir`, sorted (hidden ones included: a temporary would show here).
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

const SCENE: &str = r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[4,0],[0,4]]}]}"#;

/// The new user's scenario: `-o out.png` is fine, `--colors-out` points into a folder
/// that does not exist. Exit code 2, one line naming the bad path, and `out.png`, its
/// legend and every temporary are gone.
#[test]
fn a_failing_render_writes_no_file() {
    let dir = tempdir::Dir::new("outputs-render");
    let scene = dir.path().join("mine.json");
    std::fs::write(&scene, SCENE).unwrap();
    let out = dir.path().join("out.png");
    let bad = dir.path().join("missing").join("x.png");
    let run = bin()
        .args(["render", text(&scene), "-o", text(&out), "--colors-out", text(&bad)])
        .output()
        .unwrap();
    let err = String::from_utf8(run.stderr).unwrap();
    assert_eq!(run.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: ") && err.lines().count() == 1, "{err}");
    assert!(err.contains(&format!("{}: cannot write PNG", bad.display())), "{err}");
    assert!(!out.exists(), "out.png was left behind");
    assert_eq!(names(dir.path()), ["mine.json"], "a temporary or legend was left");

    // An output that already existed keeps its old content.
    std::fs::write(&out, "old").unwrap();
    let run = bin()
        .args(["render", text(&scene), "-o", text(&out), "--colors-out", text(&bad)])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old");
    assert_eq!(names(dir.path()), ["mine.json", "out.png"]);
}

/// A folder as an output, and one path named for two outputs, are bad input too.
#[test]
fn folders_and_repeated_outputs_are_refused() {
    let dir = tempdir::Dir::new("outputs-names");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, SCENE).unwrap();
    let a = dir.path().join("a.png");
    let a_legend = a.with_extension("legend.txt");
    let cases: [(Vec<&str>, String); 3] = [
        (
            vec!["-o", text(dir.path())],
            format!("{}: cannot write PNG: it is a folder", dir.path().display()),
        ),
        (
            vec!["-o", text(&a), "--colors-out", text(&a)],
            format!("{}: named as two outputs", a.display()),
        ),
        (
            vec!["-o", text(&a), "--colors-out", text(&a_legend)],
            "a.legend.txt: named as two outputs".to_string(),
        ),
    ];
    for (args, needle) in cases {
        let run = bin().args(["render", text(&scene)]).args(&args).output().unwrap();
        let err = String::from_utf8(run.stderr).unwrap();
        assert_eq!(run.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(&needle), "{args:?}: {err:?} lacks {needle:?}");
        assert_eq!(names(dir.path()), ["s.json"], "{args:?}");
    }
}

/// A run that succeeds leaves its outputs (the picture, its legend, the colour picture)
/// and nothing else.
#[test]
fn a_successful_render_leaves_exactly_its_outputs() {
    let dir = tempdir::Dir::new("outputs-ok");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, SCENE).unwrap();
    let run = bin()
        .current_dir(dir.path())
        .args(["render", "s.json", "-o", "cov.png", "--colors-out", "col.png"])
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert_eq!(names(dir.path()), ["col.png", "cov.legend.txt", "cov.png", "s.json"]);
}

/// `flood -o` into a folder that does not exist: exit 2, nothing written; into a fine
/// path: the PNG and nothing else.
#[test]
fn flood_writes_all_or_nothing() {
    let dir = tempdir::Dir::new("outputs-flood");
    let input = dir.path().join("in.png");
    image::RgbaImage::from_pixel(3, 2, image::Rgba([0, 0, 0, 255]))
        .save_with_format(&input, image::ImageFormat::Png)
        .unwrap();
    let bad = dir.path().join("missing").join("o.png");
    let run = bin()
        .args(["flood", text(&input), "--at", "0,0", "-o", text(&bad)])
        .output()
        .unwrap();
    let err = String::from_utf8(run.stderr).unwrap();
    assert_eq!(run.status.code(), Some(2), "{err}");
    assert!(err.contains(&format!("{}: cannot write PNG", bad.display())), "{err}");
    assert_eq!(names(dir.path()), ["in.png"]);

    let good = dir.path().join("o.png");
    let run = bin()
        .args(["flood", text(&input), "--at", "0,0", "-o", text(&good)])
        .output()
        .unwrap();
    assert!(run.status.success());
    assert_eq!(names(dir.path()), ["in.png", "o.png"]);
    assert_eq!(
        image::open(&good).unwrap().to_rgba8().get_pixel(2, 1).0,
        [255, 0, 0, 255]
    );
}
