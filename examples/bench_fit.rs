//! Benchmark of the seed identification case (SPM + contact resistance, 1C + 30 min rest,
//! 2 mV noise): one simulation, one simulation with sensitivities, and whole fits.
//! `cargo run --release --example bench_fit` prints a Markdown table of medians.

use std::time::Instant;

use cellstudio::cost::CostKind;
use cellstudio::optim::OptimOptions;
use cellstudio::problem::identification::fit;
use cellstudio::study::fit::FitStudy;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time<T>(repeats: usize, mut f: impl FnMut() -> T) -> f64 {
    median((0..repeats).map(|_| {
        let t = Instant::now();
        std::hint::black_box(f());
        t.elapsed().as_secs_f64() * 1e3
    }).collect())
}

fn main() {
    let study = FitStudy::from_file("fits/spm_contact_resistance.toml".as_ref()).expect("study");
    let problem = study.problem(None).expect("problem");
    let x0 = problem.initial();
    println!("seed case: {} recorded points, {} parameters\n", problem.data.time.len(), problem.dim());
    println!("| what | median (ms) |\n|---|---|");
    println!("| simulate | {:.2} |", time(21, || problem.simulate(&x0).unwrap()));
    println!("| simulate with sensitivities | {:.2} |", time(21, || problem.simulate_with_sensitivities(&x0).unwrap()));
    for (name, evals) in [("lbfgsb", 1000), ("cmaes", 600), ("nelder-mead", 600)] {
        let mut evaluations = 0;
        let ms = time(5, || {
            let options = OptimOptions::default().with_seed(1).with_max_evaluations(evals).unwrap();
            let r = fit(&problem, CostKind::Sse, name, options).unwrap();
            evaluations = r.evaluations + r.gradient_evaluations;
        });
        println!("| fit, {name} ({evaluations} solves) | {ms:.1} |");
    }
}
