//! Benchmark: the particle-size distribution against the plain SPM: wall time of a 1C
//! discharge and of 4 x (2C 3 min, 20 min rest), median of REPEATS, at the default tolerance
//! and at 1e-8, for 30 (PyBaMM's default), 15, 10 and 5 sizes per electrode, with relative
//! spreads of 0.4 in both electrodes; the RMS voltage gap (mV) of each size count from 30
//! sizes at the same tolerance. Prints a Markdown table; colours (right-hand sides per
//! Jacobian) and LU entries on stderr.
//!
//! `cargo run --release --example bench_psd [-- REPEATS]`

use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::ParticleSize;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::params::function::interpolate;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, simulate};
use cellstudio::stats::median;

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let mut p = chen2020();
    (p.negative.radius_relative_std, p.positive.radius_relative_std) = (0.4, 0.4);
    let pulses = Protocol { steps: (0..4).flat_map(|_| [Step::Current { current: 10.0, duration: 180.0, until_voltage: None }, Step::Rest { duration: 1200.0 }]).collect() };
    let protocols = [("1C discharge", Protocol::discharge(1.0)), ("4 pulses + rests", pulses)];
    let variants: [(&str, Option<usize>); 5] =
        [("SPM", None), ("SPM + PSD, 30 sizes", Some(30)), ("SPM + PSD, 15 sizes", Some(15)), ("SPM + PSD, 10 sizes", Some(10)), ("SPM + PSD, 5 sizes", Some(5))];
    println!("| model | states | tolerance | protocol | ms (median of {repeats}) | steps | Jacobians | rhs evals | RMS gap from 30 sizes (mV) |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for tol in [None, Some(1e-8)] {
        // Each protocol's 30-size curve (time, voltage) at this tolerance.
        let mut finest: Vec<Option<(Vec<f64>, Vec<f64>)>> = vec![None; protocols.len()];
        for (label, sizes) in variants {
            let submodels = Submodels { particle_size: if sizes.is_some() { ParticleSize::Distribution } else { ParticleSize::Single }, ..Default::default() };
            let n = sizes.unwrap_or(30);
            let mut b = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes { size_n: n, size_p: n, ..Default::default() });
            let built = b.build(&p).unwrap();
            if tol.is_none() {
                eprintln!("{label}: {} colours, {} LU entries", built.workspace.n_colours(), built.workspace.factor_nnz());
            }
            for (k, (name, protocol)) in protocols.iter().enumerate() {
                let mut opts = SimOptions::for_cell(&p);
                if let Some(t) = tol {
                    opts.solver.set_tolerance(t);
                }
                let mut times = Vec::new();
                let mut last = None;
                for _ in 0..repeats {
                    let t = Instant::now();
                    let sol = simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).unwrap();
                    times.push(t.elapsed().as_secs_f64());
                    last = Some(sol);
                }
                let sol = last.unwrap();
                let s = &sol.stats;
                if sizes == Some(30) {
                    finest[k] = Some((sol.time.clone(), sol.voltage.clone()));
                }
                let gap = match (&finest[k], sizes) {
                    (Some((t, v)), Some(_)) => {
                        // At the midpoints of the 30-size steps (a step boundary repeats its time).
                        let d: Vec<f64> = t
                            .windows(2)
                            .filter(|w| w[1] > w[0])
                            .map(|w| 0.5 * (w[0] + w[1]))
                            .map(|m| interpolate(&sol.time, &sol.voltage, m) - interpolate(t, v, m))
                            .collect();
                        format!("{:.3}", cellstudio::stats::rms(&d) * 1e3)
                    }
                    _ => "-".into(),
                };
                println!("| {label} | {} | {:.0e} | {name} | {:.2} | {} | {} | {} | {gap} |", built.model.len(), opts.solver.rtol, median(&times) * 1e3, s.steps, s.jacobian_evals, s.rhs_evals);
            }
        }
    }
}
