"""ParameterSet: dotted paths, dicts, pickling, BPX and PyBaMM-name imports, errors."""

import pickle

import pytest

import cellstudio as cs
from conftest import REPO


def test_set_get_round_trip_through_dict_and_pickle():
    ps = cs.ParameterSet.chen2020()
    ps.set("positive.thickness", 70e-6)
    assert ps.get("positive.thickness") == 70e-6
    assert ps["positive.thickness"] == 70e-6
    d = ps.to_dict()
    assert d["positive.thickness"] == 70e-6 and d["cell.nominal_capacity"] == 5.0
    # Every scalar of the set, each readable back by its path.
    assert len(d) > 70 and all(ps[k] == v for k, v in d.items())
    assert pickle.loads(pickle.dumps(ps)) == ps
    assert cs.ParameterSet.from_json(ps.to_json()) == ps


def test_bad_value_raises_with_the_field_name_and_leaves_the_set():
    ps = cs.ParameterSet.chen2020()
    with pytest.raises(cs.CellstudioError, match="positive.thickness"):
        ps.set("positive.thickness", -1.0)
    with pytest.raises(cs.CellstudioError, match="positive.thicknes"):
        ps.set("positive.thicknes", 1e-5)
    assert ps == cs.ParameterSet.chen2020()


def test_bpx_file_import():
    ps = cs.ParameterSet.from_bpx(REPO / "tests/data/bpx_example.json")
    assert 0 < ps.get("positive.thickness") < 1e-3
    with pytest.raises(cs.CellstudioError):
        cs.ParameterSet.from_bpx(REPO / "no/such/file.json")


def test_pybamm_names_import():
    # As PyBaMM writes them (ParameterValues keys), scalars only: no PyBaMM needed.
    values = {
        "Positive electrode thickness [m]": 7.0e-5,
        "Negative electrode thickness [m]": 8.0e-5,
        "Separator porosity": 0.45,
        "Negative particle radius [m]": 5.5e-6,
        "Maximum concentration in positive electrode [mol.m-3]": 63000.0,
        "Initial concentration in electrolyte [mol.m-3]": 1100.0,
        "Cation transference number": 0.26,
        "Nominal cell capacity [A.h]": 4.8,
        "Lower voltage cut-off [V]": 2.6,
        "Ambient temperature [K]": 303.15,
        "cell.contact_resistance": 0.01,
    }
    ps = cs.ParameterSet.from_pybamm(values)
    expect = {
        "positive.thickness": 7.0e-5,
        "negative.thickness": 8.0e-5,
        "separator.porosity": 0.45,
        "negative.particle_radius": 5.5e-6,
        "positive.max_concentration": 63000.0,
        "electrolyte.initial_concentration": 1100.0,
        "electrolyte.transference_number": 0.26,
        "cell.nominal_capacity": 4.8,
        "cell.lower_cutoff": 2.6,
        "thermal.ambient_temperature": 303.15,
        "cell.contact_resistance": 0.01,
    }
    for path, value in expect.items():
        assert ps.get(path) == value, path
    # Everything else, functions included, is the base set's.
    base = cs.ParameterSet.chen2020()
    for path, value in expect.items():
        base.set(path, value)
    assert ps == base


def test_pybamm_functions_and_unknown_names_are_refused_by_name():
    values = {
        "Positive electrode thickness [m]": 7.0e-5,
        "Negative electrode OCP [V]": lambda sto: 0.2 - 0.1 * sto,
        "Typical current [A]": 5.0,
    }
    with pytest.raises(cs.CellstudioError) as e:
        cs.ParameterSet.from_pybamm(values)
    assert "Negative electrode OCP [V]" in str(e.value) and "function" in str(e.value)
    assert "Typical current [A]" in str(e.value)
    ps = cs.ParameterSet.from_pybamm(values, ignore_unknown=True)
    assert ps.get("positive.thickness") == 7.0e-5


def test_pybamm_own_names_for_particle_diffusivity_fractions_and_contact_resistance():
    """Names as `pybamm.ParameterValues("Chen2020")` spells them, which BPX names otherwise."""
    ps = cs.ParameterSet.from_pybamm(
        {
            "Negative particle diffusivity [m2.s-1]": 3.0e-14,
            "Positive electrode active material volume fraction": 0.66,
            "Negative electrode Bruggeman coefficient (electrolyte)": 1.6,
            "Contact resistance [Ohm]": 0.012,
        }
    )
    assert ps.get("negative.diffusivity") == 3.0e-14
    assert ps.get("positive.active_fraction") == 0.66
    assert ps.get("negative.bruggeman_electrolyte") == 1.6
    assert ps.get("cell.contact_resistance") == 0.012
