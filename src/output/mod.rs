//! Output folders that never lose a user's data.
//!
//! Every command that writes a folder goes through [`OutputDir`]:
//! - before any work, its input files are checked against the output folder `NAME` and its
//!   sibling `NAME.rejected` (canonicalised paths): an input inside either is refused, so no
//!   run writes over what it reads;
//! - the temporary folders that interrupted runs left beside the target (`.NAME.partial-PID`
//!   of a process that no longer exists) are removed, with a note on stderr ([`partial`]);
//! - results are written into a temporary sibling folder (`.NAME.partial-PID`) and moved into
//!   place only when the whole run succeeded ([`OutputDir::commit`]); a failed run removes the
//!   temporary folder and leaves the previous results untouched, and a run that ends in an
//!   error after writing something worth inspecting moves it to `NAME.rejected` instead
//!   ([`OutputDir::reject`]), never over the previous results;
//! - a folder the run creates is renamed into place in one step. Into an existing folder,
//!   every destination is checked before anything moves: a folder, a link, a file that no
//!   earlier run listed in the folder's manifest (`.cellstudio-outputs`, so a user's own file)
//!   or a listed file whose content no longer matches the SHA-256 the manifest recorded (the
//!   user edited it) fails the run, naming it, with nothing moved. Then the files are renamed
//!   in, the manifest replaced, and the files the previous manifest listed that this run did
//!   not write are removed, only where the manifest's rules allow ([`manifest`]: plain regular
//!   files of the folder itself, unedited, none of the run's inputs); any other entry is left,
//!   with a warning.

mod manifest;
mod partial;
mod paths;

use std::collections::BTreeSet;
use std::ffi::OsString;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

pub use manifest::MANIFEST;
pub use paths::{canonical, check_inputs, is_plain_relative};

/// A run's output folder, staged in a temporary sibling until [`commit`](Self::commit) (or
/// [`reject`](Self::reject)).
#[derive(Debug)]
pub struct OutputDir {
    target: PathBuf,
    rejected: PathBuf,
    staging: PathBuf,
    /// The run's inputs, canonicalised: never removed as stale results.
    inputs: Vec<PathBuf>,
    /// Folders above the target that did not exist before this run, innermost first.
    created: Vec<PathBuf>,
    committed: bool,
}

impl OutputDir {
    /// Checks `inputs` against `target` and its `NAME.rejected` sibling, removes the temporary
    /// folders of interrupted runs beside it and creates this run's temporary sibling folder.
    pub fn create(target: &Path, inputs: &[&Path]) -> Result<Self> {
        let name = target.file_name().ok_or_else(|| Error::InvalidSetting {
            field: "output folder".into(),
            reason: format!("`{}` does not name a folder", target.display()),
        })?;
        let rejected = target.with_file_name([name, ".rejected".as_ref()].into_iter().collect::<OsString>());
        for folder in [target, &rejected] {
            check_inputs(folder, inputs)?;
            if folder.exists() && !folder.is_dir() {
                return Err(not_a_folder(folder));
            }
        }
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        // Named by the folder the user asked for, not by the temporary sibling.
        let unwritable = |e: std::io::Error| Error::InvalidSetting {
            field: "output folder".into(),
            reason: format!("cannot write into `{}`: {e}", target.display()),
        };
        // The folders this run creates above the target, removed again if it fails.
        let created: Vec<PathBuf> = parent.ancestors().take_while(|a| !a.as_os_str().is_empty() && !a.exists()).map(Path::to_path_buf).collect();
        std::fs::create_dir_all(&parent).map_err(unwritable)?;
        let name = name.to_string_lossy();
        partial::remove_abandoned(&parent, &name);
        let staging = partial::staging(&parent, &name);
        if staging.exists() {
            std::fs::remove_dir_all(&staging).map_err(Error::io(&staging))?;
        }
        std::fs::create_dir(&staging).map_err(unwritable)?;
        let inputs = inputs.iter().filter_map(|p| p.canonicalize().ok()).collect();
        Ok(Self { target: target.to_path_buf(), rejected, staging, inputs, created, committed: false })
    }

    /// The folder to write into until [`commit`](Self::commit).
    pub fn path(&self) -> &Path {
        &self.staging
    }

    /// The final folder.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Where [`reject`](Self::reject) moves the results: `NAME.rejected` beside the target.
    pub fn rejected(&self) -> &Path {
        &self.rejected
    }

    /// Moves the staged results into the target folder and returns `files` (paths in the
    /// staging folder) as they are named there.
    pub fn commit(self, files: &[PathBuf]) -> Result<Vec<PathBuf>> {
        let to = self.target.clone();
        self.move_to(&to, files)
    }

    /// For a run that ends in an error after writing outputs worth inspecting: moves them into
    /// [`rejected`](Self::rejected) under the same rules as [`commit`](Self::commit) (the last
    /// rejected run's files are replaced, stale ones removed) and leaves the target as it was.
    pub fn reject(self, files: &[PathBuf]) -> Result<Vec<PathBuf>> {
        let to = self.rejected.clone();
        self.move_to(&to, files)
    }

    /// Moves the staged results into `dest`: in one rename when nothing is there, else file by
    /// file after every destination was checked, then the manifest, then the stale files.
    fn move_to(mut self, dest: &Path, files: &[PathBuf]) -> Result<Vec<PathBuf>> {
        let new = relative_files(&self.staging)?;
        manifest::write(&self.staging, &new)?;
        if dest.symlink_metadata().is_err() {
            std::fs::rename(&self.staging, dest).map_err(Error::io(dest))?;
        } else if !dest.is_dir() {
            return Err(not_a_folder(dest));
        } else {
            let old = manifest::read(dest);
            manifest::check_destinations(dest, &new, &old)?;
            for f in &new {
                let (from, to) = (self.staging.join(f), dest.join(f));
                if let Some(parent) = to.parent() {
                    std::fs::create_dir_all(parent).map_err(Error::io(parent))?;
                }
                std::fs::rename(&from, &to).map_err(Error::io(&to))?;
            }
            let listing = dest.join(MANIFEST);
            std::fs::rename(self.staging.join(MANIFEST), &listing).map_err(Error::io(&listing))?;
            manifest::remove_stale(dest, old.iter().filter(|(entry, _)| !new.contains(*entry)), &self.inputs);
            std::fs::remove_dir_all(&self.staging).map_err(Error::io(&self.staging))?;
        }
        self.committed = true;
        Ok(files.iter().map(|f| f.strip_prefix(&self.staging).map_or_else(|_| f.clone(), |rel| dest.join(rel))).collect())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
            // Only while empty: another run may have written into them since.
            for dir in &self.created {
                let _ = std::fs::remove_dir(dir);
            }
        }
    }
}

/// The error for an output folder whose name is taken by something else (a file).
fn not_a_folder(path: &Path) -> Error {
    Error::InvalidSetting { field: "output folder".into(), reason: format!("`{}` exists and is not a folder", path.display()) }
}

/// Files under `dir`, relative, with `/` separators (the manifest excluded).
fn relative_files(dir: &Path) -> Result<BTreeSet<String>> {
    let mut out = BTreeSet::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).map_err(Error::io(&d))? {
            let path = entry.map_err(Error::io(&d))?.path();
            if path.is_dir() {
                stack.push(path);
            } else if let Ok(rel) = path.strip_prefix(dir) {
                let rel = rel.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/");
                if rel != MANIFEST {
                    out.insert(rel);
                }
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;


    #[test]
    fn failed_run_leaves_previous_results_and_no_partial_folder() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let target = root.join("out");
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("report.md"), "first").unwrap();
        out.commit(&[]).unwrap();
        {
            let out = OutputDir::create(&target, &[]).unwrap();
            crate::error::write_file(&out.path().join("report.md"), "half").unwrap();
            // dropped without commit: the run failed
        }
        assert_eq!(std::fs::read_to_string(target.join("report.md")).unwrap(), "first");
        let names: Vec<_> = std::fs::read_dir(root).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("out")]);
    }

    #[test]
    fn a_rejected_run_goes_to_name_rejected_and_leaves_the_results() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let target = root.join("out");
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("report.md"), "good").unwrap();
        out.commit(&[]).unwrap();
        let out = OutputDir::create(&target, &[]).unwrap();
        assert_eq!(out.rejected(), root.join("out.rejected"));
        let report = out.path().join("report.md");
        crate::error::write_file(&report, "pinned").unwrap();
        assert_eq!(out.reject(&[report]).unwrap(), vec![root.join("out.rejected/report.md")]);
        assert_eq!(std::fs::read_to_string(target.join("report.md")).unwrap(), "good");
        assert_eq!(std::fs::read_to_string(root.join("out.rejected/report.md")).unwrap(), "pinned");
    }

    #[test]
    fn stale_results_go_user_files_stay_and_are_never_replaced() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let target = root.join("out");
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("a.svg"), "a").unwrap();
        crate::error::write_file(&out.path().join("b.svg"), "b").unwrap();
        out.commit(&[]).unwrap();
        crate::error::write_file(&target.join("notes.txt"), "mine").unwrap();
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("a.svg"), "a2").unwrap();
        let files = out.commit(&[]).unwrap();
        assert!(files.is_empty());
        assert_eq!(std::fs::read_to_string(target.join("a.svg")).unwrap(), "a2");
        assert!(!target.join("b.svg").exists(), "a stale result of the previous run stayed");
        assert_eq!(std::fs::read_to_string(target.join("notes.txt")).unwrap(), "mine");
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("notes.txt"), "overwritten").unwrap();
        let e = out.commit(&[]).unwrap_err().to_string();
        assert!(e.contains("notes.txt") && e.contains("no earlier cellstudio run wrote it"), "{e}");
        assert_eq!(std::fs::read_to_string(target.join("notes.txt")).unwrap(), "mine");
    }

    #[test]
    fn a_folder_in_the_way_of_an_output_fails_before_anything_moves() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let target = root.join("out");
        std::fs::create_dir_all(target.join("report.md")).unwrap();
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("design.json"), "{}").unwrap();
        crate::error::write_file(&out.path().join("report.md"), "r").unwrap();
        let e = out.commit(&[]).unwrap_err().to_string();
        assert!(e.contains("report.md"), "{e}");
        assert!(!target.join("design.json").exists(), "half the results were moved in");
        let names: Vec<_> = std::fs::read_dir(root).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("out")]);
    }
}
