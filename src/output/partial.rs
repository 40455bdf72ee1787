//! Staging folders: `.NAME.partial-PID` beside the target `NAME`, one per running process, and
//! the removal of those whose process is gone (a run interrupted by a signal leaves its
//! staging folder behind).

use std::path::{Path, PathBuf};

/// This process's staging folder for the target `name` in `parent`.
pub(super) fn staging(parent: &Path, name: &str) -> PathBuf {
    parent.join(format!(".{name}.partial-{}", std::process::id()))
}

/// Removes the staging folders of target `name` in `parent` whose process no longer exists,
/// saying so on stderr. Only folders named exactly `.NAME.partial-PID` are touched; a process
/// that is still running, or whose state cannot be known (no `/proc`, not Linux), keeps its
/// folder.
pub(super) fn remove_abandoned(parent: &Path, name: &str) {
    let prefix = format!(".{name}.partial-");
    let Ok(entries) = std::fs::read_dir(parent) else { return };
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some(pid) = file_name.to_str().and_then(|n| n.strip_prefix(&prefix)).and_then(pid) else { continue };
        // `file_type` does not follow links: a link named like a staging folder stays.
        if pid == std::process::id() || !is_gone(pid) || !entry.file_type().is_ok_and(|t| t.is_dir()) {
            continue;
        }
        let path = entry.path();
        match std::fs::remove_dir_all(&path) {
            Ok(()) => eprintln!("note: removed `{}`, the temporary folder of an interrupted run (process {pid} no longer exists)", path.display()),
            Err(e) => eprintln!("warning: could not remove `{}`, the temporary folder of an interrupted run: {e}", path.display()),
        }
    }
}

/// A process id written as [`staging`] writes it (decimal, no sign or leading zero).
fn pid(text: &str) -> Option<u32> {
    text.parse::<u32>().ok().filter(|p| p.to_string() == text)
}

/// Whether process `pid` is known not to exist.
#[cfg(target_os = "linux")]
fn is_gone(pid: u32) -> bool {
    let proc = Path::new("/proc");
    proc.join("self").exists() && !proc.join(pid.to_string()).exists()
}

/// Whether process `pid` is known not to exist: never known here.
#[cfg(not(target_os = "linux"))]
fn is_gone(_pid: u32) -> bool {
    false
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    #[test]
    fn only_the_folders_of_gone_processes_of_the_same_target_go() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        // 2147483646 is above any Linux pid_max: no such process.
        let names = [".out.partial-2147483646", ".out.partial-02147483646", ".other.partial-2147483646", ".out.partial-1", ".out.partial-x"];
        for name in names {
            std::fs::create_dir_all(root.join(name)).unwrap();
        }
        let own = staging(root, "out");
        std::fs::create_dir_all(&own).unwrap();
        std::os::unix::fs::symlink(&own, root.join(".out.partial-2147483645")).unwrap();
        remove_abandoned(root, "out");
        let mut left: Vec<String> = std::fs::read_dir(root).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        left.sort();
        let mut expected: Vec<String> = names[1..].iter().map(|n| n.to_string()).collect();
        expected.push(".out.partial-2147483645".into());
        expected.push(own.file_name().unwrap().to_string_lossy().into_owned());
        expected.sort();
        assert_eq!(left, expected);
    }
}
