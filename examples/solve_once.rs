//! One configuration solved REPEATS times (default 1), printing the solver's statistics: a
//! process that does nothing else, for profilers (`valgrind --tool=callgrind`, `perf record`).
//!
//! `cargo run --release --example solve_once -- MODEL CASE RTOL [REPEATS]`, e.g.
//! `-- dfn 1C 1e-6` or `-- spme pulse 1e-4 20` (CASE: a C-rate discharge or `pulse`).
#[path = "common/solver_case.rs"]
mod solver_case;
use cellstudio::simulation::simulate;
use solver_case::SolverCase;

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() < 3 {
        eprintln!("usage: solve_once MODEL CASE RTOL [REPEATS]");
        std::process::exit(2);
    }
    let repeats = a.get(3).map_or("1", String::as_str);
    let SolverCase { protocol, options, params, mut builder, repeats } = SolverCase::new(&a[0], &a[1], &a[2], repeats);
    let built = builder.build(&params).unwrap();
    for _ in 0..repeats {
        let s = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &options, None).unwrap();
        println!("steps {}, Jacobians {}, factorisations {}, rhs evaluations {}", s.stats.steps, s.stats.jacobian_evals, s.stats.factorisations, s.stats.rhs_evals);
    }
}
