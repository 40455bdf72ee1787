"""PyBaMM reference for the lumped thermal submodel (tests/suite/thermal_reference.rs): the SPM,
SPMe and DFN on Chen 2020 (entropic change zero) with PyBaMM's option "thermal" = "lumped", a
total heat-transfer coefficient of 12 W/(m^2 K) and the cell starting at the ambient
temperature, alone and with side reactions in the negative electrode, whose current PyBaMM
leaves out of the heat source (its reaction heat is `a j eta_r` with the intercalation current
`j` only, and the SEI film's drop heats nothing):
- `{spm,spme,dfn}_thermal`: thermal only;
- `{spm,spme,dfn}_thermal_sei`: with SEI "reaction limited" at 100 times Chen 2020's SEI
  exchange current (SEI film resistance "distributed", PyBaMM's default with SEI; side
  reactions x-averaged in the SPM, per x volume in the SPMe and DFN, PyBaMM's defaults);
- `spm_sei`: that SEI isothermal (the same ambient), to tell the SEI's share from the heat's;
- `spm_thermal_plating`: the SPM with "lithium plating" = "irreversible" (PyBaMM then sets
  "SEI" = "constant": no film) and OKane2022's plating parameters (as
  scripts/make_plating_submodel_reference.py), at 5 degC ambient so that the 2C charge plates.
- `{spm,spme,dfn}_thermal_entropic`: thermal with the OCPs' entropic change of the same
  LG M50 cell (O'Regan 2022, PyBaMM's ORegan2022 functions; Chen 2020 has none): the OCP is
  `U(x) + (T - T_ref) dU/dT(x)` and the reversible heat `a j T dU/dT(x)` at the particle
  surface;
- `{spm,dfn}_entropic_cold`: that entropic change isothermal at 0 degC (25 K below the OCPs'
  reference temperature), one 1C cycle (ENTROPIC_CYCLE).
PyBaMM's default mesh (20 volumes per x-domain and per particle, as ours), IDAKLU at
rtol = atol = 1e-8, outputs every 10 s, from full (initial_soc = 1).

Protocols, repeated CYCLES times (the DFN once, to keep the test fast):
- at 35 degC ambient: "Discharge at 2C until 2.7 V", "Rest for 15 minutes", "Charge at 1C
  until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes";
- plating, at 5 degC ambient: "Discharge at 1C until 3.0 V", "Rest for 15 minutes", "Charge
  at 2C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes".

Writes into the folder given (default tests/data/thermal):
- `{case}.csv`: time_s, current_A, voltage_V, temperature_K ("X-averaged cell temperature
  [K]"), step (0-based over all cycles);
- `meta.json`: versions, options, parameters, protocols, timings.

    python3.11 -m venv /tmp/pyb && /tmp/pyb/bin/pip install -r scripts/requirements.txt
    /tmp/pyb/bin/python scripts/make_thermal_reference.py tests/data/thermal [case,...]

(the optional second argument names the cases to (re)make; the others stay in `meta.json`.)
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

from make_plating_submodel_reference import parameters as plating_parameters

CYCLE = ["Discharge at 2C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V",
         "Hold at 4.2 V until C/10", "Rest for 15 minutes"]
PLATING_CYCLE = ["Discharge at 1C until 3.0 V", "Rest for 15 minutes", "Charge at 2C until 4.2 V",
                 "Hold at 4.2 V until C/10", "Rest for 15 minutes"]
ENTROPIC_CYCLE = ["Discharge at 1C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V",
                  "Hold at 4.2 V until C/10", "Rest for 15 minutes"]
CYCLES = 2
WARM, COLD, FREEZING = 308.15, 278.15, 273.15
H = 12.0
SEI_FACTOR = 100.0
lion = pybamm.lithium_ion
# name: (model, options, SEI exchange current x100, cycle, cycles, ambient (K))
CASES = {
    "spm_thermal": (lion.SPM, {"thermal": "lumped"}, False, CYCLE, CYCLES, WARM),
    "spm_thermal_sei": (lion.SPM, {"thermal": "lumped", "SEI": "reaction limited"}, True, CYCLE, CYCLES, WARM),
    "spm_sei": (lion.SPM, {"SEI": "reaction limited"}, True, CYCLE, CYCLES, WARM),
    "spme_thermal": (lion.SPMe, {"thermal": "lumped"}, False, CYCLE, CYCLES, WARM),
    "dfn_thermal": (lion.DFN, {"thermal": "lumped"}, False, CYCLE, 1, WARM),
    "spme_thermal_sei": (lion.SPMe, {"thermal": "lumped", "SEI": "reaction limited"}, True, CYCLE, CYCLES, WARM),
    "dfn_thermal_sei": (lion.DFN, {"thermal": "lumped", "SEI": "reaction limited"}, True, CYCLE, 1, WARM),
    "spm_thermal_plating": (lion.SPM, {"thermal": "lumped", "lithium plating": "irreversible"}, False, PLATING_CYCLE, CYCLES, COLD),
    "spm_thermal_entropic": (lion.SPM, {"thermal": "lumped"}, False, CYCLE, CYCLES, WARM),
    "spme_thermal_entropic": (lion.SPMe, {"thermal": "lumped"}, False, CYCLE, CYCLES, WARM),
    "dfn_thermal_entropic": (lion.DFN, {"thermal": "lumped"}, False, CYCLE, 1, WARM),
    "spm_entropic_cold": (lion.SPM, {}, False, ENTROPIC_CYCLE, 1, FREEZING),
    "dfn_entropic_cold": (lion.DFN, {}, False, ENTROPIC_CYCLE, 1, FREEZING),
}


def entropic(p):
    """The OCPs' entropic change of O'Regan 2022 (same LG M50 cell) put into `p`."""
    o = pybamm.ParameterValues("ORegan2022")
    for side in ["Negative", "Positive"]:
        key = f"{side} electrode OCP entropic change [V.K-1]"
        p.update({key: o[key]})
    return p


def parameters(sei100, ambient):
    """Chen 2020 with OKane2022's plating parameters, the ambient and initial temperature
    `ambient` (K), the heat-transfer coefficient H, and the SEI exchange current times
    SEI_FACTOR if `sei100`."""
    p, _ = plating_parameters()
    p.update({"Ambient temperature [K]": ambient, "Initial temperature [K]": ambient,
              "Total heat transfer coefficient [W.m-2.K-1]": H})
    if sei100:
        key = "SEI reaction exchange current density [A.m-2]"
        p.update({key: SEI_FACTOR * p[key]})
    return p


def main(root):
    os.makedirs(root, exist_ok=True)
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020 + OKane2022 plating parameters, IDAKLU rtol=atol=1e-8, default mesh",
            "heat_transfer_coefficient_W_m2K": H, "sei_exchange_current_factor": SEI_FACTOR, "period_s": 10, "cases": {}}
    if os.path.exists(os.path.join(root, "meta.json")):
        with open(os.path.join(root, "meta.json")) as f:
            meta["cases"] = json.load(f)["cases"]
    names = sys.argv[2].split(",") if len(sys.argv) > 2 else list(CASES)
    for name in names:
        cls, options, sei100, cycle, cycles, ambient = CASES[name]
        # PyBaMM's SPM writes "x-average side reactions" = "true" into the options it is
        # given: each model gets its own copy.
        p = parameters(sei100, ambient)
        if "entropic" in name:
            entropic(p)
        sim = pybamm.Simulation(cls(dict(options)), parameter_values=p,
                                experiment=pybamm.Experiment(cycle * cycles, period="10 seconds"),
                                solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
        start = time.perf_counter()
        sol = sim.solve(initial_soc=1.0)
        seconds = time.perf_counter() - start
        cols = [sol[v].entries for v in ("Time [s]", "Current [A]", "Voltage [V]", "X-averaged cell temperature [K]")]
        # Each step of the list given to Experiment is a cycle of its own.
        step = np.concatenate([np.full(len(cyc["Time [s]"].entries), c) for c, cyc in enumerate(sol.cycles)])
        np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols + [step]), delimiter=",",
                   header="time_s,current_A,voltage_V,temperature_K,step", comments="", fmt="%.10g")
        meta["cases"][name] = {"model": cls.__name__, "options": options, "sei_exchange_current_x100": sei100,
                               "cycle": cycle, "cycles": cycles, "ambient_K": ambient, "points": len(step),
                               "entropic_change": "ORegan2022" if "entropic" in name else "none",
                               "solve_seconds": seconds, "end_time_s": float(cols[0][-1])}
        extra = ""
        if "lithium plating" in options:
            extra = f", lost to plating {sol['Loss of lithium to negative lithium plating [mol]'].entries[-1]:.3e} mol"
        print(f"{name}: {len(step)} points, {cols[0][-1]:.0f} s, solved in {seconds:.2f} s, "
              f"temperature max {cols[3].max():.3f} K{extra}")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/thermal")
