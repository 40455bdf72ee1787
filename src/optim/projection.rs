//! Linear constraints and the projection onto {bounds, A_eq x = b_eq, A_in x <= b_in}, solved
//! as a quadratic programme with Clarabel.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};
use serde::{Deserialize, Serialize};

use super::Bounds;
use crate::linalg::dot;
use crate::error::{Error, Result};

/// Linear constraints in model space: `a·x = b` (equalities) and `a·x <= b` (inequalities).
///
/// ```
/// use cellstudio::optim::{Bounds, LinearConstraints};
///
/// let simplex = LinearConstraints::new().equality(vec![1.0, 1.0, 1.0], 1.0);
/// let bounds = Bounds::new(vec![0.0; 3], vec![1.0; 3]).unwrap();
/// let y = simplex.project(&[0.9, 0.6, -0.4], &bounds).unwrap();
/// for (yi, ei) in y.iter().zip([0.65, 0.35, 0.0]) {
///     assert!((yi - ei).abs() < 1e-7);
/// }
/// ```
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LinearConstraints {
    /// `(a, b)` meaning `a·x = b`.
    pub equalities: Vec<(Vec<f64>, f64)>,
    /// `(a, b)` meaning `a·x <= b`.
    pub inequalities: Vec<(Vec<f64>, f64)>,
}

fn constraint_error(reason: String) -> Error {
    Error::InvalidSetting { field: "linear_constraints".into(), reason }
}

/// `2·x[0] - x[1] = 3`-style description of one constraint.
fn describe(a: &[f64], b: f64, op: &str) -> String {
    let mut s = String::new();
    for (i, &c) in a.iter().enumerate() {
        if c == 0.0 {
            continue;
        }
        let sign = if c < 0.0 { "-" } else { "+" };
        if s.is_empty() {
            if c < 0.0 {
                s.push('-');
            }
        } else {
            s.push_str(&format!(" {sign} "));
        }
        if c.abs() != 1.0 {
            s.push_str(&format!("{}·", c.abs()));
        }
        s.push_str(&format!("x[{i}]"));
    }
    if s.is_empty() {
        s.push('0');
    }
    format!("{s} {op} {b}")
}

/// Constraint matrix rows in triplet form, columns scaled by `s`.
#[derive(Default)]
struct Triplets {
    rows: Vec<usize>,
    cols: Vec<usize>,
    vals: Vec<f64>,
    rhs: Vec<f64>,
}

impl Triplets {
    fn push(&mut self, coefficients: impl Iterator<Item = (usize, f64)>, b: f64, s: &[f64]) {
        let row = self.rhs.len();
        for (i, c) in coefficients {
            if c != 0.0 {
                self.rows.push(row);
                self.cols.push(i);
                self.vals.push(c * s[i]);
            }
        }
        self.rhs.push(b);
    }
}

impl LinearConstraints {
    pub fn new() -> Self {
        Self::default()
    }
    /// Adds `a·x = b`.
    pub fn equality(mut self, a: Vec<f64>, b: f64) -> Self {
        self.equalities.push((a, b));
        self
    }
    /// Adds `a·x <= b`.
    pub fn inequality(mut self, a: Vec<f64>, b: f64) -> Self {
        self.inequalities.push((a, b));
        self
    }
    pub fn is_empty(&self) -> bool {
        self.equalities.is_empty() && self.inequalities.is_empty()
    }

    /// Human-readable list of all constraints, e.g. for error messages.
    pub fn describe(&self) -> Vec<String> {
        let eq =
            self.equalities.iter().enumerate().map(|(k, (a, b))| format!("equality {k} ({})", describe(a, *b, "=")));
        let ineq = self
            .inequalities
            .iter()
            .enumerate()
            .map(|(k, (a, b))| format!("inequality {k} ({})", describe(a, *b, "<=")));
        eq.chain(ineq).collect()
    }

    /// Coefficient vectors have `dim` entries; all numbers finite.
    pub fn validate(&self, dim: usize) -> Result<()> {
        for (kind, list) in [("equality", &self.equalities), ("inequality", &self.inequalities)] {
            for (k, (a, b)) in list.iter().enumerate() {
                if a.len() != dim {
                    return Err(constraint_error(format!(
                        "{kind} {k} has {} coefficients for {dim} variables",
                        a.len()
                    )));
                }
                if !b.is_finite() || a.iter().any(|v| !v.is_finite()) {
                    return Err(constraint_error(format!(
                        "{kind} {k} has a non-finite coefficient or right-hand side"
                    )));
                }
            }
        }
        Ok(())
    }

    /// Whether `x` satisfies every constraint to relative tolerance `tol`
    /// (`|a·x - b| <= tol·(1 + |b| + Σ|a_i x_i|)`). Bounds are not checked.
    pub fn is_satisfied(&self, x: &[f64], tol: f64) -> bool {
        let slack =
            |a: &[f64], b: f64| tol * (1.0 + b.abs() + a.iter().zip(x).map(|(a, x)| (a * x).abs()).sum::<f64>());
        self.equalities.iter().all(|(a, b)| (dot(a, x) - b).abs() <= slack(a, *b))
            && self.inequalities.iter().all(|(a, b)| dot(a, x) - b <= slack(a, *b))
    }

    /// Reports an empty feasible set before any search. Constraints that cannot hold anywhere
    /// in the box are named individually (with the range their left side takes); otherwise a
    /// Clarabel infeasibility certificate names the whole set.
    pub fn check_feasible(&self, bounds: &Bounds) -> Result<()> {
        self.validate(bounds.dim())?;
        let mut problems = Vec::new();
        let range = |a: &[f64]| {
            let (mut lo, mut hi) = (0.0, 0.0);
            for (i, &c) in a.iter().enumerate() {
                if c > 0.0 {
                    lo += c * bounds.lower()[i];
                    hi += c * bounds.upper()[i];
                } else if c < 0.0 {
                    lo += c * bounds.upper()[i];
                    hi += c * bounds.lower()[i];
                }
            }
            (lo, hi)
        };
        for (k, (a, b)) in self.equalities.iter().enumerate() {
            let (lo, hi) = range(a);
            let tol = 1e-9 * (1.0 + b.abs());
            if *b < lo - tol || *b > hi + tol {
                problems.push(format!(
                    "equality {k} ({}) cannot hold within the bounds, where its left side ranges over [{lo}, {hi}]",
                    describe(a, *b, "=")
                ));
            }
        }
        for (k, (a, b)) in self.inequalities.iter().enumerate() {
            let (lo, _) = range(a);
            if lo > b + 1e-9 * (1.0 + b.abs()) {
                problems.push(format!(
                    "inequality {k} ({}) cannot hold within the bounds, where its left side is at least {lo}",
                    describe(a, *b, "<=")
                ));
            }
        }
        if !problems.is_empty() {
            return Err(constraint_error(format!("infeasible constraint set: {}", problems.join("; "))));
        }
        if self.is_empty() {
            return Ok(());
        }
        let start: Vec<f64> = (0..bounds.dim())
            .map(|i| {
                let (l, u) = (bounds.lower()[i], bounds.upper()[i]);
                match (l.is_finite(), u.is_finite()) {
                    (true, true) => 0.5 * (l + u),
                    (true, false) => l,
                    (false, true) => u,
                    (false, false) => 0.0,
                }
            })
            .collect();
        self.project(&start, bounds).map(|_| ())
    }

    /// Euclidean projection of `x` onto {bounds, equalities, inequalities}:
    /// `argmin_y 0.5·||y - x||²`. Infinite bounds are omitted. The QP is solved in units of
    /// the largest finite bound range (a uniform rescaling that leaves the minimiser unchanged
    /// but keeps Clarabel's absolute tolerances meaningful for small or large variables).
    pub fn project(&self, x: &[f64], bounds: &Bounds) -> Result<Vec<f64>> {
        self.validate(bounds.dim())?;
        if x.len() != bounds.dim() {
            return Err(constraint_error(format!("point has {} entries for {} variables", x.len(), bounds.dim())));
        }
        let widest = (0..bounds.dim()).map(|i| bounds.range(i)).filter(|r| r.is_finite()).fold(0.0, f64::max);
        let s = if widest > 0.0 { widest } else { x.iter().fold(1.0, |m: f64, v| m.max(v.abs())) };
        self.project_scaled(x, bounds, &vec![s; bounds.dim()])
    }

    /// Projection in the metric `Σ ((y_i - x_i) / s_i)²`: the QP is solved for `w = y / s`,
    /// and the result is clamped onto the bounds exactly.
    pub(crate) fn project_scaled(&self, x: &[f64], bounds: &Bounds, s: &[f64]) -> Result<Vec<f64>> {
        let n = x.len();
        let xi: Vec<f64> = (0..n).map(|i| x[i] / s[i]).collect();
        if xi.iter().any(|v| !v.is_finite()) {
            return Err(constraint_error(format!("cannot project a non-finite point {x:?}")));
        }
        let mut t = Triplets::default();
        for (a, b) in &self.equalities {
            t.push(a.iter().copied().enumerate(), *b, s);
        }
        let n_eq = t.rhs.len();
        for (a, b) in &self.inequalities {
            t.push(a.iter().copied().enumerate(), *b, s);
        }
        for i in 0..n {
            if bounds.upper()[i].is_finite() {
                t.push([(i, 1.0)].into_iter(), bounds.upper()[i], s);
            }
            if bounds.lower()[i].is_finite() {
                t.push([(i, -1.0)].into_iter(), -bounds.lower()[i], s);
            }
        }
        let m = t.rhs.len();
        if m == 0 {
            return Ok(x.to_vec());
        }
        let Triplets { rows, cols, vals, rhs } = t;
        let a = CscMatrix::new_from_triplets(m, n, rows, cols, vals);
        let p = CscMatrix::identity(n);
        let q: Vec<f64> = xi.iter().map(|v| -v).collect();
        let mut cones = Vec::new();
        if n_eq > 0 {
            cones.push(SupportedConeT::ZeroConeT(n_eq));
        }
        if m > n_eq {
            cones.push(SupportedConeT::NonnegativeConeT(m - n_eq));
        }
        let settings = DefaultSettings {
            verbose: false,
            tol_gap_abs: 1e-11,
            tol_gap_rel: 1e-11,
            tol_feas: 1e-11,
            max_iter: 100,
            ..DefaultSettings::default()
        };
        let mut solver = DefaultSolver::new(&p, &q, &a, &rhs, &cones, settings)
            .map_err(|e| Error::Linear(format!("projection QP setup: {e}")))?;
        solver.solve();
        match solver.solution.status {
            SolverStatus::Solved | SolverStatus::AlmostSolved => {
                let y: Vec<f64> = solver.solution.x.iter().zip(s).map(|(w, s)| w * s).collect();
                Ok(bounds.clamp(&y))
            }
            SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => Err(constraint_error(format!(
                "infeasible constraint set: no point satisfies all of {} together with the bounds \
                 (Clarabel status {:?})",
                self.describe().join(", "),
                solver.solution.status
            ))),
            status => Err(Error::Linear(format!("projection QP failed: Clarabel status {status:?}"))),
        }
    }
}
