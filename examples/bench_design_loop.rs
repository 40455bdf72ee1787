//! Design-loop benchmark: N discharges at a C-rate with the positive-electrode thickness
//! evenly spaced over a range, sequentially through one `DesignProblem` (its builder
//! rebuilds once per thickness). Prints one JSON line `{"designs","total_s","rebuilds",...}`
//! (read by scripts/compare_pybamm.py).
//!
//! `cargo run --release --example bench_design_loop -- --model spme --designs 100 --c-rate 1
//!  --thickness-min-um 60 --thickness-max-um 90`

use std::time::Instant;

use cellstudio::models::ModelKind;
use cellstudio::params::chen2020;
use cellstudio::problem::design::DesignProblem;

fn arg<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> T {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let model: ModelKind = arg(&args, "--model", "spme".to_string()).parse().expect("model");
    let n: usize = arg(&args, "--designs", 100);
    let c_rate: f64 = arg(&args, "--c-rate", 1.0);
    let lo: f64 = arg(&args, "--thickness-min-um", 60.0) * 1e-6;
    let hi: f64 = arg(&args, "--thickness-max-um", 90.0) * 1e-6;
    let problem =
        DesignProblem::new(chen2020(), vec!["positive.thickness".into()], vec![], model, c_rate, false).expect("problem");
    let start = Instant::now();
    let mut energy = Vec::with_capacity(n);
    for k in 0..n {
        let l = lo + (hi - lo) * k as f64 / (n.max(2) - 1) as f64;
        energy.push(problem.evaluate(&[l]).expect("design").energy);
    }
    let total = start.elapsed().as_secs_f64();
    println!(
        "{}",
        serde_json::json!({
            "model": model.to_string(), "designs": n, "total_s": total, "rebuilds": problem.rebuild_count(),
            "per_design_ms": total * 1e3 / n as f64, "energy_Wh_first": energy[0], "energy_Wh_last": energy[n - 1],
        })
    );
}
