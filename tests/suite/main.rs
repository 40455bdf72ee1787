//! The integration tests, one module per concern, compiled into one test binary: one link
//! against the library instead of one per file, and the generic solver and fitting code
//! instantiated once (CI compiled 52 binaries before). `cargo test --release --test suite
//! <module>::` runs one module. The PyBaMM-made diagnosis cases stay in their own binary,
//! `tests/diagnosis_bench.rs`, as the README runs them on their own.

mod cli_support;
mod common;

mod architecture;
mod asymmetric_kinetics;
mod bad_input;
mod bpx;
mod builder;
mod cccv;
mod cell_format;
mod cli;
mod cycle;
mod cycler_formats;
mod cycler_never_panics;
mod design;
mod design_study;
mod diagnose;
mod diagnosis_tolerance;
mod ecm;
mod eis;
mod energy_quadrature;
mod experiment_design;
mod fade_fit;
mod fast_charge;
mod fields;
mod fitting;
mod format_study;
mod global_sensitivity;
mod identifiability;
mod integrator;
mod joint_fit;
mod lam;
mod life_design;
mod limits;
mod np_and_heat_limits;
mod optimisers;
mod output_safety;
mod output_states;
mod parameterisation;
mod pareto_study;
mod physics;
mod plating;
mod power;
mod profile_likelihood;
mod psd;
mod psd_reference;
mod pulse_power;
mod readers_never_panic;
mod readme;
mod refused_inputs;
mod reported_searches;
mod recorded_temperature;
mod recording_sign;
mod reference_curves;
mod samplers;
mod sei;
mod solver_stats;
mod study;
mod sweep_shards;
mod sweep_study;
mod thermal;
mod thermal_reference;
mod timed_energy;
mod unread_parameters;
