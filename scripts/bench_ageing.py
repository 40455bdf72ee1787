"""Side-by-side timing of SEI cycling: N CC-CV cycles of the SPM (or `--model spme|dfn`) with PyBaMM's "reaction
limited" SEI (Chen2020; the cycle of tests/suite/sei.rs), ours (`cellstudio cycle`) against
PyBaMM 26.10 (IDAKLU), both at rtol = atol = TOL, interleaved, medians over --rounds.

Accuracy of each side: the largest difference over the cycles of the discharge capacity
(mA h) and of the lithium lost to the SEI (relative), against PyBaMM at rtol = atol = 1e-10
(one untimed run; `--reference-tol` for a looser one, e.g. for the DFN).

Times: ours, the cycles inside the process (`wall_time_s` of cycles.json, the model build
excluded: about a millisecond) and the whole process; PyBaMM, its first `Simulation.solve`
(which builds and discretises the model, as a user's run does) and a second `solve` of the
same simulation (built already).

    CARGO_TARGET_DIR=... cargo build --release
    CARGO_TARGET_DIR=... .venv/bin/python scripts/bench_ageing.py [--cycles 100] [--rounds 3]
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pybamm

sys.path.insert(0, str(Path(__file__).resolve().parent))
from make_sei_reference import CYCLE, cycle_rows, simulation  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
BIN = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target")) / "release" / "cellstudio"
MODELS = {"spm": pybamm.lithium_ion.SPM, "spme": pybamm.lithium_ion.SPMe, "dfn": pybamm.lithium_ion.DFN}
OPTION = "reaction limited"


def ours(cycles, tol, workdir, model="spm"):
    """(cycles wall time (s), process wall time (s), rows as cycle_rows gives them)."""
    steps = ",\n".join(f'    "{s}"' for s in CYCLE)
    study = Path(workdir) / "study.toml"
    study.write_text(f'name = "bench"\n[cell]\nparameter_set = "chen2020"\n[model]\nkind = "{model}"\n'
                     f'submodels = {{ sei = "{OPTION}" }}\n[cycling]\ncycles = {cycles}\ntolerance = {tol}\n'
                     f'cycle = [\n{steps}\n]\n[output]\ndir = "out"\n')
    start = time.perf_counter()
    subprocess.run([str(BIN), "cycle", str(study)], cwd=workdir, check=True, capture_output=True)
    process = time.perf_counter() - start
    out = json.loads((Path(workdir) / "out" / "cycles.json").read_text())
    rows = [[c["cycle"], c["discharge_capacity_ah"], c["lithium_lost_to_sei_mol"], c["sei_thickness_m"]] for c in out["cycles"]]
    return out["wall_time_s"], process, rows


def pybamm_run(cycles, tol, model="spm"):
    """(first solve (s), second solve (s), rows)."""
    sim = simulation(MODELS[model], OPTION, cycles=cycles, tol=tol)
    start = time.perf_counter()
    sim.solve()
    first = time.perf_counter() - start
    start = time.perf_counter()
    sol = sim.solve()
    return first, time.perf_counter() - start, cycle_rows(sol)


def errors(rows, ref):
    dq = max(abs(a[1] - b[1]) for a, b in zip(rows, ref)) * 1e3
    dli = max(abs(a[2] / b[2] - 1) for a, b in zip(rows, ref))
    return dq, dli


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cycles", type=int, default=100)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--tols", type=float, nargs="+", default=[1e-6, 1e-8])
    ap.add_argument("--model", choices=sorted(MODELS), default="spm")
    ap.add_argument("--reference-tol", type=float, default=1e-10, help="PyBaMM's rtol = atol for the reference run")
    args = ap.parse_args()
    print(f"reference: PyBaMM at {args.reference_tol:g}, {args.cycles} cycles ...", file=sys.stderr, flush=True)
    start = time.perf_counter()
    ref = cycle_rows(simulation(MODELS[args.model], OPTION, cycles=args.cycles, tol=args.reference_tol).solve())
    print(f"reference took {time.perf_counter() - start:.1f} s", file=sys.stderr, flush=True)
    times = {t: {"ours": [], "ours_process": [], "pybamm_first": [], "pybamm_again": []} for t in args.tols}
    acc = {}
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.rounds):
            for tol in args.tols:
                o, op, orows = ours(args.cycles, tol, work, args.model)
                f, a, prows = pybamm_run(args.cycles, tol, args.model)
                for k, v in zip(["ours", "ours_process", "pybamm_first", "pybamm_again"], [o, op, f, a]):
                    times[tol][k].append(v)
                acc[tol] = (errors(orows, ref), errors(prows, ref))
                print(f"round {r + 1} tol {tol:g}: ours {o:.3f} s ({op:.3f} s process), PyBaMM {f:.3f} s first, {a:.3f} s again",
                      file=sys.stderr, flush=True)
    print(f"| rtol = atol | ours (s) | ours, process (s) | PyBaMM first solve (s) | PyBaMM again (s) | ratio (first / again) "
          f"| ours: capacity (mA h), lithium lost (rel.) | PyBaMM: same |")
    print("|---|---|---|---|---|---|---|---|")
    for tol in args.tols:
        m = {k: statistics.median(v) for k, v in times[tol].items()}
        (oq, oli), (pq, pli) = acc[tol]
        print(f"| {tol:g} | {m['ours']:.3f} | {m['ours_process']:.3f} | {m['pybamm_first']:.2f} | {m['pybamm_again']:.2f} "
              f"| {m['pybamm_first'] / m['ours']:.0f}x / {m['pybamm_again'] / m['ours']:.0f}x | {oq:.1e}, {oli:.1e} | {pq:.1e}, {pli:.1e} |")
    print(f"\n{args.cycles} {args.model.upper()} cycles with reaction-limited SEI, medians of {args.rounds} interleaved rounds, "
          f"errors against PyBaMM at {args.reference_tol:g}; PyBaMM {pybamm.__version__}.")


if __name__ == "__main__":
    main()
