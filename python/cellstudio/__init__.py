"""cellstudio from Python: SPM, SPMe and DFN simulation, design studies, fitting, sampling
and model-discrepancy diagnosis, with PyBaMM's names where one exists.

    import cellstudio as cs
    ps = cs.ParameterSet.chen2020()
    ps.set("positive.thickness", 70e-6)
    sol = cs.simulate("dfn", ps, ["Discharge at 1C until 2.5 V", "Rest for 10 minutes"])
    sol.to_pandas()

All values are SI units. Errors are ``cellstudio.CellstudioError`` with the command line's
message.
"""

from ._diagnose import diagnose
from ._errors import CellstudioError
from ._parameters import ParameterSet
from ._results import DesignResult, DiagnosisResult, FitResult, ParetoResult, SampleResult, SweepResult
from ._solution import Solution, simulate
from ._studies import DesignStudy, fit, sample

__all__ = [
    "CellstudioError",
    "DesignResult",
    "DesignStudy",
    "DiagnosisResult",
    "FitResult",
    "ParameterSet",
    "ParetoResult",
    "SampleResult",
    "Solution",
    "SweepResult",
    "diagnose",
    "fit",
    "sample",
    "simulate",
]
