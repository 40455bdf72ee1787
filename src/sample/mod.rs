//! MCMC samplers behind one trait, with convergence diagnostics.
