"""PyBaMM references for the parameterisation workflows (`cellstudio parameterise`,
tests/parameterisation_*.rs): Chen 2020, the DFN, IDAKLU at rtol = atol = 1e-8, the default
mesh, 298.15 K.

- `c20_discharge_charge.csv`: from rest at 100 % SOC (4.2 V OCV), 1 h rest, C/20 discharge to
  2.5 V, 2 h rest, C/20 charge to 4.2 V, 1 h rest (pseudo-OCV and electrode balancing).
- `gitt.csv`: from rest at 100 % SOC, 1 h rest, then 18 x (C/10 discharge for 30 min or to
  2.5 V, 2 h rest) (pulse resistance and GITT diffusivity).

Recordings are in cellstudio's CSV (`time_s,current_A,voltage_V`, discharge positive, a
repeated time at each current step as PyBaMM writes them), thinned: every sample in the
first 60 s of a step (1 s apart in the GITT, 60 s in the C/20 test), then one a minute
(C/20: every 120 s), and each step's last sample. `meta.json` holds the truth: PyBaMM's
electrode capacities, cyclable lithium and stoichiometry windows (its electrode-SOH solver),
the diffusivities, and per GITT pulse the average particle stoichiometries, the 1 s and
10 s resistances from the unthinned solution and the state of charge by coulomb counting.

    /tmp/pyb/bin/python scripts/make_parameterisation_reference.py tests/data/parameterisation
"""

import json
import os
import sys

import numpy as np
import pybamm


def solve(experiment_steps, period):
    params = pybamm.ParameterValues("Chen2020")
    model = pybamm.lithium_ion.DFN()
    experiment = pybamm.Experiment(experiment_steps, period=period)
    sim = pybamm.Simulation(model, parameter_values=params, experiment=experiment, solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
    return params, sim.solve(initial_soc=1.0)


def all_steps(sol):
    steps = []
    for cycle in sol.cycles:
        steps.extend(cycle.steps)
    return steps


def write_csv(path, rows):
    with open(path, "w") as f:
        f.write("time_s,current_A,voltage_V\n")
        for t, i, v in rows:
            f.write(f"{t:.6f},{i:.9g},{v:.9f}\n")


def thin_steps(steps, dense_seconds, every):
    rows = []
    for step in steps:
        t = step["Time [s]"].entries
        i = step["Current [A]"].entries
        v = step["Voltage [V]"].entries
        t0, last_kept = t[0], -np.inf
        for k in range(len(t)):
            if t[k] - t0 <= dense_seconds + 1e-9 or t[k] - last_kept >= every - 1e-9 or k == len(t) - 1:
                rows.append((t[k], i[k], v[k]))
                last_kept = t[k]
    return rows


def electrode_soh(params):
    """PyBaMM's electrode capacities (A h), cyclable lithium (A h) and windows."""
    F = 96485.33212
    area = params["Electrode height [m]"] * params["Electrode width [m]"]
    q = {}
    for e, name in [("n", "Negative"), ("p", "Positive")]:
        eps = params[f"{name} electrode active material volume fraction"]
        thickness = params[f"{name} electrode thickness [m]"]
        c_max = params[f"Maximum concentration in {name.lower()} electrode [mol.m-3]"]
        c_0 = params[f"Initial concentration in {name.lower()} electrode [mol.m-3]"]
        q[e] = eps * thickness * area * c_max * F / 3600
        q[e + "_lithium"] = eps * thickness * area * c_0 * F / 3600
    x0, x100, y100, y0 = pybamm.lithium_ion.get_min_max_stoichiometries(params)
    return {
        "negative_capacity_Ah": q["n"],
        "positive_capacity_Ah": q["p"],
        "cyclable_lithium_Ah": q["n_lithium"] + q["p_lithium"],
        "np_ratio": q["n"] / q["p"],
        "x0": float(x0),
        "x100": float(x100),
        "y0": float(y0),
        "y100": float(y100),
        "window_capacity_Ah": float((x100 - x0) * q["n"]),
    }


def main(out):
    os.makedirs(out, exist_ok=True)
    meta = {
        "made_by": f"scripts/make_parameterisation_reference.py, PyBaMM {pybamm.__version__}, Chen2020, DFN, IDAKLU rtol=atol=1e-8, default mesh, 298.15 K, initial_soc = 1",
        "negative_diffusivity_m2_s": 3.3e-14,
        "positive_diffusivity_m2_s": 4e-15,
        "negative_particle_radius_m": 5.86e-6,
        "positive_particle_radius_m": 5.22e-6,
    }

    # C/20 discharge then charge.
    steps = ["Rest for 1 hour", "Discharge at C/20 until 2.5 V", "Rest for 2 hours", "Charge at C/20 until 4.2 V", "Rest for 1 hour"]
    params, sol = solve(steps, "60 seconds")
    meta["soh"] = electrode_soh(params)
    st = all_steps(sol)
    cap = lambda s: abs(s["Discharge capacity [A.h]"].entries[-1] - s["Discharge capacity [A.h]"].entries[0])
    meta["c20"] = {
        "protocol": steps,
        "discharge_capacity_Ah": cap(st[1]),
        "charge_capacity_Ah": cap(st[3]),
    }
    rows = thin_steps(st, 0.0, 120.0)
    write_csv(os.path.join(out, "c20_discharge_charge.csv"), rows)
    meta["c20"]["rows"] = len(rows)
    print("C/20", meta["c20"], meta["soh"])

    # GITT.
    pulses = 18
    steps = ["Rest for 1 hour"] + ["Discharge at C/10 for 30 minutes or until 2.5 V", "Rest for 2 hours"] * pulses
    _, sol = solve(steps, "1 second")
    st = all_steps(sol)
    table = []
    q0 = st[0]["Discharge capacity [A.h]"].entries[0]
    for k in range(pulses):
        p = st[1 + 2 * k]
        t = p["Time [s]"].entries - p["Time [s]"].entries[0]
        v = p["Voltage [V]"].entries
        i = p["Current [A]"].entries
        v_rest = st[2 * k]["Voltage [V]"].entries[-1]
        mid = len(t) // 2
        r = lambda s: float((v_rest - np.interp(s, t, v)) / i[1])
        table.append({
            "pulse": k + 1,
            "start_s": float(p["Time [s]"].entries[0]),
            "duration_s": float(t[-1]),
            "current_A": float(i[1]),
            "discharged_Ah_at_start": float(p["Discharge capacity [A.h]"].entries[0] - q0),
            "resistance_1s_ohm": r(1.0),
            "resistance_10s_ohm": r(10.0),
            "negative_stoichiometry_mid": float(p["Average negative particle stoichiometry"].entries[mid]),
            "positive_stoichiometry_mid": float(p["Average positive particle stoichiometry"].entries[mid]),
        })
    rows = thin_steps(st, 60.0, 60.0)
    write_csv(os.path.join(out, "gitt.csv"), rows)
    meta["gitt"] = {"protocol": f"1 h rest, then {pulses} x (C/10 discharge for 30 min or until 2.5 V, 2 h rest)", "rows": len(rows), "pulses": table}
    print("GITT", len(rows), "rows", table[0], table[-1])

    with open(os.path.join(out, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/parameterisation")
