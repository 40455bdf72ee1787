//! The manifest `.cellstudio-outputs`: the files a run wrote into its output folder, one a
//! line with the SHA-256 of the content written, as `sha256sum` writes them (`HASH  PATH`).
//!
//! The manifest is a file in the user's folder, so it is read as a claim, never trusted: a
//! listed entry is removed as stale only when [`removable`] finds it is a plain relative path
//! naming a regular file (not a link, not a folder) strictly inside the folder, reached
//! through no link, none of the run's inputs, and still holding the content the manifest's
//! hash records. Anything else is left as it is, with a warning naming the entry. A listed
//! result whose content changed since it was written (the user edited it) is never replaced
//! ([`replace_problem`]). An entry without a hash (a manifest written before hashes were kept)
//! is taken as unchanged.

use std::collections::{BTreeMap, BTreeSet};
use std::io::{ErrorKind, Read};
use std::path::{Path, PathBuf};

use sha2::Digest;

use crate::error::{Error, Result};

/// Name of the manifest listing the files a run wrote into its output folder.
pub const MANIFEST: &str = ".cellstudio-outputs";

/// A manifest's entries: each listed relative path with the SHA-256 (lowercase hex) of the
/// content written there, `None` when the line has no hash.
pub(super) type Listing = BTreeMap<String, Option<String>>;

/// The entries `dir`'s manifest lists (none when it has none); the manifest's own name is
/// never an entry.
pub(super) fn read(dir: &Path) -> Listing {
    std::fs::read_to_string(dir.join(MANIFEST))
        .map(|t| t.lines().filter(|l| !l.is_empty()).map(entry).filter(|(path, _)| path != MANIFEST).collect())
        .unwrap_or_default()
}

/// One manifest line: `HASH  PATH` (64 hex digits, two spaces) or a bare `PATH`.
fn entry(line: &str) -> (String, Option<String>) {
    match line.split_at_checked(64) {
        Some((hash, rest)) if hash.bytes().all(|b| b.is_ascii_hexdigit()) && rest.len() > 2 && rest.starts_with("  ") => {
            (rest[2..].to_string(), Some(hash.to_ascii_lowercase()))
        }
        _ => (line.to_string(), None),
    }
}

/// Writes the manifest of `files` with their hashes into `dir` (a staging folder this run
/// created and wrote, so no link of the user's can redirect the write).
pub(super) fn write(dir: &Path, files: &BTreeSet<String>) -> Result<()> {
    let mut text = String::new();
    for f in files {
        let path = dir.join(f);
        let hash = content_hash(&path).map_err(Error::io(&path))?;
        text.push_str(&format!("{hash}  {f}\n"));
    }
    crate::error::write_file(&dir.join(MANIFEST), text)
}

/// SHA-256 of the content of the file at `path`, in lowercase hex.
fn content_hash(path: &Path) -> std::io::Result<String> {
    let mut file = std::fs::File::open(path)?;
    let mut hasher = sha2::Sha256::new();
    let mut buf = vec![0u8; 1 << 16];
    loop {
        match file.read(&mut buf)? {
            0 => break,
            n => hasher.update(&buf[..n]),
        }
    }
    Ok(hasher.finalize().iter().map(|b| format!("{b:02x}")).collect())
}

/// Whether the regular file at `path` no longer holds the content of hash `recorded` (an
/// unreadable file counts as changed); an entry without a hash is taken as unchanged.
fn changed(path: &Path, recorded: Option<&String>) -> bool {
    recorded.is_some_and(|h| content_hash(path).ok().as_ref() != Some(h))
}

/// The path of `entry`, listed in the manifest of `dir` with hash `recorded`, when the run may
/// remove it as a stale result: `Ok(None)` when it no longer exists, `Err(why not)` when it
/// breaks a rule. `inputs` are the run's inputs, canonicalised.
pub(super) fn removable(dir: &Path, entry: &str, recorded: Option<&String>, inputs: &[PathBuf]) -> std::result::Result<Option<PathBuf>, &'static str> {
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
    if changed(&path, recorded) {
        return Err("changed since cellstudio wrote it (its content no longer matches the manifest's hash)");
    }
    Ok(Some(path))
}

/// Removes the `stale` entries of `dir`'s manifest that [`removable`] allows; every other
/// entry is left, with a warning on stderr naming it. A file that cannot be removed is a
/// warning too: the new results are already in place.
pub(super) fn remove_stale<'a>(dir: &Path, stale: impl Iterator<Item = (&'a String, &'a Option<String>)>, inputs: &[PathBuf]) {
    for (entry, recorded) in stale {
        match removable(dir, entry, recorded.as_ref(), inputs) {
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
/// `listed` that still holds the content written), else why not.
pub(super) fn replace_problem(dir: &Path, name: &str, listed: &Listing) -> Option<String> {
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
        Ok(_) => match listed.get(name) {
            None => Some(format!("`{}` would be replaced but no earlier cellstudio run wrote it (not in `{MANIFEST}`)", path.display())),
            Some(recorded) if changed(&path, recorded.as_ref()) => Some(format!(
                "`{}` would be replaced but was changed since cellstudio wrote it (its content no longer matches the hash in `{MANIFEST}`)",
                path.display()
            )),
            Some(_) => None,
        },
    }
}

/// Why `path` cannot be replaced: something other than a regular file is there.
fn not_a_file(path: &Path) -> String {
    format!("`{}` is not a regular file (a folder or a link)", path.display())
}

/// Fails, naming every destination, when any of `names` or the manifest itself cannot replace
/// what is in `dir` (whose manifest lists `listed`).
pub(super) fn check_destinations(dir: &Path, names: &BTreeSet<String>, listed: &Listing) -> Result<()> {
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

    /// A fresh temporary folder holding `out/sub`, removed when dropped.
    fn scratch() -> tempfile::TempDir {
        let d = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(d.path().join("out/sub")).unwrap();
        d
    }

    #[test]
    fn only_plain_regular_files_of_the_folder_itself_are_removable() {
        let tmp = scratch();
        let root = tmp.path();
        let out = root.join("out");
        std::fs::write(root.join("outside.txt"), "x").unwrap();
        std::fs::write(out.join("old.svg"), "x").unwrap();
        std::fs::write(out.join("sub/old.csv"), "x").unwrap();
        std::fs::write(out.join("input.csv"), "x").unwrap();
        std::os::unix::fs::symlink("../outside.txt", out.join("link.txt")).unwrap();
        std::os::unix::fs::symlink("sub", out.join("alias")).unwrap();
        let absolute = root.join("outside.txt");
        let input = out.join("input.csv").canonicalize().unwrap();
        let rule = |entry: &str| removable(&out, entry, None, std::slice::from_ref(&input));
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
        // With the hash of what was written: removable while unchanged, kept once edited.
        let written = content_hash(&out.join("old.svg")).unwrap();
        assert_eq!(removable(&out, "old.svg", Some(&written), &[]), Ok(Some(out.join("old.svg"))));
        std::fs::write(out.join("old.svg"), "edited").unwrap();
        assert!(removable(&out, "old.svg", Some(&written), &[]).unwrap_err().starts_with("changed since cellstudio wrote it"));
    }

    #[test]
    fn lines_are_hash_and_path_or_a_bare_path() {
        let hash = "ab".repeat(32);
        assert_eq!(entry(&format!("{hash}  sub/a b.svg")), ("sub/a b.svg".to_string(), Some(hash.clone())));
        assert_eq!(entry("report.md"), ("report.md".to_string(), None));
        assert_eq!(entry(&format!("{hash}  ")), (format!("{hash}  "), None));
    }

    #[test]
    fn a_destination_must_be_absent_or_a_listed_regular_file() {
        let tmp = scratch();
        let root = tmp.path();
        let out = root.join("out");
        std::fs::write(out.join("ours.svg"), "x").unwrap();
        std::fs::write(out.join("mine.txt"), "x").unwrap();
        std::fs::create_dir(out.join("dir.svg")).unwrap();
        std::os::unix::fs::symlink("/tmp", out.join("plots")).unwrap();
        let listed: Listing = ["ours.svg", "dir.svg", "plots/v.svg"].map(|f| (f.to_string(), None)).into();
        assert_eq!(replace_problem(&out, "ours.svg", &listed), None);
        assert_eq!(replace_problem(&out, "new.svg", &listed), None);
        assert_eq!(replace_problem(&out, "sub/new.svg", &listed), None);
        assert!(replace_problem(&out, "mine.txt", &listed).unwrap().contains("no earlier cellstudio run wrote it"));
        assert!(replace_problem(&out, "dir.svg", &listed).unwrap().contains("not a regular file"));
        assert!(replace_problem(&out, "plots/v.svg", &listed).unwrap().contains("plots` is not a folder"));
        // A listed file with its hash: replaceable as written, not once its content changed.
        let hashed: Listing = [("ours.svg".to_string(), Some(content_hash(&out.join("ours.svg")).unwrap()))].into();
        assert_eq!(replace_problem(&out, "ours.svg", &hashed), None);
        std::fs::write(out.join("ours.svg"), "y").unwrap();
        assert!(replace_problem(&out, "ours.svg", &hashed).unwrap().contains("was changed since cellstudio wrote it"));
        // A manifest that is not a file would stop the run after the moves: it is checked too.
        let new: BTreeSet<String> = ["ours.svg".to_string()].into();
        assert!(check_destinations(&out, &new, &listed).is_ok());
        std::fs::create_dir(out.join(MANIFEST)).unwrap();
        let e = check_destinations(&out, &new, &listed).unwrap_err().to_string();
        assert!(e.contains(".cellstudio-outputs` is not a regular file") && e.contains("nothing was moved"), "{e}");
    }
}
