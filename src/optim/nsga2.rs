//! Multi-objective search: non-dominated sorting, crowding distance and NSGA-II
//! (Deb et al. 2002) with simulated binary crossover and polynomial mutation. All objectives
//! are maximised; candidates are evaluated in parallel and results depend only on the seed.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::Bounds;

/// NSGA-II settings.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Nsga2Options {
    /// Population size (even).
    pub population: usize,
    /// Number of generations.
    pub generations: usize,
    /// Random seed.
    pub seed: u64,
    /// SBX distribution index.
    pub eta_crossover: f64,
    /// Polynomial-mutation distribution index.
    pub eta_mutation: f64,
}

impl Nsga2Options {
    /// A population of at least 4 (even: pairs of parents), one or more generations, finite
    /// positive distribution indices; errors name the `[optimiser]` key.
    ///
    /// ```
    /// use cellstudio::optim::nsga2::Nsga2Options;
    /// let e = Nsga2Options { generations: 0, ..Default::default() }.validate().unwrap_err();
    /// assert!(e.to_string().contains("optimiser.generations"), "{e}");
    /// ```
    pub fn validate(&self) -> Result<(), crate::error::Error> {
        use crate::error::Error;
        if self.population < 4 || self.population % 2 != 0 {
            return Err(Error::invalid("optimiser.population", self.population as f64, "must be an even number of at least 4"));
        }
        if self.generations == 0 {
            return Err(Error::invalid("optimiser.generations", 0.0, "must be at least 1 (0 would report the random first sample as the front)"));
        }
        for (key, eta) in [("optimiser.eta_crossover", self.eta_crossover), ("optimiser.eta_mutation", self.eta_mutation)] {
            if !(eta > 0.0 && eta.is_finite()) {
                return Err(Error::invalid(key, eta, "must be positive"));
            }
        }
        Ok(())
    }
}

impl Default for Nsga2Options {
    fn default() -> Self {
        Self { population: 24, generations: 15, seed: 1, eta_crossover: 15.0, eta_mutation: 20.0 }
    }
}

/// An evaluated individual: decision vector and objective values (NaN-free; failed
/// evaluations carry `-inf`).
#[derive(Clone, Debug, Serialize)]
pub struct Individual {
    pub x: Vec<f64>,
    pub f: Vec<f64>,
}

/// `a` dominates `b` when it is no worse in every objective and better in one (maximising).
pub fn dominates(a: &[f64], b: &[f64]) -> bool {
    a.iter().zip(b).all(|(x, y)| x >= y) && a.iter().zip(b).any(|(x, y)| x > y)
}

/// Indices of the non-dominated fronts, best first.
pub fn non_dominated_fronts(f: &[Vec<f64>]) -> Vec<Vec<usize>> {
    let n = f.len();
    let mut dominated_by: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut count = vec![0usize; n];
    for i in 0..n {
        for j in 0..n {
            if i != j && dominates(&f[i], &f[j]) {
                dominated_by[i].push(j);
            } else if i != j && dominates(&f[j], &f[i]) {
                count[i] += 1;
            }
        }
    }
    let mut fronts = Vec::new();
    let mut current: Vec<usize> = (0..n).filter(|&i| count[i] == 0).collect();
    while !current.is_empty() {
        let mut next = Vec::new();
        for &i in &current {
            for &j in &dominated_by[i] {
                count[j] -= 1;
                if count[j] == 0 {
                    next.push(j);
                }
            }
        }
        fronts.push(current);
        current = next;
    }
    fronts
}

/// Crowding distance of each member of one front.
fn crowding(front: &[usize], f: &[Vec<f64>]) -> Vec<f64> {
    let m = front.len();
    let mut d = vec![0.0; m];
    if m <= 2 {
        return vec![f64::INFINITY; m];
    }
    for k in 0..f[front[0]].len() {
        let mut order: Vec<usize> = (0..m).collect();
        order.sort_by(|&a, &b| f[front[a]][k].total_cmp(&f[front[b]][k]));
        let (lo, hi) = (f[front[order[0]]][k], f[front[order[m - 1]]][k]);
        d[order[0]] = f64::INFINITY;
        d[order[m - 1]] = f64::INFINITY;
        if hi > lo {
            for w in 1..m - 1 {
                d[order[w]] += (f[front[order[w + 1]]][k] - f[front[order[w - 1]]][k]) / (hi - lo);
            }
        }
    }
    d
}

/// Runs NSGA-II on `evaluate` (objectives to maximise) within `bounds`, every candidate
/// (initial or child) passed through `repair` before it is evaluated and stored (e.g. a
/// projection onto linear constraints; `|x| x.to_vec()` for none), calling
/// `progress(generation)` after each generation; returns the final population's first front
/// and every individual evaluated.
pub fn nsga2(
    bounds: &Bounds,
    opts: &Nsga2Options,
    evaluate: &(dyn Fn(&[f64]) -> Vec<f64> + Sync),
    repair: &(dyn Fn(&[f64]) -> Vec<f64> + Sync),
    progress: &mut dyn FnMut(usize),
) -> (Vec<Individual>, Vec<Individual>) {
    let (lower, upper) = (bounds.lower(), bounds.upper());
    let dim = lower.len();
    let pop_size = opts.population.max(4) & !1; // validated by Nsga2Options::validate in studies
    let mut rng = StdRng::seed_from_u64(opts.seed);
    let eval_all = |xs: Vec<Vec<f64>>| -> Vec<Individual> {
        xs.into_par_iter()
            .map(|x| {
                let x = repair(&x);
                Individual { f: evaluate(&x), x }
            })
            .collect()
    };
    let initial: Vec<Vec<f64>> = (0..pop_size)
        .map(|_| (0..dim).map(|k| lower[k] + rng.random::<f64>() * (upper[k] - lower[k])).collect())
        .collect();
    let mut population = eval_all(initial);
    let mut archive = population.clone();
    for generation in 0..opts.generations {
        // Rank and crowding of the current population for tournament selection.
        let f: Vec<Vec<f64>> = population.iter().map(|p| p.f.clone()).collect();
        let fronts = non_dominated_fronts(&f);
        let mut rank = vec![0usize; pop_size];
        let mut crowd = vec![0.0; pop_size];
        for (r, front) in fronts.iter().enumerate() {
            for (&i, c) in front.iter().zip(crowding(front, &f)) {
                rank[i] = r;
                crowd[i] = c;
            }
        }
        let better = |a: usize, b: usize| rank[a] < rank[b] || (rank[a] == rank[b] && crowd[a] > crowd[b]);
        let mut children = Vec::with_capacity(pop_size);
        while children.len() < pop_size {
            let pick = |rng: &mut StdRng| {
                let (a, b) = (rng.random_range(0..pop_size), rng.random_range(0..pop_size));
                if better(a, b) { a } else { b }
            };
            let (pa, pb) = (pick(&mut rng), pick(&mut rng));
            let (mut c1, mut c2) = (population[pa].x.clone(), population[pb].x.clone());
            for k in 0..dim {
                let span = upper[k] - lower[k];
                if rng.random::<f64>() < 0.9 {
                    let u: f64 = rng.random();
                    let beta = if u <= 0.5 {
                        (2.0 * u).powf(1.0 / (opts.eta_crossover + 1.0))
                    } else {
                        (1.0 / (2.0 * (1.0 - u))).powf(1.0 / (opts.eta_crossover + 1.0))
                    };
                    let (a, b) = (c1[k], c2[k]);
                    c1[k] = 0.5 * ((1.0 + beta) * a + (1.0 - beta) * b);
                    c2[k] = 0.5 * ((1.0 - beta) * a + (1.0 + beta) * b);
                }
                for c in [&mut c1, &mut c2] {
                    if rng.random::<f64>() < 1.0 / dim as f64 {
                        let u: f64 = rng.random();
                        let delta = if u < 0.5 {
                            (2.0 * u).powf(1.0 / (opts.eta_mutation + 1.0)) - 1.0
                        } else {
                            1.0 - (2.0 * (1.0 - u)).powf(1.0 / (opts.eta_mutation + 1.0))
                        };
                        c[k] += delta * span;
                    }
                    c[k] = c[k].clamp(lower[k], upper[k]);
                }
            }
            children.push(c1);
            children.push(c2);
        }
        let offspring = eval_all(children);
        archive.extend(offspring.iter().cloned());
        // Environmental selection from parents + offspring.
        let mut merged = population;
        merged.extend(offspring);
        let f: Vec<Vec<f64>> = merged.iter().map(|p| p.f.clone()).collect();
        let mut next = Vec::with_capacity(pop_size);
        for front in non_dominated_fronts(&f) {
            if next.len() + front.len() <= pop_size {
                next.extend(front.iter().copied());
            } else {
                let c = crowding(&front, &f);
                let mut order: Vec<usize> = (0..front.len()).collect();
                order.sort_by(|&a, &b| c[b].total_cmp(&c[a]));
                next.extend(order.iter().take(pop_size - next.len()).map(|&i| front[i]));
                break;
            }
        }
        population = next.into_iter().map(|i| merged[i].clone()).collect();
        progress(generation + 1);
    }
    let f: Vec<Vec<f64>> = population.iter().map(|p| p.f.clone()).collect();
    let first = non_dominated_fronts(&f).into_iter().next().unwrap_or_default();
    let front = first.into_iter().map(|i| population[i].clone()).collect();
    (front, archive)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Schaffer's problem (maximise -x^2 and -(x-2)^2): the Pareto set is x in [0, 2].
    #[test]
    fn finds_schaffer_pareto_set() {
        let eval = |x: &[f64]| vec![-x[0] * x[0], -(x[0] - 2.0) * (x[0] - 2.0)];
        let opts = Nsga2Options { population: 40, generations: 30, ..Default::default() };
        let (front, _) = nsga2(&Bounds::new(vec![-10.0], vec![10.0]).unwrap(), &opts, &eval, &|x: &[f64]| x.to_vec(), &mut |_| {});
        assert!(front.len() >= 10);
        for ind in &front {
            assert!((-0.05..=2.05).contains(&ind.x[0]), "{}", ind.x[0]);
        }
        let spread = front.iter().map(|i| i.x[0]).fold(f64::NEG_INFINITY, f64::max)
            - front.iter().map(|i| i.x[0]).fold(f64::INFINITY, f64::min);
        assert!(spread > 1.5, "front should span the Pareto set, spread {spread}");
        // Reproducible for a seed.
        let (again, _) = nsga2(&Bounds::new(vec![-10.0], vec![10.0]).unwrap(), &opts, &eval, &|x: &[f64]| x.to_vec(), &mut |_| {});
        assert_eq!(front.iter().map(|i| i.x[0]).collect::<Vec<_>>(), again.iter().map(|i| i.x[0]).collect::<Vec<_>>());
    }

    #[test]
    fn fronts_are_sorted_by_dominance() {
        let f = vec![vec![1.0, 1.0], vec![2.0, 2.0], vec![0.0, 3.0], vec![0.0, 0.0]];
        let fronts = non_dominated_fronts(&f);
        assert_eq!(fronts[0], vec![1, 2]);
        assert_eq!(fronts[1], vec![0]);
        assert_eq!(fronts[2], vec![3]);
    }
}
