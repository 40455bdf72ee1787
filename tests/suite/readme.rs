//! Every `cargo run --release -- ...` command of the README runs as written (with the built
//! binary, in a scratch copy of the study files, in README order), except those listed in
//! `SKIPPED` with the reason.

use std::path::Path;
use std::process::Command;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

/// Commands not run here, by their first words, and why.
const SKIPPED: [(&str, &str); 4] = [
    ("parameterise fits/param_lgm50", "reads ../shared/recordings, absent from the scratch copy"),
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
    // A command may continue over lines ending in `\`.
    let mut commands: Vec<String> = Vec::new();
    let mut lines = readme.lines();
    while let Some(line) = lines.next() {
        let Some(mut cmd) = line.trim().strip_prefix("cargo run --release -- ").map(str::to_string) else { continue };
        while let Some(head) = cmd.strip_suffix('\\').map(str::to_string) {
            cmd = format!("{head} {}", lines.next().unwrap_or_default().trim());
        }
        commands.push(cmd.split(" #").next().unwrap().trim().to_string());
    }
    assert!(commands.len() >= 10, "README commands not found: {commands:?}");

    let tmp = tempfile::tempdir().unwrap();
    let dir: &Path = tmp.path();
    for sub in ["designs", "fits", "protocols", "examples", "tests/data/cycler", "tests/data/parameterisation", "tests/data/sei"] {
        copy_dir(&Path::new(REPO).join(sub), &dir.join(sub));
    }
    let seed = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    std::fs::create_dir_all(dir.join("tests/data")).unwrap();
    std::fs::copy(&seed, dir.join("tests/data/spm_contact_resistance_seed.csv")).unwrap();
    // The README's stand-in for a user's recording.
    std::fs::copy(&seed, dir.join("my_recording.csv")).unwrap();

    let mut ran = 0;
    let mut used = [false; SKIPPED.len()];
    for cmd in &commands {
        if let Some(k) = SKIPPED.iter().position(|(start, _)| cmd.starts_with(start)) {
            eprintln!("skipped `{cmd}`: {}", SKIPPED[k].1);
            used[k] = true;
            continue;
        }
        let out = Command::new(env!("CARGO_BIN_EXE_cellstudio"))
            .args(shell_words(cmd))
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
    // Every reason to skip still names a README command, and most commands run.
    assert!(used.iter().all(|u| *u), "a SKIPPED entry matches no README command: {:?}", SKIPPED.iter().zip(used).filter(|(_, u)| !u).map(|(s, _)| s.0).collect::<Vec<_>>());
    assert!(ran >= 10 && ran * 2 > commands.len(), "{ran} of {} README commands ran", commands.len());
}

/// `cmd` split into words as a shell would for these commands: on spaces outside double quotes.
fn shell_words(cmd: &str) -> Vec<String> {
    let (mut words, mut word, mut quoted) = (Vec::new(), String::new(), false);
    for c in cmd.chars() {
        match c {
            '"' => quoted = !quoted,
            c if c.is_whitespace() && !quoted => {
                if !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
            }
            c => word.push(c),
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    words
}
