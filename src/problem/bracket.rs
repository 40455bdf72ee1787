//! The edge of a feasible range: the largest value at which a monotone test still holds
//! (the largest pulse current above a voltage limit, the fastest charge without plating).

use crate::error::Error;

/// Brackets the edge of `holds` (true below it, false above): doubles `hi` from `start`
/// while the test holds (`lo` follows), erring with `too_far` once `hi` exceeds `limit`,
/// then bisects to a bracket narrower than `tolerance * hi`. Returns `(lo, hi)`: `lo` the
/// largest value known to hold (or the given `lo`), `hi` the smallest known not to.
pub fn edge(
    mut holds: impl FnMut(f64) -> Result<bool, Error>,
    lo: f64,
    start: f64,
    limit: f64,
    tolerance: f64,
    too_far: impl Fn(f64) -> Error,
) -> Result<(f64, f64), Error> {
    let (mut lo, mut hi) = (lo, start);
    while holds(hi)? {
        lo = hi;
        hi *= 2.0;
        if hi > limit {
            return Err(too_far(hi));
        }
    }
    while hi - lo > tolerance * hi {
        let mid = 0.5 * (lo + hi);
        if holds(mid)? { lo = mid } else { hi = mid }
    }
    Ok((lo, hi))
}

#[cfg(test)]
mod tests {
    #[test]
    fn finds_the_edge_of_a_step() {
        let (lo, hi) = super::edge(|x| Ok(x <= 3.7), 0.0, 1.0, 100.0, 1e-6, |_| unreachable!()).unwrap();
        assert!(lo <= 3.7 && hi > 3.7 && hi - lo <= 1e-6 * hi);
        assert!(super::edge(|_| Ok(true), 0.0, 1.0, 100.0, 1e-6, |x| crate::error::Error::invalid("x", x, "too far")).is_err());
    }
}
