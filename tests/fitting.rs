//! Fitting problems: sensitivities against finite differences, and the seed identification
//! case (SPM with contact resistance, PyBaMM's curve plus 2 mV noise).

mod common;

use cellstudio::data::Recording;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::{FitParameter, FittingProblem, ModelSpec};
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

/// PyBaMM's SPM + contact resistance (D_n = 3.3e-14 m^2/s, R = 10 mOhm), 1C then 30 min rest,
/// with seeded Gaussian noise of `sigma` volts.
fn seed_recording(sigma: f64, seed: u64) -> Recording {
    let mut rec = common::reference("spm_contact_resistance_seed");
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let noise = Normal::new(0.0, sigma).unwrap();
    for v in &mut rec.voltage {
        *v += noise.sample(&mut rng);
    }
    rec
}

fn seed_problem(rec: Recording) -> FittingProblem {
    let spec = ModelSpec::new(ModelKind::Spm, Submodels { contact_resistance: true, ..Default::default() });
    let params = vec![
        FitParameter::log("negative.diffusivity", 3.3e-14, 1e-15, 1e-12),
        FitParameter::log("cell.contact_resistance", 0.01, 1e-4, 0.1),
    ];
    FittingProblem::new(spec, chen2020(), params, rec).unwrap()
}

#[test]
fn sensitivities_match_finite_differences() {
    // Sensitivities at the default tolerances; differences of simulations need tight ones.
    let problem = seed_problem(seed_recording(0.0, 1));
    let mut fine = seed_problem(seed_recording(0.0, 1));
    fine.solver.rtol = 1e-10;
    fine.solver.atol = 1e-10;
    let x = [3.3e-14, 0.01];
    let t = std::time::Instant::now();
    let sim = problem.simulate_with_sensitivities(&x).unwrap();
    println!("with sensitivities: {:?}", t.elapsed());
    let t = std::time::Instant::now();
    problem.simulate(&x).unwrap();
    println!("plain: {:?}", t.elapsed());
    for k in 0..2 {
        let h = 1e-4 * x[k];
        let (mut xp, mut xm) = (x, x);
        xp[k] += h;
        xm[k] -= h;
        let (vp, vm) = (fine.simulate(&xp).unwrap(), fine.simulate(&xm).unwrap());
        let mut worst = 0.0f64;
        let mut size = 0.0f64;
        for i in 0..vp.len() {
            let fd = (vp[i] - vm[i]) / (2.0 * h);
            worst = worst.max((fd - sim.sensitivity[i][k]).abs());
            size = size.max(fd.abs());
        }
        println!("parameter {k}: max |dV/dθ| = {size:.4e}, max |sens - fd| = {worst:.3e}");
        assert!(worst < 1e-3 * size, "parameter {k}: {worst} vs {size}");
    }
}

/// The seed case: from a start 2x away in both parameters, L-BFGS-B (with sensitivity
/// gradients) and CMA-ES recover D_n and R within 5%, and the truth lies within a few
/// standard errors.
#[test]
fn seed_case_recovers_diffusivity_and_contact_resistance() {
    use cellstudio::cost::CostKind;
    use cellstudio::optim::OptimOptions;
    use cellstudio::problem::fit::fit;
    let truth = [3.3e-14, 0.010];
    let mut problem = seed_problem(seed_recording(0.002, 7));
    problem.parameters[0].initial = 2.0 * truth[0];
    problem.parameters[1].initial = 0.5 * truth[1];
    for (name, cost) in [("lbfgsb", CostKind::Sse), ("cmaes", CostKind::Sse), ("lbfgsb", CostKind::GaussianLogLikelihood { sigma: None })] {
        let options = OptimOptions::default().with_seed(3).with_max_evaluations(600).unwrap();
        let r = fit(&problem, cost, name, options).unwrap();
        println!(
            "{name} {}: x = {:?} ± {:?}, rmse = {:.3} mV, {} evaluations + {} gradients, {} iterations, {:.2} s, corr = {:.3}",
            cost.name(),
            r.x,
            r.std_errors,
            r.rmse * 1e3,
            r.evaluations,
            r.gradient_evaluations,
            r.iterations,
            r.seconds,
            r.correlation[0][1]
        );
        for k in 0..2 {
            let rel = (r.x[k] / truth[k] - 1.0).abs();
            assert!(rel < 0.05, "{name}: parameter {k} = {} is {:.1}% from the truth", r.x[k], 100.0 * rel);
            assert!((r.x[k] - truth[k]).abs() < 4.0 * r.std_errors[k], "{name}: truth outside 4 standard errors");
        }
        // The residual is the noise: 2 mV.
        assert!((r.rmse - 0.002).abs() < 0.0003, "rmse {}", r.rmse);
        if cost.fits_sigma() {
            assert!((r.x[2] / 0.002 - 1.0).abs() < 0.1, "fitted sigma {}", r.x[2]);
        }
    }
}
