//! The `[cell]` table of a study: the parameter set, the cell format and its dimensions, the
//! mass convention.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::params::{CellFormat, Cylindrical, FormatName, MassConvention, Override, ParameterSet, Pouch, PybopDensities, apply_overrides, chen2020};

/// The mass convention named in `[cell] mass_basis`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MassBasisName {
    /// The format's components with the parameter set's densities.
    #[default]
    Cellstudio,
    /// PyBOP's convention (its design examples).
    Pybop,
}

/// Which parameter set to start from.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CellChoice {
    /// `chen2020` (embedded) or a path to a parameter-set TOML file.
    pub parameter_set: String,
    /// Cell format: `free_area` (default: the set's plate area, fixed), `cylindrical_21700`
    /// or `pouch`; in a format the electrode area follows from the stack thickness.
    #[serde(default)]
    pub format: FormatName,
    /// Can dimensions of a cylindrical format (`[cell.can]`; defaults: a 21700).
    pub can: Option<Cylindrical>,
    /// Pouch dimensions (`[cell.pouch]`), needed by the pouch format.
    pub pouch: Option<Pouch>,
    /// Mass convention: `cellstudio` (default: the format's components) or `pybop` (PyBOP's
    /// design examples, free area only) to compare W h/kg one to one.
    #[serde(default)]
    pub mass_basis: MassBasisName,
    /// PyBOP's densities (`[cell.pybop]`; defaults: PyBaMM's Chen 2020).
    pub pybop: Option<PybopDensities>,
    /// Overrides from the command line (`--set path=value`), applied after loading.
    #[serde(skip)]
    pub overrides: Vec<Override>,
}

impl CellChoice {
    /// The parameter set: embedded Chen 2020 or a TOML file, with the overrides applied.
    pub fn load(&self) -> Result<ParameterSet, Error> {
        let mut p = match self.parameter_set.as_str() {
            "chen2020" => chen2020(),
            path if !Path::new(path).is_file() => {
                return Err(Error::InvalidSetting {
                    field: "cell.parameter_set".into(),
                    reason: format!("`{path}` is neither a built-in set (chen2020) nor a parameter file"),
                });
            }
            path => ParameterSet::from_file(Path::new(path))?,
        };
        apply_overrides(&mut p, &self.overrides)?;
        Ok(p)
    }

    /// The cell format with its dimensions; a dimension table that does not belong to the
    /// format, or a pouch without dimensions, is an error.
    pub fn cell_format(&self) -> Result<CellFormat, Error> {
        let stray = |table: &str| Error::InvalidSetting {
            field: format!("cell.{table}"),
            reason: format!("does not apply to cell.format = {}", serde_json::to_string(&self.format).unwrap_or_default()),
        };
        match self.format {
            FormatName::FreeArea if self.can.is_some() => Err(stray("can")),
            FormatName::FreeArea | FormatName::Cylindrical21700 if self.pouch.is_some() => Err(stray("pouch")),
            FormatName::Pouch if self.can.is_some() => Err(stray("can")),
            FormatName::FreeArea => Ok(CellFormat::FreeArea),
            FormatName::Cylindrical21700 => {
                let can = self.can.unwrap_or_default();
                can.validate()?;
                Ok(CellFormat::Cylindrical(can))
            }
            FormatName::Pouch => {
                let pouch = self.pouch.ok_or_else(|| Error::InvalidSetting {
                    field: "cell.pouch".into(),
                    reason: "cell.format = \"pouch\" needs a [cell.pouch] table with length, width and thickness (m)".into(),
                })?;
                pouch.validate()?;
                Ok(CellFormat::Pouch(pouch))
            }
        }
    }

    /// Paths a cell format sets from the stack (so a variable, tie or `--set` on them would be
    /// overwritten); none for free area.
    pub fn format_outputs(&self) -> &'static [&'static str] {
        match self.format {
            FormatName::FreeArea => &[],
            _ => &["cell.electrode_height", "cell.electrode_width", "thermal.cell_volume"],
        }
    }

    /// The mass convention; `pybop` needs the free-area format.
    pub fn mass_convention(&self) -> Result<MassConvention, Error> {
        match (self.mass_basis, self.format) {
            (MassBasisName::Cellstudio, _) if self.pybop.is_some() => {
                Err(Error::InvalidSetting { field: "cell.pybop".into(), reason: "applies only with cell.mass_basis = \"pybop\"".into() })
            }
            (MassBasisName::Cellstudio, _) => Ok(MassConvention::Cellstudio),
            (MassBasisName::Pybop, FormatName::FreeArea) => {
                let d = self.pybop.unwrap_or_default();
                d.validate()?;
                Ok(MassConvention::Pybop(d))
            }
            (MassBasisName::Pybop, _) => Err(Error::InvalidSetting {
                field: "cell.mass_basis".into(),
                reason: "\"pybop\" is PyBOP's fixed-area convention: use it with cell.format = \"free_area\"".into(),
            }),
        }
    }

    /// The parameter-set file, when the set is not the embedded one.
    pub fn file(&self) -> Option<&Path> {
        (self.parameter_set != "chen2020").then(|| Path::new(&self.parameter_set))
    }
}

impl Default for CellChoice {
    fn default() -> Self {
        Self { parameter_set: "chen2020".into(), format: FormatName::FreeArea, can: None, pouch: None, mass_basis: MassBasisName::Cellstudio, pybop: None, overrides: Vec::new() }
    }
}

