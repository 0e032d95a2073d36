#!/bin/sh
# `maugis eval`'s own cost per `integrate` request (issue 36, item 4: at most 10 us):
# everything but `quad::expr::integrate_range` (the request's read, JSON parse,
# arguments, the cached integrand, the response and its output).
#
#   sh reference/eval_overhead.sh            (from the workspace root)
#
# 1. Instructions (valgrind's callgrind, which the machine's load does not move): the
#    process on N1 and on N2 identical requests, the difference over N2 - N1 of the
#    program total and of `integrate_range`'s inclusive count.
# 2. Time per stage: `MAUGIS_EVAL_PROFILE=1` on 2000 requests (wall clock per stage,
#    `Instant`; on a loaded machine a share of a core).
set -eu
cd "$(dirname "$0")/.."
N1=${N1:-10}
N2=${N2:-40}
REQ='{"fn":"integrate","f":"1/(1+x^2)","a":"0","b":"1","prec":64}'
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
for n in $N1 $N2 2000; do
    i=0
    : > "$TMP/req_$n"
    while [ $i -lt $n ]; do
        echo "$REQ" >> "$TMP/req_$n"
        i=$((i + 1))
    done
done
count() { # n: prints "total integrate_range"
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg_$1" target/release/maugis eval < "$TMP/req_$1" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes "$TMP/cg_$1" 2>/dev/null | awk '
        /PROGRAM TOTALS/ {gsub(",", "", $1); t = $1}
        /quad::expr::integrate::integrate_range / && !r {gsub(",", "", $1); r = $1}
        END {print t, r}'
}
set -- $(count $N1) $(count $N2)
echo "per request: $(( ($3 - $1) / (N2 - N1) )) instructions, of which integrate_range $(( ($4 - $2) / (N2 - N1) )), eval's own $(( (($3 - $1) - ($4 - $2)) / (N2 - N1) ))"
MAUGIS_EVAL_PROFILE=1 target/release/maugis eval < "$TMP/req_2000" 2>&1 >/dev/null | tail -7
