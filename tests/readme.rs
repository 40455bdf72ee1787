//! Every `cargo run --release -- ...` command of the README runs as written (with the built
//! binary, in a scratch copy of the study files, in README order), except those listed in
//! `SKIPPED` with the reason.

use std::path::{Path, PathBuf};
use std::process::Command;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

/// Commands not run here, by their first words, and why.
const SKIPPED: [(&str, &str); 3] = [
    ("fit fits/lgm50_joint", "reads ../shared/recordings, absent from the scratch copy; tests/joint_fit.rs runs the same study"),
    ("sample ", "about 60 s of MCMC; the samplers are checked in tests/samplers.rs"),
    ("diagnose ", "reads a bench recording from tests/data; tests/diagnosis_bench.rs runs every bench case"),
];

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        if path.is_file() {
            std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
        }
    }
}

#[test]
fn readme_commands_run_as_written() {
    let readme = std::fs::read_to_string(Path::new(REPO).join("README.md")).unwrap();
    let commands: Vec<String> = readme
        .lines()
        .filter_map(|l| l.trim().strip_prefix("cargo run --release -- "))
        .map(|l| l.split('#').next().unwrap().trim().to_string())
        .collect();
    assert!(commands.len() >= 10, "README commands not found: {commands:?}");

    let dir: PathBuf = std::env::temp_dir().join(format!("cellstudio-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for sub in ["designs", "fits", "protocols", "tests/data/cycler"] {
        copy_dir(&Path::new(REPO).join(sub), &dir.join(sub));
    }
    let seed = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    std::fs::create_dir_all(dir.join("tests/data")).unwrap();
    std::fs::copy(&seed, dir.join("tests/data/spm_contact_resistance_seed.csv")).unwrap();
    // The README's stand-in for a user's recording.
    std::fs::copy(&seed, dir.join("my_recording.csv")).unwrap();

    let mut ran = 0;
    for cmd in &commands {
        if let Some((_, why)) = SKIPPED.iter().find(|(start, _)| cmd.starts_with(start)) {
            eprintln!("skipped `{cmd}`: {why}");
            continue;
        }
        let out = Command::new(env!("CARGO_BIN_EXE_cellstudio"))
            .args(cmd.split_whitespace())
            .current_dir(&dir)
            .output()
            .expect("binary runs");
        assert!(
            out.status.success(),
            "README command `{cmd}` failed:\n{}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        ran += 1;
    }
    assert!(ran + SKIPPED.len() >= commands.len());
    std::fs::remove_dir_all(&dir).unwrap();
}
