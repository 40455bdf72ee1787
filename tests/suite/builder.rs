//! The geometry-aware builder rebuilds only when a geometric parameter changes, and a re-used
//! build gives the same answer as a fresh one.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

const N: usize = 5;

#[test]
fn changing_diffusivity_costs_one_build() {
    let mut b = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
    let mut p = chen2020();
    let mut capacities = Vec::new();
    for k in 0..N {
        p.negative.diffusivity = 3.3e-14 * (1.0 + k as f64);
        p.positive.rate_constant = 3.42e-6 * (1.0 + 0.1 * k as f64);
        let built = b.build(&p).unwrap();
        let sol = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(2.0), &SimOptions::for_cell(&p), None).unwrap();
        capacities.push(sol.final_capacity());
    }
    assert_eq!(b.rebuild_count(), 1);
    // The parameter change reached the model: faster diffusion gives more capacity at 2C.
    assert!(capacities.windows(2).all(|w| w[1] > w[0]), "{capacities:?}");
}

#[test]
fn changing_thickness_costs_a_build_each() {
    let mut b = ModelBuilder::new(ModelKind::Spme, Submodels::default(), MeshSizes::default());
    let mut p = chen2020();
    for k in 0..N {
        p.positive.thickness = 60e-6 + 5e-6 * k as f64;
        b.build(&p).unwrap();
    }
    assert_eq!(b.rebuild_count(), N);
    // Same geometry again: no rebuild.
    b.build(&p).unwrap();
    assert_eq!(b.rebuild_count(), N);
}

#[test]
fn reused_build_matches_fresh_build() {
    let mut p = chen2020();
    let mut reused = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
    reused.build(&p).unwrap();
    p.negative.diffusivity = 1e-14;
    p.electrolyte.transference_number = 0.3;
    let a = reused.build(&p).unwrap();
    let opts = SimOptions::for_cell(&p);
    let va = simulate(a.model.as_ref(), &mut a.workspace, &Protocol::discharge(1.0), &opts, None).unwrap();
    let mut fresh = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
    let b = fresh.build(&p).unwrap();
    let vb = simulate(b.model.as_ref(), &mut b.workspace, &Protocol::discharge(1.0), &opts, None).unwrap();
    assert_eq!(reused.rebuild_count(), 1);
    assert_eq!(va.voltage, vb.voltage);
}
