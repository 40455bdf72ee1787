"""Design and fitting studies from their TOML files (``designs/*.toml``, ``fits/*.toml``),
run as the command line runs them, writing the same files. Relative paths in a study (its
recording, its output folder) are read from the working directory, as on the command line;
``out=`` moves a run's output folder. ``set={"path": value}`` is the CLI's ``--set``."""

import json
import os

from . import _native
from ._progress import with_progress
from ._results import CycleResult, DesignResult, FitResult, ParameterisationResult, ParetoResult, SampleResult, SweepResult


def _pairs(overrides):
    return [(str(k), float(v)) for k, v in (overrides or {}).items()]


def _path(p):
    return None if p is None else os.fspath(p)


class DesignStudy:
    """A design study file, read and checked; ``run()``, ``sweep()`` and ``pareto()`` are
    ``cellstudio design``, ``sweep`` and ``pareto`` on it."""

    def __init__(self, path, set=None):
        self.path = os.fspath(path)
        self.overrides = dict(set or {})
        self.study = json.loads(_native.load_design(self.path, _pairs(self.overrides)))

    @classmethod
    def from_file(cls, path, set=None):
        return cls(path, set)

    @property
    def name(self):
        return self.study["name"]

    def run(self, out=None, progress=True):
        """Runs the study's optimiser from the baseline design (GIL released)."""
        return DesignResult(json.loads(with_progress(_native.design, self.path, _pairs(self.overrides), _path(out), progress=progress)))

    def sweep(self, out=None, progress=True):
        """Evaluates the study's ``[sweep]`` grid in parallel (GIL released)."""
        return SweepResult(json.loads(with_progress(_native.sweep, self.path, _pairs(self.overrides), _path(out), progress=progress)))

    def pareto(self, out=None, progress=True):
        """Runs NSGA-II on the study's objectives (GIL released)."""
        return ParetoResult(json.loads(with_progress(_native.pareto, self.path, _pairs(self.overrides), _path(out), progress=progress)))

    def __repr__(self):
        return f"DesignStudy({self.path!r})"


def fit(study_path, data=None, set=None, out=None, progress=True):
    """``cellstudio fit STUDY [--data DATA]``: fits the study's parameters; raises
    ``CellstudioError`` when a parameter ends on a bound (outputs in ``NAME.rejected``)."""
    return FitResult(json.loads(with_progress(_native.fit, os.fspath(study_path), _path(data), _pairs(set), _path(out), progress=progress)))


def sample(study_path, data=None, set=None, out=None, sampler=None, progress=True):
    """``cellstudio sample STUDY``: MCMC of the study's posterior; ``sampler`` entries
    (``chains``, ``iterations``, ``warmup``, ``seed``) replace the study's ``[sampler]`` ones."""
    options = [(str(k), int(v)) for k, v in (sampler or {}).items()]
    return SampleResult(json.loads(with_progress(_native.sample, os.fspath(study_path), _path(data), _pairs(set), _path(out), options, progress=progress)))


def parameterise(study_path, set=None, out=None, progress=True):
    """``cellstudio parameterise STUDY``: its stages (pseudo-OCV, balancing, pulses, kinetics,
    GITT) in order, each feeding the next; ``parameters`` is the set they leave."""
    return ParameterisationResult(json.loads(with_progress(_native.parameterise, os.fspath(study_path), _pairs(set), _path(out), progress=progress)))


def cycle(study_path, set=None, out=None, progress=True):
    """``cellstudio cycle STUDY``: N cycles with a summary per cycle (``to_pandas()``), and
    the fade fit (``fade_fit``) when the study has a ``[fit]`` table."""
    return CycleResult(json.loads(with_progress(_native.cycle, os.fspath(study_path), _pairs(set), _path(out), progress=progress)))
