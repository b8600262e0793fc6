//! The comparison as one self-contained HTML page ([`CompareReport::to_html`]): the
//! oracle's image, theirs and the difference side by side, zoomed with sharp pixels and
//! panned together; hover a pixel for both answers, click it for its exact explanation
//! (what the text report prints for it); the summary, the scene and the command that
//! reproduces the comparison. No network: the data and the script are inline.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::report::{CompareReport, EMPTY_COLOUR, MATCHED_COLOUR};
use super::PixelKind;

/// At most this many differing pixels carry their explanation in the page (the first in
/// row order); the others show their kind and answers.
pub const HTML_EXPLAINED_AT_MOST: usize = 20_000;

impl CompareReport {
    /// The page (see the module docs). `scene` and `theirs` name the files as the text
    /// report does, `scene_json` is the scene file's text and `command` the command line
    /// that reproduces the comparison.
    ///
    /// A pixel can also be chosen from the address: `REPORT.html#pixel=X,Y` clicks pixel
    /// (X, Y) of the difference view once the page has loaded (a link to one pixel, and
    /// what the browser test uses).
    pub fn to_html(&self, scene: &str, theirs: &str, scene_json: &str, command: &str) -> String {
        let title = format!("rasterproof compare: {theirs} against {scene}");
        let mut body = format!("<h1>{}</h1>\n", escape(&title));
        body.push_str(&self.html_views(""));
        let _ = writeln!(
            body,
            "<details open><summary>Summary</summary><pre id=\"summary\">{}</pre></details>",
            escape(&self.to_text(scene, theirs, 0))
        );
        let _ = writeln!(
            body,
            "<details><summary>The scene</summary><pre id=\"scene\">{}</pre></details>",
            escape(scene_json)
        );
        let _ = writeln!(
            body,
            "<p>Reproduce: <code id=\"command\">{}</code></p>",
            escape(command)
        );
        html_page(&title, &body)
    }

    /// The interactive part of a page: the headline, the zoom controls, the three views,
    /// the legend, the hovered pixel and the chosen pixel's explanation, with the data
    /// they draw from; element ids end in `suffix` (several on one page: a hunt's
    /// findings).
    pub fn html_views(&self, suffix: &str) -> String {
        let headline = if self.identical() {
            "identical".to_string()
        } else {
            self.headline()
                .unwrap_or_else(|| format!("{} pixels differ", self.pixels.len()))
        };
        view_block(suffix, &headline, &self.html_data())
    }

    /// What the views draw: per pixel the oracle's first owner + 1 (0: none) and
    /// theirs (a mask's covered pixel is the largest u32), the pixels with several
    /// owners, the difference view's colour index (0 neither, 1 matched, 2 + kind), the
    /// palette, and each differing pixel's explanation.
    fn html_data(&self) -> Value {
        let n = usize::try_from(u64::from(self.width) * u64::from(self.height)).expect("a canvas fits memory");
        let index =
            |x: u32, y: u32| usize::try_from(u64::from(y) * u64::from(self.width) + u64::from(x)).expect("fits");
        let mut ours = vec![0u32; n];
        let mut several = Vec::new();
        let mut diff = vec![0u8; n];
        for (x, y, ids) in self.ours.iter() {
            ours[index(x, y)] = ids[0] + 1;
            if ids.len() > 1 {
                several.push(index(x, y));
            }
            diff[index(x, y)] = 1;
        }
        let mut theirs_px = ours.clone();
        // Theirs agrees with the oracle but where it differs: there, its own mark.
        let mut theirs_marked = vec![false; n];
        for &i in &several {
            theirs_marked[i] = true;
        }
        let mut explain = serde_json::Map::new();
        for (k, p) in self.pixels.iter().enumerate() {
            let i = index(p.x, p.y);
            let kind = PixelKind::ALL.iter().position(|&c| c == p.kind).expect("a kind");
            diff[i] = u8::try_from(2 + kind).expect("few kinds");
            theirs_px[i] = match (p.theirs.covered, p.theirs.ids.first()) {
                (false, _) => 0,
                (true, Some(id)) => id + 1,
                (true, None) => u32::MAX,
            };
            theirs_marked[i] = p.theirs.several;
            let text = if k < HTML_EXPLAINED_AT_MOST {
                self.pixel_text(p)
            } else {
                format!(
                    "({}, {}) {} (not explained in the page: compare --limit prints more)\n",
                    p.x,
                    p.y,
                    p.kind.name()
                )
            };
            explain.insert(format!("{},{}", p.x, p.y), Value::String(text));
        }
        let theirs_several: Vec<usize> = (0..n).filter(|&i| theirs_marked[i]).collect();
        let palette: Vec<String> = std::iter::once(EMPTY_COLOUR)
            .chain(std::iter::once(MATCHED_COLOUR))
            .chain(PixelKind::ALL.iter().map(|k| k.colour()))
            .map(|c| format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]))
            .collect();
        let kinds: Vec<&str> = ["neither covers it", "matched"]
            .into_iter()
            .chain(PixelKind::ALL.iter().map(|k| k.name()))
            .collect();
        json!({
            "width": self.width,
            "height": self.height,
            "ours": ours,
            "ours_several": several,
            "theirs": theirs_px,
            "theirs_several": theirs_several,
            "diff": diff,
            "palette": palette,
            "kinds": kinds,
            "explain": explain,
        })
    }
}

/// The interactive part of a page ([`CompareReport::html_views`]): the headline, the zoom
/// controls, the three views (the oracle, theirs, the difference), the legend, the hovered
/// pixel and the chosen pixel's explanation, drawn from `data`; element ids end in
/// `suffix`. `data` holds `width`, `height`, `ours` and `theirs` (a value per pixel, row
/// by row), `diff` (an index into `palette` and `kinds` per pixel) and `explain` (`"X,Y"`
/// to its text); and, to read the values: `ours_several`/`theirs_several` (pixels with
/// several owners) for owner ids + 1, or `levels` (the top level) for grey levels, or
/// `ours_labels`/`theirs_labels` (a word per value), or `range` (`[least, greatest]`:
/// values, `null` where there is none, drawn in grey on that scale).
pub fn view_block(suffix: &str, headline: &str, data: &Value) -> String {
    let data = data.to_string().replace("</", "<\\/"); // "</" would end the <script>
    let mut out = format!("<div class=\"compare\" data-suffix=\"{suffix}\">\n");
    let _ = writeln!(
        out,
        "<p class=\"headline\" id=\"headline{suffix}\">{}</p>",
        escape(headline)
    );
    out.push_str(
        "<div class=\"controls\">zoom <button data-role=\"zoom-out\" title=\"zoom out (-)\">&minus;</button> \
         <span data-role=\"zoom\"></span> <button data-role=\"zoom-in\" title=\"zoom in (+)\">+</button> \
         <span class=\"hint\">scroll to pan (the three views move together); hover a pixel for both answers, \
         click it for its explanation</span></div>\n<div class=\"views\">\n",
    );
    for (role, caption) in [
        ("ours", "the oracle (exact)"),
        ("theirs", "theirs"),
        ("diff", "the difference"),
    ] {
        let _ = writeln!(
            out,
            "<figure><figcaption>{caption}</figcaption><div class=\"pane\"><canvas data-role=\"{role}\" id=\"{role}{suffix}\"></canvas></div></figure>"
        );
    }
    let _ = writeln!(
        out,
        "</div>\n<div class=\"legend\" data-role=\"legend\"></div>\n<p data-role=\"hover\">&nbsp;</p>\n\
         <section class=\"pixel\"><h2 data-role=\"pixel-title\" id=\"pixel-title{suffix}\">No pixel chosen</h2>\
         <pre data-role=\"explanation\" id=\"explanation{suffix}\">Click a differing pixel.</pre></section>\n\
         <script type=\"application/json\" data-role=\"data\">{data}</script>\n</div>"
    );
    out
}

/// A whole page: `title`, the style, `body` (with its views' data) and the script that
/// brings every view block of it to life.
pub fn html_page(title: &str, body: &str) -> String {
    format!(
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{body}<script>{SCRIPT}</script>\n</body>\n</html>\n",
        escape(title)
    )
}

/// `text` with `&`, `<`, `>` and `"` escaped for HTML.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

const STYLE: &str = r#"
body { font: 14px system-ui, sans-serif; margin: 1em 2em; background: #fafafa; color: #222; }
h1 { font-size: 1.2em; } h2 { font-size: 1.05em; margin: 0.3em 0; }
.headline { font-weight: 600; }
.views { display: flex; gap: 1em; flex-wrap: wrap; }
figure { margin: 0; } figcaption { font-weight: 600; margin-bottom: 0.3em; }
.pane { width: 420px; height: 420px; overflow: auto; border: 1px solid #999; background: #000; position: relative; }
.marker { position: absolute; box-sizing: border-box; border: 2px solid #00e5ff; outline: 1px solid #000; pointer-events: none; display: none; }
canvas { image-rendering: pixelated; image-rendering: crisp-edges; display: block; cursor: crosshair; }
.legend span { display: inline-block; margin-right: 1em; }
.legend i { display: inline-block; width: 0.9em; height: 0.9em; margin-right: 0.3em; vertical-align: middle; border: 1px solid #666; }
.pixel { border: 1px solid #bbb; background: #fff; padding: 0.5em 1em; margin: 0.5em 0; }
pre { white-space: pre-wrap; font: 12px ui-monospace, monospace; }
.hint { color: #666; font-size: 0.9em; }
table { border-collapse: collapse; margin: 0.8em 0; background: #fff; }
caption { text-align: left; font-weight: 600; padding: 0.3em 0; }
th, td { border: 1px solid #ccc; padding: 2px 8px; text-align: left; vertical-align: top; }
td i { display: inline-block; width: 0.9em; height: 0.9em; border: 1px solid #666; vertical-align: middle; }
td.num { font: 12px ui-monospace, monospace; white-space: nowrap; }
td.exact { font: 12px ui-monospace, monospace; word-break: break-all; max-width: 40em; }
tr.off td.class { color: #b00; font-weight: 600; }
"#;

const SCRIPT: &str = r#"
"use strict";
function idColour(v) {
  if (v === 0) return [0, 0, 0];
  if (v === 4294967295) return [255, 255, 255];
  const h = (v * 0.61803398875) % 1, s = 0.65, l = 0.55;
  const f = n => { const k = (n + h * 12) % 12; return l - s * Math.min(l, 1 - l) * Math.max(-1, Math.min(k - 3, 9 - k, 1)); };
  return [f(0), f(8), f(4)].map(c => Math.round(c * 255));
}
function hex(c) { const n = parseInt(c.slice(1), 16); return [n >> 16, (n >> 8) & 255, n & 255]; }
function setup(block) {
  const role = r => block.querySelector('[data-role="' + r + '"]');
  const D = JSON.parse(role("data").textContent);
  const W = D.width, H = D.height;
  const views = ["ours", "theirs", "diff"].map(role);
  function paint(canvas, colourAt, several) {
    canvas.width = W; canvas.height = H;
    const ctx = canvas.getContext("2d");
    const img = ctx.createImageData(W, H);
    for (let i = 0; i < W * H; i++) {
      const c = colourAt(i);
      img.data[4 * i] = c[0]; img.data[4 * i + 1] = c[1]; img.data[4 * i + 2] = c[2]; img.data[4 * i + 3] = 255;
    }
    for (const i of several || []) { img.data[4 * i] = 255; img.data[4 * i + 1] = 255; img.data[4 * i + 2] = 255; }
    ctx.putImageData(img, 0, 0);
  }
  const palette = D.palette.map(hex);
  const top = D.levels, range = D.range;
  const scaled = v => { const g = Math.round(48 + 207 * Math.min(1, Math.max(0, (v - range[0]) / ((range[1] - range[0]) || 1)))); return [g, g, g]; };
  const colourOf = range ? (v => v === null ? [0, 0, 0] : scaled(v)) : top ? (v => { const g = Math.round(v * 255 / top); return [g, g, g]; }) : idColour;
  const oursSeveral = D.ours_several || [], theirsSeveral = D.theirs_several || [];
  paint(views[0], i => colourOf(D.ours[i]), oursSeveral);
  paint(views[1], i => colourOf(D.theirs[i]), theirsSeveral);
  paint(views[2], i => palette[D.diff[i]]);
  D.kinds.forEach((k, j) => {
    const span = document.createElement("span");
    const swatch = document.createElement("i");
    swatch.style.background = D.palette[j];
    span.append(swatch, k);
    role("legend").append(span);
  });
  if (!top && !range && !D.ours_labels) {
    const several = document.createElement("span");
    several.textContent = "(white in the first two views: two or more owners)";
    role("legend").append(several);
  }
  let zoom = Math.max(1, Math.min(32, Math.floor(400 / Math.max(W, H))));
  let chosen = null;
  const markers = views.map(c => { const m = document.createElement("div"); m.className = "marker"; c.parentElement.append(m); return m; });
  function placeMarkers() {
    if (!chosen) return;
    for (const m of markers) {
      const side = Math.max(zoom, 4);
      m.style.display = "block";
      m.style.left = (chosen[0] * zoom + zoom / 2 - side / 2 - 2) + "px"; m.style.top = (chosen[1] * zoom + zoom / 2 - side / 2 - 2) + "px";
      m.style.width = (side + 4) + "px"; m.style.height = (side + 4) + "px";
    }
  }
  function setZoom(z) {
    zoom = Math.max(1, Math.min(64, z));
    for (const c of views) {
      c.style.width = (W * zoom) + "px"; c.style.height = (H * zoom) + "px";
      // A pane no larger than its image (scroll bars aside), at most 420 px.
      c.parentElement.style.width = Math.min(420, W * zoom + 16) + "px";
      c.parentElement.style.height = Math.min(420, H * zoom + 16) + "px";
    }
    role("zoom").textContent = zoom + "x";
    placeMarkers();
  }
  setZoom(zoom);
  role("zoom-in").onclick = () => setZoom(zoom * 2);
  role("zoom-out").onclick = () => setZoom(Math.floor(zoom / 2));
  block.tabIndex = 0;
  block.addEventListener("keydown", e => { if (e.key === "+") setZoom(zoom * 2); if (e.key === "-") setZoom(Math.floor(zoom / 2)); });
  const panes = views.map(c => c.parentElement);
  let syncing = false;
  for (const p of panes) p.addEventListener("scroll", () => {
    if (syncing) return;
    syncing = true;
    for (const q of panes) if (q !== p) { q.scrollLeft = p.scrollLeft; q.scrollTop = p.scrollTop; }
    syncing = false;
  });
  function pixelAt(canvas, e) {
    const r = canvas.getBoundingClientRect();
    const x = Math.floor((e.clientX - r.left) / r.width * W), y = Math.floor((e.clientY - r.top) / r.height * H);
    return (x >= 0 && y >= 0 && x < W && y < H) ? [x, y] : null;
  }
  function owners(v, several) { return v === 0 ? "none" : v === 4294967295 ? "covered" : "id " + (v - 1) + (several ? " and more" : ""); }
  function value(v, several, labels) {
    if (range) return v === null ? "not judged" : String(v);
    return labels ? labels[v] : top ? "level " + v : owners(v, several);
  }
  function describe(x, y) {
    const i = y * W + x;
    return "(" + x + ", " + y + ") " + D.kinds[D.diff[i]] + ": oracle " + value(D.ours[i], oursSeveral.includes(i), D.ours_labels) +
      ", theirs " + value(D.theirs[i], theirsSeveral.includes(i), D.theirs_labels);
  }
  function choose(x, y) {
    chosen = [x, y];
    placeMarkers();
    role("pixel-title").textContent = "Pixel (" + x + ", " + y + ")";
    role("explanation").textContent = D.explain[x + "," + y] || (describe(x, y) + "\n(the same in both images: nothing to explain)");
  }
  for (const c of views) {
    c.addEventListener("mousemove", e => { const p = pixelAt(c, e); role("hover").textContent = p ? describe(p[0], p[1]) : "\u00a0"; });
    c.addEventListener("click", e => { const p = pixelAt(c, e); if (p) choose(p[0], p[1]); });
  }
  // A click at pixel (x, y), as a person's would be: whole CSS pixels, the first inside it.
  block.clickPixel = (x, y) => {
    const c = views[2], p = c.parentElement;
    p.scrollLeft = x * zoom - p.clientWidth / 2; p.scrollTop = y * zoom - p.clientHeight / 2;
    const r = c.getBoundingClientRect();
    c.dispatchEvent(new MouseEvent("click", { clientX: Math.ceil(r.left + x * zoom), clientY: Math.ceil(r.top + y * zoom), bubbles: true }));
  };
}
const blocks = Array.from(document.querySelectorAll(".compare"));
blocks.forEach(setup);
// #pixel=X,Y clicks pixel (X, Y) of the first block; #finding=NN&pixel=X,Y of finding NN's,
// #sample=S&pixel=X,Y of sample index S's.
const m = /^#(?:(?:finding|sample)=(\d+)&)?pixel=(\d+),(\d+)$/.exec(location.hash);
if (m) {
  const block = m[1] ? document.querySelector('.compare[data-suffix="-' + m[1] + '"]') : blocks[0];
  if (block) {
    const folded = block.closest("details");
    if (folded) folded.open = true;
    (block.closest("section") || folded || block).scrollIntoView();
    block.clickPixel(+m[2], +m[3]);
  }
}
"#;
