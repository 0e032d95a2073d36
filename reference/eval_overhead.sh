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
#    caches), the medians of five, the binaries alternated; and the same of the library
#    alone, `examples/first_call.rs ID PREC K` less `ID PREC 0` (a first call, then K
#    calls of `integrate_range`), so that eval's own time is the difference, and of C
#    Arb, `reference/arb_first_call.c ID PREC K` less `ID PREC 0` (acb_calc_integrate);
#    C Arb's instructions a call as in 1. (`ID PREC N2` less `ID PREC N1`). The ratios
#    are eval's (instructions, CPU) over C Arb's. Needs perf, valgrind and Debian's
#    libflint-arb-dev (reference/first_call_setup.sh installs what is missing).
# Then `MAUGIS_EVAL_PROFILE=1` of this tree's binary on K requests of the first: the
# wall time per stage (`Instant`; on a loaded machine a share of a core).
set -eu
cd "$(dirname "$0")/.."
N1=${N1:-300}
N2=${N2:-330}
K=${K:-2000}
NEED_VALGRIND=1 . reference/first_call_setup.sh
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
cp target/release/maugis "$TMP/after"
LIB=$ME
ARB=$TMP/arb_first_call
BINS=after
if [ -n "${BEFORE:-}" ]; then
    cp "$BEFORE" "$TMP/before"
    BINS="before after"
fi
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
REQS='1/(1+x^2)|0|1|64|atanderiv
sin(x)|-1|1|64|sin_zero
sin(x)|-1|1|333|sin_zero
exp(-x^2)|0|2|333|gauss'
lines() { # file n request: n copies of the request
    : > "$1"
    i=0
    while [ $i -lt "$2" ]; do
        echo "$3" >> "$1"
        i=$((i + 1))
    done
}
total() { # command..: total instructions under callgrind
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$@" >/dev/null 2>&1
    callgrind_annotate "$TMP/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}
count() { # bin file: prints "total integrate_range"
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$TMP/$1" eval < "$2" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes "$TMP/cg" 2>/dev/null | awk '
        /PROGRAM TOTALS/ {gsub(",", "", $1); t = $1}
        /quad::expr::integrate::integrate_range / && !r {gsub(",", "", $1); r = $1}
        END {print t, r}'
}
timed() { # command..: "wall_ns cpu_ns" of it, stdout dropped (CPU: perf's task-clock)
    t0=$(date +%s%N)
    cpu=$(perf stat -x, -e task-clock "$@" 2>&1 >/dev/null | awk -F, '/task-clock/ {printf "%.0f", $1 * 1e6}')
    t1=$(date +%s%N)
    echo "$((t1 - t0)) $cpu"
}
timing() { # bin file: `timed` of `bin eval < file`
    timed sh -c "exec \"\$0\" eval < \"\$1\"" "$TMP/$1" "$2"
}
median5() { sort -n | sed -n 3p; }
echo "| integral | bits | binary | instructions a request | in integrate_range | eval's own | C Arb instructions | eval / Arb | wall us a request | CPU us a request | library wall us | library CPU us | C Arb CPU us | eval / Arb CPU |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
echo "$REQS" | while IFS='|' read -r f a b p id; do
    req="{\"id\":1,\"fn\":\"integrate\",\"f\":\"$f\",\"a\":\"$a\",\"b\":\"$b\",\"prec\":$p}"
    lines "$TMP/r1" 1 "$req"
    lines "$TMP/rn1" "$N1" "$req"
    lines "$TMP/rn2" "$N2" "$req"
    lines "$TMP/rk" $((K + 1)) "$req"
    for j in 1 2 3 4 5; do
        for bin in $BINS; do
            echo "$(timing "$bin" "$TMP/rk") $(timing "$bin" "$TMP/r1")" >> "$TMP/wall_$bin"
        done
        echo "$(timed "$LIB" "$id" "$p" "$K") $(timed "$LIB" "$id" "$p" 0)" >> "$TMP/wall_lib"
        echo "$(timed "$ARB" "$id" "$p" "$K") $(timed "$ARB" "$id" "$p" 0)" >> "$TMP/wall_arb"
    done
    libwall=$(awk -v k="$K" '{printf "%.2f\n", ($1 - $3) / k / 1000}' "$TMP/wall_lib" | median5)
    libcpu=$(awk -v k="$K" '{printf "%.2f\n", ($2 - $4) / k / 1000}' "$TMP/wall_lib" | median5)
    arbcpu=$(awk -v k="$K" '{printf "%.2f\n", ($2 - $4) / k / 1000}' "$TMP/wall_arb" | median5)
    rm -f "$TMP/wall_lib" "$TMP/wall_arb"
    arbins=$((($(total "$ARB" "$id" "$p" "$N2") - $(total "$ARB" "$id" "$p" "$N1")) / (N2 - N1)))
    for bin in $BINS; do
        set -- $(count "$bin" "$TMP/rn1") $(count "$bin" "$TMP/rn2")
        per=$((($3 - $1) / (N2 - N1)))
        lib=$((($4 - $2) / (N2 - N1)))
        wall=$(awk -v k="$K" '{printf "%.2f\n", ($1 - $3) / k / 1000}' "$TMP/wall_$bin" | median5)
        cpu=$(awk -v k="$K" '{printf "%.2f\n", ($2 - $4) / k / 1000}' "$TMP/wall_$bin" | median5)
        rm -f "$TMP/wall_$bin"
        ins_ratio=$(awk -v e="$per" -v a="$arbins" 'BEGIN { printf "%.2fx", e / a }')
        cpu_ratio=$(awk -v c="$cpu" -v a="$arbcpu" 'BEGIN { printf "%.2fx", c / a }')
        echo "| \`$f\` on [$a, $b] | $p | $bin | $per | $lib | $((per - lib)) | $arbins | $ins_ratio | $wall | $cpu | $libwall | $libcpu | $arbcpu | $cpu_ratio |"
    done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
lines "$TMP/rk" "$K" '{"id":1,"fn":"integrate","f":"1/(1+x^2)","a":"0","b":"1","prec":64}'
MAUGIS_EVAL_PROFILE=1 "$TMP/after" eval < "$TMP/rk" 2>&1 >/dev/null | tail -7
