//! A report as JSON (the schema is in the [parent module](super)'s documentation): written
//! whole, read back with an error naming the file, field and value of whatever is wrong.

use std::collections::BTreeMap;

use serde_json::Value;

use super::super::tally::{ulps_from_key, ulps_key, Counts, Tally};
use super::super::Shards;
use super::{CaseFailure, SuiteReport, FORMAT, VERSION};

impl SuiteReport {
    /// The report as a JSON document: one field a line, in the documented order, each
    /// array item (row, finding, failure) on a line of its own, compact; ending in a
    /// newline.
    pub fn to_json(&self) -> String {
        let t = &self.tally;
        let rows = t.rows.iter().map(|((invariant, model), c)| {
            object(&[
                ("invariant", j(invariant)),
                ("model", j(model)),
                ("must_hold", j(&c.must_hold)),
                ("cases", j(&c.cases)),
                ("violations", j(&c.violations)),
                ("skipped", j(&c.skipped)),
            ])
        });
        let skipped = t.reasons.iter().map(|((invariant, model, reason), n)| {
            object(&[
                ("invariant", j(invariant)),
                ("model", j(model)),
                ("reason", j(reason)),
                ("cases", j(n)),
            ])
        });
        let families = t
            .families
            .iter()
            .map(|((family, model), n)| object(&[("family", j(family)), ("model", j(model)), ("violations", j(n))]));
        let errors = t
            .ulps
            .iter()
            .map(|(&key, n)| format!("[{}, {n}]", ulps_value(ulps_from_key(key))));
        let ulps = object(&[("skipped", j(&t.ulps_skipped)), ("errors", array(errors, "    "))]);
        let findings = self.findings().into_iter().map(|f| {
            object(&[
                ("invariant", j(f.invariant)),
                ("model", j(f.model)),
                ("reason", j(f.reason)),
                ("fatal", j(&f.fatal)),
                ("count", j(&f.count)),
                ("first", failure_json(f.first)),
            ])
        });
        let failures = self.failures.iter().map(failure_json);
        let indices: Vec<u64> = self.shards.indices().collect();
        let shard = object(&[("count", j(&self.shards.count())), ("indices", j(&indices))]);
        let fields: [(&str, String); 18] = [
            ("format", j(FORMAT)),
            ("version", j(&VERSION)),
            ("rasterproof", j(&self.rasterproof)),
            ("seed", j(&self.seed)),
            ("cases", j(&self.cases)),
            ("shard", shard),
            ("cases_run", j(&self.cases_run())),
            ("complete", j(&self.is_complete())),
            ("stopped", array(self.stopped.iter().map(j), "  ")),
            ("cases_by_family", j(&self.families)),
            ("fatal", j(&t.fatal)),
            ("passed", j(&self.passed())),
            ("rows", array(rows, "  ")),
            ("skipped", array(skipped, "  ")),
            ("mesh_violations_by_family", array(families, "  ")),
            ("float32_sum_ulps", ulps),
            ("findings", array(findings, "  ")),
            ("failures", array(failures, "  ")),
        ];
        let body: Vec<String> = fields
            .iter()
            .map(|(key, value)| format!("  {}: {value}", j(key)))
            .collect();
        format!("{{\n{}\n}}\n", body.join(",\n"))
    }

    /// Reads a report written by [`SuiteReport::to_json`]; `name` (the file's path) starts
    /// every error. `findings`, `complete` and `passed` are derived from the other fields
    /// and not read.
    ///
    /// # Errors
    /// Not JSON (a truncated file included), not a check report, a report of another
    /// schema version, or a field missing or of the wrong type or value: one line naming
    /// `name`, the field and the value.
    pub fn from_json(text: &str, name: &str) -> Result<SuiteReport, String> {
        let value: Value = serde_json::from_str(text)
            .map_err(|e| format!("{name}: not a JSON check report (truncated or damaged?): {e}"))?;
        read_report(&value).map_err(|e| format!("{name}: {e}"))
    }
}

/// `v` as compact JSON (what serde_json writes; the values written here, strings,
/// numbers, booleans and maps of them, always serialise).
pub(crate) fn j<T: serde::Serialize + ?Sized>(v: &T) -> String {
    serde_json::to_string(v).unwrap_or_else(|_| "null".to_string())
}

/// An f32 sum error as JSON: a number (which reads back to the same f64), or the text of a
/// NaN or infinity, which JSON numbers cannot hold.
fn ulps_value(u: f64) -> String {
    serde_json::Number::from_f64(u).map_or_else(|| j(&u.to_string()), |n| n.to_string())
}

/// A failure as compact JSON, its fields in the documented order.
fn failure_json(f: &CaseFailure) -> String {
    let mut fields = vec![
        ("case", j(&f.case)),
        ("invariant", j(&f.invariant)),
        ("model", j(&f.model)),
        ("fatal", j(&f.fatal)),
        ("reason", j(&f.reason)),
        ("explanation", j(&f.explanation)),
        ("scene", j(&f.scene)),
    ];
    if let Some(p) = &f.scene_path {
        fields.push(("scene_path", j(p)));
    }
    object(&fields)
}

/// A JSON object of `fields` (each value already written as JSON) in their order, on
/// one line.
pub(crate) fn object(fields: &[(&str, String)]) -> String {
    let parts: Vec<String> = fields
        .iter()
        .map(|(key, value)| format!("{}: {value}", j(key)))
        .collect();
    format!("{{{}}}", parts.join(", "))
}

/// A JSON array of the already written `items`, each on a line of its own indented by
/// `indent` and two spaces, the closing bracket by `indent`; `[]` when empty.
fn array(items: impl Iterator<Item = String>, indent: &str) -> String {
    let items: Vec<String> = items.map(|i| format!("{indent}  {i}")).collect();
    if items.is_empty() {
        "[]".to_string()
    } else {
        format!("[\n{}\n{indent}]", items.join(",\n"))
    }
}

/// A field of an object, with its path for the errors.
struct Field<'a> {
    value: &'a Value,
    path: String,
}

impl<'a> Field<'a> {
    fn wrong(&self, expected: &str) -> String {
        let mut shown = self.value.to_string();
        if shown.chars().count() > 60 {
            shown = shown.chars().take(57).collect::<String>() + "...";
        }
        if self.path.is_empty() {
            format!("expected {expected}, found {shown}")
        } else {
            format!("{}: expected {expected}, found {shown}", self.path)
        }
    }

    fn get(&self, key: &str) -> Result<Field<'a>, String> {
        let object = self.value.as_object().ok_or_else(|| self.wrong("an object"))?;
        let value = object
            .get(key)
            .ok_or_else(|| format!("{}: missing field {key:?}", self.path))?;
        Ok(Field {
            value,
            path: if self.path.is_empty() {
                key.to_string()
            } else {
                format!("{}.{key}", self.path)
            },
        })
    }

    fn u64(&self) -> Result<u64, String> {
        self.value.as_u64().ok_or_else(|| self.wrong("a non-negative integer"))
    }

    fn str(&self) -> Result<&'a str, String> {
        self.value.as_str().ok_or_else(|| self.wrong("a string"))
    }

    fn bool(&self) -> Result<bool, String> {
        self.value.as_bool().ok_or_else(|| self.wrong("true or false"))
    }

    fn items(&self) -> Result<Vec<Field<'a>>, String> {
        let array = self.value.as_array().ok_or_else(|| self.wrong("an array"))?;
        Ok(array
            .iter()
            .enumerate()
            .map(|(i, value)| Field {
                value,
                path: format!("{}[{i}]", self.path),
            })
            .collect())
    }

    fn entries(&self) -> Result<Vec<(&'a str, Field<'a>)>, String> {
        let object = self.value.as_object().ok_or_else(|| self.wrong("an object"))?;
        Ok(object
            .iter()
            .map(|(k, value)| {
                (
                    k.as_str(),
                    Field {
                        value,
                        path: format!("{}.{k}", self.path),
                    },
                )
            })
            .collect())
    }
}

fn read_report(value: &Value) -> Result<SuiteReport, String> {
    let top = Field {
        value,
        path: String::new(),
    };
    if !value.is_object() {
        return Err(top.wrong("a check report (a JSON object)"));
    }
    let format = top
        .get("format")
        .map_err(|_| "not a check report: no \"format\" field".to_string())?;
    if format.value.as_str() != Some(FORMAT) {
        return Err(format.wrong(&format!("{FORMAT:?} (not a check report)")));
    }
    let version = top.get("version")?;
    if version.u64()? != VERSION {
        return Err(format!(
            "version {}: a report of another schema version (this rasterproof, {}, reads version {VERSION})",
            version.value,
            env!("CARGO_PKG_VERSION")
        ));
    }
    let seed = top.get("seed")?.u64()?;
    let cases = top.get("cases")?.u64()?;
    let shard = top.get("shard")?;
    let indices = shard
        .get("indices")?
        .items()?
        .iter()
        .map(Field::u64)
        .collect::<Result<Vec<u64>, String>>()?;
    let shards = Shards::new(shard.get("count")?.u64()?, indices).map_err(|e| format!("{}: {e}", shard.path))?;
    let mut report = SuiteReport::new(seed, cases, shards);
    report.rasterproof = top.get("rasterproof")?.str()?.to_string();
    for s in top.get("stopped")?.items()? {
        report.stopped.push(s.str()?.to_string());
    }
    for (family, n) in top.get("cases_by_family")?.entries()? {
        report.families.insert(family.to_string(), n.u64()?);
    }
    report.tally = read_tally(&top, seed)?;
    let run = top.get("cases_run")?;
    if run.u64()? != report.tally.cases {
        return Err(format!(
            "cases_run {}: but cases_by_family adds up to {}",
            run.value, report.tally.cases
        ));
    }
    if report.tally.cases > report.shards.case_count(cases) {
        return Err(format!(
            "cases_run {}: more than shard {} of {cases} cases holds",
            report.tally.cases, report.shards
        ));
    }
    for f in top.get("failures")?.items()? {
        let failure = read_failure(&f)?;
        if failure.case >= cases || !report.shards.contains(failure.case) {
            return Err(format!(
                "{}.case {}: not a case of shard {} of {cases} cases",
                f.path, failure.case, report.shards
            ));
        }
        report.failures.push(failure);
    }
    report.failures.sort_by_key(|f| f.case);
    Ok(report)
}

/// The table's fields of the report `top`.
fn read_tally(top: &Field<'_>, seed: u64) -> Result<Tally, String> {
    let mut t = Tally::new(seed);
    t.cases = top
        .get("cases_by_family")?
        .entries()?
        .iter()
        .try_fold(0u64, |sum, (_, n)| {
            sum.checked_add(n.u64()?).ok_or_else(|| n.wrong("a count that fits"))
        })?;
    t.fatal = top.get("fatal")?.u64()?;
    for r in top.get("rows")?.items()? {
        let key = (
            r.get("invariant")?.str()?.to_string(),
            r.get("model")?.str()?.to_string(),
        );
        let counts = Counts {
            cases: r.get("cases")?.u64()?,
            violations: r.get("violations")?.u64()?,
            skipped: r.get("skipped")?.u64()?,
            must_hold: r.get("must_hold")?.bool()?,
        };
        if t.rows.insert((key.0.into(), key.1.into()), counts).is_some() {
            return Err(format!("{}: a second row of the same invariant and model", r.path));
        }
    }
    for s in top.get("skipped")?.items()? {
        let key = (
            s.get("invariant")?.str()?.to_string().into(),
            s.get("model")?.str()?.to_string().into(),
            s.get("reason")?.str()?.to_string().into(),
        );
        *t.reasons.entry(key).or_default() += s.get("cases")?.u64()?;
    }
    for f in top.get("mesh_violations_by_family")?.items()? {
        let key = (
            f.get("family")?.str()?.to_string().into(),
            f.get("model")?.str()?.to_string().into(),
        );
        *t.families.entry(key).or_default() += f.get("violations")?.u64()?;
    }
    let ulps = top.get("float32_sum_ulps")?;
    t.ulps_skipped = ulps.get("skipped")?.u64()?;
    let mut errors = BTreeMap::new();
    for e in ulps.get("errors")?.items()? {
        let pair = e.items()?;
        let [u, n] = pair.as_slice() else {
            return Err(e.wrong("[error, samples]"));
        };
        let error = match u.value {
            Value::Number(x) => x.as_f64(),
            Value::String(s) => s.parse::<f64>().ok().filter(|x| !x.is_finite()),
            _ => None,
        }
        .ok_or_else(|| u.wrong("a number (or \"NaN\", \"inf\")"))?;
        *errors.entry(ulps_key(error)).or_default() += n.u64()?;
    }
    t.ulps = errors;
    Ok(t)
}

fn read_failure(f: &Field<'_>) -> Result<CaseFailure, String> {
    let scene_path = match f.value.get("scene_path") {
        None => None,
        Some(_) => Some(f.get("scene_path")?.str()?.to_string()),
    };
    Ok(CaseFailure {
        case: f.get("case")?.u64()?,
        invariant: f.get("invariant")?.str()?.to_string(),
        model: f.get("model")?.str()?.to_string(),
        fatal: f.get("fatal")?.bool()?,
        reason: f.get("reason")?.str()?.to_string(),
        explanation: f.get("explanation")?.str()?.to_string(),
        scene: f.get("scene")?.value.clone(),
        scene_path,
    })
}
