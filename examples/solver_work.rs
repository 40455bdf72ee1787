//! Work of repeated solves, for instruction-count measurements (`perf stat -e instructions:u`):
//! builds the model once, solves REPEATS times and prints the solver's counters of one solve.
//! The instructions of one solve are the difference of two runs with different REPEATS
//! divided by the difference of REPEATS (the build and start-up cancel).
//!
//! `cargo run --release --example solver_work -- MODEL CASE RTOL REPEATS [DT]`
//! (MODEL spm|spme|dfn, CASE 0.5C|1C|2C|pulse; rtol = atol = RTOL). With DT (s), outputs
//! every DT seconds up to 4000 s (the 1C discharge's length) without charge and energy, as a
//! fit to a recording asks for them. `INTEGRALS=1` or `0` sets whether they are computed.

#[path = "common/solver_case.rs"]
mod solver_case;

use cellstudio::simulation::{Integrals, simulate};
use solver_case::SolverCase;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (model, case, rtol, repeats, dt) = match args.as_slice() {
        [m, c, r, n] => (m, c, r, n, None),
        [m, c, r, n, dt] => (m, c, r, n, Some(dt.parse::<f64>().expect("DT"))),
        _ => panic!("usage: solver_work MODEL CASE RTOL REPEATS [DT]"),
    };
    let SolverCase { protocol, options: mut opts, params: p, mut builder, repeats } = SolverCase::new(model, case, rtol, repeats);
    if let Some(dt) = dt {
        let end = protocol.steps.iter().map(|s| s.duration()).sum::<f64>().min(4000.0);
        opts.t_eval = Some((0..=(end / dt) as usize).map(|k| k as f64 * dt).collect());
        // Fits read only the voltage.
        opts.integrals = Integrals::Off;
    }
    // INTEGRALS=1 / 0 times a solve with / without the charge and energy.
    if let Some(v) = std::env::var_os("INTEGRALS") {
        opts.integrals = if v == "1" { Integrals::AtStepEnds } else { Integrals::Off };
    }
    let rtol = opts.solver.rtol;
    let built = builder.build(&p).expect("build");
    if std::env::var("SHOW_LU").is_ok() {
        println!("states {} factor entries {} colours {}", built.model.len(), built.workspace.factor_nnz(), built.workspace.n_colours());
    }
    let mut stats = None;
    for _ in 0..repeats {
        let s = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).expect("simulate");
        stats = Some(s.stats);
    }
    if let Some(s) = stats {
        println!("{model} {case} rtol {rtol:e}: {}", serde_json::to_string(&s).expect("stats"));
    }
}
