//! `compare --html`: one self-contained page, tested in a real headless browser (Debian's
//! `chromium`, which `.ci/run` installs): the page is loaded with `#pixel=X,Y`, which
//! clicks pixel (X, Y) of the difference view, and the explanation is read back from the
//! DOM the browser dumps; it must be the text report's for that pixel.

use std::path::Path;
use std::process::Command;

use crate::tempdir;

/// The browser, or `None` (a skip, except under CI, where it is a failure).
fn chromium() -> Option<String> {
    for name in ["chromium", "chromium-browser", "google-chrome"] {
        if Command::new(name)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
        {
            return Some(name.to_string());
        }
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: no chromium (apt install chromium)"
    );
    eprintln!("skipped: no chromium on PATH (apt install chromium)");
    None
}

fn rasterproof(args: &[&std::ffi::OsStr]) -> (i32, String) {
    let out = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// The DOM after the page's scripts ran, with the page opened at `fragment`.
fn dom(browser: &str, page: &Path, fragment: &str) -> String {
    let url = format!("file://{}{fragment}", page.display());
    let out = Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--dump-dom", &url])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The text of the element with `id` in `html` (its children's tags removed, entities
/// decoded: enough for the page's plain-text elements).
fn text_of(html: &str, id: &str) -> String {
    let start = html.find(&format!("id=\"{id}\"")).unwrap_or_else(|| panic!("no #{id}"));
    let open_end = start + html[start..].find('>').unwrap() + 1;
    let close = open_end + html[open_end..].find("</").unwrap();
    html[open_end..close]
        .replace("&gt;", ">")
        .replace("&lt;", "<")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

#[test]
fn a_click_on_a_pixel_shows_its_explanation() {
    let dir = tempdir::Dir::new("html-report");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/tie-grid.json");
    // Theirs: this crate's image under the gl preset (bottom-left ties) against the d3d11
    // oracle (top-left): ties differ.
    let theirs = dir.path().join("gl.png");
    let (code, _) = rasterproof(&[
        "render".as_ref(),
        scene.as_os_str(),
        "--preset".as_ref(),
        "gl".as_ref(),
        "--ids-out".as_ref(),
        theirs.as_os_str(),
    ]);
    assert_eq!(code, 0);
    let page = dir.path().join("report.html");
    let (code, json) = rasterproof(&[
        "compare".as_ref(),
        scene.as_os_str(),
        theirs.as_os_str(),
        "--html".as_ref(),
        page.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    assert_eq!(code, 1);
    let report: serde_json::Value = serde_json::from_str(&json).unwrap();
    let first = &report["pixels"][0];
    let (x, y) = (first["x"].as_u64().unwrap(), first["y"].as_u64().unwrap());
    let html = std::fs::read_to_string(&page).unwrap();
    // Self-contained: nothing is fetched.
    for fetch in ["src=\"http", "href=\"http", "src=\"//", "@import"] {
        assert!(!html.contains(fetch), "the page fetches something: {fetch}");
    }
    // The text report's words for that pixel (its first line names it).
    let (_, text) = rasterproof(&[
        "compare".as_ref(),
        scene.as_os_str(),
        theirs.as_os_str(),
        "--limit".as_ref(),
        "1".as_ref(),
    ]);
    let expected = &text[text
        .find(&format!("({x}, {y}) "))
        .expect("the first pixel in the text report")..];
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation");
    assert!(shown.contains("tie: the sample lies on edge"), "{shown}");
    assert_eq!(
        shown.trim_end(),
        expected.trim_end(),
        "the page's explanation is the text report's"
    );
    // Without a fragment nothing is chosen.
    let before = dom(&browser, &page, "");
    assert_eq!(text_of(&before, "pixel-title"), "No pixel chosen");
    // A pixel both agree on says so.
    let matched = report["pixels"]
        .as_array()
        .unwrap()
        .iter()
        .all(|p| (p["x"].as_u64(), p["y"].as_u64()) != (Some(9), Some(9)));
    assert!(matched);
    let at = dom(&browser, &page, "#pixel=9,9");
    assert!(text_of(&at, "explanation").contains("nothing to explain"));
}

/// `hunt --out DIR` writes `DIR/index.html`, every finding in one page: opened at
/// `#finding=01&pixel=X,Y` (the first differing pixel of finding 01's minimal scene, read
/// from `finding-01.txt`), finding 01's explanation is that pixel's in its `.txt`, and the
/// other findings' are untouched.
#[test]
fn a_hunts_index_explains_a_findings_pixel() {
    let dir = tempdir::Dir::new("html-hunt");
    let exe = assert_cmd::cargo::cargo_bin("rasterproof");
    let cmd = format!("{} render {{scene}} --subpixel-bits 4 --ids-out {{out}}", exe.display());
    let out = dir.path().join("found");
    let (code, _) = rasterproof(&[
        "hunt".as_ref(),
        "--cmd".as_ref(),
        cmd.as_ref(),
        "--cases".as_ref(),
        "12".as_ref(),
        "--shrink-runs".as_ref(),
        "20".as_ref(),
        "--quiet".as_ref(),
        "--out".as_ref(),
        out.as_os_str(),
    ]);
    assert_eq!(code, 1);
    let page = out.join("index.html");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("id=\"finding-01\""));
    for fetch in ["src=\"http", "href=\"http", "src=\"//"] {
        assert!(!html.contains(fetch), "the page fetches something: {fetch}");
    }
    let txt = std::fs::read_to_string(out.join("finding-01.txt")).unwrap();
    let list = &txt[txt.find("differing pixels:\n").expect("a pixel list") + "differing pixels:\n".len()..];
    let coords = &list[1..list.find(')').unwrap()];
    let (x, y) = coords.split_once(", ").unwrap();
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#finding=01&pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title-01"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation-01");
    assert!(shown.starts_with(&format!("({x}, {y}) ")), "{shown}");
    assert!(txt.contains(shown.trim_end()), "{shown}\nnot in\n{txt}");
    if after.contains("id=\"pixel-title-02\"") {
        assert_eq!(text_of(&after, "pixel-title-02"), "No pixel chosen");
    }
}
