"""Bertini 2 (the `bertini` wheel, PyPI) on the systems of the frontier benchmark
(`benches/frontier/run.sh` writes them to target/frontier): its zero-dimensional algorithm
with the total-degree start and the Cauchy endgame in double precision, timed in process, with
the finite solutions counted (projective points whose homogenising coordinate is not below
1e-8 of their size, distinct to 1e-6).

    python benches/frontier/bertini2.py katsura-8 katsura-9 ...
"""

import sys
import time

import bertini
import numpy as np


def solve(name):
    text = open(f"target/frontier/{name}.bertini").read()
    body = text.split("INPUT", 1)[1].rsplit("END", 1)[0]
    system = bertini.parse.system(body)
    algorithm = bertini.nag_algorithm.ZeroDimCauchyDoublePrecisionTotalDegree(system)
    start = time.perf_counter()
    algorithm.solve()
    seconds = time.perf_counter() - start
    finite = []
    for z in algorithm.solutions():
        z = np.array(z, dtype=complex)
        if abs(z[0]) < 1e-8 * np.linalg.norm(z):
            continue
        x = z[1:] / z[0]
        if not any(np.linalg.norm(x - y) < 1e-6 * (1 + np.linalg.norm(y)) for y in finite):
            finite.append(x)
    print(f"{name}: Bertini 2 {seconds:.2f} s, {len(finite)} distinct finite solutions")


for name in sys.argv[1:]:
    solve(name)
