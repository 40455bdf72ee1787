//! The integrator and its linear algebra on problems with known solutions (issue 17): error
//! proportional to the tolerance, event location, an index-1 DAE kept consistent, the stepper
//! driven one step at a time, steps ending on an input's kinks, an accumulating state held
//! tighter, and the sparse LU's pivoting fallback.

use cellstudio::solver::sparse::SparseSystem;
use cellstudio::solver::{Bdf, Dae, SolverOptions, SolverStats, StopReason, Workspace, integrate};

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

/// Bounds of the step-by-step test's worst errors, in tolerances (about 2.5x the achieved
/// values): against e^-t (the global error, achieved 3.9), and within one step against the
/// exact solution through its start (achieved 0.88).
const WORST_GLOBAL: f64 = 10.0;
const WORST_LOCAL: f64 = 2.0;

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
fn the_stepper_takes_one_step_at_a_time() {
    // y' = -y from 1 to t = 5, one step per call: time advances by exactly the step size, the
    // order stays within 1-5, the counters only grow (steps by one a call), and each step's
    // interpolant matches e^-t at the step's midpoint and its end.
    let (tol, t_end) = (1e-6, 5.0);
    let dae = Decay { k: 1.0 };
    let opts = options(tol);
    let mut ws = Workspace::new(1, vec![(0, 0)]).unwrap();
    let mut bdf = Bdf::new(&dae, &mut ws, &opts, 0.0, &[1.0], t_end).unwrap();
    let mut last = *bdf.stats();
    let (mut worst_mid, mut worst_end, mut worst_local, mut max_order, mut n) = (0.0f64, 0.0f64, 0.0f64, 0, 0);
    let (mut y, mut y_old) = ([0.0], [0.0]);
    while bdf.t() < t_end {
        let t_before = bdf.t();
        let step = bdf.step().unwrap();
        n += 1;
        assert_eq!(step.t_old, t_before);
        assert!(step.t > step.t_old && step.t == bdf.t() && step.h == step.t - step.t_old, "{step:?}");
        assert!((1..=5).contains(&step.order), "{step:?}");
        max_order = max_order.max(step.order);
        let stats = *bdf.stats();
        assert_eq!(stats.steps, last.steps + 1);
        assert!(stats.rhs_evals > last.rhs_evals && stats.rejected_steps >= last.rejected_steps);
        assert!(stats.jacobian_evals >= last.jacobian_evals && stats.factorisations >= last.factorisations);
        last = stats;
        let dense = bdf.dense();
        assert_eq!(dense.t_end(), step.t);
        let mid = step.t_old + 0.5 * step.h;
        dense.eval(mid, &mut y);
        worst_mid = worst_mid.max((y[0] - (-mid).exp()).abs() / tol);
        // Against the exact solution through the interpolant's start: the step's own error.
        dense.eval(step.t_old, &mut y_old);
        worst_local = worst_local.max((y[0] - y_old[0] * (-0.5 * step.h).exp()).abs() / tol);
        dense.eval(step.t, &mut y);
        assert_eq!(y[0], bdf.state()[0], "the interpolant ends on the state");
        worst_end = worst_end.max((y[0] - (-step.t).exp()).abs() / tol);
    }
    println!("{n} steps, orders up to {max_order}, {last:?}");
    println!("worst error / tol: {worst_mid:.2} at step midpoints, {worst_end:.2} at step ends, {worst_local:.3} within a step");
    assert_eq!(bdf.t(), t_end, "the last step ends on the stop time");
    assert!(max_order >= 3, "the order should climb on a smooth solution");
    assert!(worst_mid < WORST_GLOBAL && worst_end < WORST_GLOBAL, "{worst_mid} {worst_end}");
    assert!(worst_local < WORST_LOCAL, "{worst_local}");
    assert!(bdf.step().is_err(), "no step past the stop time");
}

#[test]
fn integrate_is_the_stepper_driven_to_the_end() {
    // The wrapper and a hand-driven stepper do the same arithmetic: same state, same counters.
    let dae = Decay { k: 1.0 };
    let opts = options(1e-7);
    let (y, _, stats) = solve(&dae, vec![(0, 0)], &[1.0], 3.0, 1e-7, None);
    let mut ws = Workspace::new(1, vec![(0, 0)]).unwrap();
    let mut bdf = Bdf::new(&dae, &mut ws, &opts, 0.0, &[1.0], 3.0).unwrap();
    while bdf.t() < 3.0 {
        bdf.step().unwrap();
    }
    assert_eq!(bdf.state()[0].to_bits(), y[0].to_bits());
    let s = bdf.stats();
    assert_eq!((s.steps, s.rejected_steps, s.rhs_evals, s.jacobian_evals, s.factorisations), (stats.steps, stats.rejected_steps, stats.rhs_evals, stats.jacobian_evals, stats.factorisations));
}

#[test]
fn a_zero_static_pivot_falls_back_to_partial_pivoting() {
    // diag(mass) - c J with a zero diagonal: [[0, 2], [3, 0]] needs a row exchange.
    let entries = [(0, 1), (1, 0)];
    let mut system = SparseSystem::new(2, &entries, &[]).unwrap();
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

/// `y0' = z - y0`, `0 = z - u(t)` (index 1) under a piecewise-linear input `u` through the
/// points `(k, u_k)`, k = 0, 1, 2, ... s: a recorded current replayed sample by sample. `z`
/// has a kink at every point; `breaks` are the points the integrator is told about.
struct KinkedInput {
    u: Vec<f64>,
    breaks: Vec<f64>,
}

impl KinkedInput {
    fn input(&self, t: f64) -> f64 {
        let k = (t.floor() as usize).min(self.u.len() - 2);
        self.u[k] + (t - k as f64) * (self.u[k + 1] - self.u[k])
    }

    /// `y0` at every point, exactly: on each interval `u = a + b s` (s from its start),
    /// `y0 = a - b + b s + (y0(start) - a + b) e^-s`.
    fn exact(&self, y_start: f64) -> Vec<f64> {
        let mut y = vec![y_start];
        for k in 0..self.u.len() - 1 {
            let (a, b) = (self.u[k], self.u[k + 1] - self.u[k]);
            y.push(a + (y[k] - a + b) * (-1f64).exp());
        }
        y
    }
}

impl Dae for KinkedInput {
    fn len(&self) -> usize {
        2
    }
    fn mass(&self) -> &[f64] {
        &[1.0, 0.0]
    }
    fn scale(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn rhs(&self, t: f64, y: &[f64], out: &mut [f64]) {
        out[0] = y[1] - y[0];
        out[1] = y[1] - self.input(t);
    }
    fn breakpoints(&self) -> &[f64] {
        &self.breaks
    }
}

#[test]
fn steps_end_on_the_breakpoints_of_a_kinked_input_and_keep_its_accuracy() {
    // A 1 s sampled drive-like input: steps that straddle its kinks fail the error test (the
    // algebraic state's slope jumps); told where they are, the integrator ends a step on each
    // and judges the algebraic row only once its history no longer reaches across one.
    let u: Vec<f64> = (0..=300).map(|k| { let k = k as f64; (0.05 * k).sin() + 0.5 * (0.31 * k).sin() + 0.3 * (1.7 * k).sin() }).collect();
    let tol = 1e-6;
    let t_end = (u.len() - 1) as f64;
    let run = |breaks: Vec<f64>| {
        let dae = KinkedInput { u: u.clone(), breaks };
        let exact = dae.exact(0.0);
        let mut ws = Workspace::new(2, vec![(0, 0), (0, 1), (1, 1)]).unwrap();
        let mut y = vec![0.0, u[0]];
        let (mut ends, mut worst) = (Vec::new(), 0.0f64);
        let mut buf = [0.0; 2];
        let mut stats = SolverStats::default();
        integrate(&dae, &mut ws, &options(tol), 0.0, &mut y, t_end, None, &mut |t_old, dense| {
            ends.push(dense.t_end());
            // The exact solution at every sample point the step covers.
            for k in (t_old.floor() as usize + 1)..=(dense.t_end().floor() as usize) {
                dense.eval(k as f64, &mut buf);
                worst = worst.max((buf[0] - exact[k]).abs() / tol);
            }
        }, &mut stats)
        .unwrap();
        (ends, worst, stats)
    };
    let (ends, worst, with) = run((1..u.len() - 1).map(|k| k as f64).collect());
    let (_, worst_blind, without) = run(Vec::new());
    println!("told: {with:?}, worst error {worst:.2} tol\nuntold: {without:?}, worst error {worst_blind:.2} tol");
    // Achieved (November 2026): 1190 vs 4165 rejected steps, 14763 vs 27574 right-hand sides,
    // worst error 12.8 vs 7.3 tolerances (at rtol 1e-5 told: 9457 right-hand sides, 7.6 tol;
    // so at matched accuracy told costs about 0.6 of untold).
    assert!((1..u.len()).all(|k| ends.contains(&(k as f64))), "a step ends on every breakpoint");
    assert!(worst < 2.5 * worst_blind, "worst error {worst} tolerances told, {worst_blind} untold");
    assert!(10 * with.rejected_steps < 4 * without.rejected_steps, "{} rejected steps told, {} untold", with.rejected_steps, without.rejected_steps);
    assert!(100 * with.rhs_evals < 65 * without.rhs_evals, "{} right-hand sides told, {} untold", with.rhs_evals, without.rhs_evals);
}

/// `x' = cos t - x - sin t` (relaxes onto `x = cos t`, and sets the steps) and an
/// accumulator `q' = eps (1 + cos t)^6`, a rate peaked once a period, as an SEI layer's is
/// during each charge: over whole periods `q = q0 + eps t C(12, 6) / 2^6`, a growth small
/// against `q0`.
struct Accumulating {
    eps: f64,
}

impl Dae for Accumulating {
    fn len(&self) -> usize {
        2
    }
    fn mass(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn scale(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn rhs(&self, t: f64, y: &[f64], out: &mut [f64]) {
        out[0] = t.cos() - y[0] - t.sin();
        out[1] = self.eps * (1.0 + t.cos()).powi(6);
    }
    fn accumulating_states(&self) -> Vec<usize> {
        vec![1]
    }
}

#[test]
fn a_tighter_accumulator_tolerance_holds_what_it_gathers() {
    // Over 32 periods the accumulator gathers 2 % of its value; held like the other state, its
    // error is 1.1e-4 of that growth (1488 steps). A tolerance 32 times tighter on it alone
    // (what `run_cycles` does for 32 cycles) gives 4.3e-5 for 3 % more steps (1533); factors
    // down to 0.1 change nothing (the other state sets the steps), 1e-3 gives 3.6e-6 (2060).
    let (dae, periods, tol) = (Accumulating { eps: 6.9e-6 }, 32.0, 1e-6);
    let t_end = periods * std::f64::consts::TAU;
    let growth = dae.eps * t_end * 924.0 / 64.0;
    let run = |factor: f64| {
        let mut ws = Workspace::new(2, vec![(0, 0), (1, 1)]).unwrap();
        let mut y = vec![1.0, 1.0];
        let mut stats = SolverStats::default();
        let opts = SolverOptions { accumulator_tolerance: factor, ..options(tol) };
        integrate(&dae, &mut ws, &opts, 0.0, &mut y, t_end, None, &mut |_, _| {}, &mut stats).unwrap();
        ((y[1] - 1.0 - growth).abs() / growth, (y[0] - t_end.cos()).abs(), stats.steps)
    };
    let (plain, x_plain, steps_plain) = run(1.0);
    let (tight, x_tight, steps_tight) = run(1.0 / periods);
    println!("growth {growth:.3e}, its error: plain {plain:.2e} ({steps_plain} steps), tight {tight:.2e} ({steps_tight} steps); x error {x_plain:.1e} / {x_tight:.1e}");
    assert!(tight < plain / 2.0, "tight {tight:e} vs plain {plain:e}");
    assert!(x_plain < 10.0 * tol && x_tight < 10.0 * tol);
    assert!(steps_tight * 5 < steps_plain * 6, "{steps_tight} steps vs {steps_plain}");
}
