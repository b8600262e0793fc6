//! A grey hunt's findings as one self-contained HTML page ([`GreyHuntReport::to_html`],
//! what `hunt --as grey --out DIR` writes as `DIR/index.html`: each finding's minimal
//! scene with the levels judged against, theirs and the difference by grey class, as
//! `compare --as grey --html` shows them), and each finding as a ready-to-paste Rust
//! `#[test]` ([`grey_rust_test`], `finding-NN.rs`).

use std::fmt::Write as _;

use super::grey::{GreyFinding, GreyHuntReport, GreyVerdict};
use crate::oracle::compare::{html_escape as escape, html_page};

impl GreyHuntReport {
    /// The page. `renderer` is the hunted command as the user gave it (`--cmd` with its
    /// `{scene}` and `{out}`, or `--serve`). `index.html#finding=NN&pixel=X,Y` opens it
    /// with pixel (X, Y) of finding NN chosen.
    pub fn to_html(&self, renderer: &str) -> String {
        let title = format!("rasterproof hunt --as grey: {renderer}");
        let mut body = format!("<h1>{}</h1>\n", escape(&title));
        let _ = writeln!(body, "<pre id=\"summary\">{}</pre>", escape(&self.to_text(0)));
        for (k, f) in self.findings.iter().enumerate() {
            body.push_str(&self.finding_html(f, k + 1, renderer));
        }
        if self.findings.is_empty() {
            body.push_str("<p>Nothing found.</p>\n");
        }
        html_page(&title, &body)
    }

    /// One finding's section.
    fn finding_html(&self, f: &GreyFinding, n: usize, renderer: &str) -> String {
        let nn = format!("{n:02}");
        let mut s = format!("<section class=\"finding\" id=\"finding-{nn}\">\n");
        let _ = writeln!(s, "<h2>finding {nn}: {}</h2>", escape(&f.header()));
        match &f.verdict {
            GreyVerdict::Differs(r) => s.push_str(&r.html_views(&format!("-{nn}"))),
            _ => {
                let _ = writeln!(s, "<pre class=\"failure\">{}</pre>", escape(&f.verdict_text(0)));
            }
        }
        let scene_file = format!("finding-{nn}.json");
        let theirs = format!("finding-{nn}.png");
        let render = if renderer.contains("{scene}") {
            format!(
                "{}\n",
                renderer.replace("{scene}", &scene_file).replace("{out}", &theirs)
            )
        } else {
            format!("# {theirs} is the renderer's image of {scene_file} (it was hunted kept alive: {renderer})\n")
        };
        let _ = writeln!(
            s,
            "<details><summary>The minimal scene ({scene_file})</summary><pre>{}</pre></details>\n\
             <details><summary>Reproduce</summary><pre>{}rasterproof compare {scene_file} {theirs} --as grey {} --html finding-{nn}.html</pre></details>\n\
             <details><summary>A Rust test (finding-{nn}.rs)</summary><pre>{}</pre></details>\n</section>",
            escape(&f.minimal.to_json()),
            escape(&render),
            escape(&self.judged_flags()),
            escape(&grey_rust_test(f, n, self))
        );
        s
    }

    /// The `compare --as grey` options that judge as this hunt did.
    pub fn judged_flags(&self) -> String {
        match self.config.method {
            Some(m) => format!("--method {}", m.name()),
            None => format!(
                "--semantics {} --quantization {}",
                self.config.semantics.name(),
                self.config.quantization.name()
            ),
        }
    }
}

/// A Rust `#[test]` that pastes into a project's tests: the minimal scene, the levels
/// the hunt judged against (the exact area coverage under the hunt's semantics, quantized
/// as it says, or the method's levels) asserted at every pixel where their renderer
/// differed, with theirs and the class in a comment, and where to call their renderer.
pub fn grey_rust_test(f: &GreyFinding, n: usize, report: &GreyHuntReport) -> String {
    let config = &report.config;
    let mut s = format!(
        "/// Found by `rasterproof hunt --as grey` (case {}): {}.\n#[test]\nfn grey_hunt_finding_{n:02}_{}() {{\n",
        f.case,
        f.signature.describe(),
        f.signature.slug().replace('-', "_")
    );
    let _ = writeln!(
        s,
        "    let scene = rasterproof::scene::parse_scene(r#\"{}\"#, \"finding-{n:02}.json\").unwrap();",
        f.minimal.to_json().trim()
    );
    s.push_str("    let target = scene.target().unwrap();\n");
    let width = f.minimal.width;
    match config.method {
        Some(m) => {
            let _ = writeln!(
                s,
                "    let shapes = rasterproof::model::area_shapes(&scene.primitives(), &target, rasterproof::model::Model::Exact).unwrap();\n    \
                 // The levels of {} (what the hunt judged against), row by row:\n    \
                 let levels = rasterproof::oracle::compare::fit::grey::GreyMethod::from_name({:?}, {})\n        \
                 .unwrap()\n        .levels(&shapes, target.width, target.height)\n        .unwrap();",
                m.describe(),
                m.name(),
                m.bits()
            );
        }
        None => {
            let _ = writeln!(
                s,
                "    let area = rasterproof::model::render_area(&scene.primitives(), &target, rasterproof::model::Model::Exact, \
                 rasterproof::area::Semantics::{:?}).unwrap();\n    \
                 // The exact {} coverage quantized by {}, row by row:\n    \
                 let levels = area.levels(rasterproof::area::Quantization::{:?});",
                config.semantics,
                config.semantics.name(),
                config.quantization.name(),
                config.quantization
            );
        }
    }
    match &f.verdict {
        GreyVerdict::Differs(r) => {
            s.push_str("    // Where their renderer differed:\n");
            for p in &r.pixels {
                let judged = p.method.unwrap_or(p.ours);
                let _ = writeln!(
                    s,
                    "    assert_eq!(levels[{}], {judged}); // ({}, {}): exact {}; theirs {} ({})",
                    u64::from(p.y) * u64::from(width) + u64::from(p.x),
                    p.x,
                    p.y,
                    crate::num::exact::exact_text(&p.exact),
                    p.theirs,
                    p.class.name()
                );
            }
        }
        GreyVerdict::Failed(failure) => {
            // One comment line: the message's lines joined.
            let message = failure.message.lines().collect::<Vec<_>>().join(" / ");
            let _ = writeln!(
                s,
                "    // Their renderer failed on this scene ({}): {message}",
                failure.kind.name()
            );
            s.push_str("    let _ = &levels;\n");
        }
        GreyVerdict::Same | GreyVerdict::Refused(_) => s.push_str("    let _ = &levels;\n"),
    }
    s.push_str("    // Render `scene` with your renderer here and assert its levels equal `levels`.\n}\n");
    s
}
