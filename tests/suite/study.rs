//! Study files: the shipped studies parse, and bad files give errors naming key and line.

use cellstudio::study::Study;

#[test]
fn shipped_studies_parse_and_validate() {
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/designs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            Study::from_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
}

fn seed_text() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_chen2020.toml")).unwrap()
}

#[test]
fn unknown_key_names_key_and_line() {
    let text = seed_text().replace("c_rate = 1.0", "c_rate = 1.0\nc_rat = 2.0");
    let err = Study::from_toml(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("c_rat") && err.contains("line"), "{err}");
}

#[test]
fn impossible_bounds_are_named() {
    let text = seed_text().replace("upper = 110e-6", "upper = 10e-6");
    let err = Study::from_toml(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("variables[0].upper"), "{err}");
}

#[test]
fn unknown_parameter_path_is_named() {
    let text = seed_text().replace("path = \"positive.thickness\"", "path = \"positive.thicknes\"");
    let err = Study::from_toml(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("variables[0].path") && err.contains("positive.thicknes"), "{err}");
}

#[test]
fn unknown_metric_is_an_error() {
    let text = seed_text().replace("gravimetric_energy_density\"]", "specific_energy\"]");
    let err = Study::from_toml(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("specific_energy") && err.contains("line"), "{err}");
}

#[test]
fn operating_needs_exactly_one_of_c_rate_and_power() {
    let both = seed_text().replace("c_rate = 1.0", "c_rate = 1.0\npower = 15.0");
    let err = Study::from_toml(&both, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("operating") && err.contains("exactly one"), "{err}");
}

/// A constant-power study discharges each design at that power: the mean power over the
/// discharge equals it.
#[test]
fn power_study_discharges_at_constant_power() {
    let text = seed_text().replace("c_rate = 1.0", "power = 15.0");
    let study = Study::from_toml(&text, "power.toml").unwrap();
    let m = study.problem().unwrap().evaluate(&study.baseline().unwrap()).unwrap();
    let mean_power = m.energy * 3600.0 / m.duration;
    println!("15 W: {:.3} W h in {:.0} s, mean current {:.3} A", m.energy, m.duration, m.current);
    assert!((mean_power - 15.0).abs() < 1e-6, "{mean_power} W");
    assert!(m.energy > 15.0, "a 15 W discharge of a 5 A h cell lasts over an hour");
}
