//! Coordinate-wise slice sampling with stepping out and shrinkage (Neal 2003, Figs. 3 and 5).

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rand_distr::Exp1;

use super::run::Recorder;
use super::target::Counted;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
use crate::error::Result;

/// Slice sampling, one coordinate at a time in a fixed order: the slice level is
/// `log y = log p(x) - Exp(1)`; an interval of width `w_i` placed at random around `x_i` is
/// stepped out (at most `max_stepping_out` steps in all, split at random between the sides)
/// and then shrunk towards `x_i` until a point inside the slice is drawn.
///
/// During warmup (with `adapt`) the widths become `w_i = 2·mean|Δx_i|` of the warmup moves
/// so far (about 2.3 conditional standard deviations for a Gaussian); they are fixed after
/// warmup, which keeps the kernel exact. Every iteration moves, so the acceptance rate is 1.
#[derive(Clone, Debug)]
pub struct SliceSampler {
    options: SamplerOptions,
}

impl SliceSampler {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(SliceSampler { options })
    }

    /// One slice update of coordinate `i` of `x` (log density `fx`); returns the new log density.
    fn update(&self, counted: &Counted, rng: &mut StdRng, x: &mut [f64], fx: f64, i: usize, w: f64) -> f64 {
        let e: f64 = rng.sample(Exp1);
        let level = fx - e;
        let x0 = x[i];
        let f_at = |v: f64, x: &mut [f64]| {
            x[i] = v;
            counted.log_density(x)
        };
        let mut left = x0 - w * rng.random::<f64>();
        let mut right = left + w;
        let m = self.options.max_stepping_out;
        let mut j = (m as f64 * rng.random::<f64>()) as usize;
        let mut k = m.saturating_sub(1) - j.min(m.saturating_sub(1));
        while j > 0 && f_at(left, x) > level {
            left -= w;
            j -= 1;
        }
        while k > 0 && f_at(right, x) > level {
            right += w;
            k -= 1;
        }
        loop {
            let v = left + (right - left) * rng.random::<f64>();
            let fv = f_at(v, x);
            if fv > level {
                return fv;
            }
            if v < x0 {
                left = v;
            } else {
                right = v;
            }
            if right - left <= 1e-12 * (1.0 + x0.abs()) {
                // The slice collapsed numerically onto x0 (which is always inside it).
                x[i] = x0;
                return fx;
            }
        }
    }

}

impl ChainSampler for SliceSampler {
    fn name(&self) -> &str {
        "slice"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        let counted = Counted::new(target);
        let mut rng = StdRng::seed_from_u64(seed);
        let mut rec = Recorder::new(schedule);
        let n = x0.len();
        let mut width = vec![self.options.slice_width; n];
        let mut moved = vec![0.0; n];
        let mut x = x0.to_vec();
        let mut fx = counted.log_density(&x);
        for it in 0..schedule.total() {
            for i in 0..n {
                let before = x[i];
                fx = self.update(&counted, &mut rng, &mut x, fx, i, width[i]);
                if self.options.adapt && it < schedule.warmup {
                    moved[i] += (x[i] - before).abs();
                    let mean = moved[i] / (it + 1) as f64;
                    if it >= 9 && mean > 0.0 {
                        width[i] = 2.0 * mean;
                    }
                }
            }
            rec.record(it, &x, fx, 1.0, false);
            progress();
        }
        Ok(rec.finish(&counted, None))
    }
}
