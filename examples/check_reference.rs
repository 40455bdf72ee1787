//! Prints voltage errors of SPM/SPMe/DFN against the PyBaMM reference curves.
//!
//! Environment: `BENCH_TOL` sets rtol = atol (default: the solver's defaults); `REF_DIR`
//! reads the curves from another directory than `tests/data` (e.g. the rtol 1e-10 curves of
//! `scripts/accuracy_vs_pybamm.py`); missing files are skipped.
use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn main() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        let pulse: Protocol = toml::from_str(&std::fs::read_to_string("protocols/pulse_1C.toml").unwrap()).unwrap();
        for (proto, tag) in [(Protocol::discharge(0.5), "0.5C"), (Protocol::discharge(1.0), "1C"), (Protocol::discharge(2.0), "2C"), (pulse, "pulse")] {
            let name = format!("{}_{}", kind.to_string().to_lowercase(), tag);
            let dir = std::env::var("REF_DIR").unwrap_or_else(|_| "tests/data".into());
            let Ok(rec) = Recording::from_csv(format!("{dir}/{name}.csv").as_ref()) else { continue };
            let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
            let built = b.build(&p).unwrap();
            let mut opts = SimOptions { t_eval: Some(rec.distinct_times()), ..SimOptions::for_cell(&p) };
            if let Some(tol) = std::env::var("BENCH_TOL").ok().and_then(|t| t.parse().ok()) {
                opts.solver.set_tolerance(tol);
            }
            let t = std::time::Instant::now();
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &proto, &opts, None);
            let el = t.elapsed();
            match sol {
                Ok(sol) => {
                    let e = rec.voltage_error(&sol.time, &sol.voltage);
                    println!("{name:10} rms {:9.3e} mV max {:9.3e} mV  end {:8.1} s (ref {:8.1})  Q {:.4} Ah  {:?} steps {} jac {} rhs {}",
                        e.rms * 1e3, e.max * 1e3, sol.time.last().unwrap(), rec.time.last().unwrap(), sol.final_capacity(), el, sol.stats.steps, sol.stats.jacobian_evals, sol.stats.rhs_evals);
                }
                Err(e) => println!("{name}: {e}"),
            }
        }
    }
}
