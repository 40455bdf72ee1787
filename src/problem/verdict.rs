//! What a fit's data determine, parameter by parameter, from its standard errors and
//! correlations (the Fisher information at the optimum): a verdict per parameter and the
//! sloppiest combination of parameters. Local (linearised) statements; a profile likelihood
//! would test them beyond the linearisation.

/// A relative standard error above this (-) means the data do not determine a parameter.
pub const MAX_RELATIVE_ERROR: f64 = 1.0;
/// A correlation above this in magnitude means a parameter is determined only together with
/// another.
pub const MAX_CORRELATION: f64 = 0.95;

/// What the data say about one fitted parameter.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Standing {
    /// Relative standard error (-) within [`MAX_RELATIVE_ERROR`] and no strong correlation.
    Identified { relative_error: f64 },
    /// Determined only in combination with `with`: correlation `rho` beyond
    /// [`MAX_CORRELATION`].
    Correlated { with: String, rho: f64, relative_error: f64 },
    /// Relative standard error beyond [`MAX_RELATIVE_ERROR`] (or infinite).
    NotIdentifiable { relative_error: f64 },
}

impl Standing {
    /// The verdict in words, e.g. "correlated with cell.contact_resistance (rho = -0.98)".
    pub fn describe(&self) -> String {
        match self {
            Standing::Identified { relative_error } => format!("identified (±{:.1} %)", 100.0 * relative_error),
            Standing::Correlated { with, rho, .. } => format!("correlated with {with} (rho = {rho:+.3})"),
            Standing::NotIdentifiable { relative_error } => format!("not identifiable from this data (±{:.0} %)", 100.0 * relative_error),
        }
    }
}

/// The verdict on each parameter `names[k]` at value `x[k]` with standard error `se[k]` and
/// correlation matrix `rho`.
pub fn standings(names: &[String], x: &[f64], se: &[f64], rho: &[Vec<f64>]) -> Vec<Standing> {
    (0..names.len().min(se.len()))
        .map(|k| {
            let relative_error = se[k] / x[k].abs().max(f64::MIN_POSITIVE);
            if !(relative_error <= MAX_RELATIVE_ERROR) {
                return Standing::NotIdentifiable { relative_error };
            }
            let strongest = (0..rho.len()).filter(|&j| j != k).map(|j| (j, rho[k][j])).filter(|(_, r)| r.is_finite()).max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
            match strongest {
                Some((j, r)) if r.abs() > MAX_CORRELATION => Standing::Correlated { with: names[j].clone(), rho: r, relative_error },
                _ => Standing::Identified { relative_error },
            }
        })
        .collect()
}

/// The least determined combination of the parameters' relative changes: the principal axis
/// of the relative covariance `rho_ab se_a se_b / (x_a x_b)` with the largest variance, as
/// its components over the names (those above 0.1 in magnitude) and its relative standard
/// error (-). `None` with fewer than two parameters.
pub fn sloppiest(names: &[String], x: &[f64], se: &[f64], rho: &[Vec<f64>]) -> Option<(Vec<(String, f64)>, f64)> {
    let p = rho.len();
    if p < 2 || se.len() < p {
        return None;
    }
    let rel: Vec<f64> = (0..p).map(|k| se[k] / x[k].abs().max(f64::MIN_POSITIVE)).collect();
    if let Some(k) = rel.iter().position(|r| !r.is_finite()) {
        return Some((vec![(names[k].clone(), 1.0)], f64::INFINITY));
    }
    let cov: Vec<f64> = (0..p * p).map(|i| rho[i / p][i % p] * rel[i / p] * rel[i % p]).collect();
    let (values, vectors) = crate::linalg::sym_eigen(&cov, p).ok()?;
    let top = (0..p).max_by(|&a, &b| values[a].total_cmp(&values[b]))?;
    let mut parts: Vec<(String, f64)> = (0..p).map(|a| (names[a].clone(), vectors[a * p + top])).filter(|(_, v)| v.abs() > 0.1).collect();
    // Sign: the largest component positive.
    if parts.iter().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs())).is_some_and(|(_, v)| *v < 0.0) {
        parts.iter_mut().for_each(|(_, v)| *v = -*v);
    }
    Some((parts, values[top].max(0.0).sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_follow_errors_and_correlations() {
        let names: Vec<String> = ["a", "b", "c"].iter().map(|s| s.to_string()).collect();
        let x = [1.0, 2.0, 3.0];
        let se = [0.05, 0.1, 6.0];
        let rho = vec![vec![1.0, -0.99, 0.1], vec![-0.99, 1.0, 0.0], vec![0.1, 0.0, 1.0]];
        let s = standings(&names, &x, &se, &rho);
        assert!(matches!(&s[0], Standing::Correlated { with, .. } if with == "b"));
        assert!(matches!(&s[1], Standing::Correlated { with, .. } if with == "a"));
        assert!(matches!(s[2], Standing::NotIdentifiable { relative_error } if (relative_error - 2.0).abs() < 1e-12));
        let uncorrelated = vec![vec![1.0, 0.2, 0.0], vec![0.2, 1.0, 0.0], vec![0.0, 0.0, 1.0]];
        assert!(matches!(standings(&names, &x, &se, &uncorrelated)[0], Standing::Identified { .. }));
        // c's 200 %, uncorrelated, is the sloppiest direction.
        let (parts, rel) = sloppiest(&names, &x, &se, &uncorrelated).unwrap();
        assert_eq!(parts.len(), 1);
        assert_eq!(parts[0].0, "c");
        assert!((rel - 2.0).abs() < 1e-9, "{rel}");
    }
}
