//! Butler-Volmer kinetics and Arrhenius temperature dependence.

use crate::params::{FARADAY, GAS_CONSTANT};

/// Arrhenius factor `exp(E / R (1/T_ref - 1/T))` for activation energy `e` (J/mol); exactly 1
/// without an exponential at the reference temperature (an isothermal cell at 25 degC).
pub fn arrhenius(e: f64, t_ref: f64, t: f64) -> f64 {
    if e == 0.0 || t == t_ref { 1.0 } else { (e / GAS_CONSTANT * (1.0 / t_ref - 1.0 / t)).exp() }
}

/// Regularisation width of the square roots in [`exchange_current`] (-), PyBaMM 26's
/// `reg_power` tolerance.
pub const SQRT_REGULARISATION: f64 = 1e-3;

/// Exchange-current density (A/m^2): `j0 = k c_e^0.5 c_s^0.5 (c_max - c_s)^0.5` with each
/// square root regularised as PyBaMM 26 does (`RegPower`): `sqrt(x)` becomes
/// `x (x^2 + (delta s)^2)^(-1/4)` with `delta` = [`SQRT_REGULARISATION`] and scale `s` =
/// `c_e_ref` (mol/m^3, the initial electrolyte concentration) for `c_e` and `c_max`
/// (mol/m^3) for the two particle factors. The relative change is about
/// `delta^2 s^2 / (4 x^2)` per factor: 2.6e-5 at stoichiometry 0.9, 2e-6 at 0.5; the
/// derivative stays finite at an empty or full particle. The rate constant `k`
/// (A/m^2 (m^3/mol)^1.5) is already temperature-corrected. Concentrations are clamped to
/// `c_e >= 0` and `0 <= c_s <= c_max`, as PyBaMM does before the regularisation.
pub fn exchange_current(k: f64, c_e: f64, c_e_ref: f64, c_s: f64, c_max: f64) -> f64 {
    let c_s = c_s.clamp(0.0, c_max);
    k * electrolyte_factor(c_e, c_e_ref) * particle_factor(c_s, c_max)
}

/// The regularised `c_e^0.5` (mol/m^3)^0.5 of [`exchange_current`].
pub fn electrolyte_factor(c_e: f64, c_e_ref: f64) -> f64 {
    reg_sqrt(c_e.max(0.0), SQRT_REGULARISATION * c_e_ref)
}

/// The regularised `c_s^0.5 (c_max - c_s)^0.5` (mol/m^3) of [`exchange_current`], for
/// `0 <= c_s <= c_max`.
pub fn particle_factor(c_s: f64, c_max: f64) -> f64 {
    let (a, b, d) = (c_s, c_max - c_s, SQRT_REGULARISATION * c_max);
    a * b / ((a * a + d * d) * (b * b + d * d)).sqrt().sqrt()
}

/// `x (x^2 + d^2)^(-1/4)`: `sqrt(x)` for `x >> d`, linear below `d`.
fn reg_sqrt(x: f64, d: f64) -> f64 {
    x / (x * x + d * d).sqrt().sqrt()
}

/// Butler-Volmer interfacial current density (A/m^2) for overpotential `eta` (V), PyBaMM's
/// asymmetric form `j0 (exp(alpha F eta / R T) - exp(-(1 - alpha) F eta / R T))` with the
/// anodic charge-transfer coefficient `alpha` (-). At `alpha` = 0.5 (the default) it is the
/// symmetric `2 j0 sinh(F eta / 2 R T)`, evaluated as such (PyBaMM's symmetric Butler-Volmer).
pub fn butler_volmer(j0: f64, eta: f64, alpha: f64, t: f64) -> f64 {
    if alpha == 0.5 {
        return 2.0 * j0 * sinh(alpha * FARADAY * eta / (GAS_CONSTANT * t));
    }
    let f = FARADAY / (GAS_CONSTANT * t);
    // expm1: no cancellation at small overpotentials
    j0 * ((alpha * f * eta).exp_m1() - (-(1.0 - alpha) * f * eta).exp_m1())
}

/// Overpotential (V) that drives interfacial current density `j` (A/m^2): the inverse of
/// [`butler_volmer`], in closed form (`asinh`) at `alpha` = 0.5, else by
/// [`asymmetric_inverse`].
pub fn overpotential(j: f64, j0: f64, alpha: f64, t: f64) -> f64 {
    if alpha == 0.5 {
        return GAS_CONSTANT * t / (alpha * FARADAY) * asinh(j / (2.0 * j0));
    }
    // A cathodic current is the anodic one with the coefficients swapped.
    let x = if j >= 0.0 { asymmetric_inverse(j / j0, alpha) } else { -asymmetric_inverse(-j / j0, 1.0 - alpha) };
    GAS_CONSTANT * t / FARADAY * x
}

/// The `x >= 0` (-) at which `exp(a x) - exp(-(1 - a) x) = r` for `r >= 0` and `0 < a < 1`:
/// [`bracketed_newton`] inside the bracket `[0, ln(1 + r) / a]`, to round-off, on that
/// equation written with `expm1` below `r = 1` (no cancellation at small currents) and on its
/// logarithm `a x - ln(r + exp(-(1 - a) x)) = 0` above (slope within `[a, 1]`). NaN for a NaN
/// `r`, infinite for an infinite one.
fn asymmetric_inverse(r: f64, a: f64) -> f64 {
    if r == 0.0 || !r.is_finite() {
        return if r.is_nan() { f64::NAN } else if r == 0.0 { 0.0 } else { f64::INFINITY };
    }
    let b = 1.0 - a;
    let residual = |x: f64| -> (f64, f64) {
        if r < 1.0 {
            ((a * x).exp_m1() - (-b * x).exp_m1() - r, a * (a * x).exp() + b * (-b * x).exp())
        } else {
            let e = (-b * x).exp();
            (a * x - (r + e).ln(), a + b * e / (r + e))
        }
    };
    let hi = r.ln_1p() / a;
    // The symmetric inverse as the first guess.
    let x = (2.0 * asinh(0.5 * r)).clamp(0.0, hi);
    bracketed_newton(x, (0.0, hi), 100, residual, |step, width, x| step <= 1e-15 * x || width <= 1e-15 * x)
}

/// Newton's method from `x` on `f` (the residual and its slope at a point; increasing in `x`),
/// kept inside `bracket`, which holds the root: a step that would leave the bracket, narrowed
/// at each iterate by the residual's sign, bisects it instead. Stops after `iterations` or
/// once `done(step, bracket width, new iterate)`.
fn bracketed_newton(mut x: f64, (mut lo, mut hi): (f64, f64), iterations: usize, f: impl Fn(f64) -> (f64, f64), done: impl Fn(f64, f64, f64) -> bool) -> f64 {
    for _ in 0..iterations {
        let (g, slope) = f(x);
        if g > 0.0 { hi = x } else { lo = x }
        let mut next = x - g / slope;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let step = (next - x).abs();
        x = next;
        if done(step, hi - lo, x) {
            break;
        }
    }
    x
}

/// The potential difference `delta = phi_s - phi_e` (V) shared by parallel particle classes
/// with fractions `weights` (-, summing to 1), exchange-current densities `j0` (A/m^2) and
/// open-circuit potentials `ocp` (V) such that their weighted Butler-Volmer currents
/// `j_i` = [`butler_volmer`]`(j0_i, delta - U_i, alpha, T)` add up to `j` (A/m^2):
/// `sum w_i j_i = j`. Writes each `j_i` into `currents`.
///
/// Newton's method kept inside a bracket ([`bracketed_newton`]): with `jbar0 = sum w_i j0_i` and `eta0` the
/// overpotential that drives `j` through `jbar0`, the root lies between `min U_i + eta0` and
/// `max U_i + eta0` (every term increases with `delta`). It iterates to round-off, so that
/// finite differences of the result are clean. NaN when every `j0` is zero.
pub fn shared_potential(weights: &[f64], j0: &[f64], ocp: &[f64], j: f64, alpha: f64, t: f64, currents: &mut [f64]) -> f64 {
    let (ka, kc) = (alpha * FARADAY / (GAS_CONSTANT * t), (1.0 - alpha) * FARADAY / (GAS_CONSTANT * t));
    let jbar0: f64 = weights.iter().zip(j0).map(|(w, j0)| w * j0).sum();
    let eta0 = overpotential(j, jbar0, alpha, t);
    let (u_min, u_max) = ocp.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &u| (a.min(u), b.max(u)));
    let bracket = (u_min + eta0, u_max + eta0);
    let delta = weights.iter().zip(j0).zip(ocp).map(|((w, j0), u)| w * j0 * u).sum::<f64>() / jbar0 + eta0;
    if !delta.is_finite() {
        currents.fill(f64::NAN);
        return f64::NAN;
    }
    let residual = |delta: f64| {
        let (mut g, mut dg) = (-j, 0.0);
        for ((w, j0), u) in weights.iter().zip(j0).zip(ocp) {
            let e = (ka * (delta - u)).exp();
            if alpha == 0.5 {
                g += w * j0 * (e - 1.0 / e);
                dg += w * j0 * ka * (e + 1.0 / e);
            } else {
                let c = (-kc * (delta - u)).exp();
                g += w * j0 * (e - c);
                dg += w * j0 * (ka * e + kc * c);
            }
        }
        (g, dg)
    };
    let delta = bracketed_newton(delta, bracket, 200, residual, |step, width, x| step <= 1e-14 * x.abs().max(1.0) || width <= 1e-15 * x.abs().max(1.0));
    for ((c, j0), u) in currents.iter_mut().zip(j0).zip(ocp) {
        *c = butler_volmer(*j0, delta - u, alpha, t);
    }
    delta
}

/// Mean of [`overpotential`]`(j, j0_k, alpha, t)` over an electrode's volumes, whose
/// exchange-current densities are `j0_k = j0_particle * electrolyte_factor(c_e[k], c_e_ref)`
/// (`j0_particle` in A/m^2 (m^3/mol)^0.5, the particle part times the rate constant;
/// concentrations in mol/m^3). All terms share the sign of `j`, and with `A = |j| / (2
/// j0_particle)` and the factor's square `f_k^2 = c_k^2 / sqrt(c_k^2 + d^2)` each
/// `asinh(|j| / 2 j0_k)` is `ln(A + sqrt(A^2 + f_k^2)) - ln(f_k^2) / 2`: two square roots and
/// a division per volume, in four SIMD lanes, and two logarithms per call (at `alpha` = 0.5;
/// otherwise the mean of the inverses one by one).
pub fn mean_overpotential(j: f64, j0_particle: f64, c_e: &[f64], c_e_ref: f64, alpha: f64, t: f64) -> f64 {
    use wide::f64x4;
    if alpha != 0.5 {
        // No closed form: the mean of the inverses, term by term.
        return c_e.iter().map(|&c| overpotential(j, j0_particle * electrolyte_factor(c, c_e_ref), alpha, t)).sum::<f64>() / c_e.len() as f64;
    }
    let a = j.abs() / (2.0 * j0_particle);
    let d = SQRT_REGULARISATION * c_e_ref;
    let (av, a2, d2) = (f64x4::splat(a), f64x4::splat(a * a), f64x4::splat(d * d));
    // The factors `A + sqrt(A^2 + f^2)` and `f^2` of four volumes.
    let factors = |c: f64x4| {
        let c = c.max(f64x4::ZERO);
        let c2 = c * c;
        let f2 = c2 / (c2 + d2).sqrt();
        (av + (a2 + f2).sqrt(), f2)
    };
    // Their products, lane by lane; folded into logarithms when a lane leaves 1e-100..1e100.
    let (mut num, mut f2s, mut logs) = (f64x4::ONE, f64x4::ONE, 0.0);
    let mut fold = |num: &mut f64x4, f2s: &mut f64x4| {
        for (n, f) in num.to_array().into_iter().zip(f2s.to_array()) {
            logs += n.ln() - 0.5 * f.ln();
        }
        (*num, *f2s) = (f64x4::ONE, f64x4::ONE);
    };
    let (lo, hi) = (f64x4::splat(1e-100), f64x4::splat(1e100));
    let chunks = c_e.chunks_exact(4);
    let tail = chunks.remainder();
    for chunk in chunks {
        let (n, f2) = factors(f64x4::new(chunk.try_into().expect("four lanes")));
        num *= n;
        f2s *= f2;
        if !(num.simd_ge(lo) & num.simd_le(hi) & f2s.simd_ge(lo) & f2s.simd_le(hi)).all() {
            fold(&mut num, &mut f2s);
        }
    }
    if !tail.is_empty() {
        // The last volumes in the first lanes, factors of 1 in the others.
        let mut c = [0.0; 4];
        c[..tail.len()].copy_from_slice(tail);
        let (n, f2) = factors(f64x4::new(c));
        let (mut n, mut f2) = (n.to_array(), f2.to_array());
        n[tail.len()..].fill(1.0);
        f2[tail.len()..].fill(1.0);
        num *= f64x4::new(n);
        f2s *= f64x4::new(f2);
    }
    let (n, f2) = (num.to_array().iter().product::<f64>(), f2s.to_array().iter().product::<f64>());
    let mean = if n.is_normal() && f2.is_normal() && n < 1e300 && f2 < 1e300 {
        logs + n.ln() - 0.5 * f2.ln()
    } else {
        fold(&mut num, &mut f2s);
        logs
    } / c_e.len() as f64;
    (GAS_CONSTANT * t / (alpha * FARADAY) * mean).copysign(j)
}

/// Arithmetic mean of `ln v_k` for positive `v_k`, with one logarithm per ~10^300 of
/// dynamic range instead of one per term.
pub fn log_mean(values: impl ExactSizeIterator<Item = f64>) -> f64 {
    let n = values.len();
    let (mut product, mut logs) = (1.0f64, 0.0);
    for v in values {
        product *= v;
        if !(1e-150..=1e150).contains(&product) {
            logs += product.ln();
            product = 1.0;
        }
    }
    (logs + product.ln()) / n as f64
}

/// `sinh(x)`: a Taylor series below |x| = 1/2 (truncation error < 5e-17 relative there),
/// `(e^x - e^-x) / 2` above, within a few ulp. std's version goes through `expm1` and costs
/// about four times more.
fn sinh(x: f64) -> f64 {
    let a = x.abs();
    let r = if a < 0.5 {
        let s = a * a;
        // 1/3!, 1/5!, ..., 1/13!
        const C: [f64; 6] = [1.0 / 6.0, 1.0 / 120.0, 1.0 / 5040.0, 1.0 / 362880.0, 1.0 / 39916800.0, 1.0 / 6227020800.0];
        let tail = C[0] + s * (C[1] + s * (C[2] + s * (C[3] + s * (C[4] + s * C[5]))));
        a + a * s * tail
    } else {
        let e = a.exp();
        0.5 * (e - 1.0 / e)
    };
    r.copysign(x)
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
    fn exchange_current_is_pybamms_regularised_form() {
        // PyBaMM 26.10.1.1, Chen 2020 at 298.15 K, c_e = 1000 mol/m^3 (its DFN at t = 0).
        let neg = super::exchange_current(6.48e-7, 1000.0, 1000.0, 29866.0, 33133.0);
        let pos = super::exchange_current(3.42e-6, 1000.0, 1000.0, 17038.0, 63104.0);
        assert!((neg / 0.20240754 - 1.0).abs() < 1e-7, "{neg}");
        assert!((pos / 3.02986908 - 1.0).abs() < 1e-7, "{pos}");
        // finite and zero at an empty particle, odd in x below the regularisation width
        assert_eq!(super::exchange_current(1.0, 1000.0, 1000.0, 0.0, 1.0), 0.0);
        assert!(super::reg_sqrt(1e-9, 1e-3) > 0.0 && super::reg_sqrt(-1e-9, 1e-3) < 0.0);
    }

    #[test]
    fn mean_overpotential_matches_termwise_mean() {
        let j0_particle = 0.01;
        // volumes from depleted (1e-12 mol/m^3, inside the regularisation) to 5x the reference,
        // 5 to 83 of them (whole lanes and a remainder), currents of both signs and zero
        for n in [5, 20, 83] {
            let c_e: Vec<f64> = (0..n).map(|k| if k % 3 == 1 { 1e-12 * (k + 1) as f64 } else { 30.0 + 5000.0 * k as f64 / n as f64 }).collect();
            for j in [-7.0, -1e-9, 0.0, 3e-4, 2.5, 1e4] {
                let direct = c_e.iter().map(|&c| super::overpotential(j, j0_particle * super::electrolyte_factor(c, 1000.0), 0.5, 298.15)).sum::<f64>() / n as f64;
                let fast = super::mean_overpotential(j, j0_particle, &c_e, 1000.0, 0.5, 298.15);
                // 1e-15 V absolute: ln(1 + x) rounds x at tiny currents, far below any voltage of interest.
                assert!((fast - direct).abs() <= 1e-13 * direct.abs() + 1e-15, "n = {n}, j = {j}: {fast} vs {direct}");
            }
        }
    }

    #[test]
    fn shared_potential_splits_the_current_and_reduces_to_one_particle() {
        let (w, j0, u) = ([0.2, 0.5, 0.3], [0.1, 0.4, 2.0], [0.08, 0.1, 0.25]);
        let mut j = [0.0; 3];
        for target in [-30.0, -1.0, 0.0, 0.3, 5.0, 200.0] {
            let delta = super::shared_potential(&w, &j0, &u, target, 0.5, 298.15, &mut j);
            let total: f64 = w.iter().zip(&j).map(|(w, j)| w * j).sum();
            assert!((total - target).abs() <= 1e-12 * target.abs().max(1.0), "{target}: {total}");
            for i in 0..3 {
                assert_eq!(j[i], super::butler_volmer(j0[i], delta - u[i], 0.5, 298.15));
            }
        }
        // identical classes: one particle's inverse kinetics
        let mut j = [0.0; 2];
        let delta = super::shared_potential(&[0.5, 0.5], &[0.3, 0.3], &[0.1, 0.1], 2.0, 0.5, 298.15, &mut j);
        assert!((delta - 0.1 - super::overpotential(2.0, 0.3, 0.5, 298.15)).abs() < 1e-15, "{delta}");
    }

    #[test]
    fn asymmetric_butler_volmer_inverts_and_has_its_limits() {
        use crate::params::{FARADAY, GAS_CONSTANT};
        let (j0, t) = (0.3, 275.15);
        let f = FARADAY / (GAS_CONSTANT * t);
        for alpha in [0.2, 0.4, 0.5, 0.6, 0.8] {
            for j in [-2e4, -30.0, -0.7, -1e-9, 0.0, 1e-9, 0.05, 3.0, 2e4] {
                let eta = super::overpotential(j, j0, alpha, t);
                let back = super::butler_volmer(j0, eta, alpha, t);
                assert!((back - j).abs() <= 1e-12 * j.abs(), "alpha {alpha}, j {j}: {back}");
            }
            // the small-signal conductance j0 F / R T whatever alpha (one charge-transfer resistance)
            let eta = 1e-7;
            let slope = (super::butler_volmer(j0, eta, alpha, t) - super::butler_volmer(j0, -eta, alpha, t)) / (2.0 * eta);
            assert!((slope / (j0 * f) - 1.0).abs() < 1e-9, "alpha {alpha}: {slope}");
            // Tafel lines: anodic slope alpha F / R T, cathodic (1 - alpha) F / R T
            let tafel = |e: f64| super::butler_volmer(j0, e, alpha, t).abs().ln();
            assert!(((tafel(1.01) - tafel(1.0)) / 0.01 / (alpha * f) - 1.0).abs() < 1e-9);
            assert!(((tafel(-1.01) - tafel(-1.0)) / 0.01 / ((1.0 - alpha) * f) - 1.0).abs() < 1e-9);
        }
        // continuous through the symmetric closed form
        let (a, b) = (super::overpotential(5.0, j0, 0.5, t), super::overpotential(5.0, j0, 0.5 + 1e-10, t));
        assert!((a - b).abs() < 1e-10, "{a} {b}");
        // an asymmetric class split shares its current and reduces to one particle
        let mut j = [0.0; 2];
        let delta = super::shared_potential(&[0.3, 0.7], &[0.2, 0.5], &[0.1, 0.12], -4.0, 0.4, t, &mut j);
        assert!((0.3 * j[0] + 0.7 * j[1] + 4.0).abs() < 1e-12, "{j:?}");
        let delta_one = super::shared_potential(&[0.5, 0.5], &[0.3, 0.3], &[0.1, 0.1], -4.0, 0.4, t, &mut j);
        assert!((delta_one - 0.1 - super::overpotential(-4.0, 0.3, 0.4, t)).abs() < 1e-14, "{delta}");
    }

    #[test]
    fn log_mean_survives_a_huge_range() {
        let v: Vec<f64> = (0..400).map(|k| if k % 2 == 0 { 1e-3 } else { 1e5 }).collect();
        let direct = v.iter().map(|x| x.ln()).sum::<f64>() / 400.0;
        assert!((super::log_mean(v.iter().copied()) - direct).abs() < 1e-12);
    }

    #[test]
    fn fast_sinh_matches_std() {
        for k in -3000..=3000 {
            let x = k as f64 * 1e-3 + 1e-4 * (k as f64 * 0.37).sin();
            let (a, b) = (super::sinh(x), x.sinh());
            assert!((a - b).abs() <= 4e-16 * b.abs(), "x = {x}: {a} vs {b}");
        }
        for x in [0.0, -0.0, 1e-300, 0.4999999999, 0.5, 30.0, -700.0] {
            let (a, b) = (super::sinh(x), x.sinh());
            assert!((a - b).abs() <= 4e-16 * b.abs(), "x = {x}: {a} vs {b}");
        }
        assert!(super::sinh(f64::NAN).is_nan());
    }

    #[test]
    fn fast_asinh_matches_std() {
        for k in -600..=600 {
            let x = (k as f64 * 0.03).sinh() * 1.7;
            let (a, b) = (super::asinh(x), x.asinh());
            assert!((a - b).abs() <= 1e-14 * b.abs().max(1e-300) + 1e-300, "x = {x}: {a} vs {b}");
        }
    }
}
