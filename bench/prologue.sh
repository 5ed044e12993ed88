# What every bench script starts with (sourced, not run): strict mode; the
# repository as the working directory, so scene and output paths read the same
# from anywhere; `results` (bench/results/, where the scripts write); `work`, a
# scratch directory removed on exit; and `airlight`, the release build, which
# build_airlight brings up to date (the scripts that time given binaries skip it).
set -euo pipefail
caller_dir=$PWD  # where paths given on the command line are relative to
cd "$(dirname "${BASH_SOURCE[0]}")/.."
results=bench/results
airlight=build/release/src/app/airlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$results"

# The release build, incremental (quick when nothing changed).
build_airlight() { scripts/build release >/dev/null; }

# A binary given on the command line, as an absolute path: a path from the
# caller's directory, or a command on PATH.
given_binary() {
  local path
  path=$(cd "$caller_dir" && command -v "$1") || { echo "$0: no such binary: $1" >&2; exit 2; }
  (cd "$caller_dir" && realpath "$path")
}
