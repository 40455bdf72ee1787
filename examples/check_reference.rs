//! Prints voltage errors of SPM/SPMe/DFN against the PyBaMM reference curves.
use cellstudio::data::Recording;
use cellstudio::geometry::{MeshSizes, ModelBuilder};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn main() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for (rate, tag) in [(0.5, "0.5C"), (1.0, "1C"), (2.0, "2C")] {
            let name = format!("{}_{}", kind.to_string().to_lowercase(), tag);
            let rec = Recording::from_csv(format!("tests/data/{name}.csv").as_ref()).unwrap();
            let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
            let built = b.build(&p).unwrap();
            let opts = SimOptions { t_eval: Some(rec.time.clone()), ..SimOptions::for_cell(&p) };
            let t = std::time::Instant::now();
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(rate), &opts, None);
            let el = t.elapsed();
            match sol {
                Ok(sol) => {
                    let e = rec.voltage_error(&sol.time, &sol.voltage);
                    println!("{name:10} rms {:7.3} mV max {:7.3} mV  end {:8.1} s (ref {:8.1})  Q {:.4} Ah  {:?} steps {} jac {} rhs {}",
                        e.rms * 1e3, e.max * 1e3, sol.time.last().unwrap(), rec.time.last().unwrap(), sol.final_capacity(), el, sol.stats.steps, sol.stats.jacobian_evals, sol.stats.rhs_evals);
                }
                Err(e) => println!("{name}: {e}"),
            }
        }
    }
}
