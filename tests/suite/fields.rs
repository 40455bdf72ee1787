//! Spatial fields: the electrolyte salt is conserved, the profiles point the way a discharge
//! drives them, and the field files are written.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{Field, ModelKind, Submodels};
use cellstudio::params::{ParameterSet, chen2020};
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, States, Solution, simulate};

fn run(kind: ModelKind, p: &ParameterSet) -> (Vec<Vec<Field>>, Solution) {
    let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
    let built = b.build(p).unwrap();
    let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(p) };
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(1.0), &opts, None).unwrap();
    let fields = sol.states.iter().map(|y| built.model.fields(y)).collect();
    (fields, sol)
}

fn field<'a>(fields: &'a [Field], name: &str) -> &'a Field {
    fields.iter().find(|f| f.name == name).unwrap_or_else(|| panic!("no field {name}"))
}

/// Salt in the pores, sum of eps c_e dx (mol/m^2), with the region of each x centre.
fn salt(p: &ParameterSet, ce: &Field) -> f64 {
    let (ln, ls) = (p.negative.thickness, p.separator.thickness);
    let regions = [(0.0, ln, p.negative.porosity), (ln, ln + ls, p.separator.porosity), (ln + ls, ln + ls + p.positive.thickness, p.positive.porosity)];
    regions
        .iter()
        .map(|&(a, b, eps)| {
            let inside: Vec<f64> = ce.position.iter().zip(&ce.value).filter(|&(&x, _)| x > a && x < b).map(|(_, &c)| c).collect();
            eps * (b - a) / inside.len() as f64 * inside.iter().sum::<f64>()
        })
        .sum()
}

#[test]
fn electrolyte_salt_is_conserved_and_discharge_profiles_point_the_right_way() {
    let p = chen2020();
    for kind in [ModelKind::Spme, ModelKind::Dfn] {
        let (fields, sol) = run(kind, &p);
        let initial = salt(&p, field(&fields[0], "electrolyte concentration"));
        let expected = p.electrolyte.initial_concentration
            * (p.negative.porosity * p.negative.thickness + p.separator.porosity * p.separator.thickness + p.positive.porosity * p.positive.thickness);
        assert!((initial - expected).abs() < 1e-12 * expected, "{kind}: {initial} vs {expected}");
        let worst = fields.iter().map(|f| (salt(&p, field(f, "electrolyte concentration")) / initial - 1.0).abs()).fold(0.0, f64::max);
        println!("{kind}: worst relative salt drift over {} outputs {worst:.1e}", sol.time.len());
        assert!(worst < 1e-9, "{kind}: salt drifts by {worst:e}");
        // Discharge: lithium ions leave the negative electrode and are consumed in the positive.
        let ce = field(fields.last().unwrap(), "electrolyte concentration");
        assert!(ce.position.windows(2).all(|w| w[1] > w[0]));
        assert!(ce.value[0] > 1.5 * ce.value[ce.value.len() - 1], "{kind}: {:?}", ce.value);
    }
    // DFN: the reaction runs ahead next to the separator, so the negative particles there are
    // emptier at the end of a 1C discharge than those at the current collector.
    let (fields, _) = run(ModelKind::Dfn, &p);
    let surf = field(fields.last().unwrap(), "negative particle surface concentration");
    assert_eq!(surf.value.len(), MeshSizes::default().x_n);
    assert!(surf.value[surf.value.len() - 1] < surf.value[0], "{:?}", surf.value);
}

#[test]
fn simulate_writes_the_fields_csv_and_one_plot_per_field() {
    let p = chen2020();
    let (_, sol) = run(ModelKind::Spm, &p);
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let written = cellstudio::report::fields::write_fields(built.model.as_ref(), &sol, &dir, "spm").unwrap();
    assert_eq!(written.len(), 3, "{written:?}");
    let csv = std::fs::read_to_string(&written[0]).unwrap();
    // 5 snapshots x 2 particles x the shells of each
    let shells = MeshSizes::default().r_n + MeshSizes::default().r_p;
    assert_eq!(csv.lines().count(), 1 + 5 * shells);
    assert!(csv.lines().nth(1).unwrap().starts_with("0,negative particle concentration,mol/m^3,r,"));
    // Without kept states the error names the option.
    let bare = Solution { states: Vec::new(), ..sol };
    let err = cellstudio::report::fields::write_fields(built.model.as_ref(), &bare, &dir, "spm").unwrap_err().to_string();
    assert!(err.contains("states"), "{err}");
}
