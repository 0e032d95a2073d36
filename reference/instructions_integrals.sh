#!/bin/sh
# Instructions per call of the certified integrator against C Arb (issue 22), counted by
# valgrind's callgrind: unlike wall time, a count does not move with the machine's load.
#
#   sh reference/instructions_integrals.sh            (from the workspace root)
#
# Each side runs an integral 10 and then 40 times (after its warm-up call) under
# callgrind; the difference of the two totals over 30 is the count of one call, with the
# one-time work (tables, Gauss-Legendre nodes, process start) cancelled. Needs valgrind
# and Debian's libflint-arb-dev (both installed if missing, as root or with sudo).
set -eu
cd "$(dirname "$0")/.."
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
command -v valgrind >/dev/null || $SUDO apt-get install -y valgrind >&2
[ -e /usr/include/acb_calc.h ] || $SUDO apt-get install -y libflint-arb-dev >&2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cc -O2 -o "$TMP/arb_integrals" reference/arb_integrals.c -lflint-arb -lflint -lmpfr -lgmp
cargo build -q --release --features maugis/gmp-no-check --example integrals_bench
MAUGIS=target/release/examples/integrals_bench
# total instructions of `$1 id` with MAUGIS_BENCH_PREC=$2, MAUGIS_BENCH_CALLS=$3
total() {
    MAUGIS_BENCH_PREC=$3 MAUGIS_BENCH_CALLS=$4 valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$1" "$2" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}
per_call() {
    a=$(total "$1" "$2" "$3" 10); b=$(total "$1" "$2" "$3" 40)
    echo $(( (b - a) / 30 ))
}
echo "| integral | bits | C Arb instructions | maugis instructions | maugis / Arb |"
echo "|---|---|---|---|---|"
for prec in 64 333; do
    for id in atanderiv rump exp sqrt xJ0 sin100; do
        ia=$(per_call "$TMP/arb_integrals" $id $prec)
        im=$(per_call "$MAUGIS" $id $prec)
        echo "| $id | $prec | $ia | $im | $(awk -v m="$im" -v a="$ia" 'BEGIN { printf "%.2f", m / a }')x |"
    done
done
