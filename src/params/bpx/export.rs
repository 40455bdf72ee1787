//! Export: a [`ParameterSet`] as a BPX v0.5 document.

use serde_json::{Map, Value, json};

use super::super::ParameterSet;
use super::super::function::Function1D;
use super::super::set::FARADAY;
use super::keys::{self, BPX_VERSION, SOC_KEY, USER_DEFINED_FIELDS, USER_PREFIX, mean_heat_capacity};
use super::tabulate::{ELECTROLYTE_RANGE, ELECTROLYTE_TOLERANCE, ENTROPIC_TOLERANCE, OCP_TOLERANCE, Tolerance, sample};
use super::window::stoichiometry_windows;
use crate::error::Error;

/// Writes `p` as a BPX v0.5 JSON document (model "DFN").
///
/// Built-in functions are sampled into `{"x", "y"}` tables (OCPs over stoichiometry [0, 1],
/// electrolyte properties over 0..4000 mol/m^3). The stoichiometry windows are those at which
/// the open-circuit voltage meets the cut-offs with the lithium inventory of the initial state
/// ([`stoichiometry_windows`](super::stoichiometry_windows)); the initial state of charge and
/// every field without a BPX equivalent go under `User-defined` as `cellstudio.*`, so that
/// [`from_bpx_json`](super::from_bpx_json) restores every scalar.
pub fn to_bpx_json(p: &ParameterSet) -> Result<String, Error> {
    p.validate()?;
    for (field, v) in [("electrolyte.diffusivity_factor", p.electrolyte.diffusivity_factor), ("electrolyte.conductivity_factor", p.electrolyte.conductivity_factor)] {
        if v != 1.0 {
            return Err(Error::invalid(field, v, "BPX has no transport factor: export the set with the factor at 1 (scale the function instead)"));
        }
    }
    let ce0 = p.electrolyte.initial_concentration;
    let windows = stoichiometry_windows(p)?;
    let c = &p.cell;
    let t = &p.thermal;
    let budget = p.budget();
    let density = budget.mass / budget.volume;
    let heat_capacity = mean_heat_capacity(p)? / density;

    let cell = json!({
        keys::AREA: num("cell area", c.area())?,
        keys::PAIRS: 1,
        keys::EXTERNAL_AREA: num("thermal.cooling_area", t.cooling_area)?,
        keys::VOLUME: num("thermal.cell_volume", t.cell_volume)?,
        keys::LOWER_CUTOFF: num("cell.lower_cutoff", c.lower_cutoff)?,
        keys::UPPER_CUTOFF: num("cell.upper_cutoff", c.upper_cutoff)?,
        keys::CAPACITY: num("cell.nominal_capacity", c.nominal_capacity)?,
        keys::AMBIENT_T: num("thermal.ambient_temperature", t.ambient_temperature)?,
        keys::INITIAL_T: num("thermal.initial_temperature", t.initial_temperature)?,
        keys::REFERENCE_T: num("thermal.reference_temperature", t.reference_temperature)?,
        keys::DENSITY: num("cell density", density)?,
        keys::HEAT_CAPACITY: num("cell specific heat capacity", heat_capacity)?,
    });
    let e = &p.electrolyte;
    let electrolyte_tol = Tolerance::Relative(ELECTROLYTE_TOLERANCE);
    let electrolyte = json!({
        keys::ELECTROLYTE_C0: num("electrolyte.initial_concentration", ce0)?,
        keys::TRANSFERENCE: num("electrolyte.transference_number", e.transference_number)?,
        keys::DIFFUSIVITY: function_value(&e.diffusivity, ELECTROLYTE_RANGE, electrolyte_tol),
        keys::DIFFUSIVITY_EA: num("electrolyte.activation_energy", e.activation_energy)?,
        keys::CONDUCTIVITY: function_value(&e.conductivity, ELECTROLYTE_RANGE, electrolyte_tol),
        keys::CONDUCTIVITY_EA: num("electrolyte.activation_energy", e.activation_energy)?,
    });
    let electrode = |side: &str, window: (f64, f64)| -> Result<Value, Error> {
        let el = if side == "negative" { &p.negative } else { &p.positive };
        let f = |name: &str| format!("{side}.{name}");
        Ok(json!({
            keys::THICKNESS: num(&f("thickness"), el.thickness)?,
            keys::RADIUS: num(&f("particle_radius"), el.particle_radius)?,
            keys::SURFACE_AREA: num(&f("active_fraction"), el.surface_area_density())?,
            keys::POROSITY: num(&f("porosity"), el.porosity)?,
            keys::TRANSPORT_EFFICIENCY: num(&f("bruggeman_electrolyte"), el.porosity.powf(el.bruggeman_electrolyte))?,
            keys::CONDUCTIVITY: num(&f("conductivity"), el.conductivity * (1.0 - el.porosity).powf(el.bruggeman_solid))?,
            keys::MAX_CONCENTRATION: num(&f("max_concentration"), el.max_concentration)?,
            keys::MIN_STO: num(&f("initial_concentration"), window.0)?,
            keys::MAX_STO: num(&f("initial_concentration"), window.1)?,
            keys::DIFFUSIVITY: num(&f("diffusivity"), el.diffusivity)?,
            keys::DIFFUSIVITY_EA: num(&f("diffusivity_activation_energy"), el.diffusivity_activation_energy)?,
            keys::OCP: function_value(&el.ocp, (0.0, 1.0), Tolerance::Absolute(OCP_TOLERANCE)),
            keys::ENTROPIC: match &el.ocp_entropic_change {
                Function1D::Constant { value } => num(&f("ocp_entropic_change"), value * el.ocp_entropic_change_factor)?,
                _ => {
                    let (x, y) = sample(&|v| el.entropic_change(v), (0.0, 1.0), Tolerance::Absolute(ENTROPIC_TOLERANCE));
                    json!({ "x": x, "y": y })
                }
            },
            keys::RATE: num(&f("rate_constant"), el.rate_constant * el.max_concentration * ce0.sqrt() / FARADAY)?,
            keys::RATE_EA: num(&f("rate_activation_energy"), el.rate_activation_energy)?,
        }))
    };
    let s = &p.separator;
    let separator = json!({
        keys::THICKNESS: num("separator.thickness", s.thickness)?,
        keys::POROSITY: num("separator.porosity", s.porosity)?,
        keys::TRANSPORT_EFFICIENCY: num("separator.bruggeman", s.porosity.powf(s.bruggeman))?,
    });
    let mut user = Map::new();
    for field in USER_DEFINED_FIELDS {
        user.insert(format!("{USER_PREFIX}{field}"), num(field, p.get(field)?)?);
    }
    user.insert(SOC_KEY.into(), num("initial state of charge", windows.soc)?);

    let doc = json!({
        keys::HEADER: {
            "BPX": BPX_VERSION,
            "Title": p.name,
            "Model": "DFN",
        },
        keys::PARAMETERISATION: {
            keys::CELL: cell,
            keys::ELECTROLYTE: electrolyte,
            keys::NEGATIVE: electrode("negative", windows.negative)?,
            keys::POSITIVE: electrode("positive", windows.positive)?,
            keys::SEPARATOR: separator,
            keys::USER_DEFINED: user,
        },
    });
    serde_json::to_string_pretty(&doc)
        .map_err(|e| Error::Parse { path: "BPX JSON".into(), message: e.to_string() })
}

fn num(field: &str, v: f64) -> Result<Value, Error> {
    if v.is_finite() {
        Ok(json!(v))
    } else {
        Err(Error::invalid(field, v, "must be finite to export to BPX"))
    }
}

fn function_value(f: &Function1D, range: (f64, f64), tolerance: Tolerance) -> Value {
    match f {
        Function1D::Constant { value } => json!(value),
        Function1D::Table { x, y } => json!({ "x": x, "y": y }),
        _ => {
            let (x, y) = sample(&|v| f.eval(v), range, tolerance);
            json!({ "x": x, "y": y })
        }
    }
}
