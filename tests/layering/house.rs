//! The house's rules above the layers, each a test that reads the sources:
//!
//! - **A thin CLI.** No file of `src/cli/` builds JSON by hand (`json!`, a
//!   `serde_json::Map`) or starts threads (`std::thread`, rayon): reports give
//!   their JSON, the library runs the threads. And each file of `src/cli/` names few
//!   library modules ([`cli_coupling`]: the distinct modules of the `rasterproof::` paths
//!   it names, each path counted at the deepest module it reaches), at most
//!   [`MOST_MODULES_PER_CLI_FILE`].
//! - **`Model` is asked, not matched.** Outside `src/model/` no code matches on a
//!   `Model` variant (`Model::X =>`, `Model::X | ...`, `matches!(m, Model::X)`) or reads a
//!   model's `arithmetic()`: what a caller needs to know of a model is a method of `Model`
//!   (`is_plain`, `is_integer`, `float_rule`, ...), so a new model is one more arm in
//!   `src/model/` only.
//! - **Threads start in three places.** `src/chunks.rs` (every map of a known set of items:
//!   rayon's pool, or threads of its own handed items in turn), `src/harness/runner.rs`
//!   (the case runner of the suite and the hunt) and `src/oracle/renderer/` (a reader
//!   thread per renderer process): no other file names `thread::scope`, `thread::spawn`,
//!   `thread::Builder`, `spawn_scoped` or rayon.
//! - **One comparison shape.** Every report type of `src/oracle/compare/` (a `pub struct`
//!   whose name ends in `Report`) implements `Comparison`, and the compiler checks that
//!   the reports the crate exports do (`comparison_reports_have_the_common_surface`).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

use super::code_only;
use super::map::{path_tree, source_files};

/// The most library modules one file of `src/cli/` may name (see [`cli_coupling`]).
const MOST_MODULES_PER_CLI_FILE: usize = 9;

/// What a file of `src/cli/` may not contain, in code (comments and strings blanked), and
/// why.
const NOT_IN_THE_CLI: &[(&str, &str)] = &[
    ("json!", "builds JSON by hand (the report's to_json gives it)"),
    ("serde_json::Map", "builds JSON by hand (the report's to_json gives it)"),
    ("thread::", "starts threads (the library's functions take `jobs`)"),
    ("rayon", "starts threads (the library's functions take `jobs`)"),
];

/// The breaches of [`NOT_IN_THE_CLI`] in one file's source, as `file:line: what (why)`.
fn cli_breaches(file: &str, src: &str) -> Vec<String> {
    let code = code_only(src);
    let mut out = Vec::new();
    for (n, line) in code.lines().enumerate() {
        for (what, why) in NOT_IN_THE_CLI {
            if line.contains(what) {
                out.push(format!("{file}:{}: `{what}` {why}", n + 1));
            }
        }
    }
    out
}

/// Whether `parts` names a module of the library: `src/a/b.rs` or `src/a/b/mod.rs`.
fn is_module(root: &Path, parts: &[String]) -> bool {
    let mut path = root.join("src");
    for p in parts {
        path.push(p);
    }
    path.with_extension("rs").is_file() || path.join("mod.rs").is_file()
}

/// The library modules one file's source names through `rasterproof::`: for each path (one
/// per leaf of a `use` tree), the deepest prefix that is a module of the library
/// (`rasterproof::oracle::compare::fit::samples::SampleFitOptions` counts as
/// `oracle::compare::fit::samples`).
fn modules_named(root: &Path, src: &str) -> BTreeSet<String> {
    let code = code_only(src);
    let c: Vec<char> = code.chars().collect();
    let key = "rasterproof::".len();
    let mut out = BTreeSet::new();
    let mut resume = 0;
    for i in word_starts(&c, "rasterproof::") {
        if i < resume {
            continue;
        }
        let (paths, next) = path_tree(&c, i + key, Vec::new());
        for path in paths {
            let deepest = (1..=path.len()).rev().find(|&k| is_module(root, &path[..k]));
            if let Some(k) = deepest {
                out.insert(path[..k].join("::"));
            }
        }
        resume = next.max(i + key);
    }
    out
}

/// Where `key` starts in `c` at the start of a word (no identifier character before it).
fn word_starts(c: &[char], key: &str) -> Vec<usize> {
    let key: Vec<char> = key.chars().collect();
    (0..(c.len() + 1).saturating_sub(key.len()))
        .filter(|&i| (i == 0 || !(c[i - 1].is_alphanumeric() || c[i - 1] == '_')) && c[i..i + key.len()] == key[..])
        .collect()
}

/// For each file of `src/cli/`, the library modules it names.
fn cli_coupling(root: &Path) -> BTreeMap<String, BTreeSet<String>> {
    source_files(root)
        .into_iter()
        .filter(|f| f.starts_with("src/cli/"))
        .map(|f| {
            let src = fs::read_to_string(root.join(&f)).unwrap_or_else(|e| panic!("reading {f}: {e}"));
            let modules = modules_named(root, &src);
            (f, modules)
        })
        .collect()
}

#[test]
fn the_cli_builds_no_json_and_starts_no_threads() {
    let all = found_in_sources(|f| f.starts_with("src/cli/"), cli_breaches);
    assert!(all.is_empty(), "the CLI computes:\n{}", all.join("\n"));
}

/// Prints each CLI file's coupling (`cargo test --test it house:: -- --nocapture`) and
/// holds it at most [`MOST_MODULES_PER_CLI_FILE`] per file.
#[test]
fn each_cli_file_names_few_library_modules() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let coupling = cli_coupling(root);
    assert!(
        coupling.len() >= 10,
        "found only {} files under src/cli/",
        coupling.len()
    );
    let mut every = BTreeSet::new();
    let mut over = Vec::new();
    for (file, modules) in &coupling {
        println!(
            "{:3} {file}: {}",
            modules.len(),
            modules.iter().cloned().collect::<Vec<_>>().join(" ")
        );
        every.extend(modules.iter().cloned());
        if modules.len() > MOST_MODULES_PER_CLI_FILE {
            over.push(format!("{file} names {} library modules", modules.len()));
        }
    }
    println!("{:3} distinct in all of src/cli/", every.len());
    assert!(
        over.is_empty(),
        "at most {MOST_MODULES_PER_CLI_FILE} library modules per CLI file:\n{}",
        over.join("\n")
    );
}

/// The places in one file's source that match on a `Model` variant or read a model's
/// arithmetic, as `file:line: what`.
fn model_matches(file: &str, src: &str) -> Vec<String> {
    let code = code_only(src);
    let mut out = Vec::new();
    for (n, line) in code.lines().enumerate() {
        let at = |what: &str| format!("{file}:{}: {what}", n + 1);
        if line.contains(".arithmetic()") {
            out.push(at("reads a model's arithmetic()"));
        }
        let c: Vec<char> = line.chars().collect();
        for i in word_starts(&c, "Model::") {
            let mut k = i + "Model::".len();
            let upper = c.get(k).is_some_and(|ch| ch.is_ascii_uppercase());
            while k < c.len() && (c[k].is_alphanumeric() || c[k] == '_') {
                k += 1;
            }
            let rest: String = c[k..].iter().collect::<String>().trim_start().to_string();
            let in_pattern = rest.starts_with("=>") || (rest.starts_with('|') && !rest.starts_with("||"));
            let before = &line[..line.char_indices().nth(i).map_or(line.len(), |(b, _)| b)];
            let in_matches = before.rfind("matches!(").is_some_and(|m| !before[m..].contains(')'));
            if upper && (in_pattern || in_matches) {
                out.push(at("matches on a Model variant"));
            }
        }
    }
    out.dedup();
    out
}

/// What `check` finds in every source file that `read` takes.
fn found_in_sources(read: impl Fn(&str) -> bool, check: fn(&str, &str) -> Vec<String>) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    for f in source_files(root).into_iter().filter(|f| read(f)) {
        let src = fs::read_to_string(root.join(&f)).unwrap_or_else(|e| panic!("reading {f}: {e}"));
        all.extend(check(&f, &src));
    }
    all
}

#[test]
fn no_code_outside_model_matches_on_a_model() {
    let all = found_in_sources(|f| !f.starts_with("src/model/"), model_matches);
    assert!(
        all.is_empty(),
        "ask the model (a method of Model in src/model/mod.rs) instead:\n{}",
        all.join("\n")
    );
}

/// The files that may start threads (see the module documentation).
const THREAD_PLACES: &[&str] = &["src/chunks.rs", "src/harness/runner.rs", "src/oracle/renderer/"];

/// The places in one file's source that start threads, as `file:line: what`.
fn threads_started(file: &str, src: &str) -> Vec<String> {
    let code = code_only(src);
    let mut out = Vec::new();
    for (n, line) in code.lines().enumerate() {
        for what in [
            "thread::scope",
            "thread::spawn",
            "thread::Builder",
            "spawn_scoped",
            "rayon",
        ] {
            if line.contains(what) {
                out.push(format!("{file}:{}: `{what}`", n + 1));
            }
        }
    }
    out
}

#[test]
fn threads_start_only_in_chunks_the_runner_and_the_renderer_processes() {
    let all = found_in_sources(|f| !THREAD_PLACES.iter().any(|p| f.starts_with(p)), threads_started);
    assert!(
        all.is_empty(),
        "map on threads through crate::chunks instead:\n{}",
        all.join("\n")
    );
}

#[test]
fn every_report_of_the_comparisons_implements_the_common_surface() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files: Vec<String> = source_files(root)
        .into_iter()
        .filter(|f| f.starts_with("src/oracle/compare/"))
        .collect();
    let mut code = String::new();
    for f in &files {
        code.push_str(&code_only(&fs::read_to_string(root.join(f)).expect("readable")));
    }
    let missing = reports_without_the_surface(&code);
    assert!(
        missing.is_empty(),
        "report types of src/oracle/compare/ that do not implement Comparison: {missing:?}"
    );
    assert!(reports(&code).len() >= 7, "found only {:?}", reports(&code));
}

/// The `pub struct NameReport` types of `code`.
fn reports(code: &str) -> Vec<String> {
    code.split("pub struct ")
        .skip(1)
        .filter_map(|rest| {
            let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            name.ends_with("Report").then_some(name)
        })
        .collect()
}

/// The report types of `code` with no `impl ... Comparison for Name` in it.
fn reports_without_the_surface(code: &str) -> Vec<String> {
    let flat: String = code.split_whitespace().collect::<Vec<_>>().join(" ");
    reports(code)
        .into_iter()
        .filter(|name| {
            !flat.split("impl ").any(|i| {
                i.split('{').next().is_some_and(|head| {
                    head.contains("Comparison for ") && head.trim_end().ends_with(&format!("for {name}"))
                })
            })
        })
        .collect()
}

/// The compiler's side: each report the crate exports is a `Comparison`.
#[test]
fn comparison_reports_have_the_common_surface() {
    use rasterproof::oracle::compare::conservative::ConservativeReport;
    use rasterproof::oracle::compare::fit::grey::GreyFitReport;
    use rasterproof::oracle::compare::fit::samples::SampleFitReport;
    use rasterproof::oracle::compare::grey::GreyReport;
    use rasterproof::oracle::compare::samples::SampleCompareReport;
    use rasterproof::oracle::{CompareReport, Comparison, FitReport, Judgement};
    fn surface<T: Comparison>() -> &'static str {
        std::any::type_name::<T>()
    }
    let names = [
        surface::<CompareReport>(),
        surface::<SampleCompareReport>(),
        surface::<GreyReport>(),
        surface::<ConservativeReport>(),
        surface::<FitReport>(),
        surface::<SampleFitReport>(),
        surface::<GreyFitReport>(),
        surface::<Judgement>(),
    ];
    assert!(
        names.iter().all(|n| n.starts_with("rasterproof::oracle::compare::")),
        "{names:?}"
    );
}

mod planted {
    use super::*;

    #[test]
    fn json_built_in_the_cli_is_found() {
        let src = "fn run() {\n    // json! in a comment is fine\n    let v = serde_json::json!({\"a\": 1});\n}\n";
        assert_eq!(
            cli_breaches("src/cli/x.rs", src),
            ["src/cli/x.rs:3: `json!` builds JSON by hand (the report's to_json gives it)"]
        );
    }

    #[test]
    fn threads_started_in_the_cli_are_found() {
        let src = "let s = \"thread::spawn\";\nstd::thread::scope(|s| {});\n";
        assert_eq!(
            cli_breaches("src/cli/x.rs", src),
            ["src/cli/x.rs:2: `thread::` starts threads (the library's functions take `jobs`)"]
        );
    }

    #[test]
    fn a_match_on_a_model_is_found() {
        let src = "match model {\n    Model::Exact => 1,\n    _ => 2,\n}\nlet p = matches!(m, Model::ExactPlain);\nlet q = m.arithmetic();\nlet r = m == Model::Fixed || m == Model::Scanline;\nlet s = AreaModel::Plain | AreaModel::Cells;\n";
        assert_eq!(
            model_matches("src/x.rs", src),
            [
                "src/x.rs:2: matches on a Model variant",
                "src/x.rs:5: matches on a Model variant",
                "src/x.rs:6: reads a model's arithmetic()",
            ]
        );
        let alternatives = "m @ (Model::Exact | Model::ExactSnapped) => m,\n";
        assert_eq!(
            model_matches("src/y.rs", alternatives),
            ["src/y.rs:1: matches on a Model variant"]
        );
    }

    #[test]
    fn a_thread_started_elsewhere_is_found() {
        let src =
            "let v = std::thread::scope(|s| s.spawn(|| 1).join());\n// rayon in a comment\nuse rayon::prelude::*;\n";
        assert_eq!(
            threads_started("src/x.rs", src),
            ["src/x.rs:1: `thread::scope`", "src/x.rs:3: `rayon`"]
        );
    }

    #[test]
    fn a_report_without_the_surface_is_found() {
        let code = "pub struct AReport { x: u32 }\nimpl Comparison for AReport {}\npub struct BReport;\nimpl B for BReport {}\npub struct Other;\n";
        assert_eq!(reports(code), ["AReport", "BReport"]);
        assert_eq!(reports_without_the_surface(code), ["BReport"]);
    }

    #[test]
    fn modules_are_counted_at_their_deepest() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let src = "use rasterproof::oracle::compare::fit::samples::{SampleFitOptions, POSITION_GRID};\nuse rasterproof::{model::Model, scene};\nlet x = rasterproof::num::exact::exact_text(&y);\n";
        let named: Vec<String> = modules_named(root, src).into_iter().collect();
        assert_eq!(named, ["model", "num::exact", "oracle::compare::fit::samples", "scene"]);
    }
}
