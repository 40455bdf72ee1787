//! Path checks of output folders: canonical paths, inputs kept out of the folder, and the
//! plain relative names a manifest may use.

use std::path::{Component, Path, PathBuf};

use crate::error::{Error, Result};

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
/// let tmp = tempfile::tempdir().unwrap();
/// let dir = tmp.path();
/// let input = dir.join("spectrum.csv");
/// std::fs::write(&input, "f").unwrap();
/// let e = cellstudio::output::check_inputs(dir, &[input.as_path()]).unwrap_err().to_string();
/// assert!(e.contains("spectrum.csv") && e.contains("lies inside the output folder"), "{e}");
/// assert!(cellstudio::output::check_inputs(&dir.join("elsewhere"), &[input.as_path()]).is_ok());
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

/// Whether `name` is a plain relative path: only normal components (no root, drive prefix,
/// `.` or `..`), at least one.
///
/// ```
/// use cellstudio::output::is_plain_relative;
/// assert!(is_plain_relative("report.md") && is_plain_relative("plots/voltage.svg"));
/// assert!(!is_plain_relative("/etc/passwd") && !is_plain_relative("../notes.txt"));
/// assert!(!is_plain_relative("./report.md") && !is_plain_relative(""));
/// ```
pub fn is_plain_relative(name: &str) -> bool {
    let path = Path::new(name);
    path.components().next().is_some() && path.components().all(|c| matches!(c, Component::Normal(_)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn canonical_handles_missing_tails_and_dot_dot() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let a = canonical(&root.join("x/../y/z"));
        assert_eq!(a, root.canonicalize().unwrap().join("y/z"));
    }
}
