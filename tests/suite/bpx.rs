//! BPX import and export: a lossless Chen 2020 round trip, unknown keys reported, malformed
//! values rejected by BPX key, a hand-written v0.5 NMC/graphite document (with a DFN run
//! against its 1C validation data), expressions, and the v1 `State` section.

use crate::common;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::bpx::{BpxImport, from_bpx_json, stoichiometry_windows, to_bpx_json};
use cellstudio::params::{FARADAY, Function1D, ParameterSet, chen2020};
use cellstudio::protocol::{Protocol, Step};
use serde_json::Value;

const NEG: &str = "Negative electrode";
const POS: &str = "Positive electrode";

fn example_text() -> String {
    let path = format!("{}/tests/data/bpx_example.json", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).expect("tests/data/bpx_example.json")
}

fn chen_doc() -> Value {
    serde_json::from_str(&to_bpx_json(&chen2020()).unwrap()).unwrap()
}

fn import(doc: &Value) -> Result<BpxImport, cellstudio::error::Error> {
    from_bpx_json(&doc.to_string())
}

fn import_err(doc: &Value) -> String {
    match import(doc) {
        Ok(_) => panic!("import should fail"),
        Err(e) => e.to_string(),
    }
}

/// Every number of `a` equals the one at the same place in `b` within `rel`; functions
/// (objects with a "kind") are compared elsewhere. Returns the number of scalars compared.
fn compare_scalars(a: &Value, b: &Value, path: &str, rel: f64) -> usize {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            if x.contains_key("kind") || y.contains_key("kind") {
                return 0;
            }
            assert_eq!(x.len(), y.len(), "{path}: different fields");
            x.iter().map(|(k, v)| compare_scalars(v, &y[k], &format!("{path}.{k}"), rel)).sum()
        }
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            let err = (x - y).abs() / x.abs().max(1e-300);
            assert!(x == y || err <= rel, "{path}: {x} exported, {y} imported (relative {err:.2e})");
            1
        }
        _ => {
            assert_eq!(a, b, "{path}");
            0
        }
    }
}

/// Chen 2020 -> BPX -> Chen 2020: every scalar within 1e-12, OCP and electrolyte tables
/// close to the built-in functions, nothing unknown, defaulted or approximated.
#[test]
fn chen2020_round_trip() {
    let original = chen2020();
    let text = to_bpx_json(&original).unwrap();
    let imported = from_bpx_json(&text).unwrap();
    assert!(imported.unknown_fields.is_empty(), "unknown: {:?}", imported.unknown_fields);
    assert!(imported.defaulted_fields.is_empty(), "defaulted: {:?}", imported.defaulted_fields);
    assert!(imported.approximated_fields.is_empty(), "approximated: {:?}", imported.approximated_fields);
    let p = &imported.params;
    let n = compare_scalars(
        &serde_json::to_value(&original).unwrap(),
        &serde_json::to_value(p).unwrap(),
        "",
        1e-12,
    );
    println!("{n} scalar fields round-trip within 1e-12");
    // 81 (with the leak current, the voltage offset and gain, the current gain and the two particle-radius
    // spreads, carried as `cellstudio.` keys), plus the 15 SEI, the 18 LAM (9 per electrode)
    // and the 6 plating fields, which BPX does not carry: both sides hold their defaults;
    // and the 2 entropic-change factors (1: BPX carries the entropic change with its factor);
    // and the 6 fields of a second active material per electrode (`cellstudio.` keys).
    assert_eq!(n, 81 + 15 + 18 + 6 + 2 + 6, "every scalar field compared");
    assert_eq!(p.name, original.name);

    // OCPs: tables against the Chen 2020 functions at 50 stoichiometries.
    for (name, table, exact) in [
        ("negative", &p.negative.ocp, Function1D::Chen2020GraphiteOcp),
        ("positive", &p.positive.ocp, Function1D::Chen2020Nmc811Ocp),
    ] {
        let Function1D::Table { x, .. } = table else { panic!("{name} OCP should be a table") };
        let worst = (0..50)
            .map(|i| 0.001 + 0.998 * i as f64 / 49.0)
            .map(|s| (table.eval(s) - exact.eval(s)).abs())
            .fold(0.0, f64::max);
        println!("{name} OCP: {} points, worst error {:.2e} V", x.len(), worst);
        assert!(worst < 1e-3, "{name} OCP off by {worst} V");
    }
    // Electrolyte: tables against Nyman 2008 at 50 concentrations.
    for (name, table, exact) in [
        ("diffusivity", &p.electrolyte.diffusivity, Function1D::Nyman2008Diffusivity),
        ("conductivity", &p.electrolyte.conductivity, Function1D::Nyman2008Conductivity),
    ] {
        assert!(matches!(table, Function1D::Table { .. }), "{name} should be a table");
        let worst = (0..50)
            .map(|i| 100.0 + 2900.0 * i as f64 / 49.0)
            .map(|c| ((table.eval(c) - exact.eval(c)) / exact.eval(c)).abs())
            .fold(0.0, f64::max);
        println!("electrolyte {name}: worst relative error {worst:.2e} over 100..3000 mol/m3");
        assert!(worst < 1e-3, "{name} off by {worst}");
    }
}

/// The exported document: BPX header, stoichiometry windows at the cut-offs, the reaction
/// rate in BPX's normalisation, and our extras under User-defined.
#[test]
fn export_follows_bpx() {
    let p = chen2020();
    let doc = chen_doc();
    assert_eq!(doc["Header"]["BPX"], 0.5);
    assert_eq!(doc["Header"]["Model"], "DFN");
    let par = &doc["Parameterisation"];
    for section in ["Cell", "Electrolyte", NEG, POS, "Separator", "User-defined"] {
        assert!(par[section].is_object(), "missing section {section}");
    }
    let (n, q) = (&par[NEG], &par[POS]);
    let f = |v: &Value| v.as_f64().unwrap();
    // The OCV at the window ends is the cut-off voltage.
    let v_max = p.positive.ocp.eval(f(&q["Minimum stoichiometry"]))
        - p.negative.ocp.eval(f(&n["Maximum stoichiometry"]));
    let v_min = p.positive.ocp.eval(f(&q["Maximum stoichiometry"]))
        - p.negative.ocp.eval(f(&n["Minimum stoichiometry"]));
    println!(
        "windows: negative [{:.4}, {:.4}], positive [{:.4}, {:.4}], OCV {v_min:.6}..{v_max:.6} V",
        f(&n["Minimum stoichiometry"]),
        f(&n["Maximum stoichiometry"]),
        f(&q["Minimum stoichiometry"]),
        f(&q["Maximum stoichiometry"])
    );
    assert!((v_max - 4.2).abs() < 1e-9 && (v_min - 2.5).abs() < 1e-9);
    let w = stoichiometry_windows(&p).unwrap();
    println!("initial state of charge of Chen 2020 within its windows: {:.4}", w.soc);
    assert!(w.soc > 0.9 && w.soc < 1.0);
    // k = m_ref c_max sqrt(c_e0) / F (PyBaMM's BPX convention).
    let k_n = f(&n["Reaction rate constant [mol.m-2.s-1]"]);
    let expected = 6.48e-7 * 33133.0 * 1000f64.sqrt() / FARADAY;
    assert!((k_n / expected - 1.0).abs() < 1e-12, "k_n = {k_n}, expected {expected}");
    assert!(n["OCP [V]"]["x"].is_array() && n["OCP [V]"]["y"].is_array());
    assert_eq!(par["User-defined"]["cellstudio.cell.packaging_mass_fraction"], 0.08);
}

/// Keys that map to nothing are reported by path, in any section, including User-defined.
#[test]
fn unknown_keys_are_reported() {
    let mut doc = chen_doc();
    doc["Parameterisation"][NEG]["Magic factor [-]"] = 3.0.into();
    doc["Parameterisation"]["User-defined"]["Thermal conductivity [W.m-1.K-1]"] = 1.5.into();
    doc["Parameterisation"]["User-defined"]["cellstudio.negative.thickness"] = 1.0.into();
    doc["Parameterisation"]["Cell"]["Thermal conductivity [W.m-1.K-1]"] = 2.0.into();
    doc["Extra"] = serde_json::json!({"anything": 1});
    let imported = import(&doc).unwrap();
    println!("unknown: {:?}", imported.unknown_fields);
    for key in [
        "Parameterisation/Negative electrode/Magic factor [-]",
        "Parameterisation/User-defined/Thermal conductivity [W.m-1.K-1]",
        "Parameterisation/User-defined/cellstudio.negative.thickness",
        "Parameterisation/Cell/Thermal conductivity [W.m-1.K-1]",
        "Extra",
    ] {
        assert!(imported.unknown_fields.iter().any(|u| u == key), "{key} not reported");
    }
    assert_eq!(imported.unknown_fields.len(), 5);
    // A user-defined key for a field BPX already carries does not override it.
    assert_eq!(imported.params.negative.thickness, chen2020().negative.thickness);
}

/// Malformed values fail with the BPX key in the message.
#[test]
fn malformed_values_name_the_bpx_key() {
    type Edit = Box<dyn Fn(&mut Value)>;
    let cases: Vec<(&str, Edit, &str)> = vec![
        (
            "negative thickness",
            Box::new(|d| d["Parameterisation"][NEG]["Thickness [m]"] = (-1e-5).into()),
            "Negative electrode/Thickness [m]",
        ),
        (
            "string porosity",
            Box::new(|d| d["Parameterisation"][POS]["Porosity"] = "high".into()),
            "Positive electrode/Porosity",
        ),
        (
            "missing key",
            Box::new(|d| {
                d["Parameterisation"]["Separator"].as_object_mut().unwrap().remove("Transport efficiency");
            }),
            "Separator/Transport efficiency",
        ),
        (
            "bad expression",
            Box::new(|d| d["Parameterisation"][NEG]["OCP [V]"] = "1 + foo(x)".into()),
            "Negative electrode/OCP [V]",
        ),
        (
            "table lengths",
            Box::new(|d| {
                d["Parameterisation"]["Electrolyte"]["Conductivity [S.m-1]"] =
                    serde_json::json!({"x": [0, 1, 2], "y": [1, 2]})
            }),
            "Electrolyte/Conductivity [S.m-1]",
        ),
        (
            "window order",
            Box::new(|d| d["Parameterisation"][NEG]["Maximum stoichiometry"] = 0.01.into()),
            "Negative electrode/Maximum stoichiometry",
        ),
        (
            "fractions over 1",
            Box::new(|d| d["Parameterisation"][NEG]["Surface area per unit volume [m-1]"] = 5e5.into()),
            "Negative electrode/Surface area per unit volume [m-1]",
        ),
        (
            "blended electrode",
            Box::new(|d| d["Parameterisation"][POS]["Particle"] = serde_json::json!({"Primary": {}})),
            "Positive electrode/Particle",
        ),
        ("version", Box::new(|d| d["Header"]["BPX"] = "2.0.0".into()), "Header/BPX"),
    ];
    for (what, edit, key) in cases {
        let mut doc = chen_doc();
        edit(&mut doc);
        let msg = import_err(&doc);
        println!("{what}: {msg}");
        assert!(msg.contains(key), "{what}: `{msg}` does not name `{key}`");
    }
    let msg = from_bpx_json("{ not json").unwrap_err().to_string();
    assert!(msg.contains("BPX JSON"), "{msg}");
}

/// The hand-written v0.5 NMC111/graphite document imports, validates, and maps as BPX says.
#[test]
fn hand_written_example_imports() {
    let imported = from_bpx_json(&example_text()).unwrap();
    let p = &imported.params;
    p.validate().unwrap();
    println!("unknown: {:?}", imported.unknown_fields);
    println!("defaulted: {:?}", imported.defaulted_fields);
    println!("approximated: {:?}", imported.approximated_fields);
    for key in [
        "Header/Description",
        "Parameterisation/Cell/Thermal conductivity [W.m-1.K-1]",
        "Validation/1C discharge",
    ] {
        assert!(imported.unknown_fields.iter().any(|u| u == key), "{key} not reported");
    }
    assert_eq!(imported.unknown_fields.len(), 3);
    for key in [
        "Parameterisation/Electrolyte/Conductivity [S.m-1]",
        "Parameterisation/Electrolyte/Diffusivity [m2.s-1]",
    ] {
        assert!(imported.approximated_fields.iter().any(|u| u == key), "{key} not approximated");
    }
    for field in [
        "cell.packaging_mass_fraction",
        "negative.active_density",
        "negative.initial_concentration",
        "electrolyte.density",
    ] {
        assert!(imported.defaulted_fields.iter().any(|u| u == field), "{field} not listed as defaulted");
    }
    for field in
        ["negative.thickness", "positive.rate_constant", "thermal.cell_volume", "cell.electrode_width"]
    {
        assert!(
            !imported.defaulted_fields.iter().any(|u| u == field),
            "{field} should come from the document"
        );
    }

    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    assert!(rel(p.cell.area(), 0.016808 * 34.0) < 1e-12);
    assert!(rel(p.negative.active_fraction, 499522.0 * 4.12e-6 / 3.0) < 1e-12);
    assert!(rel(p.negative.bruggeman_electrolyte, 0.128f64.ln() / 0.253991f64.ln()) < 1e-12);
    assert!(rel(p.positive.rate_constant, FARADAY * 2.305e-5 / (46200.0 * 1000f64.sqrt())) < 1e-12);
    // Initial state of charge 1 when the document has none: the full-charge window ends.
    assert!(rel(p.negative.initial_concentration, 0.75668 * 29730.0) < 1e-12);
    assert!(rel(p.positive.initial_concentration, 0.42424 * 46200.0) < 1e-12);
    // Lumped thermal: density x specific heat for every layer.
    assert!(rel(p.separator.volumetric_heat_capacity, 1847.0 * 913.0) < 1e-12);
    assert_eq!(p.thermal.cell_volume, 0.000128);
    assert_eq!(p.electrolyte.activation_energy, 17100.0);
    assert!(rel(p.electrolyte.conductivity.eval(1000.0), 0.1297 - 2.51 + 3.329) < 1e-4);
    let ocv = p.positive.ocp.eval(0.42424) - p.negative.ocp.eval(0.75668);
    assert!((ocv - 4.2).abs() < 0.01, "full-charge OCV {ocv}");
}

/// PyBaMM's DFN (26.10.1.1, default mesh) on tests/data/bpx_example.json through
/// `ParameterValues.create_from_bpx` (bpx 1.1.1), 1C (12.5 A) discharge: voltage (V) every
/// 100 s from 0 to 3600 s.
const PYBAMM_EXAMPLE_1C: [f64; 37] = [
    4.09887, 4.03669, 4.00158, 3.96699, 3.93187, 3.89722, 3.86563, 3.83397, 3.80219, 3.77311, 3.74579,
    3.71839, 3.69156, 3.66953, 3.64776, 3.62592, 3.60713, 3.59081, 3.57448, 3.55887, 3.54696, 3.53539,
    3.52374, 3.51312, 3.50335, 3.49259, 3.4796, 3.46471, 3.44751, 3.42461, 3.40055, 3.37571, 3.35398,
    3.33211, 3.30259, 3.24274, 3.11032,
];

/// End to end: the DFN on the imported example matches PyBaMM's DFN on the same file (same
/// BPX interpretation) and follows the document's 1C validation data.
#[test]
fn example_dfn_matches_pybamm_and_validation_data() {
    let text = example_text();
    let p = from_bpx_json(&text).unwrap().params;
    let doc: Value = serde_json::from_str(&text).unwrap();
    let data = &doc["Validation"]["1C discharge"];
    let list =
        |k: &str| -> Vec<f64> { data[k].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect() };
    let (time, voltage) = (list("Time [s]"), list("Voltage [V]"));
    let current = -list("Current [A]")[0];
    let protocol = Protocol { steps: vec![Step::Current { current, duration: 3900.0, until_voltage: None }] };
    let sol =
        common::run(ModelKind::Dfn, Submodels::default(), MeshSizes::default(), &p, &protocol, None, false);
    let at = |t: f64| cellstudio::params::function::interpolate(&sol.time, &sol.voltage, t);
    let stats = |errs: &[f64]| {
        let rms = (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt();
        (rms, errs.iter().fold(0.0f64, |m, e| m.max(e.abs())))
    };
    println!(
        "capacity {:.3} A h to {:.2} V at {:.0} s",
        sol.final_capacity(),
        sol.final_voltage(),
        sol.time.last().unwrap()
    );
    assert!((sol.final_capacity() / 12.948 - 1.0).abs() < 0.01, "PyBaMM delivers 12.948 A h to 2.7 V");

    // PyBaMM on the same document, up to 3500 s (before the end-of-discharge knee).
    let errs: Vec<f64> =
        PYBAMM_EXAMPLE_1C[..36].iter().enumerate().map(|(i, v)| at(i as f64 * 100.0) - v).collect();
    let (rms, worst) = stats(&errs);
    println!("vs PyBaMM: RMS {:.2} mV, worst {:.2} mV", rms * 1e3, worst * 1e3);
    assert!(rms < 3e-3 && worst < 10e-3, "RMS {rms} V, worst {worst} V from PyBaMM");

    // The measured validation data, up to 3500 s: the model's fit, not the import's.
    let errs: Vec<f64> =
        time.iter().zip(&voltage).filter(|(t, _)| **t <= 3500.0).map(|(t, v)| at(*t) - v).collect();
    let (rms, worst) = stats(&errs);
    println!(
        "vs validation data: {} points, RMS {:.1} mV, worst {:.1} mV",
        errs.len(),
        rms * 1e3,
        worst * 1e3
    );
    assert!(rms < 0.03, "RMS {rms} V from the validation data");
}

/// Expressions are evaluated: the Chen 2020 OCP written as a BPX expression imports as a
/// table that follows the built-in function, and is reported as approximated.
#[test]
fn expressions_are_evaluated() {
    let mut doc = chen_doc();
    doc["Parameterisation"][NEG]["OCP [V]"] =
        "1.9793 * exp(-39.3631 * x) + 0.2482 - 0.0909 * tanh(29.8538 * (x - 0.1234)) \
         - 0.04478 * tanh(14.9159 * (x - 0.2769)) - 0.0205 * tanh(30.4444 * (x - 0.6103))"
            .into();
    doc["Parameterisation"][NEG]["Diffusivity [m2.s-1]"] = "3.3e-14".into();
    doc["Parameterisation"][POS]["Entropic change coefficient [V.K-1]"] =
        serde_json::json!({"x": [0, 1], "y": [-2e-4, 0]});
    let imported = import(&doc).unwrap();
    let p = &imported.params;
    let worst = (0..50)
        .map(|i| 0.001 + 0.998 * i as f64 / 49.0)
        .map(|s| (p.negative.ocp.eval(s) - Function1D::Chen2020GraphiteOcp.eval(s)).abs())
        .fold(0.0, f64::max);
    println!("expression OCP: worst error {worst:.2e} V; approximated {:?}", imported.approximated_fields);
    assert!(worst < 1e-4);
    assert_eq!(p.negative.diffusivity, 3.3e-14);
    assert!(imported.approximated_fields.iter().any(|k| k == "Parameterisation/Negative electrode/OCP [V]"));
    // An entropic-change table is kept as the function of stoichiometry it is, not averaged.
    assert_eq!(p.positive.ocp_entropic_change, Function1D::Table { x: vec![0.0, 1.0], y: vec![-2e-4, 0.0] });
    assert!((p.positive.entropic_change(0.25) + 1.5e-4).abs() < 1e-18);
    assert!(
        !imported
            .approximated_fields
            .iter()
            .any(|k| k.ends_with("Positive electrode/Entropic change coefficient [V.K-1]"))
    );
}

/// BPX v1 layout: State carries the initial state of charge, temperatures, electrolyte
/// concentration and heat-transfer coefficient.
#[test]
fn v1_state_section_is_read() {
    let mut doc: Value = serde_json::from_str(&example_text()).unwrap();
    doc["Header"]["BPX"] = "1.1.0".into();
    let par = &mut doc["Parameterisation"];
    for key in ["Ambient temperature [K]", "Initial temperature [K]", "Thermal conductivity [W.m-1.K-1]"] {
        par["Cell"].as_object_mut().unwrap().remove(key);
    }
    par["Electrolyte"].as_object_mut().unwrap().remove("Initial concentration [mol.m-3]");
    doc["State"] = serde_json::json!({
        "Initial conditions": {
            "Initial state-of-charge": 0.5,
            "Initial temperature [K]": 300.0,
            "Initial electrolyte concentration [mol.m-3]": 1200.0,
        },
        "Thermal environment": {"Ambient temperature [K]": 295.0, "Heat transfer coefficient [W.m-2.K-1]": 7.5},
        "Degradation": {"LLI": 0.0, "LAM: Positive electrode": 0.0, "LAM: Negative electrode": 0.0},
    });
    // Our own copies of State values: State wins, the user-defined ones are reported unused.
    let user = &mut doc["Parameterisation"]["User-defined"];
    *user = serde_json::json!({
        "cellstudio.thermal.heat_transfer_coefficient": 99.0,
        "cellstudio.initial_state_of_charge": 0.9,
        "cellstudio.cell.packaging_mass_fraction": 0.1,
    });
    let imported = import(&doc).unwrap();
    let p = &imported.params;
    println!("unknown: {:?}", imported.unknown_fields);
    for key in [
        "State/Degradation",
        "Parameterisation/User-defined/cellstudio.thermal.heat_transfer_coefficient",
        "Parameterisation/User-defined/cellstudio.initial_state_of_charge",
    ] {
        assert!(imported.unknown_fields.iter().any(|k| k == key), "{key} not reported");
    }
    assert_eq!(p.cell.packaging_mass_fraction, 0.1);
    assert_eq!(p.thermal.initial_temperature, 300.0);
    assert_eq!(p.thermal.ambient_temperature, 295.0);
    assert_eq!(p.thermal.heat_transfer_coefficient, 7.5);
    assert_eq!(p.electrolyte.initial_concentration, 1200.0);
    let sto_n = p.negative.initial_concentration / p.negative.max_concentration;
    let sto_p = p.positive.initial_concentration / p.positive.max_concentration;
    assert!((sto_n - (0.005504 + 0.5 * (0.75668 - 0.005504))).abs() < 1e-12);
    assert!((sto_p - (0.96210 - 0.5 * (0.96210 - 0.42424))).abs() < 1e-12);
    assert!(!imported.defaulted_fields.iter().any(|f| f.ends_with("initial_concentration")));
    // The rate constant is normalised with the initial electrolyte concentration.
    let expected = FARADAY * 5.199e-6 / (29730.0 * 1200f64.sqrt());
    assert!((p.negative.rate_constant / expected - 1.0).abs() < 1e-12);
}

/// A modified set survives the round trip too: constant and table functions, a non-zero solid
/// Bruggeman exponent, a different transfer coefficient.
#[test]
fn modified_set_round_trip() {
    let mut p: ParameterSet = chen2020();
    p.negative.bruggeman_solid = 1.5;
    p.positive.charge_transfer_coefficient = 0.45;
    p.electrolyte.diffusivity = Function1D::Constant { value: 3e-10 };
    p.electrolyte.conductivity = Function1D::Table { x: vec![0.0, 1000.0, 2000.0], y: vec![0.0, 1.0, 0.8] };
    p.thermal.heat_transfer_coefficient = 25.0;
    p.cell.electrode_height = 0.1;
    p.cell.electrode_width = 1.0;
    p.positive.radius_relative_std = 0.2;
    let imported = from_bpx_json(&to_bpx_json(&p).unwrap()).unwrap();
    let n = compare_scalars(
        &serde_json::to_value(&p).unwrap(),
        &serde_json::to_value(&imported.params).unwrap(),
        "",
        1e-12,
    );
    assert_eq!(n, 81 + 15 + 18 + 6 + 2 + 6);
    assert_eq!(imported.params.positive.radius_relative_std, 0.2);
    assert_eq!(imported.params.electrolyte.diffusivity, p.electrolyte.diffusivity);
    assert_eq!(imported.params.electrolyte.conductivity, p.electrolyte.conductivity);
}

/// An entropic change that is a function of stoichiometry (O'Regan 2022's graphite, at 1.3
/// times its size) goes out as a table with its factor folded in and comes back as that
/// table, within the tabulation tolerance (1e-7 V/K) of the scaled function.
#[test]
fn entropic_change_function_round_trip() {
    let mut p: ParameterSet = chen2020();
    p.negative.ocp_entropic_change = Function1D::ORegan2022GraphiteEntropicChange;
    p.negative.ocp_entropic_change_factor = 1.3;
    let imported = from_bpx_json(&to_bpx_json(&p).unwrap()).unwrap();
    let back = &imported.params.negative;
    assert!(matches!(back.ocp_entropic_change, Function1D::Table { .. }), "{:?}", back.ocp_entropic_change);
    assert_eq!(back.ocp_entropic_change_factor, 1.0);
    let worst = (0..=200).map(|k| k as f64 / 200.0).map(|x| (back.entropic_change(x) - p.negative.entropic_change(x)).abs()).fold(0.0, f64::max);
    println!("entropic change round trip: worst {worst:.2e} V/K");
    assert!(worst < 1e-7, "worst {worst:.2e} V/K");
    assert!(imported.params.positive.ocp_entropic_change.is_zero());
}
