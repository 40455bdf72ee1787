//! Model-discrepancy diagnosis: locate a mismatch, name the missing physics, refit.
