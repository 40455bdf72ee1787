//! End-to-end tests of how runs write their output folder (`src/output/`), one per finding of
//! the output-folder audit: a manifest that names files outside the folder or behind a link,
//! partial folders left by interrupted runs, a commit that replaced half the results before
//! failing, a rejected fit that replaced the previous valid results, and a listed result the
//! user edited that the next run replaced.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::cli_support;

use cli_support::*;

/// A fast simulation (SPM, 5 volumes) into `out`, with `extra` arguments.
fn simulate(s: &Scratch, out: &str, extra: &[&str]) -> Output {
    let mut args = vec!["simulate", "--model", "spm", "--mesh", "5", "--out", out];
    args.extend_from_slice(extra);
    run(&s.0, &args)
}

/// Every regular file directly in `dir` with its bytes.
fn contents(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.symlink_metadata().unwrap().is_file())
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read(&p).unwrap()))
        .collect()
}

#[test]
fn the_manifest_never_removes_a_file_outside_the_folder_behind_a_link_or_not_a_file() {
    let s = Scratch::new("manifest");
    std::fs::create_dir_all(s.path("victim")).unwrap();
    let thesis = s.write("victim/thesis.txt", "important");
    let params = s.write("victim/set.toml", "base = \"chen2020\"\n");
    std::fs::create_dir_all(s.path("out/sub")).unwrap();
    s.write("out/sub/mine.txt", "mine");
    s.write("out/old.svg", "a stale result");
    std::os::unix::fs::symlink("../victim", s.path("out/linked")).unwrap();
    std::os::unix::fs::symlink("../victim/thesis.txt", s.path("out/link.txt")).unwrap();
    let listed = [thesis.to_str().unwrap(), "../victim/thesis.txt", "linked/thesis.txt", "linked/set.toml", "link.txt", "sub", "old.svg"];
    s.write("out/.cellstudio-outputs", &listed.map(|l| format!("{l}\n")).concat());

    let o = simulate(&s, "out", &["--params", params.to_str().unwrap()]);
    succeeds(&o);
    assert_eq!(std::fs::read_to_string(&thesis).unwrap(), "important");
    assert!(params.exists(), "the parameter file this run read was removed");
    assert!(s.path("out/link.txt").symlink_metadata().unwrap().file_type().is_symlink(), "a user's link was removed");
    assert!(s.path("out/linked").is_dir());
    assert_eq!(std::fs::read_to_string(s.path("out/sub/mine.txt")).unwrap(), "mine");
    assert!(!s.path("out/old.svg").exists(), "a stale result the manifest names plainly stayed");
    let e = stderr(&o);
    for entry in &listed[..6] {
        assert!(e.lines().any(|l| l.starts_with("warning:") && l.contains(&format!("`{entry}`"))), "no warning names `{entry}`: {e}");
    }
    assert!(!e.contains("`old.svg`"), "{e}");
    let manifest = std::fs::read_to_string(s.path("out/.cellstudio-outputs")).unwrap();
    assert!(!manifest.contains("victim") && !manifest.contains("old.svg"), "{manifest}");
}

#[test]
fn the_next_run_removes_the_partial_folders_of_interrupted_runs() {
    let s = Scratch::new("interrupted");
    let mut run = Command::new(env!("CARGO_BIN_EXE_cellstudio"));
    run.args(["simulate", "--model", "spm", "--mesh", "5", "--repeat", "100000000", "--out", "out"])
        .current_dir(&s.0)
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    // A shell without job control starts a background job with SIGINT ignored, and every
    // child inherits that (the test then waited for ever): the run gets the default action,
    // as a terminal's Ctrl-C meets it.
    // SAFETY: signal(2) is async-signal-safe, called between fork and exec.
    unsafe {
        std::os::unix::process::CommandExt::pre_exec(&mut run, || {
            libc::signal(libc::SIGINT, libc::SIG_DFL);
            Ok(())
        });
    }
    let mut child = run.spawn().unwrap();
    let partial = format!(".out.partial-{}", child.id());
    let start = Instant::now();
    while !s.path(&partial).exists() {
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the run ended ({status}) before it was interrupted");
        }
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("the run never staged its folder");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    // SAFETY: kill(2) on the child's own process id.
    assert_eq!(unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) }, 0);
    assert!(!child.wait().unwrap().success());
    // Left beside it: the folder of a live process (this test's) and one of another target.
    let live = format!(".out.partial-{}", std::process::id());
    std::fs::create_dir_all(s.path(&live)).unwrap();
    std::fs::create_dir_all(s.path(".other.partial-2147483646")).unwrap();

    let o = simulate(&s, "out", &[]);
    succeeds(&o);
    assert!(!s.path(&partial).exists(), "the interrupted run's partial folder is still there: {:?}", s.entries());
    assert!(stderr(&o).contains(&partial), "the removal is not mentioned: {}", stderr(&o));
    assert_eq!(s.entries(), vec![".other.partial-2147483646".to_string(), live, "out".to_string()]);
}

#[test]
fn a_commit_checks_every_destination_before_moving_anything() {
    let s = Scratch::new("commit");
    succeeds(&simulate(&s, "out", &[]));
    let svg = "spm_simulation_voltage.svg";
    let mut before = contents(&s.path("out"));
    before.remove(svg);
    std::fs::remove_file(s.path("out").join(svg)).unwrap();
    std::fs::create_dir_all(s.path("out").join(svg).join("x")).unwrap();
    let o = simulate(&s, "out", &["--c-rate", "2"]);
    fails_with(&o, &[svg, "not a regular file", "nothing was moved"]);
    assert_eq!(contents(&s.path("out")), before, "a failed run replaced earlier results");
    assert_eq!(s.entries(), vec!["out"], "a partial folder was left behind");

    // A link where a result was is not replaced either.
    std::fs::remove_dir_all(s.path("out").join(svg)).unwrap();
    s.write("elsewhere.svg", "not a result");
    std::os::unix::fs::symlink("../elsewhere.svg", s.path("out").join(svg)).unwrap();
    fails_with(&simulate(&s, "out", &["--c-rate", "2"]), &[svg, "not a regular file"]);
    assert_eq!(contents(&s.path("out")), before);
    assert_eq!(std::fs::read_to_string(s.path("elsewhere.svg")).unwrap(), "not a result");
}

#[test]
fn a_rejected_fit_keeps_the_previous_results_and_writes_name_rejected() {
    let s = Scratch::new("rejected");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let study = study.to_str().unwrap();
    succeeds(&run(&s.0, &["fit", study]));
    let good = contents(&s.path("out"));
    // The seed recording has R = 10 mOhm; a search range that ends at 2 mOhm pins the fit there.
    let pinned = std::fs::read_to_string(study).unwrap().replace("initial = 0.005\n", "initial = 0.001\n").replace("upper = 0.1\n", "upper = 0.002\n");
    std::fs::write(study, format!("{pinned}[landscape]\npoints = 3\n")).unwrap();
    let o = run(&s.0, &["fit", study]);
    fails_with(&o, &["ended on a bound", "no estimate", "`out.rejected`", "`out` are left as they were"]);
    assert_eq!(contents(&s.path("out")), good, "a rejected fit replaced the previous results");
    let report = std::fs::read_to_string(s.path("out.rejected/report.md")).unwrap();
    assert!(report.contains("cell.contact_resistance = 0.002 at its upper bound"), "{report}");
    assert!(s.path("out.rejected/landscape.svg").exists());

    // The next rejected run replaces the folder: its stale landscape goes.
    std::fs::write(study, pinned).unwrap();
    fails_with(&run(&s.0, &["fit", study]), &["`out.rejected`"]);
    assert!(!s.path("out.rejected/landscape.svg").exists(), "a stale file of the last rejected run stayed");
    assert!(s.path("out.rejected/report.md").exists());
    assert_eq!(contents(&s.path("out")), good);
    assert_eq!(s.entries(), vec!["fit.toml", "out", "out.rejected"]);
}

#[test]
fn a_listed_result_the_user_edited_is_never_replaced_or_removed() {
    let s = Scratch::new("edited");
    succeeds(&simulate(&s, "out", &[]));
    // Unchanged results are replaced as before.
    succeeds(&simulate(&s, "out", &["--c-rate", "2"]));
    let csv = "spm_simulation.csv";
    let edited = format!("{}my annotation\n", std::fs::read_to_string(s.path("out").join(csv)).unwrap());
    std::fs::write(s.path("out").join(csv), &edited).unwrap();
    let before = contents(&s.path("out"));
    let o = simulate(&s, "out", &[]);
    fails_with(&o, &[csv, "was changed since cellstudio wrote it", "nothing was moved"]);
    assert_eq!(contents(&s.path("out")), before, "a refused run changed the folder");
    assert_eq!(s.entries(), vec!["out"], "a partial folder was left behind");

    // A stale result (the SPMe writes other names) the user edited is left, with a warning;
    // the unedited stale ones go.
    let o = run(&s.0, &["simulate", "--model", "spme", "--mesh", "5", "--out", "out"]);
    succeeds(&o);
    assert_eq!(std::fs::read_to_string(s.path("out").join(csv)).unwrap(), edited);
    assert!(stderr(&o).lines().any(|l| l.starts_with("warning:") && l.contains(&format!("`{csv}`")) && l.contains("changed since")), "{}", stderr(&o));
    assert!(!s.path("out/spm_simulation_voltage.svg").exists(), "an unedited stale result stayed");
    assert!(s.path("out/spme_simulation.csv").exists());
}
