"""PyBaMM reference for the asymmetric Butler-Volmer kinetics (tests/suite/asymmetric_kinetics.rs):
PyBaMM's option "intercalation kinetics" = "asymmetric Butler-Volmer",
`j = j0 (exp(alpha F eta / R T) - exp(-(1 - alpha) F eta / R T))` with "Negative / Positive
electrode Butler-Volmer transfer coefficient" = alpha, on Chen 2020, isothermal at 25 degC,
from the set's initial concentrations. PyBaMM's default mesh (20 volumes per x-domain and
per particle, 30 sizes for the MPM, as ours), IDAKLU at rtol = atol = 1e-8, outputs every 10 s.

The SPMe is left out on purpose: PyBaMM switches its SPM family to "surface form" =
"algebraic" for any non-default kinetics, and for the SPMe that is another model, not only
other kinetics (2C discharge, symmetric alpha = 0.5: the algebraic-surface-form SPMe is
36 mV RMS above PyBaMM's own SPMe and 56 mV from its DFN, against 28 mV for its SPMe). The
SPM (x-averaged, one interfacial current) is the same model either way (1.6e-5 mV RMS apart at
2C), and so is the DFN.

Cases (transfer coefficients negative / positive):
- `spm_pulses`, `dfn_pulses`, `mpm_pulses` (relative std 0.3 in both electrodes): 0.4 / 0.5,
  PULSES below;
- `dfn_cycle_positive`: 0.5 / 0.65, "Discharge at 1C until 2.5 V", "Rest for 15 minutes",
  "Charge at 1C until 4.2 V", "Rest for 15 minutes".

Writes into the folder given (default tests/data/asymmetric-kinetics):
- `{case}.csv`: time_s, current_A, voltage_V, step (0-based);
- `meta.json`: versions, options, transfer coefficients, protocols, timings.

    /tmp/pyb/bin/python scripts/make_asymmetric_kinetics_reference.py tests/data/asymmetric-kinetics
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

PULSES = ["Discharge at 1C for 30 minutes", "Rest for 10 minutes"] + [
    "Discharge at 2C for 2 minutes", "Rest for 10 minutes", "Charge at 1C for 2 minutes", "Rest for 10 minutes"] * 2
CYCLE = ["Discharge at 1C until 2.5 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Rest for 15 minutes"]
# name: (model class, extra options, alpha negative, alpha positive, steps)
CASES = {
    "spm_pulses": (pybamm.lithium_ion.SPM, {}, 0.4, 0.5, PULSES),
    "dfn_pulses": (pybamm.lithium_ion.DFN, {}, 0.4, 0.5, PULSES),
    "mpm_pulses": (pybamm.lithium_ion.MPM, {}, 0.4, 0.5, PULSES),
    "dfn_cycle_positive": (pybamm.lithium_ion.DFN, {}, 0.5, 0.65, CYCLE),
}
SIZE_STD = 0.3


def main(root):
    os.makedirs(root, exist_ok=True)
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020, IDAKLU rtol=atol=1e-8, default mesh",
            "period_s": 10, "ambient_K": 298.15, "size_relative_std_mpm": SIZE_STD, "cases": {}}
    for name, (cls, extra, alpha_n, alpha_p, steps) in CASES.items():
        model = cls({"intercalation kinetics": "asymmetric Butler-Volmer", **extra})
        p = pybamm.ParameterValues("Chen2020")
        if cls is pybamm.lithium_ion.MPM:
            p = pybamm.get_size_distribution_parameters(p, sd_n=SIZE_STD, sd_p=SIZE_STD)
        p.update({"Negative electrode Butler-Volmer transfer coefficient": alpha_n,
                  "Positive electrode Butler-Volmer transfer coefficient": alpha_p}, check_already_exists=False)
        sim = pybamm.Simulation(model, parameter_values=p, experiment=pybamm.Experiment(steps, period="10 seconds"),
                                solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
        start = time.perf_counter()
        sol = sim.solve()
        seconds = time.perf_counter() - start
        cols = [sol[v].entries for v in ("Time [s]", "Current [A]", "Voltage [V]")]
        cols.append(np.concatenate([np.full(len(cyc["Time [s]"].entries), c) for c, cyc in enumerate(sol.cycles)]))
        np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols), delimiter=",",
                   header="time_s,current_A,voltage_V,step", comments="", fmt="%.10g")
        meta["cases"][name] = {"model": model.name, "alpha": [alpha_n, alpha_p], "steps": steps,
                               "options": {k: str(model.options[k]) for k in ("intercalation kinetics", "surface form")},
                               "points": len(cols[0]), "solve_seconds": seconds, "end_time_s": float(cols[0][-1])}
        assert steps is not PULSES or cols[2].max() < 4.15, f"{name}: the voltage reaches {cols[2].max()} V (above Chen 2020's 4.2 V cut-off, ours stops)"
        print(f"{name}: {len(cols[0])} points, {cols[0][-1]:.0f} s, solved in {seconds:.2f} s, V {cols[2][0]:.6f} .. {cols[2][-1]:.6f}")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/asymmetric-kinetics")
