"""traceability/diff_reports.py on two variants of the fixture: what changed between their
reports (items, links, tests, figures), timings listed only beyond the noise band. Run:
/usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from traceability import diff_reports
from traceability.tests.test_harness import REPO, run_harness

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(os.path.dirname(HERE), "diff_reports.py")
ERRORS = {"name": "Error vs dt", "columns": ["dt (s)", "max error (m)"],
          "rows": [[0.1, 0.0125], [0.05, 0.003125]]}


class TwoVariants(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="trace-diff-")
        cls.paths = {}
        for name in ("old", "new"):
            repo = os.path.join(cls.tmp, name)
            shutil.copytree(REPO, repo)
            data = os.path.join(repo, "data", "peer_compare.json")
            with open(data, encoding="utf-8") as fh:
                doc = json.load(fh)
            doc["tables"].append(json.loads(json.dumps(ERRORS)))
            if name == "new":
                cls.make_new(repo, doc)
            with open(data, "w", encoding="utf-8") as fh:
                json.dump(doc, fh)
            out = os.path.join(cls.tmp, name + "-reports")
            run_harness(repo, out)
            cls.paths[name] = os.path.join(out, "traceability.json")

    @staticmethod
    def make_new(repo, doc):
        # IM2's failing case passes, R2 leaves the SRS.
        junit = os.path.join(repo, "results", "boost", "model_tests.junit.xml")
        with open(junit, encoding="utf-8") as fh:
            text = fh.read()
        start = text.index("<failure")
        with open(junit, "w", encoding="utf-8") as fh:
            fh.write(text[:start] + text[text.index("</system-err>", start) + len("</system-err>"):])
        req = os.path.join(repo, "srs", "requirements.yaml")
        with open(req, encoding="utf-8") as fh:
            text = fh.read()
        with open(req, "w", encoding="utf-8") as fh:
            fh.write(text[:text.index("\n- label: R2") + 1])
        checks = {c["name"]: c for c in doc["checks"]}
        checks["trajectory_matches_closed_form"]["labels"] = ["IM1", "R1"]       # a link added
        checks["speed_floor_2x_peer"]["labels"] = []                             # a link removed
        checks["step_time_within_2x_of_peer"]["oracle"] = "closed form: 2 x the peer's time"  # regraded
        checks["change_cost_within_10_percent"]["figure"] = "12.1 % > 10 %"
        step = doc["tables"][0]["rows"]
        step[0][2] = 0.44   # Tamias2D's ms per step: +4.8 %, within the noise band
        step[1][2] = 0.45   # the peer's: +36 %, beyond it
        doc["tables"][1]["rows"][1][1] = 0.003125000000001  # an error: any change is listed
        # A review whose item has changed since: the link is suspect.
        os.makedirs(os.path.join(repo, "traceability"))
        with open(os.path.join(repo, "traceability", "reviews.yaml"), "w", encoding="utf-8") as fh:
            fh.write("reviews:\n- item: IM1\n  test: model_tests:model/im1_free_fall\n  reviewer: R\n"
                     "  date: '2000-01-01'\n  item_fingerprint: '0000000000000000'\n"
                     "  test_fingerprint: '0000000000000000'\n")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def run_diff(self, *args):
        return subprocess.run(["/usr/bin/python3", SCRIPT, *args], capture_output=True, text=True,
                              timeout=120)

    def test_what_changed(self):
        proc = self.run_diff(self.paths["old"], self.paths["new"], "--json")
        self.assertEqual(proc.returncode, 1, proc.stderr)
        d = json.loads(proc.stdout)
        self.assertEqual(d["items_status"], [{"label": "IM2", "old": "failing", "new": "verified"}])
        self.assertEqual((d["items_added"], d["items_removed"]), ([], ["R2"]))
        self.assertEqual([(x["item"], x["test"]) for x in d["links_added"]],
                         [("R1", "peer_compare:trajectory_matches_closed_form")])
        self.assertEqual([(x["item"], x["test"]) for x in d["links_removed"]],
                         [("NFR1", "peer_compare:speed_floor_2x_peer")])
        self.assertEqual(d["links_regraded"], [{"item": "NFR1", "test": "peer_compare:step_time_within_2x_of_peer",
                                                "old": "weak", "new": "strong"}])
        self.assertEqual(d["links_suspect"], [{"item": "IM1", "test": "model_tests:model/im1_free_fall",
                                               "changed": ["item", "test"], "new": True}])
        self.assertEqual(d["tests_status"], [{"id": "model_tests:model/im2_spin", "old": "failed", "new": "passed"}])
        self.assertEqual((d["tests_added"], d["tests_removed"]), ([], []))
        self.assertEqual([(x["where"], x["old"], x["new"], x["timing"]) for x in d["figures"]], [
            ("check change_cost_within_10_percent: figure", "13.6 % > 10 %", "12.1 % > 10 %", False),
            ("Step time / peer / ms per step", 0.33, 0.45, True),
            ("Error vs dt / 0.05 / max error (m)", 0.003125, 0.003125000000001, False)])
        self.assertEqual(d["figures_within_noise"], 1)  # Tamias2D's 0.42 -> 0.44 ms
        text = self.run_diff(self.paths["old"], self.paths["new"]).stdout
        self.assertIn("IM2: failing -> verified", text)
        self.assertIn("Step time / peer / ms per step: 0.33 -> 0.45 (+36.4 %) [timing]", text)
        self.assertIn("Timings that moved within the noise band (not listed): 1", text)

    def test_a_wider_noise_band_lists_fewer_timings(self):
        d = json.loads(self.run_diff(self.paths["old"], self.paths["new"], "--json", "--noise", "0.5").stdout)
        self.assertEqual([x["where"] for x in d["figures"] if x["timing"]], [])
        self.assertEqual(d["figures_within_noise"], 2)

    def test_a_report_against_itself_lists_nothing(self):
        proc = self.run_diff(self.paths["old"], self.paths["old"])
        self.assertEqual(proc.returncode, 0, proc.stdout)
        self.assertIn("Figures that moved (timings beyond the noise band of 10 %) (0)", proc.stdout)

    def test_moved_rules(self):
        # Oracle: the rule in diff_reports.py's docstring, case by case.
        self.assertEqual(diff_reports.moved(1.0, 1.05, True, 0.1)[0], False)
        self.assertEqual(diff_reports.moved(1.0, 1.2, True, 0.1)[0], True)
        self.assertEqual(diff_reports.moved(1.0, 1.0000001, False, 0.1)[0], True)
        self.assertEqual(diff_reports.moved("4 (1 + 1)", "4.2 (1 + 1)", True, 0.1)[0], False)
        self.assertEqual(diff_reports.moved("intact", "exploded", False, 0.1)[0], True)
        self.assertTrue(diff_reports.TIMING.search("median CPU ms/step"))
        self.assertFalse(diff_reports.TIMING.search("max |dp| (m)"))

    def test_usage_error(self):
        self.assertEqual(self.run_diff("/nonexistent.json", self.paths["old"]).returncode, 2)


if __name__ == "__main__":
    unittest.main()
