//! Costs and likelihoods of fitting problems.
