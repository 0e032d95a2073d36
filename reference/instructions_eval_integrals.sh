#!/bin/sh
# Instructions per integral of `maugis eval` (the JSON request, parsed and answered)
# against python-flint's acb.integral on the benchmark integrals of
# reference/bench_integrals.sh, at 64 and 333 bits (issue 22, "through maugis eval each
# is faster than python-flint"), counted by valgrind's callgrind: unlike wall time, a
# count does not move with the machine's load.
#
#   sh reference/instructions_eval_integrals.sh [python]     (from the workspace root)
#
# Each side runs N1 and N2 integrals in one process under callgrind; the difference of
# the two totals over N2 - N1 is the count of one, with the process start, imports,
# node caches and one-time tables cancelled. `python` is an interpreter with
# python-flint (default python3). Needs valgrind.
set -eu
cd "$(dirname "$0")/.."
PY=${1:-python3}
N1=${N1:-2}
N2=${N2:-6}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
count() { # command... ; prints the total instructions
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$@" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}
cat > "$TMP/flint_side.py" <<'PYEOF'
import sys
from flint import acb, ctx
F = {
    "atanderiv": (lambda x, _: 1 / (1 + x * x), 0, 1),
    "rump": (lambda x, _: (x + x.exp()).sin(), 0, 8),
    "exp": (lambda x, _: x.exp(), 0, 1),
    "sqrt": (lambda x, a: x.sqrt(analytic=a), 1, 4),
    "xJ0": (lambda x, _: x * x.bessel_j(0), 0, 1),
    "sin100": (lambda x, _: x.sin(), 0, 100),
}
ident, prec, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
f, a, b = F[ident]
ctx.prec = prec
for _ in range(n):
    r = acb.integral(f, a, b)
PYEOF
echo "| integral | bits | maugis eval (instructions) | python-flint acb.integral | ratio |"
echo "|---|---|---|---|---|"
for prec in 64 333; do
    for case in "atanderiv 1/(1+x^2) 0 1" "rump sin(x+exp(x)) 0 8" "exp exp(x) 0 1" \
                "sqrt sqrt(x) 1 4" "xJ0 x*besselj(0,x) 0 1" "sin100 sin(x) 0 100"; do
        set -- $case
        ident=$1 f=$2 a=$3 b=$4
        for n in $N1 $N2; do
            i=0
            : > "$TMP/req_$n"
            while [ $i -lt $n ]; do
                printf '{"fn":"integrate","f":"%s","a":"%s","b":"%s","prec":%d}\n' "$f" "$a" "$b" "$prec" >> "$TMP/req_$n"
                i=$((i + 1))
            done
        done
        m1=$(count target/release/maugis eval < "$TMP/req_$N1")
        m2=$(count target/release/maugis eval < "$TMP/req_$N2")
        p1=$(count "$PY" "$TMP/flint_side.py" "$ident" "$prec" "$N1")
        p2=$(count "$PY" "$TMP/flint_side.py" "$ident" "$prec" "$N2")
        "$PY" -c "import sys
m = (int(sys.argv[2]) - int(sys.argv[1])) / $((N2 - N1)); p = (int(sys.argv[4]) - int(sys.argv[3])) / $((N2 - N1))
print('| $ident | $prec | %.0f | %.0f | %.2fx |' % (m, p, m / p))" "$m1" "$m2" "$p1" "$p2"
    done
done
