//! RenderDoc's mesh-viewer CSV export (the VS Out or GS Out table, "Export to CSV"): a
//! header row `VTX, IDX, <name>.x, <name>.y, <name>.z, <name>.w, ...` (an element of one
//! component is its bare name), then one row per vertex in draw order, fields separated
//! by `, `, floats printed with a leading space where the sign is missing. The position's
//! name depends on the API and the shader: `SV_Position` (HLSL), `gl_Position` (GLSL),
//! `gl_PerVertex.gl_Position` (SPIR-V blocks), `POSITION`. Rows in threes are a triangle
//! list: the export already lists the vertices by index (`IDX` says which), so the rows
//! are the draw order.
//!
//! Read with the `csv` crate: quoted fields, CRLF line ends and spaces around a field are
//! accepted; columns beyond the position are ignored. Streamed row by row: the file is
//! never held in memory.
//!
//! Reference: RenderDoc's documentation, "Buffer Viewer / Mesh Viewer"
//! (renderdoc.org/docs, window/buffer_viewer), and qrenderdoc's BufferViewer.cpp
//! (`BufferViewer::exportData` writes the header from `headerData`, `VTX`, `IDX`, then
//! `name.x` ...; each cell as the table displays it).

use std::io::Read;

use num_rational::BigRational;

use super::{clip_triangles, counted, exact_f32, ImportError, ImportTarget, Imported, MAX_VERTICES};
use crate::num::parse_rational;

/// The position names tried, in order, when none is given (compared without case).
pub const POSITION_NAMES: [&str; 4] = ["SV_Position", "gl_Position", "gl_PerVertex.gl_Position", "POSITION"];

/// How the CSV is read.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CsvOptions {
    /// The position's name (its columns are `NAME.x` ... `NAME.w`, compared without case);
    /// `None` is the first of [`POSITION_NAMES`] the header has.
    pub position: Option<String>,
    /// Keep each number's decimal text exactly (`0.1` is 1/10) instead of the f32 it rounds
    /// to (`0.1` is 13421773/134217728, what the GPU held when RenderDoc printed `0.1`).
    pub exact_decimal: bool,
}

/// The four position columns: their indices in a row and their names as the header writes
/// them.
#[derive(Debug)]
struct PositionColumns {
    index: [usize; 4],
    names: [String; 4],
}

/// Reads RenderDoc's CSV export from `reader` (`source` names it in errors and the
/// summary) into a scene of clip-space triangles on `target`. Errors name a row by its
/// place in the file, the header being row 1 (blank lines are not rows), and a column by
/// its header name.
///
/// ```
/// use rasterproof::convention::Preset;
/// use rasterproof::import::renderdoc::{import_csv, CsvOptions};
/// use rasterproof::import::ImportTarget;
/// let csv = "VTX, IDX, SV_Position.x, SV_Position.y, SV_Position.z, SV_Position.w, TEXCOORD0.x\n\
///            0, 0, -1.00, -1.00, 0.00, 1.00, 0.00\n\
///            1, 1,  1.00, -1.00, 0.00, 1.00, 1.00\n\
///            2, 2, -1.00,  1.00, 0.00, 1.00, 0.00\n";
/// let target = ImportTarget { width: 8, height: 8, preset: Preset::D3d11, viewport: None };
/// let imported = import_csv(csv.as_bytes(), "mesh.csv", &CsvOptions::default(), &target).unwrap();
/// assert_eq!(imported.scene.clip_space_triangles.len(), 1);
/// assert!(imported.summary.starts_with("mesh.csv: 1 triangle from rows 2-4"));
///
/// let bad = csv.replace("0.00, 1.00, 1.00\n", "0.00, nan, 1.00\n");
/// let err = import_csv(bad.as_bytes(), "mesh.csv", &CsvOptions::default(), &target).unwrap_err();
/// assert_eq!(err.to_string(), "mesh.csv: row 3, SV_Position.w: \"nan\" is not a finite number");
/// ```
///
/// # Errors
/// An empty file, no header row, no position columns (naming the columns found), a row
/// without one of them, a value that is not a finite number (naming row, column and
/// value), a row count that is not a multiple of 3, more than
/// [`crate::scene::parse::MAX_TRIANGLES`] triangles, text that is not CSV or not UTF-8,
/// and a bad canvas or viewport.
pub fn import_csv<R: Read>(
    reader: R,
    source: &str,
    options: &CsvOptions,
    target: &ImportTarget,
) -> Result<Imported, ImportError> {
    target.check_canvas()?;
    let err = |message: String| ImportError::new(source, message);
    let mut csv = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(reader);
    let mut records = csv.records();
    let header = match records.next() {
        None => {
            return Err(err(
                "is empty (RenderDoc's export starts with a header row: VTX, IDX, ...)".into(),
            ))
        }
        Some(record) => record.map_err(|e| err(csv_error(&e, 1)))?,
    };
    let header: Vec<String> = header
        .iter()
        .enumerate()
        .map(|(k, f)| {
            unquoted(if k == 0 {
                f.trim_start_matches('\u{feff}').trim()
            } else {
                f
            })
        })
        .collect();
    if header.iter().all(|f| f.parse::<f64>().is_ok()) {
        return Err(err(format!(
            "row 1 is not a header row ({}); RenderDoc's export starts with VTX, IDX, <name>.x, ...",
            shown_list(&header)
        )));
    }
    let columns = position_columns(&header, options.position.as_deref()).map_err(err)?;
    let mut vertices: Vec<[BigRational; 4]> = Vec::new();
    let mut last_row = 0;
    for (k, record) in records.enumerate() {
        // Row numbers count records (the header is row 1): the csv crate's line numbers
        // are off after CRLF line ends, and blank lines are not rows.
        let row = k + 2;
        let record = record.map_err(|e| err(csv_error(&e, row)))?;
        if vertices.len() == MAX_VERTICES {
            return Err(err(format!(
                "row {row}: more than {MAX_VERTICES} rows (the scene limit is {} triangles)",
                crate::scene::parse::MAX_TRIANGLES
            )));
        }
        last_row = row;
        let mut pos: [BigRational; 4] = Default::default();
        for (c, slot) in pos.iter_mut().enumerate() {
            let name = &columns.names[c];
            let text = record.get(columns.index[c]).ok_or_else(|| {
                err(format!(
                    "row {row}: no {name} column (the row has {} fields, the header {})",
                    record.len(),
                    header.len()
                ))
            })?;
            *slot = parse_value(&unquoted(text), options.exact_decimal)
                .map_err(|e| err(format!("row {row}, {name}: {e}")))?;
        }
        vertices.push(pos);
    }
    let rows = vertices.len();
    if rows == 0 {
        return Err(err("has a header row but no vertex rows".into()));
    }
    if rows % 3 != 0 {
        return Err(err(format!(
            "{}: a triangle list needs a multiple of 3 rows ({} and {} left over)",
            counted(rows as u64, "vertex row", "vertex rows"),
            counted((rows / 3) as u64, "triangle", "triangles"),
            counted((rows % 3) as u64, "row", "rows")
        )));
    }
    let triangles = clip_triangles(vertices);
    let count = triangles.len();
    let scene = target.clip_scene(triangles)?;
    let reading = if options.exact_decimal {
        "each value its decimal text exactly"
    } else {
        "each value the f32 its text rounds to, exactly"
    };
    let summary = format!(
        "{source}: {} from rows 2-{last_row}, columns {} ({reading}); {}",
        counted(count as u64, "triangle", "triangles"),
        columns.names.join(", "),
        target.describe(true)
    );
    Ok(Imported { scene, summary })
}

/// The position's four columns in `header`: `name` or the first of [`POSITION_NAMES`] whose
/// `.x .y .z .w` all exist (names compared without case, spaces around them ignored).
fn position_columns(header: &[String], name: Option<&str>) -> Result<PositionColumns, String> {
    let find = |name: &str| -> Option<PositionColumns> {
        let mut index = [0; 4];
        for (slot, comp) in index.iter_mut().zip(["x", "y", "z", "w"]) {
            let want = format!("{name}.{comp}");
            *slot = header.iter().position(|h| h.trim().eq_ignore_ascii_case(&want))?;
        }
        Some(PositionColumns {
            names: index.map(|k| header[k].clone()),
            index,
        })
    };
    let found = match name {
        Some(name) => find(name).ok_or_else(|| {
            format!(
                "no {name}.x, {name}.y, {name}.z, {name}.w columns (--position); the header has {}",
                shown_list(header)
            )
        }),
        None => POSITION_NAMES.iter().find_map(|n| find(n)).ok_or_else(|| {
            format!(
                "no position columns: none of {} has .x .y .z .w columns; the header has {} (name the position with --position NAME)",
                POSITION_NAMES.join(", "),
                shown_list(header)
            )
        }),
    }?;
    Ok(found)
}

/// One value: the f32 its text rounds to, exactly, or (`exact_decimal`) the decimal
/// exactly. The error starts with the value in quotes.
fn parse_value(text: &str, exact_decimal: bool) -> Result<BigRational, String> {
    if exact_decimal {
        return parse_rational(text).map_err(|e| format!("{text:?} {e}"));
    }
    let f: f32 = text.parse().map_err(|_| {
        if text.is_empty() {
            "the value is empty".to_string()
        } else {
            format!("{text:?} is not a number")
        }
    })?;
    let lower = text.to_ascii_lowercase();
    if f.is_nan() || lower.contains("inf") {
        return Err(format!("{text:?} is not a finite number"));
    }
    exact_f32(f).ok_or_else(|| {
        format!(
            "{text:?} is beyond the f32 range (largest {:e}); --exact-decimal reads it exactly",
            f32::MAX
        )
    })
}

/// A field with its quotes removed: RenderDoc writes none, but a field quoted after the
/// `, ` separator reaches here with them (the csv crate unquotes only a field that starts
/// with the quote).
fn unquoted(field: &str) -> String {
    match field.strip_prefix('"').and_then(|f| f.strip_suffix('"')) {
        Some(inner) => inner.replace("\"\"", "\"").trim().to_string(),
        None => field.to_string(),
    }
}

/// A csv crate error at `row` as one sentence.
fn csv_error(e: &csv::Error, row: usize) -> String {
    match e.kind() {
        csv::ErrorKind::Utf8 { .. } => format!("row {row}: not UTF-8 text"),
        csv::ErrorKind::Io(io) => format!("cannot read: {io}"),
        _ => format!("row {row}: not CSV: {e}"),
    }
}

/// A header or row as `VTX, IDX, ...`, at most 16 fields shown.
fn shown_list(fields: &[String]) -> String {
    const SHOWN: usize = 16;
    let mut s = fields.iter().take(SHOWN).cloned().collect::<Vec<_>>().join(", ");
    if fields.len() > SHOWN {
        s.push_str(&format!(", ... ({} columns)", fields.len()));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_is_the_f32_its_text_rounds_to() {
        let tenth = parse_value(" 0.1".trim(), false).unwrap();
        assert_eq!(tenth, BigRational::new(13421773.into(), 134217728.into()));
        assert_eq!(parse_value("0.1", true).unwrap(), BigRational::new(1.into(), 10.into()));
        assert_eq!(parse_value("NaN", false).unwrap_err(), "\"NaN\" is not a finite number");
        assert_eq!(
            parse_value("-inf", false).unwrap_err(),
            "\"-inf\" is not a finite number"
        );
        assert!(parse_value("1e39", false).unwrap_err().contains("beyond the f32 range"));
        assert_eq!(
            parse_value("1e39", true).unwrap().to_string(),
            format!("1{}", "0".repeat(39))
        );
        assert_eq!(parse_value("---", false).unwrap_err(), "\"---\" is not a number");
    }

    #[test]
    fn the_position_is_found_without_case() {
        let header: Vec<String> = [
            "VTX",
            "IDX",
            "gl_position.x",
            "gl_Position.y",
            "GL_POSITION.z",
            "gl_Position.w",
        ]
        .map(String::from)
        .to_vec();
        let cols = position_columns(&header, None).unwrap();
        assert_eq!(cols.index, [2, 3, 4, 5]);
        assert!(position_columns(&header, Some("SV_Position"))
            .unwrap_err()
            .starts_with("no SV_Position.x, SV_Position.y, SV_Position.z, SV_Position.w columns (--position); the header has VTX, IDX, gl_position.x"));
    }
}
