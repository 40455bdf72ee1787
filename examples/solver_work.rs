//! Work of repeated solves, for instruction-count measurements (`perf stat -e instructions:u`):
//! builds the model once, solves REPEATS times and prints the solver's counters of one solve.
//! The instructions of one solve are the difference of two runs with different REPEATS
//! divided by the difference of REPEATS (the build and start-up cancel).
//!
//! `cargo run --release --example solver_work -- MODEL CASE RTOL REPEATS`
//! (MODEL spm|spme|dfn, CASE 0.5C|1C|2C|pulse; rtol = atol = RTOL).

#[path = "common/solver_case.rs"]
mod solver_case;

use cellstudio::simulation::simulate;
use solver_case::SolverCase;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [model, case, rtol, repeats] = args.as_slice() else {
        panic!("usage: solver_work MODEL CASE RTOL REPEATS");
    };
    let SolverCase { protocol, options: opts, params: p, mut builder, repeats } = SolverCase::new(model, case, rtol, repeats);
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
