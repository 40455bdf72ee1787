//! Finite-volume meshes: cell-centred, uniform within each domain.

/// A uniform 1-D cell-centred mesh on `[start, start + length]`.
#[derive(Clone, Debug)]
pub struct Mesh1D {
    /// Cell centres (m).
    pub centres: Vec<f64>,
    /// Cell width (m).
    pub dx: f64,
}

impl Mesh1D {
    pub fn uniform(start: f64, length: f64, n: usize) -> Self {
        let dx = length / n as f64;
        Self { centres: (0..n).map(|i| start + (i as f64 + 0.5) * dx).collect(), dx }
    }

    pub fn len(&self) -> usize {
        self.centres.len()
    }
}

/// Finite-volume operator for diffusion in a sphere of radius `R`, with `n` uniform shells.
///
/// For shell `k` with faces `r_{k-1/2}, r_{k+1/2}`, the discrete divergence is
/// `(r_{k+1/2}^2 N_{k+1/2} - r_{k-1/2}^2 N_{k-1/2}) / ((r_{k+1/2}^3 - r_{k-1/2}^3) / 3)`,
/// which conserves `sum_k c_k V_k` exactly.
#[derive(Clone, Debug)]
pub struct SphereMesh {
    /// Particle radius R (m).
    pub radius: f64,
    /// Shell width (m).
    pub dr: f64,
    /// Shell-centre radii (m).
    pub centres: Vec<f64>,
    /// `r_{k+1/2}^2 / V_k` for the outer face of shell k (1/m), V_k = shell volume / (4 pi).
    outer: Vec<f64>,
    /// `r_{k-1/2}^2 / V_k` for the inner face of shell k (1/m).
    inner: Vec<f64>,
    /// Shell volumes over 4 pi (m^3), so that `4 pi sum c_k vol_k` is the particle's content.
    pub volumes: Vec<f64>,
}

impl SphereMesh {
    pub fn new(radius: f64, n: usize) -> Self {
        let dr = radius / n as f64;
        let edge = |k: usize| k as f64 * dr;
        let volumes: Vec<f64> =
            (0..n).map(|k| (edge(k + 1).powi(3) - edge(k).powi(3)) / 3.0).collect();
        let outer = (0..n).map(|k| edge(k + 1).powi(2) / volumes[k]).collect();
        let inner = (0..n).map(|k| edge(k).powi(2) / volumes[k]).collect();
        let centres = (0..n).map(|k| (k as f64 + 0.5) * dr).collect();
        Self { radius, dr, centres, outer, inner, volumes }
    }

    pub fn len(&self) -> usize {
        self.centres.len()
    }

    /// Writes `dc/dt` for diffusivity `diff` (m^2/s) and outward surface molar flux `flux`
    /// (mol/(m^2 s)), i.e. `-D dc/dr = flux` at `r = R`.
    pub fn diffusion(&self, c: &[f64], diff: f64, flux: f64, out: &mut [f64]) {
        self.stressed_diffusion(c, diff, None, flux, out);
    }

    /// [`Self::diffusion`] with stress-induced diffusion when `stress = Some((theta, c_0))`:
    /// the diffusivity at shell `k` is `diff (1 + theta (c_k - c_0))` (`theta` in m^3/mol,
    /// `c_0` in mol/m^3) and at an interior face the harmonic mean of its two shells' (as
    /// PyBaMM averages a diffusivity multiplying a gradient). The surface flux is imposed
    /// as given.
    pub fn stressed_diffusion(&self, c: &[f64], diff: f64, stress: Option<(f64, f64)>, flux: f64, out: &mut [f64]) {
        let n = c.len();
        let g = diff / self.dr;
        let (outer, inner, out) = (&self.outer[..n], &self.inner[..n], &mut out[..n]);
        let factor = |k: usize| stress.map_or(1.0, |(theta, c0)| 1.0 + theta * (c[k] - c0));
        // `D dc/dr` at the inner face of the current shell (zero at the centre).
        let mut left = 0.0;
        for k in 0..n - 1 {
            let face = match stress {
                None => g,
                Some(_) => {
                    let (a, b) = (factor(k), factor(k + 1));
                    g * 2.0 * a * b / (a + b)
                }
            };
            let right = face * (c[k + 1] - c[k]);
            out[k] = outer[k] * right - inner[k] * left;
            left = right;
        }
        out[n - 1] = outer[n - 1] * -flux - inner[n - 1] * left;
    }

    /// Surface concentration by linear extrapolation of the two outermost shell values
    /// (PyBaMM's default boundary-value scheme).
    pub fn surface(&self, c: &[f64]) -> f64 {
        let n = c.len();
        if n < 2 {
            return c[0];
        }
        c[n - 1] + 0.5 * (c[n - 1] - c[n - 2])
    }

    /// Volume-averaged concentration (mol/m^3).
    pub fn average(&self, c: &[f64]) -> f64 {
        let v: f64 = self.volumes.iter().sum();
        c.iter().zip(&self.volumes).map(|(a, b)| a * b).sum::<f64>() / v
    }
}
