//! Scalar functions of one variable used by parameter sets: open-circuit potentials (V) of
//! stoichiometry, and electrolyte transport properties of concentration (mol/m^3).

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::error::Error;

/// A parameter that is a function of one variable.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Function1D {
    /// A constant value.
    Constant { value: f64 },
    /// Linear interpolation in a table (x strictly increasing), clamped-slope extrapolation.
    Table { x: Vec<f64>, y: Vec<f64> },
    /// Graphite OCP of the LG M50 negative electrode (Chen et al. 2020), V vs stoichiometry.
    Chen2020GraphiteOcp,
    /// NMC 811 OCP of the LG M50 positive electrode (Chen et al. 2020), V vs stoichiometry.
    Chen2020Nmc811Ocp,
    /// Entropic change dU/dT (V/K) of the LG M50 graphite vs stoichiometry, O'Regan et al.
    /// 2022 (Electrochim. Acta 425, 140700), as PyBaMM's `ORegan2022` set has it.
    #[serde(rename = "oregan2022_graphite_entropic_change")]
    ORegan2022GraphiteEntropicChange,
    /// Entropic change dU/dT (V/K) of the LG M50 NMC 811 vs stoichiometry, O'Regan et al.
    /// 2022, as PyBaMM's `ORegan2022` set has it.
    #[serde(rename = "oregan2022_nmc811_entropic_change")]
    ORegan2022Nmc811EntropicChange,
    /// LiPF6 in EC:EMC electrolyte diffusivity (Nyman et al. 2008), m^2/s vs mol/m^3.
    Nyman2008Diffusivity,
    /// LiPF6 in EC:EMC electrolyte conductivity (Nyman et al. 2008), S/m vs mol/m^3.
    Nyman2008Conductivity,
}

impl Function1D {
    /// Evaluates the function at `x`.
    pub fn eval(&self, x: f64) -> f64 {
        match self {
            Function1D::Constant { value } => *value,
            Function1D::Table { x: xs, y: ys } => interpolate(xs, ys, x),
            Function1D::Chen2020GraphiteOcp => {
                1.9793 * (-39.3631 * x).exp() + 0.2482
                    - 0.0909 * tanh(29.8538 * (x - 0.1234))
                    - 0.04478 * tanh(14.9159 * (x - 0.2769))
                    - 0.0205 * tanh(30.4444 * (x - 0.6103))
            }
            Function1D::Chen2020Nmc811Ocp => {
                -0.8090 * x + 4.4875
                    - 0.0428 * tanh(18.5138 * (x - 0.5542))
                    - 17.7326 * tanh(15.7890 * (x - 0.3117))
                    + 17.5842 * tanh(15.9308 * (x - 0.3120))
            }
            Function1D::ORegan2022GraphiteEntropicChange => {
                // The fit is in mV/K; its tanh pair has a zero coefficient in the paper's
                // final fit and is left out.
                (-0.1112 * x + 0.02914 + 0.3561 * (-(x - 0.08309).powi(2) / 0.004616).exp()) * 1e-3
            }
            Function1D::ORegan2022Nmc811EntropicChange => {
                (0.04006 * (-(x - 0.2828).powi(2) / 0.0009855).exp() - 0.06656 * (-(x - 0.8032).powi(2) / 0.02179).exp()) * 1e-3
            }
            Function1D::Nyman2008Diffusivity => {
                let c = x * 1e-3;
                8.794e-11 * c * c - 3.972e-10 * c + 4.862e-10
            }
            Function1D::Nyman2008Conductivity => {
                let c = x * 1e-3;
                0.1297 * c * c * c - 2.51 * (c * c.sqrt()) + 3.329 * c
            }
        }
    }

    /// The published entropic change dU/dT (V/K) of the material whose OCP this is, where one
    /// is known: O'Regan et al. 2022 measured it on the same LG M50 cell whose graphite and
    /// NMC 811 OCPs Chen et al. 2020 give.
    pub fn published_entropic_change(&self) -> Option<Function1D> {
        match self {
            Function1D::Chen2020GraphiteOcp => Some(Function1D::ORegan2022GraphiteEntropicChange),
            Function1D::Chen2020Nmc811Ocp => Some(Function1D::ORegan2022Nmc811EntropicChange),
            _ => None,
        }
    }

    /// Whether the function is zero everywhere (a constant 0).
    pub fn is_zero(&self) -> bool {
        matches!(self, Function1D::Constant { value } if *value == 0.0)
    }

    /// Checks a table's shape and values; `field` names it in the error.
    pub fn validate(&self, field: &str) -> Result<(), Error> {
        match self {
            Function1D::Constant { value } if !value.is_finite() => {
                Err(Error::invalid(field, *value, "must be finite"))
            }
            Function1D::Table { x, y } => {
                if x.len() < 2 || x.len() != y.len() {
                    return Err(Error::InvalidSetting {
                        field: field.into(),
                        reason: format!(
                            "table needs at least 2 points and equal lengths (x: {}, y: {})",
                            x.len(),
                            y.len()
                        ),
                    });
                }
                if let Some(w) = x.windows(2).find(|w| !(w[1] > w[0])) {
                    return Err(Error::invalid(field, w[1], "table x must be strictly increasing"));
                }
                if let Some(v) = x.iter().chain(y).find(|v| !v.is_finite()) {
                    return Err(Error::invalid(field, *v, "table values must be finite"));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
}

/// Reads a plain number as [`Function1D::Constant`] and anything else as a function, so a
/// parameter that was a scalar (the OCPs' entropic change) stays readable as one.
pub fn number_or_function<'de, D: Deserializer<'de>>(d: D) -> Result<Function1D, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Either {
        Number(f64),
        Function(Function1D),
    }
    Ok(match Either::deserialize(d)? {
        Either::Number(value) => Function1D::Constant { value },
        Either::Function(f) => f,
    })
}

/// Writes a [`Function1D::Constant`] as a plain number, the inverse of [`number_or_function`].
pub fn serialize_number_or_function<S: Serializer>(f: &Function1D, s: S) -> Result<S::Ok, S::Error> {
    match f {
        Function1D::Constant { value } => s.serialize_f64(*value),
        f => f.serialize(s),
    }
}

/// `tanh(x)` from one `exp`: std's `tanh` goes through `expm1` and costs about five times
/// more. The absolute error is a few 1e-16 (the relative error grows as `|x| -> 0`), which
/// is what counts where tanh terms are summed into a potential of order 1 V.
fn tanh(x: f64) -> f64 {
    let e = (2.0 * x.abs()).exp();
    (1.0 - 2.0 / (e + 1.0)).copysign(x)
}

/// Piecewise-linear interpolation with linear extrapolation from the end segments.
pub fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    let i = match xs.partition_point(|&v| v <= x) {
        0 => 0,
        k if k >= n => n - 2,
        k => k - 1,
    };
    let w = (x - xs[i]) / (xs[i + 1] - xs[i]);
    ys[i] + w * (ys[i + 1] - ys[i])
}

#[cfg(test)]
mod tests {
    use super::Function1D;

    #[test]
    fn fast_tanh_matches_std_in_absolute_terms() {
        for k in -4000..=4000 {
            let x = k as f64 * 0.01;
            let (a, b) = (super::tanh(x), x.tanh());
            assert!((a - b).abs() <= 3e-16, "x = {x}: {a} vs {b}");
        }
        assert_eq!(super::tanh(1e3), 1.0);
        assert!(super::tanh(f64::NAN).is_nan());
    }

    #[test]
    fn chen2020_ocps_and_nyman_conductivity_match_std_forms() {
        let graphite = |x: f64| {
            1.9793 * (-39.3631 * x).exp() + 0.2482
                - 0.0909 * (29.8538 * (x - 0.1234)).tanh()
                - 0.04478 * (14.9159 * (x - 0.2769)).tanh()
                - 0.0205 * (30.4444 * (x - 0.6103)).tanh()
        };
        let nmc = |x: f64| {
            -0.8090 * x + 4.4875
                - 0.0428 * (18.5138 * (x - 0.5542)).tanh()
                - 17.7326 * (15.7890 * (x - 0.3117)).tanh()
                + 17.5842 * (15.9308 * (x - 0.3120)).tanh()
        };
        let kappa = |x: f64| {
            let c = x / 1000.0;
            0.1297 * c * c * c - 2.51 * c.powf(1.5) + 3.329 * c
        };
        for k in 0..=1000 {
            let x = k as f64 * 1e-3;
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * b.abs();
            assert!(close(Function1D::Chen2020GraphiteOcp.eval(x), graphite(x)), "graphite at {x}");
            assert!(close(Function1D::Chen2020Nmc811Ocp.eval(x), nmc(x)), "NMC at {x}");
            let c = 4000.0 * x;
            assert!(close(Function1D::Nyman2008Conductivity.eval(c), kappa(c)), "kappa at {c}");
        }
    }
}
