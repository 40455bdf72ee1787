"""Multi-cycle recordings for the diagnosis's ageing candidate (issue 15 item 7), made by
PyBaMM in the diagnosis bench's format (Chen 2020, IDAKLU at rtol = atol = 1e-8, 1 mV
noise): 12 CC-CV cycles of the SPM
- g1: with SEI growth (PyBaMM's "reaction limited", its SEI exchange current x20, so that
  twelve cycles lose about 1 % of the lithium), handed the SPM without SEI: SEI named;
- g2: a control without ageing: nothing named;
- g3: 4 % less cyclable lithium from the start and no ageing: a fixed offset that does not
  drift from cycle to cycle, lithium inventory named, not SEI growth.

    .venv/bin/python scripts/make_ageing_cases.py tests/data/diagnosis-ageing
"""

import sys

import pybamm

from make_unseen_cases import chen, scaled, write_case

CYCLE = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"]
CYCLES = 12
PERIOD = 30


def main(root):
    lion = pybamm.lithium_ion
    steps = CYCLE * CYCLES
    p = scaled(chen(), "SEI reaction exchange current density [A.m-2]", 20.0)
    write_case(root, "g1_sei_growth_12_cycles_spm", lion.SPM({"SEI": "reaction limited"}), p, steps,
               {"effect": "sei_growth", "candidate_model": "spm", "accept": ["SEI"],
                "note": "reaction-limited SEI growth with PyBaMM's Chen 2020 SEI parameters, exchange current x20; 12 CC-CV cycles "
                        "(1C to 3.0 V, 10 min rest, 1C to 4.1 V, hold to C/20, 10 min rest) from the set's initial state; 30 s sampling"},
               seed=201, period=PERIOD, compare=lion.SPM())
    write_case(root, "g2_control_12_cycles_spm", lion.SPM(), chen(), steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing physics"],
                "note": "no ageing, the same 12 CC-CV cycles; 30 s sampling"},
               seed=202, period=PERIOD, compare=lion.SPM())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.96)
    write_case(root, "g3_fixed_inventory_loss_12_cycles_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["lithium inventory"],
                "note": "4 % less lithium in the negative electrode from the start, no ageing (a fixed stoichiometry offset); "
                        "the same 12 CC-CV cycles; 30 s sampling"},
               seed=203, period=PERIOD, compare=lion.SPM())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/diagnosis-ageing")
