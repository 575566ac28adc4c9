"""The dated benchmark records as the report reads them (traceability/bench_records.py).

Oracle: records written here by hand, in the two table forms of verification/bench/results/README.md,
whose points (scene, engine, ms/step, runs, range) are known from the values written.
"""
from __future__ import annotations

import csv
import json
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(os.path.dirname(HERE)))

from traceability import bench_records  # noqa: E402

MACHINE = {"name": "test-machine", "cpu": "a CPU", "cores": 2, "details": "none"}


def run(rid, date, command, tables, commit=None):
    return {"id": rid, "what": "w", "commit": commit, "date": date, "command": command,
            "tables": tables}


ENGINE_COLUMNS = {
    "name": "Step time: ms/step (thread CPU time, median of 5)",
    "columns": ["scene", "Tamias2D", "Chipmunk 7", "v3 AVX2", "Tamias2D / v3 AVX2", "vs Chipmunk 7"],
    "rows": [["pyramid40", 0.5, 1.5, 0.45, 1.11, "3.00x"],
             ["rain_16k", 4.0, None, "4.1 / 4.3", 0.98, "n/a"]],
}
FIGURE_ROWS = {
    "name": "Tamias2D ms/step and speed-ups (peer ms/step over Tamias2D's)",
    "columns": ["scene", "figure", "run 1", "run 2", "run 3"],
    "rows": [["pyramid40", "Tamias2D ms/step", 0.44, 0.40, 0.47],
             ["pyramid40", "speed-up vs Chipmunk 7", 2.7, 2.6, 2.7],
             ["scaling", "rain_16k / rain_1k (target <= 20x)", "19.5x", "17.2x", "20.0x"]],
}
WALL_CLOCK = {
    "name": "Wall-clock ms/step, median of 5",
    "columns": ["scene", "Tamias2D"],
    "rows": [["pyramid40", 0.9]],
}
NOT_STEP_TIME = {"name": "Largest error", "columns": ["scene", "Tamias2D"], "rows": [["pyramid40", 7]]}


def write_records(root):
    d = os.path.join(root, "verification", "bench", "results", "test-machine")
    os.makedirs(d)
    with open(os.path.join(d, "b.json"), "w") as fh:
        json.dump({"format": "tamias2d-record-1", "title": "t", "machine": MACHINE, "runs": [
            run("later", "2026-11-26", "build/verification/bench/tamias_bench OUT", [ENGINE_COLUMNS]),
            run("threads", "2026-11-26", "build/verification/bench/tamias_thread_bench --threads 2",
                [WALL_CLOCK]),
        ]}, fh)
    with open(os.path.join(d, "a.json"), "w") as fh:
        json.dump({"format": "tamias2d-record-1", "title": "t", "machine": MACHINE, "runs": [
            run("earlier", "2026-11-25", "tamias_bench <out_dir>", [FIGURE_ROWS, NOT_STEP_TIME]),
        ]}, fh)


class BenchRecords(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        write_records(self.root)

    def tearDown(self):
        self.tmp.cleanup()

    def test_points_of_both_forms(self):
        data = bench_records.collect(self.root)
        got = [(p["date"], p["scene"], p["engine"], p["ms_per_step"], p["runs"], p["low"], p["high"],
                p["run"]) for p in data["points"]]
        self.assertEqual(got, [
            # the figure form: the median of the three runs, their range
            ("2026-11-25", "pyramid40", "Tamias2D", 0.44, 3, 0.40, 0.47, "earlier"),
            # the engine columns: ratios and "vs" columns are not engines, v3 AVX2 is named in full
            ("2026-11-26", "pyramid40", "Box2D v3 AVX2", 0.45, 1, 0.45, 0.45, "later"),
            ("2026-11-26", "pyramid40", "Chipmunk 7", 1.5, 1, 1.5, 1.5, "later"),
            ("2026-11-26", "pyramid40", "Tamias2D", 0.5, 1, 0.5, 0.5, "later"),
            ("2026-11-26", "rain_16k", "Tamias2D", 4.0, 1, 4.0, 4.0, "later"),
        ])
        self.assertEqual(data["records"], 2)
        self.assertEqual(data["left_out"], 1)  # "4.1 / 4.3"; null (not run) is no cell to count
        self.assertTrue(all(p["record"] == "results/test-machine/" + ("a" if p["run"] == "earlier" else "b")
                            + ".json" for p in data["points"]))

    def test_csv_holds_every_point(self):
        data = bench_records.render(bench_records.collect(self.root), self.root)
        with open(os.path.join(self.root, data["csv"]), newline="") as fh:
            rows = list(csv.DictReader(fh))
        self.assertEqual(len(rows), 5)
        self.assertEqual(rows[0]["ms_per_step"], "0.44")
        self.assertEqual(rows[0]["commit"], "")
        self.assertEqual(rows[-1]["scene"], "rain_16k")

    def test_plot_is_written_the_same_twice(self):
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            self.skipTest("no matplotlib")
        warnings = []
        first = bench_records.render(bench_records.collect(self.root), self.root, warnings)
        self.assertEqual(warnings, [])
        self.assertEqual(first["svg"], "bench_records/ms_per_step.svg")
        with open(os.path.join(self.root, first["svg"]), "rb") as fh:
            one = fh.read()
        bench_records.render(bench_records.collect(self.root), self.root)
        with open(os.path.join(self.root, first["svg"]), "rb") as fh:
            self.assertEqual(fh.read(), one)
        self.assertIn(b"pyramid40", one)
        self.assertIn(b"Box2D v3 AVX2", one)

    def test_no_records_no_plot(self):
        with tempfile.TemporaryDirectory() as empty:
            data = bench_records.render(bench_records.collect(empty), empty)
            self.assertEqual(data["points"], [])
            self.assertIsNone(data["svg"])
            with open(os.path.join(empty, data["csv"])) as fh:
                self.assertEqual(fh.read().splitlines(), [",".join(bench_records.CSV_COLUMNS)])


if __name__ == "__main__":
    unittest.main()
