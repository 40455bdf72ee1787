//! Cell formats: a fixed outer envelope (a cylindrical can or a pouch) that the electrode
//! stack fills, so the electrode area, and with it capacity, mass and volume, follow from the
//! stack thickness as in a real cell. `free_area` keeps the parameter set's plate area fixed
//! (the PyBaMM/PyBOP convention).
//!
//! A cylindrical cell is a wound jelly roll of repeat units (separator, double-coated
//! negative, separator, double-coated positive) filling the annulus between the mandrel and
//! the can wall; a pouch is a stack of double-coated electrodes (negatives outermost) inside
//! an aluminium-laminate pouch.

use serde::{Deserialize, Serialize};

use super::check::{non_negative, positive};
use super::mass::{MassBasis, MassComponent, Part, StackAreas, component};
use super::set::ParameterSet;
use crate::error::Error;

/// The format named in a study's `[cell] format`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FormatName {
    /// The parameter set's plate area, fixed; packaging as fractions of the stack.
    #[default]
    FreeArea,
    /// A cylindrical can, by default the 21700 (`[cell.can]` changes its dimensions).
    #[serde(rename = "cylindrical_21700")]
    Cylindrical21700,
    /// A stacked pouch (`[cell.pouch]` gives its dimensions).
    Pouch,
}

/// A cylindrical can and what it holds besides the jelly roll (SI units).
///
/// Defaults: a 21700 (LG M50) with published outer dimensions and literature assumptions:
/// - `diameter` 21.0 mm, `height` 70.0 mm: the 21700 designation (LG Chem INR21700 M50
///   product specification: 21.1 mm max, 70.15 mm max).
/// - `wall` 0.25 mm nickel-plated steel: within the 0.22-0.34 mm typical of 21700 cans
///   (batterydesign.net, "Cylindrical cell electrode estimation").
/// - `can_density` 7900 kg/m^3: nickel-plated steel (Intercalation Station, "Back of the
///   Battery 4: cylindrical cells", 21700 example: 7.9 g/cm^3).
/// - `mandrel_diameter` 2.5 mm hollow core (same source: 2.5 mm; batterydesign.net: 2 mm for
///   an 18650).
/// - `headspace` 6 mm of the height not taken by coated electrode: can bottom, top cap,
///   vent/CID, insulators and tab bends (same source: 0.6 cm).
/// - `extra_mass` 4 g: top cap, vent, CID, gasket, insulators and tabs (same source: 4 ± 2 g).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Cylindrical {
    /// Outer diameter (m).
    pub diameter: f64,
    /// Outer height (m).
    pub height: f64,
    /// Can wall and bottom thickness (m).
    pub wall: f64,
    /// Can material density (kg/m^3).
    pub can_density: f64,
    /// Diameter of the hollow core the roll is wound on (m).
    pub mandrel_diameter: f64,
    /// Height not taken by coated electrode (m).
    pub headspace: f64,
    /// Top cap, vent, insulators and tabs (kg).
    pub extra_mass: f64,
}

impl Default for Cylindrical {
    fn default() -> Self {
        Self { diameter: 21.0e-3, height: 70.0e-3, wall: 0.25e-3, can_density: 7900.0, mandrel_diameter: 2.5e-3, headspace: 6.0e-3, extra_mass: 4.0e-3 }
    }
}

/// A stacked pouch cell (SI units). Outer dimensions have no default.
///
/// Defaults: `wall` 113 um aluminium laminate (nylon 25 um / Al 40 um / PP 40 um plus
/// adhesive: the common 88-153 um pouch films), `laminate_density` 1600 kg/m^3 (the
/// thickness-weighted mean of those layers), `seal` 5 mm heat-sealed edge on each side
/// (tabs leave through one), `tab_mass` 2 g for both tabs (assumed).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pouch {
    /// Outer length along the tabs' direction (m).
    pub length: f64,
    /// Outer width (m).
    pub width: f64,
    /// Outer thickness (m).
    pub thickness: f64,
    /// Laminate thickness of each of the two sheets (m).
    #[serde(default = "pouch_wall")]
    pub wall: f64,
    /// Laminate density (kg/m^3).
    #[serde(default = "laminate_density")]
    pub laminate_density: f64,
    /// Sealed edge on each of the four sides (m).
    #[serde(default = "pouch_seal")]
    pub seal: f64,
    /// Both tabs (kg).
    #[serde(default = "tab_mass")]
    pub tab_mass: f64,
}

fn pouch_wall() -> f64 {
    113e-6
}
fn laminate_density() -> f64 {
    1600.0
}
fn pouch_seal() -> f64 {
    5e-3
}
fn tab_mass() -> f64 {
    2e-3
}

/// A cell format with its dimensions.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum CellFormat {
    #[default]
    FreeArea,
    Cylindrical(Cylindrical),
    Pouch(Pouch),
}

/// Where a format puts the stack.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sizing {
    /// Sandwich (negative/separator/positive) area the model sees (m^2).
    pub area: f64,
    /// Coated electrode height (m).
    pub electrode_height: f64,
    /// Wound strip length (m), cylindrical only.
    pub strip_length: Option<f64>,
    /// Positive electrode layers, pouch only.
    pub layers: Option<usize>,
    /// Outer volume (m^3).
    pub volume: f64,
}

/// One repeat unit: separator, double-coated negative, separator, double-coated positive (m).
fn repeat_thickness(p: &ParameterSet) -> f64 {
    let c = &p.cell;
    2.0 * (p.negative.thickness + p.separator.thickness + p.positive.thickness) + c.negative_collector_thickness + c.positive_collector_thickness
}

impl Cylindrical {
    /// Checks every dimension; errors name `cell.can.<field>`.
    pub fn validate(&self) -> Result<(), Error> {
        positive("cell.can.diameter", self.diameter)?;
        positive("cell.can.height", self.height)?;
        positive("cell.can.wall", self.wall)?;
        positive("cell.can.can_density", self.can_density)?;
        non_negative("cell.can.mandrel_diameter", self.mandrel_diameter)?;
        non_negative("cell.can.headspace", self.headspace)?;
        non_negative("cell.can.extra_mass", self.extra_mass)?;
        if self.mandrel_diameter >= self.diameter - 2.0 * self.wall {
            return Err(Error::invalid("cell.can.mandrel_diameter", self.mandrel_diameter, format!("must be below the can's inner diameter {} m", self.diameter - 2.0 * self.wall)));
        }
        if self.headspace >= self.height {
            return Err(Error::invalid("cell.can.headspace", self.headspace, format!("must be below cell.can.height = {} m", self.height)));
        }
        Ok(())
    }

    /// Inner radius of the can: the jelly roll's outer radius (m).
    fn roll_radius(&self) -> f64 {
        0.5 * self.diameter - self.wall
    }

    /// The jelly roll: strip length `pi (R^2 - r^2) / t` for the repeat thickness `t`, and a
    /// sandwich area of `h (2 l - 2 pi R - 2 pi r)`: the innermost positive face and the
    /// outermost negative face have no counter-electrode (coated on one side only).
    fn size(&self, p: &ParameterSet) -> Result<Sizing, Error> {
        self.validate()?;
        let (big_r, r) = (self.roll_radius(), 0.5 * self.mandrel_diameter);
        let t = repeat_thickness(p);
        let length = std::f64::consts::PI * (big_r * big_r - r * r) / t;
        let height = self.height - self.headspace;
        let area = height * (2.0 * length - 2.0 * std::f64::consts::PI * (big_r + r));
        if !(area > 0.0) {
            return Err(Error::invalid(
                "cell.format",
                t,
                format!("cylindrical: a {:.1} um repeat unit does not fit one turn between the mandrel ({:.2} mm) and the can wall ({:.2} mm radius)", t * 1e6, r * 1e3, big_r * 1e3),
            ));
        }
        let volume = std::f64::consts::PI * 0.25 * self.diameter * self.diameter * self.height;
        Ok(Sizing { area, electrode_height: height, strip_length: Some(length), layers: None, volume })
    }

    fn mass_basis(&self, p: &ParameterSet, s: &Sizing) -> MassBasis {
        let strip = s.strip_length.unwrap_or(0.0) * s.electrode_height;
        let areas = StackAreas { coating: s.area, separator: 2.0 * strip, negative_collector: strip, positive_collector: strip };
        let mut components = p.stack_components(areas);
        let (outer, inner) = (0.5 * self.diameter, self.roll_radius());
        let pi = std::f64::consts::PI;
        let steel = pi * (outer * outer - inner * inner) * self.height + pi * inner * inner * self.wall;
        let wall = format!("{:.2} mm wall (cell.can.wall)", self.wall * 1e3);
        components.push(component("can (side wall and bottom)", Part::Packaging, self.can_density, steel, &wall));
        components.push(allowance("top cap, vent, insulators and tabs", self.extra_mass, "cell.can.extra_mass"));
        MassBasis::new(
            format!(
                "Mass basis: cylindrical {:.1} x {:.1} mm can; jelly roll {:.3} m long and {:.1} mm high; coatings over the {:.4} m^2 sandwich area, two separators and each collector once over the strip; electrolyte only in the pores.",
                self.diameter * 1e3, self.height * 1e3, s.strip_length.unwrap_or(0.0), s.electrode_height * 1e3, s.area
            ),
            components,
            s.volume,
            "outer cylinder".into(),
        )
    }
}

fn allowance(name: &str, mass: f64, field: &str) -> MassComponent {
    MassComponent { name: name.into(), part: Part::Packaging, density: None, volume: None, mass, source: format!("allowance ({field})") }
}

impl Pouch {
    /// Checks every dimension; errors name `cell.pouch.<field>`.
    pub fn validate(&self) -> Result<(), Error> {
        positive("cell.pouch.length", self.length)?;
        positive("cell.pouch.width", self.width)?;
        positive("cell.pouch.thickness", self.thickness)?;
        positive("cell.pouch.wall", self.wall)?;
        positive("cell.pouch.laminate_density", self.laminate_density)?;
        non_negative("cell.pouch.seal", self.seal)?;
        non_negative("cell.pouch.tab_mass", self.tab_mass)?;
        for (field, v) in [("cell.pouch.length", self.length), ("cell.pouch.width", self.width)] {
            if v <= 2.0 * self.seal {
                return Err(Error::invalid(field, v, format!("leaves no room inside two {} m seals", self.seal)));
            }
        }
        Ok(())
    }

    /// Footprint of one electrode inside the seals (m^2).
    fn footprint(&self) -> f64 {
        (self.length - 2.0 * self.seal) * (self.width - 2.0 * self.seal)
    }

    /// The stack: `N` double-coated positives between `N + 1` negatives (the outer two
    /// coated on their inner face only) fill `N t + t_Cu` of the inner thickness, so
    /// `N = floor((T - 2 wall - t_Cu) / t)` and the sandwich area is `2 N` footprints.
    fn size(&self, p: &ParameterSet) -> Result<Sizing, Error> {
        self.validate()?;
        let t = repeat_thickness(p);
        let room = self.thickness - 2.0 * self.wall - p.cell.negative_collector_thickness;
        let layers = if room > 0.0 { (room / t).floor() as usize } else { 0 };
        if layers == 0 {
            return Err(Error::invalid(
                "cell.pouch.thickness",
                self.thickness,
                format!("holds no electrode layer: one {:.1} um repeat unit needs {:.1} um inside two {:.0} um walls", t * 1e6, (t + p.cell.negative_collector_thickness) * 1e6, self.wall * 1e6),
            ));
        }
        let volume = self.length * self.width * self.thickness;
        Ok(Sizing { area: 2.0 * layers as f64 * self.footprint(), electrode_height: self.width - 2.0 * self.seal, strip_length: None, layers: Some(layers), volume })
    }

    fn mass_basis(&self, p: &ParameterSet, s: &Sizing) -> MassBasis {
        let (n, f) = (s.layers.unwrap_or(0) as f64, self.footprint());
        let areas = StackAreas { coating: s.area, separator: 2.0 * n * f, negative_collector: (n + 1.0) * f, positive_collector: n * f };
        let mut components = p.stack_components(areas);
        let laminate = 2.0 * self.length * self.width * self.wall;
        let wall = format!("{:.0} um per sheet (cell.pouch.wall)", self.wall * 1e6);
        components.push(component("pouch laminate (two sheets)", Part::Packaging, self.laminate_density, laminate, &wall));
        components.push(allowance("tabs", self.tab_mass, "cell.pouch.tab_mass"));
        MassBasis::new(
            format!(
                "Mass basis: pouch {:.1} x {:.1} x {:.2} mm; {} double-coated positives between {} negatives; coatings over the {:.4} m^2 sandwich area, separators and collectors over what they cover; electrolyte only in the pores.",
                self.length * 1e3, self.width * 1e3, self.thickness * 1e3, n, n + 1.0, s.area
            ),
            components,
            s.volume,
            "outer box".into(),
        )
    }
}

impl CellFormat {
    /// Sizes the stack of `p` in the format: sets the electrode height and (unrolled) width so
    /// that their product is the sandwich area, and the thermal cell volume. Free area leaves
    /// `p` as it is. Errors when the format cannot hold the stack.
    pub fn apply(&self, p: &mut ParameterSet) -> Result<Option<Sizing>, Error> {
        let s = match self {
            CellFormat::FreeArea => return Ok(None),
            CellFormat::Cylindrical(c) => c.size(p)?,
            CellFormat::Pouch(q) => q.size(p)?,
        };
        p.cell.electrode_height = s.electrode_height;
        p.cell.electrode_width = s.area / s.electrode_height;
        p.thermal.cell_volume = s.volume;
        Ok(Some(s))
    }

    /// The mass basis of a parameter set already sized by [`CellFormat::apply`].
    pub fn mass_basis(&self, p: &ParameterSet) -> Result<MassBasis, Error> {
        let mut sized = p.clone();
        Ok(match (self, self.apply(&mut sized)?) {
            (CellFormat::Cylindrical(c), Some(s)) => c.mass_basis(p, &s),
            (CellFormat::Pouch(q), Some(s)) => q.mass_basis(p, &s),
            _ => p.mass_basis(),
        })
    }

    /// Short name for reports.
    pub fn label(&self) -> String {
        match self {
            CellFormat::FreeArea => "free area".into(),
            CellFormat::Cylindrical(c) => format!("cylindrical {:.1} x {:.1} mm", c.diameter * 1e3, c.height * 1e3),
            CellFormat::Pouch(q) => format!("pouch {:.1} x {:.1} x {:.2} mm", q.length * 1e3, q.width * 1e3, q.thickness * 1e3),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::chen2020;

    #[test]
    fn thicker_coating_shortens_the_roll_and_keeps_the_volume() {
        let f = CellFormat::Cylindrical(Cylindrical::default());
        let (mut a, mut b) = (chen2020(), chen2020());
        b.positive.thickness *= 1.2;
        let (sa, sb) = (f.apply(&mut a).unwrap().unwrap(), f.apply(&mut b).unwrap().unwrap());
        assert!(sb.strip_length.unwrap() < sa.strip_length.unwrap());
        assert!(sb.area < sa.area);
        assert_eq!(sa.volume, sb.volume);
        // The stack fills the same annulus: strip length x repeat thickness is constant.
        let ta = repeat_thickness(&a) * sa.strip_length.unwrap();
        let tb = repeat_thickness(&b) * sb.strip_length.unwrap();
        assert!((ta / tb - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_stack_that_does_not_fit_is_an_error_naming_the_field() {
        let mut p = chen2020();
        let thin = Pouch { length: 0.1, width: 0.06, thickness: 0.3e-3, wall: pouch_wall(), laminate_density: 1600.0, seal: 5e-3, tab_mass: 2e-3 };
        let e = CellFormat::Pouch(thin).apply(&mut p).unwrap_err().to_string();
        assert!(e.contains("cell.pouch.thickness") && e.contains("no electrode layer"), "{e}");
        let bad = Cylindrical { wall: -1e-4, ..Cylindrical::default() };
        let e = CellFormat::Cylindrical(bad).apply(&mut p).unwrap_err().to_string();
        assert!(e.contains("cell.can.wall") && e.contains("-1e-4"), "{e}");
    }

    #[test]
    fn pouch_layers_step_with_the_stack() {
        let pouch = Pouch { length: 0.2, width: 0.1, thickness: 8e-3, wall: pouch_wall(), laminate_density: 1600.0, seal: 5e-3, tab_mass: 2e-3 };
        let mut p = chen2020();
        let s = CellFormat::Pouch(pouch).apply(&mut p).unwrap().unwrap();
        let n = s.layers.unwrap();
        let used = n as f64 * repeat_thickness(&p) + p.cell.negative_collector_thickness;
        assert!(used <= 8e-3 - 2.0 * pouch.wall && used + repeat_thickness(&p) > 8e-3 - 2.0 * pouch.wall);
        assert!((p.cell.area() - 2.0 * n as f64 * 0.19 * 0.09).abs() < 1e-12);
    }
}
