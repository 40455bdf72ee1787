//! Benchmark: diffsol 0.18's BDF against cellstudio's own BDF/NDF integrator on the same
//! DFN 1C discharge (chen2020, default mesh, 5 A until the 2.5 V cut-off).
//!
//! `cargo run --release --features diffsol-bench --example bench_diffsol [-- REPEATS]`
//!
//! The DFN is handed to diffsol as its own `OdeEquations` (the custom-equations route):
//! - right-hand side `f(y)` of `M y' = f(y)` = `Model::rhs` at the constant current;
//! - mass matrix `diag(Model::mass())` as a sparse faer matrix (full diagonal pattern, zeros
//!   on the algebraic rows, which is how diffsol finds the algebraic states);
//! - Jacobian: the model's structural pattern (`Model::jacobian_pattern`) as the sparsity, and
//!   the values by the *same* coloured forward differences our integrator uses
//!   (`solver::jacobian::ColouredPattern`), so both solvers see identical Jacobians and only the
//!   integrators differ. The Jacobian-vector product, which diffsol calls only in its
//!   consistent initialisation (`InitOp`, ~6 calls per run), is a one-sided directional
//!   difference;
//! - root function `V(y) - 2.5` for the cut-off;
//! - linear solver `FaerSparseLU` (faer 0.24, sequential), same tolerances:
//!   `rtol = 1e-6`, `atol_i = 1e-6 * scale_i`.
//!
//! Agreement is checked before timing (terminal voltage at 20 common times within 1 mV,
//! cut-off times within 1 s). Timing is split into setup (the solver-specific part: our
//! `Workspace::new` — colouring and symbolic LU — versus the diffsol equations and problem)
//! and solve (consistent initialisation plus integration to the cut-off), medians of REPEATS
//! runs (default 10). Model construction is shared and excluded from both. Our integrator is
//! timed twice: through `simulate` (which also records voltage, charge and energy every step)
//! and through `solver::integrate` with a no-op observer, the like-for-like comparison with
//! diffsol's bare `step()` loop. The three runs are interleaved in each repeat. diffsol's
//! symbolic LU happens on its first step, so it sits in diffsol's solve time, whereas ours is in
//! `Workspace::new` (setup).

use std::cell::Cell;
use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::builder::Built;
use cellstudio::models::{Model, ModelKind, PhysicsModel, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, consistent_initialisation, simulate};
use cellstudio::solver::jacobian::ColouredPattern;
use cellstudio::solver::{
    Dae, DenseOutput, SolverOptions, SolverStats, StopReason, Workspace, integrate,
};
use diffsol::{
    ConstantOp, FaerContext, FaerSparseLU, FaerSparseMat, FaerVec, LinearOp, Matrix, NonLinearOp,
    NonLinearOpJacobian, OdeBuilder, OdeEquations, OdeEquationsRef, OdeSolverMethod,
    OdeSolverProblem, OdeSolverStopReason, Op, ParameterisedOp, UnitCallable, Vector, VectorCommon,
};
use faer::sparse::{Pair, SymbolicSparseColMat};

type M = FaerSparseMat<f64>;
type V = FaerVec<f64>;
type LS = FaerSparseLU<f64>;
/// Sparsity type of `FaerSparseMat` (diffsol does not re-export its `MatrixSparsity` trait,
/// so the faer type is built directly).
type Sparsity = SymbolicSparseColMat<usize>;

/// Lower voltage cut-off (V).
const CUTOFF: f64 = 2.5;

/// The state of a (single-batch) faer vector as a slice.
fn slice(v: &V) -> &[f64] {
    v.inner()
        .col(0)
        .try_as_col_major()
        .expect("contiguous column")
        .as_slice()
}

/// The DFN as diffsol equations at a constant applied current.
struct DfnEqn {
    model: &'static dyn Model,
    /// Applied current (A, discharge positive).
    current: f64,
    y0: Vec<f64>,
    ctx: FaerContext,
    colouring: ColouredPattern,
    /// For each pattern entry, its position in the CSC values of `jac_sparsity`.
    csc_pos: Vec<usize>,
    jac_sparsity: Sparsity,
    mass_sparsity: Sparsity,
    /// Scratch: Jacobian values in pattern order, `f(y)`.
    jac_vals: std::cell::RefCell<Vec<f64>>,
    f0: std::cell::RefCell<Vec<f64>>,
    rhs_evals: Cell<usize>,
    jac_evals: Cell<usize>,
}

impl DfnEqn {
    fn new(model: &'static dyn Model, current: f64, y0: Vec<f64>) -> Self {
        let n = model.len();
        let mut entries = model.jacobian_pattern();
        entries.sort_unstable();
        entries.dedup();
        let pairs: Vec<Pair<usize, usize>> =
            entries.iter().map(|&(r, c)| Pair::new(r, c)).collect();
        let (jac_sparsity, _) =
            SymbolicSparseColMat::try_new_from_indices(n, n, &pairs).expect("Jacobian pattern");
        let csc_pos = entries
            .iter()
            .map(|&(r, c)| {
                let range = jac_sparsity.col_range(c);
                let start = range.start;
                start
                    + jac_sparsity.row_idx()[range]
                        .binary_search(&r)
                        .expect("entry in pattern")
            })
            .collect();
        let diag: Vec<Pair<usize, usize>> = (0..n).map(|i| Pair::new(i, i)).collect();
        let (mass_sparsity, _) =
            SymbolicSparseColMat::try_new_from_indices(n, n, &diag).expect("diagonal");
        let nnz = entries.len();
        Self {
            model,
            current,
            y0,
            ctx: FaerContext::default(),
            colouring: ColouredPattern::new(n, entries),
            csc_pos,
            jac_sparsity,
            mass_sparsity,
            jac_vals: std::cell::RefCell::new(vec![0.0; nnz]),
            f0: std::cell::RefCell::new(vec![0.0; n]),
            rhs_evals: Cell::new(0),
            jac_evals: Cell::new(0),
        }
    }

    fn rhs(&self, y: &[f64], out: &mut [f64]) {
        self.rhs_evals.set(self.rhs_evals.get() + 1);
        self.model.rhs(y, self.current, out);
    }
}

macro_rules! impl_op {
    ($ty:ty, $nout:expr) => {
        impl Op for $ty {
            type T = f64;
            type V = V;
            type M = M;
            type C = FaerContext;
            fn context(&self) -> &FaerContext {
                &self.eqn.ctx
            }
            fn nstates(&self) -> usize {
                self.eqn.model.len()
            }
            #[allow(clippy::redundant_closure_call)]
            fn nout(&self) -> usize {
                ($nout)(self)
            }
            fn nparams(&self) -> usize {
                0
            }
        }
    };
}

struct DfnRhs<'a> {
    eqn: &'a DfnEqn,
}
struct DfnMass<'a> {
    eqn: &'a DfnEqn,
}
struct DfnRoot<'a> {
    eqn: &'a DfnEqn,
}
struct DfnInit<'a> {
    eqn: &'a DfnEqn,
}
impl_op!(DfnRhs<'_>, |s: &DfnRhs| s.eqn.model.len());
impl_op!(DfnMass<'_>, |s: &DfnMass| s.eqn.model.len());
impl_op!(DfnRoot<'_>, |_s: &DfnRoot| 1);
impl_op!(DfnInit<'_>, |s: &DfnInit| s.eqn.model.len());

impl NonLinearOp for DfnRhs<'_> {
    fn call_inplace(&self, x: &V, _t: f64, y: &mut V) {
        y.for_each_batch_host([x], |y, [x], _| self.eqn.rhs(x, y));
    }
}

impl NonLinearOpJacobian for DfnRhs<'_> {
    /// One-sided directional difference `(f(x + h v) - f(x)) / h`.
    fn jac_mul_inplace(&self, x: &V, _t: f64, v: &V, y: &mut V) {
        let (xs, vs) = (slice(x), slice(v));
        let vnorm = vs.iter().map(|a| a * a).sum::<f64>().sqrt();
        if vnorm == 0.0 {
            y.fill(0.0);
            return;
        }
        let xnorm = xs.iter().map(|a| a * a).sum::<f64>().sqrt();
        let h = f64::EPSILON.sqrt() * xnorm.max(1.0) / vnorm;
        let xp: Vec<f64> = xs.iter().zip(vs).map(|(a, b)| a + h * b).collect();
        let mut f0 = vec![0.0; xs.len()];
        self.eqn.rhs(xs, &mut f0);
        y.for_each_batch_host([], |y, [], _| {
            self.eqn.rhs(&xp, y);
            for (yi, fi) in y.iter_mut().zip(&f0) {
                *yi = (*yi - fi) / h;
            }
        });
    }

    /// Coloured forward differences on the model's pattern, as in our integrator.
    fn jacobian_inplace(&self, x: &V, _t: f64, y: &mut M) {
        let eqn = self.eqn;
        eqn.jac_evals.set(eqn.jac_evals.get() + 1);
        let xs = slice(x);
        let mut f0 = eqn.f0.borrow_mut();
        let mut vals = eqn.jac_vals.borrow_mut();
        eqn.rhs(xs, &mut f0);
        let mut f = |yy: &[f64], out: &mut [f64]| eqn.rhs(yy, out);
        eqn.colouring
            .evaluate(&mut f, xs, &f0, eqn.model.scale(), &mut vals);
        let csc = y.inner_mut()[0].val_mut();
        assert_eq!(
            csc.len(),
            eqn.csc_pos.len(),
            "Jacobian matrix built on another pattern"
        );
        for (&pos, &v) in eqn.csc_pos.iter().zip(vals.iter()) {
            csc[pos] = v;
        }
    }

    fn jacobian_sparsity(&self) -> Option<Sparsity> {
        Some(self.eqn.jac_sparsity.clone())
    }
}

impl LinearOp for DfnMass<'_> {
    /// `y = diag(mass) x + beta y`.
    fn gemv_inplace(&self, x: &V, _t: f64, beta: f64, y: &mut V) {
        let mass = self.eqn.model.mass();
        y.for_each_batch_host([x], |y, [x], _| {
            for i in 0..y.len() {
                y[i] = mass[i] * x[i] + beta * y[i];
            }
        });
    }

    fn matrix_inplace(&self, _t: f64, y: &mut M) {
        // Diagonal pattern: the CSC value of column i is entry (i, i).
        let vals = y.inner_mut()[0].val_mut();
        vals.copy_from_slice(self.eqn.model.mass());
    }

    fn sparsity(&self) -> Option<Sparsity> {
        Some(self.eqn.mass_sparsity.clone())
    }
}

impl NonLinearOp for DfnRoot<'_> {
    fn call_inplace(&self, x: &V, _t: f64, y: &mut V) {
        let v = self.eqn.model.voltage(slice(x), self.eqn.current);
        y.set_index(0, v - CUTOFF);
    }
}

impl ConstantOp for DfnInit<'_> {
    fn call_inplace(&self, _t: f64, y: &mut V) {
        y.for_each_batch_host([], |y, [], _| y.copy_from_slice(&self.eqn.y0));
    }
}

impl Op for DfnEqn {
    type T = f64;
    type V = V;
    type M = M;
    type C = FaerContext;
    fn context(&self) -> &FaerContext {
        &self.ctx
    }
    fn nstates(&self) -> usize {
        self.model.len()
    }
    fn nout(&self) -> usize {
        self.model.len()
    }
    fn nparams(&self) -> usize {
        0
    }
}

impl<'a> OdeEquationsRef<'a> for DfnEqn {
    type Mass = DfnMass<'a>;
    type Rhs = DfnRhs<'a>;
    type Root = DfnRoot<'a>;
    type Init = DfnInit<'a>;
    type Out = ParameterisedOp<'a, UnitCallable<M>>;
    type Reset = ParameterisedOp<'a, UnitCallable<M>>;
}

impl OdeEquations for DfnEqn {
    fn rhs(&self) -> DfnRhs<'_> {
        DfnRhs { eqn: self }
    }
    fn mass(&self) -> Option<DfnMass<'_>> {
        Some(DfnMass { eqn: self })
    }
    fn root(&self) -> Option<DfnRoot<'_>> {
        Some(DfnRoot { eqn: self })
    }
    fn init(&self) -> DfnInit<'_> {
        DfnInit { eqn: self }
    }
    fn set_params(&mut self, _p: &V) {}
    fn get_params(&self, _p: &mut V) {}
}

/// Builds the diffsol problem (the "setup" we time for diffsol).
fn diffsol_problem(
    model: &'static dyn Model,
    current: f64,
    y0: Vec<f64>,
    rtol: f64,
    atol: f64,
) -> OdeSolverProblem<DfnEqn> {
    let eqn = DfnEqn::new(model, current, y0);
    let atol: Vec<f64> = model.scale().iter().map(|s| atol * s).collect();
    OdeBuilder::<M>::new()
        .rtol(rtol)
        .atol(atol)
        .build_from_eqn(eqn)
        .expect("diffsol problem")
}

/// Result of one diffsol discharge.
struct DiffsolRun {
    cutoff: Option<f64>,
    /// Voltages at the requested times.
    voltages: Vec<f64>,
    steps: usize,
    error_test_failures: usize,
    newton_iterations: usize,
    lu_setups: usize,
}

/// Consistent initialisation (diffsol's own) plus integration to the cut-off or `t_end`,
/// recording the voltage at `t_eval` (increasing) by the solver's interpolant.
fn diffsol_discharge(problem: &OdeSolverProblem<DfnEqn>, t_end: f64, t_eval: &[f64]) -> DiffsolRun {
    let eqn = &problem.eqn;
    let mut solver = problem.bdf::<LS>().expect("diffsol BDF state");
    solver.set_stop_time(t_end).expect("stop time");
    let mut voltages = Vec::with_capacity(t_eval.len());
    let mut next = 0;
    let cutoff = loop {
        let reason = solver.step().expect("diffsol step");
        let t = solver.state().t;
        let t_hi = match reason {
            OdeSolverStopReason::RootFound(tr, _) => tr,
            _ => t,
        };
        while next < t_eval.len() && t_eval[next] <= t_hi {
            let y = solver.interpolate(t_eval[next]).expect("interpolate");
            voltages.push(eqn.model.voltage(slice(&y), eqn.current));
            next += 1;
        }
        match reason {
            OdeSolverStopReason::InternalTimestep => {}
            OdeSolverStopReason::RootFound(tr, _) => break Some(tr),
            OdeSolverStopReason::TstopReached => break None,
        }
    };
    let s = solver.get_statistics();
    DiffsolRun {
        cutoff,
        voltages,
        steps: s.number_of_steps,
        error_test_failures: s.number_of_error_test_failures,
        newton_iterations: s.number_of_nonlinear_solver_iterations,
        lu_setups: s.number_of_linear_solver_setups,
    }
}

/// The DFN at constant current as our integrator's `Dae`.
struct OurDae {
    model: &'static dyn Model,
    current: f64,
}

impl Dae for OurDae {
    fn len(&self) -> usize {
        self.model.len()
    }
    fn mass(&self) -> &[f64] {
        self.model.mass()
    }
    fn scale(&self) -> &[f64] {
        self.model.scale()
    }
    fn rhs(&self, _t: f64, y: &[f64], out: &mut [f64]) {
        self.model.rhs(y, self.current, out)
    }
}

/// Our integrator alone, like `diffsol_discharge` with no output: consistent
/// initialisation, then `solver::integrate` with the cut-off event and an observer that does
/// nothing (no voltage/energy recording, unlike `simulate`). Returns the cut-off time.
fn our_bare_discharge(
    dae: &OurDae,
    ws: &mut Workspace,
    opts: &SolverOptions,
    y0: &[f64],
    t_end: f64,
    stats: &mut SolverStats,
) -> Option<f64> {
    let mut y = y0.to_vec();
    consistent_initialisation(dae.model, ws, dae.current, &mut y)
        .expect("consistent initialisation");
    let event = |_t: f64, yy: &[f64]| dae.model.voltage(yy, dae.current) - CUTOFF;
    let mut observer = |_t_old: f64, _dense: &DenseOutput| {};
    match integrate(
        dae,
        ws,
        opts,
        0.0,
        &mut y,
        t_end,
        Some(&event),
        &mut observer,
        stats,
    )
    .expect("our integrate")
    {
        StopReason::Event(t) => Some(t),
        StopReason::EndTime => None,
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(10);
    let p = chen2020();
    let protocol = Protocol::discharge(1.0);
    let opts = SimOptions::for_cell(&p);
    assert_eq!(opts.cutoffs.0, CUTOFF, "chen2020 lower cut-off");
    let current = p.cell.nominal_capacity; // 1C
    let t_end = protocol.duration();
    let (rtol, atol) = (opts.solver.rtol, opts.solver.atol);

    // One build, leaked so diffsol's equations can hold `&'static dyn Model`; both solvers
    // run on this same model.
    let builder: &'static mut ModelBuilder = Box::leak(Box::new(ModelBuilder::new(
        ModelKind::Dfn,
        Submodels::default(),
        MeshSizes::default(),
    )));
    let built = builder.build(&p).expect("DFN build");
    let Built {
        model, workspace, ..
    } = built;
    let model: &'static Box<dyn PhysicsModel> = model;
    let model: &'static dyn Model = &**model;
    let n = model.len();

    // Consistent start for diffsol (our `simulate` does the same at its step start).
    let mut y0 = model.initial_state();
    consistent_initialisation(model, workspace, current, &mut y0)
        .expect("consistent initialisation");

    // ---- agreement --------------------------------------------------------------------
    let ours = simulate(model, workspace, &protocol, &opts, None).expect("our discharge");
    let t_cut_ours = *ours
        .cutoff_times
        .first()
        .expect("our run reaches the cut-off");
    let t_eval: Vec<f64> = (0..20)
        .map(|k| t_cut_ours * (0.5 + k as f64) / 20.0 * 0.999)
        .collect();
    let ours_at = simulate(
        model,
        workspace,
        &protocol,
        &SimOptions {
            t_eval: Some(t_eval.clone()),
            ..opts.clone()
        },
        None,
    )
    .expect("our discharge at t_eval");
    let problem = diffsol_problem(model, current, y0.clone(), rtol, atol);
    let theirs = diffsol_discharge(&problem, t_end, &t_eval);
    let t_cut_theirs = theirs.cutoff.expect("diffsol run reaches the cut-off");
    assert_eq!(ours_at.voltage.len(), t_eval.len());
    assert_eq!(theirs.voltages.len(), t_eval.len());
    let dv = ours_at
        .voltage
        .iter()
        .zip(&theirs.voltages)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let dt = (t_cut_ours - t_cut_theirs).abs();
    println!("DFN, {n} states, 1C = {current} A, rtol = {rtol}, atol = {atol} x scale");
    println!(
        "cut-off: ours {t_cut_ours:.3} s, diffsol {t_cut_theirs:.3} s (|diff| = {dt:.3} s); \
         max |V_ours - V_diffsol| at 20 times = {:.3} mV",
        dv * 1e3
    );
    assert!(dv < 1e-3, "voltages differ by {dv} V");
    assert!(dt < 1.0, "cut-off times differ by {dt} s");

    // ---- timing (the three solvers interleaved in each repeat, so load drift hits all) -----
    let dae = OurDae { model, current };
    let y_start = model.initial_state();
    let mut our_setup = Vec::new();
    let mut our_solve = Vec::new();
    let mut our_stats = ours.stats;
    let mut bare_solve = Vec::new();
    let mut bare_stats = SolverStats::default();
    let mut ds_setup = Vec::new();
    let mut ds_solve = Vec::new();
    let mut ds_run = None;
    let mut ds_counts = (0, 0);
    for k in 0..repeats {
        let t = Instant::now();
        let ws = Workspace::new(n, model.jacobian_pattern()).expect("workspace");
        our_setup.push(t.elapsed().as_secs_f64());
        drop(ws);
        let t = Instant::now();
        let sol = simulate(model, workspace, &protocol, &opts, None).expect("our discharge");
        our_solve.push(t.elapsed().as_secs_f64());
        our_stats = sol.stats;

        let mut stats = SolverStats::default();
        let t = Instant::now();
        let t_cut = our_bare_discharge(&dae, workspace, &opts.solver, &y_start, t_end, &mut stats);
        bare_solve.push(t.elapsed().as_secs_f64());
        if k == 0 {
            let t_cut = t_cut.expect("bare run reaches the cut-off");
            assert!(
                (t_cut - t_cut_ours).abs() < 1e-6,
                "bare integrate cut-off {t_cut} s vs simulate {t_cut_ours} s"
            );
        }
        bare_stats = stats;

        let t = Instant::now();
        let problem = diffsol_problem(model, current, y0.clone(), rtol, atol);
        ds_setup.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        let run = diffsol_discharge(&problem, t_end, &[]);
        ds_solve.push(t.elapsed().as_secs_f64());
        ds_counts = (problem.eqn.jac_evals.get(), problem.eqn.rhs_evals.get());
        ds_run = Some(run);
    }
    let run = ds_run.expect("repeats >= 1");

    println!();
    println!(
        "| solver | 1C DFN discharge (ms, median of {repeats}) | setup (ms) | steps | rejected | Newton its | Jacobian evals | LU factorisations | rhs evals |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    println!(
        "| cellstudio `simulate` (records V, Q, E each step) | {:.2} | {:.3} | {} | {} | - | {} | {} | {} |",
        median(our_solve.clone()) * 1e3,
        median(our_setup.clone()) * 1e3,
        our_stats.steps,
        our_stats.rejected_steps,
        our_stats.jacobian_evals,
        our_stats.factorisations,
        our_stats.rhs_evals
    );
    println!(
        "| cellstudio `solver::integrate` (no recording) | {:.2} | {:.3} | {} | {} | - | {} | {} | {} |",
        median(bare_solve.clone()) * 1e3,
        median(our_setup.clone()) * 1e3,
        bare_stats.steps,
        bare_stats.rejected_steps,
        bare_stats.jacobian_evals,
        bare_stats.factorisations,
        bare_stats.rhs_evals
    );
    println!(
        "| diffsol 0.18 BDF (FaerSparseLU) | {:.2} | {:.3} | {} | {} | {} | {} | {} | {} |",
        median(ds_solve.clone()) * 1e3,
        median(ds_setup) * 1e3,
        run.steps,
        run.error_test_failures,
        run.newton_iterations,
        ds_counts.0,
        run.lu_setups,
        ds_counts.1
    );
    println!();
    let b = median(ds_solve);
    for (what, a) in [
        ("simulate", median(our_solve)),
        ("solver::integrate", median(bare_solve)),
    ] {
        if a < b {
            println!(
                "cellstudio {what} is {:.2}x faster than diffsol per discharge",
                b / a
            );
        } else {
            println!(
                "diffsol is {:.2}x faster than cellstudio {what} per discharge",
                a / b
            );
        }
    }
}
