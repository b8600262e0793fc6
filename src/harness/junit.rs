//! JUnit XML, the format CI systems display: a small model ([`TestSuites`] of
//! [`TestSuite`]s of [`TestCase`]s) and its one writer ([`TestSuites::to_xml`]), behind
//! both `check --junit` ([`crate::harness::suite::SuiteReport::junit`]) and `hunt --junit`
//! ([`crate::oracle::hunt::HuntReport::junit`]); [`xml_escape`] escapes every text.

use std::fmt::Write as _;

/// A JUnit document: a `<testsuites>` holding its suites, with their counts summed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestSuites {
    /// The `<testsuites>`' `name`.
    pub name: String,
    /// Its `<testsuite>`s, in order.
    pub suites: Vec<TestSuite>,
}

/// A `<testsuite>`: its properties, then its test cases.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestSuite {
    /// Its `name`.
    pub name: String,
    /// Its `<properties>`, (name, value), in order; none writes no `<properties>`.
    pub properties: Vec<(String, String)>,
    /// Its `<testcase>`s, in order.
    pub cases: Vec<TestCase>,
}

/// A `<testcase>`: passed unless it holds a [`JunitFailure`] or a skip.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestCase {
    /// Its `classname`.
    pub classname: String,
    /// Its `name`.
    pub name: String,
    /// Why it failed: a `<failure>`, counted in `failures`.
    pub failure: Option<JunitFailure>,
    /// Why it was skipped (the message of a `<skipped>`), counted in `skipped`. A case
    /// that failed too is written with its `<failure>` only (a test case holds one of
    /// them) but counted in both.
    pub skipped: Option<String>,
    /// What it printed: a `<system-out>`, after the failure or skip.
    pub system_out: Option<String>,
}

/// A `<failure>`: its `type` and `message` attributes and its text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct JunitFailure {
    /// Its `type`, e.g. `violation`.
    pub kind: String,
    /// Its `message`, one line.
    pub message: String,
    /// Its text, any number of lines.
    pub text: String,
}

/// The count attributes of a `<testsuites>` or `<testsuite>`.
#[derive(Debug, Clone, Copy, Default)]
struct Counts {
    tests: usize,
    failures: usize,
    skipped: usize,
}

impl Counts {
    fn of(cases: &[TestCase]) -> Counts {
        Counts {
            tests: cases.len(),
            failures: cases.iter().filter(|c| c.failure.is_some()).count(),
            skipped: cases.iter().filter(|c| c.skipped.is_some()).count(),
        }
    }

    fn attributes(self) -> String {
        let Counts {
            tests,
            failures,
            skipped,
        } = self;
        format!("tests=\"{tests}\" failures=\"{failures}\" errors=\"0\" skipped=\"{skipped}\"")
    }
}

impl TestSuites {
    /// The document as JUnit XML: the XML declaration, then `<testsuites name=".."
    /// tests=".." failures=".." errors="0" skipped="..">` (the counts summed over its
    /// suites; `tests` counts the test cases, `failures` those with a failure, `skipped`
    /// those skipped), each suite with the same counts of its own, its properties, and one
    /// line per passing test case or an element a line for the others; two spaces an
    /// indent, ending in a newline. Every text is escaped for XML ([`xml_escape`]).
    ///
    /// ```
    /// use rasterproof::harness::junit::{JunitFailure, TestCase, TestSuite, TestSuites};
    /// let case = |name: &str, failure| TestCase {
    ///     classname: "x".into(),
    ///     name: name.into(),
    ///     failure,
    ///     skipped: None,
    ///     system_out: None,
    /// };
    /// let failure = JunitFailure { kind: "t".into(), message: "a < b".into(), text: "why".into() };
    /// let xml = TestSuites {
    ///     name: "all".into(),
    ///     suites: vec![TestSuite {
    ///         name: "one".into(),
    ///         properties: vec![("seed".into(), "7".into())],
    ///         cases: vec![case("ok", None), case("bad", Some(failure))],
    ///     }],
    /// }
    /// .to_xml();
    /// assert!(xml.contains("<testsuite name=\"one\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\">"));
    /// assert!(xml.contains("<testcase classname=\"x\" name=\"ok\"/>"));
    /// assert!(xml.contains("<failure type=\"t\" message=\"a &lt; b\">why</failure>"));
    /// ```
    pub fn to_xml(&self) -> String {
        let total = self
            .suites
            .iter()
            .map(|s| Counts::of(&s.cases))
            .fold(Counts::default(), |a, b| Counts {
                tests: a.tests + b.tests,
                failures: a.failures + b.failures,
                skipped: a.skipped + b.skipped,
            });
        let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(
            x,
            "<testsuites name=\"{}\" {}>",
            attribute(&self.name),
            total.attributes()
        );
        for suite in &self.suites {
            suite.write(&mut x);
        }
        x.push_str("</testsuites>\n");
        x
    }
}

impl TestSuite {
    /// Writes the suite, indented once, onto `x`.
    fn write(&self, x: &mut String) {
        let counts = Counts::of(&self.cases).attributes();
        let _ = writeln!(x, "  <testsuite name=\"{}\" {counts}>", attribute(&self.name));
        if !self.properties.is_empty() {
            x.push_str("    <properties>\n");
            for (name, value) in &self.properties {
                let _ = writeln!(
                    x,
                    "      <property name=\"{}\" value=\"{}\"/>",
                    attribute(name),
                    attribute(value)
                );
            }
            x.push_str("    </properties>\n");
        }
        for case in &self.cases {
            case.write(x);
        }
        x.push_str("  </testsuite>\n");
    }
}

impl TestCase {
    /// Writes the test case, indented twice, onto `x`: one line when it passed and printed
    /// nothing, else its elements a line each inside it.
    fn write(&self, x: &mut String) {
        let _ = write!(
            x,
            "    <testcase classname=\"{}\" name=\"{}\"",
            attribute(&self.classname),
            attribute(&self.name)
        );
        let mut children = String::new();
        if let Some(f) = &self.failure {
            let _ = writeln!(
                children,
                "      <failure type=\"{}\" message=\"{}\">{}</failure>",
                attribute(&f.kind),
                attribute(&f.message),
                text(&f.text)
            );
        } else if let Some(message) = &self.skipped {
            let _ = writeln!(children, "      <skipped message=\"{}\"/>", attribute(message));
        }
        if let Some(out) = &self.system_out {
            let _ = writeln!(children, "      <system-out>{}</system-out>", text(out));
        }
        if children.is_empty() {
            x.push_str("/>\n");
        } else {
            let _ = write!(x, ">\n{children}    </testcase>\n");
        }
    }
}

/// `s` as XML character data.
fn text(s: &str) -> String {
    xml_escape(s, false)
}

/// `s` as an XML attribute value between double quotes (line breaks and tabs kept as
/// character references, which attribute normalisation would otherwise turn into spaces).
fn attribute(s: &str) -> String {
    xml_escape(s, true)
}

/// `s` as XML: character data, or (`attribute`) an attribute value between double quotes
/// (line breaks and tabs as character references); characters XML 1.0 cannot hold become
/// U+FFFD.
///
/// ```
/// use rasterproof::harness::junit::xml_escape;
/// assert_eq!(xml_escape("a < \"b\"\n", false), "a &lt; &quot;b&quot;\n");
/// assert_eq!(xml_escape("a\nb", true), "a&#10;b");
/// ```
pub fn xml_escape(s: &str, attribute: bool) -> String {
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
