//! Convergence diagnostics of Markov chains: split R-hat and effective sample size over
//! several chains (Gelman et al., Bayesian Data Analysis 3rd ed., section 11.4-11.5; the
//! estimators of Stan).
//!
//! ```
//! use cellstudio::stats::convergence::{effective_sample_size, split_rhat};
//! // Two chains stuck in different places: R-hat far above 1.
//! let stuck = vec![vec![0.0, 0.1, 0.0, 0.1, 0.0, 0.1], vec![5.0, 5.1, 5.0, 5.1, 5.0, 5.1]];
//! assert!(split_rhat(&stuck) > 5.0);
//! // Alternating draws are anti-correlated: more effective draws than draws.
//! let alternating: Vec<f64> = (0..1000).map(|i| if i % 2 == 0 { 1.0 } else { -1.0 } + 0.01 * (i as f64).sin()).collect();
//! assert!(effective_sample_size(&[alternating]) > 1000.0);
//! ```

/// Splits every chain into its first and second half (dropping the middle draw of an odd
/// length), as split R-hat and the ESS do to detect trends within chains.
fn split(chains: &[Vec<f64>]) -> Vec<&[f64]> {
    chains
        .iter()
        .flat_map(|c| {
            let h = c.len() / 2;
            [&c[..h], &c[c.len() - h..]]
        })
        .filter(|c| !c.is_empty())
        .collect()
}

use super::descriptive::{mean, quantile, variance};
use super::distributions::normal_quantile;

/// Within-chain variance `W` and the pooled estimate `var⁺ = (n-1)/n·W + B/n` of equally long
/// chains (the shortest length is used).
fn variances(chains: &[&[f64]]) -> (f64, f64, usize) {
    let n = chains.iter().map(|c| c.len()).min().unwrap_or(0);
    let chains: Vec<&[f64]> = chains.iter().map(|c| &c[..n]).collect();
    let w = chains.iter().map(|c| variance(c)).sum::<f64>() / chains.len() as f64;
    let means: Vec<f64> = chains.iter().map(|c| mean(c)).collect();
    let b_over_n = variance(&means);
    (w, (n as f64 - 1.0) / n as f64 * w + b_over_n, n)
}

/// Split R-hat: `sqrt(var⁺ / W)` over the halves of all chains. Near 1 (below 1.01 - 1.05)
/// when the chains agree; `NaN` with fewer than 2 draws per half or constant chains that
/// disagree, 1 when all draws are equal.
pub fn split_rhat(chains: &[Vec<f64>]) -> f64 {
    let halves = split(chains);
    if halves.len() < 2 || halves.iter().any(|h| h.len() < 2) {
        return f64::NAN;
    }
    let (w, var_plus, _) = variances(&halves);
    if w == 0.0 {
        return if var_plus == 0.0 { 1.0 } else { f64::NAN };
    }
    (var_plus / w).sqrt()
}

/// Rank normalisation over all chains: each draw becomes `Φ⁻¹((r - 3/8) / (S + 1/4))`, `r` its
/// pooled rank (ties averaged), `S` the number of draws.
fn rank_normalise(chains: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let mut order: Vec<(f64, usize, usize)> =
        chains.iter().enumerate().flat_map(|(c, x)| x.iter().enumerate().map(move |(t, &v)| (v, c, t))).collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    let total = order.len() as f64;
    let mut z: Vec<Vec<f64>> = chains.iter().map(|c| vec![0.0; c.len()]).collect();
    let mut i = 0;
    while i < order.len() {
        let mut j = i;
        while j + 1 < order.len() && order[j + 1].0 == order[i].0 {
            j += 1;
        }
        let rank = 0.5 * ((i + 1) + (j + 1)) as f64;
        let value = normal_quantile((rank - 0.375) / (total + 0.25));
        for &(_, c, t) in &order[i..=j] {
            z[c][t] = value;
        }
        i = j + 1;
    }
    z
}

/// Rank-normalised split R-hat (Vehtari, Gelman, Simpson, Carpenter & Bürkner 2021): the
/// larger of the split R-hat of the rank-normalised draws (bulk) and of the rank-normalised
/// distances from the pooled median (tail). Unlike [`split_rhat`] it detects chains that
/// differ in scale only, and it is defined for heavy-tailed posteriors. Recommended threshold:
/// 1.01.
pub fn rank_normalised_rhat(chains: &[Vec<f64>]) -> f64 {
    let mut pooled: Vec<f64> = chains.iter().flatten().copied().collect();
    if pooled.is_empty() {
        return f64::NAN;
    }
    pooled.sort_by(f64::total_cmp);
    let median = quantile(&pooled, 0.5);
    let folded: Vec<Vec<f64>> = chains.iter().map(|c| c.iter().map(|v| (v - median).abs()).collect()).collect();
    let bulk = split_rhat(&rank_normalise(chains));
    let tail = split_rhat(&rank_normalise(&folded));
    if bulk.is_nan() || tail.is_nan() { f64::NAN } else { bulk.max(tail) }
}

/// Autocovariance at `lag` (divided by the chain length, as Geyer's estimator needs).
fn autocovariance(x: &[f64], m: f64, lag: usize) -> f64 {
    let n = x.len();
    (0..n - lag).map(|i| (x[i] - m) * (x[i + lag] - m)).sum::<f64>() / n as f64
}

/// Effective sample size of the draws of one parameter over several chains (split in
/// halves): autocorrelations `ρ_t = 1 - (W - mean acov_t) / var⁺` combined over chains, summed
/// with Geyer's initial monotone sequence (pairs `ρ_{2k} + ρ_{2k+1}` up to the first negative
/// one, made non-increasing). As Stan, `τ` is bounded below by `1/log10(total draws)`, so the
/// ESS can exceed the number of draws for anti-correlated chains. `NaN` for fewer than 4 draws
/// per half, the number of draws for constant chains.
pub fn effective_sample_size(chains: &[Vec<f64>]) -> f64 {
    let halves = split(chains);
    if halves.is_empty() || halves.iter().any(|h| h.len() < 4) {
        return f64::NAN;
    }
    let (w, var_plus, n) = variances(&halves);
    let halves: Vec<&[f64]> = halves.iter().map(|h| &h[..n]).collect();
    let total = (halves.len() * n) as f64;
    if var_plus == 0.0 {
        return total;
    }
    let means: Vec<f64> = halves.iter().map(|h| mean(h)).collect();
    let rho = |lag: usize| -> f64 {
        let acov = halves.iter().zip(&means).map(|(h, &m)| autocovariance(h, m, lag)).sum::<f64>() / halves.len() as f64;
        // At lag 0 the formula gives 1 - (W - (n-1)/n·W)/var⁺, slightly below 1: use 1 exactly.
        if lag == 0 { 1.0 } else { 1.0 - (w - acov) / var_plus }
    };
    let mut sum = 0.0;
    let mut previous = f64::INFINITY;
    let mut k = 0;
    while 2 * k + 1 < n {
        let pair = rho(2 * k) + rho(2 * k + 1);
        if pair < 0.0 {
            break;
        }
        let pair = pair.min(previous);
        sum += pair;
        previous = pair;
        k += 1;
    }
    let tau = (2.0 * sum - 1.0).max(1.0 / total.log10());
    total / tau
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand::rngs::StdRng;
    use rand_distr::{Distribution, StandardNormal};

    /// AR(1) chains `x_t = φ·x_{t-1} + ε_t`: the ESS of the mean is `N·(1-φ)/(1+φ)`.
    #[test]
    fn ess_of_ar1_matches_theory() {
        let phi: f64 = 0.6;
        let mut rng = StdRng::seed_from_u64(11);
        let chains: Vec<Vec<f64>> = (0..4)
            .map(|_| {
                let mut x = 0.0;
                (0..20_000)
                    .map(|_| {
                        let e: f64 = StandardNormal.sample(&mut rng);
                        x = phi * x + e;
                        x
                    })
                    .collect()
            })
            .collect();
        let expected = 80_000.0 * (1.0 - phi) / (1.0 + phi);
        let ess = effective_sample_size(&chains);
        assert!((ess / expected - 1.0).abs() < 0.1, "ess {ess} expected {expected}");
        assert!((split_rhat(&chains) - 1.0).abs() < 0.01);
    }

    /// Two chains with the same centre and different scales: split R-hat misses it, the
    /// folded (tail) rank-normalised R-hat does not (Vehtari et al. 2021, section 4.2).
    #[test]
    fn rank_normalised_rhat_detects_a_scale_difference() {
        let mut rng = StdRng::seed_from_u64(4);
        let chains: Vec<Vec<f64>> = [1.0, 3.0]
            .iter()
            .map(|s| (0..4000).map(|_| s * Distribution::<f64>::sample(&StandardNormal, &mut rng)).collect::<Vec<f64>>())
            .collect();
        assert!(split_rhat(&chains) < 1.01, "{}", split_rhat(&chains));
        assert!(rank_normalised_rhat(&chains) > 1.1, "{}", rank_normalised_rhat(&chains));
        let same: Vec<Vec<f64>> = (0..4).map(|_| (0..1000).map(|_| StandardNormal.sample(&mut rng)).collect()).collect();
        assert!(rank_normalised_rhat(&same) < 1.01);
    }

}
