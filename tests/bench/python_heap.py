"""The 1000-box heap simulated from Python beside the command line, in one run (issue: "within
10 % of the command line's time").

    /usr/bin/python3 tests/bench/python_heap.py [--runs 3] [--build build]

Each round runs `impulse simulate assets/scenes/ex2_many_bodies.toml --world FILE` (the physics,
the scene's checks and one CSV row a step) and `impulse.load(...).simulate()` in this process
(the same, with every step's numbers of every body kept as arrays: 721 rows of 1001 bodies;
then again with every contact kept too, about 4000 a step), alternately, each timed from start to end (the program's start and the scene's loading
included); it prints each round's seconds and the medians' ratio. Needs quiet cores, as every
benchmark here.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = "assets/scenes/ex2_many_bodies.toml"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import impulse
    os.chdir(ROOT)
    program = os.path.join(args.build, "demos", "impulse")
    command, python, with_contacts = [], [], []
    for round_number in range(args.runs):
        start = time.perf_counter()
        with tempfile.TemporaryDirectory() as directory:
            subprocess.run([program, "simulate", SCENE, "--world", os.path.join(directory, "world.csv")], check=True,
                           capture_output=True)
        command.append(time.perf_counter() - start)
        start = time.perf_counter()
        trace = impulse.load(SCENE).simulate(contacts=False, progress=False)
        python.append(time.perf_counter() - start)
        start = time.perf_counter()
        impulse.load(SCENE).simulate(progress=False)
        with_contacts.append(time.perf_counter() - start)
        print(f"round {round_number + 1}: command line {command[-1]:.2f} s, Python {python[-1]:.2f} s "
              f"({len(trace)} rows x {len(trace.bodies)} bodies kept), with every contact kept {with_contacts[-1]:.2f} s",
              flush=True)
    median = statistics.median
    print(f"median: command line {median(command):.2f} s, Python {median(python):.2f} s "
          f"(ratio {median(python) / median(command):.3f}), with the contacts {median(with_contacts):.2f} s "
          f"(ratio {median(with_contacts) / median(command):.3f})")


if __name__ == "__main__":
    main()
