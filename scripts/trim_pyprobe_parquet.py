"""A small sample of PyProBE's LG M50T Parquet recording for the reader tests
(tests/data/cycler/pyprobe_lgm50t_cellC_trimmed.parquet): the rows with `Time [s]` in
16600-19300 s (the end of the 2 h rest, cycler step 3, step 4 and the first ~2050 s of the
C/10 discharge, step 5, as behind ../shared/recordings/lgm50t_25C_C10_pocv_discharge_cellC.csv),
every column as stored, written again with LZ4 compression as PyProBE's default
(`compression_priority="performance"`) writes it.

Source: ImperialCollegeLondon/PyProBE commit b6302b79c34a2748c2aee90e217457b0977339cb,
`tests/sample_data/LGM50/NDK - LG M50 deg - exp 2,2 - rig 3 - 25degC - cell C - BoL - RPT0_short_CA4.parquet`
(BSD-3-Clause, tests/data/cycler/LICENSE-PyProBE.txt).

    pip install pyarrow
    python scripts/trim_pyprobe_parquet.py SOURCE.parquet tests/data/cycler/pyprobe_lgm50t_cellC_trimmed.parquet
"""

import sys

import pyarrow.compute as pc
import pyarrow.parquet as pq

source, target = sys.argv[1], sys.argv[2]
table = pq.read_table(source)
t = table["Time [s]"]
kept = table.filter(pc.and_(pc.greater_equal(t, 16600.0), pc.less_equal(t, 19300.0)))
pq.write_table(kept, target, compression="lz4")
print(f"{kept.num_rows} rows of {table.num_rows} -> {target}")
