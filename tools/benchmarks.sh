#!/bin/sh
# BENCHMARKS.md's "At a glance" table from one run (tools/benchmarks_at_a_glance.py: what each row
# measures, --quick, --only, --race-json). Run at the repository root after `make build`:
#   tools/benchmarks.sh            # every row, 3 invocations each; rewrites the table
#   tools/benchmarks.sh --quick    # toy sizes, prints the table: checks that the script works
# LP_NUM_THREADS defaults to 2, the figures' setting in BENCHMARKS.md.
set -e
cd "$(dirname "$0")/.."
: "${LP_NUM_THREADS:=2}"
export LP_NUM_THREADS
exec python3 tools/benchmarks_at_a_glance.py "$@"
