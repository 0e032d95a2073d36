#!/bin/sh
# First call against warm call, maugis against C Arb (issue 36, item 1), side by side
# in one run: each (integral, precision) of issue 36's table runs in a fresh process of
# each side (examples/first_call.rs and reference/arb_first_call.c), so the first call
# builds the Gauss-Legendre nodes.  Prints a markdown table with the ratios.
#
#   sh reference/bench_first_call.sh            (from the workspace root)
#   sh reference/bench_first_call.sh --cpu      the first call alone, in CPU time
#
# --cpu: wall time under load decides little, so each side's fresh process runs the
# first call alone (FIRST_CALL_ONLY=1) under `perf stat -e task-clock`, three times
# alternated, and the table has the medians (CPU ms of the whole process, start-up
# included) and their ratio; and `first_call rule N PREC`, one Gauss-Legendre rule
# alone, at the degrees and precisions of the 3333-bit first calls. Needs perf.
#
# Needs Debian's libflint-arb-dev (C Arb 2.23): installed with apt-get when missing and
# this runs as root or with sudo; otherwise the script says so and exits 0 (it is never
# part of ./dev test).
set -eu
cd "$(dirname "$0")/.."
if [ ! -e /usr/include/acb_calc.h ] && [ ! -e /usr/include/flint/acb_calc.h ]; then
    SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
    if ! $SUDO apt-get install -y libflint-arb-dev >&2; then
        echo "bench_first_call.sh: skipped: C Arb (Debian's libflint-arb-dev) is not installed and could not be installed" >&2
        exit 0
    fi
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
INC=""; [ -e /usr/include/flint/acb_calc.h ] && INC="-I/usr/include/flint"
cc -O2 $INC -o "$TMP/arb_first_call" reference/arb_first_call.c -lflint-arb -lflint -lmpfr -lgmp
cargo build -q --release --features maugis/gmp-no-check --example first_call
ME=target/release/examples/first_call
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
# CPU ms of `$@` (perf's task-clock), with FIRST_CALL_ONLY=1
cpu() {
    FIRST_CALL_ONLY=1 perf stat -e task-clock -x, "$@" 2>&1 >/dev/null | awk -F, '/task-clock/ { print $1 }'
}
median3() { printf '%s\n%s\n%s\n' "$1" "$2" "$3" | sort -n | sed -n 2p; }
if [ "${1:-}" = "--cpu" ]; then
    echo "| integral | bits | maugis first call CPU ms | C Arb first call CPU ms | ratio |"
    echo "|---|---|---|---|---|"
    for case in atanderiv:64 atanderiv:333 atanderiv:3333 rump:64 rump:333 gauss:333 gauss:3333 sqrt:3333 xJ0:3333 sin_zero:64 sin_zero:333; do
        id=${case%%:*}; p=${case##*:}
        m1=$(cpu "$ME" "$id" "$p"); a1=$(cpu "$TMP/arb_first_call" "$id" "$p")
        m2=$(cpu "$ME" "$id" "$p"); a2=$(cpu "$TMP/arb_first_call" "$id" "$p")
        m3=$(cpu "$ME" "$id" "$p"); a3=$(cpu "$TMP/arb_first_call" "$id" "$p")
        m=$(median3 "$m1" "$m2" "$m3"); a=$(median3 "$a1" "$a2" "$a3")
        echo "$id $p $m $a" | awk '{ printf "| %s | %s | %.2f | %.2f | %.2fx |\n", $1, $2, $3, $4, $3 / $4 }'
    done
    echo
    echo "| rule degree | bits | CPU ms (whole process) |"
    echo "|---|---|---|"
    for n in 100 200 304 430 512 608; do
        for p in 333 1000 3353; do
            r=$(median3 "$(cpu "$ME" rule "$n" "$p")" "$(cpu "$ME" rule "$n" "$p")" "$(cpu "$ME" rule "$n" "$p")")
            echo "| $n | $p | $r |"
        done
    done
    echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
    exit 0
fi
echo "| integral | bits | maugis first ms | C Arb first ms | first ratio | maugis warm ms | C Arb warm ms | warm ratio |"
echo "|---|---|---|---|---|---|---|---|"
for case in atanderiv:64 atanderiv:333 atanderiv:3333 rump:64 rump:333 gauss:333 gauss:3333 sqrt:3333 xJ0:3333 sin_zero:64 sin_zero:333; do
    id=${case%%:*}; p=${case##*:}
    m=$("$ME" "$id" "$p")
    a=$("$TMP/arb_first_call" "$id" "$p")
    echo "$m	$a" | awk -F'\t' '{ printf "| %s | %s | %.2f | %.2f | %.2fx | %.3f | %.3f | %.2fx |\n", $1, $2, $3, $9, $3 / $9, $4, $10, $4 / $10 }'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
