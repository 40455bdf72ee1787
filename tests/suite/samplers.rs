//! Every MCMC sampler against posteriors with known moments (a correlated Gaussian, a
//! truncated normal in a box, a banana), reproducibility across thread counts, the
//! finite-difference gradient fallback, option validation and the reports.

use cellstudio::sample::{
    LogDensity, PosteriorSummary, SAMPLER_NAMES, SampleOptions, SampleResult, SamplerOptions, by_name, sample,
};

/// Correlated 2-D Gaussian: means (1, -2), standard deviations (0.5, 2), correlation 0.8.
struct Gaussian {
    /// Provide the analytic gradient (else samplers fall back to finite differences).
    analytic: bool,
}

const MEAN: [f64; 2] = [1.0, -2.0];
const SD: [f64; 2] = [0.5, 2.0];
const RHO: f64 = 0.8;

impl Gaussian {
    /// `(log p, ∇log p)` with the precision matrix `Σ⁻¹` written out.
    fn evaluate(x: &[f64]) -> (f64, Vec<f64>) {
        let d = [x[0] - MEAN[0], x[1] - MEAN[1]];
        let (a, b, c) = (SD[0] * SD[0], RHO * SD[0] * SD[1], SD[1] * SD[1]);
        let det = a * c - b * b;
        let g = [-(c * d[0] - b * d[1]) / det, -(-b * d[0] + a * d[1]) / det];
        (0.5 * (g[0] * d[0] + g[1] * d[1]), g.to_vec())
    }
}

impl LogDensity for Gaussian {
    fn dim(&self) -> usize {
        2
    }
    fn log_density(&self, x: &[f64]) -> f64 {
        Self::evaluate(x).0
    }
    fn log_density_and_gradient(&self, x: &[f64]) -> Option<(f64, Vec<f64>)> {
        self.analytic.then(|| Self::evaluate(x))
    }
}

/// Over-dispersed starts: the mean ± 2 sd in the four diagonal directions.
fn gaussian_starts() -> Vec<Vec<f64>> {
    [(1.0, 1.0), (-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0)]
        .iter()
        .map(|(s0, s1)| vec![MEAN[0] + 2.0 * s0 * SD[0], MEAN[1] + 2.0 * s1 * SD[1]])
        .collect()
}

fn run(target: &dyn LogDensity, name: &str, options: &SampleOptions, starts: &[Vec<f64>]) -> SampleResult {
    let sampler = by_name(name, SamplerOptions::default()).unwrap();
    sample(target, sampler.as_ref(), options, starts).unwrap()
}

/// Pooled sample correlation of parameters 0 and 1.
fn correlation(result: &SampleResult) -> f64 {
    let draws: Vec<&Vec<f64>> = result.chains.iter().flat_map(|c| c.draws.iter()).collect();
    let n = draws.len() as f64;
    let m: Vec<f64> = (0..2).map(|i| draws.iter().map(|d| d[i]).sum::<f64>() / n).collect();
    let cov = |i: usize, j: usize| draws.iter().map(|d| (d[i] - m[i]) * (d[j] - m[j])).sum::<f64>() / (n - 1.0);
    cov(0, 1) / (cov(0, 0) * cov(1, 1)).sqrt()
}

/// Checks a summary against known means and standard deviations: mean within 4 Monte-Carlo
/// standard errors (true sd / sqrt(ESS)), sd within `sd_tol` relative, split and
/// rank-normalised R-hat below 1.05.
fn check_moments(summary: &PosteriorSummary, mean: &[f64], sd: &[f64], sd_tol: f64) {
    for (i, p) in summary.parameters.iter().enumerate() {
        let mcse = sd[i] / p.ess.sqrt();
        assert!(
            (p.mean - mean[i]).abs() < 4.0 * mcse,
            "{}: {} mean {} vs {} (mcse {mcse})\n{summary}",
            summary.sampler,
            p.name,
            p.mean,
            mean[i]
        );
        assert!((p.sd / sd[i] - 1.0).abs() < sd_tol, "{}: {} sd {} vs {}\n{summary}", summary.sampler, p.name, p.sd, sd[i]);
        assert!(p.rhat < 1.05, "{}: {} R-hat {}\n{summary}", summary.sampler, p.name, p.rhat);
        assert!(p.rank_rhat < 1.05, "{}: {} rank R-hat {}\n{summary}", summary.sampler, p.name, p.rank_rhat);
    }
}

#[test]
fn every_sampler_recovers_the_correlated_gaussian() {
    let target = Gaussian { analytic: true };
    for name in SAMPLER_NAMES {
        // Isotropic random-walk Metropolis mixes slowly on this ill-conditioned target (about
        // 20 effective draws per 1000): give it twice the draws of the others.
        let iterations = if name == "rwm" { 10_000 } else { 5000 };
        let options = SampleOptions { chains: 4, warmup: 1000, iterations, seed: 42, progress: false };
        let result = run(&target, name, &options, &gaussian_starts());
        let summary = result.summary(&["a", "b"]);
        let draws = (options.chains * options.iterations) as f64;
        eprintln!(
            "{name:>20}: ESS per 1000 draws {:.0} / {:.0}, acceptance {:.3}, evaluations {}, gradients {}",
            1000.0 * summary.parameters[0].ess / draws,
            1000.0 * summary.parameters[1].ess / draws,
            summary.acceptance_rate.iter().sum::<f64>() / 4.0,
            summary.evaluations,
            result.chains.iter().map(|c| c.gradient_evaluations).sum::<usize>()
        );
        // Enough effective draws that a 10% error on the sd is > 3 standard errors.
        assert!(summary.min_ess() > 500.0, "{name}: ESS too small for the test\n{summary}");
        check_moments(&summary, &MEAN, &SD, 0.1);
        let rho = correlation(&result);
        assert!((rho - RHO).abs() < 0.05, "{name}: correlation {rho}");
    }
}

/// Standard normal truncated to the box `[0, 10] × [-1, 1]` (log density `-inf` outside).
struct BoxedNormal;

impl LogDensity for BoxedNormal {
    fn dim(&self) -> usize {
        2
    }
    fn log_density(&self, x: &[f64]) -> f64 {
        if (0.0..=10.0).contains(&x[0]) && (-1.0..=1.0).contains(&x[1]) {
            -0.5 * (x[0] * x[0] + x[1] * x[1])
        } else {
            f64::NEG_INFINITY
        }
    }
}

#[test]
fn metropolis_and_slice_respect_a_box() {
    // Half-normal on [0, inf) (the cut at 10 removes e^-50 of the mass): mean sqrt(2/π),
    // sd sqrt(1 - 2/π). Normal truncated to [-1, 1]: mean 0, variance 1 - 2φ(1)/(2Φ(1) - 1).
    let phi1 = (-0.5f64).exp() / (2.0 * std::f64::consts::PI).sqrt();
    let mass = 0.682_689_492_137_085_9; // 2Φ(1) - 1 = erf(1/√2)
    let mean = [(2.0 / std::f64::consts::PI).sqrt(), 0.0];
    let sd = [(1.0 - 2.0 / std::f64::consts::PI).sqrt(), (1.0 - 2.0 * phi1 / mass).sqrt()];
    let starts = vec![vec![0.5, 0.5], vec![2.0, -0.5], vec![0.1, 0.9], vec![1.5, 0.0]];
    for name in ["rwm", "adaptive-metropolis", "slice"] {
        let options = SampleOptions { chains: 4, warmup: 1000, iterations: 5000, seed: 7, progress: false };
        let result = run(&BoxedNormal, name, &options, &starts);
        let summary = result.summary(&["half-normal", "truncated"]);
        eprintln!("{summary}");
        assert!(result.chains.iter().flat_map(|c| &c.log_density).all(|f| f.is_finite()), "{name} left the box");
        assert!(summary.min_ess() > 500.0, "{name}: ESS too small for the test\n{summary}");
        check_moments(&summary, &mean, &sd, 0.1);
    }
}

/// Banana: `x₀ ~ N(0, 1)`, `x₁ | x₀ ~ N(b·x₀², 1)` with `b = 1/2`, so `E x₁ = b = 1/2` and
/// `Var x₁ = 1 + b²·Var(x₀²) = 1 + 2b² = 3/2`. No analytic gradient.
struct Banana;

impl LogDensity for Banana {
    fn dim(&self) -> usize {
        2
    }
    fn log_density(&self, x: &[f64]) -> f64 {
        let r = x[1] - 0.5 * x[0] * x[0];
        -0.5 * (x[0] * x[0] + r * r)
    }
}

#[test]
fn banana_moments() {
    let starts = vec![vec![-1.5, 2.0], vec![1.5, 2.0], vec![0.0, -1.0], vec![0.5, 0.5]];
    for (name, iterations) in [("rwm", 10_000), ("slice", 5000), ("nuts", 2000)] {
        let options = SampleOptions { chains: 4, warmup: 1000, iterations, seed: 3, progress: false };
        let summary = run(&Banana, name, &options, &starts).summary(&["x0", "x1"]);
        eprintln!("{summary}");
        assert!(summary.min_ess() > 500.0, "{name}: ESS too small for the test\n{summary}");
        check_moments(&summary, &[0.0, 0.5], &[1.0, 1.5f64.sqrt()], 0.1);
    }
}

#[test]
fn gradient_samplers_fall_back_to_finite_differences() {
    let target = Gaussian { analytic: false };
    for name in ["mala", "hmc", "nuts"] {
        let iterations = if name == "mala" { 5000 } else { 2000 };
        let options = SampleOptions { chains: 4, warmup: 1000, iterations, seed: 5, progress: false };
        let result = run(&target, name, &options, &gaussian_starts());
        assert!(result.chains.iter().all(|c| c.gradient_evaluations == 0 && c.evaluations > 0));
        let summary = result.summary(&["a", "b"]);
        eprintln!("{summary}");
        assert!(summary.min_ess() > 500.0, "{name}: ESS too small for the test\n{summary}");
        check_moments(&summary, &MEAN, &SD, 0.1);
    }
}

#[test]
fn same_seed_gives_identical_draws_on_any_number_of_threads() {
    let options = SampleOptions { chains: 4, warmup: 150, iterations: 200, seed: 99, progress: false };
    // Finite-difference gradients: their probes run in parallel inside each chain too.
    let target = Gaussian { analytic: false };
    for name in SAMPLER_NAMES {
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| run(&target, name, &options, &gaussian_starts()))
        };
        let one = on(1);
        let three = on(3);
        assert_eq!(one, three, "{name}: draws depend on the number of threads");
        let other_seed = run(&target, name, &SampleOptions { seed: 100, ..options.clone() }, &gaussian_starts());
        assert_ne!(one.chains[0].draws, other_seed.chains[0].draws, "{name}: the seed is ignored");
    }
}

#[test]
fn bad_options_name_the_field_and_value() {
    let cases: [(SamplerOptions, &str); 5] = [
        (SamplerOptions { leapfrog_steps: 0, ..Default::default() }, "`leapfrog_steps`: must be at least 1, got 0"),
        (SamplerOptions { proposal_scale: -1.0, ..Default::default() }, "`proposal_scale`: must be positive and finite, got -1"),
        (SamplerOptions { step_size: Some(f64::NAN), ..Default::default() }, "`step_size`: must be positive and finite, got NaN"),
        (SamplerOptions { max_tree_depth: 40, ..Default::default() }, "`max_tree_depth`: must be at most 30, got 40"),
        (SamplerOptions { de_noise: -0.5, ..Default::default() }, "`de_noise`: must be non-negative and finite, got -0.5"),
    ];
    for (options, message) in cases {
        for name in SAMPLER_NAMES {
            let err = by_name(name, options.clone()).err().expect("invalid options accepted");
            assert!(err.to_string().contains(message), "{name}: {err}");
        }
    }
    let err = toml::from_str::<SamplerOptions>("leapfrog = 3").unwrap_err();
    assert!(err.to_string().contains("leapfrog"), "{err}");

    let target = Gaussian { analytic: true };
    let nuts = by_name("nuts", SamplerOptions::default()).unwrap();
    let starts = gaussian_starts();
    let err = sample(&target, nuts.as_ref(), &SampleOptions { chains: 0, ..Default::default() }, &starts).unwrap_err();
    assert!(err.to_string().contains("`chains`: must be at least 1, got 0"), "{err}");
    let err = sample(&target, nuts.as_ref(), &SampleOptions::default(), &[vec![0.0; 3]]).unwrap_err();
    assert!(err.to_string().contains("`starts`: start 0 has 3 entries for 2 variables"), "{err}");
    let err = sample(&target, nuts.as_ref(), &SampleOptions::default(), &starts[..2]).unwrap_err();
    assert!(err.to_string().contains("`starts`: 2 start points for 4 chains"), "{err}");
    let err = sample(&BoxedNormal, nuts.as_ref(), &SampleOptions::default(), &[vec![-1.0, 0.0]]).unwrap_err();
    assert!(err.to_string().contains("`starts`: start 0 = [-1.0, 0.0] has log density -inf"), "{err}");
    let de = by_name("de-mc", SamplerOptions::default()).unwrap();
    let err = sample(&target, de.as_ref(), &SampleOptions { chains: 2, ..Default::default() }, &starts[..1]).unwrap_err();
    assert!(err.to_string().contains("`chains`: de-mc evolves a population of chains and needs at least 3, got 2"), "{err}");
    let err = by_name("gibbs", SamplerOptions::default()).err().unwrap();
    assert!(err.to_string().contains("unknown sampler `gibbs`"), "{err}");
}

#[test]
fn summary_serialises_and_plots_are_written() {
    let options = SampleOptions { chains: 3, warmup: 300, iterations: 400, seed: 1, progress: false };
    let result = run(&Gaussian { analytic: true }, "nuts", &options, &gaussian_starts()[..3]);
    let summary = result.summary(&["a", "b"]);
    let json = serde_json::to_string(&summary).unwrap();
    let back: PosteriorSummary = serde_json::from_str(&json).unwrap();
    assert_eq!(back, summary);
    let table = summary.table();
    assert!(table.lines().nth(1).unwrap().starts_with("a "), "{table}");
    assert!(table.contains("R-hat") && table.contains("nuts: 3 chains x 400 draws"), "{table}");

    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("trace.svg");
    let hist = dir.path().join("marginals.svg");
    cellstudio::report::mcmc_plot::trace_plot(&trace, "NUTS on a Gaussian", &["a", "b"], &result.chains).unwrap();
    cellstudio::report::mcmc_plot::marginal_histograms(&hist, "marginals", &["a", "b"], &result.chains, Some(&MEAN), 30)
        .unwrap();
    for (path, element) in [(&trace, "<polyline"), (&hist, "<rect")] {
        let svg = std::fs::read_to_string(path).unwrap();
        assert!(svg.starts_with("<svg") && svg.contains(element), "{}", path.display());
    }
}
