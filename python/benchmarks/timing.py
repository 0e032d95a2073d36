"""Per-element cost of maugis.bessel_j on 1e5 points: the Python call (GIL
released, rayon on all cores, and single-threaded), the plain serial Rust loop
over the same inputs, and SciPy's jv. Not a test; run it on a quiet machine:

    python python/benchmarks/timing.py

The single-threaded figure is taken in a subprocess with RAYON_NUM_THREADS=1.
"""

import os
import subprocess
import sys
import time

import numpy as np

N = 100_000
REPEATS = 3


def best(f):
    times = []
    for _ in range(REPEATS):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def inputs():
    rng = np.random.default_rng(20261123)
    n = rng.integers(0, 50, N).astype(np.int64)
    x = rng.uniform(0.0, 60.0, N)
    return n, x


def python_call_seconds():
    import maugis

    n, x = inputs()
    return best(lambda: maugis.bessel_j(n, x))


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--python-call":
        print(python_call_seconds())
        return
    import scipy.special

    import maugis
    from maugis import _maugis

    n, x = inputs()
    ns = lambda s: f"{s / N * 1e9:9.1f} ns"  # noqa: E731
    rust = min(_maugis._native_loop_seconds("bessel_j", n, x) for _ in range(REPEATS))
    parallel = python_call_seconds()
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    single = float(subprocess.run([sys.executable, __file__, "--python-call"], env=env, capture_output=True,
                                  text=True, check=True).stdout)
    scipy_s = best(lambda: scipy.special.jv(n, x))
    print(f"J_n(x), n in [0, 50), x in [0, 60), {N} points, best of {REPEATS}, per element:")
    print(f"  Rust loop (serial)          {ns(rust)}")
    print(f"  maugis.bessel_j, 1 thread   {ns(single)}   ({single / rust:.2f}x the Rust loop)")
    print(f"  maugis.bessel_j, {os.cpu_count()} threads  {ns(parallel)}   ({parallel / rust:.2f}x)")
    print(f"  scipy.special.jv            {ns(scipy_s)}")
    print(f"  max |maugis - scipy| = {np.max(np.abs(maugis.bessel_j(n, x) - scipy.special.jv(n, x))):.2e}")


if __name__ == "__main__":
    main()
