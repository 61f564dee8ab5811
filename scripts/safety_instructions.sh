#!/usr/bin/env bash
# Instructions per period of the hybrid step of the thesis trial (SCARA) and of the Panda
# wiping, bare and supervised (valgrind callgrind on examples/safety_step.rs: the
# instructions of STEPS steps less those of none, per step).
# Deterministic, unlike the time of the criterion group `safety`.
#
# Run: bash scripts/safety_instructions.sh [STEPS]   (needs valgrind)
set -euo pipefail
cd "$(dirname "$0")/.."
steps="${1:-20000}"
command -v valgrind >/dev/null || { echo "error: valgrind is not installed (apt-get install -y valgrind)" >&2; exit 1; }
cargo build --release --quiet --example safety_step
bin=target/release/examples/safety_step
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
count() {
    valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$bin" "$1" "$2" "$3" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
for robot in scara panda; do
    declare -A per
    for mode in bare supervised; do
        base="$(count "$robot" "$mode" 0)"
        total="$(count "$robot" "$mode" "$steps")"
        per[$mode]=$(( (total - base) / steps ))
        echo "$robot $mode: ${per[$mode]} instructions per step"
    done
    extra=$(( per[supervised] - per[bare] ))
    echo "$robot supervisor: $extra instructions per step ($(( 100 * extra / per[bare] )) % of the bare step)"
done
