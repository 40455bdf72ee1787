"""simulate: PyBaMM experiment strings in, NumPy arrays and a DataFrame out, pickling."""

import pickle

import numpy as np
import pytest

import cellstudio as cs


def test_experiment_to_numpy_and_pandas():
    ps = cs.ParameterSet.chen2020()
    sol = cs.simulate(model="dfn", parameters=ps, experiment=["Discharge at 1C until 2.5 V", "Rest for 10 minutes"])
    assert isinstance(sol.voltage, np.ndarray) and sol.voltage.dtype == np.float64
    assert len(sol.time) == len(sol.voltage) == len(sol.current) > 10
    assert np.all(np.diff(sol.time) >= 0)  # a step boundary repeats its time
    assert sol.voltage.min() == pytest.approx(2.5, abs=1e-3)
    assert sol.time[-1] - sol.summary["cutoff_times"][0] == pytest.approx(600.0, abs=1e-6)
    assert sol.current[-1] == 0.0
    assert 4.8 < sol.summary["capacity_Ah"] < 5.1
    df = sol.to_pandas()
    assert list(df.columns[:3]) == ["Time [s]", "Current [A]", "Voltage [V]"]
    np.testing.assert_array_equal(df["Voltage [V]"].to_numpy(), sol.voltage)
    np.testing.assert_array_equal(sol["Voltage [V]"], sol.voltage)
    again = pickle.loads(pickle.dumps(sol))
    np.testing.assert_array_equal(again.voltage, sol.voltage)
    assert again.summary == sol.summary


def test_default_discharge_matches_parameters():
    thin = cs.ParameterSet.chen2020()
    thin.set("positive.thickness", 60e-6)
    base = cs.simulate("spm").summary["capacity_Ah"]
    assert cs.simulate("spm", thin).summary["capacity_Ah"] < base


def test_bad_inputs_raise_cellstudio_error():
    with pytest.raises(cs.CellstudioError, match="experiment"):
        cs.simulate("spme", experiment=["Discharge at lots until 2.5 V"])
    with pytest.raises(cs.CellstudioError, match="c_rate"):
        cs.simulate("spme", c_rate=-1)
    with pytest.raises(cs.CellstudioError):
        cs.simulate("p2d")
