#!/usr/bin/env bash
# Runs a `dermis reference`, `stress`, `tune` or `bench` job as N shards and
# merges them (docs/shards.md).
#
#   tools/shards.sh parallel N OUT reference SCENE [options...]
#   tools/shards.sh parallel N OUT stress|tune|bench [options...]
#       GNU parallel on this machine: N shard processes (a reference's
#       each with --threads cores / N), then `dermis merge` into OUT
#       (.exr for a reference, .json for stress and tune, a directory
#       for bench).
#   tools/shards.sh slurm N OUT reference|stress|tune|bench ...
#       writes OUT.shards/array.sbatch (a Slurm job array: task K runs
#       shard K/N) and OUT.shards/merge.sbatch (the merge), and prints the
#       two sbatch commands that submit them, the merge after every task
#       ended (a stress task with failed cases exits 1; its summary is merged).
#   In parallel mode every shard runs to its end and the merge follows; the
#   exit status is 1 when a shard failed (after the merge), else the merge's.
#
# The shards' outputs go to OUT.shards/. $DERMIS names the program
# (default: build/dermis of this checkout).
set -euo pipefail

usage() {
    sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
}
fail() {
    echo "tools/shards.sh: $*" >&2
    exit 2
}

[[ $# -ge 4 ]] || usage
mode=$1 count=$2 out=$3 command=$4
shift 4
[[ $mode == parallel || $mode == slurm ]] || fail "unknown mode '$mode' (parallel or slurm)"
[[ $count =~ ^[1-9][0-9]*$ ]] || fail "N must be a positive integer, not '$count'"
case $command in
reference) [[ $out == *.exr ]] || fail "a reference's OUT must end in .exr, not '$out'"; [[ $# -ge 1 ]] || fail "reference needs a SCENE"; extension=exr ;;
stress|tune) [[ $out == *.json ]] || fail "a $command run's OUT must end in .json, not '$out'"; extension=json ;;
bench) [[ $out != *.json && $out != *.exr ]] || fail "a bench run's OUT is a directory, not '$out'"; extension="" ;;
*) fail "unknown command '$command' (reference, stress, tune or bench)" ;;
esac
root=$(cd "$(dirname "$0")/.." && pwd)
dermis=${DERMIS:-$root/build/dermis}
dir=$out.shards
mkdir -p "$dir"
shards=()
suffix=${extension:+.$extension}
merge_options=()
for option in "$@"; do [[ $option == --no-plots ]] && merge_options=(--no-plots); done
for k in $(seq 1 "$count"); do shards+=("$dir/shard-$k$suffix"); done

case $mode in
parallel)
    command -v parallel >/dev/null || { echo "tools/shards.sh: GNU parallel is missing (Debian: apt-get install parallel)" >&2; exit 1; }
    threads=()
    if [[ $command == reference ]]; then
        cores=$(nproc)
        threads=(--threads $(( cores / count > 0 ? cores / count : 1 )))
    fi
    # Every shard runs to its end: a stress shard that exits 1 has failed cases, which are
    # results and are merged; a shard that wrote nothing makes the merge fail naming it.
    shards_status=0
    parallel --will-cite --quote -j "$count" \
        "$dermis" "$command" "$@" "${threads[@]}" --quiet --shard {}/"$count" --out "$dir"/shard-{}"$suffix" \
        ::: $(seq 1 "$count") || shards_status=1
    "$dermis" merge "${merge_options[@]}" --out "$out" "${shards[@]}"
    exit "$shards_status"
    ;;
slurm)
    cat > "$dir/array.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=dermis-$command
#SBATCH --array=1-$count
#SBATCH --cpus-per-task=8
set -euo pipefail
$(printf '%q ' "$dermis" "$command" "$@")--quiet --shard "\$SLURM_ARRAY_TASK_ID/$count" --out $(printf '%q' "$dir")/shard-"\$SLURM_ARRAY_TASK_ID"$suffix
SBATCH
    cat > "$dir/merge.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=dermis-$command-merge
set -euo pipefail
$(printf '%q ' "$dermis" merge "${merge_options[@]}" --out "$out" "${shards[@]}")
SBATCH
    echo "array=\$(sbatch --parsable $dir/array.sbatch)"
    # afterany: a stress task that found failed cases exits 1, and its summary is still merged.
    echo "sbatch --dependency=afterany:\$array $dir/merge.sbatch"
    ;;
esac
