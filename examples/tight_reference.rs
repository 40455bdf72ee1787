//! Writes a tight reference curve of our own solver for `examples/work_precision.rs` when
//! PyBaMM's rtol 1e-10 curves (`scripts/accuracy_vs_pybamm.py`) are not at hand: the voltage
//! (V) of MODEL under CASE at rtol = atol = RTOL, at the times (s) of an existing curve
//! TIMES_CSV (repeated times, the two sides of a current step, are kept repeated so that the
//! error skips them as it does for PyBaMM's curves).
//!
//! `cargo run --release --example tight_reference -- MODEL CASE RTOL TIMES_CSV OUT_CSV`

#[path = "common/solver_case.rs"]
#[allow(dead_code)] // REPEATS is not used here
mod solver_case;

use std::io::Write;

use cellstudio::data::Recording;
use cellstudio::simulation::{SimOptions, simulate};
use solver_case::SolverCase;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [model, case, rtol, times, out] = args.as_slice() else {
        panic!("usage: tight_reference MODEL CASE RTOL TIMES_CSV OUT_CSV");
    };
    let SolverCase { protocol, options, params: p, mut builder, .. } = SolverCase::new(model, case, rtol, "1");
    let rec = Recording::from_csv(times.as_ref()).expect("times");
    let built = builder.build(&p).expect("build");
    let opts = SimOptions { t_eval: Some(rec.distinct_times()), ..options };
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).expect("simulate");
    let mut f = std::io::BufWriter::new(std::fs::File::create(out).expect("output"));
    writeln!(f, "time_s,current_A,voltage_V").expect("write");
    let mut k = 0;
    for &t in &rec.time {
        while k + 1 < sol.time.len() && sol.time[k] < t {
            k += 1;
        }
        if sol.time[k] != t {
            continue; // past the cut-off
        }
        writeln!(f, "{t:.17e},{:.17e},{:.17e}", sol.current[k], sol.voltage[k]).expect("write");
    }
}
