//! One triangular factor of [`StaticLu`](super::static_lu::StaticLu), stored row by row for
//! the forward or backward substitution of a solve.
//!
//! Most rows of the models' factors are very short: after minimum-degree ordering a DFN
//! particle shell's row of `L` or `U` holds one entry (its neighbouring shell), and sorting
//! the elimination by level puts the rows of one depth of all particles next to each other.
//! A row loop with an inner loop over its entries then spends more instructions on loop
//! control than on arithmetic, so consecutive rows with no entry or exactly one entry are
//! grouped into runs that are substituted without an inner loop. The arithmetic, and its
//! order within a row, is unchanged: results are bit-identical to the plain row loop.

/// How the rows of one run are substituted.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// No entries: nothing to do.
    Empty,
    /// Exactly one entry per row, at consecutive positions.
    Single,
    /// Any number of entries per row.
    General,
}

/// A run of consecutive rows `start..end` of one [`Kind`].
#[derive(Clone, Copy, Debug)]
struct Run {
    start: u32,
    end: u32,
    kind: Kind,
}

/// Rows of a triangular factor: row `i` has values `vals[ptr[i]..ptr[i + 1]]` at columns
/// `cols[..]`, copied after each factorisation from the factor values at `pos[..]`.
#[derive(Clone)]
pub(super) struct Sweep {
    ptr: Vec<u32>,
    cols: Vec<u32>,
    pub(super) pos: Vec<u32>,
    pub(super) vals: Vec<f64>,
    runs: Vec<Run>,
}

/// Shortest run of single-entry rows worth its own loop; shorter runs join the general rows.
const MIN_SINGLE_RUN: usize = 4;

impl Sweep {
    /// The positions `range(i)` of each row `i` of the filled pattern `cols`.
    pub(super) fn new(n: usize, cols: &[usize], range: impl Fn(usize) -> std::ops::Range<usize>) -> Self {
        let mut s = Sweep { ptr: vec![0], cols: Vec::new(), pos: Vec::new(), vals: Vec::new(), runs: Vec::new() };
        for i in 0..n {
            for p in range(i) {
                s.cols.push(cols[p] as u32);
                s.pos.push(p as u32);
            }
            s.ptr.push(s.cols.len() as u32);
        }
        s.vals = vec![0.0; s.cols.len()];
        s.runs = s.find_runs(n);
        s
    }

    /// Splits rows `0..n` into runs: empty rows, runs of at least [`MIN_SINGLE_RUN`]
    /// single-entry rows, and the rest.
    fn find_runs(&self, n: usize) -> Vec<Run> {
        let len = |i: usize| (self.ptr[i + 1] - self.ptr[i]) as usize;
        let mut runs: Vec<Run> = Vec::new();
        let mut i = 0;
        while i < n {
            let mut end = i + 1;
            let kind = match len(i) {
                0 => {
                    while end < n && len(end) == 0 {
                        end += 1;
                    }
                    Kind::Empty
                }
                1 => {
                    while end < n && len(end) == 1 {
                        end += 1;
                    }
                    if end - i >= MIN_SINGLE_RUN { Kind::Single } else { Kind::General }
                }
                _ => Kind::General,
            };
            match runs.last_mut() {
                Some(last) if last.kind == kind && kind != Kind::Single => last.end = end as u32,
                _ => runs.push(Run { start: i as u32, end: end as u32, kind }),
            }
            i = end;
        }
        runs
    }

    /// `z[i] -= sum_j row_i[j] z[j]` for every row `i`, rows in increasing order (forward
    /// substitution, when every column is an earlier row).
    pub(super) fn forward(&self, z: &mut [f64]) {
        for run in &self.runs {
            let (a, b) = (run.start as usize, run.end as usize);
            match run.kind {
                Kind::Empty => {}
                // SAFETY: rows and columns were built below `z.len()` (see `eliminate`).
                Kind::Single => unsafe { self.single(a..b, z) },
                Kind::General => (a..b).for_each(|i| unsafe { self.eliminate(i, z) }),
            }
        }
    }

    /// As [`Sweep::forward`], rows in decreasing order (backward substitution, when every
    /// column is a later row).
    pub(super) fn backward(&self, z: &mut [f64]) {
        for run in self.runs.iter().rev() {
            let (a, b) = (run.start as usize, run.end as usize);
            match run.kind {
                Kind::Empty => {}
                // SAFETY: as in `forward`.
                Kind::Single => unsafe { self.single((a..b).rev(), z) },
                Kind::General => (a..b).rev().for_each(|i| unsafe { self.eliminate(i, z) }),
            }
        }
    }

    /// `z[i] -= row_i[0] z[col]` for single-entry rows `i` (in the iterator's order).
    ///
    /// # Safety
    /// Every row has exactly one entry, rows and columns are below `z.len()`.
    #[inline(always)]
    unsafe fn single(&self, rows: impl Iterator<Item = usize>, z: &mut [f64]) {
        unsafe {
            for i in rows {
                let p = *self.ptr.get_unchecked(i) as usize;
                let v = *self.vals.get_unchecked(p) * *z.get_unchecked(*self.cols.get_unchecked(p) as usize);
                *z.get_unchecked_mut(i) -= v;
            }
        }
    }

    /// `z[i] -= sum_j row_i[j] z[j]`, for row `i`.
    ///
    /// # Safety
    /// `i < n` and every column is below `z.len()` (as built by `new` from a valid pattern).
    #[inline(always)]
    unsafe fn eliminate(&self, i: usize, z: &mut [f64]) {
        unsafe {
            let (a, b) = (*self.ptr.get_unchecked(i) as usize, *self.ptr.get_unchecked(i + 1) as usize);
            let mut s = *z.get_unchecked(i);
            for p in a..b {
                s -= self.vals.get_unchecked(p) * z.get_unchecked(*self.cols.get_unchecked(p) as usize);
            }
            *z.get_unchecked_mut(i) = s;
        }
    }

    /// Start of the values of row `i`.
    pub(super) fn row_start(&self, i: usize) -> usize {
        self.ptr[i] as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs of every kind give the plain row loop's results, forward and backward.
    #[test]
    fn runs_substitute_like_the_row_loop() {
        // rows: 0 empty, 1-5 single (a run), 6 two entries, 7-8 single (too short: general),
        // 9 empty
        let n = 10;
        let lower: Vec<Vec<usize>> =
            vec![vec![], vec![0], vec![1], vec![0], vec![2], vec![3], vec![4, 5], vec![6], vec![1], vec![]];
        let mut cols = Vec::new();
        let mut ranges = Vec::new();
        for r in &lower {
            ranges.push(cols.len()..cols.len() + r.len());
            cols.extend_from_slice(r);
        }
        let mut s = Sweep::new(n, &cols, |i| ranges[i].clone());
        let kinds: Vec<Kind> = s.runs.iter().map(|r| r.kind).collect();
        assert_eq!(kinds, [Kind::Empty, Kind::Single, Kind::General, Kind::Empty]);
        for (k, v) in s.vals.iter_mut().enumerate() {
            *v = 0.3 + 0.1 * k as f64;
        }
        let b: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let mut z = b.clone();
        s.forward(&mut z);
        let mut expect = b.clone();
        for i in 0..n {
            for (k, &c) in lower[i].iter().enumerate() {
                expect[i] -= s.vals[ranges[i].start + k] * expect[c];
            }
        }
        assert_eq!(z, expect);
        // The same rows as an upper factor (columns mirrored to later rows).
        let mirrored: Vec<usize> = cols.iter().map(|&c| n - 1 - c).collect();
        let mut upper = Sweep::new(n, &mirrored, |i| ranges[n - 1 - i].clone());
        upper.vals.copy_from_slice(&s.vals);
        let mut zu = b.clone();
        upper.backward(&mut zu);
        let mut expect = b;
        for i in (0..n).rev() {
            let r = &ranges[n - 1 - i];
            for p in r.clone() {
                expect[i] -= upper.vals[upper.row_start(i) + p - r.start] * expect[mirrored[p]];
            }
        }
        assert_eq!(zu, expect);
    }
}
