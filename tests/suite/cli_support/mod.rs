//! Helpers shared by the command-line tests (`tests/cli.rs`, `tests/output_safety.rs`): the
//! built binary run in scratch folders, and a small fitting study of the seed recording.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub const REPO: &str = env!("CARGO_MANIFEST_DIR");

/// A fresh scratch folder per test (uniquely named by `tempfile`), removed when dropped.
pub struct Scratch(pub PathBuf, tempfile::TempDir);

impl Scratch {
    pub fn new(tag: &str) -> Self {
        let dir = tempfile::Builder::new().prefix(&format!("cellstudio-cli-{tag}-")).tempdir().unwrap();
        Self(dir.path().to_path_buf(), dir)
    }
    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
    pub fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path(name);
        std::fs::write(&p, text).unwrap();
        p
    }
    /// Entries of the scratch folder (to see leftovers such as `.out.partial-PID`).
    pub fn entries(&self) -> Vec<String> {
        let mut v: Vec<String> =
            std::fs::read_dir(&self.0).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }
}

/// Runs the binary in `cwd`.
pub fn run(cwd: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cellstudio")).args(args).current_dir(cwd).output().expect("binary runs")
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Exit code 1 (an error, not a panic's 101) with every `needles` in stderr, on one line.
pub fn fails_with(o: &Output, needles: &[&str]) -> String {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(1), "expected a clean failure, got {:?}: {e}", o.status);
    let line = e.lines().find(|l| l.starts_with("error:")).unwrap_or_else(|| panic!("no error line in: {e}"));
    for n in needles {
        assert!(line.contains(n), "`{n}` not in the error line: {e}");
    }
    e
}

pub fn succeeds(o: &Output) {
    assert!(o.status.success(), "failed: {}\n{}", stderr(o), String::from_utf8_lossy(&o.stdout));
}

/// A small fitting study of the seed recording; `extra` is appended (more sections).
pub fn fit_study(s: &Scratch, extra: &str) -> PathBuf {
    let data = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    s.write(
        "fit.toml",
        &format!(
            r#"name = "cli fit"
[model]
kind = "spm"
submodels = {{ contact_resistance = true }}
[data]
file = "{}"
synthetic_noise = 0.002
noise_seed = 7
[[parameters]]
path = "negative.diffusivity"
initial = 6.6e-14
lower = 1e-15
upper = 1e-12
log = true
[[parameters]]
path = "cell.contact_resistance"
initial = 0.005
lower = 1e-4
upper = 0.1
log = true
[optimiser]
method = "lbfgsb"
seed = 1
[output]
dir = "out"
{extra}"#,
            data.display()
        ),
    )
}

/// The seed recording (`tests/data/spm_contact_resistance_seed.csv`: time_s, current_A,
/// voltage_V, discharge_capacity_Ah, temperature_K) with `edit(row, cells)` applied to every
/// data row (row 0 the first after the header).
pub fn seed_edited(edit: impl Fn(usize, &mut Vec<String>)) -> String {
    let seed = std::fs::read_to_string(Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv")).unwrap();
    let mut lines = seed.lines();
    let mut out = format!("{}\n", lines.next().unwrap());
    for (row, line) in lines.enumerate() {
        let mut cells: Vec<String> = line.split(',').map(str::to_string).collect();
        edit(row, &mut cells);
        out += &format!("{}\n", cells.join(","));
    }
    out
}
