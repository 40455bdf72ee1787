//! Every optimiser on reference problems with known minima, the projection against the
//! analytic simplex projection, infeasibility reporting, reproducibility and feasibility of
//! every evaluated candidate.

use std::sync::Mutex;

use cellstudio::optim::{
    Bounds, LinearConstraints, NoObserver, Objective, OptimOptions, OptimResult, Problem, StopReason, TraceObserver,
    Transform, by_name,
};

/// `Σ x_i²`, minimum 0 at the origin.
struct Sphere {
    dim: usize,
}

impl Objective for Sphere {
    fn dim(&self) -> usize {
        self.dim
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        x.iter().map(|v| v * v).sum()
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        Some(x.iter().map(|v| 2.0 * v).collect())
    }
}

/// `(1 - x)² + 100·(y - x²)²`, minimum 0 at (1, 1).
struct Rosenbrock;

impl Objective for Rosenbrock {
    fn dim(&self) -> usize {
        2
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        (1.0 - x[0]).powi(2) + 100.0 * (x[1] - x[0] * x[0]).powi(2)
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        let t = x[1] - x[0] * x[0];
        Some(vec![-2.0 * (1.0 - x[0]) - 400.0 * x[0] * t, 200.0 * t])
    }
}

/// `||x - c||²`; records every point it is evaluated at.
struct Distance {
    c: Vec<f64>,
    seen: Mutex<Vec<Vec<f64>>>,
    with_gradient: bool,
}

impl Distance {
    fn new(c: &[f64], with_gradient: bool) -> Self {
        Distance { c: c.to_vec(), seen: Mutex::new(Vec::new()), with_gradient }
    }
}

impl Objective for Distance {
    fn dim(&self) -> usize {
        self.c.len()
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        self.seen.lock().unwrap().push(x.to_vec());
        x.iter().zip(&self.c).map(|(a, b)| (a - b) * (a - b)).sum()
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.with_gradient.then(|| x.iter().zip(&self.c).map(|(a, b)| 2.0 * (a - b)).collect())
    }
}

const ALL: [&str; 11] = cellstudio::optim::OPTIMISER_NAMES;

fn options(max_evaluations: usize, max_iterations: usize, seed: u64) -> OptimOptions {
    OptimOptions::default()
        .with_seed(seed)
        .with_max_evaluations(max_evaluations)
        .unwrap()
        .with_max_iterations(max_iterations)
        .unwrap()
        .with_patience(max_iterations)
        .unwrap()
}

fn run(name: &str, problem: &Problem, x0: &[f64], options: OptimOptions) -> OptimResult {
    let mut optimiser = by_name(name, options).unwrap();
    assert_eq!(optimiser.name(), name);
    optimiser.minimise(problem, x0, &mut NoObserver).unwrap()
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
}

fn report(label: &str, name: &str, r: &OptimResult, error: f64) {
    eprintln!(
        "{label:<10} {name:<24} iterations {:>6}  evaluations {:>7}  gradients {:>6}  f {:>10.3e}  |x - x*| {:>9.2e}  {:?}",
        r.iterations, r.evaluations, r.gradient_evaluations, r.f, error, r.stop
    );
}

#[test]
fn every_optimiser_minimises_the_sphere() {
    let objective = Sphere { dim: 4 };
    let problem = Problem::new(&objective, Bounds::new(vec![-5.0; 4], vec![5.0; 4]).unwrap()).unwrap();
    let x0 = [2.0, -1.5, 1.0, 3.0];
    // Evaluation budgets, about 1.5 times the measured counts: a performance regression fails.
    let budgets = [
        ("nelder-mead", 1_200),
        ("cmaes", 1_500),
        ("xnes", 3_000),
        ("snes", 2_100),
        ("differential-evolution", 13_000),
        ("pso", 4_200),
        ("cuckoo", 46_000),
        ("gradient-descent", 40),
        ("adamw", 480),
        ("irprop-", 110),
        ("lbfgsb", 6),
    ];
    for (name, budget) in budgets {
        let r = run(name, &problem, &x0, options(200_000, 100_000, 1));
        let error = distance(&r.x, &[0.0; 4]);
        report("sphere", name, &r, error);
        assert!(error < 1e-3, "{name}: |x - 0| = {error:e}, x = {:?}, stop {:?}", r.x, r.stop);
        assert!(r.evaluations <= budget, "{name}: {} evaluations, budget {budget}", r.evaluations);
        assert_eq!(r.stop, StopReason::Tolerance, "{name}");
    }
}

#[test]
fn every_optimiser_minimises_rosenbrock() {
    let problem = Problem::new(&Rosenbrock, Bounds::new(vec![-5.0; 2], vec![5.0; 2]).unwrap()).unwrap();
    let x0 = [-1.2, 1.0];
    let budgets = [
        ("nelder-mead", 400),
        ("cmaes", 1_100),
        ("xnes", 1_600),
        ("snes", 200_000),
        ("differential-evolution", 4_000),
        ("pso", 14_000),
        ("cuckoo", 160_000),
        ("gradient-descent", 15_000),
        ("adamw", 2_000),
        ("irprop-", 11_000),
        ("lbfgsb", 75),
    ];
    for (name, budget) in budgets {
        let r = run(name, &problem, &x0, options(200_000, 100_000, 2));
        let error = distance(&r.x, &[1.0, 1.0]);
        report("rosenbrock", name, &r, error);
        assert!(error < 1e-2, "{name}: |x - (1, 1)| = {error:e}, x = {:?}, stop {:?}", r.x, r.stop);
        assert!(r.evaluations <= budget, "{name}: {} evaluations, budget {budget}", r.evaluations);
    }
}

/// Euclidean projection onto the probability simplex {x >= 0, Σx = 1} by sorting
/// (Held, Wolfe and Crowder 1974; Duchi et al. 2008).
fn simplex_projection(v: &[f64]) -> Vec<f64> {
    let mut sorted = v.to_vec();
    sorted.sort_by(|a, b| b.total_cmp(a));
    let mut cumulative = 0.0;
    let mut theta = 0.0;
    for (j, &u) in sorted.iter().enumerate() {
        cumulative += u;
        let t = (cumulative - 1.0) / (j + 1) as f64;
        if u - t > 0.0 {
            theta = t;
        }
    }
    v.iter().map(|x| (x - theta).max(0.0)).collect()
}

fn simplex_constraints(dim: usize) -> LinearConstraints {
    LinearConstraints::new().equality(vec![1.0; dim], 1.0)
}

#[test]
fn projection_matches_the_analytic_simplex_projection() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    for dim in [3, 5] {
        let bounds = Bounds::new(vec![0.0; dim], vec![1.0; dim]).unwrap();
        let constraints = simplex_constraints(dim);
        for k in 0..200 {
            let v: Vec<f64> = (0..dim).map(|_| rng.random_range(-2.0..3.0)).collect();
            let projected = constraints.project(&v, &bounds).unwrap();
            let exact = simplex_projection(&v);
            let error = distance(&projected, &exact);
            assert!(error < 1e-8, "dim {dim}, point {k} {v:?}: {projected:?} vs {exact:?} ({error:e})");
            assert!(bounds.contains(&projected));
        }
    }
    // Points already feasible are (numerically) fixed points.
    let bounds = Bounds::new(vec![0.0; 3], vec![1.0; 3]).unwrap();
    let p = simplex_constraints(3).project(&[0.2, 0.3, 0.5], &bounds).unwrap();
    assert!(distance(&p, &[0.2, 0.3, 0.5]) < 1e-9);
}

/// `||x - c||²` on {x1 + x2 + x3 = 1, 0 <= x <= 1} with `c` outside the simplex: the minimiser
/// is the simplex projection of `c`, here (0.65, 0.35, 0) with the third bound active.
#[test]
fn constrained_quadratic_is_solved_and_every_candidate_is_feasible() {
    let c = [0.9, 0.6, -0.4];
    let expected = simplex_projection(&c);
    assert!(distance(&expected, &[0.65, 0.35, 0.0]) < 1e-15);
    let bounds = Bounds::new(vec![0.0; 3], vec![1.0; 3]).unwrap();
    let x0 = [0.1, 0.1, 0.8];
    let mut solved = Vec::new();
    for name in ALL {
        let objective = Distance::new(&c, true);
        let problem =
            Problem::new(&objective, bounds.clone()).unwrap().with_constraints(simplex_constraints(3)).unwrap();
        let r = run(name, &problem, &x0, options(20_000, 20_000, 3));
        let error = distance(&r.x, &expected);
        report("simplex QP", name, &r, error);
        // Every candidate the objective saw was feasible.
        for x in objective.seen.lock().unwrap().iter() {
            assert!(bounds.contains(x), "{name}: candidate {x:?} outside the bounds");
            let sum: f64 = x.iter().sum();
            assert!((sum - 1.0).abs() < 1e-9, "{name}: candidate {x:?} has Σx - 1 = {:e}", sum - 1.0);
        }
        if error < 1e-4 {
            solved.push(name);
        }
    }
    eprintln!("simplex QP solved to 1e-4 by {solved:?}");
    for required in ["nelder-mead", "cmaes", "lbfgsb"] {
        assert!(solved.contains(&required), "{required} did not solve the constrained QP");
    }
}

#[test]
fn infeasible_constraints_are_reported_before_searching() {
    let objective = Distance::new(&[0.0, 0.0], false);
    let bounds = Bounds::new(vec![0.0; 2], vec![1.0; 2]).unwrap();
    let constraints = LinearConstraints::new().equality(vec![1.0, 1.0], 3.0);
    let message = Problem::new(&objective, bounds.clone())
        .unwrap()
        .with_constraints(constraints)
        .err()
        .expect("x1 + x2 = 3 cannot hold for 0 <= x <= 1")
        .to_string();
    assert_eq!(
        message,
        "invalid setting `linear_constraints`: infeasible constraint set: equality 0 (x[0] + x[1] = 3) \
         cannot hold within the bounds, where its left side ranges over [0, 2]"
    );
    // Each constraint alone is satisfiable, together they are not: Clarabel's certificate.
    let constraints = LinearConstraints::new().inequality(vec![1.0, 1.0], 1.0).inequality(vec![-1.0, -1.0], -1.5);
    let message = Problem::new(&objective, bounds).unwrap().with_constraints(constraints).err().unwrap().to_string();
    assert!(
        message.contains(
            "infeasible constraint set: no point satisfies all of inequality 0 (x[0] + x[1] <= 1), \
             inequality 1 (-x[0] - x[1] <= -1.5) together with the bounds"
        ),
        "{message}"
    );
    assert!(objective.seen.lock().unwrap().is_empty());
}

#[test]
fn same_seed_gives_identical_results_for_any_thread_count() {
    let problem = Problem::new(&Rosenbrock, Bounds::new(vec![-5.0; 2], vec![5.0; 2]).unwrap()).unwrap();
    let x0 = [-1.2, 1.0];
    let in_pool = |threads: usize, name: &str, seed: u64| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| run(name, &problem, &x0, options(3_000, 100_000, seed)))
    };
    for name in ALL {
        let a = in_pool(1, name, 5);
        let b = in_pool(3, name, 5);
        let c = in_pool(3, name, 5);
        assert_eq!(a, b, "{name}: 1 thread vs 3 threads");
        assert_eq!(b, c, "{name}: repeated run");
        if !["nelder-mead", "gradient-descent", "adamw", "irprop-", "lbfgsb"].contains(&name) {
            let d = in_pool(2, name, 6);
            assert_ne!(a.x, d.x, "{name}: a different seed should give a different path");
        }
    }
}

#[test]
fn log_transform_searches_in_log_space() {
    /// `(ln x0 - ln 1e-3)² + (x1 - 0.5)²`.
    struct Decades;
    impl Objective for Decades {
        fn dim(&self) -> usize {
            2
        }
        fn evaluate(&self, x: &[f64]) -> f64 {
            (x[0].ln() - 1e-3f64.ln()).powi(2) + (x[1] - 0.5).powi(2)
        }
        fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
            Some(vec![2.0 * (x[0].ln() - 1e-3f64.ln()) / x[0], 2.0 * (x[1] - 0.5)])
        }
    }
    let bounds = Bounds::new(vec![1e-6, 0.0], vec![1.0, 1.0]).unwrap();
    let problem = Problem::new(&Decades, bounds.clone())
        .unwrap()
        .with_transforms(vec![Transform::Log, Transform::Identity])
        .unwrap();
    assert!((problem.search_bounds().lower()[0] - 1e-6f64.ln()).abs() < 1e-12);
    for name in ["lbfgsb", "cmaes", "nelder-mead"] {
        let r = run(name, &problem, &[0.5, 0.9], options(20_000, 5_000, 4));
        report("log", name, &r, (r.x[0] / 1e-3 - 1.0).abs());
        assert!((r.x[0] / 1e-3 - 1.0).abs() < 1e-5 && (r.x[1] - 0.5).abs() < 1e-5, "{name}: {:?}", r.x);
    }
    let err = Problem::new(&Decades, Bounds::new(vec![0.0, 0.0], vec![1.0, 1.0]).unwrap())
        .unwrap()
        .with_transforms(vec![Transform::Log, Transform::Identity])
        .err()
        .unwrap();
    assert_eq!(err.to_string(), "invalid setting `transforms[0]`: log transform needs a positive lower bound, got 0");
}

/// A micrometre-scale variable searched as `(x - offset) / scale` reaches the same optimum,
/// and a non-positive scale is refused.
#[test]
fn affine_transform_searches_rescaled_variables() {
    struct Micro;
    impl Objective for Micro {
        fn dim(&self) -> usize {
            1
        }
        fn evaluate(&self, x: &[f64]) -> f64 {
            ((x[0] - 7.3e-5) / 1e-6).powi(2)
        }
    }
    let bounds = Bounds::new(vec![5e-5], vec![1.1e-4]).unwrap();
    let affine = Transform::Affine { scale: 1e-6, offset: 5e-5 };
    let problem = Problem::new(&Micro, bounds.clone()).unwrap().with_transforms(vec![affine]).unwrap();
    assert!((problem.search_bounds().upper()[0] - 60.0).abs() < 1e-9);
    for name in ["nelder-mead", "cmaes", "lbfgsb"] {
        let r = run(name, &problem, &[9e-5], options(5_000, 2_000, 2));
        report("affine", name, &r, (r.x[0] - 7.3e-5).abs());
        assert!((r.x[0] - 7.3e-5).abs() < 1e-9, "{name}: {:?}", r.x);
    }
    let err = Problem::new(&Micro, bounds)
        .unwrap()
        .with_transforms(vec![Transform::Affine { scale: 0.0, offset: 0.0 }])
        .err()
        .unwrap();
    assert!(err.to_string().contains("transforms[0]"), "{err}");
}

#[test]
fn finite_differences_replace_a_missing_gradient() {
    let objective = Distance::new(&[0.3, -0.2], false);
    let problem = Problem::new(&objective, Bounds::new(vec![-1.0; 2], vec![1.0; 2]).unwrap()).unwrap();
    let r = run("lbfgsb", &problem, &[0.9, 0.9], options(1_000, 100, 0));
    assert_eq!(r.gradient_evaluations, 0);
    assert!(distance(&r.x, &[0.3, -0.2]) < 1e-7, "{:?}", r.x);
    let g = cellstudio::optim::finite_difference_gradient(&Rosenbrock, &[-1.2, 1.0]);
    let exact = Rosenbrock.gradient(&[-1.2, 1.0]).unwrap();
    let fd = cellstudio::optim::central_difference(&|x: &[f64]| Rosenbrock.evaluate(x), &[-1.2, 1.0], &[1e-6; 2], None);
    assert!(distance(&g, &exact) < 1e-12 && distance(&fd, &exact) < 1e-5, "{fd:?} vs {exact:?}");
    // At a bound the difference is one-sided and stays inside the box.
    let bounds = Bounds::new(vec![-1.2, 0.0], vec![2.0, 2.0]).unwrap();
    let fd = cellstudio::optim::central_difference(
        &|x: &[f64]| {
            assert!(x[0] >= -1.2);
            Rosenbrock.evaluate(x)
        },
        &[-1.2, 1.0],
        &[1e-7; 2],
        Some(&bounds),
    );
    assert!(distance(&fd, &exact) < 1e-3, "{fd:?} vs {exact:?}");
}

#[test]
fn observers_see_every_iteration_and_options_are_checked() {
    let objective = Sphere { dim: 4 };
    let problem = Problem::new(&objective, Bounds::new(vec![-5.0; 4], vec![5.0; 4]).unwrap()).unwrap();
    let mut trace = TraceObserver::default();
    let mut cmaes = by_name("CMA-ES", options(100_000, 50, 1)).unwrap();
    let r = cmaes.minimise(&problem, &[2.0, -1.5, 1.0, 3.0], &mut trace).unwrap();
    assert_eq!(r.stop, StopReason::MaxIterations);
    assert_eq!(trace.entries.len(), r.iterations);
    assert!(trace.entries.windows(2).all(|w| w[1].best_f <= w[0].best_f && w[1].evaluations > w[0].evaluations));
    assert_eq!(trace.entries.last().unwrap().best_f, r.f);

    let err = by_name("simplex", OptimOptions::default()).err().unwrap().to_string();
    assert_eq!(
        err,
        "invalid setting `optimiser`: unknown optimiser `simplex`; valid names: nelder-mead, cmaes, xnes, snes, \
         differential-evolution, pso, cuckoo, gradient-descent, adamw, irprop-, lbfgsb"
    );
    let err = by_name("de", OptimOptions { population_size: Some(3), ..Default::default() })
        .unwrap()
        .minimise(&problem, &[0.0; 4], &mut NoObserver)
        .unwrap_err();
    assert_eq!(err.to_string(), "invalid setting `population_size`: differential evolution needs at least 4, got 3");
    let err = run_err(&problem, &[0.0; 3]);
    assert_eq!(err, "invalid setting `x0`: start point has 3 entries for 4 variables");
    assert!(toml::from_str::<OptimOptions>("max_iterations = 10\nunknown = 1").is_err());
}

fn run_err(problem: &Problem, x0: &[f64]) -> String {
    by_name("nelder-mead", OptimOptions::default())
        .unwrap()
        .minimise(problem, x0, &mut NoObserver)
        .unwrap_err()
        .to_string()
}

/// Sphere with the lower bounds of the first two variables at 0.5: the minimum (0.5, 0.5, 0, 0)
/// lies on the bounds. Every candidate must be inside the box.
#[test]
fn optimum_on_a_bound() {
    let c = [0.0; 4];
    let bounds = Bounds::new(vec![0.5, 0.5, -5.0, -5.0], vec![5.0; 4]).unwrap();
    for name in ALL {
        let objective = Distance::new(&c, true);
        let problem = Problem::new(&objective, bounds.clone()).unwrap();
        let r = run(name, &problem, &[2.0, 3.0, 1.0, -2.0], options(50_000, 20_000, 8));
        let error = distance(&r.x, &[0.5, 0.5, 0.0, 0.0]);
        report("bound", name, &r, error);
        assert!(error < 1e-3, "{name}: {:?}, stop {:?}", r.x, r.stop);
        assert!(objective.seen.lock().unwrap().iter().all(|x| bounds.contains(x)), "{name}: candidate outside the box");
    }
}

/// `||x - (1, 1)||²` subject to `x0 + 2·x1 <= 1` in the box [-1, 1]²: the minimiser is the
/// projection onto the half-plane, (0.6, 0.2). Every candidate must satisfy the inequality.
#[test]
fn inequality_constraint_is_respected() {
    let bounds = Bounds::new(vec![-1.0; 2], vec![1.0; 2]).unwrap();
    let half_plane = LinearConstraints::new().inequality(vec![1.0, 2.0], 1.0);
    let projected = half_plane.project(&[1.0, 1.0], &bounds).unwrap();
    assert!(distance(&projected, &[0.6, 0.2]) < 1e-8, "{projected:?}");
    for name in ALL {
        let objective = Distance::new(&[1.0, 1.0], true);
        let problem = Problem::new(&objective, bounds.clone()).unwrap().with_constraints(half_plane.clone()).unwrap();
        let r = run(name, &problem, &[-0.5, -0.5], options(3_000, 3_000, 9));
        let error = distance(&r.x, &[0.6, 0.2]);
        report("half-plane", name, &r, error);
        for x in objective.seen.lock().unwrap().iter() {
            assert!(bounds.contains(x) && x[0] + 2.0 * x[1] <= 1.0 + 1e-9, "{name}: candidate {x:?} infeasible");
        }
        if ["nelder-mead", "cmaes", "lbfgsb"].contains(&name) {
            assert!(error < 1e-4, "{name}: {:?}", r.x);
        }
    }
}
