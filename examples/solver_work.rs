//! Work of repeated solves, for instruction-count measurements (`perf stat -e instructions:u`):
//! builds the model once, solves REPEATS times and prints the solver's counters of one solve.
//! The instructions of one solve are the difference of two runs with different REPEATS
//! divided by the difference of REPEATS (the build and start-up cancel).
//!
//! `cargo run --release --example solver_work -- MODEL CASE RTOL REPEATS`
//! (MODEL spm|spme|dfn, CASE 0.5C|1C|2C|pulse; rtol = atol = RTOL).

use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [model, case, rtol, repeats] = args.as_slice() else {
        panic!("usage: solver_work MODEL CASE RTOL REPEATS");
    };
    let kind: ModelKind = model.parse().expect("model");
    let rtol: f64 = rtol.parse().expect("rtol");
    let repeats: usize = repeats.parse().expect("repeats");
    let protocol = match case.as_str() {
        "pulse" => toml::from_str(&std::fs::read_to_string("protocols/pulse_1C.toml").expect("protocol")).expect("protocol"),
        c => Protocol::discharge(c.trim_end_matches('C').parse().expect("C-rate")),
    };
    let p = chen2020();
    let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).expect("build");
    let mut opts = SimOptions::for_cell(&p);
    (opts.solver.rtol, opts.solver.atol) = (rtol, rtol);
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
