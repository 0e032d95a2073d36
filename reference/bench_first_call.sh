#!/bin/sh
# First call against warm call, maugis against C Arb (issue 36, item 1), side by side
# in one run: each (integral, precision) of issue 36's table runs in a fresh process of
# each side (examples/first_call.rs and reference/arb_first_call.c), so the first call
# builds the Gauss-Legendre nodes.  Prints a markdown table with the ratios.
#
#   sh reference/bench_first_call.sh            (from the workspace root)
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
echo "| integral | bits | maugis first ms | C Arb first ms | first ratio | maugis warm ms | C Arb warm ms | warm ratio |"
echo "|---|---|---|---|---|---|---|---|"
for case in atanderiv:64 atanderiv:333 atanderiv:3333 rump:64 rump:333 gauss:333 gauss:3333 sqrt:3333 xJ0:3333 sin_zero:64 sin_zero:333; do
    id=${case%%:*}; p=${case##*:}
    m=$("$ME" "$id" "$p")
    a=$("$TMP/arb_first_call" "$id" "$p")
    echo "$m	$a" | awk -F'\t' '{ printf "| %s | %s | %.2f | %.2f | %.2fx | %.3f | %.3f | %.2fx |\n", $1, $2, $3, $9, $3 / $9, $4, $10, $4 / $10 }'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
