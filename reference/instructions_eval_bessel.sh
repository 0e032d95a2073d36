#!/bin/sh
# Instructions per request of `maugis eval` for J_0(2.5) at 128 bits against Arb through
# python-flint (the call alone, and the same JSON request done in Python) and C Arb's
# arb_hypgeom_bessel_j (issue 23, item 4), counted by valgrind's callgrind: unlike wall
# time, a count does not move with the machine's load.
#
#   sh reference/instructions_eval_bessel.sh [python]      (from the workspace root)
#
# Each side runs N = 500 and N = 2500 requests (calls) in one process under callgrind;
# the difference of the two totals over 2000 is the count of one, with the process
# start, imports and one-time tables cancelled. `python` is an interpreter with
# python-flint (default python3). Needs valgrind and Debian's libflint-arb-dev.
set -eu
cd "$(dirname "$0")/.."
PY=${1:-python3}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
# J_0: the order is the ball 0
cat > "$TMP/arb_j0.c" <<'C'
#include <stdlib.h>
#include <arb_hypgeom.h>
int main(int argc, char **argv) {
    long n = atol(argv[1]);
    arb_t nu, x, y;
    arb_init(nu); arb_init(x); arb_init(y);
    arb_zero(nu);
    arb_set_str(x, "2.5", 128);
    for (long i = 0; i < n; i++) arb_hypgeom_bessel_j(y, nu, x, 128);
    arb_printn(y, 40, 0);
    return 0;
}
C
cc -O2 -o "$TMP/arb_j0" "$TMP/arb_j0.c" -lflint-arb -lflint -lmpfr -lgmp
count() { # command... ; prints the total instructions
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$@" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}
requests() { "$PY" -c "import sys
for i in range(int(sys.argv[1])): print('{\"id\":%d,\"fn\":\"bessel_j\",\"n\":0,\"x\":\"2.5\",\"prec\":128}' % i)" "$1"; }
requests 500 > "$TMP/r500"; requests 2500 > "$TMP/r2500"
eval_total() { valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" target/release/maugis eval <"$1" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'; }
cat > "$TMP/flint_call.py" <<'P'
import sys, flint
flint.ctx.prec = 128
x = flint.arb("2.5")
for _ in range(int(sys.argv[1])):
    v = x.bessel_j(0)
P
cat > "$TMP/flint_request.py" <<'P'
import sys, json, flint
for line in open(sys.argv[1]):
    req = json.loads(line)
    flint.ctx.prec = req["prec"]
    v = flint.arb(req["x"]).bessel_j(req["n"])
    digits = int(req["prec"] * 0.30103) + 4
    out = json.dumps({"id": req["id"], "mid": v.mid().str(digits, radius=False), "rad": v.rad().str(3, radius=False), "prec": req["prec"]})
P
per() { echo $(( ($2 - $1) / 2000 )); }
m=$(per "$(eval_total "$TMP/r500")" "$(eval_total "$TMP/r2500")")
c=$(per "$(count "$TMP/arb_j0" 500)" "$(count "$TMP/arb_j0" 2500)")
f=$(per "$(count "$PY" "$TMP/flint_call.py" 500)" "$(count "$PY" "$TMP/flint_call.py" 2500)")
r=$(per "$(count "$PY" "$TMP/flint_request.py" "$TMP/r500")" "$(count "$PY" "$TMP/flint_request.py" "$TMP/r2500")")
ratio() { awk -v m="$m" -v a="$1" 'BEGIN { printf "%.2f", m / a }'; }
echo "| J_0(2.5), 128 bits, per request | instructions | maugis eval / this |"
echo "|---|---:|---:|"
echo "| \`maugis eval\` (JSON Lines request) | $m | 1.00 |"
echo "| Arb via python-flint, the call alone (\`x.bessel_j(0)\`) | $f | $(ratio "$f") |"
echo "| Arb via python-flint, the same request in Python (JSON, parse, call, print) | $r | $(ratio "$r") |"
echo "| C Arb, \`arb_hypgeom_bessel_j\` alone | $c | $(ratio "$c") |"
