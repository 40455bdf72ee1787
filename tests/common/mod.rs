//! Helpers shared by the integration tests.
#![allow(dead_code)]

use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::ParameterSet;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, Solution, simulate};

/// Reference curve shipped in tests/data (copied from ../shared/reference, PyBaMM 26.10).
pub fn reference(name: &str) -> Recording {
    let path = format!("{}/tests/data/{name}.csv", env!("CARGO_MANIFEST_DIR"));
    Recording::from_csv(path.as_ref()).expect("reference curve")
}

pub fn pulse() -> Protocol {
    let path = format!("{}/protocols/pulse_1C.toml", env!("CARGO_MANIFEST_DIR"));
    toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Runs `kind` on `p` through `protocol`, with outputs at `t_eval` when given.
pub fn run(
    kind: ModelKind,
    submodels: Submodels,
    mesh: MeshSizes,
    p: &ParameterSet,
    protocol: &Protocol,
    t_eval: Option<Vec<f64>>,
    keep_states: bool,
) -> Solution {
    let mut b = ModelBuilder::new(kind, submodels, mesh);
    let built = b.build(p).expect("build");
    let opts = SimOptions { t_eval, keep_states, ..SimOptions::for_cell(p) };
    simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).expect("simulate")
}

pub fn uniform_mesh(n: usize) -> MeshSizes {
    MeshSizes { x_n: n, x_s: n, x_p: n, r_n: n, r_p: n }
}
