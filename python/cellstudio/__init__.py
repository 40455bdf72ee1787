"""cellstudio from Python: SPM, SPMe and DFN simulation, design studies, fitting, sampling,
parameterisation workflows, cycling with ageing, and model-discrepancy diagnosis, with
PyBaMM's names where one exists.

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
from ._results import CycleResult, DesignResult, DiagnosisResult, FitResult, ParameterisationResult, ParetoResult, SampleResult, SweepResult
from ._solution import Solution, simulate
from ._studies import DesignStudy, cycle, fit, parameterise, sample

__all__ = [
    "CellstudioError",
    "CycleResult",
    "DesignResult",
    "DesignStudy",
    "DiagnosisResult",
    "FitResult",
    "ParameterisationResult",
    "ParameterSet",
    "ParetoResult",
    "SampleResult",
    "Solution",
    "SweepResult",
    "cycle",
    "diagnose",
    "fit",
    "parameterise",
    "sample",
    "simulate",
]
