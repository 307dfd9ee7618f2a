#!/usr/bin/env bash
# The partet binary under mpirun: every rank ends with the agreed exit code
# and rank 0 alone prints the error. Usage: mpi_cli_test.sh MPIEXEC PARTET DATA NP
set -uo pipefail
mpiexec=$1 partet=$2 data=$3 np=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() { "$mpiexec" -np "$np" --oversubscribe "$partet" "$@" 2>&1; }

log=$(run "$data/bad/holes.off" -o "$out/h.vtu" --report "$out/r.json"); code=$?
[[ $code -eq 2 ]] || { echo "holes.off: exit $code, expected 2"; echo "$log"; exit 1; }
[[ $(grep -c "partet: error:" <<<"$log") -eq 1 ]] || { echo "expected one error line"; echo "$log"; exit 1; }
grep -q "open edges" <<<"$log" || { echo "no reason given"; echo "$log"; exit 1; }
[[ ! -e "$out/h.vtu" ]] || { echo "output written for bad input"; exit 1; }
grep -q "\"ranks\": $np" "$out/r.json" || { echo "report lacks ranks $np"; exit 1; }

log=$(run "$data/good/cube.off" -o "$out/c.pvtu"); code=$?
[[ $code -eq 0 ]] || { echo "cube.off: exit $code, expected 0"; echo "$log"; exit 1; }
log=$("$partet" check "$out/c.pvtu" --surface "$data/good/cube.off" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the cube mesh is not valid"; echo "$log"; exit 1; }

log=$(run "$data/good/ellipsoid.off" -o "$out/i.vtu"); code=$?
[[ $code -eq 3 ]] || { echo "ellipsoid.off: exit $code, expected 3"; echo "$log"; exit 1; }
grep -q "front faces remain, near" <<<"$log" || { echo "exit 3 does not say where"; echo "$log"; exit 1; }

log=$(run "$data/good/sphere966.off" -o "$out/core.pvtu" --stop-after templates); code=$?
[[ $code -eq 0 ]] || { echo "sphere966.off --stop-after templates: exit $code"; echo "$log"; exit 1; }
[[ -e "$out/core_$((np - 1)).vtu" ]] || { echo "missing piece of rank $((np - 1))"; exit 1; }
log=$("$partet" check "$out/core.pvtu" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the core pieces are not a valid mesh"; echo "$log"; exit 1; }

log=$(run --version); code=$?
[[ $code -eq 0 ]] || { echo "--version: exit $code"; exit 1; }
echo "mpi cli np=$np: ok"
