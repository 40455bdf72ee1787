//! Development probe: evaluates our SPMe/DFN voltage and DFN algebraic residuals on states
//! exported from PyBaMM (JSON written by `scripts/pybamm_states.py`; argument: its path), so that differences in
//! the model equations show up without any time integration. `PROBE_ROWS` prints every
//! algebraic residual.
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use serde_json::Value;

fn vec1(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

/// Column `k` of a (n, t) array.
fn col(v: &Value, k: usize) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|row| row[k].as_f64().unwrap()).collect()
}

fn main() {
    let path = std::env::args().nth(1).unwrap_or("/tmp/acc/probe.json".into());
    let data: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let p = chen2020();
    let current = 5.0;
    if std::env::var("PROBE_KINETICS").is_ok() {
        let mut b = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
        kinetics(b.build(&p).unwrap().model.electrochem());
    }
    for (kind, key) in [(ModelKind::Spme, "SPMe"), (ModelKind::Dfn, "DFN")] {
        let d = &data[key];
        let t = vec1(&d["t"]);
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let built = b.build(&p).unwrap();
        let model = built.model.as_ref();
        for k in 0..t.len() {
            let v_ref = vec1(&d["Voltage [V]"])[k];
            let mut y = Vec::new();
            if kind == ModelKind::Spme {
                y.extend(col(&d["X-averaged negative particle concentration [mol.m-3]"], k));
                y.extend(col(&d["X-averaged positive particle concentration [mol.m-3]"], k));
                y.extend(col(&d["Electrolyte concentration [mol.m-3]"], k));
            } else {
                for name in ["Negative particle concentration [mol.m-3]", "Positive particle concentration [mol.m-3]"] {
                    // entries (r, x, t) or (x, r, t): x-node major in our layout
                    let a = d[name].as_array().unwrap();
                    let (n0, n1) = (a.len(), a[0].as_array().unwrap().len());
                    for i in 0..n1 {
                        for r in 0..n0 {
                            y.push(a[r][i][k].as_f64().unwrap());
                        }
                    }
                }
                y.extend(col(&d["Electrolyte concentration [mol.m-3]"], k));
                y.extend(col(&d["Electrolyte potential [V]"], k));
                y.extend(col(&d["Negative electrode potential [V]"], k));
                y.extend(col(&d["Positive electrode potential [V]"], k));
            }
            assert_eq!(y.len(), model.len());
            let v = model.voltage(&y, current);
            let mut f = vec![0.0; y.len()];
            model.rhs(&y, current, &mut f);
            let alg: f64 = f.iter().zip(model.mass()).filter(|(_, m)| **m == 0.0).map(|(r, _)| r.abs()).fold(0.0, f64::max);
            if std::env::var("PROBE_ROWS").is_ok() {
                let rows: Vec<String> = f.iter().enumerate().filter(|(i, _)| model.mass()[*i] == 0.0).map(|(i, r)| format!("{i}:{r:.2e}")).collect();
                println!("{}", rows.join(" "));
            }
            println!("{key:5} t {:8.1}  V ours {:.9}  PyBaMM {:.9}  diff {:+.4} mV  max |algebraic residual| {alg:.3e}", t[k], v, v_ref, (v - v_ref) * 1e3);
        }
    }
}

/// With `PROBE_KINETICS` set: OCP, exchange current and Butler-Volmer current of the DFN at
/// PyBaMM's initial Chen 2020 surface concentrations (mol/m^3), c_e = 1000 mol/m^3, 298.15 K,
/// to set beside PyBaMM's own variables.
fn kinetics(ec: &cellstudio::models::Electrochem) {
    use cellstudio::models::electrochem::Side;
    use cellstudio::models::kinetics::butler_volmer;
    for (side, c_s, eta) in [(Side::Negative, 29866.0, 0.0978551), (Side::Positive, 17038.0, -0.1)] {
        let j0 = ec.j0(side, 1000.0, c_s, 298.15);
        println!("{side:?}: ocp {:.12} j0 {:.12} j(eta) {:.12}", ec.ocp(side, c_s, 298.15), j0, butler_volmer(j0, eta, 0.5, 298.15));
    }
}
