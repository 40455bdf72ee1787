//! Ageing parameters fitted to capacity fade (issue 15 item 5): PyBaMM's 10-cycle fade of the
//! Chen 2020 SPM with SEI growth (tests/data/sei, scripts/make_sei_reference.py) gives back
//! PyBaMM's SEI rate parameter from a start 5x off; a fit held off the value says it lies on
//! its bound; bad fade files and `[fit]` tables are refused with the field named.

use std::path::{Path, PathBuf};

use cellstudio::study::cycle::CycleStudy;

fn example() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/fade_fit_sei_chen2020.toml")).unwrap()
}

/// The example study with `edit` applied, its data path absolute, written to `name` in `dir`.
fn study(dir: &Path, name: &str, edit: impl Fn(String) -> String) -> Result<CycleStudy, String> {
    let root = env!("CARGO_MANIFEST_DIR");
    let text = edit(example().replace("data = \"tests/", &format!("data = \"{root}/tests/")));
    let out = dir.join(format!("out-{name}"));
    let text = text.replace("dir = \"out/fade_fit_sei_chen2020\"", &format!("dir = \"{}\"", out.display()));
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    CycleStudy::from_file(&path).map_err(|e| e.to_string())
}

fn fitted(s: &CycleStudy) -> (f64, f64, Vec<String>) {
    let out = s.run(&mut |_| {}).unwrap();
    let fade = out.fade.expect("a [fit] table gives a fade fit");
    println!("{} -> {:?} ± {:?}; RMSE {:.2e} A h (start {:.2e}), {} simulations", s.name, fade.values, fade.std_errors, fade.rmse_fitted_ah, fade.rmse_start_ah, fade.simulations);
    (fade.values[0], fade.std_errors[0], fade.warnings())
}

#[test]
fn fade_fit_recovers_pybamm_sei_parameters() {
    // PyBaMM's Chen 2020 SEI values (pybamm.ParameterValues("Chen2020") with its SEI set).
    let dir = tempfile::tempdir().unwrap();
    let (k, dk, w) = fitted(&study(dir.path(), "reaction", |t| t).unwrap());
    assert!((k / 1.5e-7 - 1.0).abs() < 1e-3, "exchange current {k}");
    assert!(dk > 0.0 && dk < 1e-3 * k, "standard error {dk}");
    assert!(w.is_empty(), "{w:?}");
    let (d, dd, w) = fitted(
        &study(dir.path(), "solvent", |t| {
            t.replace("spm_reaction_limited", "spm_solvent_diffusion_limited").replace("reaction limited", "solvent-diffusion limited").replace(
                "path = \"sei.exchange_current\", initial = 7.5e-7, lower = 1e-9, upper = 1e-5",
                "path = \"sei.solvent_diffusivity\", initial = 1.25e-21, lower = 1e-24, upper = 1e-19",
            )
        })
        .unwrap(),
    );
    assert!((d / 2.5e-22 - 1.0).abs() < 1e-4, "solvent diffusivity {d}");
    assert!(dd > 0.0 && dd < 1e-3 * d, "standard error {dd}");
    assert!(w.is_empty(), "{w:?}");
}

#[test]
fn a_fit_held_off_the_value_says_it_lies_on_its_bound() {
    let dir = tempfile::tempdir().unwrap();
    let (k, _, w) = fitted(&study(dir.path(), "bound", |t| t.replace("initial = 7.5e-7, lower = 1e-9, upper = 1e-5", "initial = 7.5e-7, lower = 5e-7, upper = 1e-5")).unwrap());
    assert!((k / 5e-7 - 1.0).abs() < 1e-3, "{k}");
    assert!(w.iter().any(|w| w.contains("sei.exchange_current") && w.contains("bound")), "{w:?}");
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn run_with_data(dir: &Path, name: &str, csv: &str) -> String {
    let data = write(dir, &format!("{name}.csv"), csv);
    let s = study(dir, name, |t| t.replace(&format!("{}/tests/data/sei/spm_reaction_limited_cycles.csv", env!("CARGO_MANIFEST_DIR")), &data.display().to_string())).unwrap();
    s.run(&mut |_| {}).err().expect("bad data should be refused").to_string()
}

#[test]
fn bad_fade_files_and_fit_tables_are_refused_by_name() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let e = run_with_data(dir, "nan", "cycle,discharge_capacity_Ah\n1,4.6\n2,nan\n3,4.5\n");
    assert!(e.contains("line 3") && e.contains("discharge_capacity_Ah"), "{e}");
    let e = run_with_data(dir, "back", "cycle,discharge_capacity_Ah\n1,4.6\n3,4.5\n2,4.4\n");
    assert!(e.contains("line 4") && e.contains("does not increase"), "{e}");
    let e = run_with_data(dir, "column", "cycle,capacity\n1,4.6\n2,4.5\n3,4.4\n");
    assert!(e.contains("missing column `discharge_capacity_Ah`"), "{e}");
    let e = run_with_data(dir, "short", "cycle,discharge_capacity_Ah\n1,4.6\n2,4.5\n");
    assert!(e.contains("at least 3 cycles"), "{e}");
    let e = run_with_data(dir, "zero", "cycle,discharge_capacity_Ah\n0,4.6\n1,4.5\n2,4.4\n");
    assert!(e.contains("line 2") && e.contains("cycle number"), "{e}");
    let e = study(dir, "unknown", |t| t.replace("sei.exchange_current", "sei.exchange_currant")).err().unwrap();
    assert!(e.contains("sei.exchange_currant"), "{e}");
    let e = study(dir, "empty", |t| {
        let start = t.find("parameters = [").unwrap();
        let end = start + t[start..].find('\n').unwrap();
        format!("{}parameters = []{}", &t[..start], &t[end..])
    })
    .err()
    .unwrap();
    assert!(e.contains("fit.parameters"), "{e}");
    let e = study(dir, "typo", |t| t.replace("[fit]\n", "[fit]\nweights = 1\n")).err().unwrap();
    assert!(e.contains("weights"), "{e}");
    assert!(dir.exists());
}
