//! A hunt's findings as one self-contained HTML page ([`HuntReport::to_html`], what `hunt
//! --out DIR` writes as `DIR/index.html`): the summary, then each finding with the oracle's
//! image, theirs and the difference of its minimal scene (zoom, pan, each pixel's
//! explanation on click, as `compare --html`), or the renderer's failure, and the minimal
//! scene, how to reproduce it and the ready-to-paste test.

use std::fmt::Write as _;

use super::report::{HuntFinding, HuntReport};
use super::test_text::rust_test;
use super::verdict::HuntVerdict;
use crate::model::Model;
use crate::oracle::compare::{html_escape as escape, html_page};

impl HuntReport {
    /// The page. `renderer` is the hunted command as the user gave it (`--cmd` with its
    /// `{scene}` and `{out}`, or `--serve`). `index.html#finding=NN&pixel=X,Y` opens it
    /// with pixel (X, Y) of finding NN chosen.
    pub fn to_html(&self, renderer: &str) -> String {
        let title = format!("rasterproof hunt: {renderer}");
        let mut body = format!("<h1>{}</h1>\n", escape(&title));
        let _ = writeln!(body, "<pre id=\"summary\">{}</pre>", escape(&self.to_text(None)));
        for (k, f) in self.findings.iter().enumerate() {
            body.push_str(&finding_html(f, k + 1, renderer, self.config.model));
        }
        if self.findings.is_empty() {
            body.push_str("<p>Nothing found.</p>\n");
        }
        html_page(&title, &body)
    }
}

/// One finding's section.
fn finding_html(f: &HuntFinding, n: usize, renderer: &str, model: Model) -> String {
    let nn = format!("{n:02}");
    let mut s = format!("<section class=\"finding\" id=\"finding-{nn}\">\n");
    let _ = writeln!(
        s,
        "<h2>finding {nn}: {}{}</h2>\n<p>first in case {}, {} cases; shrunk in {} steps, {} renderer calls, to {}x{} px</p>",
        escape(&f.signature.describe()),
        escape(&f.kinds_text()),
        f.case,
        f.cases,
        f.runs,
        f.renderer_calls,
        f.minimal.width,
        f.minimal.height
    );
    match &f.verdict {
        HuntVerdict::Differs(r) => s.push_str(&r.html_views(&format!("-{nn}"))),
        HuntVerdict::DiffersPerSample(r) => {
            for (k, one) in r.samples.iter().enumerate().filter(|(_, one)| !one.identical()) {
                let _ = writeln!(
                    s,
                    "<p>sample {k} at {} (the scene moved by ({}, {}), this sample at the pixel centre):</p>",
                    escape(&r.pattern.position_text(k)),
                    escape(&r.moved_by[k][0]),
                    escape(&r.moved_by[k][1])
                );
                s.push_str(&one.html_views(&format!("-{nn}-s{k}")));
            }
        }
        HuntVerdict::Failed(failure) => {
            let _ = writeln!(
                s,
                "<pre class=\"failure\">their renderer: {}</pre>",
                escape(&failure.to_string())
            );
        }
        HuntVerdict::Same => {
            s.push_str("<p>The minimal scene no longer fails: the renderer is not deterministic.</p>\n")
        }
        HuntVerdict::Refused(e) => {
            let _ = writeln!(s, "<p>The oracle refused the minimal scene: {}</p>", escape(e));
        }
    }
    let scene_file = format!("finding-{nn}.json");
    let theirs = format!("theirs-{nn}.png");
    let render = if renderer.contains("{scene}") {
        format!(
            "{}\n",
            renderer.replace("{scene}", &scene_file).replace("{out}", &theirs)
        )
    } else {
        format!("# draw {scene_file} with the renderer into {theirs} (it was hunted kept alive: {renderer})\n")
    };
    let model_flag = if model == Model::Exact { " --model exact" } else { "" };
    let _ = writeln!(
        s,
        "<details><summary>The minimal scene ({scene_file})</summary><pre>{}</pre></details>\n\
         <details><summary>Reproduce</summary><pre>{}rasterproof compare {scene_file} {theirs}{model_flag} --html finding-{nn}.html</pre></details>\n\
         <details><summary>A Rust test (finding-{nn}.rs)</summary><pre>{}</pre></details>\n</section>",
        escape(&f.minimal.to_json()),
        escape(&render),
        escape(&rust_test(f, n, model))
    );
    s
}
