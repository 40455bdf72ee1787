//! A sweep split into four shards, each run as its own process (as four cluster tasks
//! would), then merged: the merged output equals the single run's byte for byte, and merges
//! that are not one whole sweep of the study are refused with the reason.

use std::path::{Path, PathBuf};
use std::process::Command;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

fn cellstudio(dir: &Path, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_cellstudio")).args(args).current_dir(dir).output().expect("binary runs")
}

fn ok(out: std::process::Output) -> String {
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{text}");
    text
}

/// The seed study with its output in `out`.
fn study(dir: &Path, name: &str, out: &str) -> PathBuf {
    let text = std::fs::read_to_string(Path::new(REPO).join("designs/gravimetric_chen2020.toml")).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text.replace("dir = \"out/gravimetric_chen2020\"", &format!("dir = \"{out}\""))).unwrap();
    path
}

#[test]
fn four_shards_merge_to_the_single_run_byte_for_byte() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    study(dir, "single.toml", "single");
    study(dir, "sharded.toml", "sharded");
    ok(cellstudio(&dir, &["sweep", "single.toml"]));
    let shards: Vec<std::process::Child> = (1..=4)
        .map(|k| Command::new(env!("CARGO_BIN_EXE_cellstudio")).args(["sweep", "sharded.toml", "--shard", &format!("{k}/4")]).current_dir(&dir).spawn().unwrap())
        .collect();
    for mut child in shards {
        assert!(child.wait().unwrap().success());
    }
    let folders: Vec<String> = (1..=4).map(|k| format!("sharded.shard-{k}-of-4")).collect();
    // Missing or repeated parts, and another study's shards, are refused.
    let partial = cellstudio(&dir, &["sweep", "sharded.toml", "--merge", &folders[0], &folders[1], &folders[2]]);
    assert!(!partial.status.success() && String::from_utf8_lossy(&partial.stderr).contains("each of the 4 shards once"));
    let twice = cellstudio(&dir, &["sweep", "sharded.toml", "--merge", &folders[0], &folders[0], &folders[2], &folders[3]]);
    assert!(!twice.status.success());
    let other = dir.join("other.toml");
    std::fs::write(&other, std::fs::read_to_string(dir.join("sharded.toml")).unwrap().replace("points = [13, 13]", "points = [12, 13]")).unwrap();
    let wrong = cellstudio(&dir, &["sweep", "other.toml", "--merge", &folders[0], &folders[1], &folders[2], &folders[3]]);
    assert!(!wrong.status.success() && String::from_utf8_lossy(&wrong.stderr).contains("not of this study's"));
    assert!(!dir.join("sharded").exists(), "a refused merge wrote its output");

    let mut args = vec!["sweep", "sharded.toml", "--merge"];
    args.extend(folders.iter().map(String::as_str));
    ok(cellstudio(&dir, &args));
    for file in ["sweep.csv", "sweep.json", "sweep_gravimetric_energy_density.svg", "sweep_volumetric_energy_density.svg"] {
        let (a, b) = (std::fs::read(dir.join("single").join(file)).unwrap(), std::fs::read(dir.join("sharded").join(file)).unwrap());
        assert!(a == b, "{file} differs between the single run and the merged shards");
    }
    let rows = std::fs::read_to_string(dir.join("sharded/sweep.csv")).unwrap().lines().count();
    assert_eq!(rows, 1 + 169);
}
