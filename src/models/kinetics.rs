//! Butler-Volmer kinetics and Arrhenius temperature dependence.

use crate::params::{FARADAY, GAS_CONSTANT};

/// Arrhenius factor `exp(E / R (1/T_ref - 1/T))` for activation energy `e` (J/mol).
pub fn arrhenius(e: f64, t_ref: f64, t: f64) -> f64 {
    if e == 0.0 { 1.0 } else { (e / GAS_CONSTANT * (1.0 / t_ref - 1.0 / t)).exp() }
}

/// Exchange-current density `j0 = k c_e^0.5 c_s^0.5 (c_max - c_s)^0.5` (A/m^2), with rate
/// constant `k` (A/m^2 (m^3/mol)^1.5) already temperature-corrected. Concentrations are
/// clamped at zero so that a Newton iterate outside the physical range stays finite.
pub fn exchange_current(k: f64, c_e: f64, c_s: f64, c_max: f64) -> f64 {
    k * (c_e.max(0.0) * c_s.max(0.0) * (c_max - c_s).max(0.0)).sqrt()
}

/// Symmetric Butler-Volmer interfacial current density `2 j0 sinh(alpha F eta / (R T))`
/// (A/m^2) for overpotential `eta` (V).
pub fn butler_volmer(j0: f64, eta: f64, alpha: f64, t: f64) -> f64 {
    2.0 * j0 * (alpha * FARADAY * eta / (GAS_CONSTANT * t)).sinh()
}

/// Overpotential (V) that drives interfacial current density `j` (A/m^2): the inverse of
/// [`butler_volmer`].
pub fn overpotential(j: f64, j0: f64, alpha: f64, t: f64) -> f64 {
    GAS_CONSTANT * t / (alpha * FARADAY) * asinh(j / (2.0 * j0))
}

/// `asinh(x) = sign(x) ln(|x| + sqrt(x^2 + 1))`: std's version goes through `hypot` and
/// `log1p` and is several times slower; for the |x| range of kinetics (< 1e6) this form is
/// accurate to a few ulp.
fn asinh(x: f64) -> f64 {
    let a = x.abs();
    let r = if a < 1e-3 {
        // Taylor series avoids cancellation near zero.
        a * (1.0 - a * a / 6.0)
    } else {
        (a + (a * a + 1.0).sqrt()).ln()
    };
    r.copysign(x)
}

#[cfg(test)]
mod tests {
    #[test]
    fn fast_asinh_matches_std() {
        for k in -600..=600 {
            let x = (k as f64 * 0.03).sinh() * 1.7;
            let (a, b) = (super::asinh(x), x.asinh());
            assert!((a - b).abs() <= 1e-14 * b.abs().max(1e-300) + 1e-300, "x = {x}: {a} vs {b}");
        }
    }
}
