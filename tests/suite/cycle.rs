//! `cellstudio cycle`: the example study (`examples/cycle_sei_chen2020.toml`) writes one
//! summary row per cycle, all or nothing; bad settings fail with an error naming the key.

use crate::cli_support;

use cli_support::*;

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/cycle_sei_chen2020.toml");

/// The example with `edit` applied to its text, written into `s`.
fn study(s: &Scratch, edit: impl Fn(String) -> String) -> String {
    let text = edit(std::fs::read_to_string(EXAMPLE).unwrap());
    s.write("study.toml", &text).display().to_string()
}

/// The rows of a `cycles.csv` (header skipped), an empty column as NaN.
fn numbers(csv: &str) -> Vec<Vec<f64>> {
    csv.lines().skip(1).map(|l| l.split(',').map(|x| if x.is_empty() { f64::NAN } else { x.parse().unwrap() }).collect()).collect()
}

#[test]
fn cycle_study_writes_a_summary_per_cycle() {
    let s = Scratch::new("cycle");
    let path = study(&s, |t| t.replace("cycles = 20", "cycles = 6"));
    let o = run(&s.0, &["cycle", &path]);
    succeeds(&o);
    let csv = std::fs::read_to_string(s.path("out/cycle_sei/cycles.csv")).unwrap();
    // Columns of absent submodels (here loss of active material) are empty.
    let rows = numbers(&csv);
    assert_eq!(rows.len(), 6);
    assert_eq!(rows[0][4], 1.0, "retention is relative to the first cycle");
    for w in rows.windows(2) {
        // Each cycle loses capacity and lithium to a thicker SEI.
        assert!(w[1][2] < w[0][2] && w[1][5] > w[0][5] && w[1][7] > w[0][7], "{w:?}");
    }
    // Starting empty, the first charge is the largest; later charges restore what was taken.
    assert!(rows[0][3] > rows[1][3] && (rows[1][3] - rows[1][2]).abs() < 1e-3 * rows[1][2], "{rows:?}");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(s.path("out/cycle_sei/cycles.json")).unwrap()).unwrap();
    assert_eq!(json["cycles"].as_array().unwrap().len(), 6);
    assert!(s.path("out/cycle_sei/capacity_retention.svg").is_file());
}

#[test]
fn bad_cycle_settings_name_the_key() {
    let s = Scratch::new("cycle-bad");
    for (from, to, needles) in [
        ("cycles = 20", "cycles = 0", vec!["cycling.cycles", "0"]),
        ("tolerance = 1e-6", "tolerance = 0.5", vec!["cycling.tolerance", "0.5"]),
        ("initial_soc = 0.0", "initial_soc = 1.5", vec!["cycling.initial_soc", "1.5"]),
        ("\"Rest for 10 minutes\",\n    \"Discharge", "\"Rest for ten minutes\",\n    \"Discharge", vec!["cycling.cycle"]),
        ("{ sei = \"reaction limited\" }", "{ lam = \"reaction-driven\" }", vec!["model.submodels.lam", "SEI"]),
        ("sei = \"reaction limited\"", "sei = \"fast\"", vec!["study.toml", "line 12"]),
    ] {
        let path = study(&s, |t| {
            assert!(t.contains(from), "{from}");
            t.replace(from, to)
        });
        let o = run(&s.0, &["cycle", &path]);
        fails_with(&o, &needles);
        assert!(!s.path("out/cycle_sei").exists(), "{to}: a failed run left outputs");
    }
    let o = run(&s.0, &["cycle", EXAMPLE, "--set", "sei.initial_thickness=-1"]);
    fails_with(&o, &["sei.initial_thickness", "-1"]);
}

/// The LAM example (`examples/cycle_lam_chen2020.toml`): each cycle loses active material in
/// both electrodes and lithium with it, reported in its own columns; a bad LAM parameter is
/// an error naming it.
#[test]
fn cycle_study_reports_active_material_lost() {
    let s = Scratch::new("cycle-lam");
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/cycle_lam_chen2020.toml");
    let text = std::fs::read_to_string(example).unwrap().replace("cycles = 20", "cycles = 4");
    let path = s.write("study.toml", &text).display().to_string();
    let o = run(&s.0, &["cycle", &path]);
    succeeds(&o);
    let csv = std::fs::read_to_string(s.path("out/cycle_lam/cycles.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let lam = ["negative_active_material_lost", "positive_active_material_lost", "lithium_lost_to_negative_lam_mol", "lithium_lost_to_positive_lam_mol"].map(col);
    let rows = numbers(&csv);
    assert_eq!(rows.len(), 4);
    for w in rows.windows(2) {
        assert!(lam.iter().all(|&c| w[1][c] > w[0][c] && w[0][c] > 0.0), "{w:?}");
    }
    let o = run(&s.0, &["cycle", &path, "--set", "lam.positive.poisson_ratio=0.7"]);
    fails_with(&o, &["lam.positive.poisson_ratio", "0.7"]);
}

/// The plating example (`examples/cycle_plating_chen2020.toml`): its last two columns (after
/// `steps`) hold the lithium lost to plating and the dead lithium, which grows each cycle;
/// a bad plating parameter is an error naming it.
#[test]
fn cycle_study_reports_plated_lithium() {
    let s = Scratch::new("cycle-plating");
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/cycle_plating_chen2020.toml");
    let text = std::fs::read_to_string(example).unwrap().replace("cycles = 20", "cycles = 3");
    let path = s.write("study.toml", &text).display().to_string();
    let o = run(&s.0, &["cycle", &path]);
    succeeds(&o);
    let csv = std::fs::read_to_string(s.path("out/cycle_plating/cycles.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(header[header.len() - 3..], ["steps", "lithium_lost_to_plating_mol", "dead_lithium_mol"]);
    let rows = numbers(&csv);
    let (lost, dead) = (header.len() - 2, header.len() - 1);
    assert_eq!(rows.len(), 3);
    for w in rows.windows(2) {
        assert!(w[1][dead] > w[0][dead] && w[0][dead] > 0.0 && w[1][lost] >= w[1][dead], "{w:?}");
    }
    let o = run(&s.0, &["cycle", &path, "--set", "plating.transfer_coefficient=1.5"]);
    fails_with(&o, &["plating.transfer_coefficient", "1.5"]);
}
