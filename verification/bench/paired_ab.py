#!/usr/bin/python3
"""Paired A/B of two tamias_bench binaries (docs/performance.md, "How to run").

    verification/bench/paired_ab.py A B [--rounds N] [--scenes a,b] [--reps R]
    verification/bench/paired_ab.py A B --workers W --regions R [...]

Each round runs A and B once each, alternating which goes first, with
`--engines tamias --no-typing`: the host's load then falls on both alike. With --workers
(and --regions, default as many as workers), A and B are tamias_thread_bench binaries and
the times are their wall-clock ms/step on W workers in R contact regions. A change of a few
per cent is below a single run's noise on a shared machine; the median of the per-round
ratios B/A and the two minima over rounds are what to read. Prints one line per round, then
per scene the minima, the medians and the range of the ratios, and the scaling (rain_16k over
rain_1k) when both are among the scenes. Standard library only.
"""
import argparse
import re
import statistics
import subprocess
import sys
import tempfile


def run(binary, scenes, reps, out_dir):
    """Tamias2D's ms/step per scene from one tamias_bench run."""
    out = subprocess.run(
        [binary, out_dir, "--scenes", scenes, "--engines", "tamias", "--reps", str(reps),
         "--no-typing"],
        capture_output=True, text=True, check=True).stdout
    result, scene = {}, None
    for line in out.splitlines():
        m = re.match(r"^(\S+)\s+\d+ bodies", line)
        if m:
            scene = m.group(1)
        m = re.match(r"^\s+Tamias2D\s+([\d.]+) ms/step", line)
        if m and scene:
            result[scene] = float(m.group(1))
    if not result:
        sys.exit(f"{binary}: no Tamias2D times in its output")
    return result


def run_threads(binary, scenes, reps, workers, regions):
    """Tamias2D's wall ms/step per scene from one tamias_thread_bench run."""
    out = subprocess.run(
        [binary, "--scenes", scenes, "--engines", "tamias", "--threads", str(workers),
         "--contact-regions", str(regions), "--reps", str(reps)],
        capture_output=True, text=True, check=True).stdout
    result = {}
    for line in out.splitlines():
        m = re.match(r"^(\S+)\s+Tamias2D\s+(\d+)\s+(\d+)\s+([\d.]+)", line)
        if m and int(m.group(2)) == regions and int(m.group(3)) == workers:
            result[m.group(1)] = float(m.group(4))
    if not result:
        sys.exit(f"{binary}: no Tamias2D times in its output")
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--rounds", type=int, default=8)
    p.add_argument("--scenes", default="rain_1k,rain_16k,pyramid40")
    p.add_argument("--reps", type=int, default=5)
    p.add_argument("--workers", type=int, help="A and B are tamias_thread_bench binaries")
    p.add_argument("--regions", type=int, help="contact regions (default: --workers)")
    args = p.parse_args()
    if args.workers:
        regions = args.regions or args.workers

        def measure(binary, _out_dir):
            return run_threads(binary, args.scenes, args.reps, args.workers, regions)
    else:
        def measure(binary, out_dir):
            return run(binary, args.scenes, args.reps, out_dir)
    times = {"a": {}, "b": {}}
    with tempfile.TemporaryDirectory() as out_dir:
        for r in range(args.rounds):
            order = ("a", "b") if r % 2 == 0 else ("b", "a")
            got = {tag: measure(getattr(args, tag), out_dir) for tag in order}
            for tag in "ab":
                for scene, ms in got[tag].items():
                    times[tag].setdefault(scene, []).append(ms)
            print(r, " ".join(f"{s} {got['a'][s]:.4f}/{got['b'][s]:.4f}" for s in got["a"]),
                  flush=True)
    a, b = times["a"], times["b"]
    for s in a:
        ratios = [y / x for x, y in zip(a[s], b[s])]
        print(f"{s}: min A {min(a[s]):.4f} B {min(b[s]):.4f} ({min(b[s]) / min(a[s]):.4f}); "
              f"median A {statistics.median(a[s]):.4f} B {statistics.median(b[s]):.4f}; "
              f"median ratio B/A {statistics.median(ratios):.4f} "
              f"(range {min(ratios):.3f}-{max(ratios):.3f})")
    if "rain_1k" in a and "rain_16k" in a:
        def scaling(t):
            return statistics.median(x / y for x, y in zip(t["rain_16k"], t["rain_1k"]))
        print(f"scaling rain_16k / rain_1k, median over rounds: A {scaling(a):.2f} "
              f"B {scaling(b):.2f}")


if __name__ == "__main__":
    main()
