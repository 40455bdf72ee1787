#[path = "common/solver_case.rs"]
mod solver_case;
use cellstudio::simulation::simulate;
use solver_case::SolverCase;
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let SolverCase { protocol, options, params, mut builder, .. } = SolverCase::new(&a[0], &a[1], &a[2], "1");
    let built = builder.build(&params).unwrap();
    let s = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &options, None).unwrap();
    println!("steps {}", s.stats.steps);
}
