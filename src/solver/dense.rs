//! Dense output of a BDF step: the interpolating polynomial on its backward differences.

/// The interpolating polynomial of the last step, valid on `[t_old, end]`.
pub struct DenseOutput<'a> {
    /// Time (s) of the step's end, where `d[0]` holds the state.
    pub(super) t: f64,
    /// Step size (s).
    pub(super) h: f64,
    pub(super) order: usize,
    /// Backward differences of the state, `d[0]` the state itself.
    pub(super) d: &'a [Vec<f64>],
    pub(super) end: f64,
}

impl DenseOutput<'_> {
    /// End of the interval this step covers (s): the step end, or the event time.
    pub fn t_end(&self) -> f64 {
        self.end
    }

    /// Writes the states in `ranges` (of indices) at `t` into the same places of `out`; other
    /// entries are left alone.
    pub fn eval_ranges(&self, t: f64, ranges: &[std::ops::Range<usize>], out: &mut [f64]) {
        for r in ranges {
            out[r.clone()].copy_from_slice(&self.d[0][r.clone()]);
        }
        let mut p = 1.0;
        for j in 0..self.order {
            let shift = self.t - self.h * j as f64;
            p *= (t - shift) / (self.h * (j + 1) as f64);
            for r in ranges {
                for (o, dj) in out[r.clone()].iter_mut().zip(&self.d[j + 1][r.clone()]) {
                    *o += dj * p;
                }
            }
        }
    }

    /// Writes `y(t)` into `out`.
    pub fn eval(&self, t: f64, out: &mut [f64]) {
        self.eval_ranges(t, &[0..out.len()], out)
    }
}
