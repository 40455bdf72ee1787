//! Benchmark: the particle-size distribution against the plain SPM: wall time of a 1C
//! discharge and of 4 x (2C 3 min, 20 min rest), median of REPEATS, at the default tolerance
//! and at 1e-8, for 30 (PyBaMM's default), 10 and 5 sizes per electrode. Prints a Markdown
//! table; colours (right-hand sides per Jacobian) and LU entries on stderr.
//!
//! `cargo run --release --example bench_psd [-- REPEATS]`

use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::ParticleSize;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, simulate};
use cellstudio::stats::median;

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let p = chen2020();
    let pulses = Protocol { steps: (0..4).flat_map(|_| [Step::Current { current: 10.0, duration: 180.0, until_voltage: None }, Step::Rest { duration: 1200.0 }]).collect() };
    let protocols = [("1C discharge", Protocol::discharge(1.0)), ("4 pulses + rests", pulses)];
    let variants: [(&str, Option<usize>); 4] = [("SPM", None), ("SPM + PSD, 30 sizes", Some(30)), ("SPM + PSD, 10 sizes", Some(10)), ("SPM + PSD, 5 sizes", Some(5))];
    println!("| model | states | tolerance | protocol | ms (median of {repeats}) | steps | Jacobians | rhs evals |");
    println!("|---|---|---|---|---|---|---|---|");
    for tol in [None, Some(1e-8)] {
        for (label, sizes) in variants {
            let submodels = Submodels { particle_size: if sizes.is_some() { ParticleSize::Distribution } else { ParticleSize::Single }, ..Default::default() };
            let n = sizes.unwrap_or(30);
            let mut b = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes { size_n: n, size_p: n, ..Default::default() });
            let built = b.build(&p).unwrap();
            if tol.is_none() {
                eprintln!("{label}: {} colours, {} LU entries", built.workspace.n_colours(), built.workspace.factor_nnz());
            }
            for (name, protocol) in &protocols {
                let mut opts = SimOptions::for_cell(&p);
                if let Some(t) = tol {
                    (opts.solver.rtol, opts.solver.atol) = (t, t);
                }
                let mut times = Vec::new();
                let mut stats = None;
                for _ in 0..repeats {
                    let t = Instant::now();
                    let sol = simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).unwrap();
                    times.push(t.elapsed().as_secs_f64());
                    stats = Some(sol.stats);
                }
                let s = stats.unwrap();
                println!("| {label} | {} | {:.0e} | {name} | {:.2} | {} | {} | {} |", built.model.len(), opts.solver.rtol, median(&times) * 1e3, s.steps, s.jacobian_evals, s.rhs_evals);
            }
        }
    }
}
