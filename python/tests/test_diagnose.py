"""diagnose from a DataFrame: the bench's electrolyte case, SPM given."""

import pandas as pd
import pytest

import cellstudio as cs
from conftest import REPO

CASE = REPO / "tests/data/diagnosis-bench/b2_electrolyte_2C/recording.csv"


def test_diagnosis_from_dataframe(tmp_path):
    frame = pd.read_csv(CASE).rename(columns={"time_s": "Time [s]", "current_A": "Current [A]", "voltage_V": "Voltage [V]"})
    result = cs.diagnose(frame, model="spm", out=tmp_path / "diagnosis")
    assert "electrolyte" in result.verdict.lower()
    assert result.rounds[0]["found"]
    assert result.report_path and (tmp_path / "diagnosis" / "diagnosis.md").is_file()
    assert result.fitted[0], "the named candidate's fitted values"
    assert "electrolyte" in result.conclusion.lower()


def test_recording_without_voltage_is_refused_by_column():
    frame = pd.read_csv(CASE).drop(columns=["voltage_V"])
    with pytest.raises(cs.CellstudioError, match="voltage_V"):
        cs.diagnose(frame, model="spm")
