#!/usr/bin/env bash
# Runs `dermis reference` as N shards and merges them (docs/shards.md).
#
#   tools/shards.sh parallel N OUT.exr SCENE [reference options...]
#       GNU parallel on this machine: N shard processes, each with
#       --threads (cores / N), then `dermis merge` into OUT.exr.
#   tools/shards.sh slurm N OUT.exr SCENE [reference options...]
#       writes OUT.exr.shards/array.sbatch (a Slurm job array, task K runs
#       shard K/N) and OUT.exr.shards/merge.sbatch (the merge), and prints
#       the two sbatch commands that submit them, the merge after every
#       task succeeded.
#
# The shards' images and notes go to OUT.exr.shards/. $DERMIS names the
# program (default: build/dermis beside this script's folder).
set -euo pipefail

usage() {
    sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
}

[[ $# -ge 4 ]] || usage
mode=$1 count=$2 out=$3 scene=$4
shift 4
[[ $mode == parallel || $mode == slurm ]] || { echo "tools/shards.sh: unknown mode '$mode' (parallel or slurm)" >&2; exit 2; }
[[ $count =~ ^[1-9][0-9]*$ ]] || { echo "tools/shards.sh: N must be a positive integer, not '$count'" >&2; exit 2; }
[[ $out == *.exr ]] || { echo "tools/shards.sh: OUT must end in .exr, not '$out'" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
dermis=${DERMIS:-$root/build/dermis}
dir=$out.shards
mkdir -p "$dir"

case $mode in
parallel)
    command -v parallel >/dev/null || { echo "tools/shards.sh: GNU parallel is missing (Debian: apt-get install parallel)" >&2; exit 1; }
    cores=$(nproc)
    threads=$(( cores / count > 0 ? cores / count : 1 ))
    parallel --will-cite --halt now,fail=1 -j "$count" \
        "$dermis" reference "$scene" "$@" --threads "$threads" --quiet --shard {}/"$count" --out "$dir"/shard-{}.exr \
        ::: $(seq 1 "$count")
    shards=()
    for k in $(seq 1 "$count"); do shards+=("$dir/shard-$k.exr"); done
    "$dermis" merge --out "$out" "${shards[@]}"
    ;;
slurm)
    quoted=$(printf ' %q' "$@")
    cat > "$dir/array.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=dermis-reference
#SBATCH --array=1-$count
#SBATCH --cpus-per-task=8
set -euo pipefail
$(printf '%q' "$dermis") reference $(printf '%q' "$scene")$quoted --quiet --shard "\$SLURM_ARRAY_TASK_ID/$count" --out $(printf '%q' "$dir")/shard-"\$SLURM_ARRAY_TASK_ID".exr
SBATCH
    shards=""
    for k in $(seq 1 "$count"); do shards+=" $(printf '%q' "$dir/shard-$k.exr")"; done
    cat > "$dir/merge.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=dermis-reference-merge
set -euo pipefail
$(printf '%q' "$dermis") merge --out $(printf '%q' "$out")$shards
SBATCH
    echo "array=\$(sbatch --parsable $dir/array.sbatch)"
    echo "sbatch --dependency=afterok:\$array $dir/merge.sbatch"
    ;;
esac
