#!/usr/bin/env python3
"""Work-precision comparison of cellstudio and PyBaMM (IDAKLU): voltage error against a tight
reference vs wall time per solve, rtol = atol from 1e-3 to 1e-8, SPM / SPMe / DFN, 1C and the
pulse protocol, both tools on one plot.

Development script (PyBaMM is never a runtime dependency of the crate):

    /work/venv-pybamm/bin/python scripts/accuracy_vs_pybamm.py   # writes the references once
    CARGO_TARGET_DIR=... /work/venv-pybamm/bin/python scripts/work_precision.py [--rounds 3]

What is compared, and why it is fair
------------------------------------
* Same model equations on the same mesh (Chen2020, 20 volumes per x-domain and per particle):
  since issue 14 the two agree to 1e-7 mV (SPMe, DFN) and 2e-5 mV (SPM) at rtol 1e-10, so one
  reference serves both: PyBaMM at rtol = atol = 1e-10 (``out/pybamm_tight/``, written by
  ``accuracy_vs_pybamm.py``).
* Timed solves return each solver's own steps: PyBaMM ``solver.solve(model, [0, t_end])``
  with no ``t_interp`` (built once per rtol, current fixed; the pulse as Heaviside windows in
  t, one solve call); ours ``simulate`` with ``t_eval = None``
  (``examples/work_precision.rs``, timed inside the process around ``simulate``; PyBaMM's
  time is the Python-level ``solve`` call, which includes building its Solution object).
* Same outputs on both sides: the voltage at every step. PyBaMM's IDAKLU computes it inside
  the solver (``output_variables=["Voltage [V]"]``, its fastest path, the one PyBOP takes) and
  the timed region reads ``sol["Voltage [V]"].entries``; ours returns voltage, current and
  temperature at every step (``SimOptions::integrals`` off, as fits run).
  ``--ours-integrals`` adds our charge and energy quadrature over every step, which PyBaMM is
  not asked for (the comparison until 2026-12-01: 10-35 % of our SPM and SPMe solves).
  ``--pybamm-outputs state`` times PyBaMM returning the full state with no voltage read
  (the comparison before 2026-11-29: PyBaMM then does less than we do).
* Error: RMS of the voltage at the reference's times, from each solver's own dense output
  (PyBaMM ``t_interp`` = those times, ours ``t_eval``), an untimed second solve with the same
  settings. Times exactly at a current step are skipped (left/right limit ambiguity).
* Runs are interleaved: each round times every configuration on both sides (``--repeats``
  solves each, median), and the reported time is the median over ``--rounds`` rounds.
* Ratio at matched accuracy: for each of our points, PyBaMM's time at the same error,
  interpolated log-log along PyBaMM's curve (blank where our error is outside PyBaMM's range).

Writes ``out/work_precision/work_precision.{csv,md,svg}`` and prints the Markdown.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
OURS_BIN = TARGET / "release" / "examples" / "work_precision"
MODELS = {"spm": "SPM", "spme": "SPMe", "dfn": "DFN"}
PULSE_REST0, PULSE_ON, PULSE_OFF, PULSE_N = 60.0, 10.0, 600.0, 6
PULSE_END = PULSE_REST0 + PULSE_N * (PULSE_ON + PULSE_OFF)


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def read_ref(path: Path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    t, v = np.asarray(d["time_s"]), np.asarray(d["voltage_V"])
    keep = np.ones(len(t), dtype=bool)
    dup = np.flatnonzero(np.diff(t) == 0)
    keep[dup] = False
    keep[dup + 1] = False
    return t[keep], v[keep]


class Pybamm:
    def __init__(self, outputs: str):
        import pybamm

        self.outputs = outputs
        self.pb = pybamm
        self.pv = pybamm.ParameterValues("Chen2020")
        self.i1c = float(self.pv["Nominal cell capacity [A.h]"])
        self.sims = {}

    def sim(self, model: str, case: str, rtol: float):
        key = (model, case, rtol)
        if key not in self.sims:
            pb = self.pb
            p = self.pv.copy()
            if case == "pulse":
                current = 0
                for k in range(PULSE_N):
                    start = PULSE_REST0 + k * (PULSE_ON + PULSE_OFF)
                    current = current + self.i1c * (pb.t >= start) * (pb.t < start + PULSE_ON)
                p["Current function [A]"] = current
                t_end = PULSE_END
            else:
                rate = float(case.rstrip("C"))
                p["Current function [A]"] = rate * self.i1c
                t_end = 1.3 * 3600.0 / rate
            variables = ["Voltage [V]"] if self.outputs == "voltage" else None
            s = pb.Simulation(getattr(pb.lithium_ion, MODELS[model])(), parameter_values=p,
                              solver=pb.IDAKLUSolver(rtol=rtol, atol=rtol, output_variables=variables))
            s.build()
            s.solver.solve(s.built_model, [0.0, t_end])  # warm-up: sets up the solver
            self.sims[key] = (s, t_end)
        return self.sims[key]

    def time_solves(self, model, case, rtol, repeats):
        s, t_end = self.sim(model, case, rtol)
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            sol = s.solver.solve(s.built_model, [0.0, t_end])
            if self.outputs == "voltage":
                sol["Voltage [V]"].entries
            times.append(time.perf_counter() - t0)
        return statistics.median(times), len(sol.t)

    def error(self, model, case, rtol, t_ref, v_ref):
        s, t_end = self.sim(model, case, rtol)
        tq = t_ref[t_ref < t_end - 1e-6]
        if case == "pulse":  # step-edge times are not outputs of ours either
            edges = [PULSE_REST0 + k * (PULSE_ON + PULSE_OFF) + d for k in range(PULSE_N) for d in (0.0, PULSE_ON)]
            tq = tq[~np.isin(np.round(tq, 6), np.round(edges, 6))]
        sol = s.solver.solve(s.built_model, [0.0, t_end], t_interp=tq)
        ts = np.asarray(sol.t)
        vs = np.asarray(sol["Voltage [V]"].entries)
        # the solver adds step edges and the event time: keep the requested, single times
        single = np.ones(len(ts), dtype=bool)
        d = np.flatnonzero(np.diff(ts) == 0)
        single[d] = False
        single[d + 1] = False
        sel = single & np.isin(ts, tq)
        ref = np.interp(ts[sel], t_ref, v_ref)
        e = (vs[sel] - ref) * 1e3
        return float(np.sqrt(np.mean(e * e))), float(np.max(np.abs(e)))


def ours(model, case, rtol, repeats, ref_path, integrals=False):
    extra = ["integrals"] if integrals else []
    out = subprocess.run([str(OURS_BIN), model, case, repr(rtol), str(repeats), str(ref_path), *extra],
                         cwd=REPO, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def matched_ratio(err, t_ours, pyb_pts):
    """PyBaMM's time at error `err` (log-log interpolation along its curve) over ours."""
    pts = sorted((e, t) for e, t in pyb_pts if e > 0)
    for (e0, t0), (e1, t1) in zip(pts, pts[1:]):
        if e0 <= err <= e1 and e1 > e0:
            w = (math.log(err) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t1) - math.log(t0))) / t_ours
    return None


def svg(results, models, cases, path: Path):
    """Log-log panels (error in mV vs solve time in ms), one per model x case."""
    W, H, pad = 300, 240, 45
    cols, rows = len(cases), len(models)
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W * cols}" height="{H * rows}" font-family="sans-serif" font-size="10">']
    for r, m in enumerate(models):
        for c, case in enumerate(cases):
            pts = [x for x in results if x["model"] == m and x["case"] == case and x["rms_mV"] > 0]
            if not pts:
                continue
            ox, oy = c * W, r * H
            lx = [math.log10(p["solve_s"] * 1e3) for p in pts]
            ly = [math.log10(p["rms_mV"]) for p in pts]
            x0, x1 = math.floor(min(lx)), math.ceil(max(lx))
            y0, y1 = math.floor(min(ly)), math.ceil(max(ly))
            X = lambda v: ox + pad + (v - x0) / max(x1 - x0, 1e-9) * (W - pad - 10)
            Y = lambda v: oy + H - pad + 10 - (v - y0) / max(y1 - y0, 1e-9) * (H - pad - 10)
            parts.append(f'<rect x="{ox + pad}" y="{oy + 10}" width="{W - pad - 10}" height="{H - pad}" fill="none" stroke="#888"/>')
            parts.append(f'<text x="{ox + pad + 4}" y="{oy + 22}">{MODELS[m]} {case}</text>')
            for v in range(x0, x1 + 1):
                parts.append(f'<text x="{X(v) - 8}" y="{oy + H - pad + 24}">1e{v}</text>')
            for v in range(y0, y1 + 1):
                parts.append(f'<text x="{ox + 4}" y="{Y(v) + 3}">1e{v}</text>')
            parts.append(f'<text x="{ox + W // 2 - 20}" y="{oy + H - 6}">solve (ms)</text>')
            for side, colour in (("pybamm", "#d62728"), ("cellstudio", "#1f77b4")):
                sp = sorted((p for p in pts if p["side"] == side), key=lambda p: p["rtol"])
                xy = " ".join(f"{X(math.log10(p['solve_s'] * 1e3)):.1f},{Y(math.log10(p['rms_mV'])):.1f}" for p in sp)
                parts.append(f'<polyline points="{xy}" fill="none" stroke="{colour}"/>')
                for p in sp:
                    parts.append(f'<circle cx="{X(math.log10(p["solve_s"] * 1e3)):.1f}" cy="{Y(math.log10(p["rms_mV"])):.1f}" r="2.5" fill="{colour}"/>')
            if r == 0 and c == 0:
                parts.append(f'<text x="{ox + W - 110}" y="{oy + 22}" fill="#d62728">PyBaMM IDAKLU</text>')
                parts.append(f'<text x="{ox + W - 110}" y="{oy + 34}" fill="#1f77b4">cellstudio</text>')
            parts.append(f'<text x="{ox + pad + 4}" y="{oy + 34}">RMS error (mV)</text>')
    parts.append("</svg>")
    path.write_text("\n".join(parts))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--models", default="spm,spme,dfn")
    ap.add_argument("--cases", default="1C,pulse")
    ap.add_argument("--rtols", default="1e-3,1e-4,1e-5,1e-6,1e-7,1e-8")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--refs", type=Path, default=REPO / "out" / "pybamm_tight")
    ap.add_argument("--out", type=Path, default=REPO / "out" / "work_precision")
    ap.add_argument("--pybamm-outputs", choices=["voltage", "state"], default="voltage",
                    help="what PyBaMM's timed solve returns: the voltage at its steps (as ours) or its full state")
    ap.add_argument("--ours-integrals", action="store_true",
                    help="ours also integrates the charge and energy over its steps (PyBaMM is not asked for them; the comparison before 2026-12-01)")
    args = ap.parse_args()
    if not OURS_BIN.exists():
        sys.exit(f"{OURS_BIN} missing: cargo build --release --example work_precision")
    models, cases = args.models.split(","), args.cases.split(",")
    rtols = [float(r) for r in args.rtols.split(",")]
    pyb = Pybamm(args.pybamm_outputs)
    configs = [(m, c, r) for m in models for c in cases for r in rtols]
    refs = {}
    for m in models:
        for c in cases:
            path = args.refs / f"{m}_{c}.csv"
            if not path.exists():
                sys.exit(f"{path} missing: run scripts/accuracy_vs_pybamm.py first")
            refs[(m, c)] = (path, *read_ref(path))
    log(f"building {len(configs)} PyBaMM configurations")
    for cfg in configs:
        pyb.sim(*cfg)
    times = {(side, cfg): [] for side in ("pybamm", "cellstudio") for cfg in configs}
    info = {}
    for rnd in range(args.rounds):
        log(f"round {rnd + 1}/{args.rounds}")
        for cfg in configs:
            m, c, r = cfg
            t, n = pyb.time_solves(m, c, r, args.repeats)
            times[("pybamm", cfg)].append(t)
            info.setdefault(("pybamm", cfg), {"points": n})
            o = ours(m, c, r, args.repeats, refs[(m, c)][0], args.ours_integrals)
            times[("cellstudio", cfg)].append(o["solve_s"])
            info[("cellstudio", cfg)] = o
    results = []
    for cfg in configs:
        m, c, r = cfg
        path, t_ref, v_ref = refs[(m, c)]
        rms, mx = pyb.error(m, c, r, t_ref, v_ref)
        results.append({"side": "pybamm", "model": m, "case": c, "rtol": r, "solve_s": statistics.median(times[("pybamm", cfg)]),
                        "points": info[("pybamm", cfg)]["points"], "rms_mV": rms, "max_mV": mx})
        o = info[("cellstudio", cfg)]
        results.append({"side": "cellstudio", "model": m, "case": c, "rtol": r, "solve_s": statistics.median(times[("cellstudio", cfg)]),
                        "points": o["points"], "rms_mV": o["rms_mV"], "max_mV": o["max_mV"]})
    args.out.mkdir(parents=True, exist_ok=True)
    with (args.out / "work_precision.csv").open("w") as f:
        f.write("side,model,case,rtol,solve_s,points,rms_mV,max_mV\n")
        for x in results:
            f.write(f"{x['side']},{x['model']},{x['case']},{x['rtol']:g},{x['solve_s']:.6g},{x['points']},{x['rms_mV']:.4g},{x['max_mV']:.4g}\n")
    svg(results, models, cases, args.out / "work_precision.svg")
    ours_outputs = "voltage, current, temperature, charge and energy" if args.ours_integrals else "voltage, current and temperature"
    lines = [f"Work-precision, median of {args.rounds} interleaved rounds x {args.repeats} solves; PyBaMM returns {args.pybamm_outputs} at its steps; ours {ours_outputs}; error = RMS voltage vs PyBaMM rtol 1e-10 (mV); "
             "ratio = PyBaMM's time at our error (log-log interpolation) / ours.\n",
             "| model | case | rtol | PyBaMM error (mV) | PyBaMM solve (ms) | PyBaMM points | ours error (mV) | ours solve (ms) | ours points | ratio at matched accuracy |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for m in models:
        for c in cases:
            pp = [x for x in results if x["side"] == "pybamm" and x["model"] == m and x["case"] == c]
            oo = [x for x in results if x["side"] == "cellstudio" and x["model"] == m and x["case"] == c]
            curve = [(x["rms_mV"], x["solve_s"]) for x in pp]
            for p, o in zip(pp, oo):
                ratio = matched_ratio(o["rms_mV"], o["solve_s"], curve)
                lines.append(f"| {MODELS[m]} | {c} | {p['rtol']:g} | {p['rms_mV']:.2e} | {p['solve_s'] * 1e3:.2f} | {p['points']} | "
                             f"{o['rms_mV']:.2e} | {o['solve_s'] * 1e3:.2f} | {o['points']} | {'' if ratio is None else f'{ratio:.1f}x'} |")
    md = "\n".join(lines)
    (args.out / "work_precision.md").write_text(md + "\n")
    print(md)


if __name__ == "__main__":
    main()
