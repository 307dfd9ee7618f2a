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

# Every partitioner of the boundary leaves (with the removals on the ranks)
# gives a valid mesh; the report names it and, on several ranks, balances
# the front faces.
for method in rib rob; do
  log=$(run "$data/good/eight.off" -o "$out/e.pvtu" --partitioner "$method" --tree-removals-on-ranks \
    --report "$out/e.json"); code=$?
  [[ $code -eq 0 ]] || { echo "eight.off --partitioner $method: exit $code"; echo "$log"; exit 1; }
  log=$("$partet" check "$out/e.pvtu" --surface "$data/good/eight.off" 2>&1); code=$?
  [[ $code -eq 0 ]] || { echo "eight.off --partitioner $method: the mesh is not valid"; echo "$log"; exit 1; }
  if [[ $np -gt 1 ]]; then
    grep -q "\"method\": \"$method\"" "$out/e.json" || { echo "report lacks the partition by $method"; exit 1; }
    grep -q "\"bytes migrated per rank\"" "$out/e.json" || { echo "report lacks the bytes migrated"; exit 1; }
  fi
done
log=$(run "$data/good/cube.off" -o "$out/c.vtu" --partitioner bogus); code=$?
[[ $code -eq 2 ]] || { echo "--partitioner bogus: exit $code, expected 2"; echo "$log"; exit 1; }

log=$(run "$data/good/ellipsoid.off" -o "$out/i.vtu" --no-treeless); code=$?
[[ $code -eq 3 ]] || { echo "ellipsoid.off: exit $code, expected 3"; echo "$log"; exit 1; }
grep -q "front faces remain, near" <<<"$log" || { echo "exit 3 does not say where"; echo "$log"; exit 1; }

log=$(run "$data/good/sphere966.off" -o "$out/core.pvtu" --stop-after templates); code=$?
[[ $code -eq 0 ]] || { echo "sphere966.off --stop-after templates: exit $code"; echo "$log"; exit 1; }
[[ -e "$out/core_$((np - 1)).vtu" ]] || { echo "missing piece of rank $((np - 1))"; exit 1; }
log=$("$partet" check "$out/core.pvtu" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the core pieces are not a valid mesh"; echo "$log"; exit 1; }

# The ranks' core pieces together are the one-rank core: the same tets
# (compared as sets of vertex coordinates, from a one-file .mesh the pieces
# are merged into) and the same check report (counts, volume, quality).
tets_by_coordinates() {  # Medit .mesh -> one sorted line per tet
  awk '/^Vertices/ {getline n; for (i = 1; i <= n; i++) {getline; p[i] = $1 " " $2 " " $3}}
       /^Tetrahedra/ {getline n; for (i = 1; i <= n; i++) {getline; for (k = 1; k <= 4; k++) v[k] = p[$k];
         for (k = 2; k <= 4; k++) for (j = k; j > 1 && v[j] < v[j - 1]; j--) {t = v[j]; v[j] = v[j - 1]; v[j - 1] = t}
         print v[1] "|" v[2] "|" v[3] "|" v[4]}}' "$1" | sort
}
for factor in 1 0.5; do
  "$partet" "$data/good/sphere966.off" -o "$out/one.mesh" --stop-after templates --size-factor "$factor" -q ||
    { echo "one-rank core failed"; exit 1; }
  log=$(run "$data/good/sphere966.off" -o "$out/all.mesh" --stop-after templates --size-factor "$factor"); code=$?
  [[ $code -eq 0 ]] || { echo "merged core: exit $code"; echo "$log"; exit 1; }
  tets_by_coordinates "$out/one.mesh" >"$out/one.tets"
  [[ $(wc -l <"$out/one.tets") -gt 1000 ]] || { echo "x$factor: the one-rank core is too small to compare"; exit 1; }
  cmp -s "$out/one.tets" <(tets_by_coordinates "$out/all.mesh") ||
    { echo "x$factor: the core of $np ranks has other tets than the one-rank core"; exit 1; }
  log=$(run "$data/good/sphere966.off" -o "$out/parts.pvtu" --stop-after templates --size-factor "$factor"); code=$?
  [[ $code -eq 0 ]] || { echo "core pieces: exit $code"; echo "$log"; exit 1; }
  "$partet" "$data/good/sphere966.off" -o "$out/one.vtu" --stop-after templates --size-factor "$factor" -q
  cmp -s <("$partet" check "$out/one.vtu" --json | grep -v '"mesh"') \
         <("$partet" check "$out/parts.pvtu" --json | grep -v '"mesh"') ||
    { echo "x$factor: partet check differs between the $np pieces and the one-rank core"; exit 1; }
done

# Past kDelaunayFillTriangles the gap is filled first; with the removals on
# the ranks every rank fills it alike and the removals close what it leaves
# in rounds over the ranks.
log=$(run "$data/good/spool.off" -o "$out/s.vtu" --tree-removals-on-ranks --report "$out/s.json"); code=$?
[[ $code -eq 0 ]] || { echo "spool.off: exit $code"; echo "$log"; exit 1; }
grep -q '"delaunay fill"' "$out/s.json" || { echo "spool.off: no Delaunay fill in the report"; exit 1; }
log=$("$partet" check "$out/s.vtu" --surface "$data/good/spool.off" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the spool mesh is not valid"; echo "$log"; exit 1; }
if [[ $np -gt 1 ]]; then
  grep -q '"partition boundary"' "$out/s.json" || { echo "spool.off on the ranks: no boundary partition"; exit 1; }
  grep -q '"tets per rank"' "$out/s.json" || { echo "spool.off on the ranks: no removals per rank"; exit 1; }
fi

# By default rank 0 fills the gap and makes the face removals after the
# ranks' octree and templates (gathered on it alone, no boundary
# partition): the mesh before the optimizer is the one-rank mesh, byte for
# byte, and the optimized one is valid.
"$partet" "$data/good/spool.off" -o "$out/one.mesh" --no-optimize -q || { echo "one-rank spool failed"; exit 1; }
log=$(run "$data/good/spool.off" -o "$out/np.mesh" --no-optimize --report "$out/np.json"); code=$?
[[ $code -eq 0 ]] || { echo "spool.off --no-optimize: exit $code"; echo "$log"; exit 1; }
cmp -s "$out/one.mesh" "$out/np.mesh" || { echo "spool.off: the mesh of $np ranks is not the one-rank mesh"; exit 1; }
if [[ $np -gt 1 ]]; then
  grep -q '"gather on rank 0"' "$out/np.json" || { echo "spool.off: the tree was not gathered on rank 0"; exit 1; }
  grep -q '"partition boundary"' "$out/np.json" && { echo "spool.off: a boundary partition by default"; exit 1; }
fi
log=$(run "$data/good/spool.off" -o "$out/d.pvtu"); code=$?
[[ $code -eq 0 ]] || { echo "spool.off by default: exit $code"; echo "$log"; exit 1; }
log=$("$partet" check "$out/d.pvtu" --surface "$data/good/spool.off" 2>&1); code=$?
[[ $code -eq 0 ]] || { echo "the default spool mesh is not valid"; echo "$log"; exit 1; }

log=$(run --version); code=$?
[[ $code -eq 0 ]] || { echo "--version: exit $code"; exit 1; }
echo "mpi cli np=$np: ok"
