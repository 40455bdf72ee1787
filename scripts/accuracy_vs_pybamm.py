#!/usr/bin/env python3
"""Model agreement with PyBaMM on the same mesh, as both solvers' tolerances tighten.

Development script (not part of the crate; PyBaMM is never a runtime dependency).

    /work/venv-pybamm/bin/python scripts/accuracy_vs_pybamm.py                # all cases
    /work/venv-pybamm/bin/python scripts/accuracy_vs_pybamm.py --models dfn --ours-rtol 1e-8

Environment: scripts/requirements.txt (PyBaMM 26.10.1.1, the version of the references).

1. PyBaMM side: SPM, SPMe, DFN (Chen2020, PyBaMM's default mesh: 20 volumes per x-domain and
   per particle), IDAKLU at rtol = atol = ``--pybamm-rtol`` (default 1e-10), constant-current
   discharges at 0.5C, 1C, 2C to 2.5 V, sampled every 2 s, and the 1C pulse protocol
   (Experiment, sampled every 1 s).  Curves are written in the format of tests/data
   (``time_s,current_A,voltage_V,discharge_capacity_Ah``) to ``--out``
   (default out/pybamm_tight/).  Skipped when the file exists unless ``--regenerate``.
2. Our side: ``$CARGO_TARGET_DIR/release/examples/check_reference`` (or ``$CHECK_BIN``) with ``REF_DIR`` pointing at those
   curves and ``BENCH_TOL`` = each of ``--ours-rtol`` (rtol = atol), outputs at the
   reference's times (dense output, no interpolation of ours).
3. Prints a Markdown table of the RMS and max voltage difference (mV) per case and rtol.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
CHECK_BIN = Path(os.environ.get("CHECK_BIN", TARGET / "release" / "examples" / "check_reference"))
MODELS = {"spm": "SPM", "spme": "SPMe", "dfn": "DFN"}
CC_CASES = {"0.5C": 0.5, "1C": 1.0, "2C": 2.0}


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def pybamm_curve(name: str, case: str, rtol: float):
    import pybamm

    pv = pybamm.ParameterValues("Chen2020")
    model = getattr(pybamm.lithium_ion, MODELS[name])()
    solver = pybamm.IDAKLUSolver(rtol=rtol, atol=rtol)
    if case == "pulse":
        steps = ["Rest for 60 seconds"] + ["Discharge at 1C for 10 seconds", "Rest for 10 minutes"] * 6
        exp = pybamm.Experiment(steps, period="1 second")
        sim = pybamm.Simulation(model, parameter_values=pv, experiment=exp, solver=solver)
        sol = sim.solve()
    else:
        rate = CC_CASES[case]
        pv["Current function [A]"] = rate * float(pv["Nominal cell capacity [A.h]"])
        sim = pybamm.Simulation(model, parameter_values=pv, solver=solver)
        t_end = 1.3 * 3600.0 / rate
        sol = sim.solve([0.0, t_end], t_interp=np.arange(0.0, t_end, 2.0))
    cols = [np.asarray(sol[v].entries, dtype=float) for v in ("Time [s]", "Current [A]", "Voltage [V]", "Discharge capacity [A.h]")]
    return np.column_stack(cols)


def write_curve(path: Path, data: np.ndarray) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w") as f:
        f.write("time_s,current_A,voltage_V,discharge_capacity_Ah\n")
        for row in data:
            f.write(",".join(repr(float(x)) for x in row) + "\n")


def ours(ref_dir: Path, rtol: float) -> dict[str, tuple[float, float]]:
    env = dict(os.environ, REF_DIR=str(ref_dir), BENCH_TOL=repr(rtol))
    out = subprocess.run([str(CHECK_BIN)], cwd=REPO, env=env, check=True, capture_output=True, text=True).stdout
    res = {}
    for line in out.splitlines():
        m = re.match(r"(\S+)\s+rms\s+([\d.eE+-]+) mV max\s+([\d.eE+-]+) mV", line)
        if m:
            res[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return res


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pybamm-rtol", type=float, default=1e-10)
    ap.add_argument("--ours-rtol", default="1e-6,1e-8,1e-10")
    ap.add_argument("--models", default="spm,spme,dfn")
    ap.add_argument("--cases", default="0.5C,1C,2C,pulse")
    ap.add_argument("--out", type=Path, default=REPO / "out" / "pybamm_tight")
    ap.add_argument("--regenerate", action="store_true")
    args = ap.parse_args()
    models = args.models.split(",")
    cases = args.cases.split(",")
    for name in models:
        for case in cases:
            path = args.out / f"{name}_{case}.csv"
            if path.exists() and not args.regenerate:
                continue
            log(f"PyBaMM {MODELS[name]} {case} at rtol = atol = {args.pybamm_rtol:g}")
            write_curve(path, pybamm_curve(name, case, args.pybamm_rtol))
    if not CHECK_BIN.exists():
        sys.exit(f"{CHECK_BIN} missing: cargo build --release --examples")
    rtols = [float(r) for r in args.ours_rtol.split(",")]
    results = {r: ours(args.out, r) for r in rtols}
    print(f"RMS / max |V_ours - V_PyBaMM| (mV), PyBaMM IDAKLU rtol = atol = {args.pybamm_rtol:g}, same mesh\n")
    print("| case | " + " | ".join(f"ours rtol {r:g}" for r in rtols) + " |")
    print("|---|" + "---|" * len(rtols))
    for name in models:
        for case in cases:
            key = f"{name}_{case}"
            cells = []
            for r in rtols:
                v = results[r].get(key)
                cells.append("n/a" if v is None else f"{v[0]:.1e} / {v[1]:.1e}")
            print(f"| {MODELS[name]} {case} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
