# Sourced by bench_first_call.sh, instructions_first_call.sh, eval_overhead.sh and
# instructions_warm_calls.sh (from the workspace root, after `set -eu`): installs what
# is missing (Debian's libflint-arb-dev, C Arb 2.23; valgrind when NEED_VALGRIND=1)
# with apt-get, as root or with sudo, compiles reference/arb_first_call.c into
# "$TMP/arb_first_call" and builds examples/first_call.rs (release) as "$ME". A run
# that cannot install C Arb says so and exits 0 (these scripts are never part of
# ./dev test). Sets TMP (removed at exit) and ME.
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
if [ "${NEED_VALGRIND:-0}" = 1 ] && ! command -v valgrind >/dev/null; then
    $SUDO apt-get install -y valgrind >&2
fi
if [ ! -e /usr/include/acb_calc.h ] && [ ! -e /usr/include/flint/acb_calc.h ]; then
    if ! $SUDO apt-get install -y libflint-arb-dev >&2; then
        echo "$(basename "$0"): skipped: C Arb (Debian's libflint-arb-dev) is not installed and could not be installed" >&2
        exit 0
    fi
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
INC=""; [ -e /usr/include/flint/acb_calc.h ] && INC="-I/usr/include/flint"
cc -O2 $INC -o "$TMP/arb_first_call" reference/arb_first_call.c -lflint-arb -lflint -lmpfr -lgmp
cargo build -q --release --features maugis/gmp-no-check --example first_call
ME=target/release/examples/first_call
