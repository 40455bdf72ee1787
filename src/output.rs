//! Output folders that never lose a user's data.
//!
//! Every command that writes a folder goes through [`OutputDir`]:
//! - before any work, its input files are checked against the output folder (canonicalised
//!   paths): an input inside the folder is refused, so no run writes over what it reads;
//! - results are written into a temporary sibling folder (`.NAME.partial-PID`) and moved into
//!   place only when the whole run succeeded ([`OutputDir::commit`]); a failed run removes the
//!   temporary folder and leaves the previous results untouched;
//! - a folder the run creates is renamed into place in one step. Into an existing folder the
//!   files are renamed one by one; the files a previous run listed in the folder's manifest
//!   (`.cellstudio-outputs`) and this run did not write are removed (no stale plots beside a new
//!   report), and a file of the same name that no previous run wrote (a user's own file) is
//!   never replaced: the run fails and says which file.

use std::collections::BTreeSet;
use std::path::{Component, Path, PathBuf};

use crate::error::{Error, Result};

/// Name of the manifest listing the files a run wrote into its output folder.
pub const MANIFEST: &str = ".cellstudio-outputs";

/// A run's output folder, staged in a temporary sibling until [`commit`](Self::commit).
#[derive(Debug)]
pub struct OutputDir {
    target: PathBuf,
    staging: PathBuf,
    committed: bool,
}

/// `path` made absolute with symbolic links resolved, also when its last components do not
/// exist yet (the nearest existing ancestor is canonicalised, the rest appended).
pub fn canonical(path: &Path) -> PathBuf {
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().map(|d| d.join(path)).unwrap_or_else(|_| path.to_path_buf())
    };
    let mut tail = Vec::new();
    let mut head = absolute.as_path();
    loop {
        if let Ok(c) = head.canonicalize() {
            let mut out = c;
            for part in tail.iter().rev() {
                match part {
                    Component::ParentDir => {
                        out.pop();
                    }
                    Component::CurDir => {}
                    other => out.push(other.as_os_str()),
                }
            }
            return out;
        }
        match (head.parent(), head.components().next_back()) {
            (Some(parent), Some(last)) => {
                tail.push(last);
                head = parent;
            }
            _ => return absolute,
        }
    }
}

/// Refuses an output folder that holds (or is) one of the run's inputs.
///
/// ```
/// let dir = std::env::temp_dir().join(format!("cellstudio-doc-inputs-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let input = dir.join("spectrum.csv");
/// std::fs::write(&input, "f").unwrap();
/// let e = cellstudio::output::check_inputs(&dir, &[input.as_path()]).unwrap_err().to_string();
/// assert!(e.contains("spectrum.csv") && e.contains("lies inside the output folder"), "{e}");
/// assert!(cellstudio::output::check_inputs(&dir.join("elsewhere"), &[input.as_path()]).is_ok());
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn check_inputs(target: &Path, inputs: &[&Path]) -> Result<()> {
    let out = canonical(target);
    for input in inputs {
        // An input that does not exist is reported by its reader, with its own message.
        let Ok(inp) = input.canonicalize() else { continue };
        if inp.starts_with(&out) {
            return Err(Error::InvalidSetting {
                field: "output folder".into(),
                reason: format!(
                    "input `{}` lies inside the output folder `{}`, whose results this run replaces; \
                     move the input or choose another output folder",
                    input.display(),
                    target.display()
                ),
            });
        }
    }
    Ok(())
}

impl OutputDir {
    /// Checks `inputs` against `target` and creates the temporary sibling folder.
    pub fn create(target: &Path, inputs: &[&Path]) -> Result<Self> {
        check_inputs(target, inputs)?;
        if target.exists() && !target.is_dir() {
            return Err(Error::InvalidSetting {
                field: "output folder".into(),
                reason: format!("`{}` exists and is not a folder", target.display()),
            });
        }
        let name = target.file_name().ok_or_else(|| Error::InvalidSetting {
            field: "output folder".into(),
            reason: format!("`{}` does not name a folder", target.display()),
        })?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(Error::io(&parent))?;
        let staging = parent.join(format!(".{}.partial-{}", name.to_string_lossy(), std::process::id()));
        if staging.exists() {
            std::fs::remove_dir_all(&staging).map_err(Error::io(&staging))?;
        }
        std::fs::create_dir(&staging).map_err(Error::io(&staging))?;
        Ok(Self { target: target.to_path_buf(), staging, committed: false })
    }

    /// The folder to write into until [`commit`](Self::commit).
    pub fn path(&self) -> &Path {
        &self.staging
    }

    /// The final folder.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Moves the staged results into place and returns `files` (paths in the staging folder)
    /// as they are named there.
    pub fn commit(mut self, files: &[PathBuf]) -> Result<Vec<PathBuf>> {
        let new = relative_files(&self.staging)?;
        if !self.target.exists() {
            write_manifest(&self.staging, &new)?;
            std::fs::rename(&self.staging, &self.target).map_err(Error::io(&self.target))?;
        } else {
            let old = read_manifest(&self.target);
            let foreign: Vec<String> = new
                .iter()
                .filter(|f| !old.contains(*f) && self.target.join(f).exists())
                .map(|f| format!("`{}`", self.target.join(f).display()))
                .collect();
            if !foreign.is_empty() {
                return Err(Error::InvalidSetting {
                    field: "output folder".into(),
                    reason: format!(
                        "{} would be replaced but no earlier cellstudio run wrote it (not in `{MANIFEST}`); \
                         move it or choose another output folder (nothing was written)",
                        foreign.join(", ")
                    ),
                });
            }
            for stale in old.difference(&new) {
                let path = self.target.join(stale);
                if path.is_file() {
                    std::fs::remove_file(&path).map_err(Error::io(&path))?;
                }
            }
            for f in &new {
                let (from, to) = (self.staging.join(f), self.target.join(f));
                if let Some(parent) = to.parent() {
                    std::fs::create_dir_all(parent).map_err(Error::io(parent))?;
                }
                std::fs::rename(&from, &to).map_err(Error::io(&to))?;
            }
            write_manifest(&self.target, &new)?;
            std::fs::remove_dir_all(&self.staging).map_err(Error::io(&self.staging))?;
        }
        self.committed = true;
        Ok(files
            .iter()
            .map(|f| f.strip_prefix(&self.staging).map_or_else(|_| f.clone(), |rel| self.target.join(rel)))
            .collect())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
        }
    }
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

fn read_manifest(dir: &Path) -> BTreeSet<String> {
    std::fs::read_to_string(dir.join(MANIFEST))
        .map(|t| t.lines().filter(|l| !l.is_empty() && !l.contains("..")).map(str::to_string).collect())
        .unwrap_or_default()
}

fn write_manifest(dir: &Path, files: &BTreeSet<String>) -> Result<()> {
    let text: String = files.iter().map(|f| format!("{f}\n")).collect();
    let (tmp, path) = (dir.join(format!("{MANIFEST}.tmp")), dir.join(MANIFEST));
    crate::error::write_file(&tmp, text)?;
    std::fs::rename(&tmp, &path).map_err(Error::io(&path))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("cellstudio-output-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn failed_run_leaves_previous_results_and_no_partial_folder() {
        let root = scratch("fail");
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
        let names: Vec<_> = std::fs::read_dir(&root).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("out")]);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn stale_results_go_user_files_stay_and_are_never_replaced() {
        let root = scratch("merge");
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
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_folder_in_the_way_of_an_output_fails_before_anything_moves() {
        let root = scratch("dir");
        let target = root.join("out");
        std::fs::create_dir_all(target.join("report.md")).unwrap();
        let out = OutputDir::create(&target, &[]).unwrap();
        crate::error::write_file(&out.path().join("design.json"), "{}").unwrap();
        crate::error::write_file(&out.path().join("report.md"), "r").unwrap();
        let e = out.commit(&[]).unwrap_err().to_string();
        assert!(e.contains("report.md"), "{e}");
        assert!(!target.join("design.json").exists(), "half the results were moved in");
        let names: Vec<_> = std::fs::read_dir(&root).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("out")]);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn canonical_handles_missing_tails_and_dot_dot() {
        let root = scratch("canon");
        let a = canonical(&root.join("x/../y/z"));
        assert_eq!(a, root.canonicalize().unwrap().join("y/z"));
        std::fs::remove_dir_all(&root).unwrap();
    }
}
