//! The integrator and its linear algebra on problems with known solutions (issue 17): error
//! proportional to the tolerance, event location, an index-1 DAE kept consistent, and the
//! sparse LU's pivoting fallback.

use cellstudio::solver::sparse::SparseSystem;
use cellstudio::solver::{Dae, SolverOptions, SolverStats, StopReason, Workspace, integrate};

/// `y' = -k y` (one differential state).
struct Decay {
    k: f64,
}

impl Dae for Decay {
    fn len(&self) -> usize {
        1
    }
    fn mass(&self) -> &[f64] {
        &[1.0]
    }
    fn scale(&self) -> &[f64] {
        &[1.0]
    }
    fn rhs(&self, _t: f64, y: &[f64], out: &mut [f64]) {
        out[0] = -self.k * y[0];
    }
}

/// `y0' = -y0`, `0 = y1 - y0^2` (index 1): `y0 = e^-t`, `y1 = e^-2t`.
struct SquareDae;

impl Dae for SquareDae {
    fn len(&self) -> usize {
        2
    }
    fn mass(&self) -> &[f64] {
        &[1.0, 0.0]
    }
    fn scale(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn rhs(&self, _t: f64, y: &[f64], out: &mut [f64]) {
        out[0] = -y[0];
        out[1] = y[1] - y[0] * y[0];
    }
}

fn options(tol: f64) -> SolverOptions {
    SolverOptions { rtol: tol, atol: tol, ..SolverOptions::default() }
}

fn solve(dae: &dyn Dae, entries: Vec<(usize, usize)>, y0: &[f64], t_end: f64, tol: f64, event: Option<&dyn Fn(f64, &[f64]) -> f64>) -> (Vec<f64>, StopReason, SolverStats) {
    let mut ws = Workspace::new(dae.len(), entries).unwrap();
    let mut y = y0.to_vec();
    let mut stats = SolverStats::default();
    let stop = integrate(dae, &mut ws, &options(tol), 0.0, &mut y, t_end, event, &mut |_, _| {}, &mut stats).unwrap();
    (y, stop, stats)
}

#[test]
fn global_error_is_proportional_to_the_tolerance() {
    // Over five decades of tolerance the error at t = 5 follows it (log-log slope near 1) and
    // stays within a small multiple of it: the error control holds what it promises.
    let tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];
    let errors: Vec<f64> = tols
        .iter()
        .map(|&tol| {
            let (y, stop, _) = solve(&Decay { k: 1.0 }, vec![(0, 0)], &[1.0], 5.0, tol, None);
            assert_eq!(stop, StopReason::EndTime);
            (y[0] - (-5.0f64).exp()).abs()
        })
        .collect();
    for (tol, e) in tols.iter().zip(&errors) {
        println!("tol {tol:.0e}: error {e:.2e} ({:.2} x tol)", e / tol);
        assert!(*e < 10.0 * tol, "error {e:e} at tolerance {tol:e}");
    }
    let slope = (errors[0] / errors[errors.len() - 1]).log10() / (tols[0] / tols[tols.len() - 1]).log10();
    println!("log-log slope {slope:.3}");
    assert!((0.8..1.2).contains(&slope), "slope {slope}");
}

#[test]
fn a_stiff_decay_takes_few_steps() {
    // k = 1e6 over 1 s: an explicit method would need about 1e6 steps; BDF's step grows once
    // the transient has died.
    let (y, _, stats) = solve(&Decay { k: 1e6 }, vec![(0, 0)], &[1.0], 1.0, 1e-6, None);
    println!("{stats:?}");
    assert!(y[0].abs() < 1e-6, "{}", y[0]);
    assert!(stats.steps < 200, "{} steps", stats.steps);
}

#[test]
fn events_are_located_to_the_accuracy_of_the_solution() {
    // y = e^-t crosses 1/2 at ln 2.
    let event = |_t: f64, y: &[f64]| y[0] - 0.5;
    for tol in [1e-6, 1e-9] {
        let (y, stop, _) = solve(&Decay { k: 1.0 }, vec![(0, 0)], &[1.0], 10.0, tol, Some(&event));
        let StopReason::Event(t) = stop else { panic!("no event at tolerance {tol}") };
        println!("tol {tol:.0e}: event at {t:.12} (error {:.1e}), y = {:.12}", t - 2f64.ln(), y[0]);
        assert!((t - 2f64.ln()).abs() < 10.0 * tol, "event at {t}, expected ln 2");
        assert!((y[0] - 0.5).abs() < 10.0 * tol, "state at the event {}", y[0]);
    }
}

#[test]
fn an_index_one_dae_stays_on_its_constraint() {
    let tol = 1e-8;
    let (y, stop, _) = solve(&SquareDae, vec![(0, 0), (1, 0), (1, 1)], &[1.0, 1.0], 2.0, tol, None);
    assert_eq!(stop, StopReason::EndTime);
    println!("y0 error {:.1e}, y1 error {:.1e}, constraint {:.1e}", y[0] - (-2f64).exp(), y[1] - (-4f64).exp(), y[1] - y[0] * y[0]);
    assert!((y[0] - (-2f64).exp()).abs() < 10.0 * tol);
    assert!((y[1] - (-4f64).exp()).abs() < 10.0 * tol);
    assert!((y[1] - y[0] * y[0]).abs() < 1e-12, "constraint residual {}", y[1] - y[0] * y[0]);
}

#[test]
fn a_zero_static_pivot_falls_back_to_partial_pivoting() {
    // diag(mass) - c J with a zero diagonal: [[0, 2], [3, 0]] needs a row exchange.
    let entries = [(0, 1), (1, 0)];
    let mut system = SparseSystem::new(2, &entries).unwrap();
    system.factorise(&[0.0, 0.0], 1.0, &[-2.0, -3.0]).unwrap();
    assert!(system.pivoted(), "the static LU should have refused a zero pivot");
    let mut x = [4.0, 9.0];
    system.solve(&mut x);
    // 2 x1 = 4, 3 x0 = 9.
    assert!((x[0] - 3.0).abs() < 1e-14 && (x[1] - 2.0).abs() < 1e-14, "{x:?}");
    // A well-posed matrix on the same system goes back to the static LU.
    system.factorise(&[1.0, 1.0], 0.1, &[-2.0, -3.0]).unwrap();
    assert!(!system.pivoted());
}
