//! BPX `FloatFunctionTable` values (a number, an `{x, y}` table or an expression) and their
//! conversion into our functions and scalars.

use serde_json::Value;

use super::super::function::{Function1D, interpolate};
use super::expression::Expr;
use super::value::{Check, missing, number, type_error};
use super::tabulate::{Tolerance, sample};
use crate::error::Error;

/// A BPX `FloatFunctionTable` value.
pub(super) enum Bpx1D {
    Number(f64),
    Table { x: Vec<f64>, y: Vec<f64> },
    Expression(Expr),
}

impl Bpx1D {
    pub(super) fn parse(path: &str, v: &Value) -> Result<Self, Error> {
        match v {
            Value::Number(_) => Ok(Bpx1D::Number(number(path, v, Check::Finite)?)),
            Value::String(s) => {
                Expr::parse(s).map(Bpx1D::Expression).map_err(|reason| Error::InvalidSetting {
                    field: path.into(),
                    reason: format!("cannot parse the expression {s:?}: {reason}"),
                })
            }
            Value::Object(map) => {
                if let Some(k) = map.keys().find(|k| *k != "x" && *k != "y") {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!("a table has only the keys \"x\" and \"y\", found {k:?}"),
                    });
                }
                let list = |name: &str| -> Result<Vec<f64>, Error> {
                    let p = format!("{path}/{name}");
                    let arr = map.get(name).ok_or_else(|| missing(&p))?;
                    let arr = arr.as_array().ok_or_else(|| type_error(&p, "an array of numbers", arr))?;
                    arr.iter().map(|v| number(&p, v, Check::Finite)).collect()
                };
                let (x, y) = (list("x")?, list("y")?);
                if x.len() != y.len() || x.len() < 2 {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!(
                            "a table needs at least 2 points and x, y of equal length (x: {}, y: {})",
                            x.len(),
                            y.len()
                        ),
                    });
                }
                // Sorted by x as PyBaMM does; repeated x are an error.
                let mut pts: Vec<(f64, f64)> = x.into_iter().zip(y).collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                if let Some(w) = pts.windows(2).find(|w| w[1].0 <= w[0].0) {
                    return Err(Error::invalid(
                        format!("{path}/x"),
                        w[1].0,
                        "table x values must be distinct",
                    ));
                }
                Ok(Bpx1D::Table {
                    x: pts.iter().map(|p| p.0).collect(),
                    y: pts.iter().map(|p| p.1).collect(),
                })
            }
            _ => Err(type_error(path, "a number, an expression string or an {\"x\", \"y\"} table", v)),
        }
    }

    /// The value if it does not depend on x.
    fn constant(&self, path: &str) -> Result<Option<f64>, Error> {
        match self {
            Bpx1D::Number(v) => Ok(Some(*v)),
            Bpx1D::Expression(e) if !e.uses_x() => Check::Finite.apply(path, e.eval(0.0)).map(Some),
            _ => Ok(None),
        }
    }

    fn eval(&self, x: f64) -> f64 {
        match self {
            Bpx1D::Number(v) => *v,
            Bpx1D::Table { x: xs, y: ys } => interpolate(xs, ys, x),
            Bpx1D::Expression(e) => e.eval(x),
        }
    }

    /// A function of one variable; expressions are sampled over `range`.
    pub(super) fn to_function(
        &self,
        path: &str,
        range: (f64, f64),
        tolerance: Tolerance,
        approximated: &mut Vec<String>,
    ) -> Result<Function1D, Error> {
        if let Some(value) = self.constant(path)? {
            return Ok(Function1D::Constant { value });
        }
        match self {
            Bpx1D::Table { x, y } => Ok(Function1D::Table { x: x.clone(), y: y.clone() }),
            _ => {
                let (x, y) = sample(&|x| self.eval(x), range, tolerance);
                if x.len() < 2 {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!("the expression is not finite over [{}, {}]", range.0, range.1),
                    });
                }
                approximated.push(path.into());
                Ok(Function1D::Table { x, y })
            }
        }
    }

    /// A scalar: a function of stoichiometry is averaged over the window `[lo, hi]`.
    pub(super) fn to_scalar(
        &self,
        path: &str,
        window: (f64, f64),
        geometric: bool,
        approximated: &mut Vec<String>,
    ) -> Result<f64, Error> {
        if let Some(v) = self.constant(path)? {
            return Ok(v);
        }
        let n = 101;
        let samples: Vec<f64> =
            (0..n).map(|i| self.eval(window.0 + (window.1 - window.0) * i as f64 / (n - 1) as f64)).collect();
        let mean = if geometric {
            if let Some(v) = samples.iter().find(|v| !(**v > 0.0 && v.is_finite())) {
                return Err(Error::invalid(path, *v, "must be positive over the stoichiometry window"));
            }
            (samples.iter().map(|v| v.ln()).sum::<f64>() / n as f64).exp()
        } else {
            samples.iter().sum::<f64>() / n as f64
        };
        approximated.push(path.into());
        Check::Finite.apply(path, mean)
    }
}
