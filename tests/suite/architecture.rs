//! `docs/ARCHITECTURE.md` stays true: it names every module of `src/lib.rs`, every file and
//! folder directly under `src/` and every folder deeper down; every `src/` path it names
//! exists; and its table of who imports whom is the one the code has (`crate::` paths outside
//! comments and test modules).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const REPO: &str = env!("CARGO_MANIFEST_DIR");

fn doc() -> String {
    std::fs::read_to_string(Path::new(REPO).join("docs/ARCHITECTURE.md")).expect("docs/ARCHITECTURE.md")
}

fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '/' || c == '.'
}

/// Every `src/...` path the text names, whole (`src/params/` is not found in `src/params/bpx/`).
fn named_paths(text: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    for (at, _) in text.match_indices("src/") {
        if text[..at].chars().next_back().is_some_and(is_path_char) {
            continue;
        }
        let path: String = text[at..].chars().take_while(|c| is_path_char(*c)).collect();
        found.insert(path.trim_end_matches('.').to_string());
    }
    found
}

/// The modules `src/lib.rs` declares.
fn lib_modules() -> Vec<String> {
    let lib = std::fs::read_to_string(Path::new(REPO).join("src/lib.rs")).unwrap();
    lib.lines()
        .filter_map(|l| {
            let l = l.trim().trim_start_matches("pub(crate) ").trim_start_matches("pub ");
            l.strip_prefix("mod ").and_then(|m| m.strip_suffix(';')).map(|m| m.trim().to_string())
        })
        .collect()
}

/// A module's path as the document names it: `src/NAME/` for a folder, else `src/NAME.rs`.
fn module_path(name: &str) -> String {
    if Path::new(REPO).join("src").join(name).is_dir() { format!("src/{name}/") } else { format!("src/{name}.rs") }
}

/// Folders below `dir`, at any depth, as `src/...` paths ending in `/`.
fn folders(dir: &Path, out: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            out.push(format!("{}/", path.strip_prefix(REPO).unwrap().display()));
            folders(&path, out);
        }
    }
}

#[test]
fn architecture_names_every_module_file_and_folder() {
    let named = named_paths(&doc());
    let src = Path::new(REPO).join("src");
    let mut wanted: Vec<String> = lib_modules().iter().map(|m| module_path(m)).collect();
    for entry in std::fs::read_dir(&src).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        wanted.push(if path.is_dir() { format!("src/{name}/") } else { format!("src/{name}") });
    }
    folders(&src, &mut wanted);
    let missing: BTreeSet<&String> = wanted.iter().filter(|p| !named.contains(*p)).collect();
    assert!(missing.is_empty(), "docs/ARCHITECTURE.md does not name {missing:?}");
    let stale: Vec<&String> = named.iter().filter(|p| !Path::new(REPO).join(p).exists()).collect();
    assert!(stale.is_empty(), "docs/ARCHITECTURE.md names paths that do not exist: {stale:?}");
}

/// The `.rs` files of a module (a file, or every file of a folder).
fn module_files(path: &str) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let full = Path::new(REPO).join(path);
    let mut out = Vec::new();
    if full.is_dir() { walk(&full, &mut out) } else { out.push(full) }
    out
}

/// The top-level modules a module's code imports from (`crate::X`, `cellstudio::X`, and the
/// names inside `crate::{...}`), outside comments and `#[cfg(test)]` modules; `Error` and
/// `Result` re-exported at the root count as `error`.
fn imports(path: &str, modules: &BTreeSet<String>) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let mut name_at = |word: &str| {
        let word = if word == "Error" || word == "Result" { "error" } else { word };
        if modules.contains(word) {
            found.insert(word.to_string());
        }
    };
    for file in module_files(path) {
        let text = std::fs::read_to_string(&file).unwrap();
        let code: String = text
            .lines()
            .take_while(|l| !l.trim_start().starts_with("#[cfg(test)]"))
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        for root in ["crate::", "cellstudio::"] {
            for (at, _) in code.match_indices(root) {
                if code[..at].chars().next_back().is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
                    continue;
                }
                let rest = &code[at + root.len()..];
                if let Some(group) = rest.strip_prefix('{') {
                    // The first name of every item at the group's own depth.
                    let (mut depth, mut item_start) = (0usize, true);
                    let mut word = String::new();
                    for c in group.chars() {
                        if c.is_ascii_alphanumeric() || c == '_' {
                            if item_start {
                                word.push(c);
                            }
                            continue;
                        }
                        if !word.is_empty() {
                            name_at(&word);
                            word.clear();
                            item_start = false;
                        }
                        match c {
                            '{' => depth += 1,
                            '}' if depth == 0 => break,
                            '}' => depth -= 1,
                            ',' if depth == 0 => item_start = true,
                            _ => {}
                        }
                    }
                } else {
                    let word: String = rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
                    name_at(&word);
                }
            }
        }
    }
    found
}

#[test]
fn architecture_import_table_matches_the_code() {
    let doc = doc();
    let modules: BTreeSet<String> = lib_modules().into_iter().collect();
    // Rows `| \`src/...\`[, ...] | names |` of the table under "## Layers".
    let layers = &doc[doc.find("## Layers").expect("a Layers section")..];
    let layers = &layers[..layers[3..].find("\n## ").map_or(layers.len(), |k| k + 3)];
    let mut claimed: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for row in layers.lines().filter(|l| l.starts_with("| `src/")) {
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let names: BTreeSet<String> = cells[2]
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .filter(|w| modules.contains(*w) && *w != "error")
            .map(str::to_string)
            .collect();
        for path in named_paths(cells[1]) {
            claimed.insert(path, names.clone());
        }
    }
    let mut wanted: Vec<String> = lib_modules().iter().map(|m| module_path(m)).collect();
    wanted.push("src/main.rs".into());
    let mut wrong = Vec::new();
    for path in wanted {
        let Some(claim) = claimed.get(&path) else {
            wrong.push(format!("{path}: no row in the table"));
            continue;
        };
        let own = path.trim_start_matches("src/").trim_end_matches('/').trim_end_matches(".rs");
        let mut actual = imports(&path, &modules);
        actual.remove(own);
        actual.remove("error");
        if &actual != claim {
            let extra: Vec<&String> = actual.difference(claim).collect();
            let gone: Vec<&String> = claim.difference(&actual).collect();
            wrong.push(format!("{path}: the code also imports {extra:?}, no longer imports {gone:?}"));
        }
    }
    assert!(wrong.is_empty(), "docs/ARCHITECTURE.md's import table is out of date:\n{}", wrong.join("\n"));
}
