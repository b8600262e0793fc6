//! Merging the reports of a sharded hunt (`hunt --shard K/N --report FILE.json` on N
//! machines: a CI matrix, a Kubernetes Indexed Job's `JOB_COMPLETION_INDEX`) into the
//! report of the whole run ([`merge_reports`]).
//!
//! Shards of one run share every setting but the shard; each case belongs to one shard,
//! so the counts add up, a signature's cases add up, its first case is the lowest of the
//! shards', and the shard holding that case shrank it exactly as the unsharded run would
//! have (the same case, the same renderer): the merged finding is that shard's. With all N
//! shards the merged report is the unsharded run's, but for what the renderer was asked
//! (every shard shrinks its own first case of each signature, so the shards together ask
//! more) and the time budget.

use serde_json::{json, Map, Value};

use super::report::{HUNT_REPORT_FORMAT, HUNT_REPORT_VERSION};
use crate::oracle::compare::PixelKind;

/// The settings the shards of one run must share.
const SHARED: [&str; 12] = [
    "cmd",
    "seed",
    "cases",
    "families",
    "canvas",
    "float32_exact",
    "samples",
    "shrink_runs",
    "time_budget_ms",
    "convention",
    "model",
    "version",
];

/// Merges the hunt reports of the shards of one run, each `(name, report)` as
/// [`super::HuntReport::to_json`] wrote it. The result has the same fields; `shard` is
/// `{"k": 1, "n": 1}` when every shard is there, else `{"merged": [K, ...], "n": N}`;
/// `renderer_runs` adds up (`null` when some shard has none); `per_sample` adds up each
/// sample index's cases and pixels and keeps the positions every shard's `fits` holds (the
/// intersection over all the shards' findings' scenes, where the unsharded run fits on
/// the merged findings' scenes only: never fewer constraints, so never more positions).
///
/// # Errors
/// A report that is not a hunt report of this version; shards of different runs (a
/// setting differs: named with both values and files) or of different N; a shard given
/// twice; a field missing or of the wrong type. One line naming the file and field.
pub fn merge_reports(reports: &[(String, Value)]) -> Result<Value, String> {
    let Some((first_name, first)) = reports.first() else {
        return Err("no reports to merge".to_string());
    };
    for (name, r) in reports {
        if r.get("format").and_then(Value::as_str) != Some(HUNT_REPORT_FORMAT) {
            return Err(format!(
                "{name}: not a hunt report (its format is not {HUNT_REPORT_FORMAT:?})"
            ));
        }
        if r.get("version").and_then(Value::as_u64) != Some(HUNT_REPORT_VERSION) {
            return Err(format!(
                "{name}: version {}: this rasterproof merges version {HUNT_REPORT_VERSION}",
                r.get("version").map_or("(none)".to_string(), Value::to_string)
            ));
        }
        for key in SHARED {
            let (a, b) = (first.get(key), r.get(key));
            if a != b {
                let show = |v: Option<&Value>| v.map_or("(none)".to_string(), Value::to_string);
                return Err(format!(
                    "{name}: {key} {}, but {first_name} has {}: shards of different hunts",
                    show(b),
                    show(a)
                ));
            }
        }
    }
    let number = |name: &str, r: &Value, path: &[&str]| -> Result<u64, String> {
        let mut v = r;
        for p in path {
            v = v.get(p).ok_or_else(|| format!("{name}: no {}", path.join(".")))?;
        }
        v.as_u64()
            .ok_or_else(|| format!("{name}: {} is not a whole number", path.join(".")))
    };
    let n = number(first_name, first, &["shard", "n"])?;
    let mut shards: Vec<u64> = Vec::new();
    for (name, r) in reports {
        if number(name, r, &["shard", "n"])? != n {
            return Err(format!("{name}: shard.n differs from {first_name}'s {n}"));
        }
        let k = number(name, r, &["shard", "k"])?;
        if shards.contains(&k) {
            return Err(format!("{name}: shard {k}/{n} is given twice"));
        }
        shards.push(k);
    }
    shards.sort_unstable();
    let sum = |path: &[&str]| -> Result<u64, String> {
        reports
            .iter()
            .map(|(name, r)| number(name, r, path))
            .sum::<Result<u64, String>>()
    };
    let stopped = reports
        .iter()
        .any(|(_, r)| r.get("stopped_by_time").and_then(Value::as_bool) == Some(true));
    let runs = reports
        .iter()
        .map(|(name, r)| match r.get("renderer_runs") {
            Some(Value::Null) | None => Ok(None),
            Some(_) => Ok(Some((
                number(name, r, &["renderer_runs", "calls"])?,
                number(name, r, &["renderer_runs", "starts"])?,
            ))),
        })
        .collect::<Result<Option<Vec<(u64, u64)>>, String>>()?
        .map(|v| {
            let (calls, starts) = v.iter().fold((0, 0), |(c, s), (a, b)| (c + a, s + b));
            json!({"calls": calls, "starts": starts})
        });
    let findings = merge_findings(reports)?;
    let per_sample = merge_per_sample(reports)?;
    let whole = shards.len() as u64 == n;
    let mut out = Map::new();
    for (key, value) in first.as_object().expect("checked: it has a format") {
        let merged = match key.as_str() {
            "shard" if whole => json!({"k": 1, "n": 1}),
            "shard" => json!({"merged": shards, "n": n}),
            "cases_requested" => json!(sum(&["cases_requested"])?),
            "cases_run" => json!(sum(&["cases_run"])?),
            "stopped_by_time" => json!(stopped),
            "interrupted" => json!(reports
                .iter()
                .any(|(_, r)| r.get("interrupted").and_then(Value::as_bool) == Some(true))),
            "counts" => json!({
                "same": sum(&["counts", "same"])?,
                "differ": sum(&["counts", "differ"])?,
                "failed": sum(&["counts", "failed"])?,
                "refused": sum(&["counts", "refused"])?,
            }),
            "renderer_runs" => runs.clone().unwrap_or(Value::Null),
            "findings" => Value::Array(findings.clone()),
            "per_sample" => per_sample.clone(),
            _ => value.clone(),
        };
        out.insert(key.clone(), merged);
    }
    Ok(Value::Object(out))
}

/// The shards' `per_sample` lists merged index by index: cases and pixels summed, `fits`
/// intersected over the shards that have them (`null` when none has). `null` when the
/// hunt had one sample per pixel.
fn merge_per_sample(reports: &[(String, Value)]) -> Result<Value, String> {
    let mut merged: Option<Vec<Value>> = None;
    for (name, r) in reports {
        let list = match r.get("per_sample") {
            None | Some(Value::Null) => continue,
            Some(Value::Array(list)) => list,
            Some(other) => return Err(format!("{name}: per_sample is not a list: {other}")),
        };
        let Some(kept) = merged.as_mut() else {
            merged = Some(list.clone());
            continue;
        };
        if kept.len() != list.len() {
            return Err(format!(
                "{name}: per_sample has {} sample indices, the first shard {}",
                list.len(),
                kept.len()
            ));
        }
        for (i, (m, s)) in kept.iter_mut().zip(list).enumerate() {
            for key in ["cases", "pixels"] {
                let add = s
                    .get(key)
                    .and_then(Value::as_u64)
                    .ok_or_else(|| format!("{name}: per_sample[{i}].{key} is not a whole number"))?;
                let had = m.get(key).and_then(Value::as_u64).unwrap_or(0);
                m[key] = json!(had + add);
            }
            m["fits"] = match (m.get("fits").cloned(), s.get("fits")) {
                (Some(Value::Array(a)), Some(Value::Array(b))) => {
                    Value::Array(a.into_iter().filter(|p| b.contains(p)).collect())
                }
                (Some(Value::Array(a)), _) => Value::Array(a),
                (_, Some(Value::Array(b))) => Value::Array(b.clone()),
                _ => Value::Null,
            };
        }
    }
    Ok(merged.map_or(Value::Null, Value::Array))
}

/// A (merged) report's `per_sample` read back as summaries, for printing
/// ([`super::SampleIndexSummary::to_text`]); empty when it is `null`.
///
/// # Errors
/// An entry missing a field or with one of the wrong type, named by index.
pub fn per_sample_summaries(report: &Value) -> Result<Vec<super::SampleIndexSummary>, String> {
    let Some(list) = report.get("per_sample").and_then(Value::as_array) else {
        return Ok(Vec::new());
    };
    let point = |v: &Value, i: usize| -> Result<[num_rational::BigRational; 2], String> {
        let bad = || format!("per_sample[{i}]: a position is not [\"x\", \"y\"] fractions: {v}");
        let coords: Vec<num_rational::BigRational> = v
            .as_array()
            .ok_or_else(bad)?
            .iter()
            .map(|c| c.as_str().and_then(|t| t.parse().ok()).ok_or_else(bad))
            .collect::<Result<_, _>>()?;
        <[num_rational::BigRational; 2]>::try_from(coords).map_err(|_| bad())
    };
    list.iter()
        .enumerate()
        .map(|(i, e)| {
            let whole = |key: &str| {
                e.get(key)
                    .and_then(Value::as_u64)
                    .ok_or_else(|| format!("per_sample[{i}].{key} is not a whole number"))
            };
            let fits = match e.get("fits") {
                Some(Value::Array(a)) => Some(a.iter().map(|p| point(p, i)).collect::<Result<Vec<_>, _>>()?),
                _ => None,
            };
            Ok(super::SampleIndexSummary {
                index: usize::try_from(whole("index")?).map_err(|_| format!("per_sample[{i}].index is too large"))?,
                position: point(e.get("position").unwrap_or(&Value::Null), i)?,
                cases: whole("cases")?,
                pixels: whole("pixels")?,
                fits,
            })
        })
        .collect()
}

/// Every signature once: the finding of the shard with its lowest first case, its cases
/// summed over the shards and its pixel kinds united; by first case, then in that shard's
/// order.
fn merge_findings(reports: &[(String, Value)]) -> Result<Vec<Value>, String> {
    // (first case, position in its shard's list, finding, cases, kinds)
    let mut merged: Vec<(u64, usize, Value, u64, Vec<String>)> = Vec::new();
    for (name, r) in reports {
        let list = r
            .get("findings")
            .and_then(Value::as_array)
            .ok_or_else(|| format!("{name}: findings is not a list"))?;
        for (position, f) in list.iter().enumerate() {
            let field = |key: &str| {
                f.get(key)
                    .ok_or_else(|| format!("{name}: findings[{position}] has no {key}"))
            };
            let signature = field("signature")?.clone();
            let first = field("first_case")?
                .as_u64()
                .ok_or_else(|| format!("{name}: findings[{position}].first_case is not a whole number"))?;
            let cases = field("cases")?
                .as_u64()
                .ok_or_else(|| format!("{name}: findings[{position}].cases is not a whole number"))?;
            let kinds: Vec<String> = field("kinds")?
                .as_array()
                .ok_or_else(|| format!("{name}: findings[{position}].kinds is not a list"))?
                .iter()
                .filter_map(|k| k.as_str().map(str::to_string))
                .collect();
            match merged.iter_mut().find(|m| m.2.get("signature") == Some(&signature)) {
                Some(m) => {
                    m.3 += cases;
                    for k in kinds {
                        if !m.4.contains(&k) {
                            m.4.push(k);
                        }
                    }
                    if first < m.0 {
                        (m.0, m.1, m.2) = (first, position, f.clone());
                    }
                }
                None => merged.push((first, position, f.clone(), cases, kinds)),
            }
        }
    }
    merged.sort_by_key(|m| (m.0, m.1));
    Ok(merged
        .into_iter()
        .map(|(_, _, mut f, cases, mut kinds)| {
            let order = |k: &String| PixelKind::ALL.iter().position(|p| p.name() == k).unwrap_or(usize::MAX);
            kinds.sort_by_key(order);
            f["cases"] = json!(cases);
            f["kinds"] = json!(kinds);
            f
        })
        .collect())
}
