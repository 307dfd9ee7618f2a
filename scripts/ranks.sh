# Sourced by the check scripts (corpus-check, stress-check): reads RANKS, the
# MPI ranks per run (default 1), refuses anything but a positive whole number
# or a missing mpirun (exit 2, naming the calling script), and sets
# `launcher` to the command that starts partet on that many ranks (empty for
# one rank; as root, OpenMPI is allowed to run).
ranks=${RANKS:-1}
if ! [[ $ranks =~ ^[1-9][0-9]*$ ]]; then
  echo "${0##*/}: RANKS must be a positive whole number, not '$ranks'" >&2
  exit 2
fi
launcher=""
if [ "$ranks" -gt 1 ]; then
  if ! command -v mpirun >/dev/null; then
    echo "${0##*/}: RANKS=$ranks needs mpirun (make deps installs OpenMPI)" >&2
    exit 2
  fi
  launcher="mpirun -np $ranks --oversubscribe"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
