#!/bin/sh
# First call against warm call, maugis against C Arb (issue 36, item 1), side by side
# in one run: each (integral, precision) of issue 36's table runs in a fresh process of
# each side (examples/first_call.rs and reference/arb_first_call.c), so the first call
# builds the Gauss-Legendre nodes.  Prints a markdown table with the ratios.
#
#   sh reference/bench_first_call.sh            (from the workspace root)
#   sh reference/bench_first_call.sh --cpu      the first call alone, in CPU time
#
# The default run also times `maugis eval` (release) on the same integrals as JSON
# Lines `integrate` requests: the first call in a fresh process (less the process's
# start-up) and the warm call (21 requests less 1, over 20).
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
. reference/first_call_setup.sh
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
# Through `maugis eval` (as a user of the server would): first call = a fresh process
# with one request less one with no request (start-up), medians of seven; warm = the
# process with K + 1 identical requests less the one with 1, over K (K: about 200 ms
# of the library's warm calls, 20 to 20000; medians of three; the parsed integrand
# and the rules are cached after the first request).
cargo build -q --release -p maugis-cli --features maugis/gmp-no-check
EV=target/release/maugis
expr_of() { # id -> "f|a|b"
    case "$1" in
        atanderiv) echo '1/(1+x^2)|0|1' ;; rump) echo 'sin(x + exp(x))|0|8' ;;
        gauss) echo 'exp(-x^2)|0|2' ;; sqrt) echo 'sqrt(x)|1|4' ;;
        xJ0) echo 'x*besselj(0, x)|0|10' ;; sin_zero) echo 'sin(x)|-1|1' ;;
    esac
}
now_ns() { date +%s%N; }
wall_ms() { # file: wall ms of `maugis eval < file`
    t0=$(now_ns); "$EV" eval < "$1" > "$TMP/eval_out"; t1=$(now_ns)
    if grep -q '"error"' "$TMP/eval_out"; then echo "eval failed: $(head -c 300 "$TMP/eval_out")" >&2; exit 1; fi
    echo "$t0 $t1" | awk '{ printf "%.3f", ($2 - $1) / 1e6 }'
}
: > "$TMP/req_0"
median7() { # file: the median of seven wall_ms of it
    for j in 1 2 3 4 5 6 7; do wall_ms "$1"; echo; done | sort -n | sed -n 4p
}
echo "| integral | bits | maugis first ms | C Arb first ms | first ratio | maugis warm ms | C Arb warm ms | warm ratio | eval first ms | eval first / Arb | eval warm ms | eval warm / Arb |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for case in atanderiv:64 atanderiv:333 atanderiv:3333 rump:64 rump:333 gauss:333 gauss:3333 sqrt:3333 xJ0:3333 sin_zero:64 sin_zero:333; do
    id=${case%%:*}; p=${case##*:}
    m=$("$ME" "$id" "$p")
    a=$("$TMP/arb_first_call" "$id" "$p")
    spec=$(expr_of "$id")
    f=${spec%%|*}; rest=${spec#*|}; lo=${rest%%|*}; hi=${rest#*|}
    req="{\"fn\":\"integrate\",\"f\":\"$f\",\"a\":\"$lo\",\"b\":\"$hi\",\"prec\":$p}"
    echo "$req" > "$TMP/req_1"
    # K: about 200 ms of the library's warm calls (at least 20, at most 20000), so that
    # the process's start-up and its spread stay far below the K requests' time
    k=$(printf '%s\n' "$m" | awk -F'\t' '{ k = int(200 / $4); if (k < 20) k = 20; if (k > 20000) k = 20000; print k }')
    : > "$TMP/req_k"; i=0; while [ $i -le $k ]; do echo "$req" >> "$TMP/req_k"; i=$((i + 1)); done
    s0=$(median7 "$TMP/req_0")
    s1=$(median7 "$TMP/req_1")
    sk=$(median3 "$(wall_ms "$TMP/req_k")" "$(wall_ms "$TMP/req_k")" "$(wall_ms "$TMP/req_k")")
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$m" "$a" "$s0" "$s1" "$sk" "$k" | awk -F'\t' '{ ef = $13 - $12; ew = ($14 - $13) / $15;
        printf "| %s | %s | %.2f | %.2f | %.2fx | %.3f | %.3f | %.2fx | %.2f | %.2fx | %.3f | %.2fx |\n",
            $1, $2, $3, $9, $3 / $9, $4, $10, $4 / $10, ef, ef / $9, ew, ew / $10 }'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
