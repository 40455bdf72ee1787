//! Benchmark: wall time per 1C discharge of SPM, SPMe and DFN at the default mesh, and
//! build time vs re-use time of the geometry-aware builder. Prints a Markdown table.
//!
//! `cargo run --release --example bench_models [-- REPEATS]`

use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let p = chen2020();
    let protocol = Protocol::discharge(1.0);
    let mut opts = SimOptions::for_cell(&p);
    if let Some(tol) = std::env::var("BENCH_TOL").ok().and_then(|t| t.parse().ok()) {
        opts.solver.set_tolerance(tol);
    }
    println!("tolerances: rtol = {}, atol = {} (relative to each state's scale)\n", opts.solver.rtol, opts.solver.atol);
    println!("| model | states | 1C discharge (ms, median of {repeats}) | steps | Jacobians | rhs evals | build (ms) | re-use (ms) |");
    println!("|---|---|---|---|---|---|---|---|");
    let only: Option<ModelKind> = std::env::var("BENCH_MODEL").ok().and_then(|m| m.parse().ok());
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        if only.is_some_and(|o| o != kind) {
            continue;
        }
        let mut builds = Vec::new();
        let mut reuses = Vec::new();
        let mut solves = Vec::new();
        let mut stats = None;
        let mut n = 0;
        for k in 0..repeats {
            let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
            let t = Instant::now();
            b.build(&p).unwrap();
            builds.push(t.elapsed().as_secs_f64());
            // Re-use: a non-geometric change (D_n 1 % up) updates the built model in place.
            let mut q = p.clone();
            q.negative.diffusivity *= 1.01;
            let t = Instant::now();
            b.build(&q).unwrap();
            reuses.push(t.elapsed().as_secs_f64());
            // Every repeat solves the same problem: back to the nominal set (untimed).
            let built = b.build(&p).unwrap();
            n = built.model.len();
            let t = Instant::now();
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
            solves.push(t.elapsed().as_secs_f64());
            stats = Some(sol.stats);
            if k == 0 {
                eprintln!(
                    "{kind}: {} colours, {} factorisations, {} LU entries",
                    built.workspace.n_colours(),
                    sol.stats.factorisations,
                    built.workspace.factor_nnz()
                );
            }
        }
        let s = stats.unwrap();
        println!(
            "| {kind} | {n} | {:.3} | {} | {} | {} | {:.3} | {:.4} |",
            median(solves) * 1e3,
            s.steps,
            s.jacobian_evals,
            s.rhs_evals,
            median(builds) * 1e3,
            median(reuses) * 1e3
        );
    }
}
