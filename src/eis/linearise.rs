//! Linearisation of a model about a rest state: `M dy' = J dy + B dI`, `dV = C dy + D dI`.
//!
//! Every derivative is a central finite difference taken column by column over all states,
//! so couplings a model's `jacobian_pattern` leaves out (weak dense ones) are kept too.

use crate::error::Error;
use crate::models::Model;
use crate::simulation::consistent_initialisation;
use crate::solver::Workspace;

/// Current step (A) of the central differences in the applied current.
const CURRENT_STEP: f64 = 1e-3;

/// Largest `|f_i| / scale_i` (1/s) a differential row may have for the state to count as
/// rest.
const REST_TOLERANCE: f64 = 1e-9;

/// The linearised model about a state `y0` at zero current.
#[derive(Clone, Debug)]
pub struct Linearisation {
    /// Number of states.
    pub n: usize,
    /// Mass-matrix diagonal (1 differential, 0 algebraic).
    pub mass: Vec<f64>,
    /// Non-zero entries `(row, col, df_row/dy_col)` of the Jacobian `J = df/dy`, column-major
    /// order (units: those of `f` over those of `y`).
    pub jacobian: Vec<(usize, usize, f64)>,
    /// `B = df/dI` (units of `f` per A).
    pub b: Vec<f64>,
    /// `C = dV/dy` (V per unit of each state).
    pub c: Vec<f64>,
    /// `D = dV/dI` (ohm).
    pub d: f64,
}

/// The rest state of `model` at its initial concentrations: the initial state with the
/// algebraic states made consistent at zero current. Errors if the differential states are
/// not at rest there (e.g. a cell temperature away from the ambient).
pub fn rest_state(model: &dyn Model, ws: &mut Workspace) -> Result<Vec<f64>, Error> {
    let mut y = model.initial_state();
    consistent_initialisation(model, ws, 0.0, &mut y)?;
    let mut f = vec![0.0; y.len()];
    model.rhs(&y, 0.0, &mut f);
    let (mass, scale) = (model.mass(), model.scale());
    for i in 0..y.len() {
        let rate = (f[i] / scale[i]).abs();
        if mass[i] != 0.0 && !(rate <= REST_TOLERANCE) {
            return Err(Error::Solver {
                t: 0.0,
                reason: format!("the initial state is not at rest: state {i} changes at {rate:.3e} of its scale per second"),
            });
        }
    }
    Ok(y)
}

/// Step of the central difference in state `j`: `cbrt(eps) * max(|y_j|, scale_j)`, which
/// balances truncation (`h^2`) against rounding (`eps / h`).
fn state_step(y: f64, scale: f64) -> f64 {
    f64::EPSILON.cbrt() * y.abs().max(scale)
}

/// Linearises `model` about `y0` at zero current by central differences.
pub fn linearise(model: &dyn Model, y0: &[f64]) -> Result<Linearisation, Error> {
    let n = model.len();
    if y0.len() != n {
        return Err(Error::InvalidSetting {
            field: "y0".into(),
            reason: format!("state has {} entries, the model {n}", y0.len()),
        });
    }
    let scale = model.scale();
    let mut y = y0.to_vec();
    let (mut fp, mut fm) = (vec![0.0; n], vec![0.0; n]);
    let mut jacobian = Vec::new();
    let mut c = vec![0.0; n];
    for j in 0..n {
        let h = state_step(y0[j], scale[j]);
        y[j] = y0[j] + h;
        model.rhs(&y, 0.0, &mut fp);
        let vp = model.voltage(&y, 0.0);
        y[j] = y0[j] - h;
        model.rhs(&y, 0.0, &mut fm);
        let vm = model.voltage(&y, 0.0);
        y[j] = y0[j];
        for i in 0..n {
            let v = (fp[i] - fm[i]) / (2.0 * h);
            if v != 0.0 {
                jacobian.push((i, j, v));
            }
        }
        c[j] = (vp - vm) / (2.0 * h);
    }
    model.rhs(y0, CURRENT_STEP, &mut fp);
    model.rhs(y0, -CURRENT_STEP, &mut fm);
    let b: Vec<f64> = fp.iter().zip(&fm).map(|(p, m)| (p - m) / (2.0 * CURRENT_STEP)).collect();
    let d = (model.voltage(y0, CURRENT_STEP) - model.voltage(y0, -CURRENT_STEP)) / (2.0 * CURRENT_STEP);
    let finite = jacobian.iter().all(|e| e.2.is_finite())
        && b.iter().chain(&c).all(|v| v.is_finite())
        && d.is_finite();
    if !finite {
        return Err(Error::Solver { t: 0.0, reason: "non-finite derivative in the linearisation".into() });
    }
    Ok(Linearisation { n, mass: model.mass().to_vec(), jacobian, b, c, d })
}
