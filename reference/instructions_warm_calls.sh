#!/bin/sh
# Warm calls of issue 36's integrals (item 4: within 1.2x of C Arb at every precision),
# maugis against C Arb, in instructions counted by valgrind's callgrind: unlike wall
# time, a count does not move with the machine's load.
#
#   sh reference/instructions_warm_calls.sh [ID:PREC ...]     (from the workspace root)
#
# Each side (examples/first_call.rs with a CALLS argument, through the expression integrator, as `maugis
# integrate`; reference/arb_first_call.c with a CALLS argument, acb_calc_integrate with the options of Arb's
# examples/integrals.c) runs the integral after a warm-up call K1 and then K2 times
# under callgrind; the difference of the two totals over K2 - K1 is one warm call, with
# the one-time work (tables, Gauss-Legendre nodes, process start) cancelled. K1, K2 are
# 300, 330 at 64 and 333 bits (past the first 256 calls of the elementary functions, which
# go to MPFR until their tables are built: src/ball/fixed/mod.rs, LAZY_CALLS) and 1, 3 at
# 3333 bits (a 3333-bit call takes seconds under
# callgrind). Without arguments: every case of issue 36's table. Needs valgrind and
# Debian's libflint-arb-dev (both installed if missing, as root or with sudo).
set -eu
cd "$(dirname "$0")/.."
NEED_VALGRIND=1 . reference/first_call_setup.sh
# total instructions of `$1 $2 $3 $4`
total() {
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$1" "$2" "$3" "$4" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}
per_call() {
    if [ "$3" -ge 1000 ]; then k1=1; k2=3; else k1=300; k2=330; fi
    a=$(total "$1" "$2" "$3" $k1); b=$(total "$1" "$2" "$3" $k2)
    echo $(( (b - a) / (k2 - k1) ))
}
CASES=${*:-atanderiv:64 atanderiv:333 atanderiv:3333 rump:64 rump:333 gauss:333 gauss:3333 sqrt:3333 xJ0:3333 sin_zero:64 sin_zero:333}
echo "| integral | bits | maugis warm (instructions) | C Arb warm | maugis / Arb |"
echo "|---|---|---|---|---|"
for case in $CASES; do
    id=${case%%:*}; p=${case##*:}
    im=$(per_call "$ME" "$id" "$p")
    ia=$(per_call "$TMP/arb_first_call" "$id" "$p")
    echo "| $id | $p | $im | $ia | $(awk -v m="$im" -v a="$ia" 'BEGIN { printf "%.2f", m / a }')x |"
done
