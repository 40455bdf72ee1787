//! One point of a work-precision diagram, for `scripts/work_precision.py`: wall time of a
//! solve that returns the solver's own steps (median of REPEATS after one warm-up), and the
//! voltage error of the same solve's dense output at a reference curve's times.
//!
//! `cargo run --release --example work_precision -- MODEL CASE RTOL REPEATS REF_CSV [integrals]`
//! (MODEL spm|spme|dfn, CASE 0.5C|1C|2C|pulse; rtol = atol = RTOL). The timed solve returns
//! the voltage, current and temperature at every step, as PyBaMM is asked for the voltage;
//! `integrals` adds the charge and energy (their quadrature). Prints one JSON line.

use std::time::Instant;

#[path = "common/solver_case.rs"]
mod solver_case;

use cellstudio::data::Recording;
use cellstudio::simulation::{Integrals, SimOptions, simulate};
use solver_case::SolverCase;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (model, case, rtol, repeats, reference, integrals) = match args.as_slice() {
        [m, c, r, n, f] => (m, c, r, n, f, false),
        [m, c, r, n, f, i] if i == "integrals" => (m, c, r, n, f, true),
        _ => panic!("usage: work_precision MODEL CASE RTOL REPEATS REF_CSV [integrals]"),
    };
    let SolverCase { protocol, options, params: p, mut builder, repeats } = SolverCase::new(model, case, rtol, repeats);
    let opts = SimOptions { integrals: if integrals { Integrals::AtEveryOutput } else { Integrals::Off }, ..options };
    let rtol = opts.solver.rtol;
    let rec = Recording::from_csv(reference.as_ref()).expect("reference");
    let built = builder.build(&p).expect("build");
    let mut times = Vec::new();
    let mut sol = None;
    for k in 0..=repeats {
        let t0 = Instant::now();
        let s = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).expect("simulate");
        if k > 0 {
            times.push(t0.elapsed().as_secs_f64());
        }
        sol = Some(s);
    }
    times.sort_by(f64::total_cmp);
    let sol = sol.expect("at least one solve");
    // accuracy of the same solver settings, read from its dense output (untimed)
    let dense = SimOptions { t_eval: Some(rec.distinct_times()), ..opts };
    let at_ref = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &dense, None).expect("simulate");
    let err = rec.voltage_error(&at_ref.time, &at_ref.voltage);
    println!(
        "{{\"side\":\"cellstudio\",\"model\":\"{model}\",\"case\":\"{case}\",\"rtol\":{rtol:e},\"solve_s\":{:e},\"points\":{},\"steps\":{},\"rms_mV\":{:e},\"max_mV\":{:e},\"stats\":{}}}",
        times[times.len() / 2],
        sol.time.len(),
        sol.stats.steps,
        err.rms * 1e3,
        err.max * 1e3,
        serde_json::to_string(&sol.stats).expect("stats")
    );
}
