//! The map and the files agree, and no two files import each other in a circle.
//!
//! - Every `src/**/*.rs` file is named in ARCHITECTURE.md's file table, and every file the
//!   table names exists: a row's first cell is a folder (`` `src/tri/` ``), its second
//!   cell names files relative to it (`` `fixed.rs` ``, `` `suite/run.rs` ``); every test
//!   file the table names (`` `tests/planned.rs` ``, in any cell) exists too.
//! - No import circle between files: every path a file names through `crate::`, `super::`
//!   or `self::` (in `use` trees, types and expressions) is resolved to the file that
//!   defines the module it reaches, and the graph of those references, leaving out a
//!   file's references to its own ancestors and descendants (`mod.rs` and its children
//!   name each other by design), has no cycle. Two engines that share a kernel keep it in
//!   a third file both import.
//! - No source file cites a document outside the repository, and invariants are named,
//!   not numbered.

use std::collections::{BTreeMap, BTreeSet};

use super::{code_only, is_ident_char, rust_files};
use std::fs;
use std::path::Path;

/// The repository-relative paths (`src/tri/fixed.rs`) of every Rust file under `src/`.
pub(super) fn source_files(root: &Path) -> Vec<String> {
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    files
        .iter()
        .map(|f| {
            let relative = f.strip_prefix(root).expect("below the crate root");
            relative
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/")
        })
        .collect()
}

/// The backticked words of a Markdown table cell.
fn backticked(cell: &str) -> Vec<&str> {
    cell.split('`').skip(1).step_by(2).collect()
}

/// The files ARCHITECTURE.md's tables name: for every row whose first cell is a
/// backticked folder ending in `/`, that folder joined with each backticked `*.rs` word
/// of the row's second cell.
fn files_in_map(map: &str) -> BTreeSet<String> {
    let mut named = BTreeSet::new();
    for line in map.lines().map(str::trim).filter(|l| l.starts_with('|')) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').collect();
        let Some(folder) = cells
            .first()
            .and_then(|c| backticked(c).into_iter().find(|w| w.ends_with('/')))
        else {
            continue;
        };
        for word in cells.get(1).map(|c| backticked(c)).unwrap_or_default() {
            if word.ends_with(".rs") {
                named.insert(format!("{folder}{word}"));
            }
        }
    }
    named
}

/// What is wrong between the files under `src/` and the files the map names.
fn map_errors(files: &[String], map: &str) -> Vec<String> {
    let named = files_in_map(map);
    let present: BTreeSet<&String> = files.iter().collect();
    let mut errors: Vec<String> = files
        .iter()
        .filter(|f| !named.contains(*f))
        .map(|f| format!("{f} is not in ARCHITECTURE.md's file table"))
        .collect();
    errors.extend(
        named
            .iter()
            .filter(|f| f.starts_with("src/") && !present.contains(f))
            .map(|f| format!("ARCHITECTURE.md names {f}, which does not exist")),
    );
    errors
}

#[test]
fn every_source_file_is_on_the_map_and_the_map_names_no_other() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = source_files(root);
    let map = fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let mut errors = map_errors(&files, &map);
    let tests = map
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|w| w.starts_with("tests/") && w.ends_with(".rs"));
    errors.extend(
        tests
            .filter(|t| !root.join(t).is_file())
            .map(|t| format!("ARCHITECTURE.md names {t}, which does not exist")),
    );
    assert!(errors.is_empty(), "the map is not true:\n{}", errors.join("\n"));
}

/// A file's module path: `src/tri/fixed.rs` is `tri::fixed`, `src/tri/mod.rs` is `tri`,
/// `src/lib.rs` and `src/main.rs` the root.
fn module_of(file: &str) -> Vec<String> {
    let rest = file.strip_prefix("src/").unwrap_or(file).trim_end_matches(".rs");
    let mut parts: Vec<String> = rest.split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts
}

/// Every path named through `crate::`, `super::` or `self::` in `code` (already
/// [`code_only`]), as written: its leading keyword and the segments after it, one path
/// per leaf of a `use` tree (`use super::{a::B, c}` gives `super::a::B` and `super::c`).
fn named_paths(code: &str) -> Vec<Vec<String>> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if !is_ident_char(c[i]) || (i > 0 && (is_ident_char(c[i - 1]) || c[i - 1] == ':')) {
            i += 1;
            continue;
        }
        let end = (i..c.len()).find(|&e| !is_ident_char(c[e])).unwrap_or(c.len());
        let word: String = c[i..end].iter().collect();
        if matches!(word.as_str(), "crate" | "super" | "self") && c[end..].starts_with(&[':', ':']) {
            let (paths, next) = path_tree(&c, i, Vec::new());
            out.extend(paths);
            i = next.max(end);
        } else {
            i = end;
        }
    }
    out
}

/// The paths of the `use` tree (or plain path) starting at `k` under `prefix`, and the
/// index just past it.
pub(super) fn path_tree(c: &[char], mut k: usize, mut prefix: Vec<String>) -> (Vec<Vec<String>>, usize) {
    let skip = |mut k: usize| {
        while k < c.len() && c[k].is_whitespace() {
            k += 1;
        }
        k
    };
    loop {
        k = skip(k);
        match c.get(k) {
            Some('{') => {
                let mut paths = Vec::new();
                k += 1;
                loop {
                    k = skip(k);
                    match c.get(k) {
                        None => return (paths, k),
                        Some('}') => return (paths, k + 1),
                        Some(',') => k += 1,
                        Some(_) => {
                            let (inner, next) = path_tree(c, k, prefix.clone());
                            paths.extend(inner);
                            // An item that is not a path (`*`, `self as x`): step over it.
                            k = if next > k { next } else { k + 1 };
                        }
                    }
                }
            }
            Some(&ch) if is_ident_char(ch) => {
                let end = (k..c.len()).find(|&e| !is_ident_char(c[e])).unwrap_or(c.len());
                let word: String = c[k..end].iter().collect();
                if word != "self" || prefix.is_empty() {
                    prefix.push(word);
                }
                let after = skip(end);
                if c[after..].starts_with(&[':', ':']) {
                    k = after + 2;
                } else {
                    return (vec![prefix], end);
                }
            }
            _ => return (vec![prefix], k),
        }
    }
}

/// The module a path written in the module `at` reaches, before resolving it to a file.
fn absolute(at: &[String], path: &[String]) -> Vec<String> {
    let (mut base, mut rest): (Vec<String>, &[String]) = match path.first().map(String::as_str) {
        Some("crate") => (Vec::new(), &path[1..]),
        Some("self") => (at.to_vec(), &path[1..]),
        _ => (at.to_vec(), path),
    };
    while rest.first().map(String::as_str) == Some("super") {
        base.pop();
        rest = &rest[1..];
    }
    base.extend(rest.iter().cloned());
    base
}

/// The code of a file less its trailing `#[cfg(test)] mod tests { ... }` (where `super`
/// means the file itself).
fn without_tests(code: &str) -> &str {
    match code.find("#[cfg(test)]") {
        Some(at)
            if code[at..]
                .trim_start_matches("#[cfg(test)]")
                .trim_start()
                .starts_with("mod tests") =>
        {
            &code[..at]
        }
        _ => code,
    }
}

/// One edge of the import graph for each file-to-file reference that is neither to an
/// ancestor nor to a descendant.
fn import_graph(files: &BTreeMap<String, String>) -> BTreeMap<String, BTreeSet<String>> {
    let modules: BTreeMap<Vec<String>, &String> = files.keys().map(|f| (module_of(f), f)).collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, src) in files {
        let at = module_of(file);
        let code = code_only(src);
        for path in named_paths(without_tests(&code)) {
            let mut target = absolute(&at, &path);
            while !target.is_empty() && !modules.contains_key(&target) {
                target.pop();
            }
            let related = target.starts_with(&at) || at.starts_with(&target);
            if !related {
                graph.entry(file.clone()).or_default().insert(modules[&target].clone());
            }
        }
    }
    graph
}

/// Each circle of the graph once, as the files along it (`a -> b -> a`).
fn circles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let mut found = BTreeSet::new();
    for (from, tos) in graph {
        for to in tos {
            // A shortest way back from `to` to `from`, by breadth-first search.
            let mut before: BTreeMap<&String, &String> = BTreeMap::new();
            let mut queue = std::collections::VecDeque::from([to]);
            while let Some(n) = queue.pop_front() {
                if n == from {
                    break;
                }
                for m in graph.get(n).into_iter().flatten() {
                    if m != to && !before.contains_key(m) {
                        before.insert(m, n);
                        queue.push_back(m);
                    }
                }
            }
            if to == from || before.contains_key(from) {
                let mut way = vec![from.clone()];
                let mut n = from;
                while n != to {
                    n = before[n];
                    way.push(n.clone());
                }
                way.reverse();
                // One name per circle: start it at its smallest file.
                let start = way.iter().enumerate().min_by_key(|(_, f)| *f).map_or(0, |(k, _)| k);
                way.rotate_left(start);
                let first = way[0].clone();
                way.push(first);
                found.insert(way.join(" -> "));
            }
        }
    }
    found.into_iter().collect()
}

#[test]
fn no_two_files_import_each_other_in_a_circle() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files: BTreeMap<String, String> = source_files(root)
        .into_iter()
        .map(|f| {
            let src = fs::read_to_string(root.join(&f)).unwrap_or_else(|e| panic!("reading {f}: {e}"));
            (f, src)
        })
        .collect();
    let graph = import_graph(&files);
    assert!(graph.len() > 20, "the scanner found too few references: {graph:?}");
    let found = circles(&graph);
    assert!(
        found.is_empty(),
        "import circles (move what both files share into a third file):\n{}",
        found.join("\n")
    );
}

#[test]
fn sources_cite_no_outside_document_and_number_no_invariant() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = Vec::new();
    for f in source_files(root) {
        let src = fs::read_to_string(root.join(&f)).expect("readable");
        for (n, line) in src.lines().enumerate() {
            let numbered = line
                .match_indices("nvariant ")
                .any(|(k, _)| line[k + 9..].starts_with(|c: char| c.is_ascii_digit()));
            if line.contains("DESIGN.md") || numbered {
                found.push(format!("{f}:{}: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "cite a real source; name invariants:\n{}",
        found.join("\n")
    );
}

mod scanner {
    use super::*;

    fn files(list: &[(&str, &str)]) -> BTreeMap<String, String> {
        list.iter().map(|(f, s)| ((*f).to_string(), (*s).to_string())).collect()
    }

    #[test]
    fn a_missing_and_a_stale_file_are_named() {
        let map = "| folder | files |\n|---|---|\n| `src/` | `lib.rs`, `geom.rs` |\n| `src/tri/` | `mod.rs`, `fixed.rs` (blocks), `gone.rs` | `tests/tri.rs`, `blocks.rs` |\n| `src/harness/` | `suite/run.rs` |\n";
        let files: Vec<String> = [
            "src/lib.rs",
            "src/geom.rs",
            "src/tri/mod.rs",
            "src/tri/fixed.rs",
            "src/tri/blocks.rs",
            "src/harness/suite/run.rs",
        ]
        .map(String::from)
        .to_vec();
        assert_eq!(
            map_errors(&files, map),
            [
                "src/tri/blocks.rs is not in ARCHITECTURE.md's file table",
                "ARCHITECTURE.md names src/tri/gone.rs, which does not exist",
            ]
        );
    }

    #[test]
    fn use_trees_are_read_to_their_leaves() {
        let code = "use super::{fixed::BLOCK, planned::{self, Edges}};\nlet x = crate::num::plan::Lane::plus(a, b);\nuse self::inner::Y;\n";
        let got: Vec<String> = named_paths(code).iter().map(|p| p.join("::")).collect();
        assert_eq!(
            got,
            [
                "super::fixed::BLOCK",
                "super::planned",
                "super::planned::Edges",
                "crate::num::plan::Lane::plus",
                "self::inner::Y"
            ]
        );
    }

    #[test]
    fn a_circle_between_siblings_is_found_and_a_parent_child_pair_is_not() {
        let both = files(&[
            ("src/tri/mod.rs", "mod fixed; mod planned; pub use fixed::rasterize;"),
            (
                "src/tri/fixed.rs",
                "use super::planned::{traverse, Edges};\nuse super::Thing;",
            ),
            ("src/tri/planned.rs", "use crate::tri::fixed::BLOCK;"),
        ]);
        assert_eq!(
            circles(&import_graph(&both)),
            ["src/tri/fixed.rs -> src/tri/planned.rs -> src/tri/fixed.rs"]
        );
        let untied = files(&[
            ("src/tri/mod.rs", "mod blocks; mod fixed; mod planned;"),
            ("src/tri/blocks.rs", "use super::Thing;"),
            ("src/tri/fixed.rs", "use super::blocks::{traverse, Edges};"),
            ("src/tri/planned.rs", "use crate::tri::blocks::BLOCK;"),
        ]);
        assert_eq!(circles(&import_graph(&untied)), Vec::<String>::new());
    }

    #[test]
    fn a_longer_circle_and_one_through_tests_only() {
        let three = files(&[
            ("src/trade/measure.rs", "use super::plot::draw;"),
            ("src/trade/plot.rs", "use crate::trade::report::Metric;"),
            ("src/trade/report.rs", "fn f() { super::measure::UNIT }"),
        ]);
        assert_eq!(
            circles(&import_graph(&three)),
            ["src/trade/measure.rs -> src/trade/plot.rs -> src/trade/report.rs -> src/trade/measure.rs"]
        );
        let tests_only = files(&[
            (
                "src/a/x.rs",
                "use super::y::f;\n#[cfg(test)]\nmod tests { use super::super::y::g; }",
            ),
            (
                "src/a/y.rs",
                "pub fn f() {}\n#[cfg(test)]\nmod tests { use crate::a::x::h; }",
            ),
        ]);
        assert_eq!(circles(&import_graph(&tests_only)), Vec::<String>::new());
    }
}
