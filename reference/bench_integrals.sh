#!/bin/sh
# Speed comparison of the certified integrator against C Arb (issue 22, item 7).
#
#   sh reference/bench_integrals.sh            (from the workspace root)
#
# Installs Debian's libflint-arb-dev if missing (needs root or sudo), compiles
# reference/arb_integrals.c against it, runs it, runs the maugis side
# (examples/integrals_bench.rs, release build) and python-flint's acb.integral (in a
# temporary venv, or .venv-ci if it has python-flint) on the same integrals, and prints
# a markdown table.  Every side: one warm-up call, then calls repeated until 0.2 s,
# mean time per call.  The evaluation counts are those of one call.
set -eu
cd "$(dirname "$0")/.."
if [ ! -e /usr/include/acb_calc.h ]; then
    SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
    $SUDO apt-get install -y libflint-arb-dev >&2
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cc -O2 -o "$TMP/arb_integrals" reference/arb_integrals.c -lflint-arb -lflint -lmpfr -lgmp
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
"$TMP/arb_integrals" > "$TMP/arb.tsv"
cargo run -q --release --features maugis/gmp-no-check --example integrals_bench > "$TMP/maugis.tsv"
PY=""
if [ -x .venv-ci/bin/python ] && .venv-ci/bin/python -c "import flint" 2>/dev/null; then
    PY=.venv-ci/bin/python
elif python3 -m venv "$TMP/venv" >&2 && "$TMP/venv/bin/pip" -q install python-flint >&2; then
    PY="$TMP/venv/bin/python"
fi
if [ -n "$PY" ]; then
    "$PY" - > "$TMP/pyflint.tsv" <<'PYEOF'
import time
from flint import acb, ctx

def count(f):
    def g(x, analytic):
        g.n += 1
        return f(x, analytic)
    g.n = 0
    return g

INTEGRALS = [
    ("atanderiv", lambda x, _: 1 / (1 + x * x), 0, 1),
    ("rump", lambda x, _: (x + x.exp()).sin(), 0, 8),
    ("exp", lambda x, _: x.exp(), 0, 1),
    ("sqrt", lambda x, a: x.sqrt(analytic=a), 1, 4),
    ("xJ0", lambda x, _: x * x.bessel_j(0), 0, 1),
    ("sin100", lambda x, _: x.sin(), 0, 100),
]
for prec in (64, 333):
    ctx.prec = prec
    for ident, f, a, b in INTEGRALS:
        g = count(f)
        acb.integral(g, a, b)
        n = g.n
        calls, t0 = 0, time.perf_counter()
        while True:
            r = acb.integral(g, a, b)
            calls += 1
            t = time.perf_counter() - t0
            if t >= 0.2:
                break
        print(f"{ident}\t{prec}\t{1e3 * t / calls:.6f}\t{n}\t{calls}\t{r.real}")
ctx.prec = 53
PYEOF
else
    : > "$TMP/pyflint.tsv"
fi
# maugis eval: the same integrals as JSON Lines requests (expression text parsed per
# request), time per request = (time of k requests - time of 1) / (k - 1), so that the
# process start cancels
cargo build -q --release --features maugis/gmp-no-check -p maugis-cli
python3 - target/release/maugis > "$TMP/eval.tsv" <<'PYEOF'
import subprocess, sys, time
exe = sys.argv[1]
CASES = [("atanderiv", "1/(1+x^2)", 0, 1), ("rump", "sin(x+exp(x))", 0, 8), ("exp", "exp(x)", 0, 1),
         ("sqrt", "sqrt(x)", 1, 4), ("xJ0", "x*besselj(0,x)", 0, 1), ("sin100", "sin(x)", 0, 100)]
for prec in (64, 333):
    for ident, f, a, b in CASES:
        req = '{"fn":"integrate","f":"%s","a":"%s","b":"%s","prec":%d}\n' % (f, a, b, prec)
        def run(k):
            t = time.perf_counter()
            subprocess.run([exe, "eval"], input=req * k, capture_output=True, text=True, check=True)
            return time.perf_counter() - t
        t1 = min(run(1) for _ in range(3))
        k = 2
        while True:
            tk = run(k)
            if tk - t1 >= 0.3 or k >= 100000:
                break
            k *= 4
        print(f"{ident}\t{prec}\t{1e3 * (tk - t1) / (k - 1):.6f}")
PYEOF
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
python3 - "$TMP/arb.tsv" "$TMP/maugis.tsv" "$TMP/pyflint.tsv" "$TMP/eval.tsv" <<'PYEOF'
import sys
def load(p):
    out = {}
    for line in open(p):
        f = line.rstrip("\n").split("\t")
        if len(f) >= 3:
            out[(f[0], f[1])] = f
    return out
arb, mau, pyf, ev = (load(p) for p in sys.argv[1:5])
print("| integral | bits | C Arb ms | Arb evals | maugis ms | maugis evals | maugis / Arb | goal met | python-flint ms | maugis eval ms | eval / python-flint |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for key, a in arb.items():
    m = mau.get(key)
    p = pyf.get(key)
    if m is None:
        continue
    ratio = float(m[2]) / float(a[2])
    e = ev.get(key)
    pms = f"{float(p[2]):.3f}" if p else "-"
    ems = f"{float(e[2]):.3f}" if e else "-"
    eratio = f"{float(e[2]) / float(p[2]):.2f}x" if e and p else "-"
    print(f"| {key[0]} | {key[1]} | {float(a[2]):.3f} | {a[3]} | {float(m[2]):.3f} | {m[3]} | {ratio:.1f}x | {m[5]} | {pms} | {ems} | {eratio} |")
PYEOF
