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

/// `rasterproof ARGS` (strings).
fn run(args: &[&str]) -> (i32, String) {
    let os: Vec<&std::ffi::OsStr> = args.iter().map(std::ffi::OsStr::new).collect();
    rasterproof(&os)
}

/// `rasterproof compare ARGS --html PAGE --format json`, which finds a difference (exit
/// 1): its JSON report.
fn compare_with_page(args: &[&str], page: &Path) -> serde_json::Value {
    let mut all = vec!["compare"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--html", page.to_str().unwrap(), "--format", "json"]);
    let (code, json) = run(&all);
    assert_eq!(code, 1, "{json}");
    serde_json::from_str(&json).unwrap()
}

/// `compare --as grey --html`: the page shows the levels judged against and theirs, and a
/// click on a differing pixel (its first, from the JSON report) shows that pixel's line of
/// the text report and what its class means; the headline names the method that gives
/// every level. Their image: rasterproof's own levels truncated, judged under rounding.
#[test]
fn a_grey_page_explains_a_pixels_class() {
    let dir = tempdir::Dir::new("html-grey");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/glyph.json");
    let scene = scene.to_str().unwrap();
    let theirs = dir.path().join("truncated.png");
    let theirs = theirs.to_str().unwrap();
    let (code, _) = run(&[
        "render",
        scene,
        "--coverage",
        "area",
        "--quantization",
        "truncate",
        "--grey-out",
        theirs,
    ]);
    assert_eq!(code, 0);
    let page = dir.path().join("grey.html");
    let report = compare_with_page(&[scene, theirs, "--as", "grey"], &page);
    let first = &report["pixels"][0];
    let (x, y) = (first["x"].as_u64().unwrap(), first["y"].as_u64().unwrap());
    assert_eq!(first["class"], "quantization");
    let (_, text) = run(&["compare", scene, theirs, "--as", "grey"]);
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("({x}, {y}): ")))
        .expect("the pixel's line")
        .trim();
    let html = std::fs::read_to_string(&page).unwrap();
    for fetch in ["src=\"http", "href=\"http", "src=\"//", "@import"] {
        assert!(!html.contains(fetch), "the page fetches something: {fetch}");
    }
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation");
    assert!(shown.starts_with(line), "{shown}\nnot starting with\n{line}");
    assert!(
        shown.contains("quantization: their level is another legal rounding"),
        "{shown}"
    );
    assert!(
        shown.contains("Judged against its exact true coverage quantized by round"),
        "{shown}"
    );
    let headline = text_of(&after, "headline");
    assert!(
        headline.contains("give every level of their image") && headline.contains("--method exact-true-truncate"),
        "{headline}"
    );
    // A pixel whose levels agree says so.
    let at = dom(&browser, &page, "#pixel=0,0");
    assert!(text_of(&at, "explanation").contains("nothing to explain"));
}

/// `compare --samples 4 --html`: one block per sample index; their image has sample 2
/// at (1/8, 1/2) instead of (1/8, 5/8), so sample 2's block is the one that differs, and
/// `#sample=2&pixel=X,Y` (its first differing pixel, from the JSON report) shows that
/// pixel's explanation in sample 2's frame, the text report's words, while the other
/// indices' blocks choose nothing.
#[test]
fn a_sample_page_explains_a_pixel_of_one_sample_index() {
    let dir = tempdir::Dir::new("html-samples");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/fine-mesh.json");
    let mut moved: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&scene).unwrap()).unwrap();
    moved["samples"] = serde_json::json!([["3/8", "1/8"], ["7/8", "3/8"], ["1/8", "1/2"], ["5/8", "7/8"]]);
    let moved_path = dir.path().join("moved.json");
    std::fs::write(&moved_path, moved.to_string()).unwrap();
    let theirs = dir.path().join("moved.png");
    let (scene, theirs) = (scene.to_str().unwrap(), theirs.to_str().unwrap());
    let (code, _) = run(&["render", moved_path.to_str().unwrap(), "--ids-out", theirs]);
    assert_eq!(code, 0);
    let page = dir.path().join("samples.html");
    let report = compare_with_page(&[scene, theirs, "--samples", "4"], &page);
    for s in [0, 1, 3] {
        assert_eq!(
            report["samples"][s]["report"]["pixels"].as_array().unwrap().len(),
            0,
            "sample {s}"
        );
    }
    let first = &report["samples"][2]["report"]["pixels"][0];
    let (x, y) = (first["x"].as_u64().unwrap(), first["y"].as_u64().unwrap());
    let (_, text) = run(&["compare", scene, theirs, "--samples", "4", "--limit", "1"]);
    let expected = &text[text
        .find(&format!("({x}, {y}) "))
        .expect("the pixel in the text report")..];
    let expected = &expected[..expected.find("\nsample 3").unwrap_or(expected.len())];
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#sample=2&pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title-2"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation-2");
    assert!(shown.starts_with(&format!("({x}, {y}) ")), "{shown}");
    // The text report indents each sample's comparison; the page shows it unindented.
    let unindented: Vec<&str> = expected.lines().map(|l| l.strip_prefix("  ").unwrap_or(l)).collect();
    assert_eq!(shown.trim_end(), unindented.join("\n").trim_end());
    assert_eq!(text_of(&after, "pixel-title-0"), "No pixel chosen");
    assert!(after.contains("id=\"sample-2\" open"), "sample 2's block is open");
    assert!(
        !after.contains("id=\"sample-0\" open"),
        "identical sample 0's block is closed"
    );
}

/// `compare --conservative vulkan --html`: a one-sample image judged as conservative
/// rasterization misses the pixels its triangles touch without covering their centre;
/// the first missing pixel (from the JSON report) is explained with the triangles that
/// require it, as the text report says.
#[test]
fn a_conservative_page_explains_a_missing_pixel() {
    let dir = tempdir::Dir::new("html-conservative");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/tie-grid.json");
    let theirs = dir.path().join("one-sample.png");
    let (scene, theirs) = (scene.to_str().unwrap(), theirs.to_str().unwrap());
    let (code, _) = run(&["render", scene, "--ids-out", theirs]);
    assert_eq!(code, 0);
    let page = dir.path().join("conservative.html");
    let report = compare_with_page(&[scene, theirs, "--conservative", "vulkan"], &page);
    let first = &report["missing"][0];
    let (x, y) = (first[0].as_u64().unwrap(), first[1].as_u64().unwrap());
    let ids = first[2].as_array().unwrap();
    assert!(!ids.is_empty());
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation");
    let ids: Vec<String> = ids.iter().map(ToString::to_string).collect();
    assert_eq!(
        shown.trim_end(),
        format!(
            "({x}, {y}) missing: triangles [{}] overlap the pixel's square, so it must be covered",
            ids.join(", ")
        )
    );
    assert!(
        text_of(&after, "headline").starts_with(&format!("{} missing", report["missing"].as_array().unwrap().len()))
    );
}

/// `hunt --as grey --out DIR` writes `DIR/index.html` (every finding's views, as `compare
/// --as grey --html` draws them) and each finding's `.rs`. Against rasterproof's own levels
/// truncated, judged under rounding: the page opened at `#finding=01&pixel=X,Y` (finding
/// 01's first pixel, from its `.txt`) explains that pixel with its `.txt` line, and the
/// `.rs` asserts at each such pixel the level of its exact value rounded (checked here
/// from the exact fraction it quotes).
#[test]
fn a_grey_hunts_index_and_tests() {
    let dir = tempdir::Dir::new("html-grey-hunt");
    let exe = assert_cmd::cargo::cargo_bin("rasterproof");
    let cmd = format!(
        "{} render {{scene}} --coverage area --quantization truncate --grey-out {{out}}",
        exe.display()
    );
    let out = dir.path().join("found");
    let (code, _) = run(&[
        "hunt",
        "--as",
        "grey",
        "--cmd",
        &cmd,
        "--cases",
        "6",
        "--canvas",
        "6",
        "--shrink-runs",
        "20",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    let txt = std::fs::read_to_string(out.join("finding-01.txt")).unwrap();
    let line = txt
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with('(') && l.contains("): theirs "))
        .expect("a pixel line");
    let (x, y) = line[1..line.find(')').unwrap()].split_once(", ").unwrap();
    let test = std::fs::read_to_string(out.join("finding-01.rs")).unwrap();
    assert!(
        test.contains("#[test]\nfn grey_hunt_finding_01_quantization_under()"),
        "{test}"
    );
    let asserts: Vec<&str> = test
        .lines()
        .filter(|l| l.trim_start().starts_with("assert_eq!(levels["))
        .collect();
    assert!(!asserts.is_empty(), "{test}");
    for a in asserts {
        // assert_eq!(levels[I], L); // (x, y): exact N/D; theirs T (class)
        let level: u32 = a[a.find("], ").unwrap() + 3..a.find(");").unwrap()].parse().unwrap();
        let after_exact = &a[a.find("exact ").unwrap() + "exact ".len()..];
        let exact = &after_exact[..after_exact.find(';').unwrap()];
        let (n, d) = exact.split_once('/').unwrap_or((exact, "1"));
        let (n, d): (u64, u64) = (n.parse().unwrap(), d.parse().unwrap());
        // Round half to even of n/d x 255.
        let (q, r) = ((n * 255) / d, (n * 255) % d);
        let rounded = if 2 * r > d || (2 * r == d && q % 2 == 1) {
            q + 1
        } else {
            q
        };
        assert_eq!(u64::from(level), rounded, "{a}");
    }
    let page = out.join("index.html");
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, &format!("#finding=01&pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title-01"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation-01");
    assert!(shown.starts_with(line), "{shown}\nnot starting with\n{line}");
}

/// `compare --as values --html` on a real renderer's output (the committed lavapipe
/// finding, a smooth centroid varying under 4x: three samples of pixel (1, 0) divided at
/// the wrong point): the counts table names each class, sample indices with a value off
/// are open, and `#sample=1&pixel=1,0` shows that sample's line of the text report, what
/// its class means and the `explain` command that derives it. A one-sample page (the
/// affine values of a smooth varying) explains its first pixel the same way.
#[test]
fn a_values_page_explains_a_pixels_class() {
    let dir = tempdir::Dir::new("html-values");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/fixtures/wgpu-lavapipe-values");
    let scene = root.join("01-w-at-centre-smooth-centroid-4x.json");
    let theirs = root.join("01-w-at-centre-smooth-centroid-4x.tiff");
    let (scene, theirs) = (scene.to_str().unwrap(), theirs.to_str().unwrap());
    let page = dir.path().join("values.html");
    let report = compare_with_page(&[scene, theirs], &page);
    assert_eq!(report["counts"]["w-at-centre"], 3);
    let html = std::fs::read_to_string(&page).unwrap();
    for fetch in ["src=\"http", "href=\"http", "src=\"//", "@import"] {
        assert!(!html.contains(fetch), "the page fetches something: {fetch}");
    }
    assert!(html.contains("<td class=\"class\">w-at-centre</td><td class=\"num\">3</td>"));
    let (_, text) = run(&["compare", scene, theirs, "--limit", "10"]);
    let line = text
        .lines()
        .find(|l| l.starts_with("  (1, 0) sample 1 "))
        .expect("sample 1 of pixel (1, 0) in the text report")
        .trim();
    let Some(browser) = chromium() else { return };
    let after = dom(&browser, &page, "#sample=1&pixel=1,0");
    assert_eq!(text_of(&after, "pixel-title-1"), "Pixel (1, 0)");
    let shown = text_of(&after, "explanation-1");
    assert!(
        shown.starts_with(&format!("{line}\n\nw-at-centre: a smooth value divided")),
        "{shown}"
    );
    assert!(shown.contains("rasterproof explain "), "{shown}");
    assert_eq!(text_of(&after, "pixel-title-0"), "No pixel chosen");
    assert!(after.contains("id=\"sample-1\" open"), "sample 1 has a value off");
    assert!(!after.contains("id=\"sample-3\" open"), "sample 3 has none");

    let smooth = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/values-smooth.json");
    let smooth_text = std::fs::read_to_string(&smooth).unwrap();
    let affine_scene = dir.path().join("noperspective.json");
    std::fs::write(&affine_scene, smooth_text.replace("\"smooth\"", "\"noperspective\"")).unwrap();
    let affine = dir.path().join("affine.tiff");
    let (code, _) = run(&[
        "render",
        affine_scene.to_str().unwrap(),
        "--values-out",
        affine.to_str().unwrap(),
    ]);
    assert_eq!(code, 0);
    let page = dir.path().join("affine.html");
    let smooth = smooth.to_str().unwrap();
    let report = compare_with_page(&[smooth, affine.to_str().unwrap()], &page);
    let first = &report["pixels"][0];
    assert_eq!(first["class"], "affine");
    let (x, y) = (first["x"].as_u64().unwrap(), first["y"].as_u64().unwrap());
    let after = dom(&browser, &page, &format!("#pixel={x},{y}"));
    assert_eq!(text_of(&after, "pixel-title"), format!("Pixel ({x}, {y})"));
    let shown = text_of(&after, "explanation");
    assert!(
        shown.starts_with(&format!("({x}, {y}) primitive ")) && shown.contains("affine: the screen-linear value"),
        "{shown}"
    );
}
