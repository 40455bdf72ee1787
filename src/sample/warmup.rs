//! Warmup adaptation of gradient samplers: dual-averaging step size (Hoffman & Gelman 2014,
//! section 3.2.1; Nesterov 2009) and Stan's windowed diagonal mass-matrix estimation.

/// Dual averaging of `log ε` towards a target mean acceptance statistic `δ`.
#[derive(Clone, Debug)]
pub(super) struct DualAveraging {
    /// Shrinkage point `μ = log(10·ε₀)`.
    mu: f64,
    /// Target acceptance statistic `δ`.
    target: f64,
    /// Running mean `H̄` of `δ - α`.
    h_bar: f64,
    log_eps: f64,
    /// Weighted average `log ε̄` of the iterates (the final step size).
    log_eps_bar: f64,
    t: f64,
}

/// Shrinkage strength `γ`, iteration offset `t₀` and averaging exponent `κ` (Hoffman & Gelman).
const GAMMA: f64 = 0.05;
const T0: f64 = 10.0;
const KAPPA: f64 = 0.75;

impl DualAveraging {
    pub fn new(eps0: f64, target: f64) -> Self {
        DualAveraging { mu: (10.0 * eps0).ln(), target, h_bar: 0.0, log_eps: eps0.ln(), log_eps_bar: 0.0, t: 0.0 }
    }

    /// Feeds the acceptance statistic of one iteration; returns the next step size.
    pub fn update(&mut self, accept_stat: f64) -> f64 {
        let accept = if accept_stat.is_finite() { accept_stat.clamp(0.0, 1.0) } else { 0.0 };
        self.t += 1.0;
        let eta = 1.0 / (self.t + T0);
        self.h_bar = (1.0 - eta) * self.h_bar + eta * (self.target - accept);
        self.log_eps = self.mu - self.t.sqrt() / GAMMA * self.h_bar;
        let w = self.t.powf(-KAPPA);
        self.log_eps_bar = w * self.log_eps + (1.0 - w) * self.log_eps_bar;
        self.log_eps.exp()
    }

    /// The averaged step size `ε̄` used after warmup.
    pub fn final_step(&self) -> f64 {
        if self.t == 0.0 { self.log_eps.exp() } else { self.log_eps_bar.exp() }
    }
}

/// Stan's mass-matrix windows `[start, end)` for `warmup` iterations: an initial buffer of 75
/// (step size only), windows of 25 doubling in length, and a terminal buffer of 50 (step size
/// only); scaled to 15% / 75% / 10% of a short warmup, none below 20 iterations.
pub(super) fn metric_windows(warmup: usize) -> Vec<(usize, usize)> {
    if warmup < 20 {
        return Vec::new();
    }
    let (init, term, base) = if 75 + 50 + 25 > warmup {
        let init = warmup * 15 / 100;
        let term = warmup / 10;
        (init, term, warmup - init - term)
    } else {
        (75, 50, 25)
    };
    let last = warmup - term;
    let mut windows = Vec::new();
    let (mut start, mut size) = (init, base);
    loop {
        let end = start + size;
        if end + 2 * size > last {
            windows.push((start, last));
            return windows;
        }
        windows.push((start, end));
        start = end;
        size *= 2;
    }
}

/// Welford running variance per coordinate.
#[derive(Clone, Debug)]
pub(super) struct Welford {
    n: usize,
    mean: Vec<f64>,
    m2: Vec<f64>,
}

impl Welford {
    pub fn new(dim: usize) -> Self {
        Welford { n: 0, mean: vec![0.0; dim], m2: vec![0.0; dim] }
    }

    pub fn add(&mut self, x: &[f64]) {
        self.n += 1;
        for (i, &v) in x.iter().enumerate() {
            let d = v - self.mean[i];
            self.mean[i] += d / self.n as f64;
            self.m2[i] += d * (v - self.mean[i]);
        }
    }

    /// Stan's regularised variance `n/(n+5)·s² + 10⁻³·5/(n+5)`; `None` with fewer than 3
    /// samples or a non-finite result.
    pub fn regularised_variance(&self) -> Option<Vec<f64>> {
        if self.n < 3 {
            return None;
        }
        let n = self.n as f64;
        let v: Vec<f64> = self.m2.iter().map(|m| n / (n + 5.0) * m / (n - 1.0) + 1e-3 * 5.0 / (n + 5.0)).collect();
        v.iter().all(|x| x.is_finite() && *x > 0.0).then_some(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stan_windows_for_1000_warmup() {
        // Stan: 75 | 25, 50, 100, 200, 500 (last extended to 950) | 50.
        assert_eq!(metric_windows(1000), vec![(75, 100), (100, 150), (150, 250), (250, 450), (450, 950)]);
        assert!(metric_windows(10).is_empty());
        assert_eq!(metric_windows(100), vec![(15, 90)]);
    }
}
