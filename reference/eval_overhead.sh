#!/bin/sh
# `maugis eval`'s own cost per `integrate` request (issue 36, item 4: at most 10 us,
# and about 2 us so that small integrals through `eval` stay within 1.2x of C Arb):
# everything but `quad::expr::integrate_range` (the request's read, JSON parse,
# arguments, the cached integrand and ends, the response and its output).
#
#   sh reference/eval_overhead.sh                       (from the workspace root)
#   BEFORE=/path/to/older/maugis sh reference/eval_overhead.sh
#                                                       the same, side by side with
#                                                       an older build of the binary
#
# For each request below and each binary (this tree's release build, and BEFORE):
# 1. Instructions (valgrind's callgrind, which the machine's load does not move): the
#    process on N1 and on N2 identical requests, the difference over N2 - N1 of the
#    program total and of `integrate_range`'s inclusive count; eval's own is the rest.
# 2. Wall and CPU time (perf's task-clock) per request: the process on K + 1 identical
#    requests less the one on 1, over K (the first request builds the rules and the
#    caches), the medians of five, the binaries alternated. Needs perf.
# Then `MAUGIS_EVAL_PROFILE=1` of this tree's binary on K requests of the first: the
# wall time per stage (`Instant`; on a loaded machine a share of a core).
set -eu
cd "$(dirname "$0")/.."
N1=${N1:-300}
N2=${N2:-330}
K=${K:-2000}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
cp target/release/maugis "$TMP/after"
BINS=after
if [ -n "${BEFORE:-}" ]; then
    cp "$BEFORE" "$TMP/before"
    BINS="before after"
fi
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
REQS='1/(1+x^2)|0|1|64
sin(x)|-1|1|64
sin(x)|-1|1|333
exp(-x^2)|0|2|333'
lines() { # file n request: n copies of the request
    : > "$1"
    i=0
    while [ $i -lt "$2" ]; do
        echo "$3" >> "$1"
        i=$((i + 1))
    done
}
count() { # bin file: prints "total integrate_range"
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$TMP/$1" eval < "$2" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes "$TMP/cg" 2>/dev/null | awk '
        /PROGRAM TOTALS/ {gsub(",", "", $1); t = $1}
        /quad::expr::integrate::integrate_range / && !r {gsub(",", "", $1); r = $1}
        END {print t, r}'
}
timing() { # bin file: "wall_ns cpu_ns" of `bin eval < file` (CPU: perf's task-clock)
    t0=$(date +%s%N)
    cpu=$(perf stat -x, -e task-clock "$TMP/$1" eval < "$2" 2>&1 >/dev/null | awk -F, '/task-clock/ {printf "%.0f", $1 * 1e6}')
    t1=$(date +%s%N)
    echo "$((t1 - t0)) $cpu"
}
median5() { sort -n | sed -n 3p; }
echo "| integral | bits | binary | instructions a request | in integrate_range | eval's own | wall us a request | CPU us a request |"
echo "|---|---|---|---|---|---|---|---|"
echo "$REQS" | while IFS='|' read -r f a b p; do
    req="{\"id\":1,\"fn\":\"integrate\",\"f\":\"$f\",\"a\":\"$a\",\"b\":\"$b\",\"prec\":$p}"
    lines "$TMP/r1" 1 "$req"
    lines "$TMP/rn1" "$N1" "$req"
    lines "$TMP/rn2" "$N2" "$req"
    lines "$TMP/rk" $((K + 1)) "$req"
    for j in 1 2 3 4 5; do
        for bin in $BINS; do
            echo "$(timing "$bin" "$TMP/rk") $(timing "$bin" "$TMP/r1")" >> "$TMP/wall_$bin"
        done
    done
    for bin in $BINS; do
        set -- $(count "$bin" "$TMP/rn1") $(count "$bin" "$TMP/rn2")
        per=$((($3 - $1) / (N2 - N1)))
        lib=$((($4 - $2) / (N2 - N1)))
        wall=$(awk -v k="$K" '{printf "%.2f\n", ($1 - $3) / k / 1000}' "$TMP/wall_$bin" | median5)
        cpu=$(awk -v k="$K" '{printf "%.2f\n", ($2 - $4) / k / 1000}' "$TMP/wall_$bin" | median5)
        rm -f "$TMP/wall_$bin"
        echo "| \`$f\` on [$a, $b] | $p | $bin | $per | $lib | $((per - lib)) | $wall | $cpu |"
    done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
lines "$TMP/rk" "$K" '{"id":1,"fn":"integrate","f":"1/(1+x^2)","a":"0","b":"1","prec":64}'
MAUGIS_EVAL_PROFILE=1 "$TMP/after" eval < "$TMP/rk" 2>&1 >/dev/null | tail -7
