//! The command line the solver-timing examples share: MODEL (spm|spme|dfn), CASE (a C-rate
//! such as `1C`, or `pulse` for `protocols/pulse_1C.toml`), RTOL (= atol) and REPEATS; and the
//! Chen 2020 model built once on the default mesh with those tolerances.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::{ParameterSet, chen2020};
use cellstudio::protocol::Protocol;
use cellstudio::simulation::SimOptions;

/// One timed configuration.
pub struct SolverCase {
    pub protocol: Protocol,
    pub options: SimOptions,
    pub params: ParameterSet,
    pub builder: ModelBuilder,
    pub repeats: usize,
}

impl SolverCase {
    /// Parses MODEL CASE RTOL REPEATS.
    pub fn new(model: &str, case: &str, rtol: &str, repeats: &str) -> Self {
        let kind: ModelKind = model.parse().expect("model");
        let rtol: f64 = rtol.parse().expect("rtol");
        let repeats: usize = repeats.parse().expect("repeats");
        let protocol = match case {
            "pulse" => toml::from_str(&std::fs::read_to_string("protocols/pulse_1C.toml").expect("protocol")).expect("protocol"),
            c => Protocol::discharge(c.trim_end_matches('C').parse().expect("C-rate")),
        };
        let p = chen2020();
        let builder = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let mut options = SimOptions::for_cell(&p);
        options.solver.set_tolerance(rtol);
        Self { protocol, options, params: p, builder, repeats }
    }
}
