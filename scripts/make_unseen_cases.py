"""Recordings with concealed effects made by PyBaMM, in the diagnosis bench's format, that the
diagnosis was never developed on: a check that the method is general, not fitted to
../shared/diagnosis-bench. Same conventions as the bench (Chen 2020, IDAKLU at rtol = atol =
1e-8, 1 s sampling, 1 mV Gaussian voltage noise, 0.05 K on recorded temperatures; a repeated
time marks a current step).

    python -m venv .venv && .venv/bin/pip install pybamm==26.10.1.1
    .venv/bin/python scripts/make_unseen_cases.py out/unseen-cases
    BIN=target/release/cellstudio ../shared/tools/diagnosis-bench out/unseen-cases
"""

import json
import os
import sys

import numpy as np
import pybamm

NOISE_V = 1e-3
NOISE_K = 0.05


def chen():
    return pybamm.ParameterValues("Chen2020")


def scaled(p, name, factor):
    """Multiplies a parameter, constant or function of (c_e, T) or (sto, T), by `factor`."""
    value = p[name]
    if callable(value):
        p.update({name: lambda *args, f=value: factor * f(*args)})
    else:
        p.update({name: factor * value})
    return p


def write_case(root, name, model, params, steps, truth, initial_soc=None, temperature=False, seed=0):
    experiment = pybamm.Experiment(steps, period="1 second")
    solver = pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8)
    sim = pybamm.Simulation(model, parameter_values=params, experiment=experiment, solver=solver)
    sol = sim.solve(initial_soc=initial_soc)
    t = sol["Time [s]"].entries
    i = sol["Current [A]"].entries
    v = sol["Voltage [V]"].entries
    rng = np.random.default_rng(seed)
    v = v + rng.normal(0.0, NOISE_V, v.shape)
    folder = os.path.join(root, name)
    os.makedirs(folder, exist_ok=True)
    columns = [t, i, v]
    header = "time_s,current_A,voltage_V"
    if temperature:
        temp = sol["X-averaged cell temperature [K]"].entries + rng.normal(0.0, NOISE_K, t.shape)
        columns.append(temp)
        header += ",temperature_K"
    np.savetxt(os.path.join(folder, "recording.csv"), np.column_stack(columns), delimiter=",", header=header, comments="", fmt="%.6f")
    truth.update({"noise_V": NOISE_V, "points": int(len(t)), "made_by": f"PyBaMM {pybamm.__version__}, Chen2020, IDAKLU rtol=atol=1e-8"})
    truth.setdefault("ambient_temperature_K", 298.15)
    with open(os.path.join(folder, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"{name}: {len(t)} points, {t[-1]:.0f} s")


def main(root):
    lion = pybamm.lithium_ion
    discharge = lambda rate: [f"Discharge at {rate} until 2.7 V", "Rest for 30 minutes"]

    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.2)
    write_case(root, "u1_diffusivity_negative_C2", lion.DFN(), p, discharge("C/2"),
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["diffusiv"],
                "note": "negative particle diffusivity x0.2"}, seed=1)

    p = scaled(chen(), "Negative electrode active material volume fraction", 0.9)
    write_case(root, "u2_lam_negative_1C", lion.DFN(), p, discharge("1C"),
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material", "capacity", "stoichiometr"],
                "note": "10 % loss of negative active material"}, seed=2)

    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.3)
    write_case(root, "u3_conductivity_2C", lion.DFN(), p, discharge("2C"),
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"],
                "note": "electrolyte conductivity x0.3"}, seed=3)

    pulses = ["Discharge at 1C for 30 seconds", "Rest for 5 minutes"] * 8
    write_case(root, "u4_control_pulses", lion.DFN(), chen(), pulses,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"],
                "note": "negative control: DFN data, DFN model, 1C pulses from 80 % SOC"}, initial_soc=0.8, seed=4)

    p = chen()
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    p.update({"Contact resistance [Ohm]": 0.012}, check_already_exists=False)
    write_case(root, "u5_contact_cold_1C", lion.SPMe(options={"contact resistance": "true"}), p, discharge("1C"),
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance"],
                "ambient_temperature_K": 283.15, "note": "12 mOhm contact resistance at 10 degC (isothermal)"},
               temperature=True, seed=5)

    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.92)
    gitt = ["Discharge at C/2 for 10 minutes", "Rest for 20 minutes"] * 10
    write_case(root, "u6_inventory_gitt", lion.SPMe(), p, gitt,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "stoichiometr", "capacity"],
                "note": "8 % less lithium in the negative electrode, C/2 GITT"}, seed=6)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/unseen-cases")
