//! The 21700 design study: the format reaches the report (mass basis table, capacity and area
//! that follow the thickness), and bad format input is an error naming the field.

use cellstudio::study::Study;
use cellstudio::study::design::run_design;

fn text() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_21700_chen2020.toml")).unwrap()
}

#[test]
fn study_in_a_21700_reports_its_mass_basis() {
    let mut study = Study::from_toml(&text(), "21700.toml").unwrap();
    let tmp = tempfile::tempdir().unwrap();
    study.output.dir = tmp.path().join("out");
    let out = run_design(&study).unwrap();
    // Fixed can: the volume stays, the area grows as the positive coating thins.
    assert_eq!(out.initial.volume, out.optimised.volume);
    assert!(out.result.x[0] < out.initial_x[0] && out.optimised.area > out.initial.area);
    let report = std::fs::read_to_string(study.output.dir.join("report.md")).unwrap();
    for needle in ["## Mass and volume basis", "cylindrical 21.0 x 70.0 mm", "can (side wall and bottom)", "| 7900 |", "Power is the mean power"] {
        assert!(report.contains(needle), "report lacks `{needle}`");
    }
    // Every row of each Markdown table has as many cells as its header.
    let mut width = None;
    for line in report.lines() {
        if line.starts_with('|') {
            let n = line.matches('|').count();
            assert_eq!(*width.get_or_insert(n), n, "ragged table row: {line}");
        } else {
            width = None;
        }
    }
}

#[test]
fn bad_format_input_names_the_field_and_value() {
    let cases = [
        (text().replace("wall = 0.25e-3", "wall = -0.25e-3"), "cell.can.wall"),
        (text().replace("format = \"cylindrical_21700\"", "format = \"cylindrical_18650\""), "cylindrical_18650"),
        (text().replace("headspace = 6.0e-3", "headspac = 6.0e-3"), "headspac"),
        (text().replace("mandrel_diameter = 2.5e-3", "mandrel_diameter = 21e-3"), "cell.can.mandrel_diameter"),
        (text().replace("path = \"positive.active_fraction\"", "path = \"cell.electrode_width\""), "variables[1].path"),
        (text().replace("format = \"cylindrical_21700\"", "format = \"pouch\""), "cell.can"),
        (text().replace("format = \"cylindrical_21700\"", "format = \"pouch\"").replace("[cell.can]", "[cell.pouch]\nlength = 0.1\nwidth = 0.05\nthickness = 0.2e-3\n[cell.unused]"), "cell.unused"),
    ];
    for (t, needle) in cases {
        let e = Study::from_toml(&t, "bad.toml").unwrap_err().to_string();
        assert!(e.contains(needle), "expected `{needle}` in: {e}");
    }
    // A pouch too thin for one layer.
    let t = text()
        .replace("format = \"cylindrical_21700\"", "format = \"pouch\"")
        .split("[cell.can]")
        .next()
        .unwrap()
        .to_string()
        + "[cell.pouch]\nlength = 0.1\nwidth = 0.05\nthickness = 0.3e-3\n"
        + text().split("extra_mass = 4.0e-3").nth(1).unwrap();
    let e = Study::from_toml(&t, "bad.toml").unwrap_err().to_string();
    assert!(e.contains("cell.pouch.thickness") && e.contains("3e-4"), "{e}");
}

#[test]
fn pybop_mass_basis_reproduces_pybops_convention_and_needs_free_area() {
    let seed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_chen2020.toml")).unwrap();
    let t = seed.replace("parameter_set = \"chen2020\"", "parameter_set = \"chen2020\"\nmass_basis = \"pybop\"");
    let study = Study::from_toml(&t, "pybop.toml").unwrap();
    let problem = study.problem().unwrap();
    let m = problem.evaluate(&study.baseline().unwrap()).unwrap();
    // Same discharge as the default basis; only the mass (45.6 g instead of 68.0 g) changes.
    let own = Study::from_toml(&seed, "seed.toml").unwrap().problem().unwrap().evaluate(&study.baseline().unwrap()).unwrap();
    assert_eq!(m.energy, own.energy);
    assert!((m.mass * 1e3 - 45.59).abs() < 0.01 && (own.mass * 1e3 - 67.98).abs() < 0.01, "{} {}", m.mass, own.mass);
    let e = Study::from_toml(&text().replace("format = \"cylindrical_21700\"", "format = \"cylindrical_21700\"\nmass_basis = \"pybop\""), "bad.toml").unwrap_err().to_string();
    assert!(e.contains("cell.mass_basis") && e.contains("free_area"), "{e}");
    let e = Study::from_toml(&seed.replace("[model]", "[cell.pybop]\nseparator = -1.0\n\n[model]"), "bad.toml").unwrap_err().to_string();
    assert!(e.contains("cell.pybop"), "{e}");
}
