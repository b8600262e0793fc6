//! Scene-file mistakes a new user makes (issue 10), through the command line: a repeated
//! key and a bare `NaN` exit 2 with one line naming the file, the path and the key or
//! position.

use assert_cmd::Command;

use crate::tempdir;

/// `render` and `clip` on `text` saved as `scene.json`: exit 2 and the one stderr line.
fn refused(tag: &str, text: &str) -> (String, String) {
    let dir = tempdir::Dir::new(tag);
    let path = dir.path().join("scene.json");
    std::fs::write(&path, text).unwrap();
    let mut lines = Vec::new();
    for command in ["render", "clip"] {
        let out = Command::cargo_bin("rasterproof")
            .unwrap()
            .args([command, path.to_str().unwrap()])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{command}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{command}: {err}");
        lines.push(err.trim_end().replace(path.to_str().unwrap(), "scene.json"));
    }
    (lines.remove(0), lines.remove(0))
}

#[test]
fn a_repeated_key_names_its_object_and_the_key() {
    let (render, clip) = refused(
        "dup-top",
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[4,0],[0,4]]}], "width": 9}"#,
    );
    assert_eq!(render, r#"error: scene.json: duplicate key "width""#);
    assert_eq!(clip, render);
    let (render, _) = refused(
        "dup-triangle",
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[4,0],[0,4]]}, {"v": [[0,0],[4,0],[0,4]]},
            {"v": [[0,0],[4,0],[0,4]], "v": [[0,0],[2,0],[0,2]]}]}"#,
    );
    assert_eq!(render, r#"error: scene.json: triangles[2]: duplicate key "v""#);
    let (render, _) = refused(
        "dup-clip",
        r#"{"width": 4, "height": 4, "clip": {"convex": [[0,0],[4,0],[0,4]], "convex": [[0,0],[2,0],[0,2]]}}"#,
    );
    assert_eq!(render, r#"error: scene.json: clip: duplicate key "convex""#);
}

/// `{"v": [[0,0],[NaN,0],...` on line 1: `{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[`
/// is 54 bytes (12 + 13 + 16 + 13), so NaN starts at column 55.
#[test]
fn a_bare_nan_says_it_is_not_json_and_what_to_write() {
    let (render, clip) = refused(
        "nan",
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0,0],[NaN,0],[0,4]]}]}"#,
    );
    assert_eq!(
        render,
        "error: scene.json: malformed JSON: expected value at line 1 column 55: NaN is not JSON (JSON has \
         no NaN or infinity); a coordinate is a JSON number or a string holding a decimal or a fraction, \
         e.g. \"1/3\" or \"0.1\", and it must be finite"
    );
    assert_eq!(clip, render);
}

/// A parsed scene always has its target; a hand-built one with a side or subpixel bits
/// out of range gets an error naming the field and its value (not a `None` to unwrap).
#[test]
fn a_hand_built_scene_target_names_the_bad_field() {
    use rasterproof::scene::{parse_scene, Scene};
    let parsed = parse_scene(r#"{"width": 3, "height": 2, "triangles": []}"#, "s.json").unwrap();
    let target = parsed.target().unwrap();
    assert_eq!((target.width, target.height), (3, 2));
    let e = Scene::new(0, 2, vec![]).target().unwrap_err();
    assert_eq!(
        (e.field.as_str(), e.message.as_str()),
        ("width", "0 is outside 1..=16384")
    );
    let e = Scene::new(3, 20_000, vec![]).target().unwrap_err();
    assert_eq!(e.field, "height");
    let mut bits = Scene::new(3, 2, vec![]);
    bits.overrides.subpixel_bits = Some(0);
    let e = bits.target().unwrap_err();
    assert_eq!(
        (e.field.as_str(), e.message.as_str()),
        ("subpixel_bits", "0 is outside 1..=16")
    );
}
