//! The manifest `.cellstudio-outputs`: the files a run wrote into its output folder, one
//! relative path a line.
//!
//! The manifest is a file in the user's folder, so it is read as a claim, never trusted: a
//! listed entry is removed as stale only when [`removable`] finds it is a plain relative path
//! naming a regular file (not a link, not a folder) strictly inside the folder, reached
//! through no link, and none of the run's inputs. Anything else is left as it is, with a
//! warning naming the entry.

use std::collections::BTreeSet;
use std::io::ErrorKind;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// Name of the manifest listing the files a run wrote into its output folder.
pub const MANIFEST: &str = ".cellstudio-outputs";

/// The entries `dir`'s manifest lists (none when it has none); the manifest's own name is
/// never an entry.
pub(super) fn read(dir: &Path) -> BTreeSet<String> {
    std::fs::read_to_string(dir.join(MANIFEST))
        .map(|t| t.lines().filter(|l| !l.is_empty() && *l != MANIFEST).map(str::to_string).collect())
        .unwrap_or_default()
}

/// Writes the manifest of `files` into `dir` (a staging folder this run created, so no link
/// of the user's can redirect the write).
pub(super) fn write(dir: &Path, files: &BTreeSet<String>) -> Result<()> {
    let text: String = files.iter().map(|f| format!("{f}\n")).collect();
    crate::error::write_file(&dir.join(MANIFEST), text)
}

/// The path of `entry`, listed in the manifest of `dir`, when the run may remove it as a stale
/// result: `Ok(None)` when it no longer exists, `Err(why not)` when it breaks a rule.
/// `inputs` are the run's inputs, canonicalised.
pub(super) fn removable(dir: &Path, entry: &str, inputs: &[PathBuf]) -> std::result::Result<Option<PathBuf>, &'static str> {
    if !super::is_plain_relative(entry) {
        return Err("not a plain relative path");
    }
    let path = dir.join(entry);
    match path.symlink_metadata() {
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(None),
        Err(_) => return Err("unreadable"),
        Ok(meta) if !meta.is_file() => return Err("not a regular file (a folder or a link)"),
        Ok(_) => {}
    }
    let resolved = path.canonicalize().map_err(|_| "unreadable")?;
    let inside = dir.canonicalize().map_err(|_| "unreadable")?.join(entry);
    if resolved != inside {
        return Err("reached through a link, not a file of the folder itself");
    }
    if inputs.contains(&resolved) {
        return Err("one of this run's inputs");
    }
    Ok(Some(path))
}

/// Removes the `stale` entries of `dir`'s manifest that [`removable`] allows; every other
/// entry is left, with a warning on stderr naming it. A file that cannot be removed is a
/// warning too: the new results are already in place.
pub(super) fn remove_stale<'a>(dir: &Path, stale: impl Iterator<Item = &'a String>, inputs: &[PathBuf]) {
    for entry in stale {
        match removable(dir, entry, inputs) {
            Ok(None) => {}
            Ok(Some(path)) => {
                if let Err(e) = std::fs::remove_file(&path) {
                    eprintln!("warning: could not remove the stale result `{}`: {e}", path.display());
                }
            }
            Err(why) => eprintln!(
                "warning: `{}` lists `{entry}`, which is {why}: left as it is",
                dir.join(MANIFEST).display()
            ),
        }
    }
}

/// Rejects a run whose result `name` (a plain relative path) cannot replace what is at
/// `dir/name`: `None` when it may (nothing there, or a regular file an earlier run listed in
/// `listed`), else why not.
pub(super) fn replace_problem(dir: &Path, name: &str, listed: &BTreeSet<String>) -> Option<String> {
    let path = dir.join(name);
    // Each folder on the way must be a real folder of `dir` (not a link out of it) or absent.
    let mut on_the_way = path.parent();
    while let Some(folder) = on_the_way.filter(|f| *f != dir) {
        if folder.symlink_metadata().is_ok_and(|m| !m.is_dir()) {
            return Some(format!("`{}` is not a folder (a file or a link)", folder.display()));
        }
        on_the_way = folder.parent();
    }
    match path.symlink_metadata() {
        Err(_) => None,
        Ok(meta) if !meta.is_file() => Some(not_a_file(&path)),
        Ok(_) if !listed.contains(name) => {
            Some(format!("`{}` would be replaced but no earlier cellstudio run wrote it (not in `{MANIFEST}`)", path.display()))
        }
        Ok(_) => None,
    }
}

/// Why `path` cannot be replaced: something other than a regular file is there.
fn not_a_file(path: &Path) -> String {
    format!("`{}` is not a regular file (a folder or a link)", path.display())
}

/// Fails, naming every destination, when any of `names` or the manifest itself cannot replace
/// what is in `dir` (whose manifest lists `listed`).
pub(super) fn check_destinations(dir: &Path, names: &BTreeSet<String>, listed: &BTreeSet<String>) -> Result<()> {
    let mut problems: Vec<String> = names.iter().filter_map(|n| replace_problem(dir, n, listed)).collect();
    let manifest = dir.join(MANIFEST);
    if manifest.symlink_metadata().is_ok_and(|m| !m.is_file()) {
        problems.push(not_a_file(&manifest));
    }
    if problems.is_empty() {
        return Ok(());
    }
    Err(Error::InvalidSetting {
        field: "output folder".into(),
        reason: format!(
            "{}; move it or choose another output folder (nothing was moved: the previous results are as they were)",
            problems.join("; ")
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("cellstudio-manifest-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(d.join("out/sub")).unwrap();
        d
    }

    #[test]
    fn only_plain_regular_files_of_the_folder_itself_are_removable() {
        let root = scratch("rules");
        let out = root.join("out");
        std::fs::write(root.join("outside.txt"), "x").unwrap();
        std::fs::write(out.join("old.svg"), "x").unwrap();
        std::fs::write(out.join("sub/old.csv"), "x").unwrap();
        std::fs::write(out.join("input.csv"), "x").unwrap();
        std::os::unix::fs::symlink("../outside.txt", out.join("link.txt")).unwrap();
        std::os::unix::fs::symlink("sub", out.join("alias")).unwrap();
        let absolute = root.join("outside.txt");
        let input = out.join("input.csv").canonicalize().unwrap();
        let rule = |entry: &str| removable(&out, entry, std::slice::from_ref(&input));
        assert_eq!(rule("old.svg"), Ok(Some(out.join("old.svg"))));
        assert_eq!(rule("sub/old.csv"), Ok(Some(out.join("sub/old.csv"))));
        assert_eq!(rule("gone.svg"), Ok(None));
        assert_eq!(rule(absolute.to_str().unwrap()), Err("not a plain relative path"));
        assert_eq!(rule("../outside.txt"), Err("not a plain relative path"));
        assert_eq!(rule("sub/../old.svg"), Err("not a plain relative path"));
        assert_eq!(rule("link.txt"), Err("not a regular file (a folder or a link)"));
        assert_eq!(rule("sub"), Err("not a regular file (a folder or a link)"));
        assert_eq!(rule("alias/old.csv"), Err("reached through a link, not a file of the folder itself"));
        assert_eq!(rule("input.csv"), Err("one of this run's inputs"));
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_destination_must_be_absent_or_a_listed_regular_file() {
        let root = scratch("dest");
        let out = root.join("out");
        std::fs::write(out.join("ours.svg"), "x").unwrap();
        std::fs::write(out.join("mine.txt"), "x").unwrap();
        std::fs::create_dir(out.join("dir.svg")).unwrap();
        std::os::unix::fs::symlink("/tmp", out.join("plots")).unwrap();
        let listed: BTreeSet<String> = ["ours.svg", "dir.svg", "plots/v.svg"].map(String::from).into();
        assert_eq!(replace_problem(&out, "ours.svg", &listed), None);
        assert_eq!(replace_problem(&out, "new.svg", &listed), None);
        assert_eq!(replace_problem(&out, "sub/new.svg", &listed), None);
        assert!(replace_problem(&out, "mine.txt", &listed).unwrap().contains("no earlier cellstudio run wrote it"));
        assert!(replace_problem(&out, "dir.svg", &listed).unwrap().contains("not a regular file"));
        assert!(replace_problem(&out, "plots/v.svg", &listed).unwrap().contains("plots` is not a folder"));
        // A manifest that is not a file would stop the run after the moves: it is checked too.
        let new: BTreeSet<String> = ["ours.svg".to_string()].into();
        assert!(check_destinations(&out, &new, &listed).is_ok());
        std::fs::create_dir(out.join(MANIFEST)).unwrap();
        let e = check_destinations(&out, &new, &listed).unwrap_err().to_string();
        assert!(e.contains(".cellstudio-outputs` is not a regular file") && e.contains("nothing was moved"), "{e}");
        std::fs::remove_dir_all(&root).unwrap();
    }
}
