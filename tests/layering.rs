//! The layering test: the library's top-level modules form layers, and nothing imports
//! upward. Every `src/**/*.rs` file is read, its comments and string literals blanked, and
//! every `crate::X` path (in `use` lines, types and expressions, and the names inside a
//! grouped `use crate::{X, Y::Z}`) is checked against [`LAYERS`]: a file of layer M may
//! name modules of layer M or below, never above. `src/lib.rs` (the crate root, which
//! names every module), `src/main.rs` and `src/cli/` (the binary, which sees the library
//! as `rasterproof::`) are outside the table and not read.

use std::fs;
use std::path::{Path, PathBuf};

#[path = "layering/house.rs"]
mod house;
#[path = "layering/map.rs"]
mod map;

/// The layers, bottom first. A module may use its own layer and the ones below it.
/// A new top-level module must be added here, in the layer it belongs to (the test fails
/// for a file, or a `crate::X` reference, whose module is not in this table).
const LAYERS: &[(u32, &[&str])] = &[
    (0, &["num", "chunks"]),
    (1, &["geom", "convention", "raster", "pattern"]),
    (2, &["coverage", "edge"]),
    (3, &["tri", "line", "clip", "fill", "interp", "area"]),
    (4, &["model"]),
    (5, &["check"]),
    (6, &["strategy", "scene", "import"]),
    (7, &["oracle", "trade", "harness"]),
];

/// Top-level modules of the binary (`src/main.rs`'s children), outside the table.
const BINARY: &[&str] = &["cli"];

fn layer_of(module: &str) -> Option<u32> {
    LAYERS
        .iter()
        .find(|(_, modules)| modules.contains(&module))
        .map(|(layer, _)| *layer)
}

/// Where a file stands, from its path below the crate root (`src/a/b.rs`).
#[derive(Debug, PartialEq, Eq)]
enum FileKind {
    /// `src/lib.rs`, `src/main.rs`, `src/cli/...`: not checked.
    Outside,
    /// A library file, in the top-level module named here (`src/X.rs`, `src/X/...`).
    Module(String),
}

fn file_kind(path: &str) -> FileKind {
    let rest = path.strip_prefix("src/").unwrap_or(path);
    let first = rest.split('/').next().unwrap_or(rest);
    let module = first.strip_suffix(".rs").unwrap_or(first);
    if rest == "lib.rs" || rest == "main.rs" || BINARY.contains(&module) {
        FileKind::Outside
    } else {
        FileKind::Module(module.to_string())
    }
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The source with comments (`//`, `///`, `//!`, nested `/* */`) and string and char
/// literals (plain, byte, raw) replaced by spaces; newlines are kept, so line numbers and
/// everything outside those stays where it was.
fn code_only(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let blank = |out: &mut String, ch: char| out.push(if ch == '\n' { '\n' } else { ' ' });
    let at = |i: usize| c.get(i).copied();
    let mut i = 0;
    while i < c.len() {
        let (ch, next) = (c[i], at(i + 1));
        if ch == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                blank(&mut out, c[i]);
                i += 1;
            }
        } else if ch == '/' && next == Some('*') {
            let mut depth = 0usize;
            while i < c.len() {
                let pair = (c[i], at(i + 1));
                if pair == ('/', Some('*')) || pair == ('*', Some('/')) {
                    depth = if c[i] == '/' { depth + 1 } else { depth - 1 };
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
        } else if let Some(end) = raw_string_end(&c, i) {
            for &ch in &c[i..end] {
                blank(&mut out, ch);
            }
            i = end;
        } else if ch == '"' {
            blank(&mut out, ch);
            i += 1;
            while i < c.len() {
                let (ch, escaped) = (c[i], c[i] == '\\');
                blank(&mut out, ch);
                i += 1;
                if escaped {
                    if let Some(&e) = c.get(i) {
                        blank(&mut out, e);
                        i += 1;
                    }
                } else if ch == '"' {
                    break;
                }
            }
        } else if ch == '\'' && (next == Some('\\') || at(i + 2) == Some('\'')) {
            // A char literal ('x', '\n', '\'', '\u{..}'); a lone ' is a lifetime or label.
            let mut j = if next == Some('\\') { i + 3 } else { i + 2 };
            while j < c.len() && c[j] != '\'' && c[j] != '\n' {
                j += 1;
            }
            let end = (j + 1).min(c.len());
            for &ch in &c[i..end] {
                blank(&mut out, ch);
            }
            i = end;
        } else {
            out.push(ch);
            i += 1;
        }
    }
    out
}

/// If a raw string literal (`r"…"`, `r#"…"#`, `br"…"`, `cr"…"`) starts at `i`, the index
/// just past its end.
fn raw_string_end(c: &[char], i: usize) -> Option<usize> {
    let before = |k: usize| k.checked_sub(1).map(|p| c[p]);
    let starts_token = |k: usize| !matches!(before(k), Some(p) if is_ident_char(p));
    let prefix_ok = starts_token(i) || (matches!(before(i), Some('b' | 'c')) && starts_token(i - 1));
    if c[i] != 'r' || !prefix_ok {
        return None;
    }
    let mut j = i + 1;
    while c.get(j) == Some(&'#') {
        j += 1;
    }
    if c.get(j) != Some(&'"') {
        return None;
    }
    let hashes = j - i - 1;
    let mut k = j + 1;
    while k < c.len() {
        if c[k] == '"' && (1..=hashes).all(|h| c.get(k + h) == Some(&'#')) {
            return Some(k + 1 + hashes);
        }
        k += 1;
    }
    Some(c.len())
}

/// One `crate::X` reference: the 1-based line of `X` and the name (`*` for a glob).
#[derive(Debug, PartialEq, Eq)]
struct Reference {
    line: usize,
    module: String,
}

/// Every top-level module named through `crate::` in `code` (already [`code_only`]):
/// `crate::X…` anywhere and each item of `crate::{X, Y::Z, …}`, across lines.
fn crate_references(code: &str) -> Vec<Reference> {
    let c: Vec<char> = code.chars().collect();
    let line_at = |k: usize| 1 + c[..k].iter().filter(|&&ch| ch == '\n').count();
    let skip_space = |mut k: usize| {
        while k < c.len() && c[k].is_whitespace() {
            k += 1;
        }
        k
    };
    let ident_at = |k: usize| {
        let end = (k..c.len()).find(|&e| !is_ident_char(c[e])).unwrap_or(c.len());
        c[k..end].iter().collect::<String>()
    };
    let mut found = Vec::new();
    let mut push = |k: usize, name: String| {
        if !name.is_empty() && name != "self" {
            found.push(Reference {
                line: line_at(k),
                module: name,
            });
        }
    };
    let word = ['c', 'r', 'a', 't', 'e'];
    for i in 0..c.len() {
        let is_word = c[i..].starts_with(&word)
            && (i == 0 || !is_ident_char(c[i - 1]))
            && !matches!(c.get(i + word.len()), Some(&n) if is_ident_char(n));
        if !is_word {
            continue;
        }
        let k = skip_space(i + word.len());
        if !c[k..].starts_with(&[':', ':']) {
            continue;
        }
        let k = skip_space(k + 2);
        match c.get(k) {
            Some('*') => push(k, "*".to_string()),
            Some('{') => {
                // Each item of the group: its first name, at nesting depth 1.
                let (mut depth, mut item_start, mut j) = (1usize, true, k + 1);
                while j < c.len() && depth > 0 {
                    let ch = c[j];
                    if item_start && !ch.is_whitespace() {
                        item_start = false;
                        if ch == '*' {
                            push(j, "*".to_string());
                        } else if is_ident_char(ch) {
                            push(j, ident_at(j));
                        }
                    }
                    match ch {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 1 => item_start = true,
                        _ => {}
                    }
                    j += 1;
                }
            }
            Some(&ch) if is_ident_char(ch) => push(k, ident_at(k)),
            _ => {}
        }
    }
    found
}

/// The layering violations of one file, `path` being `src/a/b.rs` and `src` its text.
fn violations(path: &str, src: &str) -> Vec<String> {
    let module = match file_kind(path) {
        FileKind::Outside => return Vec::new(),
        FileKind::Module(module) => module,
    };
    let Some(own) = layer_of(&module) else {
        return vec![format!(
            "{path}: module `{module}` is not in the layer table; add it to the table in tests/layering.rs"
        )];
    };
    let mut out = Vec::new();
    for Reference { line, module: target } in crate_references(&code_only(src)) {
        match layer_of(&target) {
            Some(layer) if layer > own => {
                out.push(format!(
                    "{path}:{line}: crate::{target} (layer {layer}) from layer {own}"
                ));
            }
            Some(_) => {}
            None if target == "*" => out.push(format!(
                "{path}:{line}: crate::* (a glob of the crate root) from layer {own}; name the modules"
            )),
            None => out.push(format!(
                "{path}:{line}: crate::{target} is not in the layer table; add it to the table in tests/layering.rs"
            )),
        }
    }
    out
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|ext| ext == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_module_imports_upward() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    assert!(files.len() > 10, "found only {} files under src/", files.len());
    let mut all = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(root).expect("below the crate root");
        let path: Vec<String> = relative
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        let src = fs::read_to_string(file).unwrap_or_else(|e| panic!("reading {}: {e}", file.display()));
        all.extend(violations(&path.join("/"), &src));
    }
    assert!(
        all.is_empty(),
        "{} layering violation(s) (layers in tests/layering.rs):\n{}",
        all.len(),
        all.join("\n")
    );
}

#[test]
fn the_table_names_each_module_once() {
    let mut names: Vec<&str> = LAYERS.iter().flat_map(|(_, modules)| modules.iter().copied()).collect();
    let count = names.len();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), count, "a module is in two layers");
    assert!(
        LAYERS.windows(2).all(|w| w[0].0 < w[1].0),
        "layers are listed bottom first"
    );
}

mod scanner {
    use super::*;

    #[test]
    fn an_upward_use_is_found() {
        let v = violations("src/clip/x.rs", "use crate::geom::Point;\nuse crate::scene::Scene;\n");
        assert_eq!(v, ["src/clip/x.rs:2: crate::scene (layer 6) from layer 3"]);
    }

    #[test]
    fn a_grouped_use_is_found() {
        let v = violations("src/clip/x.rs", "use crate::{geom::Point, scene};\n");
        assert_eq!(v, ["src/clip/x.rs:1: crate::scene (layer 6) from layer 3"]);
    }

    #[test]
    fn a_grouped_use_across_lines_is_found_on_its_line() {
        let src = "use crate::{\n    geom::{Point, Triangle},\n    model::{self, Model},\n    check::Violation,\n};\n";
        let v = violations("src/tri/exact.rs", src);
        assert_eq!(
            v,
            [
                "src/tri/exact.rs:3: crate::model (layer 4) from layer 3",
                "src/tri/exact.rs:4: crate::check (layer 5) from layer 3",
            ]
        );
    }

    #[test]
    fn a_path_in_an_expression_or_type_is_found() {
        let src = "fn f() -> Result<(), crate::check::Violation> {\n    Err(crate::check::Violation::new(1, 2))\n}\n";
        let v = violations("src/clip/mod.rs", src);
        assert_eq!(
            v,
            [
                "src/clip/mod.rs:1: crate::check (layer 5) from layer 3",
                "src/clip/mod.rs:2: crate::check (layer 5) from layer 3",
            ]
        );
    }

    #[test]
    fn comments_do_not_count() {
        let src = "//! Built on [`crate::model`].\n/// See [`crate::scene::Scene`].\n// crate::check is above us\nlet x = 1; // and crate::scene too\n/* crate::model /* nested crate::check */ crate::scene */\n";
        assert_eq!(violations("src/tri/mod.rs", src), Vec::<String>::new());
    }

    #[test]
    fn strings_do_not_count_and_do_not_hide_code() {
        let src = "let a = \"crate::scene\"; let b = r#\"crate::check \"//\"#;\nlet c = \"//\"; crate::model::render();\nlet d = '\"'; crate::scene::parse();\n";
        let v = violations("src/clip/mod.rs", src);
        assert_eq!(
            v,
            [
                "src/clip/mod.rs:2: crate::model (layer 4) from layer 3",
                "src/clip/mod.rs:3: crate::scene (layer 6) from layer 3",
            ]
        );
    }

    #[test]
    fn lifetimes_are_not_char_literals() {
        let src = "fn f<'a>(x: &'a str) -> &'a str { x }\nuse crate::scene::Scene;\n";
        assert_eq!(
            violations("src/clip/x.rs", src),
            ["src/clip/x.rs:2: crate::scene (layer 6) from layer 3"]
        );
    }

    #[test]
    fn downward_and_same_layer_references_are_allowed() {
        let src = "use crate::geom::Point;\nuse crate::{num::SubPixel, coverage::CoverageSink, self};\nlet r = crate::tri::saturating_index(3);\npub(crate) fn g() {}\n";
        assert_eq!(violations("src/line/exact.rs", src), Vec::<String>::new());
    }

    #[test]
    fn modules_outside_the_table_fail() {
        let file = violations("src/render.rs", "use crate::geom::Point;\n");
        assert_eq!(file.len(), 1);
        assert!(
            file[0].starts_with("src/render.rs: module `render` is not in the layer table"),
            "{file:?}"
        );
        assert!(file[0].ends_with("add it to the table in tests/layering.rs"));
        let reference = violations("src/scene/mod.rs", "use crate::render::render;\n");
        assert_eq!(
            reference,
            ["src/scene/mod.rs:1: crate::render is not in the layer table; add it to the table in tests/layering.rs"]
        );
    }

    #[test]
    fn the_binary_and_the_root_are_not_checked() {
        assert_eq!(file_kind("src/lib.rs"), FileKind::Outside);
        assert_eq!(file_kind("src/main.rs"), FileKind::Outside);
        assert_eq!(file_kind("src/cli/check.rs"), FileKind::Outside);
        assert_eq!(file_kind("src/geom.rs"), FileKind::Module("geom".into()));
        assert_eq!(file_kind("src/check/harness.rs"), FileKind::Module("check".into()));
        assert_eq!(file_kind("src/fill/flood/png.rs"), FileKind::Module("fill".into()));
        assert_eq!(
            violations("src/lib.rs", "pub use crate::scene::Scene;"),
            Vec::<String>::new()
        );
    }

    #[test]
    fn code_only_keeps_lines_and_code() {
        let src = "a // b\n/* c\nd */ e \"f\ng\" h 'i' 'j\n";
        let code = code_only(src);
        assert_eq!(code.lines().count(), src.lines().count());
        let words: Vec<&str> = code.split_whitespace().collect();
        assert_eq!(words, ["a", "e", "h", "'j"]);
    }

    #[test]
    fn other_crates_and_extern_crate_are_not_references() {
        let src = "extern crate alloc;\nuse rasterproof::scene::Scene;\nuse mycrate::scene;\nlet x = crate_::scene;\n";
        assert_eq!(crate_references(&code_only(src)), Vec::<Reference>::new());
    }
}
