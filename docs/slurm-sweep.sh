#!/bin/bash
# `drape sweep` on a Slurm cluster: the drape-coefficient map of configs/sweep/sweep_cotton_map.yaml
# (16 tasks, about 10 s each on one core) on N nodes, one MPI rank per core.
#
#   sbatch docs/slurm-sweep.sh                       # from the repository's root
#   sbatch --nodes=4 docs/slurm-sweep.sh             # more nodes: more ranks, same results
#
# Rank 0 hands the tasks out one at a time to whichever rank is free, collects the rows and writes
# OUT/sweep.csv and OUT/sweep.html; every rank writes its own tasks' folders OUT/tasks/NNNN, so OUT
# must be on a file system that every node sees (home or scratch). drape runs CHOLMOD and OpenBLAS
# on one thread per task: one rank per core (--ntasks-per-node = cores, --cpus-per-task=1).
# Resubmitting the same script after a time limit or a crash skips the finished tasks (restart).
# At its time limit Slurm sends SIGTERM: the tasks being solved stop and are solved again next time.
#
#SBATCH --job-name=drape-sweep
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=16
#SBATCH --cpus-per-task=1
#SBATCH --time=00:30:00
#SBATCH --output=drape-sweep-%j.log

set -euo pipefail
SWEEP=${SWEEP:-configs/sweep/sweep_cotton_map.yaml}
OUT=${OUT:-out/sweep_cotton_map}
export OMP_NUM_THREADS=1

# Open MPI's srun support is PMIx; on clusters that need it say so: srun --mpi=pmix ...
srun drape sweep "$SWEEP" -o "$OUT"

# ---------------------------------------------------------------------------------------------
# The alternative without MPI: a job array, one task per array element (no rank talks to another).
# Each element solves its task into OUT/tasks/NNNN and rewrites OUT/sweep.csv from the finished
# folders; `--task-id` without a value reads $SLURM_ARRAY_TASK_ID. After the array, run the sweep
# once more (it skips every finished task) to complete sweep.csv and draw sweep.html:
#
#   #!/bin/bash
#   #SBATCH --job-name=drape-sweep-array
#   #SBATCH --array=0-15              # the sweep's tasks: 0 .. (number of tasks - 1)
#   #SBATCH --ntasks=1
#   #SBATCH --cpus-per-task=1
#   #SBATCH --time=00:10:00
#   drape sweep configs/sweep/sweep_cotton_map.yaml -o out/sweep_cotton_map --task-id
#
#   sbatch --dependency=afterany:<array job id> --wrap \
#     'drape sweep configs/sweep/sweep_cotton_map.yaml -o out/sweep_cotton_map --threads 1'
#
# With warm starts (warm_start: {along: KEY}), a task needs the earlier tasks of its chain:
# `--task-id I` solves those that are not finished yet first, so array elements of one chain
# repeat each other's work; prefer the srun form above for warm-start sweeps.
