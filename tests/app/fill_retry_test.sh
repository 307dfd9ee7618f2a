#!/usr/bin/env bash
# A front the Delaunay fill's attempts cannot close is meshed again without
# the fill, soon: stress-check seed 5193, a corrugated needle (most of its
# triangles are no Delaunay faces), meshes to a valid mesh within the time
# limit, and its report says the mesh is the one made without the fill.
# Before run_mesh tried the cheap attempts first it ran for over ten
# minutes. With MPIEXEC and NP, on NP ranks: the retries make the
# tree-supported removals on rank 0 alone, so the ranks close it as one
# rank does. Usage: fill_retry_test.sh PARTET SCRIPTS TIME_LIMIT_S [MPIEXEC NP]
set -uo pipefail
partet=$1 scripts=$2 limit=$3
launch=()
[[ $# -ge 5 ]] && launch=("$4" -np "$5" --oversubscribe)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$scripts/random-surface" 5193 "$out/needle.off" || { echo "random-surface failed"; exit 1; }
log=$(timeout "$limit" "${launch[@]}" "$partet" "$out/needle.off" -o "$out/needle.vtu" --report "$out/r.json" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "seed 5193: exit $code (124: over $limit s)"; echo "$log" | tail -20; exit 1; }
grep -q "meshing again without it" <<<"$log" || { echo "no note of the retry without the fill"; echo "$log"; exit 1; }
grep -Eq '"retried without the Delaunay fill": *true' "$out/r.json" || { echo "report lacks the retry"; exit 1; }
grep -q '"delaunay fill"' "$out/r.json" && { echo "the kept mesh ran the Delaunay fill"; exit 1; }
log=$("$partet" check "$out/needle.vtu" --surface "$out/needle.off" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the needle's mesh is not valid"; echo "$log"; exit 1; }
echo "seed 5193: valid, meshed without the Delaunay fill${5:+ on $5 ranks}"
