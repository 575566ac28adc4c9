"""Reproducible evidence: the report regenerated from the same results (--no-run) is the same
bytes, wherever the checkout lies and whatever order Python gives its sets; the report's time
is in one named field, `generated`. Run:
/usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from traceability import reproducible, reqif
from traceability.tests.test_harness import FIX, FIX_COMMIT, FIX_CONFIG, REPO

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(os.path.dirname(HERE), "build_report.py")
FILES = ("index.html", "traceability.md", "traceability.json", "tamias2d.reqif")


def harness(repo, date, hash_seed):
    """The harness as a process of its own (its own hash seed) on a copy of the fixture."""
    env = dict(os.environ, PYTHONHASHSEED=str(hash_seed))
    env.pop("SOURCE_DATE_EPOCH", None)
    out = os.path.join(repo, "reports")
    subprocess.run(["/usr/bin/python3", SCRIPT, "--source", repo, "--build", os.path.join(repo, "no-build"),
                    "--out", out, "--results", os.path.join(repo, "results"), "--data",
                    os.path.join(repo, "data"), "--no-run", "--no-checker", "--seed-tables",
                    os.path.join(FIX, "seed_tables.yaml"), "--date", date, "--quiet", "--config",
                    FIX_CONFIG, "--commit", FIX_COMMIT], env=env, capture_output=True, timeout=300)
    files = {}
    for d, _, names in os.walk(out):
        for n in names:
            path = os.path.join(d, n)
            with open(path, "rb") as fh:
                files[os.path.relpath(path, out)] = fh.read()
    return files


class SameResultsSameBytes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="trace-repro-")
        cls.runs = []
        # Two checkouts in directories of different names and depths, two hash seeds.
        for k, (where, seed, date) in enumerate((("a", 1, "2000-01-01 00:00 UTC"),
                                                 ("bb/deeper", 2, "2000-01-01 00:00 UTC"),
                                                 ("c", 3, "2031-07-15 12:34 UTC"))):
            repo = os.path.join(cls.tmp, where, "repo")
            shutil.copytree(REPO, repo)
            cls.runs.append(harness(repo, date, seed))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_every_file_is_the_same(self):
        a, b = self.runs[0], self.runs[1]
        for name in FILES:
            self.assertIn(name, a)
        self.assertEqual(sorted(a), sorted(b))
        for name in sorted(a):
            self.assertEqual(a[name], b[name], f"{name} differs between two regenerations")

    def test_no_absolute_path_of_the_checkout(self):
        for name in FILES:
            self.assertNotIn(self.tmp.encode(), self.runs[0][name], name)

    def test_the_time_is_only_in_generated(self):
        # Another --date: only `generated` (and what prints it: the pages' headers, the
        # ReqIF's CREATION-TIME) differs.
        a, c = self.runs[0], self.runs[2]
        ja, jc = json.loads(a["traceability.json"]), json.loads(c["traceability.json"])
        self.assertEqual((ja["generated"], jc["generated"]), ("2000-01-01 00:00 UTC", "2031-07-15 12:34 UTC"))
        ja["generated"] = jc["generated"]
        self.assertEqual(ja, jc)
        for name, old, new in (("index.html", b"2000-01-01 00:00 UTC", b"2031-07-15 12:34 UTC"),
                               ("traceability.md", b"2000-01-01 00:00 UTC", b"2031-07-15 12:34 UTC"),
                               ("tamias2d.reqif", b"2000-01-01T00:00:00Z", b"2031-07-15T12:34:00Z")):
            self.assertEqual(a[name].replace(old, new), c[name], name)
        for name in set(a) - set(FILES):  # plots and graphs carry no time
            self.assertEqual(a[name], c[name], name)


@unittest.skipUnless(shutil.which("ctest"), "ctest not installed")
class RunThenRegenerate(unittest.TestCase):
    """The report of a run and the report regenerated from its results (--no-run) differ only
    in inputs.ran_tests, which says whether this invocation ran the tests."""

    def test_regenerating_a_runs_report(self):
        with tempfile.TemporaryDirectory(prefix="trace-rerun-") as tmp:
            build = os.path.join(tmp, "build")
            os.makedirs(build)
            with open(os.path.join(build, "CTestTestfile.cmake"), "w", encoding="utf-8") as fh:
                fh.write('add_test(cli_smoke "/bin/true")\n'
                         'set_tests_properties(cli_smoke PROPERTIES LABELS "R1")\n')
            repo = os.path.join(tmp, "repo")
            shutil.copytree(REPO, repo)
            shutil.rmtree(os.path.join(repo, "results"))
            out = os.path.join(repo, "reports")
            base = ["/usr/bin/python3", SCRIPT, "--source", repo, "--build", build, "--out", out,
                    "--data", os.path.join(repo, "data"), "--no-checker", "--quiet", "--config",
                    FIX_CONFIG, "--commit", FIX_COMMIT, "--seed-tables",
                    os.path.join(FIX, "seed_tables.yaml"), "--date", "2000-01-01 00:00 UTC"]
            pages = []
            for extra in ([], ["--no-run"]):
                subprocess.run(base + extra, capture_output=True, timeout=300)
                with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
                    pages.append(json.load(fh))
                with open(os.path.join(out, reqif.FILE_NAME), "rb") as fh:
                    pages[-1]["_reqif"] = fh.read()
            run, again = pages
            self.assertEqual((run["inputs"]["ran_tests"], again["inputs"]["ran_tests"]), (True, False))
            self.assertEqual(run["run"]["commands"], again["run"]["commands"])  # the manifest, as recorded
            run["inputs"]["ran_tests"] = False
            self.assertEqual(run, again)


class Portable(unittest.TestCase):
    def test_paths_under_the_root_become_relative(self):
        doc = {"root": "/x/repo", "a": ["/x/repo/srs", "the build in /x/repo/build is stale",
                                        "/x/repo2/other", "no /x/repo.", {"s": {"/x/repo/b"}}]}
        got = reproducible.portable(doc, "/x/repo")
        self.assertEqual(got, {"root": ".", "a": ["srs", "the build in build is stale",
                                                  "/x/repo2/other", "no /x/repo.", {"s": ["b"]}]})

    def test_timestamps(self):
        self.assertEqual(reproducible.iso_utc("2026-11-29 10:05 UTC"), "2026-11-29T10:05:00Z")
        self.assertEqual(reproducible.iso_utc("2026-11-29T11:05:00+01:00"), "2026-11-29T10:05:00Z")
        self.assertIsNone(reproducible.iso_utc("yesterday"))


if __name__ == "__main__":
    unittest.main()
