#!/usr/bin/env bash
# A sweep split over a Slurm array job: task k of N evaluates shard k/N of the study's grid
# and writes <output.dir>.shard-k-of-N/shard.json; a last job merges the shards into the
# ordinary sweep output (sweep.csv, sweep.json, plots), bit for bit what one run writes.
#
#   sbatch --array=1-8 scripts/cluster/slurm_sweep.sh designs/gravimetric_chen2020.toml 8
#   # when every task has finished (or with --dependency=afterok:<array job id>):
#   cellstudio sweep designs/gravimetric_chen2020.toml --merge out/gravimetric_chen2020.shard-*-of-8
#
#SBATCH --job-name=cellstudio-sweep
#SBATCH --cpus-per-task=4
#SBATCH --time=01:00:00
set -euo pipefail
study=${1:?usage: slurm_sweep.sh STUDY.toml SHARDS}
shards=${2:?usage: slurm_sweep.sh STUDY.toml SHARDS}
export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
exec cellstudio sweep "$study" --shard "${SLURM_ARRAY_TASK_ID}/${shards}"
