//! Non-physical input gives an error that names the field and the value, never a panic.

use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn build_error(edit: impl Fn(&mut cellstudio::params::ParameterSet)) -> String {
    let mut p = chen2020();
    edit(&mut p);
    let mut b = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
    match b.build(&p) {
        Ok(_) => panic!("accepted a bad parameter set"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn negative_thickness_is_named() {
    let e = build_error(|p| p.positive.thickness = -7e-5);
    assert!(e.contains("positive.thickness") && e.contains("-7e-5"), "{e}");
}

#[test]
fn porosity_outside_unit_interval_is_named() {
    let e = build_error(|p| p.separator.porosity = 1.2);
    assert!(e.contains("separator.porosity") && e.contains("1.2"), "{e}");
}

#[test]
fn volume_fractions_above_one_are_named() {
    let e = build_error(|p| p.negative.active_fraction = 0.8);
    assert!(e.contains("negative.active_fraction") && e.contains("exceeds 1"), "{e}");
}

#[test]
fn cutoff_above_initial_voltage_is_named() {
    let mut p = chen2020();
    p.cell.lower_cutoff = 4.15;
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let err = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(1.0), &SimOptions::for_cell(&p), None)
        .unwrap_err()
        .to_string();
    assert!(err.contains("cell.lower_cutoff") && err.contains("4.15"), "{err}");
}

#[test]
fn unknown_parameter_path_is_named() {
    let mut p = chen2020();
    let e = p.set("positive.thicknes", 1e-5).unwrap_err().to_string();
    assert!(e.contains("positive.thicknes"), "{e}");
}

#[test]
fn recording_with_nan_or_backwards_time_is_rejected() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let nan = dir.join("nan.csv");
    std::fs::write(&nan, "time_s,current_A,voltage_V\n0,5,4.1\n1,5,NaN\n").unwrap();
    let e = Recording::from_csv(&nan).unwrap_err().to_string();
    assert!(e.contains("line 3") && e.contains("voltage_V"), "{e}");
    let back = dir.join("back.csv");
    std::fs::write(&back, "time_s,current_A,voltage_V\n0,5,4.1\n2,5,4.0\n1,5,3.9\n").unwrap();
    let e = Recording::from_csv(&back).unwrap_err().to_string();
    assert!(e.contains("line 4") && e.contains("time_s"), "{e}");
    let missing = dir.join("missing.csv");
    std::fs::write(&missing, "time_s,voltage_V\n0,4.1\n1,4.0\n").unwrap();
    let e = Recording::from_csv(&missing).unwrap_err().to_string();
    assert!(e.contains("current_A"), "{e}");
}

#[test]
fn protocol_with_negative_duration_is_named() {
    let p = chen2020();
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let protocol = Protocol { steps: vec![cellstudio::protocol::Step::Rest { duration: -5.0 }] };
    let err = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &SimOptions::for_cell(&p), None)
        .unwrap_err()
        .to_string();
    assert!(err.contains("protocol.steps[0].duration") && err.contains("-5"), "{err}");
}

#[test]
fn temperatures_in_celsius_are_named() {
    let e = build_error(|p| p.thermal.ambient_temperature = 25.0);
    assert!(e.contains("thermal.ambient_temperature") && e.contains("25") && e.contains("kelvin"), "{e}");
    let dir = tempfile::tempdir().unwrap();
    let celsius = dir.path().join("celsius.csv");
    std::fs::write(&celsius, "time_s,current_A,voltage_V,temperature_K\n0,5,4.1,298.1\n1,5,4.0,25.3\n").unwrap();
    let e = Recording::from_csv(&celsius).unwrap_err().to_string();
    assert!(e.contains("line 3") && e.contains("temperature_K") && e.contains("25.3"), "{e}");
}
