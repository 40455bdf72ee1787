//! Benchmark: wall time of a 50-frequency impedance spectrum (1e-4 to 1e4 Hz) of SPM, SPMe
//! and DFN at the default mesh, split into rest state + linearisation and the complex solves.
//! Prints a Markdown table.
//!
//! `cargo run --release --example bench_eis [-- REPEATS]`

use std::time::Instant;

use cellstudio::eis::{impedance, linearise, log_frequencies, rest_state};
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::{chen2020, set_initial_soc};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() -> Result<(), cellstudio::Error> {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let mut p = chen2020();
    set_initial_soc(&mut p, 0.5)?;
    let f = log_frequencies(1e-4, 1e4, 50)?;
    println!("threads: {}\n", rayon::current_num_threads());
    println!("| model | states | Jacobian non-zeros | linearise (ms) | 50 solves (ms) | spectrum (ms, median of {repeats}) |");
    println!("|---|---|---|---|---|---|");
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let built = b.build(&p)?;
        let (model, ws) = (built.model.as_ref(), &mut built.workspace);
        let (mut lin_t, mut solve_t, mut total) = (Vec::new(), Vec::new(), Vec::new());
        let mut nnz = 0;
        for _ in 0..repeats {
            let t = Instant::now();
            let y0 = rest_state(model, ws)?;
            let lin = linearise(model, &y0)?;
            let t1 = t.elapsed().as_secs_f64();
            let z = impedance(&lin, &f)?;
            let t2 = t.elapsed().as_secs_f64();
            assert_eq!(z.len(), f.len());
            nnz = lin.jacobian.len();
            lin_t.push(t1 * 1e3);
            solve_t.push((t2 - t1) * 1e3);
            total.push(t2 * 1e3);
        }
        println!("| {kind} | {} | {nnz} | {:.3} | {:.3} | {:.3} |", model.len(), median(lin_t), median(solve_t), median(total));
    }
    Ok(())
}
