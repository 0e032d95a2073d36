#!/bin/sh
# The first call of a certified integral in a fresh process, maugis against C Arb
# (issue 36, item 1), in instructions counted by valgrind's callgrind: unlike the wall
# times of bench_first_call.sh, a count does not move with the machine's load.
#
#   sh reference/instructions_first_call.sh            (from the workspace root)
#
# Each side runs one integral once (FIRST_CALL_ONLY=1: examples/first_call.rs and
# reference/arb_first_call.c), and the count is the inclusive one of the integrator's
# entry (`quad::expr::integrate_range`, `acb_calc_integrate`): the Gauss-Legendre
# nodes, the elementary functions' tables and the integral, not the process start.
# The cases are those of bench_first_call.sh at 64 and 333 bits. Needs valgrind and
# Debian's libflint-arb-dev (both installed if missing, as root or with sudo).
set -eu
cd "$(dirname "$0")/.."
NEED_VALGRIND=1 . reference/first_call_setup.sh
# inclusive instructions of function $1 in a run of `$2 $3 $4`
count() {
    FIRST_CALL_ONLY=1 valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$2" "$3" "$4" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes "$TMP/cg" 2>/dev/null | grep -F "$1 " | head -1 | awk '{gsub(",", "", $1); print $1}'
}
echo "| integral | bits | maugis first call (instructions) | C Arb first call | maugis / Arb |"
echo "|---|---|---|---|---|"
for case in atanderiv:64 atanderiv:333 rump:64 rump:333 gauss:333 sin_zero:64 sin_zero:333; do
    id=${case%%:*}; p=${case##*:}
    im=$(count "???:maugis::quad::expr::integrate::integrate_range" "$ME" "$id" "$p")
    ia=$(count ":acb_calc_integrate" "$TMP/arb_first_call" "$id" "$p")
    echo "| $id | $p | $im | $ia | $(awk -v m="$im" -v a="$ia" 'BEGIN { printf "%.2f", m / a }')x |"
done
