//! One point of a work-precision diagram, for `scripts/work_precision.py`: wall time of a
//! solve that returns the solver's own steps (median of REPEATS after one warm-up), and the
//! voltage error of the same solve's dense output at a reference curve's times.
//!
//! `cargo run --release --example work_precision -- MODEL CASE RTOL REPEATS REF_CSV`
//! (MODEL spm|spme|dfn, CASE 0.5C|1C|2C|pulse; rtol = atol = RTOL). Prints one JSON line.

use std::time::Instant;

use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [model, case, rtol, repeats, reference] = args.as_slice() else {
        panic!("usage: work_precision MODEL CASE RTOL REPEATS REF_CSV");
    };
    let kind: ModelKind = model.parse().expect("model");
    let rtol: f64 = rtol.parse().expect("rtol");
    let repeats: usize = repeats.parse().expect("repeats");
    let protocol = match case.as_str() {
        "pulse" => toml::from_str(&std::fs::read_to_string("protocols/pulse_1C.toml").expect("protocol")).expect("protocol"),
        c => Protocol::discharge(c.trim_end_matches('C').parse().expect("C-rate")),
    };
    let rec = Recording::from_csv(reference.as_ref()).expect("reference");
    let p = chen2020();
    let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).expect("build");
    let mut opts = SimOptions::for_cell(&p);
    (opts.solver.rtol, opts.solver.atol) = (rtol, rtol);
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
