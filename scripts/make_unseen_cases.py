"""Recordings with concealed effects made by PyBaMM, in the diagnosis bench's format, that the
diagnosis was never developed on: a check that the method is general, not fitted to
../shared/diagnosis-bench. Same conventions as the bench (Chen 2020, IDAKLU at rtol = atol =
1e-8, 1 s sampling, 1 mV Gaussian voltage noise, 0.05 K on recorded temperatures; a repeated
time marks a current step).

    python -m venv .venv && .venv/bin/pip install pybamm==26.10.1.1
    .venv/bin/python scripts/make_unseen_cases.py out/unseen-cases [batch keys, comma-separated, e.g. ab or ab,x; all by default]
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


def cycler_sampling(t, i, v, dense=60.0, short=300.0, load_period=30.0, rest_period=60.0, dv=5e-3, di=0.05):
    """Which points a real cycler would log from a 1 s simulation: every point in the first
    `dense` s of a step and in steps no longer than `short` s, then one every `load_period` s
    under load (`rest_period` s at rest), and any point where the voltage has moved `dv` or
    the current `di` since the last logged one (a CV hold, the knee); the first and last point
    of every step are kept (a repeated time still marks a current step: PyBaMM starts a step
    1e-13 s after the last one ends, written as the same time)."""
    starts = [0] + [k for k in range(1, len(t)) if t[k] - t[k - 1] < 1e-6] + [len(t)]
    keep = np.zeros(len(t), dtype=bool)
    for a, b in zip(starts[:-1], starts[1:]):
        keep[a] = keep[b - 1] = True
        long_step = t[b - 1] - t[a] > short
        period = rest_period if np.all(np.abs(i[a:b]) < 1e-9) else load_period
        last = a
        for k in range(a + 1, b - 1):
            if (not long_step or t[k] - t[a] < dense or t[k] - t[last] >= period - 1e-9
                    or abs(v[k] - v[last]) >= dv or abs(i[k] - i[last]) >= di):
                keep[k] = True
                last = k
    return keep


def write_case(root, name, model, params, steps, truth, initial_soc=None, temperature=False, seed=0, noise=NOISE_V, period=1,
               cycler=None, compare=None, leak_A=0.0, compare_steps=None, current_gain=1.0, post=None, skip_steps=0, keep=None,
               sampling=None, temp_offset_K=0.0, surface_form_ok=False):
    """`cycler` (a dict) writes what a cycler measures instead of the simulation's own points:
    `current_noise_A` (Gaussian, on the set current), `quantum_V` / `quantum_A` / `quantum_K`
    (resolution) and `irregular` (True: `cycler_sampling` from a 1 s simulation). `compare`
    (a model) adds `candidate_rmse_mV`: that model with the set's nominal parameters
    (`compare_params`, default Chen 2020 at the case's ambient), same protocol and initial
    state, against the recording, and `effect_rmse_mV` (the same against the noise-free voltage).
    `leak_A` (discharge positive) is a current the cell draws inside itself that the cycler does
    not see: `steps` carry it, the recorded current is the simulated one less it, and the
    comparison runs `compare_steps` (the protocol as the cycler set it). `current_gain`: the
    recorded current is the simulated one times it (a cycler's current channel out of
    calibration; `steps` carry the true current, `compare_steps` the set one). `post(t, i, v)`
    returns the noise-free voltage the cycler records from the simulated one (a voltage-channel
    offset, an ohmic drop added afterwards); the effect RMSE is taken after it. `skip_steps`: the
    first that many steps run but are not recorded (a recording exported from part-way through a
    test: the cell is not at rest when it starts); the recorded time starts at 0 with the next
    step, and the comparison runs the same unrecorded steps. `keep(t, i, v, rng)` returns which
    of the simulated points the logger writes (applied where `cycler_sampling` is); `sampling`
    then describes it in truth.json. `temp_offset_K` is added to the recorded temperature (a
    thermocouple's calibration offset). `surface_form_ok` lets PyBaMM's SPMe with a surface
    form through (only to remake ak7 as it was first made)."""
    # PyBaMM's SPM family switches to "surface form" = "algebraic" for any non-default
    # kinetics (asymmetric Butler-Volmer, a size distribution): for the SPMe that is another
    # model (36 mV RMS above its own SPMe at 2C with alpha = 0.5), which would hide a second,
    # unlabelled effect in the case (ak7 was made so). The SPM is the same model either way.
    if isinstance(model, pybamm.lithium_ion.SPMe) and model.options["surface form"] != "false" and not surface_form_ok:
        raise ValueError(f"{name}: PyBaMM's SPMe with surface form {model.options['surface form']!r} is another model; use the DFN")
    experiment = pybamm.Experiment(steps, period=f"{period} seconds")
    solver = pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8)
    sim = pybamm.Simulation(model, parameter_values=params, experiment=experiment, solver=solver)
    sol = sim.solve(initial_soc=initial_soc)
    t = sol["Time [s]"].entries
    i_cell = sol["Current [A]"].entries
    i = (i_cell - leak_A) * current_gain
    v = sol["Voltage [V]"].entries
    if post is not None:
        v = post(t, i_cell, v)
    temp = sol["X-averaged cell temperature [K]"].entries if temperature else None
    skipped = sum(len(c["Time [s]"].entries) for c in sol.cycles[:skip_steps])
    if skip_steps:
        t0 = t[skipped]
        t, i_cell, i, v = t[skipped:] - t0, i_cell[skipped:], i[skipped:], v[skipped:]
        temp = temp[skipped:] if temp is not None else None
    rng = np.random.default_rng(seed)
    if cycler is not None and cycler.get("irregular"):
        kept = cycler_sampling(t, i, v)
        t, i, v = t[kept], i[kept], v[kept]
        temp = temp[kept] if temp is not None else None
    if keep is not None:
        kept = keep(t, i, v, rng)
        t, i, v = t[kept], i[kept], v[kept]
        temp = temp[kept] if temp is not None else None
    v_true = v
    v = v + rng.normal(0.0, noise, v.shape)
    if cycler is not None:
        i = i + rng.normal(0.0, cycler.get("current_noise_A", 0.0), i.shape)
        i = np.round(i / cycler.get("quantum_A", 1e-4)) * cycler.get("quantum_A", 1e-4)
        v = np.round(v / cycler.get("quantum_V", 1e-4)) * cycler.get("quantum_V", 1e-4)
    folder = os.path.join(root, name)
    os.makedirs(folder, exist_ok=True)
    columns = [t, i, v]
    header = "time_s,current_A,voltage_V"
    if temperature:
        temp = temp + temp_offset_K + rng.normal(0.0, NOISE_K, t.shape)
        if cycler is not None and cycler.get("quantum_K"):
            temp = np.round(temp / cycler["quantum_K"]) * cycler["quantum_K"]
        columns.append(temp)
        header += ",temperature_K"
    np.savetxt(os.path.join(folder, "recording.csv"), np.column_stack(columns), delimiter=",", header=header, comments="", fmt="%.6f")
    truth.update({"noise_V": noise, "sampling_s": period, "points": int(len(t)), "made_by": f"PyBaMM {pybamm.__version__}, Chen2020, IDAKLU rtol=atol=1e-8"})
    if cycler is not None:
        truth["cycler"] = {k: v_ for k, v_ in cycler.items()}
        if cycler.get("irregular"):
            truth["sampling_s"] = "irregular: 1 s in the first 60 s of a step and in steps up to 5 min, then 30 s under load / 60 s at rest, plus every 5 mV or 50 mA"
    if sampling is not None:
        truth["sampling_s"] = sampling
    if compare is not None:
        amb = truth.get("ambient_temperature_K", 298.15)
        p0 = truth.pop("compare_params", None) or chen()
        p0.update({"Ambient temperature [K]": amb, "Initial temperature [K]": amb})
        ref_experiment = pybamm.Experiment(compare_steps, period=f"{period} seconds") if compare_steps is not None else experiment
        ref = pybamm.Simulation(compare, parameter_values=p0, experiment=ref_experiment, solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8)).solve(initial_soc=initial_soc)
        tr, vr = ref["Time [s]"].entries, ref["Voltage [V]"].entries
        if skip_steps:
            n0 = sum(len(c["Time [s]"].entries) for c in ref.cycles[:skip_steps])
            tr, vr = tr[n0:] - tr[n0], vr[n0:]
        single = np.ones(len(t), dtype=bool)
        single[1:] &= t[1:] - t[:-1] > 1e-6
        single[:-1] &= t[1:] - t[:-1] > 1e-6
        single &= t <= tr[-1]
        _, first = np.unique(tr, return_index=True)
        d = v[single] - np.interp(t[single], tr[first], vr[first])
        truth["candidate_rmse_mV"] = round(1e3 * float(np.sqrt(np.mean(d ** 2))), 2)
        truth["effect_rmse_mV"] = round(1e3 * float(np.sqrt(np.mean((v_true[single] - np.interp(t[single], tr[first], vr[first])) ** 2))), 2)
    truth.setdefault("ambient_temperature_K", 298.15)
    with open(os.path.join(folder, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"{name}: {len(t)} points, {t[-1]:.0f} s")


lion = pybamm.lithium_ion


def discharge(rate):
    return [f"Discharge at {rate} until 2.7 V", "Rest for 30 minutes"]


def drive_cycle(seed, steps, low, high, seconds):
    """A random current drive: `steps` steps of `seconds` at C-rates drawn from [low, high]."""
    rng = np.random.default_rng(seed)
    drive = []
    for _ in range(steps):
        c = float(rng.uniform(low, high))
        drive.append(f"{'Discharge' if c >= 0 else 'Charge'} at {abs(c):.2f}C for {seconds} seconds" if abs(c) > 0.05 else f"Rest for {seconds} seconds")
    return drive


def batch_u(root):

    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.25)
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



def batch_v(root):
    """Second batch, made after the first had been judged and the selection fixed (6/6 at the
    first run)."""
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.3)
    write_case(root, "v1_diffusivity_positive_1C", lion.DFN(), p, discharge("1C"), {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["diffusiv"], "note": "positive particle diffusivity x0.3"}, seed=11)
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.3)
    write_case(root, "v2_kinetics_1C", lion.DFN(), p, discharge("1C"), {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "charge transfer", "exchange"], "note": "exchange currents x0.3, 1C"}, seed=12)
    p = chen(); p.update({"Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    write_case(root, "v3_thermal_1p5C", lion.DFN(options={"thermal": "lumped"}), p, discharge("1.5C"), {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "heat"], "note": "lumped self-heating h = 10, 1.5C"}, temperature=True, seed=13)
    write_case(root, "v4_control_cycle", lion.SPMe(), chen(), ["Discharge at C/3 for 90 minutes", "Rest for 20 minutes", "Charge at C/3 for 60 minutes", "Rest for 20 minutes"], {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "note": "negative control, C/3 partial cycle"}, seed=14)
    p = chen(); p.update({"Contact resistance [Ohm]": 0.02}, check_already_exists=False)
    write_case(root, "v5_contact_two_rates", lion.SPM(options={"contact resistance": "true"}), p, ["Discharge at 1C for 60 seconds", "Rest for 10 minutes", "Discharge at 2C for 60 seconds", "Rest for 10 minutes"] * 4, {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance"], "note": "20 mOhm, pulses at 1C and 2C"}, seed=15)
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    write_case(root, "v6_inventory_dfn_C5", lion.DFN(), p, discharge("C/5"), {"effect": "lithium_inventory_loss", "candidate_model": "dfn", "accept": ["inventory", "stoichiometr", "capacity"], "note": "5 % less negative lithium, C/5"}, seed=16)



def batch_w(root):
    """Third batch, made at the end of the session that fixed the selection; its first run named
    5 of 6 (w5, electrolyte diffusivity x0.3 at 1.5C, ends at the cut-off after 3 minutes:
    first refused as a unit error, then "unexplained" since the candidate's refit breaks
    down where the electrolyte depletes)."""
    p = scaled(chen(), "Negative particle radius [m]", 1.6)
    write_case(root, "w1_radius_negative_1C", lion.DFN(), p, discharge("1C"), {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["diffusiv", "particle"], "note": "negative particle radius x1.6 (diffusion length)"}, seed=21)
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    write_case(root, "w2_lam_positive_C3", lion.SPMe(), p, discharge("C/3"), {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material", "capacity", "stoichiometr"], "note": "8 % positive LAM at C/3"}, seed=22)
    p = chen(); p.update({"Total heat transfer coefficient [W.m-2.K-1]": 50.0})
    write_case(root, "w3_thermal_spme_2C", lion.SPMe(options={"thermal": "lumped"}), p, discharge("2C"), {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "heat"], "note": "lumped self-heating h = 50, 2C, SPMe data"}, temperature=True, seed=23)
    drive = drive_cycle(24, 40, -1.0, 2.0, 20)
    write_case(root, "w4_control_drive_dfn", lion.DFN(), chen(), drive, {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "note": "negative control: DFN drive cycle from 60 % SOC"}, initial_soc=0.6, seed=24)
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.3)
    write_case(root, "w5_electrolyte_diffusivity_1p5C", lion.DFN(), p, discharge("1.5C"), {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "note": "electrolyte diffusivity x0.3, 1.5C"}, seed=25)
    p = chen(); p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    write_case(root, "w6_control_warm", lion.SPMe(), p, discharge("1C"), {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 308.15, "note": "negative control at 35 degC, temperature recorded"}, temperature=True, seed=26)



def batch_x(root):
    """Fourth batch, made at the start of the next session before any change to the diagnosis:
    protocols the others lack (charge with a voltage hold, GITT on a diffusivity, a drive cycle
    on a resistance, a cold cell heating up, mixed charge/discharge pulses)."""
    p = chen(); p.update({"Contact resistance [Ohm]": 0.015}, check_already_exists=False)
    write_case(root, "x1_contact_drive_dfn", lion.DFN(options={"contact resistance": "true"}), p, drive_cycle(31, 40, -1.0, 2.0, 15),
               {"effect": "contact_resistance", "candidate_model": "dfn", "accept": ["contact", "series resistance"],
                "note": "15 mOhm, DFN drive cycle from 80 % SOC"}, initial_soc=0.8, seed=31)
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.2)
    write_case(root, "x2_kinetics_cccv_charge", lion.SPMe(), p, ["Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 30 minutes"],
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "charge transfer", "exchange"],
                "note": "exchange currents x0.2, CC-CV charge from 10 % SOC"}, initial_soc=0.1, seed=32)
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.88)
    write_case(root, "x3_lam_negative_C2", lion.DFN(), p, discharge("C/2"),
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material", "capacity", "stoichiometr"],
                "note": "12 % loss of negative active material, C/2"}, seed=33)
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.1)
    write_case(root, "x4_diffusivity_negative_gitt", lion.SPMe(), p, ["Discharge at C/2 for 10 minutes", "Rest for 30 minutes"] * 6,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["diffusiv"],
                "note": "negative particle diffusivity x0.1, C/2 GITT"}, seed=34)
    p = chen(); p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15, "Total heat transfer coefficient [W.m-2.K-1]": 5.0})
    write_case(root, "x5_thermal_cold_1C", lion.DFN(options={"thermal": "lumped"}), p, discharge("1C"),
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "heat"], "ambient_temperature_K": 278.15,
                "note": "lumped self-heating h = 5 at 5 degC, 1C"}, temperature=True, seed=35)
    hppc = []
    for rate in ["1C", "2C"]:
        hppc += [f"Discharge at {rate} for 10 seconds", "Rest for 40 seconds", f"Charge at {rate} for 10 seconds", "Rest for 5 minutes", "Discharge at C/2 for 6 minutes", "Rest for 10 minutes"]
    write_case(root, "x6_control_hppc_spm", lion.SPM(), chen(), hppc * 2,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "note": "negative control: SPM HPPC pulses from 90 % SOC"},
               initial_soc=0.9, seed=36)



def with_negative_hysteresis(p, half_width):
    """One-state OCV hysteresis of the negative electrode: lithiation and delithiation OCPs
    `half_width` (V) either side of the set's OCP, decay rate 10, starting in the middle."""
    u_n = p["Negative electrode OCP [V]"]
    p.update({
        "Negative electrode lithiation OCP [V]": lambda *a: u_n(*a) - half_width,
        "Negative electrode delithiation OCP [V]": lambda *a: u_n(*a) + half_width,
        "Negative particle lithiation hysteresis decay rate": 10.0,
        "Negative particle delithiation hysteresis decay rate": 10.0,
        "Initial hysteresis state in negative electrode": 0.0,
    }, check_already_exists=False)


def batch_y(root):
    """Fifth batch, made before any change it could have guided: an effect the bench never
    shows (one-state OCV hysteresis), noisier and coarser recordings, self-heating without a
    recorded temperature, the SPM on a DFN drive cycle, lithium loss seen through a CC-CV
    charge, and a noisy DFN control."""
    p = chen()
    with_negative_hysteresis(p, 0.012)
    cycle = ["Discharge at C/2 for 30 minutes", "Rest for 30 minutes", "Charge at C/2 for 30 minutes", "Rest for 30 minutes"] * 2
    write_case(root, "y1_hysteresis_negative_spme", lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, cycle,
               {"effect": "hysteresis", "candidate_model": "spme", "accept": ["hysteresis"],
                "note": "one-state hysteresis of the negative OCP, +-12 mV, C/2 partial cycles from 60 % SOC"}, initial_soc=0.6, seed=41)
    p = chen(); p.update({"Contact resistance [Ohm]": 0.01}, check_already_exists=False)
    write_case(root, "y2_contact_noisy_coarse", lion.SPMe(options={"contact resistance": "true"}), p,
               ["Discharge at 1C for 20 minutes", "Rest for 20 minutes", "Discharge at 2C for 5 minutes", "Rest for 20 minutes"],
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance"],
                "note": "10 mOhm, 3 mV noise, sampled every 10 s"}, seed=42, noise=3e-3, period=10)
    p = chen(); p.update({"Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    write_case(root, "y3_thermal_unrecorded", lion.DFN(options={"thermal": "lumped"}), p,
               ["Discharge at C/2 for 30 minutes", "Rest for 30 minutes", "Discharge at 2C until 2.7 V", "Rest for 30 minutes"],
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "heat"],
                "note": "lumped self-heating h = 10, no temperature recorded, C/2 then 2C"}, seed=43)
    write_case(root, "y4_electrolyte_drive_spm", lion.DFN(), chen(), drive_cycle(44, 60, -1.0, 3.0, 10),
               {"effect": "electrolyte_transport", "candidate_model": "spm", "accept": ["electrolyte"],
                "note": "DFN data, SPM given: drive cycle to 3C from 90 % SOC"}, initial_soc=0.9, seed=44)
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94)
    write_case(root, "y5_inventory_cccv", lion.SPMe(), p,
               ["Discharge at 1C until 2.7 V", "Rest for 20 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 20 minutes"],
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "stoichiometr", "capacity"],
                "note": "6 % less lithium, discharge then CC-CV charge"}, seed=45)
    write_case(root, "y6_control_noisy_dfn", lion.DFN(), chen(), discharge("1C"),
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "note": "negative control: DFN, 5 mV noise"}, seed=46, noise=5e-3)



def batch_z(root):
    """Sixth batch: two effects at once (the bench has one such case), judged as the bench
    judges b8: the rounds together name both."""
    pulses = lambda rate: [f"Discharge at {rate} for 30 seconds", "Rest for 5 minutes"]
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.3)
    p.update({"Contact resistance [Ohm]": 0.008}, check_already_exists=False)
    write_case(root, "z1_kinetics_and_contact", lion.SPMe(options={"contact resistance": "true"}), p, (pulses("1C") + pulses("3C")) * 5,
               {"effect": "kinetics+contact_resistance", "candidate_model": "spme", "accept": ["kinetic|charge transfer|exchange", "contact|series resistance"],
                "note": "exchange currents x0.3 and 8 mOhm, pulses at 1C and 3C from 90 % SOC"}, initial_soc=0.9, seed=51)
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.9)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 15.0})
    write_case(root, "z2_lam_and_thermal", lion.DFN(options={"thermal": "lumped"}), p, discharge("1.5C"),
               {"effect": "active_material_loss+thermal", "candidate_model": "dfn", "accept": ["active material|capacity|stoichiometr", "thermal|heat"],
                "note": "10 % positive LAM and self-heating h = 15 at 1.5C, temperature recorded"}, temperature=True, seed=52)
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.25)
    write_case(root, "z3_inventory_and_diffusivity", lion.SPMe(), p, discharge("1C"),
               {"effect": "lithium_inventory_loss+solid_diffusivity", "candidate_model": "spme", "accept": ["inventory|stoichiometr|capacity", "diffusiv"],
                "note": "5 % less lithium and negative diffusivity x0.25, 1C"}, seed=53)
    p = chen(); p.update({"Contact resistance [Ohm]": 0.01}, check_already_exists=False)
    write_case(root, "z4_electrolyte_and_contact_spm", lion.DFN(options={"contact resistance": "true"}), p, ["Discharge at 2C for 5 minutes", "Rest for 10 minutes"] * 4,
               {"effect": "electrolyte_transport+contact_resistance", "candidate_model": "spm", "accept": ["electrolyte", "contact|series resistance"],
                "note": "DFN data with 10 mOhm, SPM given, 2C pulses"}, seed=54)



def batch_q(root):
    """Seventh batch: parameters off in the other direction (faster kinetics and diffusion
    than the set's), negative LAM under a drive cycle, and a resistance in a self-heating cell
    whose temperature is recorded (two effects)."""
    p = chen()
    p.update({"Contact resistance [Ohm]": 0.01, "Total heat transfer coefficient [W.m-2.K-1]": 20.0}, check_already_exists=False)
    write_case(root, "q1_contact_in_warming_cell", lion.DFN(options={"thermal": "lumped", "contact resistance": "true"}), p,
               ["Discharge at 2C for 2 minutes", "Rest for 5 minutes"] * 6,
               {"effect": "contact_resistance+thermal", "candidate_model": "dfn", "accept": ["contact|series resistance", "thermal|heat"],
                "note": "10 mOhm and lumped self-heating h = 20, 2C pulses, temperature recorded"}, temperature=True, seed=61)
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.92)
    write_case(root, "q2_lam_negative_drive_spme", lion.SPMe(), p, drive_cycle(62, 120, -0.5, 2.0, 30),
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material", "capacity", "stoichiometr"],
                "note": "8 % negative LAM, an hour of drive cycle from full"}, seed=62)
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 3.0)
    write_case(root, "q3_faster_kinetics_pulses", lion.SPMe(), p, ["Discharge at 1C for 60 seconds", "Rest for 5 minutes", "Discharge at 2C for 30 seconds", "Rest for 5 minutes"] * 4,
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "charge transfer", "exchange"],
                "note": "exchange currents x3 (faster than the set's), pulses at 1C and 2C from full"}, seed=63)
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 3.0)
    write_case(root, "q4_faster_diffusion_2C_dfn", lion.DFN(), p, discharge("2C"),
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["diffusiv"],
                "note": "positive particle diffusivity x3 (faster than the set's), 2C"}, seed=64)


def urban_drive(seed, segments):
    """A structured drive: each segment accelerates (1.5-3C, 5-11 s), cruises (0.3-1C, 10-39 s),
    brakes with regeneration (charge 0.5-1.5C, 4-9 s) and idles (5-29 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(segments):
        steps.append(f"Discharge at {rng.uniform(1.5, 3.0):.2f}C for {int(rng.integers(5, 12))} seconds")
        steps.append(f"Discharge at {rng.uniform(0.3, 1.0):.2f}C for {int(rng.integers(10, 40))} seconds")
        steps.append(f"Charge at {rng.uniform(0.5, 1.5):.2f}C for {int(rng.integers(4, 10))} seconds")
        steps.append(f"Rest for {int(rng.integers(5, 30))} seconds")
    return steps


def batch_r(root):
    """Eighth batch, made blind (before any run of the diagnosis on it): ambients of 40 and
    10 degC, a constant-power discharge, a CC-CV charge, effects near the detection limit
    (4 mOhm at C/2, 7 % lithium at low SOC), a structured drive cycle, a GITT sampled every 3 s,
    two effects in a partial-discharge/HPPC protocol, and a charge-then-discharge DFN control.
    Lithium loss and active-material loss are accepted only by their own words ("inventory",
    "active material"), not by the shared "capacity"/"stoichiometr" of earlier batches."""
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.4)
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    write_case(root, "r1_diffusivity_positive_power_40C", lion.SPMe(), p, ["Discharge at 18 W until 2.7 V", "Rest for 40 minutes"],
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["diffusiv"], "ambient_temperature_K": 313.15,
                "note": "positive particle diffusivity x0.4 at 40 degC (isothermal), constant-power 18 W discharge from full"}, seed=71)
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.3)
    write_case(root, "r2_diffusivity_negative_cccv_charge", lion.DFN(), p,
               ["Rest for 10 minutes", "Charge at 0.7C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"],
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["diffusiv"],
                "note": "negative particle diffusivity x0.3, seen only in a CC-CV charge (0.7C to 4.2 V, hold to C/20) from 10 % SOC"},
               initial_soc=0.1, seed=72)
    p = chen(); p.update({"Contact resistance [Ohm]": 0.004}, check_already_exists=False)
    write_case(root, "r3_contact_4mohm_c2_pulses", lion.DFN(options={"contact resistance": "true"}), p,
               ["Discharge at C/2 for 60 seconds", "Rest for 3 minutes", "Charge at C/2 for 60 seconds", "Rest for 3 minutes"] * 10,
               {"effect": "contact_resistance", "candidate_model": "dfn", "accept": ["contact", "series resistance"],
                "note": "4 mOhm contact resistance (10 mV at C/2), symmetric C/2 pulses at 50 % SOC, 1 mV noise"},
               initial_soc=0.5, seed=73)
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.93)
    write_case(root, "r4_inventory_low_soc_pulses_spm", lion.SPM(), p,
               ["Discharge at 1C for 36 minutes", "Rest for 20 minutes"] + ["Discharge at 1C for 60 seconds or until 2.7 V", "Rest for 5 minutes"] * 18,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["inventory"],
                "note": "7 % less lithium in the negative electrode; 1C for 36 min (3 A h), then 18 pulses of 1C for 60 s with 5 min rests at low SOC (the last down to 2.84 V)"}, seed=74)
    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.4)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    write_case(root, "r5_conductivity_urban_drive_10C", lion.SPMe(), p, urban_drive(75, 40),
               {"effect": "electrolyte_transport", "candidate_model": "spme", "accept": ["electrolyte"], "ambient_temperature_K": 283.15,
                "note": "electrolyte conductivity x0.4 at 10 degC (isothermal), structured drive (accelerate/cruise/regen/idle) to 3C from 75 % SOC"},
               initial_soc=0.75, seed=75)
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.9)
    write_case(root, "r6_lam_positive_gitt_3s", lion.DFN(), p,
               ["Discharge at C/3 for 15 minutes or until 2.7 V", "Rest for 25 minutes"] * 11 + ["Discharge at C/3 until 2.7 V", "Rest for 30 minutes"],
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"],
                "note": "10 % loss of positive active material, C/3 GITT (15 min on, 25 min rest) from full, sampled every 3 s"},
               seed=76, period=3)
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.4)
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.95)
    block = ["Discharge at 0.8C for 15 minutes or until 2.7 V", "Rest for 10 minutes", "Discharge at 2C for 20 seconds", "Rest for 5 minutes",
             "Charge at 1C for 20 seconds", "Rest for 5 minutes"]
    write_case(root, "r7_kinetics_and_inventory_hppc", lion.SPMe(), p, block * 4 + ["Discharge at 0.8C until 2.7 V", "Rest for 20 minutes"],
               {"effect": "kinetics+lithium_inventory_loss", "candidate_model": "spme", "accept": ["kinetic|charge transfer|exchange", "inventory"],
                "note": "exchange currents x0.4 and 5 % less lithium; 0.8C partial discharges each followed by 2C/1C pulses, then to 2.7 V"}, seed=77)
    write_case(root, "r8_control_cccv_then_discharge_dfn", lion.DFN(), chen(),
               ["Rest for 5 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 20 minutes", "Discharge at 1C until 3.0 V", "Rest for 20 minutes"],
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"],
                "note": "negative control: DFN data, DFN model, CC-CV charge from 20 % SOC then 1C discharge to 3.0 V"}, initial_soc=0.2, seed=78)


CYCLER = {"irregular": True, "current_noise_A": 3e-3, "quantum_A": 1e-4, "quantum_V": 1e-4, "quantum_K": 0.1}


def activation_energy(p, side, reference, new):
    """Exchange current of `side` with activation energy `new` (J/mol) in place of the set's
    `reference`: the same at 25 degC, different at any other temperature."""
    name = f"{side} electrode exchange-current density [A.m-2]"
    f = p[name]
    p.update({name: lambda c_e, c_s, c_max, T, f=f: f(c_e, c_s, c_max, T) * np.exp((new - reference) / pybamm.constants.R * (1 / 298.15 - 1 / T))})
    return p


def batch_s(root):
    """Ninth batch, made blind (a helper session, judged once on a frozen binary before
    anything else) and closer to measured data: what a cycler logs (3 mA current noise on
    the set point, irregular sampling with 30-60 s in long constant stretches, 0.1 mV and
    0.1 K resolution), 3 mV noise, an effect near the detection limit, parameters outside the
    candidate list whose physics maps onto a listed family (Bruggeman exponent, particle
    radius, electrode thickness, activation energies), 0 and 45 degC, a 3.6 h mixed
    recording, a charge-only recording, two effects with one thermal and the temperature
    recorded, and a reference-performance-test control. Lithium and active-material loss are
    accepted only by their own words, as in batch r. First run (frozen binary sha256
    c6cbecf0221c): 8 of 8; s4 a tie (kinetics, positive 0.802x, or 0.56 mOhm), s7's first
    round named the diffusivities at wrong values (right only when refitted with thermal)."""
    p = chen()
    p.update({f"{region} Bruggeman coefficient (electrolyte)": 1.7 for region in ["Negative electrode", "Separator", "Positive electrode"]})
    hppc = ["Discharge at 1C for 12 minutes", "Rest for 20 minutes", "Discharge at 2C for 20 seconds", "Rest for 2 minutes",
            "Charge at 1.5C for 20 seconds", "Rest for 10 minutes"]
    write_case(root, "s1_bruggeman_hppc_cycler", lion.DFN(), p, ["Rest for 10 minutes"] + hppc * 4,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"],
                "note": "Bruggeman exponent of the electrolyte 1.7 instead of 1.5 in all three regions (more tortuous: effective "
                        "diffusivity and conductivity x0.76 in the negative, x0.86 in the separator, x0.80 in the positive); not a "
                        "candidate parameter, its physics is the electrolyte transport family (properties factors). 1C partial "
                        "discharges with 2C/1.5C pulses from full; cycler artefacts"},
               seed=81, cycler=CYCLER, compare=lion.DFN())
    p = scaled(chen(), "Positive particle radius [m]", 1.5)
    write_case(root, "s2_radius_positive_charge_only", lion.SPMe(), p,
               ["Rest for 15 minutes", "Charge at 1C until 4.0 V", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/50", "Rest for 45 minutes"],
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["diffusiv", "particle"],
                "note": "positive particle radius x1.5 (diffusion time x2.25, and 1/1.5 of the surface area); not a candidate "
                        "parameter, its physics is the particle diffusion family. Charge only: two-stage CC (1C to 4.0 V, C/3 to "
                        "4.2 V) and CV to C/50 from 20 % SOC; cycler artefacts"},
               initial_soc=0.2, seed=82, cycler=CYCLER, compare=lion.SPMe())
    p = scaled(chen(), "Positive electrode thickness [m]", 0.92)
    write_case(root, "s3_thickness_positive_3mV", lion.DFN(), p, ["Discharge at C/2 until 2.7 V", "Rest for 1 hour"],
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"],
                "note": "positive electrode 8 % thinner (8 % less positive capacity, shorter ionic path); not a candidate "
                        "parameter, its physics is loss of positive active material. C/2 from full, 3 mV noise"},
               seed=83, noise=3e-3, compare=lion.DFN())
    p = scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.8)
    pulses = []
    for rate in ["1C", "2C"]:
        pulses += [f"Discharge at {rate} for 20 seconds", "Rest for 3 minutes", f"Charge at {rate} for 20 seconds", "Rest for 3 minutes"]
    write_case(root, "s4_kinetics_positive_near_limit", lion.SPMe(), p, ["Rest for 5 minutes"] + pulses * 4,
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "charge transfer", "exchange"],
                "note": "positive exchange current x0.8 only (about 6.5 mV more at a 2C pulse, 1.5 mV RMS over the 1 s record): "
                        "near the detection limit for 1 mV noise. Symmetric 1C and 2C pulses of 20 s at 60 % SOC; cycler artefacts"},
               initial_soc=0.6, seed=84, cycler=CYCLER, compare=lion.SPMe())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    mixed = (["Discharge at C/2 for 40 minutes", "Rest for 10 minutes"] + urban_drive(85, 12) + ["Rest for 10 minutes", "Charge at 1C for 15 minutes",
             "Rest for 10 minutes", "Discharge at 1C until 2.7 V", "Rest for 30 minutes", "Charge at 1C for 20 minutes", "Rest for 20 minutes"])
    write_case(root, "s5_inventory_long_mixed_45C", lion.SPMe(), p, mixed,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory"], "ambient_temperature_K": 318.15,
                "note": "5 % less lithium in the negative electrode at 45 degC (isothermal); about 3.6 h of mixed charge/discharge "
                        "from full (C/2, urban drive with regeneration, 1C charge, 1C to 2.7 V, 1C charge), 1 s sampling with "
                        "3 mA current noise and 0.1 mV resolution"},
               seed=85, cycler={"current_noise_A": 3e-3, "quantum_A": 1e-4, "quantum_V": 1e-4}, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    p = activation_energy(p, "Negative", 35000.0, 55000.0)
    p = activation_energy(p, "Positive", 17800.0, 40000.0)
    cold = []
    for rate in ["C/2", "1C"]:
        cold += [f"Discharge at {rate} for 30 seconds", "Rest for 4 minutes", f"Charge at {rate} for 30 seconds", "Rest for 4 minutes"]
    write_case(root, "s6_activation_energy_0C", lion.DFN(), p, (cold + ["Discharge at C/2 for 6 minutes", "Rest for 15 minutes"]) * 3,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "charge transfer", "exchange"], "ambient_temperature_K": 273.15,
                "note": "activation energies of the exchange currents 55 kJ/mol (negative, set 35) and 40 kJ/mol (positive, set "
                        "17.8): at 0 degC the exchange currents are 0.48x and 0.44x the set's; not a candidate parameter, at one "
                        "temperature its physics is the kinetics family. Isothermal at 0 degC (cell temperature recorded, "
                        "constant); C/2 and 1C pulses from 70 % SOC"},
               initial_soc=0.7, temperature=True, seed=86, compare=lion.DFN())
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.3)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 8.0})
    write_case(root, "s7_diffusivity_and_thermal_cycler", lion.DFN(options={"thermal": "lumped"}), p,
               ["Rest for 10 minutes", "Discharge at 1.5C until 2.7 V", "Rest for 30 minutes", "Charge at 1C for 30 minutes", "Rest for 30 minutes"],
               {"effect": "solid_diffusivity+thermal", "candidate_model": "dfn", "accept": ["diffusiv", "thermal|heat"],
                "note": "negative particle diffusivity x0.3 and lumped self-heating h = 8 W/(m2 K); 1.5C to 2.7 V, rest, 1C "
                        "charge, rest; temperature recorded (0.1 K resolution); cycler artefacts"},
               temperature=True, seed=87, cycler=CYCLER, compare=lion.DFN())
    rpt = ["Rest for 30 minutes", "Discharge at C/3 until 2.5 V", "Rest for 1 hour", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour"]
    write_case(root, "s8_control_rpt_dfn", lion.DFN(), chen(), rpt,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"],
                "note": "negative control: a reference performance test (C/3 to 2.5 V, 1 h rest, C/3 CC-CV to 4.2 V and C/20, 1 h "
                        "rest) from full, DFN data and model; cycler artefacts"},
               initial_soc=1.0, seed=88, cycler=CYCLER, compare=lion.DFN())


def batch_t(root):
    """Tenth batch, made blind (a helper session, judged once on a frozen binary before anything
    else) to test the rule that refits pairs when the best single leaves a hold-out RMSE above
    3x the size floor: four two-effect pairs not used before (negative LAM + contact under
    pulses; kinetics + self-heating with the temperature recorded; electrolyte conductivity +
    lithium loss; positive diffusivity + negative LAM), two single effects handed an SPMe on DFN
    data (the SPMe's own error near the knee, 4-9 mV RMS, stays after the right single:
    naming electrolyte transport beside it is right, any other partner is a stand-in), one large
    single (25 % positive LAM) where a pair should not be preferred, and a long mixed DFN
    control. Lithium and active-material loss are accepted only by their own words."""
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.92)
    p.update({"Contact resistance [Ohm]": 0.008}, check_already_exists=False)
    block = ["Discharge at 1C for 6 minutes or until 2.7 V", "Rest for 5 minutes", "Discharge at 2C for 30 seconds or until 2.7 V", "Rest for 3 minutes"]
    write_case(root, "t1_lam_negative_and_contact_pulses", lion.DFN(options={"contact resistance": "true"}), p,
               block * 7 + ["Discharge at 1C until 2.7 V", "Rest for 30 minutes"],
               {"effect": "active_material_loss+contact_resistance", "candidate_model": "dfn", "accept": ["active material", "contact|series resistance"],
                "note": "8 % loss of negative active material (at the lithiated state, default initial concentrations) and 8 mOhm contact "
                        "resistance; from full, 7 x (1C for 6 min, 5 min rest, 2C for 30 s, 3 min rest), then 1C to 2.7 V and 30 min rest"},
               seed=91, compare=lion.DFN())
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.3)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 20.0})
    pulses = ["Discharge at 1C for 20 seconds", "Rest for 3 minutes", "Discharge at 3C for 20 seconds", "Rest for 3 minutes",
              "Charge at 1C for 20 seconds", "Rest for 3 minutes"]
    write_case(root, "t2_kinetics_and_thermal_recorded", lion.DFN(options={"thermal": "lumped"}), p,
               ["Rest for 5 minutes"] + pulses * 3 + ["Discharge at 1.5C until 2.7 V", "Rest for 40 minutes"],
               {"effect": "kinetics+thermal", "candidate_model": "dfn", "accept": ["kinetic|charge transfer|exchange", "thermal|heat"],
                "note": "exchange currents x0.3 (both electrodes) and lumped self-heating h = 20 W/(m2 K); 3 x (1C, 3C discharge and 1C "
                        "charge pulses of 20 s with 3 min rests) from 80 % SOC, then 1.5C to 2.7 V (about 22 K rise) and 40 min rest; "
                        "temperature recorded"},
               initial_soc=0.8, temperature=True, seed=92, compare=lion.DFN())
    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.5)
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.96)
    two_rates = ["Discharge at 1C for 20 seconds", "Rest for 3 minutes", "Discharge at 3C for 20 seconds", "Rest for 3 minutes"]
    write_case(root, "t3_conductivity_and_inventory", lion.DFN(), p,
               ["Rest for 5 minutes"] + two_rates * 2 + ["Discharge at 1C until 2.7 V", "Rest for 30 minutes", "Charge at 1C for 20 minutes",
                                                       "Rest for 10 minutes"] + two_rates,
               {"effect": "electrolyte_transport+lithium_inventory_loss", "candidate_model": "dfn", "accept": ["electrolyte", "inventory"],
                "note": "electrolyte conductivity x0.5 and 4 % less lithium in the negative electrode; 1C/3C pulses from full, 1C to "
                        "2.7 V, 30 min rest, 1C charge for 20 min, 1C/3C pulses at low SOC"},
               seed=93, compare=lion.DFN())
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.3)
    p = scaled(p, "Negative electrode active material volume fraction", 0.92)
    write_case(root, "t4_diffusivity_positive_and_lam_negative", lion.SPMe(), p,
               ["Discharge at 1.5C until 2.7 V", "Rest for 20 minutes", "Discharge at C/3 until 2.7 V", "Rest for 20 minutes", "Charge at 1C until 4.1 V",
                "Rest for 20 minutes"],
               {"effect": "solid_diffusivity+active_material_loss", "candidate_model": "spme", "accept": ["diffusiv", "active material"],
                "note": "positive particle diffusivity x0.3 and 8 % loss of negative active material (default initial concentrations); "
                        "1.5C from full to 2.7 V (ends early, at about 29 min), 20 min rest, the rest of the capacity at C/3 to 2.7 V, 20 min "
                        "rest, 1C charge to 4.1 V, 20 min rest; SPMe data"},
               seed=94, compare=lion.SPMe())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94)
    write_case(root, "t5_inventory_dfn_data_spme_1p5C", lion.DFN(), p,
               ["Rest for 5 minutes", "Discharge at 1.5C until 2.7 V", "Rest for 30 minutes", "Charge at C/2 for 40 minutes", "Rest for 20 minutes"],
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory"],
                "note": "6 % less lithium in the negative electrode, DFN data handed to the SPMe; 1.5C from full to 2.7 V, 30 min rest, "
                        "C/2 charge for 40 min, 20 min rest. The SPMe's own error on this protocol (PyBaMM's SPMe against its DFN, both "
                        "with the lithium loss) is 9.1 mV RMS, most of it near the knee, against 65.8 mV from the lithium loss. One concealed effect: a first verdict must name lithium inventory; "
                        "electrolyte transport (SPMe -> DFN) beside it is right too, any other partner is a stand-in for the SPMe's error"},
               seed=95, compare=lion.SPMe())
    p = chen(); p.update({"Contact resistance [Ohm]": 0.01}, check_already_exists=False)
    write_case(root, "t6_contact_dfn_data_spme_3C_pulses", lion.DFN(options={"contact resistance": "true"}), p,
               ["Rest for 5 minutes"] + ["Discharge at 3C for 20 seconds", "Rest for 3 minutes", "Charge at 1.5C for 20 seconds", "Rest for 3 minutes"] * 4
               + ["Discharge at 1C until 2.7 V", "Rest for 30 minutes"],
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance"],
                "note": "10 mOhm contact resistance, DFN data handed to the SPMe: 3C discharge / 1.5C charge pulses of 20 s from 80 % SOC, "
                        "then 1C to 2.7 V and 30 min rest. The SPMe's own error on this protocol is 4.0 mV RMS (PyBaMM's SPMe "
                        "against its DFN, both with the resistance), most of it at the 1C knee, against 43.3 mV RMS (150 mV steps at "
                        "3C) from the resistance. One concealed "
                        "effect: electrolyte transport (SPMe -> DFN) beside it is right too, any other partner is a stand-in"},
               initial_soc=0.8, seed=96, compare=lion.SPMe())
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.75)
    write_case(root, "t7_lam_positive_25pct_dfn", lion.DFN(), p,
               ["Discharge at 1C until 2.7 V", "Rest for 30 minutes", "Charge at C/2 for 60 minutes", "Rest for 20 minutes",
                "Discharge at 2C for 30 seconds", "Rest for 5 minutes", "Charge at 1C for 30 seconds", "Rest for 10 minutes"],
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"],
                "note": "25 % loss of positive active material (large), one effect: a pair should not be preferred. 1C from full to "
                        "2.7 V, 30 min rest, C/2 charge for 60 min, 20 min rest, a 2C discharge and a 1C charge pulse of 30 s"},
               seed=97, compare=lion.DFN())
    mixed = (["Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/10", "Rest for 15 minutes"] + urban_drive(98, 12)
             + ["Rest for 10 minutes", "Discharge at C/2 for 20 minutes", "Rest for 10 minutes", "Discharge at 2C for 20 seconds", "Rest for 3 minutes",
                "Charge at 1.5C for 20 seconds", "Rest for 5 minutes", "Discharge at 1C until 3.0 V", "Rest for 20 minutes"])
    write_case(root, "t8_control_long_mixed_dfn", lion.DFN(), chen(), mixed,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"],
                "note": "negative control: DFN data and model, about 3 h mixed from 40 % SOC (1C CC-CV charge to 4.1 V and C/10, urban "
                        "drive with regeneration to 3C, C/2, 2C/1.5C pulses, 1C to 3.0 V, rests)"},
               initial_soc=0.4, seed=98, compare=lion.DFN())


def wltp_like_current(seed, capacity_A_h=5.0, peak_C=3.0, regen_C=1.5):
    """A WLTP-class-3-like drive as a 1 s cell current (A, discharge positive): four phases of
    589, 433, 455 and 323 s (low, medium, high, extra high; top speeds 56, 76, 97, 131 km/h) made of
    micro-trips (idle, accelerate, cruise with small fluctuations, brake), a 1600 kg car
    (CdA 0.7 m2, rolling 0.01, drivetrain 90 %, 60 % of the braking power recovered); the
    battery power is scaled to one cell so that the peak discharge is `peak_C` and regeneration
    is clipped at `regen_C`."""
    rng = np.random.default_rng(seed)
    speed = []
    for duration, top in [(589, 56.0), (433, 76.0), (455, 97.0), (323, 131.0)]:
        phase = [0.0]
        while len(phase) < duration:
            phase += [0.0] * int(rng.integers(5, 20))
            target = rng.uniform(0.45, 1.0) * top / 3.6
            v = 0.0
            while v < target:
                v = min(target, v + rng.uniform(0.6, 1.5))
                phase.append(v)
            for _ in range(int(rng.integers(10, 60))):
                v = max(0.0, v + rng.normal(0.0, 0.25))
                phase.append(v)
            while v > 0.0:
                v = max(0.0, v - rng.uniform(0.5, 1.2))
                phase.append(v)
        speed += phase[:duration - 1] + [0.0]
    v = np.array(speed)
    a = np.gradient(v)
    power = 1600.0 * a * v + 0.5 * 1.2 * 0.7 * v ** 3 + 0.01 * 1600.0 * 9.81 * v
    power = np.where(power > 0, power / 0.9, 0.6 * power)
    current = power / power.max() * peak_C * capacity_A_h
    current = np.maximum(current, -regen_C * capacity_A_h)
    t = np.arange(len(current), dtype=float)
    return np.column_stack([t, current])


def batch_p(root):
    """Eleventh batch, made blind (a helper session, judged once on the frozen binary
    /work/bin-p, sha256 6dfafbfbef5d, before anything else): protocol families the others
    lack or rarely use (a WLTP-like drive sampled at 0.1 s, constant-power steps at 5 degC, a
    partial cycle with a CC-CV tail at 0.5 mV noise, a GITT charge control at 45 degC with a
    flat recorded temperature, HPPC at seven SOCs, a cold cell heating up with the temperature
    recorded, OCV hysteresis seen through a bidirectional GITT), and three pairs not used
    before (contact + negative diffusivity, lithium loss + self-heating, electrolyte
    diffusivity + positive LAM). Lithium and active-material loss are accepted only by their
    own words, as since batch r. First run (2026-11-25, frozen binary sha256 6dfafbfbef5d): 6 of 8;
    p2 a tie (contact 7.02 mOhm, truth 7, or kinetics; one power level); p5 named electrolyte
    conductivity x0.47 + diffusivities in place of contact + diffusivity (in the SPMe a
    conductivity factor is an ohmic stand-in; the contact + diffusivity pair was not in the table);
    p7 a tie contact 15 mOhm / electrolyte, then "unexplained" (positive LAM 7 % beside the contact
    stand-in cut the hold-out 9 %, 10 % needed; the electrolyte + LAM pair was not tried); p6 took
    850 s of the judge's 900 s."""
    drive = wltp_like_current(101)
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.4)
    write_case(root, "p1_kinetics_wltp_drive_0p1s", lion.SPMe(), p,
               ["Rest for 2 minutes", pybamm.step.current(drive), "Rest for 15 minutes"],
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "charge transfer", "exchange"],
                "note": "exchange currents x0.4 (both electrodes); a WLTP-class-3-like drive (1800 s, four phases, peaks 3C "
                        "discharge, regeneration to 1.5C charge, current linear between 1 s points) from 85 % SOC, then 15 min "
                        "rest; sampled every 0.1 s, 1 mV noise; SPMe data"},
               initial_soc=0.85, seed=101, period=0.1, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    p.update({"Contact resistance [Ohm]": 0.007}, check_already_exists=False)
    power = ["Rest for 10 minutes"] + ["Discharge at 15 W for 10 minutes or until 2.7 V", "Rest for 10 minutes"] * 5 + [
        "Discharge at 15 W until 2.7 V", "Rest for 30 minutes", "Charge at 10 W for 20 minutes", "Rest for 20 minutes"]
    write_case(root, "p2_contact_constant_power_5C_spm", lion.SPM(options={"contact resistance": "true"}), p, power,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance"],
                "ambient_temperature_K": 278.15,
                "note": "7 mOhm contact resistance at 5 degC (isothermal, temperature not recorded); constant-power steps from "
                        "full: 5 x (15 W for 10 min, 10 min rest), 15 W to 2.7 V, 30 min rest, 10 W charge for 20 min, 20 min "
                        "rest; sampled every 5 s, 2 mV noise; SPM data"},
               seed=102, noise=2e-3, period=5, compare=lion.SPM())
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.9)
    partial = ["Rest for 10 minutes", "Discharge at C/2 for 60 minutes", "Rest for 30 minutes", "Charge at C/2 until 4.2 V",
               "Hold at 4.2 V until C/50", "Rest for 30 minutes", "Discharge at 1C for 30 minutes", "Rest for 30 minutes",
               "Charge at C/3 for 45 minutes", "Rest for 30 minutes"]
    write_case(root, "p3_lam_negative_partial_cccv_0p5mV", lion.SPMe(), p, partial,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"],
                "note": "10 % loss of negative active material (default initial concentrations); from full: C/2 for 60 min, "
                        "30 min rest, C/2 CC-CV charge to 4.2 V with the CV tail to C/50, 30 min rest, 1C for 30 min, rest, "
                        "C/3 charge for 45 min, rest; sampled every 10 s, 0.5 mV noise; SPMe data"},
               seed=103, noise=5e-4, period=10, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    gitt = ["Rest for 20 minutes"] + ["Charge at C/3 for 20 minutes", "Rest for 45 minutes"] * 7 + [
        "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/50", "Rest for 1 hour"]
    write_case(root, "p4_control_gitt_charge_45C_dfn", lion.DFN(), p, gitt,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 318.15,
                "note": "negative control at 45 degC (isothermal; the flat cell temperature is recorded, 0.05 K noise): DFN data "
                        "and model, GITT charge from 10 % SOC (7 x C/3 for 20 min, 45 min rest), then C/3 CC-CV to 4.2 V and "
                        "C/50, 1 h rest; sampled every 10 s, 0.8 mV noise"},
               initial_soc=0.1, temperature=True, seed=104, noise=8e-4, period=10, compare=lion.DFN())
    p = chen()
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.25)
    p.update({"Contact resistance [Ohm]": 0.005}, check_already_exists=False)
    hppc = ["Discharge at 2C for 30 seconds", "Rest for 2 minutes", "Charge at 1.5C for 30 seconds", "Rest for 2 minutes",
            "Discharge at C/2 for 12 minutes", "Rest for 30 minutes"]
    write_case(root, "p5_contact_and_diffusivity_hppc_spme", lion.DFN(options={"contact resistance": "true"}), p,
               ["Rest for 10 minutes"] + hppc * 7,
               {"effect": "contact_resistance+solid_diffusivity", "candidate_model": "spme", "accept": ["contact|series resistance", "diffusiv"],
                "note": "5 mOhm contact resistance and negative particle diffusivity x0.25; HPPC at seven SOCs from 90 % (2C "
                        "discharge and 1.5C charge pulses of 30 s with 2 min rests, then C/2 for 12 min and 30 min rest); DFN "
                        "data handed to the SPMe (electrolyte transport beside the two is right too); sampled every 2 s, 1 mV noise"},
               initial_soc=0.9, seed=105, period=2, compare=lion.SPMe())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15, "Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    write_case(root, "p6_inventory_and_thermal_cold_recorded", lion.DFN(options={"thermal": "lumped"}), p,
               ["Rest for 5 minutes", "Discharge at 1.5C until 2.7 V", "Rest for 40 minutes", "Charge at 1C until 4.2 V",
                "Hold at 4.2 V until C/20", "Rest for 30 minutes"],
               {"effect": "lithium_inventory_loss+thermal", "candidate_model": "dfn", "accept": ["inventory", "thermal|heat"],
                "ambient_temperature_K": 283.15,
                "note": "6 % less lithium in the negative electrode and lumped self-heating h = 12 W/(m2 K) from 10 degC (about 26 K rise); from "
                        "full: 1.5C to 2.7 V, 40 min rest, 1C CC-CV charge to 4.2 V and C/20, 30 min rest; temperature "
                        "recorded; sampled every 2 s, 1.5 mV noise; the candidate is the isothermal DFN at 10 degC"},
               temperature=True, seed=106, noise=1.5e-3, period=2, compare=lion.DFN())
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.5)
    p = scaled(p, "Positive electrode active material volume fraction", 0.9)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    write_case(root, "p7_electrolyte_diffusivity_and_lam_positive_35C", lion.SPMe(), p,
               ["Rest for 10 minutes"] + ["Discharge at 1C for 10 minutes", "Rest for 20 minutes"] * 4
               + ["Discharge at C/2 until 2.7 V", "Rest for 30 minutes", "Charge at 1C for 30 minutes", "Rest for 20 minutes"],
               {"effect": "electrolyte_transport+active_material_loss", "candidate_model": "spme", "accept": ["electrolyte", "active material"],
                "ambient_temperature_K": 308.15,
                "note": "electrolyte diffusivity x0.5 and 10 % loss of positive active material (default initial "
                        "concentrations) at 35 degC (isothermal, not recorded); from full: 4 x (1C for 10 min, 20 min rest), "
                        "C/2 to 2.7 V, 30 min rest, 1C charge for 30 min, 20 min rest; sampled every 1 s, 1 mV noise; SPMe data"},
               seed=107, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    with_negative_hysteresis(p, 0.015)
    both = (["Rest for 30 minutes"] + ["Discharge at C/5 for 15 minutes", "Rest for 30 minutes"] * 4
            + ["Charge at C/5 for 15 minutes", "Rest for 30 minutes"] * 4 + ["Discharge at C/5 for 15 minutes", "Rest for 30 minutes"] * 2)
    write_case(root, "p8_hysteresis_bidirectional_gitt_15C", lion.DFN(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, both,
               {"effect": "hysteresis", "candidate_model": "spme", "accept": ["hysteresis"], "ambient_temperature_K": 288.15,
                "note": "one-state hysteresis of the negative OCP, +-15 mV (decay rate 10, PyBaMM >= 25.10 definition), initial "
                        "state 0, at 15 degC (isothermal); bidirectional C/5 GITT from 60 % SOC (4 discharge, 4 charge, 2 "
                        "discharge pulses of 15 min, 30 min rests); DFN data handed to the SPMe; sampled every 5 s, 1.5 mV noise"},
               initial_soc=0.6, seed=108, noise=1.5e-3, period=5, compare=lion.SPMe())


def waveform(segments, dt=1.0):
    """A programmed current waveform as a 1 s (`dt`) table (time_s, current_A, discharge positive),
    for `pybamm.step.current`: each segment is (seconds, f) with f(tau) the current in A at tau
    seconds into the segment; the table is continuous in time (no repeated time: a cycler running
    a waveform logs no current steps)."""
    t, i, start = [], [], 0.0
    for seconds, f in segments:
        n = int(round(seconds / dt))
        for k in range(n):
            t.append(start + k * dt)
            i.append(float(f(k * dt)))
        start += n * dt
    t.append(start)
    i.append(i[-1])
    return np.column_stack([t, i])


def batch_o(root):
    """Twelfth batch, made blind (a helper session, judged once on the frozen binary
    /work/bin/frozen-o before anything else): protocols not used before (3C partial discharges,
    a cold cell warming towards a warmer room under HPPC-like pulses, a rest-heavy storage check
    logged by a cycler, a C/5 charge from empty with a rest, a three-stage fast charge, an
    interrupted 2C discharge, a sinusoidal current ripple, triangular current ramps with no
    current step at all); concealed parameters that are not candidates but map onto a family
    (separator porosity -> electrolyte transport; an initial temperature below the
    ambient -> thermal); a parameter off in the unusual direction (more lithium than the set);
    kinetics in DFN data handed to the SPMe (a fast charge); three pairs not used before
    (electrolyte conductivity + self-heating, negative kinetics + positive LAM, contact +
    hysteresis); and a DFN control at 15 degC. Lithium and active-material loss are accepted
    only by their own words, as since batch r. No case hides an effect outside every family:
    the judge (judge_verdict.py) counts "Unexplained" as right only for effect "none".

    First run (2026-11-26, frozen binary /work/bin/frozen-o, sha256 1771c0db7d65, load average
    4.9 before, 5.2-9.3 during, 7.8 after, on 2 cores shared with other sessions' builds): 6 of 8.
    o1 electrolyte properties (diffusivity 0.963x, conductivity 0.973x: the separator's change
    spread over the cell), then a positive kinetics 0.90x stand-in (1.49 -> 1.15 mV), 344 s;
    o3 no missing physics (1.03 mV), 1 s; o4 lithium inventory with the initial concentrations
    at the truth (896 and 55378 mol/m3), 3 s; o5 kinetics (0.47x/0.91x, refitted to 0.50x/0.50x
    once SPMe -> DFN was added in round 2), 16 s; o7 the pair in round 1 at the truth (negative
    rate constant 0.399x, positive fraction 0.6117 vs 0.6118), 315 s; o8 passed weakly, as two
    ties: RC 5.13 mOhm (time constant under the 2 s sampling) or contact 5.09 mOhm, then
    hysteresis 9.94 mV or contact 4.99 mOhm; 9 s. Missed: o2 timed out at 900 s (alone
    afterwards, a rerun: 1077 s at load ~7, same binary); the isothermal DFN and the thermal
    candidate run with the first recorded temperature (283.25 K) as the ambient, so the warming
    towards the 25 degC room needs h = 0.25 W/(m2 K), implausible though the best fit (19.00 ->
    4.05 mV), and kinetics (negative 1.57x, 7.25 mV) is named first, then lithium inventory with
    a 35 % negative LAM, then unexplained (4.88 mV). o6 named series/contact resistance 4.06
    mOhm together with thermal (h 15.03, the truth), 8.45 -> 0.99 mV, 45 s: Chen 2020's
    conductivity has no temperature dependence, so in the SPMe a conductivity factor is an
    ohmic term and this pair cannot be told from the true one (a weak case by design); the tool
    named one pair instead of a tie of pairs."""
    cap = 5.0
    p = chen()
    p.update({"Separator porosity": 0.40})
    write_case(root, "o1_separator_porosity_3C_partial_dfn", lion.DFN(), p,
               ["Rest for 5 minutes"] + ["Discharge at 3C for 3 minutes", "Rest for 15 minutes"] * 4,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"],
                "note": "separator porosity 0.40 (set: 0.47; a compressed or clogged separator): with Bruggeman 1.5 the "
                        "separator's effective conductivity and diffusivity x0.79 and less electrolyte in it; not a candidate "
                        "parameter, its physics is the electrolyte transport family (a tie with a series resistance names it "
                        "too). From full: 5 min rest, 4 x (3C for 3 min, 15 min rest); DFN data"},
               seed=111, compare=lion.DFN())
    p = chen()
    p.update({"Initial temperature [K]": 283.15, "Total heat transfer coefficient [W.m-2.K-1]": 5.0})
    hppc = ["Discharge at 2C for 10 seconds", "Rest for 2 minutes", "Charge at 1C for 10 seconds", "Rest for 2 minutes",
            "Discharge at 1C for 6 minutes", "Rest for 10 minutes"]
    write_case(root, "o2_cold_start_warming_recorded_dfn", lion.DFN(options={"thermal": "lumped"}), p, ["Rest for 2 minutes"] + hppc * 4,
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "heat"], "ambient_temperature_K": 298.15,
                "note": "a cell taken from 10 degC storage into a 25 degC room: initial temperature 283.15 K, ambient 298.15 K, lumped "
                        "thermal h = 5 W/(m2 K) (it warms to about 296 K within 15 min, then its own heat under the 1C steps takes "
                        "it to about 306 K); the initial temperature is not a candidate parameter, its physics is the thermal family "
                        "(the candidate is the isothermal DFN at 25 degC). Temperature recorded (0.05 K "
                        "noise). From 90 % SOC: 4 x (2C discharge and 1C charge pulses of 10 s with 2 min rests, 1C for 6 min, "
                        "10 min rest); sampled every 2 s; DFN data"},
               initial_soc=0.9, temperature=True, seed=112, period=2, compare=lion.DFN())
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    storage = ["Rest for 2 hours", "Discharge at C/3 for 15 minutes", "Rest for 1 hour", "Discharge at 1C for 10 seconds", "Rest for 5 minutes",
               "Charge at 1C for 10 seconds", "Rest for 30 minutes", "Charge at C/3 for 15 minutes", "Rest for 1 hour"]
    write_case(root, "o3_control_storage_check_15C_dfn", lion.DFN(), p, storage,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 288.15,
                "note": "negative control at 15 degC (isothermal): a rest-heavy storage check from 50 % SOC (2 h rest, C/3 for 15 "
                        "min, 1 h rest, 1C discharge and charge pulses of 10 s, 30 min rest, C/3 charge for 15 min, 1 h rest); DFN "
                        "data and model; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.5, seed=113, cycler=CYCLER, compare=lion.DFN())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.04)
    write_case(root, "o4_more_lithium_c5_charge_from_empty", lion.SPMe(), p,
               ["Rest for 30 minutes", "Charge at C/5 until 4.2 V", "Rest for 1 hour"],
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory"],
                "note": "4 % MORE cyclable lithium than the set (negative initial concentration x1.04, the other direction of "
                        "a lithium loss); from empty (0 % SOC of that cell, at 2.5 V): 30 min rest, C/5 charge to 4.2 V (no "
                        "hold), 1 h rest; sampled every 5 s; SPMe data"},
               initial_soc=0.0, seed=114, period=5, compare=lion.SPMe())
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.5)
    write_case(root, "o5_kinetics_fast_charge_dfn_data_spme", lion.DFN(), p,
               ["Rest for 10 minutes", "Charge at 1.5C until 3.9 V", "Charge at 1C until 4.1 V", "Charge at C/3 until 4.2 V", "Rest for 30 minutes"],
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "charge transfer", "exchange"],
                "note": "exchange currents x0.5 (both electrodes); a three-stage fast charge from 10 % SOC (1.5C to 3.9 V, 1C to 4.1 V, "
                        "C/3 to 4.2 V, no hold, 30 min rest); DFN data handed to the SPMe. Replaying the recorded current (before "
                        "noise), PyBaMM's SPMe with the nominal set is 29.0 mV RMS from the recording, its SPMe with the concealed "
                        "kinetics 5.6 mV (the SPMe's own error, most of it at the 1.5C stage): one concealed effect, electrolyte "
                        "transport (SPMe -> DFN) beside it is right too, any other partner is a stand-in; sampled every 2 s"},
               initial_soc=0.1, seed=115, period=2, compare=lion.SPMe())
    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.5)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 15.0})
    write_case(root, "o6_conductivity_and_thermal_interrupted_2C", lion.SPMe(options={"thermal": "lumped"}), p,
               ["Discharge at 2C for 5 minutes or until 2.7 V", "Rest for 1 minute"] * 5 + ["Rest for 30 minutes", "Charge at 1C for 15 minutes",
                                                                                          "Rest for 20 minutes"],
               {"effect": "electrolyte_transport+thermal", "candidate_model": "spme", "accept": ["electrolyte", "thermal|heat"],
                "note": "electrolyte conductivity x0.5 and lumped self-heating h = 15 W/(m2 K), which mask each other (the warming "
                        "cell's conductivity recovers: 22 mV RMS from the conductivity alone, 8.8 mV from both); from full: an "
                        "interrupted 2C discharge (5 x (2C for 5 min, 1 min rest)), 30 min rest, 1C charge for 15 min, 20 min "
                        "rest; temperature recorded; sampled every 2 s; SPMe data, the candidate the isothermal SPMe"},
               temperature=True, seed=116, period=2, compare=lion.SPMe())
    ripple = waveform([(3600, lambda s: cap * (0.6 + 0.9 * np.sin(2 * np.pi * s / 180.0)))], dt=2.0)
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.4)
    p = scaled(p, "Positive electrode active material volume fraction", 0.92)
    write_case(root, "o7_kinetics_negative_and_lam_positive_sine", lion.SPMe(), p,
               ["Rest for 5 minutes", pybamm.step.current(ripple), "Discharge at C/2 until 2.7 V", "Rest for 30 minutes"],
               {"effect": "kinetics+active_material_loss", "candidate_model": "spme", "accept": ["kinetic|charge transfer|exchange", "active material"],
                "note": "negative exchange current x0.4 (positive as set) and 8 % loss of positive active material (default initial "
                        "concentrations); from full: 5 min rest, an hour of sinusoidal current (0.6C mean, 0.9C amplitude, 3 min "
                        "period: -0.3C to 1.5C), then C/2 to 2.7 V, 30 min rest; sampled every 2 s; SPMe data"},
               seed=117, period=2, compare=lion.SPMe())
    tri = lambda sign: (600, lambda s: sign * cap * (s / 300.0 if s < 300 else (600 - s) / 300.0))
    rest = lambda seconds: (seconds, lambda s: 0.0)
    ramps = waveform([rest(600)] + [tri(1), rest(600), tri(-1), rest(600)] * 3, dt=2.0)
    p = chen()
    with_negative_hysteresis(p, 0.010)
    p.update({"Contact resistance [Ohm]": 0.005}, check_already_exists=False)
    write_case(root, "o8_contact_and_hysteresis_triangle_ramps_spm",
               lion.SPM(options={"contact resistance": "true", "open-circuit potential": ("one-state hysteresis", "single")}), p,
               [pybamm.step.current(ramps)],
               {"effect": "contact_resistance+hysteresis", "candidate_model": "spm", "accept": ["contact|series resistance", "hysteresis"],
                "note": "5 mOhm contact resistance and one-state hysteresis of the negative OCP, +-10 mV (decay rate 10, initial "
                        "state 0); from 60 % SOC: 10 min rest, 3 x (a triangular discharge ramp 0 -> 1C -> 0 over 10 min, 10 min "
                        "rest, the same as charge, 10 min rest): no current step anywhere; sampled every 2 s; SPM data"},
               initial_soc=0.6, seed=118, period=2, compare=lion.SPM())


class CurrentTrace:
    """A current at 1 s points (A, discharge positive) built from linear ramps and holds with
    optional Gaussian wobble, starting at rest."""

    def __init__(self, rng):
        self.rng = rng
        self.cur = [0.0]

    def ramp(self, to, seconds):
        start = self.cur[-1]
        for k in range(1, seconds + 1):
            self.cur.append(start + (to - start) * k / seconds)

    def hold(self, level, seconds, wobble=0.0):
        for _ in range(seconds):
            self.cur.append(level + (self.rng.normal(0.0, wobble) if wobble else 0.0))


def hill_regen_drive(seed, capacity_A_h=5.0):
    """A regenerative-braking-heavy drive as a 1 s cell current (A, discharge positive), no
    current step anywhere (ramps between 1 s points): a 10 min climb (accelerations to 2-3C,
    cruising at 1-1.6C), a 10 min descent held by regeneration (charge at 0.6-1.4C for 30-90 s,
    braking spikes to 2C charge, coasting on 0.05C of auxiliaries) and 10 min of town
    stop-and-go (idle on auxiliaries, accelerations to 2-2.5C, cruising at 0.5C, regenerative
    braking to 1.5C charge)."""
    rng = np.random.default_rng(seed)
    c = capacity_A_h
    trace = CurrentTrace(rng)
    cur, ramp, hold = trace.cur, trace.ramp, trace.hold

    while len(cur) < 600:
        ramp(rng.uniform(2.0, 3.0) * c, int(rng.integers(5, 9)))
        level = rng.uniform(1.0, 1.6) * c
        ramp(level, 3)
        hold(level, int(rng.integers(20, 51)), 0.05 * c)
        ramp(0.2 * c, 3)
        hold(0.2 * c, 5)
    while len(cur) < 1200:
        level = -rng.uniform(0.6, 1.4) * c
        ramp(level, 4)
        hold(level, int(rng.integers(30, 91)), 0.05 * c)
        ramp(-2.0 * c, 2)
        hold(-2.0 * c, int(rng.integers(4, 7)))
        ramp(0.05 * c, 4)
        hold(0.05 * c, int(rng.integers(10, 21)))
    while len(cur) < 1800:
        ramp(0.02 * c, 2)
        hold(0.02 * c, int(rng.integers(10, 21)))
        ramp(rng.uniform(2.0, 2.5) * c, 6)
        ramp(0.5 * c, 3)
        hold(0.5 * c, int(rng.integers(15, 31)), 0.03 * c)
        peak = -1.5 * c
        ramp(peak, int(rng.integers(3, 5)))
        ramp(0.02 * c, int(rng.integers(2, 5)))
    trace.cur = cur = cur[:1800] + [0.0] * 2
    ramp(0.0, 1)
    i = np.array(cur)
    i[-3:] = 0.0
    return np.column_stack([np.arange(len(i), dtype=float), i])


def batch_n(root):
    """Thirteenth batch, made blind (a helper session, judged once on the frozen binary
    /work/bin/frozen-n, sha256 21b42b6ae80b, before anything else): protocols not used before
    (a CC-CV charge whose CV tail runs to C/50, a partial-SOC window cycled at 1C, a pulse train
    at 20 % SOC, a C/20 discharge segment at the end of a 1C discharge, a hill-and-town drive
    with long regenerative charging and no current step, constant-power steps at 40 degC as a
    control, a constant-power discharge of a poorly cooled cell, a descending-rate staircase at
    10 degC); concealed parameters that are not candidates but map onto a family (the positive
    electrode's electronic conductivity -> an ohmic series resistance; the initial salt
    concentration of the electrolyte -> electrolyte transport; the cooling surface area ->
    thermal); two pairs not used before (kinetics + negative diffusivity; positive LAM +
    lithium loss); DFN data handed to the SPM and to the SPMe; and an SPM control at 40 degC.
    Lithium and active-material loss are accepted only by their own words, as since batch r.
    No case hides an effect outside every family.

    First run (2026-11-26, frozen binary /work/bin/frozen-n, sha256 21b42b6ae80b, load average
    1.2 when the cases were made, 4.0 at the start of the judge, 1.6-6.3 during (5-6.3 through
    n1, 1.6-4 after), 1.9 after, on 2 cores shared with other sessions): 4 of 8.
    n2 the pair in round 1 at the truth (rate constants 0.399x / 0.402x, negative diffusivity
    0.200x, positive 1.000x), 63.30 -> 0.99 mV, 47 s; n6 no missing physics (1.04 mV), 0 s; n7
    thermal (h 4.48 W/(m2 K) on the full cooling area, the truth's 10 on half of it being 5;
    ambient fitted 291.62 K) tied with electrolyte properties (diffusivity 2.26x, conductivity
    1.76x, both faster), 25.28 -> 5.80 mV, then SPMe -> DFN (0.98 mV), 42 s; n8 particle
    diffusivities (positive 0.250x, negative 0.998x), 76.26 -> 1.00 mV, 16 s. Missed: n1 timed
    out at 900 s (a DFN candidate on 2.6 h with a 89 min CV tail, 4677 points, at load 5-6;
    rerun alone afterwards, not counted: 1361 s at load 2-6, a tie, RC 12.17 mOhm / 692 F or
    series/contact resistance 12.14 mOhm, 26.65 -> 1.90 mV, which the judge would accept, then
    electrolyte properties 0.83x / 0.87x, 1.54 mV, then unexplained);
    n3 named series/contact resistance 6.72 mOhm together with an RC (5.44 mOhm, 3284 F,
    time constant 17.9 s), 20.00 -> 1.50 mV, then kinetics (0.84x / 0.55x, 1.06 mV), 41 s:
    the SPM's electrolyte candidates are structure switches with nominal properties (SPM ->
    SPMe 4.94 mV, SPM -> DFN 5.62 mV, only the SOC fitted) and cannot take up the lower salt
    concentration, while the four-parameter contact + RC pair mimics an electrolyte's ohmic
    drop and its tens-of-seconds polarisation under 10 s pulses; after it, the switches made
    things worse (-9 %, -10 % hold-out). n4 "unexplained" (17.42 mV after the initial SOC was
    fitted to 0.928), 8 s: the best single, positive LAM (fractions 0.936x negative, 0.892x
    positive, SOC 0.993), cut the training RMSE 20.06 -> 6.26 mV but raised the hold-out 2.58
    -> 5.87 mV (the held-out points, 2 of 8 equal time blocks, miss the first 1900 s, where 95 %
    of the baseline's squared error lies, and sit where the SOC-fitted baseline is close); lithium inventory alone
    fitted the negative concentration at the truth (28021 vs 28074 mol/m3) but left 15.26 mV;
    no pair was tried, since no single was named. n5 named particle diffusivity (negative
    0.41x, positive 0.97x), 2.09 -> 1.43 mV, then kinetics (1.03x / 0.95x, 1.25 mV), then
    unexplained, 346 s: OCV hysteresis was withheld as "not identifiable: needs rests after
    both charge and discharge (this recording has 1 and 0)" (the drive has no rest, only idle
    on auxiliaries, and ends on a discharge), and the RC that fitted best (1.00 mV, time
    constant 762 s, the hysteresis state's slow relaxation) was implausible by its range; the
    hysteresis is small here (4.1 mV RMS in PyBaMM, 2.1 mV once the SOC is fitted)."""
    cap = 5.0
    p = scaled(chen(), "Positive electrode conductivity [S.m-1]", 0.1)
    write_case(root, "n1_positive_conductivity_cccv_long_tail_dfn", lion.DFN(), p,
               ["Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/50", "Rest for 30 minutes"],
               {"effect": "contact_resistance", "candidate_model": "dfn", "accept": ["contact", "series resistance"],
                "note": "electronic conductivity of the positive electrode x0.1 (0.018 S/m instead of 0.18: a degraded carbon-binder "
                        "network); not a candidate parameter, its physics is an ohmic loss in series with the cell (the contact "
                        "/ series resistance family). From 20 % SOC: 10 min rest, 1C CC charge to 4.2 V, CV hold to C/50 (a long "
                        "tail), 30 min rest; sampled every 2 s; DFN data and model"},
               initial_soc=0.2, seed=121, period=2, compare=lion.DFN())
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.4)
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.2)
    window = ["Discharge at 1C for 20 minutes", "Rest for 10 minutes", "Charge at 1C for 20 minutes", "Rest for 10 minutes"]
    write_case(root, "n2_kinetics_and_diffusivity_soc_window", lion.SPMe(), p, ["Rest for 5 minutes"] + window * 3,
               {"effect": "kinetics+solid_diffusivity", "candidate_model": "spme", "accept": ["kinetic|charge transfer|exchange", "diffusiv"],
                "note": "exchange currents x0.4 (both electrodes) and negative particle diffusivity x0.2; a partial-SOC window cycled "
                        "at 1C from 60 % SOC (3 x (1C discharge for 20 min, 10 min rest, 1C charge for 20 min, 10 min rest): "
                        "between about 60 and 27 % SOC); sampled every 2 s; SPMe data"},
               initial_soc=0.6, seed=122, period=2, compare=lion.SPMe())
    p = chen()
    p.update({"Initial concentration in electrolyte [mol.m-3]": 700.0})
    train = ["Discharge at 2C for 10 seconds", "Rest for 30 seconds", "Charge at 1C for 10 seconds", "Rest for 30 seconds"]
    write_case(root, "n3_salt_depleted_pulse_train_low_soc_dfn_data_spm", lion.DFN(), p, ["Rest for 5 minutes"] + train * 15 + ["Rest for 20 minutes"],
               {"effect": "electrolyte_transport", "candidate_model": "spm", "accept": ["electrolyte"],
                "note": "initial salt concentration of the electrolyte 700 mol/m3 instead of 1000 (salt consumed; lower conductivity "
                        "and faster depletion); not a candidate parameter, its physics is the electrolyte transport family, which "
                        "the SPM also lacks structurally (DFN data handed to the SPM). From 20 % SOC: 5 min rest, a pulse train of "
                        "15 x (2C discharge for 10 s, 30 s rest, 1C charge for 10 s, 30 s rest), 20 min rest; sampled every 1 s"},
               initial_soc=0.2, seed=123, compare=lion.SPM())
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.94)
    write_case(root, "n4_lam_positive_and_inventory_c20_tail", lion.SPMe(), p,
               ["Rest for 10 minutes", "Discharge at 1C for 50 minutes or until 2.7 V", "Rest for 30 minutes",
                "Discharge at C/20 until 2.7 V", "Rest for 30 minutes"],
               {"effect": "active_material_loss+lithium_inventory_loss", "candidate_model": "spme", "accept": ["active material", "inventory"],
                "note": "8 % loss of positive active material and 6 % less lithium in the negative electrode (the commonest pair of "
                        "an aged cell); from full: 10 min rest, 1C for 50 min (or to 2.7 V), 30 min rest, the rest of the capacity "
                        "at C/20 to 2.7 V (a quasi-OCV segment across the end of discharge), 30 min rest; sampled every 10 s; SPMe data"},
               seed=124, period=10, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    with_negative_hysteresis(p, 0.010)
    drive = hill_regen_drive(125, cap)
    write_case(root, "n5_hysteresis_hill_regen_drive_35C", lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p,
               ["Rest for 5 minutes", pybamm.step.current(drive), "Rest for 20 minutes"],
               {"effect": "hysteresis", "candidate_model": "spme", "accept": ["hysteresis"], "ambient_temperature_K": 308.15,
                "note": "one-state hysteresis of the negative OCP, +-10 mV (decay rate 10, initial state 0), at 35 degC "
                        "(isothermal); from 60 % SOC: 5 min rest, a 30 min drive (10 min climb to 3C, net discharge; 10 min descent "
                        "held by regeneration at 0.6-1.4C charge with 2C braking spikes, net charge; 10 min town stop-and-go with "
                        "regenerative braking; current ramps between 1 s points, no step), 20 min rest; sampled every 1 s; SPMe data"},
               initial_soc=0.6, seed=125, compare=lion.SPMe())
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    power = ["Rest for 10 minutes", "Discharge at 12 W for 20 minutes", "Rest for 15 minutes", "Discharge at 30 W for 3 minutes",
             "Rest for 15 minutes", "Charge at 8 W for 25 minutes", "Rest for 15 minutes", "Discharge at 20 W for 10 minutes", "Rest for 20 minutes"]
    write_case(root, "n6_control_constant_power_40C_spm", lion.SPM(), p, power,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 313.15,
                "note": "negative control at 40 degC (isothermal, not recorded): SPM data and model, constant-power steps from 80 % "
                        "SOC (12 W for 20 min, 30 W for 3 min, 8 W charge for 25 min, 20 W for 10 min, rests of 15-20 min); cycler "
                        "artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.8, seed=126, cycler=CYCLER, compare=lion.SPM())
    p = scaled(chen(), "Cell cooling surface area [m2]", 0.5)
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    write_case(root, "n7_poor_cooling_constant_power_dfn_data_spme", lion.DFN(options={"thermal": "lumped"}), p,
               ["Rest for 5 minutes", "Discharge at 20 W until 2.7 V", "Rest for 30 minutes"],
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "heat"], "ambient_temperature_K": 293.15,
                "note": "lumped self-heating with half of the cooling surface (a cell packed in a module, half its can cooled): "
                        "h = 10 W/(m2 K) as set, cooling area x0.5; not a candidate parameter (the set's h is), its physics is the "
                        "thermal family. At 20 degC: 5 min rest, constant-power 20 W discharge from full to 2.7 V, 30 min rest; "
                        "temperature recorded (0.05 K noise); sampled every 2 s; DFN data handed to the isothermal SPMe "
                        "(electrolyte transport beside thermal is right too)"},
               temperature=True, seed=127, period=2, compare=lion.SPMe())
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.25)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    stairs = ["Rest for 5 minutes", "Discharge at 2C for 4 minutes", "Discharge at 1C for 8 minutes", "Discharge at C/2 for 16 minutes",
              "Discharge at C/5 for 20 minutes", "Rest for 30 minutes", "Discharge at 1C until 2.7 V", "Rest for 30 minutes"]
    write_case(root, "n8_diffusivity_positive_rate_staircase_10C_dfn", lion.DFN(), p, stairs,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["diffusiv"], "ambient_temperature_K": 283.15,
                "note": "positive particle diffusivity x0.25 at 10 degC (isothermal, not recorded); from full: 5 min rest, a "
                        "descending-rate staircase with no rest between stages (2C for 4 min, 1C for 8 min, C/2 for 16 min, C/5 "
                        "for 20 min), 30 min rest, 1C to 2.7 V, 30 min rest; sampled every 3 s; DFN data and model"},
               seed=128, period=3, compare=lion.DFN())


def batch_m(root):
    """Fourteenth batch, made blind (a helper session, judged once on the frozen binary
    /work/bin/frozen-m, sha256 05a349687035, commit 353b927, before anything else): protocols not
    used before (a USABC-style HPPC with C/3 SOC steps, a parked drive (three 5 min drives with
    15 min parking rests), a symmetric 2C/1.5C pulse pair and a 3C pulse at 70 % SOC, a C/3 CC-CV
    charge from empty with a 2 h rest, a 2C fast charge with a CV tail logged with a coarse 0.5 K
    thermocouple, a current-interrupt 1.5C discharge (150 s on, 10 s off), C/3 deep cycles with 1 h
    rests after both charge and discharge); concealed parameters that are not candidates but
    map onto a family (a 50 nm SEI film's resistance -> series resistance; a negative electrode
    porosity lowered by pore clogging -> electrolyte transport); two pairs not used before
    (electrolyte diffusivity + negative particle diffusivity; OCV hysteresis + lithium loss);
    and an SPMe control at 5 degC. Lithium and active-material loss are accepted only by their
    own words, as since batch r; in m7 the particle diffusivity is accepted by "particle" (not
    "diffusiv", which "electrolyte diffusivity" alone would match). No case hides an effect
    outside every family.

    First run (2026-11-26, frozen binary /work/bin/frozen-m, sha256 05a349687035, load average
    4.6 before, 4.3-7.8 during, 6.8 after, on 2 cores shared with other sessions): 8 of 8, 1102 s
    in all. m1 a tie: series/contact 2.91 mOhm (truth 2.98 mOhm at a 1C pulse) or electrolyte
    conductivity 0.58x, 4.00 -> 1.00 mV, 33 s; m2 kinetics (positive rate constant 0.392x,
    negative 1.010x), 9.00 -> 1.52 mV, 79 s; m3 electrolyte properties (diffusivity 0.878x,
    conductivity 1.30x) together with kinetics (negative 0.688x, positive 1.13x), 12.77 -> 1.84 mV,
    then "unexplained" (1.84 mV), 341 s: the electrolyte alone (0.854x / 0.759x, 3.21 mV) ranked
    4th, behind three kinetics pairs; m4 negative LAM (fraction 0.6974, truth 0.6975), 54.30 ->
    1.01 mV, 518 s; m5 thermal (h 11.93, ambient 288.14 K), 17.35 -> 1.02 mV, 22 s; m6 no missing
    physics (1.98 mV, noise 2.07), 1 s; m7 the pair in round 1 at the truth (electrolyte
    diffusivity 0.7502x, conductivity 1.0016x, negative particle diffusivity 0.300x, positive
    0.999x), 22.49 -> 1.01 mV, 48 s; m8 passed on the rounds together, not on its first verdict:
    round 1 named negative LAM (fraction 0.7154, "5 %") together with hysteresis (15.5 mV),
    30.83 -> 4.06 mV, where lithium inventory alone ranked 2nd (8.64 mV); round 2 named lithium
    inventory (initial concentrations 25725 / 20403 mol/m3, the truth's 25725 / 20404), 0.97 mV,
    after which the active fractions were refitted to the set's (0.7500 / 0.6650) and the
    hysteresis to 12.01 mV (truth 12), yet the conclusion still lists the LAM; 60 s."""
    cap = 5.0
    p = chen()
    p.update({"Initial SEI thickness [m]": 5e-8})
    hppc = ["Discharge at 1C for 10 seconds", "Rest for 40 seconds", "Charge at 0.75C for 10 seconds", "Rest for 10 minutes",
            "Discharge at C/3 for 18 minutes", "Rest for 30 minutes"]
    write_case(root, "m1_sei_film_resistance_usabc_hppc_cycler", lion.SPMe(options={"SEI": "constant", "SEI film resistance": "distributed"}), p,
               ["Rest for 10 minutes"] + hppc * 6,
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance"],
                "note": "a 50 nm SEI film (set: 5 nm) with the set's resistivity, 2e5 Ohm m, as a distributed film resistance on "
                        "the negative particles (no growth, no lithium consumed): about 3.0 mOhm more in series (14.9 mV at a 1C "
                        "pulse); not a candidate parameter, its physics is an ohmic loss in series (the contact / series "
                        "resistance family). USABC-style HPPC from full: 10 min rest, 6 x (1C discharge 10 s, 40 s rest, 0.75C "
                        "charge 10 s, 10 min rest, C/3 for 18 min, 30 min rest); SPMe data; cycler artefacts (irregular "
                        "sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=1.0, seed=131, cycler=CYCLER, compare=lion.SPMe())
    p = scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.4)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    parked = ["Rest for 5 minutes"]
    for k in range(3):
        parked += drive_cycle(132 + k, 30, -0.8, 2.0, 10) + ["Rest for 15 minutes"]
    write_case(root, "m2_kinetics_positive_parked_drive_10C_spm", lion.SPM(), p, parked,
               {"effect": "kinetics", "candidate_model": "spm", "accept": ["kinetic", "charge transfer", "exchange"],
                "ambient_temperature_K": 283.15,
                "note": "positive exchange current x0.4 only (negative as set) at 10 degC (isothermal, not recorded); from 85 % "
                        "SOC: 5 min rest, 3 x (a 5 min random drive of 10 s steps between 0.8C charge and 2C discharge, 15 min "
                        "parked); sampled every 2 s, 1.5 mV noise; SPM data"},
               initial_soc=0.85, seed=132, noise=1.5e-3, period=2, compare=lion.SPM())
    p = chen()
    p.update({"Negative electrode porosity": 0.19})
    pairs = ["Discharge at 2C for 2 minutes", "Rest for 8 minutes", "Charge at 1.5C for 2 minutes", "Rest for 8 minutes"]
    write_case(root, "m3_negative_porosity_pulse_pairs_dfn", lion.DFN(), p,
               ["Rest for 5 minutes"] + pairs * 3 + ["Discharge at 3C for 60 seconds", "Rest for 10 minutes"],
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"],
                "note": "negative electrode porosity 0.19 instead of 0.25 (pores clogged by SEI; the active material fraction "
                        "kept): with Bruggeman 1.5 the negative's effective electrolyte conductivity and diffusivity x0.66 and "
                        "less electrolyte in it; not a candidate parameter, its physics is the electrolyte transport family. From "
                        "70 % SOC: 5 min rest, 3 x (2C discharge for 2 min, 8 min rest, 1.5C charge for 2 min, 8 min rest), 3C "
                        "for 60 s, 10 min rest; DFN data; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution)"},
               initial_soc=0.7, seed=133, cycler=CYCLER, compare=lion.DFN())
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.93)
    write_case(root, "m4_lam_negative_cccv_charge_from_empty_dfn", lion.DFN(), p,
               ["Rest for 20 minutes", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 2 hours"],
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"],
                "note": "7 % loss of negative active material (default initial concentrations); charge only, from empty (0 % SOC "
                        "of that cell): 20 min rest, C/3 CC-CV to 4.2 V and C/20, 2 h rest; DFN data; cycler artefacts "
                        "(irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.0, seed=134, cycler=CYCLER, compare=lion.DFN())
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15, "Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    write_case(root, "m5_thermal_fast_charge_coarse_thermocouple_spm", lion.SPM(options={"thermal": "lumped"}), p,
               ["Rest for 5 minutes", "Charge at 2C until 4.1 V", "Hold at 4.1 V until C/10", "Rest for 40 minutes"],
               {"effect": "thermal", "candidate_model": "spm", "accept": ["thermal", "heat"], "ambient_temperature_K": 288.15,
                "note": "lumped self-heating, h = 12 W/(m2 K), at 15 degC; from 10 % SOC: 5 min rest, a 2C fast charge to 4.1 V, "
                        "CV hold to C/10, 40 min rest (about 15 K rise); temperature recorded by a coarse logger (0.5 K resolution, 0.05 K noise); "
                        "SPM data, the candidate the isothermal SPM; cycler artefacts (irregular sampling, 5 mA current noise, "
                        "1 mA and 0.5 mV resolution)"},
               initial_soc=0.1, temperature=True, seed=135,
               cycler={"irregular": True, "current_noise_A": 5e-3, "quantum_A": 1e-3, "quantum_V": 5e-4, "quantum_K": 0.5}, compare=lion.SPM())
    p = chen()
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    mixed = (["Rest for 10 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 30 minutes"] + urban_drive(136, 15)
             + ["Rest for 20 minutes", "Discharge at 1C for 10 minutes", "Rest for 30 minutes"])
    write_case(root, "m6_control_cccv_drive_5C_spme", lion.SPMe(), p, mixed,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 278.15,
                "note": "negative control at 5 degC (isothermal, not recorded): SPMe data and model; from 30 % SOC: 10 min rest, "
                        "C/2 CC-CV to 4.1 V and C/20, 30 min rest, an urban drive (15 segments, to 3C, regeneration to 1.5C), "
                        "20 min rest, 1C for 10 min, 30 min rest; 2 mV noise; cycler artefacts (irregular sampling, 3 mA current "
                        "noise, 0.1 mV resolution)"},
               initial_soc=0.3, seed=136, noise=2e-3, cycler=CYCLER, compare=lion.SPMe())
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.75)
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.3)
    interrupt = ["Discharge at 1.5C for 150 seconds or until 2.7 V", "Rest for 10 seconds"] * 12
    write_case(root, "m7_electrolyte_and_particle_diffusivity_current_interrupt_spme", lion.SPMe(), p,
               ["Rest for 5 minutes"] + interrupt + ["Rest for 40 minutes", "Charge at 1C for 20 minutes", "Rest for 30 minutes"],
               {"effect": "electrolyte_transport+solid_diffusivity", "candidate_model": "spme", "accept": ["electrolyte", "particle"],
                "note": "electrolyte diffusivity x0.75 and negative particle diffusivity x0.3 (alone, in PyBaMM on this protocol, about "
                        "17 and 6 mV RMS); from full: 5 min rest, a current-"
                        "interrupt 1.5C discharge (12 x (1.5C for 150 s or to 2.7 V, 10 s rest): 75 % of the capacity), 40 min rest, 1C charge for 20 min, "
                        "30 min rest; sampled every 2 s, 1 mV noise; SPMe data. The particle diffusivity is accepted by "
                        "\"particle\", since \"diffusiv\" would be matched by the electrolyte's diffusivity alone"},
               seed=137, period=2, compare=lion.SPMe())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    with_negative_hysteresis(p, 0.012)
    deep = ["Rest for 30 minutes", "Discharge at C/3 for 90 minutes", "Rest for 1 hour", "Discharge at C/3 until 2.7 V", "Rest for 1 hour",
            "Charge at C/3 for 2 hours", "Rest for 1 hour", "Charge at C/3 until 4.2 V", "Rest for 1 hour"]
    write_case(root, "m8_hysteresis_and_inventory_c3_cycle_rests_spme",
               lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, deep,
               {"effect": "hysteresis+lithium_inventory_loss", "candidate_model": "spme", "accept": ["hysteresis", "inventory"],
                "note": "one-state hysteresis of the negative OCP, +-12 mV (decay rate 10, initial state 0), and 5 % less lithium "
                        "in the negative electrode; from 90 % SOC: 30 min rest, C/3 for 90 min, 1 h rest, C/3 to 2.7 V, 1 h rest, "
                        "C/3 charge for 2 h, 1 h rest, C/3 to 4.2 V (no hold), 1 h rest; sampled every 20 s, 1 mV noise; SPMe "
                        "data"},
               initial_soc=0.9, seed=138, period=20, compare=lion.SPMe())


def with_okane2022(p, keys):
    """Copies the named OKane2022 parameters (plating, particle mechanics and LAM constants)
    into a Chen 2020 set, which has none of them (same LG M50 cell)."""
    o = pybamm.ParameterValues("OKane2022")
    for key in keys:
        p.update({key: o[key]}, check_already_exists=False)
    return p


PLATING_KEYS = ["Dead lithium decay constant [s-1]", "Dead lithium decay rate [s-1]", "Exchange-current density for plating [A.m-2]",
                "Exchange-current density for stripping [A.m-2]", "Initial plated lithium concentration [mol.m-3]",
                "Lithium metal partial molar volume [m3.mol-1]", "Lithium plating kinetic rate constant [m.s-1]",
                "Lithium plating transfer coefficient", "Typical plated lithium concentration [mol.m-3]"]


def batch_l(root):
    """Fifteenth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the frozen binary /work/bin/frozen-l, sha256 91b776e7a12b, built from main at
    eb244f4, before anything else). Three ageing recordings of 6-10 cycles (solvent-diffusion
    limited SEI at 45 degC; partially reversible plating in 1.5C charges at 5 degC, logged by a
    cycler; stress-driven cracking of the positive, with PyBaMM's stress-induced diffusion, at
    1C/1C), two effects outside the candidate list (a 20 mA internal leak the cycler does not
    see, under a CC-CV charge and long rests, DFN; the positive OCP 10 mV lower, a GITT at 35
    degC, SPM), self-heating of a poorly cooled cell in a drive at 0 degC (temperature
    recorded), a tab resistance in three CC-CV cycles at 15 degC (constant, not ageing), and a
    control of three cycles with HPPC pulses at 10 degC, 2 mV noise and cycler artefacts.
    Lithium and active-material loss are accepted only by their own words, as since batch r;
    the leak and the OCP offset by the words an engineer would accept (for the OCP offset also
    a stoichiometry / inventory stand-in, which is how an OCP offset is usually absorbed). The
    judge fails an "unexplained" verdict on any case with an effect. l6 starts at 70 % SOC and
    l8's first pulse pair comes after 30 min of C/2, both set before the judge so that no charge
    pulse overshoots 4.2 V by more than 15 mV (a first draft went to 4.44 V).

    First run (2026-11-26, frozen binary /work/bin/frozen-l, sha256 91b776e7a12b, load average
    5.0 before, 4.2-8.1 during, 5.8 after, on 2 cores shared with other sessions): 5 of 8.
    l2 lithium plating (irreversible law, rate constant 7.74e-11 m/s against the truth's 1e-9
    partially reversible), 11.72 -> 2.18 mV, then no missing physics, 113 s; l5 positive LAM
    (1 %) together with lithium inventory (negative / positive initial concentrations 30363 /
    16750 mol/m3, the set's 29866 / 17038), 3.02 -> 2.63 mV, then no missing physics (2.6x the
    noise), 38 s; l6 thermal (h 5.957, truth 6; ambient 273.06 K), 16.31 -> 1.01 mV, 51 s; l7
    series/contact 8.00 mOhm (truth 8), 23.70 -> 0.98 mV, 50 s; l8 no missing physics (2.02 mV,
    noise 2.09), 1 s. Missed: l1 timed out at 900 s, nothing written (rerun afterwards, not counted: also timed out at 1500 s, load 5.9-7.1); l3
    "unexplained" (73.76 mV): positive rate constant and positive diffusivity ran to 30x, the
    progressive positive LAM candidate stayed at its start (0.0 %); PyBaMM's stress-induced
    diffusion, on by default with stress-driven LAM, moves a 1C discharge by 67 mV RMS against
    the plain SPM by itself, more than the LAM does, 35 s; l4 a tie of negative LAM (6 %,
    fraction 0.7043) and OCV hysteresis (8.66 mV), 9.55 -> 5.20 mV, then "unexplained" (closest
    negative diffusivity 29.4x), 190 s."""
    cap = 5.0
    # l1: SEI, solvent-diffusion limited, 10 CC-CV cycles at 45 degC (an accelerated ageing test)
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    p = scaled(p, "SEI solvent diffusivity [m2.s-1]", 1500.0)
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 10 minutes")
    write_case(root, "l1_sei_solvent_diffusion_10_cccv_cycles_45C_spme", lion.SPMe(options={"SEI": "solvent-diffusion limited"}), p,
               [("Rest for 10 minutes",)] + [cycle] * 10,
               {"effect": "sei_growth", "candidate_model": "spme", "accept": ["SEI"], "ambient_temperature_K": 318.15,
                "note": "SEI growth limited by solvent diffusion (PyBaMM 'solvent-diffusion limited', distributed film resistance), "
                        "solvent diffusivity 3.75e-19 m2/s (1500x Chen 2020's 2.5e-22: an accelerated test at 45 degC; isothermal, "
                        "not recorded): 3.4 % of the cyclable lithium lost over 10 cycles (0.0063 mol), the capacity falls with "
                        "the square root of time. From full: 10 min rest, 10 x (1C to 2.7 V, 10 min rest, 1C CC-CV to 4.2 V and "
                        "C/10, 10 min rest), 26 h; sampled every 30 s; SPMe data"},
               initial_soc=1.0, seed=151, period=30, compare=lion.SPMe())
    # l2: partially reversible plating in 1.5C charges at 5 degC, cycler-logged
    p = with_okane2022(chen(), PLATING_KEYS)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15, "Dead lithium decay constant [s-1]": 5e-5})
    cycle = ("Discharge at 1C until 2.8 V", "Rest for 30 minutes", "Charge at 1.5C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes")
    write_case(root, "l2_plating_partially_reversible_1p5C_charge_5C_cycler_spme",
               lion.SPMe(options={"lithium plating": "partially reversible"}), p, [("Rest for 10 minutes",)] + [cycle] * 4,
               {"effect": "lithium_plating", "candidate_model": "spme", "accept": ["plating"], "ambient_temperature_K": 278.15,
                "note": "partially reversible lithium plating (PyBaMM 'partially reversible', OKane2022's plating parameters: "
                        "rate constant 1e-9 m/s, transfer coefficient 0.65; dead-lithium decay constant 5e-5 1/s instead of 1e-6) "
                        "in 1.5C CC-CV charges at 5 degC (isothermal, not recorded): about 0.005 mol plated at the end of each "
                        "charge, most of it stripped in the rest that follows (the stripping plateau), part of it turning dead. "
                        "From full: 10 min rest, 4 x (1C to 2.8 V, 30 min rest, 1.5C CC-CV to 4.2 V and C/20, 30 min rest), "
                        "14.6 h; SPMe data; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=1.0, seed=152, cycler=CYCLER, compare=lion.SPMe())
    # l3: stress-driven LAM of the positive (particle cracking), 6 cycles 1C/1C
    p = with_okane2022(chen(), [k for k in pybamm.ParameterValues("OKane2022").keys()
                                if k.startswith(("Positive electrode", "Negative electrode")) and k not in chen().keys()])
    p.update({"Positive electrode LAM constant proportional term [s-1]": 3.5e-4, "Negative electrode LAM constant proportional term [s-1]": 0.0})
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 15 minutes")
    write_case(root, "l3_lam_positive_stress_driven_6_cycles_spm", lion.SPM(options={"loss of active material": ("none", "stress-driven")}), p,
               [("Rest for 10 minutes",)] + [cycle] * 6,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"],
                "note": "progressive loss of positive active material driven by particle stress (PyBaMM ('none', 'stress-driven'), "
                        "with its defaults 'swelling only' mechanics and stress-induced diffusion; OKane2022's mechanical "
                        "constants; positive proportional term 3.5e-4 1/s, 1260x OKane2022's, negative none): positive fraction "
                        "0.665 -> about 0.62 over 6 cycles, about 1.2 % a cycle. At 25 degC: from full, 10 min rest, 6 x (1C to "
                        "2.7 V, 15 min rest, 1C CC-CV to 4.2 V and C/20, 15 min rest), 16 h; sampled every 20 s; SPM data"},
               initial_soc=1.0, seed=153, period=20, compare=lion.SPM())
    # l4: an internal leak (soft short) of 20 mA that the cycler does not see; DFN
    leak = 0.02
    seen = ["Rest for 30 minutes", "Charge at C/3 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 3 hours",
            "Discharge at C/3 for 2 hours", "Rest for 3 hours"]
    inside = [f"Discharge at {leak} A for 30 minutes", f"Charge at {cap / 3 - leak:.4f} A until 4.1 V", f"Hold at 4.1 V until {1000 * (cap / 20 - leak):.0f} mA",
              f"Discharge at {leak} A for 3 hours", f"Discharge at {cap / 3 + leak:.4f} A for 2 hours", f"Discharge at {leak} A for 3 hours"]
    write_case(root, "l4_internal_leak_20mA_cccv_long_rests_dfn", lion.DFN(), chen(), inside,
               {"effect": "self_discharge", "candidate_model": "dfn",
                "accept": ["self-discharge", "self discharge", "leak", "short circuit", "internal short", "soft short", "current offset", "current bias"],
                "note": "a 20 mA internal leak (a soft short of about 190 Ohm) that the cycler does not measure: the electrodes "
                        "carry the recorded current plus 20 mA of discharge all the time, so the cell drifts down 0.02 A h an hour "
                        "(0.4 % SOC) at rest and the CV hold ends at C/20 as the cycler sees it. Not a candidate of any family; an "
                        "engineer would call it self-discharge, a leak or a current offset. From 50 % SOC: 30 min rest, C/3 CC-CV "
                        "to 4.1 V and C/20, 3 h rest, C/3 for 2 h, 3 h rest (about 10 h); sampled every 20 s; DFN data and model"},
               initial_soc=0.5, seed=154, period=20, compare=lion.DFN(), leak_A=leak, compare_steps=seen)
    # l5: positive OCP 10 mV lower everywhere; GITT at 35 degC; SPM
    p = chen()
    ocp = p["Positive electrode OCP [V]"]
    p.update({"Positive electrode OCP [V]": lambda sto, f=ocp: f(sto) - 0.010,
              "Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    gitt = ["Rest for 20 minutes"] + ["Discharge at C/2 for 8 minutes", "Rest for 30 minutes"] * 12 + ["Charge at C/2 for 1 hour", "Rest for 1 hour"]
    write_case(root, "l5_positive_ocp_offset_gitt_35C_spm", lion.SPM(), p, gitt,
               {"effect": "ocp_offset", "candidate_model": "spm",
                "accept": ["open-circuit potential", "OCP", "electrode balance", "inventory", "stoichiometr"], "ambient_temperature_K": 308.15,
                "note": "the positive electrode's OCP 10 mV lower at every stoichiometry (a cathode lot or blend whose OCP differs "
                        "from the set's curve); not a candidate parameter; on the NMC curve a 10 mV shift is close to a small "
                        "stoichiometry shift, so an electrode-balance / lithium-inventory stand-in is accepted beside the OCP "
                        "itself. At 35 degC (isothermal, not recorded): from full, 20 min rest, GITT of 12 x (C/2 for 8 min, 30 "
                        "min rest) to about 20 % SOC, C/2 charge for 1 h, 1 h rest (9.6 h); sampled every 10 s; SPM data"},
               initial_soc=1.0, seed=155, period=10, compare=lion.SPM())
    # l6: self-heating of a poorly cooled cell in a drive at 0 degC, temperature recorded
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15, "Total heat transfer coefficient [W.m-2.K-1]": 6.0})
    drive = ["Rest for 5 minutes"] + urban_drive(156, 40) + ["Rest for 30 minutes"]
    write_case(root, "l6_thermal_drive_0C_poor_cooling_spme", lion.SPMe(options={"thermal": "lumped"}), p, drive,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "heat"], "ambient_temperature_K": 273.15,
                "note": "lumped self-heating with h = 6 W/(m2 K) (a cell in a foam-lined module) at 0 degC: the cell warms during "
                        "the drive and its resistances fall. From 70 % SOC: 5 min rest, an urban drive of 40 segments (to 3C, "
                        "regeneration to 1.5C), 30 min rest; temperature recorded (0.05 K noise); sampled every 1 s; SPMe data "
                        "handed to the isothermal SPMe"},
               initial_soc=0.7, temperature=True, seed=156, compare=lion.SPMe())
    # l7: a tab resistance (constant) in three CC-CV cycles at 15 degC; SPM
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    p.update({"Contact resistance [Ohm]": 0.008}, check_already_exists=False)
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 20 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes")
    write_case(root, "l7_tab_resistance_3_cccv_cycles_15C_spm", lion.SPM(options={"contact resistance": "true"}), p,
               [("Rest for 10 minutes",)] + [cycle] * 3,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance"], "ambient_temperature_K": 288.15,
                "note": "8 mOhm contact resistance (a poorly welded tab), the same in every cycle (nothing ages), at 15 degC "
                        "(isothermal, not recorded). From full: 10 min rest, 3 x (1C to 2.7 V, 20 min rest, C/2 CC-CV to 4.2 V and "
                        "C/20, 20 min rest), 11 h; sampled every 10 s; SPM data"},
               initial_soc=1.0, seed=157, period=10, compare=lion.SPM())
    # l8: control: three cycles with HPPC pulses at 10 degC, 2 mV noise, cycler artefacts; SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    cycle = ("Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes",
             "Discharge at C/2 for 30 minutes", "Rest for 30 minutes",
             "Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1.5C for 10 seconds", "Rest for 10 minutes",
             "Discharge at C/2 for 1 hour", "Rest for 30 minutes",
             "Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1.5C for 10 seconds", "Rest for 10 minutes",
             "Discharge at 1C until 2.8 V", "Rest for 30 minutes")
    write_case(root, "l8_control_3_cycles_hppc_10C_cycler_spme", lion.SPMe(), p, [("Rest for 10 minutes",)] + [cycle] * 3,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 283.15,
                "note": "negative control at 10 degC (isothermal, not recorded): SPMe data and model, nothing ages. From 20 % SOC: "
                        "10 min rest, 3 x (C/2 CC-CV to 4.2 V and C/20, 30 min rest, C/2 for 30 min, 30 min rest, HPPC pulse pair (2C 10 s, 40 s rest, 1.5C "
                        "charge 10 s, 10 min rest), C/2 for 1 h, 30 min rest, the pulse pair again, 1C to 2.8 V, 30 min rest); "
                        "2 mV noise; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.2, seed=158, noise=2e-3, cycler=CYCLER, compare=lion.SPMe())


def batch_k(root):
    """Sixteenth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the frozen binary /work/bin/frozen-k, sha256 b82473dbab20, before anything
    else), designed as lab situations rather than from any list of candidates: a control (SPM,
    0 degC, CC-CV charge and HPPC, 2.5 mV noise, cycler artefacts); three effects outside the
    usual vocabulary of cell physics (a current channel reading 3 % low, a voltage channel
    reading 8 mV high, a contact that works loose in the middle of a pulse test, 6 mOhm); a partly
    unwetted jelly roll (12 % of the electrode area inactive); a coarse-graphite negative
    (particle radius x1.8) together with a 6 mOhm contact resistance under a drive at 10 degC;
    reaction-limited SEI growth over 4 cycles at 45 degC; an over-calendered positive (porosity
    0.22) under 2C partial discharges. Lithium and active-material loss are accepted only by
    their own words, as since batch r; the measurement faults by the words an engineer would
    use for them."""
    cap = 5.0
    # k1: control, SPM at 0 degC, CC-CV charge, partial discharge, HPPC pulses; cycler artefacts, 2.5 mV noise
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    steps = ["Rest for 10 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes",
             "Discharge at C/2 for 40 minutes", "Rest for 20 minutes", "Discharge at 2C for 10 seconds", "Rest for 40 seconds",
             "Charge at 1.5C for 10 seconds", "Rest for 10 minutes", "Discharge at 1C for 20 minutes", "Rest for 30 minutes"]
    write_case(root, "k1_control_cccv_hppc_0C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 273.15,
                "note": "negative control at 0 degC (isothermal, not recorded): SPM data and model, nothing concealed. From 30 % "
                        "SOC: 10 min rest, C/2 CC-CV to 4.2 V and C/20, 30 min rest, C/2 for 40 min, 20 min rest, 2C discharge "
                        "10 s, 40 s rest, 1.5C charge 10 s, 10 min rest, 1C for 20 min, 30 min rest; 2.5 mV noise; cycler "
                        "artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.3, seed=161, noise=2.5e-3, cycler=CYCLER, compare=lion.SPM())
    # k2: the cycler's current channel reads 3 % low (gain 0.97): the cell carries 1/0.97 of the set current
    g = 0.97
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    seen = ["Rest for 10 minutes", "Discharge at 1C until 2.7 V", "Rest for 30 minutes", "Charge at C/2 until 4.2 V",
            "Hold at 4.2 V until C/20", "Rest for 30 minutes"]
    inside = ["Rest for 10 minutes", f"Discharge at {cap / g:.5f} A until 2.7 V", "Rest for 30 minutes", f"Charge at {cap / 2 / g:.5f} A until 4.2 V",
              f"Hold at 4.2 V until {1000 * cap / 20 / g:.2f} mA", "Rest for 30 minutes"]
    write_case(root, "k2_current_channel_gain_3pct_low_30C_spme", lion.SPMe(), p, inside,
               {"effect": "current_measurement_gain", "candidate_model": "spme",
                "accept": ["current sensor", "current measurement", "current channel", "current gain", "current scale", "calibration", "gain"],
                "ambient_temperature_K": 303.15,
                "note": "the cycler's current channel reads 3 % low (gain 0.97, a shunt out of calibration): the cycler regulates "
                        "on its own reading, so the cell carries 5.155 A when 5 A (1C) is set and recorded, 2.577 A at C/2, and "
                        "the CV hold ends at 257.7 mA true (250 mA recorded). Not a cell property; it looks like a uniform capacity "
                        "change of both electrodes (coulomb counting 3 % off) with slightly larger overpotentials. At 30 degC "
                        "(isothermal, not recorded), from full: 10 min rest, 1C to 2.7 V, 30 min rest, C/2 CC-CV to 4.2 V and "
                        "C/20, 30 min rest; sampled every 5 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=162, period=5, compare=lion.SPMe(), current_gain=g, compare_steps=seen)
    # k3: the voltage channel reads 8 mV high (an offset), GITT discharge then a charge, SPM at 15 degC
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    gitt = ["Rest for 30 minutes"] + ["Discharge at C/2 for 10 minutes", "Rest for 40 minutes"] * 10 + ["Charge at C/2 for 1 hour", "Rest for 1 hour"]
    write_case(root, "k3_voltage_channel_offset_8mV_gitt_15C_spm", lion.SPM(), p, gitt,
               {"effect": "voltage_offset", "candidate_model": "spm",
                "accept": ["offset", "calibration", "voltage measurement", "voltage sensor", "voltage channel"],
                "ambient_temperature_K": 288.15,
                "note": "the cycler's voltage channel reads 8 mV high everywhere (a calibration offset of the sense lines), under "
                        "current and at rest, in charge and discharge alike; the cell itself is nominal. Not a cell property; an "
                        "OCP offset is the nearest cell-side description (accepted through 'offset'). At 15 degC (isothermal, "
                        "not recorded), from full: 30 min rest, GITT of 10 x (C/2 for 10 min, 40 min rest) to about 17 % SOC, "
                        "C/2 charge for 1 h, 1 h rest; sampled every 10 s, 1.5 mV noise; SPM data and model"},
               initial_soc=1.0, seed=163, noise=1.5e-3, period=10, compare=lion.SPM(), post=lambda t, i, v: v + 0.008)
    # k4: a contact that works loose: 6 mOhm in series from the fifth pulse block on (added to the DFN voltage afterwards,
    # exact for an isothermal model on a current-controlled protocol with no voltage cut-off)
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    block = ["Discharge at 1.5C for 60 seconds", "Rest for 4 minutes", "Charge at 1C for 60 seconds", "Rest for 4 minutes"]
    steps = ["Rest for 5 minutes"] + block * 8 + ["Discharge at 1C for 10 minutes", "Rest for 20 minutes"]
    t_loose = 300.0 + 4 * 600.0
    write_case(root, "k4_contact_works_loose_midway_pulses_20C_dfn", lion.DFN(), p, steps,
               {"effect": "contact_resistance", "candidate_model": "dfn",
                "accept": ["contact", "series resistance", "loose", "intermittent"], "ambient_temperature_K": 293.15,
                "note": "a cable clamp that works loose: no extra resistance for the first 45 min (4 pulse blocks), then 6 mOhm "
                        "in series from t = 2700 s to the end (45 mV at 1.5C, 30 mV at 1C); a step change in a series / contact "
                        "resistance during the test. At 20 degC (isothermal, not recorded), from 80 % SOC: 5 min rest, 8 x (1.5C "
                        "discharge 60 s, 4 min rest, 1C charge 60 s, 4 min rest), 1C for 10 min, 20 min rest; sampled every 3 s, "
                        "1 mV noise; DFN data and model"},
               initial_soc=0.8, seed=164, period=3, compare=lion.DFN(),
               post=lambda t, i, v: v - np.where(t >= t_loose, 0.006, 0.0) * i)
    # k5: a partly unwetted jelly roll: 12 % of the electrode area inactive (electrode height x0.88), SPMe at 35 degC
    p = scaled(chen(), "Electrode height [m]", 0.88)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    write_case(root, "k5_unwetted_area_12pct_35C_spme", lion.SPMe(), p,
               ["Rest for 10 minutes", "Discharge at 1C until 2.7 V", "Rest for 30 minutes", "Charge at 1C for 30 minutes", "Rest for 20 minutes",
                "Discharge at 2C for 30 seconds", "Rest for 10 minutes"],
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material", "electrode area", "wetting"],
                "ambient_temperature_K": 308.15,
                "note": "12 % of the electrode area inactive (a jelly roll partly unwetted after a short formation soak; PyBaMM's "
                        "electrode height x0.88): both electrodes lose 12 % of their active material together with the lithium in "
                        "it (stoichiometry windows unchanged), and the current density in the rest is 1/0.88 higher; the nominal "
                        "capacity used for C-rates stays 5 A h. At 35 degC (isothermal, not recorded), from full: 10 min rest, 1C "
                        "to 2.7 V, 30 min rest, 1C charge for 30 min, 20 min rest, 2C discharge 30 s, 10 min rest; sampled every "
                        "3 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=165, period=3, compare=lion.SPMe())
    # k6: coarse graphite (negative particle radius x1.8) and a 6 mOhm contact, urban drive then C/2 at 10 degC, SPMe
    p = scaled(chen(), "Negative particle radius [m]", 1.8)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    p.update({"Contact resistance [Ohm]": 0.006}, check_already_exists=False)
    steps = ["Rest for 5 minutes"] + urban_drive(166, 25) + ["Rest for 15 minutes", "Discharge at C/2 until 3.0 V", "Rest for 20 minutes"]
    write_case(root, "k6_coarse_graphite_and_contact_drive_10C_spme", lion.SPMe(options={"contact resistance": "true"}), p, steps,
               {"effect": "solid_diffusivity+contact_resistance", "candidate_model": "spme",
                "accept": ["particle|diffusiv|radius", "contact|series resistance"], "ambient_temperature_K": 283.15,
                "note": "negative particle radius x1.8 (10.5 um instead of 5.86 um: a coarser graphite lot; diffusion time x3.2, "
                        "surface area per volume /1.8) and a 6 mOhm contact resistance. At 10 degC (isothermal, not recorded), "
                        "from 90 % SOC: 5 min rest, an urban drive of 25 segments (to 3C, regeneration to 1.5C), 15 min rest, "
                        "C/2 to 3.0 V, 20 min rest; sampled every 3 s, 1 mV noise; SPMe data and model"},
               initial_soc=0.9, seed=166, period=3, compare=lion.SPMe())
    # k7: reaction-limited SEI growth over 4 CC-CV cycles at 45 degC, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    p = scaled(p, "SEI reaction exchange current density [A.m-2]", 300.0)
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 10 minutes")
    write_case(root, "k7_sei_reaction_limited_4_cycles_45C_spm", lion.SPM(options={"SEI": "reaction limited"}), p,
               [("Rest for 10 minutes",)] + [cycle] * 4,
               {"effect": "sei_growth", "candidate_model": "spm", "accept": ["SEI", "inventory"], "ambient_temperature_K": 318.15,
                "note": "reaction-limited SEI growth (PyBaMM 'reaction limited', no film resistance), SEI exchange current 4.5e-5 "
                        "A/m2 (300x Chen 2020's 1.5e-7: an accelerated test at 45 degC; isothermal, not recorded): about 1 % of "
                        "the cyclable lithium lost a cycle, 4.1 % over the 4 cycles, discharge capacity 4.94 -> 4.59 A h (lithium "
                        "inventory loss growing through the recording; a static inventory loss is its nearest stand-in and is "
                        "accepted). From full: 10 min rest, 4 x (1C to 2.7 V, 10 min rest, 1C CC-CV to 4.2 V and C/10, 10 min "
                        "rest), 10.3 h; sampled every 20 s, 1 mV noise; SPM data and model"},
               initial_soc=1.0, seed=167, period=20, compare=lion.SPM())
    # k8: over-calendered positive (porosity 0.22 instead of 0.335, active fraction kept), 2C partial discharges, DFN
    p = chen()
    p.update({"Positive electrode porosity": 0.22})
    steps = ["Rest for 5 minutes"] + ["Discharge at 2C for 5 minutes", "Rest for 15 minutes"] * 3 + ["Discharge at 1C until 2.7 V", "Rest for 30 minutes"]
    write_case(root, "k8_positive_porosity_overcalendered_2C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte", "porosity", "tortuosity"],
                "note": "positive electrode porosity 0.22 instead of 0.335 (an over-calendered cathode; the active material fraction "
                        "kept): with Bruggeman 1.5 the positive's effective electrolyte conductivity and diffusivity x0.53 and less "
                        "electrolyte in it; not a candidate parameter, its physics is electrolyte transport. At 25 degC, from full: "
                        "5 min rest, 3 x (2C for 5 min, 15 min rest), 1C to 2.7 V, 30 min rest; sampled every 3 s, 2 mV noise; "
                        "DFN data and model"},
               initial_soc=1.0, seed=168, noise=2e-3, period=3, compare=lion.DFN())


def with_silicon_composite(p, graphite_fraction, silicon_fraction):
    """A graphite + silicon negative (PyBaMM "particle phases" ("2", "1")): the set's graphite as
    the primary phase with its active fraction set to `graphite_fraction`, Chen2020_composite's
    silicon (average OCP of Mark 2016, no hysteresis; radius 1.52 um, diffusivity 1.67e-14 m2/s,
    c_max 278000 mol/m3) as the secondary phase at `silicon_fraction`."""
    c = pybamm.ParameterValues("Chen2020_composite")
    negative = ["Negative electrode OCP [V]", "Negative electrode OCP entropic change [V.K-1]", "Negative electrode active material volume fraction",
                "Negative electrode density [kg.m-3]", "Negative electrode exchange-current density [A.m-2]",
                "Maximum concentration in negative electrode [mol.m-3]", "Initial concentration in negative electrode [mol.m-3]",
                "Negative particle diffusivity [m2.s-1]", "Negative particle radius [m]"]
    update = {f"Primary: {k}": p[k] for k in negative}
    update.update({f"Secondary: {k}": c[f"Secondary: {k}"] for k in negative})
    update.update({"Primary: Negative electrode active material volume fraction": graphite_fraction,
                   "Secondary: Negative electrode active material volume fraction": silicon_fraction})
    for k in negative:
        del p[k]
    p.update(update, check_already_exists=False)
    return p


def batch_j(root):
    """Seventeenth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the frozen binary /work/bin/frozen-j, sha256 4ac500ba58aa, before anything
    else). Four cases from the usual families under protocols, magnitudes, models and
    temperatures not used before: a DFN control on a WLTP-like drive at 35 degC with 0.3 mV
    noise; positive LAM together with a contact resistance in two 1C CC-CV cycles of an SPM at
    0 degC; kinetics in multi-rate (C/2 to 3C) pulse pairs at two SOCs, DFN at 5 degC; self-heating
    in 1.5C / 1C partial cycles (SPMe, temperature recorded). Four physically different
    effects: calendar ageing (solvent-diffusion-limited SEI during a 5 day storage at full SOC
    and 45 degC between two capacity checks); a particle-size distribution (PyBaMM's MPM, both
    electrodes lognormal, sd 0.3 of the mean) handed to the SPM under a GITT; a graphite +
    silicon negative (the LG M50's real chemistry) handed to the graphite-only SPMe; a positive
    particle diffusivity that falls 5x towards full lithiation, seen in a rate test (DFN).
    Lithium and active-material loss are accepted only by their own words, as since batch r;
    the new effects by the words an engineer would use for them (for the composite also an OCP
    naming; for the concentration-dependent diffusivity any particle-diffusivity naming).

    First run (2026-11-27, frozen binary /work/bin/frozen-j, sha256 4ac500ba58aa, load average
    4.9 before, 6.0 after, on 2 cores shared with another session): 5 of 8 by the judge, 4 on
    substance. j1 no missing physics (0.30 mV, noise 0.31), 40 s; j2 the pair in round 1 at the
    truth (positive fraction 0.5854, truth 0.5852; 6.01 mOhm), 36.39 -> 1.51 mV, 211 s; j3
    kinetics (rate constants 0.504x / 0.495x), 24.95 -> 1.01 mV, 48 s; j4 thermal (h 12.015),
    22.26 -> 1.00 mV, 47 s. j8 passed on its word only: particle diffusivity, but the fit moved
    the negative (0.62x, not concealed) and left the positive at 0.96x, 16.61 -> 11.34 mV (noise
    3.16), then unexplained, 807 s. Missed: j5 unexplained (46.81 mV, the mismatch located in
    the discharge after the storage), 33 s; j6 a tie of lithium inventory + positive LAM (1 %) or
    lithium inventory + particle diffusivities, then a leak and kinetics + a voltage offset,
    5.94 -> 3.89 mV, 48 s; j7 unexplained (106.90 mV), 45 s."""
    cap = 5.0
    # j1: control, DFN on a WLTP-like drive at 35 degC, 0.3 mV noise, 1 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    drive = wltp_like_current(171)
    write_case(root, "j1_control_wltp_drive_35C_0p3mV_dfn", lion.DFN(), p,
               ["Rest for 2 minutes", pybamm.step.current(drive), "Rest for 15 minutes"],
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 308.15,
                "note": "negative control at 35 degC (isothermal, not recorded): DFN data and model, nothing concealed. From 80 % "
                        "SOC: 2 min rest, a WLTP-class-3-like drive (1800 s, peaks 3C, regeneration to 1.5C, current linear "
                        "between 1 s points), 15 min rest; sampled every 1 s, 0.3 mV noise (a quiet cycler)"},
               initial_soc=0.8, seed=171, noise=3e-4, period=1, compare=lion.DFN())
    # j2: positive LAM 12 % and a 6 mOhm contact resistance, two 1C CC-CV cycles, SPM at 0 degC
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.88)
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    p.update({"Contact resistance [Ohm]": 0.006}, check_already_exists=False)
    cycle = ["Discharge at 1C until 2.7 V", "Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes"]
    write_case(root, "j2_lam_positive_and_contact_2_cccv_cycles_0C_spm", lion.SPM(options={"contact resistance": "true"}), p,
               ["Rest for 10 minutes"] + cycle * 2,
               {"effect": "active_material_loss+contact_resistance", "candidate_model": "spm",
                "accept": ["active material", "contact|series resistance"], "ambient_temperature_K": 273.15,
                "note": "12 % loss of positive active material (fraction 0.665 -> 0.5852, default initial concentrations) and a "
                        "6 mOhm contact resistance, at 0 degC (isothermal, not recorded). From full: 10 min rest, 2 x (1C to 2.7 V, "
                        "20 min rest, 1C CC-CV to 4.2 V and C/20, 20 min rest); sampled every 8 s, 1.5 mV noise; SPM data and model"},
               initial_soc=1.0, seed=172, noise=1.5e-3, period=8, compare=lion.SPM())
    # j3: exchange currents x0.5 (both electrodes), multi-rate pulse pairs at 50 % and 38 % SOC, DFN at 5 degC
    p = chen()
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.5)
    block = []
    for rate in ["C/2", "1C", "2C", "3C"]:
        block += [f"Discharge at {rate} for 10 seconds", "Rest for 90 seconds", f"Charge at {rate} for 10 seconds", "Rest for 90 seconds"]
    write_case(root, "j3_kinetics_multirate_pulses_5C_dfn", lion.DFN(), p,
               ["Rest for 5 minutes"] + block + ["Discharge at 1C for 12 minutes", "Rest for 15 minutes"] + block,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "charge transfer", "exchange"],
                "ambient_temperature_K": 278.15,
                "note": "exchange-current densities x0.5 in both electrodes, at 5 degC (isothermal, not recorded). From 50 % SOC: 5 min "
                        "rest, pulse pairs of 10 s at C/2, 1C, 2C and 3C (discharge, 90 s rest, charge, 90 s rest), 1C for 12 min, "
                        "15 min rest, the same pulse pairs at about 30 % SOC; sampled every 1 s, 1 mV noise; DFN data and model"},
               initial_soc=0.5, seed=173, period=1, compare=lion.DFN())
    # j4: lumped self-heating h = 12 in 1.5C / 1C partial cycles at 20 degC, temperature recorded, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15, "Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    cycle = ["Discharge at 1.5C for 20 minutes", "Rest for 10 minutes", "Charge at 1C for 30 minutes", "Rest for 10 minutes"]
    write_case(root, "j4_thermal_partial_cycles_20C_recorded_spme", lion.SPMe(options={"thermal": "lumped"}), p,
               ["Rest for 10 minutes"] + cycle * 3 + ["Rest for 20 minutes"],
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "heat"], "ambient_temperature_K": 293.15,
                "note": "lumped self-heating, h = 12 W/(m2 K), at 20 degC: partial cycles between 65 and 15 % SOC (from 65 %: 10 min "
                        "rest, 3 x (1.5C for 20 min, 10 min rest, 1C charge for 30 min, 10 min rest), 20 min rest); temperature "
                        "recorded (0.05 K noise); sampled every 4 s, 1 mV noise; SPMe data, the candidate the isothermal SPMe"},
               initial_soc=0.65, temperature=True, seed=174, period=4, compare=lion.SPMe())
    # j5: calendar ageing: solvent-diffusion-limited SEI during 5 days of storage at full SOC and 45 degC between two capacity checks
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    p = scaled(p, "SEI solvent diffusivity [m2.s-1]", 300.0)
    steps = ["Rest for 10 minutes", "Discharge at C/2 until 2.7 V", "Rest for 30 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
             "Rest for 1 hour", "Rest for 120 hours (30 minute period)", "Discharge at C/2 until 2.7 V", "Rest for 30 minutes"]
    write_case(root, "j5_calendar_ageing_sei_storage_5_days_45C_spme", lion.SPMe(options={"SEI": "solvent-diffusion limited"}), p, steps,
               {"effect": "sei_growth", "candidate_model": "spme", "accept": ["sei", "inventory", "calendar"], "ambient_temperature_K": 318.15,
                "sampling_note": "10 s, except the 120 h storage rest, logged every 30 min",
                "note": "calendar ageing: SEI growth limited by solvent diffusion (PyBaMM 'solvent-diffusion limited', distributed "
                        "film resistance), solvent diffusivity 7.5e-20 m2/s (300x Chen 2020's: an accelerated storage test), mostly "
                        "during 5 days of storage at full SOC and 45 degC (isothermal throughout, not recorded): the cyclable "
                        "lithium lost grows from about 0.001 to 0.006 mol, the C/2 discharge capacity after storage is 4.79 A h "
                        "against 4.96 A h for the candidate (3.4 % less), the first capacity check differs by 0.3 %; the storage "
                        "voltage stays on the graphite plateau (flat). A lithium-inventory loss that grows during the recording; a "
                        "static inventory loss is its nearest stand-in and is accepted. From full: 10 min rest, C/2 to 2.7 V, 30 min "
                        "rest, C/2 CC-CV to 4.2 V and C/20, 1 h rest, 120 h storage rest (logged every 30 min), C/2 to 2.7 V, 30 min "
                        "rest; sampled every 10 s outside the storage, 0.5 mV noise; SPMe data"},
               initial_soc=1.0, seed=175, noise=5e-4, period=10, compare=lion.SPMe())
    # j6: a particle-size distribution in both electrodes (PyBaMM MPM, lognormal, sd 0.3 of the mean), GITT at 15 degC, handed to the SPM
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    p = pybamm.get_size_distribution_parameters(p, sd_n=0.3, sd_p=0.3)
    gitt = ["Rest for 5 minutes"] + ["Discharge at 1C for 6 minutes", "Rest for 20 minutes"] * 7
    write_case(root, "j6_particle_size_distribution_gitt_15C_spm", lion.MPM(), p, gitt,
               {"effect": "particle_size_distribution", "candidate_model": "spm",
                "accept": ["size distribution", "particle size", "particle radius", "polydispers"], "ambient_temperature_K": 288.15,
                "note": "a distribution of particle sizes in both electrodes (PyBaMM's many-particle model, MPM: lognormal, area-weighted "
                        "mean the set's radius, standard deviation 0.3 of the mean, PyBaMM's default bounds) where the candidate SPM "
                        "has one particle size; the large particles lag and the relaxation after each pulse is a spread of time "
                        "constants. Not a candidate parameter; a particle diffusivity or radius fitted as one value is a stand-in "
                        "(accepted only through 'particle radius'). At 15 degC (isothermal, not recorded), from full: 5 min rest, "
                        "GITT of 7 x (1C for 6 min, 20 min rest) down to about 30 % SOC; sampled every 3 s, 2 mV noise; MPM data"},
               initial_soc=1.0, seed=176, noise=2e-3, period=3, compare=lion.SPM())
    # j7: a graphite + silicon negative (the LG M50's real SiOx-graphite anode) handed to the graphite-only SPMe; C/5 capacity check and CC-CV charge
    p = with_silicon_composite(chen(), 0.65, 0.012)
    write_case(root, "j7_graphite_silicon_composite_negative_c5_spme", lion.SPMe(options={"particle phases": ("2", "1")}), p,
               ["Rest for 10 minutes", "Discharge at C/5 until 2.7 V", "Rest for 1 hour", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
                "Rest for 1 hour"],
               {"effect": "composite_negative", "candidate_model": "spme",
                "accept": ["silicon", "composite", "blend", "second phase", "two-phase", "two phase", "open-circuit potential", "ocp"],
                "note": "a composite negative electrode: graphite (the set's, active fraction 0.65 instead of 0.75) with 1.2 % by volume "
                        "of silicon (Chen2020_composite's secondary phase: average OCP of Mark 2016, no hysteresis, 1.52 um "
                        "particles, c_max 278000 mol/m3), about the same total negative capacity as the set's; the silicon "
                        "delithiates at the end of discharge and gives a sloping low-SOC tail (up to 117 mV below the candidate "
                        "at C/5 near 20 % SOC) and a longer CC charge. Not a candidate parameter; naming the negative OCP is "
                        "accepted beside silicon / composite. At 25 degC, from full: 10 min rest, C/5 to 2.7 V, 1 h rest, C/2 "
                        "CC-CV to 4.2 V and C/20, 1 h rest; sampled every 10 s, 1 mV noise; SPMe (two-phase) data"},
               initial_soc=1.0, seed=177, period=10, compare=lion.SPMe())
    # j8: positive particle diffusivity falling 5x towards full lithiation (concentration-dependent), a rate test at 30 degC, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15,
              "Positive particle diffusivity [m2.s-1]": lambda sto, T: 4e-15 * pybamm.exp(-np.log(10.0) * 0.7 / (1 + pybamm.exp(-(sto - 0.82) / 0.03)))})
    cccv = ["Rest for 30 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"]
    write_case(root, "j8_concentration_dependent_positive_diffusivity_rate_test_30C_dfn", lion.DFN(), p,
               ["Rest for 10 minutes", "Discharge at C/2 until 2.5 V"] + cccv + ["Discharge at 1C until 2.5 V"] + cccv
               + ["Discharge at 2C until 2.5 V", "Rest for 30 minutes"],
               {"effect": "solid_diffusivity", "candidate_model": "dfn",
                "accept": ["particle diffusiv", "solid diffusiv", "solid-phase diffusiv", "solid-state diffusiv", "positive diffusiv",
                           "particle diffusion", "solid diffusion", "concentration-dependent"],
                "ambient_temperature_K": 303.15,
                "note": "a concentration-dependent positive particle diffusivity: the set's 4e-15 m2/s at low lithiation falling 5x "
                        "(a logistic step in log D, centre stoichiometry 0.82, width 0.03) towards full lithiation, as NMC's does; "
                        "the candidate's is constant. Rate-dependent capacity: C/2 5.057 A h (candidate 5.072), 1C 4.821 (4.919), "
                        "2C 4.123 (4.718). Any particle-diffusivity naming is accepted (a constant factor is the nearest "
                        "candidate). At 30 degC (isothermal, not recorded), from full: 10 min rest, a rate test of C/2, 1C and 2C "
                        "discharges to 2.5 V, each followed by 30 min rest, 1C CC-CV to 4.2 V and C/20, 30 min rest (the last "
                        "only by 30 min rest); sampled every 10 s, 3 mV noise; DFN data and model"},
               initial_soc=1.0, seed=178, noise=3e-3, period=10, compare=lion.DFN())


def highway_drive(seed, capacity_A_h=5.0, laps=3):
    """An aggressive highway drive as a 1 s cell current (A, discharge positive; ramps between 1 s
    points, no current step): each 600 s lap is an on-ramp acceleration to 3.5-4C (6-10 s), cruising
    at 1.2-2C with small fluctuations, overtaking bursts to 2.8-3.5C (5-8 s), lift-offs with
    regeneration to 1-2C charge (4-8 s), and a slow-down to 0.3C with a regenerative stop-and-go."""
    rng = np.random.default_rng(seed)
    c = capacity_A_h
    trace = CurrentTrace(rng)
    cur, ramp, hold = trace.cur, trace.ramp, trace.hold

    for lap in range(laps):
        end = 600 * (lap + 1)
        ramp(rng.uniform(3.5, 4.0) * c, int(rng.integers(6, 11)))
        while len(cur) < end - 90:
            level = rng.uniform(1.2, 2.0) * c
            ramp(level, 4)
            hold(level, int(rng.integers(25, 70)), 0.08 * c)
            if rng.uniform() < 0.5:
                ramp(rng.uniform(2.8, 3.5) * c, 3)
                hold(cur[-1], int(rng.integers(5, 9)))
            else:
                ramp(-rng.uniform(1.0, 2.0) * c, 3)
                hold(cur[-1], int(rng.integers(4, 9)))
        ramp(-1.5 * c, 4)
        hold(-1.5 * c, 6)
        ramp(0.3 * c, 5)
        while len(cur) < end:
            hold(0.3 * c, 1, 0.03 * c)
    trace.cur = cur = cur[:600 * laps]
    ramp(0.0, 3)
    i = np.array(cur)
    return np.column_stack([np.arange(len(i), dtype=float), i])


def batch_i(root):
    """Eighteenth batch, made blind (a helper session that did not read the diagnosis code, judged
    once on the frozen binary /work/bin/frozen-i before anything else). Five cases from the usual
    families in settings not used before: a contact resistance under an ascending-rate symmetric
    pulse ladder (C/5 to 3C) at 42 degC sampled every 0.5 s (SPM); an aged electrolyte
    (conductivity and diffusivity x0.5) under a pulsed 1.5C charge at 18 degC (DFN); self-heating
    of a cell cycled at 12 degC with the temperature not recorded, sampled every 7 s (SPMe); 10 %
    negative LAM together with a negative particle diffusivity x0.25 at 22 degC (SPMe, two
    effects); 6 % lithium loss under a CC-CV discharge (1C to 3.0 V, hold to C/20) at 38 degC
    (SPMe). A control: SPMe partial-window cycling at 28 degC with cycler artefacts and 2 mV noise.
    Two cases an engineer meets in practice: a low-temperature pulse-power test at -5 degC with
    slow kinetics (SPM), and an aggressive highway drive at 32 degC with self-heating and the
    temperature recorded (SPMe). Lithium and active-material loss are accepted only by their
    own words ("inventory", "lithium loss", "cyclable"; "active material")."""
    cap = 5.0
    # i1: 9 mOhm contact resistance, ascending-rate symmetric pulse ladder at 50 % SOC, 42 degC, SPM, 0.5 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 315.15, "Initial temperature [K]": 315.15})
    p.update({"Contact resistance [Ohm]": 0.009}, check_already_exists=False)
    ladder = ["Rest for 5 minutes"]
    for rate in ["C/5", "C/2", "1C", "2C", "3C"]:
        ladder += [f"Discharge at {rate} for 30 seconds", "Rest for 2 minutes", f"Charge at {rate} for 30 seconds", "Rest for 2 minutes"]
    ladder += ["Rest for 10 minutes"]
    write_case(root, "i1_contact_rate_ladder_42C_0p5s_spm", lion.SPM(options={"contact resistance": "true"}), p, ladder,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 315.15,
                "note": "9 mOhm contact resistance at 42 degC (isothermal, not recorded); from 50 % SOC: 5 min rest, an ascending "
                        "rate ladder of symmetric pulses (C/5, C/2, 1C, 2C, 3C: discharge 30 s, 2 min rest, charge 30 s, 2 min "
                        "rest), 10 min rest; sampled every 0.5 s, 1 mV noise; SPM data and model"},
               initial_soc=0.5, seed=181, period=0.5, compare=lion.SPM())
    # i2: aged electrolyte (conductivity and diffusivity x0.5), pulsed fast charge at 18 degC, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 291.15, "Initial temperature [K]": 291.15})
    p = scaled(p, "Electrolyte conductivity [S.m-1]", 0.5)
    p = scaled(p, "Electrolyte diffusivity [m2.s-1]", 0.5)
    steps = ["Rest for 5 minutes"] + ["Charge at 1.5C for 20 seconds", "Rest for 10 seconds"] * 30 + [
        "Rest for 20 minutes", "Discharge at 1C for 10 minutes", "Rest for 20 minutes"]
    write_case(root, "i2_electrolyte_aged_pulsed_fast_charge_18C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 291.15,
                "note": "an aged electrolyte: conductivity and diffusivity both x0.5 (all concentrations), at 18 degC (isothermal, "
                        "not recorded); from 10 % SOC: 5 min rest, a pulsed fast charge of 30 x (1.5C charge 20 s, 10 s rest) to "
                        "about 45 % SOC, 20 min rest, 1C discharge for 10 min, 20 min rest; sampled every 1 s, 1 mV noise; "
                        "DFN data and model"},
               initial_soc=0.1, seed=182, period=1, compare=lion.DFN())
    # i3: lumped self-heating h = 7 at 12 degC, a full cycle, temperature NOT recorded, SPMe, 7 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 285.15, "Initial temperature [K]": 285.15, "Total heat transfer coefficient [W.m-2.K-1]": 7.0})
    cycle = ["Rest for 5 minutes", "Discharge at 1.2C until 2.7 V", "Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10",
             "Rest for 20 minutes"]
    write_case(root, "i3_thermal_unrecorded_full_cycle_12C_7s_spme", lion.SPMe(options={"thermal": "lumped"}), p, cycle,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "temperature", "heat"],
                "ambient_temperature_K": 285.15,
                "note": "lumped self-heating, h = 7 W/(m2 K), ambient and initial 12 degC; temperature NOT recorded. From full: 5 "
                        "min rest, 1.2C to 2.7 V, 20 min rest, 1C CC-CV to 4.2 V and C/10, 20 min rest; sampled every 7 s, 1 mV "
                        "noise; SPMe data, the candidate the isothermal SPMe at 12 degC"},
               initial_soc=1.0, seed=183, period=7, compare=lion.SPMe())
    # i4: 10 % negative LAM and negative particle diffusivity x0.25, SPMe at 22 degC, 6 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 295.15, "Initial temperature [K]": 295.15})
    p = scaled(p, "Negative electrode active material volume fraction", 0.9)
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.25)
    steps = ["Rest for 10 minutes", "Discharge at 1.5C for 20 minutes", "Rest for 40 minutes", "Discharge at C/2 until 2.7 V", "Rest for 40 minutes",
             "Charge at 1C for 30 minutes", "Rest for 30 minutes"]
    write_case(root, "i4_lam_negative_and_diffusivity_22C_6s_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss+solid_diffusivity", "candidate_model": "spme",
                "accept": ["active material", "diffusiv|diffusion"], "ambient_temperature_K": 295.15,
                "note": "10 % loss of negative active material (default initial concentrations) and negative particle diffusivity "
                        "x0.25, at 22 degC (isothermal, not recorded). From full: 10 min rest, 1.5C for 20 min, 40 min rest, C/2 "
                        "to 2.7 V, 40 min rest, 1C charge for 30 min, 30 min rest; sampled every 6 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=184, period=6, compare=lion.SPMe())
    # i5: 6 % lithium loss, CC-CV discharge (1C to 3.0 V, hold to C/20) at 38 degC, SPMe, 5 s sampling
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94)
    p.update({"Ambient temperature [K]": 311.15, "Initial temperature [K]": 311.15})
    steps = ["Rest for 5 minutes", "Discharge at 1C until 3.0 V", "Hold at 3.0 V until C/20", "Rest for 30 minutes", "Charge at 1C for 30 minutes",
             "Rest for 20 minutes"]
    write_case(root, "i5_inventory_cccv_discharge_38C_spme", lion.SPMe(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 311.15,
                "note": "6 % less lithium in the negative electrode at 38 degC (isothermal, not recorded); from full: 5 min rest, a "
                        "CC-CV discharge (1C to 3.0 V, hold at 3.0 V to C/20), 30 min rest, 1C charge for 30 min, 20 min rest; "
                        "sampled every 5 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=185, period=5, compare=lion.SPMe())
    # i6: control, SPMe partial-window cycling at 28 degC, cycler artefacts, 2 mV noise
    p = chen()
    p.update({"Ambient temperature [K]": 301.15, "Initial temperature [K]": 301.15})
    window = ["Discharge at C/2 for 48 minutes", "Rest for 15 minutes", "Charge at C/2 for 48 minutes", "Rest for 15 minutes"]
    write_case(root, "i6_control_partial_window_28C_cycler_spme", lion.SPMe(), p,
               ["Rest for 10 minutes"] + window * 3 + ["Discharge at 2C for 10 seconds", "Rest for 5 minutes"],
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 301.15,
                "note": "negative control at 28 degC (isothermal, not recorded): SPMe data and model, nothing concealed. From 80 % "
                        "SOC: 10 min rest, 3 x (C/2 for 48 min, 15 min rest, C/2 charge for 48 min, 15 min rest) between about 80 "
                        "and 40 % SOC, a 2C pulse of 10 s, 5 min rest; 2 mV noise; cycler artefacts (irregular sampling, 3 mA "
                        "current noise, 0.1 mV resolution)"},
               initial_soc=0.8, seed=186, noise=2e-3, cycler=CYCLER, compare=lion.SPMe())
    # i7 (practical): a low-temperature pulse-power test at -5 degC, exchange currents x0.45, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 268.15, "Initial temperature [K]": 268.15})
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.45)
    block = []
    for rate, charge in [("C/2", "0.375C"), ("1C", "0.75C"), ("2C", "1.5C")]:
        block += [f"Discharge at {rate} for 10 seconds", "Rest for 1 minute", f"Charge at {charge} for 10 seconds", "Rest for 3 minutes"]
    write_case(root, "i7_kinetics_cold_pulse_power_minus5C_spm", lion.SPM(), p,
               ["Rest for 5 minutes"] + block + ["Discharge at C/2 for 24 minutes", "Rest for 30 minutes"] + block + ["Rest for 5 minutes"],
               {"effect": "kinetics", "candidate_model": "spm",
                "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"], "ambient_temperature_K": 268.15,
                "note": "exchange-current densities x0.45 in both electrodes, at -5 degC (isothermal, not recorded): a low-temperature "
                        "pulse-power test from 60 % SOC: 5 min rest, pulses at C/2, 1C and 2C (discharge 10 s, 1 min rest, charge "
                        "at 0.75x the rate 10 s, 3 min rest), C/2 for 24 min, 30 min rest, the same pulses at about 40 % SOC, 5 "
                        "min rest; sampled every 1 s, 1.5 mV noise; SPM data and model"},
               initial_soc=0.6, seed=187, noise=1.5e-3, period=1, compare=lion.SPM())
    # i8 (practical): aggressive highway drive at 32 degC, lumped self-heating h = 15, temperature recorded, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 305.15, "Initial temperature [K]": 305.15, "Total heat transfer coefficient [W.m-2.K-1]": 15.0})
    drive = highway_drive(188, cap)
    write_case(root, "i8_thermal_highway_drive_32C_recorded_spme", lion.SPMe(options={"thermal": "lumped"}), p,
               ["Rest for 2 minutes", pybamm.step.current(drive), "Rest for 20 minutes"],
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "temperature", "heat"],
                "ambient_temperature_K": 305.15,
                "note": "lumped self-heating, h = 15 W/(m2 K), ambient and initial 32 degC; temperature recorded (0.05 K noise). "
                        "From 95 % SOC: 2 min rest, an aggressive highway drive of 30 min (three 10 min laps: on-ramp "
                        "acceleration to 3.5-4C, cruising at 1.2-2C, overtaking bursts to 3.5C, regeneration to 2C, a slow-down; "
                        "current ramps between 1 s points), 20 min rest; sampled every 1 s, 1 mV noise; SPMe data, the "
                        "candidate the isothermal SPMe at 32 degC"},
               initial_soc=0.95, temperature=True, seed=188, period=1, compare=lion.SPMe())


DST_PROFILE = [(16, 0.0), (28, 12.5), (12, 25.0), (8, -12.5), (16, 0.0), (24, 12.5), (12, 25.0), (8, -12.5), (16, 0.0), (24, 12.5),
               (12, 25.0), (8, -12.5), (16, 0.0), (36, 12.5), (8, 100.0), (24, 62.5), (8, -25.0), (32, 25.0), (8, -50.0), (44, 0.0)]


def dst_steps(full_C):
    """The USABC Dynamic Stress Test (360 s: 20 steps at 0, +-12.5, 25, 50, 62.5 and 100 % of the
    peak, discharge positive) as current steps, the peak discharge at `full_C` C-rate."""
    steps = []
    for seconds, percent in DST_PROFILE:
        c = full_C * percent / 100.0
        steps.append(f"Rest for {seconds} seconds" if c == 0 else f"{'Discharge' if c > 0 else 'Charge'} at {abs(c):.4g}C for {seconds} seconds")
    return steps


def batch_h(root):
    """Nineteenth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s8a before anything else), harder than usual: two pairs
    not used before (kinetics + electrolyte diffusivity in the DFN under the USABC Dynamic
    Stress Test at 15 degC; negative LAM + self-heating in a CC-CV charge and a 1.5C discharge
    at 8 degC, SPMe, temperature recorded); two multi-cycle ageing recordings handed to the DFN
    (reaction-limited SEI at 35 degC, 1.5C / 0.7C CC-CV cycles, 45 s sampling; irreversible
    plating in 1.5C CC-CV charges at 5 degC, 40 s sampling), about 3 % of the lithium lost in
    4 cycles each; a DFN control (a CC-CV charge, then a hill-and-town drive at 30 degC, cycler
    artefacts, 1.5 mV noise); three single effects in practical settings: 8 % lithium loss in
    an HPPC at 0 degC with DFN data handed to the SPM (whose own error is 12 mV there), 12 %
    positive LAM seen only through partial-window cycling at 45 degC (the capacity unchanged),
    and a mild positive particle diffusivity loss (x0.65) under a highway drive at 10 degC.
    Lithium and active-material loss are accepted only by their own words, as since batch r."""
    cap = 5.0
    # h1: two effects in the DFN: kinetics x0.4 and electrolyte diffusivity x0.35, USABC DST at 15 degC
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.4)
    p = scaled(p, "Electrolyte diffusivity [m2.s-1]", 0.35)
    steps = ["Rest for 5 minutes"] + dst_steps(2.5) * 6 + ["Rest for 20 minutes"] + dst_steps(2.5) * 6 + ["Rest for 20 minutes"]
    write_case(root, "h1_kinetics_and_electrolyte_diffusivity_dst_15C_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics+electrolyte_transport", "candidate_model": "dfn",
                "accept": ["kinetic|exchange|charge-transfer|charge transfer|reaction rate", "electrolyte"], "ambient_temperature_K": 288.15,
                "note": "exchange-current densities x0.4 (both electrodes) and electrolyte diffusivity x0.35 (all concentrations), at "
                        "15 degC (isothermal, not recorded). From 75 % SOC: 5 min rest, 6 x the USABC Dynamic Stress Test (360 s, "
                        "peak discharge 2.5C, regeneration to 1.25C, mean 0.31C), 20 min rest, 6 more DST, 20 min rest; sampled "
                        "every 2 s, 1 mV noise; DFN data and model. Each effect alone moves the DFN by 35.7 mV (kinetics) and "
                        "15.8 mV (electrolyte diffusivity) RMS"},
               initial_soc=0.75, seed=191, period=2, compare=lion.DFN())
    # h2: two effects in the SPMe: 10 % negative LAM and lumped self-heating h = 15, CC-CV charge then 1.5C discharge at 8 degC, temperature recorded
    p = chen()
    p.update({"Ambient temperature [K]": 281.15, "Initial temperature [K]": 281.15, "Total heat transfer coefficient [W.m-2.K-1]": 15.0})
    p = scaled(p, "Negative electrode active material volume fraction", 0.9)
    steps = ["Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes", "Discharge at 1.5C until 2.7 V",
             "Rest for 40 minutes"]
    write_case(root, "h2_lam_negative_and_thermal_cccv_8C_recorded_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "active_material_loss+thermal", "candidate_model": "spme",
                "accept": ["active material", "thermal|self-heating|temperature|heat"], "ambient_temperature_K": 281.15,
                "note": "10 % loss of negative active material (default initial concentrations) and lumped self-heating h = 15 "
                        "W/(m2 K), ambient and initial 8 degC; temperature recorded (0.05 K noise). From 20 % SOC: 10 min rest, 1C "
                        "CC-CV charge to 4.2 V and C/20, 30 min rest, 1.5C to 2.7 V, 40 min rest (about 21 K rise in the discharge); sampled every 4 s, 1 mV "
                        "noise; SPMe data, the candidate the isothermal SPMe at 8 degC. Each effect alone moves the SPMe by 89.7 "
                        "mV (LAM) and 71.7 mV (self-heating) RMS"},
               initial_soc=0.2, temperature=True, seed=192, period=4, compare=lion.SPMe())
    # h3: ageing, reaction-limited SEI growth in the DFN at 35 degC, 4 CC-CV cycles, 45 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    p = scaled(p, "SEI reaction exchange current density [A.m-2]", 130.0)
    cycle = ("Discharge at 1.5C until 2.8 V", "Rest for 10 minutes", "Charge at 0.7C until 4.15 V", "Hold at 4.15 V until C/15", "Rest for 15 minutes")
    write_case(root, "h3_sei_reaction_limited_4_cycles_35C_45s_dfn", lion.DFN(options={"SEI": "reaction limited"}), p,
               [("Rest for 5 minutes",)] + [cycle] * 4,
               {"effect": "sei_growth", "candidate_model": "dfn", "accept": ["SEI", "inventory"], "ambient_temperature_K": 308.15,
                "note": "reaction-limited SEI growth (PyBaMM 'reaction limited', no film resistance), SEI exchange current x130 "
                        "(1.95e-5 A/m2; an accelerated test at 35 degC, isothermal, not recorded): 3.1 % of the cyclable lithium lost over the 4 cycles (0.0087 mol, about 0.8 % a "
                        "cycle), the 1.5C discharge capacity 4.42 -> 4.29 A h where the candidate gives 4.49. From 90 % SOC: "
                        "5 min rest, 4 x (1.5C to 2.8 V, 10 min rest, 0.7C CC-CV to 4.15 V and C/15, 15 min rest); sampled every "
                        "45 s, 1 mV noise; DFN data and model (a static inventory loss is its nearest stand-in and is accepted)"},
               initial_soc=0.9, seed=193, period=45, compare=lion.DFN())
    # h4: ageing, irreversible lithium plating in 1.5C CC-CV charges at 5 degC, DFN, 4 cycles, 40 s sampling
    p = with_okane2022(chen(), PLATING_KEYS)
    p = scaled(p, "Lithium plating kinetic rate constant [m.s-1]", 0.35)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    cycle = ("Charge at 1.5C until 4.1 V", "Hold at 4.1 V until C/10", "Rest for 20 minutes", "Discharge at 1C until 3.0 V", "Rest for 20 minutes")
    write_case(root, "h4_plating_irreversible_1p5C_charges_5C_40s_dfn", lion.DFN(options={"lithium plating": "irreversible"}), p,
               [("Rest for 5 minutes",)] + [cycle] * 4,
               {"effect": "lithium_plating", "candidate_model": "dfn", "accept": ["plating"], "ambient_temperature_K": 278.15,
                "note": "irreversible lithium plating (PyBaMM 'irreversible', OKane2022's plating parameters, rate constant x0.35 = "
                        "3.5e-10 m/s) at 5 degC (isothermal, not recorded): 3.0 % of the cyclable lithium lost over the 4 "
                        "cycles (0.0084 mol plated, about 0.75 % a cycle), the 1C discharge capacity 3.53 -> 3.40 A h where the "
                        "candidate gives 3.57. From 10 % SOC: 5 min rest, 4 x (1.5C "
                        "CC-CV charge to 4.1 V and C/10, 20 min rest, 1C to 3.0 V, 20 min rest); sampled every 40 s, 1 mV noise; "
                        "DFN data and model"},
               initial_soc=0.1, seed=194, period=40, compare=lion.DFN())
    # h5: control, DFN, a CC-CV charge then a hill-and-town drive at 30 degC, cycler artefacts, 1.5 mV noise
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    drive = hill_regen_drive(195, cap)
    steps = ["Rest for 10 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 20 minutes", "Discharge at 1C for 15 minutes",
             "Rest for 10 minutes", pybamm.step.current(drive),
             "Rest for 20 minutes"]
    write_case(root, "h5_control_cccv_then_drive_30C_cycler_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 303.15,
                "note": "negative control at 30 degC (isothermal, not recorded): DFN data and model, nothing concealed. From 55 % "
                        "SOC: 10 min rest, C/2 CC-CV charge to 4.1 V and C/20, 20 min rest, 1C for 15 min, 10 min rest, a 30 min hill-and-town drive (climb "
                        "to 3C, a descent held by regeneration to 2C, stop-and-go; current ramps between 1 s points), 20 min "
                        "rest; 1.5 mV noise; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.55, seed=195, noise=1.5e-3, cycler=CYCLER, compare=lion.DFN())
    # h6: 8 % lithium loss, HPPC with C/2 SOC steps at 0 degC, DFN data handed to the SPM, cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.92)
    block = ["Discharge at C/2 for 12 minutes", "Rest for 30 minutes", "Discharge at 1C for 10 seconds", "Rest for 40 seconds",
             "Charge at 0.75C for 10 seconds", "Rest for 5 minutes"]
    write_case(root, "h6_inventory_hppc_0C_cycler_dfn_data_spm", lion.DFN(), p, ["Rest for 10 minutes"] + block * 8,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 273.15,
                "note": "8 % less lithium in the negative electrode at 0 degC (isothermal, not recorded); HPPC from full: 10 min "
                        "rest, 8 x (C/2 for 12 min, 30 min rest, 1C discharge 10 s, 40 s rest, 0.75C charge 10 s, 5 min rest), "
                        "down to about 20 % SOC; 1 mV noise, cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution); DFN data handed to the SPM. With 2 s sampling and no noise, PyBaMM's SPM at nominal "
                        "parameters is 31.8 mV RMS from this DFN, 12.2 mV from the DFN without the loss (the SPM's own error, "
                        "mostly the electrolyte's) and 12.2 mV from the DFN with it when given the loss; the loss moves the DFN "
                        "by 25.7 mV: one concealed effect, electrolyte transport (SPM -> SPMe/DFN) beside it is right too"},
               initial_soc=1.0, seed=196, cycler=CYCLER, compare=lion.SPM())
    # h7: 12 % positive LAM in partial-window cycling at 45 degC, SPMe, 3 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    p = scaled(p, "Positive electrode active material volume fraction", 0.88)
    window = ["Discharge at 1C for 33 minutes", "Rest for 10 minutes", "Charge at 1C for 33 minutes", "Rest for 10 minutes"]
    write_case(root, "h7_lam_positive_partial_window_45C_spme", lion.SPMe(), p, ["Rest for 10 minutes"] + window * 3,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 318.15,
                "note": "12 % loss of positive active material (default initial concentrations) at 45 degC (isothermal, not "
                        "recorded); partial-window cycling from 75 % SOC: 10 min rest, 3 x (1C for 33 min, 10 min rest, 1C charge "
                        "for 33 min, 10 min rest): 2.75 A h of the cell's 5.12 (C/20), about 75 -> 21 % SOC, the "
                        "cell's C/20 capacity barely changed (the positive does not limit it); sampled every 3 s, 1 mV noise; SPMe data and model"},
               initial_soc=0.75, seed=197, period=3, compare=lion.SPMe())
    # h8: positive particle diffusivity x0.65 under an aggressive highway drive at 10 degC, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    p = scaled(p, "Positive particle diffusivity [m2.s-1]", 0.65)
    drive = highway_drive(198, cap, laps=3)
    write_case(root, "h8_diffusivity_positive_highway_drive_10C_spme", lion.SPMe(), p, ["Rest for 5 minutes", pybamm.step.current(drive), "Rest for 30 minutes"],
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["particle", "solid diffusiv", "diffusivity"],
                "ambient_temperature_K": 283.15,
                "note": "positive particle diffusivity x0.65 (a mild loss) at 10 degC (isothermal, not recorded); from 90 % SOC: "
                        "5 min rest, a 30 min aggressive highway drive (three 10 min laps: on-ramp to 3.5-4C, cruising 1.2-2C, "
                        "overtaking to 3.5C, regeneration to 2C; ramps between 1 s points) down to about 20 % SOC, 30 min rest; "
                        "sampled every 1 s, 1 mV noise; SPMe data and model"},
               initial_soc=0.9, seed=198, period=1, compare=lion.SPMe())


def coarsened(drive, dt):
    """A 1 s current table averaged over `dt` s blocks: the table (time_s, current_A) at `dt` s
    knots, linear between them, so that a recording sampled every `dt` s holds exactly the
    current the cell carried at its points."""
    n = (len(drive) - 1) // dt
    i = drive[: n * dt, 1].reshape(n, dt).mean(axis=1)
    i = np.append(i, drive[-1, 1])
    return np.column_stack([np.arange(n + 1, dtype=float) * dt, i])


def batch_f(root):
    """Twentieth batch, made blind (a helper session that did not read the diagnosis code, judged
    once on the binary /work/bin/s9start before anything else): protocols and settings not used
    before, one effect each from the usual families plus one pair and a control. A C/2 GITT at
    0 degC on a positive particle diffusivity x0.35 (SPMe); a constant-power discharge (25 W)
    and charge (12 W) at 15 degC on an electrolyte conductivity x0.45 (DFN); a WLTP-like drive
    (2 s knots) on the DFN at 20 degC with the positive exchange current x0.3 only; a
    grid-service duty (symmetric 2C discharge/charge blocks of 3 min, no net charge) at 35 degC
    with self-heating (h = 12, temperature recorded, SPM); the commonest ageing pair, 8 %
    negative LAM + 5 % lithium loss, seen through a slow incremental-capacity check (C/10
    discharge, C/5 CC-CV charge, 40 s sampling; SPMe); interstitial-diffusion-limited SEI
    growth over 4 cycles (2C / 1C CC-CV) at 40 degC (SPMe, 30 s sampling); a contact
    resistance under reflex (pulse) charging with short discharge pulses at 30 degC (DFN); and
    an SPM control at -5 degC, a C/3 CC-CV cycle with 2 h rests, cycler artefacts. Lithium and
    active-material loss are accepted only by their own words, as since batch r; the particle
    diffusivity by "particle" / "solid diffusiv" words (not a bare "diffusiv", which an
    electrolyte diffusivity would match).

    First run (2026-11-27, binary /work/bin/s9start, sha256 c2be88b76154, load average 2.3
    before, 2.1-3.9 during, 3.2 after, on 2 cores shared with other sessions): 8 of 8, 1039 s in
    all. f1 particle diffusivities (positive 1.400e-15 m2/s, the truth's 0.35 x 4e-15; negative
    0.971x), 14.69 -> 0.99 mV, then no missing physics, 5 s; f2 electrolyte properties
    (conductivity 0.4478x, diffusivity 1.003x), 26.56 -> 1.02 mV, 52 s; f3 kinetics (positive
    rate constant 1.014e-6, 0.296x the set's 3.42e-6; negative 1.007x), 10.96 -> 0.99 mV, 201 s;
    f4 thermal (h 12.014, ambient 308.16 K), 20.39 -> 0.98 mV, 3 s; f5 passed on the rounds
    together: round 1 negative LAM ("13 %", fractions 0.6548 / 0.6491), 87.24 -> 5.36 mV, round
    2 lithium inventory (negative / positive initial concentrations 29395 / 16646 mol/m3, the
    LAM refitted to 0.6734, i.e. 10 % against the truth's 8 %), 2.68 mV, round 3 a tie of
    particle diffusivities (1.008x / 1.015x) or kinetics stand-ins, 1.74 mV (noise 1.14), 19 s;
    f6 passed on "SEI", weakly: round 1 named "negative LAM (0 %)" together with SEI growth
    (fractions 0.7491 / 0.6647, the set's; reaction-limited SEI exchange current 2.75e-5, 183x
    the set's), 26.36 -> 3.95 mV, while SEI growth alone stayed at its start value (1.5e-7,
    25.31 mV, ranked 17th); round 2 a tie of electrolyte conductivity 0.92x or kinetics, 3.51
    mV; round 3 unexplained (3.51 mV, noise 1.03; the reaction-limited law is not the
    interstitial-diffusion-limited one), 744 s of the judge's 900; f7 series/contact 6.98 mOhm
    (truth 7), 24.01 -> 1.02 mV, 15 s; f8 no missing physics (1.05 mV, noise 1.09), 0 s."""
    cap = 5.0
    # f1: positive particle diffusivity x0.35, C/2 GITT at 0 degC, SPMe
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.35)
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    gitt = ["Rest for 20 minutes"] + ["Discharge at C/2 for 7.5 minutes", "Rest for 30 minutes"] * 8
    write_case(root, "f1_diffusivity_positive_gitt_0C_spme", lion.SPMe(), p, gitt,
               {"effect": "solid_diffusivity", "candidate_model": "spme",
                "accept": ["particle", "solid diffusiv", "solid-phase diffusiv", "positive diffusiv"], "ambient_temperature_K": 273.15,
                "note": "positive particle diffusivity x0.35 at 0 degC (isothermal, not recorded); from full: 20 min rest, a C/2 "
                        "GITT of 8 x (C/2 for 7.5 min, 30 min rest) down to about 50 % SOC; sampled every 10 s, 1 mV noise; SPMe "
                        "data and model"},
               initial_soc=1.0, seed=201, period=10, compare=lion.SPMe())
    # f2: electrolyte conductivity x0.45, constant-power discharge and charge at 15 degC, DFN
    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.45)
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    power = ["Rest for 5 minutes", "Discharge at 25 W until 2.7 V", "Rest for 30 minutes", "Charge at 12 W for 30 minutes", "Rest for 20 minutes"]
    write_case(root, "f2_conductivity_constant_power_15C_dfn", lion.DFN(), p, power,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 288.15,
                "note": "electrolyte conductivity x0.45 (all concentrations) at 15 degC (isothermal, not recorded); from full: 5 min "
                        "rest, constant-power 25 W discharge (about 1.4C) to 2.7 V, 30 min rest, constant-power 12 W charge for "
                        "30 min, 20 min rest; sampled every 5 s, 1 mV noise; DFN data and model"},
               initial_soc=1.0, seed=202, period=5, compare=lion.DFN())
    # f3: positive exchange current x0.3 only, WLTP-like drive at 2 s knots, 20 degC, DFN
    p = scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.3)
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    drive = coarsened(wltp_like_current(203), 2)
    write_case(root, "f3_kinetics_positive_wltp_20C_dfn", lion.DFN(), p,
               ["Rest for 2 minutes", pybamm.step.current(drive), "Rest for 15 minutes"],
               {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "charge transfer", "charge-transfer", "exchange", "reaction rate"],
                "ambient_temperature_K": 293.15,
                "note": "positive exchange-current density x0.3 only (negative as set) at 20 degC (isothermal, not recorded); from "
                        "75 % SOC: 2 min rest, a WLTP-class-3-like drive (1800 s, peaks 3C, regeneration to 1.5C; the 1 s current "
                        "averaged over 2 s blocks, linear between 2 s knots), 15 min rest; sampled every 2 s, 1 mV noise; DFN "
                        "data and model"},
               initial_soc=0.75, seed=203, period=2, compare=lion.DFN())
    # f4: self-heating h = 12 under a grid-service duty (symmetric 2C blocks) at 35 degC, temperature recorded, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15, "Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    duty = ["Rest for 5 minutes"] + ["Discharge at 2C for 3 minutes", "Charge at 2C for 3 minutes"] * 10 + ["Rest for 30 minutes"]
    write_case(root, "f4_thermal_grid_service_2C_blocks_35C_recorded_spm", lion.SPM(options={"thermal": "lumped"}), p, duty,
               {"effect": "thermal", "candidate_model": "spm", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 308.15,
                "note": "lumped self-heating, h = 12 W/(m2 K), ambient and initial 35 degC; a grid-service duty from 50 % SOC: 5 min "
                        "rest, 10 x (2C discharge for 3 min, 2C charge for 3 min: no net charge, about 13 K rise), 30 min rest; "
                        "temperature recorded (0.05 K noise); sampled every 2 s, 1 mV noise; SPM data, the candidate the "
                        "isothermal SPM at 35 degC"},
               initial_soc=0.5, temperature=True, seed=204, period=2, compare=lion.SPM())
    # f5: negative LAM 8 % and 5 % lithium loss, a slow incremental-capacity check (C/10 discharge, C/5 CC-CV charge), SPMe
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.92)
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    ica = ["Rest for 30 minutes", "Discharge at C/10 until 2.5 V", "Rest for 1 hour", "Charge at C/5 until 4.2 V", "Hold at 4.2 V until C/50",
           "Rest for 1 hour"]
    write_case(root, "f5_lam_negative_and_inventory_slow_ica_30C_spme", lion.SPMe(), p, ica,
               {"effect": "active_material_loss+lithium_inventory_loss", "candidate_model": "spme",
                "accept": ["active material", "inventory|lithium loss|cyclable"], "ambient_temperature_K": 303.15,
                "note": "8 % loss of negative active material (default initial concentrations) and 5 % less lithium in the negative "
                        "electrode (LAM_NE + LLI, the commonest pair of an aged graphite cell), at 30 degC (isothermal, not "
                        "recorded); a slow incremental-capacity check from full: 30 min rest, C/10 to 2.5 V, 1 h rest, C/5 CC-CV "
                        "to 4.2 V and C/50, 1 h rest; sampled every 40 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=205, period=40, compare=lion.SPMe())
    # f6: ageing, interstitial-diffusion-limited SEI over 4 cycles (2C / 1C CC-CV) at 40 degC, SPMe, 30 s sampling
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    p = scaled(p, "SEI lithium interstitial diffusivity [m2.s-1]", 4e5)
    cycle = ("Discharge at 2C until 2.7 V", "Rest for 20 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/10", "Rest for 20 minutes")
    write_case(root, "f6_sei_interstitial_diffusion_4_cycles_40C_spme", lion.SPMe(options={"SEI": "interstitial-diffusion limited"}), p,
               [("Rest for 10 minutes",)] + [cycle] * 4,
               {"effect": "sei_growth", "candidate_model": "spme", "accept": ["SEI", "inventory"], "ambient_temperature_K": 313.15,
                "note": "SEI growth limited by lithium-interstitial diffusion (PyBaMM 'interstitial-diffusion limited', distributed "
                        "film resistance), interstitial diffusivity 4e-15 m2/s (4e5 x Chen 2020's 1e-20: an accelerated test at "
                        "40 degC; isothermal, not recorded): about 0.007 mol of lithium lost over the 4 cycles (2.5 % of the "
                        "0.284 mol in the particles), growing with the square root of time; a static inventory loss is its "
                        "nearest stand-in and is accepted. From full: 10 min rest, 4 x (2C to 2.7 V, 20 min rest, 1C CC-CV to "
                        "4.1 V and C/10, 20 min rest), about 9.5 h; sampled every 30 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=206, period=30, compare=lion.SPMe())
    # f7: 7 mOhm contact resistance under reflex (pulse) charging with short discharge pulses, 30 degC, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    p.update({"Contact resistance [Ohm]": 0.007}, check_already_exists=False)
    reflex = ["Charge at 1C for 55 seconds", "Discharge at 2C for 5 seconds", "Rest for 5 seconds"] * 20
    write_case(root, "f7_contact_reflex_charging_30C_dfn", lion.DFN(options={"contact resistance": "true"}), p,
               ["Rest for 5 minutes"] + reflex + ["Rest for 15 minutes", "Discharge at 1C for 8 minutes", "Rest for 10 minutes"],
               {"effect": "contact_resistance", "candidate_model": "dfn", "accept": ["contact", "series resistance"], "ambient_temperature_K": 303.15,
                "note": "7 mOhm contact resistance at 30 degC (isothermal, not recorded); from 20 % SOC: 5 min rest, reflex (pulse) "
                        "charging of 20 x (1C charge 55 s, 2C discharge 5 s, 5 s rest), 15 min rest, 1C for 8 min, 10 min rest; "
                        "sampled every 2 s, 1 mV noise; DFN data and model"},
               initial_soc=0.2, seed=207, period=2, compare=lion.DFN())
    # f8: control, SPM at -5 degC, a C/3 CC-CV cycle with 2 h rests, cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 268.15, "Initial temperature [K]": 268.15})
    steps = ["Rest for 1 hour", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 2 hours", "Discharge at C/3 until 2.7 V",
             "Rest for 2 hours"]
    write_case(root, "f8_control_c3_cycle_long_rests_minus5C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 268.15,
                "note": "negative control at -5 degC (isothermal, not recorded): SPM data and model, nothing concealed. From 40 % SOC: "
                        "1 h rest, C/3 CC-CV to 4.2 V and C/20, 2 h rest, C/3 to 2.7 V, 2 h rest; 1 mV noise; cycler artefacts "
                        "(irregular sampling, 3 mA current noise, 0.1 mV resolution)"},
               initial_soc=0.4, seed=208, cycler=CYCLER, compare=lion.SPM())


def batch_e(root):
    """Twenty-first batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s9e before anything else): one effect from each usual
    family in settings not used before, one pair not used before and a control. A contact
    resistance in an SPM under a parked urban drive (six bursts with 8 min holds at rest
    between them) from 75 % SOC at 20 degC, cycler artefacts; an electrolyte diffusivity x0.6 seen through
    an ascending-rate charge staircase (C/3 to 1C) from 20 % SOC at 10 degC (SPMe, 1.5 mV
    noise); 6 % lithium loss in a C/2 discharge to 2.7 V and a 1C CC-CV charge to 4.0 V from
    60 % SOC at 20 degC, 0.5 mV noise, cycler artefacts (SPMe); self-heating of a poorly cooled
    DFN (h = 8, temperature recorded) in a 2C partial discharge and a 1C partial charge at
    15 degC; the negative exchange current alone x0.3 under a fast random 5 s drive at low SOC
    at 30 degC, 2 mV noise (SPM); 10 % positive LAM together with a negative particle
    diffusivity x0.3 in a rate step-down discharge (2C, then C/3 to 2.7 V) at 5 degC (SPMe);
    irreversible lithium plating in three 1.2C CC-CV charges at 2 degC on the SPMe (3.0 % of
    the lithium lost); a DFN control at 40 degC (3C / 2C pulses and a 1C discharge, 2 mV
    noise). Lithium and active-material loss are accepted only by their own words, as since
    batch r; the particle diffusivity by "particle" / "solid diffusiv" words.

    First run (2026-11-27, binary /work/bin/s9e, sha256 498dc9c15dde, load average 2.7 before,
    3.4-3.8 during, 2.2 after, on 2 cores shared with a CI run): 7 of 8, 106 s in all. e1
    series/contact 8.99 mOhm (truth 9), 34.93 -> 0.97 mV, 14 s; e2 electrolyte properties
    (diffusivity 0.5996x, conductivity 1.0009x), 11.73 -> 1.51 mV (noise 1.55), 2 s; e3 lithium
    inventory (negative / positive initial concentrations 17365 / 30650 mol/m3, the truth's 17363
    / 30652 at 60 % SOC of the aged cell), 34.67 -> 0.51 mV, 8 s; e4 thermal (h 7.870, truth 8;
    ambient 287.95 K), 30.49 -> 1.00 mV, 9 s; e5 kinetics (negative rate constant 1.943e-7, the
    truth's 0.3 x 6.48e-7; positive 3.424e-6, the set's), 30.86 -> 1.98 mV, 9 s; e6 the pair in
    round 1 at the truth (positive fraction 0.5986, truth 0.5985; negative particle diffusivity
    9.913e-15 m2/s, truth 9.9e-15; the others at the set's), 37.75 -> 0.97 mV, 9 s; e8 no missing
    physics (2.00 mV, noise 1.96), 1 s. Missed: e7 (54 s) named a leak of 21.1 mA (C/237)
    together with lithium inventory (negative / positive initial concentrations 3564 / 49654
    mol/m3), 20.69 -> 7.31 mV (hold-out 13.52 -> 9.61), then "unexplained" (7.31 mV, noise
    1.06; closest a +10.8 mV voltage offset); plating, partially reversible plating and SEI
    growth were not tried: "not identifiable: needs a recording over 3 or more cycles (this
    one spans 2.9 full swings of its charge)" -- three cycles in a 3.0-4.1 V window from 10 %
    SOC fall just short of the tool's gate (a design slip of this batch: a fourth cycle or the
    full window would have cleared it)."""
    cap = 5.0
    # e1: 9 mOhm contact resistance, parked urban drive (bursts with holds at rest), 20 degC, cycler artefacts, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    p.update({"Contact resistance [Ohm]": 0.009}, check_already_exists=False)
    parked = ["Rest for 5 minutes"]
    for k in range(6):
        parked += urban_drive(211 + k, 4) + ["Rest for 8 minutes"]
    write_case(root, "e1_contact_parked_urban_drive_20C_cycler_spm", lion.SPM(options={"contact resistance": "true"}), p, parked,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance"], "ambient_temperature_K": 293.15,
                "note": "9 mOhm contact resistance at 20 degC (isothermal, not recorded); from 75 % SOC: 5 min rest, 6 x (an urban "
                        "drive burst of 4 segments, to 3C with regeneration to 1.5C, about 4 min; then an 8 min hold at rest); "
                        "1 mV noise, cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution); SPM data and model"},
               initial_soc=0.75, seed=211, cycler=CYCLER, compare=lion.SPM())
    # e2: electrolyte diffusivity x0.6, ascending-rate charge staircase from 20 % SOC at 10 degC, SPMe
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.6)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    stair = ["Rest for 5 minutes"]
    for rate in ["C/3", "0.67C", "1C"]:
        stair += [f"Charge at {rate} for 5 minutes", "Rest for 5 minutes"]
    stair += ["Rest for 10 minutes"]
    write_case(root, "e2_electrolyte_diffusivity_charge_staircase_10C_spme", lion.SPMe(), p, stair,
               {"effect": "electrolyte_transport", "candidate_model": "spme", "accept": ["electrolyte"], "ambient_temperature_K": 283.15,
                "note": "electrolyte diffusivity x0.6 (all concentrations) at 10 degC (isothermal, not recorded); from 20 % SOC: 5 "
                        "min rest, a charge staircase of C/3, 0.67C and 1C for 5 min each with 5 min rests, 10 min more rest "
                        "(to about 37 % SOC; the salt in the positive electrode falls to about 140 mol/m3 in the 1C step; x0.4 "
                        "with rates to 2C, the first draft, emptied the SPMe's electrolyte); sampled every 2 s, 1.5 mV noise; SPMe data and model"},
               initial_soc=0.2, seed=212, period=2, noise=1.5e-3, compare=lion.SPMe())
    # e3: 6 % lithium loss, C/2 discharge then 1C CC-CV charge to 4.0 V from 60 % SOC, 20 degC, 0.5 mV noise, cycler artefacts, SPMe
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94)
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    steps = ["Rest for 10 minutes", "Discharge at C/2 until 2.7 V", "Rest for 30 minutes", "Charge at 1C until 4.0 V", "Hold at 4.0 V until C/10",
             "Rest for 30 minutes"]
    write_case(root, "e3_inventory_c2_then_cccv_4V_20C_cycler_spme", lion.SPMe(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 293.15,
                "note": "6 % less lithium in the negative electrode at 20 degC (isothermal, not recorded); from 60 % SOC (of the aged "
                        "cell): 10 min rest, C/2 to 2.7 V, 30 min rest, 1C CC-CV charge to 4.0 V and C/10, 30 min rest; 0.5 mV "
                        "noise, cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution); SPMe data and model"},
               initial_soc=0.6, seed=213, noise=5e-4, cycler=CYCLER, compare=lion.SPMe())
    # e4: self-heating h = 8, 2C partial discharge and 1C partial charge at 15 degC, temperature recorded, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15, "Total heat transfer coefficient [W.m-2.K-1]": 8.0})
    steps = ["Rest for 5 minutes", "Discharge at 2C for 12 minutes", "Rest for 5 minutes", "Charge at 1C for 10 minutes", "Rest for 20 minutes"]
    write_case(root, "e4_thermal_2C_partial_then_charge_15C_recorded_dfn", lion.DFN(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 288.15,
                "note": "lumped self-heating, h = 8 W/(m2 K), ambient and initial 15 degC; from full: 5 min rest, 2C for 12 min, 5 min "
                        "rest, 1C charge for 10 min, 20 min rest; temperature recorded (0.05 K noise); sampled every 3 s, 1 mV noise; "
                        "DFN data, the candidate the isothermal DFN at 15 degC"},
               initial_soc=1.0, temperature=True, seed=214, period=3, compare=lion.DFN())
    # e5: negative exchange current x0.3 only, fast random 5 s drive at low SOC, 30 degC, 2 mV noise, SPM
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.3)
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    drive = ["Rest for 5 minutes"] + drive_cycle(215, 120, -1.5, 2.5, 5) + ["Rest for 10 minutes"] + drive_cycle(216, 60, -1.5, 2.5, 5) + ["Rest for 10 minutes"]
    write_case(root, "e5_kinetics_negative_fast_drive_low_soc_30C_spm", lion.SPM(), p, drive,
               {"effect": "kinetics", "candidate_model": "spm", "accept": ["kinetic", "charge transfer", "charge-transfer", "exchange", "reaction rate"],
                "ambient_temperature_K": 303.15,
                "note": "negative exchange-current density x0.3 only (positive as set) at 30 degC (isothermal, not recorded); from "
                        "35 % SOC: 5 min rest, a random drive of 120 x 5 s steps (C-rates drawn from -1.5 to 2.5), 10 min rest, 60 "
                        "more steps, 10 min rest; sampled every 1 s, 2 mV noise; SPM data and model"},
               initial_soc=0.35, seed=215, noise=2e-3, compare=lion.SPM())
    # e6: 10 % positive LAM and negative particle diffusivity x0.3, a rate step-down discharge at 5 degC, SPMe
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.9)
    p = scaled(p, "Negative particle diffusivity [m2.s-1]", 0.3)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    steps = ["Rest for 10 minutes", "Discharge at 2C for 10 minutes", "Rest for 20 minutes", "Discharge at C/3 until 2.7 V", "Rest for 30 minutes"]
    write_case(root, "e6_lam_positive_and_diffusivity_negative_step_down_5C_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss+solid_diffusivity", "candidate_model": "spme",
                "accept": ["active material", "particle|solid diffusiv|solid-phase diffusiv"], "ambient_temperature_K": 278.15,
                "note": "10 % loss of positive active material (default initial concentrations) and negative particle diffusivity "
                        "x0.3, at 5 degC (isothermal, not recorded); from full: 10 min rest, 2C for 10 min, 20 min rest, C/3 to "
                        "2.7 V, 30 min rest; sampled every 10 s, 1 mV noise; SPMe data and model"},
               initial_soc=1.0, seed=216, period=10, compare=lion.SPMe())
    # e7: irreversible lithium plating in three 1.2C CC-CV charges at 2 degC, SPMe, 30 s sampling
    p = with_okane2022(chen(), PLATING_KEYS)
    p = scaled(p, "Lithium plating kinetic rate constant [m.s-1]", 0.4)
    p.update({"Ambient temperature [K]": 275.15, "Initial temperature [K]": 275.15})
    cycle = ("Charge at 1.2C until 4.1 V", "Hold at 4.1 V until C/10", "Rest for 20 minutes", "Discharge at 1C until 3.0 V", "Rest for 20 minutes")
    write_case(root, "e7_plating_irreversible_1p2C_charges_2C_30s_spme", lion.SPMe(options={"lithium plating": "irreversible"}), p,
               [("Rest for 5 minutes",)] + [cycle] * 3,
               {"effect": "lithium_plating", "candidate_model": "spme", "accept": ["plating"], "ambient_temperature_K": 275.15,
                "note": "irreversible lithium plating (PyBaMM 'irreversible', OKane2022's plating parameters, rate constant x0.4 = "
                        "4e-10 m/s) at 2 degC (isothermal, not recorded): 3.0 % of the lithium in the particles lost over the 3 "
                        "cycles (0.0086 mol plated), the 1C discharge capacity 3.62 -> 3.48 -> 3.41 A h. From 10 % SOC: 5 min "
                        "rest, 3 x (1.2C CC-CV charge to 4.1 V and C/10, 20 min rest, 1C to 3.0 V, 20 min rest), about 7.7 h; "
                        "sampled every 30 s, 1 mV noise; SPMe data and model"},
               initial_soc=0.1, seed=217, period=30, compare=lion.SPMe())
    # e8: control, DFN at 40 degC, 3C / 2C pulses and a 1C discharge, 2 mV noise
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    steps = ["Rest for 5 minutes", "Discharge at 3C for 2 minutes", "Rest for 10 minutes", "Charge at 2C for 1 minute", "Rest for 10 minutes",
             "Discharge at 1C until 3.2 V", "Rest for 15 minutes"]
    write_case(root, "e8_control_pulses_then_1C_40C_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 313.15,
                "note": "negative control at 40 degC (isothermal, not recorded): DFN data and model, nothing concealed. From 70 % "
                        "SOC: 5 min rest, 3C for 2 min, 10 min rest, 2C charge for 1 min, 10 min rest, 1C to 3.2 V, 15 min rest; "
                        "sampled every 3 s, 2 mV noise"},
               initial_soc=0.7, seed=218, period=3, noise=2e-3, compare=lion.DFN())


def prbs_steps(seed, bits, bit_s, high_C, low_C):
    """A pseudo-random binary sequence as experiment steps: `bits` bits of `bit_s` s, each a
    discharge at `high_C` or a charge at `low_C` (C-rates, both positive numbers) drawn with equal
    odds; equal neighbouring bits merge into one step, so every step boundary is a current step."""
    rng = np.random.default_rng(seed)
    b = rng.integers(0, 2, bits)
    steps, k = [], 0
    while k < bits:
        n = 1
        while k + n < bits and b[k + n] == b[k]:
            n += 1
        steps.append(f"Discharge at {high_C}C for {n * bit_s} seconds" if b[k] else f"Charge at {low_C}C for {n * bit_s} seconds")
        k += n
    return steps


def batch_g(root):
    """Twenty-second batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s10start before anything else): settings not used before.
    An SPMe control at 45 degC under an ascending-rate discharge staircase (C/5, C/2, 1C, then 2C
    to 2.7 V), the voltage quantised to 1 mV steps by the ADC on top of 1 mV noise; a contact
    resistance near the noise floor (3 mOhm, about 5 mV at C/3) in partial-window cycling between
    70 and 30 % SOC at C/3 (SPM, 20 degC); the one pair of the usual families no unseen batch has
    held, a 6 mOhm contact together with 7 % lithium loss, seen through a charge-only recording
    (0.5C CC-CV from empty) at 5 degC (SPMe); ageing by current-driven (throughput-driven) loss of
    negative active material over 4 full 1C cycles at 35 degC (SPM, 30 s logging); both exchange
    currents x0.4 at 0 degC in a recording that is 98 % rest (eight 20 s 2C pulses in 3.2 h; SPM,
    1 mV ADC steps); an aged electrolyte (diffusivity x0.35, conductivity x0.7) under a
    pseudo-random binary current (+1.5C / -1C, 4 s bits) with a noisy, offset-free current channel
    (25 mA) at 30 degC (DFN); a negative particle diffusivity x0.25 under a constant-resistance
    (0.75 Ohm) load discharge logged every 10 s at 15 degC (DFN); self-heating (h = 10, temperature
    recorded to 0.1 K) in a potentiostatic discharge (a 3.8 V hold from 90 % SOC, starting near
    3.6C) and a 1C charge at 25 degC (SPMe). Lithium and active-material loss are accepted only by
    their own words, as since batch r; the particle diffusivity by "particle" / "solid diffusiv"
    words only.

    First run (2026-11-27, binary /work/bin/s10start, sha256 6614a2b0d758, load average 4.6
    before, 5.3-5.6 during, 5.6 after, on cores shared with other sessions): 7 of 8, 1189 s in all.
    g1 no missing physics (1.04 mV, noise 1.05), 0 s; g2 a tie, series/contact 2.99 mOhm (truth 3)
    or kinetics, 4.58 -> 0.98 mV, 6 s; g4 progressive (stress-driven) negative LAM "about 4.2 %"
    (truth: fraction 0.75 -> 0.709, 5.5 %), 21.37 -> 3.58 mV, then a lithium-inventory stand-in
    (negative initial concentration 30263 mol/m3), 1.17 mV, 319 s; g5 named weakly, a tie of
    series/contact 7.90 mOhm (first) or kinetics (rate constants 3.11e-7 / 1.12e-6 "not
    identifiable"; truth 0.4x the set's, 2.59e-7 / 1.37e-6), 9.11 -> 1.04 mV, 13 s (the pulses
    are all at 2C: a design slip, two rates would separate them); g6 electrolyte (diffusivity
    0.3504x, conductivity 0.7003x), 13.71 -> 1.19 mV, 690 s of the judge's 900; g7 particle
    diffusivities (negative 8.248e-15 m2/s, truth 8.25e-15; positive the set's), 33.95 -> 0.99 mV,
    48 s; g8 thermal (h 9.989, ambient 298.14 K), 5.95 -> 1.02 mV, 25 s. Missed: g3 (88 s) named
    negative LAM "7 %" (fraction 0.6968; positive 0.665 on its search bound), 58.29 -> 5.61 mV
    (hold-out 70.36 -> 7.70), then "unexplained" (5.61 mV, noise 1.01; closest lithium inventory,
    dBIC 7.0, hold-out cut 3 %); the contact stayed at 1.22 mOhm in round 2 (truth 6), though the
    residual's own statistic gave 7.70 mOhm at the two current steps."""
    cap = 5.0
    adc = {"quantum_V": 1e-3, "quantum_A": 1e-4}
    # g1: control, SPMe at 45 degC, ascending-rate discharge staircase, 1 mV ADC steps
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    steps = ["Rest for 10 minutes", "Discharge at C/5 for 15 minutes", "Discharge at C/2 for 15 minutes", "Discharge at 1C for 15 minutes",
             "Discharge at 2C until 2.7 V", "Rest for 1 hour"]
    write_case(root, "g1_control_ascending_discharge_staircase_45C_1mV_adc_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 318.15,
                "note": "negative control at 45 degC (isothermal, not recorded): SPMe data and model, nothing concealed. From full: "
                        "10 min rest, an ascending-rate discharge staircase without rests (C/5, C/2 and 1C for 15 min each, then 2C to "
                        "2.7 V), 1 h rest; sampled every 2 s, 1 mV Gaussian noise, then the voltage quantised to 1 mV steps (an ADC's "
                        "resolution)"},
               initial_soc=1.0, seed=221, period=2, cycler=adc, compare=lion.SPMe())
    # g2: 3 mOhm contact resistance near the noise floor, partial-window cycling 70 -> 30 % SOC at C/3, SPM, 20 degC
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    p.update({"Contact resistance [Ohm]": 0.003}, check_already_exists=False)
    window = ["Rest for 20 minutes"] + ["Discharge at C/3 for 72 minutes", "Rest for 20 minutes", "Charge at C/3 for 72 minutes", "Rest for 20 minutes"] * 2
    write_case(root, "g2_contact_3mohm_partial_window_c3_20C_spm", lion.SPM(options={"contact resistance": "true"}), p, window,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance"], "ambient_temperature_K": 293.15,
                "note": "3 mOhm contact resistance (5 mV at C/3), near the noise floor, at 20 degC (isothermal, not recorded); from "
                        "70 % SOC: 20 min rest, 2 x (C/3 discharge for 72 min to about 30 % SOC, 20 min rest, C/3 charge for 72 min, "
                        "20 min rest); sampled every 5 s, 1 mV noise; SPM data and model"},
               initial_soc=0.7, seed=222, period=5, compare=lion.SPM())
    # g3: 6 mOhm contact and 7 % lithium loss, charge-only 0.5C CC-CV from empty, SPMe, 5 degC
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.93)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    p.update({"Contact resistance [Ohm]": 0.006}, check_already_exists=False)
    steps = ["Rest for 15 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 45 minutes"]
    write_case(root, "g3_contact_and_inventory_charge_only_from_empty_5C_spme", lion.SPMe(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance+lithium_inventory_loss", "candidate_model": "spme",
                "accept": ["contact|series resistance", "inventory|lithium loss|cyclable"], "ambient_temperature_K": 278.15,
                "note": "6 mOhm contact resistance and 7 % less lithium in the negative electrode, at 5 degC (isothermal, not "
                        "recorded); a charge-only recording from empty (0 % SOC of the aged cell): 15 min rest, 0.5C CC-CV to 4.2 V "
                        "and C/20, 45 min rest; sampled every 3 s, 1 mV noise; SPMe data and model"},
               initial_soc=0.0, seed=223, period=3, compare=lion.SPMe())
    # g4: ageing, current-driven (throughput-driven) negative LAM over 4 full 1C cycles, SPM, 35 degC, 30 s logging
    k_lam = LAM_G4
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    p.update({"Negative electrode current-driven LAM rate": lambda i, T: -k_lam * abs(i),
              "Positive electrode current-driven LAM rate": lambda i, T: 0 * i}, check_already_exists=False)
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes")
    write_case(root, "g4_lam_negative_current_driven_4_cycles_35C_30s_spm", lion.SPM(options={"loss of active material": ("current-driven", "none")}), p,
               [("Rest for 10 minutes",)] + [cycle] * 4,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"], "ambient_temperature_K": 308.15,
                "note": "progressive loss of negative active material proportional to charge throughput (PyBaMM ('current-driven', "
                        f"'none'): d eps_n/dt = -{LAM_G4:g} m2/(A s) x |i|, i the current density), fraction 0.75 -> 0.709 over "
                        "4 cycles, at 35 degC (isothermal, not recorded); a static negative LAM is its nearest stand-in. From full: 10 "
                        "min rest, 4 x (1C to 2.7 V, 20 min rest, 1C CC-CV to 4.2 V and C/20, 20 min rest); sampled every 30 s, 1 mV "
                        "noise; SPM data and model"},
               initial_soc=1.0, seed=224, period=30, compare=lion.SPM())
    # g5: both exchange currents x0.4 at 0 degC, a recording that is 98 % rest (eight 20 s 2C pulses), SPM, 1 mV ADC steps
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.4)
    p = scaled(p, "Positive electrode exchange-current density [A.m-2]", 0.4)
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    steps = ["Rest for 30 minutes"] + ["Discharge at 2C for 20 seconds", "Rest for 20 minutes", "Charge at 2C for 20 seconds", "Rest for 20 minutes"] * 4
    write_case(root, "g5_kinetics_mostly_rest_2C_pulses_0C_1mV_adc_spm", lion.SPM(), p, steps,
               {"effect": "kinetics", "candidate_model": "spm", "accept": ["kinetic", "charge transfer", "charge-transfer", "exchange", "reaction rate"],
                "ambient_temperature_K": 273.15,
                "note": "both exchange-current densities x0.4 at 0 degC (isothermal, not recorded): a large effect in a recording "
                        "that is 98 % rest. From 50 % SOC: 30 min rest, 4 x (2C discharge for 20 s, 20 min rest, 2C charge for 20 s, "
                        "20 min rest), 3.2 h; sampled every 1 s, 1 mV noise, the voltage quantised to 1 mV steps; SPM data and model"},
               initial_soc=0.5, seed=225, period=1, cycler=adc, compare=lion.SPM())
    # g6: aged electrolyte (diffusivity x0.35, conductivity x0.7), PRBS current, noisy current channel, DFN, 30 degC
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.35)
    p = scaled(p, "Electrolyte conductivity [S.m-1]", 0.7)
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    steps = ["Rest for 10 minutes"] + prbs_steps(2261, 225, 4, 1.5, 1) + ["Rest for 15 minutes"] + prbs_steps(2262, 225, 4, 1.5, 1) + ["Rest for 15 minutes"]
    write_case(root, "g6_electrolyte_aged_prbs_noisy_current_30C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 303.15,
                "note": "an aged electrolyte: diffusivity x0.35 and conductivity x0.7 (all concentrations) at 30 degC (isothermal, "
                        "not recorded); from 80 % SOC: 10 min rest, a pseudo-random binary current of 225 bits of 4 s (1.5C "
                        "discharge or 1C charge, equal odds), 15 min rest, a second such sequence, 15 min rest; sampled every 1 s, "
                        "1 mV noise; the current channel noisy but offset-free (25 mA Gaussian on the set current, 1 mA "
                        "resolution); DFN data and model"},
               initial_soc=0.8, seed=226, period=1, cycler={"current_noise_A": 0.025, "quantum_A": 1e-3, "quantum_V": 1e-4}, compare=lion.DFN())
    # g7: negative particle diffusivity x0.25, constant-resistance (0.75 Ohm) load discharge, 10 s logging, DFN, 15 degC
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.25)
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    steps = ["Rest for 10 minutes", "Discharge at 0.75 Ohm until 2.7 V", "Rest for 1 hour", "Charge at C/2 for 1 hour", "Rest for 30 minutes"]
    write_case(root, "g7_diffusivity_negative_constant_resistance_load_15C_10s_dfn", lion.DFN(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 288.15,
                "note": "negative particle diffusivity x0.25 at 15 degC (isothermal, not recorded); from full: 10 min rest, a "
                        "constant-resistance load of 0.75 Ohm to 2.7 V (about 1.1C falling to 0.7C; candidate_rmse compares the "
                        "candidate under the same load, so its current differs slightly), 1 h rest, C/2 charge for 1 h, 30 min rest; "
                        "logged every 10 s, 1 mV noise; DFN data and model"},
               initial_soc=1.0, seed=227, period=10, compare=lion.DFN())
    # g8: self-heating h = 10, potentiostatic discharge (3.8 V hold from 90 % SOC) and a 1C charge, 25 degC, temperature recorded, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 298.15, "Initial temperature [K]": 298.15, "Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    steps = ["Rest for 5 minutes", "Hold at 3.8 V for 20 minutes", "Rest for 20 minutes", "Charge at 1C until 4.1 V", "Rest for 20 minutes"]
    write_case(root, "g8_thermal_potentiostatic_discharge_25C_recorded_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 298.15,
                "note": "lumped self-heating, h = 10 W/(m2 K), ambient and initial 25 degC; from 90 % SOC: 5 min rest, a "
                        "potentiostatic discharge (3.8 V hold for 20 min; the current starts near 3.6C, 18 A, and decays; about 8 K rise), 20 min rest, 1C "
                        "charge to 4.1 V, 20 min rest; temperature recorded (0.05 K noise, 0.1 K resolution); sampled every 1 s, 1 mV "
                        "noise; SPMe data, the candidate the isothermal SPMe at 25 degC"},
               initial_soc=0.9, temperature=True, seed=228, period=1, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPMe())


LAM_G4 = 3e-8


def jittered_log(low, high, gaps=()):
    """A logger whose clock jitters: within each step the next point is the first simulated one at
    least U(`low`, `high`) s after the last logged one (from a fine simulation; a step's first and
    last points are kept, so a repeated time still marks a current step), and nothing is logged
    in `gaps`, (step index, from s, to s) after that step's start (the logger dropped out; each
    gap lies inside one step, so the current is the same on both sides of it)."""
    def keep(t, i, v, rng):
        starts = [0] + [k for k in range(1, len(t)) if t[k] - t[k - 1] < 1e-6] + [len(t)]
        mask = np.zeros(len(t), dtype=bool)
        for step, (a, b) in enumerate(zip(starts[:-1], starts[1:])):
            mask[a] = mask[b - 1] = True
            target = t[a] + rng.uniform(low, high)
            for k in range(a + 1, b - 1):
                if t[k] >= target - 1e-9:
                    mask[k] = True
                    target = t[k] + rng.uniform(low, high)
            for g_step, g_from, g_to in gaps:
                if g_step == step:
                    mask[a:b] &= ~((t[a:b] > t[a] + g_from) & (t[a:b] < t[a] + g_to))
        return mask
    return keep


def batch_d(root):
    """Twenty-third batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s11start before anything else): the Chen 2020 cell in
    settings not used before, at ambients not used before (3, 13, 17, 23, 27, 33, 37, 48 degC).
    A control (SPMe at 27 degC) under the USABC DST at high SOC only, logged by a logger whose
    clock jitters (0.6-1.4 s between points) and that dropped out twice; a pair not used before,
    both exchange currents x0.3 with a +-18 mV one-state hysteresis of the negative OCP, under a
    mixed-rate HPPC (C/2 to 3C in shuffled order at four levels, rests after charge and
    discharge) at 48 degC (SPMe); 11 % lithium loss in a recording exported from part-way
    through a test (it starts under load right after an unrecorded 1C discharge, the particles
    not relaxed) at 23 degC (SPM); a small (4 %) positive LAM in a slow C/25 cycle logged every
    60 s at 17 degC (SPM; the capacity changes by 0.13 %, the OCP alignment by 12 mV RMS); a
    large contact resistance (25 mOhm) seen in a 2C / 1C pulse train after a 12 h storage rest
    logged every 5 min, at 3 degC (DFN); a positive particle diffusivity x0.5 in a GITT at low
    SOC only (25 -> 2 %) at 13 degC, a small effect (3.0 mV RMS; SPMe); an electrolyte
    diffusivity x0.45 under 3C / 1.5C bursts of 40 s with C/2 segments at 33 degC (DFN);
    self-heating of a poorly cooled cell (h = 4, to about 62 degC) at 37 degC, the temperature
    recorded by a thermocouple reading 0.8 K high (DFN). Lithium and active-material loss are
    accepted only by their own words, as since batch r; the particle diffusivity by "particle" /
    "solid diffusiv" words.

    First run (2026-11-27, binary /work/bin/s11start, sha256 857fc9f8857c, load average 2.3
    before, 3.3-3.7 during, 3.4 after, on 2 cores shared with other sessions): 8 of 8, 173 s in
    all. d1 no missing physics (0.99 mV, noise 0.99; the 602 s gap reported and bridged by a
    linear current), 1 s; d2 the pair in round 1 at the truth (rate constants 1.938e-7 /
    1.035e-6, the truth's 0.3x being 1.944e-7 / 1.026e-6; hysteresis 18.29 mV, truth 18), 28.50
    -> 0.99 mV, 45 s; d3 lithium inventory (initial concentrations 12680 / 34938 mol/m3, the
    truth's volume averages at the recording's start 12672 / 34716), 56.25 -> 7.99 mV, then
    "unexplained structure in 0-450 s" (7.99 mV, noise 1.09: the unrelaxed start; closest
    series/contact, dBIC -1.1), 5 s; d4 positive LAM "4 %" (fraction 0.6384, the truth; negative
    0.75 on its bound), 10.77 -> 1.00 mV, 2 s; d5 series/contact 25.00 mOhm (truth 25), 61.88 ->
    1.04 mV, 104 s; d6 particle diffusivities (positive 2.002e-15 m2/s, truth 2.0e-15; negative
    3.296e-14, the set's 3.3e-14), 2.56 -> 0.99 mV, 3 s; d7 electrolyte properties (diffusivity
    0.4498x, conductivity 1.001x), 12.82 -> 0.97 mV, 5 s; d8 thermal (h 3.874, truth 4; ambient
    310.63 K, between the true 310.15 and the thermocouple's 310.95), 19.73 -> 1.33 mV, then
    "unexplained" (1.33 mV, noise 0.97; closest an RC of 0.75 s, under the 2 s sampling), 8 s."""
    # d1: control, SPMe at 27 degC, the USABC DST at high SOC only, a jittering logger clock with two drop-outs
    p = chen()
    p.update({"Ambient temperature [K]": 300.15, "Initial temperature [K]": 300.15})
    steps = ["Rest for 10 minutes"] + dst_steps(2.0) * 4 + ["Rest for 20 minutes", "Discharge at C/2 for 20 minutes", "Rest for 30 minutes"]
    write_case(root, "d1_control_dst_high_soc_jittered_clock_log_gaps_27C_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 300.15,
                "note": "negative control at 27 degC (isothermal, not recorded): SPMe data and model, nothing concealed. From 92 % SOC: 10 "
                        "min rest, 4 x the USABC Dynamic Stress Test (360 s, peak discharge 2C, regeneration to 1C, mean 0.27C: high SOC "
                        "only, about 92 -> 81 %), 20 min rest, C/2 for 20 min (to about 65 %), 30 min rest. A logger whose clock jitters: "
                        "0.6-1.4 s between points (uniform, taken from a 0.1 s simulation; a step's first and last points kept, a current "
                        "step still a repeated time), and that dropped out twice (no points 4-14 min into the 20 min rest, 5-13 min into "
                        "the C/2 discharge; the current is the same on both sides of each gap); 1 mV noise"},
               initial_soc=0.92, seed=231, period=0.1, keep=jittered_log(0.6, 1.4, gaps=[(81, 240.0, 840.0), (82, 300.0, 780.0)]),
               sampling="jittered: 0.6-1.4 s between points (uniform, on a 0.1 s simulation), no points 4-14 min into the 20 min rest "
                        "and 5-13 min into the C/2 discharge",
               compare=lion.SPMe())
    # d2: pair, exchange currents x0.3 and negative OCP hysteresis +-18 mV, mixed-rate HPPC at 48 degC, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 321.15, "Initial temperature [K]": 321.15})
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.3)
    with_negative_hysteresis(p, 0.018)
    def level(rates):
        block = []
        for rate in rates:
            block += [f"Discharge at {rate}C for 10 seconds", "Rest for 40 seconds", f"Charge at {0.75 * rate:g}C for 10 seconds", "Rest for 2 minutes"]
        return block
    steps = (["Rest for 10 minutes"] + level([2, 0.5, 3, 1]) + ["Discharge at C/2 for 12 minutes", "Rest for 30 minutes"]
             + level([1, 3, 0.5, 2]) + ["Discharge at C/2 for 12 minutes", "Rest for 30 minutes"] + level([0.5, 2, 1, 3])
             + ["Charge at C/2 for 24 minutes", "Rest for 30 minutes"] + level([3, 1, 2, 0.5]) + ["Rest for 10 minutes"])
    write_case(root, "d2_kinetics_and_hysteresis_mixed_rate_hppc_48C_spme",
               lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "kinetics+hysteresis", "candidate_model": "spme",
                "accept": ["kinetic|exchange|charge-transfer|charge transfer|reaction rate", "hysteresis"], "ambient_temperature_K": 321.15,
                "note": "exchange-current densities x0.3 in both electrodes and one-state hysteresis of the negative OCP, +-18 mV (decay "
                        "rate 10, initial state 0), at 48 degC (isothermal, not recorded). A mixed-rate HPPC from 60 % SOC: 10 min rest, "
                        "then at each of four levels pulses at four rates in a different order each time (C/2, 1C, 2C, 3C: discharge 10 s, "
                        "40 s rest, charge at 0.75x the rate 10 s, 2 min rest), C/2 for 12 min and 30 min rest after the first two levels "
                        "(to about 50 and 40 % SOC), a C/2 charge for 24 min and 30 min rest after the third (back to about 58 %), the "
                        "fourth level, 10 min rest; 3.4 h, sampled every 2 s, 1 mV noise; SPMe (one-state hysteresis) data. Each effect "
                        "alone moves the SPMe by 27.5 mV (kinetics) and 9.5 mV (hysteresis) RMS on this protocol, both together 29.2 mV"},
               initial_soc=0.6, seed=232, period=2, compare=lion.SPMe())
    # d3: 11 % lithium loss, the recording starts part-way (after an unrecorded 1C discharge, no rest), SPM at 23 degC
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.89)
    p.update({"Ambient temperature [K]": 296.15, "Initial temperature [K]": 296.15})
    steps = ["Discharge at 1C for 30 minutes", "Discharge at C/3 until 2.7 V", "Rest for 45 minutes", "Charge at C/2 for 50 minutes", "Rest for 30 minutes"]
    write_case(root, "d3_inventory_11pct_unrelaxed_mid_protocol_start_23C_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 296.15,
                "note": "11 % less lithium in the negative electrode (initial concentration x0.89), at 23 degC (isothermal, not recorded). "
                        "A recording exported from part-way through a test: the cell was discharged from full at 1C for 30 min (not "
                        "recorded) and the recording starts with the next step, no rest between, so the particles are not relaxed at t = 0 "
                        "(the first point is under load, 3.619 V, rising over the first minutes as the 1C gradients relax under C/3): C/3 "
                        "to 2.7 V, 45 min rest, C/2 charge for 50 min, 30 min rest; sampled every 15 s, 1 mV noise; SPM data and model. "
                        "candidate_rmse runs the nominal SPM through the same unrecorded 1C discharge (most of its 258.7 mV is the earlier "
                        "cut-off); computed when the case was made, with its initial SOC fitted from a relaxed start, the nominal SPM "
                        "leaves 56.2 mV RMS, and the true (aged) SPM started relaxed leaves 8.3 mV: what the unrelaxed start alone does"},
               initial_soc=1.0, seed=233, period=15, skip_steps=1, compare=lion.SPM())
    # d4: 4 % positive LAM in a C/25 cycle logged every 60 s, SPM at 17 degC
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.96)
    p.update({"Ambient temperature [K]": 290.15, "Initial temperature [K]": 290.15})
    steps = ["Rest for 1 hour", "Discharge at C/25 until 2.7 V", "Rest for 2 hours", "Charge at C/25 until 4.2 V", "Rest for 2 hours"]
    write_case(root, "d4_lam_positive_4pct_c25_cycle_60s_log_17C_spm", lion.SPM(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"], "ambient_temperature_K": 290.15,
                "note": "4 % loss of positive active material (fraction 0.665 -> 0.6384; initial state set as 100 % SOC of the aged cell), "
                        "at 17 degC (isothermal, not recorded). A slow C/25 cycle from full: 1 h rest, C/25 to 2.7 V, 2 h rest, C/25 "
                        "charge to 4.2 V (no hold), 2 h rest, 55.6 h in all, logged every 60 s, 1 mV noise; SPM data and model. The "
                        "capacity barely changes (the run is 265 s, 0.13 %, shorter than the candidate's): the loss shows as a shift of "
                        "the electrodes' OCPs against each other, 4-17 mV RMS in each eighth of the record, 11.9 mV in all"},
               initial_soc=1.0, seed=234, period=60, compare=lion.SPM())
    # d5: 25 mOhm contact, a 12 h storage rest logged every 5 min, then a 2C / 1C pulse train, DFN at 3 degC
    p = chen()
    p.update({"Ambient temperature [K]": 276.15, "Initial temperature [K]": 276.15})
    p.update({"Contact resistance [Ohm]": 0.025}, check_already_exists=False)
    train = ["Discharge at 2C for 5 seconds", "Rest for 15 seconds", "Charge at 1C for 5 seconds", "Rest for 15 seconds"]
    steps = ["Rest for 12 hours (5 minute period)"] + train * 30 + ["Rest for 20 minutes"]
    write_case(root, "d5_contact_25mohm_storage_rest_then_pulse_train_3C_dfn", lion.DFN(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "dfn", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 276.15,
                "note": "25 mOhm contact resistance (large: 250 mV at 2C), at 3 degC (isothermal, not recorded). From 50 % SOC: a 12 h "
                        "storage rest logged every 5 min, then a pulse train of 30 x (2C discharge 5 s, 15 s rest, 1C charge 5 s, 15 s "
                        "rest) and a 20 min rest logged every 1 s; 1 mV noise; DFN data and model"},
               initial_soc=0.5, seed=235, period=1, sampling="5 min in the 12 h storage rest, then 1 s", compare=lion.DFN())
    # d6: positive particle diffusivity x0.5, GITT at low SOC (25 % to about 2 %), SPMe at 13 degC
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.5)
    p.update({"Ambient temperature [K]": 286.15, "Initial temperature [K]": 286.15})
    steps = ["Rest for 30 minutes"] + ["Discharge at C/4 for 6 minutes or until 2.7 V", "Rest for 30 minutes"] * 9
    write_case(root, "d6_diffusivity_positive_gitt_low_soc_13C_spme", lion.SPMe(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 286.15,
                "note": "positive particle diffusivity x0.5, at 13 degC (isothermal, not recorded): a GITT at low SOC only, from 25 % SOC: "
                        "30 min rest, 9 x (C/4 for 6 min, 30 min rest) down to about 2 % SOC (the lowest voltage 2.83 V); 5.9 h, sampled "
                        "every 2 s, 1 mV noise; SPMe data and model. A small effect, 3.0 mV RMS, spread over the whole record (2.6-3.7 mV "
                        "in each eighth), much of it the slower relaxation in the rests"},
               initial_soc=0.25, seed=236, period=2, compare=lion.SPMe())
    # d7: electrolyte diffusivity x0.45, 3C discharge bursts and 1.5C charge bursts with C/2 segments, DFN at 33 degC
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.45)
    p.update({"Ambient temperature [K]": 306.15, "Initial temperature [K]": 306.15})
    steps = ["Rest for 5 minutes"] + ["Discharge at 3C for 40 seconds", "Rest for 6 minutes", "Charge at 1.5C for 40 seconds", "Rest for 6 minutes",
                                      "Discharge at C/2 for 8 minutes", "Rest for 6 minutes"] * 2
    write_case(root, "d7_electrolyte_diffusivity_3C_bursts_33C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 306.15,
                "note": "electrolyte diffusivity x0.45 (all concentrations), at 33 degC (isothermal, not recorded). From 70 % SOC: 5 min "
                        "rest, 2 x (3C discharge for 40 s, 6 min rest, 1.5C charge for 40 s, 6 min rest, C/2 for 8 min, 6 min rest); an "
                        "hour, sampled every 2 s, 1 mV noise; DFN data and model"},
               initial_soc=0.7, seed=237, period=2, compare=lion.DFN())
    # d8: self-heating h = 4 at 37 degC, temperature recorded by a thermocouple reading 0.8 K high, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 310.15, "Initial temperature [K]": 310.15, "Total heat transfer coefficient [W.m-2.K-1]": 4.0})
    steps = ["Rest for 5 minutes", "Discharge at 1.5C for 20 minutes", "Rest for 10 minutes", "Charge at 1C for 15 minutes", "Rest for 10 minutes"]
    write_case(root, "d8_thermal_h4_37C_thermocouple_offset_recorded_dfn", lion.DFN(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 310.15,
                "note": "lumped self-heating of a poorly cooled cell, h = 4 W/(m2 K), ambient and initial 37 degC. From 90 % SOC: 5 min "
                        "rest, 1.5C for 20 min, 10 min rest, 1C charge for 15 min, 10 min rest (the cell warms to about 62 degC); "
                        "temperature recorded by a thermocouple reading 0.8 K high (a calibration offset: the recorded temperature starts "
                        "near 310.95 K against the 310.15 K ambient; 0.05 K noise, 0.1 K resolution); sampled every 2 s, 1 mV noise; DFN "
                        "data, the candidate the isothermal DFN at 37 degC"},
               initial_soc=0.9, temperature=True, temp_offset_K=0.8, seed=238, period=2,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.DFN())


def batch_c(root):
    """Twenty-fourth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s11b before anything else), harder than batch d (8/8,
    every effect fitted almost exactly): three ageing recordings with laws or settings not used
    before, three pairs of families never paired before, DFN data handed to the SPM, a current
    channel out of calibration in a recording that starts unrelaxed, and a cold DFN control. The
    Chen 2020 cell throughout. SEI growth limited by electron migration through the film
    together with a 4 mOhm contact resistance over 4 CC-CV cycles at 43 degC (SPM); current-driven
    (throughput-driven) loss of POSITIVE active material over 6 partial-window 1C cycles at 8 degC,
    1.5 mV noise (SPM); partially reversible lithium plating in a charge-rate ladder (1C, 1.5C,
    2C, 2C CC-CV charges) at 10 degC, cycler artefacts (SPMe); one-state hysteresis of the
    negative OCP (+-12 mV) together with self-heating (h = 10, temperature recorded) in 1.5C / 1C
    partial cycles at 14 degC (SPMe); a positive particle diffusivity x0.3 in a C/2 GITT at 26
    degC, DFN data handed to the SPM (whose own error there is 12.7 mV RMS against the effect's
    30.2), 2 mV noise; a current channel reading 10 mA high together with 8 % positive LAM in a
    reference performance test with 2 h rests at 19 degC, exported from the end of an unrecorded
    CC-CV charge (not relaxed at t = 0), cycler artefacts (SPMe); an electrolyte diffusivity
    x0.5 together with 7 % negative LAM under 2C / 1.5C pulses and a 0.7C discharge at 31 degC
    (DFN); a DFN control at -5 degC under a fast random drive (10 s steps from 1C charge to 2.5C
    discharge). Lithium and active-material loss are accepted only by their own words, as since
    batch r (SEI growth also by a lithium-inventory stand-in, as in k7 and j5; plating only by
    "plating"); the particle diffusivity by "particle" / "solid diffusiv" words; the current
    offset by the words an engineer would use for it (a leak, self-discharge, a current offset or
    the current sensor / channel). Each effect moves the voltage by 8.9 mV RMS or more on its own
    (PyBaMM replays of the recorded current, in each note); the experiment-based effect_rmse_mV
    of the ageing cases also holds the shifted cut-offs.

    First run (2026-11-27, binary /work/bin/s11b, sha256 8a13655a8b08, load average 3.1 before,
    3.7-5.5 during, 5.5 after, on 2 cores shared with other sessions): 8 of 8 by the judge, 609 s
    in all. c2 progressive (current-driven) positive LAM "about 8.7 %" (rate 3.459e-8 m2/(A s),
    truth 3.5e-8, 8.8 %), 14.41 -> 1.50 mV (noise 1.50), 45 s; c3 partially reversible plating
    (rate constant 9.734e-10 m/s, truth 1e-9; dead-lithium decay 2.884e-5 1/s, truth 3e-5), 8.03
    -> 1.05 mV, 156 s; c4 the pair in round 1 (h 9.548, truth 10; ambient 286.88 K, truth
    287.15; hysteresis 11.92 mV, truth 12), 14.45 -> 1.02 mV, 34 s; c5 particle diffusivity
    together with electrolyte transport (SPM -> DFN) (positive 1.199e-15 m2/s, truth 1.2e-15;
    negative 3.364e-14, the set's 3.3e-14), 27.55 -> 1.99 mV (noise 2.07), 28 s; c7 the pair in
    round 1 at the truth (negative fraction 0.6975; electrolyte diffusivity 0.5002x, conductivity
    0.9987x), 36.37 -> 1.00 mV, 55 s; c8 no missing physics (1.01 mV, noise 1.02), 2 s. c6 the
    pair in round 1 (positive fraction 0.6104, truth 0.6118; a leak of 9.4 mA charging the cell,
    the truth's offset being 10 mA), 22.48 -> 2.00 mV (noise 1.02), then "no missing physics"
    though 55 % of the remaining square error lies at 0-210 s (mean -8.09 mV: the unrelaxed start
    after the unrecorded CV hold), 27 s. c1 passed weakly, on the rounds together: round 1 a tie
    of series/contact 7.30 mOhm (truth 4) or OCV hysteresis 30.89 mV (none concealed), 38.06 ->
    19.92 mV, no pair listed; round 2 a tie of progressive negative LAM "about 6.1 %" (none
    concealed) or reaction-limited SEI, 6.29 mV; round 3 SEI (exchange current 1.326e-5 A/m2),
    the contact refitted to 6.44 mOhm, 5.03 mV against 1.06 mV of noise (55 % of it at the end of
    the last discharge) when the rounds ran out; 262 s."""
    cap = 5.0
    # c1: SEI growth limited by electron migration through the film, with a 4 mOhm contact resistance, 4 CC-CV cycles at 43 degC, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 316.15, "Initial temperature [K]": 316.15})
    p = scaled(p, "SEI electron conductivity [S.m-1]", 8000.0)
    p.update({"Contact resistance [Ohm]": 0.004}, check_already_exists=False)
    cycle = ("Discharge at 1C until 2.7 V", "Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 10 minutes")
    write_case(root, "c1_sei_electron_migration_and_contact_4_cycles_43C_spm",
               lion.SPM(options={"SEI": "electron-migration limited", "contact resistance": "true"}), p, [("Rest for 10 minutes",)] + [cycle] * 4,
               {"effect": "sei_growth+contact_resistance", "candidate_model": "spm",
                "accept": ["SEI|inventory|lithium loss|cyclable", "contact|series resistance"], "ambient_temperature_K": 316.15,
                "note": "SEI growth limited by electron migration through the film (PyBaMM 'electron-migration limited', distributed "
                        "film resistance; a growth law no earlier batch used), SEI electron conductivity 7.16e-10 S/m (8000x Chen "
                        "2020's 8.95e-14: an accelerated test at 43 degC; isothermal, not recorded): 0.0053 mol of lithium lost to "
                        "the SEI over the 4 cycles (0.14 A h, 2.8 % of the nominal capacity), discharge capacities 4.91, 4.75, "
                        "4.72, 4.70 A h; together with a 4 mOhm contact resistance (20 mV at 1C), the same throughout. A "
                        "lithium-inventory loss growing through the recording is the SEI's nearest stand-in and is accepted. "
                        "From full: 10 min rest, 4 x (1C to 2.7 V, 10 min rest, 1C CC-CV to 4.2 V and C/10, 10 min rest), "
                        "10.4 h; sampled every 20 s, 1 mV noise; SPM data and model. Replaying the recorded current (noise-free, "
                        "from full), PyBaMM's nominal SPM is 43.8 mV RMS off, the SPM with the contact alone (SEI missing) "
                        "34.0 mV, the SPM with the SEI alone (contact missing) 16.7 mV"},
               initial_soc=1.0, seed=241, period=20, compare=lion.SPM())
    # c2: current-driven (throughput-driven) loss of positive active material, 6 partial-window 1C cycles at 8 degC, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 281.15, "Initial temperature [K]": 281.15})
    p.update({"Negative electrode current-driven LAM rate": lambda i, T: 0 * i,
              "Positive electrode current-driven LAM rate": lambda i, T: -3.5e-8 * abs(i)}, check_already_exists=False)
    cycle = ("Discharge at 1C for 48 minutes", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes")
    write_case(root, "c2_lam_positive_current_driven_6_partial_cycles_8C_spm", lion.SPM(options={"loss of active material": ("none", "current-driven")}), p,
               [("Rest for 10 minutes",)] + [cycle] * 6,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"], "ambient_temperature_K": 281.15,
                "note": "progressive loss of POSITIVE active material in proportion to the charge throughput (PyBaMM ('none', "
                        "'current-driven'): d eps_p/dt = -3.5e-8 m2/(A s) x |i|, i the current density; the negative none), "
                        "positive fraction 0.665 -> 0.6066 over the 6 cycles (8.8 %), 0.0149 mol of lithium lost with it; at 8 "
                        "degC (isothermal, not recorded); a static positive LAM is its nearest stand-in. Partial-window cycling "
                        "that never reaches the lower cut-off: from full, 10 min rest, 6 x (1C for 48 min (80 % of the nominal "
                        "capacity), 15 min rest, 1C CC-CV to 4.2 V and C/10, 15 min rest), 15.3 h (4.8 full swings of "
                        "charge); the end-of-discharge voltage falls 3.292 -> 3.187 V over the six cycles; sampled every 30 s, "
                        "1.5 mV noise; SPM data and model. Replaying the recorded current from full, PyBaMM's nominal SPM is "
                        "14.5 mV RMS off"},
               initial_soc=1.0, seed=242, noise=1.5e-3, period=30, compare=lion.SPM())
    # c3: partially reversible plating in a charge-rate ladder (1C, 1.5C, 2C, 2C CC-CV) at 10 degC, SPMe, cycler artefacts
    p = with_okane2022(chen(), PLATING_KEYS)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15, "Dead lithium decay constant [s-1]": 3e-5})
    steps = [("Rest for 10 minutes",)]
    for rate in ["1C", "1.5C", "2C", "2C"]:
        steps.append(("Discharge at 1C until 2.7 V", "Rest for 20 minutes", f"Charge at {rate} until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 40 minutes"))
    write_case(root, "c3_plating_partially_reversible_charge_rate_ladder_10C_cycler_spme", lion.SPMe(options={"lithium plating": "partially reversible"}), p,
               steps,
               {"effect": "lithium_plating", "candidate_model": "spme", "accept": ["plating"], "ambient_temperature_K": 283.15,
                "note": "partially reversible lithium plating (PyBaMM 'partially reversible', OKane2022's plating parameters: rate "
                        "constant 1e-9 m/s, transfer coefficient 0.65; dead-lithium decay constant 3e-5 1/s) at 10 degC "
                        "(isothermal, not recorded), in a charge-rate ladder: CC-CV charges at 1C, 1.5C, 2C and 2C to 4.2 V and "
                        "C/20 (the CC stage lasts 37, 20, 10 and 10 min), each followed by a 40 min rest. The lithium plated "
                        "(with the dead) peaks at 0.0036, 0.0045, 0.0073 and 0.0079 mol in the four charges, most of it stripped "
                        "in the rest after (the stripping plateau); 0.0025 mol is left dead at the end; discharge capacities "
                        "4.896, 4.787, 4.776, 4.759 A h. From full: 10 min rest, 4 x (1C to 2.7 V, 20 min rest, the charge, 40 "
                        "min rest), 14.4 h; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution), 1 mV "
                        "noise; SPMe data and model. Replaying the recorded current from full, PyBaMM's nominal SPMe is 7.8 mV "
                        "RMS off (12.0 mV in the rests, 5.2 mV under load); effect_rmse_mV compares the experiment, whose "
                        "cut-offs fall at other times"},
               initial_soc=1.0, seed=243, cycler=CYCLER, compare=lion.SPMe())
    # c4: one-state hysteresis of the negative OCP with lumped self-heating, temperature recorded, SPMe at 14 degC
    p = chen()
    p.update({"Ambient temperature [K]": 287.15, "Initial temperature [K]": 287.15, "Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    with_negative_hysteresis(p, 0.012)
    cycle = ["Discharge at 1.5C for 15 minutes", "Rest for 30 minutes", "Charge at 1C for 15 minutes", "Rest for 30 minutes"]
    write_case(root, "c4_hysteresis_and_thermal_partial_cycles_14C_recorded_spme",
               lion.SPMe(options={"thermal": "lumped", "open-circuit potential": ("one-state hysteresis", "single")}), p, ["Rest for 10 minutes"] + cycle * 3,
               {"effect": "hysteresis+thermal", "candidate_model": "spme", "accept": ["hysteresis", "thermal|heat|self-heating"],
                "ambient_temperature_K": 287.15,
                "note": "one-state hysteresis of the negative OCP, +-12 mV (decay rate 10, initial state 0), together with lumped "
                        "self-heating, h = 10 W/(m2 K), at 14 degC (the cell warms by up to 21 K in each 1.5C step and cools in "
                        "the rests); temperature recorded (0.05 K noise, 0.1 K resolution). From 80 % SOC: 10 min rest, 3 x (1.5C "
                        "for 15 min, 30 min rest, 1C charge for 15 min, 30 min rest), 4.7 h (rests after both charge and "
                        "discharge); sampled every 2 s, 1 mV noise; SPMe data, the candidate the isothermal SPMe without "
                        "hysteresis. Replaying the recorded current from 80 %, PyBaMM's nominal SPMe is 15.4 mV RMS off, the SPMe "
                        "with the hysteresis alone (thermal missing) 15.2 mV, the thermal SPMe alone (hysteresis missing) 8.9 mV"},
               initial_soc=0.8, temperature=True, seed=244, period=2, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.SPMe())
    # c5: positive particle diffusivity x0.3, C/2 GITT at 26 degC, DFN data handed to the SPM, 2 mV noise
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.3)
    p.update({"Ambient temperature [K]": 299.15, "Initial temperature [K]": 299.15})
    write_case(root, "c5_diffusivity_positive_gitt_26C_dfn_data_spm", lion.DFN(), p,
               ["Rest for 10 minutes"] + ["Discharge at C/2 for 10 minutes", "Rest for 30 minutes"] * 8,
               {"effect": "solid_diffusivity", "candidate_model": "spm", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 299.15,
                "note": "positive particle diffusivity x0.3 (1.2e-15 m2/s instead of 4e-15), DFN data handed to the SPM; at 26 degC "
                        "(isothermal, not recorded). From full: 10 min rest, a C/2 GITT of 8 x (C/2 for 10 min, 30 min rest) down "
                        "to about 33 % SOC, 5.5 h; sampled every 5 s, 2 mV noise. Replaying the recorded current from full, "
                        "PyBaMM's DFN with the set's diffusivity is 30.2 mV RMS off (the effect), the SPM with the set's 40.4 mV, "
                        "the SPM with the concealed diffusivity 12.7 mV (the SPM's own error, the electrolyte's polarisation in "
                        "the pulses), the SPMe with it 0.9 mV. One concealed effect: a first verdict must name the particle "
                        "diffusivity; electrolyte transport (SPM -> SPMe or DFN) beside it is right too, any other partner is a "
                        "stand-in for the SPM's error"},
               initial_soc=1.0, seed=245, noise=2e-3, period=5, compare=lion.SPM())
    # c6: the current channel reads 10 mA high and 8 % positive LAM; an RPT with 2 h rests exported from the end of a CC-CV charge; SPMe at 19 degC
    off = 0.010
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    p.update({"Ambient temperature [K]": 292.15, "Initial temperature [K]": 292.15})
    seen = ["Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour", "Discharge at C/3 for 2 hours", "Rest for 2 hours",
            "Discharge at C/3 until 2.7 V", "Rest for 2 hours", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 2 hours"]
    inside = [f"Charge at {cap / 3 + off:.5f} A until 4.2 V", f"Hold at 4.2 V until {1000 * (cap / 20 + off):.1f} mA", "Rest for 1 hour",
              f"Discharge at {cap / 3 - off:.5f} A for 2 hours", "Rest for 2 hours", f"Discharge at {cap / 3 - off:.5f} A until 2.7 V", "Rest for 2 hours",
              f"Charge at {cap / 3 + off:.5f} A until 4.2 V", f"Hold at 4.2 V until {1000 * (cap / 20 + off):.1f} mA", "Rest for 2 hours"]
    write_case(root, "c6_current_offset_10mA_and_lam_positive_rpt_unrelaxed_start_19C_cycler_spme", lion.SPMe(), p, inside,
               {"effect": "current_offset+active_material_loss", "candidate_model": "spme",
                "accept": ["current offset|current bias|current sensor|current channel|current measurement|leak|self-discharge|self discharge",
                           "active material"],
                "ambient_temperature_K": 292.15,
                "note": "the cycler's current channel reads 10 mA high (an offset: it records 10 mA of discharge when no current "
                        "flows) and the cycler regulates on its own reading, so the cell carries 1.6567 A when C/3 (1.6667 A) is "
                        "set and recorded in discharge, 1.6767 A in charge, nothing at rest (10 mA recorded), and a CV hold ends "
                        "at 260 mA true (250 mA recorded): the coulomb count drifts by 0.13 A h (2.6 %) over the 13.2 h; together "
                        "with 8 % loss of positive active material (fraction 0.665 -> 0.6118, default initial concentrations). "
                        "A reference performance test at 19 degC (isothermal, not recorded) exported from the end of the CC-CV "
                        "charge before it (from 50 % SOC, C/3 to 4.2 V and C/20, not recorded): the recording starts at the end "
                        "of the CV hold, the particles not relaxed, then 1 h rest, C/3 for 2 h, 2 h rest, C/3 to 2.7 V, 2 h rest, "
                        "C/3 CC-CV to 4.2 V and C/20, 2 h rest; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution), 1 mV noise; SPMe data and model. With the initial SOC fitted, PyBaMM's SPMe replaying the "
                        "recording is 23.2 mV RMS off (nominal, recorded current), 12.0 mV with the LAM but the recorded current "
                        "(offset missing), 18.4 mV nominal with the true current (LAM missing), and 0.67 mV when the true model "
                        "starts relaxed (what the unrelaxed start alone does). A current offset is a leak of the opposite sign "
                        "(the cell carries the recorded current less 10 mA); compare_steps is the protocol as set"},
               initial_soc=0.5, seed=246, cycler=CYCLER, compare=lion.SPMe(), leak_A=-off, compare_steps=seen, skip_steps=2)
    # c7: electrolyte diffusivity x0.5 and 7 % negative LAM, 2C / 1.5C pulses then 0.7C to 2.8 V, DFN at 31 degC
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.5)
    p = scaled(p, "Negative electrode active material volume fraction", 0.93)
    p.update({"Ambient temperature [K]": 304.15, "Initial temperature [K]": 304.15})
    steps = (["Rest for 5 minutes"] + ["Discharge at 2C for 30 seconds", "Rest for 4 minutes", "Charge at 1.5C for 30 seconds", "Rest for 4 minutes"] * 3
             + ["Discharge at 0.7C until 2.8 V", "Rest for 15 minutes"])
    write_case(root, "c7_electrolyte_diffusivity_and_lam_negative_pulses_31C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport+active_material_loss", "candidate_model": "dfn", "accept": ["electrolyte", "active material"],
                "ambient_temperature_K": 304.15,
                "note": "electrolyte diffusivity x0.5 and 7 % loss of negative active material (fraction 0.75 -> 0.6975, default "
                        "initial concentrations), at 31 degC (isothermal, not recorded). From 50 % SOC: 5 min rest, 3 x (2C for "
                        "30 s, 4 min rest, 1.5C charge for 30 s, 4 min rest), 0.7C to 2.8 V (36 min), 15 min rest, 1.4 h (the "
                        "electrolyte stays above 300 mol/m3); sampled every 2 s, 1 mV noise; DFN data and model. Replaying the "
                        "recorded current from 50 %, PyBaMM's nominal DFN is 65.7 mV RMS off, the DFN with the electrolyte alone "
                        "(LAM missing) 58.1 mV, with the LAM alone (electrolyte missing) 22.4 mV"},
               initial_soc=0.5, seed=247, period=2, compare=lion.DFN())
    # c8: control, DFN at -5 degC, a fast random drive (10 s steps, 1C charge to 2.5C discharge)
    p = chen()
    p.update({"Ambient temperature [K]": 268.15, "Initial temperature [K]": 268.15})
    steps = ["Rest for 15 minutes"] + drive_cycle(248, 180, -1.0, 2.5, 10) + ["Rest for 20 minutes"]
    write_case(root, "c8_control_fast_random_drive_minus5C_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 268.15,
                "note": "negative control at -5 degC (isothermal, not recorded): DFN data and model, nothing concealed. From 75 % SOC: "
                        "15 min rest, a fast random drive of 180 steps of 10 s, each a C-rate drawn uniformly from 1C charge to 2.5C "
                        "discharge (30 min, net 1.9 A h out, to about 37 % SOC; the voltage swings between 3.25 and 4.15 V), 20 min "
                        "rest; sampled every 1 s, 1 mV noise; 3 mA current noise, 0.1 mA and 0.1 mV resolution"},
               initial_soc=0.75, seed=248, period=1, cycler={"current_noise_A": 3e-3, "quantum_A": 1e-4, "quantum_V": 1e-4}, compare=lion.DFN())



def batch_a(root):
    """Twenty-fifth batch, made blind (a helper session that did not read the diagnosis code,
    judged once on the binary /work/bin/s12start before anything else), harder than batch c in
    other ways: an SEI law no batch used, a pair whose smaller member is near the noise, a
    concealed kinetic effect in a real-world drive, a voltage channel out of calibration by a
    gain (not an offset), DFN data handed to the SPMe, 2.5 mV noise, and a control at -10 degC,
    the coldest ambient of any batch. The Chen 2020 cell throughout. SEI growth limited by the
    EC reaction with EC diffusion through the film (PyBaMM "ec reaction limited", both limits
    active) over 5 CC-CV cycles with rests at 40 degC (SPMe); a negative OCP hysteresis of +-10
    mV together with an electrolyte diffusivity x0.5 in a day of driving at 10 degC (a hill
    drive with regeneration, a CC-CV charge, a town drive; SPMe, 0.5 mV noise); a positive
    exchange current x0.3 together with 5 % lithium loss in a CC-CV charge then a four-level
    HPPC at 15 degC, cycler artefacts (DFN); a voltage channel reading 0.3 % high (gain 1.003)
    under DST cycling, a CC-CV charge and a C/3 discharge at 30 degC, cycler artefacts (SPM); a
    negative exchange current x0.7 (a 7.2 mV effect) in a WLTP-like drive and a 1C charge at 45
    degC (SPMe); self-heating of a well-cooled cell (h = 25, temperature recorded) in a cold
    CC-CV charge and 1.5C discharge at 0 degC, DFN data handed to the SPMe (whose own error there
    is about 4 mV against the effect's 12); a positive particle diffusivity x0.7 under CC-CV,
    2C / 1C partial discharges and a C/5 discharge at 22 degC, 2.5 mV noise and cycler artefacts
    (SPM); an SPMe control at -10 degC over a day of use (two WLTP-like drives around a 3 h
    parking rest, a C/3 CC-CV charge), cycler artefacts. Lithium loss is accepted only by its
    own words (SEI growth also by a lithium-inventory stand-in, as in c1); the voltage gain by
    the words an engineer would use for a voltage channel out of calibration (a voltage offset
    is its nearest constant stand-in). Each effect's size on its own (PyBaMM replays of the
    recorded current, noise-free) is in its note.

    First run (2026-11-27, binary /work/bin/s12start, sha256 55d99b7ad137, load average 2.7
    before, 2.7-5.9 during (1 min), 3.5 after, on 2 cores shared with another session): 8 of 8
    by the judge, 1311 s in all. a2 the pair in round 1 at the truth (electrolyte diffusivity
    0.4996x, conductivity 1.0007x; hysteresis 10.17 mV, truth 10), 14.27 -> 0.53 mV (noise
    0.52), 219 s; a3 the pair in round 1 (concentrations 11990 / 37871 mol/m3, the truth's at
    40 % SOC of the aged cell 11978 / 37876; positive rate constant 1.015e-6, truth 1.026e-6;
    negative 6.539e-7, the set's 6.48e-7), 14.82 -> 0.99 mV (noise 0.99), 206 s; a5 kinetics
    (negative 4.552e-7, truth 4.536e-7; positive 3.363e-6, the set's 3.42e-6), 7.27 -> 1.01 mV,
    51 s; a6 thermal in round 1 (h 25.35, truth 25; ambient 273.17 K), 13.87 -> 3.93 mV (the
    SPMe's own error), then electrolyte transport (SPMe -> DFN), 1.00 mV (noise 0.98), 40 s; a7
    particle diffusivity (positive 2.802e-15, truth 2.8e-15; negative 3.404e-14, the set's
    3.3e-14), 19.41 -> 2.54 mV (noise 2.31), 7 s; a8 no missing physics (1.06 mV, noise 0.97),
    1 s. a4 a voltage offset of +12.2 mV (the gain's 11.1-12.6 mV), 5.18 -> 1.04 mV (noise
    0.97), then "no missing physics" though the remainder is structured (Ljung-Box p 4e-65,
    1.34 mV RMS at rest against 1.04 under load): what a constant offset leaves of a gain,
    about -1 mV at the end of the C/3 discharge and its rest (14000-16500 s), +0.3 mV in the CV
    hold; 18 s. a1 passed on "SEI" with a stand-in partner and a remainder: round 1 "SEI growth
    together with OCV hysteresis" (the reaction-limited law for the EC law, exchange current
    1.451e-5 A/m2; a 1.79 mV hysteresis, none concealed, its initial state on its bound),
    23.17 -> 3.46 mV (noise 1.11; the SEI alone 4.15 mV); round 2 "unexplained structure in
    56772-61523 s, 17579-19792 s, 31611-33316 s" (3.46 mV, noise 1.04): 57 % of the square
    error at the end of the fifth 1C discharge, its rest and the start of the charge (mean
    -8.74 mV, 25.1 mV at the 2.8 V knee at 59652 s), 19 % at the end of the second discharge
    (+7.97 mV), 7 % at the end of the third; 769 s of the 900 s cap."""
    # a1: SEI growth limited by the EC reaction and EC diffusion through the film, 5 CC-CV cycles with rests at 40 degC, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15,
              "SEI kinetic rate constant [m.s-1]": 1e-13, "EC diffusivity [m2.s-1]": 7e-19})
    cycle = ("Discharge at 1C until 2.8 V", "Rest for 20 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes")
    write_case(root, "a1_sei_ec_reaction_limited_5_cccv_cycles_40C_spme", lion.SPMe(options={"SEI": "ec reaction limited"}), p,
               [("Rest for 10 minutes",)] + [cycle] * 5,
               {"effect": "sei_growth", "candidate_model": "spme", "accept": ["SEI", "inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 313.15,
                "note": "SEI growth limited by the EC reaction with EC diffusion through the film (PyBaMM 'ec reaction limited'; a growth "
                        "law no earlier batch used), SEI kinetic rate constant 1e-13 m/s (Chen 2020's 1e-12 x0.1) and EC diffusivity 7e-19 "
                        "m2/s (2e-18 x0.35), so that both the reaction and the diffusion through the film limit the growth; at 40 degC "
                        "(isothermal, not recorded): 0.00685 mol of lithium lost to the SEI over the 5 cycles (0.184 A h, 3.7 % of the "
                        "nominal capacity), most of it early; discharge capacities 4.864, 4.740, 4.701, 4.669, 4.641 A h. A "
                        "lithium-inventory loss growing through the recording is the SEI's nearest stand-in and is accepted. From full: 10 "
                        "min rest, 5 x (1C to 2.8 V, 20 min rest, C/2 CC-CV to 4.2 V and C/20, 20 min rest), 19.5 h; sampled every 30 s, 1 "
                        "mV noise; SPMe data and model. Replaying the recorded current (noise-free, from full), PyBaMM's nominal SPMe is "
                        "29.2 mV RMS off (5.7 mV in the first eighth of the record, 51.7 mV in the seventh: the ends of the later "
                        "discharges)"},
               initial_soc=1.0, seed=251, period=30, compare=lion.SPMe())
    # a2: negative OCP hysteresis +-10 mV with electrolyte diffusivity x0.5, a day of driving at 10 degC, SPMe, 0.5 mV noise
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.5)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    with_negative_hysteresis(p, 0.010)
    steps = (["Rest for 10 minutes", pybamm.step.current(hill_regen_drive(252, 3.0)), "Rest for 40 minutes", "Charge at C/2 until 4.1 V",
              "Hold at 4.1 V until C/10", "Rest for 40 minutes"] + urban_drive(252, 25) + ["Rest for 30 minutes"])
    write_case(root, "a2_hysteresis_and_electrolyte_diffusivity_day_of_driving_10C_spme",
               lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "hysteresis+electrolyte_transport", "candidate_model": "spme", "accept": ["hysteresis", "electrolyte"],
                "ambient_temperature_K": 283.15,
                "note": "one-state hysteresis of the negative OCP, +-10 mV (decay rate 10, initial state 0), together with an electrolyte "
                        "diffusivity x0.5 (all concentrations), at 10 degC (isothermal, not recorded). A day of driving from 60 % SOC: 10 "
                        "min rest, a 30 min hill drive with regenerative braking (the hill_regen_drive of seed 252 scaled to peaks of 1.8C "
                        "discharge and 1.2C charge, current linear between 1 s points), 40 min rest, C/2 CC-CV to 4.1 V and C/10 (16 min CC, "
                        "40 min CV: the electrolyte polarisation holds the current back), 40 min rest, an urban drive (25 segments: bursts "
                        "of 1.5-3C, cruising at 0.3-1C, regeneration at 0.5-1.5C, idling), 30 min rest; 3.8 h, sampled every 2 s, 0.5 mV "
                        "noise; SPMe (one-state hysteresis) data and the SPMe without it. The electrolyte stays above 181 mol/m3. Replaying "
                        "the recorded current from 60 %, PyBaMM's nominal SPMe is 14.1 mV RMS off; the SPMe with the hysteresis alone "
                        "(electrolyte missing) 12.4 mV, the SPMe with the diffusivity alone (hysteresis missing) 4.1 mV (2.7-6.3 mV in each "
                        "eighth): the hysteresis is the smaller member, 8x the noise"},
               initial_soc=0.6, seed=252, noise=5e-4, period=2, compare=lion.SPMe())
    # a3: positive exchange current x0.3 with 5 % lithium loss, CC-CV charge then a four-level HPPC at 15 degC, cycler artefacts, DFN
    p = scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.3)
    p = scaled(p, "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    level = ["Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1.5C for 10 seconds", "Rest for 40 seconds",
             "Discharge at 1C for 10 seconds", "Rest for 40 seconds", "Charge at 0.75C for 10 seconds", "Rest for 5 minutes"]
    steps = ["Rest for 10 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes", "Discharge at C/2 for 20 minutes",
             "Rest for 20 minutes"]
    for _ in range(3):
        steps += level + ["Discharge at C/2 for 20 minutes", "Rest for 20 minutes"]
    steps += level
    write_case(root, "a3_kinetics_positive_and_inventory_cccv_hppc_15C_cycler_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics+lithium_inventory_loss", "candidate_model": "dfn",
                "accept": ["kinetic|exchange|charge-transfer|charge transfer|reaction rate", "inventory|lithium loss|cyclable"],
                "ambient_temperature_K": 288.15,
                "note": "positive exchange-current density x0.3 together with 5 % less lithium (initial negative concentration x0.95, the "
                        "initial state set as 40 % SOC of the aged cell), at 15 degC (isothermal, not recorded). From 40 % SOC: 10 min rest, "
                        "C/2 CC-CV to 4.2 V and C/20, 20 min rest, C/2 for 20 min, 20 min rest, then a four-level HPPC: at each level 2C "
                        "discharge 10 s, 40 s rest, 1.5C charge 10 s, 40 s rest, 1C discharge 10 s, 40 s rest, 0.75C charge 10 s, 5 min "
                        "rest, with C/2 for 20 min and 20 min rest between levels (about 83, 66, 50 and 33 % SOC; the 1.5C charge pulse at "
                        "the first level reaches 4.31 V); 5.4 h; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution), 1 mV noise; DFN data and model. Replaying the recorded current from 40 %, PyBaMM's nominal DFN is 27.1 "
                        "mV RMS off, the DFN with the kinetics alone (inventory missing) 24.7 mV, with the inventory alone (kinetics "
                        "missing) 12.4 mV"},
               initial_soc=0.4, seed=253, cycler=CYCLER, compare=lion.DFN())
    # a4: the voltage channel reads 0.3 % high (gain 1.003), DST cycling, CC-CV charge and C/3 discharge at 30 degC, cycler artefacts, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    steps = (["Rest for 10 minutes"] + dst_steps(2.0) * 6 + ["Rest for 30 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
                                                             "Rest for 30 minutes", "Discharge at C/3 for 90 minutes", "Rest for 30 minutes"])
    write_case(root, "a4_voltage_channel_gain_0p3pct_high_dst_cccv_30C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "voltage_measurement_gain", "candidate_model": "spm",
                "accept": ["voltage offset", "voltage gain", "voltage scale", "voltage channel", "voltage sensor", "voltage measurement",
                           "calibration"],
                "ambient_temperature_K": 303.15,
                "note": "the cycler's voltage channel reads 0.3 % high (a gain error of the voltage measurement, 1.003 x the cell's voltage: "
                        "11.1 mV at 3.7 V, 12.6 mV at 4.2 V; not an offset), under current and at rest alike; the cell itself is nominal. "
                        "Not a cell property; a voltage offset (about 12 mV) is its nearest constant stand-in and is accepted, as are the "
                        "words an engineer would use for the channel. At 30 degC (isothermal, not recorded), from 90 % SOC: 10 min rest, 6 x "
                        "the USABC Dynamic Stress Test (peak 2C, 36 min, about 90 -> 75 %), 30 min rest, C/2 CC-CV to 4.2 V and C/20, 30 min "
                        "rest, C/3 for 90 min, 30 min rest, 4.6 h; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution), 1 mV noise; SPM data and model. The fault moves the recorded voltage by 12.0 mV RMS (11.2-12.6 mV in "
                        "each eighth of the record)"},
               initial_soc=0.9, seed=254, cycler=CYCLER, compare=lion.SPM(), post=lambda t, i, v: 1.003 * v)
    # a5: negative exchange current x0.7 (concealed: a 6-7 mV effect), WLTP-like drive then a 1C charge at 45 degC, SPMe
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.7)
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    steps = ["Rest for 2 minutes", pybamm.step.current(wltp_like_current(255)), "Rest for 10 minutes", "Charge at 1C for 6 minutes",
             "Rest for 10 minutes"]
    write_case(root, "a5_kinetics_negative_concealed_wltp_drive_45C_spme", lion.SPMe(), p, steps,
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"],
                "ambient_temperature_K": 318.15,
                "note": "negative exchange-current density x0.7 (a concealed effect), at 45 degC (isothermal, not recorded). From 80 % SOC: "
                        "2 min rest, a WLTP-like drive (wltp_like_current seed 255: 30 min, peak 3C discharge, regeneration to 1.5C charge, "
                        "current linear between 1 s points, 0.48 A h out), 10 min rest, 1C charge for 6 min, 10 min rest; 58 min, sampled "
                        "every 1 s, 1 mV noise; SPMe data and model. Replaying the recorded current from 80 %, PyBaMM's nominal SPMe is 7.2 "
                        "mV RMS off (3.8-8.5 mV in each eighth under the drive, 13.1 mV in the eighth that holds the 1C charge, at most 18.4 "
                        "mV)"},
               initial_soc=0.8, seed=255, period=1, compare=lion.SPMe())
    # a6: self-heating h = 25 (well cooled), temperature recorded, cold CC-CV charge and 1.5C discharge at 0 degC, DFN data handed to the SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15, "Total heat transfer coefficient [W.m-2.K-1]": 25.0})
    steps = ["Rest for 10 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 30 minutes", "Discharge at 1.5C for 25 minutes",
             "Rest for 30 minutes", "Discharge at C/2 until 3.0 V", "Rest for 30 minutes"]
    write_case(root, "a6_thermal_h25_recorded_cold_cccv_0C_dfn_data_spme", lion.DFN(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 273.15,
                "note": "lumped self-heating of a well-cooled cell, h = 25 W/(m2 K), ambient and initial 0 degC. From 20 % SOC: 10 min rest, "
                        "1C CC-CV to 4.2 V and C/10, 30 min rest, 1.5C for 25 min, 30 min rest, C/2 to 3.0 V, 30 min rest, 4.1 h (the cell "
                        "warms by up to 13.6 K, in the 1.5C discharge); temperature recorded (0.05 K noise, 0.1 K resolution); sampled every "
                        "2 s, 1 mV noise; DFN data handed to the isothermal SPMe at 0 degC. Replaying the recorded current from 20 %, "
                        "PyBaMM's nominal SPMe is 13.9 mV RMS off, the isothermal DFN 11.9 mV (the effect), the thermal SPMe with the true h "
                        "3.8 mV (the SPMe's own error at 0 degC, at most 11.5 mV, in the charge and the 1.5C discharge), the thermal SPM "
                        "36.2 mV. One concealed effect: a first verdict must name the thermal effect; electrolyte transport (SPMe -> DFN) "
                        "beside it is right too"},
               initial_soc=0.2, temperature=True, seed=256, period=2, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPMe())
    # a7: positive particle diffusivity x0.7, CC-CV, 2C / 1C partial discharges, a C/5 discharge at 22 degC, 2.5 mV noise, cycler artefacts, SPM
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.7)
    p.update({"Ambient temperature [K]": 295.15, "Initial temperature [K]": 295.15})
    steps = ["Rest for 10 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour", "Discharge at 2C for 10 minutes",
             "Rest for 30 minutes", "Discharge at 1C for 20 minutes", "Rest for 30 minutes", "Charge at 1C for 15 minutes", "Rest for 30 minutes",
             "Discharge at C/5 for 2 hours", "Rest for 1 hour"]
    write_case(root, "a7_diffusivity_positive_partial_discharges_22C_2p5mV_cycler_spm", lion.SPM(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spm", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 295.15,
                "note": "positive particle diffusivity x0.7 (2.8e-15 m2/s instead of 4e-15), at 22 degC (isothermal, not recorded). From 50 "
                        "% SOC: 10 min rest, C/2 CC-CV to 4.2 V and C/20, 1 h rest, 2C for 10 min, 30 min rest, 1C for 20 min, 30 min rest, "
                        "1C charge for 15 min, 30 min rest, C/5 for 2 h, 1 h rest, 7.9 h; cycler artefacts (irregular sampling, 3 mA current "
                        "noise, 0.1 mV resolution), 2.5 mV noise; SPM data and model. Replaying the recorded current from 50 %, PyBaMM's "
                        "nominal SPM is 13.4 mV RMS off (14-22 mV in each of the first five eighths of the record, 1.1 mV in the last)"},
               initial_soc=0.5, seed=257, noise=2.5e-3, cycler=CYCLER, compare=lion.SPM())
    # a8: control, SPMe at -10 degC, a day of use: two WLTP-like drives around a 3 h parking rest, a C/3 CC-CV charge; cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 263.15, "Initial temperature [K]": 263.15})
    morning = wltp_like_current(258, peak_C=2.0, regen_C=0.75)[:1023]
    evening = wltp_like_current(259, peak_C=2.0, regen_C=0.75)
    steps = ["Rest for 10 minutes", pybamm.step.current(morning), "Rest for 3 hours", pybamm.step.current(evening), "Rest for 30 minutes",
             "Charge at C/3 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 30 minutes"]
    write_case(root, "a8_control_day_of_use_minus10C_cycler_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 263.15,
                "note": "negative control at -10 degC (isothermal, not recorded), the coldest ambient of any batch: SPMe data and model, "
                        "nothing concealed. A day of use from 70 % SOC: 10 min rest, a morning drive (the first 17 min of a WLTP-like drive, "
                        "seed 258, peak 2C, regeneration to 0.4C), a 3 h parking rest, an evening drive (a full 30 min WLTP-like drive, seed "
                        "259, peak 2C), 30 min rest, C/3 CC-CV to 4.1 V and C/20, 30 min rest; 6.3 h, the voltage between 3.52 and 4.10 V; "
                        "cycler artefacts (irregular sampling: the parking rest every 60 s, 3 mA current noise, 0.1 mV resolution), 1 mV "
                        "noise"},
               initial_soc=0.7, seed=258, cycler=CYCLER, compare=lion.SPMe())


def single_times(t):
    """The recorded points whose time is not repeated (a repeated time marks a current step)."""
    single = np.ones(len(t), dtype=bool)
    single[1:] &= t[1:] - t[:-1] > 1e-6
    single[:-1] &= t[1:] - t[:-1] > 1e-6
    return single


def record_rmse(folder, name, key, d):
    """Adds the RMS (mV) of the voltage differences `d` (V) to the case's truth.json under `key`."""
    with open(os.path.join(folder, "truth.json")) as f:
        truth = json.load(f)
    truth[key] = round(1e3 * float(np.sqrt(np.mean(d ** 2))), 2)
    with open(os.path.join(folder, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"  {name}: {key} = {truth[key]} mV")


def at_temperature(p, celsius):
    """`p` with the ambient and initial temperatures at `celsius` degC."""
    kelvin = 273.15 + celsius
    p.update({"Ambient temperature [K]": kelvin, "Initial temperature [K]": kelvin})
    return p


def replay_rmse(root, name, model, params, steps, initial_soc, key, period=1, skip_steps=0, shift_V=0.0, post=None):
    """Adds to `name`'s truth.json, under `key`, the RMS difference (mV) between the recorded voltage and
    `model` with `params` run through `steps` from `initial_soc` (after `skip_steps` unrecorded steps),
    at the recording's single (not repeated) times: what one effect or one model gap does on its own.
    `shift_V` is added to the replayed voltage (a voltage channel's offset put on the model); `post(t, i,
    v)`, as in `write_case`, makes the replayed voltage what the logger records of it (a delay)."""
    folder = os.path.join(root, name)
    data = np.loadtxt(os.path.join(folder, "recording.csv"), delimiter=",", skiprows=1)
    t, v = data[:, 0], data[:, 2]
    sol = pybamm.Simulation(model, parameter_values=params, experiment=pybamm.Experiment(steps, period=f"{period} seconds"),
                            solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8)).solve(initial_soc=initial_soc)
    tr, vr = sol["Time [s]"].entries, sol["Voltage [V]"].entries + shift_V
    if post is not None:
        vr = post(tr, sol["Current [A]"].entries, vr)
    if skip_steps:
        n0 = sum(len(c["Time [s]"].entries) for c in sol.cycles[:skip_steps])
        tr, vr = tr[n0:] - tr[n0], vr[n0:]
    single = single_times(t)
    single &= t <= tr[-1]
    _, first = np.unique(tr, return_index=True)
    d = v[single] - np.interp(t[single], tr[first], vr[first])
    record_rmse(folder, name, key, d)


def best_replay_rmse(root, name, new_model, params, steps, socs, key, period=1):
    """As `replay_rmse` from each initial SOC of `socs` (a fresh `new_model()` each), keeping the
    least RMS difference under `key` and its SOC under `key` with "_rmse_mV" made
    "_best_initial_soc": what one effect leaves when the initial state of charge is fitted."""
    best = None
    for soc in socs:
        replay_rmse(root, name, new_model(), params.copy(), steps, float(soc), key, period=period)
        with open(os.path.join(root, name, "truth.json")) as f:
            truth = json.load(f)
        if best is None or truth[key] < best[0]:
            best = (truth[key], round(float(soc), 4))
    truth[key], truth[key.replace("_rmse_mV", "_best_initial_soc")] = best
    with open(os.path.join(root, name, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"  {name}: {key} (best) = {best[0]} mV at SOC {best[1]}")


def regulation_blocks(seed, blocks):
    """Frequency-regulation duty around a mid SOC: alternate discharge and charge blocks of 60-240 s at
    0.2-1C, so the state of charge wanders a few per cent either side of where it started."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(blocks):
        rate = float(rng.uniform(0.2, 1.0))
        seconds = int(rng.integers(60, 241))
        steps.append(f"{'Discharge' if k % 2 == 0 else 'Charge'} at {rate:.2f}C for {seconds} seconds")
        if rng.uniform() < 0.3:
            steps.append(f"Rest for {int(rng.integers(30, 181))} seconds")
    return steps


def batch_b(root):
    """Twenty-sixth batch (prefix bb, so as not to clash with the bench's b1-b8), made blind (a
    helper session that did not read the diagnosis code, judged once on the binary /work/bin/s13gain
    before anything else). The Chen 2020 cell throughout. Effects at small size (a +-6 mV OCV
    hysteresis in an OCV step test, a 4 mA leak across a 36 h storage rest, a 2.5 mOhm contact
    resistance in a C/3 capacity check), a pair whose smaller member (SEI growth) lies under a larger
    one (self-heating, temperature recorded), DFN data handed to the SPMe (8 % positive LAM in an
    HPPC at 10 degC, cycler artefacts), a recording exported from part-way through a test (the cell
    still relaxing from an unrecorded 1.5C discharge, cycler artefacts), a DFN control under a
    frequency-regulation duty at 5 degC (cycler artefacts), and one effect outside the tool's listed
    candidates: a vehicle logger whose voltage channel is time-stamped 2 s late against its current
    channel (unsynchronised CAN messages), in a WLTP-like drive. Lithium and active-material loss
    are accepted only by their own words (SEI also by a lithium-inventory stand-in); the leak by
    the words an engineer would use (self-discharge, leak, soft short, current offset); the
    unrelaxed start by "unrelaxed" / "recording condition" / "history" words; the time lag by the
    words for a logging delay or misalignment (not the bare "lag", which an RC or hysteresis
    verdict could carry). Each note gives the effect's size on its own where a replay measures it.

    First run (2026-11-27, binary /work/bin/s13gain, sha256 d244018ba4b5, load average 7.47 before,
    8.55 after (1 min), on 2 cores shared with other work; 133 s in all): 5 of 8 by the judge, 6 on
    substance. bb1 hysteresis 6.06 mV (truth 6), 3.92 -> 1.00 mV, 5 s; bb2 a leak of 4.0 mA (truth 4),
    15.24 -> 0.99 mV, 5 s; bb4 positive LAM 8 % (fraction 0.6119, truth 0.6118), 20.13 -> 1.33 mV, then
    no missing physics (the SPMe's own 1.3 mV), 9 s; bb7 no missing physics (1.04 mV, noise 1.03), 1 s;
    bb8 a tie of contact 2.50 mOhm (truth 2.5) or kinetics, 3.56 -> 0.99 mV, 3 s. bb6 was named right
    in round 1 ("Recording condition: an unrelaxed start", a load of 7.66 A for 846 s before the first
    point; initial SOC 40.8 %), 27.03 -> 0.98 mV, 20 s, but the judge's verdict pattern has no
    "Recording condition" and took round 2's "No missing physics" as the first verdict: a judge
    artefact. Missed: bb5 refused by the recording check as a sign error ("the voltage rises when the
    discharge current rises at 23 of 27 current steps: is the current charge-positive?"), 0 s; bb3
    "unexplained" (14.67 mV; closest irreversible plating, 7.60 mV, ln BF -4.3; the thermal
    candidate alone at the truth, h 11.96, ambient 308.10 K, made the hold-out worse, 22.93 -> 30.19
    mV, so no pair with it was formed), 90 s. Correction to bb3's note, found after judging:
    the SEI is the LARGER member, not the smaller: replaying the recorded current (1 s
    zero-order hold of the 15 s log, so about 7.8 mV of the truth's own replay is interpolation),
    the isothermal SPM with the SEI leaves 15.5 mV, the thermal SPM without it 24.9 mV, the nominal
    SPM 21.4 mV (the two effects partly cancel); the note's experiment-based numbers (15.06 and
    41.85 mV) hold shifted cut-offs. The case itself is unchanged."""
    cap = 5.0
    # bb1: negative OCP hysteresis +-6 mV (small), an OCV step test (C/5 steps of 10 % with 45 min rests, down then up), SPMe at 20 degC
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    with_negative_hysteresis(p, 0.006)
    steps = (["Rest for 30 minutes"] + ["Discharge at C/5 for 30 minutes", "Rest for 45 minutes"] * 6
             + ["Charge at C/5 for 30 minutes", "Rest for 45 minutes"] * 6)
    write_case(root, "bb1_hysteresis_6mV_ocv_step_test_20C_spme",
               lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "hysteresis", "candidate_model": "spme", "accept": ["hysteresis"], "ambient_temperature_K": 293.15,
                "note": "one-state hysteresis of the negative OCP, +-6 mV (decay rate 10, initial state 0: the cell starts in the "
                        "middle), a small effect, at 20 degC (isothermal, not recorded). An OCV step test from 85 % SOC: 30 min rest, 6 x "
                        "(C/5 for 30 min, 45 min rest) down to about 25 %, then 6 x (C/5 charge for 30 min, 45 min rest) back up; 15.5 h, "
                        "sampled every 20 s, 1 mV noise; SPMe (one-state hysteresis) data and the SPMe without it. The rest voltages "
                        "after charge steps sit about 12 mV above those after discharge steps at the same SOC"},
               initial_soc=0.85, seed=301, period=20, compare=lion.SPMe())
    # bb2: a 4 mA leak (soft short) the cycler does not see, across a 36 h storage rest at 90 % SOC, SPM at 30 degC
    leak = 0.004
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    seen = ["Rest for 20 minutes", "Charge at C/3 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 36 hours (10 minute period)",
            "Discharge at C/3 until 3.0 V", "Rest for 1 hour"]
    inside = [f"Discharge at {leak} A for 20 minutes", f"Charge at {cap / 3 - leak:.4f} A until 4.1 V",
              f"Hold at 4.1 V until {1000 * (cap / 20 - leak):.0f} mA", f"Discharge at {leak} A for 36 hours (10 minute period)",
              f"Discharge at {cap / 3 + leak:.4f} A until 3.0 V", f"Discharge at {leak} A for 1 hour"]
    write_case(root, "bb2_leak_4mA_36h_storage_rest_30C_spm", lion.SPM(), p, inside,
               {"effect": "self_discharge", "candidate_model": "spm",
                "accept": ["self-discharge", "self discharge", "leak", "soft short", "internal short", "short circuit", "current offset"],
                "ambient_temperature_K": 303.15,
                "note": "a 4 mA internal leak (a soft short of about 1 kOhm; C/1250) that the cycler does not measure: the electrodes "
                        "carry the recorded current plus 4 mA of discharge throughout, so over the 36 h storage rest the cell loses "
                        "0.144 A h (2.9 % SOC) and its rest voltage sags, and the C/3 discharge after it ends earlier. A small leak, "
                        "seen mainly through a long calendar rest. At 30 degC (isothermal, not recorded), from 40 % SOC: 20 min rest, "
                        "C/3 CC-CV to 4.1 V and C/20 (as the cycler sees it), 36 h storage rest logged every 10 min, C/3 to 3.0 V, "
                        "1 h rest; sampled every 10 s elsewhere, 1 mV noise; SPM data and model"},
               initial_soc=0.4, seed=302, period=10, compare=lion.SPM(), leak_A=leak, compare_steps=seen)
    # bb3: reaction-limited SEI growth (the smaller effect) under lumped self-heating (h = 12, temperature recorded), 4 cycles 2C / 1C CC-CV, SPM at 35 degC
    p = chen()
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15, "Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    p = scaled(p, "SEI reaction exchange current density [A.m-2]", 100.0)
    cycle = ["Discharge at 2C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes"]
    steps = ["Rest for 10 minutes"] + cycle * 4
    name = "bb3_sei_under_selfheating_4_cycles_2C_35C_recorded_spm"
    write_case(root, name, lion.SPM(options={"SEI": "reaction limited", "thermal": "lumped"}), p, steps,
               {"effect": "sei_growth+thermal", "candidate_model": "spm",
                "accept": ["SEI|inventory|lithium loss|cyclable", "thermal|heat|self-heating"], "ambient_temperature_K": 308.15,
                "note": "two effects: lumped self-heating (h = 12 W/(m2 K), the larger) and reaction-limited SEI growth (SEI reaction "
                        "exchange current 1.5e-5 A/m2, 100x Chen 2020's: an accelerated ageing test; SEI growth activation energy 0 as "
                        "in the set, so the SEI does not speed up as the cell warms), at 35 degC ambient. From full: 10 min rest, 4 x "
                        "(2C to 2.7 V, 15 min rest, 1C CC-CV to 4.2 V and C/10, 15 min rest); temperature recorded (0.05 K noise, 0.1 K "
                        "resolution); sampled every 15 s, 1 mV noise; SPM (lumped thermal, SEI) data handed to the isothermal SPM "
                        "without SEI. A growing lithium-inventory loss is the SEI's nearest stand-in and is accepted. The replays below "
                        "(sei_alone_rmse_mV: the SPM with the SEI and without the heating; thermal_alone_rmse_mV: the thermal SPM without "
                        "the SEI) give what each missing effect leaves on its own"},
               initial_soc=1.0, temperature=True, seed=303, period=15, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPM())
    p0 = chen(); p0.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    replay_rmse(root, name, lion.SPM(options={"SEI": "reaction limited"}), scaled(p0.copy(), "SEI reaction exchange current density [A.m-2]", 100.0),
                steps, 1.0, "sei_alone_rmse_mV", period=15)
    p0.update({"Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    replay_rmse(root, name, lion.SPM(options={"thermal": "lumped"}), p0, steps, 1.0, "thermal_alone_rmse_mV", period=15)
    # bb4: 8 % positive LAM in an HPPC at 10 degC, cycler artefacts, DFN data handed to the SPMe
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    pulses = ["Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1.5C for 10 seconds", "Rest for 40 seconds"]
    steps = ["Rest for 10 minutes"]
    for _ in range(4):
        steps += ["Discharge at C/3 for 30 minutes", "Rest for 40 minutes"] + pulses
    steps += ["Discharge at C/3 until 2.8 V", "Rest for 40 minutes"]
    name = "bb4_lam_positive_8pct_hppc_10C_cycler_dfn_data_spme"
    write_case(root, name, lion.DFN(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 283.15,
                "note": "8 % loss of positive active material (volume fraction 0.665 -> 0.6118, the set's initial concentrations), at "
                        "10 degC (isothermal, not recorded). DFN data handed to the SPMe (a richer model than the candidate): "
                        "electrolyte transport (SPMe -> DFN) named beside the LAM is right too, but the first verdict must name the "
                        "LAM. From full: 10 min rest, 4 x (C/3 for 30 min, 40 min rest, 2C discharge 10 s, 40 s rest, 1.5C charge 10 "
                        "s, 40 s rest; the first 1.5C charge pulse, at about 83 % SOC, reaches 4.29 V), C/3 to 2.8 V, 40 min rest; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution), 1 mV noise. spme_with_lam_rmse_mV: the SPMe with the true LAM (the SPMe's own error against "
                        "the DFN); dfn_nominal_rmse_mV: the nominal DFN (what the LAM alone does)"},
               initial_soc=1.0, seed=304, cycler=CYCLER, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), p.copy(), steps, 1.0, "spme_with_lam_rmse_mV")
    p0 = chen(); p0.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    replay_rmse(root, name, lion.DFN(), p0, steps, 1.0, "dfn_nominal_rmse_mV")
    # bb5: the logger stamps the voltage 2 s late against the current (unsynchronised channels), WLTP-like drive, SPMe at 18 degC
    p = chen()
    p.update({"Ambient temperature [K]": 291.15, "Initial temperature [K]": 291.15})
    steps = ["Rest for 5 minutes", pybamm.step.current(wltp_like_current(305, peak_C=2.5, regen_C=1.0)), "Rest for 10 minutes",
             "Charge at 1C for 8 minutes or until 4.2 V", "Rest for 10 minutes"]
    write_case(root, "bb5_voltage_logged_2s_late_wltp_drive_18C_spme", lion.SPMe(), p, steps,
               {"effect": "voltage_time_lag", "candidate_model": "spme",
                "accept": ["delay", "latency", "misalign", "synchron", "time shift", "time offset", "timestamp", "time stamp", "time lag",
                           "time base", "time axis"],
                "ambient_temperature_K": 291.15,
                "note": "a logging fault, not a cell property and not among the tool's candidates: the vehicle logger stamps the "
                        "voltage 2 s later than the current (the two come in unsynchronised CAN messages), so each recorded voltage "
                        "is the cell's voltage 2 s earlier (linear interpolation of the 1 s simulation; the first 2 s hold the "
                        "first value). The cell itself is nominal. An engineer would call it a time delay / misalignment / "
                        "synchronisation error between the channels. At 18 degC (isothermal, not recorded), from 70 % SOC: 5 min "
                        "rest, a WLTP-like drive (wltp_like_current seed 305, peak 2.5C, regeneration to 1C, current linear between "
                        "1 s points, 1800 s), 10 min rest, 1C charge for 8 min or to 4.2 V, 10 min rest (a first draft from 85 % SOC "
                        "with a 10 min charge reached 4.5 V and was changed before judging); sampled every 1 s, 1 mV noise; SPMe "
                        "data and model. effect_rmse_mV is what the delay alone does"},
               initial_soc=0.7, seed=305, period=1, compare=lion.SPMe(),
               post=lambda t, i, v: np.interp(t - 2.0, t, v))
    # bb6: a recording exported from part-way through a test: it starts in the rest after an unrecorded 1.5C discharge, cycler artefacts, SPMe at 15 degC
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    steps = ["Discharge at 1.5C for 20 minutes", "Rest for 1 hour", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour",
             "Discharge at 1C for 30 minutes", "Rest for 1 hour"]
    name = "bb6_unrelaxed_start_after_unrecorded_1p5C_discharge_15C_cycler_spme"
    write_case(root, name, lion.SPMe(), p, steps,
               {"effect": "unrelaxed_start", "candidate_model": "spme",
                "accept": ["unrelaxed", "not relaxed", "recording condition", "history", "relaxing", "part-way", "partway"],
                "ambient_temperature_K": 288.15,
                "note": "a recording condition, not a cell property: the file was exported from part-way through a test, and its "
                        "first point is 1e-13 s after an unrecorded 1.5C discharge of 20 min (90 -> 40 % SOC) ended, so the cell "
                        "starts the recorded 1 h rest with 1.5C concentration gradients in its particles and electrolyte, the "
                        "voltage recovering by tens of mV. The cell itself is nominal. Recorded: 1 h rest, C/2 CC-CV to 4.2 V and "
                        "C/20, 1 h rest, 1C for 30 min, 1 h rest; at 15 degC (isothermal, not recorded); cycler artefacts "
                        "(irregular sampling, 3 mA current noise, 0.1 mV resolution), 1 mV noise; SPMe data and model. "
                        "candidate_rmse_mV runs the same unrecorded discharge (so it is only the noise); relaxed_start_rmse_mV is "
                        "the nominal SPMe started at rest, its initial SOC the best of 38-46 % in 0.2 % steps: what the unrelaxed "
                        "start does when the initial SOC is fitted"},
               initial_soc=0.9, seed=306, cycler=CYCLER, compare=lion.SPMe(), skip_steps=1)
    best = None
    for soc in np.arange(0.38, 0.4605, 0.002):
        replay_rmse(root, name, lion.SPMe(), p.copy(), steps[1:], float(soc), "relaxed_start_rmse_mV")
        with open(os.path.join(root, name, "truth.json")) as f:
            truth = json.load(f)
        best = truth["relaxed_start_rmse_mV"] if best is None else min(best, truth["relaxed_start_rmse_mV"])
    truth["relaxed_start_rmse_mV"] = best
    with open(os.path.join(root, name, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    # bb7: control, DFN under a frequency-regulation duty around 50 % SOC at 5 degC, cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    steps = ["Rest for 10 minutes"] + regulation_blocks(307, 24) + ["Rest for 30 minutes"]
    write_case(root, "bb7_control_frequency_regulation_5C_cycler_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 278.15,
                "note": "negative control at 5 degC (isothermal, not recorded): DFN data and model, nothing concealed. A "
                        "frequency-regulation (grid-service) duty from 50 % SOC: 10 min rest, 24 alternating discharge / charge blocks "
                        "of 60-240 s at 0.2-1C with occasional 30-180 s pauses, 30 min rest; cycler artefacts (irregular sampling, "
                        "3 mA current noise, 0.1 mV resolution), 1 mV noise"},
               initial_soc=0.5, seed=307, cycler=CYCLER, compare=lion.DFN())
    # bb8: 2.5 mOhm contact resistance (about 4 mV at C/3), a C/3 capacity check with CC-CV charge, SPM at 40 degC
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    p.update({"Contact resistance [Ohm]": 0.0025}, check_already_exists=False)
    steps = ["Rest for 10 minutes", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour", "Discharge at C/3 until 2.5 V",
             "Rest for 1 hour"]
    write_case(root, "bb8_contact_2p5mOhm_c3_capacity_check_40C_spm", lion.SPM(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 313.15,
                "note": "a 2.5 mOhm contact resistance (a slightly worn fixture contact; 4.2 mV at C/3), a small effect, at 40 degC "
                        "(isothermal, not recorded), in a low-rate capacity check where it has no pulse to show itself by: from 30 % "
                        "SOC, 10 min rest, C/3 CC-CV to 4.2 V and C/20, 1 h rest, C/3 to 2.5 V, 1 h rest; sampled every 10 s, 1 mV "
                        "noise; SPM data and model"},
               initial_soc=0.3, seed=308, period=10, compare=lion.SPM())


def batch_ab(root):
    """Twenty-seventh batch (key "ab"), made blind (a helper session that did not read the diagnosis
    code, judged once on the binary /work/bin/s13fe4 before anything else). The Chen 2020 cell
    throughout. Protocols earlier batches used little: a CC-CV charge with a long CV tail (to C/100),
    a GITT with short rests (5 min at 1C, 3 min rest), a partial-cycle duty between 30 and 70 % SOC,
    fast-charge cycles (3C CC then a CC-CV finish), a storage rest of a day between two C/3
    check-ups, a cold day of driving, a pulse charge, and a pulse-relaxation test. Ambients from 0 to
    45 degC. Small effects (a 0.7 mOhm contact resistance, 2.6 mV; a negative exchange current x0.87,
    4.1 mV; an electrolyte conductivity x0.6 in a cold drive, 4.9 mV), DFN data handed to the SPMe (lithium loss), and one effect outside the tool's
    listed candidates: a particle-size distribution (lognormal radii in both electrodes, PyBaMM's
    "particle size": "distribution" SPM, the MPM) handed to the single-particle SPM. Lithium loss is
    accepted only by its own words, active-material loss by "active material", the size
    distribution only by words naming a distribution of particle sizes (not "particle diffusivity",
    its nearest stand-in). Each effect's size on its own (the nominal candidate, or a replay, against
    the noise-free voltage) is in truth.json (effect_rmse_mV and the replay keys).

    First run (2026-11-27, binary /work/bin/s13fe4, sha256 87e10d092afd, load average 3.32 before,
    5.83 after (1 min), on 2 cores shared with a long test run; 475 s in all): 6 of 8 by the judge.
    ab1 round 1 "loss of lithium inventory together with electrolyte transport (SPMe -> DFN)"
    (initial concentrations 5069 / 47038 mol/m3: the cyclable lithium of the set less 2.76 % of it,
    the truth's 4 % of the negative's lithium, to four figures), 12.44 -> 1.01 mV (noise 1.07), 38 s;
    ab2 a tie "series/contact resistance 1.33 mOhm or charge-transfer kinetics" (negative rate
    constant 5.613e-7, truth 5.638e-7), 4.11 -> 0.99 mV, 8 s, accepted on the tie; ab3 a tie
    "contact resistance 0.69 mOhm (truth 0.7) or kinetics", 2.89 -> 1.01 mV, 9 s; ab5 "Parameter
    mismatch: electrolyte transport properties" (conductivity factor 0.6004, truth 0.6; diffusivity
    1.0028), 4.92 -> 0.99 mV, 322 s; ab6 "Parameter mismatch: loss of lithium inventory together with
    loss of active material, negative electrode (10 %)" (negative fraction 0.6750, truth 0.675; the
    refitted concentrations 20218 / 31869 hold the set's cyclable lithium to 0.01 %: the inventory
    partner carries no loss, as concealed), 10.05 -> 1.00 mV, 64 s; ab7 no missing physics (1.03 mV,
    noise 1.03), 0 s. Missed: ab4 "No missing physics" (1.03 mV) on the first 596 s only, 0 s: the
    tool's isothermal SPMe broke down 628 s in ("a concentration at its limit"), 28 s into the
    first 3C charge from 10 % SOC; PyBaMM's isothermal SPMe driven by the same recorded current
    runs through it with the electrolyte at the negative current collector down to 5.9 mol/m3 at
    629 s (found after judging: the fast charge nearly empties the electrolyte there), so the
    breakdown is the tool's own model at near-depletion; its report says a model that cannot follow
    the recording is evidence of a mismatch but the verdict is still "No missing physics", and the
    heating (13.8 K recorded) is never tested. ab8 (the particle-size distribution, outside the
    list) round 1 "OCV hysteresis" (24.04 mV half-width, rate 4.65; rest residual +7.6 mV after
    discharges, -28.2 mV after charges), 15.16 -> 3.68 mV, round 2 "Unexplained structure in
    8408-9471 s, 2460-3588 s, 6313-6677 s" (3.68 mV, noise 1.00; the closest, lithium inventory, cut
    the hold-out by 2 %); the particle diffusivity refit ran to its bound on the negative (9.9e-13)
    and was not named; 29 s. The stretched relaxation of a spread of particle radii has no candidate
    of its own and the slow, direction-dependent return after the 1C charge is taken for hysteresis."""
    # ab1: 4 % lithium loss, C/2 CC-CV to 4.2 V with a long CV tail (to C/100), then a 1C partial discharge, 35 degC, DFN data handed to the SPMe
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.96)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    steps = ["Rest for 15 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/100", "Rest for 45 minutes",
             "Discharge at 1C for 40 minutes", "Rest for 45 minutes"]
    name = "ab1_inventory_4pct_cccv_long_cv_tail_35C_dfn_data_spme"
    write_case(root, name, lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "lithium loss", "lithium lost", "cyclable"],
                "ambient_temperature_K": 308.15,
                "note": "4 % less lithium (initial negative concentration x0.96; the initial state set as 15 % SOC of the aged cell), at "
                        "35 degC (isothermal, not recorded). From 15 % SOC: 15 min rest, C/2 CC-CV to 4.2 V with a long CV tail (held "
                        "until C/100), 45 min rest, 1C for 40 min, 45 min rest; cycler artefacts (irregular sampling, 3 mA current "
                        "noise, 0.1 mV resolution), 1 mV noise. DFN data handed to the SPMe: electrolyte transport (SPMe -> DFN) named "
                        "beside the loss is right too, but the first verdict must name the lithium. spme_with_loss_rmse_mV: the SPMe "
                        "with the true loss (the SPMe's own error against the DFN); dfn_nominal_rmse_mV: the nominal DFN (what the loss "
                        "alone does)"},
               initial_soc=0.15, seed=2701, cycler=CYCLER, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), p.copy(), steps, 0.15, "spme_with_loss_rmse_mV")
    p0 = chen(); p0.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    replay_rmse(root, name, lion.DFN(), p0, steps, 0.15, "dfn_nominal_rmse_mV")
    # ab2: negative exchange current x0.87 (small), a GITT with short rests (1C for 5 min, 3 min rest) down then up, 10 degC, SPMe
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.87)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    steps = (["Rest for 10 minutes"] + ["Discharge at 1C for 5 minutes", "Rest for 3 minutes"] * 9 + ["Rest for 30 minutes"]
             + ["Charge at 1C for 5 minutes", "Rest for 3 minutes"] * 4 + ["Rest for 30 minutes"])
    write_case(root, "ab2_kinetics_negative_small_gitt_short_rests_10C_spme", lion.SPMe(), p, steps,
               {"effect": "kinetics", "candidate_model": "spme", "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"],
                "ambient_temperature_K": 283.15,
                "note": "negative exchange-current density x0.87, a small effect, at 10 degC (isothermal, not recorded). A GITT with "
                        "short rests from 95 % SOC: 10 min rest, 9 x (1C for 5 min, 3 min rest) down to about 20 %, 30 min rest, 4 x "
                        "(1C charge for 5 min, 3 min rest), 30 min rest; sampled every 2 s, 1 mV noise; SPMe data and model. "
                        "effect_rmse_mV is what the slower kinetics alone do"},
               initial_soc=0.95, seed=2702, period=2, compare=lion.SPMe())
    # ab3: 0.7 mOhm contact resistance (small), a partial-cycle duty between 30 and 70 % SOC, 45 degC, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    p.update({"Contact resistance [Ohm]": 0.0007}, check_already_exists=False)
    steps = ["Rest for 10 minutes"] + ["Charge at 0.8C for 30 minutes", "Rest for 10 minutes", "Discharge at 1C for 24 minutes", "Rest for 10 minutes"] * 4
    write_case(root, "ab3_contact_0p7mOhm_small_partial_cycles_30_70pct_45C_spm", lion.SPM(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 318.15,
                "note": "a 0.7 mOhm contact resistance (3.5 mV at 1C), a small effect, at 45 degC (isothermal, not recorded), in a "
                        "partial-cycle duty between 30 and 70 % SOC (as a stationary-storage or hybrid duty): from 30 % SOC, 10 min "
                        "rest, 4 x (0.8C charge for 30 min, 10 min rest, 1C for 24 min, 10 min rest), 5.5 h; sampled every 5 s, 1 mV "
                        "noise; SPM data and model"},
               initial_soc=0.3, seed=2703, period=5, compare=lion.SPM())
    # ab4: lumped self-heating (h = 10, temperature recorded) in two fast-charge cycles (3C CC, CC-CV finish, 1C discharge), 20 degC, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15, "Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    cycle = ["Charge at 3C until 4.1 V", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/5", "Rest for 20 minutes",
             "Discharge at 1C until 3.0 V", "Rest for 20 minutes"]
    steps = ["Rest for 10 minutes"] + cycle * 2
    write_case(root, "ab4_thermal_h10_recorded_fast_charge_cycles_20C_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 293.15,
                "note": "lumped self-heating, h = 10 W/(m2 K), ambient and initial 20 degC. From 10 % SOC: 10 min rest, 2 x (3C to "
                        "4.1 V, 1C to 4.2 V, hold at 4.2 V until C/5, 20 min rest, 1C to 3.0 V, 20 min rest); temperature recorded "
                        "(0.05 K noise, 0.1 K resolution); sampled every 2 s, 1 mV noise; SPMe (lumped thermal) data handed to the "
                        "isothermal SPMe. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.1, temperature=True, seed=2704, period=2, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPMe())
    # ab5: electrolyte conductivity x0.6, a cold day of driving (a WLTP-like drive, a parking rest, an urban drive) at 0 degC, DFN
    p = scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.6)
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    steps = (["Rest for 10 minutes", pybamm.step.current(wltp_like_current(2705, peak_C=1.5, regen_C=0.75)), "Rest for 30 minutes"]
             + urban_drive(2705, 20) + ["Rest for 30 minutes"])
    write_case(root, "ab5_electrolyte_conductivity_cold_drive_0C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 273.15,
                "note": "electrolyte conductivity x0.6 (all concentrations), at 0 degC (isothermal, not recorded). From 85 % SOC: 10 "
                        "min rest, a WLTP-like drive (wltp_like_current seed 2705, peak 1.5C, regeneration to 0.75C, current linear between "
                        "1 s points, 1800 s), 30 min rest, an urban drive (urban_drive seed 2705, 20 segments), 30 min rest; sampled "
                        "every 1 s, 1 mV noise; DFN data and model. effect_rmse_mV is what the conductivity alone does"},
               initial_soc=0.85, seed=2705, period=1, compare=lion.DFN())
    # ab6: 10 % negative LAM (lithium kept), a day's storage between two C/3 check-ups, 40 degC, SPMe
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.9)
    moved = (0.1 * 0.75 * p["Negative electrode thickness [m]"] * p["Initial concentration in negative electrode [mol.m-3]"]
             / (p["Positive electrode active material volume fraction"] * p["Positive electrode thickness [m]"]))
    p.update({"Initial concentration in positive electrode [mol.m-3]": p["Initial concentration in positive electrode [mol.m-3]"] + moved,
              "Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    check = ["Discharge at C/3 until 2.8 V", "Rest for 30 minutes", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20"]
    steps = ["Rest for 10 minutes"] + check + ["Rest for 24 hours (10 minute period)"] + check + ["Rest for 30 minutes"]
    write_case(root, "ab6_lam_negative_10pct_storage_with_checkups_40C_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 313.15,
                "note": "10 % loss of negative active material (volume fraction 0.75 -> 0.675) with the lithium inventory kept (the "
                        f"lithium of the lost material moved into the positive's initial concentration, +{moved:.0f} mol/m3, so "
                        "that only the electrode's capacity changes), at 40 degC (isothermal, not recorded). Storage with check-ups, "
                        "from 60 % SOC: 10 min rest, a check-up (C/3 to 2.8 V, 30 min rest, C/3 CC-CV to 4.2 V and C/20), a 24 h "
                        "storage rest at full charge logged every 10 min, the same check-up, 30 min rest; sampled every 10 s "
                        "elsewhere, 1 mV noise; SPMe data and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=0.6, seed=2706, period=10, compare=lion.SPMe())
    # ab7: control, a pulse charge (2C pulses with short discharge pulses) then a C/2 discharge, 30 degC, cycler artefacts, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    steps = (["Rest for 10 minutes"] + ["Charge at 2C for 60 seconds or until 4.2 V", "Discharge at 1C for 5 seconds", "Rest for 10 seconds"] * 16
             + ["Rest for 30 minutes", "Discharge at C/2 until 3.0 V", "Rest for 30 minutes"])
    write_case(root, "ab7_control_pulse_charge_30C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 303.15,
                "note": "negative control at 30 degC (isothermal, not recorded): SPM data and model, nothing concealed. A pulse charge "
                        "from 20 % SOC: 10 min rest, 16 x (2C charge for 60 s or to 4.2 V, 1C discharge for 5 s, 10 s rest), 30 min "
                        "rest, C/2 to 3.0 V, 30 min rest; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV "
                        "resolution), 1 mV noise"},
               initial_soc=0.2, seed=2707, cycler=CYCLER, compare=lion.SPM())
    # ab8: outside the listed candidates: a particle-size distribution (lognormal, relative spread 0.4 in both electrodes), pulse-relaxation test, 15 degC, MPM data handed to the SPM
    p = pybamm.get_size_distribution_parameters(chen(), sd_n=0.4, sd_p=0.4)
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    steps = (["Rest for 10 minutes"] + ["Discharge at 2C for 3 minutes", "Rest for 20 minutes"] * 5
             + ["Charge at 1C for 20 minutes", "Rest for 30 minutes"])
    write_case(root, "ab8_particle_size_distribution_pulse_relaxation_15C_spm", lion.SPM(options={"particle size": "distribution"}), p, steps,
               {"effect": "particle_size_distribution", "candidate_model": "spm",
                "accept": ["size distribution", "particle-size distribution", "polydisperse", "distribution of particle",
                           "distribution of radii", "radius distribution", "radii distribution"],
                "ambient_temperature_K": 288.15,
                "note": "outside the tool's listed candidates: the particles of each electrode have a lognormal distribution of radii "
                        "(pybamm.get_size_distribution_parameters, relative standard deviation 0.4 in both electrodes, the "
                        "area-weighted mean at the set's radius, radii from 0 to 2.5x the mean; PyBaMM's SPM with 'particle size': "
                        "'distribution', the many-particle model), where the candidate SPM has one particle size: small particles "
                        "fill and empty fast, large ones slowly, so the relaxation after a pulse is stretched (no single diffusion time "
                        "fits it). At 15 degC (isothermal, not recorded), a pulse-relaxation test from 80 % SOC: 10 min rest, 5 x (2C "
                        "for 3 min, 20 min rest), 1C charge for 20 min, 30 min rest; sampled every 1 s, 1 mV noise; MPM data handed to "
                        "the SPM. A particle diffusivity (or a single particle radius) refit is its nearest stand-in and is not accepted; "
                        "only words naming a distribution of particle sizes are. effect_rmse_mV is what the distribution alone does"},
               initial_soc=0.8, seed=2708, period=1, compare=lion.SPM())


def batch_ac(root):
    """Twenty-eighth batch (key "ac"), made blind (a helper session that did not read the diagnosis
    code, judged once on the binary /work/bin/s14final before anything else). The Chen 2020 cell
    throughout, ambients from 0 to 45 degC, each of the three models handed over (and DFN data handed
    to the SPMe once), sampling from 1 to 60 s (one cycler-thinned log, one with current noise and
    resolution), protocols: a cold HPPC, CC-CV with partial charges, a slow pseudo-OCV cycle, a
    WLTP-like drive, mixed-rate cycling with poor cooling, an urban drive then a CC-CV charge, long
    relaxation rests, constant-power steps. A control (DFN at 0 degC), a pair (negative OCP
    hysteresis with positive active-material loss, lithium kept), two effects outside the usual
    parameter list (the negative electrode's OCP is another graphite's, Mohtat 2020's, in place of
    Chen 2020's; the electrolyte's transference number and thermodynamic factor are Landesfeind
    2019's concentration- and temperature-dependent fits in place of Chen's constants 0.2594 and 1),
    and ordinary single effects of various sizes (self-heating, temperature recorded; 5 % lithium
    loss; a negative particle diffusivity x0.25; a small positive exchange current x0.6 at 45 degC).
    Words as an engineer would judge them: lithium loss by its own words, active-material loss by
    "active material", the OCP swap by words naming the electrode's open-circuit potential (not an
    inventory / stoichiometry stand-in, which cannot reproduce a different plateau structure), the
    electrolyte by "electrolyte" or the transference / thermodynamic factor. Each effect's size on its
    own (the nominal candidate, or a replay, against the noise-free voltage) is in truth.json
    (effect_rmse_mV and the replay keys).

    First run (2026-11-27, binary /work/bin/s14final, sha256 61e212ae7977, load average 4.73 before,
    3.42 after (1 min), on 2 cores shared with other sessions; 1178 s in all): 6 of 8 by the judge.
    ac1 no missing physics (0.99 mV, noise 1.02; initial SOC 80.0 %), 1 s; ac2 round 1 "Parameter
    mismatch: loss of active material, positive electrode (10 % of its capacity) together with loss of
    lithium inventory", 12.23 -> 2.46 mV, round 2 "Missing physics: OCV hysteresis" (8.02 mV, truth 8),
    -> 1.00 mV (noise 1.02), round 3 no missing physics (positive fraction 0.6119, truth 0.6118; the
    inventory partner holds the concealed cyclable lithium to 0.02 %, as concealed), 101 s; ac5
    "Missing physics: thermal" (h 7.959, truth 8; ambient 313.11 K), 9.27 -> 0.98 mV, 5 s; ac6 "Missing
    physics: loss of lithium inventory together with electrolyte transport (SPMe -> DFN)" (cyclable
    lithium within 0.003 % of the truth's, 3.45 % less than the set's), 28.26 -> 1.02 mV, 150 s; ac7
    "Parameter mismatch: solid (particle) diffusivity" (negative 8.307e-15, truth 8.25e-15; positive
    4.002e-15, the set's 4e-15), 3.67 -> 0.98 mV (noise 0.99), 3 s; ac8 a tie "charge-transfer
    kinetics (positive rate constant 2.054e-6, truth 2.052e-6; negative 6.477e-7, the set's 6.48e-7) or
    series/contact resistance 1.45 mOhm", 3.99 -> 1.00 mV, 11 s, accepted on the tie (two load levels
    whose overpotentials are still linear in the current, as the report says). Missed: ac3 (the other
    graphite's OCP, outside the list) round 1 "Parameter mismatch: loss of lithium inventory" (5.1 %
    more cyclable lithium than the set's, the negative's initial concentration on its search bound),
    83.94 -> 16.96 mV, round 2 "Unexplained structure in 14340-18450 s, 0-630 s" (16.96 mV, noise 1.01;
    closest a voltage offset of +22.5 mV, over its 20 mV bound), whose text does say "at rest the model
    is off by 27.48 mV RMS: the cell's open-circuit voltage differs from the set's (its electrodes' OCP
    curves or their balance)" and suggests a pseudo-OCV fit; 3 s. The judge takes the first verdict,
    the inventory stand-in, which is not accepted here. ac4 (Landesfeind t+ and thermodynamic factor)
    timed out at the judge's 900 s with nothing written ("?"). An uncounted rerun afterwards (same
    binary, no cap but a 2700 s timeout, load average about 4) printed round 1 and then timed out in
    round 2: "Missing physics: RC / double-layer dynamics together with loss of lithium inventory" (RC
    4.52 mOhm, 3580 F, a 16 s time constant), 11.79 -> 3.90 mV (hold-out 10.55 -> 4.99); electrolyte
    transport properties ranked fourth (conductivity factor 0.51, diffusivity 0.95; 6.78 mV, hold-out
    cut 16 %), so the first verdict would have missed the electrolyte even without the cap: the extra
    concentration overpotential, building over tens of seconds under the drive's bursts, is taken for
    an interface RC.
    """
    # ac1: control, a cold HPPC (four levels, two rates each way), DFN data and model at 0 degC, cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    level = ["Discharge at 1C for 10 seconds", "Rest for 40 seconds", "Charge at 0.5C for 10 seconds", "Rest for 40 seconds",
             "Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1C for 10 seconds", "Rest for 5 minutes"]
    steps = ["Rest for 10 minutes"] + (["Discharge at C/2 for 12 minutes", "Rest for 20 minutes"] + level) * 4 + ["Rest for 10 minutes"]
    write_case(root, "ac1_control_hppc_0C_cycler_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 273.15,
                "note": "negative control at 0 degC (isothermal, not recorded): DFN data and model, nothing concealed. A cold HPPC "
                        "from 80 % SOC: 10 min rest, then 4 x (C/2 for 12 min, 20 min rest, 1C discharge 10 s, 40 s rest, C/2 "
                        "charge 10 s, 40 s rest, 2C discharge 10 s, 40 s rest, 1C charge 10 s, 5 min rest; charge pulses at half the "
                        "discharge rates, as a cold HPPC limits them), 10 min rest (levels at about 70, 60, 50, 40 % SOC); cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution), 1 mV noise"},
               initial_soc=0.8, seed=2801, cycler=CYCLER, compare=lion.DFN())
    # ac2: negative OCP hysteresis +-8 mV with 8 % positive LAM (lithium kept), CC-CV with partial charges, 15 degC, SPMe
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    moved = (0.08 * 0.665 * p["Positive electrode thickness [m]"] * p["Initial concentration in positive electrode [mol.m-3]"]
             / (p["Negative electrode active material volume fraction"] * p["Negative electrode thickness [m]"]))
    p.update({"Initial concentration in negative electrode [mol.m-3]": p["Initial concentration in negative electrode [mol.m-3]"] + moved,
              "Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    with_negative_hysteresis(p, 0.008)
    steps = ["Rest for 10 minutes", "Charge at C/2 for 40 minutes", "Rest for 30 minutes", "Discharge at 1C for 20 minutes", "Rest for 30 minutes",
             "Charge at C/2 until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 1 hour", "Discharge at C/3 for 2 hours", "Rest for 1 hour",
             "Charge at 1C for 15 minutes", "Rest for 30 minutes"]
    name = "ac2_hysteresis_8mV_and_lam_positive_8pct_partial_cccv_15C_spme"
    write_case(root, name, lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "hysteresis+active_material_loss", "candidate_model": "spme", "accept": ["hysteresis", "active material"],
                "ambient_temperature_K": 288.15,
                "note": "one-state hysteresis of the negative OCP, +-8 mV (decay rate 10, initial state 0), together with an 8 % loss "
                        "of positive active material (volume fraction 0.665 -> 0.6118) with the lithium inventory kept (the lithium of "
                        f"the lost material moved into the negative's initial concentration, +{moved:.0f} mol/m3), at 15 degC "
                        "(isothermal, not recorded). CC-CV with partial charges, from 30 % SOC: 10 min rest, C/2 charge for 40 min, 30 "
                        "min rest, 1C for 20 min, 30 min rest, C/2 CC-CV to 4.1 V and C/20, 1 h rest, C/3 for 2 h, 1 h rest, 1C charge "
                        "for 15 min, 30 min rest; sampled every 10 s, 1 mV noise; SPMe (one-state hysteresis) data and the SPMe without "
                        "it. spme_hysteresis_only_rmse_mV: the SPMe with the hysteresis alone (LAM missing) against the recording; "
                        "spme_lam_only_rmse_mV: with the LAM alone (hysteresis missing). These replays and effect_rmse_mV are "
                        "time-aligned, and the CV hold ends at another time in each (the data's CC-CV takes 6549 s, the nominal's "
                        "6739 s), so after it they also measure a shift of the protocol; before it (the first 2.6 h) the hysteresis "
                        "alone is 3-5 mV RMS (the smaller member, 3-5x the noise) and the LAM alone (with the initial state set as 30 % "
                        "SOC of each cell) about 40 mV"},
               initial_soc=0.3, seed=2802, period=10, compare=lion.SPMe())
    p_h = chen(); p_h.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15}); with_negative_hysteresis(p_h, 0.008)
    replay_rmse(root, name, lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p_h, steps, 0.3,
                "spme_hysteresis_only_rmse_mV", period=10)
    p_l = scaled(chen(), "Positive electrode active material volume fraction", 0.92)
    p_l.update({"Initial concentration in negative electrode [mol.m-3]": p_l["Initial concentration in negative electrode [mol.m-3]"] + moved,
                "Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
    replay_rmse(root, name, lion.SPMe(), p_l, steps, 0.3, "spme_lam_only_rmse_mV", period=10)
    # ac3: outside the list: the negative OCP is another graphite's (Mohtat 2020) in place of Chen 2020's; slow cycle with long rests, 30 degC, SPM
    p = chen()
    mohtat = pybamm.ParameterValues("Mohtat2020")["Negative electrode OCP [V]"]
    p.update({"Negative electrode OCP [V]": lambda sto, f=mohtat: f(sto), "Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    steps = ["Rest for 10 minutes", "Discharge at C/5 until 2.7 V", "Rest for 1 hour", "Charge at C/5 for 3 hours", "Rest for 1 hour"]
    write_case(root, "ac3_negative_ocp_other_graphite_c5_cycle_30C_spm", lion.SPM(), p, steps,
               {"effect": "ocp_mismatch", "candidate_model": "spm",
                "accept": ["OCP", "open-circuit potential", "open circuit potential", "equilibrium potential", "OCV curve", "OCV shape",
                           "OCV function", "half-cell"],
                "ambient_temperature_K": 303.15,
                "note": "outside the tool's listed candidates: the negative electrode's OCP is another graphite's (PyBaMM's Mohtat 2020 "
                        "graphite_ocp_PeymanMPM) in place of Chen 2020's LG M50 graphite: the stage-2 plateau sits about 38 mV lower "
                        "and ends at another stoichiometry (a cell whose graphite is not the one its parameter set was measured on). Not "
                        "a constant offset and not a stretch of the stoichiometry axis, so a lithium-inventory / active-material / "
                        "stoichiometry refit is a stand-in and is not accepted; only words naming the electrode's open-circuit "
                        "(equilibrium) potential curve are. At 30 degC (isothermal, not recorded), from full (4.2 V): 10 min rest, C/5 "
                        "to 2.7 V, 1 h rest, C/5 charge for 3 h, 1 h rest; sampled every 30 s, 1 mV noise; SPM data and model"},
               initial_soc=1.0, seed=2803, period=30, compare=lion.SPM())
    # ac4: outside the list: Landesfeind 2019 concentration-dependent transference number and thermodynamic factor, WLTP-like drive, 25 degC, DFN
    p = chen()
    o = pybamm.ParameterValues("ORegan2022")
    p.update({"Cation transference number": o["Cation transference number"], "Thermodynamic factor": o["Thermodynamic factor"]})
    steps = ["Rest for 5 minutes", pybamm.step.current(wltp_like_current(2804)), "Rest for 20 minutes", "Discharge at 2C for 5 minutes",
             "Rest for 20 minutes"]
    write_case(root, "ac4_electrolyte_transference_and_tdf_landesfeind_wltp_25C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn",
                "accept": ["electrolyte", "transference", "thermodynamic factor"],
                "note": "outside the tool's usual parameters: the electrolyte's cation transference number and thermodynamic factor "
                        "are Landesfeind 2019's concentration- and temperature-dependent fits for LiPF6 in EC:EMC 3:7 (as in PyBaMM's "
                        "ORegan2022 set; at 25 degC and 1 M t+ = 0.22 and a thermodynamic factor of 2.2, 3.8 at 2 M) in place of "
                        "Chen 2020's constants 0.2594 and 1 (the same electrolyte); conductivity and diffusivity are Chen's: the "
                        "concentration overpotential is about twice the candidate's. Its physics is electrolyte transport. At 25 "
                        "degC (isothermal, not recorded), from 85 % SOC: 5 min rest, a WLTP-like drive (wltp_like_current seed 2804: "
                        "1800 s, four phases, peak 3C discharge, regeneration to 1.5C charge, current linear between 1 s points), 20 "
                        "min rest, 2C for 5 min, 20 min rest; sampled every 1 s, 1 mV noise; "
                        "DFN data and model"},
               initial_soc=0.85, seed=2804, period=1, compare=lion.DFN())
    # ac5: lumped self-heating, poor cooling (h = 8), temperature recorded, mixed-rate cycling at 40 degC, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15, "Total heat transfer coefficient [W.m-2.K-1]": 8.0})
    steps = ["Rest for 5 minutes", "Discharge at 1C for 10 minutes", "Discharge at 2C for 6 minutes", "Discharge at C/2 for 15 minutes",
             "Discharge at 3C for 2 minutes", "Rest for 10 minutes", "Charge at 1.5C for 12 minutes", "Discharge at 2C for 8 minutes",
             "Rest for 10 minutes", "Discharge at 1C until 3.0 V", "Rest for 30 minutes"]
    write_case(root, "ac5_thermal_h8_recorded_mixed_rate_40C_spm", lion.SPM(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spm", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 313.15,
                "note": "lumped self-heating of a poorly cooled cell, h = 8 W/(m2 K), ambient and initial 40 degC (at 40 degC the "
                        "Arrhenius dependences are flatter, so a given rise moves the voltage less than in a cold cell). Mixed-rate "
                        "cycling from 95 % SOC: 5 min rest, 1C for 10 min, 2C for 6 min, C/2 for 15 min, 3C for 2 min, 10 min rest, "
                        "1.5C charge for 12 min, 2C for 8 min, 10 min rest, 1C to 3.0 V, 30 min rest; temperature recorded (0.05 K "
                        "noise, 0.1 K resolution); sampled every 10 s, 1 mV noise; SPM (lumped thermal) data handed to the isothermal "
                        "SPM. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.95, temperature=True, seed=2805, period=10, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPM())
    # ac6: 5 % lithium loss, an urban drive then a CC-CV charge and a 1C discharge, 20 degC, DFN data handed to the SPMe
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    steps = (["Rest for 5 minutes"] + urban_drive(2806, 25) + ["Rest for 15 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
                                                              "Rest for 20 minutes", "Discharge at 1C until 3.0 V", "Rest for 15 minutes"])
    name = "ac6_inventory_5pct_urban_drive_cccv_20C_dfn_data_spme"
    write_case(root, name, lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "lithium loss", "lithium lost", "cyclable"],
                "ambient_temperature_K": 293.15,
                "note": "5 % less lithium (initial negative concentration x0.95; the initial state set as 55 % SOC of the aged cell), "
                        "at 20 degC (isothermal, not recorded). From 55 % SOC: 5 min rest, an urban drive (urban_drive seed 2806, 25 "
                        "segments: bursts of 1.5-3C, cruising, regeneration, idling), 15 min rest, C/2 CC-CV to 4.2 V and C/20, 20 min "
                        "rest, 1C to 3.0 V, 15 min rest; sampled every 2 s, 1 mV noise. DFN data handed to the SPMe: electrolyte "
                        "transport (SPMe -> DFN) named beside the loss is right too, but the first verdict must name the lithium. "
                        "spme_with_loss_rmse_mV: the SPMe with the true loss (the SPMe's own error against the DFN); "
                        "dfn_nominal_rmse_mV: the nominal DFN (what the loss alone does)"},
               initial_soc=0.55, seed=2806, period=2, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), p.copy(), steps, 0.55, "spme_with_loss_rmse_mV", period=2)
    p0 = chen(); p0.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
    replay_rmse(root, name, lion.DFN(), p0, steps, 0.55, "dfn_nominal_rmse_mV", period=2)
    # ac7: negative particle diffusivity x0.25, 1C partial discharges and a charge with 2 h relaxation rests, 10 degC, logged every 60 s, SPMe
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.25)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    steps = ["Rest for 10 minutes", "Discharge at 1C for 20 minutes", "Rest for 2 hours", "Discharge at 1C for 20 minutes", "Rest for 2 hours",
             "Charge at 1C for 15 minutes", "Rest for 90 minutes"]
    write_case(root, "ac7_diffusivity_negative_long_relaxations_10C_60s_spme", lion.SPMe(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["diffusiv"], "ambient_temperature_K": 283.15,
                "note": "negative particle diffusivity x0.25 (all stoichiometries), at 10 degC (isothermal, not recorded). From full: "
                        "10 min rest, 1C for 20 min, 2 h rest, 1C for 20 min, 2 h rest, 1C charge for 15 min, 90 min rest (6.6 h; the "
                        "long rests show the slow relaxation); logged every 60 s (a step's first and last points kept), 1 mV noise; "
                        "SPMe data and model. effect_rmse_mV is what the slower diffusion alone does"},
               initial_soc=1.0, seed=2807, period=60, compare=lion.SPMe())
    # ac8: positive exchange current x0.6 (small at 45 degC), constant-power steps, 45 degC, DFN, 5 s, current noise and resolution
    p = scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.6)
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    steps = ["Rest for 10 minutes", "Discharge at 10 W for 15 minutes", "Discharge at 25 W for 3 minutes", "Rest for 10 minutes",
             "Charge at 12 W for 10 minutes", "Rest for 10 minutes", "Discharge at 18 W for 20 minutes", "Discharge at 30 W for 1 minute",
             "Rest for 15 minutes", "Charge at 8 W for 15 minutes", "Rest for 20 minutes"]
    write_case(root, "ac8_kinetics_positive_small_constant_power_45C_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"],
                "ambient_temperature_K": 318.15,
                "note": "positive exchange-current density x0.6 (a small effect: at 45 degC the exchange currents are large), at 45 "
                        "degC (isothermal, not recorded). Constant-power steps from 80 % SOC: 10 min rest, 10 W for 15 min, 25 W for 3 "
                        "min, 10 min rest, 12 W charge for 10 min, 10 min rest, 18 W for 20 min, 30 W for 1 min, 15 min rest, 8 W charge "
                        "for 15 min, 20 min rest (2.3 h); sampled every 5 s, 3 mA current noise, 0.1 mV / 0.1 mA resolution, 1 mV "
                        "noise; DFN data and model. effect_rmse_mV is what the slower kinetics alone do"},
               initial_soc=0.8, seed=2808, period=5, cycler={"current_noise_A": 3e-3, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.DFN())


def batch_ad(root):
    """Twenty-ninth batch (key "ad"), made blind (a helper session that did not read the diagnosis
    code, judged once on the binary /work/bin/s15final before anything else). The Chen 2020 cell
    throughout, ambients from 0 to 45 degC, each of the three models handed over (DFN data handed to
    the SPM and to the SPMe once each), sampling from 1 to 60 s (one cycler-thinned log), noise from
    0.5 to 2 mV, protocols: a warm C/5 GITT, a C/20 pseudo-OCV discharge and C/10 charge, pulses at
    seven SOCs, USABC DST drives, cold 2C CC-CV fast charges, CC-CV cycling at 40 degC, an urban drive
    then a partial C/3 discharge and a 1C charge, constant-power steps at low SOC. A control (DFN at 45
    degC, 2 mV noise), single effects (3 % lithium loss; a 2.5 mOhm contact resistance; a negative
    exchange current x0.6; partially reversible lithium plating; solvent-diffusion-limited SEI growth
    over five cycles), a pair on one electrode (5 % positive active-material loss with the positive
    particle diffusivity x0.6), and one effect outside the usual list: the electrodes' OCP entropic
    change (O'Regan 2022's measured dU/dT of the same LG M50 cell), which the Chen 2020 set leaves at
    zero, so the candidate's OCPs are 25 K off their reference at 0 degC. Words as an engineer would
    judge them: lithium loss by its own words (SEI also by a lithium-inventory stand-in), active
    material by "active material", the entropic term by words naming the OCP or its temperature
    dependence. Each effect's size on its own is in the note (a replay of the truth's current through
    the nominal candidate where a step ends on a voltage, since effect_rmse_mV, time-aligned, then also
    measures the shifted step ends).

    First run (2026-11-28, binary /work/bin/s15final, sha256 fbc70adb4d9c, load average 7.84 before,
    4.07 after (1 min), on 2 cores shared with other sessions; 1360 s in all): 7 of 8 by the judge.
    ad1 no missing physics (1.97 mV, noise 1.94; initial SOC 95.0 %), 0 s; ad2 "Missing physics: loss
    of lithium inventory together with series/contact resistance" (cyclable lithium within 0.01 % of
    the truth's, 2.07 % less than the set's; the partner 12.08 mOhm, not concealed, stands where the
    SPM lacks the DFN's electrolyte: inventory with electrolyte transport ranked 2nd and 3rd at 1.04 and
    0.99 mV), 22.52 -> 1.04 mV, 86 s; ad3 a tie "series/contact resistance 2.50 mOhm (truth 2.5) or
    electrolyte transport properties (conductivity factor 0.618)", 5.67 -> 1.00 mV, 25 s; ad4
    "Parameter mismatch: charge-transfer kinetics" (negative rate constant 3.892e-7, truth 3.888e-7;
    positive 3.416e-6, the set's 3.42e-6), 12.95 -> 1.00 mV, 244 s; ad5 "Missing physics: lithium
    plating, partially reversible" (rate constant 1.019e-9, truth 1e-9; dead-lithium decay 1.38e-6,
    truth 1e-6), 3.97 -> 1.06 mV, 306 s; ad6 round 1 "Missing physics: SEI growth, reaction and
    transport in series" (the tool's EC-reaction-limited law for the concealed solvent-diffusion one),
    22.04 -> 2.94 mV, round 2 electrolyte transport (SPMe -> DFN), -> 1.55 mV (noise 1.55), 543 s; ad7
    "Parameter mismatch: solid (particle) diffusivity together with loss of active material, positive
    electrode (5 %)" (positive diffusivity 2.402e-15, truth 2.4e-15; positive fraction 0.6317, truth
    0.6318; negative at the set's), 27.13 -> 0.99 mV, 99 s. Missed: ad8 (the entropic term, outside
    the list): the initial-SOC fit alone took the candidate from the noise-free 4.13 mV to 1.69 mV
    (initial SOC 35.2 %, truth 35.0 %); round 1 "Parameter mismatch: loss of lithium inventory" (0.28 %
    more cyclable lithium than the set's), 1.69 -> 0.90 mV (noise 0.47), round 2 "Unexplained
    structure in 8160-12480 s, 18030-18660 s" (closest OCV hysteresis, hold-out -14 %); a voltage
    offset of -2.6 mV ranked 4th and a thermal candidate 14th, neither named; nothing in the report
    names the OCP's temperature dependence; 51 s."""
    # ad1: control, a C/5 GITT down and a charge, DFN data and model at 45 degC, 10 s sampling, 2 mV noise
    p = chen()
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    steps = ["Rest for 10 minutes"] + ["Discharge at C/5 for 30 minutes", "Rest for 40 minutes"] * 8 + ["Charge at C/5 for 1 hour", "Rest for 40 minutes"]
    write_case(root, "ad1_control_gitt_c5_45C_10s_2mV_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 318.15,
                "note": "negative control at 45 degC (isothermal, not recorded): DFN data and model, nothing concealed. A C/5 GITT "
                        "from 95 % SOC: 10 min rest, 8 x (C/5 for 30 min, 40 min rest) down to about 15 %, C/5 charge for 1 h, 40 min "
                        "rest (11.2 h); sampled every 10 s, 2 mV noise (noisier than most)"},
               initial_soc=0.95, seed=2901, period=10, noise=2e-3, compare=lion.DFN())
    # ad2: 3 % lithium loss, a C/20 pseudo-OCV discharge and a C/10 CC-CV charge, 35 degC, 60 s, DFN data handed to the SPM
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.97)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    steps = ["Rest for 30 minutes", "Discharge at C/20 until 2.7 V", "Rest for 2 hours", "Charge at C/10 until 4.2 V", "Hold at 4.2 V until C/50",
             "Rest for 1 hour"]
    write_case(root, "ad2_inventory_3pct_c20_pseudo_ocv_35C_60s_dfn_data_spm", lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["inventory", "lithium loss", "lithium lost", "cyclable"],
                "ambient_temperature_K": 308.15,
                "note": "3 % less lithium (initial negative concentration x0.97; the initial state set as 100 % SOC of the aged cell), at "
                        "35 degC (isothermal, not recorded). A slow pseudo-OCV test from full (4.2 V): 30 min rest, C/20 to 2.7 V, 2 h "
                        "rest, C/10 CC-CV to 4.2 V and C/50, 1 h rest (33.3 h); sampled every 60 s, 1 mV noise. DFN data handed to "
                        "the SPM: electrolyte transport (SPM -> DFN) named beside the loss is right too, but the first verdict must "
                        "name the lithium. Replaying the truth's current (1 s) through the nominal SPM: 60.8 mV RMS (mostly at the end "
                        "of the discharge, 336 mV at most); through the SPM with the true loss: 3.9 mV (the SPM's own error against the "
                        "DFN here). effect_rmse_mV is time-aligned on the experiment, whose steps end at other times"},
               initial_soc=1.0, seed=2902, period=60, compare=lion.SPM())
    # ad3: 2.5 mOhm contact resistance, pulses at seven SOCs (1C, 3C discharge, 2C charge), 25 degC, 1 s, SPMe
    p = chen()
    p.update({"Contact resistance [Ohm]": 0.0025}, check_already_exists=False)
    level = ["Discharge at 1C for 18 seconds", "Rest for 1 minute", "Discharge at 3C for 10 seconds", "Rest for 1 minute",
             "Charge at 2C for 10 seconds", "Rest for 1 minute", "Discharge at 1C for 6 minutes", "Rest for 25 minutes"]
    steps = ["Rest for 10 minutes"] + level * 7
    write_case(root, "ad3_contact_2p5mOhm_pulses_seven_socs_25C_spme", lion.SPMe(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance", "ohmic"],
                "note": "a 2.5 mOhm contact resistance (12.5 mV at 1C, 37.5 mV at 3C), at 25 degC (isothermal, not recorded). Pulses "
                        "at seven SOCs from 95 %: 10 min rest, then 7 x (1C for 18 s, 1 min rest, 3C for 10 s, 1 min rest, 2C charge "
                        "for 10 s, 1 min rest, 1C for 6 min to the next level, 25 min rest) down to about 20 %; sampled every 1 s, 1 mV "
                        "noise; SPMe data and model. effect_rmse_mV is what the resistance alone does"},
               initial_soc=0.95, seed=2903, period=1, compare=lion.SPMe())
    # ad4: negative exchange current x0.6, USABC DST drives (2.5C peak) with rests, 10 degC, 1 s, SPM
    p = scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.6)
    p.update({"Ambient temperature [K]": 283.15, "Initial temperature [K]": 283.15})
    steps = ["Rest for 5 minutes"] + dst_steps(2.5) * 5 + ["Rest for 20 minutes"] + dst_steps(2.5) * 3 + ["Rest for 20 minutes"]
    write_case(root, "ad4_kinetics_negative_x0p6_dst_drive_10C_spm", lion.SPM(), p, steps,
               {"effect": "kinetics", "candidate_model": "spm", "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"],
                "ambient_temperature_K": 283.15,
                "note": "negative exchange-current density x0.6 (all stoichiometries), at 10 degC (isothermal, not recorded). From 90 % "
                        "SOC: 5 min rest, 5 USABC DST cycles (dst_steps(2.5): 360 s each, peak 2.5C, regeneration to 1.25C), 20 min "
                        "rest, 3 more DST cycles, 20 min rest (93 min); sampled every 1 s, 1 mV noise; SPM data and model. "
                        "effect_rmse_mV is what the slower kinetics alone do"},
               initial_soc=0.9, seed=2904, period=1, compare=lion.SPM())
    # ad5: partially reversible lithium plating in cold 2C CC-CV fast charges, 5 degC, cycler artefacts, SPMe
    p = with_okane2022(chen(), PLATING_KEYS)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    cycle = ["Charge at 2C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 40 minutes", "Discharge at C/2 until 3.0 V", "Rest for 40 minutes"]
    steps = ["Rest for 10 minutes"] + cycle * 3
    write_case(root, "ad5_plating_partially_reversible_2C_cccv_5C_cycler_spme", lion.SPMe(options={"lithium plating": "partially reversible"}), p,
               steps,
               {"effect": "lithium_plating", "candidate_model": "spme", "accept": ["plating"], "ambient_temperature_K": 278.15,
                "note": "partially reversible lithium plating (PyBaMM 'partially reversible', OKane2022's plating parameters as they "
                        "are: rate constant 1e-9 m/s, transfer coefficient 0.65, dead-lithium decay constant 1e-6 1/s) in cold fast "
                        "charges at 5 degC (isothermal, not recorded): a 2C CC-CV charge plates up to 0.0082 mol (0.22 A h; the third "
                        "charge), most of it stripped again in the CV hold as the current falls (0.0019 mol left at its end) and the 40 "
                        "min rest after (0.0003 mol left). From "
                        "10 % SOC: 10 min rest, 3 x (2C to 4.2 V, hold at 4.2 V until C/20, 40 min rest, C/2 to 3.0 V, 40 min rest), "
                        "14.5 h; cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution), 1 mV noise; SPMe data and "
                        "model. Replaying the truth's current (1 s) through the nominal SPMe: 3.9 mV RMS, 137 mV at most. "
                        "effect_rmse_mV is time-aligned on the experiment, whose steps end at other times"},
               initial_soc=0.1, seed=2905, cycler=CYCLER, compare=lion.SPMe())
    # ad6: solvent-diffusion-limited SEI over 5 cycles (1C / C/2 CC-CV), 40 degC, 60 s, 1.5 mV noise, DFN data handed to the SPMe
    p = scaled(chen(), "SEI solvent diffusivity [m2.s-1]", 2000.0)
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    cycle = ["Discharge at 1C until 2.8 V", "Rest for 20 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 20 minutes"]
    steps = ["Rest for 10 minutes"] + cycle * 5
    write_case(root, "ad6_sei_solvent_diffusion_5_cycles_40C_60s_dfn_data_spme", lion.DFN(options={"SEI": "solvent-diffusion limited"}), p, steps,
               {"effect": "sei_growth", "candidate_model": "spme", "accept": ["SEI", "inventory", "lithium loss", "cyclable"],
                "ambient_temperature_K": 313.15,
                "note": "SEI growth limited by solvent diffusion (PyBaMM 'solvent-diffusion limited', distributed film resistance), "
                        "solvent diffusivity 5e-19 m2/s (2000x Chen 2020's 2.5e-22: an accelerated test at 40 degC; isothermal, not "
                        "recorded): 0.00625 mol of lithium (0.168 A h) lost to the SEI over the 5 cycles, the 1C discharge capacity "
                        "4.841, 4.726, 4.695, 4.670, 4.649 A h. A lithium-inventory loss growing through the recording is the SEI's "
                        "nearest stand-in and is accepted. From full: 10 min rest, 5 x (1C to 2.8 V, 20 min rest, C/2 CC-CV to 4.2 V and "
                        "C/20, 20 min rest), 19.5 h; sampled every 60 s, 1.5 mV noise. DFN data handed to the SPMe: electrolyte "
                        "transport named beside the SEI is right too, but the first verdict must name the SEI or the lithium. Replaying "
                        "the truth's current (1 s) through the nominal SPMe: 22.7 mV RMS (about 10 mV in the first quarter, 37.3 mV in "
                        "the seventh eighth; 176 mV at most); through the nominal DFN: 22.6 mV (the SPMe's own error is small at 40 degC). "
                        "effect_rmse_mV is time-aligned on the experiment, whose steps end at other times"},
               initial_soc=1.0, seed=2906, period=60, noise=1.5e-3, compare=lion.SPMe())
    # ad7: pair on the positive: 5 % LAM and particle diffusivity x0.6, an urban drive then C/3 and a 1C charge, 15 degC, 2 s, SPMe
    def positive(lam, diffusivity):
        q = scaled(scaled(chen(), "Positive electrode active material volume fraction", lam), "Positive particle diffusivity [m2.s-1]", diffusivity)
        q.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
        return q
    steps = (["Rest for 5 minutes"] + urban_drive(2907, 30) + ["Rest for 20 minutes", "Discharge at C/3 for 80 minutes", "Rest for 30 minutes",
                                                              "Charge at 1C for 30 minutes", "Rest for 30 minutes"])
    name = "ad7_lam_positive_5pct_and_diffusivity_positive_x0p6_urban_drive_15C_spme"
    write_case(root, name, lion.SPMe(), positive(0.95, 0.6), steps,
               {"effect": "active_material_loss+solid_diffusivity", "candidate_model": "spme", "accept": ["active material", "diffusiv"],
                "ambient_temperature_K": 288.15,
                "note": "two effects on the positive electrode (as particle cracking would give): 5 % loss of positive active material "
                        "(volume fraction 0.665 -> 0.632, the set's initial concentrations, so the lithium of the lost material goes "
                        "with it) and positive particle diffusivity x0.6, at 15 degC (isothermal, not recorded). From 90 % SOC: 5 min "
                        "rest, an urban drive (urban_drive seed 2907, 30 segments: bursts of 1.5-3C, cruising, regeneration, idling), 20 "
                        "min rest, C/3 for 80 min, 30 min rest, 1C charge for 30 min, 30 min rest (3.7 h); sampled every 2 s, 1 mV noise; "
                        "SPMe data and model. spme_lam_only_rmse_mV: the SPMe with the LAM alone against the recording (what the "
                        "diffusivity leaves); spme_diffusivity_only_rmse_mV: with the diffusivity alone (what the LAM leaves); "
                        "effect_rmse_mV: both"},
               initial_soc=0.9, seed=2907, period=2, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), positive(0.95, 1.0), steps, 0.9, "spme_lam_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.SPMe(), positive(1.0, 0.6), steps, 0.9, "spme_diffusivity_only_rmse_mV", period=2)
    # ad8: outside the list: the OCPs' entropic change (O'Regan 2022, same LG M50 cell) missing from the set, constant-power steps at low SOC, 0 degC, SPM
    o = pybamm.ParameterValues("ORegan2022")
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15})
    for side in ["Negative", "Positive"]:
        p.update({f"{side} electrode OCP entropic change [V.K-1]": o[f"{side} electrode OCP entropic change [V.K-1]"]})
    steps = (["Rest for 20 minutes"] + ["Discharge at 3 W for 30 minutes", "Rest for 1 hour"] * 3
             + ["Charge at 5 W for 90 minutes", "Rest for 1 hour", "Discharge at 4 W for 45 minutes", "Rest for 1 hour"])
    write_case(root, "ad8_entropic_ocp_term_constant_power_low_soc_0C_spm", lion.SPM(), p, steps,
               {"effect": "ocp_temperature_dependence", "candidate_model": "spm",
                "accept": ["entropic", "entropy", "dU/dT", "OCP", "open-circuit potential", "open circuit potential", "equilibrium potential",
                           "temperature coefficient"],
                "ambient_temperature_K": 273.15,
                "note": "outside the tool's listed candidates: the electrodes' OCPs depend on temperature through their entropic change "
                        "(O'Regan 2022's measured dU/dT of the same LG M50 cell, graphite and NMC 811, as in PyBaMM's ORegan2022 set: "
                        "graphite +0.18 mV/K at low lithiation, -0.08 mV/K when full; NMC down to -0.06 mV/K), which the Chen 2020 set "
                        "leaves at zero, so at 0 degC (isothermal, not recorded; 25 K below the OCPs' 25 degC reference) the cell's "
                        "open-circuit voltage differs from the set's by an SOC-dependent few mV (about +5 mV near empty, -1 to -2 mV at "
                        "mid and high SOC). Not a constant offset and not a stretch of the stoichiometry axis; a thermal (self-heating) "
                        "verdict is not accepted (the cell is isothermal at the stated ambient), only words naming the OCP or its "
                        "temperature dependence are. Constant-power steps at low SOC, from 35 % SOC: 20 min rest, 3 x (3 W for 30 min, "
                        "1 h rest) down to about 10 %, 5 W charge for 90 min, 1 h rest, 4 W for 45 min, 1 h rest (9.1 h); sampled "
                        "every 30 s, 0.5 mV noise (a quiet channel); SPM data and model. effect_rmse_mV is what the entropic term "
                        "alone does"},
               initial_soc=0.35, seed=2908, period=30, noise=5e-4, compare=lion.SPM())


def batch_ae(root):
    """Thirtieth batch (key "ae"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients from -5 to 45 degC, each of the three models
    handed over, sampling from 1 to 60 s (one cycler-thinned log), noise from 0.5 to 2 mV,
    protocols: a cold CC-CV charge then an urban drive, a capacity check with a CC-CV charge at 45
    degC, an HPPC at four SOCs, a cold WLTP-like drive, a GITT, an urban drive then a CC-CV cycle,
    a storage rest between partial cycles, a slow discharge to low SOC. A control (SPMe at -5
    degC, colder than any earlier batch), single effects (10 % positive active-material loss, the
    lithium going with it; electrolyte diffusivity x0.4 alone, conductivity kept; lumped
    self-heating with the temperature not recorded in a cold drive; positive particle diffusivity
    x0.3), a pair of ageing effects (4 % lithium loss with electrolyte conductivity and
    diffusivity x0.65, as electrolyte decomposition gives), and two effects earlier batches used
    rarely: an internal leak (soft short) the cycler does not see, over a long storage rest, and a
    graphite + silicon composite negative (the LG M50's real SiOx-graphite anode) handed to a
    graphite-only SPM in the cold. Words as an engineer would judge them: active material by
    "active material", the leak by self-discharge / leak / short / current offset, the composite
    by silicon / composite / a second phase or the negative's open-circuit potential. Each effect's
    size on its own (the nominal candidate, or a replay, against the noise-free voltage) is in
    truth.json (effect_rmse_mV and the replay keys)."""
    cap = 5.0
    # ae1: control, SPMe at -5 degC: a C/3 CC-CV charge, an urban drive, a C/2 partial discharge, cycler artefacts
    p = chen()
    p.update({"Ambient temperature [K]": 268.15, "Initial temperature [K]": 268.15})
    steps = (["Rest for 10 minutes", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"] + urban_drive(3001, 30)
             + ["Rest for 30 minutes", "Discharge at C/2 for 40 minutes", "Rest for 30 minutes"])
    write_case(root, "ae1_control_cccv_urban_drive_minus5C_cycler_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 268.15,
                "note": "negative control at -5 degC (isothermal, not recorded): SPMe data and model, nothing concealed. From 40 % "
                        "SOC: 10 min rest, C/3 CC-CV to 4.2 V and C/20, 30 min rest, an urban drive (urban_drive seed 3001, 30 "
                        "segments: bursts of 1.5-3C, cruising, regeneration, idling), 30 min rest, C/2 for 40 min, 30 min rest; "
                        "cycler artefacts (irregular sampling, 3 mA current noise, 0.1 mV resolution), 1 mV noise"},
               initial_soc=0.4, seed=3001, cycler=CYCLER, compare=lion.SPMe())
    # ae2: 10 % positive LAM (the lithium of the lost material goes with it), a capacity check and CC-CV charge, 45 degC, 10 s, 1.5 mV, DFN
    p = scaled(chen(), "Positive electrode active material volume fraction", 0.9)
    p.update({"Ambient temperature [K]": 318.15, "Initial temperature [K]": 318.15})
    steps = ["Rest for 10 minutes", "Discharge at C/3 until 2.7 V", "Rest for 1 hour", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
             "Rest for 30 minutes", "Discharge at 1C for 30 minutes", "Rest for 30 minutes"]
    write_case(root, "ae2_lam_positive_10pct_capacity_check_cccv_45C_10s_dfn", lion.DFN(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"], "ambient_temperature_K": 318.15,
                "note": "10 % loss of positive active material (volume fraction 0.665 -> 0.5985, the set's initial concentrations, so "
                        "the lithium of the lost material goes with it; the initial state set as 90 % SOC of the aged cell), at 45 "
                        "degC (isothermal, not recorded). From 90 % SOC: 10 min rest, C/3 to 2.7 V, 1 h rest, C/2 CC-CV to 4.2 V and "
                        "C/20, 30 min rest, 1C for 30 min, 30 min rest; sampled every 10 s, 1.5 mV noise; DFN data and model. "
                        "effect_rmse_mV is time-aligned on the experiment, whose steps end at other times"},
               initial_soc=0.9, seed=3002, period=10, noise=1.5e-3, compare=lion.DFN())
    # ae3: electrolyte diffusivity x0.4 (conductivity kept), an HPPC at four SOCs with 2C and 3C pulses, 25 degC, 1 s, DFN
    p = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.4)
    level = ["Discharge at 2C for 30 seconds", "Rest for 1 minute", "Charge at 1.5C for 20 seconds", "Rest for 1 minute",
             "Discharge at 3C for 20 seconds", "Rest for 2 minutes", "Discharge at C/2 for 24 minutes", "Rest for 30 minutes"]
    steps = ["Rest for 10 minutes"] + level * 4
    write_case(root, "ae3_electrolyte_diffusivity_x0p4_hppc_25C_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"],
                "note": "electrolyte diffusivity x0.4 (all concentrations; the conductivity kept), at 25 degC (isothermal, not "
                        "recorded): the concentration polarisation builds further and relaxes slower over tens of seconds. An HPPC "
                        "from 90 % SOC: 10 min rest, then 4 x (2C for 30 s, 1 min rest, 1.5C charge for 20 s, 1 min rest, 3C for "
                        "20 s, 2 min rest, C/2 for 24 min to the next level, 30 min rest) down to about 30 %; sampled every 1 s, 1 mV "
                        "noise; DFN data and model. effect_rmse_mV is what the diffusivity alone does"},
               initial_soc=0.9, seed=3003, period=1, compare=lion.DFN())
    # ae4: lumped self-heating, h = 6, temperature NOT recorded, a cold WLTP-like drive and a 1.5C discharge, 0 degC, 2 s, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 273.15, "Initial temperature [K]": 273.15, "Total heat transfer coefficient [W.m-2.K-1]": 6.0})
    steps = ["Rest for 5 minutes", pybamm.step.current(wltp_like_current(3004, peak_C=2.5, regen_C=1.0)), "Rest for 10 minutes",
             "Discharge at 1.5C for 15 minutes", "Rest for 30 minutes"]
    write_case(root, "ae4_thermal_h6_not_recorded_cold_wltp_0C_spm", lion.SPM(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spm", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 273.15,
                "note": "lumped self-heating of a poorly cooled cell, h = 6 W/(m2 K), ambient and initial 0 degC; the temperature is "
                        "NOT recorded (only time, current, voltage): the cell warms under the drive and the 1.5C discharge, its "
                        "exchange currents rise and the overpotentials fall below the isothermal candidate's, then it cools in the "
                        "rests. From 90 % SOC: 5 min rest, a WLTP-like drive (wltp_like_current seed 3004, peak 2.5C, regeneration to "
                        "1C, 1800 s), 10 min rest, 1.5C for 15 min, 30 min rest; sampled every 2 s, 1 mV noise; SPM (lumped thermal) "
                        "data handed to the isothermal SPM. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.9, seed=3004, period=2, compare=lion.SPM())
    # ae5: positive particle diffusivity x0.3, a 1C GITT down and a charge, 35 degC, 5 s, 0.5 mV, SPM
    p = scaled(chen(), "Positive particle diffusivity [m2.s-1]", 0.3)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    steps = ["Rest for 10 minutes"] + ["Discharge at 1C for 6 minutes", "Rest for 20 minutes"] * 8 + ["Charge at 1C for 20 minutes", "Rest for 30 minutes"]
    write_case(root, "ae5_diffusivity_positive_x0p3_gitt_35C_5s_spm", lion.SPM(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spm", "accept": ["diffusiv"], "ambient_temperature_K": 308.15,
                "note": "positive particle diffusivity x0.3 (1.2e-15 m2/s for the set's 4e-15), at 35 degC (isothermal, not recorded). "
                        "A GITT from 90 % SOC: 10 min rest, 8 x (1C for 6 min, 20 min rest) down to about 10 %, 1C charge for 20 min, "
                        "30 min rest (4.1 h); sampled every 5 s, 0.5 mV noise (a quiet channel); SPM data and model. effect_rmse_mV is "
                        "what the slower diffusion alone does"},
               initial_soc=0.9, seed=3005, period=5, noise=5e-4, compare=lion.SPM())
    # ae6: pair: 4 % lithium loss with electrolyte conductivity and diffusivity x0.65, an urban drive then a CC-CV cycle, 15 degC, 2 s, 1.2 mV, SPMe
    def aged(loss, electrolyte):
        q = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.0 - loss)
        q = scaled(scaled(q, "Electrolyte conductivity [S.m-1]", electrolyte), "Electrolyte diffusivity [m2.s-1]", electrolyte)
        q.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15})
        return q
    steps = (["Rest for 5 minutes"] + urban_drive(3006, 30) + ["Rest for 15 minutes", "Discharge at C/2 until 2.8 V", "Rest for 30 minutes",
                                                              "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"])
    name = "ae6_inventory_4pct_and_electrolyte_x0p65_urban_drive_cccv_15C_spme"
    write_case(root, name, lion.SPMe(), aged(0.04, 0.65), steps,
               {"effect": "lithium_inventory_loss+electrolyte_transport", "candidate_model": "spme",
                "accept": ["inventory|lithium loss|lithium lost|cyclable", "electrolyte"], "ambient_temperature_K": 288.15,
                "note": "two ageing effects, as electrolyte decomposition gives: 4 % less lithium (initial negative concentration "
                        "x0.96; the initial state set as 70 % SOC of the aged cell) and electrolyte conductivity and diffusivity both "
                        "x0.65 (all concentrations), at 15 degC (isothermal, not recorded). From 70 % SOC: 5 min rest, an urban drive "
                        "(urban_drive seed 3006, 30 segments), 15 min rest, C/2 to 2.8 V, 30 min rest, 1C CC-CV to 4.2 V and C/20, 30 "
                        "min rest; sampled every 2 s, 1.2 mV noise; SPMe data and model. spme_inventory_only_rmse_mV: the SPMe with "
                        "the lithium loss alone against the recording (what the electrolyte leaves); spme_electrolyte_only_rmse_mV: "
                        "with the electrolyte alone (what the lithium loss leaves); these and effect_rmse_mV are time-aligned on the "
                        "experiment, whose steps end at other times"},
               initial_soc=0.7, seed=3006, period=2, noise=1.2e-3, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), aged(0.04, 1.0), steps, 0.7, "spme_inventory_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.SPMe(), aged(0.0, 0.65), steps, 0.7, "spme_electrolyte_only_rmse_mV", period=2)
    # ae7: rarely used: a 15 mA internal leak (soft short) the cycler does not see, a 10 h storage rest between partial cycles, 30 degC, 60 s, 2 mV, SPMe
    leak = 0.015
    p = chen()
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    seen = ["Rest for 20 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 10 hours", "Discharge at 1C for 30 minutes",
            "Rest for 2 hours", "Discharge at C/2 until 3.0 V", "Rest for 1 hour"]
    inside = [f"Discharge at {leak} A for 20 minutes", f"Charge at {cap / 2 - leak:.4f} A until 4.2 V",
              f"Hold at 4.2 V until {1000 * (cap / 20 - leak):.0f} mA", f"Discharge at {leak} A for 10 hours",
              f"Discharge at {cap + leak:.4f} A for 30 minutes", f"Discharge at {leak} A for 2 hours",
              f"Discharge at {cap / 2 + leak:.4f} A until 3.0 V", f"Discharge at {leak} A for 1 hour"]
    write_case(root, "ae7_leak_15mA_storage_rest_partial_cycles_30C_60s_spme", lion.SPMe(), p, inside,
               {"effect": "self_discharge", "candidate_model": "spme",
                "accept": ["self-discharge", "self discharge", "leak", "soft short", "internal short", "short circuit", "current offset"],
                "ambient_temperature_K": 303.15,
                "note": "a 15 mA internal leak (a soft short of about 270 Ohm; C/330) that the cycler does not measure: the electrodes "
                        "carry the recorded current plus 15 mA of discharge throughout, so over the 10 h storage rest at full charge "
                        "the cell loses 0.15 A h (3 % SOC) and its rest voltage sags, the CV hold ends at C/20 as the cycler sees it, "
                        "and the C/2 discharge ends earlier. Not a candidate parameter; an engineer would call it self-discharge, a "
                        "leak or a current offset. At 30 degC (isothermal, not recorded), from 50 % SOC: 20 min rest, C/2 CC-CV to "
                        "4.2 V and C/20 (as the cycler sees it), 10 h rest, 1C for 30 min, 2 h rest, C/2 to 3.0 V, 1 h rest; sampled "
                        "every 60 s, 2 mV noise (a coarse, noisy logger); SPMe data and model. effect_rmse_mV is time-aligned on the "
                        "experiment, whose steps end at other times"},
               initial_soc=0.5, seed=3007, period=60, noise=2e-3, compare=lion.SPMe(), leak_A=leak, compare_steps=seen)
    # ae8: rarely used: a graphite + silicon composite negative handed to the graphite-only SPM, a slow discharge to low SOC, 5 degC, 30 s, 0.8 mV
    p = with_silicon_composite(chen(), 0.66, 0.011)
    p.update({"Ambient temperature [K]": 278.15, "Initial temperature [K]": 278.15})
    steps = ["Rest for 10 minutes", "Discharge at 1C for 30 minutes", "Rest for 1 hour", "Discharge at C/5 until 2.6 V", "Rest for 2 hours",
             "Charge at C/3 for 2 hours", "Rest for 1 hour"]
    write_case(root, "ae8_graphite_silicon_composite_negative_low_soc_5C_30s_spm", lion.SPM(options={"particle phases": ("2", "1")}), p, steps,
               {"effect": "composite_negative", "candidate_model": "spm",
                "accept": ["silicon", "composite", "blend", "second phase", "two-phase", "two phase", "open-circuit potential",
                           "open circuit potential", "OCP"],
                "ambient_temperature_K": 278.15,
                "note": "a composite negative electrode (the LG M50's real SiOx-graphite anode): graphite (the set's, active fraction "
                        "0.66 instead of 0.75) with 1.1 % by volume of silicon (Chen2020_composite's secondary phase: average OCP of "
                        "Mark 2016, no hysteresis, 1.52 um particles, c_max 278000 mol/m3), handed to the graphite-only SPM; the "
                        "silicon delithiates at the end of discharge and gives a sloping low-SOC tail, and the two phases exchange "
                        "lithium in the rests. Not a candidate parameter; naming the negative OCP is accepted beside silicon / "
                        "composite; a lithium-inventory / active-material / stoichiometry refit is a stand-in and is not. At 5 degC "
                        "(isothermal, not recorded), from full: 10 min rest, 1C for 30 min, 1 h rest, C/5 to 2.6 V, 2 h rest, C/3 "
                        "charge for 2 h, 1 h rest; sampled every 30 s, 0.8 mV noise; SPM (two-phase) data. effect_rmse_mV is "
                        "time-aligned on the experiment, whose steps end at other times"},
               initial_soc=1.0, seed=3008, period=30, noise=8e-4, compare=lion.SPM())


def drone_flight(seed):
    """One multirotor drone flight as current steps (discharge positive): a take-off climb (2.4-2.8C,
    15-25 s), a hover (1.2-1.45C, 1-3 min), 4-6 legs of forward flight (1.6-2.2C, 30-90 s) each
    followed by a hover (20-60 s) and sometimes a gust or climb (2.4-2.8C, 8-15 s), a descent
    (0.9-1.1C, 40-60 s) and a landing hover (1.4C, 15 s): about 10 min at 1.6C on average."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(2.4, 2.8):.2f}C for {int(rng.integers(15, 26))} seconds",
             f"Discharge at {rng.uniform(1.2, 1.45):.2f}C for {int(rng.integers(60, 181))} seconds"]
    for _ in range(int(rng.integers(4, 7))):
        steps.append(f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(30, 91))} seconds")
        steps.append(f"Discharge at {rng.uniform(1.2, 1.45):.2f}C for {int(rng.integers(20, 61))} seconds")
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(2.4, 2.8):.2f}C for {int(rng.integers(8, 16))} seconds")
    steps += [f"Discharge at {rng.uniform(0.9, 1.1):.2f}C for {int(rng.integers(40, 61))} seconds", "Discharge at 1.4C for 15 seconds"]
    return steps


def solar_day_steps(seed, pv_peak_C=0.22, house_C=0.05):
    """A home-storage battery's day in 15 min blocks (discharge positive): 06:00-08:00 the house's
    base load (`house_C`) with a 4 min kettle at 0.6C; 08:00-16:00 the PV surplus charges it (a
    half-sine of peak `pv_peak_C`, some blocks clouded to 30-80 %, less the base load); 16:00-20:00
    the evening load (0.06-0.2C, a 10 min cooker at 0.5C at 18:00); then the base load at 0.1C
    until the BMS stops at 3.2 V, and the night's rest (4 h)."""
    rng = np.random.default_rng(seed)
    steps = ["Rest for 10 minutes", f"Discharge at {house_C:.2f}C for 60 minutes", "Discharge at 0.6C for 4 minutes",
             f"Discharge at {house_C:.2f}C for 56 minutes"]
    for k in range(32):
        cloud = 1.0 if rng.uniform() < 0.65 else float(rng.uniform(0.3, 0.8))
        net = pv_peak_C * np.sin(np.pi * (k + 0.5) / 32) * cloud - house_C
        steps.append(f"Charge at {net:.3f}C for 15 minutes" if net > 0.005 else
                     f"Discharge at {-net:.3f}C for 15 minutes" if net < -0.005 else "Rest for 15 minutes")
    for k in range(16):
        if k == 8:
            steps += ["Discharge at 0.5C for 10 minutes", f"Discharge at {rng.uniform(0.06, 0.2):.3f}C for 5 minutes"]
        else:
            steps.append(f"Discharge at {rng.uniform(0.06, 0.2):.3f}C for 15 minutes")
    return steps + ["Discharge at 0.1C until 3.2 V", "Rest for 4 hours"]


def start_stop_steps(seed, stops):
    """A 48 V mild-hybrid's city duty per cell as current steps (discharge positive), per stop: the
    engine off at a light (accessories 0.3-0.5C, 20-60 s), the belt starter-generator's restart
    (4C for 2 s), an electric boost pulling away (1.5-2.5C, 4-10 s), the generator recharging
    (0.4-0.8C, 20-50 s), cruising with no battery current (20-90 s) and regenerative braking
    (1-2C charge, 4-8 s): the SOC drifts down a few per cent over 30 stops."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(stops):
        steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(20, 61))} seconds", "Discharge at 4C for 2 seconds",
                  f"Discharge at {rng.uniform(1.5, 2.5):.2f}C for {int(rng.integers(4, 11))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(20, 51))} seconds", f"Rest for {int(rng.integers(20, 91))} seconds",
                  f"Charge at {rng.uniform(1.0, 2.0):.2f}C for {int(rng.integers(4, 9))} seconds"]
    return steps


def batch_af(root):
    """Thirty-first batch (key "af"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients from 3 to 40 degC, each of the three models handed
    over (one DFN recording handed to the SPMe), sampling from 1 to 30 s, noise from 0.6 to 2 mV, and
    duties no earlier batch used: a UPS float with two mains outages, a home-storage day under a
    solar array, a multi-stage step-down charge from empty, a cordless power tool's bursts with
    its fast charger, a 48 V mild-hybrid's start-stop city duty in the cold, two drone flights and
    a recharge, a discharge with superimposed power pulses after a CC-CV charge, and a
    vehicle-to-grid evening with an overnight charge. Single effects (a 3 mOhm contact resistance;
    5 % lithium loss; 7 % negative active-material loss, lithium kept; lumped self-heating with the
    temperature recorded; exchange currents of both electrodes x0.6; negative particle diffusivity
    x0.25), a pair on the positive (7 % active-material loss with the positive exchange current
    x0.5, as cathode cracking and surface reconstruction give) and a DFN control. Words as an
    engineer would judge them: lithium loss by its own words, active material by "active
    material", the particle diffusivity by "particle" / "solid diffusiv" words (not the bare
    "diffusiv", which an electrolyte verdict could carry). Each effect's size on its own (the
    nominal candidate, or a replay, against the noise-free voltage) is in truth.json
    (effect_rmse_mV and the replay keys)."""
    cap = 5.0
    # af1: 3 mOhm contact resistance, a UPS float (CC-CV to 4.1 V, 90 min float) with two mains outages, 40 degC, 5 s, 2 mV, SPM
    p = chen()
    p.update({"Ambient temperature [K]": 313.15, "Initial temperature [K]": 313.15})
    p.update({"Contact resistance [Ohm]": 0.003}, check_already_exists=False)
    steps = ["Rest for 10 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V for 90 minutes", "Discharge at 2C for 5 minutes",
             "Discharge at 1C for 10 minutes", "Rest for 20 minutes", "Charge at C/2 until 4.1 V", "Hold at 4.1 V for 60 minutes",
             "Discharge at 1.5C for 12 minutes", "Rest for 30 minutes"]
    write_case(root, "af1_contact_3mOhm_ups_float_two_outages_40C_5s_2mV_spm", lion.SPM(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 313.15,
                "note": "a 3 mOhm contact resistance (a corroded busbar joint in a UPS string: 7.5 mV at C/2, 30 mV at 2C), at 40 "
                        "degC (a warm UPS cabinet; isothermal, not recorded). A UPS float duty from 60 % SOC: 10 min rest, C/2 to "
                        "4.1 V, float at 4.1 V for 90 min, a mains outage (2C for 5 min, then 1C for 10 min after load shedding), 20 "
                        "min rest (the generator takes over), C/2 to 4.1 V, float for 60 min, a second outage (1.5C for 12 min), 30 min "
                        "rest; sampled every 5 s, 2 mV noise (a noisy string monitor); SPM data and model. effect_rmse_mV is what the "
                        "resistance alone does (time-aligned on the experiment, whose CC charges end at other times)"},
               initial_soc=0.6, seed=3101, period=5, noise=2e-3, compare=lion.SPM())
    # af2: 5 % lithium loss, a home-storage day under a solar array (15 min blocks, to the BMS's 3.2 V), 35 degC, 30 s, 1.5 mV, DFN data handed to the SPMe
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95)
    p.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    steps = solar_day_steps(3102)
    name = "af2_inventory_5pct_home_storage_solar_day_35C_30s_dfn_data_spme"
    write_case(root, name, lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": ["inventory", "lithium loss", "lithium lost", "cyclable"],
                "ambient_temperature_K": 308.15,
                "note": "5 % less lithium (initial negative concentration x0.95; the initial state set as 45 % SOC of the aged cell), at "
                        "35 degC (a home-storage unit in a warm garage; isothermal, not recorded). A home-storage day in 15 min blocks "
                        "(solar_day_steps seed 3102): from 45 % SOC, 10 min rest, 2 h of base load at 0.05C with a 4 min kettle at "
                        "0.6C, 8 h of PV surplus charging (a half-sine to 0.22C less the base load, some blocks clouded), 4 h of "
                        "evening load (0.06-0.2C, a 10 min cooker at 0.5C), the base load at 0.1C until the BMS stops at 3.2 V, 4 h "
                        "rest (about 21 h); sampled every 30 s, 1.5 mV noise. DFN data handed to the SPMe: electrolyte transport "
                        "(SPMe -> DFN) named beside the loss is right too, but the first verdict must name the lithium. "
                        "spme_with_loss_rmse_mV: the SPMe with the true loss (the SPMe's own error against the DFN); "
                        "dfn_nominal_rmse_mV: the nominal DFN (what the loss alone does); both time-aligned on the experiment, whose "
                        "last discharge ends at another time"},
               initial_soc=0.45, seed=3102, period=30, noise=1.5e-3, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), p.copy(), steps, 0.45, "spme_with_loss_rmse_mV", period=30)
    p0 = chen(); p0.update({"Ambient temperature [K]": 308.15, "Initial temperature [K]": 308.15})
    replay_rmse(root, name, lion.DFN(), p0, steps, 0.45, "dfn_nominal_rmse_mV", period=30)
    # af3: 7 % negative LAM (lithium kept), a multi-stage step-down charge from near empty then a C/2 discharge, 12 degC, 5 s, DFN
    p = scaled(chen(), "Negative electrode active material volume fraction", 0.93)
    moved = (0.07 * 0.75 * p["Negative electrode thickness [m]"] * p["Initial concentration in negative electrode [mol.m-3]"]
             / (p["Positive electrode active material volume fraction"] * p["Positive electrode thickness [m]"]))
    p.update({"Initial concentration in positive electrode [mol.m-3]": p["Initial concentration in positive electrode [mol.m-3]"] + moved,
              "Ambient temperature [K]": 285.15, "Initial temperature [K]": 285.15})
    steps = ["Rest for 20 minutes", "Charge at 2C until 3.95 V", "Charge at 1C until 4.1 V", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20",
             "Rest for 1 hour", "Discharge at C/2 until 2.7 V", "Rest for 1 hour"]
    write_case(root, "af3_lam_negative_7pct_step_down_charge_from_empty_12C_5s_dfn", lion.DFN(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"], "ambient_temperature_K": 285.15,
                "note": "7 % loss of negative active material (volume fraction 0.75 -> 0.6975) with the lithium inventory kept (the "
                        f"lithium of the lost material moved into the positive's initial concentration, +{moved:.0f} mol/m3, so that "
                        "only the electrode's capacity changes: the negative reaches a stoichiometry of about 0.98 at 4.2 V instead "
                        "of 0.91), at 12 degC (isothermal, not recorded). A multi-stage step-down charge from near empty (5 % SOC of the "
                        "aged cell): 20 min rest, 2C to 3.95 V, 1C to 4.1 V, C/2 to 4.2 V, hold at 4.2 V until C/20, 1 h rest, C/2 to 2.7 V, 1 h rest; sampled every 5 s, 1 mV noise; DFN data and model. "
                        "effect_rmse_mV is what the loss alone does (time-aligned on the experiment, whose steps end at other times)"},
               initial_soc=0.05, seed=3103, period=5, compare=lion.DFN())
    # af4: lumped self-heating (h = 15, temperature recorded), a cordless power tool's 3C bursts and its 1.5C CC-CV charger, 15 degC, 1 s, 0.7 mV, SPMe
    p = chen()
    p.update({"Ambient temperature [K]": 288.15, "Initial temperature [K]": 288.15, "Total heat transfer coefficient [W.m-2.K-1]": 15.0})
    session = ["Discharge at 3C for 20 seconds", "Rest for 15 seconds"] * 12 + ["Rest for 5 minutes"]
    steps = ["Rest for 5 minutes"] + session * 3 + ["Charge at 1.5C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 20 minutes"]
    write_case(root, "af4_thermal_h15_recorded_power_tool_bursts_fast_charger_15C_1s_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 288.15,
                "note": "lumped self-heating, h = 15 W/(m2 K), ambient and initial 15 degC (a cordless tool's pack in a cool "
                        "workshop). From full: 5 min rest, 3 work sessions of 12 x (3C for 20 s, 15 s pause) each followed by a 5 min "
                        "pause (60 % of the charge out; the cell warms by up to 24 K, to 39 degC), then the tool charger's 1.5C CC-CV to 4.2 V "
                        "and C/10, 20 min rest; "
                        "temperature recorded (0.05 K noise, 0.1 K resolution); sampled every 1 s, 0.7 mV noise; SPMe (lumped thermal) "
                        "data handed to the isothermal SPMe. effect_rmse_mV is what the heating alone does (time-aligned on the "
                        "experiment, whose charge steps end at other times)"},
               initial_soc=1.0, temperature=True, seed=3104, period=1, noise=7e-4,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.SPMe())
    # af5: exchange currents of both electrodes x0.6, a 48 V mild-hybrid start-stop city duty (30 stops), 3 degC, 1 s, DFN
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.6)
    p.update({"Ambient temperature [K]": 276.15, "Initial temperature [K]": 276.15})
    steps = ["Rest for 10 minutes"] + start_stop_steps(3105, 30) + ["Rest for 20 minutes"]
    write_case(root, "af5_kinetics_both_x0p6_mild_hybrid_start_stop_3C_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"],
                "ambient_temperature_K": 276.15,
                "note": "exchange-current densities of both electrodes x0.6 (all stoichiometries; the activation energies kept), at 3 "
                        "degC (a winter morning; isothermal, not recorded). A 48 V mild-hybrid's city duty per cell from 60 % SOC "
                        "(start_stop_steps seed 3105, 30 stops): 10 min rest, then per stop the engine off at a light (accessories "
                        "0.3-0.5C, 20-60 s), the belt starter-generator's restart (4C for 2 s), an electric boost (1.5-2.5C, 4-10 s), "
                        "the generator recharging (0.4-0.8C, 20-50 s), cruising at no current (20-90 s), regenerative braking (1-2C "
                        "charge, 4-8 s); 20 min rest; sampled every 1 s, 1 mV noise; DFN data and model. effect_rmse_mV is what the "
                        "slower kinetics alone do"},
               initial_soc=0.6, seed=3105, period=1, compare=lion.DFN())
    # af6: negative particle diffusivity x0.25, two drone flights with a rest between and a 1C CC-CV recharge, 30 degC, 2 s, 0.6 mV, SPMe
    p = scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.25)
    p.update({"Ambient temperature [K]": 303.15, "Initial temperature [K]": 303.15})
    steps = (["Rest for 5 minutes"] + drone_flight(3106) + ["Rest for 15 minutes"] + drone_flight(31060)
             + ["Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"])
    write_case(root, "af6_diffusivity_negative_x0p25_drone_flights_30C_2s_spme", lion.SPMe(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 303.15,
                "note": "negative particle diffusivity x0.25 (8.25e-15 m2/s for the set's 3.3e-14), at 30 degC (isothermal, not "
                        "recorded). Two multirotor drone flights (drone_flight seeds 3106 and 31060: take-off climb at 2.4-2.8C, "
                        "hovers at 1.2-1.45C, forward-flight legs at 1.6-2.2C, gusts, descent and landing; about 10 min each at 1.6C "
                        "on average) from 95 % SOC: 5 min rest, flight, 15 min rest, flight, 20 min rest, 1C CC-CV to 4.2 V and C/20, "
                        "30 min rest; sampled every 2 s, 0.6 mV noise (a quiet channel); SPMe data and model. effect_rmse_mV is what "
                        "the slower diffusion alone does (time-aligned on the experiment, whose charge steps end at other times)"},
               initial_soc=0.95, seed=3106, period=2, noise=6e-4, compare=lion.SPMe())
    # af7: pair on the positive: 7 % LAM (lithium lost with it) and positive exchange current x0.5, a CC-CV charge then a discharge with power pulses, 20 degC, 3 s, 1.2 mV, SPM
    def cathode(lam, kinetics):
        q = scaled(scaled(chen(), "Positive electrode active material volume fraction", lam), "Positive electrode exchange-current density [A.m-2]", kinetics)
        q.update({"Ambient temperature [K]": 293.15, "Initial temperature [K]": 293.15})
        return q
    steps = (["Rest for 10 minutes", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"]
             + ["Discharge at C/2 for 10 minutes", "Discharge at 2C for 30 seconds"] * 7 + ["Discharge at C/2 until 2.8 V", "Rest for 1 hour"])
    name = "af7_lam_positive_7pct_and_kinetics_positive_x0p5_pulsed_discharge_20C_3s_spm"
    write_case(root, name, lion.SPM(), cathode(0.93, 0.5), steps,
               {"effect": "active_material_loss+kinetics", "candidate_model": "spm",
                "accept": ["active material", "kinetic|exchange|charge-transfer|charge transfer|reaction rate"], "ambient_temperature_K": 293.15,
                "note": "two effects on the positive electrode (as cathode particle cracking and surface reconstruction give): 7 % loss "
                        "of positive active material (volume fraction 0.665 -> 0.6185, the set's initial concentrations, so the "
                        "lithium of the lost material goes with it; the initial state set as 30 % SOC of the aged cell) and positive "
                        "exchange-current density x0.5, at 20 degC (isothermal, not recorded). From 30 % SOC: 10 min rest, C/3 CC-CV "
                        "to 4.2 V and C/20, 30 min rest, then a discharge with superimposed power pulses: 7 x (C/2 for 10 min, 2C for "
                        "30 s), C/2 to 2.8 V, 1 h rest; sampled every 3 s, 1.2 mV noise; SPM data and model. spm_lam_only_rmse_mV: the "
                        "SPM with the LAM alone against the recording (what the kinetics leave); spm_kinetics_only_rmse_mV: with the "
                        "kinetics alone (what the LAM leaves); these and effect_rmse_mV are time-aligned on the experiment, whose "
                        "steps end at other times"},
               initial_soc=0.3, seed=3107, period=3, noise=1.2e-3, compare=lion.SPM())
    replay_rmse(root, name, lion.SPM(), cathode(0.93, 1.0), steps, 0.3, "spm_lam_only_rmse_mV", period=3)
    replay_rmse(root, name, lion.SPM(), cathode(1.0, 0.5), steps, 0.3, "spm_kinetics_only_rmse_mV", period=3)
    # af8: control, a vehicle-to-grid evening (grid-requested discharge blocks) and an overnight C/4 CC-CV charge to 4.1 V, 28 degC, 10 s, 0.8 mV, DFN
    p = chen()
    p.update({"Ambient temperature [K]": 301.15, "Initial temperature [K]": 301.15})
    rng = np.random.default_rng(3108)
    steps = ["Rest for 10 minutes"]
    for _ in range(4):
        steps += [f"Discharge at {rng.uniform(0.25, 0.5):.2f}C for {int(rng.integers(10, 26))} minutes", f"Rest for {int(rng.integers(5, 21))} minutes"]
    steps += ["Rest for 1 hour", "Charge at C/4 until 4.1 V", "Hold at 4.1 V until C/25", "Rest for 1 hour"]
    write_case(root, "af8_control_v2g_evening_overnight_charge_28C_10s_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 301.15,
                "note": "negative control at 28 degC (isothermal, not recorded): DFN data and model, nothing concealed. A "
                        "vehicle-to-grid evening from 65 % SOC: 10 min rest, 4 grid-requested discharge blocks (0.25-0.5C for 10-25 "
                        "min, each followed by a 5-20 min rest; numpy seed 3108), 1 h rest (waiting for the off-peak tariff), an "
                        "overnight C/4 CC-CV charge to 4.1 V (an owner's 90 % limit) and C/25, 1 h rest; sampled every 10 s, 0.8 mV "
                        "noise"},
               initial_soc=0.65, seed=3108, period=10, noise=8e-4, compare=lion.DFN())


def ebike_commute(seed):
    """One pedal-assisted e-bike commute (about 20-25 min) as current steps per cell (discharge
    positive): a pull-away from home (1.2C for 20 s), then 10-13 segments of flat cruising with
    assist (0.3-0.6C, 60-150 s), sometimes a hill climb at full assist (1.2-2C, 40-100 s) followed
    by a free-wheeling descent (no current, 20-50 s), and a traffic-light stop (no current,
    15-50 s)."""
    rng = np.random.default_rng(seed)
    steps = ["Discharge at 1.2C for 20 seconds"]
    for _ in range(int(rng.integers(10, 14))):
        steps.append(f"Discharge at {rng.uniform(0.3, 0.6):.2f}C for {int(rng.integers(60, 151))} seconds")
        if rng.uniform() < 0.35:
            steps += [f"Discharge at {rng.uniform(1.2, 2.0):.2f}C for {int(rng.integers(40, 101))} seconds",
                      f"Rest for {int(rng.integers(20, 51))} seconds"]
        if rng.uniform() < 0.5:
            steps.append(f"Rest for {int(rng.integers(15, 51))} seconds")
    return steps


def phev_day_steps(seed, urban=25, highway=4, sustain=20):
    """A plug-in hybrid's trip per cell (discharge positive): charge-depleting electric driving,
    `urban` city segments (accelerate 1.5-2.5C for 5-10 s, cruise 0.4-0.9C for 20-60 s, regenerative
    braking 0.5-1.2C for 4-8 s, idle 5-25 s) and `highway` stints (cruise 1.0-1.4C for 3-5 min, an
    overtake at 2.5C for 8 s), then the charge-sustaining mode near the SOC reached, `sustain`
    cycles of the engine charging (0.6-1.0C for 15-25 s), electric assist (1.5-2.5C for 5-12 s),
    coasting (no current, 5-15 s) and regeneration (1C for 4-6 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(urban):
        steps += [f"Discharge at {rng.uniform(1.5, 2.5):.2f}C for {int(rng.integers(5, 11))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.9):.2f}C for {int(rng.integers(20, 61))} seconds",
                  f"Charge at {rng.uniform(0.5, 1.2):.2f}C for {int(rng.integers(4, 9))} seconds", f"Rest for {int(rng.integers(5, 26))} seconds"]
    for _ in range(highway):
        steps += [f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(180, 301))} seconds", "Discharge at 2.5C for 8 seconds"]
    for _ in range(sustain):
        steps += [f"Charge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(15, 26))} seconds",
                  f"Discharge at {rng.uniform(1.5, 2.5):.2f}C for {int(rng.integers(5, 13))} seconds",
                  f"Rest for {int(rng.integers(5, 16))} seconds", f"Charge at 1C for {int(rng.integers(4, 7))} seconds"]
    return steps


def phone_day_steps(seed, blocks=18):
    """A smartphone's day per cell (discharge positive) in blocks of 10-40 min: standby (0.02C),
    messaging and browsing (0.06-0.12C), video (0.12-0.18C), navigation or a game (0.2-0.35C), each
    sometimes followed by a camera burst (0.6C for 1-2 min); then the phone runs on at 0.2C until it
    shuts itself down at 3.3 V."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(blocks):
        kind = rng.choice(4, p=[0.5, 0.3, 0.1, 0.1])
        rate = [0.02, rng.uniform(0.06, 0.12), rng.uniform(0.12, 0.18), rng.uniform(0.2, 0.35)][kind]
        steps.append(f"Discharge at {rate:.3f}C for {int(rng.integers(10, 41))} minutes")
        if rng.uniform() < 0.2:
            steps.append(f"Discharge at 0.6C for {int(rng.integers(60, 121))} seconds")
    return steps + ["Discharge at 0.2C until 3.3 V"]


def delivery_route_steps(seed, drops):
    """A last-mile delivery van's round per cell (discharge positive): for each of `drops` drops,
    1-3 legs of pulling away (2-2.5C for 6-12 s), driving (0.4-0.9C for 20-60 s) and braking with
    regeneration (0.8-1.2C charge for 4-8 s), then the stop with the driver out (auxiliaries at
    0.05C for 1-4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(drops):
        for _ in range(int(rng.integers(1, 4))):
            steps += [f"Discharge at {rng.uniform(2.0, 2.5):.2f}C for {int(rng.integers(6, 13))} seconds",
                      f"Discharge at {rng.uniform(0.4, 0.9):.2f}C for {int(rng.integers(20, 61))} seconds",
                      f"Charge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(4, 9))} seconds"]
        steps.append(f"Discharge at 0.05C for {int(rng.integers(60, 241))} seconds")
    return steps


def agv_shift_steps(seed, tasks, dock_every=12):
    """An automated guided vehicle's (AGV's) duty in a warehouse per cell (discharge positive), for
    each of `tasks` tasks: travel to the pick (0.4-0.7C for 15-40 s), lift the load (1.5-2.2C for
    5-12 s), travel loaded (0.6-1.0C for 20-60 s), lower it with the lift motor regenerating
    (0.5C charge for 4-8 s) and wait for the next order (no current, 10-60 s); every `dock_every`
    tasks an opportunity charge at the dock (1C for 4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(tasks):
        steps += [f"Discharge at {rng.uniform(0.4, 0.7):.2f}C for {int(rng.integers(15, 41))} seconds",
                  f"Discharge at {rng.uniform(1.5, 2.2):.2f}C for {int(rng.integers(5, 13))} seconds",
                  f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(20, 61))} seconds",
                  f"Charge at 0.5C for {int(rng.integers(4, 9))} seconds", f"Rest for {int(rng.integers(10, 61))} seconds"]
        if (k + 1) % dock_every == 0:
            steps.append("Charge at 1C for 4 minutes")
    return steps


def strip_mowing_steps(rng, minutes, run_s, run_C, thick_s, thick_C, turn_C):
    """A mower working strips per cell (discharge positive), for about `minutes` min: each strip
    at `run_C` (low, high) for `run_s` (low, high + 1) s, in 30 % of strips thick grass or a slope
    at `thick_C` for `thick_s` s, then the turn at the strip's end at `turn_C` for 3-6 s."""
    steps, total = [], 0
    while total < 60 * minutes:
        s = int(rng.integers(*run_s))
        steps.append(f"Discharge at {rng.uniform(*run_C):.2f}C for {s} seconds")
        total += s
        if rng.uniform() < 0.3:
            s = int(rng.integers(*thick_s))
            steps.append(f"Discharge at {rng.uniform(*thick_C):.2f}C for {s} seconds")
            total += s
        s = int(rng.integers(3, 7))
        steps.append(f"Discharge at {turn_C}C for {s} seconds")
        total += s
    return steps


def mowing_steps(seed, minutes=35):
    """A ride-on electric mower's session per cell: blades and drive on ordinary grass (1.0-1.4C
    for 20-60 s), sometimes thick grass or a slope (1.8-2.4C for 10-25 s), and the turns at the
    end of each strip (0.6C, the blades still running)."""
    return strip_mowing_steps(np.random.default_rng(seed), minutes, (20, 61), (1.0, 1.4), (10, 26), (1.8, 2.4), 0.6)


def batch_ag(root):
    """Thirty-second batch (key "ag"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients no earlier batch used (1, 7, 11, 16, 21, 24, 29 and
    36 degC), each of the three models, sampling from 2 to 20 s (16 s telemetry, a BMS logger's 1 mV /
    10 mA resolution), noise from 0.5 to 1.5 mV, and duties no earlier batch used: two e-bike
    commutes and a charge, a plug-in hybrid's charge-depleting then charge-sustaining trip, a
    smartphone's day to its shutdown and a USB-PD fast charge, a C/3 CC-CV capacity cycle, a
    delivery van's round, an automated guided vehicle's duty in a chilled warehouse with
    opportunity charges, low-Earth-orbit partial cycles, and a ride-on mower's session with its
    charger. A control (SPMe), single effects (8 % positive active-material loss, the lithium going
    with it; 8 % negative active-material loss, lithium kept; electrolyte conductivity and
    diffusivity x0.5; a 3 mOhm contact resistance in the cold; 6 % lithium loss seen only through
    partial cycles that reach no cut-off; lumped self-heating with the temperature recorded) and a
    pair as SEI growth gives (5 % lithium loss with the negative exchange current x0.5). Words as
    in batches ae and af. Each effect's size on its own (the nominal candidate, or a replay, against
    the noise-free voltage) is in truth.json (effect_rmse_mV and the replay keys)."""
    at = at_temperature
    # ag1: control, SPMe, two e-bike commutes with a parked day between and a C/2 CC-CV charge, 24 degC, 4 s, a BMS logger's resolution
    p = at(chen(), 24)
    steps = (["Rest for 5 minutes"] + ebike_commute(3201) + ["Rest for 2 hours"] + ebike_commute(32010)
             + ["Rest for 30 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/15", "Rest for 30 minutes"])
    write_case(root, "ag1_control_ebike_commutes_cccv_24C_4s_bms_logger_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 297.15,
                "note": "negative control at 24 degC (isothermal, not recorded): SPMe data and model, nothing concealed. From 95 % "
                        "SOC: 5 min rest, a pedal-assisted e-bike commute (ebike_commute seed 3201: a 1.2C pull-away, cruising "
                        "with assist at 0.3-0.6C, hill climbs at 1.2-2C, free-wheeling descents and traffic-light stops at no "
                        "current), 2 h parked, the ride home (seed 32010), 30 min rest, the C/2 charger's CC-CV to 4.2 V and C/15, "
                        "30 min rest; sampled every 4 s, 1 mV noise, a BMS logger's resolution (1 mV, 10 mA) and 5 mA current noise"},
               initial_soc=0.95, seed=3201, period=4, cycler={"current_noise_A": 5e-3, "quantum_V": 1e-3, "quantum_A": 1e-2},
               compare=lion.SPMe())
    # ag2: pair, as SEI growth gives: 5 % lithium loss and negative exchange current x0.5, a plug-in hybrid's trip (charge depleting, then sustaining), 16 degC, 2 s, DFN
    def sei_aged(loss, kinetics):
        q = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.0 - loss)
        return at(scaled(q, "Negative electrode exchange-current density [A.m-2]", kinetics), 16)
    steps = ["Rest for 5 minutes"] + phev_day_steps(3202) + ["Rest for 30 minutes"]
    name = "ag2_kinetics_negative_x0p5_and_inventory_5pct_phev_depleting_sustaining_16C_2s_dfn"
    write_case(root, name, lion.DFN(), sei_aged(0.05, 0.5), steps,
               {"effect": "kinetics+lithium_inventory_loss", "candidate_model": "dfn",
                "accept": ["kinetic|exchange|charge-transfer|charge transfer|reaction rate", "inventory|lithium loss|lithium lost|cyclable"],
                "ambient_temperature_K": 289.15,
                "note": "two effects, as SEI growth on the graphite gives: 5 % less lithium (initial negative concentration x0.95; "
                        "the initial state set as 90 % SOC of the aged cell) and the negative exchange-current density x0.5 (all "
                        "stoichiometries; the activation energy kept), at 16 degC (isothermal, not recorded). A plug-in hybrid's "
                        "trip from 90 % SOC (phev_day_steps seed 3202): 5 min rest, charge-depleting electric driving (25 city "
                        "segments: 1.5-2.5C pull-aways, 0.4-0.9C cruising, 0.5-1.2C regenerative braking, idling; 4 highway stints "
                        "at 1.0-1.4C for 3-5 min with a 2.5C overtake) down to about 30 %, then the charge-sustaining mode there "
                        "(20 cycles of the engine charging at 0.6-1C, electric assist at 1.5-2.5C, coasting, 1C regeneration), 30 "
                        "min rest; sampled every 2 s, 1 mV noise; DFN data and model. dfn_inventory_only_rmse_mV: the DFN with the "
                        "lithium loss alone against the recording (what the kinetics leave); dfn_kinetics_only_rmse_mV: with the "
                        "kinetics alone (what the lithium loss leaves)"},
               initial_soc=0.9, seed=3202, period=2, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), sei_aged(0.05, 1.0), steps, 0.9, "dfn_inventory_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.DFN(), sei_aged(0.0, 0.5), steps, 0.9, "dfn_kinetics_only_rmse_mV", period=2)
    # ag3: 8 % positive LAM (the lithium of the lost material goes with it), a smartphone's day to its 3.3 V shutdown and a USB-PD fast charge, 36 degC, 15 s, 1.5 mV, SPM
    p = at(scaled(chen(), "Positive electrode active material volume fraction", 0.92), 36)
    steps = ["Rest for 10 minutes"] + phone_day_steps(3203) + ["Rest for 30 minutes", "Charge at 1.5C until 4.2 V", "Hold at 4.2 V until C/20",
                                                                "Rest for 30 minutes"]
    write_case(root, "ag3_lam_positive_8pct_smartphone_day_fast_charge_36C_15s_spm", lion.SPM(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"], "ambient_temperature_K": 309.15,
                "note": "8 % loss of positive active material (volume fraction 0.665 -> 0.6118, the set's initial concentrations, so "
                        "the lithium of the lost material goes with it: PyBaMM's plain volume-fraction change; the initial state set "
                        "as full charge of the aged cell), at 36 degC (a phone in a pocket; isothermal, not recorded). A smartphone's "
                        "day from full (phone_day_steps seed 3203): 10 min rest, 18 blocks of 10-40 min (standby 0.02C, browsing "
                        "0.06-0.12C, video 0.12-0.18C, navigation or a game 0.2-0.35C, some 0.6C camera bursts), then 0.2C until the phone "
                        "shuts down at 3.3 V, 30 min rest, a USB-PD fast charge (1.5C to 4.2 V, hold until C/20), 30 min rest; "
                        "sampled every 15 s, 1.5 mV noise; SPM data and model. effect_rmse_mV is what the loss alone does "
                        "(time-aligned on the experiment, whose last steps end at other times)"},
               initial_soc=1.0, seed=3203, period=15, noise=1.5e-3, compare=lion.SPM())
    # ag4: 8 % negative LAM (lithium kept), a C/3 CC-CV capacity cycle (discharge, charge, discharge), 21 degC, 20 s, 0.5 mV, SPMe
    lost = 0.08
    p = scaled(chen(), "Negative electrode active material volume fraction", 1.0 - lost)
    moved = (lost * 0.75 * p["Negative electrode thickness [m]"] * p["Initial concentration in negative electrode [mol.m-3]"]
             / (p["Positive electrode active material volume fraction"] * p["Positive electrode thickness [m]"]))
    p.update({"Initial concentration in positive electrode [mol.m-3]": p["Initial concentration in positive electrode [mol.m-3]"] + moved})
    p = at(p, 21)
    steps = ["Rest for 10 minutes", "Discharge at C/3 until 2.5 V", "Rest for 1 hour", "Charge at C/3 until 4.2 V", "Hold at 4.2 V until C/50",
             "Rest for 1 hour", "Discharge at C/3 until 2.5 V", "Rest for 1 hour"]
    write_case(root, "ag4_lam_negative_8pct_lithium_kept_c3_cccv_capacity_cycle_21C_20s_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 294.15,
                "note": "8 % loss of negative active material (volume fraction 0.75 -> 0.69) with the lithium inventory kept (the "
                        f"lithium of the lost material moved into the positive's initial concentration, +{moved:.0f} mol/m3, so that "
                        "only the electrode's capacity changes: the negative's stoichiometry at 4.2 V rises towards 1), at 21 degC "
                        "(a lab bench; isothermal, not recorded). A capacity cycle from 50 % SOC of the aged cell: 10 min rest, C/3 "
                        "to 2.5 V, 1 h rest, C/3 CC-CV to 4.2 V and C/50, 1 h rest, C/3 to 2.5 V, 1 h rest; sampled every 20 s, 0.5 "
                        "mV noise (a precision cycler channel); SPMe data and model. effect_rmse_mV is what the loss alone does "
                        "(time-aligned on the experiment, whose steps end at other times)"},
               initial_soc=0.5, seed=3204, period=20, noise=5e-4, compare=lion.SPMe())
    # ag5: electrolyte conductivity and diffusivity x0.5, a delivery van's round (18 drops) and its return to the depot, 11 degC, 2 s, DFN
    p = at(scaled(scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.5), "Electrolyte diffusivity [m2.s-1]", 0.5), 11)
    steps = (["Rest for 5 minutes"] + delivery_route_steps(3205, 18) + ["Discharge at 0.9C for 10 minutes", "Charge at 1C for 6 seconds",
                                                                         "Rest for 30 minutes"])
    write_case(root, "ag5_electrolyte_x0p5_delivery_van_round_11C_2s_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 284.15,
                "note": "electrolyte conductivity and diffusivity both x0.5 (all concentrations; an aged electrolyte, salt and "
                        "solvent lost), at 11 degC (isothermal, not recorded). A last-mile delivery van's round per cell from 85 % SOC "
                        "(delivery_route_steps seed 3205, 18 drops): 5 min rest, per drop 1-3 legs of a 2-2.5C pull-away (6-12 s), "
                        "0.4-0.9C driving (20-60 s) and 0.8-1.2C regenerative braking (4-8 s), then the stop with auxiliaries at 0.05C "
                        "(1-4 min); the return to the depot (0.9C for 10 min, 1C regeneration for 6 s), 30 min rest; sampled every 2 "
                        "s, 1 mV noise; DFN data and model. effect_rmse_mV is what the electrolyte alone does"},
               initial_soc=0.85, seed=3205, period=2, compare=lion.DFN())
    # ag6: 3 mOhm contact resistance, an AGV's duty in a chilled warehouse with opportunity charges at the dock, 1 degC, 2 s, 1.2 mV, SPMe
    p = at(chen(), 1)
    p.update({"Contact resistance [Ohm]": 0.003}, check_already_exists=False)
    steps = ["Rest for 10 minutes"] + agv_shift_steps(3206, 36) + ["Rest for 20 minutes"]
    write_case(root, "ag6_contact_3mOhm_agv_chilled_warehouse_dock_charges_1C_2s_spme", lion.SPMe(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 274.15,
                "note": "a 3 mOhm contact resistance (a loose pack connector: 33 mV at the 2.2C lifts), at 1 degC (a chilled "
                        "warehouse; isothermal, not recorded). An automated guided vehicle's duty from 70 % SOC (agv_shift_steps seed "
                        "3206, 36 tasks): 10 min rest, per task travel to the pick (0.4-0.7C, 15-40 s), the lift (1.5-2.2C, 5-12 s), "
                        "loaded travel (0.6-1C, 20-60 s), lowering with regeneration (0.5C charge, 4-8 s) and a wait (10-60 s); "
                        "every 12 tasks a 1C opportunity charge at the dock for 4 min; 20 min rest; sampled every 2 s, 1.2 mV noise; "
                        "SPMe data and model. effect_rmse_mV is what the resistance alone does"},
               initial_soc=0.7, seed=3206, period=2, noise=1.2e-3, compare=lion.SPMe())
    # ag7: 6 % lithium loss, low-Earth-orbit partial cycles (35 min eclipse, 60 min sun) that never reach a cut-off, 7 degC, 16 s, 0.8 mV, DFN
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94), 7)
    orbit = ["Discharge at 0.4C for 35 minutes", "Charge at 0.35C for 40 minutes", "Rest for 20 minutes"]
    steps = ["Rest for 20 minutes"] + orbit * 6
    write_case(root, "ag7_inventory_6pct_leo_orbit_partial_cycles_7C_16s_dfn", lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "dfn", "accept": ["inventory", "lithium loss", "lithium lost", "cyclable"],
                "ambient_temperature_K": 280.15,
                "note": "6 % less lithium (initial negative concentration x0.94; the initial state set as 85 % SOC of the aged "
                        "cell), at 7 degC (a satellite's thermally controlled battery; isothermal, not recorded). Low-Earth-orbit "
                        "partial cycles that never reach a voltage cut-off or a CV phase: 20 min rest, then 6 orbits of a 35 min "
                        "eclipse at 0.4C, 40 min of sunlit charging at 0.35C and 20 min with the solar array carrying the loads "
                        "(no battery current); each orbit 23 % of the charge out and back; sampled every 16 s (telemetry), 0.8 mV "
                        "noise; DFN data and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=0.85, seed=3207, period=16, noise=8e-4, compare=lion.DFN())
    # ag8: lumped self-heating, h = 8, temperature recorded, a ride-on mower's session then its 1C CC-CV charger, 29 degC, 2 s, SPM
    p = at(chen(), 29)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 8.0})
    steps = (["Rest for 5 minutes"] + mowing_steps(3208) + ["Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10",
                                                           "Rest for 20 minutes"])
    write_case(root, "ag8_thermal_h8_recorded_ride_on_mower_session_charge_29C_2s_spm", lion.SPM(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spm", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 302.15,
                "note": "lumped self-heating, h = 8 W/(m2 K) (a closed battery box under the seat), ambient and initial 29 degC (a "
                        "summer afternoon). A ride-on electric mower's session from full (mowing_steps seed 3208, about 35 min: "
                        "ordinary grass at 1.0-1.4C for 20-60 s, thick grass or a slope at 1.8-2.4C for 10-25 s, 0.6C turns), 20 min "
                        "rest, its 1C CC-CV charger to 4.2 V and C/10, 20 min rest; temperature recorded (0.05 K noise, 0.1 K "
                        "resolution); sampled every 2 s, 1 mV noise; SPM (lumped thermal) data handed to the isothermal SPM. "
                        "effect_rmse_mV is what the heating alone does (time-aligned on the experiment, whose charge steps end at "
                        "other times). The cell warms by about 10 K in the mowing (to about 39 degC) and is still 4-7 K above the ambient in the charge"},
               initial_soc=1.0, temperature=True, seed=3208, period=2, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPM())


def power_tool_steps(seed, cuts):
    """A cordless circular saw's work per cell (discharge positive): for each of `cuts` cuts the
    motor's inrush (4C for 1 s), the cut (2.6-3.4C for 4-12 s) and the repositioning of the board
    (no current, 5-40 s); every 8-12 cuts a pause of 2-5 min to measure and mark."""
    rng = np.random.default_rng(seed)
    steps, since = [], 0
    pause_after = int(rng.integers(8, 13))
    for _ in range(cuts):
        steps += ["Discharge at 4C for 1 second", f"Discharge at {rng.uniform(2.6, 3.4):.2f}C for {int(rng.integers(4, 13))} seconds",
                  f"Rest for {int(rng.integers(5, 41))} seconds"]
        since += 1
        if since == pause_after:
            steps.append(f"Rest for {int(rng.integers(120, 301))} seconds")
            since, pause_after = 0, int(rng.integers(8, 13))
    return steps


def frequency_regulation_current(seed, hours, capacity_A_h=5.0, peak_C=0.8, dt=5.0, management=0.5):
    """A grid battery's frequency-regulation duty as a cell current at `dt` s knots (A, discharge
    positive, linear between knots): the regulation signal is a sum of a slow (15 min), a medium
    (2 min) and a fast (15 s) first-order random process, a 3 % deadband, scaled so that its peak
    is `peak_C`; the controller's state-of-charge management pulls the charge moved back towards
    where it started (a 1C correction per `management` of the capacity away), as a regulation
    provider's base-point does."""
    rng = np.random.default_rng(seed)
    n = int(round(hours * 3600 / dt)) + 1
    parts = []
    for tau, weight in [(900.0, 0.6), (120.0, 0.3), (15.0, 0.1)]:
        a = np.exp(-dt / tau)
        x = np.zeros(n)
        for k in range(1, n):
            x[k] = a * x[k - 1] + np.sqrt(1 - a * a) * rng.normal()
        parts.append(weight * x)
    r = np.sum(parts, axis=0)
    r = r / np.max(np.abs(r))
    r = np.where(np.abs(r) < 0.03, 0.0, r)
    current = np.zeros(n)
    moved = 0.0
    for k in range(n):
        correction = moved / (management * capacity_A_h * 3600) * capacity_A_h
        current[k] = float(np.clip(peak_C * capacity_A_h * r[k] - correction, -peak_C * capacity_A_h, peak_C * capacity_A_h))
        moved += current[k] * dt
    current[0] = current[-1] = 0.0
    return np.column_stack([np.arange(n) * dt, current])


def forklift_shift_steps(seed, tasks, break_after):
    """An electric forklift's shift per cell (discharge positive), for each of `tasks` pallet moves:
    drive empty to the rack (0.5-0.9C for 15-45 s), lift the loaded forks (2.0-2.8C for 6-14 s),
    drive loaded (0.6-1.0C for 20-60 s), brake and lower the forks with regeneration (0.4-0.8C
    charge for 3-6 s) and wait at the dock (auxiliaries at 0.02C, 20-90 s); a 30 min break (no
    current) after `break_after` tasks."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(tasks):
        steps += [f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(15, 46))} seconds",
                  f"Discharge at {rng.uniform(2.0, 2.8):.2f}C for {int(rng.integers(6, 15))} seconds",
                  f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(20, 61))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(3, 7))} seconds",
                  f"Discharge at 0.02C for {int(rng.integers(20, 91))} seconds"]
        if k + 1 == break_after:
            steps.append("Rest for 30 minutes")
    return steps


def evtol_mission(seed):
    """One electric vertical take-off and landing (eVTOL) air-taxi hop per cell (discharge
    positive), scaled to an energy cell: avionics on the pad (0.05C for 2 min), the vertical
    take-off hover (2.0-2.4C for 60-90 s), the transition and climb (1.5-1.8C for 40-60 s), 4-6
    stretches of wing-borne cruise (0.6-0.8C for 2-3 min each), the descent (0.3-0.45C for 60-90 s),
    the transition back to thrust-borne flight (1.4C for 30 s) and the landing hover (2.2-2.6C for
    60-90 s, at the lowest state of charge of the hop)."""
    rng = np.random.default_rng(seed)
    steps = ["Discharge at 0.05C for 2 minutes", f"Discharge at {rng.uniform(2.0, 2.4):.2f}C for {int(rng.integers(60, 91))} seconds",
             f"Discharge at {rng.uniform(1.5, 1.8):.2f}C for {int(rng.integers(40, 61))} seconds"]
    for _ in range(int(rng.integers(4, 7))):
        steps.append(f"Discharge at {rng.uniform(0.6, 0.8):.2f}C for {int(rng.integers(120, 181))} seconds")
    steps += [f"Discharge at {rng.uniform(0.3, 0.45):.2f}C for {int(rng.integers(60, 91))} seconds", "Discharge at 1.4C for 30 seconds",
              f"Discharge at {rng.uniform(2.2, 2.6):.2f}C for {int(rng.integers(60, 91))} seconds"]
    return steps


def ferry_day_steps(seed, crossings):
    """An electric car ferry's day per cell (discharge positive), for each of `crossings` crossings:
    casting off and manoeuvring (0.8-1.0C for 60-120 s), the crossing in 2-3 legs of 0.4-0.6C
    (5-8 min each, the sea state changing the load), the approach and berthing (0.6-0.9C for
    60-120 s), then at the berth the automatic shore-power plug charges at 1C for 8-12 min (or
    until 4.2 V) while the cars drive off and on, and 2-4 min with the plug out before the next
    departure: about 1 % of the charge lost per crossing."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(crossings):
        steps.append(f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for {int(rng.integers(60, 121))} seconds")
        for _ in range(int(rng.integers(2, 4))):
            steps.append(f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(5, 9))} minutes")
        steps += [f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(60, 121))} seconds",
                  f"Charge at 1C for {int(rng.integers(8, 13))} minutes or until 4.2 V", f"Rest for {int(rng.integers(2, 5))} minutes"]
    return steps


def recorded_current_rmse(root, name, model, params, initial_soc, key):
    """Adds to `name`'s truth.json, under `key`, the RMS difference (mV) between the recorded voltage and
    `model` with `params` driven by the recorded current itself (linear between the recorded points, a
    step where a time repeats taken over 10 ms; every recorded time a stop of the integrator, whose
    tolerances are 1e-6 here: at 1e-8 the DFN's integrator fails at such stops) from `initial_soc`,
    at the recording's single (not repeated) times: what an effect does on its own when voltage-limited steps (a CC-CV charge, a charge
    "until" a voltage) end at other times in the two models, where the experiment-aligned replays of
    `replay_rmse` and `compare` measure the misalignment too (voltage cut-offs widened to 2.0-4.6 V so
    that a replay starting full is not stopped at once)."""
    folder = os.path.join(root, name)
    data = np.loadtxt(os.path.join(folder, "recording.csv"), delimiter=",", skiprows=1)
    t, i, v = data[:, 0].copy(), data[:, 1], data[:, 2]
    single = single_times(t)
    ts = t.copy()
    for k in range(1, len(ts)):
        if ts[k] - ts[k - 1] <= 1e-6:
            ts[k] = ts[k - 1] + 0.01
    p = params.copy()
    p.update({"Current function [A]": pybamm.Interpolant(ts, i, pybamm.t, name="recorded current"),
              "Upper voltage cut-off [V]": 4.6, "Lower voltage cut-off [V]": 2.0})
    sim = pybamm.Simulation(model, parameter_values=p, solver=pybamm.IDAKLUSolver(rtol=1e-6, atol=1e-6))
    sol = sim.solve(t_eval=ts, initial_soc=initial_soc)
    d = v[single] - sol["Voltage [V]"](t=ts[single])
    record_rmse(folder, name, key, d)


def batch_ah(root):
    """Thirty-third batch (key "ah"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -3, 6, 9, 19, 27, 34, 39 and 42 degC, each of the
    three models (one DFN recording handed to the SPMe), sampling from 1 to 30 s, noise from 0.5 to 2
    mV, and duties no earlier batch used: a cordless circular saw on a winter building site, a grid
    battery's frequency-regulation duty, an electric forklift's shift in a cold store and its
    charger, eVTOL air-taxi hops with fast turnaround charges, an electric car ferry's crossings with
    shore-power charging at each berth, an EV's multi-step DC fast charge then a highway run, an HPPC
    at seven states of charge, and an off-grid telecom site's constant-power nights and genset
    charges. A control (SPM in the frost), single effects (one-state OCV hysteresis of the negative,
    +-12 mV; 10 % positive active-material loss, the lithium going with it; 8 % lithium loss seen by
    the SPMe through DFN data; exchange currents of both electrodes x0.6; a voltage channel reading
    0.4 % low) and two pairs (a 3 mOhm contact resistance with lumped self-heating, temperature
    recorded; negative particle diffusivity x0.2 with 5 % lithium loss). Words as in batches ae-ag;
    the voltage gain as in a4. Each effect's size on its own (the nominal candidate, or a replay,
    against the noise-free voltage) is in truth.json (effect_rmse_mV and the replay keys; where a
    charge ends on a voltage, a replay driven by the recorded current, `recorded_current_rmse`)."""
    at = at_temperature
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    # ah1: control, a cordless circular saw's cuts on a winter building site, -3 degC, 1 s, 0.5 mV, SPM
    p = at(chen(), -3)
    steps = ["Rest for 10 minutes"] + power_tool_steps(3301, 60) + ["Rest for 30 minutes"]
    write_case(root, "ah1_control_circular_saw_cuts_minus3C_1s_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 270.15,
                "note": "negative control at -3 degC (a building site in winter; isothermal, not recorded): SPM data and model, "
                        "nothing concealed. From 95 % SOC: 10 min rest, 60 cuts of a cordless circular saw (power_tool_steps seed "
                        "3301: per cut a 4C inrush for 1 s, the cut at 2.6-3.4C for 4-12 s, 5-40 s repositioning at no current; a "
                        "2-5 min pause to measure and mark every 8-12 cuts), 30 min rest; no charge (a tool charger refuses below 0 "
                        "degC); sampled every 1 s, 0.5 mV noise (a quiet channel)"},
               initial_soc=0.95, seed=3301, period=1, noise=5e-4, compare=lion.SPM())
    # ah2: one-state hysteresis of the negative OCP, +-12 mV, a grid battery's frequency-regulation duty around 55 %, 27 degC, 5 s, 0.8 mV, SPMe
    p = at(chen(), 27)
    with_negative_hysteresis(p, 0.012)
    morning, afternoon = frequency_regulation_current(3302, 2.5), frequency_regulation_current(33020, 2.5)
    steps = ["Rest for 10 minutes", pybamm.step.current(morning), "Rest for 30 minutes", pybamm.step.current(afternoon), "Rest for 40 minutes"]
    write_case(root, "ah2_hysteresis_negative_12mV_frequency_regulation_27C_5s_spme",
               lion.SPMe(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "hysteresis", "candidate_model": "spme", "accept": ["hysteresis"], "ambient_temperature_K": 300.15,
                "note": "one-state OCV hysteresis of the negative electrode, lithiation and delithiation OCPs 12 mV either side of the "
                        "set's (decay rate 10, initial state 0, the middle), the positive without; at 27 degC (a grid battery's "
                        "air-conditioned container; isothermal, not recorded). From 55 % SOC: 10 min rest, 2.5 h of "
                        "frequency regulation (frequency_regulation_current seed 3302: slow, medium and fast random components, a 3 % "
                        "deadband, scaled to 0.8C at its extreme, state-of-charge management pulling back to the start at 1C per 50 % "
                        "away, so the current stays within 0.55C either way and the state of charge wanders up to 15-20 % from 55 %; a 5 s signal, linear "
                        "between its points), 30 min rest (not dispatched for a market period), another 2.5 h (seed 33020), 40 min "
                        "rest; sampled every 5 s (the signal's own points), 0.8 mV noise; SPMe data, the SPMe without hysteresis given. "
                        "effect_rmse_mV is what the hysteresis alone does"},
               initial_soc=0.55, seed=3302, period=5, noise=8e-4, compare=lion.SPMe())
    # ah3: 10 % positive LAM (the lithium of the lost material goes with it), a forklift's shift in a cold store and its charger, 6 degC, 3 s, 1.5 mV, DFN
    p = at(scaled(chen(), "Positive electrode active material volume fraction", 0.9), 6)
    steps = (["Rest for 10 minutes"] + forklift_shift_steps(3303, 36, 18)
             + ["Rest for 30 minutes", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"])
    write_case(root, "ah3_lam_positive_10pct_forklift_shift_cold_store_charger_6C_3s_dfn", lion.DFN(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"], "ambient_temperature_K": 279.15,
                "note": "10 % loss of positive active material (volume fraction 0.665 -> 0.5985, the set's initial concentrations, so "
                        "the lithium of the lost material goes with it: PyBaMM's plain volume-fraction change; the initial state set "
                        "as 95 % SOC of the aged cell), at 6 degC (a cold store's loading dock; isothermal, not recorded). An electric "
                        "forklift's shift from 95 % SOC (forklift_shift_steps seed 3303, 36 pallet moves: drive empty at 0.5-0.9C, lift "
                        "at 2.0-2.8C for 6-14 s, drive loaded at 0.6-1.0C, regenerative braking and lowering at 0.4-0.8C charge, 0.02C "
                        "auxiliaries at the dock; a 30 min break after 18 moves; down to about 30 %), 30 min rest, the C/2 CC-CV charger to 4.2 V and "
                        "C/20, 30 min rest; sampled every 3 s, 1.5 mV noise; DFN data and model. effect_rmse_mV is what the loss alone "
                        "does (time-aligned on the experiment, whose charge steps end at other times); "
                        "dfn_nominal_recorded_current_rmse_mV: the nominal DFN driven by the recorded current against the recording"},
               initial_soc=0.95, seed=3303, period=3, noise=1.5e-3, compare=lion.DFN())
    recorded_current_rmse(root, "ah3_lam_positive_10pct_forklift_shift_cold_store_charger_6C_3s_dfn", lion.DFN(), at(chen(), 6), 0.95,
                          "dfn_nominal_recorded_current_rmse_mV")
    # ah4: pair, a 3 mOhm contact resistance with lumped self-heating (h = 8, temperature recorded), eVTOL hops with turnaround charges, 39 degC, 2 s, SPMe
    def evtol_cell(contact, h):
        q = at(chen(), 39)
        q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
        if h is not None:
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": h})
        return q
    turnaround = ["Rest for 10 minutes", "Charge at 1C for 15 minutes or until 4.2 V", "Rest for 5 minutes"]
    steps = (["Rest for 5 minutes"] + evtol_mission(3304) + turnaround + evtol_mission(33040) + turnaround + evtol_mission(33041)
             + ["Rest for 30 minutes"])
    name = "ah4_contact_3mOhm_and_thermal_h8_recorded_evtol_hops_39C_2s_spme"
    write_case(root, name, lion.SPMe(options={"thermal": "lumped", "contact resistance": "true"}), evtol_cell(0.003, 8.0), steps,
               {"effect": "contact_resistance+thermal", "candidate_model": "spme",
                "accept": ["contact|series resistance|ohmic", "thermal|self-heating|heat"], "ambient_temperature_K": 312.15,
                "note": "two effects: a 3 mOhm contact resistance (a worn high-current connector: 30-40 mV at the 2-2.6C hovers) and lumped "
                        "self-heating, h = 8 W/(m2 K) (a tightly packed, poorly cooled pack), ambient and initial 39 degC (a hot "
                        "vertiport apron). From 95 % SOC: 5 min rest, three eVTOL air-taxi hops (evtol_mission seeds 3304, 33040, "
                        "33041, scaled to an energy cell: 0.05C avionics on the pad, a 2.0-2.4C take-off hover, a 1.5-1.8C transition and "
                        "climb, 0.6-0.8C cruise for 8-18 min, a 0.3-0.45C descent, a 1.4C transition and a 2.2-2.6C landing hover), each "
                        "of the first two followed by a turnaround (10 min rest, 1C charge for 15 min or to 4.2 V, 5 min rest), 30 min "
                        "rest; the cell warms by about 15 K (to about 54 degC) in the hops; "
                        "temperature recorded (0.05 K noise, 0.1 K resolution); sampled every 2 s, 1 mV noise; SPMe (lumped thermal, "
                        "contact resistance) data handed to the isothermal SPMe. Driven by the recorded current against the recording: "
                        "spme_nominal_recorded_current_rmse_mV the nominal isothermal SPMe (the two effects partly cancel: the "
                        "resistance raises the overpotentials, the heating lowers them); spme_contact_only_rmse_mV the isothermal SPMe "
                        "with the contact resistance alone (what the heating leaves); spme_thermal_only_rmse_mV the lumped SPMe "
                        "without the contact resistance (what the resistance leaves). effect_rmse_mV is time-aligned on the "
                        "experiment, whose turnaround charges may end at other times"},
               initial_soc=0.95, temperature=True, seed=3304, period=2, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPMe())
    recorded_current_rmse(root, name, lion.SPMe(), at(chen(), 39), 0.95, "spme_nominal_recorded_current_rmse_mV")
    recorded_current_rmse(root, name, lion.SPMe(options={"contact resistance": "true"}), evtol_cell(0.003, None), 0.95, "spme_contact_only_rmse_mV")
    recorded_current_rmse(root, name, lion.SPMe(options={"thermal": "lumped"}), evtol_cell(0.0, 8.0), 0.95, "spme_thermal_only_rmse_mV")
    # ah5: 8 % lithium loss, an electric car ferry's crossings with shore charging at each berth and the overnight charge, 9 degC, 10 s, 1.2 mV, DFN data handed to the SPMe
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.92), 9)
    steps = (["Rest for 10 minutes"] + ferry_day_steps(3305, 8)
             + ["Rest for 1 hour", "Charge at C/4 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour"])
    name = "ah5_inventory_8pct_ferry_crossings_shore_charging_9C_10s_dfn_data_spme"
    write_case(root, name, lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": lithium_words, "ambient_temperature_K": 282.15,
                "note": "8 % less lithium (initial negative concentration x0.92; the initial state set as 70 % SOC of the aged cell), "
                        "at 9 degC (a ferry's battery room cooled by the sea; isothermal, not recorded). An electric car ferry's day "
                        "(ferry_day_steps seed 3305, 8 crossings) from 70 % SOC: 10 min rest, per crossing casting off at 0.8-1.0C "
                        "for 1-2 min, 2-3 legs at 0.4-0.6C of 5-8 min, berthing at 0.6-0.9C for 1-2 min, shore-power charging at 1C "
                        "for 8-12 min (or to 4.2 V) and 2-4 min with the plug out (the state of charge between about 50 and 70 %); then 1 h rest, the overnight C/4 CC-CV to 4.2 V and "
                        "C/20, 1 h rest; sampled every 10 s, 1.2 mV noise. DFN data handed to the SPMe: electrolyte transport (SPMe "
                        "-> DFN) named beside the loss is right too, but the first verdict must name the lithium. "
                        "Driven by the recorded current against the recording: spme_with_loss_rmse_mV the SPMe with the true loss (the "
                        "SPMe's own error against the DFN); dfn_nominal_rmse_mV the nominal DFN (what the loss alone does); "
                        "spme_nominal_recorded_current_rmse_mV the nominal SPMe (both). effect_rmse_mV is time-aligned on the "
                        "experiment, whose charges end at other times"},
               initial_soc=0.7, seed=3305, period=10, noise=1.2e-3, compare=lion.SPMe())
    recorded_current_rmse(root, name, lion.SPMe(), p, 0.7, "spme_with_loss_rmse_mV")
    recorded_current_rmse(root, name, lion.DFN(), at(chen(), 9), 0.7, "dfn_nominal_rmse_mV")
    recorded_current_rmse(root, name, lion.SPMe(), at(chen(), 9), 0.7, "spme_nominal_recorded_current_rmse_mV")
    # ah6: exchange currents of both electrodes x0.6, an EV's multi-step DC fast charge then a highway run, 34 degC, 1 s, 2 mV, DFN
    p = chen()
    for side in ["Negative", "Positive"]:
        p = scaled(p, f"{side} electrode exchange-current density [A.m-2]", 0.6)
    p = at(p, 34)
    steps = ["Rest for 5 minutes", "Charge at 1.5C for 14 minutes", "Charge at 1C for 12 minutes", "Charge at 0.5C for 6 minutes",
             "Rest for 10 minutes", pybamm.step.current(highway_drive(3306, laps=2)), "Rest for 20 minutes"]
    write_case(root, "ah6_kinetics_both_x0p6_ev_dc_fast_charge_highway_34C_1s_2mV_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": kinetic_words, "ambient_temperature_K": 307.15,
                "note": "exchange-current densities of both electrodes x0.6 (all stoichiometries; the activation energies kept), at "
                        "34 degC (a summer road trip; isothermal, not recorded). From 15 % SOC: 5 min rest, an EV's multi-step DC "
                        "fast charge on the charger's current schedule (1.5C for 14 min, 1C for 12 min, 0.5C for 6 min: to about 75 %), 10 min rest, a highway run "
                        "(highway_drive seed 3306, 2 laps of 600 s: on-ramps to 3.5-4C, cruising at 1.2-2C, overtakes, regeneration "
                        "to 1-2C; ramps between 1 s points), 20 min rest; sampled every 1 s, 2 mV noise (an automotive BMS channel); "
                        "DFN data and model. effect_rmse_mV is what the slower kinetics alone do"},
               initial_soc=0.15, seed=3306, period=1, noise=2e-3, compare=lion.DFN())
    # ah7: pair, negative particle diffusivity x0.2 and 5 % lithium loss, an HPPC at seven states of charge, 19 degC, 2 s, 0.7 mV, DFN
    def aged(loss, diffusivity):
        q = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.0 - loss)
        return at(scaled(q, "Negative particle diffusivity [m2.s-1]", diffusivity), 19)
    level = ["Discharge at 2C for 10 seconds", "Rest for 40 seconds", "Charge at 1C for 10 seconds", "Rest for 2 minutes",
             "Discharge at 1C for 6 minutes", "Rest for 40 minutes"]
    steps = ["Rest for 10 minutes"] + level * 7
    name = "ah7_diffusivity_negative_x0p2_and_inventory_5pct_hppc_seven_soc_19C_2s_dfn"
    write_case(root, name, lion.DFN(), aged(0.05, 0.2), steps,
               {"effect": "solid_diffusivity+lithium_inventory_loss", "candidate_model": "dfn",
                "accept": ["particle|solid diffusiv|solid-phase diffusiv", "inventory|lithium loss|lithium lost|cyclable"],
                "ambient_temperature_K": 292.15,
                "note": "two ageing effects of the graphite: negative particle diffusivity x0.2 (6.6e-15 m2/s for the set's 3.3e-14) "
                        "and 5 % less lithium (initial negative concentration x0.95; the initial state set as 90 % SOC of the aged "
                        "cell), at 19 degC (isothermal, not recorded). An HPPC from 90 % SOC: 10 min rest, then 7 x (2C discharge "
                        "pulse for 10 s, 40 s rest, 1C charge pulse for 10 s, 2 min rest, 1C for 6 min to the next level, 40 min "
                        "rest) down to about 20 %; sampled every 2 s, 0.7 mV noise; DFN data and model. dfn_diffusivity_only_rmse_mV: "
                        "the DFN with the diffusivity alone against the recording (what the lithium loss leaves); "
                        "dfn_inventory_only_rmse_mV: with the lithium loss alone (what the diffusivity leaves)"},
               initial_soc=0.9, seed=3307, period=2, noise=7e-4, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), aged(0.0, 0.2), steps, 0.9, "dfn_diffusivity_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.DFN(), aged(0.05, 1.0), steps, 0.9, "dfn_inventory_only_rmse_mV", period=2)
    # ah8: the voltage channel reads 0.4 % low (a gain error), an off-grid telecom site's constant-power nights and genset charges, 42 degC, 30 s, SPM
    p = at(chen(), 42)
    night = lambda watts, hours: [f"Discharge at {watts} W for {hours} hours", "Rest for 5 minutes", "Charge at C/2 until 4.2 V",
                                  "Hold at 4.2 V until C/20", "Rest for 1 hour"]
    steps = ["Rest for 30 minutes"] + night(4.5, 3) + night(5.5, 2)
    write_case(root, "ah8_voltage_channel_gain_0p4pct_low_telecom_site_constant_power_42C_30s_spm", lion.SPM(), p, steps,
               {"effect": "voltage_measurement_gain", "candidate_model": "spm",
                "accept": ["voltage offset", "voltage gain", "voltage scale", "voltage channel", "voltage sensor", "voltage measurement",
                           "calibration"],
                "ambient_temperature_K": 315.15,
                "note": "the site controller's voltage channel reads 0.4 % low (a gain error of the voltage measurement, 0.996 x the "
                        "cell's voltage: 16.8 mV at 4.2 V, 13.6 mV at 3.4 V; not an offset), under current and at rest alike; the cell "
                        "itself is nominal. Not a cell property; a voltage offset (about 15 mV) is its nearest constant stand-in and is "
                        "accepted, as are the words an engineer would use for the channel. At 42 degC (an off-grid telecom tower's "
                        "battery cabinet in a desert; isothermal, not recorded), from full: 30 min rest, the genset off for the "
                        "night (the tower's load, 4.5 W per cell for 3 h, constant power), 5 min rest, the genset's C/2 CC-CV charge to "
                        "4.2 V and C/20, 1 h rest, a second night (5.5 W for 2 h) and charge, 1 h rest; sampled every 30 s (site "
                        "telemetry), 1 mV noise; SPM data and model"},
               initial_soc=1.0, seed=3308, period=30, compare=lion.SPM(), post=lambda t, i, v: 0.996 * v)


def glider_dives(seed, dives):
    """An underwater glider's survey per cell (discharge positive; a buoyancy-driven AUV whose pack has
    many cells in parallel), for each of `dives` dive cycles: at the surface a GPS fix and a satellite
    data call (0.25-0.35C for 2-5 min), the pitch motor trimming for the dive (0.15C for 20 s), the
    glide down with the sensors logging (0.02-0.04C for 15-25 min), the high-pressure buoyancy pump
    at depth (0.8-1.0C for 60-120 s), the pitch motor again (0.15C for 20 s) and the glide up
    (0.02-0.04C for 15-25 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(dives):
        steps += [f"Discharge at {rng.uniform(0.25, 0.35):.2f}C for {int(rng.integers(120, 301))} seconds",
                  "Discharge at 0.15C for 20 seconds",
                  f"Discharge at {rng.uniform(0.02, 0.04):.3f}C for {int(rng.integers(15, 26))} minutes",
                  f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for {int(rng.integers(60, 121))} seconds",
                  "Discharge at 0.15C for 20 seconds",
                  f"Discharge at {rng.uniform(0.02, 0.04):.3f}C for {int(rng.integers(15, 26))} minutes"]
    return steps


def race_stint_steps(seed, laps, pit_after):
    """An electric race car's stint per cell (discharge positive), for each of `laps` laps of about
    90 s: 6-8 corner sequences of a straight at full power (2.6-3.4C for 5-12 s), braking with
    regeneration (1.6-2.4C charge for 2-4 s) and the corner itself (0.3-0.8C for 4-9 s); after
    `pit_after` laps a drive-through in the pit lane under the speed limiter (0.2C for 40 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for lap in range(laps):
        for _ in range(int(rng.integers(6, 9))):
            steps += [f"Discharge at {rng.uniform(2.6, 3.4):.2f}C for {int(rng.integers(5, 13))} seconds",
                      f"Charge at {rng.uniform(1.6, 2.4):.2f}C for {int(rng.integers(2, 5))} seconds",
                      f"Discharge at {rng.uniform(0.3, 0.8):.2f}C for {int(rng.integers(4, 10))} seconds"]
        if lap + 1 == pit_after:
            steps.append("Discharge at 0.2C for 40 seconds")
    return steps


def golf_round_steps(seed, holes):
    """An electric golf cart's round per cell (discharge positive), for each of `holes` holes: the
    drive to the tee (0.6-1.0C for 30-60 s), the wait while the players tee off (no current, 2-4
    min), 2-3 drives to the balls (0.5-0.9C for 15-45 s, on some holes a climb at 1.6-2.2C for 10-25
    s or a descent regenerating at 0.3-0.5C for 8-15 s) each followed by a stop (no current, 1-3
    min), and the wait at the green (no current, 3-6 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(holes):
        steps += [f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(30, 61))} seconds",
                  f"Rest for {int(rng.integers(120, 241))} seconds"]
        for _ in range(int(rng.integers(2, 4))):
            steps.append(f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(15, 46))} seconds")
            u = rng.uniform()
            if u < 0.35:
                steps.append(f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(10, 26))} seconds")
            elif u < 0.55:
                steps.append(f"Charge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(8, 16))} seconds")
            steps.append(f"Rest for {int(rng.integers(60, 181))} seconds")
        steps.append(f"Rest for {int(rng.integers(180, 361))} seconds")
    return steps


def snowmobile_ride_steps(seed, legs):
    """An electric snowmobile's trail ride per cell (discharge positive), for each of `legs` legs:
    pulling away (2.2-2.6C for 5-8 s), trail cruising (0.8-1.3C for 60-180 s), sometimes a climb
    (1.8-2.4C for 20-40 s) and a descent with the motor regenerating (0.4-0.8C charge for 10-20 s),
    then a stop at a junction or a viewpoint (no current, 1-4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(legs):
        steps += [f"Discharge at {rng.uniform(2.2, 2.6):.2f}C for {int(rng.integers(5, 9))} seconds",
                  f"Discharge at {rng.uniform(0.8, 1.3):.2f}C for {int(rng.integers(60, 181))} seconds"]
        if rng.uniform() < 0.5:
            steps += [f"Discharge at {rng.uniform(1.8, 2.4):.2f}C for {int(rng.integers(20, 41))} seconds",
                      f"Charge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(10, 21))} seconds"]
        steps.append(f"Rest for {int(rng.integers(60, 241))} seconds")
    return steps


def peak_shaving_day_steps(seed):
    """A commercial building's behind-the-meter battery for one working day (discharge positive): the
    night's off-peak charge (C/6 to 4.1 V), 4 h on standby (no current), 6 h shaving the building's
    demand above the contracted peak in 15 min blocks (a half-sine over the afternoon's
    air-conditioning load, up to 0.22C, some blocks 40 % lower; a block under 0.02C at no current),
    then 8 h on standby (the cell relaxing) until the next night's charge."""
    rng = np.random.default_rng(seed)
    steps = ["Charge at C/6 until 4.1 V", "Rest for 4 hours"]
    for k in range(24):
        bump = np.sin(np.pi * (k + 0.5) / 24)
        rate = float(np.clip(0.22 * bump * rng.uniform(0.6, 1.1), 0.0, 0.22))
        steps.append(f"Discharge at {rate:.3f}C for 15 minutes" if rate > 0.02 else "Rest for 15 minutes")
    return steps + ["Rest for 8 hours"]


def scooter_rides_steps(seed, rides):
    """A shared e-scooter's rides per cell (discharge positive; a small pack worked hard), for each of
    `rides` rides of 6-10 min: segments of pulling away (2.0-2.5C for 4-6 s), cruising (0.9-1.4C for
    30-90 s), sometimes a hill (1.8-2.4C for 20-45 s), braking with regeneration (0.5C charge for 3-5
    s) and a stop at a light (no current, 10-40 s); between rides parked for 4-15 min."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(rides):
        total, minutes = 0, int(rng.integers(6, 11))
        while total < 60 * minutes:
            a, b = int(rng.integers(4, 7)), int(rng.integers(30, 91))
            steps += [f"Discharge at {rng.uniform(2.0, 2.5):.2f}C for {a} seconds", f"Discharge at {rng.uniform(0.9, 1.4):.2f}C for {b} seconds"]
            total += a + b
            if rng.uniform() < 0.35:
                c = int(rng.integers(20, 46))
                steps.append(f"Discharge at {rng.uniform(1.8, 2.4):.2f}C for {c} seconds")
                total += c
            d, e = int(rng.integers(3, 6)), int(rng.integers(10, 41))
            steps += [f"Charge at 0.5C for {d} seconds", f"Rest for {e} seconds"]
            total += d + e
        steps.append(f"Rest for {int(rng.integers(4, 16))} minutes")
    return steps


def city_bus_steps(seed, trips, stops):
    """An electric city bus's service per cell (discharge positive), for each of `trips` one-way trips
    of `stops` stops: pulling away (1.6-2.2C for 8-15 s), driving (0.5-0.9C for 20-60 s), braking
    with regeneration (1.0-1.6C charge for 5-10 s) and the stop with the doors open and the air
    conditioning running (0.15-0.25C for 15-40 s); at the end of each trip the pantograph charger at
    the terminus (1.5C for 5-8 min) and the driver's layover with the air conditioning on (0.15C for
    3-6 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(trips):
        for _ in range(stops):
            steps += [f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(8, 16))} seconds",
                      f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(20, 61))} seconds",
                      f"Charge at {rng.uniform(1.0, 1.6):.2f}C for {int(rng.integers(5, 11))} seconds",
                      f"Discharge at {rng.uniform(0.15, 0.25):.2f}C for {int(rng.integers(15, 41))} seconds"]
        steps += [f"Charge at 1.5C for {int(rng.integers(300, 481))} seconds", f"Discharge at 0.15C for {int(rng.integers(180, 361))} seconds"]
    return steps


def oxygen_concentrator_day_steps(seed):
    """A portable oxygen concentrator's day per cell (discharge positive; a medical device with a
    two-cell-parallel pack): in 8 blocks of 10-30 min, sitting at pulse setting 2 (0.25-0.3C), walking
    at setting 4 (0.5-0.6C) or resting at setting 1 (0.15-0.2C), with the device switched off (no
    current) now and then; halfway a car ride on the 12 V adapter, which runs the device and charges
    the pack (charge 0.3C for 50 min); at the end the mains charger (0.5C for 1 h) and the device
    put away (no current, 1 h)."""
    rng = np.random.default_rng(seed)
    steps = ["Rest for 10 minutes"]
    for k in range(8):
        if k == 4:
            steps.append("Charge at 0.3C for 50 minutes")
        u = rng.uniform()
        rate = rng.uniform(0.25, 0.3) if u < 0.45 else rng.uniform(0.5, 0.6) if u < 0.7 else rng.uniform(0.15, 0.2) if u < 0.9 else 0.0
        minutes = int(rng.integers(10, 31))
        steps.append(f"Discharge at {rate:.3f}C for {minutes} minutes" if rate > 0 else f"Rest for {minutes} minutes")
    return steps + ["Charge at 0.5C for 60 minutes", "Rest for 1 hour"]


def batch_ai(root):
    """Thirty-fourth batch (key "ai"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -5, 4, 10, 15, 22, 30, 38 and 45 degC, each of the
    three models (one DFN recording handed to the SPMe), sampling from 1 to 60 s, noise from 0.3 to 3
    mV, and duties no earlier batch used: an underwater glider's survey dives, an electric race car's
    stint, an electric golf cart's round, an electric snowmobile's trail ride in the frost, a
    commercial building's peak-shaving battery over two days, shared e-scooter rides, an electric city
    bus with pantograph charging at the terminus in a desert summer, and a portable oxygen
    concentrator's day (a medical device). A DFN control; single effects, two of them rare in earlier
    batches (the electrolyte's cation transference number, 0.38 instead of the set's 0.2594; the
    positive electrode's electronic conductivity x0.2) and three common ones in new settings
    (positive particle diffusivity x0.35 in the cold, DFN data handed to the SPMe; 6 % lithium loss
    seen through two off-peak charges; lumped self-heating with the temperature recorded); and two
    pairs (an SEI film's resistance with the lithium its growth consumed, the film's thickness set by
    that lithium; a voltage channel reading 8 mV low with 7 % positive active-material loss). Words as
    in batches ae-ah; the electrode conductivity by the series / ohmic resistance family, as n1, or
    by its own name; the offset as k3. Each effect's size on its own (the nominal candidate, or a
    replay, against the noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the
    replay keys; where a charge ends on a voltage, a replay driven by the recorded current,
    `recorded_current_rmse`)."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    # ai1: control, an underwater glider's survey (10 dive cycles), 4 degC, 60 s, 0.3 mV, DFN
    p = at(chen(), 4)
    steps = ["Rest for 10 minutes"] + glider_dives(3401, 10) + ["Rest for 30 minutes"]
    write_case(root, "ai1_control_underwater_glider_survey_4C_60s_0p3mV_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 277.15,
                "note": "negative control at 4 degC (deep sea water; isothermal, not recorded): DFN data and model, nothing "
                        "concealed. An underwater glider's survey per cell from 90 % SOC (glider_dives seed 3401, 10 dive cycles, "
                        "about 8 h): 10 min rest, per dive a GPS fix and satellite data call at the surface (0.25-0.35C for 2-5 "
                        "min), the pitch motor (0.15C for 20 s), the glide down logging (0.02-0.04C for 15-25 min), the "
                        "high-pressure buoyancy pump at depth (0.8-1.0C for 1-2 min), the pitch motor, the glide up; 30 min rest "
                        "(down to about 28 %); sampled every 60 s (the glider's engineering log), 0.3 mV noise (a quiet, slow "
                        "channel)"},
               initial_soc=0.9, seed=3401, period=60, noise=3e-4, compare=lion.DFN())
    # ai2: cation transference number 0.38 (set: 0.2594), an electric race car's stint, 38 degC, 1 s, 2 mV, DFN
    p = at(chen(), 38)
    p.update({"Cation transference number": 0.38})
    steps = (["Rest for 5 minutes", "Discharge at 0.3C for 90 seconds"] + race_stint_steps(3402, 14, 7)
             + ["Discharge at 0.3C for 90 seconds", "Rest for 30 minutes"])
    write_case(root, "ai2_transference_number_0p38_race_car_stint_38C_1s_2mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte", "transference"],
                "ambient_temperature_K": 311.15,
                "note": "the electrolyte's cation transference number 0.38 (Valoen and Reimers' value for LiPF6 in EC:EMC) "
                        "instead of the set's 0.2594: an electrolyte whose salt gradients build less under current (the "
                        "concentration overpotential and the diffusion potential smaller); not a candidate parameter, its "
                        "physics is the electrolyte transport family. At 38 degC (a race car's cooled pack on a hot track day; "
                        "isothermal, not recorded). From 90 % SOC: 5 min rest, an out-lap at 0.3C for 90 s, a 14-lap stint "
                        "(race_stint_steps seed 3402: per lap 6-8 corner sequences of full power on the straight at 2.6-3.4C "
                        "for 5-12 s, regenerative braking at 1.6-2.4C for 2-4 s and the corner at 0.3-0.8C for 4-9 s; a "
                        "pit-lane drive-through at 0.2C for 40 s after lap 7), an in-lap at 0.3C for 90 s, 30 min rest; "
                        "sampled every 1 s, 2 mV noise (the car's BMS channel); DFN data and model. effect_rmse_mV is what the "
                        "transference number alone does"},
               initial_soc=0.9, seed=3402, period=1, noise=2e-3, compare=lion.DFN())
    # ai3: positive electrode conductivity x0.2, an electric golf cart's 18-hole round, 15 degC, 5 s, 1 mV, SPMe
    p = at(scaled(chen(), "Positive electrode conductivity [S.m-1]", 0.2), 15)
    steps = ["Rest for 10 minutes"] + golf_round_steps(3403, 18) + ["Rest for 30 minutes"]
    write_case(root, "ai3_positive_conductivity_x0p2_golf_cart_round_15C_5s_spme", lion.SPMe(), p, steps,
               {"effect": "electrode_conductivity", "candidate_model": "spme",
                "accept": ["contact", "series resistance", "ohmic", "electronic conductivity", "electrode conductivity",
                           "solid-phase conductivity", "solid conductivity"],
                "ambient_temperature_K": 288.15,
                "note": "electronic conductivity of the positive electrode x0.2 (0.036 S/m instead of 0.18: a carbon-binder "
                        "network degraded by cycling, the particles losing electronic contact with each other; about 5 mOhm "
                        "more at a 2C climb, 54 mV); not a candidate parameter, its physics is an ohmic loss in series with the "
                        "cell (the contact / series resistance family, as in n1) or the electrode's own conductivity. At 15 "
                        "degC (a spring morning; isothermal, not recorded). An electric golf cart's 18-hole round from 90 % SOC "
                        "(golf_round_steps seed 3403, about 5 h): 10 min rest, per hole the drive to the tee (0.6-1.0C for "
                        "30-60 s), the tee shots (no current, 2-4 min), 2-3 drives to the balls (0.5-0.9C for 15-45 s, on some "
                        "holes a climb at 1.6-2.2C for 10-25 s or a descent regenerating at 0.3-0.5C), each followed by a stop "
                        "of 1-3 min, and the green (3-6 min, no current); 30 min rest; sampled every 5 s, 1 mV noise; SPMe data "
                        "and model. effect_rmse_mV is what the conductivity alone does"},
               initial_soc=0.9, seed=3403, period=5, compare=lion.SPMe())
    # ai4: positive particle diffusivity x0.35, an electric snowmobile's trail ride, -5 degC, 2 s, 1 mV, DFN data handed to the SPMe
    def snow_cell(diffusivity):
        return at(scaled(chen(), "Positive particle diffusivity [m2.s-1]", diffusivity), -5)
    steps = ["Rest for 10 minutes"] + snowmobile_ride_steps(3404, 12) + ["Rest for 30 minutes"]
    name = "ai4_diffusivity_positive_x0p35_snowmobile_trail_minus5C_2s_dfn_data_spme"
    write_case(root, name, lion.DFN(), snow_cell(0.35), steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 268.15,
                "note": "positive particle diffusivity x0.35 (1.4e-15 m2/s for the set's 4e-15: about what a 28 kJ/mol activation "
                        "energy gives between 25 and -5 degC, which the set's constant diffusivity lacks), at -5 degC (a winter "
                        "trail; isothermal, not recorded). An electric snowmobile's trail ride from 90 % SOC "
                        "(snowmobile_ride_steps seed 3404, 12 legs, about 1.7 h): 10 min rest, per leg pulling away at 2.2-2.6C "
                        "for 5-8 s, cruising at 0.8-1.3C for 1-3 min, sometimes a climb at 1.8-2.4C for 20-40 s and a descent "
                        "regenerating at 0.4-0.8C for 10-20 s, a stop of 1-4 min; 30 min rest; sampled every 2 s, 1 mV noise. "
                        "DFN data handed to the SPMe: electrolyte transport (SPMe -> DFN) named beside the diffusivity is right "
                        "too, but the first verdict must name the particle diffusion. spme_with_diffusivity_rmse_mV: the SPMe "
                        "with the true diffusivity against the recording (the SPMe's own error against the DFN); "
                        "dfn_nominal_rmse_mV: the nominal DFN (what the diffusivity alone does, with the noise)"},
               initial_soc=0.9, seed=3404, period=2, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), snow_cell(0.35), steps, 0.9, "spme_with_diffusivity_rmse_mV", period=2)
    replay_rmse(root, name, lion.DFN(), snow_cell(1.0), steps, 0.9, "dfn_nominal_rmse_mV", period=2)
    # ai5: 6 % lithium loss, a commercial building's peak-shaving battery over two working days, 30 degC, 30 s, 1.5 mV, SPM
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94), 30)
    steps = ["Rest for 30 minutes"] + peak_shaving_day_steps(3405) + peak_shaving_day_steps(34050)
    name = "ai5_inventory_6pct_peak_shaving_two_days_30C_30s_1p5mV_spm"
    write_case(root, name, lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": lithium_words, "ambient_temperature_K": 303.15,
                "note": "6 % less lithium (initial negative concentration x0.94; the initial state set as 30 % SOC of the aged "
                        "cell), at 30 degC (a plant room in summer; isothermal, not recorded). A commercial building's "
                        "behind-the-meter battery over two working days from 30 % SOC (peak_shaving_day_steps seeds 3405 and "
                        "34050, about 2 x 21 h): 30 min rest, then each day the off-peak charge at C/6 to 4.1 V, 4 h on standby, 6 h "
                        "shaving the building's demand above the contracted peak in 15 min blocks (0-0.22C, a half-sine over the "
                        "afternoon's air conditioning), 8 h on standby; sampled every 30 s (the energy-management system's log), 1.5 mV noise; SPM data and model. "
                        "effect_rmse_mV is time-aligned on the experiment, whose charges to 4.1 V end at other times; "
                        "spm_nominal_recorded_current_rmse_mV: the nominal SPM driven by the recorded current against the "
                        "recording (what the loss alone does)"},
               initial_soc=0.3, seed=3405, period=30, noise=1.5e-3, compare=lion.SPM())
    recorded_current_rmse(root, name, lion.SPM(), at(chen(), 30), 0.3, "spm_nominal_recorded_current_rmse_mV")
    # ai6: lumped self-heating, h = 12, temperature recorded, four shared e-scooter rides, 10 degC, 3 s, 0.8 mV, DFN
    p = at(chen(), 10)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    steps = ["Rest for 5 minutes"] + scooter_rides_steps(3406, 4) + ["Rest for 30 minutes"]
    write_case(root, "ai6_thermal_h12_recorded_shared_scooter_rides_10C_3s_0p8mV_dfn", lion.DFN(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 283.15,
                "note": "lumped self-heating, h = 12 W/(m2 K) (a sealed deck battery box), ambient and initial 10 degC (a cool "
                        "spring day). A shared e-scooter's rides from 95 % SOC (scooter_rides_steps seed 3406, 4 rides of 6-10 "
                        "min: pulling away at 2.0-2.5C for 4-6 s, cruising at 0.9-1.4C for 30-90 s, hills at 1.8-2.4C for 20-45 s, "
                        "regenerative braking at 0.5C for 3-5 s, stops at lights of 10-40 s; parked 4-15 min between rides), 30 "
                        "min rest (down to about 43 %); the cell warms by about 10 K; temperature recorded (0.05 K noise, 0.1 K "
                        "resolution); sampled every 3 s, 0.8 mV noise; DFN (lumped thermal) data handed to the isothermal DFN. "
                        "effect_rmse_mV is what the heating alone does"},
               initial_soc=0.95, temperature=True, seed=3406, period=3, noise=8e-4,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.DFN())
    # ai7: pair, as SEI growth gives: 5 % lithium loss and the film's resistance (the film as thick as that lithium makes it), an
    # electric city bus's day with pantograph charges and a depot charge, 45 degC, 10 s, 3 mV, SPM
    loss = 0.05
    q = chen()
    area = q["Electrode height [m]"] * q["Electrode width [m]"]
    surface = 3 * q["Negative electrode active material volume fraction"] / q["Negative particle radius [m]"] * q["Negative electrode thickness [m]"] * area
    lithium = q["Initial concentration in negative electrode [mol.m-3]"] * q["Negative electrode active material volume fraction"] * q["Negative electrode thickness [m]"] * area
    film = q["Initial SEI thickness [m]"] + loss * lithium / q["Ratio of lithium moles to SEI moles"] * q["SEI partial molar volume [m3.mol-1]"] / surface
    film_ohm = q["SEI resistivity [Ohm.m]"] * (film - q["Initial SEI thickness [m]"]) / surface
    def bus_cell(lost, thickness):
        c = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.0 - lost), 45)
        c.update({"Initial SEI thickness [m]": thickness})
        return c
    sei = {"SEI": "constant", "SEI film resistance": "distributed"}
    steps = (["Rest for 10 minutes"] + city_bus_steps(3407, 7, 16)
             + ["Discharge at 0.6C for 10 minutes", "Rest for 1 hour", "Charge at C/2 until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 1 hour"])
    name = "ai7_sei_film_and_inventory_5pct_city_bus_pantograph_45C_10s_3mV_spm"
    write_case(root, name, lion.SPM(options=sei), bus_cell(loss, film), steps,
               {"effect": "sei_film_resistance+lithium_inventory_loss", "candidate_model": "spm",
                "accept": ["film resistance|SEI resistance|contact|series resistance|ohmic", "inventory|lithium loss|lithium lost|cyclable|SEI growth"],
                "ambient_temperature_K": 318.15,
                "note": "two effects, as SEI growth on the graphite gives: 5 % less lithium (initial negative concentration "
                        f"x0.95; the initial state set as 80 % SOC of the aged cell) and the SEI film that lithium went into, "
                        f"{1e9 * film:.0f} nm thick (the set's 5 nm plus what the lost lithium makes at the set's SEI molar volume "
                        f"and 2 Li per SEI), with the set's resistivity as a distributed film resistance on the negative "
                        f"particles (PyBaMM SEI 'constant': no growth during the recording): about {1e3 * film_ohm:.1f} mOhm more "
                        "in series. At 45 degC (a desert city's summer; isothermal, not recorded). An electric city bus's day per "
                        "cell from 80 % SOC (city_bus_steps seed 3407, 7 trips of 16 stops: pulling away at 1.6-2.2C for 8-15 s, "
                        "driving at 0.5-0.9C for 20-60 s, regenerative braking at 1.0-1.6C for 5-10 s, the stop with the doors "
                        "open and the air conditioning on at 0.15-0.25C for 15-40 s; at each terminus the pantograph charger at "
                        "1.5C for 5-8 min and the layover at 0.15C for 3-6 min), the run back to the depot (0.6C for 10 min), 1 h "
                        "rest, the depot's C/2 CC-CV charge to 4.2 V and C/20, 1 h rest; sampled every 10 s, 3 mV noise (an "
                        "old bus's BMS channel); SPM data and model. Driven by the recorded current against the recording: "
                        "spm_nominal_recorded_current_rmse_mV the nominal SPM (both effects); spm_film_only_rmse_mV the SPM with "
                        "the film alone (what the lithium loss leaves); spm_inventory_only_rmse_mV with the lithium loss alone "
                        "(what the film leaves). effect_rmse_mV is time-aligned on the experiment, whose depot charge ends at "
                        "another time"},
               initial_soc=0.8, seed=3407, period=10, noise=3e-3, compare=lion.SPM())
    recorded_current_rmse(root, name, lion.SPM(), at(chen(), 45), 0.8, "spm_nominal_recorded_current_rmse_mV")
    recorded_current_rmse(root, name, lion.SPM(options=sei), bus_cell(0.0, film), 0.8, "spm_film_only_rmse_mV")
    recorded_current_rmse(root, name, lion.SPM(), bus_cell(loss, 5e-9), 0.8, "spm_inventory_only_rmse_mV")
    # ai8: pair: the logger's voltage channel reads 8 mV low, and 7 % positive LAM, a portable oxygen concentrator's day, 22 degC, 20 s, 0.5 mV, SPMe
    def poc_cell(lam):
        return at(scaled(chen(), "Positive electrode active material volume fraction", 1.0 - lam), 22)
    steps = oxygen_concentrator_day_steps(3408)
    name = "ai8_voltage_offset_8mV_low_and_lam_positive_7pct_oxygen_concentrator_22C_20s_0p5mV_spme"
    write_case(root, name, lion.SPMe(), poc_cell(0.07), steps,
               {"effect": "voltage_offset+active_material_loss", "candidate_model": "spme",
                "accept": ["offset|calibration|voltage measurement|voltage sensor|voltage channel", "active material"],
                "ambient_temperature_K": 295.15,
                "note": "two effects: the device's logging channel reads the cell voltage 8 mV low everywhere (a calibration "
                        "offset, under current and at rest alike; not a cell property, an OCP offset is the nearest cell-side "
                        "description and is accepted through 'offset') and 7 % loss of positive active material (volume "
                        "fraction 0.665 -> 0.6185, the set's initial concentrations, so the lithium of the lost material goes "
                        "with it; the initial state set as full charge of the aged cell), at 22 degC (indoors; isothermal, not "
                        "recorded). A portable oxygen concentrator's day per cell from full (oxygen_concentrator_day_steps seed "
                        "3408, about 6 h): 10 min rest, 8 blocks of 10-30 min at pulse setting 1, 2 or 4 (0.15-0.6C) or switched "
                        "off, after the fourth a car ride on the 12 V adapter (0.3C charge for 50 min), then the mains charger "
                        "(0.5C for 1 h) and 1 h put away; every step time-limited (no voltage cut-off reached); sampled every 20 "
                        "s, 0.5 mV noise; SPMe data and model. spme_lam_only_rmse_mV: the SPMe with the LAM alone against the "
                        "recording (what the offset leaves); spme_offset_only_rmse_mV: the nominal SPMe read 8 mV low (what the "
                        "LAM leaves)"},
               initial_soc=1.0, seed=3408, period=20, noise=5e-4, compare=lion.SPMe(), post=lambda t, i, v: v - 0.008)
    replay_rmse(root, name, lion.SPMe(), poc_cell(0.07), steps, 1.0, "spme_lam_only_rmse_mV", period=20)
    replay_rmse(root, name, lion.SPMe(), poc_cell(0.0), steps, 1.0, "spme_offset_only_rmse_mV", period=20, shift_V=-0.008)


def sonar_buoy_steps(seed, hours, daylight):
    """A moored marine sonar buoy's battery per cell (discharge positive), in 20 min slots over `hours`
    hours: each slot opens with an active-sonar ping train (1.0-1.4C for 20-30 s), then the sensors,
    logger and radio idle (0.03C) at night, or the solar panel charges the cell net of that load
    (0.04-0.12C charge, the clouds changing it) in the hours listed in `daylight`; the first slot of
    each hour also carries the satellite uplink (0.3C for 2-4 min) after the ping train."""
    rng = np.random.default_rng(seed)
    steps = []
    for hour in range(hours):
        for slot in range(3):
            ping = int(rng.integers(20, 31))
            steps.append(f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {ping} seconds")
            rest = 1200 - ping
            if slot == 0:
                uplink = int(rng.integers(120, 241))
                steps.append(f"Discharge at 0.3C for {uplink} seconds")
                rest -= uplink
            steps.append(f"Charge at {rng.uniform(0.04, 0.12):.3f}C for {rest} seconds" if hour in daylight
                         else f"Discharge at 0.03C for {rest} seconds")
    return steps


def weeding_robot_steps(seed, rows, dock_after):
    """An autonomous field-weeding robot's shift per cell (discharge positive), for each of `rows` crop
    rows: 3-5 legs along the row with the cameras and hoes working (0.18-0.28C for 40-80 s), each
    ended by a hoe actuator correcting hard (0.9-1.3C for 3-6 s), the turn at the headland (0.5-0.8C
    for 20-40 s) and a stop to re-localise (0.04C for 15-45 s); after `dock_after` rows the robot
    docks on its field trailer's charger (0.5C charge for 40 min, then 2 min idle at 0.04C)."""
    rng = np.random.default_rng(seed)
    steps = []
    for row in range(rows):
        for _ in range(int(rng.integers(3, 6))):
            steps += [f"Discharge at {rng.uniform(0.18, 0.28):.3f}C for {int(rng.integers(40, 81))} seconds",
                      f"Discharge at {rng.uniform(0.9, 1.3):.2f}C for {int(rng.integers(3, 7))} seconds"]
        steps += [f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(20, 41))} seconds",
                  f"Discharge at 0.04C for {int(rng.integers(15, 46))} seconds"]
        if row + 1 == dock_after:
            steps += ["Charge at 0.5C for 40 minutes", "Discharge at 0.04C for 2 minutes"]
    return steps


def rail_outage_steps(seed, hours):
    """A railway signalling location's backup battery through a mains outage, per cell (discharge
    positive), for `hours` hours: the track circuits, signal lamps and interlocking (0.09-0.11C for
    4-12 min between events), and at each event either a set of points thrown (2.0-2.4C for 4-7 s;
    35 % of events) or a train over the level crossing: the warning lamps (0.25C for 30-45 s), the
    barriers lowered (1.3-1.6C for 8-12 s), the lamps while the train passes (0.25C for 40-90 s) and
    the barriers raised (1.3-1.6C for 8-12 s)."""
    rng = np.random.default_rng(seed)
    steps, elapsed = [], 0
    while elapsed < 3600 * hours:
        gap = int(rng.integers(240, 721))
        steps.append(f"Discharge at {rng.uniform(0.09, 0.11):.3f}C for {gap} seconds")
        elapsed += gap
        if rng.uniform() < 0.35:
            throw = int(rng.integers(4, 8))
            steps.append(f"Discharge at {rng.uniform(2.0, 2.4):.2f}C for {throw} seconds")
            elapsed += throw
        else:
            a, b, c, d = int(rng.integers(30, 46)), int(rng.integers(8, 13)), int(rng.integers(40, 91)), int(rng.integers(8, 13))
            steps += [f"Discharge at 0.25C for {a} seconds", f"Discharge at {rng.uniform(1.3, 1.6):.2f}C for {b} seconds",
                      f"Discharge at 0.25C for {c} seconds", f"Discharge at {rng.uniform(1.3, 1.6):.2f}C for {d} seconds"]
            elapsed += a + b + c + d
    return steps


def tattoo_session_steps(seed, minutes):
    """A wireless rotary tattoo pen's day per cell (discharge positive) until `minutes` of needle
    time: alternating lining (0.25-0.35C for 3-10 min) and shading or colour packing (0.35-0.5C for
    4-12 min), each followed by a pause to wipe and re-ink (no current, 1-5 min), and a break for the
    client (no current, 12-18 min) after every hour or so of needle time."""
    rng = np.random.default_rng(seed)
    steps, work, since_break, k = [], 0, 0, 0
    while work < 60 * minutes:
        low, high, shortest, longest = (0.25, 0.35, 3, 10) if k % 2 == 0 else (0.35, 0.5, 4, 12)
        spell = 60 * int(rng.integers(shortest, longest + 1))
        steps += [f"Discharge at {rng.uniform(low, high):.3f}C for {spell} seconds", f"Rest for {int(rng.integers(60, 301))} seconds"]
        work, since_break, k = work + spell, since_break + spell, k + 1
        if since_break >= 3600:
            steps.append(f"Rest for {int(rng.integers(12, 19))} minutes")
            since_break = 0
    return steps


def wheelchair_day_steps(seed, indoor_moves, outdoor_minutes):
    """A powered wheelchair's day per cell (discharge positive), with where the chair is: `indoor_moves`
    moves about the house (0.2-0.4C for 8-30 s, each followed by a stop of 20 s-4 min at no current),
    an outing of about `outdoor_minutes` min (pavement at 0.5-0.8C for 40-150 s; 40 % of the time a
    kerb climbed at 1.8-2.2C for 3-5 s, 30 % a ramp or slope at 1.1-1.5C for 15-40 s; then a wait at a
    crossing or a shop, no current, 30 s-3 min), and the same number of moves indoors again. Returns
    the steps and the outing's (start, end) in s from the first step."""
    rng = np.random.default_rng(seed)
    def indoors():
        out = []
        for _ in range(indoor_moves):
            out += [f"Discharge at {rng.uniform(0.2, 0.4):.3f}C for {int(rng.integers(8, 31))} seconds",
                    f"Rest for {int(rng.integers(20, 241))} seconds"]
        return out
    def seconds(steps):
        return sum(int(s.split(" for ")[1].split()[0]) for s in steps)
    steps = indoors()
    start = seconds(steps)
    while seconds(steps) - start < 60 * outdoor_minutes:
        steps.append(f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(40, 151))} seconds")
        u = rng.uniform()
        if u < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.8, 2.2):.2f}C for {int(rng.integers(3, 6))} seconds")
        elif u < 0.7:
            steps.append(f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(15, 41))} seconds")
        steps.append(f"Rest for {int(rng.integers(30, 181))} seconds")
    end = seconds(steps)
    return steps + indoors(), (start, end)


def aed_rescue_steps(seed, shocks):
    """A rechargeable automated external defibrillator's (AED's) rescue per cell (discharge
    positive): switched on and self-checked (0.1C for 20 s), the pads on and the rhythm analysed
    (0.08C for 15-25 s), then for each of `shocks` shocks the capacitor charged (2.4-3.0C for 6-10
    s), the shock, and 2 min of CPR with the monitor and voice prompts (0.06-0.08C for 120 s) and a
    new analysis (0.08C for 15-25 s); the paramedics' monitoring after (0.08C for 10 min)."""
    rng = np.random.default_rng(seed)
    steps = ["Discharge at 0.1C for 20 seconds", f"Discharge at 0.08C for {int(rng.integers(15, 26))} seconds"]
    for _ in range(shocks):
        steps += [f"Discharge at {rng.uniform(2.4, 3.0):.2f}C for {int(rng.integers(6, 11))} seconds",
                  f"Discharge at {rng.uniform(0.06, 0.08):.3f}C for 120 seconds",
                  f"Discharge at 0.08C for {int(rng.integers(15, 26))} seconds"]
    return steps + ["Discharge at 0.08C for 10 minutes"]


def outboard_trip_steps(seed, spots):
    """A small fishing boat's electric outboard per cell (discharge positive): out of the harbour at
    displacement speed (0.6-0.8C for 5-8 min), a planing run to the grounds (1.3-1.5C for 3-5 min: the
    cell's continuous rating), at each of `spots` spots trolling (0.15-0.25C for 10-20 min), drifting with the fish finder on
    (0.02C for 8-20 min) and moving to the next spot (1.0-1.4C for 1-3 min); the planing run home and
    the harbour at displacement speed (0.6-0.8C for 4-6 min)."""
    rng = np.random.default_rng(seed)
    plane = lambda: f"Discharge at {rng.uniform(1.3, 1.5):.2f}C for {int(rng.integers(180, 301))} seconds"
    steps = [f"Discharge at {rng.uniform(0.6, 0.8):.2f}C for {int(rng.integers(300, 481))} seconds", plane()]
    for _ in range(spots):
        steps += [f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {int(rng.integers(10, 21))} minutes",
                  f"Discharge at 0.02C for {int(rng.integers(8, 21))} minutes",
                  f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(60, 181))} seconds"]
    return steps + [plane(), f"Discharge at {rng.uniform(0.6, 0.8):.2f}C for {int(rng.integers(240, 361))} seconds"]


def vacuum_session_steps(seed, rooms):
    """A cordless stick vacuum cleaner's session per cell (discharge positive), for each of `rooms`
    rooms: normal mode (0.7-1.0C for 60-180 s), on 40 % of rooms a rug in boost mode (1.8-2.2C for 20-50
    s), the furniture moved or the tool changed (no current, 10-40 s); the bin emptied (no current,
    60-120 s) after every 3-4 rooms."""
    rng = np.random.default_rng(seed)
    steps, since, empty_after = [], 0, int(rng.integers(3, 5))
    for _ in range(rooms):
        steps.append(f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {int(rng.integers(60, 181))} seconds")
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.8, 2.2):.2f}C for {int(rng.integers(20, 51))} seconds")
        steps.append(f"Rest for {int(rng.integers(10, 41))} seconds")
        since += 1
        if since == empty_after:
            steps.append(f"Rest for {int(rng.integers(60, 121))} seconds")
            since, empty_after = 0, int(rng.integers(3, 5))
    return steps

def batch_aj(root):
    """Thirty-fifth batch (key "aj"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -8, 3, 8, 14, 23, 27 and 30 degC and one that
    changes (21 degC indoors, -4 degC outdoors), each of the three models, sampling from 1 to 30 s and
    a cycler's irregular log, noise from 0.3 to 3 mV, and duties no earlier batch used: a moored
    marine sonar buoy with solar charging, an autonomous field-weeding robot docking on its trailer,
    a railway signalling location's backup battery through a winter-night mains outage, a wireless
    tattoo pen's day and its charger, a powered wheelchair's day with a winter outing, a rechargeable
    defibrillator's (AED's) rescue in an unheated cabinet, a fishing boat's electric outboard, and a
    cordless vacuum cleaner's two sessions. An SPMe control; single effects (a 4 mOhm contact
    resistance; 7 % lithium loss; 10 % negative active-material loss, the lithium going with it;
    negative exchange current x0.4; an aged electrolyte, diffusivity x0.6 and conductivity x0.7) and
    one no earlier batch concealed: the ambient temperature changing during the recording (the
    wheelchair taken out into the frost for 78 min and back in; lumped thermal data, the temperature
    recorded, handed to the isothermal DFN at the indoor ambient); and a pair (lumped self-heating in a
    poorly cooled handle, h = 5, temperature recorded, with positive particle diffusivity x0.5). Words
    as in batches ah-ai; the changing ambient by the thermal words, "temperature" or "ambient". Each
    effect's size on its own (the nominal candidate, or a replay, against the noise-free voltage or
    the recording) is in truth.json (effect_rmse_mV and the replay keys; where a charge ends on a
    voltage, a replay driven by the recorded current, `recorded_current_rmse`)."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    # aj1: control, a moored sonar buoy's 10 h (pre-dawn, solar day, evening), 8 degC, 20 s, 0.6 mV, SPMe
    p = at(chen(), 8)
    steps = ["Rest for 10 minutes"] + sonar_buoy_steps(3501, 10, range(3, 9)) + ["Rest for 30 minutes"]
    write_case(root, "aj1_control_sonar_buoy_solar_day_8C_20s_0p6mV_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 281.15,
                "note": "negative control at 8 degC (the buoy's hull in coastal sea water; isothermal, not recorded): SPMe "
                        "data and model, nothing concealed. From 55 % SOC: 10 min rest, 10 h of a moored sonar buoy "
                        "(sonar_buoy_steps seed 3501, 20 min slots: an active-sonar ping train at 1.0-1.4C for 20-30 s, the "
                        "satellite uplink at 0.3C for 2-4 min once an hour, the rest of the slot the sensors and logger at "
                        "0.03C in the three pre-dawn hours and the last, the solar panel charging at a net 0.04-0.12C in "
                        "hours 3-8), 30 min rest; the state of charge between about 32 and 58 %; sampled every 20 s (the "
                        "buoy's housekeeping log), 0.6 mV noise"},
               initial_soc=0.55, seed=3501, period=20, noise=6e-4, compare=lion.SPMe())
    # aj2: 4 mOhm contact resistance, a field-weeding robot's shift with a trailer charge, 27 degC, 5 s, 1 mV, SPM
    p = at(chen(), 27)
    p.update({"Contact resistance [Ohm]": 0.004}, check_already_exists=False)
    steps = ["Rest for 10 minutes"] + weeding_robot_steps(3502, 36, 24) + ["Rest for 30 minutes"]
    write_case(root, "aj2_contact_4mOhm_weeding_robot_trailer_charge_27C_5s_spm", lion.SPM(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 300.15,
                "note": "a 4 mOhm contact resistance (a corroded pack connector on a robot that works in wet fields: 20 mV at "
                        "the 1C hoe corrections, 4-5 mV while it drives the rows, -10 mV on the trailer charge), at 27 degC (a "
                        "summer field; isothermal, not recorded). From 95 % SOC: 10 min rest, an autonomous weeding robot's "
                        "shift (weeding_robot_steps seed 3502, 36 rows: 3-5 legs per row with cameras and hoes at 0.18-0.28C "
                        "for 40-80 s, each ended by a hoe correction at 0.9-1.3C for 3-6 s, the headland turn at 0.5-0.8C for "
                        "20-40 s, a re-localisation stop at 0.04C; after 24 rows docked on the field trailer's charger at 0.5C "
                        "for 40 min), 30 min rest; down to about 30 %, up to about 63 %, down to about 30 %; sampled every 5 s, "
                        "1 mV noise; SPM (with contact resistance) data handed to the plain SPM. effect_rmse_mV is what the "
                        "resistance alone does"},
               initial_soc=0.95, seed=3502, period=5, compare=lion.SPM())
    # aj3: 7 % lithium loss, a railway signalling backup through a winter-night mains outage, -8 degC, 30 s, 0.8 mV, SPMe
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.93), -8)
    steps = ["Rest for 30 minutes"] + rail_outage_steps(3503, 4) + ["Rest for 30 minutes", "Charge at 0.1C for 2 hours", "Rest for 30 minutes"]
    write_case(root, "aj3_inventory_7pct_rail_signalling_backup_outage_minus8C_30s_spme", lion.SPMe(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spme", "accept": lithium_words, "ambient_temperature_K": 265.15,
                "note": "7 % less lithium (initial negative concentration x0.93; the initial state set as full charge of the "
                        "aged cell: the battery was on float), at -8 degC (a lineside equipment cabinet on a winter night; "
                        "isothermal, not recorded). From full: 30 min rest, a 4 h mains outage (rail_outage_steps seed 3503: the "
                        "track circuits, signal lamps and interlocking at 0.09-0.11C for 4-12 min between events; at 35 % of "
                        "events a set of points thrown at 2.0-2.4C for 4-7 s, at the others a train over the level crossing: "
                        "warning lamps at 0.25C, barriers lowered at 1.3-1.6C for 8-12 s, lamps while the train passes, "
                        "barriers raised), 30 min rest, the mains back and the charger at 0.1C for 2 h (time-limited), 30 min "
                        "rest; down to about 36 %, back to about 56 %; sampled every 30 s (the location's remote condition "
                        "monitoring), 0.8 mV noise; SPMe data and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=1.0, seed=3503, period=30, noise=8e-4, compare=lion.SPMe())
    # aj4: 10 % negative active-material loss (the lithium going with it), a wireless tattoo pen's day and its CC-CV charger, 23 degC,
    # a cycler's irregular log, 1.5 mV, SPM
    p = at(scaled(chen(), "Negative electrode active material volume fraction", 0.9), 23)
    steps = (["Rest for 10 minutes"] + tattoo_session_steps(3504, 120)
             + ["Rest for 20 minutes", "Charge at 0.5C until 4.2 V", "Hold at 4.2 V until C/20", "Rest for 30 minutes"])
    name = "aj4_lam_negative_10pct_tattoo_pen_day_cccv_23C_cycler_1p5mV_spm"
    write_case(root, name, lion.SPM(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"], "ambient_temperature_K": 296.15,
                "note": "10 % loss of negative active material (volume fraction 0.75 -> 0.675, the set's initial concentrations, "
                        "so the lithium of the lost material goes with it: PyBaMM's plain volume-fraction change; the initial "
                        "state set as 95 % SOC of the aged cell), at 23 degC (a studio; isothermal, not recorded). A wireless "
                        "tattoo pen's day replayed on a cycler from 95 % SOC: 10 min rest, 2 h of needle time (tattoo_session_steps "
                        "seed 3504: lining at 0.25-0.35C for 3-10 min and shading or colour packing at 0.35-0.5C for 4-12 min in "
                        "turn, each followed by a 1-5 min pause to wipe and re-ink, a 12-18 min break for the client after every "
                        "hour of needle time), 20 min rest, the pen's charger at 0.5C CC-CV to 4.2 V and C/20, 30 min rest; down "
                        "to about 20 %; the cycler's irregular log (1 s in the first 60 s of a step and in short steps, then 30 s "
                        "under load / 60 s at rest, plus every 5 mV or 50 mA), 3 mA current noise, 0.1 mV / 0.1 mA resolution, "
                        "1.5 mV voltage noise; SPM data and model. effect_rmse_mV is time-aligned on the experiment, whose charge "
                        "ends at another time; spm_nominal_recorded_current_rmse_mV: the nominal SPM driven by the recorded "
                        "current against the recording (what the loss alone does)"},
               initial_soc=0.95, seed=3504, noise=1.5e-3, cycler=CYCLER, compare=lion.SPM())
    recorded_current_rmse(root, name, lion.SPM(), at(chen(), 23), 0.95, "spm_nominal_recorded_current_rmse_mV")
    # aj5: the ambient changes during the recording (an effect no earlier batch concealed): a powered wheelchair's day, 21 degC
    # indoors and a 78 min outing at -4 degC, lumped thermal (h = 10, the set's), temperature recorded, 10 s, 1 mV, DFN
    indoor, outdoor = 21.0, -4.0
    wheel, (out_start, out_end) = wheelchair_day_steps(3505, 15, 75)
    steps = ["Rest for 10 minutes"] + wheel + ["Rest for 40 minutes"]
    def wheelchair_cell(changing):
        q = at(chen(), indoor)
        if changing:
            a, b = 600.0 + out_start, 600.0 + out_end
            q.update({"Ambient temperature [K]": lambda y, z, t: 273.15 + indoor + (outdoor - indoor) * 0.5
                      * (pybamm.tanh((t - a) / 60.0) - pybamm.tanh((t - b) / 60.0))})
        return q
    name = "aj5_ambient_change_wheelchair_outing_in_frost_21C_to_minus4C_recorded_10s_dfn"
    write_case(root, name, lion.DFN(options={"thermal": "lumped"}), wheelchair_cell(True), steps,
               {"effect": "ambient_temperature_change", "candidate_model": "dfn",
                "accept": ["ambient", "temperature", "thermal", "heat"], "ambient_temperature_K": 294.15,
                "note": "the ambient temperature changes during the recording (no earlier batch concealed this): a powered "
                        "wheelchair's day per cell, 21 degC indoors and, for a 78 min outing, -4 degC outdoors (the air round "
                        "the battery box changing over about 2 min at the door, each way), the cell following through its "
                        f"lumped thermal mass (the set's h = 10 W/(m2 K): it cools to 2-3 degC in the outing and warms "
                        f"back to 21 degC indoors). From 90 % SOC: 10 min rest indoors, 15 moves about "
                        f"the house (0.2-0.4C for 8-30 s, stops of 20 s-4 min), the outing from {600 + out_start} s to "
                        f"{600 + out_end} s (wheelchair_day_steps seed 3505: pavement at 0.5-0.8C for 40-150 s, kerbs climbed at "
                        "1.8-2.2C for 3-5 s, ramps and slopes at 1.1-1.5C for 15-40 s, waits at crossings and shops of 30 s-3 "
                        "min), 15 moves indoors again, 40 min rest; down to about 33 %; temperature recorded (0.05 K noise, 0.1 K "
                        "resolution); sampled every 10 s, 1 mV noise; DFN (lumped thermal, the ambient a function of time) data "
                        "handed to the isothermal DFN at the indoor 21 degC (the ambient given). effect_rmse_mV is what the "
                        "temperature's course does (the change and the small self-heating); dfn_lumped_constant_ambient_rmse_mV: "
                        "the lumped DFN with the ambient held at 21 degC against the recording (what the change does beyond "
                        "self-heating)"},
               initial_soc=0.9, temperature=True, seed=3505, period=10, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(options={"thermal": "lumped"}), wheelchair_cell(False), steps, 0.9,
                "dfn_lumped_constant_ambient_rmse_mV", period=10)
    # aj6: negative exchange current x0.4, an AED's weekly self-test and a rescue, in an unheated street cabinet, 3 degC, 1 s, 2.5 mV, DFN
    p = at(scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 0.4), 3)
    steps = (["Rest for 10 minutes", "Discharge at 0.1C for 30 seconds", "Discharge at 2.2C for 5 seconds", "Rest for 20 minutes"]
             + aed_rescue_steps(3506, 8) + ["Rest for 30 minutes"])
    write_case(root, "aj6_kinetics_negative_x0p4_aed_rescue_street_cabinet_3C_1s_2p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": kinetic_words, "ambient_temperature_K": 276.15,
                "note": "negative exchange-current density x0.4 (all stoichiometries; the activation energy kept: a graphite "
                        "surface passivated by a thick, resistive SEI as a slower reaction), at 3 degC (a public-access "
                        "defibrillator's unheated street cabinet in winter; isothermal, not recorded). From 80 % SOC: 10 min "
                        "rest, the daily self-test (0.1C for 30 s, a test charge of the capacitor at 2.2C for 5 s), 20 min "
                        "standby, a rescue (aed_rescue_steps seed 3506, 8 shocks: switched on and self-checked at 0.1C, the "
                        "rhythm analysed at 0.08C, per shock the capacitor charged at 2.4-3.0C for 6-10 s then 2 min of CPR "
                        "with the monitor at 0.06-0.08C and a new analysis; 10 min of monitoring at 0.08C), 30 min rest; "
                        "sampled every 1 s, 2.5 mV noise (the device's event log); DFN data and model. effect_rmse_mV is what "
                        "the slower kinetics alone do"},
               initial_soc=0.8, seed=3506, period=1, noise=2.5e-3, compare=lion.DFN())
    # aj7: an aged electrolyte (diffusivity x0.6, conductivity x0.7), a fishing boat's electric outboard, 14 degC, 2 s, 0.3 mV, DFN
    def boat_cell(diffusivity, conductivity):
        q = scaled(chen(), "Electrolyte diffusivity [m2.s-1]", diffusivity)
        return at(scaled(q, "Electrolyte conductivity [S.m-1]", conductivity), 14)
    steps = ["Rest for 10 minutes"] + outboard_trip_steps(3507, 3) + ["Rest for 40 minutes"]
    name = "aj7_electrolyte_aged_diffusivity_x0p6_conductivity_x0p7_electric_outboard_14C_2s_0p3mV_dfn"
    write_case(root, name, lion.DFN(), boat_cell(0.6, 0.7), steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 287.15,
                "note": "an aged electrolyte (salt consumed and solvent decomposed by years of cycling): diffusivity x0.6 and "
                        "conductivity x0.7 at every concentration, at 14 degC (the outboard's battery box against the hull in "
                        "spring water; isothermal, not recorded). A fishing trip from full (outboard_trip_steps seed 3507): 10 "
                        "min rest, out of the harbour at displacement speed (0.6-0.8C for 5-8 min), a planing run to the "
                        "grounds (1.3-1.5C for 3-5 min, the cell's continuous rating; the salt concentration falls to about 60 "
                        "mol/m3 at its lowest, where the set's electrolyte keeps about 350), at 3 spots trolling (0.15-0.25C for 10-20 min), drifting with the fish "
                        "finder (0.02C for 8-20 min) and moving on (1.0-1.4C for 1-3 min), the planing run home and the "
                        "harbour, 40 min rest; down to about 36 %; sampled every 2 s, 0.3 mV noise (a laboratory-grade "
                        "logger on the boat); DFN data and model. effect_rmse_mV is what the aged electrolyte does; "
                        "dfn_diffusivity_only_rmse_mV and dfn_conductivity_only_rmse_mV: the DFN with one of the two against the "
                        "recording (what the other leaves)"},
               initial_soc=1.0, seed=3507, period=2, noise=3e-4, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), boat_cell(0.6, 1.0), steps, 1.0, "dfn_diffusivity_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.DFN(), boat_cell(1.0, 0.7), steps, 1.0, "dfn_conductivity_only_rmse_mV", period=2)
    # aj8: pair, lumped self-heating (h = 5, temperature recorded) and positive particle diffusivity x0.5, a cordless vacuum
    # cleaner's two sessions and its charger, 30 degC, 3 s, 3 mV, SPMe
    def vacuum_cell(h, diffusivity):
        q = at(scaled(chen(), "Positive particle diffusivity [m2.s-1]", diffusivity), 30)
        if h is not None:
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": h})
        return q
    steps = (["Rest for 5 minutes"] + vacuum_session_steps(3508, 9) + ["Rest for 20 minutes", "Charge at 0.5C for 25 minutes", "Rest for 20 minutes"]
             + vacuum_session_steps(35080, 4) + ["Rest for 30 minutes"])
    name = "aj8_thermal_h5_recorded_and_diffusivity_positive_x0p5_cordless_vacuum_30C_3s_3mV_spme"
    write_case(root, name, lion.SPMe(options={"thermal": "lumped"}), vacuum_cell(5.0, 0.5), steps,
               {"effect": "thermal+solid_diffusivity", "candidate_model": "spme",
                "accept": ["thermal|self-heating|heat", "particle|solid diffusiv|solid-phase diffusiv"], "ambient_temperature_K": 303.15,
                "note": "two effects: lumped self-heating, h = 5 W/(m2 K) (cells packed in the vacuum's plastic handle, no "
                        "airflow), and positive particle diffusivity x0.5 (2e-15 m2/s for the set's 4e-15: a cathode aged by "
                        "cycling), ambient and initial 30 degC (a house in summer). From 90 % SOC: 5 min rest, a whole-house "
                        "session (vacuum_session_steps seed 3508, 9 rooms: normal mode at 0.7-1.0C for 1-3 min, on some rooms "
                        "a rug in boost mode at 1.8-2.2C for 20-50 s, 10-40 s to move furniture or change the tool, the bin "
                        "emptied every 3-4 rooms), 20 min rest, the wall charger at 0.5C for 25 min (time-limited), 20 min "
                        "rest, the kitchen after dinner (seed 35080, 4 rooms), 30 min rest; the state of charge between about "
                        "58 and 80 % after the first session; the cell warms by about 12 K (to about 42 degC) in the first "
                        "session; temperature recorded (0.05 K noise, 0.1 K resolution); sampled every 3 s, 3 mV noise (the "
                        "vacuum's own BMS); SPMe (lumped thermal) data handed to the isothermal SPMe. "
                        "spme_thermal_only_rmse_mV: the lumped SPMe (h = 5) with the set's diffusivity against the recording "
                        "(what the diffusivity leaves); spme_diffusivity_only_rmse_mV: the isothermal SPMe with the diffusivity "
                        "x0.5 (what the heating leaves)"},
               initial_soc=0.9, temperature=True, seed=3508, period=3, noise=3e-3,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(options={"thermal": "lumped"}), vacuum_cell(5.0, 1.0), steps, 0.9, "spme_thermal_only_rmse_mV", period=3)
    replay_rmse(root, name, lion.SPMe(), vacuum_cell(None, 0.5), steps, 0.9, "spme_diffusivity_only_rmse_mV", period=3)


def telescope_night_steps(seed, hours):
    """An astro-imaging night on a battery-powered telescope mount per cell (discharge positive) for
    about `hours` hours: per target a slew (1.2-1.6C for 8-25 s), the plate-solve and centring nudges
    (0.5-0.7C for 3-6 s), then tracking with the camera's cooler and the dew heaters on (0.08-0.14C for
    8-25 min of exposures); once an hour a meridian flip (1.3-1.5C for 30-40 s); the mount parked at
    the end (1.2C for 20 s)."""
    rng = np.random.default_rng(seed)
    steps, elapsed, next_flip = [], 0, 3600
    while elapsed < 3600 * hours:
        slew, nudge, track = int(rng.integers(8, 26)), int(rng.integers(3, 7)), 60 * int(rng.integers(8, 26))
        steps += [f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {slew} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {nudge} seconds",
                  f"Discharge at {rng.uniform(0.08, 0.14):.3f}C for {track} seconds"]
        elapsed += slew + nudge + track
        if elapsed >= next_flip:
            flip = int(rng.integers(30, 41))
            steps.append(f"Discharge at {rng.uniform(1.3, 1.5):.2f}C for {flip} seconds")
            elapsed += flip
            next_flip += 3600
    return steps + ["Discharge at 1.2C for 20 seconds"]


def stage_lighting_show_steps(seed, songs):
    """A concert's battery-powered wireless stage lighting (LED uplighters and spots) per cell
    (discharge positive), for each of `songs` songs: 3-6 lighting scenes (0.3-0.9C for 20-90 s), in
    35 % of them a strobe or blinder hit (1.6-2.0C for 5-15 s), then the blackout between songs (0.02C
    for 20-60 s: the receivers and fans only); the interval after half the songs (0.1C for 15 min: the
    house-light wash)."""
    rng = np.random.default_rng(seed)
    steps = []
    for song in range(songs):
        for _ in range(int(rng.integers(3, 7))):
            steps.append(f"Discharge at {rng.uniform(0.3, 0.9):.2f}C for {int(rng.integers(20, 91))} seconds")
            if rng.uniform() < 0.35:
                steps.append(f"Discharge at {rng.uniform(1.6, 2.0):.2f}C for {int(rng.integers(5, 16))} seconds")
        steps.append(f"Discharge at 0.02C for {int(rng.integers(20, 61))} seconds")
        if song + 1 == songs // 2:
            steps.append("Discharge at 0.1C for 15 minutes")
    return steps


def cap_lamp_shift_steps(seed, hours):
    """An underground miner's cap lamp per cell (discharge positive) through a shift of `hours` hours:
    the lamp on its working beam (0.065-0.08C for 20-50 min), spells on the high beam in the headings
    and at the face (0.12-0.16C for 3-12 min), and the methane detector's and tracking tag's hourly
    self-test with the lamp flashing (0.4C for 10 s)."""
    rng = np.random.default_rng(seed)
    steps, elapsed, next_test = [], 0, 3600
    while elapsed < 3600 * hours:
        work, high = 60 * int(rng.integers(20, 51)), 60 * int(rng.integers(3, 13))
        steps += [f"Discharge at {rng.uniform(0.065, 0.08):.3f}C for {work} seconds",
                  f"Discharge at {rng.uniform(0.12, 0.16):.3f}C for {high} seconds"]
        elapsed += work + high
        if elapsed >= next_test:
            steps.append("Discharge at 0.4C for 10 seconds")
            elapsed += 10
            next_test += 3600
    return steps


def light_show_flight_steps(seed, formations):
    """One drone's flight in a drone-swarm light show per cell (discharge positive): the take-off
    climb to the show altitude (2.0-2.4C for 15-25 s), `formations` figures, each a transition to the
    next figure (1.8-2.2C for 6-15 s) and the figure held in the air with the LEDs lit (1.3-1.6C for
    25-60 s), and the descent and landing (0.9-1.1C for 30-45 s)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(2.0, 2.4):.2f}C for {int(rng.integers(15, 26))} seconds"]
    for _ in range(formations):
        steps += [f"Discharge at {rng.uniform(1.8, 2.2):.2f}C for {int(rng.integers(6, 16))} seconds",
                  f"Discharge at {rng.uniform(1.3, 1.6):.2f}C for {int(rng.integers(25, 61))} seconds"]
    return steps + [f"Discharge at {rng.uniform(0.9, 1.1):.2f}C for {int(rng.integers(30, 46))} seconds"]


def ventilator_backup_current(seed, minutes, capacity_A_h=5.0):
    """A transport ventilator running on its internal battery through a mains failure, per cell as a
    1 s current (A, discharge positive) for `minutes` min: breaths at 14-20 per minute (the rate
    changed every 3-6 min), each an inspiration of a third of the breath with the blower spun up
    (0.75-0.9C, rising over 0.3 s) and an expiration with the blower idling and the electronics on
    (0.2C), averaged over each second; the heated humidifier on for 8-12 min twice (0.3C more)."""
    rng = np.random.default_rng(seed)
    n = 60 * minutes
    fine = np.zeros(10 * n)
    k = 0
    while k < len(fine):
        rate, peak = rng.uniform(14, 20), rng.uniform(0.75, 0.9)
        block_end = min(len(fine), k + 10 * 60 * int(rng.integers(3, 7)))
        while k < block_end:
            breath = int(round(600 / rate))
            insp = breath // 3
            ramp = np.minimum(1.0, np.arange(insp) / 3.0)
            fine[k:k + insp] = (0.2 + (peak - 0.2) * ramp)[:max(0, min(insp, len(fine) - k))]
            fine[k + insp:k + breath] = 0.2
            k += breath
    current = fine.reshape(n, 10).mean(axis=1)
    for start in (int(rng.integers(120, 600)), int(rng.integers(n // 2, n - 900))):
        current[start:start + 60 * int(rng.integers(8, 13))] += 0.3
    t = np.arange(n, dtype=float)
    return np.column_stack([t, current * capacity_A_h])


def resurfacer_flood_steps(seed, laps):
    """A battery-electric ice resurfacer's flood of the rink per cell (discharge positive): driven onto
    the ice (0.5-0.7C for 15-25 s), `laps` passes with traction, the conditioner's auger and the water
    pumps working (1.1-1.5C for 40-70 s), each ended by the turn at the boards (0.7-0.9C for 8-15 s);
    driven off to the pit where the snow tank is dumped (the tank lift's hydraulics, 1.8-2.2C for 20-40
    s) and parked (0.01C for 1 min)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(15, 26))} seconds"]
    for _ in range(laps):
        steps += [f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(40, 71))} seconds",
                  f"Discharge at {rng.uniform(0.7, 0.9):.2f}C for {int(rng.integers(8, 16))} seconds"]
    return steps + [f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(15, 26))} seconds",
                    f"Discharge at {rng.uniform(1.8, 2.2):.2f}C for {int(rng.integers(20, 41))} seconds",
                    "Discharge at 0.01C for 1 minutes"]


def paraglider_winch_steps(seed, tows):
    """A battery-electric static tow winch for paragliders per cell, for each of `tows` tows: the pilot
    laying out and hooking in (0.01C for 2-5 min, the controller only), the tow, the drum reeling the
    pilot up under tension (a soft start at 0.8-1.0C for 8-12 s, then 1.6-2.2C for 80-140 s), the
    release, and the line pulled back out along the field by the retrieve quad with the motor braking
    the drum (regenerating, 0.3-0.5C charge for 70-120 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(tows):
        steps += [f"Discharge at 0.01C for {int(rng.integers(120, 301))} seconds",
                  f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for {int(rng.integers(8, 13))} seconds",
                  f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(80, 141))} seconds",
                  f"Charge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(70, 121))} seconds"]
    return steps


def food_cart_day_steps(seed, slots):
    """A street-food cart's battery per cell (discharge positive) in `slots` 15 min slots of service:
    the LED lights, the card terminal and the extractor fan all the time (0.025-0.035C), the
    refrigerated drawer's compressor cycling on for 4-8 min of each slot (0.15-0.2C more), and in 40 %
    of slots the blender or juicer (0.9-1.2C for 20-40 s in all)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(slots):
        base, on = rng.uniform(0.025, 0.035), 60 * int(rng.integers(4, 9))
        rest = 900 - on
        steps.append(f"Discharge at {base + rng.uniform(0.15, 0.2):.3f}C for {on} seconds")
        if rng.uniform() < 0.4:
            blend = int(rng.integers(20, 41))
            steps.append(f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {blend} seconds")
            rest -= blend
        steps.append(f"Discharge at {base:.3f}C for {rest} seconds")
    return steps


def batch_ak(root):
    """Thirty-sixth batch (key "ak"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -10, 2, 5, 12, 18, 26, 33 and 45 degC, each of the
    three models, sampling from 1 to 60 s and a cycler's irregular log, noise from 0.5 to 3 mV, and
    duties no earlier batch used: a telescope mount's astro-imaging night in the frost, a concert's
    wireless stage lighting, an underground miner's cap lamp through a shift, a drone-swarm light
    show, a transport ventilator on its battery through a mains failure (breath by breath), a
    battery-electric ice resurfacer at a rink, a static tow winch for paragliders, and a street-food
    cart's service in a hot city. An SPM control; single effects (negative particle diffusivity x0.35;
    9 % lithium loss; 12 % positive active-material loss; positive exchange current x0.3; lumped
    self-heating, h = 7, temperature recorded) and one no earlier batch concealed: an asymmetric
    charge transfer, the graphite's anodic transfer coefficient 0.4 instead of the symmetric 0.5
    (PyBaMM's asymmetric Butler-Volmer; the exchange current kept), judged by the kinetics words or
    words naming the transfer coefficient / Butler-Volmer / Tafel; and a pair (the voltage channel
    reading 6 mV high with 6 % lithium loss). Words as in batches ah-aj. Each effect's size on its own
    (the nominal candidate, or a replay, against the noise-free voltage or the recording) is in
    truth.json (effect_rmse_mV and the replay keys)."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    # ak1: control, a telescope mount's astro-imaging night, -10 degC, 60 s, 0.5 mV, SPM
    p = at(chen(), -10)
    steps = ["Rest for 10 minutes"] + telescope_night_steps(3601, 6) + ["Rest for 30 minutes"]
    write_case(root, "ak1_control_telescope_mount_imaging_night_minus10C_60s_0p5mV_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 263.15,
                "note": "negative control at -10 degC (a winter night on a mountain observing site; isothermal, not recorded): "
                        "SPM data and model, nothing concealed. A battery-powered telescope mount's astro-imaging night per cell "
                        "from 95 % SOC (telescope_night_steps seed 3601, about 6 h): 10 min rest, per target a slew at 1.2-1.6C "
                        "for 8-25 s, plate-solve and centring nudges at 0.5-0.7C for 3-6 s, tracking with the camera's cooler "
                        "and the dew heaters at 0.08-0.14C for 8-25 min; a meridian flip at 1.3-1.5C for 30-40 s once an hour; "
                        "the mount parked at 1.2C for 20 s; 30 min rest; sampled every 60 s (the mount controller's log), 0.5 mV "
                        "noise"},
               initial_soc=0.95, seed=3601, period=60, noise=5e-4, compare=lion.SPM())
    # ak2: negative particle diffusivity x0.35, a concert's wireless stage lighting and the charge after, 26 degC, 3 s, 0.5 mV, SPMe
    p = at(scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.35), 26)
    steps = (["Rest for 10 minutes"] + stage_lighting_show_steps(3602, 16)
             + ["Rest for 20 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/5", "Rest for 20 minutes"])
    name = "ak2_diffusivity_negative_x0p35_stage_lighting_concert_26C_3s_0p5mV_spme"
    write_case(root, name, lion.SPMe(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": ["particle", "solid diffusiv", "solid-phase diffusiv"],
                "ambient_temperature_K": 299.15,
                "note": "negative particle diffusivity x0.35 (1.16e-14 m2/s for the set's 3.3e-14: a graphite whose particles "
                        "cracked and filled with SEI, or a coarser lot), at 26 degC (a warm concert hall; isothermal, not "
                        "recorded). A concert's battery-powered wireless stage lights per cell from full (stage_lighting_show_steps "
                        "seed 3602, 16 songs: per song 3-6 scenes at 0.3-0.9C for 20-90 s, in 35 % of them a strobe or blinder "
                        "hit at 1.6-2.0C for 5-15 s, a blackout between songs at 0.02C for 20-60 s; a 15 min interval at 0.1C "
                        "after song 8): 10 min rest, the show, 20 min rest (pack-down), the road case's charger at 1C CC-CV to 4.2 V "
                        "and C/5, 20 min rest; sampled every 3 s, 0.5 mV noise; SPMe data and model. effect_rmse_mV is "
                        "time-aligned on the experiment, whose charge ends at another time; spme_nominal_recorded_current_rmse_mV: "
                        "the nominal SPMe driven by the recorded current against the recording (what the diffusivity alone does)"},
               initial_soc=1.0, seed=3602, period=3, noise=5e-4, compare=lion.SPMe())
    recorded_current_rmse(root, name, lion.SPMe(), at(chen(), 26), 1.0, "spme_nominal_recorded_current_rmse_mV")
    # ak3: 9 % lithium loss, an underground miner's cap lamp through a 9 h shift and the lamp-room charger, 33 degC, a cycler's
    # irregular log, 1 mV, SPM
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.91), 33)
    steps = (["Rest for 10 minutes"] + cap_lamp_shift_steps(3603, 9)
             + ["Rest for 30 minutes", "Charge at 0.25C for 150 minutes", "Rest for 30 minutes"])
    write_case(root, "ak3_inventory_9pct_miner_cap_lamp_shift_33C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": lithium_words, "ambient_temperature_K": 306.15,
                "note": "9 % less lithium (initial negative concentration x0.91; the initial state set as full charge of the aged "
                        "cell: the lamp comes off the lamp-room rack full), at 33 degC (a deep, hot mine; isothermal, not "
                        "recorded). A miner's cap lamp replayed on a cycler: 10 min rest, a 9 h shift (cap_lamp_shift_steps seed "
                        "3603: the working beam at 0.065-0.08C for 20-50 min, spells on the high beam at 0.12-0.16C for 3-12 min, "
                        "the methane detector's and tracking tag's hourly self-test at 0.4C for 10 s), 30 min rest, the rack "
                        "charger at 0.25C for 150 min (time-limited), 30 min rest; the cycler's irregular log (1 s in the first "
                        "60 s of a step and in short steps, then 30 s under load / 60 s at rest, plus every 5 mV or 50 mA), 3 mA "
                        "current noise, 0.1 mV / 0.1 mA resolution, 1 mV voltage noise; SPM data and model. effect_rmse_mV is "
                        "what the loss alone does"},
               initial_soc=1.0, seed=3603, cycler=CYCLER, compare=lion.SPM())
    # ak4: 12 % positive active-material loss, two flights of a drone-swarm light show and the fast charge between, 12 degC, 1 s,
    # 2 mV, SPMe
    p = at(scaled(chen(), "Positive electrode active material volume fraction", 0.88), 12)
    steps = (["Rest for 3 minutes"] + light_show_flight_steps(3604, 14) + ["Rest for 5 minutes", "Charge at 1.5C until 4.2 V", "Hold at 4.2 V until C/2", "Rest for 5 minutes"]
             + light_show_flight_steps(36040, 14) + ["Rest for 15 minutes"])
    name = "ak4_lam_positive_12pct_drone_swarm_light_show_12C_1s_2mV_spme"
    write_case(root, name, lion.SPMe(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 285.15,
                "note": "12 % loss of positive active material (volume fraction 0.665 -> 0.5852, the set's initial concentrations, "
                        "so the lithium of the lost material goes with it; the initial state set as 95 % SOC of the aged cell), at "
                        "12 degC (an autumn evening show over a harbour; isothermal, not recorded). One drone of a light-show "
                        "swarm from 95 % SOC: 3 min rest on the launch pad, a flight (light_show_flight_steps seed 3604: the "
                        "climb to show altitude at 2.0-2.4C for 15-25 s, 14 figures, each a transition at 1.8-2.2C for 6-15 s "
                        "and the figure held with the LEDs lit at 1.3-1.6C for 25-60 s, the descent and landing at 0.9-1.1C for "
                        "30-45 s), 5 min rest, the swap-station fast charge at 1.5C CC-CV to 4.2 V and C/2, 5 min rest, the "
                        "encore flight (seed 36040), 15 min rest; sampled every 1 s, 2 mV noise (the flight controller's log); "
                        "SPMe data and model. effect_rmse_mV is time-aligned on the experiment, whose charge ends at another "
                        "time; spme_nominal_recorded_current_rmse_mV: the nominal SPMe driven by the recorded current against the "
                        "recording (what the loss alone does)"},
               initial_soc=0.95, seed=3604, period=1, noise=2e-3, compare=lion.SPMe())
    recorded_current_rmse(root, name, lion.SPMe(), at(chen(), 12), 0.95, "spme_nominal_recorded_current_rmse_mV")
    # ak5: positive exchange current x0.3, a transport ventilator on its battery through a mains failure, breath by breath,
    # 18 degC, 1 s, 1.5 mV, DFN
    p = at(scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.3), 18)
    steps = (["Rest for 5 minutes", pybamm.step.current(ventilator_backup_current(3605, 35)), "Rest for 10 minutes",
              "Charge at 0.3C for 15 minutes", "Rest for 10 minutes"])
    write_case(root, "ak5_kinetics_positive_x0p3_ventilator_mains_failure_breaths_18C_1s_1p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": kinetic_words, "ambient_temperature_K": 291.15,
                "note": "positive exchange-current density x0.3 (all stoichiometries; the activation energy kept: a cathode "
                        "surface grown a resistive rock-salt layer), at 18 degC (an ambulance in autumn; isothermal, not "
                        "recorded). A transport ventilator's internal battery per cell from 90 % SOC: 5 min rest, a 35 min mains "
                        "failure as a 1 s current (ventilator_backup_current seed 3605: breaths at 14-20 per minute, the rate "
                        "changed every 3-6 min, each an inspiration of a third of the breath with the blower at 0.75-0.9C and an "
                        "expiration at 0.2C, averaged over each second; the heated humidifier on for 8-12 min twice at 0.3C "
                        "more; current linear between the 1 s points), 10 min rest, the mains back and the charger at 0.3C for "
                        "15 min, 10 min rest; sampled every 1 s, 1.5 mV noise; DFN data and model. effect_rmse_mV is what the "
                        "slower kinetics alone do"},
               initial_soc=0.9, seed=3605, period=1, noise=1.5e-3, compare=lion.DFN())
    # ak6: lumped self-heating, h = 7, temperature recorded, a battery-electric ice resurfacer's three floods, 5 degC, 5 s, 0.8 mV, DFN
    p = at(chen(), 5)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 7.0})
    steps = ["Rest for 5 minutes"]
    for k, laps in enumerate((9, 8, 9)):
        steps += resurfacer_flood_steps(3606 + 10 * k, laps) + ["Rest for 25 minutes"]
    write_case(root, "ak6_thermal_h7_recorded_ice_resurfacer_rink_5C_5s_0p8mV_dfn", lion.DFN(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "dfn", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 278.15,
                "note": "lumped self-heating, h = 7 W/(m2 K) (cells packed in a closed battery tray under the machine's body), "
                        "ambient and initial 5 degC (the rink's resurfacer room beside the ice). A battery-electric ice "
                        "resurfacer per cell from 95 % SOC: 5 min rest, three floods between the periods of a hockey game "
                        "(resurfacer_flood_steps seeds 3606, 3616, 3626 with 9, 8, 9 laps: driven onto the ice at 0.5-0.7C for "
                        "15-25 s, each lap with traction, auger and water pumps at 1.1-1.5C for 40-70 s and the turn at the "
                        "boards at 0.7-0.9C for 8-15 s, driven off at 0.5-0.7C, the snow tank dumped with the hydraulic lift at "
                        "1.8-2.2C for 20-40 s, parked at 0.01C for 1 min), each followed by 25 min rest; temperature recorded "
                        "(0.05 K noise, 0.1 K resolution); sampled every 5 s, 0.8 mV noise; DFN (lumped thermal) data handed to "
                        "the isothermal DFN. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.95, temperature=True, seed=3606, period=5, noise=8e-4,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.DFN())
    # ak7: an asymmetric charge transfer at the graphite (anodic transfer coefficient 0.4, cathodic 0.6; no earlier batch concealed
    # this), a static tow winch for paragliders with regenerative line retrieval, 2 degC, 10 s, 1 mV, SPMe
    p, steps = ak7_cell_and_day()
    write_case(root, "ak7_asymmetric_charge_transfer_negative_alpha0p4_paraglider_tow_winch_2C_10s_spme",
               lion.SPMe(options={"intercalation kinetics": "asymmetric Butler-Volmer"}), p, steps,
               {"effect": "kinetics", "candidate_model": "spme",
                "accept": kinetic_words + ["transfer coefficient", "Butler-Volmer", "Tafel", "symmetry factor"],
                "ambient_temperature_K": 275.15,
                "note": "an effect no earlier batch concealed: the charge transfer at the graphite is asymmetric, anodic transfer "
                        "coefficient 0.4 and cathodic 0.6 instead of the symmetric 0.5 (PyBaMM's asymmetric Butler-Volmer, "
                        "j = j0 (exp(0.4 F eta / RT) - exp(-0.6 F eta / RT)); the set's exchange current kept; the positive "
                        "symmetric): the same small-signal charge-transfer resistance, but under load the graphite's overpotential "
                        "grows faster on discharge (delithiation) and slower on charge than the symmetric candidate's. Not a "
                        "candidate parameter, its physics is the kinetics family (or its own name: transfer coefficient, "
                        "Butler-Volmer, Tafel). At 2 degC (a winter flying day on an open field; isothermal, not recorded). A "
                        "battery-electric static tow winch per cell from 90 % SOC: 10 min rest, 12 tows (paraglider_winch_steps "
                        "seed 3607: the pilot laying out and hooking in at 0.01C for 2-5 min, the tow with a soft start at "
                        "0.8-1.0C for 8-12 s and the drum reeling in under tension at 1.6-2.2C for 80-140 s, the line pulled "
                        "back out by the retrieve quad with the motor braking the drum, regenerating at 0.3-0.5C for 70-120 s), "
                        "30 min rest; sampled every 10 s (the winch controller's log), 1 mV noise; SPMe (asymmetric "
                        "Butler-Volmer) data handed to the plain SPMe. effect_rmse_mV is what the asymmetry alone does"},
               initial_soc=0.9, seed=3607, period=10, compare=lion.SPMe(),
               surface_form_ok=True)  # as first made; flawed, see remake_ak7
    # ak8: pair: the voltage channel reads 6 mV high, and 6 % lithium loss, a street-food cart's service and the commissary charge,
    # 45 degC, 15 s, 3 mV, SPMe
    def cart_cell(lost):
        return at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 1.0 - lost), 45)
    steps = ["Rest for 10 minutes"] + food_cart_day_steps(3608, 20) + ["Rest for 30 minutes", "Charge at 0.3C for 2 hours", "Rest for 30 minutes"]
    name = "ak8_voltage_offset_6mV_high_and_inventory_6pct_street_food_cart_45C_15s_3mV_spme"
    write_case(root, name, lion.SPMe(), cart_cell(0.06), steps,
               {"effect": "voltage_offset+lithium_inventory_loss", "candidate_model": "spme",
                "accept": ["offset|calibration|voltage measurement|voltage sensor|voltage channel", "inventory|lithium loss|lithium lost|cyclable"],
                "ambient_temperature_K": 318.15,
                "note": "two effects: the cart's battery monitor reads the cell voltage 6 mV high everywhere (a calibration "
                        "offset, under current and at rest alike; not a cell property, an OCP offset is the nearest cell-side "
                        "description and is accepted through 'offset') and 6 % less lithium (initial negative concentration "
                        "x0.94; the initial state set as 95 % SOC of the aged cell), at 45 degC (the battery box under the "
                        "griddle of a street-food cart in a hot city's summer; isothermal, not recorded). The cart's service per "
                        "cell from 95 % SOC: 10 min rest, 5 h of service (food_cart_day_steps seed 3608, 20 slots of 15 min: "
                        "lights, card terminal and extractor fan at 0.025-0.035C throughout, the refrigerated drawer's "
                        "compressor on for 4-8 min of each slot at 0.15-0.2C more, in 40 % of slots the blender or juicer at "
                        "0.9-1.2C for 20-40 s), 30 min rest, the commissary's charger at 0.3C for 2 h (time-limited), 30 min "
                        "rest; sampled every 15 s, 3 mV noise (the cart's cheap battery monitor); SPMe data and model. "
                        "spme_inventory_only_rmse_mV: the SPMe with the lithium loss alone against the recording (what the "
                        "offset leaves); spme_offset_only_rmse_mV: the nominal SPMe read 6 mV high (what the lithium loss "
                        "leaves)"},
               initial_soc=0.95, seed=3608, period=15, noise=3e-3, compare=lion.SPMe(), post=lambda t, i, v: v + 0.006)
    replay_rmse(root, name, lion.SPMe(), cart_cell(0.06), steps, 0.95, "spme_inventory_only_rmse_mV", period=15)
    replay_rmse(root, name, lion.SPMe(), cart_cell(0.0), steps, 0.95, "spme_offset_only_rmse_mV", period=15, shift_V=0.006)

def ak7_cell_and_day():
    """ak7's cell (Chen 2020 at 2 degC, graphite's anodic transfer coefficient 0.4, the positive
    symmetric) and its tow-winch day (seed 3607, 12 tows between rests)."""
    p = at_temperature(chen(), 2)
    p.update({"Negative electrode Butler-Volmer transfer coefficient": 0.4, "Positive electrode Butler-Volmer transfer coefficient": 0.5},
             check_already_exists=False)
    return p, ["Rest for 10 minutes"] + paraglider_winch_steps(3607, 12) + ["Rest for 30 minutes"]


def remake_ak7(root):
    """ak7 made cleanly (not blind: made after its judging): PyBaMM's SPMe with asymmetric
    kinetics is its algebraic-surface-form SPMe, another model, so ak7's recording held that
    model's difference (10.2 mV RMS on its protocol) beside the asymmetry (19.0 mV; together
    11.7 mV, partly cancelling). The same graphite at 0.4 and the same winch day in the DFN,
    handed to the DFN, where the asymmetry is the only difference."""
    p, steps = ak7_cell_and_day()
    write_case(root, "ak7d_asymmetric_charge_transfer_negative_alpha0p4_paraglider_tow_winch_2C_10s_dfn",
               lion.DFN(options={"intercalation kinetics": "asymmetric Butler-Volmer"}), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn",
                "accept": ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate", "transfer coefficient",
                           "Butler-Volmer", "Tafel", "symmetry factor"],
                "ambient_temperature_K": 275.15,
                "note": "ak7 remade in the DFN (not blind): graphite's anodic transfer coefficient 0.4 (PyBaMM's asymmetric "
                        "Butler-Volmer), the positive symmetric, the set's exchange currents, 2 degC, the same tow-winch day "
                        "(paraglider_winch_steps seed 3607), 10 s, 1 mV; DFN data handed to the DFN"},
               initial_soc=0.9, seed=3607, period=10, compare=lion.DFN())


def stairlift_day_steps(seed, trips):
    """A home stairlift's day per cell (discharge positive), `trips` journeys up and down the stairs in
    turn: up, a soft start (0.5-0.7C for 2-3 s) and the climb (1.2-1.6C for 25-40 s), the chair then
    parked at the top off the charge strip (the control board, 0.004C for 20-80 min); down, the motor
    holding the descent (0.3-0.45C for 25-40 s), the chair then parked at the bottom on the charge
    strip (0.05-0.07C charge for 20-80 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(trips):
        park = 60 * int(rng.integers(20, 81))
        if k % 2 == 0:
            steps += [f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(2, 4))} seconds",
                      f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(25, 41))} seconds",
                      f"Discharge at 0.004C for {park} seconds"]
        else:
            steps += [f"Discharge at {rng.uniform(0.3, 0.45):.2f}C for {int(rng.integers(25, 41))} seconds",
                      f"Charge at {rng.uniform(0.05, 0.07):.3f}C for {park} seconds"]
    return steps


def erickshaw_fares_steps(seed, fares):
    """An electric auto-rickshaw's (e-rickshaw's) fares in a crowded city per cell (discharge
    positive), for each of `fares` fares: the wait for passengers at a stand (the lights and the
    meter, 0.005C for 1-6 min), then 4-9 stretches through the traffic, each a pull-away with the
    passengers aboard (1.6-2.2C for 4-8 s), a crawl or cruise (0.4-0.8C for 15-60 s) and a stop in
    the traffic (no current, 5-25 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(fares):
        steps.append(f"Discharge at 0.005C for {int(rng.integers(60, 361))} seconds")
        for _ in range(int(rng.integers(4, 10))):
            steps += [f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(4, 9))} seconds",
                      f"Discharge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(15, 61))} seconds",
                      f"Rest for {int(rng.integers(5, 26))} seconds"]
    return steps


def refuse_round_steps(seed, stops):
    """A battery-electric refuse collection truck's round per cell (discharge positive), for each of
    `stops` stops: the pull-away to the next bins (1.3-1.8C for 8-20 s), the roll (0.3-0.5C for 5-15
    s), regenerative braking (0.8-1.2C charge for 3-6 s), the bin lift's hydraulics (1.0-1.3C for 8-12
    s) and the crew loading (the body's electronics, 0.05C for 10-30 s); every 6-9 stops the packer
    blade compacting the load (1.6-2.0C for 20-30 s)."""
    rng = np.random.default_rng(seed)
    steps, since, pack_after = [], 0, int(rng.integers(6, 10))
    for _ in range(stops):
        steps += [f"Discharge at {rng.uniform(1.3, 1.8):.2f}C for {int(rng.integers(8, 21))} seconds",
                  f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(5, 16))} seconds",
                  f"Charge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(3, 7))} seconds",
                  f"Discharge at {rng.uniform(1.0, 1.3):.2f}C for {int(rng.integers(8, 13))} seconds",
                  f"Discharge at 0.05C for {int(rng.integers(10, 31))} seconds"]
        since += 1
        if since == pack_after:
            steps.append(f"Discharge at {rng.uniform(1.6, 2.0):.2f}C for {int(rng.integers(20, 31))} seconds")
            since, pack_after = 0, int(rng.integers(6, 10))
    return steps


def mobile_xray_round_steps(seed, patients):
    """A battery-driven mobile X-ray unit's ward round per cell (discharge positive), for each of
    `patients` patients: driven along the corridors on its motorised wheels (0.5-0.8C for 40-120 s),
    the tube arm and the detector positioned at the bed (0.15-0.25C for 30-90 s), and 1-3 exposures,
    each the generator drawing on the battery (2.5-3.0C for 2-3 s) and the image checked on the
    console (0.04C for 30-60 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(patients):
        steps += [f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(40, 121))} seconds",
                  f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {int(rng.integers(30, 91))} seconds"]
        for _ in range(int(rng.integers(1, 4))):
            steps += [f"Discharge at {rng.uniform(2.5, 3.0):.2f}C for {int(rng.integers(2, 4))} seconds",
                      f"Discharge at 0.04C for {int(rng.integers(30, 61))} seconds"]
    return steps


def camper_van_night_steps(seed):
    """A camper van's house battery per cell (discharge positive) from the evening's arrival at a
    winter campsite to the morning: the diesel heater started (its glow plug, 0.8-1.0C for 2 min),
    4 h of evening in 15 min slots (lights, water pump and the heater's fan and fuel pump at
    0.02-0.03C, the compressor fridge on for 5-9 min of each slot at 0.04-0.05C more) with dinner
    cooked on the induction hob through the inverter (0.8-1.0C for 10-15 min) after the first hour,
    the night in 1 h slots (the heater's fan at 0.012-0.018C, the fridge on for 3-6 min at 0.04C
    more), and the coffee machine through the inverter in the morning (1.0-1.2C for 2-4 min)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for 120 seconds"]
    for slot in range(16):
        base, on = rng.uniform(0.02, 0.03), 60 * int(rng.integers(5, 10))
        steps += [f"Discharge at {base + rng.uniform(0.04, 0.05):.3f}C for {on} seconds", f"Discharge at {base:.3f}C for {900 - on} seconds"]
        if slot == 3:
            steps.append(f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for {60 * int(rng.integers(10, 16))} seconds")
    for _ in range(8):
        base, on = rng.uniform(0.012, 0.018), 60 * int(rng.integers(3, 7))
        steps += [f"Discharge at {base + 0.04:.3f}C for {on} seconds", f"Discharge at {base:.3f}C for {3600 - on} seconds"]
    return steps + [f"Discharge at {rng.uniform(1.0, 1.2):.2f}C for {60 * int(rng.integers(2, 5))} seconds"]


def snow_blower_steps(seed, passes):
    """A cordless two-stage snow blower clearing a driveway and the pavement per cell (discharge
    positive), for each of `passes` passes: the auger, the impeller and the drive through fresh snow
    (1.1-1.5C for 40-90 s), in 40 % of passes the packed windrow the plough left at the road's edge
    (1.8-2.2C for 8-20 s), and the turn at the end (0.5-0.7C for 5-10 s); every 5-7 passes a pause to
    clear the chute (no current, 20-60 s)."""
    rng = np.random.default_rng(seed)
    steps, since, clear_after = [], 0, int(rng.integers(5, 8))
    for _ in range(passes):
        steps.append(f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(40, 91))} seconds")
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.8, 2.2):.2f}C for {int(rng.integers(8, 21))} seconds")
        steps.append(f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(5, 11))} seconds")
        since += 1
        if since == clear_after:
            steps.append(f"Rest for {int(rng.integers(20, 61))} seconds")
            since, clear_after = 0, int(rng.integers(5, 8))
    return steps


def scissor_lift_shift_steps(seed, jobs, lunch_after):
    """An electric scissor lift's shift on a building site per cell (discharge positive), for each of
    `jobs` jobs: driven to the work position (0.4-0.7C for 20-90 s), the platform raised by the
    hydraulic pump (1.5-1.9C for 15-35 s), 5-15 min of work at height (the controls at 0.01C; in 60 %
    of jobs the platform's socket feeding a drill or a saw at 0.2-0.4C for 1-4 min of it), the
    platform lowered on its valve (0.02C for 25-40 s); after `lunch_after` jobs plugged in over lunch
    (0.3C charge for 45 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for job in range(jobs):
        work = 60 * int(rng.integers(5, 16))
        steps += [f"Discharge at {rng.uniform(0.4, 0.7):.2f}C for {int(rng.integers(20, 91))} seconds",
                  f"Discharge at {rng.uniform(1.5, 1.9):.2f}C for {int(rng.integers(15, 36))} seconds"]
        if rng.uniform() < 0.6:
            tool = 60 * int(rng.integers(1, 5))
            steps += [f"Discharge at {rng.uniform(0.2, 0.4):.2f}C for {tool} seconds", f"Discharge at 0.01C for {work - tool} seconds"]
        else:
            steps.append(f"Discharge at 0.01C for {work} seconds")
        steps.append(f"Discharge at 0.02C for {int(rng.integers(25, 41))} seconds")
        if job + 1 == lunch_after:
            steps.append("Charge at 0.3C for 45 minutes")
    return steps


def pool_robot_cycle_steps(seed, minutes):
    """A cordless robotic pool cleaner's cleaning cycle per cell (discharge positive) for about
    `minutes` min: legs across the floor with the suction pump and the drive tracks working
    (0.4-0.55C for 1-4 min), each ended by a climb of the wall to scrub the waterline (0.75-0.95C for
    15-35 s) and the turn back (0.3C for 5-10 s)."""
    rng = np.random.default_rng(seed)
    steps, elapsed = [], 0
    while elapsed < 60 * minutes:
        leg, climb, turn = int(rng.integers(60, 241)), int(rng.integers(15, 36)), int(rng.integers(5, 11))
        steps += [f"Discharge at {rng.uniform(0.4, 0.55):.3f}C for {leg} seconds",
                  f"Discharge at {rng.uniform(0.75, 0.95):.2f}C for {climb} seconds", f"Discharge at 0.3C for {turn} seconds"]
        elapsed += leg + climb + turn
    return steps


def batch_al(root):
    """Thirty-seventh batch (key "al"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -10, -1, 6, 13, 19, 24, 32 and 44 degC, each of the
    three models, sampling from 1 to 60 s and a cycler's irregular log, noise from 0.5 to 3 mV, and
    duties no earlier batch used: a home stairlift's day on its charge strip, an e-rickshaw's fares in
    a hot city with a midday charge, a battery-electric refuse truck's collection round, a mobile
    X-ray unit's ward rounds and its dock charge, a camper van's winter night on its house battery and
    the drive's charge, a cordless snow blower in the frost, an electric scissor lift's shift on a
    building site, and a cordless robotic pool cleaner's cycle and its charger. An SPM control; single
    effects, three of them in a direction earlier batches rarely used (negative exchange current x1.6,
    faster than the set's; a finer positive powder, particle radius x0.75; a low-temperature
    electrolyte better than the set's, conductivity x1.8 and diffusivity x1.5) and two common ones in
    new settings (a 5 mOhm contact resistance at 44 degC; lumped self-heating, h = 12, temperature
    recorded, at -10 degC); and two pairs no earlier batch concealed together (one-state hysteresis of
    the negative OCP, +-10 mV, with positive particle diffusivity x0.6; the positive electrode's
    electronic conductivity x0.25 with 6 % lithium loss). Words as in batches ah-ak; the particle
    radius by the particle words or its own name (radius, particle size); the electrode conductivity
    by the series / ohmic resistance family or by its own name, as ai3. Each effect's size on its own
    (the nominal candidate, or a replay, against the noise-free voltage or the recording) is in
    truth.json (effect_rmse_mV and the replay keys); every charge is time-limited, so the
    experiment-aligned comparison needs no replay on the recorded current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    # al1: control, a home stairlift's day, 19 degC, a cycler's irregular log, 1 mV, SPM
    p = at(chen(), 19)
    steps = ["Rest for 10 minutes"] + stairlift_day_steps(3701, 16) + ["Rest for 30 minutes"]
    write_case(root, "al1_control_home_stairlift_day_19C_cycler_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 292.15,
                "note": "negative control at 19 degC (a house's stairwell; isothermal, not recorded): SPM data and model, nothing "
                        "concealed. A home stairlift's day replayed on a cycler from 60 % SOC (a battery left off its charge "
                        "strip overnight): 10 min rest, 16 journeys (stairlift_day_steps seed 3701: up, a soft start at 0.5-0.7C "
                        "for 2-3 s and the climb at 1.2-1.6C for 25-40 s, the chair then parked at the top off the charge strip, "
                        "the control board at 0.004C for 20-80 min; down, the motor holding the descent at 0.3-0.45C for 25-40 s, "
                        "the chair then parked at the bottom on the charge strip at 0.05-0.07C charge for 20-80 min), 30 min "
                        "rest; 13.1 h, the state of charge between about 58 and 85 %; the cycler's irregular log (1 s in the "
                        "first 60 s of a step and in short steps, then 30 s under load / 60 s at rest, plus every 5 mV or 50 mA), "
                        "3 mA current noise, 0.1 mV / 0.1 mA resolution, 1 mV voltage noise"},
               initial_soc=0.6, seed=3701, cycler=CYCLER, compare=lion.SPM())
    # al2: 5 mOhm contact resistance, an e-rickshaw's fares and a midday charge in a hot city, 44 degC, 5 s, 2 mV, SPM
    p = at(chen(), 44)
    p.update({"Contact resistance [Ohm]": 0.005}, check_already_exists=False)
    steps = (["Rest for 10 minutes"] + erickshaw_fares_steps(3702, 6)
             + ["Rest for 5 minutes", "Charge at 0.5C for 35 minutes", "Rest for 5 minutes"]
             + erickshaw_fares_steps(37020, 6) + ["Rest for 30 minutes"])
    write_case(root, "al2_contact_5mOhm_erickshaw_fares_midday_charge_44C_5s_2mV_spm",
               lion.SPM(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spm", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 317.15,
                "note": "a 5 mOhm contact resistance (a tab weld cracked by the vibration of potholed streets, or a corroded "
                        "busbar bolt: about 50 mV at a 2C pull-away, 15 mV while cruising, -12 mV on the charge), at 44 degC (the "
                        "battery box under the seat of an e-rickshaw in a hot city's pre-monsoon summer; isothermal, not "
                        "recorded). From 95 % SOC: 10 min rest, 6 fares (erickshaw_fares_steps seed 3702: per fare the wait for "
                        "passengers at a stand with the lights and the meter at 0.005C for 1-6 min, then 4-9 stretches through "
                        "the traffic, each a pull-away with the passengers aboard at 1.6-2.2C for 4-8 s, a crawl or cruise at "
                        "0.4-0.8C for 15-60 s and a stop in the traffic at no current for 5-25 s), 5 min rest, a midday charge at "
                        "a charging point at 0.5C for 35 min (time-limited), 5 min rest, 6 more fares (seed 37020), 30 min rest; "
                        "the state of charge down to about 58 %, up to about 88 %, down to about 53 %; sampled every 5 s, 2 mV "
                        "noise (the vehicle's BMS); SPM (with contact resistance) data handed to the plain SPM. effect_rmse_mV is "
                        "what the resistance alone does"},
               initial_soc=0.95, seed=3702, period=5, noise=2e-3, compare=lion.SPM())
    # al3: negative exchange current x1.6 (faster than the set's), a refuse truck's collection round, 13 degC, 2 s, 1 mV, DFN
    p = at(scaled(chen(), "Negative electrode exchange-current density [A.m-2]", 1.6), 13)
    steps = (["Rest for 10 minutes", "Discharge at 0.8C for 5 minutes"] + refuse_round_steps(3703, 45)
             + ["Discharge at 0.8C for 6 minutes", "Rest for 30 minutes"])
    write_case(root, "al3_kinetics_negative_x1p6_faster_refuse_truck_round_13C_2s_dfn", lion.DFN(), p, steps,
               {"effect": "kinetics", "candidate_model": "dfn", "accept": kinetic_words, "ambient_temperature_K": 286.15,
                "note": "negative exchange-current density x1.6, faster than the set's (all stoichiometries, the activation "
                        "energy kept: a graphite from another supplier whose edge-rich surface and thin formation SEI react "
                        "faster than the LG M50's), at 13 degC (an autumn morning round; isothermal, not recorded). A "
                        "battery-electric refuse collection truck's round per cell from 95 % SOC: 10 min rest, the drive out of "
                        "the depot at 0.8C for 5 min, 45 stops (refuse_round_steps seed 3703: the pull-away to the next bins at "
                        "1.3-1.8C for 8-20 s, the roll at 0.3-0.5C for 5-15 s, regenerative braking at 0.8-1.2C charge for 3-6 s, "
                        "the bin lift's hydraulics at 1.0-1.3C for 8-12 s, the crew loading with the body's electronics at 0.05C "
                        "for 10-30 s; every 6-9 stops the packer blade compacting the load at 1.6-2.0C for 20-30 s), the drive to "
                        "the tip at 0.8C for 6 min, 30 min rest; down to about 32 %; sampled every 2 s, 1 mV noise; DFN data and "
                        "model. effect_rmse_mV is what the faster kinetics alone do"},
               initial_soc=0.95, seed=3703, period=2, compare=lion.DFN())
    # al4: positive particle radius x0.75 (a finer cathode powder), a mobile X-ray unit's ward rounds and its dock charge, 24 degC,
    # 1 s, 1.5 mV, DFN
    p = at(scaled(chen(), "Positive particle radius [m]", 0.75), 24)
    steps = (["Rest for 10 minutes"] + mobile_xray_round_steps(3704, 18)
             + ["Rest for 10 minutes", "Charge at 0.6C for 30 minutes", "Rest for 20 minutes"]
             + mobile_xray_round_steps(37040, 8) + ["Rest for 20 minutes"])
    write_case(root, "al4_radius_positive_x0p75_mobile_xray_ward_rounds_24C_1s_1p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": particle_words + ["radius", "particle size"],
                "ambient_temperature_K": 297.15,
                "note": "positive particle radius x0.75 (3.9 um instead of the set's 5.22 um: a finer NMC 811 powder from another "
                        "lot; the diffusion time R^2/D x0.56 and the surface per volume x1.33, so the positive's reaction "
                        "overpotential smaller too, the active-material volume fraction and the capacity the set's); not a "
                        "candidate parameter, its physics is the particle diffusion family (or its own name, radius / particle "
                        "size). At 24 degC (a hospital's wards; isothermal, not recorded). A battery-driven mobile X-ray unit per "
                        "cell from 90 % SOC: 10 min rest, a morning ward round (mobile_xray_round_steps seed 3704, 18 patients: "
                        "driven along the corridors on its motorised wheels at 0.5-0.8C for 40-120 s, the tube arm and the "
                        "detector positioned at the bed at 0.15-0.25C for 30-90 s, 1-3 exposures, each the generator drawing on "
                        "the battery at 2.5-3.0C for 2-3 s and the image checked on the console at 0.04C for 30-60 s), 10 min "
                        "rest, docked in the imaging department at 0.6C charge for 30 min (time-limited), 20 min rest, an "
                        "afternoon call-out round (seed 37040, 8 patients), 20 min rest; down to about 46 %, up to about 76 %, "
                        "down to about 59 %; sampled every 1 s, 1.5 mV noise; DFN data and model. effect_rmse_mV is what the "
                        "finer powder alone does"},
               initial_soc=0.9, seed=3704, period=1, noise=1.5e-3, compare=lion.DFN())
    # al5: a low-temperature electrolyte (conductivity x1.8, diffusivity x1.5), a camper van's winter night and the drive's
    # charge, -1 degC, 10 s, 0.5 mV, SPMe
    p = at(scaled(scaled(chen(), "Electrolyte conductivity [S.m-1]", 1.8), "Electrolyte diffusivity [m2.s-1]", 1.5), -1)
    steps = camper_van_night_steps(3705) + ["Rest for 10 minutes", "Charge at 0.4C for 60 minutes", "Rest for 20 minutes"]
    write_case(root, "al5_electrolyte_conductivity_x1p8_diffusivity_x1p5_camper_van_winter_night_minus1C_10s_0p5mV_spme", lion.SPMe(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "spme", "accept": ["electrolyte"], "ambient_temperature_K": 272.15,
                "note": "a low-temperature electrolyte: conductivity x1.8 and diffusivity x1.5 at every concentration (an ester "
                        "co-solvent such as methyl acetate in the carbonate blend, chosen for winter use: less viscous, more "
                        "mobile ions), better than the set's, at -1 degC (a camper van's house battery under a seat on a winter "
                        "campsite; isothermal, not recorded). From 95 % SOC (camper_van_night_steps seed 3705): the diesel heater "
                        "started, its glow plug at 0.85C for 2 min; 4 h of evening in 15 min slots (lights, water pump and the "
                        "heater's fan and fuel pump at 0.02-0.03C, the compressor fridge on for 5-9 min of each slot at "
                        "0.04-0.05C more) with dinner cooked on the induction hob through the inverter at 0.93C for 13 min after "
                        "the first hour; the night in 1 h slots (the heater's fan at 0.012-0.018C, the fridge on for 3-6 min at "
                        "0.04C more) for 8 h; the coffee machine through the inverter at 1.14C for 4 min; 10 min rest, the drive "
                        "with the DC-DC charger from the alternator at 0.4C for 60 min (time-limited), 20 min rest; 13.8 h, down "
                        "to about 31 %, back to about 71 %; sampled every 10 s, 0.5 mV noise (a shunt-based battery monitor); "
                        "SPMe data and model. effect_rmse_mV is what the electrolyte alone does"},
               initial_soc=0.95, seed=3705, period=10, noise=5e-4, compare=lion.SPMe())
    # al6: lumped self-heating, h = 12, temperature recorded, a cordless snow blower in the frost, -10 degC, 3 s, 3 mV, SPMe
    p = at(chen(), -10)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 12.0})
    steps = (["Rest for 5 minutes"] + snow_blower_steps(3706, 16) + ["Rest for 40 minutes"] + snow_blower_steps(37060, 8) + ["Rest for 30 minutes"])
    write_case(root, "al6_thermal_h12_recorded_snow_blower_frost_minus10C_3s_3mV_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 263.15,
                "note": "lumped self-heating, h = 12 W/(m2 K) (cells in the snow blower's closed plastic battery pack, a little "
                        "air from the impeller), ambient and initial -10 degC (a clear morning after a snowfall). A cordless "
                        "two-stage snow blower per cell from 95 % SOC: 5 min rest, the driveway and the pavement "
                        "(snow_blower_steps seed 3706, 16 passes: the auger, the impeller and the drive through fresh snow at "
                        "1.1-1.5C for 40-90 s, in 40 % of passes the packed windrow the plough left at the road's edge at "
                        "1.8-2.2C for 8-20 s, the turn at the end at 0.5-0.7C for 5-10 s; every 5-7 passes a pause to clear the "
                        "chute, no current for 20-60 s), 40 min rest outside, the plough's second windrow and the path to the "
                        "shed (seed 37060, 8 passes), 30 min rest outside; down to about 52 % and then 32 %; the cell warms by "
                        "about 19 K (to about +9 degC) in the first session and cools back towards the ambient in the rests; "
                        "temperature recorded (0.05 K noise, 0.1 K resolution); sampled every 3 s, 3 mV noise (the tool's BMS); "
                        "SPMe (lumped thermal) data handed to the isothermal SPMe. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.95, temperature=True, seed=3706, period=3, noise=3e-3,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.SPMe())
    # al7: pair, one-state hysteresis of the negative OCP (+-10 mV) and positive particle diffusivity x0.6, an electric scissor
    # lift's shift with a lunch charge and the overnight charger, 6 degC, 20 s, 0.8 mV, SPM
    def lift_cell(hysteresis, diffusivity):
        q = at(scaled(chen(), "Positive particle diffusivity [m2.s-1]", diffusivity), 6)
        if hysteresis:
            with_negative_hysteresis(q, 0.010)
        return q
    hysteresis_spm = lambda: lion.SPM(options={"open-circuit potential": ("one-state hysteresis", "single")})
    steps = (["Rest for 10 minutes"] + scissor_lift_shift_steps(3707, 20, 10)
             + ["Rest for 10 minutes", "Charge at 0.2C for 100 minutes", "Rest for 30 minutes"])
    name = "al7_hysteresis_negative_10mV_and_diffusivity_positive_x0p6_scissor_lift_shift_6C_20s_0p8mV_spm"
    write_case(root, name, hysteresis_spm(), lift_cell(True, 0.6), steps,
               {"effect": "hysteresis+solid_diffusivity", "candidate_model": "spm",
                "accept": ["hysteresis", "particle|solid diffusiv|solid-phase diffusiv"], "ambient_temperature_K": 279.15,
                "note": "two effects: one-state OCV hysteresis of the negative electrode, lithiation and delithiation OCPs 10 mV "
                        "either side of the set's (decay rate 10, initial state 0, the middle; the SiOx in the LG M50's "
                        "graphite), and positive particle diffusivity x0.6 (2.4e-15 m2/s for the set's 4e-15: a cathode aged by "
                        "cycling), at 6 degC (a building site in early spring; isothermal, not recorded). An electric scissor "
                        "lift's shift per cell from 90 % SOC: 10 min rest, 20 jobs (scissor_lift_shift_steps seed 3707: driven to "
                        "the work position at 0.4-0.7C for 20-90 s, the platform raised by the hydraulic pump at 1.5-1.9C for "
                        "15-35 s, 5-15 min of work at height with the controls at 0.01C, in 60 % of jobs the platform's socket "
                        "feeding a drill or a saw at 0.2-0.4C for 1-4 min of it, the platform lowered on its valve at 0.02C for "
                        "25-40 s), plugged in over lunch after job 10 at 0.3C charge for 45 min, 10 min rest after the last job, "
                        "the overnight charger at 0.2C for 100 min (time-limited), 30 min rest; down to about 60 %, up to about "
                        "83 %, down to about 54 %, back to about 87 %; sampled every 20 s (the machine's telematics), 0.8 mV "
                        "noise; SPM (one-state hysteresis) data handed to the plain SPM. spm_hysteresis_only_rmse_mV: the SPM "
                        "with the hysteresis and the set's diffusivity against the recording (what the diffusivity leaves); "
                        "spm_diffusivity_only_rmse_mV: the plain SPM with the diffusivity x0.6 (what the hysteresis leaves)"},
               initial_soc=0.9, seed=3707, period=20, noise=8e-4, compare=lion.SPM())
    replay_rmse(root, name, hysteresis_spm(), lift_cell(True, 1.0), steps, 0.9, "spm_hysteresis_only_rmse_mV", period=20)
    replay_rmse(root, name, lion.SPM(), lift_cell(False, 0.6), steps, 0.9, "spm_diffusivity_only_rmse_mV", period=20)
    # al8: pair, positive electrode conductivity x0.25 and 6 % lithium loss, a cordless pool robot's cycle and its charger, 32 degC,
    # 60 s, 1.5 mV, DFN
    def pool_cell(conductivity, lost):
        q = scaled(chen(), "Positive electrode conductivity [S.m-1]", conductivity)
        return at(scaled(q, "Initial concentration in negative electrode [mol.m-3]", 1.0 - lost), 32)
    steps = (["Rest for 10 minutes"] + pool_robot_cycle_steps(3708, 70)
             + ["Rest for 30 minutes", "Charge at 0.4C for 80 minutes", "Rest for 30 minutes"])
    name = "al8_positive_conductivity_x0p25_and_inventory_6pct_pool_robot_32C_60s_1p5mV_dfn"
    write_case(root, name, lion.DFN(), pool_cell(0.25, 0.06), steps,
               {"effect": "electrode_conductivity+lithium_inventory_loss", "candidate_model": "dfn",
                "accept": ["contact|series resistance|ohmic|electronic conductivity|electrode conductivity|solid-phase conductivity"
                           "|solid conductivity",
                           "inventory|lithium loss|lithium lost|cyclable"],
                "ambient_temperature_K": 305.15,
                "note": "two effects: the positive electrode's electronic conductivity x0.25 (0.045 S/m instead of 0.18: a "
                        "carbon-binder network degraded in a hot, wet device, the particles losing electronic contact with each "
                        "other) and 6 % less lithium (initial negative concentration x0.94; the initial state set as 95 % SOC of "
                        "the aged cell), at 32 degC (the sealed robot in a hot-climate pool's water in summer; isothermal, not "
                        "recorded). A cordless robotic pool cleaner per cell from 95 % SOC: 10 min rest, a 70 min cleaning cycle "
                        "(pool_robot_cycle_steps seed 3708: legs across the floor with the suction pump and the drive tracks "
                        "working at 0.4-0.55C for 1-4 min, each ended by a climb of the wall to scrub the waterline at 0.75-0.95C "
                        "for 15-35 s and the turn back at 0.3C for 5-10 s), 30 min rest (lifted out and drip-dried), the charger "
                        "at 0.4C for 80 min (time-limited), 30 min rest; down to about 33 %, back to about 86 % (counted in the "
                        "set's 5 A h); sampled every 60 s (the robot's app log: inside a step only every 60 s, every step's start "
                        "and end), 1.5 mV noise; DFN data and model. The electrode conductivity is judged by the series / ohmic "
                        "resistance family or by its own name, as ai3. dfn_conductivity_only_rmse_mV: the DFN with the "
                        "conductivity x0.25 and the set's lithium against the recording (what the lithium loss leaves); "
                        "dfn_inventory_only_rmse_mV: the DFN with the lithium loss and the set's conductivity (what the "
                        "conductivity leaves)"},
               initial_soc=0.95, seed=3708, period=60, noise=1.5e-3, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), pool_cell(0.25, 0.0), steps, 0.95, "dfn_conductivity_only_rmse_mV", period=60)
    replay_rmse(root, name, lion.DFN(), pool_cell(1.0, 0.06), steps, 0.95, "dfn_inventory_only_rmse_mV", period=60)


def ice_fishing_day_steps(seed, holes):
    """An ice-fishing day's portable power pack per cell (discharge positive), for each of `holes`
    holes: the cordless auger drilling through the ice (1.2-1.6C for 15-35 s), reversed to clear the
    slush (0.3-0.5C for 3-6 s), the walk to the next spot (no current, 1-4 min); after every 3-4
    holes a spell of fishing in the shelter with the sonar fish finder, the lights and the shelter's
    heater fan (0.03-0.05C for 20-40 min)."""
    rng = np.random.default_rng(seed)
    steps, since, fish_after = [], 0, int(rng.integers(3, 5))
    for _ in range(holes):
        steps += [f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(15, 36))} seconds",
                  f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(3, 7))} seconds",
                  f"Rest for {int(rng.integers(60, 241))} seconds"]
        since += 1
        if since == fish_after:
            steps.append(f"Discharge at {rng.uniform(0.03, 0.05):.3f}C for {60 * int(rng.integers(20, 41))} seconds")
            since, fish_after = 0, int(rng.integers(3, 5))
    return steps


def feed_pusher_round_steps(seed, legs):
    """A dairy barn's feed-pushing robot's round per cell (discharge positive), for each of `legs`
    legs along the feed fence: pushing the feed back to the cows with its rotating skirt (0.7-1.0C
    for 40-120 s), in 30 % of legs a heavy heap left by the cows (1.4-1.8C for 5-15 s), and the turn
    at the end of the fence (0.4C for 5-10 s); then the drive back to its charging station (0.5C for
    30-60 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(legs):
        steps.append(f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {int(rng.integers(40, 121))} seconds")
        if rng.uniform() < 0.3:
            steps.append(f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {int(rng.integers(5, 16))} seconds")
        steps.append(f"Discharge at 0.4C for {int(rng.integers(5, 11))} seconds")
    return steps + [f"Discharge at 0.5C for {int(rng.integers(30, 61))} seconds"]


def patient_hoist_round_steps(seed, transfers):
    """A care home's mobile patient hoist per cell (discharge positive) through a round of
    `transfers` transfers in quick succession (the morning get-up round): the resident lifted from
    the bed in the sling (1.8-2.4C for 12-25 s), the boom's leg spread adjusted (0.6-0.8C for 3-5 s),
    the hoist wheeled by the carer to the chair (the control box, 0.004C for 30-90 s), the resident
    lowered with the motor running (0.3-0.5C for 10-20 s), and the sling unhooked and the hoist taken
    to the next room (0.004C for 2-5 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(transfers):
        steps += [f"Discharge at {rng.uniform(1.8, 2.4):.2f}C for {int(rng.integers(12, 26))} seconds",
                  f"Discharge at {rng.uniform(0.6, 0.8):.2f}C for {int(rng.integers(3, 6))} seconds",
                  f"Discharge at 0.004C for {int(rng.integers(30, 91))} seconds",
                  f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Discharge at 0.004C for {60 * int(rng.integers(2, 6))} seconds"]
    return steps


def harvest_trolley_day_steps(seed, rows, stops=5):
    """A tomato greenhouse's battery pipe-rail harvesting trolley per cell (discharge positive) through
    a day of `rows` rows: driven in along the heating pipes (0.4-0.6C for 60-120 s), `stops` picking
    stops per row, each the scissor platform raised (1.2-1.5C for 8-15 s), the picking with the work
    lights and the crate conveyor on (0.03-0.05C for 3-6 min) and the move along the row (0.3C for
    10-20 s), driven out with the full crates (0.5-0.7C for 60-120 s), and the crates unloaded on the
    path (no current, 1-3 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(rows):
        steps.append(f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(60, 121))} seconds")
        for _ in range(stops):
            steps += [f"Discharge at {rng.uniform(1.2, 1.5):.2f}C for {int(rng.integers(8, 16))} seconds",
                      f"Discharge at {rng.uniform(0.03, 0.05):.3f}C for {60 * int(rng.integers(3, 7))} seconds",
                      f"Discharge at 0.3C for {int(rng.integers(10, 21))} seconds"]
        steps += [f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(60, 121))} seconds",
                  f"Rest for {int(rng.integers(60, 181))} seconds"]
    return steps


def mini_excavator_current(seed, minutes, capacity_A_h=5.0, dt=2):
    """A battery-electric mini excavator digging a trench, per cell as a current at `dt` s knots (A,
    discharge positive, linear between knots) for `minutes` min: dig cycles of 12-18 s (the bucket
    filled, 1.6-2.2C for 4-6 s; the loaded swing, 1.0-1.3C for 3-5 s; the dump, 0.5-0.7C for 2-3 s;
    the swing back, 0.7-0.9C for 3-4 s), every 8-12 cycles the machine tracked forward along the
    trench (0.8-1.0C for 10-20 s); the 1 s profile averaged over each `dt` s (the machine's
    controller logs its mean current)."""
    rng = np.random.default_rng(seed)
    n = 60 * minutes
    current, k, since, move_after = np.zeros(n), 0, 0, int(rng.integers(8, 13))
    while k < n:
        for rate, (lo, hi) in ((rng.uniform(1.6, 2.2), (4, 7)), (rng.uniform(1.0, 1.3), (3, 6)), (rng.uniform(0.5, 0.7), (2, 4)),
                                (rng.uniform(0.7, 0.9), (3, 5))):
            d = int(rng.integers(lo, hi))
            current[k:k + d] = rate
            k += d
        since += 1
        if since == move_after:
            d = int(rng.integers(10, 21))
            current[k:k + d] = rng.uniform(0.8, 1.0)
            k += d
            since, move_after = 0, int(rng.integers(8, 13))
    current = current[:n - n % dt].reshape(-1, dt).mean(axis=1)
    return np.column_stack([dt * np.arange(len(current), dtype=float), current * capacity_A_h])


def vaccine_fridge_night_steps(seed, hours=12):
    """A rural clinic's solar vaccine refrigerator's battery per cell (discharge positive) through the
    night from dusk to dawn, `hours` h: the compressor cycling on the thermostat (on at 0.12-0.16C
    for 10-20 min, then off with the controller and the temperature logger at 0.005C for 15-35 min),
    and for the first 3 h the clinic's lights and a phone charger (0.05C more)."""
    rng = np.random.default_rng(seed)
    steps, elapsed = [], 0
    while elapsed < 3600 * hours:
        extra = 0.05 if elapsed < 3 * 3600 else 0.0
        on, off = 60 * int(rng.integers(10, 21)), 60 * int(rng.integers(15, 36))
        steps += [f"Discharge at {rng.uniform(0.08, 0.11) + extra:.3f}C for {on} seconds", f"Discharge at {0.005 + extra:.3f}C for {off} seconds"]
        elapsed += on + off
    return steps


def solar_morning_charge_steps(seed, hours=6):
    """The same refrigerator's morning: the panel's charge rising through the morning sun in 30 min
    blocks (0.04-0.3C charge, less under passing cloud), the compressor still cycling (0.13C for 15 min of
    each block, counted against the charge)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(2 * hours):
        sun = 0.3 * np.sin(np.pi * (k + 0.5) / (4 * hours)) * rng.uniform(0.6, 1.0)
        steps += [f"Charge at {max(0.01, sun - 0.13):.3f}C for 900 seconds", f"Charge at {sun:.3f}C for 900 seconds"]
    return steps


def shearing_run_steps(seed, sheep):
    """A cordless sheep-shearing handpiece through a run in a shearing shed, per cell (discharge
    positive), for each of `sheep` sheep: 4-7 blows, each the comb through the fleece (1.2-1.6C for
    12-30 s) and the handpiece running free between blows (0.3C for 2-5 s); then the shorn sheep
    let out and the next dragged from the pen (no current, 25-60 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(sheep):
        for _ in range(int(rng.integers(4, 8))):
            steps += [f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(12, 31))} seconds",
                      f"Discharge at 0.3C for {int(rng.integers(2, 6))} seconds"]
        steps.append(f"Rest for {int(rng.integers(25, 61))} seconds")
    return steps


def floor_scrubber_night_steps(seed, aisles):
    """A supermarket's ride-on floor scrubber-dryer through the night per cell (discharge positive),
    for each of `aisles` aisles: the brush deck, the vacuum and the solution pump working down the
    aisle (0.35-0.5C for 60-180 s), the squeegee lifted for the turn at the end (0.2C for 8-15 s);
    every 6-8 aisles the recovery tank emptied and the solution tank refilled (the machine off, 4-8
    min)."""
    rng = np.random.default_rng(seed)
    steps, since, tank_after = [], 0, int(rng.integers(6, 9))
    for _ in range(aisles):
        steps += [f"Discharge at {rng.uniform(0.35, 0.5):.2f}C for {int(rng.integers(60, 181))} seconds",
                  f"Discharge at 0.2C for {int(rng.integers(8, 16))} seconds"]
        since += 1
        if since == tank_after:
            steps.append(f"Rest for {60 * int(rng.integers(4, 9))} seconds")
            since, tank_after = 0, int(rng.integers(6, 9))
    return steps


def batch_am(root):
    """Thirty-eighth batch (key "am"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -15, -8, 2, 10, 20, 28, 36 and 45 degC, each of the
    three models, sampling from 1 to 60 s and a cycler's irregular log, noise from 0.5 to 3 mV, and
    duties no earlier batch used: an ice-fishing day's auger and shelter on a frozen lake, a dairy
    barn's feed-pushing robot and its dock, a care home's mobile patient hoist, a tomato greenhouse's
    pipe-rail harvesting trolley, a battery-electric mini excavator digging a trench with a lunchtime
    charge, a rural clinic's solar vaccine refrigerator through a hot night and the morning sun, a
    cordless sheep-shearing handpiece in a cold shed, and a supermarket's floor scrubber-dryer through
    the night and its charger. An SPMe control; single effects, two of them better than the set's
    (positive exchange current x1.8, faster; a heavier positive coating, electrode thickness x1.08),
    two the set's structure at another value (negative particle radius x2, a coarser graphite; the
    negative's tortuosity higher, Bruggeman exponent 1.8 for 1.5) and a common one (6 % lithium loss,
    most of its misfit in one stretch of the night); and two pairs no earlier batch concealed
    together (the positive electrode's electronic conductivity x0.4 with lumped self-heating, h = 10,
    temperature recorded; the electrolyte's salt concentration x0.7 with 6 % lithium loss, as SEI
    growth gives them). Words as in batches ah-al; the particle radius by the particle words or its
    own name (radius, particle size); the thickness by the active-material words or its own name
    (thickness, loading); the tortuosity by the electrolyte words or its own name (tortuosity,
    Bruggeman, MacMullin); the salt by "electrolyte" or "salt"; the electrode conductivity by the
    series / ohmic resistance family or by its own name, as ai3 and al8. Each effect's size on its
    own (the nominal candidate, or a replay, against the noise-free voltage or the recording) is in
    truth.json (effect_rmse_mV and the replay keys); every charge is time-limited, so the
    experiment-aligned comparison needs no replay on the recorded current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    # am1: control, an ice-fishing day's power pack, -15 degC, a cycler's irregular log, 1 mV, SPMe
    p = at(chen(), -15)
    steps = ["Rest for 10 minutes"] + ice_fishing_day_steps(3801, 14) + ["Rest for 30 minutes"]
    write_case(root, "am1_control_ice_fishing_auger_day_minus15C_cycler_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 258.15,
                "note": "negative control at -15 degC (a frozen lake in mid-winter; isothermal, not recorded): SPMe data and model, "
                        "nothing concealed. An ice-fishing day's portable power pack replayed on a cycler in a climate chamber from 90 "
                        "% SOC: 10 min rest, 14 holes (ice_fishing_day_steps seed 3801: the cordless auger drilling through the ice at "
                        "1.2-1.6C for 15-35 s, reversed to clear the slush at 0.3-0.5C for 3-6 s, the walk to the next spot at no "
                        "current for 1-4 min; after every 3-4 holes a spell of fishing in the shelter with the sonar fish finder, the "
                        "lights and the heater fan at 0.03-0.05C for 20-40 min), 30 min rest; 3.9 h, down to about 64 %; the cycler's "
                        "irregular log (1 s in the first 60 s of a step and in short steps, then 30 s under load / 60 s at rest, plus "
                        "every 5 mV or 50 mA), 3 mA current noise, 0.1 mV / 0.1 mA resolution, 1 mV voltage noise"},
               initial_soc=0.9, seed=3801, cycler=CYCLER, compare=lion.SPMe())
    # am2: positive exchange current x1.8 (faster), a dairy barn's feed-pushing robot's rounds and its dock charges, -8 degC,
    # 1 s, 0.5 mV, SPM
    p = at(scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 1.8), -8)
    steps = ["Rest for 5 minutes"]
    for k in range(3):
        steps += feed_pusher_round_steps(3802 + 10 * k, 9) + ["Charge at 0.6C for 9 minutes"]
    steps += ["Rest for 5 minutes"]
    write_case(root, "am2_kinetics_positive_x1p8_faster_barn_feed_pusher_robot_minus8C_1s_0p5mV_spm", lion.SPM(), p, steps,
               {"effect": "kinetics", "candidate_model": "spm", "accept": kinetic_words, "ambient_temperature_K": 265.15,
                "note": "positive exchange-current density x1.8, faster than the set's (all stoichiometries, the activation energy "
                        "kept: an NMC 811 whose particles carry a thin conductive coating from another supplier's process, so more of "
                        "their surface reacts), at -8 degC (an unheated dairy barn in a cold winter; isothermal, not recorded). A "
                        "battery feed-pushing robot per cell from 75 % SOC: 5 min rest, three rounds of the feed fence, each followed "
                        "by a charge on its dock at 0.6C for 9 min (time-limited) (feed_pusher_round_steps seeds 3802, 3812, 3822, 9 "
                        "legs each: pushing the feed back to the cows with the rotating skirt at 0.7-1.0C for 40-120 s, in 30 % of legs "
                        "a heavy heap left by the cows at 1.4-1.8C for 5-15 s, the turn at the end of the fence at 0.4C for 5-10 s; the "
                        "drive back to the dock at 0.5C for 30-60 s), 5 min rest; 1.4 h, the state of charge down to about 58, 42 and "
                        "32 % after the rounds, each charge giving back about 9 %; the misfit spread over every load (the candidate's "
                        "positive overpotential larger than the data's on discharge and on charge); sampled every 1 s, 0.5 mV noise; "
                        "SPM data and model. effect_rmse_mV is what the faster kinetics alone do"},
               initial_soc=0.75, seed=3802, period=1, noise=5e-4, compare=lion.SPM())
    # am3: negative particle radius x2 (a coarser natural graphite), a care home's mobile patient hoist, 28 degC, 5 s, 1.5 mV, DFN
    p = at(scaled(chen(), "Negative particle radius [m]", 2.0), 28)
    steps = (["Rest for 10 minutes"] + patient_hoist_round_steps(3803, 12) + ["Discharge at 0.004C for 90 minutes"]
             + patient_hoist_round_steps(38030, 8) + ["Rest for 30 minutes"])
    write_case(root, "am3_radius_negative_x2_care_home_patient_hoist_28C_5s_1p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": particle_words + ["radius", "particle size"],
                "ambient_temperature_K": 301.15,
                "note": "negative particle radius x2 (11.7 um instead of the set's 5.86 um: a coarser natural graphite, D50 about 23 "
                        "um, from another lot; the diffusion time R^2/D x4 and the surface per volume x0.5, so the negative's reaction "
                        "overpotential larger too, the active-material volume fraction and the capacity the set's); not a candidate "
                        "parameter, its physics is the particle diffusion family (or its own name, radius / particle size). At 28 degC "
                        "(a warm care home; isothermal, not recorded). A mobile patient hoist per cell from 90 % SOC: 10 min rest, the "
                        "morning get-up round in quick succession (patient_hoist_round_steps seed 3803, 12 transfers: the resident "
                        "lifted from the bed in the sling at 1.8-2.4C for 12-25 s, the leg spread adjusted at 0.6-0.8C for 3-5 s, the "
                        "hoist wheeled by the carer to the chair with the control box at 0.004C for 30-90 s, the resident lowered with "
                        "the motor running at 0.3-0.5C for 10-20 s, the hoist taken to the next room at 0.004C for 2-5 min), 90 min "
                        "parked at 0.004C, the evening bedtime round (seed 38030, 8 transfers), 30 min rest; 3.9 h, down to about 64 %; "
                        "nearly all the misfit in the two rounds' lift trains (about 9-15 mV RMS there, under 0.5 mV while parked); "
                        "sampled every 5 s (the hoist's service log), 1.5 mV noise; DFN data and model. effect_rmse_mV is what the "
                        "coarser graphite alone does"},
               initial_soc=0.9, seed=3803, period=5, noise=1.5e-3, compare=lion.DFN())
    # am4: positive electrode thickness x1.08 (a heavier cathode coating), a greenhouse's pipe-rail harvesting trolley's day,
    # 36 degC, 30 s, 2 mV, SPMe
    p = at(scaled(chen(), "Positive electrode thickness [m]", 1.08), 36)
    steps = ["Rest for 10 minutes"] + harvest_trolley_day_steps(3804, 12) + ["Rest for 30 minutes"]
    write_case(root, "am4_thickness_positive_x1p08_greenhouse_harvest_trolley_36C_30s_2mV_spme", lion.SPMe(), p, steps,
               {"effect": "electrode_thickness", "candidate_model": "spme",
                "accept": ["active material", "thickness", "loading"], "ambient_temperature_K": 309.15,
                "note": "positive electrode thickness x1.08 (81.6 um instead of the set's 75.6 um: a heavier cathode coating from "
                        "another coating line, 8 % more positive capacity and lithium per area, the porosity, the particles and the "
                        "negative the set's); the nearest candidate parameter is the positive active-material fraction (capacity per "
                        "area), judged by the active-material words or its own name (thickness, loading). At 36 degC (the trolley's "
                        "battery under the platform in a tomato greenhouse on a summer day; isothermal, not recorded). A battery "
                        "pipe-rail harvesting trolley per cell from 98 % SOC (off the overnight charger): 10 min rest, 12 rows "
                        "(harvest_trolley_day_steps seed 3804: driven in along the heating pipes at 0.4-0.6C for 60-120 s, 5 picking "
                        "stops per row, each the scissor platform raised at 1.2-1.5C for 8-15 s, the picking with the work lights and "
                        "the crate conveyor on at 0.03-0.05C for 3-6 min and the move along the row at 0.3C for 10-20 s, driven out "
                        "with the full crates at 0.5-0.7C for 60-120 s, the crates unloaded on the path at no current for 1-3 min), 30 "
                        "min rest; 6.6 h, down to about 13 % of the set's capacity (the heavier cell less deep); the misfit grows "
                        "through the day, the data above the candidate (3-4 mV in the first hour, about 30 mV in the afternoon and the "
                        "closing rest); sampled every 30 s (the trolley's logger), 2 mV noise; SPMe data and model. effect_rmse_mV is "
                        "what the heavier coating alone does"},
               initial_soc=0.98, seed=3804, period=30, noise=2e-3, compare=lion.SPMe())
    # am5: the negative electrode's tortuosity higher than the set's (Bruggeman exponent 1.8 for 1.5), a battery-electric mini
    # excavator digging a trench with a charge at lunch, 10 degC, 2 s, 1 mV, DFN
    p = at(chen(), 10)
    p.update({"Negative electrode Bruggeman coefficient (electrolyte)": 1.8})
    steps = (["Rest for 5 minutes", pybamm.step.current(mini_excavator_current(3805, 12)), "Rest for 10 minutes",
              pybamm.step.current(mini_excavator_current(38050, 12)), "Rest for 5 minutes", "Charge at 0.8C for 20 minutes",
              "Rest for 5 minutes", pybamm.step.current(mini_excavator_current(38051, 10)), "Rest for 20 minutes"])
    write_case(root, "am5_tortuosity_negative_bruggeman1p8_mini_excavator_trench_10C_2s_1mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn",
                "accept": ["electrolyte", "tortuosity", "Bruggeman", "MacMullin"], "ambient_temperature_K": 283.15,
                "note": "the negative electrode's tortuosity higher than the set's: the Bruggeman exponent for the electrolyte in the "
                        "negative 1.8 instead of 1.5 (tortuosity 0.25^-0.8 = 3.0 instead of 2.0, the effective conductivity and "
                        "diffusivity there x0.66: a graphite calendered harder, its flakes lying flat; the separator and the positive "
                        "the set's), judged by the electrolyte words or its own name (tortuosity, Bruggeman, MacMullin). At 10 degC (a "
                        "cool spring day on a building site; isothermal, not recorded). A battery-electric mini excavator per cell from "
                        "85 % SOC: 5 min rest, 12 min digging a trench as a current at 2 s knots (mini_excavator_current seed 3805: dig "
                        "cycles of 12-18 s, the bucket filled at 1.6-2.2C for 4-6 s, the loaded swing at 1.0-1.3C for 3-5 s, the dump "
                        "at 0.5-0.7C for 2-3 s, the swing back at 0.7-0.9C for 3-4 s, every 8-12 cycles the machine tracked forward at "
                        "0.8-1.0C for 10-20 s; the 1 s profile averaged over each 2 s, linear between knots; about 1.2C on average), 10 "
                        "min rest (a tea break), 12 min more (seed 38050), 5 min rest, a lunchtime charge from the site supply at 0.8C "
                        "for 20 min (time-limited), 5 min rest, 10 min more (seed 38051), 20 min rest; 1.65 h, down to about 37 %, up "
                        "to about 64 %, down to about 44 %; the misfit in the digging and the charge (about 15-25 mV RMS in the digging "
                        "stretches), the data below the candidate on discharge and above it on the charge; sampled every 2 s, 1 mV "
                        "noise; DFN data and model. effect_rmse_mV is what the tortuosity alone does"},
               initial_soc=0.85, seed=3805, period=2, noise=1e-3, compare=lion.DFN())
    # am6: 6 % lithium loss, a rural clinic's solar vaccine refrigerator through a night and the morning sun, 45 degC, 60 s,
    # 3 mV, SPM
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94), 45)
    steps = vaccine_fridge_night_steps(3806, 12) + solar_morning_charge_steps(38060, 6)
    write_case(root, "am6_inventory_6pct_solar_vaccine_fridge_night_45C_60s_3mV_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": lithium_words, "ambient_temperature_K": 318.15,
                "note": "6 % less lithium (initial negative concentration x0.94; the initial state set as 95 % SOC of the aged cell), "
                        "at 45 degC (the battery box of a solar vaccine refrigerator at a rural clinic in a hot climate's dry season; "
                        "isothermal, not recorded). From dusk (vaccine_fridge_night_steps seed 3806, 12 h): the compressor cycling on "
                        "its thermostat, on at 0.08-0.11C for 10-20 min, then off with the controller and the temperature logger at "
                        "0.005C for 15-35 min, for the first 3 h the clinic's lights and a phone charger at 0.05C more; then the "
                        "morning sun (solar_morning_charge_steps seed 38060, 6 h: the panel's charge rising in 30 min blocks to about "
                        "0.3C, less under passing cloud, the compressor still cycling, 0.13C less charge for 15 min of each block); "
                        "18.4 h, down to about 24 % at dawn (of the set's capacity), back to about 81 %; most of the misfit in one "
                        "stretch, the small hours and the dawn (about 25-29 mV RMS there, the data below the candidate), a smaller "
                        "one in the evening's second and third hours (about 15 mV), under 12 mV elsewhere; sampled every 60 s "
                        "(the solar charge controller's log), 3 mV noise; SPM data and model. "
                        "effect_rmse_mV is what the loss alone does"},
               initial_soc=0.95, seed=3806, period=60, noise=3e-3, compare=lion.SPM())
    # am7: pair, positive electrode conductivity x0.4 and lumped self-heating (h = 10, temperature recorded), a cordless
    # sheep-shearing handpiece in a cold shed, 2 degC, 10 s, 0.8 mV, DFN
    def shearing_cell(conductivity, h=None):
        q = at(scaled(chen(), "Positive electrode conductivity [S.m-1]", conductivity), 2)
        if h is not None:
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": h})
        return q
    steps = ["Rest for 5 minutes"] + shearing_run_steps(3807, 10) + ["Rest for 40 minutes"]
    name = "am7_positive_conductivity_x0p4_and_thermal_h10_recorded_sheep_shearing_2C_10s_0p8mV_dfn"
    write_case(root, name, lion.DFN(options={"thermal": "lumped"}), shearing_cell(0.4, 10.0), steps,
               {"effect": "electrode_conductivity+thermal", "candidate_model": "dfn",
                "accept": ["contact|series resistance|ohmic|electronic conductivity|electrode conductivity|solid-phase conductivity"
                           "|solid conductivity", "thermal|heat|self-heating"],
                "ambient_temperature_K": 275.15,
                "note": "two effects: the positive electrode's electronic conductivity x0.4 (0.072 S/m instead of 0.18: a cathode with "
                        "too little conductive carbon in its mix) and lumped self-heating, h = 10 W/(m2 K) (the handpiece's battery in "
                        "a belt pouch under the shearer's clothing), ambient and initial 2 degC (a shearing shed on a frosty "
                        "early-spring morning). A cordless sheep-shearing handpiece per cell from 95 % SOC: 5 min rest, a run of 10 "
                        "sheep (shearing_run_steps seed 3807: per sheep 4-7 blows, each the comb through the fleece at 1.2-1.6C for "
                        "12-30 s and the handpiece running free at 0.3C for 2-5 s between blows, then the shorn sheep let out and the "
                        "next dragged from the pen at no current for 25-60 s), 40 min rest (the battery swapped, cooling on the bench); "
                        "1.3 h, down to about 44 %; the cell warms by about 18 K (to about 20 degC) through the run and cools back in "
                        "the rest; all the misfit in the run (none in the rest); temperature recorded (0.05 K noise, 0.1 K resolution); "
                        "sampled every 10 s, 0.8 mV noise; DFN (lumped thermal) data handed to the isothermal DFN. The electrode "
                        "conductivity is judged by the series / ohmic resistance family or by its own name, as ai3 and al8. "
                        "dfn_conductivity_only_rmse_mV: the isothermal DFN with the conductivity x0.4 against the recording (what the "
                        "heating leaves); dfn_thermal_only_rmse_mV: the lumped-thermal DFN with the set's conductivity (what the "
                        "conductivity leaves)"},
               initial_soc=0.95, temperature=True, seed=3807, period=10, noise=8e-4,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), shearing_cell(0.4), steps, 0.95, "dfn_conductivity_only_rmse_mV", period=10)
    replay_rmse(root, name, lion.DFN(options={"thermal": "lumped"}), shearing_cell(1.0, 10.0), steps, 0.95, "dfn_thermal_only_rmse_mV", period=10)
    # am8: pair, electrolyte salt concentration x0.7 and 6 % lithium loss, a supermarket's floor scrubber-dryer through the
    # night and its charger, 20 degC, 15 s, 1.2 mV, SPMe
    def scrubber_cell(salt, lost):
        q = scaled(chen(), "Initial concentration in electrolyte [mol.m-3]", salt)
        return at(scaled(q, "Initial concentration in negative electrode [mol.m-3]", 1.0 - lost), 20)
    steps = (["Rest for 10 minutes"] + floor_scrubber_night_steps(3808, 40)
             + ["Rest for 20 minutes", "Charge at 0.3C for 100 minutes", "Rest for 30 minutes"])
    name = "am8_electrolyte_salt_x0p7_and_inventory_6pct_floor_scrubber_20C_15s_1p2mV_spme"
    write_case(root, name, lion.SPMe(), scrubber_cell(0.7, 0.06), steps,
               {"effect": "electrolyte_concentration+lithium_inventory_loss", "candidate_model": "spme",
                "accept": ["electrolyte|salt", "inventory|lithium loss|lithium lost|cyclable"], "ambient_temperature_K": 293.15,
                "note": "two effects as an aged cell's SEI growth gives them: the electrolyte's salt concentration x0.7 (700 mol/m3 "
                        "instead of 1000: LiPF6 consumed by the SEI and by decomposition) and 6 % less lithium (initial negative "
                        "concentration x0.94; the initial state set as 98 % SOC of the aged cell), at 20 degC (a supermarket at night; "
                        "isothermal, not recorded). A ride-on floor scrubber-dryer per cell from 98 % SOC: 10 min rest, 40 aisles "
                        "(floor_scrubber_night_steps seed 3808: the brush deck, the vacuum and the solution pump working down the aisle "
                        "at 0.35-0.5C for 60-180 s, the squeegee lifted for the turn at the end at 0.2C for 8-15 s; every 6-8 aisles "
                        "the recovery tank emptied and the solution tank refilled, the machine off for 4-8 min), 20 min rest, the "
                        "charger at 0.3C for 100 min (time-limited), 30 min rest; 4.7 h, down to about 37 %, back to about 87 % "
                        "(counted in the set's 5 A h); sampled every 15 s, 1.2 mV noise (the machine's battery monitor); SPMe data and "
                        "model. spme_salt_only_rmse_mV: the SPMe with the salt x0.7 and the set's lithium against the recording (what "
                        "the lithium loss leaves); spme_inventory_only_rmse_mV: the SPMe with the lithium loss and the set's salt (what "
                        "the salt leaves)"},
               initial_soc=0.98, seed=3808, period=15, noise=1.2e-3, compare=lion.SPMe())
    replay_rmse(root, name, lion.SPMe(), scrubber_cell(0.7, 0.0), steps, 0.98, "spme_salt_only_rmse_mV", period=15)
    replay_rmse(root, name, lion.SPMe(), scrubber_cell(1.0, 0.06), steps, 0.98, "spme_inventory_only_rmse_mV", period=15)


def baggage_tug_shift_steps(seed, flights):
    """An airport's electric baggage tractor (tug) per cell (discharge positive), for each of
    `flights` flights: driven out to the aircraft's stand towing the empty carts (0.6-0.9C for
    60-150 s), parked at the stand with the beacon and the lights on while the hold is unloaded
    (0.01C for 3-8 min), the pull-away with the loaded cart train (1.8-2.3C for 6-12 s), the tow
    along the apron road (0.9-1.2C for 90-200 s), regenerative braking at the baggage hall (0.4-0.6C
    charge for 4-8 s) and parked while the carts are emptied (no current, 2-6 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(flights):
        steps += [f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(60, 151))} seconds",
                  f"Discharge at 0.01C for {60 * int(rng.integers(3, 9))} seconds",
                  f"Discharge at {rng.uniform(1.8, 2.3):.2f}C for {int(rng.integers(6, 13))} seconds",
                  f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {int(rng.integers(90, 201))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(4, 9))} seconds",
                  f"Rest for {60 * int(rng.integers(2, 7))} seconds"]
    return steps


def cargo_bike_round_steps(seed, drops):
    """An electric cargo bike's parcel round per cell (discharge positive; a small pack and a heavy
    box), for each of `drops` drops: the ride to the next address with the motor assisting (0.25-0.45C
    for 2-5 min), in 40 % of legs a climb or a bridge with the loaded box (0.9-1.3C for 20-60 s), and
    the parcel carried to the door (no current, 1-4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(drops):
        steps.append(f"Discharge at {rng.uniform(0.25, 0.45):.2f}C for {60 * int(rng.integers(2, 6))} seconds")
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(0.9, 1.3):.2f}C for {int(rng.integers(20, 61))} seconds")
        steps.append(f"Rest for {int(rng.integers(60, 241))} seconds")
    return steps


def chainsaw_felling_steps(seed, trees):
    """An arborist's cordless chainsaw per cell (discharge positive), for each of `trees` trees: the
    felling cuts (2-3 cuts, the chain through the trunk at 2.0-2.6C for 8-20 s, the trigger released
    between them for 10-30 s), the limbing (6-10 bursts at 1.2-1.6C for 2-4 s, 2-5 s apart), the
    logs cross-cut (3-5 cuts at 1.8-2.3C for 5-12 s, 8-20 s apart) and the walk to the next tree with
    the saw off (no current, 1-3 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(trees):
        for _ in range(int(rng.integers(2, 4))):
            steps += [f"Discharge at {rng.uniform(2.0, 2.6):.2f}C for {int(rng.integers(8, 21))} seconds",
                      f"Rest for {int(rng.integers(10, 31))} seconds"]
        for _ in range(int(rng.integers(6, 11))):
            steps += [f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(2, 5))} seconds",
                      f"Rest for {int(rng.integers(2, 6))} seconds"]
        for _ in range(int(rng.integers(3, 6))):
            steps += [f"Discharge at {rng.uniform(1.8, 2.3):.2f}C for {int(rng.integers(5, 13))} seconds",
                      f"Rest for {int(rng.integers(8, 21))} seconds"]
        steps.append(f"Rest for {int(rng.integers(60, 181))} seconds")
    return steps


def yacht_anchorage_steps(seed, hours):
    """A cruising yacht's house battery per cell (discharge positive) at a tropical anchorage: the
    anchor windlass dropping and setting the anchor (1.6-2.0C for 40-70 s), then `hours` h in 15 min
    slots (the instruments, the anchor light and the fans at 0.015-0.025C, the fridge's compressor on
    for 5-10 min of each slot at 0.08-0.1C more), the watermaker run for an hour through the inverter
    (0.35-0.45C) for 30 min in the second hour, and the windlass hauling the anchor at the end (2.0-2.4C for
    60-90 s)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(1.6, 2.0):.2f}C for {int(rng.integers(40, 71))} seconds"]
    for slot in range(int(4 * hours)):
        base, on = rng.uniform(0.015, 0.025), 60 * int(rng.integers(5, 11))
        extra = rng.uniform(0.35, 0.45) if 4 <= slot < 6 else 0.0
        steps += [f"Discharge at {base + extra + rng.uniform(0.08, 0.1):.3f}C for {on} seconds",
                  f"Discharge at {base + extra:.3f}C for {900 - on} seconds"]
    return steps + [f"Discharge at {rng.uniform(2.0, 2.4):.2f}C for {int(rng.integers(60, 91))} seconds"]


def hedge_trimmer_steps(seed, sections):
    """A gardening crew's cordless hedge trimmer per cell (discharge positive), for each of `sections`
    stretches of hedge: the blades through the face of the hedge (0.6-0.9C for 30-120 s), in half the
    stretches a thick woody branch (1.3-1.7C for 3-8 s) and the top cut from the platform (0.7-1.0C for
    20-60 s), and the platform moved and the clippings raked (no current, 30-120 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(sections):
        steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(30, 121))} seconds")
        if rng.uniform() < 0.5:
            steps += [f"Discharge at {rng.uniform(1.3, 1.7):.2f}C for {int(rng.integers(3, 9))} seconds",
                      f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {int(rng.integers(20, 61))} seconds"]
        steps.append(f"Rest for {int(rng.integers(30, 121))} seconds")
    return steps


def power_barrow_loads_steps(seed, loads):
    """A tracked electric power barrow (a motorised wheelbarrow) on a building site per cell (discharge
    positive), for each of `loads` loads of concrete or spoil: driven up the ramp loaded (1.3-1.8C for
    20-60 s), the skip tipped (0.3C for 4-8 s), driven back empty (0.4-0.6C for 20-60 s), and parked
    while the next load is shovelled in (no current, 1-3 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(loads):
        steps += [f"Discharge at {rng.uniform(1.3, 1.8):.2f}C for {int(rng.integers(20, 61))} seconds",
                  f"Discharge at 0.3C for {int(rng.integers(4, 9))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(20, 61))} seconds",
                  f"Rest for {int(rng.integers(60, 181))} seconds"]
    return steps


def efoil_session_steps(seed, runs):
    """An electric hydrofoil surfboard's (e-foil's) session per cell (discharge positive; a compact
    pack in the board's sealed box), for each of `runs` runs: the taxi off the beach or after a fall
    (0.3-0.5C for 30-90 s), the take-off onto the foil (2.8-3.3C for 4-8 s), the flight (1.5-2.1C for
    40-150 s) and the fall or the stop in the water (no current, 20-60 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(runs):
        steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(30, 91))} seconds",
                  f"Discharge at {rng.uniform(2.8, 3.3):.2f}C for {int(rng.integers(4, 9))} seconds",
                  f"Discharge at {rng.uniform(1.5, 2.1):.2f}C for {int(rng.integers(40, 151))} seconds",
                  f"Rest for {int(rng.integers(20, 61))} seconds"]
    return steps


def mobility_scooter_day_steps(seed, stops):
    """A mobility scooter's outing per cell (discharge positive), for each of `stops` stops: the ride
    along the pavement (0.3-0.5C for 2-5 min), 1-3 dropped kerbs or ramps on the way (1.1-1.5C for 3-8
    s, each followed by 0.3C for 20-40 s), and the stop (a shop, the post office, a friend's; the
    scooter off, no current, 8-20 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(stops):
        steps.append(f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {60 * int(rng.integers(2, 6))} seconds")
        for _ in range(int(rng.integers(1, 4))):
            steps += [f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(3, 9))} seconds",
                      f"Discharge at 0.3C for {int(rng.integers(20, 41))} seconds"]
        steps.append(f"Rest for {60 * int(rng.integers(8, 21))} seconds")
    return steps


def with_leak(steps, leak_A, capacity_A_h=5.0):
    """The steps the electrodes carry when the cell draws `leak_A` (discharge positive) inside itself on
    top of the set `steps` ("Discharge|Charge at <x>C for <n> seconds" or "Rest for <n> seconds"), in A."""
    inside = []
    for s in steps:
        words = s.split()
        unit = {"seconds": 1, "minutes": 60, "hours": 3600}
        if words[0] == "Rest":
            current, seconds = 0.0, int(words[2]) * unit[words[3]]
        else:
            current = float(words[2].rstrip("C")) * capacity_A_h * (1 if words[0] == "Discharge" else -1)
            seconds = int(words[4]) * unit[words[5]]
        current += leak_A
        inside.append(f"{'Discharge' if current >= 0 else 'Charge'} at {abs(current):.4f} A for {seconds} seconds")
    return inside


def batch_an(root):
    """Thirty-ninth batch (key "an"), made blind (a helper session that did not read the diagnosis
    code). The Chen 2020 cell throughout, ambients -5, 4, 10, 16, 18, 27, 34 and 40 degC, each of the
    three models, sampling from 1 to 20 s and a cycler's irregular log, noise from 0.8 to 2 mV, and
    duties no earlier batch used: an airport's electric baggage tug, an electric cargo bike's parcel
    round with a lunchtime charge, an arborist's cordless chainsaw in the frost, a cruising yacht's
    house battery at a tropical anchorage, a gardening crew's cordless hedge trimmer and the van's
    charger, a tracked electric power barrow on a hot building site, an electric hydrofoil surfboard's
    (e-foil's) session, and a mobility scooter's outing. A DFN control; single effects (9 % negative
    active-material loss; negative particle diffusivity x0.3 in the frost; 5 % lithium loss; a 3 mOhm
    contact resistance in the cold; an aged electrolyte, conductivity x0.4 and diffusivity x0.5, at 40
    degC) and two pairs no earlier batch concealed together (a voltage channel reading 5 mV low with
    lumped self-heating, h = 15, temperature recorded; a 60 mA internal leak the logger does not see
    with negative exchange current x0.35). Words as in batches ah-am; the offset by the voltage-channel
    words (offset, calibration, ...), the leak by the self-discharge words (self-discharge, leak, soft
    short, ..., current offset). Each effect's size on its own (the nominal candidate, or a replay,
    against the noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the replay
    keys); every step is time-limited (no voltage cut-off reached), so the experiment-aligned
    comparison needs no replay on the recorded current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    offset_words = ["offset", "calibration", "voltage measurement", "voltage sensor", "voltage channel"]
    leak_words = ["self-discharge", "self discharge", "leak", "soft short", "internal short", "short circuit", "current offset"]
    # an1: control, an airport's electric baggage tug, 16 degC, 5 s, 1 mV, DFN
    p = at(chen(), 16)
    steps = ["Rest for 5 minutes"] + baggage_tug_shift_steps(3901, 6) + ["Rest for 20 minutes"]
    write_case(root, "an1_control_airport_baggage_tug_16C_5s_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 289.15,
                "note": "negative control at 16 degC (an airport apron on a mild spring day; isothermal, not recorded): DFN data and "
                        "model, nothing concealed. An electric baggage tractor (tug) per cell from 80 % SOC: 5 min rest, 6 flights "
                        "(baggage_tug_shift_steps seed 3901: driven out to the aircraft's stand towing the empty carts at 0.6-0.9C for "
                        "60-150 s, parked at the stand with the beacon and the lights on at 0.01C for 3-8 min, the pull-away with the "
                        "loaded cart train at 1.8-2.3C for 6-12 s, the tow along the apron road at 0.9-1.2C for 90-200 s, "
                        "regenerative braking at the baggage hall at 0.4-0.6C charge for 4-8 s, parked while the carts are emptied "
                        "at no current for 2-6 min), 20 min rest; 1.8 h, down to about 37 %; sampled every 5 s (the tug's telematics), 1 mV noise"},
               initial_soc=0.8, seed=3901, period=5, compare=lion.DFN())
    # an2: 9 % negative active-material loss, an electric cargo bike's parcel round with a lunchtime charge, 27 degC, a cycler's
    # irregular log, 1.5 mV, SPMe
    p = at(scaled(chen(), "Negative electrode active material volume fraction", 0.91), 27)
    steps = (["Rest for 10 minutes"] + cargo_bike_round_steps(3902, 14) + ["Rest for 5 minutes", "Charge at 0.6C for 25 minutes",
             "Rest for 5 minutes"] + cargo_bike_round_steps(39020, 10) + ["Rest for 30 minutes"])
    write_case(root, "an2_lam_negative_9pct_cargo_bike_parcel_round_27C_cycler_1p5mV_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 300.15,
                "note": "9 % loss of negative active material (volume fraction 0.75 -> 0.6825, the set's initial concentrations, so "
                        "the lithium of the lost material goes with it; the initial state set as 95 % SOC of the aged cell), at 27 "
                        "degC (a city's summer streets; isothermal, not recorded). An electric cargo bike's parcel round replayed on a "
                        "cycler, per cell from 95 % SOC: 10 min rest, 14 drops (cargo_bike_round_steps seed 3902: the ride to the next "
                        "address with the motor assisting at 0.25-0.45C for 2-5 min, in 40 % of legs a climb or a bridge with the "
                        "loaded box at 0.9-1.3C for 20-60 s, the parcel carried to the door at no current for 1-4 min), 5 min rest, "
                        "a lunchtime charge at the depot at 0.6C for 25 min (time-limited), 5 min rest, 10 more drops (seed 39020), "
                        "30 min rest; 3.7 h, down to about 60 %, up to about 85 %, down to about 62 % (counted in the set's 5 A h); the cycler's irregular log (1 s in the first 60 s of a step and in short steps, then 30 s "
                        "under load / 60 s at rest, plus every 5 mV or 50 mA), 3 mA current noise, 0.1 mV / 0.1 mA resolution, 1.5 "
                        "mV voltage noise; SPMe data and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=0.95, seed=3902, noise=1.5e-3, cycler=CYCLER, compare=lion.SPMe())
    # an3: negative particle diffusivity x0.3, an arborist's cordless chainsaw in the frost, -5 degC, 2 s, 0.8 mV, DFN
    p = at(scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.3), -5)
    steps = ["Rest for 5 minutes"] + chainsaw_felling_steps(3903, 8) + ["Rest for 30 minutes"]
    write_case(root, "an3_diffusivity_negative_x0p3_arborist_chainsaw_frost_minus5C_2s_0p8mV_dfn", lion.DFN(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": particle_words, "ambient_temperature_K": 268.15,
                "note": "negative particle diffusivity x0.3 (a graphite whose particles' diffusion paths are longer or blocked: "
                        "another lot, or ageing), at -5 degC (a winter woodland on a frosty morning; isothermal, not recorded). An "
                        "arborist's cordless chainsaw per cell from 90 % SOC: 5 min rest, 8 trees (chainsaw_felling_steps seed 3903: "
                        "2-3 felling cuts, the chain through the trunk at 2.0-2.6C for 8-20 s with the trigger released for 10-30 s "
                        "between them, the limbing in 6-10 bursts at 1.2-1.6C for 2-4 s, 2-5 s apart, 3-5 cross-cuts of the logs at "
                        "1.8-2.3C for 5-12 s, 8-20 s apart, the walk to the next tree with the saw off for 1-3 min), 30 min rest; "
                        "1.3 h, down to about 47 %; sampled every 2 s, 0.8 mV noise; DFN data and model. effect_rmse_mV is what the diffusivity alone "
                        "does"},
               initial_soc=0.9, seed=3903, period=2, noise=8e-4, compare=lion.DFN())
    # an4: 5 % lithium loss, a cruising yacht's house battery at a tropical anchorage, 34 degC, 20 s, 2 mV, SPM
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.95), 34)
    steps = yacht_anchorage_steps(3904, 3.75) + ["Rest for 10 minutes"]
    write_case(root, "an4_inventory_5pct_yacht_house_battery_anchorage_34C_20s_2mV_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": lithium_words, "ambient_temperature_K": 307.15,
                "note": "5 % less lithium (initial negative concentration x0.95; the initial state set as 85 % SOC of the aged cell), "
                        "at 34 degC (a yacht's battery locker at a tropical anchorage; isothermal, not recorded). A cruising yacht's "
                        "house battery per cell from 85 % SOC (yacht_anchorage_steps seed 3904, 3.75 h): the anchor windlass dropping "
                        "and setting the anchor at 1.6-2.0C for 40-70 s, then 15 min slots (the instruments, the anchor light and the "
                        "fans at 0.015-0.025C, the fridge's compressor on for 5-10 min of each slot at 0.08-0.1C more), the "
                        "watermaker run through the inverter at 0.35-0.45C for 30 min in the second hour, the windlass hauling the "
                        "anchor at 2.0-2.4C for 60-90 s at the end; 10 min rest; 4.0 h, down to about 33 % (counted in the set's 5 A h); sampled every 20 s (the boat's battery "
                        "monitor), 2 mV noise; SPM data and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=0.85, seed=3904, period=20, noise=2e-3, compare=lion.SPM())
    # an5: a 3 mOhm contact resistance, a gardening crew's cordless hedge trimmer and the van's charger, 4 degC, 10 s, 1 mV, SPMe
    p = at(chen(), 4)
    p.update({"Contact resistance [Ohm]": 0.003}, check_already_exists=False)
    steps = (["Rest for 10 minutes"] + hedge_trimmer_steps(3905, 18) + ["Rest for 5 minutes", "Charge at 0.5C for 30 minutes",
             "Rest for 5 minutes"] + hedge_trimmer_steps(39050, 12) + ["Rest for 20 minutes"])
    write_case(root, "an5_contact_3mOhm_hedge_trimmer_van_charge_4C_10s_spme", lion.SPMe(options={"contact resistance": "true"}), p, steps,
               {"effect": "contact_resistance", "candidate_model": "spme", "accept": ["contact", "series resistance", "ohmic"],
                "ambient_temperature_K": 277.15,
                "note": "a 3 mOhm contact resistance (a battery pack's worn spring contacts in the tool's slide-on mount: about 10 "
                        "mV while trimming, -7.5 mV on the charge), at 4 degC (a late-autumn morning; isothermal, not recorded). A "
                        "gardening crew's cordless hedge trimmer per cell from 95 % SOC: 10 min rest, 18 stretches of hedge "
                        "(hedge_trimmer_steps seed 3905: the blades through the face of the hedge at 0.6-0.9C for 30-120 s, in half "
                        "the stretches a thick woody branch at 1.3-1.7C for 3-8 s and the top cut from the platform at 0.7-1.0C for "
                        "20-60 s, the platform moved and the clippings raked at no current for 30-120 s), 5 min rest, the van's "
                        "charger at 0.5C for 30 min (time-limited), 5 min rest, 12 more stretches (seed 39050), 20 min rest; "
                        "2.7 h, down to about 57 %, up to about 82 %, down to about 56 %; sampled every 10 s, 1 mV noise; SPMe (with contact resistance) data handed to the plain SPMe. "
                        "effect_rmse_mV is what the resistance alone does"},
               initial_soc=0.95, seed=3905, period=10, compare=lion.SPMe())
    # an6: an aged electrolyte (conductivity x0.4, diffusivity x0.5), a tracked power barrow on a hot building site, 40 degC, 3 s,
    # 1.2 mV, DFN
    p = at(scaled(scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.4), "Electrolyte diffusivity [m2.s-1]", 0.5), 40)
    steps = ["Rest for 5 minutes"] + power_barrow_loads_steps(3906, 25) + ["Rest for 20 minutes"]
    write_case(root, "an6_electrolyte_conductivity_x0p4_diffusivity_x0p5_power_barrow_40C_3s_1p2mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 313.15,
                "note": "an aged electrolyte: conductivity x0.4 and diffusivity x0.5 at every concentration (solvent lost to "
                        "decomposition and gas in a cell kept hot, the remaining liquid more viscous), at 40 degC (a building site in "
                        "a hot summer, the barrow standing in the sun; isothermal, not recorded). A tracked electric power barrow per "
                        "cell from 95 % SOC: 5 min rest, 25 loads (power_barrow_loads_steps seed 3906: driven up the ramp loaded at "
                        "1.3-1.8C for 20-60 s, the skip tipped at 0.3C for 4-8 s, driven back empty at 0.4-0.6C for 20-60 s, parked "
                        "while the next load is shovelled in at no current for 1-3 min), 20 min rest; 1.8 h, down to about 37 %; sampled every 3 s, 1.2 "
                        "mV noise; DFN data and model. effect_rmse_mV is what the electrolyte alone does"},
               initial_soc=0.95, seed=3906, period=3, noise=1.2e-3, compare=lion.DFN())
    # an7: pair, the voltage channel reading 5 mV low and lumped self-heating (h = 15, temperature recorded), an e-foil session,
    # 18 degC, 1 s, 1 mV, SPMe
    def efoil_cell(h=None):
        q = at(chen(), 18)
        if h is not None:
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": h})
        return q
    steps = ["Rest for 3 minutes"] + efoil_session_steps(3907, 10) + ["Rest for 30 minutes"]
    name = "an7_voltage_offset_5mV_low_and_thermal_h15_recorded_efoil_session_18C_1s_spme"
    write_case(root, name, lion.SPMe(options={"thermal": "lumped"}), efoil_cell(15.0), steps,
               {"effect": "voltage_offset+thermal", "candidate_model": "spme",
                "accept": ["offset|calibration|voltage measurement|voltage sensor|voltage channel", "thermal|heat|self-heating"],
                "ambient_temperature_K": 291.15,
                "note": "two effects: the board's battery management reads the cell voltage 5 mV low everywhere (a calibration offset, "
                        "under current and at rest alike; not a cell property, an OCP offset is the nearest cell-side description and "
                        "is accepted through 'offset') and lumped self-heating, h = 15 W/(m2 K) (the pack in the board's sealed box, "
                        "the sea water under the hull taking some heat away), ambient and initial 18 degC (the sea in early summer). "
                        "An electric hydrofoil surfboard's (e-foil's) session per cell from 95 % SOC: 3 min rest on the beach, 10 "
                        "runs (efoil_session_steps seed 3907: the taxi off the beach or after a fall at 0.3-0.5C for 30-90 s, the "
                        "take-off onto the foil at 2.8-3.3C for 4-8 s, the flight at 1.5-2.1C for 40-150 s, the fall or the stop in "
                        "the water at no current for 20-60 s), 30 min rest on the beach; 1.1 h, down to about 28 %; temperature recorded (0.05 K noise, "
                        "0.1 K resolution); sampled every 1 s, 1 mV noise; SPMe (lumped thermal) data, read 5 mV low, handed to the "
                        "isothermal SPMe. spme_thermal_only_rmse_mV: the lumped-thermal SPMe with the set's parameters against the "
                        "recording (what the offset leaves); spme_offset_only_rmse_mV: the isothermal SPMe read 5 mV low (what the "
                        "heating leaves)"},
               initial_soc=0.95, temperature=True, seed=3907, period=1, compare=lion.SPMe(),
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, post=lambda t, i, v: v - 0.005)
    replay_rmse(root, name, lion.SPMe(options={"thermal": "lumped"}), efoil_cell(15.0), steps, 0.95, "spme_thermal_only_rmse_mV")
    replay_rmse(root, name, lion.SPMe(), efoil_cell(), steps, 0.95, "spme_offset_only_rmse_mV", shift_V=-0.005)
    # an8: pair, a 60 mA internal leak the logger does not see and negative exchange current x0.35, a mobility scooter's outing,
    # 10 degC, 5 s, 0.8 mV, DFN
    leak = 0.06
    def scooter_cell(j0):
        return at(scaled(chen(), "Negative electrode exchange-current density [A.m-2]", j0), 10)
    seen = ["Rest for 300 seconds"] + mobility_scooter_day_steps(3908, 5) + ["Rest for 600 seconds"]
    inside = with_leak(seen, leak)
    name = "an8_leak_60mA_and_kinetics_negative_x0p35_mobility_scooter_outing_10C_5s_0p8mV_dfn"
    write_case(root, name, lion.DFN(), scooter_cell(0.35), inside,
               {"effect": "self_discharge+kinetics", "candidate_model": "dfn",
                "accept": ["self-discharge|self discharge|leak|soft short|internal short|short circuit|current offset",
                           "kinetic|exchange|charge-transfer|charge transfer|reaction rate"],
                "ambient_temperature_K": 283.15,
                "note": "two effects: a 60 mA internal leak (a soft short of about 60 Ohm; C/83) that the scooter's logger does not "
                        "measure, the electrodes carrying the recorded current plus 60 mA of discharge throughout, and negative "
                        "exchange-current density x0.35 (all stoichiometries, the activation energy kept: a graphite whose surface is "
                        "covered by a thick, resistive SEI grown in storage), at 10 degC (a cool spring day; isothermal, not "
                        "recorded). A mobility scooter's outing per cell from 70 % SOC: 5 min rest, 5 stops "
                        "(mobility_scooter_day_steps seed 3908: the ride along the pavement at 0.3-0.5C for 2-5 min, 1-3 dropped kerbs "
                        "or ramps at 1.1-1.5C for 3-8 s, each followed by 0.3C for 20-40 s, the stop with the scooter off at no "
                        "current for 8-20 min), 10 min rest; 2.0 h, down to about 50 % as the logger counts it (about 48 % with the leak); sampled every 5 s, 0.8 mV noise; DFN data and model. "
                        "dfn_kinetics_only_rmse_mV: the DFN with the slow kinetics on the recorded protocol against the recording "
                        "(what the leak leaves); dfn_leak_only_rmse_mV: the DFN with the set's kinetics carrying the leak (what the "
                        "kinetics leave)"},
               initial_soc=0.7, seed=3908, period=5, noise=8e-4, compare=lion.DFN(), leak_A=leak, compare_steps=seen)
    replay_rmse(root, name, lion.DFN(), scooter_cell(0.35), seen, 0.7, "dfn_kinetics_only_rmse_mV", period=5)
    replay_rmse(root, name, lion.DFN(), scooter_cell(1.0), inside, 0.7, "dfn_leak_only_rmse_mV", period=5)



def hospital_bed_day_steps(seed, events):
    """An electric hospital bed's backup battery per cell (discharge positive; a bed left unplugged after
    a transport), for each of `events` events: the bed standing on its battery, the control box and the
    under-bed night light at 0.004-0.006C for 4-12 min, then in 70 % of events a repositioning (2-4
    actuator moves 5-20 s apart at 0.005C: the backrest raised at 0.6-0.9C for 8-20 s, the knee break at
    0.5-0.7C for 6-12 s, the height raised with the patient at 1.2-1.6C for 15-30 s, or lowered at
    0.25-0.35C for 15-30 s, the weight helping), otherwise a transport with the drive-assist wheel along
    the corridors (0.7-1.0C for 2-4 min) over a lift's threshold (1.3-1.6C for 5-10 s) and on (0.7-1.0C
    for 1-2 min)."""
    rng = np.random.default_rng(seed)
    moves = [(0.6, 0.9, 8, 20), (0.5, 0.7, 6, 12), (1.2, 1.6, 15, 30), (0.25, 0.35, 15, 30)]
    steps = []
    for _ in range(events):
        steps.append(f"Discharge at {rng.uniform(0.004, 0.006):.4f}C for {60 * int(rng.integers(4, 13))} seconds")
        if rng.uniform() < 0.7:
            for k in range(int(rng.integers(2, 5))):
                low, high, short, long = moves[int(rng.integers(0, len(moves)))]
                if k:
                    steps.append(f"Discharge at 0.005C for {int(rng.integers(5, 21))} seconds")
                steps.append(f"Discharge at {rng.uniform(low, high):.2f}C for {int(rng.integers(short, long + 1))} seconds")
        else:
            steps += [f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {60 * int(rng.integers(2, 5))} seconds",
                      f"Discharge at {rng.uniform(1.3, 1.6):.2f}C for {int(rng.integers(5, 11))} seconds",
                      f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {60 * int(rng.integers(1, 3))} seconds"]
    return steps


def electric_kayak_steps(seed, legs):
    """A sit-on-top fishing kayak's electric drive per cell (discharge positive), for each of `legs`
    legs: the push off the shore or away from a spot (1.4-1.8C for 10-20 s), the cruise to the next spot
    (0.4-0.7C for 3-8 min), in 40 % of legs a sprint against the wind or the tide (1.0-1.4C for 60-180 s),
    and drifting while fishing (no current, 2-8 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(legs):
        steps += [f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.7):.2f}C for {60 * int(rng.integers(3, 9))} seconds"]
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(60, 181))} seconds")
        steps.append(f"Rest for {60 * int(rng.integers(2, 9))} seconds")
    return steps


def robot_mower_steps(seed, minutes):
    """A boundary-wire robotic lawn mower's mowing run per cell (discharge positive), about `minutes`
    min: straight runs with the blade disc and the wheel motors (0.35-0.5C for 60-180 s), in 30 % of runs
    a patch of long, wet grass (0.8-1.0C for 10-30 s), the turn at the boundary wire (0.25C for 3-6 s);
    then the drive back to the dock along the wire (0.3C for 60-180 s)."""
    rng = np.random.default_rng(seed)
    steps = strip_mowing_steps(rng, minutes, (60, 181), (0.35, 0.5), (10, 31), (0.8, 1.0), 0.25)
    return steps + [f"Discharge at 0.3C for {int(rng.integers(60, 181))} seconds"]


def cable_car_recovery_steps(seed, cabins):
    """An aerial ropeway's (cable car's) battery-powered recovery drive per cell (discharge positive),
    bringing the line's cabins into the station after a grid failure, for each of `cabins` cabins: the
    service brake released and the haul rope started (1.6-1.9C for 5-8 s), the rope crawling at recovery
    speed (0.8-1.05C for 90-200 s) with 1-2 tower crossings (1.15-1.35C for 10-20 s each, the crawl
    between), and the rope stopped while the cabin is unloaded in the station (the control cabinet and
    the station's emergency lights at 0.02-0.03C for 40-90 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(cabins):
        steps += [f"Discharge at {rng.uniform(1.6, 1.9):.2f}C for {int(rng.integers(5, 9))} seconds",
                  f"Discharge at {rng.uniform(0.8, 1.05):.2f}C for {int(rng.integers(45, 101))} seconds"]
        for _ in range(int(rng.integers(1, 3))):
            steps += [f"Discharge at {rng.uniform(1.15, 1.35):.2f}C for {int(rng.integers(10, 21))} seconds",
                      f"Discharge at {rng.uniform(0.8, 1.05):.2f}C for {int(rng.integers(45, 101))} seconds"]
        steps.append(f"Discharge at {rng.uniform(0.02, 0.03):.3f}C for {int(rng.integers(40, 91))} seconds")
    return steps


def leaf_blower_steps(seed, minutes):
    """A landscaper's cordless backpack leaf blower per cell (discharge positive), about `minutes` min:
    full throttle along a lawn or a path (1.8-2.3C for 30-120 s), half throttle shaping the pile
    (0.9-1.2C for 20-60 s), and in 30 % of passes the trigger released while a tarp is moved (no
    current, 5-20 s)."""
    rng = np.random.default_rng(seed)
    steps, elapsed = [], 0
    while elapsed < 60 * minutes:
        full, half = int(rng.integers(30, 121)), int(rng.integers(20, 61))
        steps += [f"Discharge at {rng.uniform(1.8, 2.3):.2f}C for {full} seconds",
                  f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {half} seconds"]
        elapsed += full + half
        if rng.uniform() < 0.3:
            pause = int(rng.integers(5, 21))
            steps.append(f"Rest for {pause} seconds")
            elapsed += pause
    return steps


def vape_sessions_steps(seed, sessions):
    """A single-cell box-mod vaporiser (e-cigarette) at 20-30 W per cell (discharge positive), for each
    of `sessions` sessions: 8-14 puffs (the coil fired at 1.1-1.5C for 2-5 s, the device idle between
    puffs for 20-60 s), then the device in a pocket (no current, 8-20 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(sessions):
        for _ in range(int(rng.integers(8, 15))):
            steps += [f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(2, 6))} seconds",
                      f"Rest for {int(rng.integers(20, 61))} seconds"]
        steps.append(f"Rest for {60 * int(rng.integers(8, 21))} seconds")
    return steps


def tram_catenary_gap_steps(seed, gaps, stops=4):
    """A tram's traction battery per cell (discharge positive) on a line with catenary-free sections
    through a historic centre, for each of `gaps` passages: at each of `stops` stops the pull-away
    (2.2-2.7C for 15-25 s), the run (0.9-1.4C for 40-90 s), regenerative braking into the stop
    (1.2-1.7C charge for 8-15 s) and the dwell with the doors open, the heating and the lights (0.10-0.15C
    for 20-40 s); then back under the wire, the battery recharged from the catenary while the tram runs
    (0.9-1.2C charge for 4-7 min), and in 30 % of passages a layover at the terminus (no current, 3-6
    min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(gaps):
        for _ in range(stops):
            steps += [f"Discharge at {rng.uniform(2.2, 2.7):.2f}C for {int(rng.integers(15, 26))} seconds",
                      f"Discharge at {rng.uniform(0.9, 1.4):.2f}C for {int(rng.integers(40, 91))} seconds",
                      f"Charge at {rng.uniform(1.2, 1.7):.2f}C for {int(rng.integers(8, 16))} seconds",
                      f"Discharge at {rng.uniform(0.10, 0.15):.2f}C for {int(rng.integers(20, 41))} seconds"]
        steps.append(f"Charge at {rng.uniform(0.9, 1.2):.2f}C for {60 * int(rng.integers(4, 8))} seconds")
        if rng.uniform() < 0.3:
            steps.append(f"Rest for {60 * int(rng.integers(3, 7))} seconds")
    return steps


def home_evening_peak_steps(seed, hours):
    """A home storage battery's evening peak per cell (discharge positive; the battery's inverter capped
    at 0.5C), `hours` h from 5 pm in 15 min slots: the first slot the last of the solar panels' output
    still charging it (0.03-0.06C charge); then the house's base load (fridge, lights, the television;
    0.06-0.12C), the cooking in slots 2-5 (the induction hob and the oven, 0.25-0.35C more for 8-15 min
    of the slot), after dinner the dishwasher (its heater 0.2C more through slot 6, its pumps 0.02C more
    through slots 7 and 8), and after 30 % of slots a kettle (0.35C more for 3 min, the total capped at
    0.5C)."""
    rng = np.random.default_rng(seed)
    steps = [f"Charge at {rng.uniform(0.03, 0.06):.3f}C for 900 seconds"]
    for slot in range(1, int(4 * hours)):
        base = rng.uniform(0.06, 0.12)
        if 2 <= slot <= 5:
            on = 60 * int(rng.integers(8, 16))
            steps += [f"Discharge at {base + rng.uniform(0.25, 0.35):.3f}C for {on} seconds", f"Discharge at {base:.3f}C for {900 - on} seconds"]
        elif slot == 6:
            steps.append(f"Discharge at {base + 0.2:.3f}C for 900 seconds")
        elif slot in (7, 8):
            steps.append(f"Discharge at {base + 0.02:.3f}C for 900 seconds")
        else:
            steps.append(f"Discharge at {base:.3f}C for 900 seconds")
        if rng.uniform() < 0.3:
            steps.append(f"Discharge at {min(base + 0.35, 0.5):.3f}C for 180 seconds")
    return steps


def batch_ao(root):
    """Fortieth batch (key "ao"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -10, 8, 14, 20, 22, 24, 26 and 45 degC, each of the three
    models (data and candidate the same model in every case), sampling from 1 to 30 s, noise from 0.5 to
    2 mV, and duties no earlier batch used: an electric hospital bed left on its backup battery, a
    fishing kayak's electric drive, a boundary-wire robotic lawn mower and its dock, a cable car's
    battery recovery drive in a ski resort's frost, a landscaper's backpack leaf blower, a box-mod
    vaporiser's puffs, a tram's catenary-free sections through a historic centre, and a home storage
    battery's evening peak in a desert heatwave. An SPM control; five single effects (10 % positive
    active-material loss; a 120 mA internal leak the mower's logger does not see; positive exchange
    current x0.3 at -10 degC; lumped self-heating, h = 14, temperature recorded; 7 % lithium loss at 45
    degC) and two pairs no earlier batch concealed together (an 80 mA internal leak with an 8 mOhm
    contact resistance; positive particle diffusivity x0.3 with the voltage channel reading 6 mV high).
    Words as in batches ah-an; the offset by the voltage-channel words, the leak by the self-discharge
    words. Each effect's size on its own (the nominal candidate, or a replay, against the noise-free
    voltage or the recording) is in truth.json (effect_rmse_mV and the replay keys); every step is
    time-limited (no voltage cut-off reached), so the experiment-aligned comparison needs no replay on
    the recorded current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    offset_words = ["offset", "calibration", "voltage measurement", "voltage sensor", "voltage channel"]
    leak_words = ["self-discharge", "self discharge", "leak", "soft short", "internal short", "short circuit", "current offset"]
    contact_words = ["contact", "series resistance", "ohmic"]
    # ao1: control, an electric hospital bed left on its backup battery, 22 degC, 2 s, 0.5 mV, SPM
    p = at(chen(), 22)
    steps = ["Rest for 10 minutes"] + hospital_bed_day_steps(4001, 10) + ["Rest for 20 minutes"]
    write_case(root, "ao1_control_hospital_bed_backup_battery_22C_2s_0p5mV_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 295.15,
                "note": "negative control at 22 degC (a hospital ward; isothermal, not recorded): SPM data and model, nothing "
                        "concealed. An electric hospital bed's backup battery per cell from 80 % SOC (the bed left unplugged after "
                        "a transport): 10 min rest, 10 events (hospital_bed_day_steps seed 4001: the bed standing on its battery, "
                        "the control box and the under-bed night light at 0.004-0.006C for 4-12 min, then in 70 % of events a "
                        "repositioning, 2-4 actuator moves 5-20 s apart at 0.005C (the backrest raised at 0.6-0.9C for 8-20 s, the "
                        "knee break at 0.5-0.7C for 6-12 s, the height raised with the patient at 1.2-1.6C for 15-30 s or lowered "
                        "at 0.25-0.35C for 15-30 s), otherwise a transport with the drive-assist wheel along the corridors at "
                        "0.7-1.0C for 2-4 min, over a lift's threshold at 1.3-1.6C for 5-10 s and on at 0.7-1.0C for 1-2 min), "
                        "20 min rest; 2.3 h, down to about 44 % (counted in the set's 5 A h); sampled every 2 s, 0.5 mV noise"},
               initial_soc=0.8, seed=4001, period=2, noise=5e-4, compare=lion.SPM())
    # ao2: 10 % positive active-material loss, a fishing kayak's electric drive, 14 degC, 5 s, 1 mV, DFN
    p = at(scaled(chen(), "Positive electrode active material volume fraction", 0.9), 14)
    steps = ["Rest for 5 minutes"] + electric_kayak_steps(4002, 8) + ["Rest for 30 minutes"]
    write_case(root, "ao2_lam_positive_10pct_electric_kayak_14C_5s_dfn", lion.DFN(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"], "ambient_temperature_K": 287.15,
                "note": "10 % loss of positive active material (volume fraction x0.9, the set's initial concentrations, so the "
                        "lithium of the lost material goes with it: cathode particles cracked and cut off from the conductive "
                        "network; the initial state set as 95 % SOC of the aged cell), at 14 degC (a lake in late spring; "
                        "isothermal, not recorded). A sit-on-top fishing kayak's electric drive per cell from 95 % SOC: 5 min rest, "
                        "8 legs (electric_kayak_steps seed 4002: the push off the shore or away from a spot at 1.4-1.8C for 10-20 "
                        "s, the cruise to the next spot at 0.4-0.7C for 3-8 min, in 40 % of legs a sprint against the wind or the "
                        "tide at 1.0-1.4C for 60-180 s, drifting while fishing at no current for 2-8 min), 30 min rest; 2.3 h, "
                        "down to about 31 % (counted in the set's 5 A h); sampled every 5 s, 1 mV noise; DFN data and model. "
                        "effect_rmse_mV is what the loss alone does"},
               initial_soc=0.95, seed=4002, period=5, compare=lion.DFN())
    # ao3: a 120 mA internal leak the logger does not see, a robotic lawn mower and its dock, 26 degC, 20 s, 1.5 mV, SPM
    leak = 0.12
    seen = (["Rest for 5 minutes"] + robot_mower_steps(4003, 40) + ["Charge at 0.7C for 24 minutes", "Rest for 5 minutes"]
            + robot_mower_steps(40030, 40) + ["Charge at 0.7C for 24 minutes", "Rest for 10 minutes"])
    write_case(root, "ao3_leak_120mA_robot_mower_dock_charges_26C_20s_1p5mV_spm", lion.SPM(), at(chen(), 26), with_leak(seen, leak),
               {"effect": "self_discharge", "candidate_model": "spm", "accept": leak_words, "ambient_temperature_K": 299.15,
                "note": "a 120 mA internal leak (a soft short of about 30 Ohm, C/42, from a dented cell: the mower's pack hit a "
                        "stone) that the mower's logger does not measure, the electrodes carrying the recorded current plus 120 mA "
                        "of discharge throughout, at 26 degC (a garden on a summer morning; isothermal, not recorded). A "
                        "boundary-wire robotic lawn mower per cell from 80 % SOC: 5 min rest, a 40 min mowing run "
                        "(robot_mower_steps seed 4003: straight runs with the blade disc and the wheel motors at 0.35-0.5C for "
                        "60-180 s, in 30 % of runs a patch of long, wet grass at 0.8-1.0C for 10-30 s, the turn at the boundary "
                        "wire at 0.25C for 3-6 s; the drive back to the dock along the wire at 0.3C for 60-180 s), the dock's "
                        "charge at 0.7C for 24 min (time-limited), 5 min rest, a second run (seed 40030), the dock's charge again, "
                        "10 min rest; 2.6 h, down to about 47 %, back to about 75 % as the logger counts it (the leak takes about "
                        "6 % more; counted in the set's 5 A h); sampled every 20 s (the mower's app), 1.5 mV noise; SPM data and "
                        "model. effect_rmse_mV is what the leak alone does"},
               initial_soc=0.8, seed=4003, period=20, noise=1.5e-3, compare=lion.SPM(), leak_A=leak, compare_steps=seen)
    # ao4: positive exchange current x0.3, a cable car's battery recovery drive in the frost, -10 degC, 1 s, 1 mV, SPMe
    p = at(scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.3), -10)
    steps = ["Rest for 5 minutes"] + cable_car_recovery_steps(4004, 10) + ["Rest for 20 minutes"]
    write_case(root, "ao4_kinetics_positive_x0p3_cable_car_recovery_drive_minus10C_1s_spme", lion.SPMe(), p, steps,
               {"effect": "kinetics", "candidate_model": "spme", "accept": kinetic_words, "ambient_temperature_K": 263.15,
                "note": "positive exchange-current density x0.3 (all stoichiometries, the activation energy kept: a cathode whose "
                        "surface has grown a resistive rock-salt and CEI layer), at -10 degC (a ski resort's valley station on a "
                        "winter night; isothermal, not recorded). An aerial ropeway's (cable car's) battery-powered recovery drive "
                        "per cell from 95 % SOC, bringing the cabins into the station after a grid failure: 5 min rest, 10 cabins "
                        "(cable_car_recovery_steps seed 4004: the service brake released and the haul rope started at 1.6-1.9C for "
                        "5-8 s, the rope crawling at recovery speed at 0.8-1.05C for 45-100 s, 1-2 tower crossings at 1.15-1.35C "
                        "for 10-20 s each, the crawl again after each, the rope stopped while the cabin is unloaded, the control "
                        "cabinet and the station's emergency lights at 0.02-0.03C for 40-90 s), 20 min rest; 1.2 h, down to about "
                        "40 % (counted in the set's 5 A h); sampled every 1 s, 1 mV noise; SPMe data and model. effect_rmse_mV is "
                        "what the kinetics alone do"},
               initial_soc=0.95, seed=4004, period=1, compare=lion.SPMe())
    # ao5: lumped self-heating, h = 14, temperature recorded, a backpack leaf blower, 8 degC, 2 s, 0.8 mV, SPMe
    p = at(chen(), 8)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 14.0})
    steps = (["Rest for 5 minutes"] + leaf_blower_steps(4005, 14) + ["Rest for 15 minutes"] + leaf_blower_steps(40050, 8)
             + ["Rest for 30 minutes"])
    write_case(root, "ao5_thermal_h14_recorded_backpack_leaf_blower_8C_2s_0p8mV_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": ["thermal", "self-heating", "heat"], "ambient_temperature_K": 281.15,
                "note": "lumped self-heating, h = 14 W/(m2 K) (cells in the blower's backpack battery, against the operator's "
                        "back, a little air from the fan's intake), ambient and initial 8 degC (a park on a damp autumn morning). "
                        "A landscaper's cordless backpack leaf blower per cell from 95 % SOC: 5 min rest, about 14 min of work "
                        "(leaf_blower_steps seed 4005: full throttle along a lawn or a path at 1.8-2.3C for 30-120 s, half "
                        "throttle shaping the pile at 0.9-1.2C for 20-60 s, in 30 % of passes the trigger released while a tarp "
                        "is moved, no current for 5-20 s), 15 min rest while the leaves are bagged, about 8 min more (seed 40050), "
                        "30 min rest; 1.2 h, down to about 58 % and then 32 % (counted in the set's 5 A h); temperature recorded "
                        "(0.05 K noise, 0.1 K resolution); sampled every 2 s, 0.8 mV noise; SPMe (lumped thermal) data handed to "
                        "the isothermal SPMe. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.95, temperature=True, seed=4005, period=2, noise=8e-4,
               cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4}, compare=lion.SPMe())
    # ao6: pair, an 80 mA internal leak the logger does not see and an 8 mOhm contact resistance, a box-mod vaporiser's puffs,
    # 24 degC, 1 s, 0.7 mV, SPMe
    leak = 0.08
    def vape_cell(contact):
        q = at(chen(), 24)
        q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
        return q
    seen = ["Rest for 5 minutes"] + vape_sessions_steps(4006, 6) + ["Rest for 10 minutes"]
    inside = with_leak(seen, leak)
    contact_model = lambda: lion.SPMe(options={"contact resistance": "true"})
    name = "ao6_leak_80mA_and_contact_8mOhm_boxmod_vaporiser_puffs_24C_1s_0p7mV_spme"
    write_case(root, name, contact_model(), vape_cell(0.008), inside,
               {"effect": "self_discharge+contact_resistance", "candidate_model": "spme",
                "accept": ["|".join(leak_words), "|".join(contact_words)], "ambient_temperature_K": 297.15,
                "note": "two effects: an 80 mA internal leak (a soft short of about 45 Ohm, C/62, in a cell dropped in its "
                        "device) that the device's logger does not measure, the electrodes carrying the recorded current plus 80 "
                        "mA of discharge throughout, and an 8 mOhm contact resistance (the box mod's spring-loaded battery contacts "
                        "and the worn wrap at the cell's positive cap: about 50 mV in a puff), at 24 degC (indoors; isothermal, "
                        "not recorded). A single-cell box-mod vaporiser (e-cigarette) at 20-30 W per cell from 90 % SOC: 5 min "
                        "rest, 6 sessions (vape_sessions_steps seed 4006: 8-14 puffs, the coil fired at 1.1-1.5C for 2-5 s, the "
                        "device idle between puffs for 20-60 s, then the device in a pocket at no current for 8-20 min), 10 min "
                        "rest; 2.4 h, down to about 82 % as the logger counts it (about 78 % with the leak; counted in the set's 5 "
                        "A h); sampled every 1 s, 0.7 mV noise; SPMe (with contact resistance) data handed to the plain SPMe. "
                        "spme_contact_only_rmse_mV: the SPMe with the contact resistance on the recorded protocol against the "
                        "recording (what the leak leaves); spme_leak_only_rmse_mV: the plain SPMe carrying the leak (what the "
                        "contact resistance leaves)"},
               initial_soc=0.9, seed=4006, period=1, noise=7e-4, compare=lion.SPMe(), leak_A=leak, compare_steps=seen)
    replay_rmse(root, name, contact_model(), vape_cell(0.008), seen, 0.9, "spme_contact_only_rmse_mV")
    replay_rmse(root, name, lion.SPMe(), vape_cell(0.0), inside, 0.9, "spme_leak_only_rmse_mV")
    # ao7: pair, positive particle diffusivity x0.3 and the voltage channel reading 6 mV high, a tram's catenary-free sections,
    # 20 degC, 3 s, 1.2 mV, DFN
    def tram_cell(diffusivity):
        return at(scaled(chen(), "Positive particle diffusivity [m2.s-1]", diffusivity), 20)
    steps = ["Rest for 5 minutes"] + tram_catenary_gap_steps(4007, 9) + ["Rest for 10 minutes"]
    name = "ao7_diffusivity_positive_x0p3_and_voltage_offset_6mV_high_tram_catenary_free_20C_3s_1p2mV_dfn"
    write_case(root, name, lion.DFN(), tram_cell(0.3), steps,
               {"effect": "solid_diffusivity+voltage_offset", "candidate_model": "dfn",
                "accept": ["|".join(particle_words), "|".join(offset_words)], "ambient_temperature_K": 293.15,
                "note": "two effects: positive particle diffusivity x0.3 (a cathode whose particles' diffusion is slower: another "
                        "lot, or ageing) and the tram's battery management reading the cell voltage 6 mV high everywhere (a "
                        "calibration offset, under current and at rest alike; not a cell property, an OCP offset is the nearest "
                        "cell-side description and is accepted through 'offset'), at 20 degC (the tram's battery compartment, "
                        "air-conditioned; isothermal, not recorded). A tram's traction battery per cell from 60 % SOC on a line with "
                        "catenary-free sections through a historic centre: 5 min rest, 9 passages (tram_catenary_gap_steps seed "
                        "4007, 4 stops each: the pull-away at 2.2-2.7C for 15-25 s, the run at 0.9-1.4C for 40-90 s, regenerative "
                        "braking into the stop at 1.2-1.7C charge for 8-15 s, the dwell with the doors open, the heating and the "
                        "lights at 0.10-0.15C for 20-40 s; then back under the wire, the battery recharged from the catenary at "
                        "0.9-1.2C for 4-7 min, and in 30 % of passages a layover at the terminus at no current for 3-6 min), 10 min "
                        "rest; 2.4 h, the state of charge between about 30 and 60 % (counted in the set's 5 A h; from 70 % the "
                        "catenary's recharge took the slow cathode over 4.2 V); sampled every 3 "
                        "s, 1.2 mV noise; DFN data, read 6 mV high, handed to the DFN. dfn_diffusivity_only_rmse_mV: the DFN with "
                        "the slow diffusion against the recording (what the offset leaves); dfn_offset_only_rmse_mV: the DFN with "
                        "the set's diffusivity read 6 mV high (what the diffusivity leaves)"},
               initial_soc=0.6, seed=4007, period=3, noise=1.2e-3, compare=lion.DFN(), post=lambda t, i, v: v + 0.006)
    replay_rmse(root, name, lion.DFN(), tram_cell(0.3), steps, 0.6, "dfn_diffusivity_only_rmse_mV", period=3)
    replay_rmse(root, name, lion.DFN(), tram_cell(1.0), steps, 0.6, "dfn_offset_only_rmse_mV", period=3, shift_V=0.006)
    # ao8: 7 % lithium loss, a home storage battery's evening peak in a desert heatwave, 45 degC, 30 s, 2 mV, DFN
    p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.93), 45)
    steps = ["Rest for 5 minutes"] + home_evening_peak_steps(4008, 2.5) + ["Rest for 10 minutes"]
    write_case(root, "ao8_inventory_7pct_home_storage_evening_peak_heatwave_45C_30s_2mV_dfn", lion.DFN(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "dfn", "accept": lithium_words, "ambient_temperature_K": 318.15,
                "note": "7 % less lithium (initial negative concentration x0.93, lithium lost to SEI growth in a battery kept hot; "
                        "the initial state set as 90 % SOC of the aged cell), at 45 degC (a home battery on a garage wall in a "
                        "desert heatwave; isothermal, not recorded). A home storage battery's evening peak per cell from 90 % SOC, "
                        "the inverter capped at 0.5C: 5 min rest, 2.5 h from 5 pm in 15 min slots (home_evening_peak_steps seed "
                        "4008: the first slot the last of the solar panels' output still charging it at 0.03-0.06C, then the "
                        "house's base load at 0.06-0.12C, the cooking in slots 2-5 at 0.25-0.35C more for 8-15 min of the slot, "
                        "after dinner the dishwasher's heater at 0.2C more through slot 6 and its pumps at 0.02C more through slots "
                        "7 and 8, after 30 % of slots a kettle at 0.35C more for 3 min), 10 min rest; 2.9 h, down to about 34 % "
                        "(counted in the set's 5 A h); sampled every 30 s (the inverter's portal), 2 mV noise; DFN data and model. "
                        "effect_rmse_mV is what the loss alone does"},
               initial_soc=0.9, seed=4008, period=30, noise=2e-3, compare=lion.DFN())


def buffered_charger_day_steps(seed, cars):
    """A battery-buffered DC fast charger on a weak grid connection (a rural motorway services) per
    cell (discharge positive), for each of `cars` cars: the wait for the next car with the buffer
    refilled from the grid connection (0.35-0.45C charge for 8-18 min), the car's high-power phase with
    the buffer supplying what the grid cannot (0.5-0.8C for 6-12 min), the car's taper (0.2-0.35C for
    4-8 min), and the handover to the next driver (no current, 1-3 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(cars):
        steps += [f"Charge at {rng.uniform(0.35, 0.45):.3f}C for {60 * int(rng.integers(8, 19))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.8):.3f}C for {60 * int(rng.integers(6, 13))} seconds",
                  f"Discharge at {rng.uniform(0.2, 0.35):.3f}C for {60 * int(rng.integers(4, 9))} seconds",
                  f"Rest for {60 * int(rng.integers(1, 4))} seconds"]
    return steps


def vineyard_tractor_rows_steps(seed, rows):
    """A battery-electric straddle tractor spraying a hillside vineyard per cell (discharge positive),
    for each of `rows` rows: the headland turn (0.6-0.9C for 15-30 s), the run along the row with the
    sprayer's fan and pump (0.8-1.1C for 2-4 min), in 30 % of rows a steep stretch (1.4-1.8C for 20-40
    s) and the run on (0.8-1.0C for 20-60 s); after every 4-6 rows the tank refilled at the bowser
    (the cab's electronics, 0.02C for 5-10 min)."""
    rng = np.random.default_rng(seed)
    steps, since, refill_after = [], 0, int(rng.integers(4, 7))
    for _ in range(rows):
        steps += [f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(15, 31))} seconds",
                  f"Discharge at {rng.uniform(0.8, 1.1):.2f}C for {int(rng.integers(120, 241))} seconds"]
        if rng.uniform() < 0.3:
            steps += [f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {int(rng.integers(20, 41))} seconds",
                      f"Discharge at {rng.uniform(0.8, 1.0):.2f}C for {int(rng.integers(20, 61))} seconds"]
        since += 1
        if since == refill_after:
            steps.append(f"Discharge at 0.02C for {60 * int(rng.integers(5, 11))} seconds")
            since, refill_after = 0, int(rng.integers(4, 7))
    return steps


def rescue_tools_drill_steps(seed, cuts):
    """A fire brigade's battery hydraulic rescue tools (cutter and spreader) freeing a trapped driver at
    a road-collision drill, per cell (discharge positive), for each of `cuts` cuts: the blades closing
    through a pillar or a hinge (1.8-2.4C for 6-15 s), the pump idling at standby pressure while the
    crew checks the cut (0.15-0.25C for 10-40 s), the tool set down while the glass and the trim are
    cleared (no current, 30-90 s); after every 4-6 cuts the spreader forcing a door or pushing the dash
    (1.5-2.0C for 15-30 s)."""
    rng = np.random.default_rng(seed)
    steps, since, spread_after = [], 0, int(rng.integers(4, 7))
    for _ in range(cuts):
        steps += [f"Discharge at {rng.uniform(1.8, 2.4):.2f}C for {int(rng.integers(6, 16))} seconds",
                  f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {int(rng.integers(10, 41))} seconds",
                  f"Rest for {int(rng.integers(30, 91))} seconds"]
        since += 1
        if since == spread_after:
            steps.append(f"Discharge at {rng.uniform(1.5, 2.0):.2f}C for {int(rng.integers(15, 31))} seconds")
            since, spread_after = 0, int(rng.integers(4, 7))
    return steps


def cloud_ramp_smoothing_steps(seed, clouds):
    """A solar farm's ramp-rate-control battery on a day of passing cumulus per cell (discharge
    positive), for each of `clouds` clouds: the shadow arriving, the battery filling the dip the ramp
    limit will not allow (0.4-0.9C for 1-4 min) and easing off as the limit lets the farm's output down
    (0.15-0.3C for 1-3 min); the sun back, the battery absorbing the upswing beyond the limit (0.3-0.7C
    charge for 1-3 min), then restoring its state of charge (0.15-0.25C charge for 2-5 min); clear sky
    until the next cloud (no current, 2-10 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(clouds):
        steps += [f"Discharge at {rng.uniform(0.4, 0.9):.2f}C for {int(rng.integers(60, 241))} seconds",
                  f"Discharge at {rng.uniform(0.15, 0.3):.3f}C for {int(rng.integers(60, 181))} seconds",
                  f"Charge at {rng.uniform(0.3, 0.7):.2f}C for {int(rng.integers(60, 181))} seconds",
                  f"Charge at {rng.uniform(0.15, 0.25):.3f}C for {int(rng.integers(120, 301))} seconds",
                  f"Rest for {int(rng.integers(120, 601))} seconds"]
    return steps


def wheel_loader_yard_steps(seed, cycles):
    """An electric compact wheel loader feeding a shredder at a recycling yard per cell (discharge
    positive), for each of `cycles` load cycles: the bucket driven into the pile and broken out
    (2.0-2.6C for 4-8 s), the reverse with the raised bucket (0.8-1.2C for 6-12 s), the drive to the
    shredder's hopper (0.7-1.0C for 10-20 s), the lift and tip (1.2-1.6C for 4-7 s), the drive back
    (0.6-0.9C for 10-20 s) and the stop at the pile with regeneration (0.4-0.7C charge for 2-4 s); after
    every 6-9 cycles a wait while the shredder clears (the cab's heater and lights, 0.02C for 60-180 s)."""
    rng = np.random.default_rng(seed)
    steps, since, wait_after = [], 0, int(rng.integers(6, 10))
    for _ in range(cycles):
        steps += [f"Discharge at {rng.uniform(2.0, 2.6):.2f}C for {int(rng.integers(4, 9))} seconds",
                  f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(6, 13))} seconds",
                  f"Discharge at {rng.uniform(0.7, 1.0):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(4, 8))} seconds",
                  f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.7):.2f}C for {int(rng.integers(2, 5))} seconds"]
        since += 1
        if since == wait_after:
            steps.append(f"Discharge at 0.02C for {int(rng.integers(60, 181))} seconds")
            since, wait_after = 0, int(rng.integers(6, 10))
    return steps


def karting_heat_steps(seed, laps):
    """An indoor karting track's electric kart through a heat of `laps` laps per cell (discharge
    positive), each lap: the main straight at full throttle (2.2-2.8C for 5-8 s), braking into the
    hairpin with regeneration (0.5-0.8C charge for 2-3 s), the twisty infield (0.6-1.0C for 10-16 s) and
    the last corner's exit (1.4-1.8C for 3-5 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(laps):
        steps += [f"Discharge at {rng.uniform(2.2, 2.8):.2f}C for {int(rng.integers(5, 9))} seconds",
                  f"Charge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(2, 4))} seconds",
                  f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(10, 17))} seconds",
                  f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {int(rng.integers(3, 6))} seconds"]
    return steps


def gantry_crane_moves_steps(seed, moves):
    """A container terminal's battery rubber-tyred gantry crane per cell (discharge positive), for each
    of `moves` container moves: the container hoisted off the truck (1.6-2.2C for 15-25 s), the trolley
    across the stack (0.3-0.5C for 10-20 s), the container lowered onto the stack with the hoist
    regenerating (0.8-1.2C charge for 12-20 s), the empty spreader hoisted (0.5-0.7C for 8-12 s) and the
    wait for the next truck (the cabin's climate control and the lights, 0.02-0.04C for 30-120 s); after
    every 8-12 moves the gantry driven along the block to the next bay (0.6-0.9C for 40-90 s)."""
    rng = np.random.default_rng(seed)
    steps, since, travel_after = [], 0, int(rng.integers(8, 13))
    for _ in range(moves):
        steps += [f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(15, 26))} seconds",
                  f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Charge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(12, 21))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {int(rng.integers(8, 13))} seconds",
                  f"Discharge at {rng.uniform(0.02, 0.04):.3f}C for {int(rng.integers(30, 121))} seconds"]
        since += 1
        if since == travel_after:
            steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(40, 91))} seconds")
            since, travel_after = 0, int(rng.integers(8, 13))
    return steps


def canal_boat_tour_steps(seed, stretches):
    """An electric canal tour boat's round trip per cell (discharge positive): cast off and manoeuvred out
    of the landing stage (0.6-1.0C for 30-60 s), then `stretches` stretches, each a cruise along a canal
    (0.25-0.4C for 3-7 min), a low bridge or a lock approach taken slowly (0.1-0.15C for 60-120 s) and,
    in 40 % of stretches, a tight turn into a side canal against the wind (0.9-1.2C for 20-40 s); the
    boat moored at the landing stage with the lights and the commentary system on while the passengers
    change (0.015C for 8-15 min)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(30, 61))} seconds"]
    for _ in range(stretches):
        steps += [f"Discharge at {rng.uniform(0.25, 0.4):.3f}C for {60 * int(rng.integers(3, 8))} seconds",
                  f"Discharge at {rng.uniform(0.1, 0.15):.3f}C for {int(rng.integers(60, 121))} seconds"]
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {int(rng.integers(20, 41))} seconds")
    return steps + [f"Discharge at 0.015C for {60 * int(rng.integers(8, 16))} seconds"]


def with_current_gain(steps, gain, capacity_A_h=5.0):
    """`steps` ("Discharge|Charge at <x>C for <n> seconds" or "Rest for <n> seconds") with every current
    times `gain`, in A (what a current channel with that gain records of them)."""
    scaled_steps = []
    for s in with_leak(steps, 0.0, capacity_A_h):
        words = s.split()
        amps = float(words[2]) * gain
        scaled_steps.append(f"{words[0]} at {amps:.4f} A for {words[5]} seconds" if amps > 0 else f"Rest for {words[5]} seconds")
    return scaled_steps


def batch_ap(root):
    """Forty-first batch (key "ap"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -5, 2, 7, 12, 17, 21, 28 and 41 degC, each of the three
    models (data and candidate the same model in every case), sampling from 1 to 30 s, noise from 0.6 to
    2 mV, and duties no earlier batch used: a battery-buffered DC fast charger on a weak grid connection,
    a battery-electric straddle tractor spraying a hillside vineyard, a fire brigade's battery hydraulic
    rescue tools at a winter road-collision drill, a solar farm's ramp-rate-control battery under passing
    cumulus, an electric wheel loader feeding a shredder at a recycling yard with a lunchtime charge, an
    indoor karting track's electric kart through three heats, a container terminal's battery
    rubber-tyred gantry crane on a raw winter day, and an electric canal tour boat's round trips with a
    charge at the landing stage. An SPMe control; five single effects (8 % negative active-material
    loss; an aged electrolyte, conductivity and diffusivity x0.5, at -5 degC; one-state OCV hysteresis of
    the negative, +-10 mV; negative particle diffusivity x0.3; lumped self-heating, h = 10, temperature
    not recorded) and two pairs no earlier batch concealed together (a 100 mA internal leak with lumped
    self-heating, h = 8, temperature recorded; a current channel reading 2.5 % high with the negative's
    exchange current x0.35). Words as in batches ah-ao; the current gain by the current-channel words as
    k2, the leak by the self-discharge words. Each effect's size on its own (the nominal candidate, or a
    replay, against the noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the
    replay keys); every step is time-limited (no voltage cut-off reached), so the experiment-aligned
    comparison needs no replay on the recorded current."""
    at = at_temperature
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    thermal_words = ["thermal", "self-heating", "heat"]
    leak_words = ["self-discharge", "self discharge", "leak", "soft short", "internal short", "short circuit", "current offset"]
    gain_words = ["current sensor", "current measurement", "current channel", "current gain", "current scale", "calibration", "gain"]
    # ap1: control, a battery-buffered DC fast charger on a weak grid connection, 41 degC, 5 s, 1 mV, SPMe
    p = at(chen(), 41)
    steps = ["Rest for 10 minutes"] + buffered_charger_day_steps(4101, 5) + ["Rest for 20 minutes"]
    write_case(root, "ap1_control_buffered_ev_fast_charger_weak_grid_41C_5s_spme", lion.SPMe(), p, steps,
               {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 314.15,
                "note": "negative control at 41 degC (the charger's battery cabinet in the sun at a desert highway's services "
                        "on a summer afternoon; isothermal, not recorded): SPMe data and model, nothing concealed. A "
                        "battery-buffered DC fast charger on a weak grid connection per cell from 75 % SOC: 10 min rest, 5 cars "
                        "(buffered_charger_day_steps seed 4101: the wait for the next car with the buffer refilled from the grid "
                        "connection at 0.35-0.45C charge for 8-18 min, the car's high-power phase with the buffer supplying what "
                        "the grid cannot at 0.5-0.8C for 6-12 min, the car's taper at 0.2-0.35C for 4-8 min, the handover at no "
                        "current for 1-3 min), 20 min rest; 3.0 h, up to about 84 % and down to about 48 % (counted in the set's "
                        "5 A h); sampled every 5 s, 1 mV noise"},
               initial_soc=0.75, seed=4101, period=5, compare=lion.SPMe())
    # ap2: 8 % negative active-material loss, a straddle tractor spraying a hillside vineyard, 12 degC, 10 s, 2 mV, SPMe
    p = at(scaled(chen(), "Negative electrode active material volume fraction", 0.92), 12)
    steps = ["Rest for 5 minutes"] + vineyard_tractor_rows_steps(4102, 11) + ["Rest for 30 minutes"]
    write_case(root, "ap2_lam_negative_8pct_vineyard_straddle_tractor_12C_10s_2mV_spme", lion.SPMe(), p, steps,
               {"effect": "active_material_loss", "candidate_model": "spme", "accept": ["active material"], "ambient_temperature_K": 285.15,
                "note": "8 % loss of negative active material (volume fraction x0.92, the set's initial concentrations, so the "
                        "lithium of the lost graphite goes with it: graphite particles isolated as the binder weakened; the initial "
                        "state set as 95 % SOC of the aged cell), at 12 degC (a hillside vineyard on a cool spring morning; "
                        "isothermal, not recorded). A battery-electric straddle tractor spraying the vines per cell from 95 % SOC: "
                        "5 min rest, 11 rows (vineyard_tractor_rows_steps seed 4102: the headland turn at 0.6-0.9C for 15-30 s, "
                        "the run along the row with the sprayer's fan and pump at 0.8-1.1C for 2-4 min, in 30 % of rows a steep "
                        "stretch at 1.4-1.8C for 20-40 s and the run on at 0.8-1.0C for 20-60 s; after every 4-6 rows the tank "
                        "refilled at the bowser, the cab's electronics at 0.02C for 5-10 min), 30 min rest; 1.4 h, down to about "
                        "35 % (counted in the set's 5 A h); sampled every 10 s (the tractor's telematics), 2 mV noise; SPMe data "
                        "and model. effect_rmse_mV is what the loss alone does"},
               initial_soc=0.95, seed=4102, period=10, noise=2e-3, compare=lion.SPMe())
    # ap3: an aged electrolyte (conductivity and diffusivity x0.5), rescue tools at a winter road-collision drill, -5 degC,
    # 3 s, 1.2 mV, DFN
    p = at(scaled(scaled(chen(), "Electrolyte conductivity [S.m-1]", 0.5), "Electrolyte diffusivity [m2.s-1]", 0.5), -5)
    steps = (["Rest for 10 minutes"] + rescue_tools_drill_steps(4103, 22) + ["Rest for 20 minutes"]
             + rescue_tools_drill_steps(41030, 16) + ["Rest for 20 minutes"])
    write_case(root, "ap3_electrolyte_aged_x0p5_rescue_tools_drill_minus5C_3s_1p2mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 268.15,
                "note": "an aged electrolyte: conductivity and diffusivity x0.5 at every concentration and temperature (the "
                        "solvent partly decomposed and the salt's transport hindered by its products), at -5 degC (a fire "
                        "station's yard on a frosty winter evening; isothermal, not recorded). A fire brigade's battery hydraulic "
                        "rescue tools per cell from 90 % SOC at a road-collision drill: 10 min rest, 22 cuts "
                        "(rescue_tools_drill_steps seed 4103: the blades closing through a pillar or a hinge at 1.8-2.4C for 6-15 "
                        "s, the pump idling at standby pressure at 0.15-0.25C for 10-40 s, the tool set down while the glass and "
                        "the trim are cleared at no current for 30-90 s; after every 4-6 cuts the spreader forcing a door at "
                        "1.5-2.0C for 15-30 s), 20 min rest (the debrief before the second car), 16 cuts more (seed 41030), 20 "
                        "min rest; 1.9 h, down to about 53 % (counted in the set's 5 A h); sampled every 3 s, 1.2 mV noise; DFN "
                        "data and model. effect_rmse_mV is what the aged electrolyte alone does"},
               initial_soc=0.9, seed=4103, period=3, noise=1.2e-3, compare=lion.DFN())
    # ap4: one-state hysteresis of the negative OCP, +-10 mV, a solar farm's ramp-rate-control battery, 21 degC, 15 s, 0.8 mV, SPM
    p = at(chen(), 21)
    with_negative_hysteresis(p, 0.010)
    steps = ["Rest for 10 minutes"] + cloud_ramp_smoothing_steps(4104, 11) + ["Rest for 20 minutes"]
    write_case(root, "ap4_hysteresis_negative_10mV_solar_ramp_rate_control_21C_15s_0p8mV_spm",
               lion.SPM(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
               {"effect": "hysteresis", "candidate_model": "spm", "accept": ["hysteresis"], "ambient_temperature_K": 294.15,
                "note": "one-state OCV hysteresis of the negative electrode, lithiation and delithiation OCPs 10 mV either side "
                        "of the set's (decay rate 10, initial state 0, the middle; the SiOx in the LG M50's graphite), the "
                        "positive without, at 21 degC (the battery container's air conditioning; isothermal, not recorded). A "
                        "solar farm's ramp-rate-control battery per cell from 60 % SOC on a day of passing cumulus: 10 min rest, "
                        "11 clouds (cloud_ramp_smoothing_steps seed 4104: the shadow arriving, the battery filling the dip the "
                        "ramp limit will not allow at 0.4-0.9C for 1-4 min and easing off at 0.15-0.3C for 1-3 min; the sun back, "
                        "the battery absorbing the upswing beyond the limit at 0.3-0.7C charge for 1-3 min, then restoring its "
                        "state of charge at 0.15-0.25C charge for 2-5 min; clear sky at no current for 2-10 min), 20 min rest; "
                        "3.5 h, the state of charge drifting down to about 45 % (counted in the set's 5 A h); sampled every 15 s "
                        "(the plant controller's historian), 0.8 mV noise; SPM (one-state hysteresis) data handed to the plain "
                        "SPM. effect_rmse_mV is what the hysteresis alone does"},
               initial_soc=0.6, seed=4104, period=15, noise=8e-4, compare=lion.SPM())
    # ap5: negative particle diffusivity x0.3, an electric wheel loader at a recycling yard, 7 degC, 1 s, 0.6 mV, DFN
    p = at(scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.3), 7)
    steps = (["Rest for 5 minutes"] + wheel_loader_yard_steps(4105, 20)
             + ["Rest for 5 minutes", "Charge at 0.5C for 20 minutes", "Rest for 5 minutes"]
             + wheel_loader_yard_steps(41050, 20) + ["Rest for 20 minutes"])
    write_case(root, "ap5_diffusivity_negative_x0p3_recycling_yard_wheel_loader_7C_1s_0p6mV_dfn", lion.DFN(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "dfn", "accept": particle_words, "ambient_temperature_K": 280.15,
                "note": "negative particle diffusivity x0.3 (a graphite whose solid diffusion is slower: another supplier's lot, "
                        "or ageing), at 7 degC (an open recycling yard in late autumn; isothermal, not recorded). An electric "
                        "compact wheel loader feeding a shredder per cell from 85 % SOC: 5 min rest, 20 load cycles "
                        "(wheel_loader_yard_steps seed 4105: the bucket driven into the pile and broken out at 2.0-2.6C for 4-8 "
                        "s, the reverse with the raised bucket at 0.8-1.2C for 6-12 s, the drive to the hopper at 0.7-1.0C for "
                        "10-20 s, the lift and tip at 1.2-1.6C for 4-7 s, the drive back at 0.6-0.9C for 10-20 s, the stop at "
                        "the pile with regeneration at 0.4-0.7C charge for 2-4 s; after every 6-9 cycles a wait while the "
                        "shredder clears, the cab's heater and lights at 0.02C for 60-180 s), 5 min rest, a lunchtime charge at "
                        "0.5C for 20 min (time-limited), 5 min rest, 20 cycles more (seed 41050), 20 min rest; 1.6 h, down to "
                        "about 57 %, up to about 74 %, down to about 44 % (counted in the set's 5 A h); sampled every 1 s, 0.6 mV "
                        "noise; DFN data and model. effect_rmse_mV is what the slower diffusion alone does"},
               initial_soc=0.85, seed=4105, period=1, noise=6e-4, compare=lion.DFN())
    # ap6: lumped self-heating, h = 10, temperature not recorded, an indoor karting track's electric kart, 17 degC, 2 s, 1 mV, SPMe
    p = at(chen(), 17)
    p.update({"Total heat transfer coefficient [W.m-2.K-1]": 10.0})
    steps = (["Rest for 5 minutes"] + karting_heat_steps(4106, 22) + ["Rest for 8 minutes"] + karting_heat_steps(41060, 22)
             + ["Rest for 8 minutes"] + karting_heat_steps(41061, 22) + ["Rest for 20 minutes"])
    write_case(root, "ap6_thermal_h10_unrecorded_indoor_electric_karting_17C_2s_spme", lion.SPMe(options={"thermal": "lumped"}), p, steps,
               {"effect": "thermal", "candidate_model": "spme", "accept": thermal_words, "ambient_temperature_K": 290.15,
                "note": "lumped self-heating, h = 10 W/(m2 K) (cells packed tightly in the kart's sealed battery box under the "
                        "seat), ambient and initial 17 degC (an indoor karting hall); the temperature not recorded (the kart's "
                        "logger writes current and voltage only). An indoor karting track's electric kart per cell from 90 % "
                        "SOC: 5 min rest, three heats of 22 laps (karting_heat_steps seeds 4106, 41060, 41061: per lap the main "
                        "straight at full throttle at 2.2-2.8C for 5-8 s, braking into the hairpin with regeneration at 0.5-0.8C "
                        "charge for 2-3 s, the twisty infield at 0.6-1.0C for 10-16 s, the last corner's exit at 1.4-1.8C for 3-5 "
                        "s), 8 min in the pit lane at no current between heats, 20 min rest; 1.2 h, down to about 31 % (counted in "
                        "the set's 5 A h); sampled every 2 s, 1 mV noise; SPMe (lumped thermal) data handed to the isothermal "
                        "SPMe. effect_rmse_mV is what the heating alone does"},
               initial_soc=0.9, seed=4106, period=2, compare=lion.SPMe())
    # ap7: pair, a 100 mA internal leak the crane's logger does not see and lumped self-heating (h = 8, temperature recorded),
    # a container terminal's battery gantry crane, 2 degC, 20 s, 1 mV, SPM
    leak = 0.10
    def crane_cell(h):
        q = at(chen(), 2)
        if h is not None:
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": h})
        return q
    seen = ["Rest for 5 minutes"] + gantry_crane_moves_steps(4107, 34) + ["Rest for 15 minutes"]
    inside = with_leak(seen, leak)
    name = "ap7_leak_100mA_and_thermal_h8_recorded_container_gantry_crane_2C_20s_spm"
    write_case(root, name, lion.SPM(options={"thermal": "lumped"}), crane_cell(8.0), inside,
               {"effect": "self_discharge+thermal", "candidate_model": "spm",
                "accept": ["|".join(leak_words), "|".join(thermal_words)], "ambient_temperature_K": 275.15,
                "note": "two effects: a 100 mA internal leak (a soft short of about 35 Ohm, C/50, from a burr on an electrode edge) "
                        "that the crane's logger does not measure, the electrodes carrying the recorded current plus 100 mA of "
                        "discharge throughout, and lumped self-heating, h = 8 W/(m2 K) (the crane's insulated battery room on the "
                        "sill beam, the cells packed tightly), ambient and initial 2 degC (a container terminal at a northern port "
                        "on a raw winter day). A container terminal's battery rubber-tyred gantry crane per cell from 75 % SOC: 5 "
                        "min rest, 34 container moves (gantry_crane_moves_steps seed 4107: the container hoisted off the truck at "
                        "1.6-2.2C for 15-25 s, the trolley across the stack at 0.3-0.5C for 10-20 s, the container lowered with the "
                        "hoist regenerating at 0.8-1.2C charge for 12-20 s, the empty spreader hoisted at 0.5-0.7C for 8-12 s, the "
                        "wait for the next truck with the cabin's climate control and the lights at 0.02-0.04C for 30-120 s; after "
                        "every 8-12 moves the gantry driven along the block at 0.6-0.9C for 40-90 s), 15 min rest; 1.7 h, down to "
                        "about 35 % as the logger counts it (about 31 % with the leak; counted in the set's 5 A h); temperature "
                        "recorded (0.05 K noise, 0.1 K resolution); sampled every 20 s (the crane's condition monitoring), 1 mV "
                        "noise; SPM (lumped thermal) data handed to the isothermal SPM. spm_thermal_only_rmse_mV: the SPM with the "
                        "self-heating on the recorded protocol against the recording (what the leak leaves); spm_leak_only_rmse_mV: "
                        "the isothermal SPM carrying the leak (what the heating leaves)"},
               initial_soc=0.75, temperature=True, seed=4107, period=20, cycler={"quantum_K": 0.1, "quantum_V": 1e-4, "quantum_A": 1e-4},
               compare=lion.SPM(), leak_A=leak, compare_steps=seen)
    replay_rmse(root, name, lion.SPM(options={"thermal": "lumped"}), crane_cell(8.0), seen, 0.75, "spm_thermal_only_rmse_mV", period=20)
    replay_rmse(root, name, lion.SPM(), crane_cell(None), inside, 0.75, "spm_leak_only_rmse_mV", period=20)
    # ap8: pair, the current channel reading 2.5 % high and the negative's exchange current x0.35, an electric canal tour boat,
    # 28 degC, 30 s, 1.5 mV, SPM
    gain = 1.025
    def boat_cell(kinetics):
        return at(scaled(chen(), "Negative electrode exchange-current density [A.m-2]", kinetics), 28)
    steps = (["Rest for 5 minutes"] + canal_boat_tour_steps(4108, 7) + ["Charge at 0.4C for 25 minutes"]
             + canal_boat_tour_steps(41080, 7) + ["Rest for 10 minutes"])
    seen = with_current_gain(steps, gain)
    name = "ap8_current_gain_2p5pct_high_and_kinetics_negative_x0p35_canal_tour_boat_28C_30s_1p5mV_spm"
    write_case(root, name, lion.SPM(), boat_cell(0.35), steps,
               {"effect": "current_measurement_gain+kinetics", "candidate_model": "spm",
                "accept": ["|".join(gain_words), "|".join(kinetic_words)], "ambient_temperature_K": 301.15,
                "note": "two effects: the boat's battery management reading the current 2.5 % high (gain 1.025, a shunt out of "
                        "calibration: the recorded current is the cell's times 1.025 on charge and discharge alike; not a cell "
                        "property) and the negative's exchange-current density x0.35 (all stoichiometries, the activation energy "
                        "kept: graphite covered by a thick SEI), at 28 degC (a canal city in summer; isothermal, not recorded). An "
                        "electric canal tour boat per cell from 90 % SOC: 5 min rest, a round trip (canal_boat_tour_steps seed "
                        "4108: cast off and manoeuvred out at 0.6-1.0C for 30-60 s, 7 stretches, each a cruise at 0.25-0.4C for "
                        "3-7 min, a low bridge or a lock approach taken slowly at 0.1-0.15C for 60-120 s and, in 40 % of "
                        "stretches, a tight turn into a side canal at 0.9-1.2C for 20-40 s; moored at the landing stage with the "
                        "lights and the commentary on at 0.015C for 8-15 min), the landing stage's charger at 0.4C for 25 min "
                        "(time-limited), a second round trip (seed 41080), 10 min rest; 2.8 h, down to about 64 %, up to about 80 "
                        "%, down to about 54 % (the cell's own current, counted in the set's 5 A h; the logger counts 2.5 % more "
                        "both ways); sampled every 30 s (the boat's telemetry), 1.5 mV noise; SPM data and model. "
                        "spm_kinetics_only_rmse_mV: the SPM with the slow negative kinetics on the recorded current's protocol "
                        "against the recording (what the gain leaves); spm_gain_only_rmse_mV: the SPM with the set's kinetics "
                        "carrying the cell's own current (what the kinetics leave)"},
               initial_soc=0.9, seed=4108, period=30, noise=1.5e-3, compare=lion.SPM(), current_gain=gain, compare_steps=seen)
    replay_rmse(root, name, lion.SPM(), boat_cell(0.35), seen, 0.9, "spm_kinetics_only_rmse_mV", period=30)
    replay_rmse(root, name, lion.SPM(), boat_cell(1.0), steps, 0.9, "spm_gain_only_rmse_mV", period=30)


def ice_cream_van_round_steps(seed, streets):
    """An electric ice-cream van's afternoon round per cell (discharge positive), for each of `streets`
    streets: the drive to the next street with the chimes playing (0.5-0.8C for 60-180 s), then parked
    serving: the freezer's compressor running with the soft-serve machine (0.2-0.3C for 2-4 min) and
    cycling off, the lights and the till only (0.03C for 1-3 min); in 30 % of streets a second spell of
    the compressor (0.2-0.3C for 1-3 min) while the queue lasts."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(streets):
        steps += [f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(60, 181))} seconds",
                  f"Discharge at {rng.uniform(0.2, 0.3):.3f}C for {int(rng.integers(120, 241))} seconds",
                  f"Discharge at 0.03C for {int(rng.integers(60, 181))} seconds"]
        if rng.uniform() < 0.3:
            steps.append(f"Discharge at {rng.uniform(0.2, 0.3):.3f}C for {int(rng.integers(60, 181))} seconds")
    return steps


def milk_float_round_steps(seed, streets):
    """An electric milk float's pre-dawn doorstep round per cell (discharge positive), for each of
    `streets` streets: the pull-away laden with crates (1.0-1.4C for 8-15 s), the drive to the street
    (0.6-0.9C for 60-120 s), then 3-6 doorsteps, each a creep along the kerb (0.3-0.5C for 10-20 s) and
    the float stopped while the milkman walks to the door (the cab light, 0.01C for 20-40 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(streets):
        steps += [f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(8, 16))} seconds",
                  f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(60, 121))} seconds"]
        for _ in range(int(rng.integers(3, 7))):
            steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(10, 21))} seconds",
                      f"Discharge at 0.01C for {int(rng.integers(20, 41))} seconds"]
    return steps


def ground_power_turn_steps(seed, turns):
    """An airport's battery ground power unit (eGPU) per cell (discharge positive), for each of `turns`
    aircraft turnarounds: the unit driven to the stand (0.3-0.5C for 3-6 min), the parked aircraft's
    cabin lights and avionics on ground power (0.25-0.4C for 15-25 min) with the galley ovens heating the
    next flight's meals (0.6-0.9C for 3-5 min) part-way through, and the unit unplugged and waiting for
    the next arrival (its own electronics, 0.01C for 5-15 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(turns):
        cabin = int(rng.integers(15, 26))
        before = int(rng.integers(4, cabin - 4))
        steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {60 * int(rng.integers(3, 7))} seconds",
                  f"Discharge at {rng.uniform(0.25, 0.4):.3f}C for {60 * before} seconds",
                  f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {60 * int(rng.integers(3, 6))} seconds",
                  f"Discharge at {rng.uniform(0.25, 0.4):.3f}C for {60 * (cabin - before)} seconds",
                  f"Discharge at 0.01C for {60 * int(rng.integers(5, 16))} seconds"]
    return steps


def school_bus_run_steps(seed, stops):
    """An electric school bus's morning run per cell (discharge positive), for each of `stops` stops:
    the pull-away (1.5-2.0C for 8-15 s), the run along a country road (0.5-0.9C for 30-90 s),
    regenerative braking into the stop (0.6-1.0C charge for 5-10 s) and the children boarding with the
    doors open and the cabin heater on (0.1-0.15C for 20-60 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(stops):
        steps += [f"Discharge at {rng.uniform(1.5, 2.0):.2f}C for {int(rng.integers(8, 16))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(30, 91))} seconds",
                  f"Charge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(5, 11))} seconds",
                  f"Discharge at {rng.uniform(0.1, 0.15):.3f}C for {int(rng.integers(20, 61))} seconds"]
    return steps


def trials_bike_sections_steps(seed, sections):
    """An electric trials motorcycle's competition per cell (discharge positive), for each of `sections`
    observed sections: 5-9 obstacles, each a burst of throttle onto a rock or a log (2.0-3.0C for 1-3 s)
    and the balance and the approach to the next one (0.2-0.4C for 3-8 s); then the rider walks the
    next section with the bike standing (no current, 2-5 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(sections):
        for _ in range(int(rng.integers(5, 10))):
            steps += [f"Discharge at {rng.uniform(2.0, 3.0):.2f}C for {int(rng.integers(1, 4))} seconds",
                      f"Discharge at {rng.uniform(0.2, 0.4):.2f}C for {int(rng.integers(3, 9))} seconds"]
        steps.append(f"Rest for {60 * int(rng.integers(2, 6))} seconds")
    return steps


def snow_groomer_night_steps(seed, passes):
    """A battery-electric snow groomer preparing a ski slope through the night per cell (discharge
    positive), for each of `passes` passes: the climb up the slope (0.9-1.2C for 90-180 s), the descent
    with the tiller and the blade grooming (0.2-0.35C for 120-200 s), and a pause at the top or the
    bottom while the driver checks the piste (the cab's heater and lights, 0.02C for 30-90 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(passes):
        steps += [f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {int(rng.integers(90, 181))} seconds",
                  f"Discharge at {rng.uniform(0.2, 0.35):.3f}C for {int(rng.integers(120, 201))} seconds",
                  f"Discharge at 0.02C for {int(rng.integers(30, 91))} seconds"]
    return steps


def road_train_loop_steps(seed, stations):
    """A theme park's electric road train on its loop per cell (discharge positive), for each of
    `stations` stations: the pull-away with three laden carriages (1.2-1.6C for 10-20 s), the cruise
    along the park's paths (0.4-0.6C for 60-150 s), regenerative braking into the station (0.4-0.7C
    charge for 5-10 s) and the dwell with the commentary and the lights on (0.03C for 60-120 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(stations):
        steps += [f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(60, 151))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.7):.2f}C for {int(rng.integers(5, 11))} seconds",
                  f"Discharge at 0.03C for {int(rng.integers(60, 121))} seconds"]
    return steps


def orchard_platform_steps(seed, trees):
    """An orchard's self-propelled electric picking platform per cell (discharge positive), for each of
    `trees` stretches of the row: the drive along the row (0.3-0.5C for 60-180 s), the platform raised
    into the canopy by its hydraulic pump (1.0-1.4C for 10-20 s), the pickers at work with the platform
    standing (its lights and the bin conveyor, 0.02-0.05C for 2-4 min), and the platform lowered (the
    pump's valve only, 0.1C for 10 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(trees):
        steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(60, 181))} seconds",
                  f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(10, 21))} seconds",
                  f"Discharge at {rng.uniform(0.02, 0.05):.3f}C for {int(rng.integers(120, 241))} seconds",
                  "Discharge at 0.1C for 10 seconds"]
    return steps


def batch_aq(root):
    """Forty-second batch (key "aq"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -10, 5, 9, 15, 21, 27, 33 and 40 degC, each of the three
    models (data and candidate the same model in every case), sampling from 1 to 30 s, noise from 0.5 to
    2 mV, and duties no earlier batch used: an electric ice-cream van's afternoon round, an electric milk
    float's pre-dawn doorstep round, an airport's battery ground power unit through four aircraft
    turnarounds with a charge between, an electric school bus's morning run on a frosty morning, an
    electric trials motorcycle's competition in a summer heat, a battery-electric snow groomer's night on
    a ski slope, a theme park's electric road train on its loop, and an orchard's electric picking
    platform along the rows in the autumn. A DFN control; five single effects (positive particle radius
    x1.4, a coarser cathode powder; the voltage channel reading 0.35 % high, a gain error; a heavier
    negative coating, electrode thickness x1.1; the voltage logged 3 s late against the current; the
    electrolyte's salt concentration x0.7 at -10 degC) and two pairs no earlier batch concealed together
    (an asymmetric charge transfer at the graphite, anodic transfer coefficient 0.4, with 6 % lithium
    loss; a 6 mOhm contact resistance with the current channel reading 2 % low). Words as in batches
    ah-ap; the particle radius by the particle words or its own name (radius, particle size); the
    thickness by the active-material words or its own name (thickness, loading), as am4; the voltage gain
    as ah8; the delay as bb5; the salt by "electrolyte" or "salt", as am8; the transfer coefficient by
    the kinetics words or its own name, as ak7; the current gain by the current-channel words, as ap8.
    Each effect's size on its own (the nominal candidate, or a replay, against the noise-free voltage or
    the recording) is in truth.json (effect_rmse_mV and the replay keys); every step is time-limited (no
    voltage cut-off reached), so the experiment-aligned comparison needs no replay on the recorded
    current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
    particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
    contact_words = ["contact", "series resistance", "ohmic"]
    gain_words = ["current sensor", "current measurement", "current channel", "current gain", "current scale", "calibration", "gain"]
    transfer_words = ["transfer coefficient", "Butler-Volmer", "Tafel", "symmetry factor"]
    # aq1: control, an electric ice-cream van's afternoon round, 33 degC, 10 s, 1.5 mV, DFN
    p = at(chen(), 33)
    steps = ["Rest for 10 minutes"] + ice_cream_van_round_steps(4201, 12) + ["Rest for 20 minutes"]
    write_case(root, "aq1_control_ice_cream_van_round_33C_10s_1p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 306.15,
                "note": "negative control at 33 degC (the van's battery under the floor on a hot summer afternoon; isothermal, "
                        "not recorded). An electric ice-cream van's afternoon round per cell from 90 % SOC: 10 min rest, 12 "
                        "streets (ice_cream_van_round_steps seed 4201: the drive to the next street with the chimes at 0.5-0.8C "
                        "for 60-180 s, parked serving with the freezer's compressor and the soft-serve machine at 0.2-0.3C for "
                        "2-4 min, the lights and the till only at 0.03C for 1-3 min, in 30 % of streets a second spell of the "
                        "compressor at 0.2-0.3C for 1-3 min), 20 min rest; 2.0 h, down to about 43 % (counted in the set's 5 A "
                        "h); sampled every 10 s, 1.5 mV noise; DFN data and model"},
               initial_soc=0.9, seed=4201, period=10, noise=1.5e-3, compare=lion.DFN())
    # aq2: positive particle radius x1.4 (a coarser cathode powder), an electric milk float's doorstep round, 15 degC, 5 s, 1 mV, SPMe
    p = at(scaled(chen(), "Positive particle radius [m]", 1.4), 15)
    steps = ["Rest for 5 minutes"] + milk_float_round_steps(4202, 16) + ["Rest for 20 minutes"]
    write_case(root, "aq2_radius_positive_x1p4_milk_float_doorstep_round_15C_5s_spme", lion.SPMe(), p, steps,
               {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": particle_words + ["radius", "particle size"],
                "ambient_temperature_K": 288.15,
                "note": "positive particle radius x1.4 (7.3 um instead of the set's 5.22 um: a coarser NMC 811 powder from another "
                        "supplier; the diffusion length longer and the specific surface area smaller). Not itself a candidate "
                        "parameter, its physics is the particle diffusion family (or its own name, radius / particle size). At "
                        "15 degC (a summer dawn; isothermal, not recorded). An electric milk float's pre-dawn doorstep round per "
                        "cell from 90 % SOC: 5 min rest, 16 streets (milk_float_round_steps seed 4202: the pull-away laden with "
                        "crates at 1.0-1.4C for 8-15 s, the drive to the street at 0.6-0.9C for 60-120 s, then 3-6 doorsteps, "
                        "each a creep along the kerb at 0.3-0.5C for 10-20 s and the float stopped with the cab light on at "
                        "0.01C for 20-40 s), 20 min rest; 1.6 h, down to about 43 % (counted in the set's 5 A h); sampled every "
                        "5 s, 1 mV noise; SPMe data and model. effect_rmse_mV is what the coarser powder alone does"},
               initial_soc=0.9, seed=4202, period=5, compare=lion.SPMe())
    # aq3: the voltage channel reads 0.35 % high (a gain error), an airport's battery ground power unit, 27 degC, 20 s, 2 mV, SPM
    p = at(chen(), 27)
    steps = (["Rest for 10 minutes"] + ground_power_turn_steps(4203, 2) + ["Charge at 0.5C for 30 minutes", "Rest for 5 minutes"]
             + ground_power_turn_steps(42030, 2) + ["Rest for 20 minutes"])
    write_case(root, "aq3_voltage_channel_gain_0p35pct_high_airport_ground_power_unit_27C_20s_2mV_spm", lion.SPM(), p, steps,
               {"effect": "voltage_measurement_gain", "candidate_model": "spm",
                "accept": ["voltage offset", "voltage gain", "voltage scale", "voltage channel", "voltage sensor", "voltage measurement",
                           "calibration"],
                "ambient_temperature_K": 300.15,
                "note": "the unit's battery management reads the cell voltage 0.35 % high (a gain error of the voltage "
                        "measurement, 1.0035 x the cell's voltage: 14.4 mV at 4.1 V, 12.6 mV at 3.6 V; not an offset), under "
                        "current and at rest alike; the cell itself is nominal. Not a cell property; a voltage offset (about 13 mV) "
                        "is its nearest constant stand-in and is accepted, as are the words an engineer would use for the "
                        "channel. At 27 degC (an apron in summer; isothermal, not recorded). An airport's battery ground power "
                        "unit (eGPU) per cell from 95 % SOC: 10 min rest, 2 aircraft turnarounds (ground_power_turn_steps seed "
                        "4203: the unit driven to the stand at 0.3-0.5C for 3-6 min, the parked aircraft's cabin and avionics at "
                        "0.25-0.4C for 15-25 min with the galley ovens at 0.6-0.9C for 3-5 min part-way through, the unit "
                        "unplugged and waiting at 0.01C for 5-15 min), a charge at the depot at 0.5C for 30 min (time-limited), 5 "
                        "min rest, 2 turnarounds more (seed 42030), 20 min rest; 3.7 h, down to about 45 % (counted in the set's 5 "
                        "A h); sampled every 20 s (the unit's telematics), 2 mV noise; SPM data and model"},
               initial_soc=0.95, seed=4203, period=20, noise=2e-3, compare=lion.SPM(), post=lambda t, i, v: 1.0035 * v)
    # aq4: negative electrode thickness x1.1 (a heavier anode coating), an electric school bus's morning run, 5 degC, 4 s, 0.8 mV, DFN
    p = at(scaled(chen(), "Negative electrode thickness [m]", 1.1), 5)
    steps = ["Rest for 5 minutes"] + school_bus_run_steps(4204, 30) + ["Rest for 30 minutes"]
    write_case(root, "aq4_thickness_negative_x1p1_school_bus_morning_run_5C_4s_0p8mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrode_thickness", "candidate_model": "dfn",
                "accept": ["active material", "thickness", "loading"], "ambient_temperature_K": 278.15,
                "note": "negative electrode thickness x1.1 (93.5 um instead of the set's 85.2 um: a heavier graphite coating from "
                        "another production line, the negative's capacity and its lithium per area both 10 % larger), judged by the "
                        "active-material words or its own name (thickness, loading). At 5 degC (a frosty morning; isothermal, not "
                        "recorded). An electric school bus's morning run per cell from 85 % SOC: 5 min rest, 30 stops "
                        "(school_bus_run_steps seed 4204: the pull-away at 1.5-2.0C for 8-15 s, the run along a country road at "
                        "0.5-0.9C for 30-90 s, regenerative braking into the stop at 0.6-1.0C charge for 5-10 s, the children "
                        "boarding with the doors open and the heater on at 0.1-0.15C for 20-60 s), 30 min rest at the school; 1.6 "
                        "h, down to about 37 % (counted in the set's 5 A h); sampled every 4 s, 0.8 mV noise; DFN data and model. "
                        "effect_rmse_mV is what the heavier coating alone does"},
               initial_soc=0.85, seed=4204, period=4, noise=8e-4, compare=lion.DFN())
    # aq5: the logger stamps the voltage 3 s late against the current, an electric trials motorcycle, 40 degC, 1 s, 0.5 mV, SPMe
    p = at(chen(), 40)
    steps = ["Rest for 5 minutes"] + trials_bike_sections_steps(4205, 10) + ["Rest for 15 minutes"]
    write_case(root, "aq5_voltage_logged_3s_late_trials_motorcycle_40C_1s_0p5mV_spme", lion.SPMe(), p, steps,
               {"effect": "voltage_time_lag", "candidate_model": "spme",
                "accept": ["delay", "latency", "misalign", "synchron", "time shift", "time offset", "timestamp", "time stamp", "time lag",
                           "time base", "time axis"],
                "ambient_temperature_K": 313.15,
                "note": "a logging fault, not a cell property and not among the tool's candidates: the bike's data logger stamps "
                        "the voltage 3 s later than the current (the battery management sends them in separate, unsynchronised "
                        "messages), so each recorded voltage is the cell's voltage 3 s earlier (linear interpolation of the 1 s "
                        "simulation; the first 3 s hold the first value). The cell itself is nominal. An engineer would call it a "
                        "time delay / misalignment / synchronisation error between the channels. At 40 degC (a summer trial in a "
                        "quarry; isothermal, not recorded). An electric trials motorcycle's competition per cell from 90 % SOC: 5 "
                        "min rest, 10 observed sections (trials_bike_sections_steps seed 4205: 5-9 obstacles, each a burst of "
                        "throttle onto a rock or a log at 2.0-3.0C for 1-3 s and the balance and the approach to the next at "
                        "0.2-0.4C for 3-8 s; then the bike standing while the rider walks the next section, no current for 2-5 "
                        "min), 15 min rest; 1.2 h, down to about 77 % (counted in the set's 5 A h); sampled every 1 s, 0.5 mV "
                        "noise; SPMe data and model. effect_rmse_mV is what the delay alone does"},
               initial_soc=0.9, seed=4205, period=1, noise=5e-4, compare=lion.SPMe(), post=lambda t, i, v: np.interp(t - 3.0, t, v))
    # aq6: the electrolyte's salt concentration x0.7, a battery-electric snow groomer's night, -10 degC, 15 s, 1.5 mV, DFN
    p = at(scaled(chen(), "Initial concentration in electrolyte [mol.m-3]", 0.7), -10)
    steps = ["Rest for 5 minutes"] + snow_groomer_night_steps(4206, 10) + ["Rest for 20 minutes"]
    write_case(root, "aq6_electrolyte_salt_x0p7_snow_groomer_night_minus10C_15s_1p5mV_dfn", lion.DFN(), p, steps,
               {"effect": "electrolyte_salt_concentration", "candidate_model": "dfn", "accept": ["electrolyte", "salt"],
                "ambient_temperature_K": 263.15,
                "note": "the electrolyte's salt concentration x0.7 (700 mol/m3 instead of the set's 1000: LiPF6 consumed by "
                        "decomposition and SEI growth, or a lean fill), conductivity, diffusivity and the exchange currents "
                        "following the set's concentration dependences, at -10 degC (a ski slope at night; isothermal, not "
                        "recorded). A battery-electric snow groomer per cell from 95 % SOC: 5 min rest, 10 passes "
                        "(snow_groomer_night_steps seed 4206: the climb up the slope at 0.9-1.2C for 90-180 s, the descent with "
                        "the tiller and the blade at 0.2-0.35C for 120-200 s, a pause while the driver checks the piste with the "
                        "cab's heater and lights at 0.02C for 30-90 s), 20 min rest; 1.5 h, down to about 41 % (counted in the "
                        "set's 5 A h); sampled every 15 s, 1.5 mV noise; DFN data and model. effect_rmse_mV is what the lower salt "
                        "concentration alone does"},
               initial_soc=0.95, seed=4206, period=15, noise=1.5e-3, compare=lion.DFN())
    # aq7: pair, the graphite's anodic transfer coefficient 0.4 (asymmetric Butler-Volmer) and 6 % lithium loss, a theme park's
    # electric road train, 21 degC, 2 s, 1 mV, SPM
    def train_cell(alpha, lithium):
        q = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", lithium), 21)
        q.update({"Negative electrode Butler-Volmer transfer coefficient": alpha,
                  "Positive electrode Butler-Volmer transfer coefficient": 0.5}, check_already_exists=False)
        return q
    asym = lambda: lion.SPM(options={"intercalation kinetics": "asymmetric Butler-Volmer"})
    steps = ["Rest for 5 minutes"] + road_train_loop_steps(4207, 14) + ["Rest for 15 minutes"]
    name = "aq7_asymmetric_charge_transfer_negative_alpha0p4_and_inventory_6pct_theme_park_road_train_21C_2s_spm"
    write_case(root, name, asym(), train_cell(0.4, 0.94), steps,
               {"effect": "kinetics+lithium_inventory_loss", "candidate_model": "spm",
                "accept": ["|".join(kinetic_words + transfer_words), "|".join(lithium_words)], "ambient_temperature_K": 294.15,
                "note": "two effects: the charge transfer at the graphite asymmetric, anodic transfer coefficient 0.4 and cathodic "
                        "0.6 (PyBaMM's asymmetric Butler-Volmer; the set's exchange currents kept, the positive symmetric: an "
                        "SEI-covered graphite surface), and 6 % less lithium (initial negative concentration x0.94, lithium lost to "
                        "SEI growth; the initial state set as 85 % SOC of the aged cell), at 21 degC (a theme park in late spring; "
                        "isothermal, not recorded). A theme park's electric road train per cell from 85 % SOC: 5 min rest, 14 "
                        "stations (road_train_loop_steps seed 4207: the pull-away with three laden carriages at 1.2-1.6C for 10-20 "
                        "s, the cruise along the park's paths at 0.4-0.6C for 60-150 s, regenerative braking into the station at "
                        "0.4-0.7C charge for 5-10 s, the dwell with the commentary and the lights at 0.03C for 60-120 s), 15 min "
                        "rest; 1.2 h, down to about 57 % (counted in the set's 5 A h); sampled every 2 s, 1 mV noise; SPM "
                        "(asymmetric Butler-Volmer) data handed to the plain SPM. spm_transfer_only_rmse_mV: the asymmetric SPM "
                        "with the set's lithium against the recording (what the lithium loss leaves); spm_inventory_only_rmse_mV: "
                        "the plain SPM with the lithium loss (what the asymmetry leaves)"},
               initial_soc=0.85, seed=4207, period=2, compare=lion.SPM())
    replay_rmse(root, name, asym(), train_cell(0.4, 1.0), steps, 0.85, "spm_transfer_only_rmse_mV", period=2)
    replay_rmse(root, name, lion.SPM(), train_cell(0.5, 0.94), steps, 0.85, "spm_inventory_only_rmse_mV", period=2)
    # aq8: pair, a 6 mOhm contact resistance and the current channel reading 2 % low, an orchard's electric picking platform,
    # 9 degC, 30 s, 2 mV, SPMe
    gain = 0.98
    def platform_cell(contact):
        q = at(chen(), 9)
        q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
        return q
    contact_model = lambda: lion.SPMe(options={"contact resistance": "true"})
    steps = ["Rest for 5 minutes"] + orchard_platform_steps(4208, 20) + ["Rest for 15 minutes"]
    seen = with_current_gain(steps, gain)
    name = "aq8_contact_6mOhm_and_current_gain_2pct_low_orchard_picking_platform_9C_30s_2mV_spme"
    write_case(root, name, contact_model(), platform_cell(0.006), steps,
               {"effect": "contact_resistance+current_measurement_gain", "candidate_model": "spme",
                "accept": ["|".join(contact_words), "|".join(gain_words)], "ambient_temperature_K": 282.15,
                "note": "two effects: a 6 mOhm contact resistance (a corroded busbar joint in the platform's battery tray: about "
                        "35 mV at 1.2C) and the platform's battery management reading the current 2 % low (gain 0.98, a shunt out "
                        "of calibration: the recorded current is the cell's times 0.98; not a cell property), at 9 degC (an apple "
                        "orchard on an autumn morning; isothermal, not recorded). An orchard's self-propelled electric picking "
                        "platform per cell from 90 % SOC: 5 min rest, 20 stretches of the row (orchard_platform_steps seed 4208: "
                        "the drive along the row at 0.3-0.5C for 60-180 s, the platform raised by its hydraulic pump at 1.0-1.4C "
                        "for 10-20 s, the pickers at work with the lights and the bin conveyor at 0.02-0.05C for 2-4 min, the "
                        "platform lowered at 0.1C for 10 s), 15 min rest; 2.1 h, down to about 50 % (the cell's own current, "
                        "counted in the set's 5 A h; the logger counts 2 % less); sampled every 30 s, 2 mV noise; SPMe (with "
                        "contact resistance) data handed to the plain SPMe. spme_contact_only_rmse_mV: the SPMe with the contact "
                        "resistance on the recorded current's protocol against the recording (what the gain leaves); "
                        "spme_gain_only_rmse_mV: the plain SPMe carrying the cell's own current (what the contact leaves)"},
               initial_soc=0.9, seed=4208, period=30, noise=2e-3, compare=lion.SPMe(), current_gain=gain, compare_steps=seen)
    replay_rmse(root, name, contact_model(), platform_cell(0.006), seen, 0.9, "spme_contact_only_rmse_mV", period=30)
    replay_rmse(root, name, lion.SPMe(), platform_cell(0.0), steps, 0.9, "spme_gain_only_rmse_mV", period=30)


def shunting_loco_moves_steps(seed, moves):
    """A battery-electric shunting locomotive marshalling wagons in a rail yard per cell (discharge
    positive), for each of `moves` moves: the start pulling a rake of wagons (1.4-2.0C for 15-30 s),
    the haul along the yard's tracks (0.5-0.8C for 40-120 s), braking with regeneration (0.4-0.8C
    charge for 8-15 s) and the wait while wagons are coupled, brake pipes connected and the points
    set (the air compressor and the cab, 0.02-0.04C for 60-240 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(moves):
        steps += [f"Discharge at {rng.uniform(1.4, 2.0):.2f}C for {int(rng.integers(15, 31))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(40, 121))} seconds",
                  f"Charge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(8, 16))} seconds",
                  f"Discharge at {rng.uniform(0.02, 0.04):.3f}C for {int(rng.integers(60, 241))} seconds"]
    return steps


def taxi_fares_steps(seed, fares):
    """An electric taxi's fares on a winter night per cell (discharge positive), for each of `fares`
    fares: 3-6 stretches of town driving to and with the passenger, each a pull-away (1.0-1.6C for 6-12
    s), the cruise (0.4-0.8C for 20-70 s), regenerative braking (0.3-0.6C charge for 4-8 s) and a
    wait at lights with the cabin heater (0.06-0.1C for 10-40 s); then the wait at a rank for the next
    fare with the heater on (0.06-0.1C for 3-10 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(fares):
        for _ in range(int(rng.integers(3, 7))):
            steps += [f"Discharge at {rng.uniform(1.0, 1.6):.2f}C for {int(rng.integers(6, 13))} seconds",
                      f"Discharge at {rng.uniform(0.4, 0.8):.2f}C for {int(rng.integers(20, 71))} seconds",
                      f"Charge at {rng.uniform(0.3, 0.6):.2f}C for {int(rng.integers(4, 9))} seconds",
                      f"Discharge at {rng.uniform(0.06, 0.1):.3f}C for {int(rng.integers(10, 41))} seconds"]
        steps.append(f"Discharge at {rng.uniform(0.06, 0.1):.3f}C for {60 * int(rng.integers(3, 11))} seconds")
    return steps


def site_hub_day_steps(seed, blocks, charge_after):
    """A construction site's battery power hub (replacing a diesel generator for the welfare cabin and
    the tools) per cell (discharge positive), `blocks` blocks of the working day, each: the cabin's
    lights, fridge and tool chargers (0.06-0.12C for 15-35 min), in 60 % of blocks a heater cycling on
    (0.25-0.35C for 6-15 min), in 40 % a kettle and a microwave at a break (0.6-0.9C for 2-4 min) or a
    site saw or a breaker run from the hub (1.0-1.4C for 1-3 min); after `charge_after` blocks the hub
    topped up from a solar trailer at midday (0.25-0.3C charge for 60-80 min). Every step in seconds
    (with_leak's form)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(blocks):
        if k == charge_after:
            steps.append(f"Charge at {rng.uniform(0.25, 0.3):.3f}C for {60 * int(rng.integers(60, 81))} seconds")
        steps.append(f"Discharge at {rng.uniform(0.06, 0.12):.3f}C for {60 * int(rng.integers(15, 36))} seconds")
        if rng.uniform() < 0.6:
            steps.append(f"Discharge at {rng.uniform(0.25, 0.35):.3f}C for {60 * int(rng.integers(6, 16))} seconds")
        u = rng.uniform()
        if u < 0.4:
            steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(120, 241))} seconds")
        elif u < 0.7:
            steps.append(f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(60, 181))} seconds")
    return steps


def rov_inspection_dive_steps(seed, welds):
    """An electric work-class underwater ROV inspecting a jacket's welds per cell (discharge positive):
    the descent with the thrusters (0.8-1.2C for 60-120 s), then for each of `welds` welds the transit
    to it (0.6-1.0C for 20-60 s), station-keeping in the current with the lights and the cameras on:
    3-6 thruster corrections (1.5-2.5C for 3-8 s) between quiet holds (0.15-0.25C for 10-30 s), then
    sitting on the member while the probe reads the weld (lights and the electronics only, 0.04-0.06C
    for 2-5 min); last the ascent (0.8-1.2C for 60-120 s)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(60, 121))} seconds"]
    for _ in range(welds):
        steps.append(f"Discharge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(20, 61))} seconds")
        for _ in range(int(rng.integers(3, 7))):
            steps += [f"Discharge at {rng.uniform(1.5, 2.5):.2f}C for {int(rng.integers(3, 9))} seconds",
                      f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {int(rng.integers(10, 31))} seconds"]
        steps.append(f"Discharge at {rng.uniform(0.04, 0.06):.3f}C for {60 * int(rng.integers(2, 6))} seconds")
    steps.append(f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(60, 121))} seconds")
    return steps


def polar_camp_day_steps(seed, hours):
    """A polar research field camp's battery bank per cell (discharge positive) for `hours` hours: each
    hour the instruments, the radio and the tents' lights (0.03-0.05C), a satellite uplink of the
    data (0.5-0.8C for 30-90 s), in 50 % of hours the melt-water heater (0.25-0.4C for 5-15 min), and in
    35 % of hours a gusty spell in which the wind turbine charges the bank (0.1-0.3C charge for 10-25
    min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(hours):
        left = 3600
        uplink = int(rng.integers(30, 91))
        steps.append(f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {uplink} seconds")
        left -= uplink
        if rng.uniform() < 0.5:
            heater = 60 * int(rng.integers(5, 16))
            steps.append(f"Discharge at {rng.uniform(0.25, 0.4):.3f}C for {heater} seconds")
            left -= heater
        if rng.uniform() < 0.35:
            gust = 60 * int(rng.integers(10, 26))
            steps.append(f"Charge at {rng.uniform(0.1, 0.3):.3f}C for {gust} seconds")
            left -= gust
        steps.append(f"Discharge at {rng.uniform(0.03, 0.05):.3f}C for {left} seconds")
    return steps


def airport_shuttle_loops_steps(seed, loops):
    """An electric airport shuttle minibus between the terminal and the long-stay car parks per cell
    (discharge positive), for each of `loops` loops: 4-6 stops, each the pull-away laden with
    passengers and luggage (1.3-1.8C for 8-14 s), the drive along the airport's roads (0.5-0.9C for
    30-90 s), regenerative braking into the stop (0.5-0.9C charge for 5-9 s) and the doors open with the
    air conditioning running (0.12-0.2C for 30-90 s); then the layover at the terminal (0.1C for 3-6
    min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(loops):
        for _ in range(int(rng.integers(4, 7))):
            steps += [f"Discharge at {rng.uniform(1.3, 1.8):.2f}C for {int(rng.integers(8, 15))} seconds",
                      f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(30, 91))} seconds",
                      f"Charge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(5, 10))} seconds",
                      f"Discharge at {rng.uniform(0.12, 0.2):.3f}C for {int(rng.integers(30, 91))} seconds"]
        steps.append(f"Discharge at 0.1C for {60 * int(rng.integers(3, 7))} seconds")
    return steps


def waterski_tow_steps(seed, pulls):
    """An electric water-ski tow boat's session on a lake per cell (discharge positive), for each of
    `pulls` pulls: the skier pulled out of the water (2.4-3.0C for 4-8 s), the run along the course at
    speed (1.2-1.6C for 40-100 s), in 40 % of pulls a second, longer run after the turn at the end of
    the lake (1.1-1.5C for 40-80 s), then the skier down and the boat idling back to pick them up
    (0.2-0.35C for 30-60 s) and waiting while they get ready (0.02C for 30-120 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(pulls):
        steps += [f"Discharge at {rng.uniform(2.4, 3.0):.2f}C for {int(rng.integers(4, 9))} seconds",
                  f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(40, 101))} seconds"]
        if rng.uniform() < 0.4:
            steps += [f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(10, 21))} seconds",
                      f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(40, 81))} seconds"]
        steps += [f"Discharge at {rng.uniform(0.2, 0.35):.3f}C for {int(rng.integers(30, 61))} seconds",
                  f"Discharge at 0.02C for {int(rng.integers(30, 121))} seconds"]
    return steps


def market_stall_evening_steps(seed, slots):
    """A winter Christmas market stall's mobile battery unit per cell (discharge positive), for each of
    `slots` 20-minute slots of the evening: the stall's lights and the till (0.12-0.18C), the mulled-wine
    urns' heaters cycling on (0.5-0.8C for 3-8 min) and, in 40 % of slots, the waffle iron (0.9-1.2C for
    2-4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(slots):
        left = 1200
        urn = 60 * int(rng.integers(3, 9))
        steps.append(f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {urn} seconds")
        left -= urn
        if rng.uniform() < 0.4:
            waffle = 60 * int(rng.integers(2, 5))
            steps.append(f"Discharge at {rng.uniform(0.9, 1.2):.2f}C for {waffle} seconds")
            left -= waffle
        steps.append(f"Discharge at {rng.uniform(0.12, 0.18):.3f}C for {left} seconds")
    return steps


def batch_ar(root):
    """Forty-third batch (key "ar"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -12, -2, 4, 10, 16, 23, 30 and 36 degC, each of the three
    models (data and candidate the same model in every case), sampling from 1 to 30 s, noise from 0.5 to
    2 mV, and duties no earlier batch used: a battery-electric shunting locomotive marshalling wagons in
    a rail yard, an electric taxi's winter night with a rapid top-up at a DC charger, a construction
    site's battery power hub through a working day, an electric work-class ROV inspecting a jacket's
    welds, a polar field camp's battery bank through a day, an electric airport shuttle's log started as
    it left the depot charger, an electric water-ski tow boat's session on a lake, and a Christmas market
    stall's mobile battery unit through a winter evening. An SPM control; five single effects chosen
    among the rarely concealed ones (partially reversible lithium plating in a cold rapid charge; the
    current channel's zero offset, 25 mA, never concealed alone; a particle-size distribution in both
    electrodes; the OCPs' entropic change missing from the set at -12 degC; a recording started right
    after an unrecorded charge, the cell not relaxed) and two pairs no earlier batch concealed together
    (a cracked positive: 6 % positive active-material loss with its electronic conductivity x0.25; a
    graphite + silicon composite negative with 7 % lithium loss). Words as in batches ah-aq; the
    plating by "plating", as ad5; the current offset by the current-channel, offset and leak words, as
    c6; the size distribution by the distribution words only, as ab8; the entropic term by the entropic
    and OCP words, as ad8; the unrelaxed start by bb6's words; the electrode conductivity by the
    contact / series-resistance or conductivity words, as ai3; the composite by the silicon / composite
    / OCP words, as ae8. Each effect's size on its own (the nominal candidate, or a replay, against the
    noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the replay keys); every
    step is time-limited (no voltage cut-off reached), so the experiment-aligned comparison needs no
    replay on the recorded current."""
    at = at_temperature
    lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
    conductivity_words = ["contact", "series resistance", "ohmic", "electronic conductivity", "electrode conductivity",
                          "solid-phase conductivity", "solid conductivity"]
    composite_words = ["silicon", "composite", "blend", "second phase", "two-phase", "two phase", "open-circuit potential",
                       "open circuit potential", "OCP"]
    # ar1: control, a battery-electric shunting locomotive in a rail yard, 36 degC, 5 s, 1 mV, SPM
    p = at(chen(), 36)
    steps = ["Rest for 10 minutes"] + shunting_loco_moves_steps(4301, 22) + ["Rest for 20 minutes"]
    write_case(root, "ar1_control_shunting_locomotive_rail_yard_36C_5s_spm", lion.SPM(), p, steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 309.15,
                "note": "negative control at 36 degC (a rail yard's sidings on a hot summer afternoon, the battery in the "
                        "locomotive's hood; isothermal, not recorded): SPM data and model, nothing concealed. A battery-electric "
                        "shunting locomotive marshalling wagons per cell from 90 % SOC: 10 min rest, 22 moves "
                        "(shunting_loco_moves_steps seed 4301: the start pulling a rake of wagons at 1.4-2.0C for 15-30 s, the "
                        "haul along the yard's tracks at 0.5-0.8C for 40-120 s, braking with regeneration at 0.4-0.8C charge for "
                        "8-15 s, the wait while wagons are coupled and the points set, the air compressor and the cab at "
                        "0.02-0.04C for 60-240 s), 20 min rest; 2.0 h, down to about 36 % (counted in the set's 5 A h); sampled "
                        "every 5 s, 1 mV noise; SPM data and model"},
               initial_soc=0.9, seed=4301, period=5, compare=lion.SPM())
    # ar2: partially reversible lithium plating in a cold rapid top-up, an electric taxi's winter night, -2 degC, 10 s, 1.5 mV, DFN
    p = at(with_okane2022(chen(), PLATING_KEYS), -2)
    rapid = ["Charge at 2.2C for 300 seconds", "Charge at 1.7C for 300 seconds", "Charge at 1.2C for 300 seconds",
             "Charge at 0.8C for 300 seconds"]
    steps = (["Rest for 5 minutes"] + taxi_fares_steps(4302, 4) + rapid + ["Rest for 3 minutes"] + taxi_fares_steps(43020, 4)
             + ["Rest for 20 minutes"])
    write_case(root, "ar2_plating_partially_reversible_taxi_cold_rapid_charge_minus2C_10s_1p5mV_dfn",
               lion.DFN(options={"lithium plating": "partially reversible"}), p, steps,
               {"effect": "lithium_plating", "candidate_model": "dfn", "accept": ["plating"], "ambient_temperature_K": 271.15,
                "note": "partially reversible lithium plating (PyBaMM 'partially reversible', OKane2022's plating parameters as "
                        "they are: rate constant 1e-9 m/s, transfer coefficient 0.65, dead-lithium decay constant 1e-6 1/s) in a "
                        "cold rapid top-up at -2 degC (a taxi rank's DC charger on a frosty winter night, the pack not "
                        "preconditioned; isothermal, not recorded): the step-down rapid charge plates up to 0.13 A h (0.0049 mol), most of "
                        "it stripped again in the minutes after (the stripping plateau) and in the fares that follow, 0.0007 A h "
                        "left at the end. An electric taxi's night per cell from 35 % SOC: 5 min rest, 4 fares "
                        "(taxi_fares_steps seed 4302: 3-6 stretches of town driving each, a pull-away at 1.0-1.6C for 6-12 s, "
                        "the cruise at 0.4-0.8C for 20-70 s, regenerative braking at 0.3-0.6C charge for 4-8 s, a wait at "
                        "lights with the cabin heater at 0.06-0.1C for 10-40 s; then the rank with the heater on at 0.06-0.1C "
                        "for 3-10 min), the rapid top-up stepping down as the charger's table for a cold pack does (2.2C, 1.7C, "
                        "1.2C, 0.8C, 5 min each, time-limited, up to 4.20 V at most), 3 min rest (unplugging), 4 fares more "
                        "(seed 43020), 20 min rest; 2.5 h, down to about 16 %, up to about 65 %, down to about 42 % (counted in "
                        "the set's 5 A h); sampled every 10 s (the taxi's telematics), 1.5 mV noise; DFN data and model. "
                        "effect_rmse_mV is what the plating alone does"},
               initial_soc=0.35, seed=4302, period=10, noise=1.5e-3, compare=lion.DFN())
    # ar3: the current channel's zero offset, 25 mA (reads that much more discharge than flows), a construction site's battery
    # power hub, 16 degC, 20 s, 0.8 mV, SPMe
    off = 0.025
    duty = ["Rest for 600 seconds"] + site_hub_day_steps(4303, 10, 5) + ["Rest for 1800 seconds"]
    true, seen = with_leak(duty, 0.0), with_leak(duty, off)
    write_case(root, "ar3_current_offset_25mA_construction_site_battery_hub_16C_20s_0p8mV_spme", lion.SPMe(), at(chen(), 16), true,
               {"effect": "current_offset", "candidate_model": "spme",
                "accept": ["current offset", "current bias", "current sensor", "current channel", "current measurement", "current zero",
                           "zero offset", "leak", "self-discharge", "self discharge"],
                "ambient_temperature_K": 289.15,
                "note": "the hub's battery management reads the current 25 mA high (a Hall-effect sensor's zero offset, 0.5 % of "
                        "1C: the recorded current is the cell's plus 25 mA of discharge, at rest too, where it records 25 mA "
                        "while none flows); not a cell property, the cell itself is nominal. Over the day the logger counts "
                        "0.17 A h (3.4 %) more charge out than the cell gave. A current offset is a leak of the opposite sign "
                        "(the cell carries the recorded current less 25 mA), so the leak words are accepted beside the "
                        "current-channel words, as c6. At 16 degC (a building site in spring; isothermal, not recorded). A "
                        "construction site's battery power hub (replacing the diesel generator for the welfare cabin and the "
                        "tools) per cell from 85 % SOC: 10 min rest, 10 blocks of the working day (site_hub_day_steps seed 4303: "
                        "the cabin's lights, fridge and tool chargers at 0.06-0.12C for 15-35 min, in 60 % of blocks a heater "
                        "cycling on at 0.25-0.35C for 6-15 min, in 40 % a kettle and a microwave at a break at 0.6-0.9C for 2-4 "
                        "min or in 30 % a site saw or a breaker at 1.0-1.4C for 1-3 min; after 5 blocks a midday top-up from a "
                        "solar trailer at 0.25-0.3C charge for 60-80 min), 30 min rest; 6.9 h, down to about 30 % (the cell's "
                        "own current, counted in the set's 5 A h; the logger counts about 26 %); sampled every 20 s, 0.8 mV "
                        "noise; SPMe data and model. effect_rmse_mV is what the offset alone does (the candidate on the "
                        "recorded current's protocol against the noise-free voltage)"},
               initial_soc=0.85, seed=4303, period=20, noise=8e-4, compare=lion.SPMe(), leak_A=-off, compare_steps=seen)
    # ar4: a particle-size distribution in both electrodes, an electric work-class ROV inspecting welds, 10 degC, 1 s, 0.5 mV,
    # MPM data handed to the SPM
    p = at(pybamm.get_size_distribution_parameters(chen(), sd_n=0.45, sd_p=0.3), 10)
    steps = ["Rest for 10 minutes"] + rov_inspection_dive_steps(4304, 9) + ["Rest for 20 minutes"]
    write_case(root, "ar4_particle_size_distribution_rov_weld_inspection_10C_1s_0p5mV_spm",
               lion.SPM(options={"particle size": "distribution"}), p, steps,
               {"effect": "particle_size_distribution", "candidate_model": "spm",
                "accept": ["size distribution", "particle-size distribution", "polydisperse", "distribution of particle",
                           "distribution of radii", "radius distribution", "radii distribution"],
                "ambient_temperature_K": 283.15,
                "note": "the particles of each electrode have a lognormal distribution of radii (pybamm.get_size_distribution_"
                        "parameters, relative standard deviation 0.45 in the graphite, a milled and unclassified powder, and 0.3 "
                        "in the NMC, the area-weighted means at the set's radii, radii from 0 to 1 + 5 sd times the mean; "
                        "PyBaMM's SPM with 'particle size': 'distribution', the many-particle model), where the candidate SPM "
                        "has one particle size: small particles fill and empty fast, large ones slowly, so the relaxation after "
                        "a burst is stretched. A particle diffusivity (or a single radius) refit is its nearest stand-in and is "
                        "not accepted; only words naming a distribution of particle sizes are, as ab8. At 10 degC (the North "
                        "Sea at depth; isothermal, not recorded). An electric work-class ROV inspecting a jacket's welds per "
                        "cell from 90 % SOC: 10 min rest on deck, the dive (rov_inspection_dive_steps seed 4304: the descent "
                        "at 0.8-1.2C for 60-120 s, 9 welds, each the transit to it at 0.6-1.0C for 20-60 s, station-keeping in "
                        "the current with 3-6 thruster corrections at 1.5-2.5C for 3-8 s between quiet holds at 0.15-0.25C for "
                        "10-30 s, then sitting on the member while the probe reads the weld at 0.04-0.06C for 2-5 min; the "
                        "ascent at 0.8-1.2C for 60-120 s), 20 min rest; 1.4 h, down to about 61 % (counted in the set's 5 A h); "
                        "sampled every 1 s, 0.5 mV noise; MPM data handed to the SPM. effect_rmse_mV is what the distribution "
                        "alone does"},
               initial_soc=0.9, seed=4304, period=1, noise=5e-4, compare=lion.SPM())
    # ar5: the OCPs' entropic change (O'Regan 2022, same LG M50 cell) missing from the set, a polar field camp's battery bank,
    # -12 degC, 30 s, 0.5 mV, SPMe
    o = pybamm.ParameterValues("ORegan2022")
    p = at(chen(), -12)
    for side in ["Negative", "Positive"]:
        p.update({f"{side} electrode OCP entropic change [V.K-1]": o[f"{side} electrode OCP entropic change [V.K-1]"]})
    steps = ["Rest for 10 minutes"] + polar_camp_day_steps(4305, 11) + ["Rest for 30 minutes"]
    write_case(root, "ar5_entropic_ocp_term_polar_field_camp_minus12C_30s_0p5mV_spme", lion.SPMe(), p, steps,
               {"effect": "ocp_temperature_dependence", "candidate_model": "spme",
                "accept": ["entropic", "entropy", "dU/dT", "OCP", "open-circuit potential", "open circuit potential",
                           "equilibrium potential", "temperature coefficient"],
                "ambient_temperature_K": 261.15,
                "note": "outside the tool's listed candidates: the electrodes' OCPs depend on temperature through their entropic "
                        "change (O'Regan 2022's measured dU/dT of the same LG M50 cell, graphite and NMC 811, as in PyBaMM's "
                        "ORegan2022 set), which the Chen 2020 set leaves at zero, so at -12 degC (isothermal, not recorded; 37 K "
                        "below the OCPs' 25 degC reference) the cell's open-circuit voltage differs from the set's by an "
                        "SOC-dependent few mV, largest towards empty. Not a constant offset; a thermal (self-heating) verdict is "
                        "not accepted (the cell is isothermal at the stated ambient), only words naming the OCP or its "
                        "temperature dependence are, as ad8. A polar research field camp's battery bank per cell from 80 % SOC: "
                        "10 min rest, 11 hours (polar_camp_day_steps seed 4305: each hour the instruments, the radio and the "
                        "tents' lights at 0.03-0.05C, a satellite uplink of the data at 0.5-0.8C for 30-90 s, in 50 % of hours "
                        "the melt-water heater at 0.25-0.4C for 5-15 min, in 35 % a gusty spell in which the wind turbine "
                        "charges the bank at 0.1-0.3C for 10-25 min), 30 min rest; 11.7 h, down to about 8 % (counted in the "
                        "set's 5 A h); sampled every 30 s, 0.5 mV noise (a quiet channel); SPMe data and model. effect_rmse_mV is "
                        "what the entropic term alone does"},
               initial_soc=0.8, seed=4305, period=30, noise=5e-4, compare=lion.SPMe())
    # ar6: the log starts right after an unrecorded depot charge (the cell not relaxed), an electric airport shuttle, 23 degC,
    # 2 s, 1 mV, SPMe
    p = at(chen(), 23)
    steps = (["Charge at 0.6C for 30 minutes", "Discharge at 0.02C for 20 minutes"] + airport_shuttle_loops_steps(4306, 6)
             + ["Rest for 20 minutes"])
    name = "ar6_unrelaxed_start_airport_shuttle_log_after_depot_charge_23C_2s_spme"
    write_case(root, name, lion.SPMe(), p, steps,
               {"effect": "unrelaxed_start", "candidate_model": "spme",
                "accept": ["unrelaxed", "not relaxed", "recording condition", "history", "relaxing", "part-way", "partway",
                           "not at rest"],
                "ambient_temperature_K": 296.15,
                "note": "a recording condition, not a cell property: the shuttle's log starts when it is unplugged from the "
                        "depot charger, 1e-13 s after an unrecorded 0.6C charge of 30 min (50 -> 80 % SOC, up to 4.20 V) ended, "
                        "so the cell starts the recording with the charge's concentration gradients in its particles and "
                        "electrolyte, the voltage relaxing by tens of mV in the first minutes. The cell itself is nominal. "
                        "Recorded (an electric airport shuttle minibus between the terminal and the long-stay car parks, per "
                        "cell): 20 min waiting for the first flight with its systems on at 0.02C, 6 loops "
                        "(airport_shuttle_loops_steps seed 4306: 4-6 stops each, the pull-away laden with passengers and "
                        "luggage at 1.3-1.8C for 8-14 s, the drive at 0.5-0.9C for 30-90 s, regenerative braking at 0.5-0.9C "
                        "charge for 5-9 s, the doors open with the air conditioning at 0.12-0.2C for 30-90 s; the layover at "
                        "the terminal at 0.1C for 3-6 min), 20 min rest; 2.3 h, down to about 23 % (counted in the set's 5 "
                        "A h); at 23 degC (isothermal, not recorded); sampled every 2 s, 1 mV noise; SPMe data and model. "
                        "candidate_rmse_mV runs the same unrecorded charge (so it is only the noise); relaxed_start_rmse_mV is "
                        "the nominal SPMe started at rest, its initial SOC the best of 77-83 % in 0.25 % steps (79.25 %): what the "
                        "unrelaxed start does when the initial SOC is fitted"},
               initial_soc=0.5, seed=4306, period=2, compare=lion.SPMe(), skip_steps=1)
    best = None
    for soc in np.arange(0.77, 0.83001, 0.0025):
        replay_rmse(root, name, lion.SPMe(), p.copy(), steps[1:], float(soc), "relaxed_start_rmse_mV", period=2)
        with open(os.path.join(root, name, "truth.json")) as f:
            truth = json.load(f)
        best = truth["relaxed_start_rmse_mV"] if best is None else min(best, truth["relaxed_start_rmse_mV"])
    truth["relaxed_start_rmse_mV"] = best
    with open(os.path.join(root, name, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"  {name}: relaxed_start_rmse_mV (best) = {best} mV")
    # ar7: pair on the positive, as cracking gives: 6 % positive active-material loss and its electronic conductivity x0.25,
    # an electric water-ski tow boat's session, 30 degC, 3 s, 1.2 mV, DFN
    def boat_cell(lam, sigma):
        q = scaled(chen(), "Positive electrode active material volume fraction", lam)
        return at(scaled(q, "Positive electrode conductivity [S.m-1]", sigma), 30)
    steps = (["Rest for 5 minutes"] + waterski_tow_steps(4307, 7) + ["Rest for 20 minutes"] + waterski_tow_steps(43070, 7)
             + ["Rest for 20 minutes"])
    name = "ar7_lam_positive_6pct_and_positive_conductivity_x0p25_waterski_tow_boat_30C_3s_1p2mV_dfn"
    write_case(root, name, lion.DFN(), boat_cell(0.94, 0.25), steps,
               {"effect": "active_material_loss+electrode_conductivity", "candidate_model": "dfn",
                "accept": ["active material", "|".join(conductivity_words)], "ambient_temperature_K": 303.15,
                "note": "two effects on the positive electrode, as particle cracking in a cycled NMC 811 gives: 6 % loss of "
                        "positive active material (volume fraction 0.665 -> 0.625, the set's initial concentrations, so the "
                        "lithium of the lost material goes with it; the initial state set as 95 % SOC of the aged cell) and the "
                        "positive's electronic conductivity x0.25 (0.045 S/m instead of 0.18: the carbon-binder network "
                        "detached from the cracked particles), judged by the active-material words and, for the conductivity, by "
                        "the contact / series-resistance words or the conductivity's own name, as ai3. At 30 degC (a lake in "
                        "summer; isothermal, not recorded). An electric water-ski tow boat's session per cell from 95 % SOC: 5 "
                        "min rest, 7 pulls (waterski_tow_steps seed 4307: the skier pulled out of the water at 2.4-3.0C for 4-8 "
                        "s, the run along the course at 1.2-1.6C for 40-100 s, in 40 % of pulls the turn at the end of the lake "
                        "at 0.3-0.5C for 10-20 s and a second run at 1.1-1.5C for 40-80 s, the skier down and the boat idling "
                        "back at 0.2-0.35C for 30-60 s, waiting while they get ready at 0.02C for 30-120 s), 20 min rest while "
                        "the skiers swap, 7 pulls more (seed 43070), 20 min rest; 1.7 h, down to about 27 % (counted in the "
                        "set's 5 A h); sampled every 3 s, 1.2 mV noise; DFN data and model. dfn_lam_only_rmse_mV: the DFN with "
                        "the loss alone against the recording (what the conductivity leaves); dfn_conductivity_only_rmse_mV: "
                        "with the conductivity alone (what the loss leaves)"},
               initial_soc=0.95, seed=4307, period=3, noise=1.2e-3, compare=lion.DFN())
    replay_rmse(root, name, lion.DFN(), boat_cell(0.94, 1.0), steps, 0.95, "dfn_lam_only_rmse_mV", period=3)
    replay_rmse(root, name, lion.DFN(), boat_cell(1.0, 0.25), steps, 0.95, "dfn_conductivity_only_rmse_mV", period=3)
    # ar8: pair, a graphite + silicon composite negative (the LG M50's real SiOx-graphite anode) and 7 % lithium loss, a
    # Christmas market stall's mobile battery unit, 4 degC, 15 s, 2 mV, SPM
    def stall_cell(composite, lithium):
        if composite:
            q = with_silicon_composite(chen(), 0.66, 0.011)
            for phase in ["Primary", "Secondary"]:
                scaled(q, f"{phase}: Initial concentration in negative electrode [mol.m-3]", lithium)
        else:
            q = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", lithium)
        return at(q, 4)
    composite_model = lambda: lion.SPM(options={"particle phases": ("2", "1")})
    steps = ["Rest for 10 minutes"] + market_stall_evening_steps(4308, 7) + ["Rest for 30 minutes"]
    name = "ar8_silicon_composite_negative_and_inventory_7pct_christmas_market_stall_4C_15s_2mV_spm"
    write_case(root, name, composite_model(), stall_cell(True, 0.93), steps,
               {"effect": "composite_negative+lithium_inventory_loss", "candidate_model": "spm",
                "accept": ["|".join(composite_words), "|".join(lithium_words)], "ambient_temperature_K": 277.15,
                "note": "two effects: a composite negative electrode (the LG M50's real SiOx-graphite anode: graphite, the set's, "
                        "active fraction 0.66 instead of 0.75, with 1.1 % by volume of silicon, Chen2020_composite's secondary "
                        "phase: average OCP of Mark 2016, no hysteresis, 1.52 um particles, c_max 278000 mol/m3; PyBaMM's "
                        "'particle phases' ('2', '1')) handed to the graphite-only SPM, and 7 % less lithium (the initial "
                        "negative concentrations of both phases x0.93, lithium lost to SEI growth, which the silicon's swelling "
                        "speeds; the initial state set as 90 % SOC of the aged cell), at 4 degC (a town square on a December "
                        "evening; isothermal, not recorded). The composite judged by the silicon / composite / OCP words, as "
                        "ae8. A Christmas market stall's mobile battery unit per cell from 90 % SOC: 10 min rest, 7 slots of 20 "
                        "min (market_stall_evening_steps seed 4308: the mulled-wine urns' heaters at 0.5-0.8C for 3-8 min, in "
                        "40 % of slots the waffle iron at 0.9-1.2C for 2-4 min, the stall's lights and the till at 0.12-0.18C "
                        "for the rest of the slot), 30 min rest; 3.0 h, down to about 28 % (counted in the set's 5 A h); "
                        "sampled every 15 s, 2 mV noise; SPM (two-phase) data handed to the plain SPM. "
                        "spm_composite_only_rmse_mV: the two-phase SPM with the set's lithium against the recording (what the "
                        "lithium loss leaves); spm_inventory_only_rmse_mV: the plain SPM with the lithium loss (what the "
                        "composite leaves)"},
               initial_soc=0.9, seed=4308, period=15, noise=2e-3, compare=lion.SPM())
    replay_rmse(root, name, composite_model(), stall_cell(True, 1.0), steps, 0.9, "spm_composite_only_rmse_mV", period=15)
    replay_rmse(root, name, lion.SPM(), stall_cell(False, 0.93), steps, 0.9, "spm_inventory_only_rmse_mV", period=15)


def quadruped_patrol_current(seed, waypoints, capacity_A_h=5.0, dt=0.5):
    """A legged (quadruped) inspection robot's patrol of a chemical plant as a cell current at `dt` s
    knots (A, discharge positive; ramps between knots, no current step): it stands up from its dock
    (0.3C for 2 s), then for each of `waypoints` waypoints walks there (0.7-1.0C for 20-90 s, with a
    gait ripple of 0.08C from knot to knot), in 30 % of them climbing a steel staircase to a platform
    (1.8-2.4C for 8-20 s, ripple 0.15C), stands scanning the gauges with its camera and gas sensor
    (0.10-0.15C for 20-60 s), and in 25 % of them turns a valve handle with its arm (0.35-0.5C for 5-12
    s); last it lies down (0.02C for 30 s)."""
    rng = np.random.default_rng(seed)
    c = capacity_A_h
    n = lambda seconds: max(1, int(round(seconds / dt)))
    cur = [0.0]

    def ramp(to, seconds):
        start, k_n = cur[-1], n(seconds)
        cur.extend(start + (to - start) * (k + 1) / k_n for k in range(k_n))

    def hold(level, seconds, ripple=0.0):
        cur.extend(level + (rng.normal(0.0, ripple) if ripple else 0.0) for _ in range(n(seconds)))

    ramp(0.3 * c, 1.0)
    hold(0.3 * c, 2.0)
    for _ in range(waypoints):
        walk = rng.uniform(0.7, 1.0) * c
        ramp(walk, 1.0)
        hold(walk, rng.integers(20, 91), 0.08 * c)
        if rng.uniform() < 0.3:
            climb = rng.uniform(1.8, 2.4) * c
            ramp(climb, 1.0)
            hold(climb, rng.integers(8, 21), 0.15 * c)
        stand = rng.uniform(0.10, 0.15) * c
        ramp(stand, 1.0)
        hold(stand, rng.integers(20, 61), 0.01 * c)
        if rng.uniform() < 0.25:
            arm = rng.uniform(0.35, 0.5) * c
            ramp(arm, 0.5)
            hold(arm, rng.integers(5, 13))
            ramp(stand, 0.5)
    ramp(0.02 * c, 1.0)
    hold(0.02 * c, 30.0)
    ramp(0.0, 0.5)
    i = np.array(cur)
    return np.column_stack([dt * np.arange(len(i)), i])


def leo_orbit_steps(seed, orbits, charge_C=0.5):
    """A low-Earth-orbit satellite's battery in a ground life test (per cell, discharge positive), for
    each of `orbits` 95 min orbits: the eclipse on the battery (the bus with the heaters on, 0.32-0.40C
    for 33-36 min), then in sunlight, in 30 % of orbits a payload pass beyond what the arrays give
    (imaging or a downlink over a ground station, 0.25-0.45C for 4-8 min), the charge at `charge_C`
    that puts back what the eclipse and the pass took (time-limited, whole seconds), and the battery
    idle on the shunt regulator (no current) for the rest of the orbit."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(orbits):
        eclipse_C, eclipse_s = rng.uniform(0.32, 0.40), 60 * int(rng.integers(33, 37))
        steps.append(f"Discharge at {eclipse_C:.3f}C for {eclipse_s} seconds")
        taken = eclipse_C * eclipse_s
        used = eclipse_s
        if rng.uniform() < 0.3:
            pass_C, pass_s = rng.uniform(0.25, 0.45), 60 * int(rng.integers(4, 9))
            steps.append(f"Discharge at {pass_C:.3f}C for {pass_s} seconds")
            taken += pass_C * pass_s
            used += pass_s
        charge_s = int(round(taken / charge_C))
        steps.append(f"Charge at {charge_C}C for {charge_s} seconds")
        steps.append(f"Rest for {95 * 60 - used - charge_s} seconds")
    return steps


def harbour_tug_job_steps(seed, ships):
    """A battery-electric harbour tug's work per cell (discharge positive), for each of `ships` ships
    it helps to berth: the transit out to meet the ship (0.5-0.8C for 4-8 min), escorting it in at
    its speed (0.2-0.3C for 2-5 min), 3-5 pushes against its hull (1.6-2.3C for 40-110 s) with
    holding on the rope between them (0.15-0.3C for 30-90 s), the transit back (0.5-0.7C for 4-7 min)
    and waiting at the tug berth (the wheelhouse, 0.02C for 3-5 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(ships):
        steps += [f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {60 * int(rng.integers(4, 9))} seconds",
                  f"Discharge at {rng.uniform(0.2, 0.3):.3f}C for {60 * int(rng.integers(2, 6))} seconds"]
        for _ in range(int(rng.integers(3, 6))):
            steps += [f"Discharge at {rng.uniform(1.6, 2.3):.2f}C for {int(rng.integers(40, 111))} seconds",
                      f"Discharge at {rng.uniform(0.15, 0.3):.3f}C for {int(rng.integers(30, 91))} seconds"]
        steps += [f"Discharge at {rng.uniform(0.5, 0.7):.2f}C for {60 * int(rng.integers(4, 8))} seconds",
                  f"Discharge at 0.02C for {60 * int(rng.integers(3, 6))} seconds"]
    return steps


def mountain_hut_steps(seed, sun_blocks, evening_blocks):
    """An off-grid mountain hut's battery bank per cell (discharge positive) from the early afternoon
    into the evening: `sun_blocks` blocks of 6-12 min with the solar array charging through passing
    clouds (sun: 0.25-0.45C charge; cloud: 0.03-0.08C charge, or in 30 % of clouds the kitchen's
    dishwasher outrunning the array, 0.15-0.3C discharge), then `evening_blocks` blocks of 8-15 min of
    the evening on the battery: the lights, the fridge and the wardens' radio (0.05-0.08C) with, in
    60 % of blocks, the induction hob or the kettle for the guests' dinner (0.6-0.9C for 2-6 min) and,
    in 30 %, the water pump (0.35-0.45C for 1-2 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(sun_blocks):
        u = rng.uniform()
        seconds = 60 * int(rng.integers(6, 13))
        if u < 0.5:
            steps.append(f"Charge at {rng.uniform(0.25, 0.45):.3f}C for {seconds} seconds")
        elif u < 0.85:
            steps.append(f"Charge at {rng.uniform(0.03, 0.08):.3f}C for {seconds} seconds")
        else:
            steps.append(f"Discharge at {rng.uniform(0.15, 0.3):.3f}C for {seconds} seconds")
    for _ in range(evening_blocks):
        left = 60 * int(rng.integers(8, 16))
        if rng.uniform() < 0.6:
            hob = 60 * int(rng.integers(2, 7))
            steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {hob} seconds")
            left -= hob
        if rng.uniform() < 0.3:
            pump = 60 * int(rng.integers(1, 3))
            steps.append(f"Discharge at {rng.uniform(0.35, 0.45):.2f}C for {pump} seconds")
            left -= pump
        if left > 0:
            steps.append(f"Discharge at {rng.uniform(0.05, 0.08):.3f}C for {left} seconds")
    return steps


def pipeline_welder_steps(seed, joints):
    """A battery-powered welding power source on a pipeline spread per cell (discharge positive), for
    each of `joints` girth welds: the root pass in 3-5 arcs (1.3-1.7C for 40-100 s) with the welder
    idling between them while the bead is ground (0.03C for 15-40 s), the hot and fill passes in 2-3
    longer arcs (1.4-1.8C for 60-120 s, same pauses), then the crew moving the shelter to the next
    joint with the machine on standby (0.01C for 4-8 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(joints):
        for _ in range(int(rng.integers(3, 6))):
            steps += [f"Discharge at {rng.uniform(1.3, 1.7):.2f}C for {int(rng.integers(40, 101))} seconds",
                      f"Discharge at 0.03C for {int(rng.integers(15, 41))} seconds"]
        for _ in range(int(rng.integers(2, 4))):
            steps += [f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {int(rng.integers(60, 121))} seconds",
                      f"Discharge at 0.03C for {int(rng.integers(15, 41))} seconds"]
        steps.append(f"Discharge at 0.01C for {60 * int(rng.integers(4, 9))} seconds")
    return steps


def ambulance_shift_steps(seed, calls):
    """An electric ambulance's shift per cell (discharge positive), for each of `calls` calls after the
    first: the patient handed over in the hospital's bay with the compartment's air conditioning and the
    medical equipment on (0.08-0.12C for 10-20 min), the drive back to the station (4-7 stretches, each
    a pull-away at 1.1-1.5C for 6-12 s, town driving at 0.4-0.7C for 40-120 s and regenerative braking at
    0.3-0.6C charge for 4-8 s), standby at the station (0.03C for 10-25 min), then the next emergency run
    with the blue lights (6-10 stretches, each an acceleration at 1.4-1.9C for 8-15 s, driving at
    0.8-1.2C for 30-90 s and braking with regeneration at 0.5-0.8C charge for 4-8 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(calls):
        steps.append(f"Discharge at {rng.uniform(0.08, 0.12):.3f}C for {60 * int(rng.integers(10, 21))} seconds")
        for _ in range(int(rng.integers(4, 8))):
            steps += [f"Discharge at {rng.uniform(1.1, 1.5):.2f}C for {int(rng.integers(6, 13))} seconds",
                      f"Discharge at {rng.uniform(0.4, 0.7):.2f}C for {int(rng.integers(40, 121))} seconds",
                      f"Charge at {rng.uniform(0.3, 0.6):.2f}C for {int(rng.integers(4, 9))} seconds"]
        steps.append(f"Discharge at 0.03C for {60 * int(rng.integers(10, 26))} seconds")
        if k < calls - 1:
            for _ in range(int(rng.integers(6, 11))):
                steps += [f"Discharge at {rng.uniform(1.4, 1.9):.2f}C for {int(rng.integers(8, 16))} seconds",
                          f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(30, 91))} seconds",
                          f"Charge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(4, 9))} seconds"]
    return steps


def street_sweeper_route_steps(seed, streets):
    """An electric compact street sweeper's early-morning route per cell (discharge positive), for each
    of `streets` streets: sweeping along the kerb with the brushes and the suction fan (0.6-0.9C for
    3-6 min) with, in 50 % of streets, the fan boosted through a drift of leaves (1.1-1.4C for 20-40
    s); the transit to the next street (0.4-0.6C for 60-120 s); every fourth street the hopper emptied
    into a skip by its hydraulic lift (1.3-1.7C for 15-25 s) and the sweeper stopped while the driver
    refills the water tank (0.02C for 3-5 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(streets):
        sweep = 60 * int(rng.integers(3, 7))
        if rng.uniform() < 0.5:
            first = int(rng.integers(30, sweep - 60))
            boost = int(rng.integers(20, 41))
            level = rng.uniform(0.6, 0.9)
            steps += [f"Discharge at {level:.2f}C for {first} seconds",
                      f"Discharge at {rng.uniform(1.1, 1.4):.2f}C for {boost} seconds",
                      f"Discharge at {level:.2f}C for {sweep - first - boost} seconds"]
        else:
            steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {sweep} seconds")
        steps.append(f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(60, 121))} seconds")
        if k % 4 == 3:
            steps += [f"Discharge at {rng.uniform(1.3, 1.7):.2f}C for {int(rng.integers(15, 26))} seconds",
                      f"Discharge at 0.02C for {60 * int(rng.integers(3, 6))} seconds"]
    return steps


def jetski_rental_steps(seed, rides):
    """A rental electric personal watercraft's (jet ski's) afternoon per cell (discharge positive), for
    each of `rides` customers' rides: idling out through the harbour's no-wake zone (0.15-0.25C for 2-4
    min), 5-9 runs in the open bay, each a full-throttle sprint (2.0-2.7C for 15-45 s), cruising
    (0.8-1.2C for 30-80 s) and a turn (0.3-0.5C for 5-15 s), idling back in (0.15-0.25C for 2-4 min),
    and the craft tied at the dock while the next customer is briefed (no current, 5-10 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(rides):
        steps.append(f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {60 * int(rng.integers(2, 5))} seconds")
        for _ in range(int(rng.integers(5, 10))):
            steps += [f"Discharge at {rng.uniform(2.0, 2.7):.2f}C for {int(rng.integers(15, 46))} seconds",
                      f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(30, 81))} seconds",
                      f"Discharge at {rng.uniform(0.3, 0.5):.2f}C for {int(rng.integers(5, 16))} seconds"]
        steps += [f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {60 * int(rng.integers(2, 5))} seconds",
                  f"Rest for {60 * int(rng.integers(5, 11))} seconds"]
    return steps


# Accept words shared by batches as, at and au (one effect, one list, as the judge reads them).
composite_words = ["silicon", "composite", "blend", "second phase", "two-phase", "two phase", "open-circuit potential",
                   "open circuit potential", "OCP"]
contact_words = ["contact", "series resistance", "ohmic"]
delay_words = ["delay", "latency", "misalign", "synchron", "time shift", "time offset", "timestamp", "time stamp", "time lag",
               "time base", "time axis"]
gain_words = ["current sensor", "current measurement", "current channel", "current gain", "current scale", "calibration", "gain"]
kinetic_words = ["kinetic", "exchange", "charge-transfer", "charge transfer", "reaction rate"]
lithium_words = ["inventory", "lithium loss", "lithium lost", "cyclable"]
offset_words = ["current offset", "current bias", "current sensor", "current channel", "current measurement", "current zero",
                "zero offset", "leak", "self-discharge", "self discharge"]
particle_words = ["particle", "solid diffusiv", "solid-phase diffusiv"]
thermal_words = ["thermal", "self-heating", "heat"]
unrelaxed_words = ["unrelaxed", "not relaxed", "recording condition", "history", "relaxing", "part-way", "partway", "not at rest"]


def batch_as(root, only=None):
    """Forty-fourth batch (key "as"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -8, 0, 8, 15, 18, 26, 31 and 43 degC, each of the three models
    (the candidate the data's model without the concealed physics), sampling from 0.5 to 30 s, noise
    from 0.4 to 2 mV, and duties no earlier batch used: a legged (quadruped) inspection robot's patrol of a
    chemical plant (a programmed current at 0.5 s knots, sampled every 0.5 s), a low-Earth-orbit
    satellite battery's ground life test over 80 orbits (126.7 h), a battery-electric harbour tug with a
    rapid charge at the quay in winter, an off-grid mountain hut's battery bank through a winter
    afternoon and evening, a battery-powered welding power source on a desert pipeline, an electric
    ambulance's shift logged from the hospital bay, an electric street sweeper's early-morning route, and
    a rental electric jet ski's afternoon. An SPMe control; four single effects (SEI growth limited by
    lithium-interstitial diffusion over 80 orbits, a growth law concealed once before; one-state
    hysteresis of the negative OCP, +-15 mV, at -8 degC; the electrolyte's cation transference number
    0.38 instead of the set's 0.2594, never concealed before; the positive's exchange current x0.5 alone)
    and three pairs no earlier batch concealed together (8 % negative active-material loss with partially
    reversible lithium plating in a cold rapid charge; an unrelaxed start, the log begun right after an
    unrecorded run, with a 3 mOhm contact resistance; lumped self-heating, h = 12, temperature recorded,
    with the current channel's 50 mA zero offset). Words as in batches ah-ar; the SEI by "SEI" or the
    lithium words, as a1; the plating by "plating", as ar2; the transference number by "electrolyte" or
    its own name; the hysteresis by "hysteresis", as ap4; the unrelaxed start by ar6's words; the current
    offset by ar3's words. Each effect's size on its own (the nominal candidate, or a replay, against the
    noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the replay keys); every step
    is time-limited (no voltage cut-off reached: the charges stay below 4.2 V), so the experiment-aligned
    comparison needs no replay on the recorded current. `only` (a set of case keys, "as1" ...) makes
    only those cases."""
    at = at_temperature
    run = lambda case: only is None or case in only
    # as1: control, a legged inspection robot's patrol, 18 degC, 0.5 s, 0.6 mV, SPMe
    if run("as1"):
        p = at(chen(), 18)
        steps = ["Rest for 2 minutes", pybamm.step.current(quadruped_patrol_current(4401, 34)), "Rest for 15 minutes"]
        write_case(root, "as1_control_quadruped_inspection_robot_patrol_18C_0p5s_0p6mV_spme", lion.SPMe(), p, steps,
                   {"effect": "none", "candidate_model": "spme", "accept": ["no missing"], "ambient_temperature_K": 291.15,
                    "note": "negative control at 18 degC (a chemical plant's process hall; isothermal, not recorded): SPMe data "
                            "and model, nothing concealed. A legged (quadruped) inspection robot's patrol per cell from 95 % SOC: 2 "
                            "min rest on its dock, the patrol as a programmed current at 0.5 s knots with ramps, no current step "
                            "(quadruped_patrol_current seed 4401, 34 waypoints: standing up at 0.3C, walking at 0.7-1.0C for 20-90 s "
                            "with a gait ripple of 0.08C from knot to knot, in 30 % of waypoints a steel staircase at 1.8-2.4C for "
                            "8-20 s, standing to scan gauges at 0.10-0.15C for 20-60 s, in 25 % a valve turned by the arm at "
                            "0.35-0.5C for 5-12 s; lying down at 0.02C), 15 min rest; 1.2 h, down to about 39 % (counted in the "
                            "set's 5 A h); sampled every 0.5 s (the robot's own log), 0.6 mV noise; SPMe data and model"},
                   initial_soc=0.95, seed=4401, period=0.5, noise=6e-4, compare=lion.SPMe())
    # as2: SEI growth limited by lithium-interstitial diffusion (x8000) over 80 orbits, a LEO satellite battery's ground life
    # test, 15 degC, 30 s, 0.8 mV, SPMe
    if run("as2"):
        p = at(scaled(chen(), "SEI lithium interstitial diffusivity [m2.s-1]", 8000.0), 15)
        steps = leo_orbit_steps(4402, 80, charge_C=0.4)
        write_case(root, "as2_sei_interstitial_diffusion_x8000_80_leo_orbits_life_test_15C_30s_0p8mV_spme",
                   lion.SPMe(options={"SEI": "interstitial-diffusion limited"}), p, steps,
                   {"effect": "sei_growth", "candidate_model": "spme", "accept": ["SEI"] + lithium_words, "ambient_temperature_K": 288.15,
                    "note": "SEI growth limited by the diffusion of lithium interstitials through the film (PyBaMM "
                            "'interstitial-diffusion limited', distributed film resistance; SEI lithium interstitial diffusivity "
                            "x8000, 8e-17 m2/s instead of Chen 2020's 1e-20: a cell from a lot whose formation left a poorly "
                            "passivating SEI; the film's other parameters Chen 2020's): 0.0038 mol of lithium (0.103 A h, 2.1 % of the "
                            "set's 5 A h) lost to the SEI over the 80 orbits, fastest at first (parabolic growth: 0.031 A h after 10 "
                            "orbits, 0.046 after 20, 0.070 after 40). A lithium-inventory loss growing through the recording is "
                            "the SEI's nearest stand-in and is accepted. A low-Earth-orbit satellite's battery in a ground life "
                            "test in a thermal chamber at 15 degC (isothermal, not recorded), per cell from 75 % SOC, 80 orbits of "
                            "95 min with no rest before (leo_orbit_steps seed 4402: the eclipse on the battery at 0.32-0.40C for "
                            "33-36 min, in 30 % of orbits a payload pass in sunlight at 0.25-0.45C for 4-8 min, the charge at 0.4C "
                            "for as long as puts back what the eclipse and the pass took, time-limited, then idle on the shunt "
                            "regulator, no current, for the rest of the orbit), the state of charge swinging between about 75 and "
                            "47-54 % (counted in the set's 5 A h; the SEI takes its lithium out of that); 126.7 h; sampled every 30 s "
                            "(the test rig's housekeeping rate), 0.8 mV noise; the charges end at 4.14 V at most; SPMe (with SEI) data "
                            "handed to the plain SPMe. "
                            "effect_rmse_mV is what the SEI (its lithium loss and its film) does"},
                   initial_soc=0.75, seed=4402, period=30, noise=8e-4, compare=lion.SPMe())
    # as3: pair, 8 % negative active-material loss and partially reversible lithium plating in a cold rapid charge, a harbour
    # tug, 0 degC, 5 s, 1.2 mV, DFN
    if run("as3"):
        def tug_cell(lam):
            q = with_okane2022(scaled(chen(), "Negative electrode active material volume fraction", lam), PLATING_KEYS)
            return at(q, 0)
        plating_model = lambda: lion.DFN(options={"lithium plating": "partially reversible"})
        rapid = ["Charge at 2C for 360 seconds", "Charge at 1.5C for 300 seconds", "Charge at 0.8C for 300 seconds"]
        steps = (["Rest for 5 minutes"] + harbour_tug_job_steps(4403, 2) + ["Rest for 3 minutes"] + rapid + ["Rest for 3 minutes"]
                 + harbour_tug_job_steps(44030, 1) + ["Rest for 20 minutes"])
        name = "as3_lam_negative_8pct_and_plating_harbour_tug_cold_rapid_charge_0C_5s_1p2mV_dfn"
        write_case(root, name, plating_model(), tug_cell(0.92), steps,
                   {"effect": "active_material_loss+lithium_plating", "candidate_model": "dfn", "accept": ["active material", "plating"],
                    "ambient_temperature_K": 273.15,
                    "note": "two effects, as an aged graphite gives: 8 % loss of negative active material (volume fraction 0.75 -> "
                            "0.69, the set's initial concentrations, so the lithium of the lost material goes with it; the initial "
                            "state set as 80 % SOC of the aged cell) and partially reversible lithium plating (PyBaMM 'partially "
                            "reversible', OKane2022's plating parameters as they are: rate constant 1e-9 m/s, transfer coefficient "
                            "0.65, dead-lithium decay constant 1e-6 1/s) in a cold rapid charge at 0 degC (a harbour in winter, the "
                            "pack not preconditioned; isothermal, not recorded), the lost graphite making the rest plate sooner: "
                            "the rapid charge plates up to 0.0028 mol (0.075 A h), "
                            "nearly all of it stripped again in the rest and the work after it (3e-6 mol left at the end). A "
                            "battery-electric harbour tug per cell from 80 % SOC: 5 min rest, 2 ships berthed "
                            "(harbour_tug_job_steps seed 4403: the transit out at 0.5-0.8C for 4-8 min, escorting the ship in at "
                            "0.2-0.3C for 2-5 min, 3-5 pushes against its hull at 1.6-2.3C for 40-110 s with holding on the rope at "
                            "0.15-0.3C for 30-90 s between them, the transit back at 0.5-0.7C for 4-7 min, waiting at the berth at "
                            "0.02C for 3-5 min), 3 min rest (plugging in), the shore charger's rapid charge stepping down (2C for 6 "
                            "min, 1.5C for 5 min, 0.8C for 5 min, time-limited, up to 4.19 V at most), 3 min rest, 1 ship more "
                            "(seed 44030), 20 min rest; 2.2 h, down to about 16 %, up to about 56 %, down to about 25 % (counted "
                            "in the set's 5 A h); sampled every 5 s, 1.2 mV noise; DFN data and model. dfn_lam_only_rmse_mV: the DFN with "
                            "the loss alone against the recording (what the plating leaves); dfn_plating_only_rmse_mV: the plating "
                            "DFN with the set's graphite (what the loss leaves)"},
                   initial_soc=0.8, seed=4403, period=5, noise=1.2e-3, compare=lion.DFN())
        replay_rmse(root, name, lion.DFN(), tug_cell(0.92), steps, 0.8, "dfn_lam_only_rmse_mV", period=5)
        replay_rmse(root, name, plating_model(), tug_cell(1.0), steps, 0.8, "dfn_plating_only_rmse_mV", period=5)
    # as4: one-state hysteresis of the negative OCP, +-15 mV, an off-grid mountain hut's battery bank, -8 degC, 20 s, 1.2 mV, SPM
    if run("as4"):
        p = at(chen(), -8)
        with_negative_hysteresis(p, 0.015)
        steps = ["Rest for 10 minutes"] + mountain_hut_steps(4404, 9, 7) + ["Rest for 20 minutes"]
        write_case(root, "as4_hysteresis_negative_15mV_off_grid_mountain_hut_minus8C_20s_1p2mV_spm",
                   lion.SPM(options={"open-circuit potential": ("one-state hysteresis", "single")}), p, steps,
                   {"effect": "hysteresis", "candidate_model": "spm", "accept": ["hysteresis"], "ambient_temperature_K": 265.15,
                    "note": "one-state OCV hysteresis of the negative electrode, lithiation and delithiation OCPs 15 mV "
                            "either side of the set's (decay rate 10, initial state 0, the middle; the SiOx in the LG M50's "
                            "graphite), the positive without, at -8 degC (the hut's unheated battery room in winter; isothermal, "
                            "not recorded). An off-grid mountain hut's battery bank per cell from 55 % SOC: 10 min rest, the "
                            "afternoon in 9 blocks of 6-12 min (mountain_hut_steps seed 4404: the solar array charging through "
                            "passing clouds, sun at 0.25-0.45C charge, cloud at 0.03-0.08C charge or, in 30 % of clouds, the "
                            "kitchen's dishwasher outrunning the array at 0.15-0.3C discharge), then the evening in 7 blocks of "
                            "8-15 min (the lights, the fridge and the wardens' radio at 0.05-0.08C, in 60 % of blocks the "
                            "induction hob or the kettle for the guests' dinner at 0.6-0.9C for 2-6 min, in 30 % the water pump at "
                            "0.35-0.45C for 1-2 min), 20 min rest; 3.05 h, up to about 69 % in the afternoon and down to "
                            "about 47 % in the evening (counted in the set's 5 A h); sampled every 20 s (the charge controller's "
                            "log), 1.2 mV noise; SPM (one-state hysteresis) data handed to the plain SPM. effect_rmse_mV is what "
                            "the hysteresis alone does"},
                   initial_soc=0.55, seed=4404, period=20, noise=1.2e-3, compare=lion.SPM())
    # as5: cation transference number 0.38 instead of 0.2594 (another electrolyte), a pipeline welding power source, 43 degC,
    # 2 s, 0.4 mV, DFN
    if run("as5"):
        p = at(chen(), 43)
        p.update({"Cation transference number": 0.38})
        steps = ["Rest for 5 minutes"] + pipeline_welder_steps(4405, 3) + ["Rest for 20 minutes"]
        write_case(root, "as5_electrolyte_transference_number_0p38_pipeline_welder_43C_2s_0p4mV_dfn", lion.DFN(), p, steps,
                   {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte", "transference"],
                    "ambient_temperature_K": 316.15,
                    "note": "the electrolyte's cation transference number 0.38 instead of the set's 0.2594 (the cell filled "
                            "with a second-source electrolyte), so the salt's concentration gradients under load, and their "
                            "relaxation after it, differ from the set's; the electrolyte's conductivity and diffusivity are the "
                            "set's. Judged by the electrolyte words (or 'transference'). At 43 degC (a pipeline spread in a desert "
                            "in summer, the machine in the sun; isothermal, not recorded). A battery-powered welding power source "
                            "per cell from 95 % SOC: 5 min rest, 3 girth welds (pipeline_welder_steps seed 4405: the root pass in "
                            "3-5 arcs at 1.3-1.7C for 40-100 s, the hot and fill passes in 2-3 arcs at 1.4-1.8C for 60-120 s, the "
                            "welder idling at 0.03C for 15-40 s between arcs while the bead is ground, then standby at 0.01C for 4-8 "
                            "min while the shelter is moved to the next joint), 20 min rest; 1.3 h, down to about 33 % (counted "
                            "in the set's 5 A h); sampled every 2 s, "
                            "0.4 mV noise (a quiet channel); DFN data and model. effect_rmse_mV is what the transference number "
                            "alone does"},
                   initial_soc=0.95, seed=4405, period=2, noise=4e-4, compare=lion.DFN())
    # as6: pair, the log starts right after an unrecorded emergency run (the cell not relaxed) and a 3 mOhm contact resistance,
    # an electric ambulance's shift, 31 degC, 4 s, 1 mV, SPMe
    if run("as6"):
        def ambulance_cell(contact):
            q = at(chen(), 31)
            q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
            return q
        contact_model = lambda: lion.SPMe(options={"contact resistance": "true"})
        steps = ["Discharge at 1.3C for 12 minutes"] + ambulance_shift_steps(4406, 2) + ["Rest for 20 minutes"]
        name = "as6_unrelaxed_start_and_contact_3mOhm_ambulance_shift_31C_4s_spme"
        write_case(root, name, contact_model(), ambulance_cell(0.003), steps,
                   {"effect": "unrelaxed_start+contact_resistance", "candidate_model": "spme",
                    "accept": ["|".join(unrelaxed_words), "|".join(contact_words)], "ambient_temperature_K": 304.15,
                    "note": "two effects: a recording condition, the log (the ambulance's data recorder, read out after the "
                            "shift) starts as the ambulance stops in the hospital's bay, 1e-13 s after an unrecorded emergency run "
                            "(1.3C for 12 min, 90 -> 64 % SOC), so the cell starts the recording with the run's concentration "
                            "gradients, the voltage relaxing by tens of mV in the first minutes; and a 3 mOhm contact "
                            "resistance (a loose, corroded module busbar bolt: about 23 mV at 1.5C). At 31 degC (a "
                            "summer day; isothermal, not recorded). Recorded (an electric ambulance's shift per cell): 2 calls "
                            "(ambulance_shift_steps seed 4406: the patient handed over in the bay with the compartment's air "
                            "conditioning and the medical equipment at 0.08-0.12C for 10-20 min, the drive back in 4-7 stretches "
                            "of a pull-away at 1.1-1.5C for 6-12 s, town driving at 0.4-0.7C for 40-120 s and regenerative braking at "
                            "0.3-0.6C charge for 4-8 s, standby at the station at 0.03C for 10-25 min, then, after the first call "
                            "only, the next emergency run in 6-10 stretches of an acceleration at 1.4-1.9C for 8-15 s, driving at "
                            "0.8-1.2C for 30-90 s and braking at 0.5-0.8C charge for 4-8 s), 20 min rest; 1.9 h recorded, down to about "
                            "26 % (counted in the set's 5 A h); sampled every 4 s, 1 mV noise; SPMe (with contact resistance) data "
                            "handed to the plain SPMe. candidate_rmse_mV "
                            "runs the same unrecorded run on the plain SPMe (what the contact resistance leaves); "
                            "spme_contact_only_rmse_mV is the contact-resistance SPMe started at rest, its initial SOC the best of "
                            "62.75-65.75 % in 0.25 % steps (what the unrelaxed start leaves when the initial SOC is fitted)"},
                   initial_soc=0.9, seed=4406, period=4, compare=lion.SPMe(), skip_steps=1)
        best_replay_rmse(root, name, contact_model, ambulance_cell(0.003), steps[1:], np.arange(0.6275, 0.65751, 0.0025),
                         "spme_contact_only_rmse_mV", period=4)
    # as7: positive exchange current x0.5 (a resistive surface layer on the NMC), an electric street sweeper's early route,
    # 8 degC, 1 s, 1.8 mV, SPM
    if run("as7"):
        p = at(scaled(chen(), "Positive electrode exchange-current density [A.m-2]", 0.5), 8)
        steps = ["Rest for 5 minutes"] + street_sweeper_route_steps(4407, 10) + ["Rest for 15 minutes"]
        write_case(root, "as7_exchange_current_positive_x0p5_street_sweeper_early_route_8C_1s_1p8mV_spm", lion.SPM(), p, steps,
                   {"effect": "kinetics", "candidate_model": "spm", "accept": kinetic_words, "ambient_temperature_K": 281.15,
                    "note": "the positive electrode's exchange-current density x0.5 (a rock-salt surface layer grown on the "
                            "NMC 811 particles in storage at high SOC slowing its charge transfer), the negative's the set's, at 8 "
                            "degC (a town centre before dawn in spring; isothermal, not recorded). An electric compact street "
                            "sweeper's early-morning route per cell from 90 % SOC: 5 min rest, 10 streets "
                            "(street_sweeper_route_steps seed 4407: sweeping along the kerb with the brushes and the suction fan at "
                            "0.6-0.9C for 3-6 min, in 50 % of streets the fan boosted through a drift of leaves at 1.1-1.4C for "
                            "20-40 s, the transit to the next street at 0.4-0.6C for 60-120 s, every fourth street the hopper "
                            "emptied by its hydraulic lift at 1.3-1.7C for 15-25 s and the water tank refilled at 0.02C for 3-5 "
                            "min), 15 min rest; 1.6 h, down to about 15 % (counted in the set's 5 A h); "
                            "sampled every 1 s, 1.8 mV noise (a noisy channel beside the "
                            "brush motors' drives); SPM data and model. effect_rmse_mV is what the slower positive charge "
                            "transfer alone does"},
                   initial_soc=0.9, seed=4407, period=1, noise=1.8e-3, compare=lion.SPM())
    # as8: pair, lumped self-heating (h = 12, temperature recorded) and the current channel's zero offset, 50 mA, a rental
    # electric jet ski, 26 degC, 10 s, 2 mV, SPMe
    if run("as8"):
        off = 0.05
        def jetski_cell():
            q = at(chen(), 26)
            q.update({"Total heat transfer coefficient [W.m-2.K-1]": 12.0})
            return q
        duty = ["Rest for 600 seconds"] + jetski_rental_steps(4408, 3) + ["Rest for 1200 seconds"]
        true, seen = with_leak(duty, 0.0), with_leak(duty, off)
        name = "as8_thermal_h12_recorded_and_current_offset_50mA_rental_jet_ski_26C_10s_2mV_spme"
        write_case(root, name, lion.SPMe(options={"thermal": "lumped"}), jetski_cell(), true,
                   {"effect": "thermal+current_offset", "candidate_model": "spme",
                    "accept": ["|".join(thermal_words), "|".join(offset_words)], "ambient_temperature_K": 299.15,
                    "note": "two effects: lumped self-heating, h = 12 W/(m2 K) (the cells in a sealed box in the hull; "
                            "ambient and initial 26 degC, a bay in summer), the temperature recorded (the craft's battery "
                            "management, 0.05 K noise): the cell warms from 26 to about 41 degC in the sprints; and the battery "
                            "management reading the current 50 mA "
                            "high (a Hall-effect sensor's zero offset: the recorded current is the cell's plus 50 mA of "
                            "discharge, at rest too, where it records that while none flows; not a cell property; over the "
                            "afternoon the logger counts 0.09 A h, 1.8 %, more charge out than the cell gave). A current "
                            "offset is a leak of the opposite sign, so the leak words are accepted beside the current-channel "
                            "words, as ar3. A rental electric personal watercraft's (jet ski's) afternoon per cell from 95 % "
                            "SOC: 10 min rest, 3 customers' rides (jetski_rental_steps seed 4408: idling out through the no-wake "
                            "zone at 0.15-0.25C for 2-4 min, 5-9 runs in the open bay, each a full-throttle sprint at 2.0-2.7C for "
                            "15-45 s, cruising at 0.8-1.2C for 30-80 s and a turn at 0.3-0.5C for 5-15 s, idling back in at "
                            "0.15-0.25C for 2-4 min, tied at the dock while the next customer is briefed, no current, 5-10 min), "
                            "20 min rest; 1.8 h, down to about 15 % (the cell's own current, counted in the set's 5 A h); sampled every 10 s "
                            "(the craft's telematics), 2 mV noise; SPMe (lumped thermal) data handed to the isothermal SPMe. "
                            "spme_thermal_only_rmse_mV: the lumped SPMe on the recorded current's protocol against the recording "
                            "(what the offset leaves); spme_offset_only_rmse_mV: the isothermal SPMe carrying the cell's own "
                            "current (what the self-heating leaves)"},
                   initial_soc=0.95, seed=4408, period=10, noise=2e-3, compare=lion.SPMe(), leak_A=-off, compare_steps=seen,
                   temperature=True)
        replay_rmse(root, name, lion.SPMe(options={"thermal": "lumped"}), jetski_cell(), seen, 0.95, "spme_thermal_only_rmse_mV", period=10)
        replay_rmse(root, name, lion.SPMe(), at(chen(), 26), true, 0.95, "spme_offset_only_rmse_mV", period=10)


def pitch_backup_drill_steps(seed, drills):
    """A wind turbine's pitch-system backup battery (in the hub) per cell (discharge positive) through a
    service team's grid-loss drills after maintenance, for each of `drills` drills: the battery takes
    over the pitch drive in gusty wind, 4-8 corrections (the pitch motor at 0.8-1.5C for 10-30 s, the
    pitch controller and the held brake between them at 0.08-0.12C for 20-60 s), the emergency
    feathering run of the blade to 90 degrees (1.8-2.5C for 6-12 s), the feathered blade held on the
    battery (0.05C for 2-4 min), then the grid back: the hub charger at 0.3-0.5C for 3-6 min
    (time-limited) and the cabinet on float (no current, 2-5 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(drills):
        for _ in range(int(rng.integers(4, 9))):
            steps += [f"Discharge at {rng.uniform(0.8, 1.5):.2f}C for {int(rng.integers(10, 31))} seconds",
                      f"Discharge at {rng.uniform(0.08, 0.12):.3f}C for {int(rng.integers(20, 61))} seconds"]
        steps += [f"Discharge at {rng.uniform(1.8, 2.5):.2f}C for {int(rng.integers(6, 13))} seconds",
                  f"Discharge at 0.05C for {60 * int(rng.integers(2, 5))} seconds",
                  f"Charge at {rng.uniform(0.3, 0.5):.2f}C for {60 * int(rng.integers(3, 7))} seconds",
                  f"Rest for {60 * int(rng.integers(2, 6))} seconds"]
    return steps


def bascule_bridge_outage_steps(seed, openings):
    """A bascule bridge's battery backup drive per cell (discharge positive) through a grid outage, for
    each of `openings` openings for shipping: the warning lights on and the road barriers lowered
    (0.1-0.15C for 60-90 s), the leaves raised by the main drives (1.6-2.2C for 50-80 s), held open with
    the hydraulic holding brakes and the lights while the ship passes (0.15-0.25C for 3-7 min), lowered,
    driven down against the wind (0.5-0.8C for 40-70 s), the barriers raised (0.1C for 30-60 s), then
    the control room and the navigation lights until the next ship (0.03C for 10-25 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(openings):
        steps += [f"Discharge at {rng.uniform(0.1, 0.15):.3f}C for {int(rng.integers(60, 91))} seconds",
                  f"Discharge at {rng.uniform(1.6, 2.2):.2f}C for {int(rng.integers(50, 81))} seconds",
                  f"Discharge at {rng.uniform(0.15, 0.25):.3f}C for {60 * int(rng.integers(3, 8))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(40, 71))} seconds",
                  f"Discharge at 0.1C for {int(rng.integers(30, 61))} seconds",
                  f"Discharge at 0.03C for {60 * int(rng.integers(10, 26))} seconds"]
    return steps


def dpv_cave_dive_steps(seed, legs):
    """A technical diver's diver propulsion vehicle (underwater scooter) in a flooded cave per cell
    (discharge positive): the descent at the entrance (0.6-0.8C for 60-120 s), `legs` legs into the
    cave, each a cruise along the passage (0.8-1.2C for 2-5 min), in 30 % of legs a sprint against the
    outflow through a restriction (1.5-1.9C for 30-60 s), and a stop at a survey station or a line
    tie-off with the motor off (no current, 1-4 min); the turn and the ride back out at a steady
    0.9-1.1C for 80 % of the time the way in took on the motor (the outflow helps, whole seconds); the
    decompression stops on the ascent with the scooter clipped off (no current, 6-12 min)."""
    rng = np.random.default_rng(seed)
    steps = [f"Discharge at {rng.uniform(0.6, 0.8):.2f}C for {int(rng.integers(60, 121))} seconds"]
    motor = 0
    for _ in range(legs):
        cruise = 60 * int(rng.integers(2, 6))
        steps.append(f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {cruise} seconds")
        motor += cruise
        if rng.uniform() < 0.3:
            sprint = int(rng.integers(30, 61))
            steps.append(f"Discharge at {rng.uniform(1.5, 1.9):.2f}C for {sprint} seconds")
            motor += sprint
        steps.append(f"Rest for {60 * int(rng.integers(1, 5))} seconds")
    steps += [f"Discharge at {rng.uniform(0.9, 1.1):.2f}C for {int(round(0.8 * motor))} seconds",
              f"Rest for {60 * int(rng.integers(6, 13))} seconds"]
    return steps


def cable_cam_match_steps(seed, plays):
    """A cable-suspended stadium camera's winch battery per cell (discharge positive) through a football
    match, for each of `plays` passages of play: the camera following the play at walking pace
    (0.25-0.4C for 20-60 s), a fast run across the pitch with a counter-attack (1.2-1.8C for 4-10 s),
    braking at the end of it with the winches regenerating (0.5-0.9C charge for 2-5 s); at half time
    (after half the plays) the camera parked high over the centre circle (0.05C for 15 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(plays):
        steps += [f"Discharge at {rng.uniform(0.25, 0.4):.3f}C for {int(rng.integers(20, 61))} seconds",
                  f"Discharge at {rng.uniform(1.2, 1.8):.2f}C for {int(rng.integers(4, 11))} seconds",
                  f"Charge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(2, 6))} seconds"]
        if k == plays // 2 - 1:
            steps.append("Discharge at 0.05C for 900 seconds")
    return steps


def sailplane_day_steps(seed, flights):
    """A self-launching electric sailplane's battery (behind the cockpit) per cell (discharge positive),
    for each of `flights` flights: the ground checks with the avionics on (0.01C for 3-6 min), the
    self-launch climb to 600 m (1.7-2.1C for 300-420 s), 2-3 spells of soaring with the propeller folded
    and the avionics and the collision-warning unit on (0.01C for 10-20 min) with, between them, a
    restart of the motor as a sustainer when the thermals fail (1.3-1.7C for 90-180 s), then the landing
    and the glider pushed back to the launch point (no current, 10-20 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(flights):
        steps += [f"Discharge at 0.01C for {60 * int(rng.integers(3, 7))} seconds",
                  f"Discharge at {rng.uniform(1.7, 2.1):.2f}C for {int(rng.integers(300, 421))} seconds"]
        spells = int(rng.integers(2, 4))
        for k in range(spells):
            steps.append(f"Discharge at 0.01C for {60 * int(rng.integers(10, 21))} seconds")
            if k < spells - 1:
                steps.append(f"Discharge at {rng.uniform(1.3, 1.7):.2f}C for {int(rng.integers(90, 181))} seconds")
        steps.append(f"Rest for {60 * int(rng.integers(10, 21))} seconds")
    return steps


def rover_field_trial_steps(seed, legs, charge_after):
    """A planetary rover prototype's field trial at a desert analogue site per cell (discharge positive),
    for each of `legs` legs of the traverse: driving to the next waypoint on the six wheel motors
    (0.4-0.7C for 2-6 min), in 40 % of legs climbing over a rock field or up a dune slope (1.2-1.6C for
    20-60 s), then a science stop with the mast cameras, the spectrometer and the radio link to the
    control tent (0.08-0.12C for 5-10 min), in 35 % of stops the arm's core drill (0.8-1.1C for 1-3
    min); after `charge_after` legs the midday stop with the solar panels deployed (0.2-0.3C charge for
    30-50 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(legs):
        steps.append(f"Discharge at {rng.uniform(0.4, 0.7):.2f}C for {60 * int(rng.integers(2, 7))} seconds")
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.2, 1.6):.2f}C for {int(rng.integers(20, 61))} seconds")
        steps.append(f"Discharge at {rng.uniform(0.08, 0.12):.3f}C for {60 * int(rng.integers(5, 11))} seconds")
        if rng.uniform() < 0.35:
            steps.append(f"Discharge at {rng.uniform(0.8, 1.1):.2f}C for {60 * int(rng.integers(1, 4))} seconds")
        if k == charge_after - 1:
            steps.append(f"Charge at {rng.uniform(0.2, 0.3):.3f}C for {60 * int(rng.integers(30, 51))} seconds")
    return steps


def sailing_passage_steps(seed, stretches):
    """A cruising sailing yacht's house battery with a towed hydrogenerator per cell (discharge
    positive) on a coastal passage under sail, for each of `stretches` stretches of 10-25 min: the
    hydrogenerator's charge less the house loads (the autopilot, the instruments, the fridge) as the
    boat speed varies (0.08-0.2C charge), in 40 % of stretches first a tack or a reef with the
    electric winch (1.5-2.2C for 5-15 s), in 25 % the galley's induction hob (0.5-0.8C for 3-8 min) and
    in 20 % the watermaker (0.2-0.3C for 10-20 min) in place of the charge for that long; at the end the
    sails down and motoring into the harbour on the electric drive (0.6-0.9C for 10-15 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(stretches):
        left = 60 * int(rng.integers(10, 26))
        if rng.uniform() < 0.4:
            steps.append(f"Discharge at {rng.uniform(1.5, 2.2):.2f}C for {int(rng.integers(5, 16))} seconds")
        if rng.uniform() < 0.25:
            hob = 60 * int(rng.integers(3, 9))
            steps.append(f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {hob} seconds")
            left -= hob
        if rng.uniform() < 0.2:
            water = min(60 * int(rng.integers(10, 21)), left - 60)
            steps.append(f"Discharge at {rng.uniform(0.2, 0.3):.3f}C for {water} seconds")
            left -= water
        if left > 0:
            steps.append(f"Charge at {rng.uniform(0.08, 0.2):.3f}C for {left} seconds")
    steps.append(f"Discharge at {rng.uniform(0.6, 0.9):.2f}C for {60 * int(rng.integers(10, 16))} seconds")
    return steps


def delivery_robot_rounds_steps(seed, rounds, charge_C=0.5):
    """An autonomous hospital delivery robot (meals, linen and the pharmacy's totes) per cell (discharge
    positive), for each of `rounds` rounds: 4-7 deliveries, each a drive along the corridors with its load
    (0.35-0.55C for 2-5 min) and the wait for a lift, the ride and the hand-over at a ward (the lidar,
    the computer and the touchscreen, 0.05-0.08C for 2-6 min); back on its dock the charge at
    `charge_C` that puts back what the round took (time-limited, whole seconds), then the robot idle on
    the dock (no current, 10-30 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(rounds):
        taken = 0.0
        for _ in range(int(rng.integers(4, 8))):
            drive_C, drive_s = rng.uniform(0.35, 0.55), 60 * int(rng.integers(2, 6))
            ward_C, ward_s = rng.uniform(0.05, 0.08), 60 * int(rng.integers(2, 7))
            steps += [f"Discharge at {drive_C:.3f}C for {drive_s} seconds", f"Discharge at {ward_C:.3f}C for {ward_s} seconds"]
            taken += float(f"{drive_C:.3f}") * drive_s + float(f"{ward_C:.3f}") * ward_s
        steps += [f"Charge at {charge_C}C for {int(round(taken / charge_C))} seconds",
                  f"Rest for {60 * int(rng.integers(10, 31))} seconds"]
    return steps


def batch_at(root, only=None):
    """Forty-fifth batch (key "at"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -4, 6, 14, 17, 20, 22, 24 and 35 degC, each of the three
    models (the candidate the data's model without the concealed physics), sampling from 1 to 10 s, noise
    from 0.5 to 2 mV, and duties no earlier batch used: a wind turbine's pitch-system backup battery
    through grid-loss drills in winter, a bascule bridge's battery backup drive through a grid outage, a
    diver propulsion vehicle in a flooded cave, a cable-suspended stadium camera's winches through a
    football match, a self-launching electric sailplane's two flights, a planetary rover prototype's
    field trial at a desert analogue site, a sailing yacht's house battery with a towed hydrogenerator
    logged from when the motor was switched off, and an autonomous hospital delivery robot over 12
    rounds (16.7 h). A DFN control; four single effects (negative particle diffusivity x0.1; electrolyte
    diffusivity x0.4; the current channel reading 3.5 % high; lumped self-heating, h = 7, temperature
    recorded) and three pairs no earlier batch concealed together (a graphite + silicon composite
    negative with a 5 mOhm contact resistance; an unrecorded motoring run before the log, the cell not
    relaxed, with 6 % lithium loss; SEI growth limited by solvent diffusion over 12 rounds with the
    positive particle diffusivity x0.5). Words as in batches ap-as: the particle diffusivity by the
    particle words, as ap5; the electrolyte by "electrolyte"; the current gain by the current-channel
    words, as ap8; the composite by ar8's words; the unrelaxed start by ar6's words; the SEI by "SEI" or
    the lithium words, as as2. Each effect's size on its own (the nominal candidate, or a replay, against
    the noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the replay keys); every
    step is time-limited (no voltage cut-off reached), so the experiment-aligned comparison needs no
    replay on the recorded current. `only` (a set of case keys, "at1" ...) makes only those cases."""
    at = at_temperature
    run = lambda case: only is None or case in only
    # at1: control, a wind turbine's pitch-system backup battery through grid-loss drills, -4 degC, 2 s, 1 mV, DFN
    if run("at1"):
        p = at(chen(), -4)
        steps = ["Rest for 10 minutes"] + pitch_backup_drill_steps(4501, 10) + ["Rest for 20 minutes"]
        write_case(root, "at1_control_wind_turbine_pitch_backup_grid_loss_drills_minus4C_2s_dfn", lion.DFN(), p, steps,
                   {"effect": "none", "candidate_model": "dfn", "accept": ["no missing"], "ambient_temperature_K": 269.15,
                    "note": "negative control at -4 degC (the hub of an onshore wind turbine in winter, the pitch cabinets "
                            "unheated; isothermal, not recorded): DFN data and model, nothing concealed. A wind turbine's "
                            "pitch-system backup battery per cell from 80 % SOC through a service team's grid-loss drills after "
                            "maintenance: 10 min rest, 10 drills (pitch_backup_drill_steps seed 4501: the battery takes over the "
                            "pitch drive in gusty wind, 4-8 corrections with the pitch motor at 0.8-1.5C for 10-30 s and the "
                            "controller and the held brake at 0.08-0.12C for 20-60 s between them, the emergency feathering run "
                            "to 90 degrees at 1.8-2.5C for 6-12 s, the feathered blade held at 0.05C for 2-4 min, then the grid "
                            "back: the hub charger at 0.3-0.5C for 3-6 min, time-limited, and float at no current for 2-5 min), "
                            "20 min rest; 3.4 h, down to about 51 % (counted in the set's 5 A h); sampled every 2 s, 1 mV noise; "
                            "DFN data and model"},
                   initial_soc=0.8, seed=4501, period=2, compare=lion.DFN())
    # at2: negative particle diffusivity x0.1, a bascule bridge's battery backup drive through a grid outage, 6 degC, 5 s,
    # 1 mV, SPMe
    if run("at2"):
        p = at(scaled(chen(), "Negative particle diffusivity [m2.s-1]", 0.1), 6)
        steps = ["Rest for 10 minutes"] + bascule_bridge_outage_steps(4502, 8) + ["Rest for 20 minutes"]
        write_case(root, "at2_diffusivity_negative_x0p1_bascule_bridge_backup_drive_outage_6C_5s_spme", lion.SPMe(), p, steps,
                   {"effect": "solid_diffusivity", "candidate_model": "spme", "accept": particle_words, "ambient_temperature_K": 279.15,
                    "note": "the graphite's particle diffusivity x0.1 (3.3e-15 m2/s instead of the set's 3.3e-14: a graphite "
                            "from another supplier, its flakes less well rounded), the positive's the set's, at 6 degC (a "
                            "harbour city's bridge on a wet autumn day; isothermal, not recorded). A bascule bridge's battery "
                            "backup drive per cell from 90 % SOC through a grid outage: 10 min rest, 8 openings for shipping "
                            "(bascule_bridge_outage_steps seed 4502: the warning lights and the road barriers at 0.1-0.15C for "
                            "60-90 s, the leaves raised by the main drives at 1.6-2.2C for 50-80 s, held open with the hydraulic "
                            "holding brakes and the lights at 0.15-0.25C for 3-7 min while the ship passes, lowered against the "
                            "wind at 0.5-0.8C for 40-70 s, the barriers raised at 0.1C for 30-60 s, the control room and the "
                            "navigation lights at 0.03C for 10-25 min until the next ship), 20 min rest; 3.8 h, down to about "
                            "33 % (counted in the set's 5 A h); sampled every 5 s, 1 mV noise; SPMe data and model. "
                            "effect_rmse_mV is what the slower diffusion alone does"},
                   initial_soc=0.9, seed=4502, period=5, compare=lion.SPMe())
    # at3: electrolyte diffusivity x0.4, a diver propulsion vehicle in a flooded cave, 14 degC, 1 s, 0.8 mV, DFN
    if run("at3"):
        p = at(scaled(chen(), "Electrolyte diffusivity [m2.s-1]", 0.4), 14)
        steps = ["Rest for 5 minutes"] + dpv_cave_dive_steps(4503, 4) + ["Rest for 15 minutes"]
        write_case(root, "at3_electrolyte_diffusivity_x0p4_diver_propulsion_vehicle_cave_dive_14C_1s_0p8mV_dfn", lion.DFN(), p,
                   steps,
                   {"effect": "electrolyte_transport", "candidate_model": "dfn", "accept": ["electrolyte"], "ambient_temperature_K": 287.15,
                    "note": "the electrolyte's salt diffusivity x0.4 at every concentration and temperature (an electrolyte "
                            "with a viscous co-solvent), its conductivity and transference number the set's, so the salt's "
                            "concentration gradients under load are steeper and relax more slowly. At 14 degC (the water of a "
                            "spring-fed flooded cave all year; isothermal, not recorded). A technical diver's diver propulsion "
                            "vehicle (underwater scooter) per cell from 95 % SOC: 5 min rest, the dive (dpv_cave_dive_steps seed "
                            "4503: the descent at the entrance at 0.6-0.8C for 60-120 s, 4 legs into the cave, each a cruise at "
                            "0.8-1.2C for 2-5 min, in 30 % of legs a sprint against the outflow through a restriction at 1.5-1.9C "
                            "for 30-60 s, a stop at a survey station with the motor off for 1-4 min; the ride back out at a "
                            "steady 0.9-1.1C for 80 % of the motor time of the way in, the decompression stops with the scooter "
                            "clipped off, no current, 6-12 min), 15 min rest; 1.3 h, down to about 35 % (counted in the set's 5 "
                            "A h); sampled every 1 s, 0.8 mV noise; DFN data and model. effect_rmse_mV is what the slower salt "
                            "diffusion alone does"},
                   initial_soc=0.95, seed=4503, period=1, noise=8e-4, compare=lion.DFN())
    # at4: the current channel reading 3.5 % high, a cable-suspended stadium camera's winches, 20 degC, 2 s, 0.6 mV, SPM
    if run("at4"):
        gain = 1.035
        p = at(chen(), 20)
        steps = ["Rest for 10 minutes"] + cable_cam_match_steps(4504, 100) + ["Rest for 15 minutes"]
        seen = with_current_gain(steps, gain)
        write_case(root, "at4_current_gain_3p5pct_high_stadium_cable_camera_winches_20C_2s_0p6mV_spm", lion.SPM(), p, steps,
                   {"effect": "current_measurement_gain", "candidate_model": "spm", "accept": gain_words, "ambient_temperature_K": 293.15,
                    "note": "the winch battery's management reading the current 3.5 % high (gain 1.035, a shunt amplifier out "
                            "of calibration: the recorded current is the cell's times 1.035 on charge and discharge alike; not "
                            "a cell property, the cell itself is nominal), at 20 degC (a covered stadium's roof truss on a "
                            "spring evening; isothermal, not recorded). A cable-suspended stadium camera's winch battery per "
                            "cell from 95 % SOC through a football match: 10 min rest, 100 passages of play "
                            "(cable_cam_match_steps seed 4504: the camera following the play at walking pace at 0.25-0.4C for "
                            "20-60 s, a fast run across the pitch with a counter-attack at 1.2-1.8C for 4-10 s, braking with the "
                            "winches regenerating at 0.5-0.9C charge for 2-5 s; at half time, after 50 plays, parked over the "
                            "centre circle at 0.05C for 15 min), 15 min rest; 2.1 h, down to about 37 % (the cell's own current, "
                            "counted in the set's 5 A h; the logger counts 3.5 % more, about 35 %); sampled every 2 s, 0.6 mV "
                            "noise; SPM data and model. effect_rmse_mV is what the gain alone does (the candidate on the "
                            "recorded current's protocol against the noise-free voltage)"},
                   initial_soc=0.95, seed=4504, period=2, noise=6e-4, compare=lion.SPM(), current_gain=gain, compare_steps=seen)
    # at5: lumped self-heating, h = 7, temperature recorded, a self-launching electric sailplane's two flights, 24 degC, 1 s,
    # 1 mV, SPMe
    if run("at5"):
        p = at(chen(), 24)
        p.update({"Total heat transfer coefficient [W.m-2.K-1]": 7.0})
        steps = ["Rest for 5 minutes"] + sailplane_day_steps(4505, 2) + ["Rest for 10 minutes"]
        write_case(root, "at5_thermal_h7_recorded_self_launching_sailplane_two_flights_24C_1s_spme",
                   lion.SPMe(options={"thermal": "lumped"}), p, steps,
                   {"effect": "thermal", "candidate_model": "spme", "accept": thermal_words, "ambient_temperature_K": 297.15,
                    "note": "lumped self-heating, h = 7 W/(m2 K) (the cells packed in foam in a closed box behind the "
                            "cockpit, no cooling air), ambient and initial 24 degC (a gliding site on a summer day); the "
                            "temperature recorded (the motor controller's battery sensor, 0.05 K noise): the cell warms by "
                            "about 19 K in the climbs. A self-launching electric sailplane's battery per cell from 95 % SOC: 5 "
                            "min rest, 2 flights "
                            "(sailplane_day_steps seed 4505: the ground checks with the avionics at 0.01C for 3-6 min, the "
                            "self-launch climb to 600 m at 1.7-2.1C for 300-420 s, 2-3 spells of soaring with the propeller folded "
                            "at 0.01C for 10-20 min with, between them, a restart of the motor as a sustainer when the thermals "
                            "fail at 1.3-1.7C for 90-180 s, then the landing and the glider pushed back to the launch point, no "
                            "current, 10-20 min), 10 min rest; 2.1 h, down to about 46 % (counted in the set's 5 A h); sampled "
                            "every 1 s, 1 mV noise; SPMe (lumped thermal) data handed to the isothermal SPMe. effect_rmse_mV is "
                            "what the self-heating alone does"},
                   initial_soc=0.95, seed=4505, period=1, compare=lion.SPMe(), temperature=True)
    # at6: pair, a graphite + silicon composite negative and a 5 mOhm contact resistance, a planetary rover prototype's field
    # trial, 35 degC, 8 s, 2 mV, SPM
    if run("at6"):
        def rover_cell(composite, contact):
            q = with_silicon_composite(chen(), 0.62, 0.016) if composite else chen()
            q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
            return at(q, 35)
        composite_model = lambda: lion.SPM(options={"particle phases": ("2", "1"), "contact resistance": "true"})
        contact_model = lambda: lion.SPM(options={"contact resistance": "true"})
        steps = ["Rest for 10 minutes"] + rover_field_trial_steps(4506, 12, 6) + ["Rest for 20 minutes"]
        name = "at6_silicon_composite_negative_and_contact_5mOhm_planetary_rover_field_trial_35C_8s_2mV_spm"
        write_case(root, name, composite_model(), rover_cell(True, 0.005), steps,
                   {"effect": "composite_negative+contact_resistance", "candidate_model": "spm",
                    "accept": ["|".join(composite_words), "|".join(contact_words)], "ambient_temperature_K": 308.15,
                    "note": "two effects: a composite negative electrode (graphite, the set's, active fraction 0.62 instead "
                            "of 0.75, with 1.6 % by volume of silicon, Chen2020_composite's secondary phase: average OCP of "
                            "Mark 2016, no hysteresis, 1.52 um particles, c_max 278000 mol/m3; PyBaMM's 'particle phases' ('2', "
                            "'1'), the same capacity as the set's graphite) handed to the graphite-only SPM, and a 5 mOhm contact "
                            "resistance (a crimped cable lug in the rover's battery box shaken loose on the traverse: about 38 mV "
                            "at 1.5C), at 35 degC (a desert analogue site in the afternoon, the battery box in the sun; "
                            "isothermal, not recorded). The composite judged by ar8's words, the contact by the contact / "
                            "series-resistance words. A planetary rover prototype's field trial per cell from 95 % SOC: 10 min "
                            "rest, 12 legs of the traverse (rover_field_trial_steps seed 4506: driving to the next waypoint on the "
                            "six wheel motors at 0.4-0.7C for 2-6 min, in 40 % of legs a rock field or a dune slope at 1.2-1.6C "
                            "for 20-60 s, a science stop with the mast cameras, the spectrometer and the radio link at "
                            "0.08-0.12C for 5-10 min, in 35 % of stops the arm's core drill at 0.8-1.1C for 1-3 min; after 6 "
                            "legs the midday stop with the solar panels deployed at 0.2-0.3C charge for 30-50 min), 20 min "
                            "rest; 3.7 h, down to about 33 % (counted in the set's 5 A h); sampled every 8 s, 2 mV noise; SPM "
                            "(two-phase, with contact resistance) data handed to the plain SPM. spm_composite_only_rmse_mV: the "
                            "two-phase SPM without the contact resistance against the recording (what the contact leaves); "
                            "spm_contact_only_rmse_mV: the graphite-only SPM with the contact resistance (what the composite "
                            "leaves)"},
                   initial_soc=0.95, seed=4506, period=8, noise=2e-3, compare=lion.SPM())
        replay_rmse(root, name, composite_model(), rover_cell(True, 0.0), steps, 0.95, "spm_composite_only_rmse_mV", period=8)
        replay_rmse(root, name, contact_model(), rover_cell(False, 0.005), steps, 0.95, "spm_contact_only_rmse_mV", period=8)
    # at7: pair, the log starts right after an unrecorded motoring run (the cell not relaxed) and 6 % lithium loss, a sailing
    # yacht's house battery with a towed hydrogenerator, 17 degC, 4 s, 1.2 mV, DFN
    if run("at7"):
        p = at(scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.94), 17)
        steps = ["Discharge at 0.8C for 15 minutes"] + sailing_passage_steps(4507, 12) + ["Rest for 20 minutes"]
        name = "at7_unrelaxed_start_and_inventory_6pct_sailing_yacht_hydrogenerator_passage_17C_4s_1p2mV_dfn"
        write_case(root, name, lion.DFN(), p, steps,
                   {"effect": "unrelaxed_start+lithium_inventory_loss", "candidate_model": "dfn",
                    "accept": ["|".join(unrelaxed_words), "|".join(lithium_words)], "ambient_temperature_K": 290.15,
                    "note": "two effects: a recording condition, the yacht's battery monitor log (read out after the "
                            "passage) starts as the electric drive is switched off and the hydrogenerator lowered, 1e-13 s "
                            "after an unrecorded 0.8C motoring run of 15 min out of the marina (80 -> 60 % SOC), so the cell "
                            "starts the recording with the run's concentration gradients, the voltage relaxing by tens of mV "
                            "in the first minutes; and 6 % less cyclable lithium (initial negative concentration x0.94, lithium "
                            "lost to SEI growth over the boat's seasons; the initial state set as 80 % SOC of the aged cell). At "
                            "17 degC (a coastal passage in early summer; isothermal, not recorded). Recorded (a cruising sailing "
                            "yacht's house battery per cell): 12 stretches under sail of 10-25 min (sailing_passage_steps seed "
                            "4507: the hydrogenerator's charge less the house loads at 0.08-0.2C charge, in 40 % of stretches "
                            "first a tack or a reef with the electric winch at 1.5-2.2C for 5-15 s, in 25 % the galley's "
                            "induction hob at 0.5-0.8C for 3-8 min, in 20 % the watermaker at 0.2-0.3C for 10-20 min), then the "
                            "sails down and motoring into the harbour at 0.6-0.9C for 10-15 min, 20 min rest; 4.3 h recorded, "
                            "down to about 27 % (counted in the set's 5 A h); sampled every 4 s, 1.2 mV noise; DFN data and "
                            "model. candidate_rmse_mV runs the same unrecorded run on the nominal DFN (what the lithium loss "
                            "leaves); dfn_inventory_only_rmse_mV is the DFN with the lithium loss started at rest, its initial "
                            "SOC the best of 58-61 % in 0.5 % steps (what the unrelaxed start leaves when the initial SOC is "
                            "fitted)"},
                   initial_soc=0.8, seed=4507, period=4, noise=1.2e-3, compare=lion.DFN(), skip_steps=1)
        best_replay_rmse(root, name, lion.DFN, p, steps[1:], np.arange(0.58, 0.61001, 0.005), "dfn_inventory_only_rmse_mV", period=4)
    # at8: pair, SEI growth limited by solvent diffusion (x900) over 12 rounds and the positive particle diffusivity x0.5, an
    # autonomous hospital delivery robot, 22 degC, 10 s, 0.5 mV, SPMe
    if run("at8"):
        def robot_cell(sei, diffusivity):
            q = scaled(chen(), "SEI solvent diffusivity [m2.s-1]", sei)
            return at(scaled(q, "Positive particle diffusivity [m2.s-1]", diffusivity), 22)
        sei_model = lambda: lion.SPMe(options={"SEI": "solvent-diffusion limited"})
        steps = ["Rest for 10 minutes"] + delivery_robot_rounds_steps(4508, 12, charge_C=0.4) + ["Rest for 20 minutes"]
        name = "at8_sei_solvent_diffusion_x900_and_diffusivity_positive_x0p5_hospital_delivery_robot_12_rounds_22C_10s_0p5mV_spme"
        write_case(root, name, sei_model(), robot_cell(900.0, 0.5), steps,
                   {"effect": "sei_growth+solid_diffusivity", "candidate_model": "spme",
                    "accept": ["|".join(["SEI"] + lithium_words), "|".join(particle_words)], "ambient_temperature_K": 295.15,
                    "note": "two effects: SEI growth limited by the diffusion of solvent through the film (PyBaMM "
                            "'solvent-diffusion limited'; SEI solvent diffusivity x900, 2.25e-19 m2/s instead of Chen 2020's "
                            "2.5e-22: a cell whose formation left a porous, poorly passivating SEI; the film's other parameters "
                            "Chen 2020's): 0.0038 mol of lithium (0.101 A h, 2.0 % of the set's 5 A h) lost to the SEI over the "
                            "12 rounds, fastest at first (0.030 A h after 2 h, 0.067 after 8 h), and the NMC's particle "
                            "diffusivity x0.5 (2e-15 m2/s instead of the set's 4e-15: a cathode powder from another lot, "
                            "denser secondary particles). A lithium-inventory loss growing through the recording is the SEI's "
                            "nearest stand-in and is accepted, as as2; the diffusivity by the particle words. At 22 degC (a "
                            "hospital's corridors; isothermal, not recorded). An autonomous hospital delivery robot per cell from "
                            "78 % SOC: 10 min rest, 12 rounds (delivery_robot_rounds_steps seed 4508: 4-7 deliveries each, the "
                            "drive along the corridors with its load at 0.35-0.55C for 2-5 min and the wait for a lift, the ride "
                            "and the hand-over at a ward at 0.05-0.08C for 2-6 min; back on its dock the charge at 0.4C that puts "
                            "back what the round took, time-limited, then idle on the dock, no current, 10-30 min), 20 min rest; "
                            "16.7 h, the state of charge swinging between 78 % and 55-66 % (counted in the set's 5 A h; the SEI "
                            "takes its lithium out of that); sampled every 10 s (the fleet manager's telemetry), 0.5 mV noise; "
                            "SPMe (with SEI) data handed to the plain SPMe. spme_sei_only_rmse_mV: the SEI SPMe with the set's "
                            "positive diffusivity against the recording (what the diffusivity leaves); "
                            "spme_diffusivity_only_rmse_mV: the plain SPMe with the slower positive diffusion (what the SEI "
                            "leaves)"},
                   initial_soc=0.78, seed=4508, period=10, noise=5e-4, compare=lion.SPMe())
        replay_rmse(root, name, sei_model(), robot_cell(900.0, 1.0), steps, 0.78, "spme_sei_only_rmse_mV", period=10)
        replay_rmse(root, name, lion.SPMe(), robot_cell(1.0, 0.5), steps, 0.78, "spme_diffusivity_only_rmse_mV", period=10)


def laptop_workday_steps(seed, hours):
    """A laptop's working day per cell (discharge positive; a 3S1P pack), in blocks of 20-50 min for
    about `hours` hours: office work (mail, documents, the browser) at 0.07-0.1C, in 30 % of blocks a
    video call at 0.2-0.26C instead, in 20 % a build or a data crunch with the processor at full power
    in bursts (0.6-0.75C for 2-6 min, between them 0.15-0.2C for 1-3 min), in 15 % the lid closed in a
    meeting elsewhere (suspended, 0.004C); at lunch (after half the blocks) plugged in at a desk, the
    charger's 0.45-0.55C charge for 40-55 min (time-limited), then unplugged."""
    rng = np.random.default_rng(seed)
    steps = []
    blocks = int(round(hours * 60 / 35))
    for k in range(blocks):
        minutes = int(rng.integers(20, 51))
        u = rng.uniform()
        if u < 0.3:
            steps.append(f"Discharge at {rng.uniform(0.2, 0.26):.3f}C for {60 * minutes} seconds")
        elif u < 0.5:
            left = 60 * minutes
            while left > 0:
                burst = min(60 * int(rng.integers(2, 7)), left)
                steps.append(f"Discharge at {rng.uniform(0.6, 0.75):.2f}C for {burst} seconds")
                left -= burst
                if left > 0:
                    idle = min(60 * int(rng.integers(1, 4)), left)
                    steps.append(f"Discharge at {rng.uniform(0.15, 0.2):.3f}C for {idle} seconds")
                    left -= idle
        elif u < 0.65:
            steps.append(f"Discharge at 0.004C for {60 * minutes} seconds")
        else:
            steps.append(f"Discharge at {rng.uniform(0.07, 0.1):.3f}C for {60 * minutes} seconds")
        if k == blocks // 2 - 1:
            steps.append(f"Charge at {rng.uniform(0.45, 0.55):.3f}C for {60 * int(rng.integers(40, 56))} seconds")
    return steps


def heated_apparel_ski_day_steps(seed, runs, lunch_after):
    """A heated ski jacket's and gloves' battery per cell (discharge positive) through a ski day, for each
    of `runs` runs: the chairlift ride with the heating on high (0.16-0.2C for 8-14 min), the run down on
    low (0.05-0.07C for 4-9 min), in 30 % of runs a wait in the lift queue on medium (0.11-0.14C for 3-8
    min); after `lunch_after` runs the lunch in the mountain restaurant with the heating off but a phone
    charged from the jacket's USB port (0.12-0.16C for 20-35 min, then no current for 20-30 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(runs):
        if rng.uniform() < 0.3:
            steps.append(f"Discharge at {rng.uniform(0.11, 0.14):.3f}C for {60 * int(rng.integers(3, 9))} seconds")
        steps += [f"Discharge at {rng.uniform(0.16, 0.2):.3f}C for {60 * int(rng.integers(8, 15))} seconds",
                  f"Discharge at {rng.uniform(0.05, 0.07):.3f}C for {60 * int(rng.integers(4, 10))} seconds"]
        if k == lunch_after - 1:
            steps += [f"Discharge at {rng.uniform(0.12, 0.16):.3f}C for {60 * int(rng.integers(20, 36))} seconds",
                      f"Rest for {60 * int(rng.integers(20, 31))} seconds"]
    return steps


def quarry_haul_steps(seed, loads):
    """A quarry's battery-electric dump truck hauling rock down from the face to the crusher per cell
    (discharge positive), for each of `loads` loads: waiting under the excavator while it is loaded
    (0.03C for 2-4 min), the laden descent down the haul road holding its speed on the motors
    (regeneration at 0.6-1.0C charge, 2-4 stretches of 30-70 s with the brakes eased between them at
    0.2-0.4C charge for 5-15 s), the flat to the crusher (0.5-0.8C for 20-40 s), tipping with the body
    raised by its hydraulics (1.0-1.4C for 15-25 s), then the empty climb back up the ramp (1.4-1.8C
    for 120-200 s, with a passing place at 0.1C for 10-30 s in 40 % of climbs) and the flat to the face
    (0.4-0.6C for 20-40 s)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(loads):
        steps.append(f"Discharge at 0.03C for {60 * int(rng.integers(2, 5))} seconds")
        stretches = int(rng.integers(2, 5))
        for k in range(stretches):
            steps.append(f"Charge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(30, 71))} seconds")
            if k < stretches - 1:
                steps.append(f"Charge at {rng.uniform(0.2, 0.4):.2f}C for {int(rng.integers(5, 16))} seconds")
        steps += [f"Discharge at {rng.uniform(0.5, 0.8):.2f}C for {int(rng.integers(20, 41))} seconds",
                  f"Discharge at {rng.uniform(1.0, 1.4):.2f}C for {int(rng.integers(15, 26))} seconds"]
        climb = int(rng.integers(120, 201))
        if rng.uniform() < 0.4:
            first = int(rng.integers(40, climb - 40))
            steps += [f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {first} seconds",
                      f"Discharge at 0.1C for {int(rng.integers(10, 31))} seconds",
                      f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {climb - first} seconds"]
        else:
            steps.append(f"Discharge at {rng.uniform(1.4, 1.8):.2f}C for {climb} seconds")
        steps.append(f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {int(rng.integers(20, 41))} seconds")
    return steps


def reefer_delivery_day_steps(seed, drops):
    """An electric transport refrigeration unit's (a battery-powered reefer on a chilled-food delivery
    lorry's box) battery per cell (discharge positive) through a delivery day, for each of `drops` drops:
    the drive to the next shop with the axle generator running the unit and charging the battery
    (0.22-0.3C charge for 10-25 min), the doors open while the cages are unloaded (the compressor off,
    the evaporator fans and the lights at 0.04-0.06C for 3-8 min), the pull-down after the doors close
    with the compressor at full speed (0.7-0.85C for 5-9 min), then the unit cycling while the driver does
    the paperwork (0.4-0.5C for 2-4 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(drops):
        steps += [f"Charge at {rng.uniform(0.22, 0.3):.3f}C for {60 * int(rng.integers(10, 26))} seconds",
                  f"Discharge at {rng.uniform(0.04, 0.06):.3f}C for {60 * int(rng.integers(3, 9))} seconds",
                  f"Discharge at {rng.uniform(0.7, 0.85):.2f}C for {60 * int(rng.integers(5, 10))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.5):.3f}C for {60 * int(rng.integers(2, 5))} seconds"]
    return steps


def sump_pump_storm_steps(seed, hours):
    """A basement sump pump's battery backup per cell (discharge positive) through a storm's mains power
    cut of `hours` hours, hour by hour: the rain's inflow drawn per hour (heavy, steady or easing), the pump
    running each time the float switch trips (0.55-0.7C for 40-90 s) with the controller and the alarm
    between runs (0.004C) for 3-6 min in heavy rain, 8-15 min in steady rain and 20-40 min as it eases,
    whole runs only, until the hour is over."""
    rng = np.random.default_rng(seed)
    steps = []
    for _ in range(hours):
        kind = rng.choice(["heavy", "steady", "easing"], p=[0.3, 0.45, 0.25])
        low, high = {"heavy": (3, 7), "steady": (8, 16), "easing": (20, 41)}[kind]
        used = 0
        while used < 3600:
            run = int(rng.integers(40, 91))
            wait = 60 * int(rng.integers(low, high))
            steps += [f"Discharge at {rng.uniform(0.55, 0.7):.3f}C for {run} seconds", f"Discharge at 0.004C for {wait} seconds"]
            used += run + wait
    return steps


def eskateboard_ride_steps(seed, hills, session_lines):
    """An electric skateboard's ride per cell (discharge positive; a 10S pack in the deck worked hard):
    the ride out through town to the skate park, for each of `hills` hills a climb at 2.2-2.8C for 25-60 s,
    a rolling stretch at 0.8-1.2C for 40-120 s and a descent braked by the motor (regeneration at
    0.6-1.0C charge for 15-40 s), a stop at lights or a crossing (no current, 10-40 s) between; at the
    park `session_lines` lines of pushing off hard (1.8-2.4C for 5-10 s), carving (0.5-0.9C for 10-25 s)
    and braking (0.6-0.9C charge for 3-6 s), then the board carried for a while (no current, 5-10 min);
    the ride home over as many hills, drawn anew the same way."""
    rng = np.random.default_rng(seed)
    def ride():
        out = []
        for _ in range(hills):
            out += [f"Discharge at {rng.uniform(2.2, 2.8):.2f}C for {int(rng.integers(25, 61))} seconds",
                    f"Discharge at {rng.uniform(0.8, 1.2):.2f}C for {int(rng.integers(40, 121))} seconds",
                    f"Charge at {rng.uniform(0.6, 1.0):.2f}C for {int(rng.integers(15, 41))} seconds",
                    f"Rest for {int(rng.integers(10, 41))} seconds"]
        return out
    steps = ride()
    for _ in range(session_lines):
        steps += [f"Discharge at {rng.uniform(1.8, 2.4):.2f}C for {int(rng.integers(5, 11))} seconds",
                  f"Discharge at {rng.uniform(0.5, 0.9):.2f}C for {int(rng.integers(10, 26))} seconds",
                  f"Charge at {rng.uniform(0.6, 0.9):.2f}C for {int(rng.integers(3, 7))} seconds"]
    steps.append(f"Rest for {60 * int(rng.integers(5, 11))} seconds")
    return steps + ride()


def charging_robot_shift_steps(seed, cars, recharge_every, recharge):
    """A mobile EV-charging robot's shift in an open-air park-and-ride car park per cell (discharge
    positive; the robot carries a battery and charges parked cars from it), for each of `cars` cars: the
    drive across the car park to the car (0.12-0.2C for 1-3 min), the plug-in and the handshake (0.02C for
    30-60 s), the car's charge from the robot's battery (0.85-1.1C for 8-12 min, then its taper at
    0.4-0.6C for 3-6 min), the drive on (0.12-0.2C for 1-3 min); after every `recharge_every` cars the
    robot docks at its grid-connected base and recharges with `recharge` (a list of steps), then waits
    for the next booking (no current, 5-15 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for k in range(cars):
        steps += [f"Discharge at {rng.uniform(0.12, 0.2):.3f}C for {60 * int(rng.integers(1, 4))} seconds",
                  f"Discharge at 0.02C for {int(rng.integers(30, 61))} seconds",
                  f"Discharge at {rng.uniform(0.85, 1.1):.2f}C for {60 * int(rng.integers(8, 13))} seconds",
                  f"Discharge at {rng.uniform(0.4, 0.6):.2f}C for {60 * int(rng.integers(3, 7))} seconds",
                  f"Discharge at {rng.uniform(0.12, 0.2):.3f}C for {60 * int(rng.integers(1, 4))} seconds"]
        if (k + 1) % recharge_every == 0 and k < cars - 1:
            steps += list(recharge) + [f"Rest for {60 * int(rng.integers(5, 16))} seconds"]
    return steps


def moto_taxi_day_steps(seed, trips_per_spell, spells, top_up_C=0.5, back=0.85):
    """An electric motorcycle taxi's (a boda-boda's) day in a hot city per cell (discharge positive), in
    `spells` spells of `trips_per_spell` trips: each trip the ride to the passenger and with them through
    traffic (4-8 stretches of a pull-away at 1.3-1.8C for 5-10 s, riding at 0.5-0.9C for 20-90 s and
    braking with regeneration at 0.3-0.5C charge for 3-6 s), then waiting at the stage for the next
    fare (no current, 3-15 min); after each spell but the last a top-up at a charging kiosk at
    `top_up_C` that puts back `back` of what the spell took (time-limited, whole seconds; the rider pays
    for a part charge) while the rider eats or rests (then no current, 10-20 min)."""
    rng = np.random.default_rng(seed)
    steps = []
    for s in range(spells):
        taken = 0.0
        for _ in range(trips_per_spell):
            for _ in range(int(rng.integers(4, 9))):
                a_C, a_s = rng.uniform(1.3, 1.8), int(rng.integers(5, 11))
                r_C, r_s = rng.uniform(0.5, 0.9), int(rng.integers(20, 91))
                b_C, b_s = rng.uniform(0.3, 0.5), int(rng.integers(3, 7))
                steps += [f"Discharge at {a_C:.2f}C for {a_s} seconds", f"Discharge at {r_C:.2f}C for {r_s} seconds",
                          f"Charge at {b_C:.2f}C for {b_s} seconds"]
                taken += float(f"{a_C:.2f}") * a_s + float(f"{r_C:.2f}") * r_s - float(f"{b_C:.2f}") * b_s
            steps.append(f"Rest for {60 * int(rng.integers(3, 16))} seconds")
        if s < spells - 1:
            steps += [f"Charge at {top_up_C}C for {int(round(back * taken / top_up_C))} seconds",
                      f"Rest for {60 * int(rng.integers(10, 21))} seconds"]
    return steps


def batch_au(root, only=None):
    """Forty-sixth batch (key "au"), made blind (a helper session that did not read the diagnosis code).
    The Chen 2020 cell throughout, ambients -12, -6, 11, 14, 19, 27, 33 and 37 degC, each of the three
    models (the candidate the data's model without the concealed physics), sampling from 1 to 10 s, noise
    from 0.5 to 2 mV, and duties no earlier batch used: a laptop's working day with a charge at lunch, a
    heated jacket's and gloves' battery through a ski day, a quarry's battery-electric dump truck hauling
    down to the crusher (laden descents regenerating), an electric transport refrigeration unit on a
    chilled-food lorry logged from when it left the depot after the pre-cool, a basement sump pump's
    battery backup through a storm's power cut, an electric skateboard's ride to the skate park and back,
    a mobile EV-charging robot in a park-and-ride car park with rapid recharges at its base in frost, and
    an electric motorcycle taxi's day with part top-ups. An SPM control; four single effects (9 % positive
    active-material loss at -12 degC; the current channel's zero offset reading 30 mA low, the sign no
    earlier case used; lumped self-heating, h = 9, temperature not recorded, on the DFN; SEI growth
    limited by electron migration, a growth law concealed once before and only in a pair) and three pairs
    no earlier batch concealed together (7 % negative active-material loss with the voltage logged 2 s
    late; an unrelaxed start, the log begun right after an unrecorded pre-cool, with the positive's
    exchange current x0.35; partially reversible lithium plating in cold rapid recharges with a 4 mOhm
    contact resistance). Words as in batches ap-at: the active material by "active material", as ap2;
    the delay by aq5's words; the unrelaxed start by ar6's words; the kinetics by the kinetics words; the
    current offset by ar3's words; the plating by "plating", as ar2; the SEI by "SEI" or the lithium
    words, as as2. Each effect's size on its own (the nominal candidate, or a replay, against the
    noise-free voltage or the recording) is in truth.json (effect_rmse_mV and the replay keys); every step
    is time-limited (no voltage cut-off reached: the charges stay below 4.2 V), so the experiment-aligned
    comparison needs no replay on the recorded current. `only` (a set of case keys, "au1" ...) makes
    only those cases."""
    at = at_temperature
    run = lambda case: only is None or case in only
    # au1: control, a laptop's working day with a charge at lunch, 27 degC, 8 s, 0.5 mV, SPM
    if run("au1"):
        p = at(chen(), 27)
        steps = ["Rest for 10 minutes"] + laptop_workday_steps(4601, 9) + ["Rest for 20 minutes"]
        write_case(root, "au1_control_laptop_working_day_lunch_charge_27C_8s_0p5mV_spm", lion.SPM(), p, steps,
                   {"effect": "none", "candidate_model": "spm", "accept": ["no missing"], "ambient_temperature_K": 300.15,
                    "note": "negative control at 27 degC (a laptop on a desk in a warm office in summer; isothermal, not "
                            "recorded): SPM data and model, nothing concealed. A laptop's working day per cell (a 3S1P pack) "
                            "from 95 % SOC: 10 min rest, blocks of 20-50 min for about 9 h (laptop_workday_steps seed 4601: "
                            "office work at 0.07-0.1C, in 30 % of blocks a video call at 0.2-0.26C, in 20 % a build with the "
                            "processor at full power in bursts at 0.6-0.75C for 2-6 min and 0.15-0.2C for 1-3 min between them, "
                            "in 15 % the lid closed, suspended at 0.004C; at lunch plugged in at a desk, the charger's 0.45-0.55C "
                            "for 40-55 min, time-limited), 20 min rest; 8.8 h, down to about 26 %, up to about 70 % at lunch, down to about 29 % (counted in the set's 5 A h); sampled "
                            "every 8 s (the operating system's battery log), 0.5 mV noise; SPM data and model"},
                   initial_soc=0.95, seed=4601, period=8, noise=5e-4, compare=lion.SPM())
    # au2: 9 % positive active-material loss, a heated jacket's and gloves' battery through a ski day, -12 degC, 6 s, 1 mV, SPM
    if run("au2"):
        p = at(scaled(chen(), "Positive electrode active material volume fraction", 0.91), -12)
        steps = ["Rest for 10 minutes"] + heated_apparel_ski_day_steps(4602, 15, 7) + ["Rest for 30 minutes"]
        write_case(root, "au2_lam_positive_9pct_heated_apparel_ski_day_minus12C_6s_spm", lion.SPM(), p, steps,
                   {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"],
                    "ambient_temperature_K": 261.15,
                    "note": "9 % loss of positive active material (volume fraction x0.91, the set's initial concentrations, so "
                            "the lithium of the lost material goes with it: NMC particles cracked off the conductive network "
                            "after the pack's winters of use; the initial state set as 95 % SOC of the aged cell), at -12 degC "
                            "(a ski resort on a clear January day, the pack in the jacket's outer pocket cold-soaked; "
                            "isothermal, not recorded). A heated ski jacket's and gloves' battery per cell from 95 % SOC: 10 min "
                            "rest, 15 runs (heated_apparel_ski_day_steps seed 4602: the chairlift ride with the heating on high "
                            "at 0.16-0.2C for 8-14 min, the run down on low at 0.05-0.07C for 4-9 min, in 30 % of runs first a "
                            "wait in the lift queue on medium at 0.11-0.14C for 3-8 min; after 7 runs lunch in the mountain "
                            "restaurant with the heating off, a phone charged from the jacket's USB port at 0.12-0.16C for 20-35 "
                            "min, then no current for 20-30 min), 30 min rest; 6.1 h, down to about 26 % (counted in the set's 5 A h); "
                            "sampled every 6 s, 1 mV noise; SPM data and model. effect_rmse_mV is what the loss alone does"},
                   initial_soc=0.95, seed=4602, period=6, compare=lion.SPM())
    # au3: pair, 7 % negative active-material loss and the voltage logged 2 s late, a quarry's battery-electric dump truck,
    # 14 degC, 1 s, 1.2 mV, SPMe
    if run("au3"):
        def quarry_cell(lam):
            return at(scaled(chen(), "Negative electrode active material volume fraction", lam), 14)
        late = lambda t, i, v: np.interp(t - 2.0, t, v)
        steps = ["Rest for 5 minutes"] + quarry_haul_steps(4603, 6) + ["Rest for 15 minutes"]
        name = "au3_lam_negative_7pct_and_voltage_logged_2s_late_quarry_dump_truck_14C_1s_1p2mV_spme"
        write_case(root, name, lion.SPMe(), quarry_cell(0.93), steps,
                   {"effect": "active_material_loss+voltage_time_lag", "candidate_model": "spme",
                    "accept": ["active material", "|".join(delay_words)], "ambient_temperature_K": 287.15,
                    "note": "two effects: 7 % loss of negative active material (volume fraction 0.75 -> 0.6975, the set's "
                            "initial concentrations, so the lithium of the lost graphite goes with it: graphite isolated as "
                            "the binder weakened under the truck's vibration; the initial state set as 60 % SOC of the aged "
                            "cell), and a logging fault, not a cell property: the truck's data logger stamps the voltage 2 s "
                            "later than the current (the battery management sends them in separate, unsynchronised messages), "
                            "so each recorded voltage is the cell's voltage 2 s earlier (linear interpolation of the 1 s "
                            "simulation; the first 2 s hold the first value); the delay judged by aq5's words. At 14 degC (a "
                            "limestone quarry in spring; isothermal, not recorded). A quarry's battery-electric dump truck per "
                            "cell from 60 % SOC (the fleet starts the shift there so that the first laden descents can "
                            "regenerate): 5 min rest, 6 loads (quarry_haul_steps seed 4603: waiting under the excavator "
                            "while loaded at 0.03C for 2-4 min, the laden descent down the haul road holding its speed on the "
                            "motors, regenerating at 0.6-1.0C charge in 2-4 stretches of 30-70 s with the brakes eased between "
                            "them at 0.2-0.4C charge for 5-15 s, the flat to the crusher at 0.5-0.8C for 20-40 s, tipping with "
                            "the body raised by its hydraulics at 1.0-1.4C for 15-25 s, the empty climb back up the ramp at "
                            "1.4-1.8C for 120-200 s, in 40 % of climbs with a passing place at 0.1C for 10-30 s, the flat to "
                            "the face at 0.4-0.6C for 20-40 s), 15 min rest; 1.3 h, up to about 63 % on the first descents, down to about 30 % (counted in the set's 5 A h); "
                            "sampled every 1 s, 1.2 mV noise; SPMe data and model. spme_lam_only_rmse_mV: the SPMe with the loss "
                            "alone, no delay, against the recording (what the delay leaves); spme_delay_only_rmse_mV: the "
                            "nominal SPMe logged 2 s late (what the loss leaves)"},
                   initial_soc=0.6, seed=4603, period=1, noise=1.2e-3, compare=lion.SPMe(), post=late)
        replay_rmse(root, name, lion.SPMe(), quarry_cell(0.93), steps, 0.6, "spme_lam_only_rmse_mV", period=1)
        replay_rmse(root, name, lion.SPMe(), quarry_cell(1.0), steps, 0.6, "spme_delay_only_rmse_mV", period=1, post=late)
    # au4: pair, the log starts right after an unrecorded pre-cool (the cell not relaxed) and the positive's exchange current
    # x0.35, an electric transport refrigeration unit on a chilled-food lorry, 37 degC, 5 s, 0.8 mV, DFN
    if run("au4"):
        reefer_cell = lambda k: at(scaled(chen(), "Positive electrode exchange-current density [A.m-2]", k), 37)
        steps = ["Discharge at 0.6C for 15 minutes"] + reefer_delivery_day_steps(4604, 12) + ["Rest for 20 minutes"]
        name = "au4_unrelaxed_start_and_exchange_current_positive_x0p35_reefer_delivery_day_37C_5s_0p8mV_dfn"
        write_case(root, name, lion.DFN(), reefer_cell(0.35), steps,
                   {"effect": "unrelaxed_start+kinetics", "candidate_model": "dfn",
                    "accept": ["|".join(unrelaxed_words), "|".join(kinetic_words)], "ambient_temperature_K": 310.15,
                    "note": "two effects: a recording condition, the refrigeration unit's log (read out at the depot in the "
                            "evening) starts as the lorry leaves the depot, 1e-13 s after an unrecorded pre-cool of the "
                            "loaded box with the compressor at full speed on the battery (0.6C for 15 min, 95 -> 80 % SOC), so "
                            "the cell starts the recording with the pre-cool's concentration gradients, the voltage relaxing "
                            "in the first minutes under the drive's charge; and the positive electrode's exchange-current "
                            "density x0.35 (a resistive rock-salt surface layer grown on the NMC 811 in the unit's hot "
                            "summers), the negative's the set's. At 37 degC (a heatwave, the battery box under the lorry's "
                            "chassis; isothermal, not recorded). Recorded (an electric transport refrigeration unit's battery "
                            "on a chilled-food delivery lorry, per cell): 12 drops (reefer_delivery_day_steps seed 4604: the "
                            "drive to the next shop with the axle generator running the unit and charging the battery at "
                            "0.22-0.3C charge for 10-25 min, the doors open while the cages are unloaded, the compressor off and "
                            "the evaporator fans and the lights at 0.04-0.06C for 3-8 min, the pull-down after the doors close "
                            "with the compressor at full speed at 0.7-0.85C for 5-9 min, the unit cycling while the driver does "
                            "the paperwork at 0.4-0.5C for 2-4 min), 20 min rest; 6.8 h recorded, the state of charge between about 93 % and 41 % (the drives lifting it, the pull-downs lowering it), about 41 % at the end (counted in the "
                            "set's 5 A h); sampled every 5 s, 0.8 mV noise; DFN data and model. candidate_rmse_mV runs the same "
                            "unrecorded pre-cool on the nominal DFN (what the slower positive kinetics leaves); "
                            "dfn_kinetics_only_rmse_mV is the DFN with the slower kinetics started at rest, its initial SOC the "
                            "best of 78.5-81.5 % in 0.5 % steps (what the unrelaxed start leaves when the initial SOC is fitted)"},
                   initial_soc=0.95, seed=4604, period=5, noise=8e-4, compare=lion.DFN(), skip_steps=1)
        best_replay_rmse(root, name, lion.DFN, reefer_cell(0.35), steps[1:], np.arange(0.785, 0.81501, 0.005),
                         "dfn_kinetics_only_rmse_mV", period=5)
    # au5: the current channel's zero offset, 30 mA low (reads that much less discharge than flows), a basement sump pump's battery
    # backup through a storm's power cut, 11 degC, 10 s, 1 mV, SPMe
    if run("au5"):
        off = 0.03
        duty = ["Rest for 600 seconds"] + sump_pump_storm_steps(4605, 10) + ["Rest for 1200 seconds"]
        true, seen = with_leak(duty, 0.0), with_leak(duty, -off)
        write_case(root, "au5_current_offset_30mA_low_sump_pump_backup_storm_power_cut_11C_10s_spme", lion.SPMe(), at(chen(), 11),
                   true,
                   {"effect": "current_offset", "candidate_model": "spme", "accept": offset_words, "ambient_temperature_K": 284.15,
                    "note": "the backup unit's battery monitor reads the current 30 mA low (a Hall-effect sensor's zero offset, "
                            "0.6 % of 1C: the recorded current is the cell's less 30 mA, so at rest it records 30 mA of "
                            "charge while none flows); not a cell property, the cell itself is nominal. Over the power cut the "
                            "logger counts 0.34 A h (6.9 % of the set's 5 A h) less charge out than the cell gave. A current offset is a leak of "
                            "the opposite sign (here the cell carries the recorded current plus 30 mA, as if it leaked), so the "
                            "leak words are accepted beside the current-channel words, as ar3. At 11 degC (a basement in "
                            "autumn; isothermal, not recorded). A basement sump pump's battery backup per cell from 98 % SOC "
                            "(kept there by the float charger until the mains failed): 10 min rest, 10 hours of the storm "
                            "(sump_pump_storm_steps seed 4605: each hour heavy, steady or easing rain, the pump running each "
                            "time the float switch trips at 0.55-0.7C for 40-90 s, the controller and the alarm between runs at "
                            "0.004C for 3-6 min in heavy rain, 8-15 min in steady rain, 20-40 min as it eases), 20 min rest; "
                            "11.5 h, down to about 32 % (the cell's own current, counted in the set's 5 A h); sampled every 10 s, 1 mV "
                            "noise; SPMe data and model. effect_rmse_mV is what the offset alone does (the candidate on the "
                            "recorded current's protocol against the noise-free voltage)"},
                   initial_soc=0.98, seed=4605, period=10, compare=lion.SPMe(), leak_A=off, compare_steps=seen)
    # au6: lumped self-heating, h = 9, temperature not recorded, an electric skateboard's ride, 19 degC, 3 s, 2 mV, DFN
    if run("au6"):
        p = at(chen(), 19)
        p.update({"Total heat transfer coefficient [W.m-2.K-1]": 9.0})
        steps = ["Rest for 5 minutes"] + eskateboard_ride_steps(4606, 5, 25) + ["Rest for 15 minutes"]
        write_case(root, "au6_thermal_h9_unrecorded_electric_skateboard_ride_19C_3s_2mV_dfn", lion.DFN(options={"thermal": "lumped"}),
                   p, steps,
                   {"effect": "thermal", "candidate_model": "dfn", "accept": thermal_words, "ambient_temperature_K": 292.15,
                    "note": "lumped self-heating, h = 9 W/(m2 K) (the cells in a sealed enclosure under the deck, no air "
                            "flow), ambient and initial 19 degC (a town on a mild spring evening); the temperature not recorded "
                            "(the board's app logs current and voltage only): the cell warms by about 19 K, to about 38 degC on the ride home. An "
                            "electric skateboard's ride per cell (a 10S pack worked hard) from 95 % SOC: 5 min rest, the ride "
                            "(eskateboard_ride_steps seed 4606: out through town over 5 hills, each a climb at 2.2-2.8C for "
                            "25-60 s, a rolling stretch at 0.8-1.2C for 40-120 s, a descent braked by the motor regenerating at "
                            "0.6-1.0C charge for 15-40 s and a stop at lights or a crossing, no current, for 10-40 s; at the "
                            "skate park 25 lines of pushing off hard at 1.8-2.4C for 5-10 s, carving at 0.5-0.9C for 10-25 s "
                            "and braking at 0.6-0.9C charge for 3-6 s; the board carried for 5-10 min, no current; home over 5 "
                            "hills the same way), 15 min rest; 1.1 h, down to about 32 % (counted in the set's 5 A h); sampled every "
                            "3 s, 2 mV noise (a noisy channel beside the motor drive); DFN (lumped thermal) data handed to the "
                            "isothermal DFN. effect_rmse_mV is what the self-heating alone does"},
                   initial_soc=0.95, seed=4606, period=3, noise=2e-3, compare=lion.DFN())
    # au7: pair, partially reversible lithium plating in cold rapid recharges and a 4 mOhm contact resistance, a mobile
    # EV-charging robot in a park-and-ride car park, -6 degC, 4 s, 0.5 mV, SPMe
    if run("au7"):
        def robot_cell(plating, contact):
            q = with_okane2022(chen(), PLATING_KEYS) if plating else chen()
            q.update({"Contact resistance [Ohm]": contact}, check_already_exists=False)
            return at(q, -6)
        both_model = lambda: lion.SPMe(options={"lithium plating": "partially reversible", "contact resistance": "true"})
        plating_model = lambda: lion.SPMe(options={"lithium plating": "partially reversible"})
        contact_model = lambda: lion.SPMe(options={"contact resistance": "true"})
        recharge = ["Charge at 1.4C for 480 seconds", "Charge at 1.0C for 480 seconds", "Charge at 0.5C for 480 seconds"]
        steps = ["Rest for 10 minutes"] + charging_robot_shift_steps(4607, 6, 2, recharge) + ["Rest for 20 minutes"]
        name = "au7_plating_partially_reversible_and_contact_4mOhm_ev_charging_robot_frost_minus6C_4s_0p5mV_spme"
        write_case(root, name, both_model(), robot_cell(True, 0.004), steps,
                   {"effect": "lithium_plating+contact_resistance", "candidate_model": "spme",
                    "accept": ["plating", "|".join(contact_words)], "ambient_temperature_K": 267.15,
                    "note": "two effects: partially reversible lithium plating (PyBaMM 'partially reversible', OKane2022's "
                            "plating parameters as they are: rate constant 1e-9 m/s, transfer coefficient 0.65, dead-lithium "
                            "decay constant 1e-6 1/s) in the robot's rapid recharges at its base at -6 degC (an open-air "
                            "park-and-ride car park on a frosty morning, the battery not preconditioned; isothermal, not "
                            "recorded): the first recharge plates up to 0.0046 mol (0.124 A h), nearly all of it stripped again in the wait and the next car's charge (1.3e-5 mol left at the end); and a 4 mOhm contact resistance (a worn charging-connector contact in the "
                            "robot's battery path: about 20 mV at 1C). A mobile EV-charging robot's shift per cell from 65 % "
                            "SOC: 10 min rest, 6 cars (charging_robot_shift_steps seed 4607: the drive across the car park to "
                            "the car at 0.12-0.2C for 1-3 min, the plug-in and the handshake at 0.02C for 30-60 s, the car's "
                            "charge from the robot's battery at 0.85-1.1C for 8-12 min and its taper at 0.4-0.6C for 3-6 min, "
                            "the drive on at 0.12-0.2C for 1-3 min; after every 2 cars, not after the last, docked at its "
                            "grid-connected base, the rapid recharge stepping down, 1.4C, 1.0C and 0.5C for 8 min each, "
                            "time-limited, up to 4.17 V at most, then waiting for the next booking, no current, 5-15 min), "
                            "20 min rest; 3.6 h, down to about 26 %, up to about 64 %, down to about 19 %, up to about 58 %, down to about 24 % (counted in the set's 5 A h); sampled every 4 s, 0.5 mV noise (a quiet channel); "
                            "SPMe (with plating and contact resistance) data handed to the plain SPMe. "
                            "spme_plating_only_rmse_mV: the plating SPMe without the contact resistance against the recording "
                            "(what the contact leaves); spme_contact_only_rmse_mV: the contact-resistance SPMe without plating "
                            "(what the plating leaves)"},
                   initial_soc=0.65, seed=4607, period=4, noise=5e-4, compare=lion.SPMe())
        replay_rmse(root, name, plating_model(), robot_cell(True, 0.0), steps, 0.65, "spme_plating_only_rmse_mV", period=4)
        replay_rmse(root, name, contact_model(), robot_cell(False, 0.004), steps, 0.65, "spme_contact_only_rmse_mV", period=4)
    # au8: SEI growth limited by electron migration (x5000), an electric motorcycle taxi's day with part top-ups, 33 degC, 10 s,
    # 0.7 mV, SPM
    if run("au8"):
        p = at(scaled(chen(), "SEI electron conductivity [S.m-1]", 5000.0), 33)
        steps = ["Rest for 10 minutes"] + moto_taxi_day_steps(4608, 6, 4) + ["Rest for 20 minutes"]
        write_case(root, "au8_sei_electron_migration_x5000_motorcycle_taxi_day_part_top_ups_33C_10s_0p7mV_spm",
                   lion.SPM(options={"SEI": "electron-migration limited"}), p, steps,
                   {"effect": "sei_growth", "candidate_model": "spm", "accept": ["SEI"] + lithium_words, "ambient_temperature_K": 306.15,
                    "note": "SEI growth limited by the migration of electrons through the film (PyBaMM 'electron-migration "
                            "limited', distributed film resistance; SEI electron conductivity x5000, 4.5e-10 S/m instead of "
                            "Chen 2020's 8.95e-14: a cell from a lot whose formation left a poorly insulating SEI; the film's "
                            "other parameters Chen 2020's): 0.0043 mol of lithium (0.116 A h, 2.3 % of the set's 5 A h) lost to the SEI over the day, fastest at first (0.032 A h after 1 h, 0.047 after 2 h, 0.071 after 4 h, 0.104 after 8 h). A lithium-inventory loss growing through the recording "
                            "is the SEI's nearest stand-in and is accepted, as as2. At 33 degC (a hot tropical city; isothermal, "
                            "not recorded). An electric motorcycle taxi's (a boda-boda's) day per cell from 92 % SOC: 10 min "
                            "rest, 4 spells of 6 trips (moto_taxi_day_steps seed 4608: each trip 4-8 stretches through traffic "
                            "of a pull-away at 1.3-1.8C for 5-10 s, riding at 0.5-0.9C for 20-90 s and braking with regeneration "
                            "at 0.3-0.5C charge for 3-6 s, then waiting at the stage for the next fare, no current, 3-15 min; "
                            "after each spell but the last a part top-up at a charging kiosk at 0.5C putting back 85 % of what "
                            "the spell took, time-limited, while the rider eats or rests, then no current for 10-20 min), 20 "
                            "min rest; 10.1 h, down to about 44, 40 and 37 % before the top-ups, up to about 85, 78 and 72 % after them, down to about 27 % at the end (counted in the set's 5 A h; the SEI takes its lithium out of "
                            "that); sampled every 10 s (the fleet's telematics), 0.7 mV noise; SPM (with SEI) data handed to "
                            "the plain SPM. effect_rmse_mV is what the SEI (its lithium loss and its film) does"},
                   initial_soc=0.92, seed=4608, period=10, noise=7e-4, compare=lion.SPM())


BATCHES = {"u": batch_u, "v": batch_v, "w": batch_w, "x": batch_x, "y": batch_y, "z": batch_z, "q": batch_q, "r": batch_r, "s": batch_s, "t": batch_t, "p": batch_p, "o": batch_o, "n": batch_n, "m": batch_m, "l": batch_l, "k": batch_k, "j": batch_j, "i": batch_i, "h": batch_h, "f": batch_f, "e": batch_e, "g": batch_g, "d": batch_d, "c": batch_c, "a": batch_a, "b": batch_b, "ab": batch_ab, "ac": batch_ac, "ad": batch_ad, "ae": batch_ae, "af": batch_af, "ag": batch_ag, "ah": batch_ah, "ai": batch_ai, "aj": batch_aj, "ak": batch_ak, "ak7d": remake_ak7, "al": batch_al, "am": batch_am, "an": batch_an, "ao": batch_ao, "ap": batch_ap, "aq": batch_aq, "ar": batch_ar, "as": batch_as, "at": batch_at, "au": batch_au}

if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else "out/unseen-cases"
    # batch keys, comma-separated ("ab" or "ab,x"); all by default
    keys = [k.strip() for k in sys.argv[2].split(",") if k.strip()] if len(sys.argv) > 2 else list(BATCHES)
    unknown = [k for k in keys if k not in BATCHES]
    if unknown:
        sys.exit(f"unknown batch keys {unknown}; known: {','.join(BATCHES)}")
    for name in keys:
        BATCHES[name](root)
