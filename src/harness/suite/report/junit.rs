//! A report as JUnit XML (`check --junit`), the format CI systems display: one test case
//! per row of the table, failed when the row's model must hold and it has violations.

use std::fmt::Write as _;

use super::Report;

/// How many failing cases a test case's `<failure>` lists before "and N more".
const LISTED: usize = 10;

impl Report {
    /// The report as JUnit XML: one `<testsuite>` in a `<testsuites>`, with the seed,
    /// cases, shard and version as properties, and one `<testcase classname="rasterproof.check"
    /// name="INVARIANT / MODEL">` per row of the table, in its order. A row whose model
    /// must hold and that has violations holds a `<failure>` (its message counts them, its
    /// text gives the first cases' explanations and scenes' paths); a row whose every case
    /// was skipped holds `<skipped>`; a float model's violations (the measured trade) are
    /// counted in `<system-out>`, not failed. Every text is escaped for XML; characters
    /// XML cannot hold become U+FFFD.
    ///
    /// ```
    /// use rasterproof::harness::suite::Plan;
    /// let xml = Plan::new(7, 1).run().unwrap().junit();
    /// assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites "));
    /// assert!(xml.contains("name=\"watertight / fixed\""));
    /// ```
    pub fn junit(&self) -> String {
        let t = self.tally();
        let rows: Vec<_> = t.rows().collect();
        let failed = rows
            .iter()
            .filter(|r| r.violations > 0 && t.row_must_hold(r.invariant, r.label))
            .count();
        let skipped = rows.iter().filter(|r| r.cases == 0).count();
        let counts = format!(
            "tests=\"{}\" failures=\"{failed}\" errors=\"0\" skipped=\"{skipped}\"",
            rows.len()
        );
        let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(x, "<testsuites name=\"rasterproof check\" {counts}>");
        let _ = writeln!(
            x,
            "  <testsuite name=\"{}\" {counts}>",
            attribute(&format!(
                "rasterproof check, seed {}, shard {}",
                self.seed(),
                self.shards()
            ))
        );
        x.push_str("    <properties>\n");
        for (name, value) in [
            ("rasterproof", self.rasterproof_version().to_string()),
            ("seed", self.seed().to_string()),
            ("cases", self.cases().to_string()),
            ("shard", self.shards().to_string()),
            ("cases_run", self.cases_run().to_string()),
            ("complete", self.is_complete().to_string()),
        ] {
            let _ = writeln!(x, "      <property name=\"{name}\" value=\"{}\"/>", attribute(&value));
        }
        x.push_str("    </properties>\n");
        for r in &rows {
            let name = attribute(&format!("{} / {}", r.invariant, r.label));
            let _ = write!(x, "    <testcase classname=\"rasterproof.check\" name=\"{name}\"");
            let of = format!("{} of {} cases", r.violations, r.cases);
            if r.violations > 0 && t.row_must_hold(r.invariant, r.label) {
                let message = format!("{of} violate {} on {}", r.invariant, r.label);
                let _ = write!(
                    x,
                    ">\n      <failure type=\"violation\" message=\"{}\">",
                    attribute(&message)
                );
                x.push_str(&text(&self.failure_text(r.invariant, r.label)));
                x.push_str("</failure>\n    </testcase>\n");
            } else if r.cases == 0 {
                let message = format!("all {} cases skipped (the check could not run)", r.skipped);
                let _ = writeln!(
                    x,
                    ">\n      <skipped message=\"{}\"/>\n    </testcase>",
                    attribute(&message)
                );
            } else if r.violations > 0 {
                let out = format!("{of} violate it: a float model's measured trade, not a failure");
                let _ = writeln!(x, ">\n      <system-out>{}</system-out>\n    </testcase>", text(&out));
            } else {
                x.push_str("/>\n");
            }
        }
        x.push_str("  </testsuite>\n</testsuites>\n");
        x
    }

    /// The first failing cases of the row (`invariant`, `label`): case, explanation and
    /// scene path, then how many more.
    fn failure_text(&self, invariant: &str, label: &str) -> String {
        let mine: Vec<_> = self
            .failures()
            .iter()
            .filter(|f| f.invariant == invariant && f.model == label)
            .collect();
        let mut s = String::new();
        for f in mine.iter().take(LISTED) {
            let _ = write!(s, "case {}: {}", f.case, f.explanation);
            if let Some(p) = &f.scene_path {
                let _ = write!(s, "\n  scene: {p}");
            }
            s.push('\n');
        }
        if mine.len() > LISTED {
            let _ = writeln!(s, "and {} more", mine.len() - LISTED);
        }
        s
    }
}

/// `s` as XML character data.
fn text(s: &str) -> String {
    escape(s, false)
}

/// `s` as an XML attribute value between double quotes (line breaks and tabs kept as
/// character references, which attribute normalisation would otherwise turn into spaces).
fn attribute(s: &str) -> String {
    escape(s, true)
}

/// `s` as XML: character data, or (`attribute`) an attribute value between double quotes
/// (line breaks and tabs as character references); characters XML 1.0 cannot hold become
/// U+FFFD. Shared with `hunt`'s JUnit file.
pub(crate) fn escape(s: &str, attribute: bool) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' if attribute => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' if attribute => out.push_str("&#9;"),
            '\n' | '\t' => out.push(c),
            // XML 1.0 holds no other control character, not even as a reference.
            c if u32::from(c) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escape_covers_markup_quotes_and_control_characters() {
        assert_eq!(
            text("a < b && c > \"d\" 'e'"),
            "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;"
        );
        assert_eq!(text("x\ny\tz\u{1}\r"), "x\ny\tz\u{FFFD}&#13;");
        assert_eq!(attribute("x\ny\tz"), "x&#10;y&#9;z");
    }
}
