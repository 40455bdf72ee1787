"""Design and fitting studies from Python give what the command line gives."""

import math
import re

import pytest

import cellstudio as cs
from conftest import REPO, run_cli

SEED = REPO / "designs" / "gravimetric_chen2020.toml"


def test_seed_design_matches_the_cli(tmp_path):
    study = cs.DesignStudy.from_file(SEED)
    result = study.run(out=tmp_path / "py")
    printed = run_cli(["design", str(SEED)], cwd=tmp_path)
    initial = float(re.search(r"^initial\s+([\d.]+)", printed, re.M).group(1))
    optimised = float(re.search(r"^optimised\s+([\d.]+)", printed, re.M).group(1))
    assert round(result.initial_value, 2) == initial
    assert round(result.value, 2) == optimised
    assert result.value > result.initial_value
    df = result.to_pandas()
    assert df.loc["optimised", "gravimetric_energy_density"] == result.value
    assert set(result.x) == {"positive.thickness", "positive.active_fraction"}
    assert (tmp_path / "py" / "report.md").is_file()


def test_sweep_and_pareto_frames(tmp_path):
    study = cs.DesignStudy.from_file(SEED)
    sweep = study.sweep(out=tmp_path / "sweep")
    df = sweep.to_pandas()
    assert len(df) == 169 and (df["status"] == "valid").sum() > 100
    best = df[df["status"] == "valid"]["gravimetric_energy_density"].max()
    assert best == sweep.best["gravimetric_energy_density"]["metrics"]["gravimetric_energy_density"]
    pareto = cs.DesignStudy.from_file(REPO / "designs" / "energy_vs_power_chen2020.toml").pareto(out=tmp_path / "pareto")
    front = pareto.to_pandas()
    assert len(front) > 3 and front.shape[1] == len(pareto.data["variables"]) + len(pareto.data["objectives"])


def test_bad_study_override_names_the_field():
    with pytest.raises(cs.CellstudioError, match="positive.thicknes"):
        cs.DesignStudy.from_file(SEED, set={"positive.thicknes": 7e-5})
    with pytest.raises(cs.CellstudioError, match="no_such_study.toml"):
        cs.DesignStudy.from_file("no_such_study.toml")


def test_contact_resistance_fit_and_sample(at_repo, tmp_path):
    study = at_repo / "fits" / "spm_contact_resistance.toml"
    result = cs.fit(study, out=tmp_path / "fit")
    assert result.values["cell.contact_resistance"] == pytest.approx(0.010, rel=0.01)
    assert result.values["negative.diffusivity"] == pytest.approx(3.3e-14, rel=0.02)
    assert result.rmse == pytest.approx(0.002, rel=0.05)
    assert result.to_pandas().loc["cell.contact_resistance", "std_error"] > 0
    posterior = cs.sample(study, out=tmp_path / "sample", sampler={"chains": 2, "iterations": 400, "warmup": 200})
    summary = posterior.to_pandas()
    assert math.isclose(summary.loc["cell.contact_resistance", "mean"], 0.010, rel_tol=0.02)


def test_long_runs_draw_the_library_progress_with_tqdm(at_repo, tmp_path, monkeypatch):
    """A run goes on in a worker thread while the caller polls the library's current bar and
    hands it to tqdm: the sampler's bar is seen, and the result is the one drawn without."""
    import cellstudio._progress as progress

    seen = []

    class FakeTqdm:
        def __init__(self, total, desc, leave):
            self.total, self.n = total, 0
            seen.append((desc, total))

        def refresh(self):
            pass

        def close(self):
            pass

    monkeypatch.setattr(progress, "_tqdm", lambda: FakeTqdm)
    study = at_repo / "fits" / "spm_contact_resistance.toml"
    options = {"chains": 2, "iterations": 3000, "warmup": 500}
    drawn = cs.sample(study, out=tmp_path / "drawn", sampler=options)
    plain = cs.sample(study, out=tmp_path / "plain", sampler=options, progress=False)
    assert any(total == 2 * 3500 for _, total in seen), seen
    assert drawn.to_pandas().equals(plain.to_pandas())
    assert progress.with_progress(lambda: 42) == 42
    with pytest.raises(ZeroDivisionError):
        progress.with_progress(lambda: 1 / 0)


def test_parameterise_gives_the_cli_balance_and_its_parameter_set(at_repo, tmp_path):
    study = at_repo / "fits" / "param_ocv_c20.toml"
    result = cs.parameterise(study, out=tmp_path / "py")
    printed = run_cli(["parameterise", str(study)], cwd=at_repo)
    assert set(result.stages) == {"ocv", "balancing"}
    assert all(line in printed for line in result.summary)
    # The balance was applied: the set the stages leave carries the fitted window.
    balance = result.stages["balancing"]
    assert result.parameters != cs.ParameterSet.chen2020()
    assert balance and (tmp_path / "py" / "parameters.json").is_file()


def test_cycle_summaries_and_fade_fit(at_repo, tmp_path):
    study = at_repo / "examples" / "fade_fit_sei_chen2020.toml"
    result = cs.cycle(study, out=tmp_path / "py")
    df = result.to_pandas()
    assert list(df.index) == list(range(1, len(df) + 1)) and len(df) >= 2
    assert df["capacity_retention"].iloc[0] == 1.0 and 0.0 < result.retention < 1.0
    # PyBaMM's SEI exchange current behind the fade curve (tests/data, scripts/make_sei_reference.py).
    assert result.fade_fit["values"]["sei.exchange_current"] == pytest.approx(1.5e-7, rel=1e-3)
    with pytest.raises(cs.CellstudioError, match="sei.exchange_curren"):
        cs.cycle(study, set={"sei.exchange_curren": 1e-7}, out=tmp_path / "bad")
