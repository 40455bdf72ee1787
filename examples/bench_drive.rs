//! Benchmark: replaying a recorded drive, the current given every second and linear between
//! (a table step with a kink at every sample, as `diagnose` and `fit` replay a recording).
//! SPM, SPMe and DFN at rtol = atol 1e-4 and 1e-6: wall time (median of 5), solver work, and
//! the voltage error against the same replay at 1e-10. Prints a Markdown table.
//!
//! `cargo run --release --example bench_drive [-- RECORDING.csv]`: the recording's current
//! (e.g. a PyBaMM-made WLTP drive); without one, a 30-minute synthetic drive (three sines,
//! peak about 2C, regeneration to 1C) from 90 % state of charge.

use std::time::Instant;

use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{Integrals, SimOptions, simulate};
use cellstudio::stats::{median, rms};

/// A 30-minute drive sampled every second (A): three incommensurate sines.
fn synthetic_drive(capacity: f64) -> Recording {
    let time: Vec<f64> = (0..=1800).map(f64::from).collect();
    let current = time.iter().map(|t| capacity * (0.5 + 0.9 * (0.011 * t).sin() + 0.5 * (0.13 * t).sin() + 0.3 * (0.5 * t).sin())).collect();
    let n = time.len();
    Recording { time, current, voltage: vec![3.7; n], temperature: None }
}

fn main() {
    let mut p = chen2020();
    let rec = match std::env::args().nth(1) {
        Some(path) => Recording::from_csv(std::path::Path::new(&path)).expect("recording"),
        None => {
            cellstudio::params::set_initial_soc(&mut p, 0.9).expect("initial state");
            synthetic_drive(p.cell.nominal_capacity)
        }
    };
    let t0 = rec.time[0];
    let t_eval: Vec<f64> = rec.distinct_times().iter().map(|t| t - t0).collect();
    let protocol: Protocol = rec.protocol();
    println!("{} samples over {:.0} s, {} protocol steps\n", t_eval.len(), t_eval[t_eval.len() - 1], protocol.steps.len());
    println!("| model | rtol | replay (ms, median of 5) | steps | rejected | LU factorisations | error vs 1e-10 (mV RMS) |");
    println!("|---|---|---|---|---|---|---|");
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let built = b.build(&p).expect("build");
        let opts = |tol: f64| {
            let mut o = SimOptions { t_eval: Some(t_eval.clone()), cutoffs: (0.0, 100.0), integrals: Integrals::AtStepEnds, ..SimOptions::for_cell(&p) };
            o.solver.set_tolerance(tol);
            o
        };
        let reference = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts(1e-10), None).expect("reference");
        for tol in [1e-4, 1e-6] {
            let o = opts(tol);
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..5 {
                let t = Instant::now();
                let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &o, None).expect("replay");
                times.push(t.elapsed().as_secs_f64());
                last = Some(sol);
            }
            let sol = last.expect("five replays");
            let err = rms(&sol.voltage.iter().zip(&reference.voltage).map(|(a, b)| a - b).collect::<Vec<_>>());
            let s = sol.stats;
            println!("| {kind} | {tol:e} | {:.1} | {} | {} | {} | {:.1e} |", 1e3 * median(&times), s.steps, s.rejected_steps, s.factorisations, 1e3 * err);
        }
    }
}
